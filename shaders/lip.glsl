// The giant wave's lip (TL_FEATURE_GIANT_LIP): where the crest breaks, a
// tube along an arc in the crest's cross-section (a circle stretched
// along the travel, TL_GIANT_LIP_THROW), thrown
// forward from the crest's top and falling onto the face in front, marched
// as an implicit surface inside its own box and combined with the height
// field by the nearest hit (trace_water). src/waves/tl_giant.c
// (tl_giant_lip_at, tl_giant_lip_distance) is the same model in double and
// the TL_GIANT_LIP_* constants are its; keep the two in step.
//
// The cross-section at w across is in the (s, y) plane, s the wave's
// coordinate along its travel, y absolute; angles are from straight up,
// clockwise toward the travel.

struct GiantLip {
    bool present;
    vec2 center;     // (s, y) of the arc's centre
    float radius;    // of the tube's centre line
    float thickness; // its half thickness
    float from, to;  // the arc's angles
    float progress;  // the throw, 0 .. 1
    float spent;     // 0 .. 1 once it has landed: it collapses, whitens and thins away
    float fillet;    // metres the inner side is thicker at the root (the barrel's roof)
    float rate;      // how fast the cross-section moves along w, m/m (marching)
    float slope;     // how fast the lumps change the half thickness along the arc, m/m
    float w;         // where across the crest (the lumps' noise is taken there)
};

// How far `angle` lies along the whole sweep, from the root (0) to where
// a full throw ends (1).
float giant_lip_along(float angle)
{
    return clamp((angle - radians(TL_GIANT_LIP_ROOT)) / radians(TL_GIANT_LIP_SWEEP), 0.0, 1.0);
}

// The tube's half thickness at `angle` along its arc before its lumps
// and its edge: it thins from the root to TL_GIANT_LIP_TIP of that at the
// end of the whole sweep, and evens out as it collapses into whitewater.
float giant_lip_half_body(GiantLip lip, float angle)
{
    float along = giant_lip_along(angle);
    return lip.thickness * (1.0 - (1.0 - TL_GIANT_LIP_TIP) * along * (1.0 - lip.spent));
}

// The body thinned toward the free end, however short the throw
// (TL_GIANT_LIP_EDGE over the last TL_GIANT_LIP_EDGE_ARC degrees).
float giant_lip_half_smooth(GiantLip lip, float angle)
{
    float edge = smoothstep(0.0, radians(TL_GIANT_LIP_EDGE_ARC), lip.to - angle);
    return giant_lip_half_body(lip, angle) *
           (1.0 - (1.0 - TL_GIANT_LIP_EDGE) * (1.0 - edge) * (1.0 - lip.spent));
}

// How much the lumps roughen the tube at `angle` (tl_giant_lip_roughness:
// its free edge tears as it throws, all of it once landed), 0 .. 1.
float giant_lip_roughness(GiantLip lip, float angle)
{
    return max(smoothstep(0.0, TL_GIANT_LIP_ROUGHEN, lip.spent),
               TL_GIANT_LIP_TEAR * smoothstep(0.7, 1.0, giant_lip_along(angle)));
}

// The lumps' factor on the half thickness at `angle`, taken at w across
// the crest (tl_giant_lip_lump).
float giant_lip_lump(GiantLip lip, float angle, float w)
{
    float n = foam_noise(
        vec2(w / TL_GIANT_LIP_LUMP_CELL, 17.3 + angle * lip.radius / TL_GIANT_LIP_LUMP_CELL));
    return 1.0 + TL_GIANT_LIP_LUMP * giant_lip_roughness(lip, angle) * (2.0 * n - 1.0);
}

// The tube's half thickness at `angle` along its arc, lumped.
float giant_lip_half(GiantLip lip, float angle)
{
    return giant_lip_half_smooth(lip, angle) * giant_lip_lump(lip, angle, lip.w);
}

