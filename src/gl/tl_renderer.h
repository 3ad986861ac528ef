/* tl_renderer: the only code that calls gl*. It builds a program per
 * feature set (cached), uploads a frame's uniforms, draws the ocean into
 * float targets (linear colour, distance along the ray), runs the display
 * pass (exposure, ACES, sRGB) and reads everything back into a tl_frame.
 *
 * It needs a current OpenGL 3.3 core context and does not care whether it
 * came from EGL (headless) or a window. */
#ifndef TL_RENDERER_H
#define TL_RENDERER_H

#include "core/tl_error.h"
#include "image/tl_frame.h"
#include "mesh/tl_mesh.h"
#include "prepare/tl_prepare.h"
#include "shader/tl_shader_lib.h"

typedef struct tl_renderer tl_renderer;

/* How the display pass turns the scene's radiance into the display image. */
typedef struct tl_display_settings {
    float exposure; /* linear scale before the tonemap */
    float bloom;    /* share of the light spread into glare */
    /* Sigma, in output pixels, of a 3x3 Gaussian over the tonemapped
     * display values (quality.pixel_filter; 0: none), after any upscale. */
    float pixel_filter;
    float white_gain[3]; /* the white balance, per channel, before the exposure */
} tl_display_settings;

/* The display's settings a frame's uniforms carry. */
static inline tl_display_settings tl_display_of(const tl_frame_uniforms *u)
{
    return (tl_display_settings){u->exposure,
                                 u->bloom,
                                 u->pixel_filter,
                                 {u->white_gain[0], u->white_gain[1], u->white_gain[2]}};
}

int tl_renderer_create(tl_renderer **out, const tl_shader_lib *lib, tl_error *err);
void tl_renderer_destroy(tl_renderer *r);

/* Drops every compiled program so the next frame compiles the shader
 * files again (the preview's hot reload); the display program is rebuilt
 * at once and, if it fails, everything is kept as it was. */
int tl_renderer_reload_shaders(tl_renderer *r, tl_error *err);
/* Renders with the shaders of `lib` from now on (the bench's variants
 * with another folder's shaders): reloads them when they are not the ones
 * in use, and draws the sky-view table again. On failure the renderer
 * keeps the shaders it had. */
int tl_renderer_use_shaders(tl_renderer *r, const tl_shader_lib *lib, tl_error *err);

/* For frames with TL_FEATURE_SKY_PHYSICAL, after tl_prepare_sky_tables
 * brought the atmosphere's tables in `luts` up to date: draws the sky-view
 * table for the sun's elevation and the altitude it gave
 * (shaders/sky_view.frag) when either moved or the tables changed, and
 * reads it back into luts->view, where tl_prepare_sky_ambient finds it.
 * The table stays bound to its texture unit, where those frames read it.
 * tl_render_prepare_sky runs the three steps. */
struct tl_sky_luts;
int tl_renderer_prepare_sky(tl_renderer *r, struct tl_sky_luts *luts, double sun_elevation,
                            double altitude, tl_error *err);

/* Uploads the boat's mesh (replacing any before it; NULL removes it). Frames
 * whose uniforms carry TL_FEATURE_BOAT draw it; without a mesh they do not. */
int tl_renderer_set_mesh(tl_renderer *r, const tl_mesh *mesh, tl_error *err);
/* Uploads `count` meshes (up to TL_OBJECT_MAX), replacing any before them:
 * a floating object is drawn with mesh tl_boat.model, the first when that
 * is out of range. */
int tl_renderer_set_meshes(tl_renderer *r, const tl_mesh *meshes, int count, tl_error *err);

/* Renders one frame of u->width x u->height into `frame` (allocated by the
 * caller with the same size). Rows come back top row first. The same as
 * begin + one accumulate (weight 1, with depth) + finish. */
int tl_renderer_render(tl_renderer *r, const tl_frame_uniforms *u, tl_frame *frame, tl_error *err);

/* A frame built from several passes (motion blur sub-frames): begin clears
 * the float target of width x height; each accumulate adds weight x its
 * radiance (weights should sum to 1) and, when write_depth is set, keeps
 * the nearer of its depth and the target's (begin starts it at the sky's); finish runs the display
 * pass at out_width x out_height with `display`'s settings (glare and the pixel filter touch the
 * display plane only, never the colour plane) and reads back the planes asked for. A render smaller
 * than the output (quality.render_scale) is upscaled there: colour and display by Catmull-Rom,
 * distance nearest. */
