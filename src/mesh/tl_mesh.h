/* tl_mesh: triangle meshes on the CPU: the boat the author brings (glTF
 * or OBJ through assimp's C API) or the one tideline builds itself.
 *
 * Conventions (model space): metres, +Y up, the bow toward +Z, the design
 * waterline at y = 0 (the floating pose puts it on the water). A model
 * authored otherwise is turned and scaled by boat.model_yaw and
 * boat.model_scale at render time. Colours are linear RGB. */
#ifndef TL_MESH_H
#define TL_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "core/tl_error.h"

typedef struct tl_mesh {
    size_t vertex_count;
    size_t index_count; /* three per triangle */
    float *positions;   /* x y z per vertex */
    float *normals;     /* unit x y z per vertex */
    float *colors;      /* linear r g b per vertex: the material's base colour */
    uint32_t *indices;
    float bounds_min[3], bounds_max[3];
} tl_mesh;

/* Loads every triangle of a glTF 2.0 (.glb, .gltf) or Wavefront OBJ file,
 * its node transforms applied, with smooth normals where the file has
 * none. A missing, empty or unreadable file, a folder, another format, a
 * file assimp cannot parse and one without triangles each fail with a
 * one-line message naming the file (TL_ERR_USAGE). */
int tl_mesh_load(const char *path, tl_mesh *out, tl_error *err);

/* The built-in fishing boat (hull, deck, wheelhouse, mast; about a
 * thousand triangles), one metre long: scale it by the hull length. */
int tl_mesh_default_boat(tl_mesh *out, tl_error *err);

void tl_mesh_free(tl_mesh *m);

/* A mesh under construction: vertices and triangles appended, arrays grown
 * as needed. tl_mesh_builder_finish computes the bounds. */
typedef struct tl_mesh_builder {
    tl_mesh mesh;
    size_t vertex_capacity, index_capacity;
    int failed; /* out of memory: every later call does nothing */
} tl_mesh_builder;

uint32_t tl_mesh_add_vertex(tl_mesh_builder *b, const float p[3], const float n[3],
                            const float rgb[3]);
void tl_mesh_add_triangle(tl_mesh_builder *b, uint32_t i0, uint32_t i1, uint32_t i2);
int tl_mesh_builder_finish(tl_mesh_builder *b, tl_mesh *out, tl_error *err);

#endif
