/* tl_render: the headless pipeline in one handle: an EGL context, the
 * renderer, and the wave table of the current ocean. Commands (still,
 * render) and library users call this; it calls prepare and the renderer.
 *
 *     tl_render *r;
 *     tl_render_open(&r, &lib, &err);
 *     tl_render_frame(r, &scene, &frame, &err);   // any number of frames
 *     tl_render_close(r);
 */
#ifndef TL_RENDER_H
#define TL_RENDER_H

#include "core/tl_error.h"
#include "cutscene/tl_cutscene.h"
#include "image/tl_frame.h"
#include "mesh/tl_mesh.h"
#include "scene/tl_scene.h"
#include "shader/tl_shader_lib.h"
#include "timeline/tl_timeline.h"

typedef struct tl_render tl_render;

int tl_render_open(tl_render **out, const tl_shader_lib *lib, tl_error *err);
/* Compiles the shaders again on the next frame (their files changed). */
int tl_render_reload_shaders(tl_render *r, tl_error *err);
/* Renders with the shaders of `lib` from now on (compiled again when they
 * are not the ones in use); on failure the old ones stay. */
int tl_render_use_shaders(tl_render *r, const tl_shader_lib *lib, tl_error *err);
void tl_render_close(tl_render *r);

/* "EGL surfaceless: llvmpipe (...), OpenGL 4.5 (Core Profile) ..." */
const char *tl_render_describe(const tl_render *r);

/* The boat's mesh (the timeline's model or the built-in boat), uploaded
 * once; frames with a boat in view draw it. NULL removes it. */
int tl_render_set_boat(tl_render *r, const tl_mesh *mesh, tl_error *err);
/* The floating objects' meshes (tl_models: object k is drawn with the
 * mesh its tl_boat.model names), replacing any before them. */
int tl_render_set_models(tl_render *r, const tl_models *models, tl_error *err);
/* Uploads what a loaded cutscene references (its floating objects' meshes, or none), so
 * that its frames draw as `tideline still` draws them. */
int tl_render_use_cutscene(tl_render *r, const tl_cutscene *cs, tl_error *err);

/* The display image through a display transform's table (src/color's
 * layout, as src/ocio bakes an OpenColorIO display and view) in place of
 * the ACES fit; NULL goes back to the ACES fit. */
int tl_render_set_display_lut(tl_render *r, const float *rgb, int n, tl_error *err);

/* The shader features (tl_feature bits) of the last frame rendered: the
 * union over its passes. tl_feature_describe turns them into words. */
unsigned tl_render_last_features(const tl_render *r);

/* Progress of long frames: while a frame draws, fn gets the share of its
 * pixel samples drawn so far, rising to 1 (after each of the renderer's
 * ocean draws, each of which it then waits for; tl_renderer_set_progress).
 * For `still`'s progress display; NULL (the default) turns it off. */
typedef void (*tl_render_progress_fn)(void *ctx, double fraction);
void tl_render_set_progress(tl_render *r, tl_render_progress_fn fn, void *ctx);

/* Renders `scene` into `frame`, (re)allocating it to the scene's size. */
int tl_render_frame(tl_render *r, const tl_scene *scene, tl_frame *frame, tl_error *err);
/* The same, reading back `planes` (TL_PLANE_*; with TL_PLANE_AOV the
 * frame gets its aov plane and the passes' data are drawn). */
int tl_render_frame_planes(tl_render *r, const tl_scene *scene, unsigned planes, tl_frame *frame,
                           tl_error *err);
/* The same with the light layers in `layers` (bit k: tl_light_layer k)
 * into the frame's layer planes: each shaded layer is the frame drawn
 * again with that layer's light alone (so each costs about a frame), the
 * glare's a display pass. */
int tl_render_frame_layers(tl_render *r, const tl_scene *scene, unsigned planes, unsigned layers,
                           tl_frame *frame, tl_error *err);

/* The physical sky of a prepared frame, in the order its data flows: the
 * scene's atmosphere into the tables in `luts` (tl_prepare_sky_tables),
 * the sky-view table drawn from them on the GPU (tl_renderer_prepare_sky),
 * and u->sky_ambient from that table (tl_prepare_sky_ambient). Nothing
 * for frames without TL_FEATURE_SKY_PHYSICAL. For code that drives a
 * tl_renderer itself; tl_render's frames call it. */
struct tl_renderer;
struct tl_sky_luts;
struct tl_frame_uniforms;
int tl_render_prepare_sky(struct tl_renderer *renderer, const tl_scene *scene,
                          struct tl_sky_luts *luts, struct tl_frame_uniforms *u, tl_error *err);

/* Auto exposure's meters already taken (tl_exposure.h), kept by a caller
 * that renders many frames of one timeline so that consecutive frames
 * share them: zeroed (tl_meter_cache_reset) before the first frame and
 * whenever the timeline changes. The camera they were taken from is
 * part of the key (a new one resets it). */
