#include "timeline/tl_curve.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const char *const interp_names[TL_INTERP_COUNT] = {
    "constant", "linear", "bezier", "ease", "spline",
};
static const char *const handle_names[TL_HANDLE_COUNT] = {
    "auto-clamped", "auto", "vector", "aligned", "free",
};
static const char *const extrap_names[TL_EXTRAP_COUNT] = {
    "constant", "linear", "cycle", "cycle-offset", "ping-pong",
};

static const char *const smoothing_names[TL_SMOOTH_COUNT] = {"none", "continuous"};

static int name_index(const char *const *names, int count, const char *name)
{
    if (!name)
        return -1;
    for (int i = 0; i < count; i++)
        if (strcmp(names[i], name) == 0)
            return i;
    return -1;
}

const char *tl_interp_name(tl_interp interp)
{
    return (unsigned)interp < TL_INTERP_COUNT ? interp_names[interp] : NULL;
}

bool tl_interp_from_name(const char *name, tl_interp *out)
{
    int i = name_index(interp_names, TL_INTERP_COUNT, name);
    if (i >= 0 && out)
        *out = (tl_interp)i;
    return i >= 0;
}

const char *tl_handle_type_name(tl_handle_type type)
{
    return (unsigned)type < TL_HANDLE_COUNT ? handle_names[type] : NULL;
}

bool tl_handle_type_from_name(const char *name, tl_handle_type *out)
{
    int i = name_index(handle_names, TL_HANDLE_COUNT, name);
    if (i >= 0 && out)
        *out = (tl_handle_type)i;
    return i >= 0;
}

const char *tl_extrap_name(tl_extrap extrap)
{
    return (unsigned)extrap < TL_EXTRAP_COUNT ? extrap_names[extrap] : NULL;
}

bool tl_extrap_from_name(const char *name, tl_extrap *out)
{
    int i = name_index(extrap_names, TL_EXTRAP_COUNT, name);
    if (i >= 0 && out)
        *out = (tl_extrap)i;
    return i >= 0;
}

const char *tl_smoothing_name(tl_smoothing smoothing)
{
    return (unsigned)smoothing < TL_SMOOTH_COUNT ? smoothing_names[smoothing] : NULL;
}

bool tl_smoothing_from_name(const char *name, tl_smoothing *out)
{
    int i = name_index(smoothing_names, TL_SMOOTH_COUNT, name);
    if (i >= 0 && out)
        *out = (tl_smoothing)i;
    return i >= 0;
}

/* ---- storage ---------------------------------------------------------- */

tl_key tl_key_make(double t, double v, tl_interp interp)
{
    tl_key k;
    memset(&k, 0, sizeof k);
    k.t = t;
    k.v = v;
    k.interp = interp;
    k.ease_family = TL_EASE_SINE;
    k.ease_dir = TL_EASE_IN_OUT;
    k.left_type = k.right_type = TL_HANDLE_AUTO_CLAMPED;
    k.left.t = k.right.t = t;
    k.left.v = k.right.v = v;
    k.ease.back = TL_EASE_BACK_OVERSHOOT;
    k.ease.amplitude = TL_EASE_BLENDER_AMPLITUDE;
    k.ease.period = TL_EASE_BLENDER_PERIOD_FRAMES;
    return k;
}

void tl_curve_init(tl_curve *c)
{
    memset(c, 0, sizeof *c);
    c->fps = 24.0;
}

void tl_curve_set_extrap(tl_curve *c, tl_extrap mode)
{
    c->before = c->after = mode;
    c->before_cycles = c->after_cycles = 0;
    c->prepared = false;
}

void tl_curve_free(tl_curve *c)
{
    if (!c)
        return;
    free(c->keys);
    memset(c, 0, sizeof *c);
}

int tl_curve_add_key(tl_curve *c, const tl_key *key, tl_error *err)
{
    if (c->count == c->capacity) {
        size_t cap = c->capacity ? c->capacity * 2 : 8;
        if (cap > SIZE_MAX / sizeof *c->keys)
            return tl_error_set(err, TL_ERR_RUNTIME, "too many keys in one curve");
        tl_key *keys = realloc(c->keys, cap * sizeof *keys);
        if (!keys)
            return tl_error_set(err, TL_ERR_RUNTIME, "out of memory for %zu curve keys", cap);
        c->keys = keys;
        c->capacity = cap;
    }
    c->keys[c->count++] = *key;
    c->prepared = false;
    return 0;
}

