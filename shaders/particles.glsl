// Suspended particles (TL_FEATURE_PARTICLES): the motes in the water near
// the camera that catch the light, one at most in each cell of a world
// grid TL_PARTICLE_CELL metres on a side (u_particles per cubic metre on
// average), out to TL_PARTICLE_RANGE. Each is a sphere of radius
// TL_PARTICLE_RADIUS_MIN .. MAX (a density ∝ 1/r²: many fine, a few
// coarse; tl_optics_particle_scattering) that scatters TL_PARTICLE_EFFICIENCY
// times its cross-section of the sun's beam (by the water's phase
// function: bright looking toward the sun) and of the sky's light at its
// depth, dimmed on the way back to the eye. A mote is drawn as a Gaussian
// spot no narrower than TL_PARTICLE_PIXEL_SPREAD pixels, widened out of
// the lens's focus (TL_PARTICLE_FOCUS, TL_PARTICLE_PUPIL), of the same
// total light, so a frame's mean is what a cloud of them scatters
// (tl_optics_water_inscatter with their scattering: test_particles).
// They hang still in the water: the camera moves past them. Needs
// water_light.glsl.

// Four hashes of a grid cell (wrapped every TL_PARTICLE_PERIOD metres).
vec4 particle_hash(ivec3 c)
{
    const int n = int(float(TL_PARTICLE_PERIOD) / TL_PARTICLE_CELL + 0.5);
    uvec3 q = uvec3(((c % n) + n) % n);
    uint h = q.x * 0x8da6b343u ^ q.y * 0xd8163841u ^ q.z * 0xcb1ab31fu;
    vec4 out_hash;
    for (int i = 0; i < 4; i++) {
        h ^= h >> 15;
        h *= 0x2c1b3c6du;
        h ^= h >> 12;
        h *= 0x297a2d39u;
        h ^= h >> 15;
        out_hash[i] = float(h & 0xffffu) / 65535.0;
    }
    return out_hash;
}

// The light the motes add along `ray` (unit, from the eye) over its first
// `dist` metres: the cells the ray crosses walked in order (a 3D DDA).
vec3 water_particles(vec3 ray, float dist)
{
    float range = min(dist, TL_PARTICLE_RANGE);
    // The eye in cell units, relative to the wrapped grid.
    vec3 eye = u_particle_offset / TL_PARTICLE_CELL;
    ivec3 cell = ivec3(floor(eye));
    vec3 dir = ray + vec3(equal(ray, vec3(0.0))) * 1e-6;
    ivec3 stride = ivec3(sign(dir));
    vec3 delta = abs(1.0 / dir);
    vec3 next = (vec3(cell) + max(vec3(stride), vec3(0.0)) - eye) / dir;
    float presence = u_particles * TL_PARTICLE_CELL * TL_PARTICLE_CELL * TL_PARTICLE_CELL;
    float pixel = 2.0 * u_tan_half_vfov / u_resolution.y;
    float least = TL_PARTICLE_PIXEL_SPREAD * pixel;
    float mu = dot(u_sun_water, -ray);
    vec3 sum = vec3(0.0);
    float t = 0.0; // cell units along the ray
    for (int i = 0; i < TL_PARTICLE_MAX_CELLS && t * TL_PARTICLE_CELL < range; i++) {
        vec4 h = particle_hash(cell);
        if (h.w < presence) {
            // Kept inside the cell's middle, so that no spot is cut by a
            // neighbouring cell's rays.
            vec3 rel = (vec3(cell) + 0.15 + 0.7 * h.xyz - eye) * TL_PARTICLE_CELL;
            float along = dot(rel, ray);
            if (along > TL_PARTICLE_NEAR && along < range) {
                // h.w / presence is even in [0, 1) for the cells that hold
                // one: the inverse of the 1/r² law's distribution.
                float radius = 1.0 / mix(1.0 / TL_PARTICLE_RADIUS_MIN, 1.0 / TL_PARTICLE_RADIUS_MAX,
                                         h.w / presence);
                // Its angular spread: its size, and out of focus a blur
                // disc (a disc D across has a standard deviation of D / 4).
                float blur = 0.25 * TL_PARTICLE_PUPIL * abs(1.0 / along - 1.0 / TL_PARTICLE_FOCUS);
                float spot = max(length(vec2(radius / along, blur)), least);
                float off2 = max(dot(rel, rel) - along * along, 0.0) / (along * along);
                float depth = -(u_cam_height + rel.y);
                float cross_section = TL_PARTICLE_EFFICIENCY * TL_PI * radius * radius;
                // As the water scatters them (water_inscatter).
                vec3 light = water_phase(mu) * water_sun_at(depth) + TL_WATER_SKY_SCATTER * water_sky_at(depth);
                if (depth > 0.0)
                    sum += light * optics_water_transmittance(along) *
                       (cross_section * exp(-0.5 * off2 / (spot * spot)) /
                        (2.0 * TL_PI * spot * spot * along * along));
            }
        }
        // Into the next cell across the nearest face.
        if (next.x < next.y && next.x < next.z) {
            t = next.x;
            next.x += delta.x;
            cell.x += stride.x;
        } else if (next.y < next.z) {
            t = next.y;
            next.y += delta.y;
            cell.y += stride.y;
        } else {
            t = next.z;
            next.z += delta.z;
            cell.z += stride.z;
        }
    }
    return sum;
}
