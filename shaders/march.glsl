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

// How a march ends: at a hit (`above` there), refined
// from the last point above the surface; or out of steps, where the last
// position is the best estimate of the hit (the reference returns the start
// point instead, which brightens grazing rays at the horizon; `seed` keeps
// that). The refinement is here, after the march's loop, not inside it:
// llvmpipe runs a loop body's code for every pixel, hit or not.
float march_end(vec3 ray, bool hit, float t_start, float t_last, float above_last, float t,
                float above)
{
    if (!hit)
        return u_miss_at_start ? t_start : t;
    if (above_last > 0.0 && u_refine_steps > 0)
        return march_refine(ray, t_last, above_last, t, above);
    return t;
}

// Distance along `ray` to the surface, or a negative value for a miss;
// the view starts t_min along the ray.
#ifndef TL_FEATURE_GIANT_WAVE
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
    float t = max(t_high, t_min);
    float t_start = t;
    float t_last = t, above_last = -1.0, above_hit = 0.0;
    bool hit = false;
    // Over-relaxation (u_march_relax > 1, enhanced sphere tracing): a step
    // of that many heights above the surface stands when the free interval
    // around the point it reaches overlaps the last point's; otherwise the
    // march goes back to the last point plus its height, which is always
    // safe. r_safe: the last point's height after a relaxed step, 1e30
    // ("nothing to check") after a plain one.
    float t_safe = 0.0, r_safe = 1e30;
    for (int i = 0; i < u_march_steps; i++) {
        vec3 pos = vec3(0.0, u_cam_height, 0.0) + ray * t;
        float above = pos.y - surface_height(pos.xz, TL_MARCH_OCTAVES, t * u_lod_angle);
        if (t - above > t_safe + r_safe) {
            t = t_safe + r_safe; // the relaxed step may have crossed the surface
            r_safe = 1e30;
            continue;
        }
        if (above < u_hit_epsilon) {
            hit = true;
            above_hit = above;
            break;
        }
        t_last = t;
        above_last = above;
        // A relaxed step ends at the band's far plane at most, where the next
        // point checks it; only a plain step leaves the band.
        float next = t + u_march_relax * above;
        if (next > t_end)
            next = max(t + above, t_end);
        t_safe = t;
        r_safe = next > t + above ? above : 1e30;
        t = next;
        if (t > t_end)
            return ray.y < 0.0 ? t_end : -1.0;
    }
    return march_end(ray, hit, t_start, t_last, above_last, t, above_hit);
}
#else
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
    float t = max(has_box ? min(t_high, box.x) : t_high, t_min);
    float t_start = t;
    float t_last = t, above_last = -1.0; // the previous point, for refinement
    float above_hit = 0.0;
    bool hit = false;
    // Over-relaxation as in the lean march above, over radii: a relaxed step
    // stands when the free interval around the point it reaches overlaps the
    // last point's; otherwise the march goes back to one radius past the
    // last point.
    float t_prev = 0.0, r_prev = 0.0;
    bool relaxed = false; // the step that led to t was over-relaxed
    for (int i = 0; i < u_march_steps; i++) {
        bool in_box = t >= box.x && t <= box.y;
        vec3 pos = vec3(0.0, u_cam_height, 0.0) + ray * t;
        // Rays leaving the ocean band upward see the sky (camera in the
        // band), unless the wave's box still lies ahead of them.
        if (ray.y >= 0.0 && pos.y > 0.0 && !in_box) {
            if (t > box.y)
                return -1.0;
            t = box.x;
            above_last = -1.0;
            continue;
        }
        float above = pos.y - surface_height(pos.xz, TL_MARCH_OCTAVES, t * u_lod_angle);
        float radius = above; // how far along the ray is surely free
        // A step no longer than `above` moves at most above·ray_along in s.
        if (in_box)
            radius /= 1.0 + ray_flat * giant_slope_near(giant_coords(pos.xz).x, above * ray_along);
        if (relaxed && t - radius > t_prev + r_prev) {
            t = t_prev + r_prev;
            relaxed = false;
            continue;
        }
        if (above < u_hit_epsilon) {
            hit = true;
            above_hit = above;
            break;
        }
        t_last = t;
        above_last = above;
        // Over-relax: inside the box by TL_MARCH_RELAX, staying in it;
        // outside by the preset's u_march_relax on the way down (a rising
        // ray's plain step is what tells it has left the band for the sky).
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
        t_prev = t;
        r_prev = radius;
        relaxed = next > t + radius;
        t = next;
        // Below the trough plane outside the box: the surface was crossed
        // (past the box only if the ray has one: a miss's box.y means
        // nothing, and the lean program returns t_low there too).
        if (t > t_low && (t < box.x || t > box.y))
            return has_box && t > box.y ? max(t_low, box.y) : t_low;
    }
    return march_end(ray, hit, t_start, t_last, above_last, t, above_hit);
}
#endif
