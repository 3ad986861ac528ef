/* tl_curve: a scalar keyed animation channel (vectors are several curves).
 *
 * Keys are appended in time order, then tl_curve_validate checks them and
 * tl_curve_prepare computes Bezier handles and spline tangents once;
 * tl_curve_eval is then a pure function of time. Bezier keys follow
 * Blender's F-curve rules (handle calculation, handle correction,
 * extrapolation); docs/curves.md describes the model. */
#ifndef TL_CURVE_H
#define TL_CURVE_H

#include <stdbool.h>
#include <stddef.h>

#include "core/tl_error.h"
#include "timeline/tl_ease.h"

/* Interpolation of the segment that FOLLOWS a key. */
typedef enum tl_interp {
    TL_INTERP_CONSTANT, /* step: hold this key's value */
    TL_INTERP_LINEAR,
    TL_INTERP_BEZIER,   /* cubic Bezier through this key's right and the next key's left handle */
    TL_INTERP_EASE,     /* tl_ease(ease_family, ease_dir) between the two values */
    TL_INTERP_SPLINE,   /* C1 cubic Hermite with three-point (Bessel) tangents in time */
    TL_INTERP_COUNT
} tl_interp;

/* Bezier handle types, Blender's names. Auto-clamped is the default (0). */
typedef enum tl_handle_type {
    TL_HANDLE_AUTO_CLAMPED, /* auto, but flat at extremes and never past the neighbours */
    TL_HANDLE_AUTO,         /* smooth, from the neighbouring keys */
    TL_HANDLE_VECTOR,       /* points at the neighbouring key, 1/3 of the way */
    TL_HANDLE_ALIGNED,      /* user position, kept opposite to the other handle */
    TL_HANDLE_FREE,         /* user position, untouched */
    TL_HANDLE_COUNT
} tl_handle_type;

/* What the curve does before its first and after its last key. */
typedef enum tl_extrap {
    TL_EXTRAP_CONSTANT,     /* hold the end values (default) */
    TL_EXTRAP_LINEAR,       /* continue with the end slope */
    TL_EXTRAP_CYCLE,        /* repeat [first, last] */
    TL_EXTRAP_CYCLE_OFFSET, /* repeat, each cycle shifted by last - first value */
    TL_EXTRAP_PINGPONG,     /* repeat forwards, backwards, forwards, ... */
    TL_EXTRAP_COUNT
} tl_extrap;

/* Auto-handle smoothing (Blender's F-curve setting). */
typedef enum tl_smoothing {
    TL_SMOOTH_NONE,       /* each key's handles from its neighbours alone (default) */
    TL_SMOOTH_CONTINUOUS, /* "Continuous Acceleration": C2 through runs of auto keys */
    TL_SMOOTH_COUNT
} tl_smoothing;

/* A 2-D point in (time, value) space: a Bezier handle. */
typedef struct tl_curve_point {
    double t, v;
} tl_curve_point;

typedef struct tl_key {
    double t, v;               /* time in seconds, value */
    tl_interp interp;          /* of the segment from this key to the next */
    tl_ease_family ease_family; /* for TL_INTERP_EASE */
    tl_ease_dir ease_dir;
    tl_handle_type left_type, right_type;
    /* Absolute (time, value) handle positions. Inputs for free/aligned
     * handles; tl_curve_prepare computes the others (and aligns). */
    tl_curve_point left, right;
    bool cut;                  /* the channel jumps here; nothing interpolates across */
    /* Back's overshoot, elastic's amplitude (value units) and period in
     * FRAMES (Blender's unit, converted with the curve's fps; 0: 0.3 of the
     * segment), for the ease segment after this key. */
    tl_ease_params ease;
    double slope;              /* computed: spline tangent dv/dt at this key */
    bool locked;               /* computed: auto handles held flat (an extreme or an eased
                                  end; Blender's "locked"), which smoothing leaves alone */
} tl_key;

typedef struct tl_curve {
    tl_key *keys; /* owned, time order */
    size_t count, capacity;
    /* Before the first and after the last key (tl_curve_set_extrap sets
     * both). The cyclic modes repeat `cycles` times, 0 = forever, and then
     * hold the end key's value (Blender's Cycles modifier). */
    tl_extrap before, after;
    unsigned before_cycles, after_cycles;
    tl_smoothing smoothing;
    /* Frames per second: Blender measures aligned handle lengths (and the
     * default length of a missing handle) in (frame, value) space and elastic
     * periods in frames. tl_curve_init sets 24. */
    double fps;
    bool prepared; /* cleared by tl_curve_add_key, set by tl_curve_prepare */
} tl_curve;

/* A key with defaults: auto-clamped handles at the key, ease-in-out-sine
 * for TL_INTERP_EASE with the settings Blender gives an inserted key (back
 * 1.70158, amplitude 0.8, period 4.1 frames), no cut. */
tl_key tl_key_make(double t, double v, tl_interp interp);

void tl_curve_init(tl_curve *c);

/* The same extrapolation on both sides, repeating forever. */
void tl_curve_set_extrap(tl_curve *c, tl_extrap mode);
void tl_curve_free(tl_curve *c);

/* Appends a copy of key (order is checked by tl_curve_validate). */
int tl_curve_add_key(tl_curve *c, const tl_key *key, tl_error *err);

/* Checks finiteness, enum ranges, time order and the equal-time rule (a key
 * may share its predecessor's time only if it is a cut or the predecessor is
 * constant). On failure *bad_key (may be NULL) is the 0-based index of the
 * offending key and the message starts with "key N: ". */
int tl_curve_validate(const tl_curve *c, size_t *bad_key, tl_error *err);

/* Computes handles (Blender's F-curve rules) and spline tangents. Call after
 * the keys are added and validated, and again after changing them. */
void tl_curve_prepare(tl_curve *c);

/* Value at time t: finite for any finite t and valid keys. Empty curve: 0. */
double tl_curve_eval(const tl_curve *c, double t);

/* True if the channel jumps at a cut whose time lies in (t0, t1], cycles
 * included (so motion blur can avoid blurring across it). */
bool tl_curve_has_cut_between(const tl_curve *c, double t0, double t1);

/* Shifts key values (and their handles) by multiples of period so that
 * consecutive values differ by at most period/2: angles take the short way.
 * Call before tl_curve_prepare. A period <= 0 or not finite does nothing. */
void tl_curve_unwrap(tl_curve *c, double period);

/* Names for the parser: "constant" "linear" "bezier" "ease" "spline";
 * "auto-clamped" "auto" "vector" "aligned" "free"; "constant" "linear"
 * "cycle" "cycle-offset" "ping-pong". Lookups return false if unknown. */
const char *tl_interp_name(tl_interp interp);
bool tl_interp_from_name(const char *name, tl_interp *out);
const char *tl_handle_type_name(tl_handle_type type);
bool tl_handle_type_from_name(const char *name, tl_handle_type *out);
const char *tl_extrap_name(tl_extrap extrap);
bool tl_extrap_from_name(const char *name, tl_extrap *out);
/* "none" "continuous". */
const char *tl_smoothing_name(tl_smoothing smoothing);
bool tl_smoothing_from_name(const char *name, tl_smoothing *out);

#endif
