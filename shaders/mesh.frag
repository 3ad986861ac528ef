// The boat's hull, lit by the same sun and sky as the water: diffuse from
// the sky's hemisphere and the sun, and a modest specular highlight.
// Writes linear radiance and the distance along the view ray, like the
// ocean, for the ocean pass to composite (shaders/boat.glsl).
#include "uniforms.glsl"
#include "sky.glsl"

in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;

uniform vec3 u_eye; // the camera (the origin), or its mirror image for the reflection
uniform float u_sunlit; // the share of the sun the hull sees past the giant wave's crest

layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_depth;

void main()
{
    vec3 view = normalize(v_world - u_eye); // from the eye
    vec3 n = normalize(v_normal);
    // Two-sided: models may be open or wound either way.
    if (dot(n, view) > 0.0)
        n = -n;
    vec3 sun = sky_sun_light() * u_sunlit;
    float lambert = max(dot(n, u_sun_dir), 0.0);
    // The sky lights what faces up more than what faces down.
    vec3 ambient = sky_ambient() * (0.6 + 0.4 * n.y);
    vec3 diffuse = v_color * (ambient + sun * (lambert / TL_PI));
    vec3 h = normalize(u_sun_dir - view);
    vec3 spec = sun * (pow(max(dot(n, h), 0.0), 48.0) * 0.04 * lambert);
    vec3 color = diffuse + spec;
    if (any(isnan(color)) || any(isinf(color)))
        color = vec3(0.0);
    out_color = vec4(max(color, vec3(0.0)), 1.0);
    out_depth = length(v_world - u_eye);
}
