/* The compositing passes without a GPU: pass names, Cryptomatte's IDs
 * against the specification's and Blender's, the camera's matrices against
 * the view rays, and a multilayer EXR written from a made-up frame and
 * read back channel by channel. */
#include <OpenEXR/openexr.h>
#include <stdlib.h>
#include <unistd.h>

#include "core/tl_math.h"
#include "image/tl_image_io.h"
#include "passes/tl_passes.h"
#include "tl_test.h"

static uint32_t id_bits(const char *name)
{
    uint32_t bits;
    tl_crypto_id(name, &bits);
    return bits;
}

static void test_ids(void)
{
    /* The specification's manifest example, and what Blender 3.4 writes
     * for an object named Cube in its ViewLayer.CryptoObject layer. Their
     * lengths leave tails of 1, 3, 0 and 2 bytes. */
    CHECK(id_bits("bunny") == 0x13851a76u);
    CHECK(id_bits("default") == 0x42c9679fu);
    CHECK(id_bits("Cube") == 0xa8fce865u);
    char key[8];
    tl_crypto_key("ViewLayer.CryptoObject", key);
    CHECK_STR_EQ(key, "542cafa");
    CHECK(tl_crypto_murmur3("", 0, 0) == 0u);
    /* Every ID is a normal float: no NaN, Inf, zero or denormal. */
    int bad = 0, clamped = 0;
    for (int i = 0; i < 200000; i++) {
        char name[32];
        snprintf(name, sizeof name, "object_%d", i);
        uint32_t bits;
        float f = tl_crypto_id(name, &bits);
        uint32_t h = tl_crypto_murmur3(name, strlen(name), 0);
        bad += !isnormal(f);
        clamped += bits != h;
        /* Only the exponent may change, and only at its ends. */
        bad += (bits & 0x807fffffu) != (h & 0x807fffffu);
    }
    CHECK(bad == 0);
    CHECK(clamped > 0); /* about 2 in 256 names have an exponent of 0 or 255 */
}

static void test_names(void)
{
    unsigned p = 0;
    size_t at = 99, len = 99;
    CHECK(tl_passes_parse("depth,normal", &p, &at, &len) == 0);
    CHECK(p == (TL_PASSES_COMBINED | TL_PASSES_DEPTH | TL_PASSES_NORMAL));
    CHECK(tl_passes_parse("all", &p, &at, &len) == 0 && p == TL_PASSES_ALL);
    CHECK(tl_passes_parse("masks", &p, &at, &len) == 0 &&
          p == (TL_PASSES_COMBINED | TL_PASSES_MASKS));
    CHECK(tl_passes_parse("none", &p, &at, &len) == 0 && p == 0);
    CHECK(tl_passes_parse("depth,nope", &p, &at, &len) == -1 && at == 6 && len == 4);
    CHECK(tl_passes_parse("", &p, &at, &len) == -1 && at == 0 && len == 0);
    CHECK(tl_passes_parse("depth,,normal", &p, &at, &len) == -1 && at == 6 && len == 0);
    CHECK(tl_passes_parse("none,depth", &p, &at, &len) == -1 && at == 0 && len == 4);
    char names[256];
    tl_passes_format(TL_PASSES_ALL, names, sizeof names);
    CHECK(tl_passes_parse(names, &p, &at, &len) == 0 && p == TL_PASSES_ALL);
    CHECK_STR_CONTAINS(names, "mask_underwater");
    CHECK(!strstr(names, "masks") && !strstr(names, "all"));
    CHECK(tl_passes_need_aov(TL_PASSES_COMBINED | TL_PASSES_DEPTH | TL_PASSES_POSITION) == 0);
    CHECK(tl_passes_need_aov(TL_PASSES_CRYPTOMATTE) == 1);
}

/* p (x y z 1) times the row-vector matrix m. */
static void transform(const double m[16], const double p[3], double out[4])
{
    for (int j = 0; j < 4; j++)
        out[j] = p[0] * m[j] + p[1] * m[4 + j] + p[2] * m[8 + j] + m[12 + j];
}

