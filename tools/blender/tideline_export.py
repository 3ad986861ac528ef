# tideline exporter: writes a tideline timeline (.tl) from a Blender scene.
#
# Install it from Edit > Preferences > Add-ons > Install (this file), then
# File > Export > tideline timeline (.tl). Or headless:
#
#   blender -b scene.blend --python tools/blender/tideline_export.py -- out.tl
#
# What it writes (docs/blender.md has the conversions and the axis table):
# the scene's fps, frame range and resolution; the active camera's
# F-curves for location, rotation (in the camera's own rotation mode) and
# focal length, with its sensor; a sun lamp's direction as sun.elevation
# and sun.azimuth; objects chosen as boats (a custom property
# `tideline_boat`, or the name `boat`) as paths. Curves keep their keys,
# interpolation, easing and handles where tideline expresses them; where
# it cannot (a modifier, a driver, keys the components do not share, a
# parent or constraint, several cameras bound to markers, a sun's
# direction) the channel is baked to a key at every frame, marked `baked`
# and explained in a comment above it, and listed in Blender's report.

bl_info = {
    "name": "tideline timeline (.tl)",
    "author": "tideline",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "File > Export > tideline timeline (.tl)",
    "description": "Export the camera, the sun and boats as a tideline timeline",
    "category": "Import-Export",
}

import math
import re
import sys

import bpy
from bpy_extras.io_utils import ExportHelper
from mathutils import Euler, Matrix, Vector

# Blender's rotation modes as tideline's camera.rotation_mode names.
ROTATION_MODES = {"XYZ": "xyz", "XZY": "xzy", "YXZ": "yxz", "YZX": "yzx", "ZXY": "zxy",
                  "ZYX": "zyx", "QUATERNION": "quaternion", "AXIS_ANGLE": "axis_angle"}
HANDLE_TYPES = {"AUTO_CLAMPED": "auto-clamped", "AUTO": "auto", "VECTOR": "vector"}
EASED = {"SINE": "sine", "QUAD": "quad", "CUBIC": "cubic", "QUART": "quart", "QUINT": "quint",
         "EXPO": "expo", "CIRC": "circ", "BACK": "back", "BOUNCE": "bounce", "ELASTIC": "elastic"}
# Blender's automatic easing: ease out for the dynamic effects, in for the rest.
AUTO_EASE_OUT = {"BACK", "BOUNCE", "ELASTIC"}
NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]{0,30}$")
GROUPS = {"camera", "sun", "ocean", "water", "sky", "fog", "underwater", "giant", "quality", "render"}


class ExportError(Exception):
    """A scene the exporter cannot write; its message names what and why."""


def num(v):
    """A number as tideline reads it back exactly."""
    v = float(v)
    if not math.isfinite(v):
        raise ExportError("a value is not a finite number (%r)" % v)
    return repr(v) if v != int(v) or abs(v) > 1e15 else str(int(v))


def blender_to_tideline(v):
    """Blender's world (x east, y north, z up) to tideline's (x east, y up, z north)."""
    return (v[0], v[2], v[1])


class Channel:
    """A tideline channel fed by Blender properties: one F-curve (or a
    constant) per component, each value mapped by `scale` (radians stay
    radians: tideline reads them with a rad suffix)."""

    def __init__(self, name, anim, path, indices, values, unit=""):
        self.name, self.anim, self.path = name, anim, path
        self.indices, self.values, self.unit = indices, values, unit

    def fcurves(self):
        found = []
        for i in self.indices:
            fc = self.anim.action.fcurves.find(self.path, index=i) if self.anim and self.anim.action else None
            found.append(fc)
        return found

    def driven(self):
        if not self.anim:
            return False
        return any(d.data_path == self.path and d.array_index in self.indices for d in self.anim.drivers)


def layered(anim):
    """Why an owner's animation is more than its action's F-curves, or None."""
    if anim is None:
        return None
    if any(not t.mute and len(t.strips) for t in anim.nla_tracks):
        return "NLA strips animate it"
    if anim.action and (anim.action_influence != 1.0 or anim.action_blend_type != "REPLACE"):
        return "its action is blended"
    return None


