/* Several floating objects (`boat NAME`): two boats in one timeline each
 * float as they would alone, each has its own slot, wake and shadow layer,
 * and neither touches a pixel the other does not: moving or adding one
 * changes only the pixels it changes by itself (its hull, mirror image,
 * wake and shadow). */
#include <stdio.h>
#include <string.h>

#include "timeline/tl_parse.h"
#include "timeline/tl_timeline.h"
#include "tl_gl_test.h"

enum { W = 160, H = 90 };
#define AT 3.0
/* Where the rescue boat starts: far enough to the boat's starboard that
 * the two and their wakes lie apart on screen. */
#define RESCUE_X 24.0
#define RESCUE_Z 3.0

/* The shot: the boat heading north, the rescue boat `rescue_x` m to its
 * starboard and `rescue_z` m ahead, seen from astern and above; `extra` is
 * appended (one more setting, or none). */
#define HEADER                                                                                     \
    "tideline 1\nfps 24\nduration 4\nsize 160x90\nquality preview\n"                               \
    "set quality.render_scale 1\nset quality.pixel_filter 0\nset render.bloom 0\n"                 \
    "set sun.elevation 35deg\nset sun.azimuth 120deg\n"

static int parse(const char *text, tl_timeline *tl)
{
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_timeline_parse_text("two.tl", text, strlen(text), tl, &diags, &err);
    if (rc || diags.errors) {
        tl_diags_write(&diags, stderr);
        CHECK(0);
        return 1;
    }
    return 0;
}

static int two_boats(double rescue_x, double rescue_z, const char *extra, tl_timeline *tl)
{
    char text[2048];
    snprintf(text, sizeof text,
             HEADER "boat rescue\n"
                    "path boat\n  0s 0 0\n  4s 0 12\n"
                    "path rescue\n  0s %.3f %.3f\n  4s %.3f %.3f\n"
                    "set rescue.size 10\n"
                    "set camera.position 12 10 -18\nlook camera at boat + 12 0 10\n%s\n",
             rescue_x, rescue_z, rescue_x, rescue_z + 12.0, extra);
    return parse(text, tl);
}

/* The frame at AT of the shot (boat and rescue boat visible as asked). */
static int shot(tl_renderer *r, double rescue_x, double rescue_z, const char *extra, tl_frame *f,
                tl_frame_uniforms *u)
{
    tl_timeline tl;
    if (two_boats(rescue_x, rescue_z, extra, &tl))
        return 1;
    tl_scene s;
    tl_timeline_eval(&tl, AT, &s);
    tl_timeline_free(&tl);
    gl_test_prepare(r, &s, u);
    return render_prepared(r, u, W, H, f);
}

/* Pixels where a and b differ (by more than 1e-3 of the brighter, or
 * 1e-5 absolute) into `mask`; their count. */
static long diff_mask(const tl_frame *a, const tl_frame *b, unsigned char *mask)
{
    long n = 0;
    for (int i = 0; i < W * H; i++) {
        double x = luminance(a->color + 4 * i), y = luminance(b->color + 4 * i);
        mask[i] = fabs(x - y) > 1e-3 * fmax(x, y) + 1e-5;
        n += mask[i];
    }
    return n;
}

/* The mask grown by `by` pixels (the foam's and spray's textures are
 * filtered over a pixel or two). */
static void dilate(unsigned char *mask, int by)
{
    static unsigned char was[W * H];
    memcpy(was, mask, sizeof was);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            if (!was[y * W + x])
                continue;
            for (int dy = -by; dy <= by; dy++)
                for (int dx = -by; dx <= by; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < W && yy < H)
                        mask[yy * W + xx] = 1;
                }
        }
}

/* Set pixels of `a` outside `allowed`. */
static long outside(const unsigned char *a, const unsigned char *allowed)
{
    long n = 0;
    for (int i = 0; i < W * H; i++)
        n += a[i] && !allowed[i];
    return n;
}

/* Each object floats as it would alone: the two-boat timeline's poses are
 * those of timelines with one of them as the only boat. */
static void test_float_alone(void)
{
    tl_timeline both, alone;
    if (two_boats(RESCUE_X, RESCUE_Z, "", &both))
        return;
    tl_scene s, a;
    tl_timeline_eval(&both, AT, &s);
    CHECK(s.objects == 2);
    CHECK(s.boat.enabled && s.fleet[0].enabled);
    CHECK_NEAR(s.fleet[0].length, 10.0, 1e-9);
    CHECK_NEAR(s.boat.length, 8.0, 1e-9);
    char text[1024];
    snprintf(text, sizeof text, HEADER "set boat.size 10\npath boat\n  0s %g %g\n  4s %g %g\n",
             RESCUE_X, RESCUE_Z, RESCUE_X, RESCUE_Z + 12.0);
    if (parse(text, &alone))
        return;
    tl_timeline_eval(&alone, AT, &a);
    printf("rescue at %.4f %.4f %.4f, pitch %.4f, roll %.4f; alone %.4f %.4f %.4f\n",
           s.fleet[0].position[0], s.fleet[0].position[1], s.fleet[0].position[2], s.fleet[0].pitch,
           s.fleet[0].roll, a.boat.position[0], a.boat.position[1], a.boat.position[2]);
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(s.fleet[0].position[i], a.boat.position[i], 1e-12);
    CHECK_NEAR(s.fleet[0].pitch, a.boat.pitch, 1e-12);
    CHECK_NEAR(s.fleet[0].roll, a.boat.roll, 1e-12);
    CHECK_NEAR(s.fleet[0].heading, a.boat.heading, 1e-12);
    CHECK_NEAR(s.fleet[0].impact, a.boat.impact, 1e-12);
    /* The two ride different water. */
    CHECK(fabs(s.fleet[0].position[1] - s.boat.position[1]) > 1e-4 ||
          fabs(s.fleet[0].roll - s.boat.roll) > 1e-4);
    tl_timeline_free(&alone);
    tl_timeline_free(&both);
}

