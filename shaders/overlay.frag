// The overlay's colour, blended over the frame by its alpha.
in vec4 v_colour;
layout(location = 0) out vec4 out_colour;

void main()
{
    out_colour = v_colour;
}
