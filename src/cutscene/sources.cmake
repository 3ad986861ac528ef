tl_module(cutscene SOURCES tl_cutscene.c DEPS core mesh timeline)
