/* tl_shutter: the times a frame's shutter samples, never across a cut
 * (motion blur that mixed two shots would ghost one over the other). */
#include <math.h>

#include "tl_timeline.h"

/* Narrows (lo, hi] around the cut inside it to ~1e-12 relative. */
static void locate_cut(const tl_timeline *tl, double *lo, double *hi)
{
    for (int i = 0; i < 200 && *hi - *lo > 1e-12 * fmax(1.0, fabs(*hi)); i++) {
        double mid = 0.5 * (*lo + *hi);
        if (tl_timeline_has_cut_between(tl, *lo, mid))
            *hi = mid;
        else
            *lo = mid;
    }
}

void tl_timeline_shutter_interval(const tl_timeline *tl, long frame, double shutter_deg,
                                  double *open, double *close)
{
    double t = tl_timeline_frame_time(tl, frame);
    double half = 0.5 * (shutter_deg / 360.0) / tl->fps;
    double a = t - half, b = t + half;
    if (tl_timeline_has_cut_between(tl, a, t)) { /* a cut before: open at it */
        double lo = a, hi = t;
        locate_cut(tl, &lo, &hi);
        a = hi; /* the cut's own time already shows the new shot */
    }
    if (tl_timeline_has_cut_between(tl, t, b)) { /* a cut after: close before it */
        double lo = t, hi = b;
        locate_cut(tl, &lo, &hi);
        b = lo;
    }
    *open = a;
    *close = b;
}

int tl_timeline_shutter_times(const tl_timeline *tl, long frame, double shutter_deg, int samples,
                              double *times)
{
    double t = tl_timeline_frame_time(tl, frame);
    if (shutter_deg <= 0.0 || samples <= 1) {
        times[0] = t;
        return 0;
    }
    double open, close;
    tl_timeline_shutter_interval(tl, frame, shutter_deg, &open, &close);
    int nearest = 0;
    for (int k = 0; k < samples; k++) {
        times[k] = open + (close - open) * (k + 0.5) / samples;
        if (fabs(times[k] - t) < fabs(times[nearest] - t))
            nearest = k;
    }
    return nearest;
}
