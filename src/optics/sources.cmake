tl_module(optics SOURCES tl_optics.c DEPS scene)