/* ---- validation ------------------------------------------------------- */

static bool handle_is_input(tl_handle_type type)
{
    return type == TL_HANDLE_FREE || type == TL_HANDLE_ALIGNED;
}

static int key_error(size_t i, size_t *bad_key, tl_error *err, const char *what)
{
    if (bad_key)
        *bad_key = i;
    return tl_error_set(err, TL_ERR_RUNTIME, "key %zu: %s", i, what);
}

int tl_curve_validate(const tl_curve *c, size_t *bad_key, tl_error *err)
{
    if ((unsigned)c->before >= TL_EXTRAP_COUNT || (unsigned)c->after >= TL_EXTRAP_COUNT)
        return key_error(0, bad_key, err, "invalid extrapolation mode");
    if ((unsigned)c->smoothing >= TL_SMOOTH_COUNT)
        return key_error(0, bad_key, err, "invalid auto-handle smoothing");
    if (!(c->fps > 0.0) || !isfinite(c->fps))
        return key_error(0, bad_key, err, "frames per second must be positive");
    for (size_t i = 0; i < c->count; i++) {
        const tl_key *k = &c->keys[i];
        if (!isfinite(k->t))
            return key_error(i, bad_key, err, "time is not a finite number");
        if (!isfinite(k->v))
            return key_error(i, bad_key, err, "value is not a finite number");
        if ((unsigned)k->interp >= TL_INTERP_COUNT)
            return key_error(i, bad_key, err, "invalid interpolation");
        if (k->interp == TL_INTERP_EASE && ((unsigned)k->ease_family >= TL_EASE_FAMILY_COUNT ||
                                            (unsigned)k->ease_dir >= TL_EASE_DIR_COUNT))
            return key_error(i, bad_key, err, "invalid easing");
        if (!(k->ease.back >= 0.0 && k->ease.amplitude >= 0.0 && k->ease.period >= 0.0) ||
            !isfinite(k->ease.back + k->ease.amplitude + k->ease.period))
            return key_error(i, bad_key, err, "easing settings must be finite and not negative");
        if ((unsigned)k->left_type >= TL_HANDLE_COUNT ||
            (unsigned)k->right_type >= TL_HANDLE_COUNT)
            return key_error(i, bad_key, err, "invalid handle type");
        if ((handle_is_input(k->left_type) && !(isfinite(k->left.t) && isfinite(k->left.v))) ||
            (handle_is_input(k->right_type) && !(isfinite(k->right.t) && isfinite(k->right.v))))
            return key_error(i, bad_key, err, "handle is not a finite point");
        if (i == 0)
            continue;
        const tl_key *p = &c->keys[i - 1];
        if (k->t < p->t) {
            if (bad_key)
                *bad_key = i;
            return tl_error_set(err, TL_ERR_RUNTIME,
                                "key %zu: time %.9g is before the previous key's time %.9g", i,
                                k->t, p->t);
        }
        if (k->t == p->t && !k->cut && p->interp != TL_INTERP_CONSTANT) {
            if (bad_key)
                *bad_key = i;
            return tl_error_set(err, TL_ERR_RUNTIME,
                                "key %zu: same time %.9g as the previous key (allowed only for a "
                                "cut or after a constant key)",
                                i, k->t);
        }
    }
    return 0;
}

/* ---- angles ----------------------------------------------------------- */

void tl_curve_unwrap(tl_curve *c, double period)
{
    if (!(period > 0.0) || !isfinite(period))
        return;
    for (size_t i = 1; i < c->count; i++) {
        tl_key *k = &c->keys[i];
        double turns = nearbyint((k->v - c->keys[i - 1].v) / period);
        if (turns == 0.0 || !isfinite(turns))
            continue;
        double shift = -turns * period;
        k->v += shift;
        k->left.v += shift;
        k->right.v += shift;
    }
    c->prepared = false;
}

/* ---- Bezier segments ---------------------------------------------------- */

