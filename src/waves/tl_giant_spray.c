#include "tl_giant_spray.h"

#include "tl_bow_spray.h"
#include "tl_glsl.h"
#include "tl_noise.h"

#include <math.h>
#include <string.h>

/* The plume's thickness (metres, its Gaussian's scale) over a crest
 * `height` tall whose spray reaches `reach` back. */
static double plume_rise(double height, double reach)
{
    return TL_SPRAY_RISE * (height + reach);
}

/* Where the crest's top is at w, and its height there: as the lip's
 * anchor (tl_giant_lip_at). */
static double crest_top(const tl_giant *g, double w, double base, double *top_s, double *height)
{
    double dl, db, lambda = tl_giant_lambda(g, w, &dl);
    *height = lambda * g->amplitude;
    *top_s = tl_giant_bow(g, w, &db) + lambda * g->curl / g->k;
    return base + *height;
}

/* The burst at the bow where the hull lies on the wave's slope along its
 * heading, either way (heading into a face the bow slams into it; lifted
 * from behind, it digs into the water below): its strength, centre and
 * radius. */
static double bow_burst(const tl_giant *g, const tl_giant_hull *hull, double centre[3],
                        double *radius)
{
    tl_giant_sample smp;
    tl_giant_sample_at(g, hull->stem[0], hull->stem[2], 8, &smp);
    double slope = fabs(smp.grad[0] * hull->heading[0] + smp.grad[1] * hull->heading[1]);
    *radius = TL_SPRAY_BOW_RADIUS * hull->length;
    centre[0] = hull->stem[0] + hull->heading[0] * 0.5 * *radius;
    centre[1] = hull->stem[1] + 0.6 * *radius;
    centre[2] = hull->stem[2] + hull->heading[1] * 0.5 * *radius;
    return tl_smoothstep(TL_SPRAY_BOW_SLOPE_FROM, TL_SPRAY_BOW_SLOPE, slope);
}

/* The burst where the crest passes under the hull: its strength, centre
 * (over the crest where it meets the hull) and radius, and `*hold`, how
 * much it holds the bow's burst off (all of it from when it starts until
 * as long again after it has gone: the bow's burst, metres away, takes
 * over only once the crossing's has faded). The crest moves toward +s, so
 * it meets the end with the lower s first; u is how far it has come along
 * the hull from there, in hull lengths. A hull lying along the crest
 * (beam on) does not split it: no burst. */
static double crossing_burst(const tl_giant *g, const tl_giant_hull *hull, double base,
                             double centre[3], double *radius, double *split, double *hold)
{
    *hold = 0.0;
    double mid[2] = {0.5 * (hull->stem[0] + hull->stern[0]),
                     0.5 * (hull->stem[2] + hull->stern[2])};
    double w = g->across[0] * (mid[0] - g->origin[0]) + g->across[1] * (mid[1] - g->origin[1]);
    double s_stem =
        g->dir[0] * (hull->stem[0] - g->origin[0]) + g->dir[1] * (hull->stem[2] - g->origin[1]);
    double s_stern =
        g->dir[0] * (hull->stern[0] - g->origin[0]) + g->dir[1] * (hull->stern[2] - g->origin[1]);
    double span = fabs(s_stern - s_stem);
    if (!(span > 0.3 * hull->length))
        return 0.0;
    double top_s, height, top_y = crest_top(g, w, base, &top_s, &height);
    const double *first = s_stem < s_stern ? hull->stem : hull->stern;
    const double *last = s_stem < s_stern ? hull->stern : hull->stem;
    double u = (top_s - fmin(s_stem, s_stern)) / span;
    double tall =
        tl_smoothstep(TL_SPRAY_FROM, TL_SPRAY_FULL, height / (g->lambda_max * g->amplitude));
    double start = tl_smoothstep(-TL_SPRAY_CROSS_EARLY, 0.0, u);
    double strength = start * (1.0 - tl_smoothstep(1.0, 1.0 + TL_SPRAY_CROSS_LATE, u)) * tall;
    *hold = start * tall *
            (1.0 - tl_smoothstep(1.0 + TL_SPRAY_CROSS_LATE, 1.0 + 2.0 * TL_SPRAY_CROSS_LATE, u));
    if (!(strength > 0.0))
        return 0.0;
    double k = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u, at[3];
    for (int i = 0; i < 3; i++)
        at[i] = first[i] + k * (last[i] - first[i]);
    *radius = TL_SPRAY_CROSS_RADIUS * hull->length;
    *split = TL_SPRAY_CROSS_SPLIT * hull->length;
    centre[0] = at[0];
    /* A skirt where the hull splits the crest, the bow rising out of it:
     * centred higher, it veiled the bow. */
    centre[1] = fmax(at[1], top_y) - 0.1 * *radius;
    centre[2] = at[2];
    return strength;
}

