#include "timeline/tl_path.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Arc-length table resolution; with a Gauss-Legendre rule per sample and a
 * Newton polish on lookup this is far finer than the 1% speed budget. */
#define ARC_SAMPLES_PER_SEGMENT 64

void tl_path_init(tl_path *path)
{
    memset(path, 0, sizeof *path);
}

void tl_path_free(tl_path *path)
{
    if (!path)
        return;
    free(path->points);
    free(path->arc);
    free(path->point_arc);
    memset(path, 0, sizeof *path);
}

int tl_path_add_point(tl_path *path, double t, const double pos[3], tl_error *err)
{
    if (path->count == path->capacity) {
        size_t cap = path->capacity ? path->capacity * 2 : 8;
        if (cap > SIZE_MAX / sizeof *path->points)
            return tl_error_set(err, TL_ERR_RUNTIME, "too many path points");
        tl_path_point *pts = realloc(path->points, cap * sizeof *pts);
        if (!pts)
            return tl_error_set(err, TL_ERR_RUNTIME, "out of memory for %zu path points", cap);
        path->points = pts;
        path->capacity = cap;
    }
    tl_path_point *pt = &path->points[path->count++];
    pt->t = t;
    memcpy(pt->p, pos, sizeof pt->p);
    path->prepared = false;
    return 0;
}

int tl_path_validate(const tl_path *path, size_t *bad_point, tl_error *err)
{
    for (size_t i = 0; i < path->count; i++) {
        const tl_path_point *pt = &path->points[i];
        const char *what = NULL;
        if (!isfinite(pt->t))
            what = "time is not a finite number";
        else if (!isfinite(pt->p[0]) || !isfinite(pt->p[1]) || !isfinite(pt->p[2]))
            what = "position is not finite";
        else if (i > 0 && !(pt->t > path->points[i - 1].t))
            what = "time is not after the previous point's time";
        if (what) {
            if (bad_point)
                *bad_point = i;
            return tl_error_set(err, TL_ERR_RUNTIME, "point %zu: %s", i, what);
        }
    }
    return 0;
}

/* ---- one segment -------------------------------------------------------- */

static void lerp3(double out[3], const double a[3], const double b[3], double w)
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] + (b[k] - a[k]) * w;
}

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Control point j of segment i's window (i-1 .. i+2), with mirrored
 * phantoms beyond the ends. */
static void control_point(const tl_path *path, long j, double out[3])
{
    long n = (long)path->count;
    const tl_path_point *pts = path->points;
    if (j < 0) {
        for (int k = 0; k < 3; k++)
            out[k] = 2.0 * pts[0].p[k] - pts[1].p[k];
    } else if (j >= n) {
        for (int k = 0; k < 3; k++)
            out[k] = 2.0 * pts[n - 1].p[k] - pts[n - 2].p[k];
    } else {
        memcpy(out, pts[j].p, 3 * sizeof(double));
    }
}

/* Position and d/du on segment i (count >= 2) at u in [0,1], by the
 * Barry-Goldman pyramid with centripetal knots; lerp forms keep coincident
 * points exact. */
static void segment_eval(const tl_path *path, size_t i, double u, double pos[3], double du[3])
{
    double P[4][3];
    for (int j = 0; j < 4; j++)
        control_point(path, (long)i - 1 + j, P[j]);
    double d[3];
    for (int j = 0; j < 3; j++)
        d[j] = sqrt(dist3(P[j], P[j + 1])); /* alpha = 0.5 */
    /* Coincident points would give empty knot intervals; a tiny floor keeps
     * the weights finite without changing the shape measurably. */
    double floor_d = 1e-12 * (d[0] + d[1] + d[2]);
    if (floor_d == 0.0)
        floor_d = 1.0;
    for (int j = 0; j < 3; j++)
        d[j] = fmax(d[j], floor_d);
    double k0 = 0.0, k1 = d[0], k2 = k1 + d[1], k3 = k2 + d[2];
    double s = k1 + u * d[1];

    double A[3][3], dA[3][3];
    const double kn[4] = {k0, k1, k2, k3};
    for (int j = 0; j < 3; j++) {
        double span = kn[j + 1] - kn[j];
        lerp3(A[j], P[j], P[j + 1], (s - kn[j]) / span);
        for (int k = 0; k < 3; k++)
            dA[j][k] = (P[j + 1][k] - P[j][k]) / span;
    }
    double B[2][3], dB[2][3];
    for (int j = 0; j < 2; j++) {
        double span = kn[j + 2] - kn[j], w = (s - kn[j]) / span;
        lerp3(B[j], A[j], A[j + 1], w);
        for (int k = 0; k < 3; k++)
            dB[j][k] = dA[j][k] + (dA[j + 1][k] - dA[j][k]) * w + (A[j + 1][k] - A[j][k]) / span;
    }
    double w = (s - k1) / (k2 - k1);
    if (pos) {
        if (u <= 0.0)
            memcpy(pos, P[1], sizeof P[1]); /* hit the points exactly */
        else if (u >= 1.0)
            memcpy(pos, P[2], sizeof P[2]);
        else
            lerp3(pos, B[0], B[1], w);
    }
    if (du) {
        for (int k = 0; k < 3; k++)
            du[k] = (dB[0][k] + (dB[1][k] - dB[0][k]) * w + (B[1][k] - B[0][k]) / (k2 - k1)) *
                    d[1];
    }
}

