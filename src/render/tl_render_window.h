/* tl_render_window: the headless pipeline (tl_render) drawing into a
 * desktop window (GLFW), for the live preview. Its own library,
 * `tideline_window`, links the window system; tl_render_close closes the
 * window too. */
#ifndef TL_RENDER_WINDOW_H
#define TL_RENDER_WINDOW_H

#include "render/tl_render.h"

/* The same pipeline drawing into a desktop window (GLFW) of the given size:
 * the live preview. */
struct tl_gl_window;
int tl_render_open_window(tl_render **out, const tl_shader_lib *lib, int width, int height,
                          const char *title, tl_error *err);
struct tl_gl_window *tl_render_window(tl_render *r);
/* What the window shows over the frame (never part of a frame read back):
 * the false colour in place of the display image, and an overlay of
 * triangles (`vertices` of 6 floats: x, y in window pixels from the top
 * left, RGBA; blended by alpha). Zero: the frame alone. */
typedef struct tl_render_view {
    int false_colour;
    const float *overlay;
    int overlay_vertices;
} tl_render_view;

/* Shows the last frame rendered (letterboxed) with `view` (may be NULL)
 * and swaps the window. */
int tl_render_present(tl_render *r, const tl_render_view *view, tl_error *err);

#endif
