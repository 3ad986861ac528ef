# The compositing passes: their names, the camera's attributes, Cryptomatte
# and the multilayer EXR.
tl_module(passes SOURCES tl_passes.c tl_cryptomatte.c tl_passes_exr.c tl_passes_motion.c
  DEPS color core image scene waves)
