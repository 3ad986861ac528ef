// An object's mesh seen from the sun, into its shadow map: the map's s, t
// and depth (0 to 1) are the clip space's x, y, z halved and shifted.
#include "uniforms.glsl"

layout(location = 0) in vec3 a_position;

uniform mat4 u_boat_model;
uniform mat4 u_boat_shadow;         // the object's (tl_object_uniforms.shadow)
uniform float u_boat_shadow_extent; // the share of its layer in use

void main()
{
    vec3 s = (u_boat_shadow * (u_boat_model * vec4(a_position, 1.0))).xyz;
    // The map's corner in use fills the viewport.
    s.xy /= u_boat_shadow_extent;
    gl_Position = vec4(2.0 * s - 1.0, 1.0);
}
