tl_module(timeline
  SOURCES tl_ease.c tl_curve.c tl_curve_prepare.c tl_curve_smooth.c tl_path.c tl_channels.c
          tl_timeline.c tl_float.c tl_shutter.c tl_parse.c tl_parse_diag.c tl_parse_values.c
          tl_parse_checks.c tl_parse_links.c tl_parse_keys.c tl_parse_lex.c tl_parse_files.c
          tl_parse_header.c
  DEPS color core passes scene waves)
