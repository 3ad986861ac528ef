#!/usr/bin/env python3
# Compares `tideline eval` of an exported timeline with what Blender
# evaluated (blender_export_scenes.py's NAME.json) at every frame: the
# camera's position, its view direction and up, its vertical field of
# view, the sun's direction and the boats' positions. Prints the worst of
# each and exits non-zero past the round trip's tolerances.
#   export_compare.py TIDELINE NAME.tl NAME.json
import json
import math
import subprocess
import sys

POSITION_M = 1e-4
ANGLE_DEG = 1e-3


def tideline(v):
    """Blender's (x, y, z) in tideline's axes (x, z, y)."""
    return (v[0], v[2], v[1])


def angle_deg(a, b):
    dot = sum(x * y for x, y in zip(a, b))
    na = math.sqrt(sum(x * x for x in a))
    nb = math.sqrt(sum(x * x for x in b))
    c = max(-1.0, min(1.0, dot / (na * nb)))
    # acos loses precision near 0: the cross product's length is exact there.
    cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    s = math.sqrt(sum(x * x for x in cross)) / (na * nb)
    return math.degrees(math.atan2(s, c))


def basis(yaw, pitch, roll):
    """tl_scene_camera_basis: forward and up from degrees."""
    y, p, r = (math.radians(v) for v in (yaw, pitch, roll))
    f = (math.cos(p) * math.sin(y), math.sin(p), math.cos(p) * math.cos(y))
    r0 = (math.cos(y), 0.0, -math.sin(y))
    u0 = (f[1] * r0[2] - f[2] * r0[1], f[2] * r0[0] - f[0] * r0[2], f[0] * r0[1] - f[1] * r0[0])
    up = tuple(math.cos(r) * u0[i] - math.sin(r) * r0[i] for i in range(3))
    return f, up


def main():
    binary, timeline, reference = sys.argv[1:4]
    with open(reference) as f:
        frames = json.load(f)
    out = subprocess.run([binary, "eval", timeline, "--frames", "0-%d" % (len(frames) - 1), "--json"],
                         check=True, capture_output=True, text=True).stdout
    samples = json.loads(out)["samples"]
    if len(samples) != len(frames):
        print("FAILED: %d samples for %d frames" % (len(samples), len(frames)))
        return 1
    worst = {"position": 0.0, "direction": 0.0, "up": 0.0, "fov": 0.0, "sun": 0.0, "boat": 0.0}
    for n, (s, b) in enumerate(zip(samples, frames)):
        ch = s["channels"]
        worst["position"] = max(worst["position"], max(
            abs(x - y) for x, y in zip(ch["camera.position"], tideline(b["position"]))))
        forward, up = basis(ch["camera.yaw"], ch["camera.pitch"], ch["camera.roll"])
        worst["direction"] = max(worst["direction"], angle_deg(forward, tideline(b["forward"])))
        worst["up"] = max(worst["up"], angle_deg(up, tideline(b["up"])))
        worst["fov"] = max(worst["fov"], abs(ch["camera.fov"] - math.degrees(b["vfov"])))
        if "sun" in b:
            e, a = math.radians(ch["sun.elevation"]), math.radians(ch["sun.azimuth"])
            sun = (math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a))
            worst["sun"] = max(worst["sun"], angle_deg(sun, tideline(b["sun"])))
        objects = {o["name"]: o["pose"]["position"] for o in s["objects"] if o.get("pose")}
        for name, p in b["boats"].items():
            got = objects.get(name)
            if got is None:
                print("FAILED: frame %d: no boat '%s' in tideline's eval" % (n, name))
                return 1
            worst["boat"] = max(worst["boat"], abs(got[0] - p[0]), abs(got[2] - p[1]))
    print("WORST position %.3g m, direction %.3g deg, up %.3g deg, fov %.3g deg, sun %.3g deg, "
          "boat %.3g m over %d frames" % (worst["position"], worst["direction"], worst["up"],
                                          worst["fov"], worst["sun"], worst["boat"], len(frames)))
    ok = (worst["position"] <= POSITION_M and worst["boat"] <= POSITION_M and
          max(worst["direction"], worst["up"], worst["fov"], worst["sun"]) <= ANGLE_DEG)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
