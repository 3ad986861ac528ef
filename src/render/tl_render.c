#include "tl_render.h"

#include <stdlib.h>
#include <string.h>

#include "gl/tl_gl_context.h"
#include "gl/tl_renderer.h"
#include "prepare/tl_prepare.h"
#include "waves/tl_waves.h"

struct tl_render {
    tl_gl_context *context;
    tl_renderer *renderer;
    tl_waves waves;
    tl_ocean waves_ocean; /* the parameters `waves` was built from */
    int waves_valid;
};

int tl_render_open(tl_render **out, const tl_shader_lib *lib, tl_error *err)
{
    *out = NULL;
    tl_render *r = calloc(1, sizeof *r);
    if (!r)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    int rc = tl_gl_context_create_headless(&r->context, err);
    if (!rc)
        rc = tl_renderer_create(&r->renderer, lib, err);
    if (rc) {
        tl_render_close(r);
        return rc;
    }
    *out = r;
    return TL_OK;
}

void tl_render_close(tl_render *r)
{
    if (!r)
        return;
    tl_renderer_destroy(r->renderer);
    tl_gl_context_destroy(r->context);
    free(r);
}

const char *tl_render_describe(const tl_render *r)
{
    return tl_gl_context_describe(r->context);
}

int tl_render_frame(tl_render *r, const tl_scene *scene, tl_frame *frame, tl_error *err)
{
    int rc = tl_scene_validate(scene, err);
    if (rc)
        return rc;
    /* The octave table depends only on the ocean parameters: rebuild it
     * when they change (keyed ocean channels), not every frame. */
    if (!r->waves_valid || memcmp(&r->waves_ocean, &scene->ocean, sizeof scene->ocean) != 0) {
        tl_waves_init(&r->waves, &scene->ocean);
        r->waves_ocean = scene->ocean;
        r->waves_valid = 1;
    }
    if (frame->width != scene->width || frame->height != scene->height) {
        tl_frame_free(frame);
        rc = tl_frame_alloc(frame, scene->width, scene->height, err);
        if (rc)
            return rc;
    }
    tl_frame_uniforms u;
    tl_prepare_frame(scene, &r->waves, &u);
    return tl_renderer_render(r->renderer, &u, frame, err);
}
