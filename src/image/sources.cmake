tl_module(image SOURCES tl_frame.c tl_atomic.c tl_exr.c tl_png.c tl_image_io.c DEPS core
  EXTERNAL tl_openexr_core PkgConfig::PNG Threads::Threads)
