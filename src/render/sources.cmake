tl_module(render SOURCES tl_render.c tl_render_meter.c
  DEPS core cutscene gl image mesh metrics prepare scene shader sky timeline waves)
tl_module(render_window SOURCES tl_render_window.c DEPS render gl gl_window)
