/* tl_giant: the scripted giant wave on the CPU, in double.
 *
 * One Gerstner crest (seed 003) travelling along a compass direction
 * toward a centre, cut to a single crest by a mask along its travel and to
 * a finite width by a mask across it. Its horizontal displacement (the
 * Gerstner pinch plus a forward curl of the crest) is clamped so that the
 * displaced surface stays a height field, and inverted per point with a
 * safeguarded Newton iteration, exactly as shaders/giant.glsl does. This is
 * the accuracy reference for the shader, floats the boat, and gives the
 * renderer the bounds it marches with. docs/rendering.md has the model.
 *
 * Coordinates: `s` runs along the travel direction, relative to the crest
 * (positive = ahead of it, toward the centre and beyond); `w` runs across,
 * relative to the centre line. `s0` is the undisplaced ("Lagrangian")
 * position along: the surface point that started at s0 sits at
 * s = s0 + lambda(w)·D(s0) + bow(w) at height lambda(w)·Y(s0). lambda(w),
 * the crest's envelope, is the fade times the width mask, the taper from
 * the peak toward the ends, the seeded variation along the crest and what
 * the break has let down; bow(w) <= 0 is how far the crest lags behind its
 * peak there. */
#ifndef TL_GIANT_H
#define TL_GIANT_H

#include <stdbool.h>

#include "scene/tl_scene.h"

#define TL_GIANT_GRAVITY 9.81
/* Smallest Jacobian of the horizontal map the clamps allow: the surface is
 * compressed at most ten times, so slopes stay finite. */
#define TL_GIANT_MIN_JACOBIAN 0.1
/* The single-crest mask is 1 within this many wavelengths of the crest
 * (the crest and its faces), and fades over the falloff beyond, so the
 * troughs on either side rise gently back to the sea. Holding the mask to
 * half a wavelength left a trough as deep as the crest is high, whose far
 * wall, seen from a camera beyond it, grazed the view and mirrored the sky
 * as a pale band. */
#define TL_GIANT_CREST_HALF_LENGTH 0.25
/* The share of a trough's depth the profile lifts (Stokes' asymmetry): a
 * steep wave's crest stands well above the sea and its trough is broad and
 * shallow. The cosine profile alone made troughs as deep as the crest was
 * high; beside a short-crested peak they ended in a round, dark pit. At
 * 1/2 the trough's bottom is flat; above it the trough would have two. */
#define TL_GIANT_TROUGH_LIFT 0.5
/* The trough behind the crest is filled by this share more (its depth
 * times 1 − FILL·t·(2 − t), t = −cos θ where the profile is below the
 * sea's level behind the crest; the profile is 0 where t = 0, so it stays
 * smooth there, and its deepest point stays mid-trough). The wave
 * draws its water up its face, from the trough ahead; behind it the back
 * runs long and gentle. As deep as the trough ahead, the trough behind
 * faced a camera over the crest and mirrored the sky at a few per cent: a
 * dark trench along the whole wave. */
#define TL_GIANT_BACK_FILL 0.6
/* Along the travel the mask fades over at least three quarters of a
 * wavelength: the troughs rise back to the sea as gently as a swell, not
 * up a ramp whose far side grazes the view. */
#define TL_GIANT_MIN_FALLOFF_ALONG 0.75
/* The crest mask fades over at least a quarter and at most four
 * wavelengths; the width mask over at least a quarter wavelength. */
#define TL_GIANT_MIN_FALLOFF_WAVELENGTHS 0.25
#define TL_GIANT_MAX_FALLOFF_WAVELENGTHS 4.0
/* The Newton bracket is this many times the largest displacement. */
#define TL_GIANT_BRACKET 1.25
/* The shader's Newton iteration stops once the height it would give is
 * within this many metres (0.1 mm): most points converge in two or three
 * steps, and a loop that stops early saves a giant-wave frame 12%. The
 * CPU, the accuracy reference, always runs the full count. */
#define TL_GIANT_CONVERGED 1.0e-4
/* Samples of the along-profile scanned for the clamps and bounds, and of
 * the envelope across for its slope bounds. */
#define TL_GIANT_PROFILE_SAMPLES 2048
/* The peak stays within this fraction of the half width of the centre
 * line, so that the taper has room on both sides. */