static void test_camera(void)
{
    tl_camera cams[3] = {{{0.0, 1.5, 0.0}, 0.0, -0.1, 0.0, 1.0},
                         {{-1.0e5, 12.0, 3.0e4}, 2.2, 0.3, 0.2, 0.6},
                         {{5.0, -3.0, 7.0}, -1.3, -0.7, -0.4, 1.6}};
    const int w = 320, h = 180;
    double worst_ndc = 0.0, worst_ortho = 0.0, worst_z = 0.0;
    for (int c = 0; c < 3; c++) {
        const tl_camera *cam = &cams[c];
        double to_cam[16], to_ndc[16];
        tl_passes_world_to_camera(cam, to_cam);
        tl_passes_world_to_ndc(cam, w, h, to_ndc);
        /* The rotation's rows are orthonormal. */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double dot = 0.0;
                for (int k = 0; k < 3; k++)
                    dot += to_cam[i * 4 + k] * to_cam[j * 4 + k];
                worst_ortho = fmax(worst_ortho, fabs(dot - (i == j)));
            }
        const int px[4][2] = {{0, 0}, {w - 1, 0}, {17, 101}, {w - 1, h - 1}};
        for (int k = 0; k < 4; k++) {
            double ray[3], p[3], q[4], e[4];
            tl_passes_pixel_ray(cam, w, h, px[k][0], px[k][1], ray);
            for (int i = 0; i < 3; i++)
                p[i] = cam->position[i] + 37.0 * ray[i];
            transform(to_ndc, p, q);
            /* The pixel's centre, (x + 0.5) / w across, (y + 0.5) / h down. */
            worst_ndc = fmax(worst_ndc, fabs(q[0] / q[3] * w - (px[k][0] + 0.5)));
            worst_ndc = fmax(worst_ndc, fabs(q[1] / q[3] * h - (px[k][1] + 0.5)));
            /* Camera z is the distance along the view's axis: positive. */
            transform(to_cam, p, e);
            double right[3], up[3], fwd[3];
            tl_scene_camera_basis(cam, right, up, fwd);
            worst_z = fmax(
                worst_z, fabs(e[2] - 37.0 * (ray[0] * fwd[0] + ray[1] * fwd[1] + ray[2] * fwd[2])));
            CHECK(e[2] > 0.0);
        }
    }
    CHECK(worst_ortho < 1e-12);
    CHECK(worst_ndc < 1e-6);
    CHECK(worst_z < 1e-6);

    tl_passes_meta m;
    int n = tl_passes_camera_meta(&cams[0], 1920, 1080, 24.0, TL_WORKING_REC709, &m);
    CHECK(n == TL_PASSES_CAMERA_META);
    /* vfov 1 rad over 16:9: the horizontal from the aspect, the focal
     * length from the 36 mm sensor's half width. */
    double tx = tan(0.5) * 1920.0 / 1080.0;
    int seen = 0;
    for (int i = 0; i < n; i++) {
        if (strcmp(m.meta[i].name, "tideline/focal_length_mm") == 0) {
            seen++;
            CHECK_NEAR(m.meta[i].d, 18.0 / tx, 1e-12);
        }
        if (strcmp(m.meta[i].name, "tideline/fov_vertical_deg") == 0) {
            seen++;
            CHECK_NEAR(m.meta[i].d, 1.0 / TL_DEG, 1e-9);
        }
        if (strcmp(m.meta[i].name, "framesPerSecond") == 0) {
            seen++;
            CHECK(m.meta[i].v[0] == 24.0 && m.meta[i].v[1] == 1.0);
        }
    }
    CHECK(seen == 3);
    tl_passes_camera_meta(&cams[0], 1920, 1080, 23.976, TL_WORKING_ACESCG, &m);
    CHECK(m.chromaticities[0] == 0.713 && m.chromaticities[7] == 0.33767);
    CHECK(m.fps[0] == 2997.0 && m.fps[1] == 125.0);
}

/* Value c of group g of pixel i of f's aov plane. */
static float *aov(tl_frame *f, int g, int i, int c)
{
    return f->aov + ((size_t)g * (size_t)f->width * (size_t)f->height + (size_t)i) * 4 + c;
}

static float *read_channel(const char *path, const char *name)
{
    int w = 0, h = 0;
    float *data = NULL;
    tl_error err;
    int rc = tl_exr_read_channel(path, name, &w, &h, &data, &err);
    CHECK(rc == 0);
    if (rc)
        fprintf(stderr, "%s\n", err.message);
    CHECK(w == 4 && h == 2);
    return data;
}

