#!/usr/bin/env python3
"""Expected values for tests/test_curve.c, from Blender 3.4's F-curve formulas.

Written from the formulas (BLI_easing, BKE_nurb_handle_calc for F-curves,
BKE_nurb_handle_smooth_fcurve, the Cycles modifier, F-curve extrapolation),
independently of tideline's C code, in plain Python floats (double; Blender
itself computes in float, so it agrees to ~1e-7 of the value span). Times are
in frames, as Blender keeps them. Run: python3 tests/blender_curve_ref.py
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
        print("elastic %-6s u=%g change=%g dur=%gf amp=%g period=%gf (%.17g s): %.17g"
              % (d, u, change, dur, amp, per, per / fps, v))
    for d, u, s in [("in", 0.4, 3.0), ("out", 0.3, 0.0), ("in-out", 0.2, 2.5)]:
        print("back %-6s u=%g s=%g change=2: %.17g" % (d, u, s, back(d, u, 0.0, 2.0, 1.0, s)))


if __name__ == "__main__":
    easing_cases()