/* The frame's slots: both in view, each with its own wake along its own
 * path and its own shadow layer. */
static void test_slots(const tl_frame_uniforms *u, const tl_scene *s)
{
    CHECK(u->object_count == 2);
    CHECK(u->features & TL_FEATURE_BOAT);
    CHECK(u->features & TL_FEATURE_WAKE);
    CHECK(u->features & TL_FEATURE_BOAT_SHADOW);
    for (int k = 0; k < 2 && k < u->object_count; k++) {
        const tl_boat *b = tl_scene_object_const(s, k);
        const tl_object_uniforms *o = &u->objects[k];
        CHECK(u->object_pass[k].object == k);
        CHECK(u->object_pass[k].drawn);
        CHECK(o->wake_params[2] > 0.0f);
        CHECK_NEAR(o->wake[0][0], b->position[0] - s->camera.position[0], 1e-4);
        CHECK_NEAR(o->wake[0][1], b->position[2] - s->camera.position[2], 1e-4);
        CHECK_NEAR(o->wake_params[3], b->length, 1e-5);
        CHECK_NEAR(o->hull[3], (float)k, 0.0); /* shadow layers 0 and 1 */
        CHECK(u->object_pass[k].shadow_size > 0);
    }
}

static void test_pixels(tl_renderer *r)
{
    static unsigned char rescue_a[W * H], rescue_b[W * H], boat_only[W * H], moved[W * H],
        added[W * H], shadow[W * H], both_allowed[W * H];
    tl_frame a = {0}, b = {0}, boat = {0}, ra = {0}, rb = {0}, empty = {0}, unshadowed = {0};
    tl_frame_uniforms u;
    const double x = RESCUE_X, z = RESCUE_Z;
    int rc = shot(r, x, z, "", &a, &u);
    if (!rc) {
        tl_timeline tl;
        two_boats(x, z, "", &tl);
        tl_scene s;
        tl_timeline_eval(&tl, AT, &s);
        tl_timeline_free(&tl);
        test_slots(&u, &s);
    }
    rc = rc || shot(r, x, z + 2.0, "", &b, &u);
    rc = rc || shot(r, x, z, "set rescue.visible off", &boat, &u);
    rc = rc || shot(r, x, z, "set boat.visible off", &ra, &u);
    rc = rc || shot(r, x, z + 2.0, "set boat.visible off", &rb, &u);
    rc = rc || shot(r, x, z, "set boat.visible off\nset rescue.visible off", &empty, &u);
    rc = rc || shot(r, x, z, "set rescue.shadows off", &unshadowed, &u);
    if (!rc) {
        long na = diff_mask(&ra, &empty, rescue_a), nb = diff_mask(&rb, &empty, rescue_b);
        long nboat = diff_mask(&boat, &empty, boat_only);
        long nmoved = diff_mask(&a, &b, moved), nadded = diff_mask(&a, &boat, added);
        long nshadow = diff_mask(&a, &unshadowed, shadow);
        dilate(rescue_a, 2);
        dilate(rescue_b, 2);
        for (int i = 0; i < W * H; i++)
            both_allowed[i] = rescue_a[i] || rescue_b[i];
        long overlap = 0;
        for (int i = 0; i < W * H; i++)
            overlap += boat_only[i] && rescue_a[i];
        long stray_moved = outside(moved, both_allowed), stray_added = outside(added, rescue_a);
        long stray_shadow = outside(shadow, rescue_a);
        printf("pixels: the rescue boat's %ld (moved: %ld), the boat's %ld, both %ld; moving the "
               "rescue boat changes %ld, %ld of them outside its own; adding it %ld, %ld "
               "outside; its shadow %ld, %ld outside\n",
               na, nb, nboat, overlap, nmoved, stray_moved, nadded, stray_added, nshadow,
               stray_shadow);
        CHECK(na > 200 && nb > 200 && nboat > 200);
        CHECK(overlap < nboat / 2); /* apart on screen: the test can tell them apart */
        CHECK(nmoved > 50);
        CHECK(stray_moved == 0);
        CHECK(nadded > 50);
        CHECK(stray_added == 0);
        CHECK(nshadow > 20); /* the rescue boat's own shadow, on itself and the water */
        CHECK(stray_shadow == 0);
    }
    tl_frame_free(&a);
    tl_frame_free(&b);
    tl_frame_free(&boat);
    tl_frame_free(&ra);
    tl_frame_free(&rb);
    tl_frame_free(&empty);
    tl_frame_free(&unshadowed);
}

int main(void)
{
    test_float_alone();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    CHECK(r != NULL);
    if (r) {
        tl_mesh boat;
        tl_error err;
        tl_error_clear(&err);
        CHECK(tl_mesh_default_boat(&boat, &err) == 0);
        CHECK(tl_renderer_set_mesh(r, &boat, &err) == 0);
        test_pixels(r);
        tl_mesh_free(&boat);
        tl_renderer_destroy(r);
        tl_gl_context_destroy(ctx);
    }
    TEST_END();
}
