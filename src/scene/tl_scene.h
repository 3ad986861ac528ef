/* tl_scene: everything one frame needs, in world units and double.
 *
 * World axes: +Y up, +Z north, +X east. Yaw and azimuth are compass
 * angles: 0 looks along +Z, positive turns toward +X. Pitch and elevation
 * are positive upward. The mean water plane is y = 0; waves occupy
 * [-ocean.depth, 0] like the reference shader.
 *
 * A scene is plain data: scene evaluation (from a timeline or from flags)
 * fills it, tl_prepare turns it into what the GPU needs. */
#ifndef TL_SCENE_H
#define TL_SCENE_H

#include <stdbool.h>

#include "scene/tl_quality.h"

typedef struct tl_camera {
    double position[3];      /* world metres */
    double yaw, pitch, roll; /* radians */
    double vfov;             /* vertical field of view, radians, in (0, pi) */
} tl_camera;

/* How the camera's orientation is given: tideline's own yaw, pitch and
 * roll, or Blender's rotation modes (its Euler orders, quaternion, axis
 * and angle), so that a shot laid out in Blender keeps its curves. */
typedef enum tl_rotation_mode {
    TL_ROTATION_YAW_PITCH_ROLL,
    TL_ROTATION_XYZ,
    TL_ROTATION_XZY,
    TL_ROTATION_YXZ,
    TL_ROTATION_YZX,
    TL_ROTATION_ZXY,
    TL_ROTATION_ZYX,
    TL_ROTATION_QUATERNION,
    TL_ROTATION_AXIS_ANGLE,
} tl_rotation_mode;

/* Blender's sensor fit: which side of the frame the sensor spans. */
typedef enum tl_sensor_fit {
    TL_SENSOR_AUTO,
    TL_SENSOR_HORIZONTAL,
    TL_SENSOR_VERTICAL
} tl_sensor_fit;

/* The camera as a 3D package gives it (tl_scene_apply_rig turns it into
 * tl_camera's yaw, pitch, roll and field of view). Rotations are in
 * Blender's world axes (Z up, Y north) and its camera's (looking along its
 * own -Z, +Y up). */
typedef struct tl_camera_rig {
    tl_rotation_mode rotation_mode;
    double euler[3];                    /* X, Y, Z angles, radians, applied in the mode's order */
    double quat_w, quat[3];             /* W, and X Y Z (normalised before use, as Blender does) */
    double axis_angle, axis[3];         /* radians about the axis (normalised) */
    double focal_length;                /* mm; 0: the field of view is camera.fov */
    double sensor_width, sensor_height; /* mm */
    tl_sensor_fit sensor_fit;
} tl_camera_rig;

typedef struct tl_sun {
    double elevation, azimuth; /* radians */
    double intensity;          /* peak radiance of the disc (reference: 210) */
    double sharpness;          /* exponent of the disc lobe (reference: 720) */
    double angular_diameter;   /* physical sky: the disc, radians (0.53 deg) */
} tl_sun;

/* The exp(sin) wave model with derivative drag (seed 002). */
typedef struct tl_ocean {
    double depth;            /* metres between crest plane and trough plane */
    double drag;             /* domain-warp strength (0.38) */
    double frequency;        /* first octave, radians per metre (1.0) */
    double frequency_growth; /* per octave (1.18) */
    double speed;            /* first octave, radians per second (2.0) */
    double speed_growth;     /* per octave: dispersion (1.07) */
    double weight_ratio;     /* per octave amplitude weight ratio (0.8) */
    double direction_step;   /* radians between octave directions (1232.399963) */
    double radial_phase;     /* phase per metre from the origin (0.1) */
    double floor_depth;      /* metres to a sandy sea floor; 0: none, the deep sea (0) */
} tl_ocean;

typedef struct tl_water {
    double absorption[3];        /* per metre, R G B (pure water: 0.34, 0.057, 0.009) */
    double scattering;           /* per metre, grey: particles that light the water body */
    double color_at_distance[3]; /* the colour white light takes after color_distance */
    double color_distance;       /* metres; > 0 sets the extinction from the colour above */
    double ior;                  /* refractive index (1.333) */
    double foam;                 /* scale of every foam term, 0..1 (1) */
    double fresnel_f0;           /* Schlick F0 (0.04) */
    double capillaries;        /* the capillary ripples' slope variance over the waves' own (0.5) */
    double scatter_color[3];   /* linear RGB (0.0293, 0.0698, 0.1717) */
    double scatter_strength;   /* (0.1) */
    double scatter_base;       /* scattering at the wave troughs (0.2) */
    double normal_smooth_max;  /* max blend of far normals toward up (0.8) */
    double normal_smooth_rate; /* per metre inside the sqrt (0.01) */
    double normal_smooth_gain; /* (1.1) */
} tl_water;

