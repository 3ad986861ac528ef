/* The boat on the GPU (llvmpipe on CI): its distance in the frame against
 * a CPU ray cast into the same mesh, the water it hides, a loaded model in
 * place of the built-in boat, no water on deck when the boat sits low, its
 * wake: culled exactly, and swept off the giant wave's face, and its mirror
 * image: culled exactly, and hidden where a swell stands between.
 * argv[1] is tests/meshes, argv[2] timelines/. */
#include <string.h>

#include "mesh/tl_mesh.h"
#include "timeline/tl_parse.h"
#include "tl_gl_test.h"

/* A camera 14 m off the boat's starboard quarter, 4 m up, looking at it. */
static void boat_scene(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 160;
    s->height = 96;
    s->time = 2.0;
    s->boat.enabled = true;
    s->boat.position[0] = 0.0;
    s->boat.position[1] = -0.4;
    s->boat.position[2] = 0.0;
    s->boat.heading = 0.3;
    s->boat.pitch = 0.02;
    s->boat.roll = -0.03;
    s->camera.position[0] = 10.0;
    s->camera.position[1] = 4.0;
    s->camera.position[2] = -10.0;
    const double target[3] = {0.0, 0.5, 0.0};
    tl_scene_camera_look_at(&s->camera, target, NULL);
}

/* Möller-Trumbore: distance along the unit ray from o to the triangle. */
static double ray_triangle(const double o[3], const double d[3], const double a[3],
                           const double b[3], const double c[3])
{
    double e1[3], e2[3], p[3], q[3], t[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = b[i] - a[i];
        e2[i] = c[i] - a[i];
        t[i] = o[i] - a[i];
    }
    p[0] = d[1] * e2[2] - d[2] * e2[1];
    p[1] = d[2] * e2[0] - d[0] * e2[2];
    p[2] = d[0] * e2[1] - d[1] * e2[0];
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (fabs(det) < 1e-15)
        return INFINITY;
    double u = (t[0] * p[0] + t[1] * p[1] + t[2] * p[2]) / det;
    q[0] = t[1] * e1[2] - t[2] * e1[1];
    q[1] = t[2] * e1[0] - t[0] * e1[2];
    q[2] = t[0] * e1[1] - t[1] * e1[0];
    double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    double dist = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return u >= 0.0 && v >= 0.0 && u + v <= 1.0 && dist > 0.0 ? dist : INFINITY;
}

/* The nearest hit of the pixel centre's ray with the mesh placed as the
 * renderer places it (the prepare step's model matrix). */
static double cast_into_mesh(const tl_scene *s, const tl_mesh *m, int px, int py)
{
    tl_waves w;
    tl_waves_init(&w, &s->ocean);
    tl_frame_uniforms u;
    tl_prepare_frame(s, &w, &u);
    double ray[3];
    pixel_ray(s, px, py, ray);
    const double origin[3] = {0.0, 0.0, 0.0}; /* camera-relative */
    double best = INFINITY;
    for (size_t t = 0; t < m->index_count; t += 3) {
        double v[3][3];
        for (int k = 0; k < 3; k++) {
            const float *p = m->positions + 3 * m->indices[t + k];
            for (int i = 0; i < 3; i++) /* column-major: row i of M times (p, 1) */
                v[k][i] = u.object_pass[0].model[i] * p[0] + u.object_pass[0].model[4 + i] * p[1] +
                          u.object_pass[0].model[8 + i] * p[2] + u.object_pass[0].model[12 + i];
        }
        best = fmin(best, ray_triangle(origin, ray, v[0], v[1], v[2]));
    }
    return best;
}

/* The boat's distance in the frame matches a CPU ray cast at its centre
 * and around it, wherever the hull stands above the water (the water hides
 * what is under it); without the boat the same pixels show water, farther. */
