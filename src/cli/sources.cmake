# The commands: a library of their own so that tests can call them.
tl_module(cli
  SOURCES tl_args.c tl_cli_common.c tl_cli_still.c tl_cli_timeline.c tl_cli_render.c
          tl_cli_preview.c tl_cli_compare.c tl_cli_bench.c tl_cli_export.c tl_cli_color.c
          tl_cli_movie.c tl_cli_overlay.c tl_cli_preview_keys.c tl_cli_preview_view.c
  DEPS audio audio_play bench color core cutscene export gl_window image job mesh metrics movie ocio passes prepare render render_window run scene
       shader timeline waves
  EXTERNAL Threads::Threads PkgConfig::STB)
