// Bounded height-field march (seed 002): the ocean lies between the crest
// plane y = 0 and the trough plane y = -depth, so the ray is only marched
// between its hits with those planes, with the adaptive step "height above
// the surface" (it cannot overshoot the surface below it).
// Positions are camera-relative in xz; y is absolute.
//
// With the giant wave the band grows only inside the wave's bounding box:
// the ray also marches the part of it inside the box, where each step is
// divided by (1 + K × horizontal part of the ray), K bounding the wave's
// slope wherever the step could reach, so that even its steepest face
// cannot be stepped through.

// The pixel (continuous, full-resolution) of the ray being marched, set by
// the caller: where the march looks up its neighbours in the prepass.
vec2 g_pixel;

#ifdef TL_MARCH_HINT
// The march prepass (quality.march_prepass) marched this same march at a
// quarter and then half the render's size (src/gl/tl_renderer_prepass.c);
// the four coarser rays around a ray tell where it meets the water. Where
// they agree (a smooth stretch of water: the nearest at least
// TL_HINT_SMOOTH of the farthest) the hit lies between them, the bracket
// widened by 1% each way: if the bracket holds a crossing, up to
// TL_HINT_REFINE regula falsi steps find it. Where the four disagree (a
// crest's silhouette, or rays grazing the far sea, whose distances spread
// by the view's geometry alone) the march starts 1% short of the nearest,
// where it finds a crest the ray clips within its first steps; after
// quality.prepass_budget steps without a hit, regula falsi searches the
// rest of the bracket from the last point marched (grazing rays close on
// the surface slowly: marched to the end, they took 40% of a calm frame's
// surface evaluations). Where the walk fails (no crossing at the
// bracket's ends, regula falsi has not converged) the march goes on from
// its last proven point: the bracket's near end or the budget's last
// step. Next to the sky the march starts 10% short of the nearest and
// takes no bracket (the budget's far end there is the trough plane).
// Where the march's own start lies past the nearest (a grazing ray whose
// lower neighbours meet the water before it enters the band), the walk
// starts there. Wherever the first point is already under the surface (a
// crest between the coarser rays), the march starts over.
uniform sampler2D u_march_hint;
uniform float u_hint_pixel; // this pass's pixel, in the frame's pixels (the prepass's are larger)
#define TL_HINT_SMOOTH 0.9
#define TL_HINT_WIDEN 0.01
#define TL_HINT_EDGE_WIDEN 0.1
#ifndef TL_HINT_REFINE
#define TL_HINT_REFINE 8
#endif
#ifndef TL_GIANT_GENTLE
#define TL_GIANT_GENTLE 0.25
#endif

// The nearest and farthest of the four prepass distances around this
// pixel, the sky as 1e30, and their bilinear blend at the pixel (where
// all four saw water).
vec3 march_hint()
{
    ivec2 last = textureSize(u_march_hint, 0) - 1;
    vec2 at = g_pixel / u_hint_pixel * 0.5 - 0.5; // in the coarser level's texels
    ivec2 j = ivec2(floor(at));
    vec2 f = at - vec2(j);
    vec2 range = vec2(1e30, 0.0);
    float blend = 0.0;
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 2; x++) {
            float t = texelFetch(u_march_hint, clamp(j + ivec2(x, y), ivec2(0), last), 0).r;
            range = vec2(t > 0.0 ? min(range.x, t) : range.x, t > 0.0 ? max(range.y, t) : 1e30);
            blend += (x == 0 ? 1.0 - f.x : f.x) * (y == 0 ? 1.0 - f.y : f.y) * t;
        }
    return vec3(range, blend);
}

// The walk through the prepass's bracket, inside the march's own loop:
// llvmpipe runs a loop's body at least once for every pixel, so a second
// loop would cost every pixel a surface evaluation. Its stages:
#define HINT_MARCHING 0 // not walking: the march steps on its own
#define HINT_FIRST    1 // at the first point (the four's blend, the bracket's near end,
                        // or the start short of a silhouette)
