# The headless GL layer, and the desktop window (GLFW) apart from it: a
# program that renders headless does not link the window system.
tl_module(gl
  SOURCES tl_gl_context.c tl_renderer.c tl_renderer_prepass.c tl_renderer_display.c
          tl_renderer_sky.c tl_renderer_timers.c tl_renderer_probe.c tl_renderer_boat.c
          tl_renderer_target.c tl_renderer_overlay.c
  DEPS color core image mesh optics prepare shader sky waves EXTERNAL PkgConfig::EPOXY PkgConfig::EGL)
tl_module(gl_window SOURCES tl_gl_window.c DEPS core EXTERNAL PkgConfig::EPOXY PkgConfig::GLFW)