// What the barrel's roof adds to the inner side's half thickness at
// `angle` (tl_giant_lip_fillet).
float giant_lip_fillet(GiantLip lip, float angle)
{
    float f = 1.0 - smoothstep(0.0, radians(TL_GIANT_LIP_FILLET_ARC), angle);
    return lip.fillet * f * f;
}

GiantLip giant_lip_at(float w)
{
    GiantLip lip = GiantLip(false, vec2(0.0), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, w);
    float age = giant_break_age(w), T = u_giant_break.z;
    if (abs(w) >= u_giant_mask.z || !(age > 0.0) || age >= T * (1.0 + TL_GIANT_LIP_FADE))
        return lip;
    float dl, db;
    float lambda = giant_lambda(w, dl), height = lambda * u_giant_shape.y;
    float life = 1.0 - smoothstep(T, T * (1.0 + TL_GIANT_LIP_FADE), age);
    lip.spent = 1.0 - life;
    float tall = smoothstep(TL_GIANT_LIP_LOW, TL_GIANT_LIP_HIGH, lambda);
    lip.progress = giant_breaking(w);
    lip.thickness = TL_GIANT_LIP_THICKNESS * height * tall *
                    (1.0 + TL_GIANT_LIP_SWELL * lip.spent) * sqrt(life) *
                    smoothstep(0.0, TL_GIANT_LIP_GROW, lip.progress);
    lip.present = lip.thickness > 0.0;
    lip.radius = TL_GIANT_LIP_RADIUS * height;
    const float anchor = radians(TL_GIANT_LIP_ANCHOR);
    float top_s = giant_bow(w, db) + lambda * u_giant_shape.w / u_giant_shape.x;
    float top_y = -0.5 * u_depth + height;
    // The tube's outer surface passes through the crest's top at the
    // anchor: the lip is the crest's top thrown on, not a tube laid on it.
    lip.center = vec2(top_s, top_y) -
                 (lip.radius + giant_lip_half_body(lip, anchor)) * vec2(sin(anchor), cos(anchor));
    float sweep = lip.progress * tall * radians(TL_GIANT_LIP_SWEEP);
    lip.to = radians(TL_GIANT_LIP_ROOT) + sweep;
    lip.from = radians(TL_GIANT_LIP_ROOT) +
               TL_GIANT_LIP_COLLAPSE * smoothstep(0.0, 1.0, lip.spent) * sweep;
    lip.fillet =
        TL_GIANT_LIP_FILLET * lip.radius * (1.0 - lip.spent) *
        smoothstep(radians(TL_GIANT_LIP_FILLET_FROM), radians(TL_GIANT_LIP_FILLET_TO), lip.to);
    // The march's local bound on how far a point of the tube moves per
    // metre along w. Its free end sweeps with the throw (which runs from 0
    // to 1 over T·peel metres of crest, at most 1.5 times as fast as on
    // average: a smoothstep) and with the tall-crest gate (a smoothstep of
    // the envelope, 1.5 / (high - low) steep); its root end falls in as it
    // collapses (over FADE·T·peel metres, as fast again); the tube grows
    // over the throw's start and swells as it collapses, and its centre
    // moves with its thickness (its outer surface holds the crest's top);
    // and the whole arc
    // moves with the crest's top (bow and envelope) and grows with the
    // envelope (radius).
    float throw_rate = 1.5 / (T * u_giant_break.y); // d progress / dw at most
    float spent_rate = lip.spent > 0.0 && lip.spent < 1.0
                           ? 1.5 / (TL_GIANT_LIP_FADE * T * u_giant_break.y)
                           : 0.0; // d spent / dw at most
    float gate_rate = 1.5 / (TL_GIANT_LIP_HIGH - TL_GIANT_LIP_LOW) * abs(dl);
    float sweep_rate = radians(TL_GIANT_LIP_SWEEP) *
                       ((lip.progress < 1.0 ? throw_rate * tall : 0.0) + lip.progress * gate_rate);
    float root_thickness = TL_GIANT_LIP_THICKNESS * height;
    float tip =
        TL_GIANT_LIP_THROW * lip.radius *
            (sweep_rate + TL_GIANT_LIP_COLLAPSE * 1.5 * spent_rate * sweep) +
        2.0 * root_thickness *
            ((lip.progress < TL_GIANT_LIP_GROW ? 1.5 * throw_rate / TL_GIANT_LIP_GROW : 0.0) +
             gate_rate + 2.0 * TL_GIANT_LIP_SWELL * spent_rate);
    // The lumps: a value noise changes by at most 1.5 of its range per
    // cell (its smoothstep's steepest), so their factor by 3 LUMP per
    // cell, along w and along the arc (on the arc's inner side, whose
    // radius is at least half the centre line's for these thicknesses,
    // twice that per metre); and the roughness grows with the collapse
    // along w.
    float lumped = lip.thickness * (1.0 + TL_GIANT_LIP_LUMP);
    float lump_rate = lumped * 3.0 * TL_GIANT_LIP_LUMP / TL_GIANT_LIP_LUMP_CELL;
    // The edge thins the tube along the arc at most 1.5 (1 - EDGE) of it
    // per EDGE_ARC (the smoothstep's steepest; on the inner side, twice
    // that per metre), and along w as the free end sweeps (it follows the
    // arc's end) and as the collapse evens it out.
    float edge_thin = lumped * (1.0 - TL_GIANT_LIP_EDGE);
    float edge_arc = 1.5 / radians(TL_GIANT_LIP_EDGE_ARC);
    lip.slope = 2.0 * lump_rate + 2.0 * edge_thin * edge_arc / max(lip.radius, 1.0e-3);
    tip += edge_thin * (1.0 + TL_GIANT_LIP_SWELL) * (edge_arc * sweep_rate + spent_rate);
    // The barrel's roof thickens the inner side by at most 2 · 1.5 of
    // itself per FILLET_ARC along the arc (the square of a smoothstep; on
    // the inner side, twice that per metre), and along w as the throw's end
    // passes FILLET_FROM .. FILLET_TO, as it collapses and with the radius.
    float roof = TL_GIANT_LIP_FILLET * lip.radius;
    lip.slope +=
        2.0 * 3.0 * lip.fillet / (radians(TL_GIANT_LIP_FILLET_ARC) * max(lip.radius, 1.0e-3));
    tip += roof * (1.5 / radians(TL_GIANT_LIP_FILLET_TO - TL_GIANT_LIP_FILLET_FROM) * sweep_rate +
                   spent_rate) +
           TL_GIANT_LIP_FILLET * TL_GIANT_LIP_RADIUS * u_giant_shape.y * abs(dl);
    lip.rate = tip + abs(db) + lump_rate +
               lumped * TL_GIANT_LIP_LUMP * 1.5 / TL_GIANT_LIP_ROUGHEN * spent_rate +
               abs(dl) * (u_giant_shape.w / u_giant_shape.x + u_giant_shape.y +
                          2.0 * TL_GIANT_LIP_THROW * TL_GIANT_LIP_RADIUS * u_giant_shape.y);
    return lip;
}

