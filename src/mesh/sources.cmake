tl_module(mesh SOURCES tl_mesh.c tl_mesh_boat.c tl_mesh_maps.c tl_mesh_occlusion.c tl_mesh_shading.c tl_mesh_soup.c DEPS core EXTERNAL PkgConfig::ASSIMP PkgConfig::STB)
