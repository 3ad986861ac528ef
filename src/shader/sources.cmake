# The shaders are embedded into the library (cmake/embed.cmake).
# The frame uniforms' GLSL declarations come from prepare's table.
tl_module(shader SOURCES tl_shader_lib.c ${TL_EMBEDDED_SHADERS_C} DEPS core prepare)