typedef enum tl_sky_model {
    TL_SKY_PHYSICAL = 0, /* Rayleigh + Mie + ozone, multiple scattering (src/sky/) */
    TL_SKY_SEED,         /* the reference shader's cheap atmosphere, as it was */
} tl_sky_model;

typedef struct tl_sky {
    tl_sky_model model;
    double brightness;        /* seed: scale of the cheap atmosphere (0.5) */
    double sun_illuminance;   /* physical: the sun's illuminance above the air */
    double turbidity;         /* physical: aerosols (Mie) relative to a clear day (1) */
    double ozone;             /* physical: ozone relative to the standard layer (1) */
    double ground_albedo;     /* physical: the planet's surface below (0.1: sea) */
    double planet_radius;     /* km (6360) */
    double atmosphere_height; /* km (100) */
} tl_sky;

/* Distance fog: extinction plus in-scatter toward `color`, thinning with
 * height above the water. */
typedef struct tl_fog {
    double density;  /* per metre at the water; 0 turns fog off */
    double color[3]; /* linear RGB */
    double height;   /* metres over which the density falls by e */
} tl_fog;

typedef enum tl_underwater_mode {
    TL_UNDERWATER_AUTO = 0, /* under water when the camera is below the surface */
    TL_UNDERWATER_ON,
    TL_UNDERWATER_OFF,
} tl_underwater_mode;

/* The most suspended motes per cubic metre: one in each cell of their grid
 * (TL_PARTICLE_CELL, src/optics/tl_optics.h). */
#define TL_PARTICLE_MAX_DENSITY 64.0

typedef struct tl_underwater {
    tl_underwater_mode mode;
    double caustics;  /* the caustics' strength: 0 off, 1 physical (1) */
    double shafts;    /* the light shafts' strength: 0 off, 1 physical (1) */
    double particles; /* suspended motes per cubic metre near the camera (0: none) */
} tl_underwater;

/* The scripted giant wave (seed 003, "North Star"): one Gerstner crest
 * with width and falloff masks, faded in and out by the timeline. The
 * model, its clamps and its cost are in docs/rendering.md; the CPU mirror
 * is src/waves/tl_giant.c. */
typedef struct tl_giant_wave {
    bool enabled;
    double height;           /* crest amplitude, metres */
    double width;            /* extent across the travel direction, metres */
    double wavelength;       /* metres */
    double angle;            /* travel direction, compass radians */
    double center[2];        /* world x, z of the point the crest travels toward */
    double falloff;          /* softness of the width/crest masks, metres */
    double phase;            /* radians along the travel direction, added to the travel */
    double arrival;          /* seconds: when the crest reaches the centre (phase 0) */
    double speed;            /* multiple of the deep-water phase speed sqrt(g / k) */
    double steepness;        /* Gerstner steepness q·k·A in [0, 1] */
    double curve_strength;   /* crest curl toward the travel direction, [0, 1] */
    double fade;             /* 0 invisible .. 1 full strength */
    double peak;             /* metres across from the centre line to the crest's peak */
    double taper;            /* how much lower the ends stand than the peak, [0, 1] */
    double bow;              /* metres the crest's ends lag behind its peak */
    double variation;        /* seeded height variation along the crest, a fraction */
    int seed;                /* seed of that variation */
    bool breaking;           /* the crest breaks, from the peak outward */
    double break_time;       /* seconds: when the lip begins to throw at the peak */
    double peel_speed;       /* m/s the break runs along the crest */
    double break_drop;       /* fraction of its height a broken crest loses */
    double spray;            /* amount of spray off the crest and at the bow */
    double spray_wind;       /* m/s of wind blowing the spindrift back off the crest */
    double ride;             /* share of the wave's push the small waves ride, [0, 1] */
    double foam_compression; /* Jacobian below which the surface foams, (0, 1] */
    double foam_trail;       /* metres over which foam fades behind the crest */
    double scatter;          /* strength of the light through the crest */
    double scatter_forward;  /* forward lobe g of the two-lobe phase function */
    double scatter_back;     /* backward lobe g (the lobe is mirrored) */
    double caustics;         /* share of the far side's caustic web in that light, [0, 1] */
    double scatter_color[3]; /* that light's colour: the water's transmittance (linear RGB)
                                a quarter of the way down the crest */
} tl_giant_wave;

