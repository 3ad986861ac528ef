/* The screen rectangles of the features that only part of the frame can
 * show: the giant wave's, where the renderer draws the wave's program and
 * the lean ocean's everywhere else, and the boat's wake's, outside which
 * the programs leave the wake's foam out (docs/rendering.md, "Only the
 * pixels that can show the wave pay for it"). */
#include "tl_prepare_internal.h"

#include <math.h>
#include <string.h>

#include "waves/tl_bow_spray.h"

/* The longest shadow the crest casts on the water (giant_sunlit in
 * shaders/giant.glsl), metres along the sun's horizontal direction from
 * the crest line, for water no lower than the trough plane: there the
 * sun's ray has risen by dist·tan(elevation) and the crest is at most
 * `top` high, its penumbra 0.3 + 0.01·dist + 0.08·top wide. 0 without a
 * shadow (the sun down, or in line with the crest); HUGE_VAL for a sun so
 * low that no distance clears the penumbra. *along and *across: the sun's
 * horizontal direction in the wave's frame. */
static double shadow_reach(const tl_frame_uniforms *u, double top, double *along, double *across)
{
    const double sx = u->sun_dir[0], sy = u->sun_dir[1], sz = u->sun_dir[2];
    const double flat = sqrt(sx * sx + sz * sz);
    *along = *across = 0.0;
    if (!(sy > 0.0) || flat <= 1.0e-4)
        return 0.0;
    *along = (u->giant_frame[0] * sx + u->giant_frame[1] * sz) / flat;
    *across = (u->giant_frame[1] * sx - u->giant_frame[0] * sz) / flat;
    if (fabs(*along) < 1.0e-4)
        return 0.0;
    const double rise = sy / flat - 0.01;
    return rise > 0.0 ? (1.08 * top + 0.3 + u->depth) / rise : HUGE_VAL;
}

/* The box the wave's program must cover, in the wave's frame (along, up,
 * across; camera-relative along and across, absolute up): the wave's
 * bounding box (giant_ray_interval in shaders/giant.glsl, from the same
 * float uniforms), widened and, from a camera `min_y` or more above the
 * crest plane, cut.
 *
 * Widened: the water in the crest's shadow (giant_sunlit shades it, inside
 * the box or not) needs the wave's program, so the box takes in the
 * shadow's reach.
 *
 * Cut: only the box's part above the trough plane counts. A ray that
 * enters the box lower down crossed the trough plane outside it first,
 * where the ocean alone lies above that plane, so it met the water there
 * and never sees the wave. (The box reaches deep for the wave's troughs;
 * from a low camera in front of the wave its bottom took in every pixel
 * below the horizon: voyage's first shot.) Only where the lean program
 * starts from the march prepass too: without it (`seed`) the pixels that
 * leave the wave's program march from scratch, and voyage's frames took
 * longer. */
static void cover_box(const tl_frame_uniforms *u, double cam_y, double min_y, double lo[3],
                      double hi[3])
{
    const double top = (double)u->giant_bounds[3] * u->giant_shape[1];
    lo[0] = -(double)u->giant_bounds[0];
    hi[0] = u->giant_bounds[0];
    lo[1] = -(double)u->depth - top;
    hi[1] = top;
    lo[2] = -(double)u->giant_mask[2];
    hi[2] = u->giant_mask[2];
    if (cam_y >= min_y && u->plan.march_prepass)
        lo[1] = -(double)u->depth;
    /* The lip and the spray rise above the height field's top and reach
     * beyond its s (their own boxes, in the same frame): the wave's program
     * draws them, so its rectangle holds them too. */
    const float *more[2] = {u->features & TL_FEATURE_GIANT_LIP ? u->giant_lip_box : NULL,
                            u->features & TL_FEATURE_GIANT_SPRAY ? u->giant_spray_box : NULL};
    for (int i = 0; i < 2; i++)
        if (more[i]) {
            lo[0] = fmin(lo[0], more[i][0]);
            hi[0] = fmax(hi[0], more[i][1]);
            hi[1] = fmax(hi[1], more[i][3]);
        }
    if ((u->features & TL_FEATURE_GIANT_SPRAY) && u->giant_spray_bow[3] > 0.0) {
        /* The bow's burst: its sphere (spray.glsl's reach) in the wave's frame. */
        const double dx = u->giant_frame[0], dz = u->giant_frame[1];
        const double bx = u->giant_spray_bow[0], bz = u->giant_spray_bow[2];
        const double s = u->giant_frame[2] + dx * bx + dz * bz;
        const double w = u->giant_frame[3] + dz * bx - dx * bz;
        const double r = tl_bow_spray_reach(u->giant_spray[3], u->giant_spray_heading[2]);
        lo[0] = fmin(lo[0], s - r);
        hi[0] = fmax(hi[0], s + r);
        hi[1] = fmax(hi[1], u->giant_spray_bow[1] + r);
        lo[2] = fmin(lo[2], w - r);
        hi[2] = fmax(hi[2], w + r);
    }
    double along, across, shadow = shadow_reach(u, top, &along, &across);
    if (shadow <= 0.0)
        return;
    /* The shadow lies on the crest's side away from the sun: s below the
     * crest line (0 .. fade·C/k) when the sun is ahead of the travel,
     * above it when behind. A shadow of no finite reach makes the box
     * infinite, which the caller does not cull. */
    const double crest = (double)u->giant_bounds[3] * u->giant_shape[3] / u->giant_shape[0];
    if (along > 0.0)
        lo[0] = fmin(lo[0], -shadow * along);
    else
        hi[0] = fmax(hi[0], crest - shadow * along);
    lo[2] -= shadow * fabs(across);
    hi[2] += shadow * fabs(across);
}

