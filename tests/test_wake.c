/* The boat's wake's foam (shaders/wake.glsl), probed on the GPU (probe mode
 * 9) behind a boat that ran straight: fresh foam behind the stern is mostly
 * white but open in places, and thicker inside its patches than at their
 * edges; old foam lies in streaks drawn out along the path; bubbles lie
 * under all of it; outside the wedge there is nothing. */
#include <string.h>

#include "tl_gl_test.h"

enum { NX = 48, NB = 120 };

/* A boat that has run straight along +z at 6 m/s to the origin; the camera
 * 20 m above the path looks down the wake. */
static void straight_wake(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 160;
    s->height = 90;
    s->boat.enabled = true;
    s->boat.heading = 0.0;
    const double speed = 6.0;
    s->boat.wake_step = 2.0 * s->boat.wake_time / (TL_WAKE_POINTS - 1);
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        s->boat.wake_path[k][0] = 0.0;
        s->boat.wake_path[k][1] = -speed * s->boat.wake_step * k;
        s->boat.wake_along[k] = 500.0 - speed * s->boat.wake_step * k;
    }
    s->camera.position[0] = 5.0;
    s->camera.position[1] = 20.0;
    s->camera.position[2] = -10.0;
    const double target[3] = {0.0, 0.0, -40.0};
    tl_scene_camera_look_at(&s->camera, target, NULL);
}

/* Foam, thickness and bubbles on an NX x NB grid: x across the path from x0
 * by dx, metres behind the boat from b0 by db. 0 when probed. */
static int probe_grid(tl_renderer *r, const tl_scene *s, const tl_frame_uniforms *u, double x0,
                      double dx, double b0, double db, float out[NB][NX][4])
{
    static float xz[NB * NX * 2];
    for (int j = 0; j < NB; j++)
        for (int i = 0; i < NX; i++) {
            xz[(j * NX + i) * 2 + 0] = (float)(x0 + dx * i - s->camera.position[0]);
            xz[(j * NX + i) * 2 + 1] = (float)(-(b0 + db * j) - s->camera.position[2]);
        }
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_renderer_probe(r, u, 9, xz, NB * NX, 1, &out[0][0][0], &err);
    if (rc)
        fprintf(stderr, "probe: %s\n", err.message);
    return rc;
}

/* Of the grid's foam cells (foam > 0.5), the share whose neighbour `di`
 * across and `dj` along is foam too. */
static double foam_kept(float g[NB][NX][4], int di, int dj)
{
    long foam = 0, both = 0;
    for (int j = 0; j + dj < NB; j++)
        for (int i = 0; i + di < NX; i++)
            if (g[j][i][0] > 0.5f) {
                foam++;
                both += g[j + dj][i + di][0] > 0.5f;
            }
    return foam ? (double)both / (double)foam : 0.0;
}

static float grid[NB][NX][4];

/* Right behind the stern (3 to 9 m, the middle of the band): white over
 * half the water or more, never a solid sheet, and the foam thicker inside
 * its patches than at their edges (a threshold that saturated drew flat
 * sheets with hard outlines there: 0.41 thick at their edges, 0.44
 * inside). */
static void test_fresh(tl_renderer *r, const tl_scene *s, const tl_frame_uniforms *u)
{
    const double half_beam = u->wake_params[0];
    if (probe_grid(r, s, u, -0.5 * half_beam, half_beam / NX, 3.0, 6.0 / NB, grid)) {
        CHECK(0);
        return;
    }
    long n = 0, foam = 0, edge = 0, inner = 0;
    double aerated = 0.0, thick_edge = 0.0, thick_inner = 0.0;
    for (int j = 1; j + 1 < NB; j++)
        for (int i = 1; i + 1 < NX; i++) {
            const float *c = grid[j][i];
            n++;
            aerated += c[2];
            if (c[0] <= 0.5f)
                continue;
            foam++;
            /* Next to open water (within one cell), or inside a patch. */
            bool open = grid[j - 1][i][0] <= 0.5f || grid[j + 1][i][0] <= 0.5f ||
                        grid[j][i - 1][0] <= 0.5f || grid[j][i + 1][0] <= 0.5f;
            if (open) {
                edge++;
                thick_edge += c[1];
            } else {
                inner++;
                thick_inner += c[1];
            }
        }
    double share = (double)foam / (double)n;
    printf("fresh wake: %.3f of the water foam, thickness %.3f at patches' edges, %.3f inside; "
           "bubbles %.3f\n",
           share, edge ? thick_edge / edge : 0.0, inner ? thick_inner / inner : 0.0, aerated / n);
    CHECK(share > 0.45);
    CHECK(share < 0.95);
    CHECK(edge > 0 && inner > 0);
    if (edge > 0 && inner > 0)
        CHECK(thick_inner / inner > thick_edge / edge + 0.15);
    CHECK(aerated / n > 0.3);
}

/* 20 to 44 m behind (3 to 7 s old, the foam's e-fold 6 s): thinner, in
 * streaks drawn out along the path: foam a metre further along is foam
 * more often than foam a metre across. */
static void test_old(tl_renderer *r, const tl_scene *s, const tl_frame_uniforms *u)
{
    const double half_beam = u->wake_params[0];
    const double dx = 2.0 * half_beam / NX, db = 24.0 / NB, b0 = 20.0;
    if (probe_grid(r, s, u, -half_beam, dx, b0, db, grid)) {
        CHECK(0);
        return;
    }
    long foam = 0;
    for (int j = 0; j < NB; j++)
        for (int i = 0; i < NX; i++)
            foam += grid[j][i][0] > 0.5f;
    double share = (double)foam / (NB * NX);
    double along = foam_kept(grid, 0, (int)lround(1.0 / db));
    double across = foam_kept(grid, (int)lround(1.0 / dx), 0);
    printf("old wake: %.3f of the water foam; foam 1 m on is foam %.2f along, %.2f across\n", share,
           along, across);
    CHECK(share > 0.01 && share < 0.4);
    CHECK(along > across + 0.1);
}

/* Beside the wedge (its arm about 0.35 of the distance behind, out from
 * the half beam) the function returns zeros without computing the foam. */
static void test_outside(tl_renderer *r, const tl_scene *s, const tl_frame_uniforms *u)
{
    if (probe_grid(r, s, u, 30.0, 0.5, 3.0, 0.1, grid)) {
        CHECK(0);
        return;
    }
    long lit = 0;
    for (int j = 0; j < NB; j++)
        for (int i = 0; i < NX; i++)
            lit += grid[j][i][0] != 0.0f || grid[j][i][1] != 0.0f || grid[j][i][2] != 0.0f;
    printf("beside the wake: %ld of %d points with foam, thickness or bubbles\n", lit, NB * NX);
    CHECK(lit == 0);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    tl_scene s;
    straight_wake(&s);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_WAKE);
    if (u.features & TL_FEATURE_WAKE) {
        test_fresh(r, &s, &u);
        test_old(r, &s, &u);
        test_outside(r, &s, &u);
    }
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
