/* tl_curve_prepare: Bezier handles by Blender's F-curve rules
 * (BKE_nurb_handle_calc for F-curves, BKE_fcurve_handles_recalc, then the
 * optional auto-smoothing pass in tl_curve_smooth.c) and the spline
 * tangents. Cuts split the keys into sections; handle and tangent
 * calculation never looks across a cut. Times are seconds; where Blender's
 * result depends on the time unit (lengths of aligned handles, the length
 * a missing one gets) it is measured in frames at the curve's fps. */
#include "timeline/tl_curve.h"
#include "timeline/tl_curve_smooth.h"

#include <math.h>

/* Blender's auto-handle factor: an F-curve auto handle reaches
 * 1 / 2.5614 = 0.39 of the time interval towards its neighbour. */
#define AUTO_HANDLE_FAC 2.5614
#define ALIGN_EPS       1e-5 /* in (frame, value) space, as Blender's */

typedef tl_curve_point vec2;

static bool is_auto(tl_handle_type type)
{
    return type == TL_HANDLE_AUTO || type == TL_HANDLE_AUTO_CLAMPED;
}

/* Free and aligned handles are positioned by the author. */
static bool handle_is_user(tl_handle_type type)
{
    return type == TL_HANDLE_FREE || type == TL_HANDLE_ALIGNED;
}

static bool both_auto(const tl_key *k)
{
    return is_auto(k->left_type) && is_auto(k->right_type);
}

static vec2 key_point(const tl_key *k)
{
    vec2 p = {k->t, k->v};
    return p;
}

/* Auto-clamped: flat at a local extremum of the key values, otherwise the
 * handle may not pass the neighbour's value. Returns 1 if flattened (Blender's
 * "locked" state), 2 if clamped ("violate"), 0 otherwise. */
static int clamp_auto(tl_key *k, vec2 *h, double neighbour_v, double ydiff_prev,
                      double ydiff_next, bool towards_next)
{
    if ((ydiff_prev <= 0.0 && ydiff_next <= 0.0) || (ydiff_prev >= 0.0 && ydiff_next >= 0.0)) {
        h->v = k->v;
        return 1;
    }
    /* ydiff_prev <= 0: the curve rises through the key, going forwards. */
    bool rising = ydiff_prev <= 0.0;
    bool past = towards_next ? (rising ? neighbour_v < h->v : neighbour_v > h->v)
                             : (rising ? neighbour_v > h->v : neighbour_v < h->v);
    if (past) {
        h->v = neighbour_v;
        return 2;
    }
    return 0;
}

/* Length of a handle in Blender's (frame, value) space; a handle on its
 * key counts as 1 (Blender's default length for a missing handle). */
static double frame_length(vec2 key, vec2 h, double fps)
{
    double len = hypot((key.t - h.t) * fps, key.v - h.v);
    return len == 0.0 ? 1.0 : len;
}

/* Auto and auto-clamped handles: along the mean of the two chord slopes.
 * Without smoothing each reaches its time gap / 2.5614 (a gap first limited
 * to 5x the other); with smoothing 1/3 of it, so time is a linear spline
 * for the smoothing pass. Returns true when clamping flattened a handle at
 * an extremum (Blender's "locked"). */