/* a before b: by x, then y */
static int before(const double a[2], const double b[2])
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

/* Andrew's monotone chain: the convex hull of n points (n <= 32),
 * counter-clockwise into hull (room for 2n); returns its size. */
static int convex_hull(double (*p)[2], int n, double (*hull)[2])
{
    for (int i = 1; i < n; i++) /* insertion sort by x, then y */
        for (int j = i; j > 0 && before(p[j], p[j - 1]); j--) {
            double t[2] = {p[j][0], p[j][1]};
            memcpy(p[j], p[j - 1], sizeof t);
            memcpy(p[j - 1], t, sizeof t);
        }
    int k = 0;
    for (int pass = 0; pass < 2; pass++) {
        int floor_k = k;
        for (int step = 0; step < n; step++) {
            const double *q = p[pass == 0 ? step : n - 1 - step];
            while (k >= floor_k + 2) {
                const double *a = hull[k - 2], *b = hull[k - 1];
                if ((b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) > 0.0)
                    break;
                k--;
            }
            memcpy(hull[k++], q, sizeof hull[0]);
        }
        k--; /* the last point is the next chain's first */
    }
    return n < 3 ? n : k;
}

/* Clips a convex polygon to x in [x0, x1] and y in [y0, y1]
 * (Sutherland-Hodgman) and gives the bounds of what is left in
 * bounds (x0, y0, x1, y1); returns 0 if nothing is. */
static int clipped_bounds(double (*poly)[2], int n, const double clip[4], double bounds[4])
{
    double buf[2][48][2];
    memcpy(buf[0], poly, (size_t)n * sizeof poly[0]);
    int cur = 0;
    for (int edge = 0; edge < 4 && n > 0; edge++) {
        const int axis = edge & 1, upper = edge >= 2;
        const double limit = clip[edge];
        int m = 0;
        for (int i = 0; i < n; i++) {
            const double *a = buf[cur][i], *b = buf[cur][(i + 1) % n];
            double da = upper ? limit - a[axis] : a[axis] - limit;
            double db = upper ? limit - b[axis] : b[axis] - limit;
            if (da >= 0.0)
                memcpy(buf[!cur][m++], a, sizeof buf[0][0]);
            if ((da >= 0.0) != (db >= 0.0)) {
                double t = da / (da - db);
                buf[!cur][m][0] = a[0] + t * (b[0] - a[0]);
                buf[!cur][m][1] = a[1] + t * (b[1] - a[1]);
                m++;
            }
        }
        cur = !cur;
        n = m;
    }
    if (n == 0)
        return 0;
    bounds[0] = bounds[2] = buf[cur][0][0];
    bounds[1] = bounds[3] = buf[cur][0][1];
    for (int i = 1; i < n; i++) {
        bounds[0] = fmin(bounds[0], buf[cur][i][0]);
        bounds[1] = fmin(bounds[1], buf[cur][i][1]);
        bounds[2] = fmax(bounds[2], buf[cur][i][0]);
        bounds[3] = fmax(bounds[3], buf[cur][i][1]);
    }
    return 1;
}