/* Real roots of c3 s^3 + c2 s^2 + c1 s + c0 (closed form); returns count. */
static int solve_cubic(double c3, double c2, double c1, double c0, double roots[3])
{
    double scale = fmax(fmax(fabs(c3), fabs(c2)), fmax(fabs(c1), fabs(c0)));
    if (scale == 0.0)
        return 0;
    if (fabs(c3) <= 1e-12 * scale) {
        if (fabs(c2) <= 1e-12 * scale) {
            if (c1 == 0.0)
                return 0;
            roots[0] = -c0 / c1;
            return 1;
        }
        double disc = c1 * c1 - 4.0 * c2 * c0;
        if (disc < 0.0)
            return 0;
        /* Numerically stable quadratic roots. */
        double q = -0.5 * (c1 + copysign(sqrt(disc), c1));
        int n = 0;
        roots[n++] = q / c2;
        if (q != 0.0)
            roots[n++] = c0 / q;
        return n;
    }
    double a = c2 / c3, b = c1 / c3, c = c0 / c3;
    double a3 = a / 3.0;
    double p = b / 3.0 - a3 * a3;
    double q = (2.0 * a3 * a3 * a3 - a3 * b + c) / 2.0;
    double d = q * q + p * p * p;
    if (d > 0.0) {
        double t = sqrt(d);
        roots[0] = cbrt(-q + t) + cbrt(-q - t) - a3;
        return 1;
    }
    if (p == 0.0) {
        roots[0] = -a3; /* triple root */
        return 1;
    }
    double r = sqrt(-p);
    double phi = acos(fmax(-1.0, fmin(1.0, -q / (r * r * r))));
    roots[0] = 2.0 * r * cos(phi / 3.0) - a3;
    roots[1] = 2.0 * r * cos((phi + 2.0 * M_PI) / 3.0) - a3;
    roots[2] = 2.0 * r * cos((phi + 4.0 * M_PI) / 3.0) - a3;
    return 3;
}

/* The parameter s in [0,1] with x(s) = u for the normalised time cubic
 * x(s) = 3a s(1-s)^2 + 3(1-b) s^2(1-s) + s^3 (a, b in [0,1], so x is
 * monotonic). Closed form first, then Newton safeguarded by bisection. */
static double solve_time(double a, double b, double u)
{
    const double c1 = 3.0 * a, c2 = 3.0 - 3.0 * b - 6.0 * a, c3 = 3.0 * a + 3.0 * b - 2.0;
    double roots[3];
    int n = solve_cubic(c3, c2, c1, -u, roots);
    double s = u, best = INFINITY;
    for (int i = 0; i < n; i++) {
        double dist = fmax(0.0, fmax(-roots[i], roots[i] - 1.0));
        if (isfinite(roots[i]) && dist < best) {
            best = dist;
            s = fmin(1.0, fmax(0.0, roots[i]));
        }
    }
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 60; it++) {
        double x = ((c3 * s + c2) * s + c1) * s;
        double f = x - u;
        if (f == 0.0)
            break;
        if (f < 0.0)
            lo = s;
        else
            hi = s;
        double dx = (3.0 * c3 * s + 2.0 * c2) * s + c1;
        double next = (dx > 0.0) ? s - f / dx : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        if (fabs(next - s) <= 1e-15)
            return next;
        s = next;
    }
    return s;
}

/* Blender's BKE_fcurve_correct_bezpart: a handle reaching past the other
 * key in time is scaled down (keeping its direction) to the segment span,
 * which keeps the time polynomial monotonic. */
static void correct_handle(tl_curve_point key, tl_curve_point *handle, double span)
{
    double len = fabs(handle->t - key.t);
    if (len > span) {
        double fac = span / len;
        handle->t = key.t + fac * (handle->t - key.t);
        handle->v = key.v + fac * (handle->v - key.v);
    }
}

static double eval_bezier(const tl_key *k0, const tl_key *k1, double t)
{
    tl_curve_point p0 = {k0->t, k0->v}, p3 = {k1->t, k1->v};
    tl_curve_point p1 = k0->right, p2 = k1->left;
    double span = p3.t - p0.t;
    if (p0.v == p1.v && p1.v == p2.v && p2.v == p3.v)
        return p0.v;
    correct_handle(p0, &p1, span);
    correct_handle(p3, &p2, span);
    double a = fmin(1.0, fmax(0.0, (p1.t - p0.t) / span));
    double b = fmin(1.0, fmax(0.0, (p3.t - p2.t) / span));
    double u = fmin(1.0, fmax(0.0, (t - p0.t) / span));
    double s = solve_time(a, b, u);
    double r = 1.0 - s;
    return r * r * r * p0.v + 3.0 * r * r * s * p1.v + 3.0 * r * s * s * p2.v + s * s * s * p3.v;
}

/* ---- evaluation --------------------------------------------------------- */