#define TL_GIANT_PEAK_LIMIT 0.9
/* The variation along the crest: three sines of these wavelengths (in
 * wavelengths of the wave) and weights (summing to 1), their phases drawn
 * from giant.seed. Long against the small waves, short against the crest:
 * the height changes gently, and no stretch of the crest repeats another. */
#define TL_GIANT_VARIATION_PERIODS                                                                 \
    {                                                                                              \
        0.9, 0.53, 0.31                                                                            \
    }
#define TL_GIANT_VARIATION_WEIGHTS                                                                 \
    {                                                                                              \
        0.5, 0.3, 0.2                                                                              \
    }
/* A breaking crest's lip throws and lands over this many times the time a
 * body takes to fall the crest's height; the broken crest then settles
 * (loses giant.break_drop of its height) over twice that. */
#define TL_GIANT_THROW_FALLS 1.5
/* The break's distance from the peak is rounded over this many metres
 * there (sqrt(x² + r²) - r), so the settling crest has no corner at it. */
#define TL_GIANT_PEEL_ROUND 2.0
/* The lip: a tube along an arc in the crest's cross-section (a circle
 * stretched along the travel, TL_GIANT_LIP_THROW),
 * of this radius and half thickness (fractions of the crest's height
 * there). The arc's point at TL_GIANT_LIP_ANCHOR (degrees from straight
 * up, clockwise toward the travel) sits on the crest's top; it starts at
 * TL_GIANT_LIP_ROOT, buried in the crest, and its free end sweeps
 * TL_GIANT_LIP_SWEEP degrees forward and down over the throw, landing on
 * the face in front (at a fifth of the crest's height). Then it collapses
 * over TL_GIANT_LIP_FADE throw times: the arc falls in from its root, so
 * that TL_GIANT_LIP_COLLAPSE of it has gone by the end and what is left
 * hangs down to where it landed; the water there swells into whitewater
 * (up to 1 + TL_GIANT_LIP_SWELL times the root's thickness, and as thick
 * at the tip as at the root) and thins away (as the square root of what
 * is left: it stays thick, then goes). A tube that kept its arc and only
 * thinned read as a hoop at the spent end of the break. */
#define TL_GIANT_LIP_RADIUS    0.45
#define TL_GIANT_LIP_THICKNESS 0.08
#define TL_GIANT_LIP_ANCHOR    0.0
#define TL_GIANT_LIP_ROOT      -45.0
#define TL_GIANT_LIP_SWEEP     195.0
#define TL_GIANT_LIP_FADE      0.8
#define TL_GIANT_LIP_COLLAPSE  0.85
#define TL_GIANT_LIP_SWELL     1.0
/* The arc is a circle stretched forward into an ellipse: its reach along
 * the travel is TL_GIANT_LIP_THROW times its radius, its drop the radius.
 * The lip is thrown out over the face and falls, leaving a barrel of air
 * under it; a circle's arc, falling at 45 degrees from the top, lay on any
 * face steeper than that (a rope on the face, judges). The tube keeps its
 * thickness across the arc (tl_giant_lip_distance). */
#define TL_GIANT_LIP_THROW 1.6
/* The tube thins from its root to its free end: its half thickness
 * falls linearly along the arc, to TL_GIANT_LIP_TIP of the root's at the
 * end of the whole sweep, so the lip reads as a sheet thrown off the crest
 * that thins to an edge, not as a hose of even bore. */
#define TL_GIANT_LIP_TIP 0.15
/* Thrown water is thinnest at its leading edge, however short the throw:
 * over the last TL_GIANT_LIP_EDGE_ARC degrees of its arc the tube thins to
 * TL_GIANT_LIP_EDGE of itself (evening out as it collapses). Thinned along
 * the whole sweep alone, a short throw ended as thick as its root: at the
 * peel's front the lip came out of the crest as a tube cut square
 * (judges). The arc's centre keeps the root's thickness, so the crest's
 * top holds the tube's outer surface once the throw is past the arc. */
