# Blender 3.4 as a compositor reads a tideline EXR with passes: its
# Cryptomatte node pulls an object's matte by name, and the matte is
# compared with tideline's own mask of that object (intersection over
# union). Run headless:
#   blender -b --factory-startup --python blender_cryptomatte.py -- \
#       FRAME.exr NAME MASK_PASS OUT.exr WIDTH HEIGHT [LAYER]
# (OUT.exr: where the compositor's result goes; the frame's size; LAYER:
# the Cryptomatte layer, ViewLayer.CryptoObject unless given).
# Prints the image node's passes and "IOU <value>"; exits non-zero on any failure.
import sys

import bpy


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    path, name, mask_pass, out_path = args[0], args[1], args[2], args[3]
    # A multilayer image's size is not known to Python before the
    # compositor loads it: the caller gives it.
    width, height = int(args[4]), int(args[5])
    layer = args[6] if len(args) > 6 else "ViewLayer.CryptoObject"
    image = bpy.data.images.load(path)

    scene = bpy.context.scene
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.use_compositing = True
    scene.use_nodes = True
    tree = scene.node_tree
    tree.nodes.clear()

    source = tree.nodes.new("CompositorNodeImage")
    source.image = image
    outputs = [o.name for o in source.outputs]
    print("PASSES", ",".join(outputs))
    if mask_pass not in outputs:
        raise SystemExit("no pass %s in %s" % (mask_pass, outputs))

    crypto = tree.nodes.new("CompositorNodeCryptomatteV2")
    crypto.source = "IMAGE"
    crypto.image = image
    crypto.layer_name = layer
    crypto.matte_id = name
    tree.links.new(source.outputs[0], crypto.inputs["Image"])

    # R: min(matte, mask), G: max(matte, mask), into the Viewer.
    low = tree.nodes.new("CompositorNodeMath")
    low.operation = "MINIMUM"
    high = tree.nodes.new("CompositorNodeMath")
    high.operation = "MAXIMUM"
    for node in (low, high):
        tree.links.new(crypto.outputs["Matte"], node.inputs[0])
        tree.links.new(source.outputs[mask_pass], node.inputs[1])
    combine = tree.nodes.new("CompositorNodeCombRGBA")
    tree.links.new(low.outputs[0], combine.inputs["R"])
    tree.links.new(high.outputs[0], combine.inputs["G"])
    composite = tree.nodes.new("CompositorNodeComposite")
    composite.use_alpha = False
    tree.links.new(combine.outputs["Image"], composite.inputs["Image"])

    # The composite written as a float EXR, then read back (in the
    # background a Viewer node's pixels are not filled).
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = out_path
    bpy.ops.render.render(write_still=True)
    result = bpy.data.images.load(out_path)
    pixels = result.pixels[:]
    inter = sum(pixels[0::4])
    union = sum(pixels[1::4])
    print("MATTE", sum(1 for v in pixels[0::4] if v > 0.5), "of", len(pixels) // 4)
    if union <= 0.0:
        raise SystemExit("the matte and the mask are both empty")
    print("IOU %.6f" % (inter / union))


try:
    main()
except SystemExit:
    raise
except Exception as e:  # a Python error is a failure, with its message
    print("ERROR", e)
    sys.exit(1)
