/* Blender's "Continuous Acceleration" auto-handle smoothing
 * (BKE_nurb_handle_smooth_fcurve), in double.
 *
 * Through a run of free auto keys the right handle's value offset h[i] of
 * each key is an unknown; the left one is -h[i] / l[i] with l[i] the ratio
 * of the next interval to the previous (so the first derivative is
 * continuous), and one equation per key makes the second derivative
 * continuous:
 *
 *   l[i]^2 h[i-1] + 2 (l[i] + 1) h[i] + h[i+1] / l[i+1] = dy[i] l[i]^2 + dy[i+1]
 *
 * The ends of a run are either fixed handles (a non-auto or locked key) or
 * zero acceleration (a free end of the curve); a full cycle closes the
 * tri_system instead. Auto-clamped keys bound their h so the curve neither turns
 * back at the key nor passes its neighbours; bounds are enforced by locking
 * offending unknowns and re-solving, as Blender does. Handle time offsets
 * are 1/3 of each interval (the first pass sets them so), so time is a
 * linear spline and the value alone is smoothed. */
#include "timeline/tl_curve_smooth.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static bool is_auto(tl_handle_type type)
{
    return type == TL_HANDLE_AUTO || type == TL_HANDLE_AUTO_CLAMPED;
}

static bool is_free_auto(const tl_key *k)
{
    return is_auto(k->left_type) && is_auto(k->right_type) && !k->locked;
}

static bool is_clamped(const tl_key *k)
{
    return k->left_type == TL_HANDLE_AUTO_CLAMPED || k->right_type == TL_HANDLE_AUTO_CLAMPED;
}

/* ---- tridiagonal systems: a[i] x[i-1] + b[i] x[i] + c[i] x[i+1] = d[i] --- */

/* Thomas' algorithm; a[0] and c[n-1] are ignored. x may alias d. */
static bool solve_plain(const double *a, const double *b, const double *c, const double *d,
                        double *x, int n, double *cp)
{
    if (b[0] == 0.0)
        return false;
    cp[0] = c[0] / b[0];
    x[0] = d[0] / b[0];
    for (int i = 1; i < n; i++) {
        double m = b[i] - a[i] * cp[i - 1];
        if (m == 0.0)
            return false;
        cp[i] = c[i] / m;
        x[i] = (d[i] - a[i] * x[i - 1]) / m;
    }
    for (int i = n - 2; i >= 0; i--)
        x[i] -= cp[i] * x[i + 1];
    return isfinite(x[0]);
}

/* Indices wrap (a[0] couples x[n-1], c[n-1] couples x[0]): the corners are
 * a rank-one update of a plain tri_system (Sherman-Morrison). work: 3n. */
static bool solve_cyclic(const double *a, const double *b, const double *c, const double *d,
                         double *x, int n, double *work)
{
    if (n == 1) {
        double s = a[0] + b[0] + c[0];
        x[0] = d[0] / s;
        return s != 0.0;
    }
    double a0 = a[0], cn = c[n - 1];
    if (a0 == 0.0 && cn == 0.0)
        return solve_plain(a, b, c, d, x, n, work);
    double *b2 = work, *z = work + n, *cp = work + 2 * n;
    memcpy(b2, b, sizeof *b2 * (size_t)n);
    b2[0] -= a0;
    b2[n - 1] -= cn;
    memset(z, 0, sizeof *z * (size_t)n);
    z[0] = a0;
    z[n - 1] = cn;
    if (!solve_plain(a, b2, c, z, z, n, cp) || !solve_plain(a, b2, c, d, x, n, cp))
        return false;
    double coeff = (x[0] + x[n - 1]) / (1.0 + z[0] + z[n - 1]);
    for (int i = 0; i < n; i++)
        x[i] -= coeff * z[i];
    return isfinite(coeff);
}

typedef struct tri_system {
    double *a, *b, *c, *d;     /* the equations being solved */
    double *a0, *b0, *c0, *d0; /* the original ones */
    double *h, *hmin, *hmax;
    double *work; /* 3n */
    char *locked, *unlocks;
} tri_system;

