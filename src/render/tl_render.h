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
#include "image/tl_frame.h"
#include "scene/tl_scene.h"
#include "shader/tl_shader_lib.h"

typedef struct tl_render tl_render;

int tl_render_open(tl_render **out, const tl_shader_lib *lib, tl_error *err);
void tl_render_close(tl_render *r);

/* "EGL surfaceless: llvmpipe (...), OpenGL 4.5 (Core Profile) ..." */
const char *tl_render_describe(const tl_render *r);

/* Renders `scene` into `frame`, (re)allocating it to the scene's size. */
int tl_render_frame(tl_render *r, const tl_scene *scene, tl_frame *frame, tl_error *err);

#endif
