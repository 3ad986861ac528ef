/* tl_passes: the compositing passes of an EXR frame. Which passes a render
 * writes (their names, as `--passes` and the timeline's `passes` line take
 * them), the camera's standard attributes every EXR carries, and the
 * multilayer EXR itself, laid out as Blender 3.4 writes and reads one
 * (ViewLayer.Combined.R, ViewLayer.Depth.Z, ViewLayer.Normal.X, ...,
 * ViewLayer.CryptoObject00.r, ...). docs/compositing.md documents each. */
#ifndef TL_PASSES_H
#define TL_PASSES_H

#include <stddef.h>
#include <stdint.h>

#include "color/tl_color.h"
#include "core/tl_error.h"
#include "image/tl_frame.h"
#include "image/tl_image_io.h"
#include "scene/tl_scene.h"

/* The passes, one bit each. Combined (the radiance) is in every file with
 * passes; asking for it alone gives the multilayer layout with nothing
 * else. */
enum {
    TL_PASSES_COMBINED = 1u << 0,
    TL_PASSES_DEPTH = 1u << 1,
    TL_PASSES_NORMAL = 1u << 2,
    TL_PASSES_POSITION = 1u << 3,
    TL_PASSES_MASK_WATER = 1u << 4,
    TL_PASSES_MASK_FOAM = 1u << 5,
    TL_PASSES_MASK_GIANT = 1u << 6,
    TL_PASSES_MASK_BOAT = 1u << 7,
    TL_PASSES_MASK_SKY = 1u << 8,
    TL_PASSES_MASK_UNDERWATER = 1u << 9,
    TL_PASSES_CRYPTOMATTE = 1u << 10,
    TL_PASSES_VECTOR = 1u << 11,
    /* The light layers, tl_light_layer k as bit TL_PASSES_LIGHT0 + k. */
    TL_PASSES_LIGHT0 = 12,
    TL_PASSES_LIGHT_SKY = 1u << 12,
    TL_PASSES_LIGHT_REFLECTION = 1u << 13,
    TL_PASSES_LIGHT_BODY = 1u << 14,
    TL_PASSES_LIGHT_GLITTER = 1u << 15,
    TL_PASSES_LIGHT_FOAM = 1u << 16,
    TL_PASSES_LIGHT_SPRAY = 1u << 17,
    TL_PASSES_LIGHT_BOAT = 1u << 18,
    TL_PASSES_LIGHT_GLARE = 1u << 19,
    TL_PASSES_CRYPTO_MATERIAL = 1u << 20,
};
#define TL_PASSES_MASKS                                                                            \
    (TL_PASSES_MASK_WATER | TL_PASSES_MASK_FOAM | TL_PASSES_MASK_GIANT | TL_PASSES_MASK_BOAT |     \
     TL_PASSES_MASK_SKY | TL_PASSES_MASK_UNDERWATER)
#define TL_PASSES_LIGHTS (((1u << TL_FRAME_LAYERS) - 1u) << TL_PASSES_LIGHT0)
#define TL_PASSES_ALL    ((1u << 21) - 1u)
/* Room for every pass's name in a list (tl_passes_format). */
#define TL_PASSES_NAMES_SIZE 512

/* Parses a list of pass names separated by commas ("depth,normal", "all",
 * "masks" for every mask) into *passes, with TL_PASSES_COMBINED; "none"
 * alone gives 0 (the plain RGBA + Z file). 0 on success; -1 on an unknown
 * or empty name (or "none" in a list), whose offset and length in `list`
 * go to *bad_at and *bad_len. */
int tl_passes_parse(const char *list, unsigned *passes, size_t *bad_at, size_t *bad_len);
/* The valid names, for messages: "combined, depth, ..., all". */
const char *tl_passes_valid_names(void);
/* The same as a NULL-terminated list (for "did you mean"). */
const char *const *tl_passes_name_list(void);
/* The names of the passes in `passes`, separated by commas, into out. */
void tl_passes_format(unsigned passes, char *out, size_t size);
/* Whether the passes need the renderer's per-sample data (tl_frame's aov
 * plane): normal, masks, Cryptomatte, vector (which surface each pixel
 * shows). Depth and position need only the distance plane. */
int tl_passes_need_aov(unsigned passes);
/* The light layers the passes ask for, bit k for tl_light_layer k (each
 * shaded one costs the frame drawn again: tl_render_frame_layers). */
unsigned tl_passes_light_layers(unsigned passes);

/* ---- Cryptomatte (Psyop's specification 1.1) ---- */

/* MurmurHash3's 32-bit variant (x86_32) of `len` bytes, seed 0. */
uint32_t tl_crypto_murmur3(const void *data, size_t len, uint32_t seed);
/* A name's ID: its hash with the exponent held in 1..254 (no NaN, Inf or
 * denormal), as the float the pixels hold; *bits gets its bit pattern (the
 * manifest's eight hex digits). */
