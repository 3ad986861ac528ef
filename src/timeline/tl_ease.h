/* tl_ease: Robert Penner's easing functions on a normalised parameter.
 *
 * Each function maps u in [0,1] to a progress value with f(0) = 0 and
 * f(1) = 1; back and elastic overshoot outside [0,1] in between. u outside
 * [0,1] is clamped. Definitions are Blender's BLI_easing (Penner's
 * equations; back overshoot 1.70158, 1.525x for in-out; expo rescaled by
 * 1 / (1 - 2^-10) so it is continuous at both ends). tl_ease is the
 * normalised curve: elastic with amplitude = the change and period 0.3 of
 * the duration (0.45 for in-out). tl_ease_segment takes Blender's per-key
 * back, amplitude and period in absolute units, as F-curve keys hold them. */
#ifndef TL_EASE_H
#define TL_EASE_H

#include <stdbool.h>

#define TL_EASE_BACK_OVERSHOOT        1.70158
#define TL_EASE_ELASTIC_PERIOD        0.3 /* fraction of the duration, in and out */
#define TL_EASE_ELASTIC_PERIOD_IN_OUT 0.45
/* What Blender gives an inserted key (keyframing's defaults): amplitude in
 * value units, period in frames. */
#define TL_EASE_BLENDER_AMPLITUDE     0.8
#define TL_EASE_BLENDER_PERIOD_FRAMES 4.1

typedef enum tl_ease_family {
    TL_EASE_SINE,
    TL_EASE_QUAD,
    TL_EASE_CUBIC,
    TL_EASE_QUART,
    TL_EASE_QUINT,
    TL_EASE_EXPO,
    TL_EASE_CIRC,
    TL_EASE_BACK,
    TL_EASE_BOUNCE,
    TL_EASE_ELASTIC,
    TL_EASE_FAMILY_COUNT
} tl_ease_family;

typedef enum tl_ease_dir { TL_EASE_IN, TL_EASE_OUT, TL_EASE_IN_OUT, TL_EASE_DIR_COUNT } tl_ease_dir;

/* Eased progress at u. An out-of-range family or direction gives u. */
double tl_ease(tl_ease_family family, tl_ease_dir dir, double u);

/* Blender's per-key easing settings (BezTriple back, amplitude, period). */
typedef struct tl_ease_params {
    double back;      /* back's overshoot; 0 overshoots nothing (a cubic) */
    double amplitude; /* elastic, value units; below |change| (or 0) Blender scales the wave
                         down by amplitude / |change|, blending to full size at the end */
    double period;    /* elastic, in the duration's time unit; 0: 0.3 of it (0.45 in-out) */
} tl_ease_params;

/* Blender's F-curve easing of a segment: the value minus the segment's
 * start at fraction u of it, for a segment of the given change and duration
 * (any time unit, the period's). NULL params: the normalised tl_ease. */
double tl_ease_segment(tl_ease_family family, tl_ease_dir dir, const tl_ease_params *params,
                       double u, double change, double duration);

/* Parses "ease-in-sine", "ease-out-bounce", "ease-in-out-elastic", ...
 * Returns false (outputs untouched) for an unknown name. */
bool tl_ease_from_name(const char *name, tl_ease_family *family, tl_ease_dir *dir);

/* The canonical name ("ease-in-out-sine"), or NULL when out of range. */
const char *tl_ease_name(tl_ease_family family, tl_ease_dir dir);
/* How many names tl_ease_name gives. */
#define TL_EASE_NAME_COUNT (TL_EASE_FAMILY_COUNT * TL_EASE_DIR_COUNT)

/* "sine", "quad", ...; NULL when out of range. */
const char *tl_ease_family_name(tl_ease_family family);

#endif
