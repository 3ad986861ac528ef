# Blender 3.4's Vector Blur node on a tideline EXR with the Depth and
# Vector passes: the frame is blurred along the motion its vectors give.
# Run headless:
#   blender -b --factory-startup --python blender_vector_blur.py -- \
#       FRAME.exr OUT_DIR WIDTH HEIGHT
# Prints "GRADIENT x_before x_after y_before y_after": the mean absolute
# difference between neighbouring pixels across (x) and down (y), of the
# image straight from the file and through Vector Blur. Exits non-zero on
# any failure.
import os
import sys

import bpy


def composite(tree, source, blur, out_path):
    tree.links.clear()
    composite = tree.nodes.get("Composite") or tree.nodes.new("CompositorNodeComposite")
    composite.name = "Composite"
    composite.use_alpha = False
    if blur:
        node = tree.nodes.new("CompositorNodeVecBlur")
        node.samples = 32
        node.factor = 1.0
        node.speed_max = 0
        tree.links.new(source.outputs["Combined"], node.inputs["Image"])
        tree.links.new(source.outputs["Depth"], node.inputs["Z"])
        tree.links.new(source.outputs["Vector"], node.inputs["Speed"])
        tree.links.new(node.outputs["Image"], composite.inputs["Image"])
    else:
        tree.links.new(source.outputs["Combined"], composite.inputs["Image"])
    bpy.context.scene.render.filepath = out_path
    bpy.ops.render.render(write_still=True)
    return bpy.data.images.load(out_path)


def gradients(image, width, height):
    px = image.pixels[:]
    lum = [0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2] for i in range(0, len(px), 4)]
    gx = gy = 0.0
    for y in range(height - 1):
        for x in range(width - 1):
            i = y * width + x
            gx += abs(lum[i + 1] - lum[i])
            gy += abs(lum[i + width] - lum[i])
    n = (width - 1) * (height - 1)
    return gx / n, gy / n


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    frame, out_dir, width, height = args[0], args[1], int(args[2]), int(args[3])
    scene = bpy.context.scene
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.render.use_compositing = True
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.use_nodes = True
    tree = scene.node_tree
    tree.nodes.clear()
    source = tree.nodes.new("CompositorNodeImage")
    source.image = bpy.data.images.load(frame)
    names = [o.name for o in source.outputs]
    for needed in ("Combined", "Depth", "Vector"):
        if needed not in names:
            raise SystemExit("no %s pass in %s" % (needed, names))
    before = gradients(composite(tree, source, False, os.path.join(out_dir, "plain.exr")),
                       width, height)
    after = gradients(composite(tree, source, True, os.path.join(out_dir, "blurred.exr")),
                      width, height)
    print("GRADIENT %.6f %.6f %.6f %.6f" % (before[0], after[0], before[1], after[1]))


try:
    main()
except SystemExit:
    raise
except Exception as e:  # a Python error is a failure, with its message
    print("ERROR", e)
    sys.exit(1)
