#!/usr/bin/env python3
"""Expected values for tests/test_curve.c, tests/test_curve_ends.c and
tests/test_timeline.c, from Blender 3.4's F-curve formulas.

Written from the formulas (BLI_easing, BKE_nurb_handle_calc for F-curves,
BKE_nurb_handle_smooth_fcurve, the Cycles modifier, F-curve extrapolation),
independently of tideline's C code, in plain Python floats (double; Blender
itself computes in float, so it agrees to ~1e-7 of the value span). Times are
in frames, as Blender keeps them.

It writes the fixture tests/fixtures/curve_reference.txt, which test_curve,
test_curve_ends and test_timeline read (ctest passes its path): one
"NAME VALUE" line per expected value, NAME built from the case's inputs, "#"
lines comments. Plain Python 3, no Blender needed; ctest's
fixture_curve_reference checks that the file is this script's output. After a
change here, regenerate it from the repository root and commit both:

    python3 tests/blender_curve_ref.py > tests/fixtures/curve_reference.txt
"""
import math

# ---- easing (BLI_easing) ---------------------------------------------------


def elastic_blend(time, change, duration, amplitude, s, f):
    if change:
        t = abs(s)
        f = f * amplitude / abs(change) if amplitude else 0.0
        if abs(time * duration) < t:
            l = abs(time * duration) / t
            f = f * l + (1.0 - l)
    return f


def elastic(direction, time, begin, change, duration, amplitude, period):
    """BLI_easing_elastic_ease_in/out/in_out."""
    if time == 0.0:
        return begin
    f = 1.0
    if direction == "in":
        time /= duration
        if time == 1.0:
            return begin + change
        time -= 1.0
        period = period or duration * 0.3
    elif direction == "out":
        time /= duration
        if time == 1.0:
            return begin + change
        time = -time
        period = period or duration * 0.3
    else:
        time /= duration / 2
        if time == 2.0:
            return begin + change
        time -= 1.0
        period = period or duration * 0.45
    if not amplitude or amplitude < abs(change):
        s = period / 4
        f = elastic_blend(time, change, duration, amplitude, s, f)
        amplitude = change
    else:
        s = period / (2 * math.pi) * math.asin(change / amplitude)

    def wave(x):
        return amplitude * 2 ** (10 * x) * math.sin((x * duration - s) * 2 * math.pi / period)

    if direction == "in":
        return -f * wave(time) + begin
    if direction == "out":
        return f * wave(time) + change + begin
    if time < 0:
        return -0.5 * f * wave(time) + begin
    return 0.5 * f * wave(-time) + change + begin


def back(direction, time, begin, change, duration, overshoot):
    """BLI_easing_back_ease_in/out/in_out (no substitute for overshoot 0)."""
    if direction == "in":
        time /= duration
        return change * time * time * ((overshoot + 1) * time - overshoot) + begin
    if direction == "out":
        time = time / duration - 1
        return change * (time * time * ((overshoot + 1) * time + overshoot) + 1) + begin
    overshoot *= 1.525
    time /= duration / 2
    if time < 1:
        return change / 2 * (time * time * ((overshoot + 1) * time - overshoot)) + begin
    time -= 2
    return change / 2 * (time * time * ((overshoot + 1) * time + overshoot) + 2) + begin


def section(title):
    print("\n# " + title)


def value(name, v):
    """One fixture line; %.17g gives back the same double in C's strtod."""
    print("%s %.17g" % (name, v))


def easing_cases():
    section("elastic and back (value - begin), frames at 24 fps")
    fps = 24.0
    cases = [
        # direction, u, change, duration (frames), amplitude, period (frames)
        ("out", 0.3, 10.0, 24.0, 0.8, 4.1),  # an inserted key's defaults
        ("out", 0.02, 10.0, 24.0, 0.8, 4.1),  # inside the blend zone
        ("in", 0.9, 10.0, 24.0, 0.8, 4.1),
        ("in-out", 0.45, 10.0, 24.0, 0.8, 4.1),
        ("in-out", 0.7, 10.0, 24.0, 0.8, 4.1),
        ("in", 0.7, 1.0, 24.0, 2.0, 6.0),  # amplitude above the change: asin phase
        ("out", 0.4, -1.0, 24.0, 2.0, 6.0),
        ("in", 0.95, 3.0, 24.0, 0.0, 0.0),  # amplitude 0: only the blend at the end
    ]
    for d, u, change, dur, amp, per in cases:
        v = elastic(d, u * dur, 0.0, change, dur, amp, per)
        value("elastic.%s.u=%g.change=%g.dur=%gf.amp=%g.period=%gf" % (d, u, change, dur, amp, per), v)
    for d, u, s in [("in", 0.4, 3.0), ("out", 0.3, 0.0), ("in-out", 0.2, 2.5)]:
        value("back.%s.u=%g.s=%g.change=2" % (d, u, s), back(d, u, 0.0, 2.0, 1.0, s))


