/* The giant wave's lip in double: where the crest breaks, a tube along an
 * arc in the crest's cross-section (a circle stretched along the travel),
 * thrown from the crest's top and falling onto the face
 * (tl_giant.h's TL_GIANT_LIP_* and tl_giant_lip_*; shaders/lip.glsl is
 * the same model in GLSL). */
#include "tl_giant.h"

#include "tl_glsl.h"
#include "tl_noise.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* How far `angle` lies along the whole sweep, from the root (0) to where
 * a full throw ends (1). */
static double lip_along(double angle)
{
    double along =
        (angle - TL_GIANT_LIP_ROOT * (M_PI / 180.0)) / (TL_GIANT_LIP_SWEEP * (M_PI / 180.0));
    return along < 0.0 ? 0.0 : along > 1.0 ? 1.0 : along;
}

/* The tube's half thickness at `angle` before its lumps and its edge: it
 * thins along the whole sweep (TL_GIANT_LIP_TIP) and evens out as it
 * collapses. */
static double lip_half_body(const tl_giant_lip *lip, double angle)
{
    return lip->thickness *
           (1.0 - (1.0 - TL_GIANT_LIP_TIP) * lip_along(angle) * (1.0 - lip->spent));
}

/* The body's half thickness thinned toward the free end
 * (TL_GIANT_LIP_EDGE). */
static double lip_half_smooth(const tl_giant_lip *lip, double angle)
{
    double edge = tl_smoothstep(0.0, TL_GIANT_LIP_EDGE_ARC * (M_PI / 180.0), lip->to - angle);
    return lip_half_body(lip, angle) *
           (1.0 - (1.0 - TL_GIANT_LIP_EDGE) * (1.0 - edge) * (1.0 - lip->spent));
}

void tl_giant_lip_at(const tl_giant *g, double w, double base, tl_giant_lip *lip)
{
    memset(lip, 0, sizeof *lip);
    if (!g->active || !g->breaks || fabs(w) >= g->half_width)
        return;
    double age = tl_giant_break_age(g, w), T = g->throw_time, dp;
    if (!(age > 0.0) || age >= T * (1.0 + TL_GIANT_LIP_FADE))
        return;
    double dl, db, lambda = tl_giant_lambda(g, w, &dl);
    double height = lambda * g->amplitude;
    double life = 1.0 - tl_smoothstep(T, T * (1.0 + TL_GIANT_LIP_FADE), age);
    lip->spent = 1.0 - life;
    double tall = tl_smoothstep(TL_GIANT_LIP_LOW, TL_GIANT_LIP_HIGH, lambda);
    double progress = tl_giant_break_progress(g, w, &dp);
    lip->thickness = TL_GIANT_LIP_THICKNESS * height * tall *
                     (1.0 + TL_GIANT_LIP_SWELL * lip->spent) * sqrt(life) *
                     tl_smoothstep(0.0, TL_GIANT_LIP_GROW, progress);
    if (!(lip->thickness > 0.0))
        return;
    lip->present = true;
    lip->w = w;
    lip->radius = TL_GIANT_LIP_RADIUS * height;
    lip->progress = progress;
    double anchor = TL_GIANT_LIP_ANCHOR * (M_PI / 180.0);
    double top_s = tl_giant_bow(g, w, &db) + lambda * g->curl / g->k, top_y = base + height;
    /* The tube's outer surface passes through the crest's top at the
     * anchor: the lip is the crest's top thrown on, not a tube laid on it. */
    double outer = lip->radius + lip_half_body(lip, anchor);
    lip->center[0] = top_s - outer * sin(anchor);
    lip->center[1] = top_y - outer * cos(anchor);
    double sweep = progress * tall * TL_GIANT_LIP_SWEEP * (M_PI / 180.0);
    lip->to = TL_GIANT_LIP_ROOT * (M_PI / 180.0) + sweep;
    lip->from = TL_GIANT_LIP_ROOT * (M_PI / 180.0) +
                TL_GIANT_LIP_COLLAPSE * tl_smoothstep(0.0, 1.0, lip->spent) * sweep;
    lip->fillet = TL_GIANT_LIP_FILLET * lip->radius * (1.0 - lip->spent) *
                  tl_smoothstep(TL_GIANT_LIP_FILLET_FROM * (M_PI / 180.0),
                                TL_GIANT_LIP_FILLET_TO * (M_PI / 180.0), lip->to);
}