static void lock_unknown(tri_system *s, int i, double value)
{
    s->a[i] = s->c[i] = 0.0;
    s->b[i] = 1.0;
    s->d[i] = value;
}

/* Solves with h inside [hmin, hmax]: an unknown past a bound is locked to
 * it (those that should move off zero first) and the rest re-solved; a
 * locked one that wants back inside is released, at most twice. */
static bool solve_with_limits(tri_system *s, int n)
{
    memcpy(s->a0, s->a, sizeof(double) * (size_t)n);
    memcpy(s->b0, s->b, sizeof(double) * (size_t)n);
    memcpy(s->c0, s->c, sizeof(double) * (size_t)n);
    memcpy(s->d0, s->d, sizeof(double) * (size_t)n);
    memset(s->locked, 0, (size_t)n);
    memset(s->unlocks, 0, (size_t)n);
    bool overshoot, unlocked;
    int rounds = 0;
    do {
        if (!solve_cyclic(s->a, s->b, s->c, s->d, s->h, n, s->work) || ++rounds > 4 * n + 16)
            return false;
        bool all = false, locked = false;
        overshoot = unlocked = false;
        do {
            for (int i = 0; i < n; i++) {
                if (s->h[i] >= s->hmin[i] && s->h[i] <= s->hmax[i])
                    continue;
                overshoot = true;
                double target = s->h[i] > s->hmax[i] ? s->hmax[i] : s->hmin[i];
                if (target != 0.0 || all) {
                    s->locked[i] = 1;
                    lock_unknown(s, i, target);
                    locked = true;
                }
            }
            all = true;
        } while (overshoot && !locked);
        if (locked)
            continue;
        for (int i = 0; i < n; i++) {
            if (!s->locked[i] || s->unlocks[i] >= 2)
                continue;
            /* Which way the original equation wants h[i] to go. */
            double state = s->a0[i] * s->h[(i + n - 1) % n] + s->b0[i] * s->h[i] +
                           s->c0[i] * s->h[(i + 1) % n] - s->d0[i];
            double relax = -state * s->b0[i];
            if ((relax > 0.0 && s->h[i] < s->hmax[i]) || (relax < 0.0 && s->h[i] > s->hmin[i])) {
                s->a[i] = s->a0[i];
                s->b[i] = s->b0[i];
                s->c[i] = s->c0[i];
                s->d[i] = s->d0[i];
                s->locked[i] = 0;
                s->unlocks[i]++;
                unlocked = true;
            }
        }
    } while (overshoot || unlocked);
    return true;
}

/* ---- equations ---------------------------------------------------------- */

static void eq_continuous(tri_system *s, const double *dy, const double *l, int i)
{
    s->a[i] = l[i] * l[i];
    s->b[i] = 2.0 * (l[i] + 1.0);
    s->c[i] = 1.0 / l[i + 1];
    s->d[i] = dy[i] * l[i] * l[i] + dy[i + 1];
}

static void eq_noaccel_right(tri_system *s, const double *dy, const double *l, int i)
{
    s->a[i] = 0.0;
    s->b[i] = 2.0;
    s->c[i] = 1.0 / l[i + 1];
    s->d[i] = dy[i + 1];
}

static void eq_noaccel_left(tri_system *s, const double *dy, const double *l, int i)
{
    s->a[i] = l[i] * l[i];
    s->b[i] = 2.0 * l[i];
    s->c[i] = 0.0;
    s->d[i] = dy[i] * l[i] * l[i];
}

/* Auto-clamped: no turning back at the key, no passing the neighbour. */
static void clamp_range(tri_system *s, int i, double dy, bool clamped)
{
    if (!clamped)
        return;
    if (dy > 0.0) {
        s->hmax[i] = fmin(s->hmax[i], dy);
        s->hmin[i] = 0.0;
    } else if (dy < 0.0) {
        s->hmax[i] = 0.0;
        s->hmin[i] = fmax(s->hmin[i], dy);
    } else {
        s->hmax[i] = s->hmin[i] = 0.0;
    }
}