# ---- keys and handles (BKE_fcurve_handles_recalc, calchandleNurb_intern) ---
# A key is a dict: x (frames), y, h1/h2 handle types ("auto-clamped", "auto",
# "vector", "aligned", "free"), l/r handle points [x, y], and "locked".

AUTO = ("auto", "auto-clamped")


def key(x, y, h1="auto-clamped", h2=None, l=None, r=None):
    return {"x": x, "y": y, "h1": h1, "h2": h2 or h1, "l": list(l or (x, y)),
            "r": list(r or (x, y)), "locked": False}


def calc_handle(k, prev, nxt, smoothing):
    """calchandleNurb_intern with is_fcurve, no handle selected."""
    k["locked"] = False
    p2 = (k["x"], k["y"])
    if prev is None and nxt is None:
        return
    if prev is None:
        p3 = (nxt["x"], nxt["y"])
        p1 = (2 * p2[0] - p3[0], 2 * p2[1] - p3[1])
    else:
        p1 = (prev["x"], prev["y"])
    if nxt is None:
        p3 = (2 * p2[0] - p1[0], 2 * p2[1] - p1[1])
    else:
        p3 = (nxt["x"], nxt["y"])
    da = (p2[0] - p1[0], p2[1] - p1[1])
    db = (p3[0] - p2[0], p3[1] - p2[1])
    len_a = da[0] or 1.0
    len_b = db[0] or 1.0
    if k["h1"] in AUTO or k["h2"] in AUTO:
        tv = (db[0] / len_b + da[0] / len_a, db[1] / len_b + da[1] / len_a)
        ln = 6.0 if smoothing else tv[0] * 2.5614
        if ln != 0:
            lviol = rviol = False
            if not smoothing:
                len_a = min(len_a, 5 * len_b)
                len_b = min(len_b, 5 * len_a)
            if k["h1"] in AUTO:
                f = len_a / ln
                k["l"] = [p2[0] - tv[0] * f, p2[1] - tv[1] * f]
                if k["h1"] == "auto-clamped" and prev and nxt:
                    y1, y2 = prev["y"] - k["y"], nxt["y"] - k["y"]
                    if (y1 <= 0 and y2 <= 0) or (y1 >= 0 and y2 >= 0):
                        k["l"][1] = k["y"]
                        k["locked"] = True
                    elif (y1 <= 0 and prev["y"] > k["l"][1]) or (y1 > 0 and prev["y"] < k["l"][1]):
                        k["l"][1] = prev["y"]
                        lviol = True
            if k["h2"] in AUTO:
                f = len_b / ln
                k["r"] = [p2[0] + tv[0] * f, p2[1] + tv[1] * f]
                if k["h2"] == "auto-clamped" and prev and nxt:
                    y1, y2 = prev["y"] - k["y"], nxt["y"] - k["y"]
                    if (y1 <= 0 and y2 <= 0) or (y1 >= 0 and y2 >= 0):
                        k["r"][1] = k["y"]
                        k["locked"] = True
                    elif (y1 <= 0 and nxt["y"] < k["r"][1]) or (y1 > 0 and nxt["y"] > k["r"][1]):
                        k["r"][1] = nxt["y"]
                        rviol = True
            if lviol or rviol:
                h1x = k["l"][0] - p2[0]
                h2x = p2[0] - k["r"][0]
                if lviol:
                    k["r"][1] = p2[1] + (p2[1] - k["l"][1]) / h1x * h2x
                else:
                    k["l"][1] = p2[1] + (p2[1] - k["r"][1]) / h2x * h1x
    if k["h1"] == "vector":
        k["l"] = [p2[0] - da[0] / 3, p2[1] - da[1] / 3]
    if k["h2"] == "vector":
        k["r"] = [p2[0] + db[0] / 3, p2[1] + db[1] / 3]
    if "free" in (k["h1"], k["h2"]) or "aligned" not in (k["h1"], k["h2"]):
        return
    la = math.hypot(p2[0] - k["l"][0], p2[1] - k["l"][1]) or 1.0
    lb = math.hypot(p2[0] - k["r"][0], p2[1] - k["r"][1]) or 1.0
    if k["h1"] == "aligned" and lb > 1e-5:
        k["l"] = [p2[0] + la / lb * (p2[0] - k["r"][0]), p2[1] + la / lb * (p2[1] - k["r"][1])]
    if k["h2"] == "aligned" and la > 1e-5:
        k["r"] = [p2[0] + lb / la * (p2[0] - k["l"][0]), p2[1] + lb / la * (p2[1] - k["l"][1])]


