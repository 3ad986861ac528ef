/* A breaking giant wave the lip's and the spray's tests share
 * (test_giant_lip.c, test_spray_march.c). Header-only. */
#ifndef TL_BREAKING_TEST_H
#define TL_BREAKING_TEST_H

#include <math.h>

#include "tl_gl_test.h"

/* A breaking wave whose peak broke `age` seconds before t, centred on
 * (cx, cz) with the crest on the centre line there. */
static inline void breaking_scene(tl_scene *s, double t, double age, double cx, double cz)
{
    tl_scene_defaults(s);
    s->time = t;
    s->giant.enabled = true;
    s->giant.height = 16.0;
    s->giant.wavelength = 100.0;
    s->giant.width = 160.0;
    s->giant.steepness = 0.75;
    s->giant.curve_strength = 0.6;
    s->giant.angle = 20.0 * M_PI / 180.0;
    s->giant.center[0] = cx;
    s->giant.center[1] = cz;
    s->giant.arrival = t;
    s->giant.peak = -20.0;
    s->giant.breaking = true;
    s->giant.break_time = t - age;
    s->giant.peel_speed = 7.0;
    s->giant.spray = 1.5;
}

#endif
