/* tl_quality: every knob that trades speed for accuracy, grouped into
 * named presets. `tideline bench` (later) measures each preset against
 * `reference`; nothing else in the renderer hard-codes these numbers. */
#ifndef TL_QUALITY_H
#define TL_QUALITY_H

#include <stdbool.h>

#include "core/tl_error.h"

/* Upper bound on wave octaves; the uniform arrays are sized by it. */
#define TL_MAX_OCTAVES 64
/* Upper bound on samples per pixel (each one a full ray march). */
#define TL_MAX_SPP 1024
/* Over-relaxation of the march's steps: the presets that relax use it, and
 * the march always steps by it inside the giant wave's bounding box (the
 * shaders' TL_MARCH_RELAX, from tl_renderer_defines). */
#define TL_QUALITY_MARCH_RELAX 1.3
/* The least share of one of quality.march_steps a step inside the giant
 * wave's box costs (shaders/march.glsl): a step the slope bound divides by
 * g costs 1/g, so a ray crossing the box gets as far as over the open sea,
 * and at most 1/this box steps run for each counted one (samples_per_draw
 * keeps a fragment under llvmpipe's loop limit with it). */
#define TL_QUALITY_GIANT_STEP_COST 0.25

typedef struct tl_quality {
    const char *name;
    int march_octaves;     /* octaves of the height field while marching */
    int normal_octaves;    /* octaves for the shading normal */
    int march_steps;       /* max adaptive steps between the two planes */
    double hit_epsilon;    /* metres above the surface that count as a hit */
    double normal_epsilon; /* finite-difference step for normals, metres */
    int spp;               /* stratified samples per pixel */
    int giant_iterations;  /* Newton steps inverting the giant wave's horizontal map */
    double spray_step;     /* metres of a ray in the giant wave's spray per step of its march */
    int shaft_steps;       /* samples of the light shafts along a ray under water (0: none) */
    int mesh_scale;        /* the hulls' pass: n x n samples a pixel (1: one, its edges aliased) */
    int refine_steps;      /* secant steps toward the surface after the march hits */
    bool lod;              /* fade octaves finer than the pixel's footprint to their mean */
    bool analytic_normals; /* the wave sum's exact gradient instead of finite differences */
    /* The reference shader's behaviours that tideline improves on, kept
     * for `seed` so it reproduces that shader's image (a third,
     * facing_normals, is last in the struct): */
    bool miss_at_start;      /* a ray out of steps reports where its march began */
    bool normalize_smoothed; /* renormalise the distance-smoothed normal (false: seed) */
    double render_scale;     /* the ocean renders at this share of the output's width and
                                height, then is upscaled (1: full size) */
    bool filtered_shading;   /* with lod: the faded octaves' slopes widen the reflection */
    double pixel_filter;     /* sigma, in output pixels, of the display image's 3x3 Gaussian
                                (0: none) */
    double march_relax;      /* over-relaxation of the ocean's march steps (1: plain steps) */
    bool march_prepass;      /* march one ray per 2x2 pixels first; the pixels then solve for
                                the hit between their four neighbours' */
    int prepass_budget;      /* with the prepass: march steps a ray whose four neighbours
                                disagree takes before regula falsi searches the rest of
                                their bracket (0: it marches to the end) */
    bool giant_prepass;      /* with march_prepass off: the prepass still runs over the giant
                                wave's rectangle, and only the wave's pixels start from it */
    bool polish;             /* one Newton step moves the march's hit onto the finer surface
                                of normal_octaves before it is shaded */
    bool facing_normals;     /* a shading normal the ray meets from behind is turned to face
                                it before the sky is reflected (false: seed) */
} tl_quality;

/* Known presets: draft, preview, final (the default), reference, seed. */
int tl_quality_preset(const char *name, tl_quality *out, tl_error *err);
/* Comma-separated preset names, for help and error texts. */
const char *tl_quality_names(void);
tl_quality tl_quality_default(void);

#endif