/* The boat's burst: at its bow on a steep face, over the crest where the
 * crest passes under the hull; as the crest reaches the hull, the centre
 * and radius move from the bow's to the crossing's by their shares (no
 * jump from frame to frame). */
static void prepare_burst(tl_giant_spray *sp, const tl_giant *g, double amount,
                          const tl_giant_hull *hull)
{
    /* Set even where the crossing has none: weighted by 0 it must not be
     * garbage (0 times NaN is NaN). */
    double at_bow[3], at_crest[3] = {0.0, 0.0, 0.0}, r_bow, r_crest = 0.0, split = 0.0, hold;
    double crest = crossing_burst(g, hull, sp->base, at_crest, &r_crest, &split, &hold);
    double bow = bow_burst(g, hull, at_bow, &r_bow) * (1.0 - hold);
    if (!(bow + crest > 0.0))
        return;
    double k = crest / (bow + crest);
    for (int i = 0; i < 3; i++)
        sp->bow[i] = at_bow[i] + k * (at_crest[i] - at_bow[i]);
    sp->bow_radius = r_bow + k * (r_crest - r_bow);
    sp->bow_split = k * split; /* the bow's burst is one sheet */
    sp->shelter = crest;
    sp->bow_amount = amount * fmax(TL_SPRAY_BOW_GAIN * bow, TL_SPRAY_CROSS_GAIN * crest);
    sp->heading[0] = hull->heading[0];
    sp->heading[1] = hull->heading[1];
    sp->active = true;
}

void tl_giant_spray_prepare(tl_giant_spray *sp, const tl_giant *g, double amount, double wind,
                            double t, double depth, const tl_giant_hull *hull)
{
    memset(sp, 0, sizeof *sp);
    if (!g->active || !(amount > 0.0))
        return;
    sp->amount = amount;
    sp->base = -0.5 * depth;
    double full = g->lambda_max * g->amplitude;
    sp->reach = TL_SPRAY_FLIGHT * wind + 0.05 * full;
    sp->drift = fmod(wind * t, 4096.0);
    if (sp->drift < 0.0)
        sp->drift += 4096.0;
    /* The plume's box: behind the crest by TL_SPRAY_REACHES of its reach,
     * ahead by a tenth of the crest, and from TL_SPRAY_BOX_RISES rises
     * below the lowest tall top to as many above the highest lifted one
     * (the layer is down to e^-6.25 of its middle there): a tight box
     * keeps the shader's few steps inside the plume. Where no stretch
     * of the crest is tall enough, no spray. */
    bool tall = false;
    const int n = TL_GIANT_PROFILE_SAMPLES;
    double s_lo = 1e30, s_hi = -1e30, y_lo = 1e30, y_hi = -1e30;
    for (int i = 0; i <= n; i++) {
        double w = -g->half_width + 2.0 * g->half_width * i / n, top_s, height;
        double top_y = crest_top(g, w, sp->base, &top_s, &height);
        if (height < TL_SPRAY_FROM * g->amplitude)
            continue;
        tall = true;
        double rise = plume_rise(height, sp->reach);
        s_lo = fmin(s_lo, top_s - TL_SPRAY_REACHES * sp->reach);
        s_hi = fmax(s_hi, top_s + 0.1 * full);
        y_lo = fmin(y_lo, top_y - TL_SPRAY_BOX_RISES * rise);
        y_hi =
            fmax(y_hi, top_y + (TL_SPRAY_LIFT * (1.0 + TL_SPRAY_GUST) + TL_SPRAY_BOX_RISES) * rise);
    }
    if (tall) {
        sp->box[0] = s_lo;
        sp->box[1] = s_hi;
        sp->box[2] = y_lo;
        sp->box[3] = y_hi;
        sp->active = true;
    }
    /* The lip's landing: its box, widened by the cloud's reach. */
    double lip[4], across[2];
    if (tl_giant_lip_bounds(g, sp->base, lip, across)) {
        double grow = (3.0 * TL_SPRAY_LANDING_RADIUS * (1.0 + TL_SPRAY_SPLASH_GROW) +
                       TL_SPRAY_SPLASH_RISE + TL_SPRAY_SPLASH_AHEAD) *
                      TL_GIANT_LIP_RADIUS * full;
        sp->box[0] = fmin(sp->active ? sp->box[0] : 1e30, lip[0] - grow);
        sp->box[1] = fmax(sp->active ? sp->box[1] : -1e30, lip[1] + grow);
        sp->box[2] = fmin(sp->active ? sp->box[2] : 1e30, lip[2] - grow);
        sp->box[3] = fmax(sp->active ? sp->box[3] : -1e30, lip[3] + grow);
        sp->active = true;
    }
    if (hull && hull->length > 0.0)
        prepare_burst(sp, g, amount, hull);
}

