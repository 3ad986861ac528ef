/* The Kelvin wake's waves: the pattern a boat at steady speed leaves on
 * deep water, by stationary phase. Behind the boat, inside the wedge of
 * half-angle 19.47 deg, two systems of waves meet at each point: the
 * transverse waves across the track (wavelength 2 pi U^2 / g) and the
 * divergent waves along the wedge's arms, both taller toward the cusp
 * line and lower as they spread. The CPU mirror of shaders/wake.glsl's
 * wake_kelvin_slope (test_wake probes it). */
#ifndef TL_KELVIN_H
#define TL_KELVIN_H

/* Their height at the boat is this share of the hull's length at a
 * Froude number U / sqrt(g L) of TL_KELVIN_FROUDE and above (quadratic
 * below: a slow boat's waves are low). */
#define TL_KELVIN_HEIGHT 0.05
#define TL_KELVIN_FROUDE 0.4
/* At the cusp line, where the two systems meet, the waves are taller by
 * 1 + TL_KELVIN_CUSP_GAIN (stationary phase's caustic, rounded off). */
#define TL_KELVIN_CUSP_GAIN 0.8
/* The crests break white along the cusp line (tl_kelvin_whitecap): where
 * 1 - 8 r^2 (0 on the line) is under TL_KELVIN_WHITECAP_CUSP, fading as
 * e^(-behind / (TL_KELVIN_WHITECAP_LENGTHS hull lengths)). */
#define TL_KELVIN_WHITECAP_CUSP    0.5
#define TL_KELVIN_WHITECAP_LENGTHS 2.5

/* The waves' slope d height / d (behind, across) at a point `behind`
 * metres back along the track from a boat `length` metres long moving at
 * `speed` m/s, `across` metres to its side; waves shorter than four of
 * the pixel's `footprint` (metres) are faded out. 0 outside the wedge. */
void tl_kelvin_slope(double behind, double across, double speed, double length, double footprint,
                     double slope[2]);

/* How white the Kelvin waves' crests are at that point, in [0, 1]: on the
 * crests (cos of the divergent waves' phase near 1) along the cusp line,
 * over the first few hull lengths, as the Froude factor squared. */
double tl_kelvin_whitecap(double behind, double across, double speed, double length);

#endif