static void test_file(void)
{
    tl_frame f;
    tl_error err;
    CHECK(tl_frame_alloc(&f, 4, 2, &err) == 0);
    CHECK(tl_frame_alloc_aov(&f, &err) == 0);
    for (int i = 0; i < 8; i++) {
        for (int c = 0; c < 4; c++)
            f.color[i * 4 + c] = 0.25f * (float)(i + c);
        f.depth[i] = i == 0 ? TL_FRAME_SKY_DEPTH : 10.0f + (float)i;
        *aov(&f, 0, i, 0) = 0.0f;
        *aov(&f, 0, i, 1) = 1.0f;
        *aov(&f, 0, i, 2) = 0.0f;
    }
    /* Pixel 0: the sky. Pixel 1: half ocean, a quarter sky, a quarter the
     * second boat, a tenth of it foam. Pixel 2: the giant wave, under the
     * water. Pixel 3: three quarters the first boat, a quarter ocean, with
     * a NaN that must not reach the file. */
    *aov(&f, 1, 0, 0) = 1.0f;
    *aov(&f, 1, 1, 0) = 0.25f, *aov(&f, 1, 1, 1) = 0.5f, *aov(&f, 2, 1, 1) = 0.25f;
    *aov(&f, 0, 1, 3) = 0.1f;
    *aov(&f, 1, 2, 2) = 1.0f, *aov(&f, 1, 2, 3) = 1.0f;
    *aov(&f, 2, 3, 0) = 0.75f, *aov(&f, 1, 3, 1) = 0.25f, *aov(&f, 0, 3, 0) = NAN;
    for (int i = 4; i < 8; i++)
        *aov(&f, 1, i, 1) = 1.0f;
    const tl_camera cam = {{100.0, 5.0, -40.0}, 0.4, -0.2, 0.0, 1.0};
    const char *names[2] = {"boat", "dinghy"};
    /* The first drawn with the built-in boat, the second with a model. */
    const char *models[2] = {"", "/models/boats/din\"ghy.glb"}; /* a quote to escape */
    tl_passes_frame info = {TL_PASSES_ALL & ~(TL_PASSES_VECTOR | TL_PASSES_LIGHTS),
                            &cam,
                            names,
                            2,
                            24.0,
                            NULL,
                            NULL,
                            NULL,
                            TL_WORKING_REC709,
                            NULL,
                            models};
    char path[] = "/tmp/tideline_test_passes_XXXXXX.exr";
    int fd = mkstemps(path, 4);
    CHECK(fd >= 0);
    close(fd);
    const tl_meta extra[1] = {{"tideline/frame", TL_META_INT, NULL, 0, 7, NULL}};
    tl_image_options opt = {.meta = extra, .meta_count = 1};
    int rc = tl_passes_write_frame(path, &f, &info, &opt, &err);
    CHECK(rc == 0);
    if (rc)
        fprintf(stderr, "%s\n", err.message);

    float *r = read_channel(path, "ViewLayer.Combined.R");
    float *z = read_channel(path, "ViewLayer.Depth.Z");
    float *px = read_channel(path, "ViewLayer.Position.X");
    float *py = read_channel(path, "ViewLayer.Position.Y");
    float *ny = read_channel(path, "ViewLayer.Normal.Y");
    float *nx = read_channel(path, "ViewLayer.Normal.X");
    float *water = read_channel(path, "ViewLayer.mask_water.X");
    float *foam = read_channel(path, "ViewLayer.mask_foam.X");
    float *giant = read_channel(path, "ViewLayer.mask_giant.X");
    float *boat = read_channel(path, "ViewLayer.mask_boat.X");
    float *sky = read_channel(path, "ViewLayer.mask_sky.X");
    float *under = read_channel(path, "ViewLayer.mask_underwater.X");
    float *id0 = read_channel(path, "ViewLayer.CryptoObject00.r");
    float *cov0 = read_channel(path, "ViewLayer.CryptoObject00.g");
    float *id1 = read_channel(path, "ViewLayer.CryptoObject00.b");
    float *cov1 = read_channel(path, "ViewLayer.CryptoObject00.a");
    float *id2 = read_channel(path, "ViewLayer.CryptoObject01.r");
    float *cov2 = read_channel(path, "ViewLayer.CryptoObject01.g");
    float *cov5 = read_channel(path, "ViewLayer.CryptoObject02.a");
    if (r && z && px && py && ny && nx && water && foam && giant && boat && sky && under && id0 &&
        cov0 && id1 && cov1 && id2 && cov2 && cov5) {
        CHECK_NEAR(r[5], 0.25 * 5, 1e-3);
        /* Depth as Blender writes it: along the camera's axis. */
        double right[3], up[3], fwd[3], ray3[3];
        tl_scene_camera_basis(&cam, right, up, fwd);
        tl_passes_pixel_ray(&cam, 4, 2, 3, 0, ray3);
        CHECK(z[0] == TL_FRAME_SKY_DEPTH);
        CHECK_NEAR(z[3], 13.0 * (ray3[0] * fwd[0] + ray3[1] * fwd[1] + ray3[2] * fwd[2]), 1e-5);
        CHECK(z[3] < 13.0f);
        /* Position: camera-relative, the view ray times the distance. */
        double ray[3];
        tl_passes_pixel_ray(&cam, 4, 2, 1, 1, ray);
        CHECK_NEAR(px[5], ray[0] * 15.0, 1e-5);
        CHECK_NEAR(py[5], ray[1] * 15.0, 1e-5);
        CHECK(px[0] == 0.0f && py[0] == 0.0f);
        CHECK(ny[4] == 1.0f && nx[3] == 0.0f); /* the NaN left out */
        CHECK(sky[0] == 1.0f && water[0] == 0.0f && water[4] == 1.0f);
        CHECK_NEAR(water[1], 0.5, 1e-3);
        CHECK_NEAR(foam[1], 0.1, 1e-3);
        CHECK(giant[2] == 1.0f && under[2] == 1.0f && under[1] == 0.0f);
        CHECK(boat[3] == 0.75f && boat[1] == 0.25f);
        /* Ranks: most coverage first, normalised by the pixel's total. */
        CHECK(id0[0] == tl_crypto_id("sky", NULL) && cov0[0] == 1.0f && cov1[0] == 0.0f);
        CHECK(id0[1] == tl_crypto_id("ocean", NULL) && cov0[1] == 0.5f);
        CHECK(cov1[1] == 0.25f && cov2[1] == 0.25f);
        CHECK((id1[1] == tl_crypto_id("sky", NULL) && id2[1] == tl_crypto_id("dinghy", NULL)) ||
              (id2[1] == tl_crypto_id("sky", NULL) && id1[1] == tl_crypto_id("dinghy", NULL)));
        CHECK(id0[2] == tl_crypto_id("giant", NULL));
        CHECK(id0[3] == tl_crypto_id("boat", NULL) && cov0[3] == 0.75f);
        CHECK(cov5[1] == 0.0f);
    }
    float *all[] = {r,   z,     px,  py,   ny,  nx,   water, foam, giant, boat,
                    sky, under, id0, cov0, id1, cov1, id2,   cov2, cov5};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
        free(all[i]);

    /* The materials: the ocean and the giant wave are water, less the
     * foam's share; a floating object's is its model's. */
    float *mid0 = read_channel(path, "ViewLayer.CryptoMaterial00.r");
    float *mcov0 = read_channel(path, "ViewLayer.CryptoMaterial00.g");
    float *mid3 = read_channel(path, "ViewLayer.CryptoMaterial01.b");
    float *mcov3 = read_channel(path, "ViewLayer.CryptoMaterial01.a");
    if (mid0 && mcov0 && mid3 && mcov3) {
        CHECK(mid0[1] == tl_crypto_id("water", NULL));
        CHECK_NEAR(mcov0[1], 0.4, 1e-6);
        CHECK(mid3[1] == tl_crypto_id("foam", NULL)); /* the fourth rank */
        CHECK_NEAR(mcov3[1], 0.1, 1e-6);
        CHECK(mid0[2] == tl_crypto_id("water", NULL) && mcov0[2] == 1.0f);
        CHECK(mid0[3] == tl_crypto_id("builtin_boat", NULL) && mcov0[3] == 0.75f);
    }
    free(mid0);
    free(mcov0);
    free(mid3);
    free(mcov3);
    char material_key[8], attr[64];
    tl_crypto_key("ViewLayer.CryptoMaterial", material_key);
    snprintf(attr, sizeof attr, "cryptomatte/%s/manifest", material_key);
    char material_manifest[512], material_want[512];
    CHECK(tl_exr_read_attr_string(path, attr, material_manifest, sizeof material_manifest, &err) ==
          0);
    snprintf(material_want, sizeof material_want,
             "{\"sky\":\"%08x\",\"water\":\"%08x\",\"foam\":\"%08x\",\"builtin_boat\":\"%08x\","
             "\"din\\\"ghy.glb\":\"%08x\"}",
             (unsigned)id_bits("sky"), (unsigned)id_bits("water"), (unsigned)id_bits("foam"),
             (unsigned)id_bits("builtin_boat"), (unsigned)id_bits("din\"ghy.glb"));
    CHECK_STR_EQ(material_manifest, material_want);

    char text[1024];
    CHECK(tl_exr_read_attr_string(path, "cryptomatte/542cafa/name", text, sizeof text, &err) == 0);
    CHECK_STR_EQ(text, "ViewLayer.CryptoObject");
    CHECK(tl_exr_read_attr_string(path, "cryptomatte/542cafa/manifest", text, sizeof text, &err) ==
          0);
    char want[512];
    snprintf(want, sizeof want,
             "{\"sky\":\"%08x\",\"ocean\":\"%08x\",\"giant\":\"%08x\",\"boat\":\"%08x\",\"dinghy\":"
             "\"%08x\"}",
             (unsigned)id_bits("sky"), (unsigned)id_bits("ocean"), (unsigned)id_bits("giant"),
             (unsigned)id_bits("boat"), (unsigned)id_bits("dinghy"));
    CHECK_STR_EQ(text, want);
    CHECK(tl_exr_read_attr_string(path, "tideline/passes", text, sizeof text, &err) == 0);
    CHECK_STR_CONTAINS(text, "cryptomatte");
    double frame_no = 0.0;
    CHECK(tl_exr_read_attr_double(path, "tideline/frame", &frame_no, &err) == 0 && frame_no == 7);

    /* The standard attributes, as OpenEXR's own reader sees them. */
    exr_context_t ctx = NULL;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    CHECK(exr_start_read(&ctx, path, &init) == EXR_ERR_SUCCESS);
    const exr_attribute_t *a = NULL;
    double to_cam[16];
    tl_passes_world_to_camera(&cam, to_cam);
    if (ctx && exr_get_attribute_by_name(ctx, 0, "worldToCamera", &a) == EXR_ERR_SUCCESS) {
        CHECK(a->type == EXR_ATTR_M44F);
        CHECK_NEAR(a->m44f->m[12], to_cam[12], 1e-4);
    } else {
        CHECK(!"worldToCamera");
    }
    if (ctx && exr_get_attribute_by_name(ctx, 0, "tideline/position_origin", &a) == EXR_ERR_SUCCESS)
        CHECK(a->type == EXR_ATTR_V3D && a->v3d->x == 100.0 && a->v3d->z == -40.0);
    else
        CHECK(!"tideline/position_origin");
    if (ctx && exr_get_attribute_by_name(ctx, 0, "chromaticities", &a) == EXR_ERR_SUCCESS)
        CHECK(a->type == EXR_ATTR_CHROMATICITIES && a->chromaticities->red_x == 0.64f);
    else
        CHECK(!"chromaticities");
    if (ctx)
        exr_finish(&ctx);

    /* tideline's own reader (compare, resume) finds Combined and Depth. */
    tl_frame back;
    CHECK(tl_exr_read(path, &back, &err) == 0);
    /* Depth from the layered file is its planar Depth. */
    CHECK(back.width == 4 && back.depth && back.depth[3] > 5.0f && back.depth[3] < 13.0f);
    CHECK_NEAR(back.color[5 * 4], 1.25, 1e-3);
    tl_frame_free(&back);
    int w, h;
    float *none = NULL;
    CHECK(tl_exr_read_channel(path, "ViewLayer.Nope.X", &w, &h, &none, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "no channel 'ViewLayer.Nope.X'");
    unlink(path);

    /* The passes that need the per-sample data refuse a frame without it,
     * and write nothing. */
    free(f.aov);
    f.aov = NULL;
    info.passes = TL_PASSES_COMBINED | TL_PASSES_MASK_BOAT;
    CHECK(tl_passes_write_frame(path, &f, &info, NULL, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "no data for its passes");
    CHECK(access(path, F_OK) != 0);
    /* Depth and position need none. */
    info.passes = TL_PASSES_DEPTH | TL_PASSES_POSITION;
    CHECK(tl_passes_write_frame(path, &f, &info, NULL, &err) == 0);
    unlink(path);
    tl_frame_free(&f);
}

int main(void)
{
    test_ids();
    test_names();
    test_camera();
    test_file();
    TEST_END();
}