double tl_giant_lip_fillet(const tl_giant_lip *lip, double angle)
{
    double f = 1.0 - tl_smoothstep(0.0, TL_GIANT_LIP_FILLET_ARC * (M_PI / 180.0), angle);
    return lip->fillet * f * f;
}

double tl_giant_lip_roughness(const tl_giant_lip *lip, double angle)
{
    return fmax(tl_smoothstep(0.0, TL_GIANT_LIP_ROUGHEN, lip->spent),
                TL_GIANT_LIP_TEAR * tl_smoothstep(0.7, 1.0, lip_along(angle)));
}

double tl_giant_lip_lump(const tl_giant_lip *lip, double angle)
{
    double n = tl_noise_value(lip->w / TL_GIANT_LIP_LUMP_CELL,
                              17.3 + angle * lip->radius / TL_GIANT_LIP_LUMP_CELL);
    return 1.0 + TL_GIANT_LIP_LUMP * tl_giant_lip_roughness(lip, angle) * (2.0 * n - 1.0);
}

double tl_giant_lip_half_thickness(const tl_giant_lip *lip, double angle)
{
    return lip_half_smooth(lip, angle) * tl_giant_lip_lump(lip, angle);
}

/* The arc's point at `angle`, from its centre (TL_GIANT_LIP_THROW). */
static void lip_arc_point(const tl_giant_lip *lip, double angle, double *s, double *y)
{
    *s = TL_GIANT_LIP_THROW * lip->radius * sin(angle);
    *y = lip->radius * cos(angle);
}

double tl_giant_lip_angle(const tl_giant_lip *lip, double s, double y)
{
    return atan2((s - lip->center[0]) / TL_GIANT_LIP_THROW, y - lip->center[1]);
}

/* The tube's signed distance in the cross-section. The arc is an ellipse:
 * with the travel's axis shrunk by TL_GIANT_LIP_THROW it is a circle of
 * radius R, and r the distance from its centre there; the distance to the
 * arc is |r - R| over the gradient of r (first order, so the tube keeps
 * its thickness where the arc runs down as where it runs across). *bound:
 * |r - R| less the half thickness, which never exceeds the distance (r
 * changes by at most a metre per metre), for marching. */
static double tl_giant_lip_tube_distance(const tl_giant_lip *lip, double s, double y, double *bound)
{
    double qs = s - lip->center[0], qy = y - lip->center[1];
    double es = qs / TL_GIANT_LIP_THROW;
    double angle = tl_giant_lip_angle(lip, s, y);
    if (angle >= lip->from && angle <= lip->to) {
        double r = fmax(hypot(es, qy), 1e-9);
        double slope = hypot(es / TL_GIANT_LIP_THROW, qy) / r;
        double body = tl_giant_lip_half_thickness(lip, angle), half = body, roof = 0.0;
        if (r < lip->radius) {
            /* The roof is thicker toward the root: the bound takes it as
             * thick as it is within the point's reach along the inner
             * side (whose radius is at least half the centre line's). */
            double reach = (lip->radius - r) / fmax(r, 0.5 * lip->radius);
            roof = tl_giant_lip_fillet(lip, angle - reach);
            half += tl_giant_lip_fillet(lip, angle);
        }
        *bound = fabs(r - lip->radius) - fmax(half, body + roof);
        return fabs(r - lip->radius) / slope - half;
    }
    /* Past either end: the round cap there, as thick as the tube's end.
     * The caps are not the nearest part of an ellipse's arc everywhere
     * past its ends (near the centre, its top is): the bound is the
     * nearer of them and of the band the arc lies in, |r - R| less the
     * thickest the tube can be. */
    double d = 1e30;
    const double ends[2] = {lip->from, lip->to};
    for (int i = 0; i < 2; i++) {
        double ps, py;
        lip_arc_point(lip, ends[i], &ps, &py);
        d = fmin(d, hypot(qs - ps, qy - py) - tl_giant_lip_half_thickness(lip, ends[i]));
    }
    *bound = fmin(d, fabs(hypot(es, qy) - lip->radius) -
                         lip->thickness * (1.0 + TL_GIANT_LIP_LUMP) - lip->fillet);
    return d;
}

/* The lip is the tube in front of the vertical through the crest's top
 * (the arc's centre, as the anchor is straight up: test_giant_lip checks
 * TL_GIANT_LIP_ANCHOR is 0); behind it the crest's own back is the water,
 * and the tube's root stood above a back that falls away (a smooth slab
 * over the wave's back, seen from behind). The cut face lies under the
 * crest's top, inside the water. */
