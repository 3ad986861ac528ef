tl_module(prepare SOURCES tl_prepare.c tl_prepare_rect.c tl_prepare_wash.c DEPS core mesh optics scene sky waves
  EXTERNAL PkgConfig::CGLM)
