# Blender 3.4 imports the glTF `tideline export-camera` writes, and its
# camera and boat stand where `tideline eval` says they are at every frame
# the eval JSON holds (`tideline eval --frames A-B --json`). Run headless:
#   blender -b --factory-startup --python blender_camera.py -- CAMERA.gltf EVAL.json
# Prints the worst over the frames: "CAMERA <position error m> <view
# direction error rad> <lens error rad> <the camera's own angle_y at the
# first frame>", "UP <error rad>" and "BOAT <position error m> <heading
# error rad> <deck error rad>", each with "at FRAME" of its worst; exits
# non-zero on any failure.
import json
import math
import sys

import bpy


def angle(a, b):
    """The angle between two vectors, exact for small angles too (acos of
    a dot product of float vectors is noise below about 3e-4 rad)."""
    a, b = tuple(a), tuple(b)
    cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    return math.atan2(math.sqrt(sum(c * c for c in cross)), sum(x * y for x, y in zip(a, b)))


def blender_axes(v):
    # tideline x east, y up, z north -> glTF (x, y, -z) -> Blender z up:
    # (x, z, y).
    return (v[0], v[2], v[1])


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    path, eval_path = args[0], args[1]
    samples = json.load(open(eval_path))["samples"]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = 24
    bpy.ops.import_scene.gltf(filepath=path)
    names = sorted(o.name for o in bpy.data.objects)
    print("OBJECTS", ",".join(names))
    cam = next(o for o in bpy.data.objects if o.type == "CAMERA")
    boat = bpy.data.objects.get("boat")
    # Blender's importer puts glTF's time t at frame t * fps (+1 when its
    # scene starts at frame 1: it shifts to the scene's first frame).
    start = min(int(fc.range()[0]) for a in bpy.data.actions for fc in a.fcurves)
    worst = {}

    def note(what, value, frame):
        if what not in worst or value > worst[what][0]:
            worst[what] = (value, frame)

    for sample in samples:
        frame = sample["frame"]
        scene.frame_set(start + frame)
        measure(sample, frame, cam, boat, note)
    angle_y = cam.data.angle_y
    scene.frame_set(start + samples[0]["frame"])
    for what in ("CAMERA", "UP", "BOAT"):
        keys = [k for k in worst if k.startswith(what + " ")]
        if keys:
            keys.sort()
            print(what, " ".join("%.6g" % worst[k][0] for k in keys),
                  "at", " ".join(str(worst[k][1]) for k in keys))
    print("FRAMES", len(samples), "ANGLE_Y %.6f" % angle_y)


def measure(sample, frame, cam, boat, note):
    ch = sample["channels"]
    p = ch["camera.position"]
    yaw, pitch = math.radians(ch["camera.yaw"]), math.radians(ch["camera.pitch"])
    forward = (math.cos(pitch) * math.sin(yaw), math.sin(pitch), math.cos(pitch) * math.cos(yaw))
    want_p, want_f = blender_axes(p), blender_axes(forward)
    m = cam.matrix_world
    got_p = m.translation
    got_f = -m.col[2].xyz
    roll = math.radians(ch["camera.roll"])
    # The camera's up: tideline's basis (right from the yaw alone, rolled).
    right0 = (math.cos(yaw), 0.0, -math.sin(yaw))
    up0 = (forward[1] * right0[2] - forward[2] * right0[1],
           forward[2] * right0[0] - forward[0] * right0[2],
           forward[0] * right0[1] - forward[1] * right0[0])
    up = tuple(math.cos(roll) * u - math.sin(roll) * r for u, r in zip(up0, right0))
    want_up = blender_axes(up)
    got_up = m.col[1].xyz.normalized()
    dup = angle(got_up, want_up)
    note("UP 0", dup, frame)
    dp = math.dist(tuple(got_p), want_p)
    df = angle(got_f, want_f)
    # glTF animates no lens: the camera has frame 0's, and the lens of
    # every frame rides along as extras, which Blender keeps as a custom
    # property of the camera.
    keys = cam.data.get("tideline_yfov_per_frame")
    lens = keys[frame] if keys is not None else float("nan")
    dfov = abs(lens - math.radians(ch["camera.fov"]))
    note("CAMERA 0 position", dp, frame)
    note("CAMERA 1 direction", df, frame)
    note("CAMERA 2 lens", dfov, frame)
    if boat is not None:
        b = sample["boat"]
        heading = math.radians(b["heading"])
        bow = blender_axes((math.sin(heading), 0.0, math.cos(heading)))
        # The node's glTF +z, the bow, is its Blender -y (the importer turns
        # a node's own y up into z up as it does the world's).
        got_bow = -boat.matrix_world.col[1].xyz.normalized()
        db = math.dist(tuple(boat.matrix_world.translation), blender_axes(b["position"]))
        # The bow's compass heading, level (pitch and roll leave it alone).
        dh = abs(math.atan2(got_bow.x, got_bow.y) - math.atan2(bow[0], bow[1]))
        # The deck's up, pitched and rolled: R = Ry(heading) Rx(-pitch)
        # Rz(-roll) applied to (0, 1, 0), as tideline places the hull.
        p_, r_ = -math.radians(b["pitch"]), -math.radians(b["roll"])
        v = (-math.sin(r_), math.cos(r_), 0.0)
        v = (v[0], v[1] * math.cos(p_) - v[2] * math.sin(p_), v[1] * math.sin(p_) + v[2] * math.cos(p_))
        v = (v[0] * math.cos(heading) + v[2] * math.sin(heading), v[1],
             -v[0] * math.sin(heading) + v[2] * math.cos(heading))
        want_deck = blender_axes(v)
        got_deck = boat.matrix_world.col[2].xyz.normalized()  # glTF +y: Blender's +z
        dd = angle(got_deck, want_deck)
        note("BOAT 0 position", db, frame)
        note("BOAT 1 heading", min(dh, 2 * math.pi - dh), frame)
        note("BOAT 2 deck", dd, frame)


try:
    main()
except SystemExit:
    raise
except Exception as e:  # a Python error is a failure, with its message
    print("ERROR", e)
    sys.exit(1)