/* A fixed handle whose time offset is not 1/3 of the interval changes the
 * neighbouring equation by this much (handles that cross are scaled to
 * fit first, as in the curve itself). */
static double handle_adjust(double hsize[2], double dx)
{
    double fac = dx / (hsize[0] + dx / 3.0);
    if (fac < 1.0) {
        hsize[0] *= fac;
        hsize[1] *= fac;
    }
    return 1.0 - 3.0 * hsize[0] / dx;
}

static double frame_len(tl_curve_point key, tl_curve_point h, double fps)
{
    return hypot((h.t - key.t) * fps, h.v - key.v);
}

/* Writes a solved value offset into an auto or vector handle; an aligned
 * partner turns to stay opposite (keeping its length), an auto or vector
 * partner at an end of the curve mirrors it. */
static void output_handle(tl_key *k, bool right, double dy, bool endpoint, double fps)
{
    tl_handle_type own = right ? k->right_type : k->left_type;
    tl_handle_type other = right ? k->left_type : k->right_type;
    if (!is_auto(own) && own != TL_HANDLE_VECTOR)
        return;
    tl_curve_point key = {k->t, k->v};
    tl_curve_point *h = right ? &k->right : &k->left, *o = right ? &k->left : &k->right;
    h->v = k->v + dy;
    if (other == TL_HANDLE_ALIGNED) {
        double hlen = frame_len(key, *o, fps), len = frame_len(key, *h, fps);
        if (len > 0.0) {
            o->t = key.t + (key.t - h->t) * hlen / len;
            o->v = key.v + (key.v - h->v) * hlen / len;
        }
    } else if (endpoint && (is_auto(other) || other == TL_HANDLE_VECTOR)) {
        o->t = 2.0 * key.t - h->t;
        o->v = 2.0 * key.v - h->v;
    }
}

static bool solve_end(const tl_key *k, tl_handle_type type, bool end)
{
    return type == TL_HANDLE_VECTOR || (end && is_auto(type) && !k->locked);
}

/* One run of `count` keys from `start` (wrapping past the end when cyclic;
 * the last key is then the first one cycle on). */
