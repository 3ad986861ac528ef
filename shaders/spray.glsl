// The giant wave's spray (TL_FEATURE_GIANT_SPRAY): spindrift the wind
// blows back off a tall crest, and a burst at the boat's bow where it
// meets the face, as a light volume composited over whatever the ray saw
// before it. src/waves/tl_giant_spray.c is the same density in double and
// has the TL_SPRAY_* constants; keep the two in step.
#include "bow_spray.glsl"

// The mean of exp(-x²/r²) over [x - span/2, x + span/2]
// (tl_giant_spray_layer).
float giant_spray_layer(float x, float r, float span)
{
    float h = 0.5 * span, g = exp(-x * x / (r * r));
    if (h < 0.1 * r) {
        float u2 = x * x / (r * r), e2 = h * h / (r * r);
        return g * (1.0 + e2 * (2.0 * u2 - 1.0) / 3.0 +
                    e2 * e2 * (4.0 * u2 * u2 - 12.0 * u2 + 3.0) / 30.0);
    }
    return 0.25 * sqrt(TL_PI) * r / h * (spray_erf((x + h) / r) - spray_erf((x - h) / r));
}

// The landing's billows' field at w across the crest, (ts, ty) from its
// centre: round lumps (two noises in crossed planes multiplied, with a
// finer grain), shifted up in its core (tl_giant_spray.c's
// billow_coarse).
float giant_spray_billow_coarse(float envelope, float w, float ts, float ty)
{
    float billow = foam_noise(vec2(w / 1.6 + 5.0, ts / 1.6)) *
                   foam_noise(vec2(w / 1.6 - 2.0, ty / 1.6 + 4.0));
    float grain = foam_noise(vec2(w / 0.5 - 3.0, (ts + ty) / 0.5));
    return (0.8 + 0.2 * grain) * billow + 0.1 * grain +
           TL_SPRAY_LANDING_CLOSE * (sqrt(envelope) - TL_SPRAY_LANDING_OPEN);
}

// The smaller lumps on them, TL_SPRAY_LANDING_FINE_LOW ..
// TL_SPRAY_LANDING_FINE_HIGH (billow_fine).
float giant_spray_billow_fine(float w, float ts, float ty)
{
    float fine = foam_noise(vec2(w / 0.6 + 1.3, ts / 0.6)) *
                 foam_noise(vec2(w / 0.6 - 4.1, ty / 0.6 + 2.2));
    float finer = foam_noise(vec2(w / 0.25 + 7.7, (ts - ty) / 0.25));
    return TL_SPRAY_LANDING_FINE * (fine - 0.25) + TL_SPRAY_LANDING_FINER * (finer - 0.5);
}

// smoothstep(lo, hi) of the field: the smaller lumps are taken only where
// they can change it (tl_giant_spray.c's billow_ramp).
float giant_spray_billow_ramp(float lo, float hi, float envelope, float w, float ts, float ty)
{
    float coarse = giant_spray_billow_coarse(envelope, w, ts, ty);
    if (coarse + TL_SPRAY_LANDING_FINE_HIGH <= lo)
        return 0.0;
    if (coarse + TL_SPRAY_LANDING_FINE_LOW >= hi)
        return 1.0;
    return smoothstep(lo, hi, coarse + giant_spray_billow_fine(w, ts, ty));
}

// Billows' density over their peak: whole, with hard edges, fewer toward
// the cloud's edge (tl_giant_spray_billows).
float giant_spray_billows(float envelope, float w, float ts, float ty)
{
    return smoothstep(TL_SPRAY_LANDING_EDGE_FROM, TL_SPRAY_LANDING_EDGE_TO, sqrt(envelope)) *
           giant_spray_billow_ramp(TL_SPRAY_LANDING_TEAR_FROM, TL_SPRAY_LANDING_TEAR_TO, envelope,
                                   w, ts, ty);
}

// Where the landing's jets can be, 0 .. 1, and their direction from the
// impact (tl_giant_spray.c's jet_reach).
float giant_spray_jet_reach(float ts, float ty, float r, out vec2 dir)
{
    vec2 j = vec2(-ts, TL_SPRAY_JET_DROP * r - ty); // forward and up from the impact
    float rho = length(j);
    dir = rho > 1.0e-9 ? j / rho : vec2(0.0);
    return smoothstep(TL_SPRAY_JET_FROM * r, TL_SPRAY_JET_IN * r, rho) *
           (1.0 - smoothstep(TL_SPRAY_JET_OUT * r, TL_SPRAY_JET_END * r, rho)) *
           smoothstep(-0.2, 0.4, dir.y);
}

