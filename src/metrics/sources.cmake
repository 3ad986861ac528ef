tl_module(metrics SOURCES tl_metrics.c tl_exposure.c EXTERNAL ${MATH_LIB})