static void test_depth(tl_renderer *r, const tl_mesh *m, const char *name, tl_scene *s)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_frame with, without;
    if (render(r, s, &with))
        return;
    tl_scene calm = *s;
    calm.boat.enabled = false;
    if (render(r, &calm, &without)) {
        tl_frame_free(&with);
        return;
    }
    /* Where the boat's centre projects. */
    tl_waves w;
    tl_waves_init(&w, &s->ocean);
    tl_frame_uniforms u;
    tl_prepare_frame(s, &w, &u);
    CHECK(u.features & TL_FEATURE_BOAT);
    float c[4] = {u.object_pass[0].model[12], u.object_pass[0].model[13],
                  u.object_pass[0].model[14], 1.0f},
          clip[4] = {0};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            clip[i] += u.view_proj[k * 4 + i] * c[k];
    int cx = (int)((clip[0] / clip[3] * 0.5 + 0.5) * s->width);
    int cy = s->height - 1 - (int)((clip[1] / clip[3] * 0.5 + 0.5) * s->height);
    int checked = 0, close = 1, water_behind = 1, differs = 1;
    double worst = 0.0;
    for (int dy = -3; dy <= 3; dy++)
        for (int dx = -3; dx <= 3; dx++) {
            int x = cx + dx, y = cy + dy;
            double want = cast_into_mesh(s, m, x, y);
            if (!isfinite(want) || want >= without.depth[(size_t)y * s->width + x] - 0.2)
                continue; /* no hull here, or under the water */
            float got = with.depth[(size_t)y * s->width + x];
            size_t at = ((size_t)y * s->width + x) * 4;
            differs &= memcmp(with.color + at, without.color + at, 3 * sizeof(float)) != 0;
            worst = fmax(worst, fabs(got - want));
            close &= fabs(got - want) <= 0.5;
            water_behind &= without.depth[(size_t)y * s->width + x] > got;
            checked++;
        }
    printf("%s: %d pixels round its centre (%d, %d): max |Z - ray cast| = %.3g m\n", name, checked,
           cx, cy, worst);
    CHECK(checked >= 10);
    CHECK(close);
    CHECK(water_behind);
    /* The frames differ where the boat is, and only finite, non-negative
     * light reaches a pixel. */
    CHECK(differs);
    int finite = 1;
    for (size_t i = 0; i < (size_t)s->width * s->height * 4; i++)
        finite &= isfinite(with.color[i]) && with.color[i] >= 0.0f;
    CHECK(finite);
    tl_frame_free(&with);
    tl_frame_free(&without);
}

/* Over the pixels where frames a and b differ, their summed radiance
 * error against `ref` (4x their size) box-filtered down: into *err_a and
 * *err_b. Returns how many pixels differ. */
static int box_errors(const tl_frame *ref, const tl_frame *a, const tl_frame *b, double *err_a,
                      double *err_b)
{
    int pixels = 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            double box[3] = {0, 0, 0};
            for (int j = 0; j < 4; j++)
                for (int i = 0; i < 4; i++)
                    for (int c = 0; c < 3; c++)
                        box[c] +=
                            ref->color[((size_t)(4 * y + j) * ref->width + 4 * x + i) * 4 + c] /
                            16.0;
            size_t at = ((size_t)y * a->width + x) * 4;
            int differ = 0;
            for (int c = 0; c < 3; c++)
                differ |= fabs(a->color[at + c] - b->color[at + c]) > 1e-5f;
            for (int c = 0; differ && c < 3; c++) {
                *err_a += fabs(a->color[at + c] - box[c]);
                *err_b += fabs(b->color[at + c] - box[c]);
            }
            pixels += differ;
        }
    return pixels;
}

/* At one sample a pixel, the hulls' pass at 2 x 2 samples a pixel
 * (quality.mesh_scale 2, `final`'s) comes closer to the frame rendered at
 * 4x the size and box-filtered down than one sample (mesh_scale 1) over
 * the pixels where the two differ (the hull's edges and paint lines):
 * antialiased. The water is the same in both. */
static void test_mesh_scale(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_scene(&s);
    s.quality.lod = false; /* the same water detail at both sizes */
    s.quality.spp = 1;
    tl_scene big = s, two = s;
    big.width *= 4;
    big.height *= 4;
    big.quality.mesh_scale = 1;
    s.quality.mesh_scale = 1;
    two.quality.mesh_scale = 2;
    tl_frame ref, one, fine;
    if (render(r, &big, &ref))
        return;
    if (render(r, &s, &one) || render(r, &two, &fine)) {
        tl_frame_free(&ref);
        return;
    }
    double err_one = 0.0, err_two = 0.0;
    int pixels = box_errors(&ref, &one, &fine, &err_one, &err_two);
    printf("the hulls' pass at 2x2 samples against 4x the size, box-filtered, over the %d pixels "
           "where it differs from one sample: one %.3f, 2x2 %.3f (summed radiance error)\n",
           pixels, err_one, err_two);
    CHECK(pixels > 50);
    CHECK(err_two < 0.8 * err_one);
    tl_frame_free(&ref);
    tl_frame_free(&one);
    tl_frame_free(&fine);
}

/* From just under the surface, level with the boat: between the keel and
 * the surface the eye sees the surface's underside, which mirrors the
 * hull's part below the water (total internal reflection). Where the ray
 * ends on the surface in both frames, the frame with the boat differs from
 * the one without over a band above the hull, and only there. */