def animated(ob):
    """Whether anything moves an object (its action, NLA, drivers, a parent
    or constraints)."""
    anim = ob.animation_data
    return bool(anim and (anim.action or anim.drivers or layered(anim))) \
        or ob.parent is not None or len(ob.constraints) > 0


def why_not_exact(channel, curves, frame_start):
    """None when the F-curves can be written as tideline keys, else why not."""
    if channel.driven():
        return "a driver sets it"
    why = layered(channel.anim)
    if why:
        return why
    present = [c for c in curves if c is not None]
    if not present:
        return None
    for c in present:
        if c.mute:
            return "its F-curve is muted"
        if c.modifiers:
            return "its F-curve has a %s modifier" % c.modifiers[0].type.lower().replace("_", " ")
        if c.extrapolation not in ("CONSTANT", "LINEAR"):
            return "its extrapolation is %s" % c.extrapolation.lower()
    ref = present[0]
    frames = [k.co[0] for k in ref.keyframe_points]
    for c in present[1:]:
        if [k.co[0] for k in c.keyframe_points] != frames:
            return "its components have keys on different frames"
        if c.extrapolation != ref.extrapolation or c.auto_smoothing != ref.auto_smoothing:
            return "its components extrapolate or smooth differently"
    for i, k in enumerate(ref.keyframe_points):
        for c in present[1:]:
            o = c.keyframe_points[i]
            if (o.interpolation, o.easing, o.handle_left_type, o.handle_right_type) != (
                    k.interpolation, k.easing, k.handle_left_type, k.handle_right_type):
                return "its components' keys differ in interpolation or handles"
            if (o.back, o.amplitude, o.period) != (k.back, k.amplitude, k.period):
                return "its components' keys differ in easing settings"
            for side in ("left", "right"):
                if getattr(k, "handle_%s_type" % side) in ("FREE", "ALIGNED"):
                    if getattr(o, "handle_" + side)[0] != getattr(k, "handle_" + side)[0]:
                        return "its components' free handles lie at different times"
        if k.interpolation == "ELASTIC" and any(
                c.keyframe_points[i].amplitude != k.amplitude for c in present):
            return "its components' elastic amplitudes differ"
    return None


def key_lines(channel, curves, frame_start):
    """The channel's keys as tideline key lines (its F-curves are exact)."""
    present = [c for c in curves if c is not None]
    ref = present[0]
    unit = channel.unit
    # Where a key has a free or aligned handle, Blender computes the auto
    # handles around it its own way: every handle is then written where
    # Blender has put it.
    explicit = any(getattr(k, "handle_%s_type" % side) not in HANDLE_TYPES
                   for k in ref.keyframe_points for side in ("left", "right"))
    lines = []
    for i, k in enumerate(ref.keyframe_points):
        t = k.co[0] - frame_start
        values, left, right = [], [], []
        for comp, c in enumerate(curves):
            if c is None:
                values.append(channel.values[comp])
                left.append(0.0)
                right.append(0.0)
            else:
                kk = c.keyframe_points[i]
                values.append(kk.co[1])
                left.append(kk.handle_left[1] - kk.co[1])
                right.append(kk.handle_right[1] - kk.co[1])
        words = ["  %sf" % num(t)] + [num(v) + unit for v in values]
        if k.interpolation == "CONSTANT":
            words.append("constant")
        elif k.interpolation == "LINEAR":
            words.append("linear")
        elif k.interpolation == "BEZIER":
            words.append("bezier")
        else:
            easing = k.easing
            if easing == "AUTO":
                easing = "EASE_OUT" if k.interpolation in AUTO_EASE_OUT else "EASE_IN"
            direction = {"EASE_IN": "in", "EASE_OUT": "out", "EASE_IN_OUT": "in-out"}[easing]
            words.append("ease-%s-%s" % (direction, EASED[k.interpolation]))
            if k.interpolation == "BACK":
                words += ["back", num(k.back)]
            if k.interpolation == "ELASTIC":
                words += ["amplitude", num(k.amplitude) + unit, "period", "%sf" % num(k.period)]
        for side, offsets in (("left", left), ("right", right)):
            htype = getattr(k, "handle_%s_type" % side)
            if htype in HANDLE_TYPES and not explicit:
                words += [side, HANDLE_TYPES[htype]]
            else:  # free or aligned: where Blender put it, exactly
                dt = getattr(k, "handle_" + side)[0] - k.co[0]
                words += [side, "free", "%sf" % num(dt)] + [num(v) + unit for v in offsets]
        lines.append(" ".join(words))
    return lines


