# The Blender side of the exporter's round trip: builds scenes headless,
# exports each with tools/blender/tideline_export.py, and writes what
# Blender itself evaluates at every frame (the camera's world matrix and
# vertical field of view from its projection matrix, the sun's direction,
# the boats' positions) for test_blender_export.sh to compare with
# `tideline eval`. Run:
#   blender -b --factory-startup --python blender_export_scenes.py -- ADDON_DIR OUT_DIR
# Writes OUT_DIR/NAME.tl and OUT_DIR/NAME.json per scene, and for the
# scenes the exporter must refuse OUT_DIR/NAME.err with its message.
import json
import math
import os
import sys

import bpy
from mathutils import Quaternion, Vector

args = sys.argv[sys.argv.index("--") + 1:]
sys.path.insert(0, args[0])
out_dir = args[1]
import tideline_export  # noqa: E402  (the add-on, from the repository)

W, H = 320, 180


def fresh_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = 24
    scene.frame_start, scene.frame_end = 1, 48
    scene.render.resolution_x, scene.render.resolution_y = W, H
    scene.render.resolution_percentage = 100
    return scene


def add_camera(scene, name, mode="XYZ"):
    data = bpy.data.cameras.new(name)
    cam = bpy.data.objects.new(name, data)
    scene.collection.objects.link(cam)
    cam.rotation_mode = mode
    scene.camera = cam
    return cam


def key(ob, path, frame, value, interpolation=None, easing=None):
    setattr(ob, path, value)
    ob.keyframe_insert(path, frame=frame)
    if interpolation:
        for fc in ob.animation_data.action.fcurves:
            if fc.data_path == path:
                for k in fc.keyframe_points:
                    if k.co[0] == frame:
                        k.interpolation = interpolation
                        if easing:
                            k.easing = easing


def add_sun(scene, rotating):
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    scene.collection.objects.link(sun)
    sun.rotation_euler = (math.radians(60), 0.0, math.radians(30))
    if rotating:
        key(sun, "rotation_euler", 1, (math.radians(60), 0.0, math.radians(30)))
        key(sun, "rotation_euler", 48, (math.radians(75), math.radians(10), math.radians(120)))
    return sun


def add_boat(scene, name, prop=None):
    boat = bpy.data.objects.new(name, None)
    scene.collection.objects.link(boat)
    if prop is not None:
        boat["tideline_boat"] = prop
    key(boat, "location", 1, (2.0, 30.0, 0.0))
    key(boat, "location", 20, (6.0, 34.0, 0.0), "BEZIER")
    key(boat, "location", 48, (4.0, 45.0, 0.0))
    return boat


def reference(scene, boats):
    """What Blender evaluates at every frame."""
    W = scene.render.resolution_x * scene.render.resolution_percentage // 100
    H = scene.render.resolution_y * scene.render.resolution_percentage // 100
    frames = []
    depsgraph = bpy.context.evaluated_depsgraph_get()
    for f in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(f)
        cam = scene.camera
        m = cam.matrix_world
        proj = cam.calc_matrix_camera(depsgraph, x=W, y=H)
        sample = {
            "position": list(m.translation),
            "forward": list(-m.col[2].xyz.normalized()),
            "up": list(m.col[1].xyz.normalized()),
            "vfov": 2.0 * math.atan(1.0 / proj[1][1]),
            "boats": {name: list(ob.matrix_world.translation) for name, ob in boats},
        }
        suns = [o for o in scene.objects
                if o.type == "LIGHT" and o.data.type == "SUN" and not o.hide_render]
        suns.sort(key=lambda o: o.name.lower() != "sun")  # the exporter's choice first
        if suns:
            sample["sun"] = list((suns[0].matrix_world.to_3x3() @ Vector((0.0, 0.0, 1.0))).normalized())
        frames.append(sample)
    return frames