def shifted(k, frm, to):
    d = (to["x"] - frm["x"], to["y"] - frm["y"])
    s = dict(k)
    s["x"], s["y"] = k["x"] + d[0], k["y"] + d[1]
    s["l"] = [k["l"][0] + d[0], k["l"][1] + d[1]]
    s["r"] = [k["r"][0] + d[0], k["r"][1] + d[1]]
    return s


def is_autoh(k):
    return k["h1"] in AUTO and k["h2"] in AUTO


def recalc(keys, extend="constant", cyclic=False, smoothing=False):
    """sort_time_fcurve's handle swap, then BKE_fcurve_handles_recalc_ex.
    cyclic: a Cycles modifier repeating forever on both sides."""
    for k in keys:
        if k["l"][0] > k["x"] and k["r"][0] < k["x"]:
            k["l"], k["r"] = k["r"], k["l"]
    n = len(keys)
    first, last = keys[0], keys[-1]
    cycle = cyclic and is_autoh(first) and is_autoh(last)
    prev = shifted(keys[n - 2], last, first) if cycle else None
    for i, k in enumerate(keys):
        k["l"][0] = min(k["l"][0], k["x"])
        k["r"][0] = max(k["r"][0], k["x"])
        nxt = keys[i + 1] if i + 1 < n else (shifted(keys[1], first, last) if cycle else None)
        calc_handle(k, prev, nxt, smoothing)
        if is_autoh(k) and not cycle and i in (0, n - 1) and extend == "constant":
            k["l"][1] = k["r"][1] = k["y"]
            k["locked"] = True
        if prev is not None and prev["x"] >= k["x"]:
            prev["locked"] = k["locked"] = True
        prev = k
    if cycle and (first["locked"] or last["locked"]):
        for k in (first, last):
            k["l"][1] = k["r"][1] = k["y"]
            k["locked"] = True
    if smoothing:
        smooth_fcurve(keys, n, cycle)


# ---- Continuous Acceleration (BKE_nurb_handle_smooth_fcurve) ---------------


def tridiagonal(a, b, c, d):
    """Dense Gaussian elimination of the cyclic tridiagonal system (an
    independent method: no Thomas, no Sherman-Morrison)."""
    n = len(b)
    m = [[0.0] * n + [d[i]] for i in range(n)]
    for i in range(n):
        m[i][i] += b[i]
        m[i][(i - 1) % n] += a[i]
        m[i][(i + 1) % n] += c[i]
    for col in range(n):
        piv = max(range(col, n), key=lambda r: abs(m[r][col]))
        m[col], m[piv] = m[piv], m[col]
        for r in range(n):
            if r != col and m[r][col]:
                f = m[r][col] / m[col][col]
                m[r] = [x - f * y for x, y in zip(m[r], m[col])]
    return [m[i][n] / m[i][i] for i in range(n)]


