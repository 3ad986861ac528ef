/* tl_color: the colour spaces tideline's frames are in. Its radiance is
 * linear Rec.709 (D65); an EXR's colour may be written in another working
 * space (ACEScg). The display transforms of a studio's OpenColorIO config
 * come through src/ocio; this module names the spaces and holds what the
 * renderer and the files need of them without OpenColorIO. */
#ifndef TL_COLOR_H
#define TL_COLOR_H

/* The working spaces of an EXR's colour. */
typedef enum tl_working_space { TL_WORKING_REC709 = 0, TL_WORKING_ACESCG = 1 } tl_working_space;

/* "rec709" or "acescg" into *out; 0, or -1 for another name. */
int tl_color_working_parse(const char *name, tl_working_space *out);
const char *tl_color_working_name(tl_working_space space);
/* The space's primaries and white (OpenEXR's chromaticities: red, green,
 * blue and white x y). */
void tl_color_working_chromaticities(tl_working_space space, double out[8]);

/* A display transform baked into a 3D table for the display pass
 * (src/ocio bakes it, shaders/present.frag reads it trilinearly): n x n x n
 * RGB values, red fastest, over a log2 shaper: entry i along an axis holds
 * the output for a radiance (after exposure) of
 * 2^(LO + (HI - LO) * i / (n - 1)) in that channel; below 2^LO, and 0, the
 * first entry's. Two entries a stop. */
/* The preview's false colour (X; shaders/false_colour.frag): zones of a
 * pixel's luminance after the exposure, in stops from mid-grey (0.18).
 * Below BLACK the display's tonemap crushes it to black; from HIGHLIGHT
 * it nears white and from CLIP it clips; within BAND of 0 is mid-grey,
 * within BAND of +1 a stop over (where skin sits). */
#define TL_FALSE_COLOUR_BLACK     -6.0
#define TL_FALSE_COLOUR_SHADOW    -4.5
#define TL_FALSE_COLOUR_BAND      0.25
#define TL_FALSE_COLOUR_HIGHLIGHT 4.0
#define TL_FALSE_COLOUR_CLIP      5.5
typedef enum tl_false_zone {
    TL_FALSE_CRUSHED,    /* purple */
    TL_FALSE_SHADOW,     /* blue */
    TL_FALSE_GREY,       /* grey, as bright as shown */
    TL_FALSE_MID,        /* green */
    TL_FALSE_SKIN,       /* pink */
    TL_FALSE_NEAR_WHITE, /* yellow */
    TL_FALSE_CLIPPED     /* red */
} tl_false_zone;
/* The zone of a luminance `stops` from mid-grey (the shader's mirror). */
tl_false_zone tl_color_false_zone(double stops);

#define TL_COLOR_SHAPER_LO -14.0
#define TL_COLOR_SHAPER_HI 10.0
#define TL_COLOR_LUT_SIZE  49

#endif
