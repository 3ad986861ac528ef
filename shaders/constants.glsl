// Constants every program shares: uniforms.glsl includes this file, and
// programs without the frame's uniforms include it themselves.
#define TL_PI 3.1415927