// The arc's point at `angle`, from its centre: a circle stretched along
// the travel by TL_GIANT_LIP_THROW (the lip is thrown out over the face).
vec2 giant_lip_arc_point(GiantLip lip, float angle)
{
    return lip.radius * vec2(TL_GIANT_LIP_THROW * sin(angle), cos(angle));
}

// The angle along the arc of the point sy of the cross-section
// (tl_giant_lip_angle).
float giant_lip_angle(GiantLip lip, vec2 sy)
{
    vec2 q = sy - lip.center;
    return atan(q.x / TL_GIANT_LIP_THROW, q.y);
}

// Signed distance to the tube in the cross-section (negative inside), and
// in *n2 the unit direction of its gradient there (the thinning along the
// arc tilts it by a few degrees at most: left out). With the travel's axis
// shrunk by THROW the arc is a circle of radius R, r the distance from its
// centre there: the distance is |r - R| over r's gradient (first order;
// the tube keeps its thickness where the arc runs down). *bound: |r - R|
// less the half thickness, never more than the distance (r changes by at
// most a metre per metre), which the march steps by.
// (tl_giant_lip_distance_bounded)
float giant_lip_tube_distance(GiantLip lip, vec2 sy, out vec2 n2, out float bound)
{
    n2 = vec2(0.0, 1.0);
    bound = 1e30;
    if (!lip.present)
        return 1e30;
    vec2 q = sy - lip.center;
    vec2 e = vec2(q.x / TL_GIANT_LIP_THROW, q.y);
    float angle = giant_lip_angle(lip, sy);
    if (angle >= lip.from && angle <= lip.to) {
        float r = max(length(e), 1.0e-6);
        vec2 grad = vec2(e.x / TL_GIANT_LIP_THROW, e.y) / r;
        float slope = length(grad);
        float body = giant_lip_half(lip, angle), half_thickness = body, roof = 0.0;
        if (r < lip.radius) {
            // The roof is thicker toward the root: the bound takes it as
            // thick as within the point's reach along the inner side.
            roof = giant_lip_fillet(lip, angle - (lip.radius - r) / max(r, 0.5 * lip.radius));
            half_thickness += giant_lip_fillet(lip, angle);
        }
        n2 = (r >= lip.radius ? 1.0 : -1.0) * grad / slope;
        bound = abs(r - lip.radius) - max(half_thickness, body + roof);
        return abs(r - lip.radius) / slope - half_thickness;
    }
    vec2 d0 = q - giant_lip_arc_point(lip, lip.from), d1 = q - giant_lip_arc_point(lip, lip.to);
    float c0 = length(d0) - giant_lip_half(lip, lip.from),
          c1 = length(d1) - giant_lip_half(lip, lip.to);
    vec2 d = c0 < c1 ? d0 : d1;
    n2 = d / max(length(d), 1.0e-6);
    // The caps are not the nearest part of the arc everywhere past its
    // ends (near the centre, its top is): the bound is the nearer of them
    // and of the band the arc lies in, less the thickest the tube can be.
    bound = min(min(c0, c1), abs(length(e) - lip.radius) -
                                 lip.thickness * (1.0 + TL_GIANT_LIP_LUMP) - lip.fillet);
    return min(c0, c1);
}