def solve_limits(a, b, c, d, hmin, hmax):
    n = len(b)
    a0, b0, c0, d0 = list(a), list(b), list(c), list(d)
    locked = [False] * n
    unlocks = [0] * n
    while True:
        h = tridiagonal(a, b, c, d)
        all_, lock, overshoot, unlocked = False, False, False, False
        while True:
            for i in range(n):
                if hmin[i] <= h[i] <= hmax[i]:
                    continue
                overshoot = True
                target = hmax[i] if h[i] > hmax[i] else hmin[i]
                if target != 0 or all_:
                    locked[i] = True
                    a[i], b[i], c[i], d[i] = 0.0, 1.0, 0.0, target
                    lock = True
            all_ = True
            if not (overshoot and not lock):
                break
        if not lock:
            for i in range(n):
                if not locked[i] or unlocks[i] >= 2:
                    continue
                state = a0[i] * h[(i - 1) % n] + b0[i] * h[i] + c0[i] * h[(i + 1) % n] - d0[i]
                relax = -state * b0[i]
                if (relax > 0 and h[i] < hmax[i]) or (relax < 0 and h[i] > hmin[i]):
                    a[i], b[i], c[i], d[i] = a0[i], b0[i], c0[i], d0[i]
                    locked[i] = False
                    unlocks[i] += 1
                    unlocked = True
        if not (overshoot or unlocked):
            return h


def free_auto(k):
    return is_autoh(k) and not k["locked"]


def output_handle(k, right, dy, endpoint):
    own, other = (k["h2"], k["h1"]) if right else (k["h1"], k["h2"])
    if own not in AUTO + ("vector",):
        return
    hk, ok = ("r", "l") if right else ("l", "r")
    k[hk] = [k[hk][0], k["y"] + dy]
    if other == "aligned":
        hlen = math.hypot(k["x"] - k[ok][0], k["y"] - k[ok][1])
        h2len = math.hypot(k["x"] - k[hk][0], k["y"] - k[hk][1])
        k[ok] = [k["x"] + (k["x"] - k[hk][0]) * hlen / h2len,
                 k["y"] + (k["y"] - k[hk][1]) * hlen / h2len]
    elif endpoint and other in AUTO + ("vector",):
        k[ok] = [2 * k["x"] - k[hk][0], 2 * k["y"] - k[hk][1]]


