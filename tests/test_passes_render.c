/* The compositing passes on the GPU, on the hero cutscene's frame where the
 * boat climbs the giant wave's face under the sun (giant_wave.tl, 10.4 s):
 * the passes leave the image as it was; the covers add up; the boat's
 * matte lies where the camera's matrices put the boat; the giant wave's
 * matte is the CPU mirror's (tl_giant_in_matte at the hit points the
 * position pass gives); those points lie on the CPU's surface. */
#include <stdlib.h>
#include <unistd.h>

#include "cutscene/tl_cutscene.h"
#include "image/tl_image_io.h"
#include "passes/tl_passes.h"
#include "tl_gl_test.h"
#include "tl_run.h"

#define W 160
#define H 90

/* Value c of group g of pixel i of the aov plane. */
static float aov(const tl_frame *f, int g, int i, int c)
{
    return f->aov[((size_t)g * W * H + (size_t)i) * 4 + (size_t)c];
}

/* Reads channel `name` of `path` (W2 x H2 floats), or NULL (a failed check). */
#define W2 96
#define H2 54
static float *channel(const char *path, const char *name)
{
    int w = 0, h = 0;
    float *data = NULL;
    tl_error err;
    CHECK(tl_exr_read_channel(path, name, &w, &h, &data, &err) == 0);
    CHECK(w == W2 && h == H2);
    return data;
}

/* The matte of the names (NULL after the last) in Cryptomatte layer
 * `layer` of the file: their IDs' coverage summed over the ranks. */
static float *crypto_matte(const char *path, const char *layer, const char *const name[2])
{
    float *matte = calloc((size_t)W * H, sizeof *matte);
    for (int rank = 0; matte && rank < TL_CRYPTO_RANKS; rank++) {
        char id_name[64], cov_name[64];
        snprintf(id_name, sizeof id_name, "ViewLayer.%s%02d.%c", layer, rank / 2,
                 rank % 2 ? 'b' : 'r');
        snprintf(cov_name, sizeof cov_name, "ViewLayer.%s%02d.%c", layer, rank / 2,
                 rank % 2 ? 'a' : 'g');
        float *id = NULL, *cov = NULL;
        int w, h;
        tl_error err;
        CHECK(tl_exr_read_channel(path, id_name, &w, &h, &id, &err) == 0);
        CHECK(tl_exr_read_channel(path, cov_name, &w, &h, &cov, &err) == 0);
        for (int i = 0; id && cov && i < W * H; i++)
            for (int k = 0; k < 2 && name[k]; k++)
                matte[i] += id[i] == tl_crypto_id(name[k], NULL) ? cov[i] : 0.0f;
        free(id);
        free(cov);
    }
    return matte;
}

/* The Vector pass through `tideline render`: a camera panning at 24 deg/s
 * over a sea whose waves stand still, then a cut. Each pixel of the
 * horizon's rows (pitch 0: its rays turn about the camera's own up axis)
 * moves as the pan's rotation predicts, found here from angles alone:
 * towards the frame before by the turn back, towards the frame after by
 * the turn on, the two opposite. At the cut's frame the motion from the
 * frame before is zero; a camera and sea at rest move nothing. */
