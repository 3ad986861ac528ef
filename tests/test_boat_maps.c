/* A model's texture maps on the GPU (llvmpipe on CI), from glTF files the
 * test writes (tl_gltf_test.h): the normal map's formula against its CPU
 * mirror; a checker base colour drawn with its sRGB values, the right way
 * up; a normal map that lights a flat quad as the same quad turned; the
 * metallic-roughness, occlusion and emissive maps by what they scale. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mesh/tl_mesh.h"
#include "tl_gl_test.h"
#include "tl_gltf_test.h"

static char dir[] = "/tmp/tideline-maps-XXXXXX";

static double srgb_to_linear(unsigned char v)
{
    double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

/* A quad of plain white paint with no maps: the factors alone. */
static gltf_quad plain_quad(void)
{
    gltf_quad q = {0};
    q.base_color[0] = q.base_color[1] = q.base_color[2] = 1.0;
    q.roughness = 0.6;
    q.normal_scale = 1.0;
    q.occlusion_strength = 1.0;
    return q;
}

/* Writes q as a .glb and loads it: 0 on success. */
static int load_quad(const gltf_quad *q, tl_mesh *m)
{
    char path[256];
    snprintf(path, sizeof path, "%s/quad.glb", dir);
    tl_error err;
    tl_error_clear(&err);
    int rc = gltf_write_quad(path, q) || tl_mesh_load(path, m, &err);
    if (rc)
        fprintf(stderr, "quad: %s\n", err.message);
    CHECK(rc == 0);
    unlink(path);
    return rc;
}

/* The quad 1 m per unit at the origin, its face toward a camera 5 m off
 * along +z; the sun 30 degrees up from azimuth `sun_azimuth`. */
static void quad_scene(tl_scene *s, const tl_mesh *m, double sun_azimuth)
{
    tl_scene_defaults(s);
    s->width = 200;
    s->height = 150;
    s->time = 3.0;
    /* A texel's value at a pixel's centre: one sample a pixel (2 x 2
     * blends the checker's squares along their edges). */
    s->quality.mesh_scale = 1;
    s->boat.enabled = true;
    s->boat.scale = 1.0;
    s->boat.size = 2.0;
    s->boat.length = 2.0;
    s->boat.beam = 2.0;
    s->boat.wake = 0.0;
    s->boat.heading = 0.0;
    s->boat.position[1] = 0.0;
    for (int i = 0; i < 3; i++) {
        s->boat.model_min[i] = m->bounds_min[i];
        s->boat.model_max[i] = m->bounds_max[i];
    }
    s->sun.elevation = 30.0 * M_PI / 180.0;
    s->sun.azimuth = sun_azimuth;
    s->camera.position[0] = 0.0;
    s->camera.position[1] = 2.0;
    s->camera.position[2] = 5.0;
    const double target[3] = {0.0, 2.0, 0.0};
    tl_scene_camera_look_at(&s->camera, target, NULL);
}

/* Renders model m in the quad's scene (its lamps lit by `lights`). */
static int render_quad(tl_renderer *r, const tl_mesh *m, double sun_azimuth, double lights,
                       tl_frame *f)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    quad_scene(&s, m, sun_azimuth);
    s.boat.lights = lights;
    return render(r, &s, f);
}

/* The pixel rectangle (x0 y0 x1 y1, top row first) where the frame with
 * the quad differs from one without it. */
static void quad_rect(const tl_frame *a, const tl_frame *b, int rect[4])
{
    rect[0] = a->width, rect[1] = a->height, rect[2] = -1, rect[3] = -1;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            const float *p = a->color + ((size_t)y * a->width + x) * 4;
            const float *q = b->color + ((size_t)y * b->width + x) * 4;
            if (fabs(luminance(p) - luminance(q)) < 1e-3)
                continue;
            rect[0] = x < rect[0] ? x : rect[0];
            rect[1] = y < rect[1] ? y : rect[1];
            rect[2] = x > rect[2] ? x : rect[2];
            rect[3] = y > rect[3] ? y : rect[3];
        }
}