double tl_giant_spray_gust(double w)
{
    return 1.0 + TL_SPRAY_GUST * (2.0 * tl_noise_value(w / TL_SPRAY_GUST_CELL, 41.7) - 1.0);
}

double tl_giant_spray_layer(double x, double r, double span)
{
    double h = 0.5 * span, g = exp(-x * x / (r * r));
    /* Below a tenth of the rise the difference of two erfs cancels (in the
     * shader's float): there the mean's Taylor series to h⁴, with u = x/r
     * and e = h/r, g·(1 + e²(2u² − 1)/3 + e⁴(4u⁴ − 12u² + 3)/30). */
    if (h < 0.1 * r) {
        double u2 = x * x / (r * r), e2 = h * h / (r * r);
        return g * (1.0 + e2 * (2.0 * u2 - 1.0) / 3.0 +
                    e2 * e2 * (4.0 * u2 * u2 - 12.0 * u2 + 3.0) / 30.0);
    }
    return 0.25 * sqrt(M_PI) * r / h * (erf((x + h) / r) - erf((x - h) / r));
}

/* The droplets the lip's free edge tears off while it throws, at (s, y)
 * and the lip's w (TL_SPRAY_TIP_*). */
static double tip_density(const tl_giant_spray *sp, const tl_giant_lip *lip, double s, double y)
{
    if (!lip->present)
        return 0.0;
    double ts = lip->center[0] + lip->radius * TL_GIANT_LIP_THROW * sin(lip->to) - s;
    double ty = lip->center[1] + lip->radius * cos(lip->to) - y;
    double r = TL_SPRAY_TIP_RADIUS * lip->radius;
    double torn = TL_SPRAY_TIP_GAIN * sp->amount *
                  tl_smoothstep(TL_SPRAY_TIP_START, TL_SPRAY_TIP_FULL, lip->progress) *
                  (1.0 - tl_smoothstep(TL_SPRAY_TIP_FADE, TL_SPRAY_TIP_GONE, lip->progress));
    if (!(torn > 0.0))
        return 0.0;
    return torn * tl_giant_spray_billows(exp(-(ts * ts + ty * ty) / (r * r)),
                                         lip->w * TL_SPRAY_TIP_SCALE, ts * TL_SPRAY_TIP_SCALE,
                                         ty * TL_SPRAY_TIP_SCALE);
}

/* The lip's landing cloud as seen from (s, y) at the lip's w: the offset
 * (ts, ty) from the point to the cloud's middle, its radius, and its
 * density at the middle (before the noise); false where there is none. */
static bool landing_at(const tl_giant_spray *sp, const tl_giant_lip *lip, double s, double y,
                       double *ts, double *ty, double *r, double *peak)
{
    if (!lip->present || !(lip->progress > TL_SPRAY_LANDING_FROM))
        return false;
    double ahead = TL_SPRAY_SPLASH_AHEAD * (0.3 + 0.7 * lip->spent);
    *ts = lip->center[0] + lip->radius * (TL_GIANT_LIP_THROW * sin(lip->to) + ahead) - s;
    *ty = lip->center[1] + lip->radius * (cos(lip->to) + TL_SPRAY_SPLASH_RISE * lip->spent) - y;
    *r = TL_SPRAY_LANDING_RADIUS * lip->radius * (1.0 + TL_SPRAY_SPLASH_GROW * lip->spent) *
         (TL_SPRAY_LANDING_SEED +
          (1.0 - TL_SPRAY_LANDING_SEED) * tl_smoothstep(TL_SPRAY_LANDING_FROM, 1.0, lip->progress));
    *peak = TL_SPRAY_LANDING_GAIN * sp->amount * (1.0 - lip->spent * lip->spent);
    return true;
}

