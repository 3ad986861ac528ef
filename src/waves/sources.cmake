tl_module(waves SOURCES tl_waves.c tl_noise.c tl_giant.c tl_giant_lip.c tl_giant_spray.c tl_bow_spray.c tl_kelvin.c tl_caustics.c DEPS scene)
