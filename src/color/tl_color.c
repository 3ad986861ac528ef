/* The working spaces (tl_color.h). */
#include "color/tl_color.h"

#include <math.h>
#include <string.h>

int tl_color_working_parse(const char *name, tl_working_space *out)
{
    if (strcmp(name, "rec709") == 0)
        *out = TL_WORKING_REC709;
    else if (strcmp(name, "acescg") == 0)
        *out = TL_WORKING_ACESCG;
    else
        return -1;
    return 0;
}

const char *tl_color_working_name(tl_working_space space)
{
    return space == TL_WORKING_ACESCG ? "acescg" : "rec709";
}

void tl_color_working_chromaticities(tl_working_space space, double out[8])
{
    /* Rec.709 (ITU-R BT.709) with D65, and ACES AP1 (SMPTE ST 2065-1,
     * S-2014-004) with the ACES white. */
    static const double rec709[8] = {0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290};
    static const double ap1[8] = {0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767};
    memcpy(out, space == TL_WORKING_ACESCG ? ap1 : rec709, sizeof rec709);
}

tl_false_zone tl_color_false_zone(double stops)
{
    /* In the shader's order: the first test that holds decides. */
    if (!(stops >= TL_FALSE_COLOUR_BLACK))
        return TL_FALSE_CRUSHED;
    if (stops < TL_FALSE_COLOUR_SHADOW)
        return TL_FALSE_SHADOW;
    if (fabs(stops) < TL_FALSE_COLOUR_BAND)
        return TL_FALSE_MID;
    if (fabs(stops - 1.0) < TL_FALSE_COLOUR_BAND)
        return TL_FALSE_SKIN;
    if (stops >= TL_FALSE_COLOUR_CLIP)
        return TL_FALSE_CLIPPED;
    if (stops >= TL_FALSE_COLOUR_HIGHLIGHT)
        return TL_FALSE_NEAR_WHITE;
    return TL_FALSE_GREY;
}