static bool calc_auto(tl_key *k, const tl_key *prev, const tl_key *next, vec2 da, vec2 db,
                      double len_a, double len_b, bool smooth)
{
    vec2 p2 = key_point(k);
    vec2 tv = {db.t / len_b + da.t / len_a, db.v / len_b + da.v / len_a};
    double len = smooth ? 6.0 : tv.t * AUTO_HANDLE_FAC;
    if (len == 0.0)
        return false;
    int left_state = 0, right_state = 0;
    if (!smooth) {
        if (len_a > 5.0 * len_b)
            len_a = 5.0 * len_b;
        if (len_b > 5.0 * len_a)
            len_b = 5.0 * len_a;
    }
    if (is_auto(k->left_type)) {
        double f = len_a / len;
        k->left.t = p2.t - tv.t * f;
        k->left.v = p2.v - tv.v * f;
        if (k->left_type == TL_HANDLE_AUTO_CLAMPED && prev && next)
            left_state = clamp_auto(k, &k->left, prev->v, prev->v - k->v, next->v - k->v, false);
    }
    if (is_auto(k->right_type)) {
        double f = len_b / len;
        k->right.t = p2.t + tv.t * f;
        k->right.v = p2.v + tv.v * f;
        if (k->right_type == TL_HANDLE_AUTO_CLAMPED && prev && next)
            right_state = clamp_auto(k, &k->right, next->v, prev->v - k->v, next->v - k->v, true);
    }
    /* A clamped handle drags the other one into line (Blender realigns the
     * right from the left when both were clamped). */
    if (left_state == 2 || right_state == 2) {
        double h1 = k->left.t - p2.t, h2 = p2.t - k->right.t;
        if (left_state == 2)
            k->right.v = p2.v + ((p2.v - k->left.v) / h1) * h2;
        else
            k->left.v = p2.v + ((p2.v - k->right.v) / h2) * h1;
    }
    return left_state == 1 || right_state == 1;
}

/* Aligned: opposite the other handle, keeping its own length measured in
 * (frame, value) space. Nothing to do if either is free or neither is
 * aligned. Blender's order for keys without selected handles: the left
 * follows the right first, so when both are aligned the right handle's
 * direction wins. */
static void calc_aligned(tl_key *k, double fps)
{
    if (k->left_type == TL_HANDLE_FREE || k->right_type == TL_HANDLE_FREE ||
        (k->left_type != TL_HANDLE_ALIGNED && k->right_type != TL_HANDLE_ALIGNED))
        return;
    vec2 p2 = key_point(k);
    double la = frame_length(p2, k->left, fps), lb = frame_length(p2, k->right, fps);
    if (k->left_type == TL_HANDLE_ALIGNED && lb > ALIGN_EPS) {
        double r = la / lb;
        k->left.t = p2.t + r * (p2.t - k->right.t);
        k->left.v = p2.v + r * (p2.v - k->right.v);
    }
    if (k->right_type == TL_HANDLE_ALIGNED && la > ALIGN_EPS) {
        double r = lb / la;
        k->right.t = p2.t + r * (p2.t - k->left.t);
        k->right.v = p2.v + r * (p2.v - k->left.v);
    }
}

/* Handles of one key from its neighbours (NULL at a section end). Returns
 * true when auto-clamping flattened a handle at an extremum. */
static bool calc_handles(tl_key *k, const tl_key *prev, const tl_key *next, double fps, bool smooth)
{
    if (k->left_type == TL_HANDLE_FREE && k->right_type == TL_HANDLE_FREE)
        return false;
    vec2 p2 = key_point(k);
    if (!prev && !next) {
        /* A lone key has no direction: computed handles sit on the key. */
        if (!handle_is_user(k->left_type))
            k->left = p2;
        if (!handle_is_user(k->right_type))
            k->right = p2;
        return false;
    }
    /* A missing neighbour is the other one mirrored through the key. */
    vec2 p1, p3;
    if (prev) {
        p1 = key_point(prev);
    } else {
        p3 = key_point(next);
        p1.t = 2.0 * p2.t - p3.t;
        p1.v = 2.0 * p2.v - p3.v;
    }
    if (next) {
        p3 = key_point(next);
    } else {
        p3.t = 2.0 * p2.t - p1.t;
        p3.v = 2.0 * p2.v - p1.v;
    }
    vec2 da = {p2.t - p1.t, p2.v - p1.v}, db = {p3.t - p2.t, p3.v - p2.v};
    /* F-curves weigh by the time spans only; a zero span counts as 1 frame. */
    double len_a = da.t != 0.0 ? da.t : 1.0 / fps;
    double len_b = db.t != 0.0 ? db.t : 1.0 / fps;
    bool locked = false;
    if (is_auto(k->left_type) || is_auto(k->right_type))
        locked = calc_auto(k, prev, next, da, db, len_a, len_b, smooth);
    if (k->left_type == TL_HANDLE_VECTOR) {
        k->left.t = p2.t - da.t / 3.0;
        k->left.v = p2.v - da.v / 3.0;
    }
    if (k->right_type == TL_HANDLE_VECTOR) {
        k->right.t = p2.t + db.t / 3.0;
        k->right.v = p2.v + db.v / 3.0;
    }
    calc_aligned(k, fps);
    return locked;
}