// The landing's jets over its peak (tl_giant_spray_jets).
float giant_spray_jets(float w, float ts, float ty, float r)
{
    vec2 dir;
    float reach = giant_spray_jet_reach(ts, ty, r, dir);
    if (!(reach > 0.0))
        return 0.0;
    float streak = foam_noise(vec2(6.0 * dir.x + w / 1.2, 6.0 * dir.y + 3.3)) *
                   foam_noise(vec2(15.0 * dir.x - 1.7, 15.0 * dir.y + w / 0.5));
    return TL_SPRAY_JET * reach * smoothstep(0.35, 0.6, streak);
}

// What of a light along unit `light` a billow at (w, ts, ty) of a cloud
// of radius r lets in: its field TL_SPRAY_BURY_STEP toward the light
// (tl_giant_spray.c's billow_open).
float giant_spray_billow_open(float w, float ts, float ty, float r, vec3 light)
{
    vec2 d = u_giant_frame.xy;
    float ls = dot(d, light.xz), lw = dot(vec2(d.y, -d.x), light.xz);
    float s2 = ts - TL_SPRAY_BURY_STEP * ls, y2 = ty - TL_SPRAY_BURY_STEP * light.y;
    return 1.0 - TL_SPRAY_BURY * giant_spray_billow_ramp(TL_SPRAY_BURY_FROM, TL_SPRAY_BURY_TO,
                                                         exp(-(s2 * s2 + y2 * y2) / (r * r)),
                                                         w + TL_SPRAY_BURY_STEP * lw, s2, y2);
}

