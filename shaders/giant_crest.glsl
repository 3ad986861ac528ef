// The giant wave's crest line: its envelope along the crest (the width
// mask, the taper from the peak, the seeded variation, the settling after
// the break) and how much of the sky a point of the water sees past it.
// giant.glsl's height field builds on it; the ocean's program without the
// wave (outside the wave's rectangle, TL_GIANT_MIRROR) includes it alone,
// so that the water there mirrors the wave's face as the wave's program
// does. src/waves/tl_giant.c is the same in double.

float giant_smooth(float x, out float dx)
{
    x = clamp(x, 0.0, 1.0);
    dx = 6.0 * x * (1.0 - x);
    return x * x * (3.0 - 2.0 * x);
}

// Wave coordinates (s, w) of camera-relative p.
vec2 giant_coords(vec2 p)
{
    vec2 d = u_giant_frame.xy;
    return u_giant_frame.zw + vec2(dot(d, p), dot(vec2(d.y, -d.x), p));
}

// Distance from the peak toward the end on w's side (0 at the peak, 1 at
// the end) and its derivative in *dr.
float giant_from_peak(float w, out float dr)
{
    float H = u_giant_mask.z, p = u_giant_crest.x;
    dr = w >= p ? 1.0 / (H - p) : -1.0 / (H + p);
    return min(w >= p ? (w - p) / (H - p) : (p - w) / (H + p), 1.0);
}

// The crest's lag behind its peak at w (<= 0) and its derivative in *db.
float giant_bow(float w, out float db)
{
    float dr, r = giant_from_peak(w, dr);
    db = r < 1.0 ? -2.0 * u_giant_crest.z * r * dr : 0.0;
    return -u_giant_crest.z * r * r;
}

#ifdef TL_FEATURE_GIANT_BREAK
// Seconds since the lip began to throw at w (negative before).
float giant_break_age(float w)
{
    float x = w - u_giant_crest.x;
    return u_giant_break.x -
           (sqrt(x * x + TL_GIANT_PEEL_ROUND * TL_GIANT_PEEL_ROUND) - TL_GIANT_PEEL_ROUND) /
               u_giant_break.y;
}
#endif

// How far the break has gone at w: 0 before the lip throws, 1 once it has
// landed. Without a scripted break, the crest's compression says how much
// it breaks, all along (u_giant_foam.w).
float giant_breaking(float w)
{
#ifdef TL_FEATURE_GIANT_BREAK
    return smoothstep(0.0, 1.0, giant_break_age(w) / u_giant_break.z);
#else
    return u_giant_foam.w;
#endif
}

// The crest's envelope at w across: the fade times the width mask, the
// taper from the peak, the seeded variation and the settling after the
// break; its derivative in *dl.
float giant_lambda(float w, out float dl)
{
    float ds, dr;
    float fw = u_giant_mask.w;
    float sgn = w < 0.0 ? -1.0 : 1.0;
    float m = 1.0 - giant_smooth((abs(w) - (u_giant_mask.z - fw)) / fw, ds);
    float dm = -ds / fw * sgn;
    float r = giant_from_peak(w, dr);
    float taper = 1.0 - u_giant_crest.y * r * r;
    float dtaper = r < 1.0 ? -2.0 * u_giant_crest.y * r * dr : 0.0;
    const vec3 weights = vec3(TL_GIANT_VARIATION_WEIGHTS);
    vec3 a = u_giant_vary_k * w + u_giant_vary_phase;
    float vary = 1.0 + u_giant_crest.w * dot(weights, sin(a));
    float dvary = u_giant_crest.w * dot(weights * u_giant_vary_k, cos(a));
    float settle = 1.0, dsettle = 0.0;
#ifdef TL_FEATURE_GIANT_BREAK
    float T = u_giant_break.z, dx;
    settle = 1.0 - u_giant_break.w * giant_smooth((giant_break_age(w) - T) / (2.0 * T), dx);
    float x = w - u_giant_crest.x;
    dsettle = u_giant_break.w * dx / (2.0 * T * u_giant_break.y) *
              (x / sqrt(x * x + TL_GIANT_PEEL_ROUND * TL_GIANT_PEEL_ROUND));
#endif
    float F = u_giant_fade;
    dl = F * (dm * taper * vary * settle + m * dtaper * vary * settle + m * taper * dvary * settle +
              m * taper * vary * dsettle);
    return F * m * taper * vary * settle;
}

// How much of the sky in (unit, upward) direction `sun` a point of the
// water at camera-relative p and height y sees past the wave's crest: 0
// where the crest hides it, 1 in the open (tl_giant_clear). The crest is
// the line across the travel where s0 = 0: at s = bow + lambda·C/k (the
// curl's push, D(0) = C/k) and lambda·A high. The ray is followed to that
// line, lambda taken where it crosses it; the edge is soft over a
// penumbra that widens with the distance (the sun's half degree, and a
// rounded crest), and by `spread` (radians: the spread of the rays it
// stands for) times the distance.
float giant_clear(vec2 p, float y, vec3 sun, float spread)
{
    float flat_len = length(sun.xz);
    vec2 d = u_giant_frame.xy;
    float along = flat_len > 1.0e-4 ? dot(d, sun.xz) / flat_len : 0.0;
    float across = flat_len > 1.0e-4 ? dot(vec2(d.y, -d.x), sun.xz) / flat_len : 0.0;
    if (sun.y <= 0.0 || abs(along) < 1.0e-4)
        return 1.0; // no light to shadow, or a crest in line with the sun
    vec2 sw = giant_coords(p);
    float k = u_giant_shape.x, A = u_giant_shape.y, C = u_giant_shape.w, dl, db;
    float crest = giant_bow(sw.y, db) + giant_lambda(sw.y, dl) * C / k;
    float dist = (crest - sw.x) / along; // metres toward the sun to the crest line
    if (dist <= 0.0)
        return 1.0; // the sun's side of the crest
    float w = sw.y + dist * across;
    float crest_height = abs(w) < u_giant_mask.z ? giant_lambda(w, dl) * A : 0.0;
    float ray_height = y + dist * sun.y / flat_len;
    float soft = 0.3 + (0.01 + spread) * dist + 0.08 * crest_height;
    // No crest, no shadow: where the width mask has let the crest down to
    // the sea's mean level, the penumbra alone darkened the troughs beside
    // the wave along the whole crest line.
    float shade = 1.0 - smoothstep(-soft, soft, ray_height - crest_height);
    return 1.0 - shade * smoothstep(0.0, TL_GIANT_SHADOW_FADE, crest_height);
}

// The share of the sun the water at p, y sees past the crest: the
// crest's shadow (tl_giant_sunlit). Light through the crest
// (giant_scatter) is not shadowed: it is the light that came through.
float giant_sunlit(vec2 p, float y)
{
    return giant_clear(p, y, u_sun_dir, 0.0);
}