#define TL_GIANT_LIP_EDGE     0.2
#define TL_GIANT_LIP_EDGE_ARC 50.0
/* The barrel's roof: where the lip leaves the face the water curves from
 * the one into the other. The tube's inner side is thicker near its root
 * by up to TL_GIANT_LIP_FILLET of its radius, thinning to nothing over the
 * first TL_GIANT_LIP_FILLET_ARC degrees past straight up (as the square
 * of 1 - a smoothstep), once the throw's end has passed from
 * TL_GIANT_LIP_FILLET_FROM to TL_GIANT_LIP_FILLET_TO degrees past it (a
 * short throw's stub is thin to its root) and less as it collapses. The
 * outer side is the crest's top as before. Of even thickness, the tube's
 * underside met the face at a sharp crease: seen from the foot of the face
 * the lip was a blade stuck into the crest (judges). */
#define TL_GIANT_LIP_FILLET      0.3
#define TL_GIANT_LIP_FILLET_ARC  50.0
#define TL_GIANT_LIP_FILLET_FROM 30.0
#define TL_GIANT_LIP_FILLET_TO   90.0
/* The tube grows from nothing over the throw's first TL_GIANT_LIP_GROW
 * (of its progress): at the peel's front the lip rises out of the crest
 * instead of starting as a wall of full thickness. */
#define TL_GIANT_LIP_GROW 0.15
/* Thrown water tears and landed water is whitewater, not a smooth sheet:
 * the tube's half thickness is lumped by a value noise (cells
 * TL_GIANT_LIP_LUMP_CELL metres along the crest and along the arc) by up
 * to TL_GIANT_LIP_LUMP of itself, at its free edge as it throws (up to
 * TL_GIANT_LIP_TEAR of that, over the last 0.3 of the sweep) and all
 * along it once it has landed (growing over the first
 * TL_GIANT_LIP_ROUGHEN of its collapse). A smooth tube read as a glassy
 * shell with hard edges. */
#define TL_GIANT_LIP_LUMP      0.6
#define TL_GIANT_LIP_LUMP_CELL 0.9
#define TL_GIANT_LIP_TEAR      0.6
#define TL_GIANT_LIP_ROUGHEN   0.4
/* Short waves riding a long one are heightened on its crest (their
 * amplitude goes as 1 + A·k·cos θ of the long wave's phase, Longuet-Higgins
 * and Stewart's radiation stress; the squeeze that shortens them there is
 * giant.ride's): the face's small waves steepen toward the crest by up to
 * this factor. Without it the face was a smooth glassy sheet. */
#define TL_GIANT_SHORT_WAVE_GAIN_MAX 2.0
/* The foam trail's edge (where the break had reached when the crest
 * passed) is ragged: the break's age there is taken up to
 * TL_GIANT_TRAIL_RAGGED seconds earlier or later by a value noise fixed in
 * the world, cells TL_GIANT_TRAIL_RAGGED_CELL metres. A straight seam
 * along the travel read as a pasted texture. */
#define TL_GIANT_TRAIL_RAGGED      1.0
#define TL_GIANT_TRAIL_RAGGED_CELL 12.0
/* tl_giant_lip_heights scans a vertical line across the tube in this
 * many intervals for its crossings. */
#define TL_GIANT_LIP_SCAN 512
/* Only a tall stretch of the crest throws a lip: the tube's thickness and
 * its throw's sweep grow from nothing where the envelope is
 * TL_GIANT_LIP_LOW to whole at TL_GIANT_LIP_HIGH, so the break dies out
 * toward the crest's low ends in ever smaller curls on the crest's top,
 * not in long thin blades (the thickness alone) nor in shrinking hoops
 * (the radius with it). */
#define TL_GIANT_LIP_LOW  0.55
#define TL_GIANT_LIP_HIGH 0.8
/* A crest that breaks by the script (giant.breaking) stays green until its
 * lip throws: where it is compressed but has not broken yet it foams only
 * this share of what it does once broken. A wave without a script breaks
 * by its compression alone and foams fully there. */
#define TL_GIANT_UNBROKEN_FOAM 0.2
/* The slope bound is kept per bin of s across the reach, so the march
 * takes small steps only near the steep faces. */
#define TL_GIANT_SLOPE_BINS 32
/* The crest casts its full shadow once it stands this many metres above
 * the sea's mean level; a crest the width mask lets down casts a fainter
 * one, and none at 0 (tl_giant_sunlit). */
