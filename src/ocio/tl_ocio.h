/* tl_ocio: OpenColorIO behind a C interface (tl_ocio.cpp, C++): the
 * working space's matrix and the display transforms of a config, a
 * studio's (--ocio, $OCIO) or tideline's own (src/ocio/tideline.ocio,
 * built in). */
#ifndef TL_OCIO_H
#define TL_OCIO_H

#include "color/tl_color.h"
#include "core/tl_error.h"

/* The 3x3 matrix (row-major, rows give the outputs) that takes linear
 * Rec.709 to `space`, as OpenColorIO's built-in ACES transforms give it
 * through tideline's own config (a linear conversion: exact). */
int tl_ocio_working_matrix(tl_working_space space, double m[9], tl_error *err);

/* A display transform: tideline's radiance (linear Rec.709) to a
 * display's code values through a config's display and view. */
typedef struct tl_ocio_display tl_ocio_display;
/* `config`: a config file, or NULL for $OCIO when set, else the built-in
 * one; `display`, `view`: NULL for the config's defaults. Errors (usage,
 * 2) name the config, display or view and list the ones it has. */
int tl_ocio_display_open(const char *config, const char *display, const char *view,
                         tl_ocio_display **out, tl_error *err);
void tl_ocio_display_close(tl_ocio_display *d);
/* "CONFIG: DISPLAY / VIEW", for logs and metadata. */
const char *tl_ocio_display_describe(const tl_ocio_display *d);
/* The transform baked over tl_color.h's shaper into n^3 RGB values. */
int tl_ocio_display_bake(const tl_ocio_display *d, int n, float *rgb, tl_error *err);
/* The transform of one linear Rec.709 value, exactly (the tests'
 * reference for the table); non-finite outputs become 0. */
void tl_ocio_display_apply(const tl_ocio_display *d, const float in[3], float out[3]);

#endif