#define HINT_ENDS     2 // at the bracket's other end (side: which one)
#define HINT_FALSI    3 // HINT_FALSI + k: after k regula falsi steps
// and the side the last regula falsi step moved (Illinois halves the other
// end's height when the same side moves twice):
#define HINT_SIDE_NONE  0
#define HINT_SIDE_NEAR  1  // the near end, b0
#define HINT_SIDE_FAR   -1 // the far end, b1
#define HINT_CHECK_NEAR 2  // at HINT_ENDS: the near end is the one to check
struct hint_walk {
    int stage, side, budget;
    bool bracket;
    float b0, c0, b1, c1; // the bracket's ends and the heights above the surface there
    float resume;         // where the march goes on from if the walk fails
};

// The walk for a march that would start at t: moves t to its first point
// and gives the march the walk's steps. budget_from: the march may give
// up on a disagreeing bracket that starts there or later (past the giant
// wave's box, whose crest a budget could pass); t_far: the bracket's far
// end next to the sky (where the ray meets the trough plane; 0 for a
// rising ray).
hint_walk hint_begin(inout float t, inout int steps, float budget_from, float t_far)
{
    hint_walk w = hint_walk(HINT_MARCHING, HINT_SIDE_NONE, 0, false, 0.0, 0.0, 0.0, 0.0, 0.0);
    vec3 hint = march_hint();
    // Next to the sky (the horizon, a crest's silhouette) the ray may clip
    // the crest nearer than any of the four saw water: it starts further
    // short of the nearest.
    float short_of = hint.x * (1.0 - (hint.y >= 1e30 ? TL_HINT_EDGE_WIDEN : TL_HINT_WIDEN));
    if (hint.x < 1e30 && hint.y * (1.0 + TL_HINT_WIDEN) > t) {
        w.bracket = hint.x >= TL_HINT_SMOOTH * hint.y;
        w.b0 = max(short_of, t);
        w.resume = w.b0;
        w.b1 = hint.y * (1.0 + TL_HINT_WIDEN);
        w.stage = HINT_FIRST;
        t = w.b0;
        steps += 3 + TL_HINT_REFINE;
        if (hint.y >= 1e30)
            w.b1 = t_far;
        if (w.bracket)
            t = clamp(hint.z, w.b0, w.b1); // the four agree: probe their blend first
        if (w.b0 >= budget_from && u_prepass_budget > 0 && !w.bracket) {
            w.budget = u_prepass_budget;
            steps += 1 + TL_HINT_REFINE;
        }
    }
    return w;
}

// The march's point t, `above` the surface, with nothing skipped before
// it: after the budget's last step, regula falsi takes over from t to the
// bracket's far end (a crossing there) or the march goes on from t.
bool hint_give_up(inout hint_walk w, inout float t, float above)
{
    if (w.budget <= 0 || --w.budget > 0 || !(w.b1 > t))
        return false;
    w.b0 = t;
    w.c0 = above;
    w.resume = t;
    w.stage = HINT_ENDS;
    t = w.b1;
    return true;
}

const int HINT_MARCH = 0; // march on from t with this height
const int HINT_NEXT = 1;  // evaluate the next t
const int HINT_FOUND = 2; // t is the hit