static void test_underside_mirror(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_scene(&s);
    s.quality.mesh_scale = 1;
    s.boat.pitch = s.boat.roll = 0.0;
    s.boat.heading = 0.0;
    s.ocean.depth = 0.3; /* a low chop: the underside mirrors */
    s.camera.position[0] = 9.0;
    s.camera.position[1] = -0.35;
    s.camera.position[2] = 0.0;
    s.camera.yaw = -90.0 * M_PI / 180.0;
    s.camera.pitch = 2.0 * M_PI / 180.0;
    tl_frame with, without;
    if (render_boat_pair(r, &s, &with, &without))
        return;
    long mirrored = 0, surface = 0;
    /* The image's far edge: per column, the row furthest from the hull
     * (rows run top first: the smallest) that the image changed. */
    int edge[256];
    CHECK(s.width <= 256);
    for (int x = 0; x < s.width && x < 256; x++)
        edge[x] = -1;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            size_t i = (size_t)y * s.width + x;
            /* The ray ends on the surface in both (not on the hull, not in
             * the depths). */
            if (!(with.depth[i] < 1e5f && fabsf(with.depth[i] - without.depth[i]) < 0.01f))
                continue;
            surface++;
            double seen = luminance(with.color + 4 * i), bare = luminance(without.color + 4 * i);
            int changed = fabs(seen - bare) > 0.05 * bare;
            mirrored += changed;
            if (changed && x < 256 && edge[x] < 0)
                edge[x] = y;
        }
    /* How far the edge jumps from column to column: the ripples' own
     * normal broke it into a serrated fringe (0.22 rows a column here;
     * the waves at a metre's detail, 0.10). */
    double jump = 0.0;
    int pairs = 0;
    for (int x = 0; x + 1 < s.width && x + 1 < 256; x++)
        if (edge[x] >= 0 && edge[x + 1] >= 0) {
            jump += abs(edge[x + 1] - edge[x]);
            pairs++;
        }
    jump /= pairs > 0 ? pairs : 1;
    printf("from under the surface: %ld of %ld pixels of the surface's underside changed by the "
           "hull mirrored in it; its far edge moves %.2f rows a column over %d columns\n",
           mirrored, surface, jump, pairs);
    CHECK(surface > 1000);
    CHECK(mirrored > 50);
    CHECK(mirrored < surface / 2);
    CHECK(pairs > s.width / 4);
    CHECK(jump < 0.16);
    tl_frame_free(&with);
    tl_frame_free(&without);
}

/* A boat that came round a bend at 6 m/s, seen from above its stern: its
 * wake curves away in front of the camera, thick with foam. */
static void wake_scene(tl_scene *s)
{
    boat_scene(s);
    const double speed = 6.0, radius = 40.0;
    s->boat.wake_step = 2.0 * s->boat.wake_time / (TL_WAKE_POINTS - 1);
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        double turn = k * s->boat.wake_step * speed / radius;
        s->boat.wake_path[k][0] = radius * (1.0 - cos(turn));
        s->boat.wake_path[k][1] = -radius * sin(turn);
        s->boat.wake_along[k] = 100.0 - radius * turn;
    }
    s->boat.heading = 0.0;
    s->boat.wake = 3.0; /* foam down to the path's far end */
    s->camera.position[0] = 12.0;
    s->camera.position[1] = 14.0;
    s->camera.position[2] = 18.0;
    const double target[3] = {8.0, 0.0, -30.0};
    tl_scene_camera_look_at(&s->camera, target, NULL);
}

/* The wake's groups of segments (tl_prepare, shaders/wake.glsl) cull none
 * of its foam. On the CPU, every point a segment's foam can reach (the
 * shader's own test, in float) lies in its group's circle; on the GPU the
 * frame equals the one with every circle covering the whole sea, and
 * differs from the frame without the wake. */
