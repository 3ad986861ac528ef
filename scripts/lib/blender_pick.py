# The Cryptomatte of a tideline EXR as Blender's Cryptomatte node shows it
# (its Pick output: a colour per ID, brighter where it covers more), written
# to a PNG. For scripts/passes-sheet.sh:
#   blender -b --factory-startup --python blender_pick.py -- FRAME.exr OUT.png WIDTH HEIGHT
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
frame, out, width, height = args[0], args[1], int(args[2]), int(args[3])
scene = bpy.context.scene
scene.render.engine = "BLENDER_WORKBENCH"
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.use_compositing = True
scene.use_nodes = True
scene.view_settings.view_transform = "Standard"
tree = scene.node_tree
tree.nodes.clear()
image = bpy.data.images.load(frame)
source = tree.nodes.new("CompositorNodeImage")
source.image = image
crypto = tree.nodes.new("CompositorNodeCryptomatteV2")
crypto.source = "IMAGE"
crypto.image = image
crypto.layer_name = "ViewLayer.CryptoObject"
tree.links.new(source.outputs[0], crypto.inputs["Image"])
composite = tree.nodes.new("CompositorNodeComposite")
composite.use_alpha = False
tree.links.new(crypto.outputs["Pick"], composite.inputs["Image"])
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_mode = "RGB"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
