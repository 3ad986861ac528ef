/* The giant wave's face keeps its small waves far away, and its facets
 * met edge-on are shaded as the footprint sees them: the water's
 * normals are blended toward up with distance (a far, grazing view of a
 * level sea averages their detail away), less on the face, which the view
 * meets nearly head on (TL_GIANT_FACE_SHARP_*). The blend on the GPU
 * (llvmpipe on CI, probe mode 28) against its double mirror, near the
 * origin and 1e4 m out at t = 1e5 s. */
#include <math.h>
#include <stdlib.h>

#include "optics/tl_optics.h"
#include "tl_giant_test.h"

/* Along the wave's centre line from 60 m behind its crest to 60 m in
 * front, and 400 m beside it (off the wave), at distances from 5 m to
 * 400 m: the GPU's blend against the CPU's; off the wave and on its level
 * top the level sea's; on the steepest face the level sea's less
 * TL_GIANT_FACE_SHARP_SHARE of it. */
static void test_blend_probe(tl_renderer *r, double x, double z, double t)
{
    enum { N = 64 };
    centre_line c;
    centre_line_open(&c, x, z, t);
    float in4[4 * N], gpu[4 * N];
    for (int i = 0; i < N; i++) {
        double at = c.crest - 60.0 + 120.0 * i / (N - 2), beside = i == N - 1 ? 400.0 : 0.0;
        centre_line_point(&c.g, c.cam, at, beside, in4 + 4 * i);
        in4[4 * i + 2] = (float)(5.0 + 395.0 * (i % 7) / 6.0);
        in4[4 * i + 3] = 0.0f;
    }
    if (!centre_line_probe4(r, &c, 28, in4, N, gpu))
        return;
    double worst = 0.0, steepest = 0.0, at_steepest = 0.0, off = -1.0;
    for (int i = 0; i < N; i++) {
        tl_giant_sample smp;
        tl_giant_sample_at(&c.g, c.cam[0] + (double)in4[4 * i], c.cam[2] + (double)in4[4 * i + 1],
                           c.s.quality.giant_iterations, &smp);
        double level = tl_optics_normal_blend(&c.s.water, in4[4 * i + 2]);
        double face = tl_giant_face_blend(&smp, level);
        worst = fmax(worst, fmax(fabs(gpu[4 * i] - level), fabs(gpu[4 * i + 1] - face)));
        double slope = hypot(smp.grad[0], smp.grad[1]);
        if (i < N - 1 && slope > steepest) {
            steepest = slope;
            at_steepest = face / level;
        }
        if (i == N - 1)
            off = face / level;
    }
    printf("normal blend at (%g, %g), t = %g: |gpu-cpu| <= %.2e; steepest slope %.2f keeps "
           "%.3f of the level sea's blend; off the wave %.3f\n",
           x, z, t, worst, steepest, at_steepest, off);
    CHECK(worst <= 2e-4); /* the wave's slope in float, through the smoothstep */
    CHECK(steepest > TL_GIANT_FACE_SHARP_TO);
    CHECK(fabs(at_steepest - (1.0 - TL_GIANT_FACE_SHARP_SHARE)) <= 1e-9);
    CHECK(off == 1.0);
}

/* The small waves' facets on the face (TL_GIANT_FACET_GRAZE): the GPU's
 * turned normal against the CPU's, along the centre line and beside the
 * wave, with small-wave slopes up to 3 in every direction, so that some
 * facets face away from the camera or graze. Every facet is met at least
 * at the limit after; one met more squarely than that is unchanged; off
 * the wave the limit is 0 (the sea keeps its own facets). */
static void test_facet_probe(tl_renderer *r, double x, double z, double t)
{
    enum { N = 96 };
    centre_line c;
    centre_line_open(&c, x, z, t);
    float in4[4 * N], gpu[4 * N];
    for (int i = 0; i < N; i++) {
        double at = c.crest - 60.0 + 120.0 * (i % 24) / 23.0, beside = i >= 88 ? 400.0 : 0.0;
        centre_line_point(&c.g, c.cam, at, beside, in4 + 4 * i);
        double angle = 2.399963 * i, size = 3.0 * ((i * 7) % 11) / 10.0;
        in4[4 * i + 2] = (float)(size * cos(angle));
        in4[4 * i + 3] = (float)(size * sin(angle));
    }
    if (!centre_line_probe4(r, &c, 29, in4, N, gpu))
        return;
    double worst = 0.0, least_after = 1.0, off_limit = 0.0;
    int turned = 0, kept = 0;
    for (int i = 0; i < N; i++) {
        double px = c.cam[0] + (double)in4[4 * i], pz = c.cam[2] + (double)in4[4 * i + 1];
        tl_giant_sample smp;
        tl_giant_sample_at(&c.g, px, pz, c.s.quality.giant_iterations, &smp);
        double slope[2] = {smp.grad[0] + in4[4 * i + 2], smp.grad[1] + in4[4 * i + 3]};
        double len = sqrt(slope[0] * slope[0] + 1.0 + slope[1] * slope[1]);
        double n[3] = {-slope[0] / len, 1.0 / len, -slope[1] / len};
        double ray[3] = {in4[4 * i], smp.height - c.cam[1], in4[4 * i + 1]};
        double ray_len = sqrt(ray[0] * ray[0] + ray[1] * ray[1] + ray[2] * ray[2]);
        for (int k = 0; k < 3; k++)
            ray[k] /= ray_len;
        double out[3];
        tl_giant_facet_seen(n, ray, smp.grad, out);
        for (int k = 0; k < 3; k++)
            worst = fmax(worst, fabs(gpu[4 * i + k] - out[k]));
        double wave_len = sqrt(smp.grad[0] * smp.grad[0] + 1.0 + smp.grad[1] * smp.grad[1]);
        double wave_seen = -(-smp.grad[0] * ray[0] + ray[1] - smp.grad[1] * ray[2]) / wave_len;
        double face = hypot(smp.grad[0], smp.grad[1]);
        face = fmin(fmax((face - TL_GIANT_FACE_SHARP_FROM) /
                             (TL_GIANT_FACE_SHARP_TO - TL_GIANT_FACE_SHARP_FROM),
                         0.0),
                    1.0);
        double limit =
            TL_GIANT_FACET_GRAZE * fmax(wave_seen, 0.0) * face * face * (3.0 - 2.0 * face);
        double seen = -(n[0] * ray[0] + n[1] * ray[1] + n[2] * ray[2]);
        double after = -(out[0] * ray[0] + out[1] * ray[1] + out[2] * ray[2]);
        if (seen < limit) {
            turned++;
            least_after = fmin(least_after, after - limit);
        } else {
            kept++;
            CHECK(out[0] == n[0] && out[1] == n[1] && out[2] == n[2]);
        }
        if (i >= 88)
            off_limit = fmax(off_limit, limit);
    }
    printf("facets at (%g, %g), t = %g: |gpu-cpu| <= %.2e; %d turned (met at least %.3f past "
           "the limit after), %d kept; off the wave the limit is %g\n",
           x, z, t, worst, turned, least_after, kept, off_limit);
    CHECK(worst <= 2e-4);
    CHECK(turned >= 10 && kept >= 10);
    CHECK(least_after >= -0.02); /* turning by the difference, then normalising */
    CHECK(off_limit == 0.0);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_blend_probe(r, 0.0, 0.0, 10.0);
    test_blend_probe(r, 1e4, -7e3, 1e5);
    test_facet_probe(r, 0.0, 0.0, 10.0);
    test_facet_probe(r, 1e4, -7e3, 1e5);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
