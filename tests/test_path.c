/* Path tests. The reference is the Hermite form of centripetal Catmull-Rom
 * (tangents from the knot-space divided differences, Yuksel et al.), an
 * independent derivation of the pyramid the code evaluates. */
#include "timeline/tl_path.h"
#include "tl_test.h"

#define NPTS 5
static const double pt_t[NPTS] = {0.0, 1.0, 2.5, 4.0, 5.0};
static const double pt_p[NPTS][3] = {
    {0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {2, 3, 1}, {0, 4, 1},
};

static double len3(const double v[3])
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static double dist(const double a[3], const double b[3])
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return len3(d);
}

static void build(tl_path *path, int count, const double *ts, const double (*ps)[3])
{
    tl_path_init(path);
    for (int i = 0; i < count; i++)
        CHECK(tl_path_add_point(path, ts[i], ps[i], NULL) == 0);
    CHECK(tl_path_validate(path, NULL, NULL) == 0);
    CHECK(tl_path_prepare(path, NULL) == 0);
}

/* Control point j with mirrored phantoms beyond the ends. */
static void ctrl(int j, double out[3])
{
    for (int k = 0; k < 3; k++) {
        if (j < 0)
            out[k] = 2 * pt_p[0][k] - pt_p[1][k];
        else if (j >= NPTS)
            out[k] = 2 * pt_p[NPTS - 1][k] - pt_p[NPTS - 2][k];
        else
            out[k] = pt_p[j][k];
    }
}

/* Hermite form of segment i at u: position and d/du. */
static void hermite(int i, double u, double pos[3], double du[3])
{
    double P[4][3];
    for (int j = 0; j < 4; j++)
        ctrl(i - 1 + j, P[j]);
    double k[4] = {0};
    for (int j = 1; j < 4; j++)
        k[j] = k[j - 1] + sqrt(dist(P[j - 1], P[j]));
    double D = k[2] - k[1];
    double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
    double h01 = 3 * u * u - 2 * u * u * u, h11 = u * u * u - u * u;
    double d00 = 6 * u * u - 6 * u, d10 = 3 * u * u - 4 * u + 1;
    double d01 = 6 * u - 6 * u * u, d11 = 3 * u * u - 2 * u;
    for (int c = 0; c < 3; c++) {
        double m1 = (P[1][c] - P[0][c]) / (k[1] - k[0]) - (P[2][c] - P[0][c]) / (k[2] - k[0]) +
                    (P[2][c] - P[1][c]) / (k[2] - k[1]);
        double m2 = (P[2][c] - P[1][c]) / (k[2] - k[1]) - (P[3][c] - P[1][c]) / (k[3] - k[1]) +
                    (P[3][c] - P[2][c]) / (k[3] - k[2]);
        pos[c] = h00 * P[1][c] + h10 * D * m1 + h01 * P[2][c] + h11 * D * m2;
        du[c] = d00 * P[1][c] + d10 * D * m1 + d01 * P[2][c] + d11 * D * m2;
    }
}