/* The landing cloud as seen from world (x, y, z) in the spray's box: the
 * point's w and landing_at's values; false outside the box or where the
 * lip there has no landing. */
static bool landing_near(const tl_giant_spray *sp, const tl_giant *g, double x, double y, double z,
                         double *w, double *ts, double *ty, double *r, double *peak)
{
    if (!sp->active)
        return false;
    double rx = x - g->origin[0], rz = z - g->origin[1];
    double s = g->dir[0] * rx + g->dir[1] * rz;
    *w = g->across[0] * rx + g->across[1] * rz;
    if (!(fabs(*w) < g->half_width && s >= sp->box[0] && s <= sp->box[1] && y >= sp->box[2] &&
          y <= sp->box[3]))
        return false;
    tl_giant_lip lip;
    tl_giant_lip_at(g, *w, sp->base, &lip);
    return landing_at(sp, &lip, s, y, ts, ty, r, peak);
}

double tl_giant_spray_landing_shade(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                                    double z, const double sun[3])
{
    double w, ts, ty, r, peak;
    if (!landing_near(sp, g, x, y, z, &w, &ts, &ty, &r, &peak))
        return 0.0;
    /* Toward the sun the point's (s, y) moves by v per metre, so the
     * offset to the cloud's middle is q - v t; with u = |v| t, a = q·v/|v|
     * and d² = |q|² - a², the envelope's integral over t >= 0 is
     * exp(-d²/r²) (sqrt(pi) r / 2) (1 + erf(a / r)) / |v|. A sun along
     * the crest (|v| small) is held at 0.1: the tube is long, not endless. */
    double vs = sun[0] * g->dir[0] + sun[2] * g->dir[1], vy = sun[1];
    double len = hypot(vs, vy), reach = fmax(len, 0.1);
    double a = len > 1e-9 ? (ts * vs + ty * vy) / len : 0.0;
    double d2 = fmax(ts * ts + ty * ty - a * a, 0.0);
    double integral = exp(-d2 / (r * r)) * 0.5 * sqrt(M_PI) * r * (1.0 + erf(a / r)) / reach;
    return TL_SPRAY_SIGMA * peak * TL_SPRAY_LANDING_MEAN * integral;
}

double tl_giant_spray_density(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                              double z, double span)
{
    if (!sp->active)
        return 0.0;
    double rx = x - g->origin[0], rz = z - g->origin[1];
    double s = g->dir[0] * rx + g->dir[1] * rz, w = g->across[0] * rx + g->across[1] * rz;
    double density = 0.0;
    if (fabs(w) < g->half_width && s >= sp->box[0] && s <= sp->box[1] && y >= sp->box[2] &&
        y <= sp->box[3]) {
        double top_s, height;
        double top_y = crest_top(g, w, sp->base, &top_s, &height);
        double dp, breaking = g->breaks ? tl_giant_break_progress(g, w, &dp) : 0.0;
        double source = tl_smoothstep(TL_SPRAY_FROM, TL_SPRAY_FULL, height / g->amplitude) *
                        (0.4 + 0.6 * breaking);
        double back = top_s - s, up = y - top_y;
        double rise = plume_rise(height, sp->reach);
        double gust = tl_giant_spray_gust(w);
        double lift = TL_SPRAY_LIFT * rise * gust * sqrt(fmin(fmax(back, 0.0) / sp->reach, 1.0));
        double plume =
            tl_smoothstep(-0.05 * height, 0.05 * height, back) * exp(-fmax(back, 0.0) / sp->reach) *
            (1.0 + TL_SPRAY_ROOT_GAIN * exp(-fmax(back, 0.0) / (TL_SPRAY_ROOT_REACH * sp->reach))) *
            (1.0 - tl_smoothstep(0.6, 1.0, back / (TL_SPRAY_REACHES * sp->reach))) *
            tl_giant_spray_layer(up - lift, rise + 1e-6, span);
        /* Streaks drawn out along the wind, narrow across the crest. */
        double drifted = back + sp->drift;
        double wisps = tl_smoothstep(0.3, 0.75,
                                     0.65 * tl_noise_value(w / 0.9, drifted / 6.0 + up / 2.0) +
                                         0.35 * tl_noise_value(w / 0.4, drifted / 2.5 - up / 0.8));
        if (sp->shelter > 0.0) {
            double bw = g->across[0] * (sp->bow[0] - g->origin[0]) +
                        g->across[1] * (sp->bow[2] - g->origin[1]);
            source *=
                1.0 - sp->shelter * (1.0 - tl_smoothstep(TL_SPRAY_SHELTER_IN * sp->bow_radius,
                                                         TL_SPRAY_SHELTER_OUT * sp->bow_radius,
                                                         fabs(w - bw)));
        }
        density += TL_SPRAY_PLUME_GAIN * sp->amount * gust * source * plume *
                   (TL_SPRAY_WISP_FLOOR + (1.0 - TL_SPRAY_WISP_FLOOR) * wisps);
        /* The lip's torn edge and its landing. */
        tl_giant_lip lip;
        tl_giant_lip_at(g, w, sp->base, &lip);
        density += tip_density(sp, &lip, s, y);
        double ts, ty, r, peak;
        if (landing_at(sp, &lip, s, y, &ts, &ty, &r, &peak)) {
            density +=
                peak * tl_giant_spray_whitewater(exp(-(ts * ts + ty * ty) / (r * r)), w, ts, ty, r);
        }
    }
    if (sp->bow_amount > 0.0) {
        const double d[3] = {x - sp->bow[0], y - sp->bow[1], z - sp->bow[2]};
        density +=
            sp->bow_amount * tl_bow_spray_sheet(d, sp->heading, sp->bow_radius, sp->bow_split);
    }
    return density;
}

