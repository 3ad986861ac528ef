tl_module(mesh SOURCES tl_mesh.c tl_mesh_boat.c DEPS core EXTERNAL PkgConfig::ASSIMP)