int tl_renderer_begin(tl_renderer *r, int width, int height, int out_width, int out_height,
                      tl_error *err);
/* Whether a frame drawn at width x height into an output of out_width x
 * out_height (with the passes' data: aov) fits the device: each side
 * within what the driver reports (GL_MAX_TEXTURE_SIZE, the viewport's
 * limit) and its float framebuffers within the device's memory (NVIDIA's
 * count, or the machine's for a CPU renderer). A usage error naming the
 * limit otherwise: refused before any drawing, not after a long wait. */
int tl_renderer_check_size(int width, int height, int out_width, int out_height, int aov,
                           tl_error *err);
/* Whether the frames begun from now on carry the compositing passes' data
 * (the normal, the foam, the covers of the sky, the water, the giant wave
 * and each floating object: tl_frame.h's aov plane), read back with
 * TL_PLANE_AOV. Off by default: it costs six more float targets' writes. */
void tl_renderer_want_aov(tl_renderer *r, int on);
/* The light layer (tl_light_layer, below TL_LIGHT_SHADED) the ocean draws
 * keep from now on, every other source of light left out
 * (shaders/layers.glsl); -1 (the default) keeps them all. */
void tl_renderer_light_layer(tl_renderer *r, int layer);
/* The glare's light layer of the frame drawn last, into frame's colour
 * plane: u_bloom times the glare image, which the display adds to the
 * colour times (1 - bloom); 0 without glare. */
int tl_renderer_finish_glare(tl_renderer *r, const tl_display_settings *display, tl_frame *frame,
                             tl_error *err);
int tl_renderer_accumulate(tl_renderer *r, const tl_frame_uniforms *u, float weight,
                           int write_depth, tl_error *err);
int tl_renderer_finish(tl_renderer *r, const tl_display_settings *display, unsigned planes,
                       tl_frame *frame, tl_error *err);
/* One of u->spp samples per pixel as its own pass, adding weight x its
 * radiance (accumulate with a boat in view: each sample's pass draws the
 * hull shifted by that sample's offset, tl_prepare_boat_sample, so its
 * edges are anti-aliased too). Distances keep the nearest any pass wrote.
 * Samples after 0 start from the march prepass sample 0 ran
 * (quality.march_prepass): a frame's samples come in order, 0 first, with
 * the same uniforms but the boat's. Refinement below likewise. */
int tl_renderer_accumulate_sample(tl_renderer *r, const tl_frame_uniforms *u, float weight,
                                  int write_depth, int sample, tl_error *err);
/* Progress of a long frame (a `reference` still): after each ocean draw
 * the renderer waits for it (glFinish) and calls fn with the pixel
 * samples it drew; `sky_only` for the rows above the horizon, which meet
 * no water and take next to no time (they are drawn first). NULL turns
 * it off (the default: no waits). */
typedef void (*tl_renderer_progress_fn)(void *ctx, double pixel_samples, int sky_only);
void tl_renderer_set_progress(tl_renderer *r, tl_renderer_progress_fn fn, void *ctx);
/* Progressive refinement (the preview, paused): sample `sample` of u->spp
 * alone, into the running mean of the samples before it, so that after
 * samples 0..spp-1 the float target holds what one accumulate of all of
 * them gives. Sample 0 goes into a target begin has just cleared. Then
 * finish or display. */
int tl_renderer_refine(tl_renderer *r, const tl_frame_uniforms *u, int sample, tl_error *err);
/* tl_renderer_finish in two halves, so that the GPU draws the next frame
 * while this one's planes travel (tideline render): finish_begin runs the
 * display pass and queues the planes' transfers; finish_end waits for the
 * oldest queued frame's and copies them into `frame` (of the size
 * tl_renderer_queued_size gives). Up to TL_READBACK_SLOTS frames wait at a
 * time; the frames are the same as tl_renderer_finish's. */
#define TL_READBACK_SLOTS 2
int tl_renderer_finish_begin(tl_renderer *r, const tl_display_settings *display, unsigned planes,
                             tl_error *err);
