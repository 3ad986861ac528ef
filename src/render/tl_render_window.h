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
/* Shows the last frame rendered (letterboxed) and swaps the window. */
int tl_render_present(tl_render *r, tl_error *err);

#endif
