tl_module(prepare SOURCES tl_prepare.c tl_prepare_rect.c DEPS core mesh optics scene sky waves
  EXTERNAL PkgConfig::CGLM)