static double eval_segment(const tl_curve *c, const tl_key *k0, const tl_key *k1, double t)
{
    double h = k1->t - k0->t;
    double u = (t - k0->t) / h;
    if (!(u > 0.0))
        return k0->v;
    if (u > 1.0)
        u = 1.0;
    switch (k0->interp) {
    case TL_INTERP_LINEAR:
        return (1.0 - u) * k0->v + u * k1->v;
    case TL_INTERP_EASE: {
        tl_ease_params p = k0->ease;
        p.period /= c->fps; /* frames -> seconds, the segment's unit */
        return k0->v + tl_ease_segment(k0->ease_family, k0->ease_dir, &p, u, k1->v - k0->v, h);
    }
    case TL_INTERP_SPLINE: {
        double u2 = u * u, u3 = u2 * u;
        return (2.0 * u3 - 3.0 * u2 + 1.0) * k0->v + (u3 - 2.0 * u2 + u) * h * k0->slope +
               (3.0 * u2 - 2.0 * u3) * k1->v + (u3 - u2) * h * k1->slope;
    }
    case TL_INTERP_BEZIER:
        return eval_bezier(k0, k1, t);
    default:
        return k0->v;
    }
}

/* Value inside [first, last] key time. */
static double eval_inside(const tl_curve *c, double t)
{
    const tl_key *keys = c->keys;
    size_t n = c->count;
    if (t >= keys[n - 1].t)
        return keys[n - 1].v;
    /* Invariant keys[lo].t <= t < keys[hi].t, so the segment has a span. */
    size_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (keys[mid].t <= t)
            lo = mid;
        else
            hi = mid;
    }
    if (keys[lo + 1].cut)
        return keys[lo].v; /* hold until the jump */
    return eval_segment(c, &keys[lo], &keys[lo + 1], t);
}

/* dv/dt leaving the curve at its first (at_end false) or last key. As in
 * Blender, it follows the END KEY's own interpolation, even after the last
 * key, which starts no segment: constant holds, linear continues the chord
 * from its neighbour, Bezier and ease keys their outer handle; a spline key
 * (tideline's own) its tangent. */
static double end_slope(const tl_curve *c, bool at_end)
{
    size_t n = c->count;
    const tl_key *e = at_end ? &c->keys[n - 1] : &c->keys[0];
    const tl_key *nb = at_end ? &c->keys[n - 2] : &c->keys[1];
    if (at_end ? e->cut : nb->cut)
        return 0.0; /* the end key is alone in its section */
    double dt = 0.0, dv = 0.0;
    switch (e->interp) {
    case TL_INTERP_CONSTANT:
        return 0.0;
    case TL_INTERP_LINEAR:
        dt = e->t - nb->t;
        dv = e->v - nb->v;
        break;
    case TL_INTERP_SPLINE: return e->slope;
    default: {
        tl_curve_point hd = at_end ? e->right : e->left;
        dt = e->t - hd.t;
        dv = e->v - hd.v;
        break;
    }
    }
    return dt != 0.0 ? dv / dt : 0.0;
}

static bool is_cyclic(tl_extrap mode)
{
    return mode == TL_EXTRAP_CYCLE || mode == TL_EXTRAP_CYCLE_OFFSET || mode == TL_EXTRAP_PINGPONG;
}

/* Blender's Cycles modifier (fcm_cycles_time): maps t beyond the keys into
 * [first, last] and gives the value offset of its cycle. Seams: each repeat
 * is a closed copy of the keys, and where two meet the one nearer the keys
 * wins, so after the keys a seam shows the last key's value (the end of a
 * cycle) and before them the first key's (in ping-pong the copies alternate
 * direction, so odd seams swap). False where this side does not repeat. */
static bool cycle_time(const tl_curve *c, bool after, double t, double *mapped, double *offset)
{
    tl_extrap mode = after ? c->after : c->before;
    unsigned count = after ? c->after_cycles : c->before_cycles;
    const tl_key *first = &c->keys[0], *last = &c->keys[c->count - 1];
    double span = last->t - first->t;
    if (!is_cyclic(mode) || !(span > 0.0) || !isfinite(t))
        return false;
    double rel = t - (after ? last->t : first->t);
    if (count > 0 && fabs(rel) > count * span)
        return false;                            /* past the repeats: the end key holds */
    double ct = fmod(rel, span);                 /* exact; the sign of rel */
    double whole = nearbyint((rel - ct) / span); /* signed whole spans, consistent with ct */
    bool odd = fmod(fabs(whole), 2.0) != 0.0;
    *offset = 0.0;
    if (mode == TL_EXTRAP_CYCLE_OFFSET) {
        double k = after ? whole + (ct > 0.0) : whole - (ct < 0.0);
        *offset = k * (last->v - first->v);
    }
    if (ct == 0.0) {
        bool at_last = mode == TL_EXTRAP_PINGPONG && odd ? !after : after;
        *mapped = at_last ? last->t : first->t;
    } else if (mode == TL_EXTRAP_PINGPONG && !odd) {
        *mapped = (after ? last->t : first->t) - ct; /* played backwards */
    } else {
        *mapped = first->t + ct;
        if (*mapped < first->t)
            *mapped += span;
    }
    *mapped = fmax(first->t, fmin(last->t, *mapped));
    return true;
}