/* A key shifted by the curve's (time, value) extent: the neighbour one
 * cycle over, as Blender's cycle-aware handles use it. */
static tl_key shifted(const tl_key *k, const tl_key *from, const tl_key *to)
{
    tl_key s = *k;
    double dt = to->t - from->t, dv = to->v - from->v;
    s.t += dt;
    s.v += dv;
    s.left.t += dt;
    s.left.v += dv;
    s.right.t += dt;
    s.right.v += dv;
    return s;
}

/* Holds an end's auto handles flat; smoothing leaves them so. */
static void flatten(tl_key *k)
{
    k->left.v = k->right.v = k->v;
    k->locked = true;
}

static bool section_start(const tl_curve *c, size_t i)
{
    return i == 0 || c->keys[i].cut;
}

static bool section_end(const tl_curve *c, size_t i)
{
    return i + 1 == c->count || c->keys[i + 1].cut;
}

static bool repeats(tl_extrap mode)
{
    return mode == TL_EXTRAP_CYCLE || mode == TL_EXTRAP_CYCLE_OFFSET;
}

/* Blender's cycle-aware handles need the keys to repeat forever on both
 * sides (cycle or cycle-offset) and auto handles on both end keys. */
static bool smooth_seam(const tl_curve *c)
{
    size_t n = c->count;
    const tl_key *keys = c->keys;
    return repeats(c->before) && repeats(c->after) && c->before_cycles == 0 &&
           c->after_cycles == 0 && n >= 2 && keys[n - 1].t > keys[0].t && both_auto(&keys[0]) &&
           both_auto(&keys[n - 1]) && !keys[1].cut && !keys[n - 1].cut;
}

/* Blender swaps a key's handles when both are on the wrong side in time,
 * and otherwise moves a handle that is to the key's time. */
static void order_handles(tl_key *k)
{
    if (k->left.t > k->t && k->right.t < k->t) {
        tl_curve_point h = k->left;
        k->left = k->right;
        k->right = h;
    }
    if (k->left.t > k->t)
        k->left.t = k->t;
    if (k->right.t < k->t)
        k->right.t = k->t;
}

/* Automatic ease in/out: both-auto handles lie flat at a section end the
 * curve holds past (a cut, or an outer end whose side does not extrapolate
 * linearly), as Blender does for the ends of an F-curve with constant
 * extrapolation; never at the seam of a smooth cycle. */
static bool eases_end(const tl_curve *c, size_t i, bool cycle)
{
    size_t n = c->count;
    bool start = section_start(c, i), end = section_end(c, i);
    if (!both_auto(&c->keys[i]) || !(start || end))
        return false;
    if ((start && i != 0) || (end && i != n - 1))
        return true;
    if (cycle)
        return false;
    bool linear =
        (i == 0 && c->before == TL_EXTRAP_LINEAR) || (i == n - 1 && c->after == TL_EXTRAP_LINEAR);
    return !linear;
}

static void smooth_sections(tl_curve *c, bool cycle)
{
    for (size_t s = 0; s < c->count;) {
        size_t e = s;
        while (!section_end(c, e))
            e++;
        bool whole = s == 0 && e + 1 == c->count;
        tl_curve_smooth(&c->keys[s], e - s + 1, cycle && whole, c->fps);
        s = e + 1;
    }
}