static void test_vectors(void)
{
    char dir[] = "/tmp/tideline-vectors-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char tl[256], pattern[256], at_cut[256], still[256];
    snprintf(tl, sizeof tl, "%s/pan.tl", dir);
    snprintf(pattern, sizeof pattern, "%s/f_####.exr", dir);
    snprintf(at_cut, sizeof at_cut, "%s/f_0060.exr", dir);
    snprintf(still, sizeof still, "%s/f_0006.exr", dir);
    tl_test_write_file(tl, "tideline 1\nfps 24\nduration 4s\nsize 96x54\nquality draft\n"
                           "set ocean.speed 0\nset camera.position 0 3 0\nset camera.pitch 0\n"
                           "set camera.fov 50deg\n"
                           "key camera.yaw linear\n  0s 0deg\n  0.5s 0deg\n  2s 36deg\n"
                           "  2.5s cut 120deg\n  4s 150deg\n");
    CHECK(tl_run(&(tl_run_opts){0}, "render", tl, "--frames", "6,36,60", "--passes", "vector", "-o",
                 pattern, "-q", NULL) == 0);
    if (strstr(tl_run_output, "error"))
        fprintf(stderr, "%s\n", tl_run_output);
    char mid[256];
    snprintf(mid, sizeof mid, "%s/f_0036.exr", dir);
    float *vx = channel(mid, "ViewLayer.Vector.X"), *vy = channel(mid, "ViewLayer.Vector.Y");
    float *vz = channel(mid, "ViewLayer.Vector.Z"), *vw = channel(mid, "ViewLayer.Vector.W");
    const double fy = 0.5 * H2 / tan(0.5 * 50.0 * M_PI / 180.0), fx = fy, turn = M_PI / 180.0;
    double worst = 0.0;
    int rows = 0, opposite = 0;
    for (int y = H2 / 2 - 3; vx && vy && vz && vw && y < H2 / 2 + 3; y++)
        for (int x = 0; x < W2; x++) {
            size_t i = (size_t)y * W2 + (size_t)x;
            /* The pixel's ray in the camera's frame, turned by a degree
             * (24 deg/s at 24 fps) about the up axis. */
            double u = x + 0.5 - 0.5 * W2, v = 0.5 * H2 - (y + 0.5);
            double dx = u / fx, dz = 1.0;
            double back_x = dx * cos(turn) + dz * sin(turn),
                   back_z = -dx * sin(turn) + dz * cos(turn);
            double on_x = dx * cos(turn) - dz * sin(turn), on_z = dx * sin(turn) + dz * cos(turn);
            double want_x = fx * back_x / back_z - u, want_y = fy * (v / fy) / back_z - v;
            double want_z = u - fx * on_x / on_z;
            worst = fmax(worst, fabs(vx[i] - want_x) / fabs(want_x));
            worst = fmax(worst, fabs(vy[i] - want_y) - 0.02 * fabs(want_x));
            worst = fmax(worst, fabs(vz[i] - want_z) / fabs(want_z));
            /* Blender's layout stores both as a move along the motion:
             * toward the frame before and from the frame after point the
             * same way on screen when the motion keeps on. */
            opposite += (vx[i] > 0.0f) == (want_x > 0.0) && (vz[i] > 0.0f) == (want_z > 0.0);
            rows++;
        }
    printf("pan: %d pixels, worst error %.5f of the predicted move\n", rows, worst);
    CHECK(rows == 6 * W2);
    CHECK(worst < 0.02);
    CHECK(opposite == rows);
    free(vx), free(vy), free(vz), free(vw);

    /* At the cut: nothing from the frame before (another shot), the new
     * shot's pan (20 deg/s) toward the frame after. */
    vx = channel(at_cut, "ViewLayer.Vector.X");
    vz = channel(at_cut, "ViewLayer.Vector.Z");
    double before = 0.0, after = 0.0;
    for (int i = 0; vx && vz && i < W2 * H2; i++) {
        before = fmax(before, fabs(vx[i]));
        after += vz[i] / (W2 * H2);
    }
    printf("cut: largest move toward the frame before %g px, mean toward the one after %.3f px\n",
           before, after);
    CHECK(before == 0.0);
    CHECK(after > 0.5 * fx * tan(20.0 / 24.0 * turn));
    free(vx), free(vz);

    /* At rest (0.25 s: the pan has not begun; the waves stand still). */
    double rest = 0.0;
    const char *names[4] = {"ViewLayer.Vector.X", "ViewLayer.Vector.Y", "ViewLayer.Vector.Z",
                            "ViewLayer.Vector.W"};
    for (int c = 0; c < 4; c++) {
        float *v = channel(still, names[c]);
        for (int i = 0; v && i < W2 * H2; i++)
            rest = fmax(rest, fabs(v[i]));
        free(v);
    }
    printf("at rest: largest move %g px\n", rest);
    CHECK(rest < 1e-3);
    const char *files[4] = {still, mid, at_cut, tl};
    for (int k = 0; k < 4; k++)
        unlink(files[k]);
    rmdir(dir);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: test_passes_render TIMELINES_DIR TIDELINE\n");
        return 2;
    }
    tl_run_binary = argv[2];
    test_vectors();
    char path[4096];
    snprintf(path, sizeof path, "%s/giant_wave.tl", argv[1]);
    tl_cutscene cs;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    if (tl_cutscene_load(path, &cs, &diags, &err)) {
        tl_cutscene_report(stderr, "test_passes_render", &diags, &err);
        return 1;
    }
    tl_render *r = render_test_open();
    CHECK(r != NULL);
    if (!r)
        TEST_END();
    CHECK(tl_render_use_cutscene(r, &cs, &err) == 0);
    const tl_timeline *tl = &cs.timeline;
    const long frame = 250;
    tl_render_settings settings = {.width = W, .height = H, .spp = 4};
    tl_frame plain = {0}, with = {0};
    tl_scene scene;
    settings.planes = TL_PLANES_ALL;
    CHECK(tl_render_timeline_frame(r, tl, frame, &settings, &plain, &scene, &err) == 0);
    settings.planes = TL_PLANES_ALL | TL_PLANE_AOV;
    int rc = tl_render_timeline_frame(r, tl, frame, &settings, &with, &scene, &err);
    CHECK(rc == 0);
    if (rc)
        fprintf(stderr, "%s\n", err.message);
    CHECK(with.aov != NULL);
    if (rc || !with.aov)
        TEST_END();

    /* The passes change no pixel of the image. */
    double worst = 0.0;
    for (size_t i = 0; i < (size_t)W * H * 4; i++)
        worst = fmax(worst, fabs(plain.color[i] - with.color[i]));
    for (size_t i = 0; i < (size_t)W * H; i++)
        worst = fmax(worst, fabs(plain.depth[i] - with.depth[i]));
    CHECK(worst == 0.0);

    /* Every sample met one thing: the covers add up to 1. */
    double worst_sum = 0.0;
    int giant_px = 0, sky_px = 0, boat_px = 0, away = 0;
    for (int i = 0; i < W * H; i++) {
        double sum = aov(&with, 1, i, 0) + aov(&with, 1, i, 1) + aov(&with, 1, i, 2);
        double boats = 0.0;
        for (int k = 0; k < TL_FRAME_AOV_OBJECTS; k++)
            boats += aov(&with, (TL_FRAME_AOV_OBJECT0 + k) / 4, i, (TL_FRAME_AOV_OBJECT0 + k) % 4);
        worst_sum = fmax(worst_sum, fabs(sum + boats - 1.0));
        giant_px += aov(&with, 1, i, 2) > 0.99f;
        sky_px += aov(&with, 1, i, 0) > 0.99f;
        boat_px += boats > 0.99;
        /* A pixel's normal faces the eye: the mean of its samples' normals
         * points back along its ray. */
        double ray[3];
        tl_passes_pixel_ray(&scene.camera, W, H, i % W, i / W, ray);
        double n_dot = aov(&with, 0, i, 0) * ray[0] + aov(&with, 0, i, 1) * ray[1] +
                       aov(&with, 0, i, 2) * ray[2];
        away += aov(&with, 1, i, 0) < 0.01f && n_dot > 0.0;
    }
    CHECK(away == 0);
    CHECK(worst_sum < 1e-4);
    printf("pixels: giant wave %d, sky %d, boat %d of %d\n", giant_px, sky_px, boat_px, W * H);
    CHECK(giant_px > W * H / 4 && sky_px > W * H / 20 && boat_px > 40);

    /* The boat's position projects into its matte (worldToNDC), and its
     * matte is object 0's cover alone. */
    double to_ndc[16];
    tl_passes_world_to_ndc(&scene.camera, W, H, to_ndc);
    const double *b = scene.boat.position;
    double q[4];
    for (int j = 0; j < 4; j++)
        q[j] =
            b[0] * to_ndc[j] + (b[1] + 1.0) * to_ndc[4 + j] + b[2] * to_ndc[8 + j] + to_ndc[12 + j];
    int bx = (int)floor(q[0] / q[3] * W), by = (int)floor(q[1] / q[3] * H);
    printf("the boat projects to pixel (%d, %d)\n", bx, by);
    CHECK(bx >= 0 && bx < W && by >= 0 && by < H);
    if (bx >= 0 && bx < W && by >= 0 && by < H) {
        int hits = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                int x = bx + dx, y = by + dy;
                if (x >= 0 && x < W && y >= 0 && y < H)
                    hits += aov(&with, 2, y * W + x, 0) > 0.5f;
            }
        CHECK(hits >= 5);
    }

    /* The giant wave's matte against the CPU's rule at the hit points the
     * position pass gives, and those points on the CPU's surface, where a
     * pixel's samples all met the water (edges left out). */
    tl_giant g;
    tl_giant_prepare(&g, &scene.giant, scene.time);
    tl_waves w;
    tl_waves_init(&w, &scene.ocean);
    int checked = 0, disagree = 0, off_surface = 0, on_water = 0, surfaces = 0;
    const double pixel_angle = 2.0 * tan(0.5 * scene.camera.vfov) / H;
    for (int y = 0; y < H; y += 2)
        for (int x = 0; x < W; x += 2) {
            int i = y * W + x;
            double water = aov(&with, 1, i, 1) + aov(&with, 1, i, 2);
            if (water < 0.999 || !(with.depth[i] < 2000.0))
                continue;
            /* Not at a silhouette (the crest against the water behind):
             * there the nearest sample's depth on the centre's ray is a
             * point in the air. */
            double step = 0.0;
            for (int k = 0; k < 4; k++) {
                int nx = x + (k == 0) - (k == 1), ny = y + (k == 2) - (k == 3);
                if (nx >= 0 && nx < W && ny >= 0 && ny < H)
                    step = fmax(step, fabs(with.depth[ny * W + nx] - with.depth[i]));
            }
            if (step > 0.05 * with.depth[i])
                continue;
            on_water++;
            double ray[3];
            tl_passes_pixel_ray(&scene.camera, W, H, x, y, ray);
            double p[3];
            for (int k = 0; k < 3; k++)
                p[k] = scene.camera.position[k] + ray[k] * with.depth[i];
            tl_giant_sample smp;
            tl_giant_sample_at(&g, p[0], p[2], 8, &smp);
            double share = smp.height / g.amplitude;
            /* The depth is the nearest of the pixel's samples: the point
             * on the centre's ray may lie up to a pixel's angle off the
             * surface. The matte is compared clear of its edge by the
             * height the wave gains over that much water. */
            double slip = with.depth[i] * pixel_angle;
            double across = slip / fmax(fabs(ray[1]), 0.05);
            double margin = hypot(smp.grad[0], smp.grad[1]) * across / g.amplitude;
            if (fabs(share - TL_GIANT_MATTE_SHARE) > margin + 0.005) {
                checked++;
                int cpu = tl_giant_in_matte(&g, smp.height);
                int gpu = aov(&with, 1, i, 2) > 0.5f;
                disagree += cpu != gpu;
            }
            /* Where the crest has broken the lip's lumps and tears are
             * the shader's alone: the height field and the smooth lip
             * stand for the rest. */
            double wa = (p[0] - g.origin[0]) * g.across[0] + (p[2] - g.origin[1]) * g.across[1];
            double dprogress;
            if (tl_giant_break_progress(&g, wa, &dprogress) > 0.0)
                continue;
            surfaces++;
            double heights[4];
            int n = tl_waves_surfaces(&w, &g, p[0], p[2], scene.time, scene.quality.normal_octaves,
                                      8, heights, 4);
            double gap = INFINITY;
            for (int k = 0; k < n; k++)
                gap = fmin(gap, fabs(p[1] - heights[k]));
            if (gap > 0.05 + slip && off_surface < 5)
                printf("  (%d, %d) at %.1f m: %.3f m from the surface\n", x, y, with.depth[i], gap);
            off_surface += gap > 0.05 + slip;
        }
    printf("giant matte: %d of %d points clear of its edge disagree with the CPU; %d of %d "
           "points off the surface\n",
           disagree, checked, off_surface, surfaces);
    CHECK(checked > 300);
    CHECK(disagree <= checked / 200);
    CHECK(surfaces > 300);
    CHECK(off_surface <= surfaces / 100);

    /* Through the file: the boat's Cryptomatte matte is its mask. */
    const char *names[TL_OBJECT_MAX], *models[TL_OBJECT_MAX];
    for (int k = 0; k < tl->object_count; k++) {
        names[k] = tl->objects[k].name;
        models[k] = tl->objects[k].model;
    }
    tl_passes_frame info = {TL_PASSES_ALL & ~(TL_PASSES_VECTOR | TL_PASSES_LIGHTS),
                            &scene.camera,
                            names,
                            tl->object_count,
                            tl->fps,
                            &scene,
                            NULL,
                            NULL,
                            TL_WORKING_REC709,
                            NULL,
                            models};
    char out[] = "/tmp/tideline_test_passes_render_XXXXXX.exr";
    int fd = mkstemps(out, 4);
    close(fd);
    CHECK(tl_passes_write_frame(out, &with, &info, NULL, &err) == 0);
    int fw, fh;
    /* The boat's matte as a Cryptomatte reader pulls it (its ID's coverage
     * summed over the ranks), by its object and by its material (the
     * built-in boat's), against mask_boat; the material water's and
     * foam's together against mask_water. */
    float *mask = NULL, *water_mask = NULL;
    CHECK(tl_exr_read_channel(out, "ViewLayer.mask_boat.X", &fw, &fh, &mask, &err) == 0);
    CHECK(tl_exr_read_channel(out, "ViewLayer.mask_water.X", &fw, &fh, &water_mask, &err) == 0);
    const struct {
        const char *layer, *name[2];
        const float *against;
    } mattes[3] = {{"CryptoObject", {"boat", NULL}, mask},
                   {"CryptoMaterial", {"builtin_boat", NULL}, mask},
                   {"CryptoMaterial", {"water", "foam"}, water_mask}};
    for (int m = 0; m < 3 && mask && water_mask; m++) {
        float *matte = crypto_matte(out, mattes[m].layer, mattes[m].name);
        double inter = 0.0, uni = 0.0;
        for (int i = 0; matte && i < W * H; i++) {
            inter += fmin(matte[i], mattes[m].against[i]);
            uni += fmax(matte[i], mattes[m].against[i]);
        }
        printf("%s %s%s%s: its matte against the mask, IoU %.4f\n", mattes[m].layer,
               mattes[m].name[0], mattes[m].name[1] ? " + " : "",
               mattes[m].name[1] ? mattes[m].name[1] : "", inter / uni);
        CHECK(inter / uni > 0.99);
        free(matte);
    }
    free(mask);
    free(water_mask);
    unlink(out);

    tl_frame_free(&plain);
    tl_frame_free(&with);
    tl_render_close(r);
    tl_cutscene_free(&cs);
    TEST_END();
}