def export(name, scene, boats=()):
    path = os.path.join(out_dir, name + ".tl")
    try:
        report = tideline_export.export(scene, path)
    except tideline_export.ExportError as e:
        with open(os.path.join(out_dir, name + ".err"), "w") as f:
            f.write(str(e) + "\n")
        print("REFUSED", name, e)
        return
    for line in report:
        print("REPORT", name, line)
    with open(os.path.join(out_dir, name + ".json"), "w") as f:
        json.dump(reference(scene, boats), f)
    print("EXPORTED", name)


# 1. Keys kept: Bezier location keys, an XYZ rotation with an eased key,
# a keyed focal length, a rotating sun, a boat by name and one by property.
scene = fresh_scene()
cam = add_camera(scene, "Cam")
key(cam, "location", 1, (0.0, -10.0, 3.0))
key(cam, "location", 20, (4.0, -6.0, 5.0))
key(cam, "location", 48, (8.0, 2.0, 2.5))
key(cam, "rotation_euler", 1, (math.radians(80), 0.0, math.radians(-10)))
key(cam, "rotation_euler", 30, (math.radians(70), math.radians(8), math.radians(20)), "SINE", "EASE_IN_OUT")
key(cam, "rotation_euler", 48, (math.radians(95), math.radians(-5), math.radians(40)))
cam.data.lens = 35.0
cam.data.keyframe_insert("lens", frame=1)
cam.data.lens = 70.0
cam.data.keyframe_insert("lens", frame=40)
# A free handle, moved by hand: written where Blender has it.
fc = cam.animation_data.action.fcurves.find("location", index=2)
k = fc.keyframe_points[1]
k.handle_right_type = "FREE"
k.handle_right = (k.co[0] + 6.0, k.co[1] + 1.5)
for c in cam.animation_data.action.fcurves.values():
    if c.data_path == "location":
        c.keyframe_points[1].handle_right_type = "FREE"
        c.keyframe_points[1].handle_right = (c.keyframe_points[1].co[0] + 6.0, c.keyframe_points[1].handle_right[1])
add_sun(scene, True)
boats = [("boat", add_boat(scene, "boat")), ("rescue", add_boat(scene, "Rescue.001", "rescue"))]
boats[1][1].location.x += 5
boats[1][1].animation_data_clear()
export("keys", scene, boats)
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out_dir, "keys.blend"))

# 2. A quaternion camera, vertical sensor fit, a still sun.
scene = fresh_scene()
cam = add_camera(scene, "Cam", "QUATERNION")
key(cam, "location", 1, (1.0, -8.0, 2.0))
key(cam, "location", 48, (-3.0, 4.0, 6.0))
key(cam, "rotation_quaternion", 1, Quaternion((1, 0, 0), math.radians(80)))
key(cam, "rotation_quaternion", 24, Quaternion((0.2, 0.1, 1), math.radians(100)), "LINEAR")
key(cam, "rotation_quaternion", 48, Quaternion((1, 0.3, 0.2), math.radians(60)))
cam.data.sensor_fit = "VERTICAL"
cam.data.sensor_height = 20.0
cam.data.lens = 28.0
add_sun(scene, False)
export("quaternion", scene)

# 3. An axis-angle camera in another Euler order's neighbour: ZXY Euler.
scene = fresh_scene()
cam = add_camera(scene, "Cam", "AXIS_ANGLE")
key(cam, "location", 1, (0.0, 0.0, 4.0))
key(cam, "rotation_axis_angle", 1, (math.radians(70), 1.0, 0.2, 0.1))
key(cam, "rotation_axis_angle", 48, (math.radians(110), 0.8, 0.1, 0.6))
export("axis_angle", scene)
scene = fresh_scene()
cam = add_camera(scene, "Cam", "ZXY")
key(cam, "location", 1, (0.0, 0.0, 4.0))
key(cam, "rotation_euler", 1, (math.radians(70), 0.3, 0.2))
key(cam, "rotation_euler", 24, (math.radians(100), -0.2, 1.2), "BACK", "AUTO")
key(cam, "rotation_euler", 48, (math.radians(80), 0.1, 0.7))
export("zxy", scene)