#define TL_GIANT_SHADOW_FADE 0.5
/* The steps of tl_giant_water_along: a few dozen metres covered in a few
 * steps, fine near the start where a thin sheet is crossed. */
#define TL_GIANT_THROUGH_STEPS  10
#define TL_GIANT_THROUGH_FIRST  0.5
#define TL_GIANT_THROUGH_GROWTH 1.6

/* The giant wave's matte (the compositing passes' mask_giant and its
 * Cryptomatte object): the water it raises above this share of its height
 * (giant.height), and its lip. The small waves' own heights are left out,
 * so the matte's edge runs along the wave's body, not its ripples; the
 * trough ahead, lowered by the wave, is the ocean's. */
#define TL_GIANT_MATTE_SHARE 0.1

/* The wave at one moment, ready to evaluate. All lengths in metres. */
typedef struct tl_giant {
    bool active;          /* enabled, fade > 0 and height > 0 */
    double dir[2];        /* unit travel direction (x, z) */
    double across[2];     /* unit perpendicular (x, z): dir turned 90 deg clockwise */
    double origin[2];     /* world x, z of the crest on the centre line */
    double k;             /* wavenumber 2π / wavelength */
    double speed;         /* crest speed, m/s (deep-water speed times giant.speed) */
    double amplitude;     /* giant.height */
    double fade;          /* giant.fade */
    double steepness;     /* Gerstner q·k·A after the height-field clamp */
    double curl;          /* curve strength after the clamp */
    double half_length;   /* the crest mask is 1 inside |s0| <= this (TL_GIANT_CREST_HALF_LENGTH) */
    double falloff_along; /* the crest mask reaches 0 at half_length + this */
    double half_width;    /* width / 2: the width mask is 0 beyond |w| >= this */
    double falloff_across;   /* the width mask is 1 inside |w| <= half_width - this */
    double peak;             /* w of the peak (giant.peak, held within TL_GIANT_PEAK_LIMIT) */
    double taper;            /* giant.taper: the ends' height below the peak's, a fraction */
    double bow;              /* giant.bow: metres the ends lag behind the peak */
    double variation;        /* giant.variation: a fraction of the height */
    double vary_k[3];        /* wavenumbers of the variation's sines, rad/m */
    double vary_phase[3];    /* their phases, from giant.seed */
    bool scripted;           /* giant.breaking: the crest breaks when the script says */
    bool breaks;             /* giant.breaking and the break has begun somewhere */
    double break_age;        /* seconds since the break began at the peak (t - giant.break_time) */
    double peel_speed;       /* m/s the break runs along the crest from the peak */
    double throw_time;       /* seconds the lip takes to throw and land */
    double break_drop;       /* giant.break_drop: the height a broken crest loses */
    double lambda_max;       /* bound on lambda: fade·(1 + variation) */
    double max_dlambda;      /* bound on |lambda'(w)| */
    double max_dbow;         /* bound on |bow'(w)| */
    double max_displacement; /* max |D(s0)| over the profile */
    double reach_along;      /* |s| beyond this: no wave (mask support + displacement) */
    double min_jacobian;     /* smallest Jacobian of the map at this fade */
    double max_slope;        /* bound on |grad height| of the wave (marching) */
    double ride;             /* giant.ride: the share of the push the small waves ride */
    /* slope_bin[i] bounds |grad height| for s in [-reach_along + i·bin,
     * -reach_along + (i + 1)·bin), bin = 2·reach_along / TL_GIANT_SLOPE_BINS. */
    double slope_bin[TL_GIANT_SLOPE_BINS];
    /* height_bin[i] bounds the wave's height (metres added to the ocean)
     * over the same bins: a ray that stays higher cannot meet it there. */
    double height_bin[TL_GIANT_SLOPE_BINS];
    /* squeeze_bin[i] bounds |grad displacement| over the same bins: the
     * small waves riding the wave's water (giant.ride) steepen by at most
     * ride times this times their own slope there (marching). */
    double squeeze_bin[TL_GIANT_SLOPE_BINS];
    double max_squeeze;
} tl_giant;

/* The wave of `p` at time t (seconds). Inactive waves evaluate to zero. */
void tl_giant_prepare(tl_giant *g, const tl_giant_wave *p, double t);

