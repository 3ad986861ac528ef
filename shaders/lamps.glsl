// The floating objects' lamps mirrored by the water (with the boat's
// feature): each lit lamp (objects.glsl: its centre, radius and radiance
// times boat.lights, all zero when the lights are off) seen along the
// mirrored ray `r` from the water point `hit` (x z camera-relative, y
// absolute), as optics_lamp_glint's widened disc. Summed over the
// objects in view; the light layers count it as the water's reflection.
// A side light's glints fall on its own side of the hull only.
vec3 lamps_mirrored(vec3 hit, vec3 r)
{
    vec3 at = vec3(hit.x, hit.y - u_cam_height, hit.z);
    vec3 sum = vec3(0.0);
    for (int o = 0; o < u_object_count; o++)
        for (int k = 0; k < TL_MESH_LAMPS; k++) {
            vec3 light = u_objects[o].lamp_light[k].rgb;
            if (!(max(light.r, max(light.g, light.b)) > 0.0))
                continue;
            vec4 lamp = u_objects[o].lamp[k];
            vec3 to = lamp.xyz - at;
            float dist = max(length(to), 1.0e-3);
            // A side light lights the water on its own side of the hull
            // only (its screen): the water point's model x against the
            // lamp's, faded over a tenth of the way.
            float side = u_objects[o].lamp_light[k].w;
            if (side != 0.0) {
                mat4 to_model = u_objects[o].to_model;
                float off = (to_model * vec4(at, 1.0)).x - (to_model * vec4(lamp.xyz, 1.0)).x;
                float per_metre = length(to_model[0].xyz);
                light *= smoothstep(-0.1, 0.1, side * off / (per_metre * dist));
            }
            sum += light * optics_lamp_glint(dot(r, to / dist), lamp.w / dist);
        }
    return layer_emit(TL_LIGHT_REFLECTION, sum);
}
