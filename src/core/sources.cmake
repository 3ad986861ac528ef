tl_module(core SOURCES tl_error.c tl_clock.c EXTERNAL ${MATH_LIB})