static void test_interpolation(void)
{
    tl_path path;
    build(&path, NPTS, pt_t, pt_p);
    double pos[3], tan[3];
    for (int i = 0; i < NPTS; i++) {
        tl_path_eval(&path, pt_t[i], pos, tan);
        for (int k = 0; k < 3; k++)
            CHECK_NEAR(pos[k], pt_p[i][k], 1e-12);
        CHECK_NEAR(len3(tan), 1.0, 1e-12);
    }
    /* Against the Hermite form, position and heading, all segments. */
    for (int i = 0; i + 1 < NPTS; i++) {
        for (int j = 1; j < 10; j++) {
            double u = j / 10.0, want[3], wd[3];
            hermite(i, u, want, wd);
            tl_path_eval(&path, pt_t[i] + u * (pt_t[i + 1] - pt_t[i]), pos, tan);
            double wl = len3(wd);
            for (int k = 0; k < 3; k++) {
                CHECK_NEAR(pos[k], want[k], 1e-12);
                CHECK_NEAR(tan[k], wd[k] / wl, 1e-9);
            }
        }
    }
    /* Unit heading everywhere. */
    for (double t = -1.0; t <= 6.0; t += 0.003) {
        tl_path_eval(&path, t, pos, tan);
        CHECK_NEAR(len3(tan), 1.0, 1e-12);
    }
    /* Mirrored end points: leave P0 heading at P1, arrive from P3. */
    tl_path_eval(&path, 0.0, pos, tan);
    CHECK_NEAR(tan[0], 1.0, 1e-12);
    CHECK_NEAR(tan[1], 0.0, 1e-12);
    tl_path_eval(&path, 5.0, pos, tan);
    double e[3] = {-2, 1, 0}, el = sqrt(5.0);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(tan[k], e[k] / el, 1e-12);
    /* Clamped outside the time range (position and heading). */
    tl_path_eval(&path, -10.0, pos, tan);
    CHECK(pos[0] == 0.0 && pos[1] == 0.0 && pos[2] == 0.0);
    CHECK_NEAR(tan[0], 1.0, 1e-12);
    tl_path_eval(&path, 1e6, pos, tan);
    for (int k = 0; k < 3; k++) {
        CHECK(pos[k] == pt_p[NPTS - 1][k]);
        CHECK_NEAR(tan[k], e[k] / el, 1e-12);
    }
    tl_path_eval(&path, NAN, pos, NULL); /* NULL outputs are allowed */
    CHECK(isfinite(pos[0]));
    tl_path_free(&path);

    /* Evenly spaced collinear points at even times: uniform straight motion. */
    const double lt[4] = {10.0, 11.0, 12.0, 13.0};
    const double lp[4][3] = {{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {6, 0, 0}};
    build(&path, 4, lt, lp);
    for (double t = 10.0; t <= 13.0; t += 0.01) {
        tl_path_eval(&path, t, pos, tan);
        CHECK_NEAR(pos[0], 2.0 * (t - 10.0), 1e-12);
        CHECK_NEAR(pos[1], 0.0, 1e-15);
        CHECK_NEAR(tan[0], 1.0, 1e-15);
    }
    tl_path_free(&path);
}

/* Finite-difference speeds over [t0, t1]; returns (max - min) / mean. */
static double speed_variation(const tl_path *path, double t0, double t1, double *mean)
{
    const int n = 4000;
    double dt = (t1 - t0) / n, lo = INFINITY, hi = 0.0, sum = 0.0;
    double prev[3], cur[3];
    tl_path_eval(path, t0, prev, NULL);
    for (int i = 1; i <= n; i++) {
        tl_path_eval(path, t0 + i * dt, cur, NULL);
        double v = dist(cur, prev) / dt;
        lo = fmin(lo, v);
        hi = fmax(hi, v);
        sum += v;
        for (int k = 0; k < 3; k++)
            prev[k] = cur[k];
    }
    *mean = sum / n;
    return (hi - lo) / *mean;
}

static void test_constant_speed(void)
{
    tl_path path;
    build(&path, NPTS, pt_t, pt_p);
    double mean;
    /* By point times the speed varies a lot (the check below means something). */
    CHECK(speed_variation(&path, 0.0, 5.0, &mean) > 0.2);
    /* Length by a dense polyline, independent of the arc table. */
    double length = 0.0, prev[3], cur[3];
    tl_path_eval(&path, 0.0, prev, NULL);
    for (int i = 1; i <= 200000; i++) {
        tl_path_eval(&path, 5.0 * i / 200000.0, cur, NULL);
        length += dist(cur, prev);
        for (int k = 0; k < 3; k++)
            prev[k] = cur[k];
    }
    CHECK_NEAR(path.length, length, 1e-6 * length);

    path.constant_speed = true;
    CHECK(tl_path_prepare(&path, NULL) == 0);
    double var = speed_variation(&path, 0.0, 5.0, &mean);
    printf("constant-speed variation %.3g (mean %.6f, length / duration %.6f)\n", var, mean,
           length / 5.0);
    CHECK(var < 0.01);
    CHECK(var < 1e-3); /* the table is much better than the 1% budget */
    CHECK_NEAR(mean, length / 5.0, 1e-4 * mean);
    double pos[3], tan[3];
    tl_path_eval(&path, 0.0, pos, tan);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(pos[k], pt_p[0][k], 1e-12);
    tl_path_eval(&path, 5.0, pos, tan);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(pos[k], pt_p[NPTS - 1][k], 1e-12);
    /* Half the time, half the length: the polyline length up to that point. */
    tl_path_eval(&path, 2.5, pos, tan);
    CHECK(isfinite(pos[0]) && isfinite(pos[1]) && isfinite(pos[2]));
    for (double t = -1.0; t <= 6.0; t += 0.01) {
        tl_path_eval(&path, t, pos, tan);
        CHECK_NEAR(len3(tan), 1.0, 1e-12);
    }
    tl_path_free(&path);
}

/* tl_path_distance against a dense polyline of the same path, by point
 * times and at constant speed: 0 before the start, the length after the
 * end, and in between the polyline's length up to that time. */
static void test_distance(void)
{
    tl_path path;
    build(&path, NPTS, pt_t, pt_p);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) {
            path.constant_speed = true;
            CHECK(tl_path_prepare(&path, NULL) == 0);
        }
        CHECK(tl_path_distance(&path, -1.0) == 0.0);
        CHECK_NEAR(tl_path_distance(&path, 9.0), path.length, 1e-12);
        double along = 0.0, prev[3], cur[3], worst = 0.0;
        tl_path_eval(&path, 0.0, prev, NULL);
        const int steps = 100000;
        for (int i = 1; i <= steps; i++) {
            double t = 5.0 * i / steps;
            tl_path_eval(&path, t, cur, NULL);
            along += dist(cur, prev);
            for (int k = 0; k < 3; k++)
                prev[k] = cur[k];
            if (i % 997 == 0 || i == steps)
                worst = fmax(worst, fabs(tl_path_distance(&path, t) - along));
        }
        printf("%s: distance against a polyline, worst %.3g m of %.4f\n",
               pass ? "constant speed" : "by point times", worst, path.length);
        CHECK(worst < 1e-6 * path.length);
    }
    /* Fewer than two points: no distance. */
    tl_path one;
    build(&one, 1, pt_t, pt_p);
    CHECK(tl_path_distance(&one, 3.0) == 0.0);
    tl_path_free(&one);
    tl_path_free(&path);
}