int tl_renderer_finish_end(tl_renderer *r, tl_frame *frame, tl_error *err);
/* How many frames wait for their readback, and the oldest one's size. */
int tl_renderer_queued_size(const tl_renderer *r, int *width, int *height);
/* The planes the oldest queued frame reads back (0 when none waits). */
unsigned tl_renderer_queued_planes(const tl_renderer *r);
/* Seconds the last tl_renderer_finish spent reading the planes back (after
 * waiting for the GPU to finish drawing), or finish_end waiting for and
 * copying them. */
double tl_renderer_last_readback(const tl_renderer *r);

/* A display transform as a table (src/color/tl_color.h's layout: n^3 RGB
 * over its log2 shaper, as src/ocio bakes an OpenColorIO display and
 * view): the display pass then reads it in place of the ACES fit and the
 * sRGB curve (the table's outputs are the display's code values). NULL
 * goes back to the ACES fit. */
int tl_renderer_set_display_lut(tl_renderer *r, const float *rgb, int n, tl_error *err);

/* The glare image (render.bloom) is this many times smaller than the
 * output on each side (rounded up), read back bilinearly. */
#define TL_GLARE_DIVISOR 4

/* The kinds of pass tl_renderer_pass_seconds reports: the boat's hull and
 * mirror image, the march prepass, the ocean outside and inside the giant
 * wave's rectangle, the glare (its mip levels and its pass), the display
 * pass (tonemap, upscale) and the pixel filter. */
enum {
    TL_TIMED_BOAT,
    TL_TIMED_PREPASS,
    TL_TIMED_OCEAN,
    TL_TIMED_GIANT,
    TL_TIMED_GLARE,
    TL_TIMED_DISPLAY,
    TL_TIMED_FILTER,
    TL_TIMED_COUNT
};
/* Times each pass from the next frame on, fenced with glFinish on both
 * sides (off by default: a GPU idles at the fences; only the bench asks). */
void tl_renderer_time_passes(tl_renderer *r, int on);
/* The seconds each kind of pass took in the last frame that
 * tl_renderer_finish read back, summed over its draws. Returns 1 with
 * them, 0 (and zeros) while timing is off or no frame has finished. */
int tl_renderer_pass_seconds(const tl_renderer *r, double out[TL_TIMED_COUNT]);
const char *tl_renderer_pass_name(int pass);

/* The display pass alone (finish without the readback), then the display
 * image drawn into the current window's framebuffer of width x height,
 * letterboxed: the live preview. */
int tl_renderer_display(tl_renderer *r, const tl_display_settings *display, tl_error *err);
int tl_renderer_present(tl_renderer *r, int width, int height, tl_error *err);
/* tl_renderer_present, then the window's view over it: with `false_colour`
 * the scene's exposure zones in place of the display image (the shader
 * false_colour.frag, tl_color_false_zone), and `overlay_vertices`
 * triangles' vertices (6 floats each: x, y in window pixels from the top
 * left, then RGBA, blended by alpha). Window only: the frame's planes
 * are made before and are not touched. */
int tl_renderer_present_view(tl_renderer *r, int width, int height, int false_colour,
                             const float *overlay, int overlay_vertices, tl_error *err);

/* Evaluates one of the shaders' functions (shaders/probe.frag lists the
 * modes: surface height, Fresnel, water and fog transmittance, the lens's
 * gap to the surface, the sky, the surface's slope for the normal, the giant
 * wave's shadow and its small waves' steepening, the foam's close-up detail) at
 * `count` input pairs, with the frame's uniforms and features; out4 gets
 * four floats per input. The GPU side of the tests. */
#define TL_PROBE_MODE_MAX 32 /* modes run 0 .. this */
int tl_renderer_probe(tl_renderer *r, const tl_frame_uniforms *u, int mode, const float *xy,
                      int count, int octaves, float *out4, tl_error *err);
/* The same with four floats per input (the modes that read more than two:
 * the spray's density at camera-relative (x, z) and height y, as x z y). */
int tl_renderer_probe4(tl_renderer *r, const tl_frame_uniforms *u, int mode, const float *in4,
                       int count, int octaves, float *out4, tl_error *err);

/* Evaluates the shader's wave height at `count` camera-relative points
 * (x, z pairs) with `octaves` octaves: the GPU side of the accuracy tests. */
int tl_renderer_probe_heights(tl_renderer *r, const tl_frame_uniforms *u, const float *xz,
                              int count, int octaves, float *heights, tl_error *err);

#endif
