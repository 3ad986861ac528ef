// The giant wave's lip's shading (TL_FEATURE_GIANT_LIP; its geometry is
// lip.glsl's): after water.glsl, whose normal and reflection it uses.

// The lip at camera-relative `hit`, seen along `ray`: glassy water that
// mirrors the sky, lit through (it is thin: the sun's light crosses it
// and glows turquoise when it is behind), whitening from its tip as it
// throws and all over once it has landed.
vec3 giant_lip_color(vec3 ray, vec3 hit)
{
    vec2 sw = giant_coords(hit.xz), n2;
    GiantLip lip = giant_lip_at(sw.y);
    giant_lip_distance(lip, vec2(sw.x, hit.y), n2);
    vec2 d = u_giant_frame.xy;
    vec3 n = normalize(n2.x * vec3(d.x, 0.0, d.y) + vec3(0.0, n2.y, 0.0));
    // The small waves ride on the thrown water too, flattened.
    float value, slope_var;
    vec3 ripples = water_normal(hit.xz, u_normal_epsilon, 0.0, value, slope_var);
    n = water_facing(ray, normalize(n + 0.6 * vec3(ripples.x, 0.0, ripples.z)));
    float sunlit = giant_sunlit(hit.xz, hit.y);
    // Light through the tube: its thickness there along the sun's ray.
    vec2 q = vec2(sw.x, hit.y) - lip.center;
    float angle = atan(q.x, q.y);
    float daylight = smoothstep(-0.05, 0.1, u_sun_dir.y);
    float across = 2.0 * giant_lip_half(lip, angle) / max(abs(dot(u_sun_dir, n)), 0.25);
    float mu = dot(refract(ray, n, 1.0 / u_water_ior), u_sun_dir);
    float phase = 0.5 * (giant_hg(mu, u_giant_scatter.y) + giant_hg(mu, -u_giant_scatter.z));
    vec3 lit = u_giant_scatter_color * exp(-u_giant_sigma * across) * sky_sun_light() *
               (u_giant_scatter.x * daylight);
    vec3 body = u_scatter_color * u_scatter_strength * (u_scatter_base + 0.5);
    // What it mirrors: the sky above, and below (the lip's underside faces
    // the face and the trough) the lit water of the face, not the sky.
    float fresnel = optics_schlick(ray, n);
    vec3 r = normalize(reflect(ray, n));
    vec3 below = body + lit * (0.25 / TL_PI);
    vec3 reflection = mix(below, sky_reflected(vec3(r.x, abs(r.y), r.z), sunlit),
                          smoothstep(-0.1, 0.05, r.y));
    vec3 color = fresnel * reflection + (1.0 - fresnel) * (body + lit * phase);
    // Foam: at the tip, more of it as the lip throws; a lace keeps it from
    // being a painted band.
    float along = clamp((angle - lip.from) / max(lip.to - lip.from, 1.0e-3), 0.0, 1.0);
    // Once landed, the lip breaks up into whitewater as it goes: in
    // patches of the lace, more of them as it is spent, never a solid coat
    // (a wholly white tube read as a hose hanging over the broken crest).
    float white = max(smoothstep(0.85, 1.0, along) * (0.15 + 0.65 * lip.progress),
                      0.7 * smoothstep(0.0, 0.8, lip.spent));
    vec2 at = vec2(sw.y, sw.x + hit.y);
    float lace = foam_lace(at * 1.5);
    float foam = smoothstep(1.1 - white, 1.25 - white, lace + 0.2 * white);
    return foam_shade(color, n, foam, lace, max(sunlit, 0.6));
}