static void test_wake_groups(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    wake_scene(&s);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_WAKE);
    const float half_beam = u.objects[0].wake_params[0];
    long reached = 0, outside = 0;
    for (int j = 0; j <= 400; j++)
        for (int i = 0; i <= 400; i++) {
            float p[2] = {u.objects[0].wake[0][0] - 80.0f + 0.45f * (float)i,
                          u.objects[0].wake[0][1] - 100.0f + 0.45f * (float)j};
            for (int k = 0; k + 1 < TL_WAKE_POINTS; k++) {
                float ax = u.objects[0].wake[k][0], az = u.objects[0].wake[k][1];
                float bx = u.objects[0].wake[k + 1][0] - ax, bz = u.objects[0].wake[k + 1][1] - az;
                float len2 = bx * bx + bz * bz;
                if (len2 < 1.0e-8f)
                    continue;
                float along = ((p[0] - ax) * bx + (p[1] - az) * bz) / len2;
                float t = fminf(fmaxf(along, 0.0f), 1.0f);
                float d = hypotf(p[0] - (ax + bx * t), p[1] - (az + bz * t));
                float behind = u.objects[0].wake[k][3] +
                               (u.objects[0].wake[k + 1][3] - u.objects[0].wake[k][3]) * t;
                if (d > (half_beam + behind * 0.35355f) * 1.3f + 2.0f)
                    continue;
                const float *c = u.objects[0].wake_groups[k / TL_WAKE_GROUP];
                float cx = p[0] - c[0], cz = p[1] - c[1];
                reached++;
                outside += cx * cx + cz * cz > c[2] * c[2];
            }
        }
    printf("wake: %ld (point, segment) pairs in the foam's reach, %ld outside their group's "
           "circle\n",
           reached, outside);
    CHECK(reached > 10000);
    CHECK(outside == 0);

    tl_frame culled, all, none;
    CHECK(tl_frame_alloc(&culled, s.width, s.height, &err) == 0);
    CHECK(tl_frame_alloc(&all, s.width, s.height, &err) == 0);
    CHECK(tl_renderer_render(r, &u, &culled, &err) == 0);
    tl_frame_uniforms everywhere = u;
    for (int g = 0; g < TL_WAKE_GROUPS; g++) {
        everywhere.objects[0].wake_groups[g][0] = everywhere.objects[0].wake_groups[g][1] = 0.0f;
        everywhere.objects[0].wake_groups[g][2] = 1.0e18f;
    }
    CHECK(tl_renderer_render(r, &everywhere, &all, &err) == 0);
    size_t n = (size_t)s.width * s.height * 4;
    CHECK(memcmp(culled.color, all.color, n * sizeof(float)) == 0);
    s.boat.wake = 0.0;
    if (render(r, &s, &none) == 0) {
        long foam = lighter_pixels(&culled, &none);
        printf("wake: %ld of %d pixels lighter with its foam\n", foam, s.width * s.height);
        CHECK(foam > 200);
        tl_frame_free(&none);
    }
    tl_frame_free(&culled);
    tl_frame_free(&all);
}

/* Frame `frame` of timelines/`name` at 240x135 into `s`, with the mesh
 * `m` set; 0 when the timeline parsed. */
static int cutscene_frame(tl_renderer *r, const tl_mesh *m, const char *timelines, const char *name,
                          int frame, tl_scene *s)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", timelines, name);
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_timeline_parse_file(path, &tl, &diags, &err);
    CHECK(rc == TL_OK);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    if (rc != TL_OK)
        return rc;
    tl_timeline_eval(&tl, tl_timeline_frame_time(&tl, frame), s);
    tl_timeline_free(&tl);
    s->width = 240;
    s->height = 135;
    return 0;
}

/* As cutscene_frame, with the line `from` of the timeline replaced by
 * `to` (which must be there). */
static int cutscene_frame_edited(tl_renderer *r, const tl_mesh *m, const char *timelines,
                                 const char *name, int frame, const char *from, const char *to,
                                 tl_scene *s)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", timelines, name);
    FILE *f = fopen(path, "rb");
    CHECK(f != NULL);
    if (!f)
        return 1;
    static char text[65536], edited[65536 + 256];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    const char *at = strstr(text, from);
    CHECK(at != NULL && strlen(to) < 256);
    if (!at || strlen(to) >= 256)
        return 1;
    snprintf(edited, sizeof edited, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_timeline_parse_text(name, edited, strlen(edited), &tl, &diags, &err);
    CHECK(rc == TL_OK);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    if (rc != TL_OK)
        return rc;
    tl_timeline_eval(&tl, tl_timeline_frame_time(&tl, frame), s);
    tl_timeline_free(&tl);
    s->width = 240;
    s->height = 135;
    return 0;
}

/* The hero cutscene's frame 216: the boat, ending its turn, heads down
 * into the trough ahead of the giant wave's face, its wake's path on the
 * water the wave lowers and lifts. The wave sweeps the wake away, so the
 * frame is the one without the wake; the foam once showed as a white trail
 * where the face crosses the mean water level (the wave's height alone
 * gated it). */
