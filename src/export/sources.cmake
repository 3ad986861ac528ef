# A timeline's camera, sun and floating objects for a 3D package (glTF).
# Its one C++ file wraps tinygltf behind a C interface.
tl_module(export SOURCES tl_export.c tl_gltf.cpp DEPS core image timeline
  EXTERNAL TinyGLTF::TinyGLTF)
