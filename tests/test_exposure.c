/* Auto exposure's GL-free half (src/metrics/tl_exposure): the meter's
 * centre weighting, the adaptation's nodes and weights (a first-order lag
 * on a grid shared by neighbouring frames), and the exposure they give,
 * with its clamps. */
#include <math.h>
#include <stdlib.h>

#include "metrics/tl_exposure.h"
#include "tl_test.h"

#define W 32
#define H 18

static float img[W * H * 4];

/* `inner` luminance (grey) inside the central half of the frame, `outer`
 * outside it. */
static void fill(double inner, double outer)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int centre = x >= W / 4 && x < 3 * W / 4 && y >= H / 4 && y < 3 * H / 4;
            float v = (float)(centre ? inner : outer);
            float *p = img + ((size_t)y * W + x) * 4;
            p[0] = p[1] = p[2] = v;
            p[3] = 1.0f;
        }
}

static void test_meter(void)
{
    fill(0.18, 0.18);
    CHECK_NEAR(tl_exposure_meter(img, W, H), log2(0.18), 1e-6);
    /* A centre of a quarter of the frame, at +2 stops against -2 around it
     * (area mean -1) and the reverse (+1): a pixel at the centre weighs
     * more than one at the edge. */
    fill(4.0, 0.25);
    double centre = tl_exposure_meter(img, W, H);
    fill(0.25, 4.0);
    double surround = tl_exposure_meter(img, W, H);
    CHECK(centre > -1.0 + 0.3 && surround < 1.0 - 0.3);
    CHECK_NEAR(centre, -surround, 1e-9);
    /* Black and NaN count as the floor: finite. */
    fill(0.0, NAN);
    CHECK_NEAR(tl_exposure_meter(img, W, H), log2(TL_EXPOSURE_FLOOR), 1e-9);
}

static double sum(const double *w, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += w[i];
    return s;
}

/* The lag's response to a step at time 0 from meter 0 to 1 (nodes before
 * the step read 0): the adapted value at t is sum(weights of nodes > 0). */
static double step_response(double t, double tau, double step_at)
{
    double times[TL_EXPOSURE_NODES], w[TL_EXPOSURE_NODES];
    int n = tl_exposure_nodes(t, tau, times, w);
    double v = 0.0;
    for (int i = 0; i < n; i++)
        v += times[i] >= step_at ? w[i] : 0.0;
    return v;
}

static void test_nodes(void)
{
    double times[TL_EXPOSURE_NODES], w[TL_EXPOSURE_NODES];
    /* No lag, or the first frame: the meter at t alone. */
    CHECK(tl_exposure_nodes(3.0, 0.0, times, w) == 1 && times[0] == 3.0 && w[0] == 1.0);
    CHECK(tl_exposure_nodes(0.0, 1.0, times, w) == 1 && times[0] == 0.0 && w[0] == 1.0);
    /* Mid-timeline: t, then multiples of tau/4 down to t - 4 tau. */
    int n = tl_exposure_nodes(10.1, 1.0, times, w);
    CHECK(n == 17);
    CHECK_NEAR(sum(w, n), 1.0, 1e-12);
    CHECK(times[0] == 10.1 && times[1] == 10.0 && times[n - 1] == 6.25);
    for (int i = 1; i < n; i++) {
        CHECK(times[i] < times[i - 1]);
        CHECK_NEAR(times[i] / 0.25, round(times[i] / 0.25), 1e-9);
        CHECK(w[i] > 0.0);
    }
    /* Near the start the window stops at 0, whose meter takes the rest. */
    n = tl_exposure_nodes(0.6, 1.0, times, w);
    CHECK(n == 4 && times[n - 1] == 0.0);
    CHECK_NEAR(sum(w, n), 1.0, 1e-12);
    /* Frames a 24th of a second apart share all but their own node. */
    double later[TL_EXPOSURE_NODES], lw[TL_EXPOSURE_NODES];
    int m = tl_exposure_nodes(10.1 + 1.0 / 24.0, 1.0, later, lw);
    CHECK(m == n + 14 || m >= 17);
    n = tl_exposure_nodes(10.1, 1.0, times, w);
    int shared = 0;
    for (int i = 1; i < n; i++)
        for (int j = 1; j < m; j++)
            shared += times[i] == later[j];
    CHECK(shared >= n - 2);
    /* A first-order lag. The meter is taken as linear between nodes, so a
     * jump between the nodes at 9.75 and 10 acts as one at 9.875: after a
     * time constant 1 - 1/e of the way, after three 95 %. */
    CHECK_NEAR(step_response(11.0 - 0.125, 1.0, 10.0), 1.0 - exp(-1.0), 0.005);
    CHECK_NEAR(step_response(13.0 - 0.125, 1.0, 10.0), 1.0 - exp(-3.0), 0.005);
    double before = 0.0;
    for (double t = 10.0; t < 15.0; t += 1.0 / 24.0) {
        double now = step_response(t, 1.0, 10.0);
        CHECK(now >= before - 1e-12 && now <= 1.0 + 1e-12);
        before = now;
    }
}

static void test_scale(void)
{
    /* Full strength: the meter's average is brought to the key. */
    CHECK_NEAR(tl_exposure_scale(2.0, 1.0, log2(0.09)), 2.0, 1e-12);
    CHECK_NEAR(tl_exposure_scale(2.0, 1.0, log2(0.0018)), 100.0, 1e-9);
    /* Off: render.exposure alone; half: the geometric mean. */
    CHECK_NEAR(tl_exposure_scale(3.0, 0.0, -40.0), 3.0, 1e-12);
    CHECK_NEAR(tl_exposure_scale(2.0, 0.5, log2(0.18 / 8.0)), 4.0, 1e-12);
    /* A black frame: at most TL_EXPOSURE_MAX_STOPS of gain. */
    CHECK_NEAR(tl_exposure_scale(1.0, 1.0, -40.0), exp2(TL_EXPOSURE_MAX_STOPS), 1e-3);
    CHECK_NEAR(tl_exposure_scale(1.0, 1.0, 200.0), exp2(-TL_EXPOSURE_MAX_STOPS), 1e-12);
    CHECK(tl_exposure_scale(0.0, 0.5, log2(0.18)) == 0.0);
}

int main(void)
{
    test_meter();
    test_nodes();
    test_scale();
    TEST_END();
}
