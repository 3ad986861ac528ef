/* Internal to the curve engine: Blender's "Continuous Acceleration"
 * auto-handle smoothing, the second pass of tl_curve_prepare. */
#ifndef TL_CURVE_SMOOTH_H
#define TL_CURVE_SMOOTH_H

#include <stdbool.h>
#include <stddef.h>

#include "timeline/tl_curve.h"

/* Re-solves the value offsets of the auto handles of keys[0..total-1] (one
 * section: no cut inside) so the curve's second derivative is continuous
 * through every run of free auto keys (both handles auto, not locked by
 * clamping or an end), as Blender's BKE_nurb_handle_smooth_fcurve does.
 * Expects the first pass's handles (time offsets 1/3 of each interval).
 * cyclic: the keys repeat (the last key is the first one cycle on). fps
 * scales time for the lengths of aligned handles. Returns false if out of
 * memory (the first pass's handles then stay). */
bool tl_curve_smooth(tl_key *keys, size_t total, bool cyclic, double fps);

#endif
