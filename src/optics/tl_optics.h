/* tl_optics: the optics of the water and the air, on the CPU in double:
 * the exact Fresnel reflectance at the water surface, Snell's window, the
 * water body's extinction, and the fog's optical depth. shaders/optics.glsl
 * holds the same formulas; tests compare the two. docs/rendering.md shows
 * the equations. */
#ifndef TL_OPTICS_H
#define TL_OPTICS_H

#include "scene/tl_scene.h"

/* Reflectance of unpolarised light at a smooth interface, light arriving
 * in the medium of index n1 at cos_i from the normal, leaving into n2:
 * (r_s² + r_p²) / 2 from the Fresnel equations; 1 under total internal
 * reflection. */
double tl_optics_fresnel(double cos_i, double n1, double n2);

/* Half-angle of Snell's window seen from a medium of index n into air:
 * asin(1 / n) radians (48.6° for water). */
double tl_optics_snell_window(double n);

/* Extinction per metre of the water body, R G B. With
 * water.color_distance > 0: -ln(color_at_distance) / color_distance (the
 * colour white light takes after that distance; seed 003's "colour at
 * distance"), else water.absorption + water.scattering. Never zero (the
 * shader holds the scattering albedo at 1 at most). */
void tl_optics_water_extinction(const tl_water *w, double sigma[3]);

/* Optical depth of the fog along a ray from height y0 (metres above the
 * mean water) with vertical direction component ray_y, over `dist` metres:
 * the integral of density · exp(-y / height) along it. */
double tl_optics_fog_depth(double density, double height, double y0, double ray_y, double dist);

#endif