def smooth_run(bz, total, start, count, cycle):
    if count < 2:
        return
    full = start == 0 and count == total and cycle
    first = bz[start]
    last = bz[start + count - total if start + count > total else start + count - 1]

    def solve_end(k, ht, end):
        return ht == "vector" or (end and ht in AUTO and not k["locked"])

    sf = solve_end(first, first["h2"], start == 0)
    sl = solve_end(last, last["h1"], start + count == total)
    if count == 2 and not full and sf == sl:
        return
    dx, dy = [math.nan] * count, [math.nan] * count
    j = start + 1
    for i in range(1, count):
        dx[i] = bz[j]["x"] - bz[j - 1]["x"]
        dy[i] = bz[j]["y"] - bz[j - 1]["y"]
        if cycle and j == total - 1:
            j = 0
        j += 1
    l = [1.0] * count
    if full:
        dx[0], dy[0] = dx[count - 1], dy[count - 1]
        l[0] = l[count - 1] = dx[1] / dx[0]
    for i in range(1, count - 1):
        l[i] = dx[i + 1] / dx[i]
    hmax, hmin = [math.inf] * count, [-math.inf] * count

    def clamp(i, d, on):
        if not on:
            return
        if d > 0:
            hmax[i], hmin[i] = min(hmax[i], d), 0.0
        elif d < 0:
            hmax[i], hmin[i] = 0.0, max(hmin[i], d)
        else:
            hmax[i] = hmin[i] = 0.0

    def clamped(k):
        return "auto-clamped" in (k["h1"], k["h2"])

    cur = clamped(first)
    j = start + 1
    for i in range(1, count):
        prev_c, cur = cur, clamped(bz[j])
        if cycle and j == total - 1:
            j = 0
            cur = cur or clamped(bz[0])
        clamp(i - 1, dy[i], prev_c)
        clamp(i, dy[i] * l[i], cur)
        j += 1
    a, b, c, d = [0.0] * count, [0.0] * count, [0.0] * count, [0.0] * count

    def cont(i):
        a[i], b[i], c[i], d[i] = l[i] ** 2, 2 * (l[i] + 1), 1 / l[i + 1], dy[i] * l[i] ** 2 + dy[i + 1]

    def adj(hs, dxv):
        fac = dxv / (hs[0] + dxv / 3)
        if fac < 1:
            hs[0] *= fac
            hs[1] *= fac
        return 1 - 3 * hs[0] / dxv

    n_solve = count
    fadj = ladj = 0.0
    if full:
        n_solve = count - 1
        hmin[0] = max(hmin[0], hmin[n_solve])
        hmax[0] = min(hmax[0], hmax[n_solve])
        sf = sl = True
        cont(0)
    else:
        if not sf:
            hs = [first["r"][0] - first["x"], first["r"][1] - first["y"]]
            fadj = adj(hs, dx[1])
            a[0], b[0], c[0], d[0] = 0.0, 1.0, 0.0, hs[1]
        else:
            a[0], b[0], c[0], d[0] = 0.0, 2.0, 1 / l[1], dy[1]
        e = count - 1
        if not sl:
            hs = [last["x"] - last["l"][0], last["y"] - last["l"][1]]
            ladj = adj(hs, dx[e])
            a[e], b[e], c[e], d[e] = 0.0, 1.0, 0.0, hs[1]
        else:
            a[e], b[e], c[e], d[e] = l[e] ** 2, 2 * l[e], 0.0, dy[e] * l[e] ** 2
    for i in range(1, count - 1):
        cont(i)
    if not full:
        if count > 2 or sl:
            b[1] += l[1] * fadj
        if count > 2 or sf:
            b[count - 2] += ladj
    if full:
        # the unknowns wrap: the last equation's c couples h[0]
        h = solve_limits(a[:n_solve], b[:n_solve], c[:n_solve], d[:n_solve],
                         hmin[:n_solve], hmax[:n_solve])
        h.append(h[0])
    else:
        h = solve_limits(a, b, c, d, hmin, hmax)
    j = start + 1
    for i in range(1, count - 1):
        end = j == total - 1
        output_handle(bz[j], False, -h[i] / l[i], end)
        if end:
            j = 0
        output_handle(bz[j], True, h[i], end)
        j += 1
    if sf:
        output_handle(first, True, h[0], start == 0)
    if sl:
        output_handle(last, False, -h[count - 1] / l[count - 1], start + count == total)


def smooth_fcurve(bz, total, cyclic):
    cyclic = cyclic and free_auto(bz[0]) and free_auto(bz[total - 1])
    base = 0
    if cyclic:
        for i in range(1, total - 1):
            if not free_auto(bz[i]):
                base = i
                break
        if base == 0:
            smooth_run(bz, total, 0, total, cyclic)
            return
    start, count = base, 1
    j = start + 1
    for i in range(1, total):
        if j == total - 1 and cyclic:
            j = 0
        if not free_auto(bz[j]):
            smooth_run(bz, total, start, count + 1, cyclic)
            start, count = j, 1
        else:
            count += 1
        j += 1
    if count > 1:
        smooth_run(bz, total, start, count, cyclic)


# ---- evaluation ----------------------------------------------------------


def bezier_value(k0, k1, x):
    """One segment: handles corrected to the span (BKE_fcurve_correct_bezpart),
    then x(s) = x inverted by bisection (x is monotonic after correction)."""
    p0, p3 = (k0["x"], k0["y"]), (k1["x"], k1["y"])
    p1, p2 = list(k0["r"]), list(k1["l"])
    span = p3[0] - p0[0]
    for key_, h in ((p0, p1), (p3, p2)):
        ln = abs(h[0] - key_[0])
        if ln > span:
            f = span / ln
            h[0] = key_[0] + f * (h[0] - key_[0])
            h[1] = key_[1] + f * (h[1] - key_[1])

    def pt(s, i):
        r = 1 - s
        return r ** 3 * p0[i] + 3 * r * r * s * p1[i] + 3 * r * s * s * p2[i] + s ** 3 * p3[i]

    lo, hi = 0.0, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if pt(mid, 0) < x:
            lo = mid
        else:
            hi = mid
    return pt(0.5 * (lo + hi), 1)


