/* tl_giant_spray: the giant wave's spray, in double: spindrift the wind
 * blows back off a tall crest, and a burst at a boat's bow where it meets
 * the face. shaders/spray.glsl draws it as a light volume with the same
 * density; docs/rendering.md has the model. */
#ifndef TL_GIANT_SPRAY_H
#define TL_GIANT_SPRAY_H

#include "scene/tl_scene.h"
#include "waves/tl_giant.h"

/* Extinction per metre of spray at density 1: thin enough that the
 * crest shows through the plume's middle. */
#define TL_SPRAY_SIGMA 0.025
/* Seconds the wind carries a droplet back from the crest before it falls:
 * the plume's reach is the wind times this (plus a twentieth of the crest). */
#define TL_SPRAY_FLIGHT 0.6
/* The plume's thickness: this share of the crest's height plus its
 * reach. The plume ends TL_SPRAY_REACHES reaches behind the crest (faded
 * to nothing over its last two fifths), and rises TL_SPRAY_LIFT of its
 * thicknesses over its first reach, as the square root of how far back
 * it has come: the wind meeting the face is turned up over the crest, so
 * the spray leaves the top steeply before the wind lays it back. Half as
 * thick, rising 1.5 of itself over two thirds of the reach, it hugged the
 * crest: from in front of the wave only a faint haze showed along the
 * top; rising in proportion to the distance, it lay behind the top, and
 * from the foot of the face nothing of it showed. Its box reaches
 * TL_SPRAY_BOX_RISES thicknesses below and above it. */
#define TL_SPRAY_RISE      0.1
#define TL_SPRAY_BOX_RISES 2.5
#define TL_SPRAY_REACHES   2.5
#define TL_SPRAY_LIFT      2.5
/* The plume's density at giant.spray 1, at its middle just behind the
 * crest (the other clouds' gains below are per unit of giant.spray too).
 * At 1 the plume was a faint beige haze over the crest's top (judges: "no
 * spindrift anywhere"); backlit spindrift glows. At 6, seen from above
 * through its length toward a low sun, it was a white fog that hid the sea
 * and the horizon behind the crest, and from the foot of the face a white
 * fringe along the crest (judges). */
#define TL_SPRAY_PLUME_GAIN 3.0
/* The crest sheds spray unevenly along its length: in gusts
 * TL_SPRAY_GUST_CELL metres across (a value noise along the crest), the
 * plume rises 1 ∓ TL_SPRAY_GUST of its lift and is as much denser or
 * thinner. Even along the crest, it was one haze over the whole of it
 * (judges), a band along the top seen from below the face; at 0.5, seen
 * through its length against the sun, still a white wall over the
 * horizon (judge): at 0.8 the lulls between gusts open it. */
#define TL_SPRAY_GUST      0.8
#define TL_SPRAY_GUST_CELL 9.0
/* Between its streaks the plume keeps this share of its density. At 0.65
 * the plume was one even veil, a fog rather than streaks torn off the
 * crest (judges); at 0.3, seen from above toward a low sun, still a flat
 * white haze over the sea behind the crest ("not thin backlit veils", a
 * judge). With none, the crest's dark top once showed through the gaps as
 * a dotted kerb; the gusts and the plume's root now close them there. */
#define TL_SPRAY_WISP_FLOOR 0.0
/* The spray is densest where it leaves the crest: 1 + TL_SPRAY_ROOT_GAIN
 * times the plume's density there, falling back to the plume's over
 * TL_SPRAY_ROOT_REACH of its reach. With no root, the veil over the
 * crest's rounded top let it through as a brown-grey stripe (judges); at
 * 2, seen from above toward a low sun, the root itself was that stripe:
 * warm light scattered over the dark trough behind the crest (a judge). */
#define TL_SPRAY_ROOT_GAIN  1.0
#define TL_SPRAY_ROOT_REACH 0.25
/* Where the crest passes under a hull, the hull has broken its top, and
 * no spindrift comes off that stretch: the plume is gone within
 * TL_SPRAY_SHELTER_IN of the burst's radius across the crest from its
 * centre, whole again at TL_SPRAY_SHELTER_OUT, by the crossing's
 * strength. Blown back over the boat, the denser plume veiled its
 * foredeck. */
#define TL_SPRAY_SHELTER_IN  0.6
#define TL_SPRAY_SHELTER_OUT 1.5
/* The crest makes spindrift once its envelope is this high (a share of
 * the wave's full height), fully at the second. */
#define TL_SPRAY_FROM 0.3
#define TL_SPRAY_FULL 0.8
/* The bow's burst: a cloud of this radius (a share of the hull's length)
 * ahead of and above the bow, from where the wave's slope along the
 * heading (up or down) is TL_SPRAY_BOW_SLOPE_FROM, at full strength where
 * it is TL_SPRAY_BOW_SLOPE or more. */
