// The whole water surface: the ocean plus every feature that changes its
// height. tl_waves_surface_height is the same sum in double.

// `footprint`: the water a pixel covers there, for the ocean's level of
// detail (0: every octave); the giant wave is always whole.
float surface_height(vec2 p, int octaves, float footprint)
{
#ifdef TL_FEATURE_GIANT_WAVE
    GiantSample g = giant_sample(p);
    return waves_height(giant_ride(p, g), octaves, footprint * giant_ride_squeeze(g)) + g.height;
#else
    return waves_height(p, octaves, footprint);
#endif
}

#ifdef TL_FEATURE_POLISH
// The march stops where the ray crosses the surface of quality.march_octaves
// octaves; the normal sums quality.normal_octaves, a surface that lies a
// few centimetres off it, so shading at the march's hit draws the fine
// ripples where the ray does not meet them. One Newton step on the finer
// surface's height, with its exact gradient, moves t onto it, and the
// normal is then evaluated where the ray meets the surface it describes
// (quality.polish: the largest gain against `reference` at `preview`
// and `final`). Held where a step cannot be trusted: a ray within
// TL_POLISH_GRAZE of the surface's tangent, whose step could leap to
// another wave, and steps beyond TL_POLISH_MOST of t (the finer octaves
// move the surface by centimetres; a longer step is a bad linearisation).
// The step's height sums TL_POLISH_EXTRA octaves past the march's, not
// all of the normals': the octaves beyond those move the surface by a
// millimetre or two (test_polish), and only the normal needs them. 9 more
// octaves came as close to `reference` as all of the normals' and cost
// less; 6 or 3 lost accuracy.
#define TL_POLISH_GRAZE 0.02
#define TL_POLISH_MOST 0.01
#define TL_POLISH_EXTRA 9
float surface_polish(vec3 ray, float t)
{
    vec3 p = vec3(0.0, u_cam_height, 0.0) + ray * t;
    vec2 grad;
    float slope_var;
    const int octaves = min(TL_NORMAL_OCTAVES, TL_MARCH_OCTAVES + TL_POLISH_EXTRA);
#ifdef TL_FEATURE_GIANT_WAVE
    GiantSample giant = giant_sample(p.xz);
    float h = (waves_value_grad(giant_ride(p.xz, giant), octaves,
                                t * u_lod_angle * giant_ride_squeeze(giant), grad, slope_var) -
               1.0) *
              u_depth;
    grad = giant_ride_grad(grad * u_depth, giant) + giant.grad;
    h += giant.height;
#else
    float h = (waves_value_grad(p.xz, octaves, t * u_lod_angle, grad, slope_var) - 1.0) * u_depth;
    grad *= u_depth;
#endif
    // d(p.y - h)/dt along the ray: negative where a ray from above meets
    // the surface, positive from below.
    float rate = ray.y - dot(grad, ray.xz);
    float step = (h - p.y) / rate;
    if (!(abs(rate) > TL_POLISH_GRAZE) || isnan(step))
        return t;
    return t + clamp(step, -TL_POLISH_MOST * t, TL_POLISH_MOST * t);
}
#endif