def channel_header(channel, curves):
    ref = [c for c in curves if c is not None][0]
    words = ["key", channel.name]
    if ref.extrapolation == "LINEAR":
        words += ["extrapolate", "linear"]
    words += ["smoothing", "continuous" if ref.auto_smoothing == "CONT_ACCEL" else "none"]
    return " ".join(words)


class Writer:
    def __init__(self, scene):
        self.scene = scene
        self.fps = scene.render.fps / scene.render.fps_base
        self.start, self.end = scene.frame_start, scene.frame_end
        self.lines = []
        self.baked = []  # (channel, why): for the report

    def frames(self):
        return range(self.start, self.end + 1)

    def set(self, name, *values):
        self.lines.append("set %s %s" % (name, " ".join(values)))

    def bake(self, name, why, sample, unit="", cuts=()):
        """Keys at every frame of sample(frame) -> values, linear."""
        self.baked.append((name, why))
        self.lines.append("# baked: %s (%s): a key at every frame" % (name, why))
        self.lines.append("key %s linear baked" % name)
        for f in self.frames():
            values = sample(f)
            cut = " cut" if f in cuts else ""
            self.lines.append("  %sf%s %s" % (num(f - self.start), cut, " ".join(num(v) + unit for v in values)))

    def channel(self, channel):
        curves = channel.fcurves()
        why = why_not_exact(channel, curves, self.start)
        if why is None and all(c is None for c in curves):
            self.set(channel.name, *[num(v) + channel.unit for v in channel.values])
            return
        if why is None:
            self.lines.append(channel_header(channel, curves))
            self.lines += key_lines(channel, curves, self.start)
            return
        prop = channel.anim_owner

        def sample(f):
            self.scene.frame_set(f)
            value = getattr(prop, channel.path)
            return [value[i] if hasattr(value, "__len__") else value for i in channel.indices]
        self.bake(channel.name, why, sample, channel.unit)


def camera_cuts(scene):
    """The frames where a marker binds another camera, and the cameras."""
    bound = sorted((m.frame, m.camera) for m in scene.timeline_markers if m.camera)
    return bound


def rendered_objects(scene):
    """The objects a render of the scene shows: in its view layer (not in an
    excluded collection) and not hidden from renders."""
    layer = scene.view_layers[0] if scene.view_layers else None
    if bpy.context.scene == scene and bpy.context.view_layer:
        layer = bpy.context.view_layer
    if layer is None:
        return [ob for ob in scene.objects if not ob.hide_render]
    layer.update()  # objects linked by a script join the layer's list here
    return [ob for ob in layer.objects if not ob.hide_render]


def export(scene, path):
    """Writes the scene as a timeline at `path`; returns the report's lines
    (what was baked, what was left out). Raises ExportError. The scene's
    current frame is where it was."""
    current = scene.frame_current
    try:
        return export_frames(scene, path)
    finally:
        scene.frame_set(current)


