# Shaders live as files in shaders/ and are embedded into the binary at
# build time (tideline still runs from anywhere); --shader-dir loads them
# from disk instead, for editing without rebuilding.
file(GLOB TL_SHADER_FILES CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/shaders/*.glsl
  ${PROJECT_SOURCE_DIR}/shaders/*.frag
  ${PROJECT_SOURCE_DIR}/shaders/*.vert)
set(TL_EMBEDDED_SHADERS_C ${PROJECT_BINARY_DIR}/generated/tl_shaders_embedded.c)
add_custom_command(
  OUTPUT ${TL_EMBEDDED_SHADERS_C}
  COMMAND ${CMAKE_COMMAND} -DOUT=${TL_EMBEDDED_SHADERS_C} "-DFILES=${TL_SHADER_FILES}"
          -P ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
  DEPENDS ${TL_SHADER_FILES} ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
  COMMENT "Embedding shaders"
  VERBATIM)
