/* The hit polish (quality.polish, surface_polish in shaders/surface.glsl):
 * the march finds where a ray crosses the surface of march_octaves
 * octaves; the polish steps the hit onto the finer surface of
 * normal_octaves, where the normal is evaluated. Checked against the CPU's
 * double-precision surface, from above the open sea, facing the giant wave
 * and from under the water. */
#include "tl_gl_test.h"

#include <stdio.h>

/* The sea from 3 m up, looking down a little, over the full-detail surface
 * the CPU computes (level of detail off), the march's octaves well below
 * the normals'. */
static void sea_scene(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 128;
    s->height = 72;
    s->time = 3.0;
    s->camera.position[1] = 3.0;
    s->camera.pitch = -12.0 * M_PI / 180.0;
    s->quality.lod = false;
    s->quality.march_octaves = 8;
    s->quality.normal_octaves = 26;
}

/* The same sea with the giant wave rising 60 m ahead, facing the camera. */
static void wave_scene(tl_scene *s)
{
    sea_scene(s);
    s->camera.position[2] = -60.0;
    s->camera.pitch = -4.0 * M_PI / 180.0;
    s->giant.enabled = true;
    s->giant.height = 12.0;
    s->giant.wavelength = 90.0;
    s->giant.width = 260.0;
    s->giant.angle = M_PI;
    s->giant.arrival = 3.0; /* its crest on the world origin at t = 3 */
}

/* The underside, from 2 m down, looking up. */
static void under_scene(tl_scene *s)
{
    sea_scene(s);
    s->camera.position[1] = -2.0;
    s->camera.pitch = 35.0 * M_PI / 180.0;
}

typedef struct residual {
    int hits;     /* water pixels within 150 m (in the frame that picks them) */
    double mean;  /* mean |y - surface(x, z)| of their hits, metres */
    double worst; /* the largest */
} residual;

/* How far the hits in `f` lie off the CPU's surface of `octaves` octaves,
 * over the pixels `pick` has water within 150 m at (the same pixels for
 * two frames: the polish may move a hit across the 150 m line). */
static residual hits_off_surface(const tl_scene *s, const tl_frame *f, const tl_frame *pick,
                                 int octaves)
{
    tl_waves waves;
    tl_waves_init(&waves, &s->ocean);
    tl_giant giant;
    tl_giant_prepare(&giant, &s->giant, s->time);
    residual r = {0, 0.0, 0.0};
    for (int y = 0; y < s->height; y++)
        for (int x = 0; x < s->width; x++) {
            double d = f->depth[(size_t)y * s->width + x];
            if (pick->depth[(size_t)y * s->width + x] > 150.0)
                continue; /* sky, the depths, and grazing far water */
            double ray[3], p[3];
            pixel_ray(s, x, y, ray);
            for (int i = 0; i < 3; i++)
                p[i] = s->camera.position[i] + ray[i] * d;
            double e = fabs(p[1] - tl_waves_surface_height(&waves, &giant, p[0], p[2], s->time,
                                                           octaves, s->quality.giant_iterations));
            r.mean += e;
            r.worst = fmax(r.worst, e);
            r.hits++;
        }
    if (r.hits > 0)
        r.mean /= r.hits;
    return r;
}

/* With the polish the hits lie on the normals' surface, at most `share` of
 * the march's hits' distance from it on average; the polish moves no hit
 * by more than 1% of its distance and turns no pixel from water to sky or
 * back. */
static void check_polish(tl_renderer *r, tl_scene *s, const char *label, double share)
{
    tl_frame plain, polished;
    s->quality.polish = false;
    if (render(r, s, &plain))
        return;
    s->quality.polish = true;
    if (render(r, s, &polished)) {
        tl_frame_free(&plain);
        return;
    }
    int normal = s->quality.normal_octaves, march = s->quality.march_octaves;
    residual before = hits_off_surface(s, &plain, &plain, normal);
    residual after = hits_off_surface(s, &polished, &plain, normal);
    residual marched = hits_off_surface(s, &plain, &plain, march);
    int side = 0, far = 0;
    size_t n = (size_t)s->width * s->height;
    for (size_t i = 0; i < n; i++) {
        double a = plain.depth[i], b = polished.depth[i];
        side += (a >= TL_FRAME_SKY_DEPTH) != (b >= TL_FRAME_SKY_DEPTH);
        if (a < TL_FRAME_SKY_DEPTH)
            far += fabs(b - a) > 0.0101 * a + 1e-4;
    }
    printf("%s: %d hits off the %d-octave surface by %.4f m on average (worst %.3f) marched "
           "(%.4f m off the %d octaves marched), %.4f m (worst %.3f) polished; %d moved more "
           "than 1%%, %d changed between water and sky\n",
           label, before.hits, normal, before.mean, before.worst, marched.mean, march, after.mean,
           after.worst, far, side);
    CHECK(before.hits > (int)n / 4);
    /* The march itself lands on its own surface, to its hit epsilon. */
    CHECK(marched.mean < 2.0 * s->quality.hit_epsilon);
    /* Without the polish the shading is centimetres off; with it, closer. */
    CHECK(before.mean > 0.01);
    CHECK(after.mean < share * before.mean);
    CHECK(far == 0);
    CHECK(side == 0);
    tl_frame_free(&plain);
    tl_frame_free(&polished);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    tl_scene s;
    sea_scene(&s);
    /* From above (measured: 0.18 and 0.04 of the march's distance). */
    check_polish(r, &s, "open sea", 0.3);
    wave_scene(&s);
    check_polish(r, &s, "giant wave", 0.3);
    /* From below the march stops further off its own surface (its steps,
     * the depth under the surface, can overshoot a sloping one: 5 mm on
     * average against 1-2 from above), and one step from there closes
     * less of the gap (measured: 0.43). */
    under_scene(&s);
    check_polish(r, &s, "under water", 0.6);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