/* Bounds of the built-in boat in model units (src/mesh/tl_mesh_boat.c;
 * test_mesh checks them): one unit long, waterline at y = 0. */
#define TL_BOAT_BUILTIN_MIN                                                                        \
    {                                                                                              \
        -0.17, -0.1, -0.5                                                                          \
    }
#define TL_BOAT_BUILTIN_MAX                                                                        \
    {                                                                                              \
        0.17, 0.5012, 0.5                                                                          \
    }
#define TL_BOAT_BEAM_RATIO 0.34
/* The built-in boat's own paint, linear RGB: its topsides and its
 * wheelhouse (src/mesh/tl_mesh_boat.c; test_mesh checks them). */
#define TL_BOAT_PAINT                                                                              \
    {                                                                                              \
        0.60, 0.58, 0.53                                                                           \
    }
#define TL_BOAT_CABIN_PAINT                                                                        \
    {                                                                                              \
        0.66, 0.66, 0.62                                                                           \
    }

/* Past positions of the boat kept for its wake. */
#define TL_WAKE_POINTS 24
/* The wake's segments in groups of this many, each with a bounding circle
 * (tl_frame_uniforms.wake_groups): a pixel loops only over the groups that
 * can reach it. */
#define TL_WAKE_GROUP  4
#define TL_WAKE_GROUPS ((TL_WAKE_POINTS - 1 + TL_WAKE_GROUP - 1) / TL_WAKE_GROUP)
/* Only a boat under way churns white water: the wake's coverage scales by
 * a smoothstep of the boat's speed there, none below TL_WAKE_SPEED_NONE m/s
 * (drifting), all of it from TL_WAKE_SPEED_FULL (4 knots, a slow cruise).
 * Where boat.wake times the most of that is under TL_WAKE_LEAST, no foam
 * can form (it needs about 0.2) and the bubbles would be under 2% of the
 * daylight: the wake's feature stays off, and costs nothing. */
#define TL_WAKE_SPEED_NONE 0.3
#define TL_WAKE_SPEED_FULL 2.0
#define TL_WAKE_LEAST      0.05
/* The churned band behind the stern: 1 half-beam wide (e-fold) at the
 * stern, wider by 1 + TL_WAKE_SPREAD sqrt(behind / hull length) (turbulence
 * widens slowly; the wedge's arms are waves, not foam). Its foam thins as
 * it ages, to TL_WAKE_OLD_OPACITY of a fresh patch's opacity. */
#define TL_WAKE_SPREAD      0.6
#define TL_WAKE_OLD_OPACITY 0.15

/* The most floating objects a scene holds: the boat and 15 declared with
 * `boat NAME` (each has its own slot in the ocean pass's uniform block,
 * src/prepare/tl_prepare.h, tl_object_uniforms). */
#define TL_OBJECT_MAX 16

/* A floating object's pose and the knobs of its model and floating (the
 * boat, and each object a timeline declares). */
typedef struct tl_boat {
    bool enabled;       /* true when the timeline has a boat path */
    bool visible;       /* drawn (hull, reflection, wake); off renders the water plate */
    double position[3]; /* world metres; y: the model's waterline, floating */
    double heading;     /* compass radians, from the path tangent */
    double pitch, roll; /* radians from floating: bow up, starboard down positive */
    double size;        /* hull length of the built-in boat, metres */
    double model_yaw;   /* turns a model whose bow is not along +Z */
    double model_scale; /* metres per model unit of a loaded model */
    double float_time;  /* response time of the floating spring, seconds */
    double wake;        /* strength of the wake's foam, 0 = none */
    double wake_time;   /* seconds over which the wake's foam fades (e-fold) */
    double lights;      /* navigation lights' share of their emission, 0 = off */
    bool shadows;       /* the sun casts the boat's shadows (TL_FEATURE_BOAT_SHADOW) */
    /* Derived by evaluation from the model: */
    double scale;                      /* metres per model unit */
    double model_min[3], model_max[3]; /* the model's bounds, model units */
    double length, beam;               /* hull length and beam, metres */
    /* How fast the water rises against the bow, m/s (0 unless floated by
     * a timeline): it throws the bow's spray. */
    double impact;
    double spray; /* boat.spray: the bow spray's strength, 0 = none */
    /* boat.paint, boat.cabin_paint: the built-in boat's topsides and
     * wheelhouse colours, linear RGB (set only: its mesh is built once). */
    double paint[3], cabin_paint[3];
    int model; /* which of the loaded models it is drawn with (tl_cutscene.models) */
    /* The wake: where the boat was, every wake_step seconds back from now
     * (wake_path[0] is the boat itself), world x z. */
    double wake_path[TL_WAKE_POINTS][2];
    /* How far along the boat's path each of those points lies, metres from
     * the path's start (tl_path_distance): the same wherever the boat is
     * now, so the foam's texture stays where the boat left it. */
    double wake_along[TL_WAKE_POINTS];
    double wake_step;
} tl_boat;

