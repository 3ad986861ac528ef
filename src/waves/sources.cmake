tl_module(waves SOURCES tl_waves.c tl_giant.c DEPS scene)
