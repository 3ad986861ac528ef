tl_module(render SOURCES tl_render.c
  DEPS core cutscene gl image mesh prepare scene shader sky timeline waves)
tl_module(render_window SOURCES tl_render_window.c DEPS render gl gl_window)
