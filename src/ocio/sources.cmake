# OpenColorIO (C++ behind a C interface); its built-in config
# (tideline.ocio) is compiled in as text.
tl_module(ocio SOURCES tl_ocio.cpp DEPS color core EXTERNAL PkgConfig::OCIO)
set(tl_ocio_config ${CMAKE_CURRENT_LIST_DIR}/tideline.ocio)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${tl_ocio_config})
file(READ ${tl_ocio_config} tl_ocio_hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," tl_ocio_bytes "${tl_ocio_hex}")
file(WRITE ${PROJECT_BINARY_DIR}/generated/ocio/tl_ocio_config.h
  "/* Generated from src/ocio/tideline.ocio by src/ocio/sources.cmake: do not edit. */\n"
  "static const char tl_ocio_builtin_config[] = {${tl_ocio_bytes}0x00};\n")
target_include_directories(tl_ocio PRIVATE ${PROJECT_BINARY_DIR}/generated/ocio)
