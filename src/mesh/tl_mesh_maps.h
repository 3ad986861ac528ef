/* tl_mesh_maps (private to mesh/): a loaded model's materials' texture
 * maps and their factors, through assimp's C API, the images decoded by
 * stb_image (PNG and JPEG), embedded or beside the model. */
#ifndef TL_MESH_MAPS_H
#define TL_MESH_MAPS_H

#include <assimp/scene.h>

#include "tl_mesh.h"

/* The images decoded so far and what they were read from, so that a map
 * shared by several materials is decoded once. */
typedef struct tl_mesh_map_cache {
    char **keys; /* parallel to mesh->images */
} tl_mesh_map_cache;

/* Fills `part`'s maps (indices into mesh->images, decoding those not seen
 * yet) and factors from material `index` of `scene`. `model` is the
 * model's path: external images are found beside it, and errors name it,
 * the material and the image. */
int tl_mesh_read_maps(const struct aiScene *scene, unsigned index, const char *model, tl_mesh *mesh,
                      tl_mesh_map_cache *cache, tl_mesh_part *part, tl_error *err);

void tl_mesh_map_cache_free(tl_mesh_map_cache *cache, size_t count);

#endif