#define TL_SPRAY_BOW_RADIUS 0.45
/* Where the crest passes under the hull, the hull splits it: a burst of
 * this radius (a share of the hull's length) stands over the crest where
 * it meets the hull, from when the crest is TL_SPRAY_CROSS_EARLY of the
 * hull's length short of the end it meets first, at full strength once it
 * is under the hull, until it has passed the other end by TL_SPRAY_CROSS_LATE
 * of the length (the thrown water hangs as the hull goes on). The burst at
 * the bow alone ended as the bow cleared the face: the boat sat on the
 * crest's ridge dry, a model pasted on the water. */
#define TL_SPRAY_CROSS_RADIUS 0.4
/* The crossing's burst's density per unit of giant.spray: the
 * crest's top thrown up by the hull, a white skirt around it (at 25 times
 * the boat it lifts over the crest was washed out to a white ghost). */
#define TL_SPRAY_CROSS_GAIN 10.0
/* The crossing's burst is split into a wing each side of the hull
 * (TL_BOW_SPRAY_WING), their centres this share of the hull's length out
 * from its centre line: the hull's half beam and the wing's half width.
 * One sheet across the centre line sat on the deck, a pale fog that made
 * the boat a ghost (judges). */
#define TL_SPRAY_CROSS_SPLIT 0.4
#define TL_SPRAY_CROSS_EARLY 0.3
#define TL_SPRAY_CROSS_LATE  0.4
/* Where the lip lands, whitewater erupts: a cloud around its tip of this
 * radius (a share of the lip's), from half the throw until it has landed
 * and gone. As the lip collapses the splash rises off the face by up to
 * TL_SPRAY_SPLASH_RISE of the lip's radius and grows to 1 +
 * TL_SPRAY_SPLASH_GROW times as wide, fading as the square of what is
 * spent: the eruption goes up as the curtain comes down (a cloud that
 * only faded at the tip was hidden by the crest from behind). It is thrown
 * forward of the tip by TL_SPRAY_SPLASH_AHEAD of the lip's radius, from
 * 0.3 of that as it lands to all of it once spent: centred on the tip,
 * half of it lay under the face and the rest behind the curtain, and from
 * in front of the wave nothing of it showed. */
#define TL_SPRAY_LANDING_RADIUS 0.7
#define TL_SPRAY_SPLASH_RISE    0.8
#define TL_SPRAY_SPLASH_GROW    1.2
#define TL_SPRAY_SPLASH_AHEAD   0.6
/* The landing's whitewater's density per unit of giant.spray: an
 * opaque, churning cloud, not a veil (at 30, seen against the sky from
 * the low shot, it read as steam). It has all of it from the moment the
 * lip lands, and grows instead: its radius starts at
 * TL_SPRAY_LANDING_SEED of the full one and reaches it as the throw ends
 * (faded in by density, the growing cloud was a veil the sky showed
 * through: "steam", judges). */
#define TL_SPRAY_LANDING_GAIN 60.0
#define TL_SPRAY_LANDING_SEED 0.3
/* The whitewater erupts once the throw passes TL_SPRAY_LANDING_FROM, as
 * the lip's tip comes down to the face (until then its torn edge alone
 * sprays). From half the throw, a cloud hung in the air beside the lip
 * while it was still thrown and hid its curl ("steam drifting sideways,
 * detached from the lip", a judge). */
#define TL_SPRAY_LANDING_FROM 0.8
/* The landing's billows: where crossed noises pass from
 * TL_SPRAY_LANDING_TEAR_FROM to _TO, a billow's edge. Toward the cloud's
 * edge the billows shrink rather than fade alike, and its core closes: its
 * coverage c (the square root of its Gaussian envelope) shifts the noise
 * by TL_SPRAY_LANDING_CLOSE · (c − TL_SPRAY_LANDING_OPEN).
 * Faded alike, the whitewater was a soft mist the sky showed through, a
 * cotton ball (judges). */
#define TL_SPRAY_LANDING_TEAR_FROM 0.2
#define TL_SPRAY_LANDING_TEAR_TO   0.3
#define TL_SPRAY_LANDING_CLOSE     0.8
#define TL_SPRAY_LANDING_OPEN      0.75
/* The smaller lumps' shares of the field (0.6 m, 0.25 m;
 * billow_fine in tl_giant_spray.c), and the least and most they add to it
 * (the noises are 0 .. 1; their product's mean is 0.25). */
