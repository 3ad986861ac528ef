// The spray a boat's bow throws where it meets rising water: a sheet
// thrown up and out to both sides of the stem (bow_spray_sheet, which the
// giant wave's spray throws too where the bow meets its face), and, with
// TL_FEATURE_BOW_SPRAY, its light volume over what the ray saw.
// src/waves/tl_bow_spray.c is the same density in double.

// The spray's light, for the giant wave's (spray.glsl) and the bow's: a
// march of at least TL_SPRAY_STEPS_MIN and at most TL_SPRAY_STEPS_MAX
// steps, the droplets' forward lobe g, their albedo, and the share of
// TL_SPRAY_DIFFUSE / pi a dense cloud scatters many times inside.
#define TL_SPRAY_STEPS_MIN 16
#define TL_SPRAY_STEPS_MAX 64
#define TL_SPRAY_PHASE_G   0.7
#define TL_SPRAY_ALBEDO    0.9
#define TL_SPRAY_DIFFUSE   0.6

// The share of the sun's light scattered many times inside a dense cloud
// that gets through an optical depth `shade` of it toward the sun: the
// two-stream diffusion's 1 / (1 + 3/4 (1 - g) shade). Most of it goes on
// forward through a thick cloud, so a backlit whitewater glows on its far
// side; as the square root of the direct light's exp(-shade), the far
// side of the landing's cloud, lit by the sky alone, was a grey-blue
// puff no brighter than the sky behind it ("steam", "cotton", judges).
float spray_many_through(float shade)
{
    return 1.0 / (1.0 + 0.75 * (1.0 - TL_SPRAY_PHASE_G) * shade);
}

// Where in its segment a spray march's steps sample, in [0, 1): a hash
// of the pixel, the same every frame (a frame renders alike alone or in a
// sequence), different between neighbours (no blotches where the same
// offset everywhere would alias). Its grain reads as droplets;
// interleaved gradient noise left a regular hatch at the whitewater's
// edges.
float spray_step_offset()
{
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint k = pixel.x * 0x8da6b343u ^ pixel.y * 0xd8163841u;
    k ^= k >> 15;
    k *= 0x2c1b3c6du;
    k ^= k >> 12;
    return float(k & 0xffffu) / 65536.0;
}

