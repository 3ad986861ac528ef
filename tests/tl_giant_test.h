/* Scenes the giant wave's GPU tests share (test_giant_render.c,
 * test_giant_light.c). Header-only. */
#ifndef TL_GIANT_TEST_H
#define TL_GIANT_TEST_H

#include <string.h>

#include "tl_gl_test.h"

/* A wave of `height` whose crest is a few metres past its centre, 25 m in
 * front of and 10 m beside the camera at `cam`, at time t. */
static inline void wave_scene(tl_scene *s, double height, double t, const double cam[3])
{
    tl_scene_defaults(s);
    s->time = t;
    memcpy(s->camera.position, cam, sizeof s->camera.position);
    s->giant.enabled = true;
    s->giant.height = height;
    s->giant.center[0] = cam[0] + 10.0;
    s->giant.center[1] = cam[2] + 25.0;
    s->giant.arrival = t - 1.0; /* the crest is a few metres past the centre */
    s->giant.angle = 0.3;
}

/* A 20 m wave at full strength (wave_scene), prepared, seen from 6 m up
 * at (x, z): its ocean, the wave in double, the frame's uniforms and
 * where its crest lies along its travel (the probes along its centre
 * line: test_giant_light, test_giant_face). */
typedef struct centre_line {
    double cam[3];
    tl_scene s;
    tl_waves w;
    tl_giant g;
    tl_frame_uniforms u;
    double crest; /* metres along the travel from the wave's origin */
} centre_line;

static inline void centre_line_open(centre_line *c, double x, double z, double t)
{
    c->cam[0] = x;
    c->cam[1] = 6.0;
    c->cam[2] = z;
    wave_scene(&c->s, 20.0, t, c->cam);
    c->s.giant.fade = 1.0;
    tl_waves_init(&c->w, &c->s.ocean);
    tl_giant_prepare(&c->g, &c->s.giant, c->s.time);
    tl_prepare_frame(&c->s, &c->w, &c->u);
    c->crest = c->g.fade * c->g.curl / c->g.k;
}

/* Probe mode `mode` at n points for c's frame; false (and a failed check)
 * where the probe fails. */
static inline bool centre_line_probe4(tl_renderer *r, const centre_line *c, int mode,
                                      const float *in4, int n, float *out)
{
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe4(r, &c->u, mode, in4, n, c->s.quality.march_octaves, out, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return false;
    }
    return true;
}

/* The camera-relative (x, z) of the point `at` metres along the wave's
 * travel from its origin and `beside` metres across it. */
static inline void centre_line_point(const tl_giant *g, const double cam[3], double at,
                                     double beside, float xz[2])
{
    xz[0] = (float)(g->origin[0] + g->dir[0] * at + g->across[0] * beside - cam[0]);
    xz[1] = (float)(g->origin[1] + g->dir[1] * at + g->across[1] * beside - cam[2]);
}

/* A camera 120 m in front of a 20 m wave that travels toward it. */
static inline void facing_scene(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 160;
    s->height = 96;
    s->time = 7.0;
    s->camera.position[0] = 0.0;
    s->camera.position[1] = 4.0;
    s->camera.position[2] = -120.0;
    s->camera.yaw = 0.0;
    s->camera.pitch = 0.0;
    s->sun.azimuth = M_PI; /* behind the camera */
    s->sun.elevation = 0.4;
    s->giant.enabled = true;
    s->giant.height = 20.0;
    s->giant.wavelength = 90.0;
    s->giant.width = 260.0;
    s->giant.angle = M_PI;  /* toward the camera */
    s->giant.arrival = 7.0; /* crest on the centre, the world origin */
}

#endif
