/* Auto exposure's meters (tl_exposure.h): small frames of the scene's
 * linear light at the grid's times, drawn through the same pipeline with
 * a fixed size and quality, so that a frame's exposure depends on the
 * timeline and its time alone, never on the output's size or preset. */
#include <math.h>
#include <string.h>

#include "metrics/tl_exposure.h"
#include "render/tl_render.h"
#include "render/tl_render_internal.h"

/* The meter's frame: this wide, as tall as the timeline's aspect makes it. */
#define METER_WIDTH 64

void tl_meter_cache_reset(tl_meter_cache *c)
{
    memset(c, 0, sizeof *c);
}

static int cached(const tl_meter_cache *c, double t, double *value)
{
    for (int i = 0; c && i < c->count; i++)
        if (c->time[i] == t) {
            *value = c->value[i];
            return 1;
        }
    return 0;
}

static void remember(tl_meter_cache *c, double t, double value)
{
    if (!c)
        return;
    int slot = c->count < TL_METER_CACHE ? c->count++ : c->next;
    c->next = (slot + 1) % TL_METER_CACHE;
    c->time[slot] = t;
    c->value[slot] = value;
}

/* The meter at time t: the timeline's scene (its camera, or `camera`) in
 * a METER_WIDTH-wide frame at the `preview` preset, one sample a pixel. */
static int meter_at(tl_render *r, const tl_timeline *tl, double t, const tl_camera *camera,
                    tl_frame *frame, double *value, tl_error *err)
{
    tl_scene s;
    tl_timeline_eval(tl, t, &s);
    int rc = tl_quality_preset("preview", &s.quality, err);
    if (rc)
        return rc;
    s.quality.spp = 1;
    s.width = METER_WIDTH;
    s.height = (int)lround(METER_WIDTH * (double)tl->height / (double)tl->width);
    s.height = s.height < 8 ? 8 : s.height > 4 * METER_WIDTH ? 4 * METER_WIDTH : s.height;
    if (camera)
        s.camera = *camera;
    rc = tl_render_frame_planes(r, &s, TL_PLANE_COLOR, frame, err);
    if (!rc)
        *value = tl_exposure_meter(frame->color, frame->width, frame->height);
    return rc;
}

int tl_render_meter_exposure(tl_render *r, const tl_timeline *tl, double t, const tl_camera *camera,
                             tl_meter_cache *cache, tl_scene *scene, tl_error *err)
{
    if (!(scene->auto_exposure > 0.0))
        return TL_OK;
    if (cache && (cache->has_camera != (camera != NULL) ||
                  (camera && memcmp(&cache->camera, camera, sizeof *camera) != 0))) {
        tl_meter_cache_reset(cache); /* metered from another viewpoint */
        cache->has_camera = camera != NULL;
        if (camera)
            cache->camera = *camera;
    }
    double times[TL_EXPOSURE_NODES], weights[TL_EXPOSURE_NODES];
    int n = tl_exposure_nodes(t, scene->adapt_time, times, weights);
    const unsigned features = r->last_features;
    tl_frame frame = {0};
    double adapted = 0.0;
    int rc = TL_OK;
    for (int i = 0; !rc && i < n; i++) {
        double value;
        if (!cached(cache, times[i], &value)) {
            rc = meter_at(r, tl, times[i], camera, &frame, &value, err);
            if (!rc)
                remember(cache, times[i], value);
        }
        adapted += weights[i] * value;
    }
    tl_frame_free(&frame);
    r->last_features = features; /* the frame's, not the meters' */
    if (rc)
        return rc;
    scene->exposure = tl_exposure_scale(scene->exposure, scene->auto_exposure, adapted);
    return TL_OK;
}
