/* The giant wave's face keeps its small waves far away: the water's
 * normals are blended toward up with distance (a far, grazing view of a
 * level sea averages their detail away), but not on the face, which the
 * view meets nearly head on. Rendered on the GPU (llvmpipe on CI). */
#include <math.h>
#include <stdlib.h>

#include "tl_giant_test.h"

/* The texture of `f` where the wave stands against the sky: the mean
 * absolute difference of the luminance between neighbouring pixels over
 * the mean luminance, over the pixels above the horizon where `f` and
 * their neighbours differ from `bare` (the frame without the wave); the
 * count in *count. Neighbours' differences see the small waves and not the
 * face's gradient from its glowing top to its foot. */
static double texture_on_face(const tl_scene *s, const tl_frame *f, const tl_frame *bare,
                              int *count)
{
    int w = s->width, h = s->height;
    unsigned char *face = calloc((size_t)w * (size_t)h, 1);
    if (!face)
        return -1.0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            double ray[3], l = luminance(f->color + 4 * i), b = luminance(bare->color + 4 * i);
            pixel_ray(s, x, y, ray);
            face[i] = ray[1] > 0.0 && fabs(l - b) > 1e-2 * fmax(b, 1e-3);
        }
    double sum = 0.0, diff = 0.0;
    int n = 0;
    for (int y = 0; y + 1 < h; y++)
        for (int x = 0; x + 1 < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            if (!face[i] || !face[i + 1] || !face[i + (size_t)w])
                continue;
            double l = luminance(f->color + 4 * i);
            diff += fabs(luminance(f->color + 4 * (i + 1)) - l) +
                    fabs(luminance(f->color + 4 * (i + (size_t)w)) - l);
            sum += l;
            n++;
        }
    free(face);
    *count = n;
    return n ? diff / fmax(sum, 1e-9) : 0.0;
}

/* facing_scene (a 20 m wave 120 m away) backlit by a low sun, through a
 * long lens filled by the face: its texture with the default distance
 * blend against with none, the same within 5% (the blend lifted there; it
 * took a seventh of it before). */
static void test_face_keeps_small_waves(tl_renderer *r)
{
    tl_scene s;
    facing_scene(&s);
    s.width = 320;
    s.height = 180;
    s.camera.position[1] = 4.0;
    s.camera.pitch = 0.07;
    s.camera.vfov = 0.12;
    s.sun.azimuth = 0.6; /* behind the wave, low: a backlit face */
    s.sun.elevation = 0.25;
    s.giant.breaking = false;
    tl_scene bare = s, flat = s, bare_flat;
    bare.giant.fade = 0.0;
    flat.water.normal_smooth_max = 0.0;
    bare_flat = flat;
    bare_flat.giant.fade = 0.0;
    tl_frame f[4];
    const tl_scene *scenes[4] = {&s, &bare, &flat, &bare_flat};
    for (int k = 0; k < 4; k++)
        if (render(r, scenes[k], &f[k])) {
            for (int j = 0; j < k; j++)
                tl_frame_free(&f[j]);
            return;
        }
    int faces[2];
    double face = texture_on_face(&s, &f[0], &f[1], &faces[0]);
    double face_sharp = texture_on_face(&s, &f[2], &f[3], &faces[1]);
    printf("face: texture %.4f with the distance blend, %.4f without (%d, %d pixels)\n", face,
           face_sharp, faces[0], faces[1]);
    CHECK(faces[0] > s.width * s.height / 20 && faces[1] > s.width * s.height / 20);
    CHECK(face >= 0.95 * face_sharp);
    for (int k = 0; k < 4; k++)
        tl_frame_free(&f[k]);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_face_keeps_small_waves(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
