tl_module(metrics SOURCES tl_metrics.c EXTERNAL ${MATH_LIB})