/* The pixels whose rays can meet a box, into rect (x0, y0, x1, y1; all 0
 * when none can). The box is given in its own axes (along `dir`, a unit
 * vector in xz; up; across, dir turned a right angle): lo and hi, and
 * the camera `cam` in the same coordinates. It is clipped at `near` in
 * front of the camera, what is left projected, and the bounds of its
 * outline on the screen taken (a point just past `near` projects far
 * outside the frame: the outline is clipped to the frame first, or a
 * corner far to the side would stretch the rectangle to the frame's
 * edge). A ray meets the box closer than `near` only if the camera is
 * within near × `spread` of it, and the lens's points (TL_LENS_DISTANCE
 * ahead) lie within that too: such a camera gets the whole frame, as does
 * a box of no finite size. Two pixels of margin cover the samples' jitter
 * (half a pixel) and the GPU's float rounding. */
static void box_rect(const tl_scene *s, int width, int height, const double dir[2],
                     const double cam[3], const double lo[3], const double hi[3], int rect[4])
{
    rect[0] = rect[1] = rect[2] = rect[3] = 0;
    double right[3], up[3], fwd[3];
    tl_scene_camera_basis(&s->camera, right, up, fwd);
    double ty = tan(0.5 * s->camera.vfov), tx = ty * width / height;
    /* 1 / cos of the widest angle a sample's ray makes with the axis */
    double spread = sqrt(1.0 + 1.21 * (tx * tx + ty * ty));
    double near = fmax(0.5, 2.0 * TL_LENS_DISTANCE);
    double margin = near * spread;
    int near_box = 1, finite = 1;
    for (int i = 0; i < 3; i++) {
        near_box = near_box && cam[i] > lo[i] - margin && cam[i] < hi[i] + margin;
        finite = finite && isfinite(cam[i]) && isfinite(lo[i]) && isfinite(hi[i]);
    }
    if (near_box || !finite) {
        rect[2] = width;
        rect[3] = height;
        return;
    }
    double across[2] = {dir[1], -dir[0]};
    double corner[8][3]; /* camera space: right, up, forward */
    for (int i = 0; i < 8; i++) {
        double a = (i & 1 ? hi[0] : lo[0]) - cam[0];
        double y = (i & 2 ? hi[1] : lo[1]) - cam[1];
        double c = (i & 4 ? hi[2] : lo[2]) - cam[2];
        double p[3] = {a * dir[0] + c * across[0], y, a * dir[1] + c * across[1]};
        corner[i][0] = p[0] * right[0] + p[1] * right[1] + p[2] * right[2];
        corner[i][1] = p[0] * up[0] + p[1] * up[1] + p[2] * up[2];
        corner[i][2] = p[0] * fwd[0] + p[1] * fwd[1] + p[2] * fwd[2];
    }
    /* The clipped box's vertices: corners in front of `near`, and where
     * its 12 edges cross the plane. Projected to pixels. */
    double point[32][2], hull[64][2];
    int n = 0;
    for (int i = 0; i < 8; i++) {
        for (int e = 0; e < 4; e++) {
            double q[3];
            if (e == 0) { /* the corner itself */
                if (corner[i][2] < near)
                    continue;
                memcpy(q, corner[i], sizeof q);
            } else { /* the edge to the corner across axis e - 1 */
                int j = i | 1 << (e - 1);
                if (j == i || (corner[i][2] - near) * (corner[j][2] - near) >= 0.0)
                    continue;
                double t = (near - corner[i][2]) / (corner[j][2] - corner[i][2]);
                for (int k = 0; k < 3; k++)
                    q[k] = corner[i][k] + t * (corner[j][k] - corner[i][k]);
            }
            point[n][0] = (q[0] / (q[2] * tx) + 1.0) * 0.5 * width;
            point[n][1] = (q[1] / (q[2] * ty) + 1.0) * 0.5 * height;
            n++;
        }
    }
    if (n == 0)
        return; /* the box lies behind the camera */
    const double frame[4] = {-4.0, -4.0, width + 4.0, height + 4.0};
    double b[4];
    if (!clipped_bounds(hull, convex_hull(point, n, hull), frame, b))
        return;
    int x0 = (int)floor(b[0]) - 2, x1 = (int)ceil(b[2]) + 2;
    int y0 = (int)floor(b[1]) - 2, y1 = (int)ceil(b[3]) + 2;
    x0 = x0 < 0 ? 0 : x0;
    y0 = y0 < 0 ? 0 : y0;
    x1 = x1 > width ? width : x1;
    y1 = y1 > height ? height : y1;
    if (x0 < x1 && y0 < y1) {
        rect[0] = x0;
        rect[1] = y0;
        rect[2] = x1;
        rect[3] = y1;
    }
}