double tl_giant_lip_distance(const tl_giant_lip *lip, double s, double y)
{
    double bound;
    return tl_giant_lip_distance_bounded(lip, s, y, &bound);
}

double tl_giant_lip_distance_bounded(const tl_giant_lip *lip, double s, double y, double *bound)
{
    *bound = 1e30;
    if (!lip->present)
        return 1e30;
    double behind = lip->center[0] - s;
    double tube = tl_giant_lip_tube_distance(lip, s, y, bound);
    *bound = fmax(*bound, behind);
    return fmax(tube, behind);
}

bool tl_giant_lip_bounds(const tl_giant *g, double base, double box[4], double across[2])
{
    box[0] = box[2] = across[0] = 1e30;
    box[1] = box[3] = across[1] = -1e30;
    if (!g->active || !g->breaks)
        return false;
    /* Scanned across at the envelope's sample spacing; each cross-section's
     * ellipse (its reach along the travel, THROW·radius, plus the
     * thickness) bounds its arc, widened by the spacing
     * times the largest slope the arc's centre could have between samples. */
    const int n = TL_GIANT_PROFILE_SAMPLES;
    const double spacing = 2.0 * g->half_width / n;
    bool any = false;
    for (int i = 0; i <= n; i++) {
        double w = -g->half_width + spacing * i;
        tl_giant_lip lip;
        tl_giant_lip_at(g, w, base, &lip);
        if (!lip.present)
            continue;
        any = true;
        double reach = TL_GIANT_LIP_THROW * lip.radius + lip.thickness * (1.0 + TL_GIANT_LIP_LUMP) +
                       spacing * (1.0 + g->max_dbow) + spacing * g->max_dlambda * g->amplitude;
        box[0] = fmin(box[0], lip.center[0] - reach);
        box[1] = fmax(box[1], lip.center[0] + reach);
        box[2] = fmin(box[2], lip.center[1] - reach);
        box[3] = fmax(box[3], lip.center[1] + reach);
        across[0] = fmin(across[0], w - spacing);
        across[1] = fmax(across[1], w + spacing);
    }
    return any;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int tl_giant_lip_heights(const tl_giant *g, double x, double z, double floor, double base,
                         double *heights, int max)
{
    if (!g->active || !g->breaks || max < 1)
        return 0;
    double rx = x - g->origin[0], rz = z - g->origin[1];
    double s = g->dir[0] * rx + g->dir[1] * rz, w = g->across[0] * rx + g->across[1] * rz;
    tl_giant_lip lip;
    tl_giant_lip_at(g, w, base, &lip);
    if (!lip.present)
        return 0;
    /* The tube's boundary is no longer on circles (it thins along the
     * arc): the vertical line's crossings are the sign changes of the
     * distance over its span, TL_GIANT_LIP_SCAN intervals of it, each
     * bisected to rounding. The thinnest part (the free end) is many
     * intervals thick. */
    double found[8];
    int n = 0;
    const double reach = lip.radius + lip.thickness * (1.0 + TL_GIANT_LIP_LUMP);
    const double lo = lip.center[1] - reach, hi = lip.center[1] + reach;
    const double tolerance = 1e-9 * (lip.radius + 1.0);
    double y0 = fmax(lo, floor), d0 = tl_giant_lip_distance(&lip, s, y0);
    for (int k = 1; k <= TL_GIANT_LIP_SCAN && n < 8; k++) {
        double y1 = lo + (hi - lo) * k / TL_GIANT_LIP_SCAN;
        if (y1 <= y0)
            continue;
        double d1 = tl_giant_lip_distance(&lip, s, y1);
        if ((d0 < 0.0) != (d1 < 0.0)) {
            double a = y0, b = y1, da = d0;
            for (int it = 0; it < 60 && b - a > tolerance; it++) {
                double m = 0.5 * (a + b), dm = tl_giant_lip_distance(&lip, s, m);
                if ((dm < 0.0) == (da < 0.0)) {
                    a = m;
                    da = dm;
                } else {
                    b = m;
                }
            }
            found[n++] = 0.5 * (a + b);
        }
        y0 = y1;
        d0 = d1;
    }
    qsort(found, (size_t)n, sizeof found[0], compare_doubles);
    int count = 0;
    for (int i = 0; i < n && count < max; i++)
        if (count == 0 || found[i] - heights[count - 1] > tolerance)
            heights[count++] = found[i];
    return count;
}