double tl_curve_eval(const tl_curve *c, double t)
{
    size_t n = c->count;
    if (n == 0)
        return 0.0;
    const tl_key *first = &c->keys[0], *last = &c->keys[n - 1];
    if (isnan(t))
        t = first->t;
    if (t >= first->t && t <= last->t)
        return eval_inside(c, t);
    if (n == 1)
        return first->v;
    bool after = t > last->t;
    const tl_key *e = after ? last : first;
    double mapped, offset;
    if (cycle_time(c, after, t, &mapped, &offset))
        return eval_inside(c, mapped) + offset;
    if ((after ? c->after : c->before) == TL_EXTRAP_LINEAR && isfinite(t)) {
        double v = e->v + end_slope(c, after) * (t - e->t);
        return isfinite(v) ? v : e->v;
    }
    return e->v;
}

/* ---- cuts --------------------------------------------------------------- */

/* Any cut key (index > 0: a cut on the first key makes no jump) in (a, b]. */
static bool window_has_cut(const tl_curve *c, double a, double b)
{
    if (!(b > a))
        return false;
    size_t lo = 0, hi = c->count; /* first key with t > a */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (c->keys[mid].t <= a)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (size_t i = lo; i < c->count && c->keys[i].t <= b; i++)
        if (i > 0 && c->keys[i].cut)
            return true;
    return false;
}

/* Any image of a cut key in (t0, t1] when the keys repeat forever with
 * period span (2 span, mirrored, for ping-pong). */
static bool periodic_has_cut(const tl_curve *c, bool pingpong, double t0, double t1)
{
    size_t n = c->count;
    double first = c->keys[0].t, span = c->keys[n - 1].t - first;
    double period = pingpong ? 2.0 * span : span;
    bool any = window_has_cut(c, first, first + span);
    if (!any || t1 - t0 >= period || !isfinite(t1 - t0))
        return any;
    /* Window start as an offset into the period; then test every image of
     * every cut key (forwards, and mirrored for ping-pong) for one period
     * on. Cyclic curves rarely hold many keys, so a scan is fine. */
    double a = fmod(t0 - first, period);
    if (a < 0.0)
        a += period;
    double b = a + (t1 - t0);
    for (size_t i = 1; i < n; i++) {
        if (!c->keys[i].cut)
            continue;
        double x = c->keys[i].t - first;
        if ((x > a && x <= b) || (x + period > a && x + period <= b))
            return true;
        /* Played backwards the jump comes just after the mirrored time, so
         * the interval is closed at its start there. */
        if (pingpong) {
            double m0 = period - x, m1 = 2.0 * period - x;
            if ((m0 >= a && m0 < b) || (m1 >= a && m1 < b))
                return true;
        }
    }
    return false;
}

bool tl_curve_has_cut_between(const tl_curve *c, double t0, double t1)
{
    size_t n = c->count;
    if (n < 2 || !(t1 > t0))
        return false;
    if (window_has_cut(c, t0, t1))
        return true;
    double first = c->keys[0].t, last = c->keys[n - 1].t, span = last - first;
    if (!(span > 0.0))
        return false;
    /* The repeats on each side, as far as their counts reach. */
    if (is_cyclic(c->before) && t0 < first) {
        double lo = c->before_cycles ? fmax(t0, first - c->before_cycles * span) : t0;
        double hi = fmin(t1, first);
        if (hi > lo && periodic_has_cut(c, c->before == TL_EXTRAP_PINGPONG, lo, hi))
            return true;
    }
    if (is_cyclic(c->after) && t1 > last) {
        double lo = fmax(t0, last);
        double hi = c->after_cycles ? fmin(t1, last + c->after_cycles * span) : t1;
        if (hi > lo && periodic_has_cut(c, c->after == TL_EXTRAP_PINGPONG, lo, hi))
            return true;
    }
    return false;
}