static void test_wake_swept(tl_renderer *r, const tl_mesh *m, const char *timelines)
{
    tl_scene s;
    if (cutscene_frame(r, m, timelines, "giant_wave.tl", 216, &s))
        return;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_WAKE);
    CHECK(u.features & TL_FEATURE_GIANT_WAVE);
    tl_frame with, without;
    if (render_wake_pair(r, &s, &with, &without))
        return;
    long foam = lighter_pixels(&with, &without);
    printf("giant_wave.tl frame 216: %ld pixels lighter with the wake\n", foam);
    CHECK(foam == 0);
    tl_frame_free(&without);
    tl_frame_free(&with);
}

/* Pixels of `a` and `b` whose colour differs by more than 1% (and 1e-4),
 * among those `mask` keeps (NULL: all). */
static long differing_pixels(const tl_frame *a, const tl_frame *b, const unsigned char *mask)
{
    long n = 0;
    for (int i = 0; i < a->width * a->height; i++) {
        if (mask && !mask[i])
            continue;
        double la = luminance(a->color + (size_t)i * 4), lb = luminance(b->color + (size_t)i * 4);
        n += fabs(la - lb) > fmax(1.0e-4, 0.01 * fmax(la, lb));
    }
    return n;
}

/* The hull's mirror image in the water next to it (boat_scene): the
 * programs that draw it run only inside u.plan.boat_mirror_rect, which culls
 * none of it (the frame equals the one with the rectangle covering the
 * whole frame, bit for bit), and there is an image to cull (the frame
 * with an empty rectangle, no image anywhere, differs). */
static void test_mirror_rect(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_scene(&s);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    const int *rect = u.plan.boat_mirror_rect;
    long area = (long)(rect[2] - rect[0]) * (rect[3] - rect[1]);
    printf("mirror image: rectangle %d,%d .. %d,%d (%ld of %d pixels)\n", rect[0], rect[1], rect[2],
           rect[3], area, s.width * s.height);
    CHECK(area > 0 && area < s.width * s.height / 2);
    tl_frame_uniforms whole = u, none = u;
    const int all[4] = {0, 0, s.width, s.height}, empty[4] = {0, 0, 0, 0};
    memcpy(whole.plan.boat_mirror_rect, all, sizeof all);
    memcpy(none.plan.boat_mirror_rect, empty, sizeof empty);
    tl_frame culled, everywhere, without;
    if (render_prepared(r, &u, s.width, s.height, &culled))
        return;
    if (render_prepared(r, &whole, s.width, s.height, &everywhere) == 0) {
        size_t n = (size_t)s.width * s.height * 4;
        CHECK(memcmp(culled.color, everywhere.color, n * sizeof(float)) == 0);
        tl_frame_free(&everywhere);
    }
    if (render_prepared(r, &none, s.width, s.height, &without) == 0) {
        long image = differing_pixels(&culled, &without, NULL);
        printf("mirror image: %ld pixels show it\n", image);
        CHECK(image > 20);
        tl_frame_free(&without);
    }
    tl_frame_free(&culled);
}

/* The hero cutscene's frame 120, the giant wave arriving at 8.7 s: the
 * camera rides a swell's back, and the boat lies beyond its crest, low in
 * the trough ahead of the giant wave. The hull's mirror image lands, on
 * screen, on the swell's near face, which cannot mirror the hull: it lies
 * far above the plane the image mirrors in. The hull's dark image was
 * drawn there (and the mast's, a wavering line; 951 of the near water's
 * pixels at this size); the water nearer than 0.6 of the boat's distance
 * now shows almost none of it (the frame with no image at all, the
 * mirror's rectangle empty, is the yardstick). The timeline's own arrival
 * (10.5 s) once put the boat there too, while `follow giant.center boat`
 * carried the wave along with the boat; now that it aims the wave (along
 * the travel, at where the boat is at the arrival) the crest is 25 m
 * further off at 5 s and the boat floats on the level sea, its water only
 * 0.27 m below the camera's, where its image on the near water is a true
 * one. Arriving 1.8 s earlier brings the trough back under the boat (its
 * broad bottom, since the profile lifts the troughs). */