// One point of the walk, `above` the surface at t; t_start: where the
// march would have started without the prepass.
int hint_step(inout hint_walk w, float above, inout float t, float t_start)
{
    if (w.stage == HINT_MARCHING)
        return HINT_MARCH;
    if (w.stage == HINT_FIRST && !w.bracket) {
        if (!(above > 0.0)) { // under a crest between the prepass rays
            w.stage = HINT_MARCHING;
            w.budget = 0; // the crest lies before the bracket: march all the way
            t = t_start;
            return HINT_NEXT;
        }
        w.stage = HINT_MARCHING; // march on from short of the silhouette
        return HINT_MARCH;
    }
    if (abs(above) < (w.stage > HINT_FIRST ? 1.0 : 0.25) * u_hit_epsilon) {
        w.stage = HINT_MARCHING;
        return HINT_FOUND; // within the hit epsilon of the surface
    }
    if (w.stage == HINT_FIRST) { // the blend of the four: it splits the bracket
        if (above > 0.0) {
            w.b0 = t;
            w.c0 = above;
            w.stage = HINT_ENDS;
            t = w.b1;
        } else if (above <= 0.0) {
            w.b1 = t;
            w.c1 = above;
            w.stage = HINT_ENDS;
            w.side = HINT_CHECK_NEAR; // the near end is still to check
            t = w.b0;
        } else { // NaN: start over
            w.stage = HINT_MARCHING;
            t = t_start;
        }
        return HINT_NEXT;
    }
    if (w.stage == HINT_ENDS) {
        if (w.side == HINT_CHECK_NEAR) { // the near end
            w.side = HINT_SIDE_NONE;
            if (!(above > 0.0)) { // under a crest before the bracket: march all the way
                w.stage = HINT_MARCHING;
                t = t_start;
                return HINT_NEXT;
            }
            w.c0 = above;
            w.stage = HINT_FALSI;
        } else {
            if (above > 0.0) {
                // No crossing at the bracket's ends: there may be two between
                // them (a crest the ray clips), so the march goes on from the
                // near end, where nothing was skipped.
                w.stage = HINT_MARCHING;
                t = w.resume;
                return HINT_NEXT;
            }
            w.stage = HINT_MARCHING;
            if (!(above <= 0.0)) { // NaN: start over
                t = t_start;
                return HINT_NEXT;
            }
            w.c1 = above;
            w.stage = HINT_FALSI;
        }
    } else if (w.stage == HINT_FALSI + TL_HINT_REFINE) {
        w.stage = HINT_MARCHING; // not converged (a steep face): march on from the last proven point
        t = w.resume;
        return HINT_NEXT;
    } else if (above > 0.0) { // Illinois: the bracket always holds the crossing
        w.b0 = t;
        w.c0 = above;
        w.c1 *= w.side == HINT_SIDE_NEAR ? 0.5 : 1.0;
        w.side = HINT_SIDE_NEAR;
        w.stage++;
    } else {
        w.b1 = t;
        w.c1 = above;
        w.c0 *= w.side == HINT_SIDE_FAR ? 0.5 : 1.0;
        w.side = HINT_SIDE_FAR;
        w.stage++;
    }
    t = w.b1 + w.c1 * (w.b1 - w.b0) / (w.c0 - w.c1);
    return HINT_NEXT;
}
#endif

#ifdef TL_MARCH_PREPASS
// A prepass ray stands for a block of pixels. Where it passes within about
// a block of a crest and then rises away from the water (the crest's
// silhouette, against far water or the sky), the pixels around it may clip
// that crest: it reports the crest's distance instead of its own hit, so
// that they start in front of the crest rather than past it. Grazing rays
// over open water come ever closer to the surface and never rise: they
// report their hit.
#define TL_PREPASS_REACH 2.0
float g_pass_near = -1.0; // where the ray first came within reach of the surface
bool g_pass_rose = false; // and rose out of reach after it

void march_note_pass(float t, float above)
{
    float pixel = 2.0 * u_tan_half_vfov / u_resolution.y; // radians
    if (above < TL_PREPASS_REACH * u_prepass_scale * pixel * t)
        g_pass_near = g_pass_near < 0.0 ? t : g_pass_near;
    else if (g_pass_near >= 0.0)
        g_pass_rose = true;
}
#else
void march_note_pass(float t, float above)
{
}
#endif