static double norm3(const double v[3])
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static double speed(const tl_path *path, double g)
{
    size_t seg = (size_t)g;
    if (seg > path->count - 2)
        seg = path->count - 2;
    double du[3];
    segment_eval(path, seg, g - (double)seg, NULL, du);
    return norm3(du);
}

/* Arc length over [g0, g1] (within one table step) by 5-point Gauss-Legendre. */
static double arc_between(const tl_path *path, double g0, double g1)
{
    static const double x[5] = {0.0, -0.5384693101056831, 0.5384693101056831,
                                -0.9061798459386640, 0.9061798459386640};
    static const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                0.2369268850561891, 0.2369268850561891};
    double half = 0.5 * (g1 - g0), mid = 0.5 * (g0 + g1), sum = 0.0;
    for (int i = 0; i < 5; i++)
        sum += w[i] * speed(path, mid + half * x[i]);
    return sum * half;
}

int tl_path_prepare(tl_path *path, tl_error *err)
{
    free(path->arc);
    free(path->point_arc);
    path->arc = path->point_arc = NULL;
    path->arc_samples = 0;
    path->length = 0.0;
    path->prepared = true;
    if (path->count < 2)
        return 0;
    size_t samples = (path->count - 1) * ARC_SAMPLES_PER_SEGMENT;
    double *arc = NULL;
    if (samples + 1 > SIZE_MAX / sizeof *arc)
        return tl_error_set(err, TL_ERR_RUNTIME, "path too long for an arc-length table");
    if (path->constant_speed) {
        arc = malloc((samples + 1) * sizeof *arc);
        if (!arc)
            return tl_error_set(err, TL_ERR_RUNTIME, "out of memory for an arc-length table");
        arc[0] = 0.0;
    }
    double *point_arc = malloc(path->count * sizeof *point_arc);
    if (!point_arc) {
        free(arc);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory for an arc-length table");
    }
    point_arc[0] = 0.0;
    double total = 0.0;
    for (size_t j = 0; j < samples; j++) {
        double g0 = (double)j / ARC_SAMPLES_PER_SEGMENT;
        double g1 = (double)(j + 1) / ARC_SAMPLES_PER_SEGMENT;
        total += arc_between(path, g0, g1);
        if (arc)
            arc[j + 1] = total;
        if ((j + 1) % ARC_SAMPLES_PER_SEGMENT == 0)
            point_arc[(j + 1) / ARC_SAMPLES_PER_SEGMENT] = total;
    }
    path->arc = arc;
    path->arc_samples = arc ? samples : 0;
    path->point_arc = point_arc;
    path->length = total;
    return 0;
}

/* Global parameter g at which the arc length from the start is target. */
static double g_at_length(const tl_path *path, double target)
{
    const double *arc = path->arc;
    size_t lo = 0, hi = path->arc_samples; /* arc[lo] <= target < arc[hi] */
    if (target >= arc[hi])
        return (double)(path->count - 1);
    if (target <= 0.0)
        return 0.0;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (arc[mid] <= target)
            lo = mid;
        else
            hi = mid;
    }
    double step = 1.0 / ARC_SAMPLES_PER_SEGMENT;
    double ga = (double)lo * step, gb = (double)hi * step;
    double seg_len = arc[hi] - arc[lo];
    if (!(seg_len > 0.0))
        return ga;
    double want = target - arc[lo];
    double g = ga + step * (want / seg_len), a = ga, b = gb;
    for (int it = 0; it < 8; it++) {
        double f = arc_between(path, ga, g) - want;
        if (fabs(f) <= 1e-13 * path->length)
            break;
        if (f < 0.0)
            a = g;
        else
            b = g;
        double v = speed(path, g);
        double next = v > 0.0 ? g - f / v : 0.5 * (a + b);
        if (!(next > a && next < b))
            next = 0.5 * (a + b);
        g = next;
    }
    return g;
}