static void test_mirror_hidden(tl_renderer *r, const tl_mesh *m, const char *timelines)
{
    tl_scene s;
    if (cutscene_frame_edited(r, m, timelines, "voyage.tl", 120, "set giant.arrival 10.5s",
                              "set giant.arrival 8.7s", &s))
        return;
    /* The camera where the timeline once had it at 5 s, 24 m off, low on
     * a swell's back (it now rides beside the boat at the deck's height). */
    s.camera.position[0] = -10.247;
    s.camera.position[1] = 2.563;
    s.camera.position[2] = 12.517;
    s.camera.yaw = 40.118 * M_PI / 180.0;
    s.camera.pitch = 2.273 * M_PI / 180.0;
    s.camera.vfov = 49.697 * M_PI / 180.0;
    /* The premise: the boat's water well below the camera's. */
    tl_waves waves;
    tl_waves_init(&waves, &s.ocean);
    tl_giant giant;
    tl_giant_prepare(&giant, &s.giant, s.time);
    const int mo = s.quality.march_octaves, gi = s.quality.giant_iterations;
    double under_boat = tl_waves_surface_height(&waves, &giant, s.boat.position[0],
                                                s.boat.position[2], s.time, mo, gi);
    double under_camera = tl_waves_surface_height(&waves, &giant, s.camera.position[0],
                                                  s.camera.position[2], s.time, mo, gi);
    printf("voyage.tl frame 120, arriving at 8.7 s: the water %.2f m under the boat, %.2f m under "
           "the camera\n",
           under_boat, under_camera);
    CHECK(under_boat < under_camera - 1.5);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_BOAT);
    CHECK(u.plan.boat_mirror_rect[0] < u.plan.boat_mirror_rect[2]);
    tl_frame_uniforms none = u;
    memset(none.plan.boat_mirror_rect, 0, sizeof none.plan.boat_mirror_rect);
    tl_frame with, without;
    if (render_prepared(r, &u, s.width, s.height, &with))
        return;
    if (render_prepared(r, &none, s.width, s.height, &without)) {
        tl_frame_free(&with);
        return;
    }
    double d[3];
    for (int i = 0; i < 3; i++)
        d[i] = s.boat.position[i] - s.camera.position[i];
    const double boat = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    unsigned char *near = calloc((size_t)s.width * s.height, 1);
    long water = 0;
    for (int i = 0; near && i < s.width * s.height; i++) {
        near[i] = with.depth[i] < 0.6 * boat;
        water += near[i];
    }
    long shown = near ? differing_pixels(&with, &without, near) : -1;
    printf("voyage.tl frame 120: the boat %.1f m away; %ld of the %ld water pixels nearer than "
           "0.6 of that show its mirror image\n",
           boat, shown, water);
    CHECK(water > 2000);
    CHECK(shown >= 0 && shown <= water / 200);
    free(near);
    tl_frame_free(&with);
    tl_frame_free(&without);
}

/* A boat floating low, its deck below the water around it: looking down
 * into it shows the deck, never water inside the hull. */
static void test_no_water_on_deck(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_scene(&s);
    s.boat.position[1] = -1.2; /* deck about 0.55 m under the mean water */
    s.boat.heading = 0.0;
    s.boat.pitch = s.boat.roll = 0.0;
    s.camera.position[0] = 0.0;
    s.camera.position[1] = 12.0;
    s.camera.position[2] = -2.0;
    s.camera.yaw = 0.0;
    s.camera.pitch = -80.0 * M_PI / 180.0;
    tl_frame f;
    if (render(r, &s, &f))
        return;
    int cx = s.width / 2, cy = s.height / 2;
    double want = cast_into_mesh(&s, m, cx, cy);
    float got = f.depth[(size_t)cy * s.width + cx];
    printf("low boat: deck at %.3f m, frame Z %.3f m\n", want, got);
    CHECK(isfinite(want));
    CHECK(fabs(got - want) <= 0.5);
    tl_frame_free(&f);
}

/* The foam where the hull meets the water needs water that meets it: a
 * boat at rest whitens the water along its side (against the same sea
 * without the boat); held 3 m up, over water far below its keel (seen
 * under it), it whitens none of it (its shadow only darkens). */
static void test_contact_needs_water(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    long whiter[2] = {0, 0}, water[2] = {0, 0};
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        boat_scene(&s);
        s.boat.heading = 0.0;
        s.boat.pitch = s.boat.roll = 0.0;
        s.boat.position[1] = k == 0 ? -0.4 : 3.0;
        s.width = 480; /* the line is a few pixels wide at this size */
        s.height = 288;
        tl_frame with, without;
        if (render_boat_pair(r, &s, &with, &without))
            return;
        for (size_t i = 0; i < (size_t)s.width * s.height; i++) {
            if (!(with.depth[i] < 1e5f && fabsf(with.depth[i] - without.depth[i]) < 0.01f))
                continue; /* the hull, or its foam's water hidden */
            water[k]++;
            whiter[k] += luminance(with.color + 4 * i) > luminance(without.color + 4 * i) + 0.05;
        }
        tl_frame_free(&with);
        tl_frame_free(&without);
    }
    printf("contact foam: %ld of %ld water pixels whiter at rest, %ld of %ld held 3 m up\n",
           whiter[0], water[0], whiter[1], water[1]);
    CHECK(water[0] > 1000 && water[1] > 1000);
    CHECK(whiter[0] > 100);
    CHECK(whiter[1] < whiter[0] / 50);
}