float tl_crypto_id(const char *name, uint32_t *bits);
/* The metadata key of a Cryptomatte layer: the first seven hex digits of
 * its name's hash ("ViewLayer.CryptoObject" -> "542cafa"). */
void tl_crypto_key(const char *layer, char out[8]);
/* The ranks each pixel keeps: three layers of two (ID, coverage) pairs. */
#define TL_CRYPTO_RANKS 6
/* The material of a floating object drawn with the model at `model` (a
 * path; "" for the built-in boat): the file's name ("trawler.glb"), or
 * "builtin_boat". Objects that share a model share it. */
const char *tl_crypto_material_name(const char *model);

/* ---- the camera's attributes ---- */

/* The sensor a lens is given for its focal length: a full-frame film
 * back's width (Blender's default sensor, fitted to the width). */
#define TL_PASSES_SENSOR_WIDTH_MM 36.0

/* Imath's row-vector matrices (p * M) for OpenEXR's standard attributes:
 * world -> camera (x right, y up, z along the view: OpenEXR's left-handed
 * camera space) and world -> NDC ((0, 0) the top-left corner of the
 * image, (1, 1) the bottom-right, after the division by w). */
void tl_passes_world_to_camera(const tl_camera *camera, double m[16]);
void tl_passes_world_to_ndc(const tl_camera *camera, int width, int height, double m[16]);
/* The view ray through the centre of pixel (x, y), rows top first: as
 * shaders/ocean.frag's camera_ray, world axes, unit length. */
void tl_passes_pixel_ray(const tl_camera *camera, int width, int height, int x, int y,
                         double ray[3]);

/* Storage for a frame's camera attributes (tl_passes_camera_meta). */
#define TL_PASSES_CAMERA_META 10
typedef struct tl_passes_meta {
    double world_to_camera[16], world_to_ndc[16];
    double chromaticities[8];
    double fps[2];
    double origin[3];
    tl_meta meta[TL_PASSES_CAMERA_META];
} tl_passes_meta;
/* Fills m with the attributes every EXR frame carries: worldToCamera,
 * worldToNDC, chromaticities (the working space's), framesPerSecond (when
 * fps > 0), the lens (focal length and sensor in mm, the horizontal and
 * vertical field of view in degrees) and the origin of the Position
 * pass (the camera's position in double). Returns how many (in m->meta). */
int tl_passes_camera_meta(const tl_camera *camera, int width, int height, double fps,
                          tl_working_space space, tl_passes_meta *m);

/* ---- the file ---- */

/* What the multilayer file needs besides the frame. */
typedef struct tl_passes_frame {
    unsigned passes;           /* TL_PASSES_* (TL_PASSES_COMBINED always) */
    const tl_camera *camera;   /* the frame's camera (positions, rays) */
    const char *const *object; /* the floating objects' names by scene index, NULL past them */
    int objects;
    double fps; /* the timeline's frames per second (framesPerSecond; 0: none) */
    /* The Vector pass: the frame's scene, and the scenes one frame before
     * and after it (NULL: no motion that way, as across a cut). */
    const tl_scene *scene, *prev, *next;
    /* The colour's working space, and the matrix (row-major 3x3) from the
     * frame's linear Rec.709 to it (src/ocio gives it); NULL: as rendered. */
    tl_working_space space;
    const double *working;
    /* The floating objects' model paths by scene index ("" or NULL: the
     * built-in boat), for the material Cryptomatte; NULL: all built-in. */
    const char *const *model;
} tl_passes_frame;

/* The Vector pass of `frame` (Blender's layout, 4 floats a pixel, rows top
 * first, in pixels with y up): x y the move to where the point a pixel
 * shows was a frame before, z w from where it will be a frame after. A
 * point moves with what it lies on: the sky with the camera's turn alone,
 * a hull with its object, the giant wave with its crest's travel, the
 * ocean up and down with its waves. Needs the aov plane (which surface a
 * pixel shows). */
void tl_passes_vectors(const tl_frame *frame, const tl_passes_frame *info, float *out);

/* Writes `frame` (its colour and depth, and its aov plane for the passes
 * that need it) as a multilayer EXR with the passes in info, atomically,
 * with opt's compression and metadata plus the Cryptomatte's. */
int tl_passes_write_exr(const char *path, const tl_frame *frame, const tl_passes_frame *info,
                        const tl_image_options *opt, tl_error *err);
/* An EXR frame as tideline writes every one: opt's metadata plus the
 * camera's (tl_passes_camera_meta), as the plain RGBA + Z file when
 * info->passes is 0, else the multilayer file (with a tideline/passes
 * attribute naming its passes). */
int tl_passes_write_frame(const char *path, const tl_frame *frame, const tl_passes_frame *info,
                          const tl_image_options *opt, tl_error *err);

#endif
