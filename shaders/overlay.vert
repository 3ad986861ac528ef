// The preview window's overlay (tl_renderer_overlay.c): coloured triangles
// in window pixels, y down, as the builder lays them out.
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec4 a_colour;
uniform vec2 u_window; // pixels
out vec4 v_colour;

void main()
{
    v_colour = a_colour;
    gl_Position = vec4(a_position.x / u_window.x * 2.0 - 1.0, 1.0 - a_position.y / u_window.y * 2.0,
                       0.0, 1.0);
}