def export_frames(scene, path):
    w = Writer(scene)
    camera = scene.camera
    if camera is None or camera.type != "CAMERA":
        raise ExportError("the scene has no active camera (Scene properties > Camera)")
    if camera.data.type != "PERSP":
        raise ExportError("camera '%s' is %s: tideline renders perspective cameras only"
                          % (camera.name, camera.data.type.lower()))
    out = ["tideline 1",
           "# Exported from Blender %s by tools/blender/tideline_export.py: scene '%s', frames %d-%d"
           % (bpy.app.version_string, scene.name, w.start, w.end),
           "fps %s" % num(w.fps),
           "duration %sf" % num(w.end - w.start + 1),
           # Blender's render size: the percentage in integer arithmetic.
           "size %dx%d" % (scene.render.resolution_x * scene.render.resolution_percentage // 100,
                           scene.render.resolution_y * scene.render.resolution_percentage // 100)]

    if scene.render.pixel_aspect_x != scene.render.pixel_aspect_y:
        raise ExportError("the scene's pixels are not square (pixel aspect %g:%g): tideline's are"
                          % (scene.render.pixel_aspect_x, scene.render.pixel_aspect_y))
    # Boats first: `boat NAME` declares a floating object before anything names it.
    boats = []
    for ob in rendered_objects(scene):
        mark = ob.get("tideline_boat")
        if mark is None and ob.name != "boat":
            continue
        name = mark if isinstance(mark, str) and mark else ob.name
        if ob.type in ("CAMERA", "LIGHT"):
            raise ExportError("object '%s' is a %s: a boat is a mesh or an empty"
                              % (ob.name, ob.type.lower()))
        if not NAME.fullmatch(name) or name in GROUPS:
            raise ExportError("object '%s': '%s' is not a tideline boat name (letters, digits "
                              "and _, starting with a letter, at most 31, not a channel group)"
                              % (ob.name, name))
        if name in [b[0] for b in boats]:
            raise ExportError("two objects are the boat '%s'" % name)
        boats.append((name, ob))
    for name, ob in boats:
        if name != "boat":
            out.append("boat %s" % name)

    cuts = camera_cuts(scene)
    cameras = {c for _, c in cuts} | {camera}
    if len(cameras) > 1:
        out += write_camera_shots(w, scene, cuts)
    else:
        write_camera(w, scene, camera)
    write_sun(w, scene)
    for name, ob in boats:
        write_boat(w, scene, name, ob)
    scene.frame_set(w.start)
    notes = ["baked %s: %s" % (name, why) for name, why in w.baked]
    if camera.data.shift_x or camera.data.shift_y:
        notes.append("not carried over: camera '%s''s lens shift" % camera.name)
    with open(path, "w", encoding="ascii", errors="replace") as f:
        f.write("\n".join(out + w.lines) + "\n")
    return notes


def exact_transform(ob):
    """Why an object's world transform is not its own channels, or None."""
    if ob.parent:
        return "it has a parent"
    if len(ob.constraints):
        return "it has constraints"
    if any(ob.delta_location) or any(ob.delta_rotation_euler) or tuple(ob.delta_scale) != (1, 1, 1) \
            or tuple(ob.delta_rotation_quaternion) != (1, 0, 0, 0):
        return "it has delta transforms"
    anim = ob.animation_data
    curves = anim.action.fcurves if anim and anim.action else []
    paths = {c.data_path for c in curves} | ({d.data_path for d in anim.drivers} if anim else set())
    if any(p.startswith("delta_") for p in paths):
        return "its delta transforms are animated"
    if "rotation_mode" in paths:
        return "its rotation mode is animated"
    return layered(anim)


def write_camera(w, scene, camera):
    anim = camera.animation_data
    why = exact_transform(camera)
    loc = camera.location
    position = Channel("camera.position", anim, "location", (0, 2, 1), (loc[0], loc[2], loc[1]))
    position.anim_owner = camera
    mode = camera.rotation_mode
    if why is None:
        w.channel(position)
        w.set("camera.rotation_mode", ROTATION_MODES[mode])
        if mode == "QUATERNION":
            q = camera.rotation_quaternion
            for ch in (Channel("camera.quaternion_w", anim, "rotation_quaternion", (0,), (q[0],)),
                       Channel("camera.quaternion", anim, "rotation_quaternion", (1, 2, 3), tuple(q[1:]))):
                ch.anim_owner = camera
                w.channel(ch)
        elif mode == "AXIS_ANGLE":
            a = camera.rotation_axis_angle
            for ch in (Channel("camera.axis_angle", anim, "rotation_axis_angle", (0,), (a[0],), "rad"),
                       Channel("camera.axis", anim, "rotation_axis_angle", (1, 2, 3), tuple(a[1:]))):
                ch.anim_owner = camera
                w.channel(ch)
        else:
            e = camera.rotation_euler
            ch = Channel("camera.rotation", anim, "rotation_euler", (0, 1, 2), tuple(e), "rad")
            ch.anim_owner = camera
            w.channel(ch)
    else:
        bake_camera_transform(w, scene, why, lambda f: camera)
    write_lens(w, scene, camera)


def bake_camera_transform(w, scene, why, camera_at, cuts=()):
    """Position and an XYZ Euler rotation at every frame, from the world
    matrix of camera_at(frame)."""
    w.set("camera.rotation_mode", "xyz")
    state = {"euler": None}

    def position(f):
        scene.frame_set(f)
        return blender_to_tideline(camera_at(f).matrix_world.translation)

    def rotation(f):
        scene.frame_set(f)
        e = camera_at(f).matrix_world.to_euler("XYZ", state["euler"]) if state["euler"] else \
            camera_at(f).matrix_world.to_euler("XYZ")
        state["euler"] = e
        return tuple(e)
    w.bake("camera.position", why, position, "", cuts)
    w.bake("camera.rotation", why, rotation, "rad", cuts)


def write_lens(w, scene, camera, cuts=(), camera_at=None):
    data = camera.data
    anim = data.animation_data
    keyed = {c.data_path for c in anim.action.fcurves} if anim and anim.action else set()
    if anim:
        keyed |= {d.data_path for d in anim.drivers}
    if "sensor_fit" in keyed:
        raise ExportError("camera '%s''s sensor fit is animated: tideline's is one setting"
                          % camera.name)
    w.set("camera.sensor_fit", data.sensor_fit.lower())
    for path, name in (("sensor_width", "camera.sensor"), ("sensor_height", "camera.sensor_height")):
        if path in keyed or layered(anim):
            ch = Channel(name, anim, path, (0,), (getattr(data, path),))
            ch.anim_owner = data
            w.channel(ch)
        else:
            w.set(name, num(getattr(data, path)))
    if camera_at is not None:
        def lens(f):
            scene.frame_set(f)
            return (camera_at(f).data.lens,)
        w.bake("camera.focal_length", "several cameras", lens, "", cuts)
        return
    ch = Channel("camera.focal_length", data.animation_data, "lens", (0,), (data.lens,))
    ch.anim_owner = data
    w.channel(ch)


def write_camera_shots(w, scene, cuts):
    """Several cameras bound to markers: each frame's camera, baked, with a
    cut where the camera changes."""
    def camera_at(f):
        scene.frame_set(f)
        return scene.camera
    cut_frames = set()
    previous = None
    for f in w.frames():
        cam = camera_at(f)
        if previous is not None and cam != previous:
            cut_frames.add(f)
        previous = cam
    why = "the shot cuts between cameras at markers"
    bake_camera_transform(w, scene, why, camera_at, cut_frames)
    sensors = {(c.data.sensor_width, c.data.sensor_height, c.data.sensor_fit) for _, c in cuts}
    sensors.add((scene.camera.data.sensor_width, scene.camera.data.sensor_height, scene.camera.data.sensor_fit))
    if len(sensors) > 1:
        raise ExportError("the cameras bound to markers have different sensors: tideline's "
                          "camera has one (give them the same sensor width, height and fit)")
    scene.frame_set(w.start)
    write_lens(w, scene, scene.camera, cut_frames, camera_at)
    return []


def sun_direction(sun):
    """Toward the sun (the lamp shines along its -Z), tideline's axes:
    elevation and azimuth in radians."""
    d = sun.matrix_world.to_3x3() @ Vector((0.0, 0.0, 1.0))
    d.normalize()
    x, y, z = blender_to_tideline(d)
    return math.asin(max(-1.0, min(1.0, y))), math.atan2(x, z)


def write_sun(w, scene):
    suns = [ob for ob in rendered_objects(scene) if ob.type == "LIGHT" and ob.data.type == "SUN"]
    if not suns:
        return
    sun = next((s for s in suns if s.name.lower() == "sun"), suns[0])
    if not animated(sun):
        scene.frame_set(w.start)
        elevation, azimuth = sun_direction(sun)
        w.set("sun.elevation", num(elevation) + "rad")
        w.set("sun.azimuth", num(azimuth) + "rad")
        return
    state = {"azimuth": None}

    def elevation(f):
        scene.frame_set(f)
        return (sun_direction(sun)[0],)

    def azimuth(f):
        scene.frame_set(f)
        a = sun_direction(sun)[1]
        if state["azimuth"] is not None:  # no jump of a turn between frames
            a += 2 * math.pi * round((state["azimuth"] - a) / (2 * math.pi))
        state["azimuth"] = a
        return (a,)
    why = "a lamp's rotation is not an elevation and an azimuth"
    w.bake("sun.elevation", why, elevation, "rad")
    w.bake("sun.azimuth", why, azimuth, "rad")


def write_boat(w, scene, name, ob):
    def where(f):
        scene.frame_set(f)
        p = ob.matrix_world.translation
        return p[0], p[1]
    if not animated(ob):
        x, z = where(w.start)
        w.lines.append("path %s" % name)
        w.lines.append("  0f %s %s" % (num(x), num(z)))
        return
    why = "tideline's paths are Catmull-Rom curves through points"
    w.baked.append(("path " + name, why))
    w.lines.append("# baked: path %s (%s): a point at every frame" % (name, why))
    w.lines.append("path %s baked" % name)
    for f in w.frames():
        x, z = where(f)
        w.lines.append("  %sf %s %s" % (num(f - w.start), num(x), num(z)))


class EXPORT_OT_tideline(bpy.types.Operator, ExportHelper):
    """Export the camera, the sun and boats as a tideline timeline"""
    bl_idname = "export_scene.tideline"
    bl_label = "Export tideline timeline"
    filename_ext = ".tl"
    filter_glob: bpy.props.StringProperty(default="*.tl", options={"HIDDEN"})

    def execute(self, context):
        try:
            report = export(context.scene, self.filepath)
        except Exception as e:  # ExportError says why; anything else is named
            self.report({"ERROR"}, "tideline: %s" % e)
            return {"CANCELLED"}
        for line in report:
            self.report({"WARNING"}, "tideline: %s" % line)
        self.report({"INFO"}, "tideline: wrote %s" % self.filepath)
        return {"FINISHED"}


def menu_export(self, context):
    self.layout.operator(EXPORT_OT_tideline.bl_idname, text="tideline timeline (.tl)")


def register():
    bpy.utils.register_class(EXPORT_OT_tideline)
    bpy.types.TOPBAR_MT_file_export.append(menu_export)


def unregister():
    bpy.types.TOPBAR_MT_file_export.remove(menu_export)
    bpy.utils.unregister_class(EXPORT_OT_tideline)


def main(argv):
    """Headless: blender -b scene.blend --python tideline_export.py -- out.tl"""
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    if len(args) != 1 or not args[0].endswith(".tl"):
        print("tideline_export: usage: blender -b scene.blend --python tideline_export.py -- OUT.tl",
              file=sys.stderr)
        return 2
    try:
        report = export(bpy.context.scene, args[0])
    except ExportError as e:
        print("tideline_export: error: %s" % e, file=sys.stderr)
        return 1
    except Exception as e:  # a bug or a scene not foreseen: still a failure
        print("tideline_export: error: %s: %s" % (type(e).__name__, e), file=sys.stderr)
        return 1
    for line in report:
        print("tideline_export: %s" % line)
    print("tideline_export: wrote %s" % args[0])
    return 0


if __name__ == "__main__":
    if bpy.app.background:
        sys.exit(main(sys.argv))
    register()