void tl_prepare_giant_rect(const tl_scene *s, tl_frame_uniforms *u)
{
    double near = fmax(0.5, 2.0 * TL_LENS_DISTANCE);
    double cam[3] = {u->giant_frame[2], s->camera.position[1], u->giant_frame[3]};
    double dir[2] = {u->giant_frame[0], u->giant_frame[1]};
    double lo[3], hi[3];
    cover_box(u, cam[1], near, lo, hi);
    box_rect(s, u->width, u->height, dir, cam, lo, hi, u->plan.giant_rect);
}

/* rect grows to hold part (an empty one, x0 >= x1 or y0 >= y1, adds
 * nothing). */
static void union_rect(int rect[4], const int part[4])
{
    if (part[0] >= part[2] || part[1] >= part[3])
        return;
    int empty = rect[0] >= rect[2] || rect[1] >= rect[3];
    for (int i = 0; i < 2; i++) {
        rect[i] = !empty && rect[i] < part[i] ? rect[i] : part[i];
        rect[i + 2] = !empty && rect[i + 2] > part[i + 2] ? rect[i + 2] : part[i + 2];
    }
}

void tl_prepare_mirror_rect(const tl_scene *s, const double corner[8][3], double water,
                            tl_frame_uniforms *u)
{
    int *rect = u->plan.boat_mirror_rect;
    /* The box in the frame of the hull's length (its first edge), up and
     * across; what stands above the water, mirrored below it. */
    double dx = corner[1][0] - corner[0][0], dz = corner[1][2] - corner[0][2];
    double len = sqrt(dx * dx + dz * dz);
    double dir[2] = {len > 0.0 ? dx / len : 1.0, len > 0.0 ? dz / len : 0.0};
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int i = 0; i < 8; i++) {
        const double *c = corner[i];
        const double q[3] = {c[0] * dir[0] + c[2] * dir[1], c[1], c[0] * dir[1] - c[2] * dir[0]};
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], q[k]);
            hi[k] = fmax(hi[k], q[k]);
        }
    }
    if (!(hi[1] > water))
        return; /* nothing above the water to mirror */
    lo[1] = 2.0 * water - hi[1];
    hi[1] = water;
    const double cam[3] = {0.0, 0.0, 0.0};
    int part[4];
    box_rect(s, u->width, u->height, dir, cam, lo, hi, part);
    union_rect(rect, part);
}

/* The union of the rectangles of the wake's groups: each group's circle
 * (u->wake_groups, camera-relative, already holding every point its foam
 * can reach) as a box from the lowest to the highest the water can be
 * there: the ocean's band, widened by the giant wave's height when it is
 * in the frame (cover_box's). Under water the frame is whole: the lens's
 * and the surface's rays from below are left as they are. */
void tl_prepare_wake_rect(const tl_scene *s, tl_frame_uniforms *u)
{
    int *rect = u->plan.wake_rect;
    rect[0] = rect[1] = rect[2] = rect[3] = 0;
    if (!(u->features & TL_FEATURE_WAKE))
        return;
    if (u->features & TL_FEATURE_UNDERWATER) {
        rect[2] = u->width;
        rect[3] = u->height;
        return;
    }
    double top = 0.0;
    if (u->features & TL_FEATURE_GIANT_WAVE)
        top = (double)u->giant_bounds[3] * u->giant_shape[1];
    const double dir[2] = {1.0, 0.0}; /* along x; across is -z */
    const double cam[3] = {0.0, s->camera.position[1], 0.0};
    for (int k = 0; k < u->object_count; k++)
        for (int g = 0; g < TL_WAKE_GROUPS; g++) {
            const float *c = u->objects[k].wake_groups[g];
            double x = c[0], z = c[1], r = c[2];
            if (!(r > 0.0))
                continue; /* no wake in view */
            double lo[3] = {x - r, -(double)u->depth - top, -z - r};
            double hi[3] = {x + r, top, -z + r};
            int part[4];
            box_rect(s, u->width, u->height, dir, cam, lo, hi, part);
            union_rect(rect, part);
        }
}