#ifdef TL_FEATURE_REFINE
// Secant steps from the march's last two points (t0, a0) and (t1, a1),
// a = height above the surface, toward a = 0: the march stops anywhere
// within the hit epsilon above the surface, which for a grazing ray is a
// long way along it. Each step stays within twice the last step's span.
float march_refine(vec3 ray, float t0, float a0, float t1, float a1)
{
    for (int i = 0; i < u_refine_steps; i++) {
        float slope = a0 - a1;
        if (!(slope > 0.0))
            break; // no descent to follow
        float span = abs(t1 - t0);
        float t = clamp(t1 + a1 * (t1 - t0) / slope, t1 - 2.0 * span, t1 + 2.0 * span);
        vec3 pos = vec3(0.0, u_cam_height, 0.0) + ray * t;
        float a = pos.y - surface_height(pos.xz, TL_MARCH_OCTAVES, t * u_lod_angle);
        t0 = t1;
        a0 = a1;
        t1 = t;
        a1 = a;
        if (abs(a) < 1e-6 * max(1.0, t))
            break;
    }
    return t1;
}
#endif

// What both marches carry from step to step, and their common step.
struct march_state {
    float t;                  // the point being evaluated
    float t_start;            // where the march began (a miss's answer in `seed`)
    float t_last, above_last; // the last point above the surface, for refinement
    bool hit;                 // t is within the hit epsilon of the surface
    float above_hit;          // the height above it there
    // Over-relaxation (enhanced sphere tracing): a step of more than the
    // point's free radius stands when the free interval around the point
    // it reaches overlaps the last point's; otherwise the march goes back
    // to the last point plus its radius, which is always safe.
    float t_prev, r_prev; // the last point and its radius
    bool relaxed;         // the step that led to t was over-relaxed
#ifdef TL_MARCH_HINT
    hint_walk walk;
#endif
};

march_state march_begin(float t)
{
    march_state m;
    m.t = t;
    m.t_start = t;
    m.t_last = t;
    m.above_last = -1.0;
    m.hit = false;
    m.above_hit = 0.0;
    m.t_prev = 0.0;
    m.r_prev = 0.0;
    m.relaxed = false;
    return m;
}

#define MARCH_STEP  0 // the caller steps on from t (march_advance)
#define MARCH_NEXT  1 // t moved: evaluate the new t
#define MARCH_HIT   2 // t is the hit (m.hit): the march ends
#define MARCH_FOUND 3 // the prepass's walk found the hit at t: return t as it is

// One point of a march: `above` the surface at m.t, `radius` of it surely
// free along the ray (above itself for the ocean; less in the giant
// wave's box, where the slope bound divides it).
int march_step(inout march_state m, float above, float radius)
{
#ifdef TL_MARCH_HINT
    int act = hint_step(m.walk, above, m.t, m.t_start);
    if (act == HINT_FOUND)
        return MARCH_FOUND;
    if (act == HINT_NEXT)
        return MARCH_NEXT;
#endif
    if (m.relaxed && m.t - radius > m.t_prev + m.r_prev) {
        m.t = m.t_prev + m.r_prev; // the relaxed step may have crossed the surface
        m.relaxed = false;
        return MARCH_NEXT;
    }
    march_note_pass(m.t, above);
    if (above < u_hit_epsilon) {
        m.hit = true;
        m.above_hit = above;
        return MARCH_HIT;
    }
#ifdef TL_MARCH_HINT
    if (hint_give_up(m.walk, m.t, above))
        return MARCH_NEXT;
#endif
    m.t_last = m.t;
    m.above_last = above;
    return MARCH_STEP;
}

// The step from m.t (free for `radius`) to `next`, at least that radius
// on; over-relaxed when it is further.
void march_advance(inout march_state m, float radius, float next)
{
    m.t_prev = m.t;
    m.r_prev = radius;
    m.relaxed = next > m.t + radius;
    m.t = next;
}

// How a march ends: at a hit (`above` there), refined
// from the last point above the surface; or out of steps, where the last
// position is the best estimate of the hit (the reference returns the start
// point instead, which brightens grazing rays at the horizon; `seed` keeps
// that). The refinement is here, after the march's loop, not inside it:
// llvmpipe runs a loop body's code for every pixel, hit or not. It is
// compiled only for presets that refine (TL_FEATURE_REFINE): a loop that
// runs zero times still costs llvmpipe one pass of its body, a surface
// evaluation for every pixel.
float march_end(vec3 ray, march_state m)
{
    if (!m.hit)
        return u_miss_at_start ? m.t_start : m.t;
#ifdef TL_FEATURE_REFINE
    if (m.above_last > 0.0)
        return march_refine(ray, m.t_last, m.above_last, m.t, m.above_hit);
#endif
    return m.t;
}

