// Frame uniforms shared by every program (filled by tl_prepare on the CPU).
// Their declarations are frame_uniforms.glsl, which no folder holds: the
// shader library writes it from the table in src/prepare/tl_uniform_list.h,
// which the renderer uploads from too. A uniform is added there. Samplers,
// and the uniforms one pass sets outside the frame's upload (u_sample_*,
// u_prepass_scale, u_hint_pixel, u_probe_*, the mesh pass's), are declared
// by the files that use them.
// Nothing here holds an absolute time or an absolute horizontal position:
// x and z are relative to the camera, and per-octave phases are reduced on
// the CPU in double.

#include "constants.glsl"
#include "frame_uniforms.glsl"

// The ocean programs are built with the octave counts as constants: a wave
// loop with a constant bound is unrolled and its per-octave uniforms become
// direct loads. Other programs (the probe) read the uniforms.
#ifndef TL_MARCH_OCTAVES
#define TL_MARCH_OCTAVES u_march_octaves
#endif
#ifndef TL_NORMAL_OCTAVES
#define TL_NORMAL_OCTAVES u_normal_octaves
#endif

#include "objects.glsl"
