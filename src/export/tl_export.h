/* tl_export: a timeline's animation for a 3D package, so that elements
 * made there match the shot: the camera (its pose every frame and its
 * lens), the sun (a directional light along its rays) and each floating
 * object's pose, as a glTF 2.0 scene (`tideline export-camera`). */
#ifndef TL_EXPORT_H
#define TL_EXPORT_H

#include "core/tl_error.h"
#include "timeline/tl_timeline.h"

/* Writes frames 0 .. tl_timeline_frame_count - 1 of `tl` to `path`
 * (.gltf: JSON with the data embedded; .glb: binary), atomically: a key
 * per frame at its time (frame / fps) for each node. */
int tl_export_camera(const tl_timeline *tl, const char *path, tl_error *err);
/* The most frames an export holds (a day at 24 fps, well inside the
 * float key times' resolution of a frame). */
#define TL_EXPORT_MAX_FRAMES 2073600
/* Checks `path`'s extension (.gltf or .glb) before any work: a usage
 * error naming it otherwise. */
int tl_export_check_path(const char *path, tl_error *err);

/* tideline's world is x east, y up, z north: left-handed. glTF's is
 * right-handed with y up, so a point (x, y, z) goes to (x, y, -z) there
 * (north is glTF's -z: Blender, which turns glTF's y up into its z up,
 * shows north as its +y). */
void tl_export_point(const double world[3], double gltf[3]);

/* One node of the glTF scene, its animation sampled per frame. */
enum { TL_GLTF_EMPTY, TL_GLTF_CAMERA, TL_GLTF_SUN };
typedef struct tl_gltf_node {
    const char *name;
    int kind;
    double yfov, aspect;      /* TL_GLTF_CAMERA: the lens at frame 0 */
    const float *translation; /* frames x 3, glTF's axes */
    const float *rotation;    /* frames x 4: unit quaternions (x y z w) */
    const float *yfov_keys;   /* TL_GLTF_CAMERA: frames (the lens per frame, as extras) */
} tl_gltf_node;

/* The glTF writer (tl_gltf.cpp, on tinygltf): `count` nodes animated over
 * `frames` frames at `fps`, into the bytes of a .gltf (binary: .glb);
 * *out is malloc'd. 0 on success, else -1 with a reason in `why`. */
int tl_gltf_encode(const tl_gltf_node *nodes, int count, int frames, double fps, int binary,
                   unsigned char **out, size_t *size, char *why, size_t why_size);

#endif
