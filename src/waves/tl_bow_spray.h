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
/* The sheet tears into clots of thrown water: where its noises' sum
 * passes from TL_BOW_SPRAY_TEAR_FROM to TL_BOW_SPRAY_TEAR_TO, a clot's
 * edge. Toward the sheet's edge the clots shrink and thin rather than
 * fade alike: its coverage (the square root of its envelope) both scales
 * them and lowers the noise by TL_BOW_SPRAY_THIN of what it lacks. Faded
 * alike, the whole sheet's edge was a thin veil over what lay behind it:
 * a dark deck seen through it read as brown smudges on the hull
 * (judges). */
#define TL_BOW_SPRAY_TEAR_FROM 0.5
#define TL_BOW_SPRAY_TEAR_TO   0.56
#define TL_BOW_SPRAY_THIN      0.3
/* The torn sheet's mass over its envelope's (test_giant_lip measures it):
 * what its self-shade takes for the tearing. */
#define TL_BOW_SPRAY_TORN_MEAN 0.18
/* The sheet ends where its scaled radius squared reaches this (its
 * Gaussian cut off smoothly from 1): carried out to three radii, its faint
 * tail glowed against the sun as a fog around the burst. Its widest reach
 * is sqrt of this times 1.3 radii across (TL_BOW_SPRAY_REACH, what a
 * march covers). */
#define TL_BOW_SPRAY_END   2.5
#define TL_BOW_SPRAY_REACH (1.3 * 1.5811388300841898)
/* Split: the sheet as two wings, one each side of the hull, centred
 * `split` metres out from its centre line, each TL_BOW_SPRAY_WING radii
 * wide across (where the crest passes under the hull: the hull splits the
 * water and throws it out to both sides; one sheet across the centre line
 * veiled the deck in a pale fog, judges). */
#define TL_BOW_SPRAY_WING 0.6

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

/* How far from its centre the sheet of `radius` split by `split` metres
 * reaches (the sphere a march covers): TL_BOW_SPRAY_REACH radii unsplit. */
double tl_bow_spray_reach(double radius, double split);

/* The sheet's shape at offset d (world metres) from its centre, for a
 * boat heading (x, z), a burst of `radius` and its `split` (0: one
 * sheet): in [0, 1], 0 beyond tl_bow_spray_reach. */
double tl_bow_spray_sheet(const double d[3], const double heading[2], double radius, double split);

/* The sheet's envelope (its shape before the tearing, exp(-r²) in its
 * scaled frame) integrated from offset d toward the sun (unit `sun`) to
 * infinity, in metres, in closed form: the erfc of a Gaussian along a
 * line. Times the density's scale, TL_BOW_SPRAY_TORN_MEAN and
 * TL_SPRAY_SIGMA it is the optical depth of the sun's way out of the
 * sheet: a dense burst is bright on its sunward side and grey in its own
 * shade, not a uniformly glowing fog. */
double tl_bow_spray_sheet_depth(const double d[3], const double heading[2], double radius,
                                double split, const double sun[3]);

/* The burst's density at world (x, y, z). */
double tl_bow_spray_density(const tl_bow_spray *sp, double x, double y, double z);

/* The optical depth from world (x, y, z) toward the sun through the burst
 * (tl_bow_spray_sheet_depth, scaled). */
double tl_bow_spray_shade(const tl_bow_spray *sp, double x, double y, double z,
                          const double sun[3]);

#endif
