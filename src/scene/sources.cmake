tl_module(scene SOURCES tl_scene.c tl_quality.c tl_scene_rig.c DEPS core)