// The lip is the tube in front of the vertical through the crest's top
// (the arc's centre: the anchor is straight up); behind it the crest's own
// back is the water. The tube's root there stood above a back that falls
// away, and seen from behind it drew a smooth slab with a stair-stepped
// edge over the wave's back. The cut face lies under the crest's top,
// inside the water. tl_giant_lip_distance_bounded.
float giant_lip_distance(GiantLip lip, vec2 sy, out vec2 n2, out float bound)
{
    float tube = giant_lip_tube_distance(lip, sy, n2, bound);
    float behind = lip.center.x - sy.x;
    bound = max(bound, behind);
    if (behind > tube) {
        n2 = vec2(-1.0, 0.0);
        return behind;
    }
    return tube;
}

float giant_lip_distance(GiantLip lip, vec2 sy, out vec2 n2)
{
    float bound;
    return giant_lip_distance(lip, sy, n2, bound);
}

// The part of the ray inside the lip's box (u_giant_lip_box: s and y
// ranges; u_giant_lip_w: its w range), as giant_ray_interval.
vec2 giant_lip_interval(vec3 ray)
{
    vec3 lo = vec3(u_giant_lip_box.x, u_giant_lip_box.z, u_giant_lip_w.x);
    vec3 hi = vec3(u_giant_lip_box.y, u_giant_lip_box.w, u_giant_lip_w.y);
    return giant_box_interval(ray, lo, hi, TL_FAR);
}

