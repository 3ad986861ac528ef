/* Inside the tl_render handle: shared by tl_render.c (the headless
 * pipeline) and tl_render_window.c (the same pipeline in a desktop window,
 * in its own library so that the headless one does not link GLFW). */
#ifndef TL_RENDER_INTERNAL_H
#define TL_RENDER_INTERNAL_H

#include "gl/tl_renderer.h"
#include "render/tl_render.h"
#include "sky/tl_sky.h"
#include "waves/tl_waves.h"

struct tl_gl_context;

struct tl_render {
    struct tl_gl_context *context; /* headless, or */
    struct tl_gl_window *window;   /* a desktop window (tl_render_window.c) */
    /* The window's own calls, set by the window's opener: the headless
     * library does not link the window system. */
    void (*close_window)(struct tl_gl_window *window);
    const char *(*describe_window)(const struct tl_gl_window *window);
    tl_renderer *renderer;
    tl_waves waves;
    tl_ocean waves_ocean; /* the parameters `waves` was built from */
    int waves_valid;
    unsigned last_features; /* of the last frame, over all its passes */
    tl_sky_luts *sky;       /* the physical sky's tables, rebuilt when they change */
    double render_seconds, readback_seconds; /* of the last timeline frame */
    tl_render_progress_fn progress;          /* tl_render_set_progress */
    void *progress_ctx;
    double progress_done, progress_total; /* pixel samples of the frame being drawn */
    double refine_exposure;               /* the refined frame's, metered at its first sample */
};

/* The renderer on whichever context `open_context` made current; headless
 * and windowed differ only in that step. */
int tl_render_open_with(tl_render **out, const tl_shader_lib *lib, tl_error *err,
                        int (*open_context)(tl_render *r, void *arg, tl_error *err), void *arg);

#endif
