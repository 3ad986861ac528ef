// The ocean: one ray per pixel from the camera, sky above the horizon,
// marched water below. Writes linear radiance and the distance along the
// view ray (TL_SKY_DEPTH where nothing is hit).
#include "uniforms.glsl"
#include "waves.glsl"
#include "sky.glsl"
#include "march.glsl"
#include "water.glsl"

layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_depth;

vec3 camera_ray(vec2 pixel)
{
    vec2 ndc = pixel / u_resolution * 2.0 - 1.0;
    float aspect = u_resolution.x / u_resolution.y;
    vec3 d = u_cam_forward + (ndc.x * aspect * u_tan_half_vfov) * u_cam_right +
             (ndc.y * u_tan_half_vfov) * u_cam_up;
    return normalize(d);
}

void main()
{
    vec3 ray = camera_ray(gl_FragCoord.xy);
    vec3 color;
    float depth = TL_SKY_DEPTH;
    float dist = march_water(ray);
    if (dist < 0.0) {
        color = sky_color(ray);
    } else {
        vec3 hit = vec3(0.0, u_cam_height, 0.0) + ray * dist;
        color = water_color(ray, hit, dist);
        depth = dist;
    }
    // Last guard: no NaN or Inf may reach a pixel.
    if (any(isnan(color)) || any(isinf(color)))
        color = vec3(0.0);
    out_color = vec4(color, 1.0);
    out_depth = depth;
}