/* render.white_depth's range, metres: deeper, the default water's red
 * daylight is under 1e-9 of what came in, past any balance. */
#define TL_WHITE_DEPTH_MAX 50.0

typedef struct tl_scene {
    double time; /* seconds since the start of the timeline */
    int width, height;
    double exposure; /* linear multiplier before tonemapping (2.0) */
    double ev;       /* exposure value in stops: each +1 halves the light (0) */
    /* Exposure that meters itself (tl_exposure.h): its strength, 0 (off,
     * `exposure` alone) to 1 (the meter's alone), and the adaptation's time
     * constant, seconds (1). */
    double auto_exposure;
    double adapt_time;
    double bloom; /* share of the light spread into glare in the display image */
    /* The white balance (display only): the scene's colour shown as
     * neutral, linear Rec.709 (1 1 1), times the daylight left after
     * `white_depth` metres of the scene's water (0). */
    double white_point[3];
    double white_depth;
    tl_camera camera;
    tl_camera_rig rig; /* the camera as Blender gives it (camera.rotation_mode, .focal_length) */
    tl_sun sun;
    tl_ocean ocean;
    tl_water water;
    tl_sky sky;
    tl_fog fog;
    tl_underwater underwater;
    tl_giant_wave giant;
    /* The floating objects: `boat` is the timeline's boat (object 0), the
     * fleet the objects it declares with `boat NAME`, in their order. */
    tl_boat boat;
    tl_boat fleet[TL_OBJECT_MAX - 1];
    int objects; /* how many of them the scene has, the boat included */
    tl_quality quality;
} tl_scene;

/* Floating object k (0: the boat). */
static inline tl_boat *tl_scene_object(tl_scene *s, int k)
{
    return k == 0 ? &s->boat : &s->fleet[k - 1];
}
static inline const tl_boat *tl_scene_object_const(const tl_scene *s, int k)
{
    return k == 0 ? &s->boat : &s->fleet[k - 1];
}

/* The default scene: the reference shader's ocean, a camera 1.5 m above
 * the water looking slightly down toward a low sun. */
void tl_scene_defaults(tl_scene *scene);

/* Unit vector toward the sun from elevation and azimuth. */
void tl_scene_sun_direction(const tl_sun *sun, double out[3]);

/* The camera's yaw, pitch and roll from a Blender rotation (rig's mode
 * but yaw_pitch_roll), and its vertical field of view from a lens
 * (rig's focal_length > 0) on a frame of width x height, as Blender fits
 * the sensor. Nothing for what the rig leaves to tl_camera. */
void tl_scene_apply_rig(const tl_camera_rig *rig, int width, int height, tl_camera *camera);
/* The 3x3 rotation (row-major) of a rig's Blender rotation, in Blender's
 * axes. */
void tl_scene_rig_rotation(const tl_camera_rig *rig, double m[9]);

/* Camera basis (right, up, forward), all unit vectors, from yaw/pitch/roll. */
void tl_scene_camera_basis(const tl_camera *cam, double right[3], double up[3], double forward[3]);

/* Sets yaw and pitch so the camera looks at `target` (roll unchanged).
 * Fails if the target coincides with the camera. */
int tl_scene_camera_look_at(tl_camera *cam, const double target[3], tl_error *err);

/* Checks ranges (sizes, fov, finite values). The message names the field. */
int tl_scene_validate(const tl_scene *scene, tl_error *err);

#endif
