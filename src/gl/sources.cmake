set(TL_GL_SOURCES ${CMAKE_CURRENT_LIST_DIR}/tl_gl_context.c ${CMAKE_CURRENT_LIST_DIR}/tl_gl_window.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_renderer.c ${CMAKE_CURRENT_LIST_DIR}/tl_renderer_prepass.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_renderer_display.c ${CMAKE_CURRENT_LIST_DIR}/tl_renderer_sky.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_renderer_timers.c
  ${CMAKE_CURRENT_LIST_DIR}/tl_renderer_probe.c)