/* Profile along the travel direction at full strength (lambda = 1):
 * height Y, displacement D and their derivatives with respect to s0. */
void tl_giant_profile(const tl_giant *g, double s0, double *y, double *dy, double *d, double *dd);

/* Width mask in [0, 1] and its derivative with respect to w. */
double tl_giant_width_mask(const tl_giant *g, double w, double *dmask);

/* How far the break has gone at w across: 0 before the lip throws there,
 * 1 once it has landed; *dprogress its derivative with respect to w. 0
 * everywhere for a wave that does not break. */
double tl_giant_break_progress(const tl_giant *g, double w, double *dprogress);

/* The break's age at w: seconds since the lip began to throw there
 * (negative before). */
double tl_giant_break_age(const tl_giant *g, double w);

/* The crest's envelope lambda(w) (see above) and its derivative in *dl. */
double tl_giant_lambda(const tl_giant *g, double w, double *dl);

/* The crest's lag behind its peak at w, metres (<= 0), and its derivative
 * in *db. */
double tl_giant_bow(const tl_giant *g, double w, double *db);

/* Solves s = s0 + lambda·D(s0) for s0 with `iterations` safeguarded Newton
 * steps (the shader's algorithm). */
double tl_giant_invert(const tl_giant *g, double s, double lambda, int iterations);

/* Everything the shading needs at a world point. */
typedef struct tl_giant_sample {
    double height;       /* metres added to the ocean */
    double grad[2];      /* d height / d (x, z) */
    double s, w, s0;     /* wave coordinates (see above) */
    double lambda;       /* the envelope lambda(w) */
    double jacobian;     /* 1 + lambda·D'(s0) */
    double displacement; /* lambda·D(s0): how far the point moved along */
    double ride[2];      /* d displacement / d (x, z) */
    double bow;          /* bow(w): the crest's lag behind its peak there */
} tl_giant_sample;

void tl_giant_sample_at(const tl_giant *g, double x, double z, int iterations,
                        tl_giant_sample *out);

/* Where the small waves at world (x, z) came from, into q: the wave
 * pushes its water along the travel by `displacement` (of `smp`, the
 * wave's sample there), and giant.ride of the small waves ride with it,
 * compressed up the face where the water is (J < 1) and drawn out on the
 * back. The ocean is evaluated at q (shaders/giant.glsl's giant_ride). */
void tl_giant_ride_point(const tl_giant *g, const tl_giant_sample *smp, double x, double z,
                         double q[2]);

/* A gradient `grad` of the small waves at q, in (x, z): the chain rule
 * through q(x, z). */
void tl_giant_ride_grad(const tl_giant *g, const tl_giant_sample *smp, double grad[2]);

/* The factor the small waves' slopes are steepened by on the wave at a
 * point (its sample `smp`): 1 + k·A·lambda times how far up the crest the
 * point is (0 at the sea's mean level, 1 at the top), at most
 * TL_GIANT_SHORT_WAVE_GAIN_MAX; 1 in the trough, where the small
 * waves stay as they are, and off the wave. Shading only: the march meets
 * the surface without it. */
double tl_giant_short_wave_gain(const tl_giant *g, const tl_giant_sample *smp);

/* The water's normal blend toward up (`level`, tl_optics_normal_blend) on
 * the giant wave at its sample: less by TL_GIANT_FACE_SHARP_SHARE where
 * its slope is steep (shaders/giant.glsl, giant_face_blend). */
double tl_giant_face_blend(const tl_giant_sample *smp, double level);

/* The shading normal n (unit) of a small wave on the giant wave, whose
 * own slope there is `grad`, seen along the unit `ray`: turned toward the
 * ray until the ray meets it at TL_GIANT_FACET_GRAZE of the cosine at
 * which it meets the wave's surface (times the face's share by slope,
 * TL_GIANT_FACE_SHARP_*), if it meets it more edge-on; else n
 * (shaders/giant.glsl, giant_facet_seen). */
void tl_giant_facet_seen(const double n[3], const double ray[3], const double grad[2],
                         double out[3]);

/* The wave's origin in its own frame (along the travel, across it),
 * wrapped every 65536 m: the world-fixed coordinates of the foam it
 * leaves behind are these plus (s0, w) (the shaders' u_giant_world). */
