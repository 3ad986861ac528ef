tl_module(sky SOURCES tl_sky.c DEPS scene)