/* The field less its smaller lumps. */
static double billow_coarse(double envelope, double w, double ts, double ty)
{
    /* Two noises in crossed planes multiplied, round lumps about 1.6 m
     * across in all three directions, with a finer grain. A noise of one
     * plane drew the cloud out in streaks: an airbrushed smear,
     * see-through (judge). */
    double billow =
        tl_noise_value(w / 1.6 + 5.0, ts / 1.6) * tl_noise_value(w / 1.6 - 2.0, ty / 1.6 + 4.0);
    double grain = tl_noise_value(w / 0.5 - 3.0, (ts + ty) / 0.5);
    return (0.8 + 0.2 * grain) * billow + 0.1 * grain +
           TL_SPRAY_LANDING_CLOSE * (sqrt(envelope) - TL_SPRAY_LANDING_OPEN);
}

/* Smaller lumps on them, 0.6 m (crossed) and 0.25 m, cut their edges into
 * cauliflower: smooth 1.6 m lumps alone read as cotton wool (judge).
 * TL_SPRAY_LANDING_FINE_LOW .. _HIGH. */
static double billow_fine(double w, double ts, double ty)
{
    double fine =
        tl_noise_value(w / 0.6 + 1.3, ts / 0.6) * tl_noise_value(w / 0.6 - 4.1, ty / 0.6 + 2.2);
    double finer = tl_noise_value(w / 0.25 + 7.7, (ts - ty) / 0.25);
    return TL_SPRAY_LANDING_FINE * (fine - 0.25) + TL_SPRAY_LANDING_FINER * (finer - 0.5);
}

/* smoothstep(lo, hi) of the field, the smaller lumps taken only where
 * they can change it (the same value: the shader's saves their noise). */
static double billow_ramp(double lo, double hi, double envelope, double w, double ts, double ty)
{
    double coarse = billow_coarse(envelope, w, ts, ty);
    if (coarse + TL_SPRAY_LANDING_FINE_HIGH <= lo)
        return 0.0;
    if (coarse + TL_SPRAY_LANDING_FINE_LOW >= hi)
        return 1.0;
    return tl_smoothstep(lo, hi, coarse + billow_fine(w, ts, ty));
}

double tl_giant_spray_billows(double envelope, double w, double ts, double ty)
{
    double cover = sqrt(envelope);
    return tl_smoothstep(TL_SPRAY_LANDING_EDGE_FROM, TL_SPRAY_LANDING_EDGE_TO, cover) *
           billow_ramp(TL_SPRAY_LANDING_TEAR_FROM, TL_SPRAY_LANDING_TEAR_TO, envelope, w, ts, ty);
}

