# The shaders are embedded into the library (cmake/embed.cmake).
tl_module(shader SOURCES tl_shader_lib.c ${TL_EMBEDDED_SHADERS_C} DEPS core)
