tl_module(audio SOURCES tl_audio.c DEPS core EXTERNAL PkgConfig::SNDFILE)