static void calc_all_handles(tl_curve *c)
{
    size_t n = c->count;
    tl_key *keys = c->keys;
    bool smooth = c->smoothing == TL_SMOOTH_CONTINUOUS;
    /* Blender smooths through the seam of a cycle when both end keys are
     * auto; each end then sees the other end's neighbour, one cycle over. */
    bool cycle = smooth_seam(c);
    tl_key wrap_prev, wrap_next;
    if (cycle) {
        wrap_prev = shifted(&keys[n - 2], &keys[n - 1], &keys[0]);
        wrap_next = shifted(&keys[1], &keys[0], &keys[n - 1]);
    }
    bool first_locked = false, last_locked = false;
    for (size_t i = 0; i < n; i++) {
        tl_key *k = &keys[i];
        order_handles(k);
        bool start = section_start(c, i), end = section_end(c, i);
        const tl_key *prev = start ? NULL : &keys[i - 1];
        const tl_key *next = end ? NULL : &keys[i + 1];
        if (cycle && i == 0)
            prev = &wrap_prev;
        if (cycle && i == n - 1)
            next = &wrap_next;
        k->locked = calc_handles(k, prev, next, c->fps, smooth);
        if (i == 0)
            first_locked = k->locked;
        if (i == n - 1)
            last_locked = k->locked;
        if (eases_end(c, i, cycle))
            flatten(k);
        /* Keys at one time (a step, a cut) keep their handles (Blender). */
        if (i > 0 && keys[i - 1].t >= k->t)
            keys[i - 1].locked = k->locked = true;
    }
    /* If auto-clamping flattened an end of a cycle, flatten both ends so the
     * seam stays smooth (Blender does the same). */
    if (cycle && (first_locked || last_locked)) {
        flatten(&keys[0]);
        flatten(&keys[n - 1]);
    }
    if (smooth)
        smooth_sections(c, cycle);
}

/* Spline tangents: the slope of the parabola through the key and its two
 * neighbours (Bessel), or through the three end keys of a section, so
 * quadratic data is reproduced exactly. Neighbours across a cut or at the
 * same time do not count. */
static void calc_spline_slopes(tl_curve *c)
{
    size_t n = c->count;
    const tl_key *keys = c->keys;
    for (size_t i = 0; i < n; i++) {
        bool has_prev = !section_start(c, i) && keys[i - 1].t < keys[i].t;
        bool has_next = !section_end(c, i) && keys[i + 1].t > keys[i].t;
        double slope = 0.0;
        if (has_prev && has_next) {
            double ha = keys[i].t - keys[i - 1].t, hb = keys[i + 1].t - keys[i].t;
            double da = (keys[i].v - keys[i - 1].v) / ha, db = (keys[i + 1].v - keys[i].v) / hb;
            slope = (hb * da + ha * db) / (ha + hb);
        } else if (has_next) {
            double hb = keys[i + 1].t - keys[i].t;
            double db = (keys[i + 1].v - keys[i].v) / hb;
            slope = db;
            if (!section_end(c, i + 1) && keys[i + 2].t > keys[i + 1].t) {
                double hc = keys[i + 2].t - keys[i + 1].t;
                double dc = (keys[i + 2].v - keys[i + 1].v) / hc;
                slope = db + (db - dc) * hb / (hb + hc);
            }
        } else if (has_prev) {
            double ha = keys[i].t - keys[i - 1].t;
            double da = (keys[i].v - keys[i - 1].v) / ha;
            slope = da;
            if (!section_start(c, i - 1) && keys[i - 1].t > keys[i - 2].t) {
                double hz = keys[i - 1].t - keys[i - 2].t;
                double dz = (keys[i - 1].v - keys[i - 2].v) / hz;
                slope = da + (da - dz) * ha / (ha + hz);
            }
        }
        c->keys[i].slope = isfinite(slope) ? slope : 0.0;
    }
}

void tl_curve_prepare(tl_curve *c)
{
    if (c->count > 0) {
        calc_all_handles(c);
        calc_spline_slopes(c);
    }
    c->prepared = true;
}
