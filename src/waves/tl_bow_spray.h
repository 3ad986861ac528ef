/* tl_bow_spray: the spray a boat's bow throws where it meets rising water,
 * in double: a sheet thrown up and out to both sides of the stem, its
 * strength from how fast the water rises against the bow (tl_boat.impact,
 * from the floated pose; no simulation state). shaders/bow_spray.glsl
 * draws it as a light volume with the same density; the giant wave's
 * spray throws the same sheet where the bow meets its face. */
#ifndef TL_BOW_SPRAY_H
#define TL_BOW_SPRAY_H

#include <stdbool.h>

#include "scene/tl_scene.h"

/* No spray while the water rises against the bow slower than
 * TL_BOW_SPRAY_FROM m/s (the hull riding the chop), all of it from
 * TL_BOW_SPRAY_FULL (the bow slamming into a wave's face). */
#define TL_BOW_SPRAY_FROM 0.5
#define TL_BOW_SPRAY_FULL 1.8
/* The sheet's radius at full strength, a share of the hull's length (it
 * reaches 1.3 radii out to each side and 0.9 up), and its density at the
 * centre then: thrown water, an opaque white sheet where it is thickest. */
#define TL_BOW_SPRAY_RADIUS 0.25
#define TL_BOW_SPRAY_GAIN   8.0

/* One frame's burst at one bow. */
typedef struct tl_bow_spray {
    bool active;
    double center[3];  /* world metres */
    double radius;     /* metres */
    double amount;     /* density at the centre */
    double heading[2]; /* the boat's heading, unit (x, z) */
} tl_bow_spray;

/* The burst of boat b (its pose, length, impact and boat.spray). */
void tl_bow_spray_prepare(tl_bow_spray *sp, const tl_boat *b);

/* The sheet's shape at offset d (world metres) from its centre, for a
 * boat heading (x, z) and a burst of `radius`: in [0, 1], 0 beyond three
 * radii (the sphere a march covers). */
double tl_bow_spray_sheet(const double d[3], const double heading[2], double radius);

/* The burst's density at world (x, y, z). */
double tl_bow_spray_density(const tl_bow_spray *sp, double x, double y, double z);

#endif
