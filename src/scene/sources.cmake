tl_module(scene SOURCES tl_scene.c tl_quality.c DEPS core)