// erf, to 1.5e-7 (Abramowitz and Stegun 7.1.26).
float spray_erf(float x)
{
    float t = 1.0 / (1.0 + 0.3275911 * abs(x));
    float poly = t * (0.254829592 + t * (-0.284496736 +
                                         t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    return sign(x) * (1.0 - poly * exp(-x * x));
}

// How far from its centre the sheet of `radius` split by `split` metres
// reaches: the sphere a march covers (tl_bow_spray_reach).
float bow_spray_reach(float radius, float split)
{
    return split > 0.0 ? split + sqrt(TL_BOW_SPRAY_END) * max(TL_BOW_SPRAY_WING, 0.9) * radius
                       : TL_BOW_SPRAY_REACH * radius;
}

// The sheet's width across the heading: one sheet's, or each wing's.
float bow_spray_across(float radius, float split)
{
    return (split > 0.0 ? TL_BOW_SPRAY_WING : 1.3) * radius;
}

// One lobe's envelope integrated from q (scaled) toward the sun, e scaled
// by the same widths (tl_bow_spray_sheet_depth's closed form).
float bow_spray_lobe_depth(vec3 q, vec3 e)
{
    float len = length(e), a = dot(q, e) / len;
    float perp = max(dot(q, q) - a * a, 0.0);
    return exp(-perp) * 0.5 * sqrt(TL_PI) / len * (1.0 - spray_erf(a));
}

// The sheet's envelope integrated from offset d toward the sun, in closed
// form; split, its wings' sum (tl_bow_spray_sheet_depth).
float bow_spray_sheet_depth(vec3 d, vec2 h, float radius, float split, vec3 sun)
{
    vec3 scale = vec3(0.4 * radius, bow_spray_across(radius, split), 0.9 * radius);
    vec3 e = vec3(dot(sun.xz, h), sun.x * h.y - sun.z * h.x, sun.y) / scale;
    vec3 q = vec3(dot(d.xz, h), d.x * h.y - d.z * h.x, d.y);
    float depth = bow_spray_lobe_depth((q - vec3(0.0, split, 0.0)) / scale, e);
    if (split > 0.0)
        depth += bow_spray_lobe_depth((q + vec3(0.0, split, 0.0)) / scale, e);
    return depth;
}

// One lobe's envelope at scaled (along, side, up): a Gaussian cut off
// smoothly from 1 to TL_BOW_SPRAY_END of its scaled radius squared.
float bow_spray_lobe(float along, float side, float up)
{
    float r2 = along * along + side * side + up * up;
    return r2 < TL_BOW_SPRAY_END ? exp(-r2) * (1.0 - smoothstep(1.0, TL_BOW_SPRAY_END, r2)) : 0.0;
}

// The sheet's shape at offset d (metres) from its centre for a boat
// heading h (unit x z), a burst of `radius` and its `split` (0: one
// sheet; else a wing each side of the hull, `split` metres out,
// TL_BOW_SPRAY_WING radii wide): thin along the heading, wide across it,
// rising; torn by the noise. 0 beyond bow_spray_reach (tl_bow_spray_sheet).
float bow_spray_sheet(vec3 d, vec2 h, float radius, float split)
{
    float along = dot(d.xz, h) / (0.4 * radius);
    float side_m = d.x * h.y - d.z * h.x;
    float up = d.y / (0.9 * radius), across = bow_spray_across(radius, split);
    float envelope = bow_spray_lobe(along, (side_m - split) / across, up);
    if (split > 0.0)
        envelope += bow_spray_lobe(along, (side_m + split) / across, up);
    if (!(envelope > 0.0))
        return 0.0;
    // Torn into sheets and clots of droplets: two scales of noise, the
    // clots shrinking toward the edge; the wings tear alike, mirrored.
    float side = (split > 0.0 ? abs(side_m) - split : side_m) / across;
    float torn = 0.65 * foam_noise(vec2(side * 2.6 + 17.0, up * 3.1 - along)) +
                 0.35 * foam_noise(vec2(side * 7.3 - 4.0, up * 8.9 + along * 2.0));
    float cover = sqrt(min(envelope, 1.0));
    return cover * smoothstep(TL_BOW_SPRAY_TEAR_FROM, TL_BOW_SPRAY_TEAR_TO,
                              torn + TL_BOW_SPRAY_THIN * (cover - 1.0));
}

#ifdef TL_FEATURE_BOW_SPRAY
// Object o's burst's density at camera-relative p (y absolute)
// (tl_bow_spray_density).
float bow_spray_density(int o, vec3 p)
{
    vec4 spray = u_objects[o].bow_spray, shape = u_objects[o].bow_spray_shape;
    return spray.w * bow_spray_sheet(p - spray.xyz, shape.xy, shape.z, 0.0);
}

// The optical depth from camera-relative p toward the sun through object
// o's burst (tl_bow_spray_shade).
float bow_spray_shade(int o, vec3 p)
{
    vec4 spray = u_objects[o].bow_spray, shape = u_objects[o].bow_spray_shape;
    return TL_SPRAY_SIGMA * TL_BOW_SPRAY_TORN_MEAN * spray.w *
           bow_spray_sheet_depth(p - spray.xyz, shape.xy, shape.z, 0.0, u_sun_dir);
}

// Object o's burst along `ray` from the camera to `dist`, over `color`,
// lit as the giant wave's spray is (giant_spray, without the wave's
// shade): the sun's single scattering in a forward lobe, many times inside
// where it is dense, both dimmed by the sheet's own shade, and the sky; in
// steps over the ray's part in the sheet's sphere, each at an offset by a
// hash of the pixel (a frame is the same alone or in a sequence).
vec3 bow_spray_one(int o, vec3 ray, float dist, vec3 color)
{
    vec4 spray = u_objects[o].bow_spray;
    if (!(spray.w > 0.0))
        return color;
    vec3 c = spray.xyz - vec3(0.0, u_cam_height, 0.0);
    float along = dot(c, ray), R = bow_spray_reach(u_objects[o].bow_spray_shape.z, 0.0);
    float h = R * R - (dot(c, c) - along * along);
    if (h <= 0.0)
        return color;
    float t0 = max(along - sqrt(h), 0.0), t1 = min(along + sqrt(h), dist);
    if (!(t0 < t1))
        return color;
    const float g = TL_SPRAY_PHASE_G;
    float mu = dot(ray, u_sun_dir);
    float phase = (1.0 - g * g) / (4.0 * TL_PI * pow(1.0 + g * g - 2.0 * g * mu, 1.5));
    vec3 sun = sky_sun_light(), ambient = sky_ambient();
    int steps = clamp(int(ceil((t1 - t0) / u_spray_step)), TL_SPRAY_STEPS_MIN, TL_SPRAY_STEPS_MAX);
    float dt = (t1 - t0) / float(steps);
    float offset = spray_step_offset();
    float trans = 1.0;
    vec3 scattered = vec3(0.0);
    for (int i = 0; i < steps; i++) {
        vec3 p = vec3(0.0, u_cam_height, 0.0) + ray * (t0 + (float(i) + offset) * dt);
        float density = bow_spray_density(o, p);
        float step_trans = exp(-TL_SPRAY_SIGMA * density * dt);
        float many = TL_SPRAY_DIFFUSE / TL_PI * smoothstep(1.0, 4.0, density);
        float shade = density > 0.0 ? bow_spray_shade(o, p) : 0.0;
        vec3 light = TL_SPRAY_ALBEDO *
                     (sun * (phase * exp(-shade) + many * spray_many_through(shade)) + ambient);
        scattered += trans * (1.0 - step_trans) * light;
        trans *= step_trans;
    }
    return color * trans + layer_emit(TL_LIGHT_SPRAY, scattered);
}

// Every object's burst in view.
vec3 bow_spray(vec3 ray, float dist, vec3 color)
{
    for (int o = 0; o < u_object_count; o++)
        color = bow_spray_one(o, ray, dist, color);
    return color;
}
#endif
