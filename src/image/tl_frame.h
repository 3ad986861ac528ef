/* tl_frame: one rendered frame in CPU memory.
 *
 * Rows are stored top row first (image order, as EXR and PNG want them);
 * the renderer's display pass writes its planes that way up, so the
 * readback needs no flip. */
#ifndef TL_FRAME_H
#define TL_FRAME_H

#include "core/tl_error.h"

/* Depth written where a view ray hits nothing (sky): a large finite
 * distance in metres, so that no Inf ever reaches a file. */
#define TL_FRAME_SKY_DEPTH 1.0e10f

/* The planes of a frame, for reading back only what the outputs need. */
enum {
    TL_PLANE_COLOR = 1u << 0,   /* EXR */
    TL_PLANE_DEPTH = 1u << 1,   /* EXR */
    TL_PLANE_DISPLAY = 1u << 2, /* PNG, movies, metrics */
    TL_PLANES_ALL = 7u,
    /* The compositing passes' data (EXR with --passes): read back only
     * into a frame with an `aov` plane, and never part of TL_PLANES_ALL. */
    TL_PLANE_AOV = 1u << 3,
};

/* The light layers a compositor grades apart. The first TL_LIGHT_SHADED
 * are the scene's own light, split where it is emitted (shaders/layers.glsl
 * tags each source): they add up to the frame's colour. The glare is the
 * display's: the display image is colour * (1 - bloom) + glare. */
typedef enum tl_light_layer {
    TL_LIGHT_SKY,        /* the sky seen directly (through Snell's window too), the fog's haze */
    TL_LIGHT_REFLECTION, /* the sky and the hulls mirrored by the water */
    TL_LIGHT_BODY,       /* the light the water body scatters: the sea's colour, the light
                          * through the crest and the lip, under water its haze, shafts and
                          * motes, the sea floor */
    TL_LIGHT_GLITTER,    /* the sun mirrored by the waves */
    TL_LIGHT_FOAM,       /* foam, whitewater and the bubbles under them */
    TL_LIGHT_SPRAY,      /* the giant wave's spray and the bows' bursts */
    TL_LIGHT_BOAT,       /* the floating objects' surfaces */
    TL_LIGHT_GLARE,      /* the display's glare (render.bloom) */
    TL_FRAME_LAYERS
} tl_light_layer;
#define TL_LIGHT_SHADED TL_LIGHT_GLARE
/* A layer's name: "sky", "reflection", ..., "glare" (its pass is
 * light_<name>, its shader constant TL_LIGHT_<NAME>). */
const char *tl_light_layer_name(int layer);

/* The `aov` plane: per pixel, the mean over the pixel's samples of what
 * each saw, TL_FRAME_AOV_FLOATS values (src/passes turns them into an
 * EXR's layers). They come in groups of four, each a plane of its own
 * (value c of group g at aov[((size_t)g * width * height + pixel) * 4 + c],
 * rows top first), in this order:
 *   0-2  the normal of the surface hit, world axes, facing the eye (0 for
 *        the sky), 3 the foam's cover there;
 *   4-7  the share of samples that saw the sky, the ocean, the giant wave,
 *        and that were under the water;
 *   8-   the share that saw each floating object, by its index in the
 *        scene (TL_FRAME_AOV_OBJECTS of them: the scene's most). */
#define TL_FRAME_AOV_OBJECTS 16
#define TL_FRAME_AOV_OBJECT0 8
#define TL_FRAME_AOV_FLOATS  (TL_FRAME_AOV_OBJECT0 + TL_FRAME_AOV_OBJECTS)

typedef struct tl_frame {
    int width, height;
    float *color;   /* width*height*4: linear scene-referred RGBA */
    float *depth;   /* width*height: distance along the view ray, metres */
    float *display; /* width*height*4: tonemapped, sRGB-encoded RGBA in [0,1] */
    float *aov;     /* width*height*TL_FRAME_AOV_FLOATS, or NULL (tl_frame_alloc_aov) */
    /* width*height*3: light layer k's linear RGB, rows top first, or NULL
     * where not asked for (tl_frame_alloc_layers) */
    float *layer[TL_FRAME_LAYERS];
} tl_frame;

/* Allocates all three planes, zero-filled. */
int tl_frame_alloc(tl_frame *frame, int width, int height, tl_error *err);
void tl_frame_free(tl_frame *frame);
/* Adds the `aov` plane, zero-filled, to an allocated frame (nothing when
 * it has one). */
int tl_frame_alloc_aov(tl_frame *frame, tl_error *err);
/* Adds the planes of the light layers in `layers` (bit k: layer k),
 * zero-filled, to an allocated frame (those it has stay). */
int tl_frame_alloc_layers(tl_frame *frame, unsigned layers, tl_error *err);
/* The layers a frame has planes for, bit k for layer k. */
unsigned tl_frame_layers(const tl_frame *frame);

/* Row y of the display plane as 8-bit RGB codes (3 bytes a pixel), for
 * 8-bit PNGs and movies. Dithered, so that a smooth sky does not band into
 * steps of one code: a value between two codes takes the lower or the
 * upper as a fixed noise per pixel and channel decides (every frame and
 * run gets the same), the nearer the more often, so that on average it is
 * the value it stands for. A value on a code stays exact; below 0 and NaN
 * give 0, above 1 gives 255. `dither` 0: rounded to the nearest code. */
void tl_frame_display_row8(const tl_frame *frame, int y, int dither, unsigned char *rgb);

#endif