// Density (0 or more) at camera-relative p (y absolute); `span`:
// the height a march's sample stands for (tl_giant_spray_density).
// `cloud`: the most density the lip's spray (its torn edge, its landing)
// can have there (0 outside it), where the march takes finer steps.
// `open`: what of the sun's light (x) and the sky's overhead (y) the
// landing's billows let in there (tl_giant_spray_open).
float giant_spray_sample(vec3 p, float span, out float shade, out float cloud, out vec2 open)
{
    float density = 0.0, billowed = 0.0;
    shade = 0.0;
    cloud = 0.0;
    open = vec2(1.0);
    vec2 sw = giant_coords(p.xz);
    if (abs(sw.y) < u_giant_mask.z && sw.x >= u_giant_spray_box.x && sw.x <= u_giant_spray_box.y &&
        p.y >= u_giant_spray_box.z && p.y <= u_giant_spray_box.w) {
        float dl, db;
        float lambda = giant_lambda(sw.y, dl), height = lambda * u_giant_shape.y;
        float top_s = giant_bow(sw.y, db) + lambda * u_giant_shape.w / u_giant_shape.x;
        float top_y = -0.5 * u_depth + height;
        float breaking = 0.0;
#ifdef TL_FEATURE_GIANT_BREAK
        breaking = giant_breaking(sw.y);
#endif
        float source = smoothstep(TL_SPRAY_FROM, TL_SPRAY_FULL, height / u_giant_shape.y) *
                       (0.4 + 0.6 * breaking);
        float reach = u_giant_spray.y;
        float back = top_s - sw.x, up = p.y - top_y;
        float rise = TL_SPRAY_RISE * (height + reach);
        // Gusts along the crest (tl_giant_spray_gust).
        float gust =
            1.0 + TL_SPRAY_GUST * (2.0 * foam_noise(vec2(sw.y / TL_SPRAY_GUST_CELL, 41.7)) - 1.0);
        float lift = TL_SPRAY_LIFT * rise * gust * sqrt(min(max(back, 0.0) / reach, 1.0));
        float plume = smoothstep(-0.05 * height, 0.05 * height, back) *
                      exp(-max(back, 0.0) / reach) *
                      (1.0 + TL_SPRAY_ROOT_GAIN *
                                 exp(-max(back, 0.0) / (TL_SPRAY_ROOT_REACH * reach))) *
                      (1.0 - smoothstep(0.6, 1.0, back / (TL_SPRAY_REACHES * reach))) *
                      giant_spray_layer(up - lift, rise + 1.0e-6, span);
        // Streaks drawn out along the wind, narrow across the crest.
        float drifted = back + u_giant_spray.z;
        float wisps = smoothstep(0.3, 0.75,
                                 0.65 * foam_noise(vec2(sw.y / 0.9, drifted / 6.0 + up / 2.0)) +
                                     0.35 * foam_noise(vec2(sw.y / 0.4, drifted / 2.5 - up / 0.8)));
        // No spindrift off the stretch of crest a hull has broken.
        if (u_giant_spray_heading.w > 0.0) {
            float bw = giant_coords(u_giant_spray_bow.xz).y;
            source *= 1.0 - u_giant_spray_heading.w *
                                (1.0 - smoothstep(TL_SPRAY_SHELTER_IN * u_giant_spray.w,
                                                  TL_SPRAY_SHELTER_OUT * u_giant_spray.w,
                                                  abs(sw.y - bw)));
        }
        density += TL_SPRAY_PLUME_GAIN * u_giant_spray.x * gust * source * plume *
                   (TL_SPRAY_WISP_FLOOR + (1.0 - TL_SPRAY_WISP_FLOOR) * wisps);
#ifdef TL_FEATURE_GIANT_LIP
        // The lip's free edge tears into droplets while it throws
        // (TL_SPRAY_TIP_*, tl_giant_spray.c's tip_density).
        GiantLip lip = giant_lip_at(sw.y);
        if (lip.present) {
            float tip_s = lip.center.x + lip.radius * TL_GIANT_LIP_THROW * sin(lip.to) - sw.x;
            float tip_y = lip.center.y + lip.radius * cos(lip.to) - p.y;
            float rt = TL_SPRAY_TIP_RADIUS * lip.radius;
            float torn = TL_SPRAY_TIP_GAIN * u_giant_spray.x *
                         smoothstep(TL_SPRAY_TIP_START, TL_SPRAY_TIP_FULL, lip.progress) *
                         (1.0 - smoothstep(TL_SPRAY_TIP_FADE, TL_SPRAY_TIP_GONE, lip.progress));
            float envelope = exp(-(tip_s * tip_s + tip_y * tip_y) / (rt * rt));
            cloud = max(cloud, torn * sqrt(envelope));
            density += torn * giant_spray_billows(envelope, lip.w * TL_SPRAY_TIP_SCALE,
                                                  tip_s * TL_SPRAY_TIP_SCALE,
                                                  tip_y * TL_SPRAY_TIP_SCALE);
        }
        // Where the lip lands, whitewater erupts.
        if (lip.present && lip.progress > TL_SPRAY_LANDING_FROM) {
            float ahead = TL_SPRAY_SPLASH_AHEAD * (0.3 + 0.7 * lip.spent);
            float ts = lip.center.x + lip.radius * (TL_GIANT_LIP_THROW * sin(lip.to) + ahead) - sw.x;
            float ty =
                lip.center.y + lip.radius * (cos(lip.to) + TL_SPRAY_SPLASH_RISE * lip.spent) - p.y;
            float r = TL_SPRAY_LANDING_RADIUS * lip.radius *
                      (1.0 + TL_SPRAY_SPLASH_GROW * lip.spent) *
                      (TL_SPRAY_LANDING_SEED +
                       (1.0 - TL_SPRAY_LANDING_SEED) * smoothstep(TL_SPRAY_LANDING_FROM, 1.0, lip.progress));
            float landing = TL_SPRAY_LANDING_GAIN * u_giant_spray.x * (1.0 - lip.spent * lip.spent);
            // Its own shade (tl_giant_spray_landing_shade): the envelope
            // integrated toward the sun in closed form.
            vec2 v = vec2(dot(u_sun_dir.xz, u_giant_frame.xy), u_sun_dir.y);
            float len = length(v), a = len > 1.0e-6 ? dot(vec2(ts, ty), v) / len : 0.0;
            float d2 = max(ts * ts + ty * ty - a * a, 0.0);
            shade = TL_SPRAY_SIGMA * landing * TL_SPRAY_LANDING_MEAN * exp(-d2 / (r * r)) * 0.5 *
                    sqrt(TL_PI) * r * (1.0 + spray_erf(a / r)) / max(len, 0.1);
            float envelope = exp(-(ts * ts + ty * ty) / (r * r));
            float cover = sqrt(envelope);
            vec2 jet_dir;
            float jet_reach = giant_spray_jet_reach(ts, ty, r, jet_dir);
            cloud = max(cloud, landing * (smoothstep(TL_SPRAY_LANDING_EDGE_FROM,
                                                     TL_SPRAY_LANDING_EDGE_TO, cover) +
                                          TL_SPRAY_LANDING_MIST * cover + TL_SPRAY_JET * jet_reach));
            // Its billows in their mist, and its jets (tl_giant_spray_whitewater).
            float billows = giant_spray_billows(envelope, sw.y, ts, ty) +
                            TL_SPRAY_LANDING_MIST * cover + giant_spray_jets(sw.y, ts, ty, r);
            density += landing * billows;
            if (billows > 0.1 && landing > 0.0) {
                billowed = landing * billows;
                open = vec2(giant_spray_billow_open(sw.y, ts, ty, r, u_sun_dir),
                            giant_spray_billow_open(sw.y, ts, ty, r, vec3(0.0, 1.0, 0.0)));
            }
        }
#endif
    }
    if (u_giant_spray_bow.w > 0.0) {
        vec3 d = p - u_giant_spray_bow.xyz;
        float sheet = bow_spray_sheet(d, u_giant_spray_heading.xy, u_giant_spray.w,
                                      u_giant_spray_heading.z);
        density += u_giant_spray_bow.w * sheet;
        // Its own shade (tl_giant_spray_shade), where it has any spray.
        if (sheet > 0.0)
            shade += TL_SPRAY_SIGMA * TL_BOW_SPRAY_TORN_MEAN * u_giant_spray_bow.w *
                     bow_spray_sheet_depth(d, u_giant_spray_heading.xy, u_giant_spray.w,
                                                u_giant_spray_heading.z, u_sun_dir);
    }
    // The billows' shade weighed by their share of the density there.
    if (billowed > 0.0)
        open = 1.0 + (open - 1.0) * (billowed / density);
    return density;
}