#define TL_SPRAY_LANDING_FINE      0.35
#define TL_SPRAY_LANDING_FINER     0.12
#define TL_SPRAY_LANDING_FINE_LOW  (-0.25 * TL_SPRAY_LANDING_FINE - 0.5 * TL_SPRAY_LANDING_FINER)
#define TL_SPRAY_LANDING_FINE_HIGH (0.75 * TL_SPRAY_LANDING_FINE + 0.5 * TL_SPRAY_LANDING_FINER)
/* The billows are whole, at the cloud's full density, wherever its
 * coverage is over TL_SPRAY_LANDING_EDGE_TO, and come in from
 * TL_SPRAY_LANDING_EDGE_FROM at its edge: whitewater is opaque lumps with
 * hard edges, and only its fringe is mist. Billows that thinned with the
 * envelope were see-through over most of the cloud (judges: steam). The
 * mist round them: TL_SPRAY_LANDING_MIST of the peak times the coverage. */
#define TL_SPRAY_LANDING_EDGE_FROM 0.05
#define TL_SPRAY_LANDING_EDGE_TO   0.3
#define TL_SPRAY_LANDING_MIST      0.03
/* The billows' own shade: the billows' field (before its edge is drawn)
 * TL_SPRAY_BURY_STEP metres toward a light (the sun, the sky overhead),
 * passing from TL_SPRAY_BURY_FROM to _TO, takes up to TL_SPRAY_BURY of
 * that light: a lump's top is lit, its underside and the folds between
 * lumps are not. Lit alike, the opaque cloud was a flat white or, in the
 * wave's shadow, a flat grey-blue cut-out. */
/* The landing's jets: the explosion throws streaks of water out and up
 * from where the lip hit, TL_SPRAY_JET_DROP radii below the cloud's
 * middle. Between TL_SPRAY_JET_FROM and TL_SPRAY_JET_END radii from there
 * (whole from _IN to _OUT), pointing up more than down, where two
 * noises of the direction (and of w: each jet is narrow along the crest)
 * pass 0.35 .. 0.6, they add TL_SPRAY_JET of the cloud's peak. Round
 * billows alone had no direction: "popcorn", "cotton balls", "not a
 * violent, directional explosion" (judges). */
#define TL_SPRAY_JET       0.4
#define TL_SPRAY_JET_DROP  0.6
#define TL_SPRAY_JET_FROM  0.5
#define TL_SPRAY_JET_IN    0.9
#define TL_SPRAY_JET_OUT   1.3
#define TL_SPRAY_JET_END   2.0
#define TL_SPRAY_BURY_STEP 0.6
#define TL_SPRAY_BURY      0.6
#define TL_SPRAY_BURY_FROM 0.1
#define TL_SPRAY_BURY_TO   0.6
/* The whitewater's mass (billows, mist, jets) over its envelope's
 * (test_giant_lip measures it): what its self-shade takes for them. */
#define TL_SPRAY_LANDING_MEAN 0.94
/* The lip's free edge tears into droplets while it throws: a tube along
 * the crest round the tip of its arc, TL_SPRAY_TIP_RADIUS of the lip's
 * radius across, TL_SPRAY_TIP_GAIN per unit of giant.spray at its middle,
 * in the landing's billows TL_SPRAY_TIP_SCALE times finer. It comes in as
 * the throw passes from TL_SPRAY_TIP_START to _FULL and goes as it passes
 * from TL_SPRAY_TIP_FADE to _GONE (the landing's whitewater takes over).
 * Without it the lip ended in a clean, hard edge, "a stiff paper flap"
 * (judges); seen along the crest the tube is long, and at 20 and a
 * third of the radius it hid the whole lip in a white wall. */
#define TL_SPRAY_TIP_RADIUS 0.15
#define TL_SPRAY_TIP_GAIN   3.0
#define TL_SPRAY_TIP_SCALE  3.0
#define TL_SPRAY_TIP_START  0.02
#define TL_SPRAY_TIP_FULL   0.2
#define TL_SPRAY_TIP_FADE   0.6
#define TL_SPRAY_TIP_GONE   0.9
/* The bow's burst's density per unit of giant.spray: thrown water, not
 * blown droplets. */
#define TL_SPRAY_BOW_GAIN  12.0
#define TL_SPRAY_BOW_SLOPE 0.8
/* No burst below this slope: the wave's long gentle front, far ahead of
 * its face, lifts a hull without throwing water. */
#define TL_SPRAY_BOW_SLOPE_FROM 0.3

/* A boat's hull as the spray sees it: its ends where the pitched hull has
 * them (world metres), the stem ahead along the heading. */
typedef struct tl_giant_hull {
    double stem[3], stern[3];
    double heading[2]; /* unit (x, z) */
    double length;     /* metres */
} tl_giant_hull;