static bool smooth_run(tl_key *keys, int total, int start, int count, bool cycle, double fps)
{
    if (count < 2)
        return true;
    bool full_cycle = start == 0 && count == total && cycle;
    tl_key *first = &keys[start];
    tl_key *last = &keys[start + count > total ? start + count - total : start + count - 1];
    bool solve_first = solve_end(first, first->right_type, start == 0);
    bool solve_last = solve_end(last, last->left_type, start + count == total);
    if (count == 2 && !full_cycle && solve_first == solve_last)
        return true;

    double *mem = malloc(sizeof(double) * (size_t)count * 19 + 2 * (size_t)count);
    if (!mem)
        return false;
    double *dx = mem, *dy = dx + count, *l = dy + count;
    tri_system s = {l + count,
                    l + 2 * count,
                    l + 3 * count,
                    l + 4 * count,
                    l + 5 * count,
                    l + 6 * count,
                    l + 7 * count,
                    l + 8 * count,
                    l + 9 * count,
                    l + 10 * count,
                    l + 11 * count,
                    l + 12 * count,
                    (char *)(l + 16 * count),
                    (char *)(l + 16 * count) + count};

    dx[0] = dy[0] = NAN;
    for (int i = 1, j = start + 1; i < count; i++, j++) {
        dx[i] = keys[j].t - keys[j - 1].t;
        dy[i] = keys[j].v - keys[j - 1].v;
        if (cycle && j == total - 1)
            j = 0; /* from the last key on to the first */
    }
    if (full_cycle) {
        dx[0] = dx[count - 1];
        dy[0] = dy[count - 1];
        l[0] = l[count - 1] = dx[1] / dx[0];
    } else {
        l[0] = l[count - 1] = 1.0;
    }
    for (int i = 1; i < count - 1; i++)
        l[i] = dx[i + 1] / dx[i];

    for (int i = 0; i < count; i++) {
        s.hmax[i] = DBL_MAX;
        s.hmin[i] = -DBL_MAX;
    }
    bool clamped_prev, clamped_cur = is_clamped(first);
    for (int i = 1, j = start + 1; i < count; i++, j++) {
        clamped_prev = clamped_cur;
        clamped_cur = is_clamped(&keys[j]);
        if (cycle && j == total - 1) {
            j = 0;
            clamped_cur = clamped_cur || is_clamped(&keys[0]);
        }
        clamp_range(&s, i - 1, dy[i], clamped_prev);
        clamp_range(&s, i, dy[i] * l[i], clamped_cur);
    }

    int solve_count = count;
    double first_adj = 0.0, last_adj = 0.0;
    if (full_cycle) {
        /* The first and last key are one point: one unknown fewer. */
        int i = solve_count = count - 1;
        s.hmin[0] = fmax(s.hmin[0], s.hmin[i]);
        s.hmax[0] = fmin(s.hmax[0], s.hmax[i]);
        solve_first = solve_last = true;
        eq_continuous(&s, dy, l, 0);
    } else {
        double tmp[2];
        if (!solve_first) {
            tmp[0] = first->right.t - first->t;
            tmp[1] = first->right.v - first->v;
            first_adj = handle_adjust(tmp, dx[1]);
            lock_unknown(&s, 0, tmp[1]);
        } else {
            eq_noaccel_right(&s, dy, l, 0);
        }
        if (!solve_last) {
            tmp[0] = last->t - last->left.t;
            tmp[1] = last->v - last->left.v;
            last_adj = handle_adjust(tmp, dx[count - 1]);
            lock_unknown(&s, count - 1, tmp[1]);
        } else {
            eq_noaccel_left(&s, dy, l, count - 1);
        }
    }
    for (int i = 1; i < count - 1; i++)
        eq_continuous(&s, dy, l, i);
    if (!full_cycle) {
        if (count > 2 || solve_last)
            s.b[1] += l[1] * first_adj;
        if (count > 2 || solve_first)
            s.b[count - 2] += last_adj;
    }

    if (solve_with_limits(&s, solve_count)) {
        double *h = s.h;
        if (full_cycle)
            h[count - 1] = h[0];
        for (int i = 1, j = start + 1; i < count - 1; i++, j++) {
            bool end = j == total - 1;
            output_handle(&keys[j], false, -h[i] / l[i], end, fps);
            if (end)
                j = 0;
            output_handle(&keys[j], true, h[i], end, fps);
        }
        if (solve_first)
            output_handle(first, true, h[0], start == 0, fps);
        if (solve_last)
            output_handle(last, false, -h[count - 1] / l[count - 1], start + count == total, fps);
    }
    free(mem);
    return true;
}

bool tl_curve_smooth(tl_key *keys, size_t n, bool cyclic, double fps)
{
    if (n < 2 || n > (size_t)(INT_MAX / 32))
        return n < 2;
    int total = (int)n;
    /* A cycle whose ends are locked smooths as an open curve. */
    cyclic = cyclic && is_free_auto(&keys[0]) && is_free_auto(&keys[total - 1]);
    int base = 0;
    if (cyclic) {
        for (int i = 1; i < total - 1; i++)
            if (!is_free_auto(&keys[i])) {
                base = i;
                break;
            }
        if (base == 0)
            return smooth_run(keys, total, 0, total, true, fps);
    }
    /* Runs of free auto keys between fixed ones, starting at base; when
     * cyclic a run may cross the seam. */
    bool ok = true;
    int start = base, count = 1;
    for (int i = 1, j = start + 1; i < total; i++, j++) {
        if (j == total - 1 && cyclic)
            j = 0;
        if (!is_free_auto(&keys[j])) {
            ok = smooth_run(keys, total, start, count + 1, cyclic, fps) && ok;
            start = j;
            count = 1;
        } else {
            count++;
        }
    }
    if (count > 1)
        ok = smooth_run(keys, total, start, count, cyclic, fps) && ok;
    return ok;
}