float giant_spray_sample(vec3 p, float span, out float shade)
{
    float cloud;
    vec2 open;
    return giant_spray_sample(p, span, shade, cloud, open);
}

// The spray's density alone (tl_giant_spray_density).
float giant_spray_density(vec3 p, float span)
{
    float shade;
    return giant_spray_sample(p, span, shade);
}

// The spray along `ray` from the camera to `dist`, over `color`: single
// scattering of the sun (a forward lobe: backlit spray glows) and of the
// sky, by water droplets (albedo near 1), in steps over the part of the
// ray in the spray's boxes (quality.spray_step), each step at a fixed offset in
// its segment by a hash of the pixel (so a frame renders the same alone
// or in a sequence): the blobs (the landing, the bow) are sampled at other
// depths in neighbouring pixels, and the eye sees no blotches where the
// same offsets everywhere would alias. The plume's layer is thinner than a
// step of a ray that looks down through it: each sample takes its mean
// over the step's height (giant_spray_layer), or the steps that hit it
// and those that missed it were pixels apart (a grain like asphalt over
// the back of the wave).
// Steps: one per quality.spray_step metres of the ray in the boxes
// (u_spray_step), at least TL_SPRAY_STEPS_MIN and at most
// TL_SPRAY_STEPS_MAX (bow_spray.glsl). Sixteen over the whole box, whatever
// its length, put 4 m between the samples of a ray that crossed the
// landing's tall box, against wisps under a metre: each pixel's few
// samples found other wisps, a grain like asphalt over the back of the
// wave.
#define TL_SPRAY_SHADE_WATER 2.0
// The lip's spray is marched TL_SPRAY_CLOUD_REFINE times finer than
// quality.spray_step, in at most TL_SPRAY_CLOUD_STEPS parts of a step,
// where a step could hold an optical depth over TL_SPRAY_CLOUD_FROM of it;
// the march stops with under TL_SPRAY_OPAQUE of the light left.
#define TL_SPRAY_CLOUD_REFINE 2.0
#define TL_SPRAY_CLOUD_STEPS  16
#define TL_SPRAY_CLOUD_FROM   0.01
#define TL_SPRAY_OPAQUE       0.005
vec3 giant_spray(vec3 ray, float dist, vec3 color)
{
    // The crest's box in the wave's frame, and the bow's sphere.
    vec3 lo = vec3(u_giant_spray_box.x, u_giant_spray_box.z, -u_giant_mask.z);
    vec3 hi = vec3(u_giant_spray_box.y, u_giant_spray_box.w, u_giant_mask.z);
    vec2 box = giant_box_interval(ray, lo, hi, min(dist, TL_FAR));
    float t0 = box.x, t1 = box.y;
    float step_len = u_spray_step;
    if (u_giant_spray_bow.w > 0.0) {
        // The sphere the bow's burst reaches.
        vec3 c = u_giant_spray_bow.xyz - vec3(0.0, u_cam_height, 0.0);
        float along = dot(c, ray),
              R = bow_spray_reach(u_giant_spray.w, u_giant_spray_heading.z);
        float h = R * R - (dot(c, c) - along * along);
        if (h > 0.0) {
            float b0 = max(along - sqrt(h), 0.0), b1 = min(along + sqrt(h), dist);
            t0 = t0 <= t1 ? min(t0, b0) : b0;
            t1 = t0 <= t1 ? max(t1, b1) : b1;
            // The sheet is thin along the heading (0.4 of its radius): a ray
            // through it takes steps of at most a quarter of that, or each
            // pixel's few samples in it scattered it into speckle.
            step_len = min(step_len, 0.1 * u_giant_spray.w);
        }
    }
    if (!(t0 < t1))
        return color;
    float mu = dot(ray, u_sun_dir);
    float g = TL_SPRAY_PHASE_G;
    float phase = (1.0 - g * g) / (4.0 * TL_PI * pow(1.0 + g * g - 2.0 * g * mu, 1.5));
    vec3 sun = sky_sun_light(), ambient = sky_ambient();
    int steps = clamp(int(ceil((t1 - t0) / step_len)), TL_SPRAY_STEPS_MIN, TL_SPRAY_STEPS_MAX);
    float dt = (t1 - t0) / float(steps);
    float trans = 1.0;
    vec3 scattered = vec3(0.0);
    float offset = spray_step_offset();
    // In the lip's spray a step is cut into TL_SPRAY_CLOUD_REFINE or
    // more parts (at most TL_SPRAY_CLOUD_STEPS): its billows' edges are
    // sharper than a step, and each pixel's one sample per step fell in or
    // out of them, a grain of white dots over its edges. Whether the cloud
    // is there is known from the step before (the envelope is metres
    // across, smooth): the first step into it is taken whole.
    // One loop over steps and their parts (nested loops of a varying
    // count compiled to far slower code on llvmpipe).
    float cloud = 0.0;
    int i = 0, k = 0, parts = 1;
    for (int n = 0; n < TL_SPRAY_STEPS_MAX * TL_SPRAY_CLOUD_STEPS; n++) {
        if (k == parts) {
            k = 0;
            i++;
            parts = TL_SPRAY_SIGMA * cloud * dt > TL_SPRAY_CLOUD_FROM
                        ? clamp(int(ceil(TL_SPRAY_CLOUD_REFINE * dt / u_spray_step)), 1,
                                TL_SPRAY_CLOUD_STEPS)
                        : 1;
        }
        // Past TL_SPRAY_OPAQUE of the light left, the rest of the ray adds
        // at most that share of the cloud's light: the march stops.
        if (i >= steps || trans < TL_SPRAY_OPAQUE)
            break;
        float part = dt / float(parts);
        vec3 p = vec3(0.0, u_cam_height, 0.0) +
                 ray * (t0 + float(i) * dt + (float(k) + offset) * part);
        float shade;
        vec2 open;
        float density = giant_spray_sample(p, abs(ray.y) * part, shade, cloud, open);
        k++;
        float sigma = TL_SPRAY_SIGMA * density;
        float step_trans = exp(-sigma * part);
        // A dense cloud (the landing's whitewater, the bow's burst) scatters
        // the sun many times inside and looks white from every side: its
        // share of TL_SPRAY_DIFFUSE/pi on top of the single-scattering lobe.
        float dense = smoothstep(1.0, 4.0, density);
        float many = TL_SPRAY_DIFFUSE / TL_PI * dense;
        // Below the crest, on the side away from the sun, the wave shades
        // the spray as it shades the water: lit by the full sun there, the
        // spray under a backlit lip glowed brown against the dark face.
        // A dense cloud there still sees the sun through the wave's water
        // (the curtain and the crest's top), tinted as that water tints it:
        // the landing's whitewater under a backlit lip, lit by the sky
        // alone, was a faint grey puff. The water crossed is taken as
        // TL_SPRAY_SHADE_WATER metres: marched toward the sun once a ray it
        // looked alike and cost a third more over the lip's frames; over
        // 10 m the whitewater was tinted into cyan smoke, over 4 m mint
        // (the curtain and the lip it comes through are a metre or two).
        float sunlit = density > 0.0 ? giant_sunlit(p.xz, p.y) : 1.0;
        vec3 through = max(vec3(sunlit), dense * exp(-u_giant_sigma * TL_SPRAY_SHADE_WATER));
        // The landing's and the burst's own shade dims the sun's single
        // scattering, and its many scatterings far less (they carry light
        // on from the lit side, spray_many_through); the billows' own shade
        // dims the sun's and the sky's light alike.
        vec3 light = TL_SPRAY_ALBEDO *
                     (sun * (phase * exp(-shade) + many * spray_many_through(shade)) * through *
                          open.x +
                      ambient * open.y);
        scattered += trans * (1.0 - step_trans) * light;
        trans *= step_trans;
    }
    return color * trans + layer_emit(TL_LIGHT_SPRAY, scattered);
}