/* The nearest hit of pixel (px, py)'s ray with the mesh placed by `u`:
 * its distance (INFINITY for none), the hit in model units and its
 * triangle's model normal's y, facing up. */
static double cast_hit(const tl_scene *s, const tl_mesh *m, const tl_frame_uniforms *u, int px,
                       int py, double model_hit[3], double *normal_y)
{
    double ray[3];
    pixel_ray(s, px, py, ray);
    const double origin[3] = {0.0, 0.0, 0.0};
    double best = INFINITY;
    size_t hit = 0;
    for (size_t t = 0; t < m->index_count; t += 3) {
        double v[3][3];
        for (int k = 0; k < 3; k++) {
            const float *p = m->positions + 3 * m->indices[t + k];
            for (int i = 0; i < 3; i++)
                v[k][i] = u->object_pass[0].model[i] * p[0] +
                          u->object_pass[0].model[4 + i] * p[1] +
                          u->object_pass[0].model[8 + i] * p[2] + u->object_pass[0].model[12 + i];
        }
        double d = ray_triangle(origin, ray, v[0], v[1], v[2]);
        if (d < best) {
            best = d;
            hit = t;
        }
    }
    if (!isfinite(best))
        return best;
    double w[3] = {ray[0] * best, ray[1] * best, ray[2] * best};
    for (int i = 0; i < 3; i++)
        model_hit[i] = u->objects[0].to_model[i] * w[0] + u->objects[0].to_model[4 + i] * w[1] +
                       u->objects[0].to_model[8 + i] * w[2] + u->objects[0].to_model[12 + i];
    const float *a = m->positions + 3 * m->indices[hit],
                *b = m->positions + 3 * m->indices[hit + 1],
                *c = m->positions + 3 * m->indices[hit + 2];
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
           e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    *normal_y = fabs(n[1]) / sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return best;
}

/* The clip surface: a boat pitched bow up with its stern deck below the
 * sea, seen from above and astern. Over every pixel where the CPU's ray
 * meets the deck, the frame shows the deck, not water nearer than it,
 * though at many of them the sea outside stands above the deck. */
static void test_pitched_deck(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_scene(&s);
    s.quality.mesh_scale = 1; /* the CPU's ray through each pixel's centre */
    s.boat.heading = 0.0;
    s.boat.pitch = 0.25; /* bow up, 14 degrees: the stern deck goes under */
    s.boat.roll = 0.05;
    s.boat.position[1] = -0.3;
    s.camera.position[0] = 2.5;
    s.camera.position[1] = 6.0;
    s.camera.position[2] = -9.0;
    const double target[3] = {0.0, 0.0, -2.5};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    tl_frame f;
    if (render(r, &s, &f))
        return;
    tl_frame_uniforms u;
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_prepare_frame(&s, &w, &u);
    int deck = 0, under = 0, water = 0;
    for (int y = 0; y < s.height; y += 2)
        for (int x = 0; x < s.width; x += 2) {
            double mh[3], ny;
            double d = cast_hit(&s, m, &u, x, y, mh, &ny);
            /* The deck: faces up, above the waterline, inside the bulwarks. */
            if (!isfinite(d) || ny < 0.9 || mh[1] < 0.05 || fabs(mh[0]) > 0.1)
                continue;
            deck++;
            double ray[3];
            pixel_ray(&s, x, y, ray);
            const double wx = s.camera.position[0] + ray[0] * d,
                         wy = s.camera.position[1] + ray[1] * d,
                         wz = s.camera.position[2] + ray[2] * d;
            under += tl_waves_height(&w, wx, wz, s.time, TL_MAX_OCTAVES) > wy;
            /* Water nearer than the deck, and within the hull's length:
             * inside it. (Beyond the transom a crest standing above the
             * deck rightly hides the deck's edge.) */
            float seen = f.depth[(size_t)y * s.width + x];
            double wm[3];
            for (int i = 0; i < 3; i++)
                wm[i] = u.objects[0].to_model[i] * ray[0] * seen +
                        u.objects[0].to_model[4 + i] * ray[1] * seen +
                        u.objects[0].to_model[8 + i] * ray[2] * seen +
                        u.objects[0].to_model[12 + i];
            if (seen < d - 0.05) {
                int inside = wm[2] > m->bounds_min[2] && wm[2] < m->bounds_max[2];
                water += inside;
                printf("  water over the deck at (%d, %d): deck at %.3f m (model %.3f %.3f %.3f), "
                       "water at %.3f m (model %.3f %.3f %.3f: %s the hull's length)\n",
                       x, y, d, mh[0], mh[1], mh[2], seen, wm[0], wm[1], wm[2],
                       inside ? "within" : "beyond");
            }
        }
    printf("pitched boat: %d deck pixels, %d of them below the sea outside, %d showing water "
           "inside the hull\n",
           deck, under, water);
    CHECK(deck > 80); /* enough of it sampled (the hatches cover a little) */
    CHECK(under > 20);
    CHECK(water == 0);
    tl_frame_free(&f);
}