/* Mean luminance over the box of half size h around (x, y). */
static double mean_at(const tl_frame *f, int x, int y, int h)
{
    double sum = 0.0;
    int n = 0;
    for (int j = y - h; j <= y + h; j++)
        for (int i = x - h; i <= x + h; i++) {
            sum += luminance(f->color + ((size_t)j * f->width + i) * 4);
            n++;
        }
    return sum / n;
}

static void test_normal_map_probe(tl_renderer *r)
{
    enum { N = 48 };
    tl_scene s;
    tl_scene_defaults(&s);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    float in[N * 4], out[N * 4];
    srand(11);
    for (int i = 0; i < N; i++) {
        for (int c = 0; c < 3; c++)
            in[4 * i + c] = (float)rand() / RAND_MAX;
        in[4 * i + 2] = 0.5f + 0.5f * in[4 * i + 2]; /* facing out of the surface */
        float scale = (float)(0.1 + 1.9 * rand() / RAND_MAX);
        in[4 * i + 3] = i % 2 ? -scale : scale;
    }
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe4(r, &u, 17, in, N, u.octaves, out, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    const double l = sqrt(0.3 * 0.3 + 0.9 * 0.9 + 0.2 * 0.2);
    const double n[3] = {0.3 / l, 0.9 / l, -0.2 / l};
    double worst = 0.0;
    for (int i = 0; i < N; i++) {
        const double t[4] = {1.0, 0.0, 0.4, in[4 * i + 3] < 0.0f ? -1.0 : 1.0};
        const double texel[3] = {in[4 * i], in[4 * i + 1], in[4 * i + 2]};
        double want[3];
        tl_mesh_normal_map(n, t, texel, fabs(in[4 * i + 3]), want);
        for (int c = 0; c < 3; c++)
            worst = fmax(worst, fabs(out[4 * i + c] - want[c]));
    }
    printf("normal map, GPU against CPU over %d texels: %.2g\n", N, worst);
    CHECK(worst < 1e-5);
}

/* A 2 x 2 checker of sRGB 230 and 40 as the base colour over a white
 * factor. Lighting is linear in the base colour, so a frame with a black
 * map (k) and one with a white map (w) give each pixel's share:
 * (checker - k) / (w - k) is the texel's linear value. The top left
 * square is light, as the image has it. */
static void test_checker(tl_renderer *r)
{
    enum { SIZE = 64 };
    unsigned char *checker = gltf_checker(SIZE, 230, 40), *white = gltf_solid(SIZE, 255, 255, 255),
                  *black = gltf_solid(SIZE, 0, 0, 0);
    const unsigned char *maps[3] = {checker, white, black};
    tl_frame f[3], none;
    int ok = 1;
    for (int i = 0; i < 3; i++) {
        gltf_quad q = plain_quad();
        q.map[TL_MESH_MAP_BASE_COLOR] = (gltf_map){SIZE, SIZE, maps[i], 0};
        tl_mesh m;
        ok &= load_quad(&q, &m) == 0 && tl_mesh_has_maps(&m);
        if (ok)
            ok &= render_quad(r, &m, 0.3, 0.0, &f[i]) == 0;
        tl_mesh_free(&m);
    }
    free(checker);
    free(white);
    free(black);
    if (!ok)
        return;
    tl_scene empty;
    tl_mesh unused = {0};
    quad_scene(&empty, &unused, 0.3);
    empty.boat.enabled = false;
    if (render(r, &empty, &none))
        return;
    /* The quad is square and centred in the frame; below it, its mirror
     * image in the water differs too: take its width alone. */
    int rect[4];
    quad_rect(&f[1], &none, rect);
    const int half = (rect[2] - rect[0]) / 2;
    rect[1] = none.height / 2 - half;
    rect[3] = none.height / 2 + half;
    const double light = srgb_to_linear(230), dark = srgb_to_linear(40);
    long pixels = 0, near_light = 0, near_dark = 0;
    double quadrant[2][2] = {{0, 0}, {0, 0}};
    long quadrant_n[2][2] = {{0, 0}, {0, 0}};
    const int cx = (rect[0] + rect[2]) / 2, cy = (rect[1] + rect[3]) / 2;
    for (int y = rect[1] + 1; y < rect[3]; y++)
        for (int x = rect[0] + 1; x < rect[2]; x++) {
            size_t i = ((size_t)y * none.width + x) * 4;
            double t = luminance(f[0].color + i), w = luminance(f[1].color + i),
                   k = luminance(f[2].color + i);
            if (!(w - k > 1e-3))
                continue;
            double share = (t - k) / (w - k);
            pixels++;
            near_light += fabs(share - light) < 0.02;
            near_dark += fabs(share - dark) < 0.02;
            quadrant[y < cy][x < cx] += share;
            quadrant_n[y < cy][x < cx]++;
        }
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            quadrant[a][b] /= quadrant_n[a][b] ? quadrant_n[a][b] : 1;
    printf("checker: quad %d..%d x %d..%d, %ld pixels: %ld at the light texel's %.4f, %ld at the "
           "dark's %.4f; quadrants (top left, top right, bottom left, bottom right) %.3f %.3f "
           "%.3f %.3f\n",
           rect[0], rect[2], rect[1], rect[3], pixels, near_light, light, near_dark, dark,
           quadrant[1][1], quadrant[1][0], quadrant[0][1], quadrant[0][0]);
    CHECK(pixels > 1500);
    CHECK(near_light + near_dark > 0.85 * pixels);
    CHECK(near_light > 0.4 * pixels && near_dark > 0.4 * pixels);
    CHECK(quadrant[1][1] > 0.7 && quadrant[0][0] > 0.7);
    CHECK(quadrant[1][0] < 0.1 && quadrant[0][1] < 0.1);
    for (int i = 0; i < 3; i++)
        tl_frame_free(&f[i]);
    tl_frame_free(&none);
}

/* A flat quad whose normal map tilts it 0.4 rad toward +x is lit as the
 * quad turned 0.4 rad with a flat map, and not as the flat quad: the mean
 * at the quad's centre, under a sun from the side. */
static void test_normal_map(tl_renderer *r)
{
    const double tilt = 0.4;
    unsigned char *tilted = gltf_solid(8, (unsigned char)lround(255 * (0.5 + 0.5 * sin(tilt))), 128,
                                       (unsigned char)lround(255 * (0.5 + 0.5 * cos(tilt))));
    unsigned char *flat = gltf_solid(8, 128, 128, 255);
    const unsigned char *maps[3] = {tilted, flat, flat};
    const double turns[3] = {0.0, tilt, 0.0};
    double centre[3] = {0, 0, 0};
    int ok = 1;
    for (int i = 0; i < 3; i++) {
        gltf_quad q = plain_quad();
        q.turn = turns[i];
        q.map[TL_MESH_MAP_NORMAL] = (gltf_map){8, 8, maps[i], 0};
        tl_mesh m;
        tl_frame f;
        ok &= load_quad(&q, &m) == 0;
        if (ok && render_quad(r, &m, 1.2, 0.0, &f) == 0) {
            centre[i] = mean_at(&f, f.width / 2, f.height / 2, 2);
            tl_frame_free(&f);
        } else
            ok = 0;
        tl_mesh_free(&m);
    }
    free(tilted);
    free(flat);
    if (!ok)
        return;
    printf("normal map: the mapped quad %.4f, the turned quad %.4f, the flat quad %.4f\n",
           centre[0], centre[1], centre[2]);
    CHECK(fabs(centre[1] - centre[2]) > 0.2 * centre[1]);
    CHECK(fabs(centre[0] - centre[1]) < 0.05 * fabs(centre[1] - centre[2]));
}

/* Renders two quads and gives the largest relative difference. */
static double quads_differ(tl_renderer *r, const gltf_quad *a, const gltf_quad *b, double lights,
                           double sun_azimuth)
{
    const gltf_quad *q[2] = {a, b};
    tl_frame f[2];
    for (int i = 0; i < 2; i++) {
        tl_mesh m;
        if (load_quad(q[i], &m) || render_quad(r, &m, sun_azimuth, lights, &f[i])) {
            if (i)
                tl_frame_free(&f[0]);
            return INFINITY;
        }
        tl_mesh_free(&m);
    }
    double worst = 0.0;
    for (size_t i = 0; i < (size_t)f[0].width * f[0].height * 4; i++)
        worst = fmax(worst, fabs(f[0].color[i] - f[1].color[i]) / fmax(f[1].color[i], 0.01));
    tl_frame_free(&f[0]);
    tl_frame_free(&f[1]);
    return worst;
}

/* Each map scales its factor as glTF says, seen as the same frame as the
 * factor alone would give: metallic-roughness (G, B), occlusion (R by its
 * strength, with the sun behind the quad so that only the sky and the sea
 * light it) and emissive (sRGB, lit by boat.lights). */
static void test_factor_maps(tl_renderer *r)
{
    unsigned char *mr = gltf_solid(4, 0, 128, 255), *occlusion = gltf_solid(4, 64, 64, 64),
                  *emissive = gltf_solid(4, 188, 188, 188);
    gltf_quad mapped = plain_quad(), plain = plain_quad();
    mapped.roughness = 1.0;
    mapped.metallic = 1.0;
    mapped.map[TL_MESH_MAP_METALLIC_ROUGHNESS] = (gltf_map){4, 4, mr, 0};
    plain.roughness = 128.0 / 255.0;
    plain.metallic = 1.0;
    double d_mr = quads_differ(r, &mapped, &plain, 0.0, 0.3);

    mapped = plain_quad();
    plain = plain_quad();
    mapped.occlusion_strength = 0.5;
    mapped.map[TL_MESH_MAP_OCCLUSION] = (gltf_map){4, 4, occlusion, 0};
    /* The plain quad's occlusion is its baked 1: scale its colour
     * instead, which the sky's and sea's light is linear in. */
    tl_mesh a, b;
    tl_frame fa, fb;
    double ratio = NAN;
    if (!load_quad(&mapped, &a) && !load_quad(&plain, &b) && !render_quad(r, &a, M_PI, 0.0, &fa)) {
        if (!render_quad(r, &b, M_PI, 0.0, &fb)) {
            ratio = mean_at(&fa, fa.width / 2, fa.height / 2, 3) /
                    mean_at(&fb, fb.width / 2, fb.height / 2, 3);
            tl_frame_free(&fb);
        }
        tl_frame_free(&fa);
    }
    tl_mesh_free(&a);
    tl_mesh_free(&b);
    const double occluded = 1.0 + 0.5 * (64.0 / 255.0 - 1.0);

    mapped = plain_quad();
    plain = plain_quad();
    mapped.emissive[0] = mapped.emissive[1] = mapped.emissive[2] = 1.0;
    mapped.map[TL_MESH_MAP_EMISSIVE] = (gltf_map){4, 4, emissive, 0};
    const double glow = srgb_to_linear(188);
    plain.emissive[0] = plain.emissive[1] = plain.emissive[2] = glow;
    double d_emissive = quads_differ(r, &mapped, &plain, 1.0, 0.3);
    printf("maps against factors: metallic-roughness %.2g, emissive %.2g (relative); occlusion "
           "%.4f of the unoccluded light, want %.4f\n",
           d_mr, d_emissive, ratio, occluded);
    CHECK(d_mr < 0.02);
    CHECK(d_emissive < 0.02);
    CHECK(fabs(ratio - occluded) < 0.01);
    /* And the lamps' switch: with boat.lights 0 the glowing quad is the
     * plain one. */
    plain = plain_quad();
    double d_off = quads_differ(r, &mapped, &plain, 0.0, 0.3);
    printf("emissive quad with boat.lights 0 against a plain one: %.2g\n", d_off);
    CHECK(d_off < 1e-4);
    free(mr);
    free(occlusion);
    free(emissive);
}

int main(void)
{
    if (!mkdtemp(dir))
        return 1;
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_normal_map_probe(r);
    test_checker(r);
    test_normal_map(r);
    test_factor_maps(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    rmdir(dir);
    TEST_END();
}
