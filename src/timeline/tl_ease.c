#include "tl_ease.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

static const char *const family_names[TL_EASE_FAMILY_COUNT] = {
    "sine", "quad", "cubic", "quart", "quint", "expo", "circ", "back", "bounce", "elastic",
};

/* Every "ease-<dir>-<family>" spelled out, so tl_ease_name needs no buffer. */
static const char *const full_names[TL_EASE_FAMILY_COUNT][TL_EASE_DIR_COUNT] = {
    {"ease-in-sine", "ease-out-sine", "ease-in-out-sine"},
    {"ease-in-quad", "ease-out-quad", "ease-in-out-quad"},
    {"ease-in-cubic", "ease-out-cubic", "ease-in-out-cubic"},
    {"ease-in-quart", "ease-out-quart", "ease-in-out-quart"},
    {"ease-in-quint", "ease-out-quint", "ease-in-out-quint"},
    {"ease-in-expo", "ease-out-expo", "ease-in-out-expo"},
    {"ease-in-circ", "ease-out-circ", "ease-in-out-circ"},
    {"ease-in-back", "ease-out-back", "ease-in-out-back"},
    {"ease-in-bounce", "ease-out-bounce", "ease-in-out-bounce"},
    {"ease-in-elastic", "ease-out-elastic", "ease-in-out-elastic"},
};

/* u^n for the polynomial families. */
static double ipow(double u, int n)
{
    double r = 1.0;
    for (int i = 0; i < n; i++)
        r *= u;
    return r;
}

/* Polynomial ease of degree n (quad..quint), written as Penner does. */
static double ease_poly(int n, tl_ease_dir dir, double u)
{
    double sign = (n % 2 == 0) ? -1.0 : 1.0; /* even powers need a flip on the way out */
    switch (dir) {
    case TL_EASE_IN:
        return ipow(u, n);
    case TL_EASE_OUT:
        return sign * (ipow(u - 1.0, n) - (n % 2 == 0 ? 1.0 : -1.0));
    default:
        if (u < 0.5)
            return 0.5 * ipow(2.0 * u, n);
        return 0.5 * (sign * ipow(2.0 * u - 2.0, n) + 2.0);
    }
}

static double bounce_out(double u)
{
    const double k = 7.5625;
    if (u < 1.0 / 2.75)
        return k * u * u;
    if (u < 2.0 / 2.75) {
        u -= 1.5 / 2.75;
        return k * u * u + 0.75;
    }
    if (u < 2.5 / 2.75) {
        u -= 2.25 / 2.75;
        return k * u * u + 0.9375;
    }
    u -= 2.625 / 2.75;
    return k * u * u + 0.984375;
}

/* Blender's elastic_blend: with an amplitude below the change the wave is
 * scaled down by amplitude / |change| (to nothing for 0), blending linearly
 * back to full size over the last quarter period before the end it eases
 * into, where x (the shifted normalised time) reaches 0. */
static double elastic_blend(double x, double change, double duration, double amplitude, double s)
{
    double f = 1.0;
    if (change != 0.0) {
        double reach = fabs(s), at = fabs(x * duration);
        f = amplitude != 0.0 ? amplitude / fabs(change) : 0.0;
        if (at < reach) {
            double l = at / reach;
            f = f * l + (1.0 - l);
        }
    }
    return f;
}

/* BLI_easing_elastic_ease_{in,out,in_out} less the start value, in double. */
static double ease_elastic(tl_ease_dir dir, double u, double change, double duration,
                           double amplitude, double period)
{
    if (u <= 0.0)
        return 0.0;
    if (u >= 1.0)
        return change;
    double x; /* Blender's shifted time: 0 where the wave is largest */
    if (dir == TL_EASE_IN)
        x = u - 1.0;
    else if (dir == TL_EASE_OUT)
        x = -u;
    else
        x = 2.0 * u - 1.0;
    if (period == 0.0)
        period = duration *
                 (dir == TL_EASE_IN_OUT ? TL_EASE_ELASTIC_PERIOD_IN_OUT : TL_EASE_ELASTIC_PERIOD);
    double s, f = 1.0;
    if (amplitude == 0.0 || amplitude < fabs(change)) {
        s = period / 4.0;
        f = elastic_blend(x, change, duration, amplitude, s);
        amplitude = change;
    } else {
        s = period / (2.0 * M_PI) * asin(change / amplitude);
    }
    /* In (and the first half of in-out) eases out of the start value,
     * out (and the second half) into the end value. */
    bool into_end = dir == TL_EASE_OUT || (dir == TL_EASE_IN_OUT && x >= 0.0);
    if (dir == TL_EASE_IN_OUT) {
        f *= into_end ? 0.5 : -0.5;
        x = into_end ? -x : x;
    } else if (dir == TL_EASE_IN) {
        f = -f;
    }
    double wave =
        f * amplitude * pow(2.0, 10.0 * x) * sin((x * duration - s) * (2.0 * M_PI) / period);
    return into_end ? wave + change : wave;
}

static double ease_back(tl_ease_dir dir, double u, double s)
{
    switch (dir) {
    case TL_EASE_IN:
        return u * u * ((s + 1.0) * u - s);
    case TL_EASE_OUT:
        u -= 1.0;
        return u * u * ((s + 1.0) * u + s) + 1.0;
    default:
        s *= 1.525;
        u *= 2.0;
        if (u < 1.0)
            return 0.5 * (u * u * ((s + 1.0) * u - s));
        u -= 2.0;
        return 0.5 * (u * u * ((s + 1.0) * u + s) + 2.0);
    }
}

