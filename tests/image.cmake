# Image I/O tests.
tl_add_test(test_image_io SOURCES test_image_io.c LIBS tideline_core LABELS unit)
# PSNR, SSIM and pixel-error percentiles (tideline compare / bench).
tl_add_test(test_metrics SOURCES test_metrics.c LIBS tideline_core LABELS unit)