// Distance along `ray` to the surface, or a negative value for a miss;
// the view starts t_min along the ray.
#if defined(TL_SKY_ONLY)
// The rows above the horizon (tl_frame_uniforms.sky_rows): every ray
// rises from a camera above the water and meets nothing the lean march
// below could (it returns the same -1 for them), without the march's
// loop, which llvmpipe charges even a ray that skips it.
float march_water(vec3 ray, float t_min)
{
    return -1.0;
}
#elif !defined(TL_FEATURE_GIANT_WAVE)
// The ocean alone: the ray is marched from where it enters the band to
// where it leaves it, through the trough plane (a hit, held finite for rays
// that graze the horizon) or up through the crest plane (the sky). Each
// check and variable here is paid on every step of every pixel.
float march_water(vec3 ray, float t_min)
{
    if (ray.y >= 0.0 && u_cam_height >= 0.0)
        return -1.0;
    float t_high = ray.y < 0.0 ? max((0.0 - u_cam_height) / ray.y, 0.0) : 0.0;
    float t_end = min((ray.y < 0.0 ? -u_depth - u_cam_height : -u_cam_height) / ray.y, TL_FAR);
    march_state m = march_begin(max(t_high, t_min));
    int steps = u_march_steps;
#ifdef TL_MARCH_HINT
    m.walk = hint_begin(m.t, steps, 0.0, ray.y < 0.0 ? t_end : 0.0);
#endif
    for (int i = 0; i < steps; i++) {
        vec3 pos = vec3(0.0, u_cam_height, 0.0) + ray * m.t;
        float above = pos.y - surface_height(pos.xz, TL_MARCH_OCTAVES, m.t * u_lod_angle);
        int act = march_step(m, above, above);
        if (act == MARCH_FOUND)
            return m.t;
        if (act == MARCH_HIT)
            break;
        if (act == MARCH_NEXT)
            continue;
        // A relaxed step ends at the band's far plane at most, where the next
        // point checks it; only a plain step leaves the band.
        float next = m.t + u_march_relax * above;
        if (next > t_end)
            next = max(m.t + above, t_end);
        march_advance(m, above, next);
        if (m.t > t_end)
            return ray.y < 0.0 ? t_end : -1.0;
    }
    return march_end(ray, m);
}
#else
// TL_BOX_STEP_COST (TL_QUALITY_GIANT_STEP_COST, src/scene/tl_quality.h):
// the least share of a step one step inside the giant wave's box costs.
// With the giant wave: the band and the wave's box.
float march_water(vec3 ray, float t_min)
{
    vec2 box = giant_ray_interval(ray); // the giant wave's part of the ray
    float ray_along = abs(dot(u_giant_frame.xy, ray.xz)), ray_flat = length(ray.xz);
    bool has_box = box.x <= box.y;
    if (ray.y >= 0.0 && u_cam_height >= 0.0 && !has_box)
        return -1.0;
    float t_high = ray.y < 0.0 ? max((0.0 - u_cam_height) / ray.y, 0.0) : 0.0;
    // Rays that graze the horizon meet the trough plane very far away; the
    // limit keeps the distance finite (the normal is fully smoothed there).
    float t_low = ray.y < 0.0 ? min((-u_depth - u_cam_height) / ray.y, TL_FAR) : TL_FAR;
    march_state m = march_begin(max(has_box ? min(t_high, box.x) : t_high, t_min));
    int steps = u_march_steps;
#ifdef TL_MARCH_HINT
    m.walk = hint_begin(m.t, steps, has_box ? box.y : 0.0, ray.y < 0.0 ? t_low : 0.0);
    // A bracket that lies where the wave is gentle (its slope bound over
    // the bracket's s below TL_GIANT_GENTLE, a swell on the sea's own
    // slopes) takes the budget too: no crest lies there to pass.
    if (has_box && m.walk.stage == HINT_FIRST && !m.walk.bracket && m.walk.budget == 0 &&
        u_prepass_budget > 0) {
        float s0 = giant_coords(ray.xz * m.walk.b0).x, s1 = giant_coords(ray.xz * m.walk.b1).x;
        if (giant_slope_near(0.5 * (s0 + s1), 0.5 * abs(s1 - s0)) < TL_GIANT_GENTLE) {
            m.walk.budget = u_prepass_budget;
            steps += 1 + TL_HINT_REFINE;
        }
    }
#endif
    // The steps are counted in the ocean's: inside the box the slope bound
    // divides a step by `grow`, and such a step costs 1/grow of one
    // (TL_BOX_STEP_COST at least), so that a ray crossing the box gets as
    // far as over the open sea. Counted whole, a ray grazing the sea or the
    // face inside the box ran out of steps a fraction of the way to its hit
    // and was shaded there, in front of the surface: where no prepass
    // brackets the hit (a camera at the waterline) draft stopped short on a
    // third of a low shot's pixels beside the face (wrong_surface).
    float left = float(steps), cost = 1.0;
    while (left > 0.0) {
        left -= cost;
        cost = 1.0;
        bool in_box = m.t >= box.x && m.t <= box.y;
        vec3 pos = vec3(0.0, u_cam_height, 0.0) + ray * m.t;
        // Rays leaving the ocean band upward see the sky (camera in the
        // band), unless the wave's box still lies ahead of them.
        bool walking = false; // still in the prepass's bracket: no shortcut to the sky
#ifdef TL_MARCH_HINT
        walking = m.walk.stage != HINT_MARCHING;
#endif
        if (ray.y >= 0.0 && pos.y > 0.0 && !in_box && !walking) {
            if (m.t > box.y)
                return -1.0;
            m.t = box.x;
            m.above_last = -1.0;
            continue;
        }
        float above = pos.y - surface_height(pos.xz, TL_MARCH_OCTAVES, m.t * u_lod_angle);
        float radius = above; // how far along the ray is surely free
        // A step no longer than `above` moves at most above·ray_along in s.
        if (in_box) {
            float grow = 1.0 + ray_flat * giant_slope_near(giant_coords(pos.xz).x, above * ray_along);
            radius /= grow;
            cost = max(1.0 / grow, TL_BOX_STEP_COST);
        }
        int act = march_step(m, above, radius);
        if (act == MARCH_FOUND)
            return m.t;
        if (act == MARCH_HIT)
            break;
        if (act == MARCH_NEXT)
            continue;
        // Over-relax: inside the box by TL_MARCH_RELAX, staying in it;
        // outside by the preset's u_march_relax on the way down (a rising
        // ray's plain step is what tells it has left the band for the sky).
        float t = m.t;
        float relax = in_box ? TL_MARCH_RELAX : ray.y < 0.0 ? u_march_relax : 1.0;
        float next = t + relax * radius;
        if (in_box)
            next = max(t + radius, min(next, box.y));
        if (t < box.x && next > box.x)
            next = box.x; // enter the box, then step with the slope bound
        // A relaxed step ends at the trough plane at most, where the next
        // point checks it; only a plain step goes below.
        if (next > t_low && (next < box.x || next > box.y))
            next = max(t + radius, t_low);
        march_advance(m, radius, next);
        // Below the trough plane outside the box: the surface was crossed
        // (past the box only if the ray has one: a miss's box.y means
        // nothing, and the lean program returns t_low there too).
        if (m.t > t_low && (m.t < box.x || m.t > box.y))
            return has_box && m.t > box.y ? max(t_low, box.y) : t_low;
    }
    return march_end(ray, m);
}
#endif