/* Supersampled, the hull's edges are anti-aliased: a pass per sample with
 * the hull drawn at that sample's offset (tl_prepare_boat_sample, what
 * tl_render does with a boat in view) comes closer to the frame rendered
 * at 4x the size and box-filtered down than one pass of all the samples,
 * which draws the hull at the pixels' centres. Their water samples are the
 * same, so only the hull's pixels can tell them apart. */
static void test_hull_antialiased(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_scene(&s);
    s.quality.lod = false; /* the same water detail at both sizes */
    tl_scene big = s;
    big.width *= 4;
    big.height *= 4;
    s.quality.spp = 16;
    tl_frame ref, one, each;
    if (render(r, &big, &ref) || render(r, &s, &one))
        return;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(tl_frame_alloc(&each, s.width, s.height, &err) == 0);
    int rc = tl_renderer_begin(r, u.width, u.height, u.out_width, u.out_height, &err);
    for (int k = 0; !rc && k < 16; k++) {
        tl_frame_uniforms pass = u;
        tl_prepare_boat_sample(&pass, k);
        rc = tl_renderer_accumulate_sample(r, &pass, 1.0f / 16.0f, 1, k, &err);
    }
    const tl_display_settings display = tl_display_of(&u);
    if (!rc)
        rc = tl_renderer_finish(r, &display, TL_PLANES_ALL, &each, &err);
    CHECK(rc == 0);
    double err_one = 0.0, err_each = 0.0;
    int pixels = box_errors(&ref, &one, &each, &err_one, &err_each); /* they differ at the hull */
    printf("16 samples against 4x the size, box-filtered, over the %d pixels where they differ: "
           "one pass %.3f, a pass per sample %.3f (summed radiance error)\n",
           pixels, err_one, err_each);
    CHECK(pixels > 50);
    CHECK(err_each < 0.8 * err_one);
    tl_frame_free(&ref);
    tl_frame_free(&one);
    tl_frame_free(&each);
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return 1;
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    tl_error err;
    tl_error_clear(&err);
    tl_mesh builtin, skiff;
    char path[1024];
    snprintf(path, sizeof path, "%s/skiff.gltf", argv[1]);
    CHECK(tl_mesh_default_boat(&builtin, &err) == 0);
    CHECK(tl_mesh_load(path, &skiff, &err) == 0);

    /* The geometry checks take each pixel's centre ray, as a pass of one
     * sample a pixel draws it (quality.mesh_scale 1). */
    tl_scene s;
    boat_scene(&s);
    s.quality.mesh_scale = 1;
    test_depth(r, &builtin, "built-in boat", &s);
    /* A loaded model replaces it: the skiff (4 m long, 2 m wide, its top 1 m
     * above its origin) at 1 m per unit, its bounds given to the scene. */
    boat_scene(&s);
    s.quality.mesh_scale = 1;
    s.boat.scale = 1.0;
    for (int i = 0; i < 3; i++) {
        s.boat.model_min[i] = skiff.bounds_min[i];
        s.boat.model_max[i] = skiff.bounds_max[i];
    }
    test_depth(r, &skiff, "skiff.gltf", &s);
    test_no_water_on_deck(r, &builtin);
    test_pitched_deck(r, &builtin);
    test_contact_needs_water(r, &builtin);
    test_hull_antialiased(r, &builtin);
    test_mesh_scale(r, &builtin);
    test_underside_mirror(r, &builtin);
    test_wake_groups(r, &builtin);
    test_wake_swept(r, &builtin, argv[2]);
    test_mirror_rect(r, &builtin);
    test_mirror_hidden(r, &builtin, argv[2]);

    tl_mesh_free(&builtin);
    tl_mesh_free(&skiff);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