// Sphere tracing of the lip from t_min to t_max (the height field's hit,
// or the far plane): its distance or -1. The cross-section's distance is
// not the 3D one: the lip changes along w, fastest at the peel's front,
// where its free end sweeps metres per metre of crest. A step of h along
// the ray changes the cross-section's distance by at most
// h·(|ray in the (s, y) plane|·(1 + slope) + rate·|ray along w|) (the
// slope: the lumps make it change faster than the distance along the
// arc), so the step is the
// distance over that (locally: the rate is the lip's here), times
// TL_GIANT_LIP_RELAX, and at least TL_GIANT_LIP_MIN_STEP of the tube's
// root thickness (a ray grazing the long tube crept along it and ran out
// of steps; a step that lands inside is bisected back to the surface, and
// the thinnest part, the free end, is thicker than that step).
// Trusting the cross-section's distance alone stepped
// over most of a peeling lip seen along the crest, leaving a floating
// green blade where a few rays happened to land on it.
#define TL_GIANT_LIP_STEPS    128
#define TL_GIANT_LIP_RELAX    0.8
#define TL_GIANT_LIP_GAP      2.0
#define TL_GIANT_LIP_BISECT   8
#define TL_GIANT_LIP_MIN_STEP 0.25
float giant_lip_march(vec3 ray, float t_min, float t_max)
{
    vec2 box = giant_lip_interval(ray);
    float t = max(box.x, t_min), t_end = min(box.y, t_max);
    if (!(t < t_end))
        return -1.0;
    vec2 d = u_giant_frame.xy;
    float ray_w = abs(dot(ray.xz, vec2(d.y, -d.x))), ray_sy = sqrt(max(1.0 - ray_w * ray_w, 0.0));
    float t_out = t; // the last point known outside the tube
    for (int i = 0; i < TL_GIANT_LIP_STEPS; i++) {
        vec3 p = vec3(0.0, u_cam_height, 0.0) + ray * t;
        vec2 sw = giant_coords(p.xz), n2;
        GiantLip lip = giant_lip_at(sw.y);
        float bound;
        float dist = giant_lip_distance(lip, vec2(sw.x, p.y), n2, bound);
        float eps = max(u_hit_epsilon, 1.0e-4 * t);
        if (dist < eps) {
            // A long step (a gap's, or one the local rate underestimated)
            // may land inside the tube: its surface lies between the last
            // point outside and here, and is bisected for. Unrefined, a ray
            // entering the lip from its end along w was shaded metres
            // inside it.
            float a = t_out, b = t;
            for (int k = 0; k < TL_GIANT_LIP_BISECT && b - a > eps; k++) {
                float m = 0.5 * (a + b);
                vec3 q = vec3(0.0, u_cam_height, 0.0) + ray * m;
                vec2 qw = giant_coords(q.xz), qn;
                if (giant_lip_distance(giant_lip_at(qw.y), vec2(qw.x, q.y), qn) < eps)
                    b = m;
                else
                    a = m;
            }
            return b;
        }
        t_out = t;
        // Where the crest has no lip the ray moves on by TL_GIANT_LIP_GAP
        // metres of w: the lip begins (the peel's front), ends (its life)
        // and stops (the tall-crest gate) as a vanishing tube, so nothing
        // visible lies within that of its edges.
        t += lip.present ? max(TL_GIANT_LIP_RELAX * min(bound, 1.0e3) /
                                   (ray_sy * (1.0 + lip.slope) + lip.rate * ray_w),
                               TL_GIANT_LIP_MIN_STEP * lip.thickness)
                         : min(TL_GIANT_LIP_GAP / max(ray_w, 1.0e-6), 1.0e3);
        if (t > t_end)
            return -1.0;
    }
    return -1.0;
}