#define TL_METER_CACHE 64
typedef struct tl_meter_cache {
    int count, next;
    double time[TL_METER_CACHE];
    double value[TL_METER_CACHE]; /* the meter: mean log2 luminance */
    int has_camera;
    tl_camera camera;
} tl_meter_cache;
void tl_meter_cache_reset(tl_meter_cache *c);

/* How a timeline's frames are rendered; zero fields keep the timeline's. */
typedef struct tl_render_settings {
    int width, height;         /* 0: the timeline's size */
    const tl_quality *quality; /* NULL: the timeline's preset and knobs */
    int spp;                   /* 0: the quality's samples per pixel */
    double shutter_deg;        /* 0: no motion blur; 360 = the whole frame interval */
    int shutter_samples;       /* sub-frames when shutter_deg > 0 (0: 8) */
    const tl_camera *camera;   /* NULL: the timeline's; else this camera (the preview's) */
    unsigned planes;           /* TL_PLANE_* bits to read back (0: all); others keep old data */
    unsigned layers;           /* light layers read back (tl_render_frame_layers); not queued */
    tl_meter_cache *meter;     /* auto exposure's meters to reuse (NULL: none kept) */
} tl_render_settings;

/* Auto exposure: when scene->auto_exposure > 0 (the timeline's at time t),
 * draws the meters the adapted exposure at t is made of (those not in
 * `cache`, which may be NULL) and sets scene->exposure to the metered one
 * (tl_exposure_scale); otherwise leaves the scene alone. The meters use
 * the timeline's camera, or `camera` when not NULL. Call it before a
 * frame's drawing starts: the meters draw through the same targets.
 * tl_render_timeline_frame and its kin call it themselves, with the
 * timeline's camera even where settings->camera replaces it (the
 * preview's free camera keeps the shot's exposure). */
int tl_render_meter_exposure(tl_render *r, const tl_timeline *tl, double t, const tl_camera *camera,
                             tl_meter_cache *cache, tl_scene *scene, tl_error *err);

/* The scene a frame is rendered from: the timeline at frame / fps with the
 * settings applied. */
void tl_render_frame_scene(const tl_timeline *tl, double t, const tl_render_settings *settings,
                           tl_scene *scene);

/* Renders frame `frame` of `tl` (time = frame / fps, from the integer) into
 * `out`. With a shutter, radiance averages `shutter_samples` sub-frames at
 * the times tl_timeline_shutter_times gives; depth comes from the sub-frame
 * nearest the frame's time. `scene_out` (may be NULL) receives the scene
 * at the frame's time. With `out` NULL nothing is read back: the frame
 * stays on the GPU for tl_render_present. */
int tl_render_timeline_frame(tl_render *r, const tl_timeline *tl, long frame,
                             const tl_render_settings *settings, tl_frame *out, tl_scene *scene_out,
                             tl_error *err);

/* tl_render_timeline_frame with its readback left in flight, so that the
 * GPU draws the next frame while this one's planes travel (tideline
 * render): the frame is drawn and its planes queued; tl_render_collect
 * fills `out` (allocated to size) with the oldest queued frame's. At most
 * two frames wait; the frames are tl_render_timeline_frame's. Light
 * layers (settings->layers) are not queued: tl_render_timeline_frame
 * reads them. */
int tl_render_timeline_frame_queue(tl_render *r, const tl_timeline *tl, long frame,
                                   const tl_render_settings *settings, tl_scene *scene_out,
                                   tl_error *err);
int tl_render_collect(tl_render *r, tl_frame *out, tl_error *err);

/* Progressive refinement of frame `frame` (no shutter): its sample
 * `sample` of `samples` stratified ones per pixel is added to the running
 * mean of the samples before it (sample 0 starts it afresh), then shown or
 * read back as tl_render_timeline_frame does. After samples 0..samples-1
 * the frame is the one tl_render_timeline_frame renders with
 * settings->spp = samples. */
int tl_render_timeline_refine(tl_render *r, const tl_timeline *tl, long frame,
                              const tl_render_settings *settings, int sample, int samples,
                              tl_frame *out, tl_error *err);

/* Where the last tl_render_timeline_frame spent its time: preparing and
 * drawing until the GPU finished (render), and reading the planes back. */
void tl_render_last_timing(const tl_render *r, double *render_seconds, double *readback_seconds);

/* The kinds of pass whose time tl_render_pass_seconds reports (the
 * renderer's TL_TIMED_*: boat, prepass, ocean, giant wave, glare, display,
 * filter; tl_render_pass_name names them). */
#define TL_RENDER_PASSES 7
/* Times each pass from the next frame on, fenced with glFinish (off by
 * default; tideline bench --passes). */
void tl_render_time_passes(tl_render *r, int on);
/* The seconds of each kind of pass in the last frame read back; 1 with
 * them, 0 (and zeros) while timing is off. */
int tl_render_pass_seconds(const tl_render *r, double out[TL_RENDER_PASSES]);
const char *tl_render_pass_name(int pass);

#endif
