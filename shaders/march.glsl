// Bounded height-field march (seed 002): the surface lies between the
// crest plane y = 0 and the trough plane y = -depth, so the ray is only
// marched between its hits with those planes, with the adaptive step
// "height above the surface" (it cannot overshoot the surface below it).
// Positions are camera-relative in xz; y is absolute.

// Distance along `ray` to the surface, or a negative value for a miss.
float march_water(vec3 ray)
{
    if (ray.y >= 0.0 && u_cam_height >= 0.0)
        return -1.0;
    float t_high = ray.y < 0.0 ? max((0.0 - u_cam_height) / ray.y, 0.0) : 0.0;
    // Rays that graze the horizon meet the trough plane very far away; the
    // limit keeps the distance finite (the normal is fully smoothed there).
    float t_low = ray.y < 0.0 ? min((-u_depth - u_cam_height) / ray.y, TL_FAR) : TL_FAR;
    float t = t_high;
    for (int i = 0; i < u_march_steps; i++) {
        vec3 pos = vec3(0.0, u_cam_height, 0.0) + ray * t;
        float h = waves_height(pos.xz, u_march_octaves);
        // Rays leaving the wave band upward see the sky (camera in the band).
        if (ray.y >= 0.0 && pos.y > 0.0)
            return -1.0;
        float above = pos.y - h;
        if (above < u_hit_epsilon)
            return t;
        t += above;
        if (t > t_low)
            return t_low;
    }
    // Out of steps: the last position is the best estimate of the hit (the
    // reference returns the start point instead, which brightens grazing
    // rays at the horizon).
    return t;
}
