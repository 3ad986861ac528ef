/* tl_prepare's parts shared between its files; not for other modules. */
#ifndef TL_PREPARE_INTERNAL_H
#define TL_PREPARE_INTERNAL_H

#include "tl_prepare.h"

/* The pixels where the renderer draws the giant wave's program, into
 * u->plan.giant_rect (tl_prepare_rect.c). Needs u's giant-wave, sun and depth
 * uniforms filled. */
void tl_prepare_giant_rect(const tl_scene *s, tl_frame_uniforms *u);
/* The pixels where the renderer draws the wake's foam, into u->plan.wake_rect
 * (tl_prepare_rect.c). Needs u's features, wake groups, depth and
 * giant-wave uniforms filled. */
void tl_prepare_wake_rect(const tl_scene *s, tl_frame_uniforms *u);

/* The pixels that can show an object's mirror image, added to
 * u->plan.boat_mirror_rect (tl_prepare_rect.c): those of the model's bounding
 * box (its eight corners camera-relative, corner i at the maximum along
 * axis k where bit k of i is set) above the water plane `water`
 * (camera-relative y), mirrored in that plane. */
void tl_prepare_mirror_rect(const tl_scene *s, const double corner[8][3], double water,
                            tl_frame_uniforms *u);

/* The water's height along an object's sides, into o->wash_water
 * (tl_prepare_wash.c): the surface (ocean and giant wave) at
 * TL_WASH_STATIONS points along each side of its model's bounds, placed by
 * `model` (model -> camera-relative world, column-major), camera-relative;
 * the hull's wash rides on it. */
void tl_prepare_wash_water(const tl_scene *s, const tl_waves *w, const tl_giant *giant,
                           const tl_boat *b, const float model[16], tl_object_uniforms *o);

#endif