/* The spray of one frame. */
typedef struct tl_giant_spray {
    bool active;       /* giant.spray > 0 and a crest tall enough somewhere */
    double amount;     /* giant.spray */
    double reach;      /* metres the plume reaches back from the crest */
    double drift;      /* metres the wind has moved the wisps (wrapped every 4096 m) */
    double base;       /* the ocean's mean level, -depth / 2 */
    double bow[3];     /* world position of the burst's centre */
    double bow_radius; /* metres */
    double bow_amount; /* its density, 0 without a burst */
    double bow_split;  /* metres its wings lie out from the hull's centre line (0: one sheet) */
    double shelter;    /* 0 .. 1: the crossing's strength, which keeps the plume off the hull */
    double heading[2]; /* the boat's heading, unit (x, z) */
    double box[4];     /* (s low, s high, y low, y high) in the wave's coordinates */
} tl_giant_spray;

/* The spray of wave `g` at time t with giant.spray `amount`, the wind
 * `wind` m/s (giant.spray_wind), ocean depth `depth`, and the boat's
 * `hull` (NULL for none). */
void tl_giant_spray_prepare(tl_giant_spray *sp, const tl_giant *g, double amount, double wind,
                            double t, double depth, const tl_giant_hull *hull);

/* Spray density (0 or more: its extinction is TL_SPRAY_SIGMA times it per
 * metre) at world (x, y, z). `span`: the height (m) a sample of a march
 * stands for (0 for the point): the plume's thin
 * layer is averaged over [y - span/2, y + span/2] in closed form
 * (tl_giant_spray_layer), so a step that straddles it counts what it
 * holds wherever the step's sample lands. */
double tl_giant_spray_density(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                              double z, double span);

/* The optical depth toward the sun (unit `sun`, world) from world (x, y,
 * z) through the lip's landing cloud: its Gaussian envelope integrated in
 * closed form along the sun's ray in the crest's cross-section (the lip
 * held as at the point's w, the noise at its mean TL_SPRAY_LANDING_MEAN),
 * times TL_SPRAY_SIGMA. A dense cloud is bright on its sunward side and
 * grey in its own shade. 0 outside the spray's box or without a landing
 * at the point's w. */
double tl_giant_spray_landing_shade(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                                    double z, const double sun[3]);

/* All the spray's shade at world (x, y, z): the landing's
 * (tl_giant_spray_landing_shade) and, where its sheet holds spray, the
 * boat's burst's (tl_bow_spray_sheet_depth, scaled as tl_bow_spray_shade). */
double tl_giant_spray_shade(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                            double z, const double sun[3]);

/* The hull of boat b as the burst sees it: its ends where its pitch puts
 * them. */
void tl_giant_hull_of(tl_giant_hull *hull, const tl_boat *b);

/* The mean of exp(-x²/r²) over [x - h, x + h], h = span/2: the plume's
 * profile in height, x the height over its middle and r its rise. */
double tl_giant_spray_layer(double x, double r, double span);

/* Billows' density over their peak for their Gaussian `envelope` (0 ..
 * 1) at w across the crest, (ts, ty) from the cloud's centre: where a
 * field of crossed noises with smaller lumps on them, shifted by the
 * coverage (TL_SPRAY_LANDING_CLOSE, _OPEN, _FINE*), passes
 * TL_SPRAY_LANDING_TEAR_FROM .. _TO, with the edge TL_SPRAY_LANDING_EDGE_*:
 * the lip's torn edge's and its landing's. */
double tl_giant_spray_billows(double envelope, double w, double ts, double ty);

/* The landing's density over its peak there, for a cloud of radius r: its
 * billows, their mist (TL_SPRAY_LANDING_MIST) and its jets
 * (tl_giant_spray_jets). */
double tl_giant_spray_whitewater(double envelope, double w, double ts, double ty, double r);

/* The landing's jets over its peak at w across the crest, (ts, ty) from
 * the middle of a cloud of radius r: streaks thrown out and up from where
 * the lip hit (TL_SPRAY_JET_*). */
double tl_giant_spray_jets(double w, double ts, double ty, double r);

/* How much of a light along unit `light` (world) the landing's billows
 * let reach world (x, y, z): 1 - TL_SPRAY_BURY at most taken where the
 * billows' field TL_SPRAY_BURY_STEP toward the light is inside a billow,
 * weighed by the landing's share of the spray's density there (`span` as
 * for tl_giant_spray_density). 1 where the point holds no billow. */
double tl_giant_spray_open(const tl_giant_spray *sp, const tl_giant *g, double x, double y,
                           double z, double span, const double light[3]);

/* The plume's gust at w metres across the crest: its lift's and its
 * density's factor, 1 - TL_SPRAY_GUST .. 1 + TL_SPRAY_GUST. */
double tl_giant_spray_gust(double w);

#endif