/* Direction of the nearest segment with length, for a stationary spot. */
static void fallback_tangent(const tl_path *path, size_t seg, double tangent[3])
{
    size_t n = path->count;
    for (size_t off = 0; off < n; off++) {
        for (int side = 0; side < 2; side++) {
            long j = side ? (long)seg + (long)off : (long)seg - (long)off;
            if (j < 0 || j + 1 >= (long)n)
                continue;
            double len = dist3(path->points[j].p, path->points[j + 1].p);
            if (len > 0.0) {
                for (int k = 0; k < 3; k++)
                    tangent[k] = (path->points[j + 1].p[k] - path->points[j].p[k]) / len;
                return;
            }
        }
    }
    tangent[0] = tangent[1] = tangent[2] = 0.0;
}

/* The segment and its parameter in [0, 1] where the path is at time t
 * (two or more points). */
static void locate(const tl_path *path, double t, size_t *seg_out, double *u_out)
{
    size_t n = path->count;
    const tl_path_point *pts = path->points;
    double t0 = pts[0].t, t1 = pts[n - 1].t;
    if (isnan(t))
        t = t0;
    size_t seg;
    double u;
    if (path->constant_speed && path->arc && t1 > t0) {
        double frac = fmin(1.0, fmax(0.0, (t - t0) / (t1 - t0)));
        double g = g_at_length(path, frac * path->length);
        seg = (size_t)g;
        if (seg > n - 2)
            seg = n - 2;
        u = fmin(1.0, fmax(0.0, g - (double)seg));
    } else if (!(t > t0)) {
        seg = 0;
        u = 0.0;
    } else if (t >= t1) {
        seg = n - 2;
        u = 1.0;
    } else {
        size_t lo = 0, hi = n - 1; /* pts[lo].t <= t < pts[hi].t */
        while (hi - lo > 1) {
            size_t mid = lo + (hi - lo) / 2;
            if (pts[mid].t <= t)
                lo = mid;
            else
                hi = mid;
        }
        seg = lo;
        u = fmin(1.0, fmax(0.0, (t - pts[lo].t) / (pts[lo + 1].t - pts[lo].t)));
    }
    *seg_out = seg;
    *u_out = u;
}

void tl_path_eval(const tl_path *path, double t, double pos[3], double tangent[3])
{
    size_t n = path->count;
    double scratch[3];
    if (!pos)
        pos = scratch;
    if (n == 0 || n == 1) {
        for (int k = 0; k < 3; k++)
            pos[k] = n ? path->points[0].p[k] : 0.0;
        if (tangent)
            tangent[0] = tangent[1] = tangent[2] = 0.0;
        return;
    }
    size_t seg;
    double u;
    locate(path, t, &seg, &u);
    double du[3];
    segment_eval(path, seg, u, pos, du);
    if (!tangent)
        return;
    double len = norm3(du);
    if (len > 0.0 && isfinite(len)) {
        for (int k = 0; k < 3; k++)
            tangent[k] = du[k] / len;
    } else {
        fallback_tangent(path, seg, tangent);
    }
}

double tl_path_distance(const tl_path *path, double t)
{
    if (path->count < 2 || !path->point_arc)
        return 0.0;
    const double t0 = path->points[0].t, t1 = path->points[path->count - 1].t;
    if (path->constant_speed && path->arc && t1 > t0) /* what locate() inverts */
        return fmin(1.0, fmax(0.0, (isnan(t) ? 0.0 : t - t0) / (t1 - t0))) * path->length;
    size_t seg;
    double u;
    locate(path, t, &seg, &u);
    if (u >= 1.0)
        return path->point_arc[seg + 1];
    /* From the segment's start, the table's panels in the table's order. */
    double s = path->point_arc[seg], g = (double)seg + u, step = 1.0 / ARC_SAMPLES_PER_SEGMENT;
    size_t j = seg * ARC_SAMPLES_PER_SEGMENT;
    for (; (double)(j + 1) * step <= g; j++)
        s += arc_between(path, (double)j * step, (double)(j + 1) * step);
    return s + arc_between(path, (double)j * step, g);
}
