# Image I/O tests.
tl_add_test(test_image_io SOURCES test_image_io.c LIBS tideline_core)
