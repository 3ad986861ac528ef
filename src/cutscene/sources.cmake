tl_module(cutscene SOURCES tl_cutscene.c DEPS audio core mesh timeline)
