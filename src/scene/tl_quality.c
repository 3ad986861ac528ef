#include "tl_quality.h"

#include <string.h>

/* `seed` is the reference shader's own settings, kept verbatim so tideline
 * can always be compared with the look it started from. `final` uses the
 * same octave counts (the look authors see) and a finer hit epsilon;
 * `reference` is the slow ground truth the bench compares against. */
/* draft renders the ocean at half the output's size: nearly twice as fast
 * for a small loss against reference. Filtered shading is off there: at
 * half size it takes draft further from reference on the cutscenes, where
 * it brings preview and final closer. */
/* The pixel filter's sigma in preview and final: 0.6 px came closest to
 * reference on the cutscenes (wider blurs, and none, further). Draft's
 * half-size render, upscaled, gains most from 0.85 (wider only blurs). */
#define PIXEL_FILTER 0.6
/* Over-relaxed march steps: 1.3 takes final and preview less time and
 * brings them closer to reference (rays that ran out of steps at the
 * horizon now get there); 1.2 gained as much, 1.4 less, 1.6 was slower
 * than plain steps (more steps taken back). */
#define RELAX TL_QUALITY_MARCH_RELAX
/* With the prepass, a ray whose four coarser neighbours disagree marches
 * this many steps, then regula falsi searches the rest of their bracket
 * (grazing rays close on the water slowly: marched to the end they took
 * 40% of a calm frame's surface evaluations). What it may skip is a crest
 * tip the ray clips after those steps: on a sea twice as steep as the
 * default, under a pixel deep (docs/rendering.md, test_render). 8 steps
 * save final time for the same accuracy, 6 save draft and preview more for
 * a hair of it; fewer are slower (regula falsi then fails on longer
 * brackets). */
#define BUDGET_FINAL 8
#define BUDGET_FAST  6
/* polish: the march's hit stepped onto the normals' finer surface before
 * it is shaded (one Newton step): the largest gain in accuracy preview and
 * final have, for a small share of their time. draft, whose target is
 * time, leaves it off. `seed` keeps the shader's hit; `reference`
 * marches the normals' octaves, where the step is nil. */
/* The presets, every knob named (tl_quality documents each). */
static const tl_quality presets[] = {
    {
        .name = "draft",
        .march_octaves = 8,
        .normal_octaves = 18,
        .march_steps = 32,
        .hit_epsilon = 0.02,
        .normal_epsilon = 0.02,
        .spp = 1,
        .giant_iterations = 4,
        .spray_step = 4.0,
        .shaft_steps = 6,
        .mesh_scale = 1,
        .refine_steps = 0,
        .lod = true,
        .analytic_normals = true,
        .miss_at_start = false,
        .normalize_smoothed = true,
        .render_scale = 0.5,
        .filtered_shading = false,
        .pixel_filter = 0.85,
        .march_relax = RELAX,
        .march_prepass = true,
        .prepass_budget = BUDGET_FAST,
        .giant_prepass = true,
        .polish = false,
        .facing_normals = true,
    },
    {
        .name = "preview",
        .march_octaves = 10,
        .normal_octaves = 26,
        .march_steps = 48,
        .hit_epsilon = 0.01,
        .normal_epsilon = 0.01,
        .spp = 1,
        .giant_iterations = 5,
        .spray_step = 2.5,
        .shaft_steps = 10,
        .mesh_scale = 1,
        .refine_steps = 0,
        .lod = true,
        .analytic_normals = true,
        .miss_at_start = false,
        .normalize_smoothed = true,
        .render_scale = 1.0,
        .filtered_shading = true,
        .pixel_filter = PIXEL_FILTER,
        .march_relax = RELAX,
        .march_prepass = true,
        .prepass_budget = BUDGET_FAST,
        .giant_prepass = true,
        .polish = true,
        .facing_normals = true,
    },
    {
        .name = "final",
        .march_octaves = 12,
        .normal_octaves = 36,
        .march_steps = 96,
        .hit_epsilon = 0.005,
        .normal_epsilon = 0.01,
        .spp = 1,
        .giant_iterations = 6,
        .spray_step = 1.0,
        .shaft_steps = 16,
        .mesh_scale = 2,
        .refine_steps = 0,
        .lod = true,
        .analytic_normals = true,
        .miss_at_start = false,
        .normalize_smoothed = true,
        .render_scale = 1.0,
        .filtered_shading = true,
        .pixel_filter = PIXEL_FILTER,
        .march_relax = RELAX,
        .march_prepass = true,
        .prepass_budget = BUDGET_FINAL,
        .giant_prepass = true,
        .polish = true,
        .facing_normals = true,
    },
    /* Converged: every octave the normals use is marched too, a hit is
     * 0.1 mm, refined, normals exact, and 64 stratified samples average
     * the pixel (no level of detail: it is the brute-force answer LOD
     * approximates; plain march steps). Its doubled self differs from it
     * by the samples alone, and 16 left too much noise; 64 bring three of
     * the four cutscenes past the 45 dB aim (docs/quality.md, "Is
     * `reference` converged?"). */
    {
        .name = "reference",
        .march_octaves = 48,
        .normal_octaves = 48,
        .march_steps = 1000,
        .hit_epsilon = 0.0001,
        .normal_epsilon = 0.002,
        .spp = 64,
        .giant_iterations = 10,
        .spray_step = 0.5,
        .shaft_steps = 64,
        .mesh_scale = 3,
        .refine_steps = 4,
        .lod = false,
        .analytic_normals = true,
        .miss_at_start = false,
        .normalize_smoothed = true,
        .render_scale = 1.0,
        .filtered_shading = false,
        .pixel_filter = 0.0,
        .march_relax = 1.0,
        .march_prepass = false,
        .prepass_budget = 0,
        .giant_prepass = false,
        .polish = false,
        .facing_normals = true,
    },
    /* The reference shader has no giant wave: it gets final's inversion,
     * and its pixels march from a prepass over the wave's rectangle alone
     * (no shader image to keep there; the open water is the shader's own
     * march). */
    {
        .name = "seed",
        .march_octaves = 12,
        .normal_octaves = 36,
        .march_steps = 64,
        .hit_epsilon = 0.01,
        .normal_epsilon = 0.01,
        .spp = 1,
        .giant_iterations = 6,
        .spray_step = 4.0,
        .shaft_steps = 0,
        .mesh_scale = 1,
        .refine_steps = 0,
        .lod = false,
        .analytic_normals = false,
        .miss_at_start = true,
        .normalize_smoothed = false,
        .render_scale = 1.0,
        .filtered_shading = false,
        .pixel_filter = 0.0,
        .march_relax = 1.0,
        .march_prepass = false,
        .prepass_budget = 0,
        .giant_prepass = true,
        .polish = false,
        .facing_normals = false,
    },
};

int tl_quality_preset(const char *name, tl_quality *out, tl_error *err)
{
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++) {
        if (strcmp(presets[i].name, name) == 0) {
            *out = presets[i];
            return TL_OK;
        }
    }
    return tl_error_set(err, TL_ERR_USAGE, "unknown quality preset '%s' (known: %s)", name,
                        tl_quality_names());
}

const char *tl_quality_names(void)
{
    return "draft, preview, final, reference, seed";
}

tl_quality tl_quality_default(void)
{
    return presets[2];
}
