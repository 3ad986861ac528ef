# Image I/O tests.
tl_add_test(test_image_io SOURCES test_image_io.c LIBS tideline_core LABELS unit)
# PSNR, SSIM and pixel-error percentiles (tideline compare / bench).
# Against the values tests/metrics_reference.py wrote (the file says how).
tl_add_test(test_metrics SOURCES test_metrics.c LIBS tideline_core
  ARGS ${CMAKE_CURRENT_SOURCE_DIR}/fixtures/metrics_reference.txt LABELS unit)
tl_add_test(test_passes SOURCES test_passes.c LIBS tideline_core LABELS unit)
# Auto exposure's meter, adaptation and scale (no GL).
tl_add_test(test_exposure SOURCES test_exposure.c LIBS tideline_core LABELS unit)
