// The boat's mesh: model -> camera-relative world -> clip. The world
// position and normal go to the fragment shader for lighting and the
// distance along the view ray. The reflection pass draws the same mesh
// through u_mirror (a reflection about the water plane y = u_clip_height)
// from the mirrored eye, clipped to what stands above the water.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in vec4 a_surface; // roughness, metallic, occlusion, emission
#ifdef TL_MESH_MAPS
layout(location = 4) in vec2 a_uv;
layout(location = 5) in vec4 a_tangent; // xyz, and w: the bitangent's side of n x t
#endif

uniform mat4 u_view_proj;
uniform mat4 u_boat_model;
uniform mat4 u_mirror;       // identity, or the reflection about the water plane
uniform float u_clip_height; // camera-relative y of the water plane (reflection pass)
uniform float u_clip_sign;   // 1 keeps what stands above it, -1 what lies below

out vec3 v_world; // camera-relative metres, before any mirror
out vec3 v_normal;
out vec3 v_color;
out vec4 v_surface;
out vec2 v_wet; // metres above the design waterline, and along the hull (the streaks)
#ifdef TL_MESH_MAPS
out vec2 v_uv;
out vec4 v_tangent;
#endif

void main()
{
    vec4 world = u_boat_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    // Uniform scale: the model matrix's rotation turns normals too.
    v_normal = mat3(u_boat_model) * a_normal;
    v_color = a_color;
    v_surface = a_surface;
#ifdef TL_MESH_MAPS
    v_uv = a_uv;
    v_tangent = vec4(mat3(u_boat_model) * a_tangent.xyz, a_tangent.w);
#endif
    float scale = length(u_boat_model[0].xyz);
    v_wet = vec2(a_position.y, a_position.z + 0.7 * a_position.x) * scale;
    gl_ClipDistance[0] = u_clip_sign * (world.y - u_clip_height);
    gl_Position = u_view_proj * (u_mirror * world);
}