/* Penner's expo misses 0 and 1 by 2^-10; Blender (2.91 on) rescales it so
 * the curve starts at 0 and ends at 1 without a jump. */
static double expo_in(double u)
{
    const double lo = 1.0 / 1024.0;
    return u <= 0.0 ? 0.0 : (pow(2.0, 10.0 * (u - 1.0)) - lo) / (1.0 - lo);
}

static double ease_expo(tl_ease_dir dir, double u)
{
    switch (dir) {
    case TL_EASE_IN: return expo_in(u);
    case TL_EASE_OUT: return 1.0 - expo_in(1.0 - u);
    default:
        if (u <= 0.5)
            return 0.5 * expo_in(2.0 * u);
        return 0.5 + 0.5 * (1.0 - expo_in(2.0 - 2.0 * u));
    }
}

static double ease_circ(tl_ease_dir dir, double u)
{
    switch (dir) {
    case TL_EASE_IN:
        return 1.0 - sqrt(fmax(0.0, 1.0 - u * u));
    case TL_EASE_OUT:
        u -= 1.0;
        return sqrt(fmax(0.0, 1.0 - u * u));
    default:
        u *= 2.0;
        if (u < 1.0)
            return 0.5 * (1.0 - sqrt(fmax(0.0, 1.0 - u * u)));
        u -= 2.0;
        return 0.5 * (sqrt(fmax(0.0, 1.0 - u * u)) + 1.0);
    }
}

static double ease_bounce(tl_ease_dir dir, double u)
{
    switch (dir) {
    case TL_EASE_IN:
        return 1.0 - bounce_out(1.0 - u);
    case TL_EASE_OUT:
        return bounce_out(u);
    default:
        if (u < 0.5)
            return 0.5 * (1.0 - bounce_out(1.0 - 2.0 * u));
        return 0.5 * bounce_out(2.0 * u - 1.0) + 0.5;
    }
}

static double ease_sine(tl_ease_dir dir, double u)
{
    switch (dir) {
    case TL_EASE_IN:
        return 1.0 - cos(u * M_PI_2);
    case TL_EASE_OUT:
        return sin(u * M_PI_2);
    default:
        return 0.5 * (1.0 - cos(M_PI * u));
    }
}

double tl_ease(tl_ease_family family, tl_ease_dir dir, double u)
{
    if (!(u > 0.0))
        u = 0.0; /* also catches NaN */
    if (u > 1.0)
        u = 1.0;
    if ((unsigned)dir >= TL_EASE_DIR_COUNT)
        return u;
    switch (family) {
    case TL_EASE_SINE:
        return ease_sine(dir, u);
    case TL_EASE_QUAD:
        return ease_poly(2, dir, u);
    case TL_EASE_CUBIC:
        return ease_poly(3, dir, u);
    case TL_EASE_QUART:
        return ease_poly(4, dir, u);
    case TL_EASE_QUINT:
        return ease_poly(5, dir, u);
    case TL_EASE_EXPO:
        return ease_expo(dir, u);
    case TL_EASE_CIRC:
        return ease_circ(dir, u);
    case TL_EASE_BACK: return ease_back(dir, u, TL_EASE_BACK_OVERSHOOT);
    case TL_EASE_BOUNCE:
        return ease_bounce(dir, u);
    case TL_EASE_ELASTIC: return ease_elastic(dir, u, 1.0, 1.0, 1.0, 0.0);
    default:
        return u;
    }
}

double tl_ease_segment(tl_ease_family family, tl_ease_dir dir, const tl_ease_params *params,
                       double u, double change, double duration)
{
    if (!(u > 0.0))
        u = 0.0;
    if (u > 1.0)
        u = 1.0;
    if (params && (unsigned)dir < TL_EASE_DIR_COUNT) {
        if (family == TL_EASE_BACK)
            return change * ease_back(dir, u, params->back);
        if (family == TL_EASE_ELASTIC)
            return ease_elastic(dir, u, change, duration, params->amplitude, params->period);
    }
    return change * tl_ease(family, dir, u);
}

bool tl_ease_from_name(const char *name, tl_ease_family *family, tl_ease_dir *dir)
{
    if (!name)
        return false;
    for (int f = 0; f < TL_EASE_FAMILY_COUNT; f++) {
        for (int d = 0; d < TL_EASE_DIR_COUNT; d++) {
            if (strcmp(name, full_names[f][d]) == 0) {
                if (family)
                    *family = (tl_ease_family)f;
                if (dir)
                    *dir = (tl_ease_dir)d;
                return true;
            }
        }
    }
    return false;
}

const char *tl_ease_name(tl_ease_family family, tl_ease_dir dir)
{
    if ((unsigned)family >= TL_EASE_FAMILY_COUNT || (unsigned)dir >= TL_EASE_DIR_COUNT)
        return NULL;
    return full_names[family][dir];
}

const char *tl_ease_family_name(tl_ease_family family)
{
    if ((unsigned)family >= TL_EASE_FAMILY_COUNT)
        return NULL;
    return family_names[family];
}