static void test_degenerate_and_validation(void)
{
    /* A repeated point: finite everywhere, heading stays a unit vector. */
    tl_path path;
    const double dt[4] = {0, 1, 2, 3};
    const double dp[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}};
    build(&path, 4, dt, dp);
    double pos[3], tan[3];
    for (double t = 0.0; t <= 3.0; t += 0.01) {
        tl_path_eval(&path, t, pos, tan);
        CHECK(isfinite(pos[0]) && isfinite(pos[1]) && isfinite(pos[2]));
        CHECK_NEAR(len3(tan), 1.0, 1e-9);
    }
    tl_path_eval(&path, 1.5, pos, tan);
    CHECK_NEAR(pos[0], 1.0, 1e-12); /* parked on the repeated point */
    /* Constant speed still works; the repeated point is a corner, where a
     * finite-difference chord is shorter than the arc, so check that no
     * chord is faster than length / duration and the mean matches it. */
    path.constant_speed = true;
    CHECK(tl_path_prepare(&path, NULL) == 0);
    double v = path.length / 3.0, prev[3], cur[3], sum = 0.0, fastest = 0.0;
    tl_path_eval(&path, 0.0, prev, NULL);
    for (int i = 1; i <= 3000; i++) {
        tl_path_eval(&path, i * 0.001, cur, NULL);
        double s = dist(cur, prev) / 0.001;
        sum += s;
        fastest = fmax(fastest, s);
        for (int k = 0; k < 3; k++)
            prev[k] = cur[k];
    }
    CHECK(fastest <= v * 1.0001);
    CHECK_NEAR(sum / 3000.0, v, 0.01 * v);
    CHECK(path.length >= 1.0 + sqrt(2.0) - 1e-12); /* at least the chords */
    tl_path_free(&path);

    /* One point: that position, no heading. Empty: the origin. */
    const double one_t[1] = {2.0};
    const double one_p[1][3] = {{1, 2, 3}};
    build(&path, 1, one_t, one_p);
    tl_path_eval(&path, 0.0, pos, tan);
    CHECK(pos[0] == 1 && pos[1] == 2 && pos[2] == 3);
    CHECK(tan[0] == 0 && tan[1] == 0 && tan[2] == 0);
    tl_path_free(&path);
    tl_path_init(&path);
    tl_path_eval(&path, 1.0, pos, tan);
    CHECK(pos[0] == 0 && pos[1] == 0 && pos[2] == 0);
    tl_path_free(&path);

    /* Validation names the point. */
    tl_path_init(&path);
    double p[3] = {0, 0, 0};
    CHECK(tl_path_add_point(&path, 0.0, p, NULL) == 0);
    CHECK(tl_path_add_point(&path, 1.0, p, NULL) == 0);
    CHECK(tl_path_add_point(&path, 1.0, p, NULL) == 0);
    tl_error err;
    tl_error_clear(&err);
    size_t bad = 99;
    CHECK(tl_path_validate(&path, &bad, &err) != 0);
    CHECK(bad == 2);
    CHECK_STR_CONTAINS(err.message, "point 2");
    path.points[2].t = 2.0;
    path.points[1].p[1] = NAN;
    tl_error_clear(&err);
    CHECK(tl_path_validate(&path, &bad, &err) != 0);
    CHECK(bad == 1);
    CHECK_STR_CONTAINS(err.message, "point 1");
    tl_path_free(&path);
}

int main(void)
{
    test_interpolation();
    test_constant_speed();
    test_distance();
    test_degenerate_and_validation();
    TEST_END();
}