def handle_cases():
    fps = 24.0
    section("aligned handles at 24 fps (frame, value) space")
    # The old test's key: keys (0,0) (1,1) (2,0) s; key 1 aligned both sides,
    # left (0,1), right (3,3) s. Blender in frames:
    ks = [key(0, 0), key(24, 1, "aligned", l=(0, 1), r=(72, 3)), key(48, 0)]
    recalc(ks)
    value("aligned_both.left_t", ks[1]["l"][0] / fps)
    value("aligned_both.left_v", ks[1]["l"][1])
    value("aligned_both.right_t", ks[1]["r"][0] / fps)
    value("aligned_both.right_v", ks[1]["r"][1])
    ks = [key(0, 0), key(24, 1, "aligned", "auto-clamped", l=(12, 1.5)), key(48, 0)]
    recalc(ks)
    value("aligned_left_auto_clamped_right.left_t", ks[1]["l"][0] / fps)
    value("aligned_left_auto_clamped_right.left_v", ks[1]["l"][1])
    # A missing aligned handle (on its key) gets length 1 in frame space.
    ks = [key(0, 0), key(24, 1, "aligned", l=(24, 1), r=(36, 2)), key(48, 0)]
    recalc(ks)
    value("aligned_left_on_its_key.left_t", ks[1]["l"][0] / fps)
    value("aligned_left_on_its_key.left_v", ks[1]["l"][1])
    # value of a segment with an aligned key at 24 fps
    ks = [key(0, 0, "vector"), key(24, 1, "aligned", l=(12, 0.2), r=(30, 1.5)), key(48, 0, "vector")]
    recalc(ks)
    value("aligned_segment.at=1.5", bezier_value(ks[1], ks[2], 36))
    value("aligned_segment.left_t", ks[1]["l"][0] / fps)
    value("aligned_segment.left_v", ks[1]["l"][1])

    section("handles on the wrong side: swapped (both) / clamped (one)")
    ks = [key(0, 0, "vector"), key(24, 1, "free", l=(36, 3), r=(12, -1)), key(48, 0, "vector")]
    recalc(ks)
    value("swapped.left_t", ks[1]["l"][0] / fps)
    value("swapped.left_v", ks[1]["l"][1])
    value("swapped.right_t", ks[1]["r"][0] / fps)
    value("swapped.right_v", ks[1]["r"][1])
    for t in (0.5, 1.25, 1.5):
        seg = (ks[0], ks[1]) if t < 1 else (ks[1], ks[2])
        value("swapped.at=%g" % t, bezier_value(seg[0], seg[1], t * fps))



def cycles_time(first, last, t, mode_before, mode_after, n_before=0, n_after=0):
    """The Cycles modifier's fcm_cycles_time: (mapped time, value offset),
    or None where it does not apply. first/last: (x, y) of the end keys."""
    if t < first[0]:
        side, mode, cycles, ofs = -1, mode_before, n_before, first[0]
    elif t > last[0]:
        side, mode, cycles, ofs = 1, mode_after, n_after, last[0]
    else:
        return None
    if mode == "none":
        return None
    dx, dy = last[0] - first[0], last[1] - first[1]
    cycle = side * (t - ofs) / dx
    cyct = math.fmod(t - ofs, dx)
    if cycles and cycle > cycles:
        return None
    yofs = 0.0
    if mode == "offset":
        yofs = (math.floor if side < 0 else math.ceil)((t - ofs) / dx) * dy
    if cyct == 0:
        t = last[0] if side == 1 else first[0]
        if mode == "mirror" and int(cycle) % 2:
            t = first[0] if side == 1 else last[0]
    elif mode == "mirror" and int(cycle + 1) % 2:
        t = (first[0] if side < 0 else last[0]) - cyct
    else:
        t = first[0] + cyct
    if t < first[0]:
        t += dx
    return t, yofs


def linear_value(pts, t):
    """Linear keys, constant extrapolation (the F-curve under the modifier)."""
    if t <= pts[0][0]:
        return pts[0][1]
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        if t <= x1:
            return y0 + (y1 - y0) * (t - x0) / (x1 - x0)
    return pts[-1][1]


