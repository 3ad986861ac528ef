/* The headless pipeline drawing into a desktop window (the live
 * preview): only the context differs. Built into the `tideline_window`
 * library, the one that links GLFW. */
#include "render/tl_render_window.h"

#include "gl/tl_gl_window.h"
#include "gl/tl_renderer.h"
#include "render/tl_render_internal.h"

typedef struct window_args {
    int width, height;
    const char *title;
} window_args;

static int open_window(tl_render *r, void *arg, tl_error *err)
{
    const window_args *w = arg;
    r->close_window = tl_gl_window_close;
    r->describe_window = tl_gl_window_describe;
    return tl_gl_window_open(&r->window, w->width, w->height, w->title, err);
}

int tl_render_open_window(tl_render **out, const tl_shader_lib *lib, int width, int height,
                          const char *title, tl_error *err)
{
    window_args w = {width, height, title};
    return tl_render_open_with(out, lib, err, open_window, &w);
}

tl_gl_window *tl_render_window(tl_render *r)
{
    return r->window;
}

int tl_render_present(tl_render *r, const tl_render_view *view, tl_error *err)
{
    int w, h;
    tl_gl_window_size(r->window, &w, &h);
    int rc = view ? tl_renderer_present_view(r->renderer, w, h, view->false_colour, view->overlay,
                                             view->overlay_vertices, err)
                  : tl_renderer_present(r->renderer, w, h, err);
    if (!rc)
        tl_gl_window_swap(r->window);
    return rc;
}