# 3b. The render size and rate as Blender computes them: a portrait frame
# at 50 % (odd sizes: integer division), 30000/1001 fps, a horizontal
# sensor fit, the YZX order; a lens shift (reported, not carried).
scene = fresh_scene()
scene.render.resolution_x, scene.render.resolution_y = 1083, 1923
scene.render.resolution_percentage = 50
scene.render.fps, scene.render.fps_base = 30, 1.001
cam = add_camera(scene, "Cam", "YZX")
cam.data.sensor_fit = "HORIZONTAL"
cam.data.shift_x = 0.1
key(cam, "location", 1, (0.0, -5.0, 3.0))
key(cam, "location", 48, (3.0, 2.0, 5.0))
key(cam, "rotation_euler", 1, (math.radians(80), 0.2, 0.4))
key(cam, "rotation_euler", 48, (math.radians(95), -0.3, -0.5))
export("formats", scene)

# 3c. Animation Blender layers over the action: an action pushed into an
# NLA strip, a muted F-curve (the property's value holds), a boat in an
# excluded collection (not rendered: not exported), a hidden sun lamp
# named sun (the visible one is the sun).
scene = fresh_scene()
cam = add_camera(scene, "Cam")
key(cam, "rotation_euler", 1, (math.radians(80), 0.0, 0.0))
key(cam, "rotation_euler", 48, (math.radians(90), 0.0, math.radians(30)))
key(cam, "location", 1, (0.0, -10.0, 3.0))
key(cam, "location", 48, (6.0, -2.0, 4.0))
cam.animation_data.action.fcurves.find("location", index=0).mute = True
cam.location.x = 2.5
track = cam.animation_data.nla_tracks.new()
track.strips.new("layout", 1, cam.animation_data.action)
cam.animation_data.action = None
hidden = bpy.data.collections.new("Hidden")
scene.collection.children.link(hidden)
ghost = bpy.data.objects.new("boat", None)
hidden.objects.link(ghost)
key(ghost, "location", 1, (0.0, 0.0, 0.0))
bpy.context.view_layer.layer_collection.children["Hidden"].exclude = True
add_sun(scene, False).name = "Sunlight"
off = bpy.data.objects.new("sun", bpy.data.lights.new("sun2", "SUN"))
scene.collection.objects.link(off)
off.hide_render = True
off.rotation_euler = (0.0, 0.0, 0.0)
export("layered", scene)

# 4. Baked: a Noise modifier on the camera's height.
scene = fresh_scene()
cam = add_camera(scene, "Cam")
key(cam, "location", 1, (0.0, -10.0, 3.0))
key(cam, "location", 48, (5.0, 0.0, 3.0))
key(cam, "rotation_euler", 1, (math.radians(85), 0.0, 0.0))
noise = cam.animation_data.action.fcurves.find("location", index=2).modifiers.new("NOISE")
noise.scale, noise.strength = 4.0, 0.8
export("noise", scene)

# 5. Two cameras, a marker binding the second at frame 25: a cut.
scene = fresh_scene()
a = add_camera(scene, "CamA")
key(a, "location", 1, (0.0, -10.0, 3.0))
key(a, "location", 48, (5.0, -5.0, 3.0))
a.rotation_euler = (math.radians(85), 0.0, 0.0)
b = add_camera(scene, "CamB", "QUATERNION")
b.location = (20.0, 10.0, 8.0)
b.rotation_quaternion = Quaternion((1, 0, 0), math.radians(60))
scene.camera = a
ma = scene.timeline_markers.new("A", frame=1)
ma.camera = a
mb = scene.timeline_markers.new("B", frame=25)
mb.camera = b
export("cut", scene)

# 6. What the exporter refuses: no camera; a lamp marked as a boat. The
# first is saved too, for the add-on run headless on a .blend.
scene = fresh_scene()
export("no_camera", scene)
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out_dir, "no_camera.blend"))
scene = fresh_scene()
add_camera(scene, "Cam")
lamp = bpy.data.objects.new("lamp", bpy.data.lights.new("lamp", "POINT"))
scene.collection.objects.link(lamp)
lamp["tideline_boat"] = "lamp"
export("lamp_boat", scene)