def cycle_cases():
    section("cycles (linear keys, seconds)")
    pts = [(0.0, 0.0), (1.0, 1.0)]
    for t in (1.0, 2.0, 3.0, 1.5, -1.0, -0.5, -2.0):
        m = cycles_time(pts[0], pts[-1], t, "cycle", "cycle")
        v = linear_value(pts, t) if m is None else linear_value(pts, m[0]) + m[1]
        value("cycle_0_1.at=%g" % t, v)
    pts = [(0.0, 0.0), (1.0, 1.0), (2.0, 0.5)]
    for t in (-0.25, -1.5, -2.0, -3.25, -4.5, -7.0, 2.5, 4.0, 4.5, 3.0, 6.5):
        m = cycles_time(pts[0], pts[-1], t, "mirror", "offset", 3, 2)
        v = linear_value(pts, t) if m is None else linear_value(pts, m[0]) + m[1]
        value("pingpong3_offset2.at=%g" % t, v)


def handles(prefix, ks, fps=24.0):
    """Each key's handles, in seconds: PREFIX.keyI.left_t/left_v/right_t/right_v."""
    for i, k in enumerate(ks):
        value("%s.key%d.left_t" % (prefix, i), k["l"][0] / fps)
        value("%s.key%d.left_v" % (prefix, i), k["l"][1])
        value("%s.key%d.right_t" % (prefix, i), k["r"][0] / fps)
        value("%s.key%d.right_v" % (prefix, i), k["r"][1])


def smooth_cases():
    fps = 24.0
    section("Continuous Acceleration, keys in seconds at 24 fps")
    data = [(0, 0), (1, 2), (1.5, 2.5), (3, 1), (4, 1.5), (6, -1)]

    def make(types):
        return [key(x * fps, y, types) for x, y in data]

    for types in ("auto", "auto-clamped"):
        ks = make(types)
        recalc(ks, smoothing=True)
        handles("smooth.%s" % types, ks)
        for t in (0.5, 1.2, 2.2, 3.5, 5.0):
            i = max(j for j in range(len(ks) - 1) if ks[j]["x"] <= t * fps)
            value("smooth.%s.at=%g" % (types, t), bezier_value(ks[i], ks[i + 1], t * fps))
    section("Continuous Acceleration, a full cycle (auto), keys in seconds at 24 fps")
    cyc = [(0, 0), (1, 1), (2.5, -0.5), (4, 0)]
    ks = [key(x * fps, y, "auto") for x, y in cyc]
    recalc(ks, cyclic=True, smoothing=True)
    handles("smooth.cycle", ks)
    for t in (0.3, 1.7, 3.6):
        i = max(j for j in range(len(ks) - 1) if ks[j]["x"] <= t * fps)
        value("smooth.cycle.at=%g" % t, bezier_value(ks[i], ks[i + 1], t * fps))


def language_cases():
    section("tests/test_timeline.c (fps 30)")
    for u in (0.3, 0.5):
        # ease-out-elastic amplitude 0.5 period 6f, 0 -> 10 over 30 frames
        value("timeline.exposure_elastic.u=%g" % u, elastic("out", u * 30, 0.0, 10.0, 30.0, 0.5, 6.0))
    # ease-in-elastic, an inserted key's defaults, 0 -> 10 over 30 frames
    value("timeline.speed_elastic.u=0.8", elastic("in", 0.8 * 30, 0.0, 10.0, 30.0, 0.8, 4.1))
    m = cycles_time((0, 0), (2, 0.5), -3.5, "mirror", "offset", 2, 1)
    # before: ping-pong 2, keys (0 s, 0), (1 s, 1), (2 s, 0.5)
    value("timeline.pingpong2.at=-3.5", linear_value([(0, 0), (1, 1), (2, 0.5)], m[0]) + m[1])


if __name__ == "__main__":
    print("# Expected values for tests/test_curve.c, test_curve_ends.c and test_timeline.c, written by")
    print("# tests/blender_curve_ref.py (Blender 3.4's F-curve formulas); do not edit. Regenerate:")
    print("#   python3 tests/blender_curve_ref.py > tests/fixtures/curve_reference.txt")
    print("# NAME VALUE a line; times in seconds unless NAME says f (frames).")
    language_cases()
    easing_cases()
    handle_cases()
    cycle_cases()
    smooth_cases()
