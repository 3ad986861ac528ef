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
#define RELAX 1.3
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
#define BUDGET_FAST 6
/* polish: the march's hit stepped onto the normals' finer surface before
 * it is shaded (one Newton step): the largest gain in accuracy preview and
 * final have, for a small share of their time. draft, whose target is
 * time, leaves it off. `seed` keeps the shader's hit; `reference`
 * marches the normals' octaves, where the step is nil. */
/* One preset a row, its knobs in the order of tl_quality. */
/* clang-format off */
static const tl_quality presets[] = {
    /* name  march normal steps hit normal spp giant refine lod analytic start renorm scale
     * filtered pixel_filter relax prepass budget giant_prepass polish facing */
    {"draft", 8, 18, 32, 0.02, 0.02, 1, 4, 0, true, true, false, true, 0.5, false, 0.85, RELAX,
     true, BUDGET_FAST, true, false, true},
    {"preview", 10, 26, 48, 0.01, 0.01, 1, 5, 0, true, true, false, true, 1.0, true, PIXEL_FILTER,
     RELAX, true, BUDGET_FAST, true, true, true},
    {"final", 12, 36, 96, 0.005, 0.01, 1, 6, 0, true, true, false, true, 1.0, true, PIXEL_FILTER,
     RELAX, true, BUDGET_FINAL, true, true, true},
    /* Converged: every octave the normals use is marched too, a hit is
     * 0.1 mm, refined, normals exact, and 64 stratified samples average
     * the pixel (no level of detail: it is the brute-force answer LOD
     * approximates; plain march steps). Its doubled self differs from it
     * by the samples alone, and 16 left too much noise; 64 bring three of
     * the four cutscenes past the 45 dB aim (docs/quality.md, "Is
     * `reference` converged?"). */
    {"reference", 48, 48, 1000, 0.0001, 0.002, 64, 10, 4, false, true, false, true, 1.0, false, 0.0,
     1.0, false, 0, false, false, true},
    /* The reference shader has no giant wave: it gets final's inversion,
     * and its pixels march from a prepass over the wave's rectangle alone
     * (no shader image to keep there; the open water is the shader's own
     * march). */
    {"seed", 12, 36, 64, 0.01, 0.01, 1, 6, 0, false, false, true, false, 1.0, false, 0.0, 1.0,
     false, 0, true, false, false},
};
/* clang-format on */

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