void tl_giant_world_origin(const tl_giant *g, double out[2]);

/* Whether water the wave raises by `height` (tl_giant_sample.height) is in
 * its matte (TL_GIANT_MATTE_SHARE); shaders/aov.glsl's rule. */
bool tl_giant_in_matte(const tl_giant *g, double height);

/* Height of the wave alone at world (x, z); 0 outside its reach. */
double tl_giant_height(const tl_giant *g, double x, double z, int iterations);

/* The lip's cross-section at w across: an arc in the (s, y) plane, s as
 * the wave's (along the travel, from the crest on the centre line), y
 * absolute. */
typedef struct tl_giant_lip {
    bool present;     /* the break has begun there and the lip has not thinned away */
    double center[2]; /* (s, y) of the arc's centre */
    double radius;    /* of the tube's centre line */
    double thickness; /* the tube's half thickness at its root */
    double from, to;  /* the arc's angles, radians from up, clockwise toward +s */
    double progress;  /* the throw, 0 .. 1 (tl_giant_break_progress) */
    double spent;     /* 0 .. 1 once it has landed: it collapses, whitens and thins away */
    double fillet;    /* metres the inner side is thicker at the root (TL_GIANT_LIP_FILLET) */
    double w;         /* where across the crest (the lumps' noise is taken there) */
} tl_giant_lip;

/* The lip at w across; `base` is the ocean's mean level (-depth / 2). */
void tl_giant_lip_at(const tl_giant *g, double w, double base, tl_giant_lip *lip);

/* The tube's half thickness at `angle` along its arc (TL_GIANT_LIP_TIP),
 * lumped (TL_GIANT_LIP_LUMP). */
double tl_giant_lip_half_thickness(const tl_giant_lip *lip, double angle);

/* What the barrel's roof adds to the inner side's half thickness at
 * `angle` (TL_GIANT_LIP_FILLET). */
double tl_giant_lip_fillet(const tl_giant_lip *lip, double angle);

/* How much the lumps roughen the tube at `angle` along its arc, 0 .. 1,
 * and their factor on the half thickness there
 * (1 + TL_GIANT_LIP_LUMP * roughness * (2 * noise - 1)). */
double tl_giant_lip_roughness(const tl_giant_lip *lip, double angle);
double tl_giant_lip_lump(const tl_giant_lip *lip, double angle);

/* The box that holds the lip: box = (s low, s high, y low, y high) in the
 * wave's coordinates, across = (w low, w high). False when no lip is
 * thrown anywhere (then the frame compiles none). */
bool tl_giant_lip_bounds(const tl_giant *g, double base, double box[4], double across[2]);

/* The angle along the lip's arc (from up, clockwise toward the travel)
 * of the point (s, y) of its cross-section: the circle's, with the
 * travel's axis shrunk by TL_GIANT_LIP_THROW. */
double tl_giant_lip_angle(const tl_giant_lip *lip, double s, double y);

/* Signed distance from (s, y) to the lip's tube in its cross-section
 * (negative inside); a large positive value where there is no lip. */
double tl_giant_lip_distance(const tl_giant_lip *lip, double s, double y);
/* The same, and in *bound a lower bound of the distance to the lip's
 * surface (the march's step; the distance itself is first order). */
double tl_giant_lip_distance_bounded(const tl_giant_lip *lip, double s, double y, double *bound);

/* The heights above `floor` (the height field's there) at which a
 * vertical line at world (x, z) crosses the lip's faces, lowest first, at
 * most `max`; `base` is the ocean's mean level (-depth / 2). Returns the
 * count: 0 where no lip overhangs. */
int tl_giant_lip_heights(const tl_giant *g, double x, double z, double floor, double base,
                         double *heights, int max);

/* Where the wave's foam can be at a sample and how much, before its
 * texture: the coverage giant_foam in shaders/giant.glsl computes (the
 * compressed surface, the cap and whitewater of a breaking crest, the trail
 * behind it; the streaks' noise left out), times `amount` (water.foam),
 * in [0, 1]. `foam_compression` and `foam_trail` are the channels'. */
double tl_giant_foam_coverage(const tl_giant *g, const tl_giant_sample *smp, double amount,
                              double foam_compression, double foam_trail);