/* Where the jets can be: their shell and their upward side, 0 .. 1. */
static double jet_reach(double ts, double ty, double r, double *dx, double *dy)
{
    double js = -ts, jy = TL_SPRAY_JET_DROP * r - ty; /* forward and up from the impact */
    double rho = hypot(js, jy);
    *dx = rho > 1e-9 ? js / rho : 0.0;
    *dy = rho > 1e-9 ? jy / rho : 0.0;
    return tl_smoothstep(TL_SPRAY_JET_FROM * r, TL_SPRAY_JET_IN * r, rho) *
           (1.0 - tl_smoothstep(TL_SPRAY_JET_OUT * r, TL_SPRAY_JET_END * r, rho)) *
           tl_smoothstep(-0.2, 0.4, *dy);
}

double tl_giant_spray_jets(double w, double ts, double ty, double r)
{
    double dx, dy, reach = jet_reach(ts, ty, r, &dx, &dy);
    if (!(reach > 0.0))
        return 0.0;
    /* Noises of the direction (a point on the unit circle, so no seam
     * where the angle wraps) and of w. */
    double streak = tl_noise_value(6.0 * dx + w / 1.2, 6.0 * dy + 3.3) *
                    tl_noise_value(15.0 * dx - 1.7, 15.0 * dy + w / 0.5);
    return TL_SPRAY_JET * reach * tl_smoothstep(0.35, 0.6, streak);
}

double tl_giant_spray_whitewater(double envelope, double w, double ts, double ty, double r)
{
    return tl_giant_spray_billows(envelope, w, ts, ty) + TL_SPRAY_LANDING_MIST * sqrt(envelope) +
           tl_giant_spray_jets(w, ts, ty, r);
}

/* What of a light along (ls, ly) in the crest's cross-section and lw
 * across it a billow at (w, ts, ty) of a cloud of radius r lets in. */
static double billow_open(double w, double ts, double ty, double r, double ls, double lw, double ly)
{
    double s2 = ts - TL_SPRAY_BURY_STEP * ls, y2 = ty - TL_SPRAY_BURY_STEP * ly;
    return 1.0 - TL_SPRAY_BURY * billow_ramp(TL_SPRAY_BURY_FROM, TL_SPRAY_BURY_TO,
                                             exp(-(s2 * s2 + y2 * y2) / (r * r)),
                                             w + TL_SPRAY_BURY_STEP * lw, s2, y2);
}

double tl_giant_spray_open(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                           double z, double span, const double light[3])
{
    double w, ts, ty, r, peak;
    if (!landing_near(sp, g, x, y, z, &w, &ts, &ty, &r, &peak))
        return 1.0;
    double b = tl_giant_spray_whitewater(exp(-(ts * ts + ty * ty) / (r * r)), w, ts, ty, r);
    if (!(b > 0.1) || !(peak > 0.0))
        return 1.0;
    double ls = light[0] * g->dir[0] + light[2] * g->dir[1],
           lw = light[0] * g->across[0] + light[2] * g->across[1];
    double open = billow_open(w, ts, ty, r, ls, lw, light[1]);
    double share = peak * b / tl_giant_spray_density(sp, g, x, y, z, span);
    return 1.0 + (open - 1.0) * share;
}

double tl_giant_spray_shade(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                            double z, const double sun[3])
{
    double shade = tl_giant_spray_landing_shade(sp, g, x, y, z, sun);
    const double d[3] = {x - sp->bow[0], y - sp->bow[1], z - sp->bow[2]};
    /* Only where the sheet holds spray: the shade of empty air is no use. */
    if (sp->bow_amount > 0.0 &&
        tl_bow_spray_sheet(d, sp->heading, sp->bow_radius, sp->bow_split) > 0.0) {
        shade += TL_SPRAY_SIGMA * sp->bow_amount * TL_BOW_SPRAY_TORN_MEAN *
                 tl_bow_spray_sheet_depth(d, sp->heading, sp->bow_radius, sp->bow_split, sun);
    }
    return shade;
}

void tl_giant_hull_of(tl_giant_hull *hull, const tl_boat *b)
{
    /* Bow down on a face the stem is metres below the boat's middle (taken
     * level, the burst rose from the crest beside the boat, not from its
     * bow). */
    hull->heading[0] = sin(b->heading);
    hull->heading[1] = cos(b->heading);
    hull->length = b->length;
    double reach = 0.5 * b->length * cos(b->pitch);
    const double ahead[3] = {hull->heading[0] * reach, 0.5 * b->length * sin(b->pitch),
                             hull->heading[1] * reach};
    for (int i = 0; i < 3; i++) {
        hull->stem[i] = b->position[i] + ahead[i];
        hull->stern[i] = b->position[i] - ahead[i];
    }
}
