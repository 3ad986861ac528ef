tl_module(audio SOURCES tl_audio.c DEPS core EXTERNAL PkgConfig::SNDFILE)
# The preview's playback: its own library, so that headless programs do
# not link the audio system.
tl_module(audio_play SOURCES tl_audio_play.c DEPS audio core EXTERNAL PkgConfig::SDL2)