/* How much of the sky in unit direction `dir` a point at world (x, z) and
 * height y sees past the wave's crest: 0 where the crest hides it, 1 in
 * the open, soft in between over a penumbra that widens with the distance
 * and by `spread` (radians, the spread of the rays the point stands for)
 * times the distance. The crest is the line where s0 = 0, at s = bow +
 * lambda·curl/k and lambda·amplitude high; the ray is followed to it.
 * shaders/giant.glsl's giant_clear is the same rule. */
double tl_giant_clear(const tl_giant *g, double x, double z, double y, const double dir[3],
                      double spread);

/* Metres of the wave's water that a ray from world `from` along unit
 * `dir` crosses (the height field alone, not the lip): the ray is stepped,
 * each step TL_GIANT_THROUGH_GROWTH times the last from
 * TL_GIANT_THROUGH_FIRST metres, TL_GIANT_THROUGH_STEPS in all, and the
 * stretches under the surface summed (linearly between steps); a ray still
 * under water at the end adds the depth left over the rate it climbs (the
 * surface held level beyond; at least 0.1). The light through the lip's
 * sheet comes along these rays (giant_water_along). */
double tl_giant_water_along(const tl_giant *g, const double from[3], const double dir[3],
                            int iterations);

/* How much of the sun (unit direction `sun`, toward it) a point sees past
 * the crest: its shadow, tl_giant_clear toward the sun with no spread
 * (giant_sunlit). */
double tl_giant_sunlit(const tl_giant *g, double x, double z, double y, const double sun[3]);

/* The water mirrors the sky through tl_giant_clear along its mirrored ray,
 * spread by this many times the slopes' deviation and at least
 * TL_GIANT_MIRROR_SPREAD_MIN radians; where the crest hides the sky it
 * mirrors the face, at TL_GIANT_FACE_FRESNEL. */
#define TL_GIANT_MIRROR_SPREAD     3.0
#define TL_GIANT_MIRROR_SPREAD_MIN 0.25
#define TL_GIANT_FACE_FRESNEL      0.05

/* The water's normals are blended toward up with distance
 * (water.normal_smooth_*): that stands for the detail a far, grazing view
 * averages away on a level sea. The giant wave's face is met nearly head
 * on, so TL_GIANT_FACE_SHARP_SHARE of the blend is lifted where the wave's
 * own slope rises from TL_GIANT_FACE_SHARP_FROM to TL_GIANT_FACE_SHARP_TO:
 * the small waves on a face 100 m away show (they were blended to a fifth
 * there, and the face read as a smooth, featureless wall). Lifted whole,
 * `final`'s one sample a pixel aliased the sharper face and drifted from
 * `reference` twice as far as half lifted (docs/rendering.md). */
#define TL_GIANT_FACE_SHARP_FROM  0.1
#define TL_GIANT_FACE_SHARP_TO    0.5
#define TL_GIANT_FACE_SHARP_SHARE 0.5

/* A small wave's facet on the face that the view meets more edge-on than
 * TL_GIANT_FACET_GRAZE of the cosine at which it meets the wave's own
 * surface is shaded as if met at that (tl_giant_facet_seen). A pixel's
 * one sample stands for all the facets its footprint covers, weighted by
 * how much of the view each takes: one met edge-on takes almost none of
 * it. Shaded as it was, each small wave's limb mirrored the sky at
 * Fresnel's grazing 1 and lost the light through the crest, in dark
 * hairlines down the glowing face (judges). Only on the face: the limit
 * grows as TL_GIANT_FACE_SHARP_* with the wave's slope, 0 off the wave and
 * on its level top (the sea's own facets, and the silhouette's mirror of
 * the horizon, stay). */
#define TL_GIANT_FACET_GRAZE 0.3

/* The light through the crest leaves the face by the phase function of the
 * view ray refracted in: refracted by a normal this share of the way from
 * the small waves' to the wave's own. Sunlight that has crossed metres of
 * water is scattered broadly by the time it leaves, so a small wave's tilt
 * changes it little; refracted by the small waves' normal alone, the
 * forward lobe lit each of them like a bump of gel (judges: "soft cloud
 * or jelly" seen from above). Their Fresnel and mirror keep the full
 * normal. */
#define TL_GIANT_GLOW_WAVE_SHARE 0.6

#endif
