/* tl_image_io: writing (and, for tests and resume, reading) frame files.
 *
 * EXR: linear scene-referred half RGBA plus a 32-bit float Z channel
 *      (distance along the view ray), ZIP compression, through OpenEXR's
 *      C API (OpenEXRCore). Metadata entries become header attributes.
 * PNG: the frame's tonemapped `display` plane, 8- or 16-bit sRGB (libpng).
 *
 * Every write is atomic: the bytes go to a temporary file in the target's
 * folder, which is flushed, fsync'd and renamed over the target only when
 * complete. On any failure the temporary file is removed and an existing
 * target is left untouched. */
#ifndef TL_IMAGE_IO_H
#define TL_IMAGE_IO_H

#include <stdbool.h>

#include "core/tl_error.h"
#include "image/tl_frame.h"

typedef enum tl_image_format {
    TL_IMAGE_UNKNOWN = 0,
    TL_IMAGE_EXR,
    TL_IMAGE_PNG,
} tl_image_format;

typedef enum tl_meta_type {
    TL_META_STRING,
    TL_META_DOUBLE,
    TL_META_INT,
    TL_META_FLOAT,          /* d, stored as a 32-bit float */
    TL_META_M44F,           /* v[16], row-major as Imath's M44f (v * M) */
    TL_META_V3D,            /* v[3] */
    TL_META_CHROMATICITIES, /* v[8]: red, green, blue, white x y */
    TL_META_RATIONAL,       /* v[2]: numerator, denominator (integers) */
} tl_meta_type;

/* How many values `v` holds for a type (0 for the scalar ones). */
int tl_meta_values(tl_meta_type type);

/* One EXR header attribute. PNG writes strings as tEXt chunks, numbers
 * printed with %.17g (several separated by spaces). */
typedef struct tl_meta {
    const char *name; /* e.g. "tideline/frame" */
    tl_meta_type type;
    const char *s;
    double d;
    int i;
    const double *v; /* the values of the types that hold several */
} tl_meta;

/* zlib level of PNGs when the options leave it 0: fast. Level 1 encodes
 * a 640x360 ocean frame several times faster than zlib's default 6, for
 * files about a tenth larger. */
#define TL_PNG_COMPRESSION_DEFAULT 1

/* zlib level of EXR's ZIP chunks when the options leave it 0. OpenEXR's
 * own default, 6, takes about twice as long as 4 for files barely
 * smaller; 1 is a little faster than 4 for files a tenth larger
 * (docs/rendering.md). */
#define TL_EXR_COMPRESSION_DEFAULT 4

typedef struct tl_image_options {
    int png_bits;        /* 8 (default when 0) or 16 */
    int no_dither;       /* 8-bit PNG rounded to nearest (default: dithered) */
    int png_compression; /* zlib level 1..9; 0: TL_PNG_COMPRESSION_DEFAULT */
    int exr_compression; /* zlib level 1..9; 0: TL_EXR_COMPRESSION_DEFAULT */
    const tl_meta *meta; /* may be NULL */
    int meta_count;
} tl_image_options;

/* Format from the path's extension (case-insensitive .exr / .png). */
tl_image_format tl_image_format_from_path(const char *path);

/* Checks, before any rendering, that `path` could be written: a known
 * extension, an existing folder that we may create files in, and not a
 * folder itself. The message names the path. */
int tl_image_check_writable(const char *path, tl_error *err);

/* Checks opt's metadata entries (a name of 1..255 bytes, a known type, a
 * string value for strings); the writers call it before creating a file.
 * The message names the path. */
int tl_image_check_meta(const char *path, const tl_image_options *opt, tl_error *err);

/* Writes frame to path atomically, in the format of path's extension. */
int tl_image_write(const char *path, const tl_frame *frame, const tl_image_options *opt,
                   tl_error *err);

int tl_exr_write(const char *path, const tl_frame *frame, const tl_image_options *opt,
                 tl_error *err);

/* One channel of an EXR written by tl_exr_write_channels: its full name
 * ("ViewLayer.Combined.R"), stored as half or 32-bit float, from `data`:
 * the top-left pixel's value, `stride` floats from one pixel to the next,
 * rows one after another. Halves are saturated as tl_exr_write's colour
 * (NaN 0, beyond the half range its largest finite value). */
typedef struct tl_exr_channel {
    const char *name;
    int half;
    const float *data;
    int stride;
} tl_exr_channel;

/* Writes any set of channels (1 .. TL_EXR_CHANNELS_MAX, distinct names)
 * of width x height atomically, with opt's compression and metadata. */
#define TL_EXR_CHANNELS_MAX 256
int tl_exr_write_channels(const char *path, int width, int height, const tl_exr_channel *channels,
                          int count, const tl_image_options *opt, tl_error *err);
int tl_png_write(const char *path, const tl_frame *frame, const tl_image_options *opt,
                 tl_error *err);

/* Reads an EXR written by tl_exr_write into a freshly allocated frame
 * (color and depth filled; display left zero). Any scanline EXR with
 * R,G,B[,A] (half or float) and optional Z is accepted, or the same as
 * Blender's multilayer names them (ViewLayer.Combined.R .. A,
 * ViewLayer.Depth.Z: tideline's frames with passes, whose depth is planar,
 * along the camera's axis). */
int tl_exr_read(const char *path, tl_frame *frame, tl_error *err);

/* Reads channel `name` of an EXR (half or float) into a freshly
 * malloc'd *out of *width x *height floats, rows top first (tests, and a
 * compositor's view of the passes). */
int tl_exr_read_channel(const char *path, const char *name, int *width, int *height, float **out,
                        tl_error *err);

/* Reads one string/double/int attribute from an EXR header (tests). */
int tl_exr_read_attr_string(const char *path, const char *name, char *out, int out_size,
                            tl_error *err);
int tl_exr_read_attr_double(const char *path, const char *name, double *out, tl_error *err);

/* Reads a PNG (8- or 16-bit RGB/RGBA) into frame->display as values in
 * [0,1]; *bits_out (may be NULL) receives the bit depth. */
int tl_png_read(const char *path, tl_frame *frame, int *bits_out, tl_error *err);

#endif
