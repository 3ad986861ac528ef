// The giant wave's lip's shading (TL_FEATURE_GIANT_LIP; its geometry is
// lip.glsl's): after water.glsl, whose normal and reflection it uses.

// How far the combing along the flow tilts the lip's normal across the
// crest (a share of the unit normal), and how much it thickens the sheet
// under its ridges (a share of its thickness). Stronger, the ridges read
// as corrugated plastic.
#define TL_GIANT_LIP_COMB    0.3
#define TL_GIANT_LIP_THICKEN 0.25
// The foam the sheet carries up from the face everywhere, in streaks along
// the flow (the lace's whiteness there).
#define TL_GIANT_LIP_STREAKS 0.2
// Per metre of the wave's water between the lip's foam and the sun: the
// sun's beam is gone within a metre or so (what gets through is the glow,
// added over the foam). The foam under the lip and on the collapsing
// curtain is in shade, lit by the sky: floored at 0.6 of the sun, it read
// as salmon-pink shells.
#define TL_GIANT_LIP_BEAM 2.0
// Where the tube faces down (its normal's height below
// TL_GIANT_LIP_UNDER_FROM, none of it above TL_GIANT_LIP_UNDER_TO), what
// it mirrors is the barrel's water, wherever the combing tilts the
// mirrored ray: a ray off the lip's underside runs into the barrel, onto
// the face or the lip again. Mirroring the sky wherever that ray rose a
// little, the combed underside was striped with pale sky, a sheet torn
// into strips (judges).
#define TL_GIANT_LIP_UNDER_FROM -0.4
#define TL_GIANT_LIP_UNDER_TO   0.1
// Per metre, grey: what the air and the stirred-up matter in the thrown
// sheet take out of the light seen through it, over the water's own
// extinction. Clear water alone let the sky through a metre-thick lip
// nearly whole, a sheet of tinted glass; at a metre per metre it was a
// dull opaque teal again.
#define TL_GIANT_LIP_AERATION 0.3

// The lip at camera-relative `hit`, seen along `ray`: water thrown off
// the crest that mirrors the sky, lit through (it is thin: the sun's light
// crosses it and glows turquoise when it is behind), combed into streaks
// along its flow, aerated and white toward its free edge as it throws, and
// a ball of whitewater once it has landed and collapses.
vec3 giant_lip_color(vec3 ray, vec3 hit)
{
    vec2 sw = giant_coords(hit.xz), n2;
    GiantLip lip = giant_lip_at(sw.y);
    giant_lip_distance(lip, vec2(sw.x, hit.y), n2);
    vec2 d = u_giant_frame.xy;
    vec3 n = normalize(n2.x * vec3(d.x, 0.0, d.y) + vec3(0.0, n2.y, 0.0));
    vec3 across = vec3(d.y, 0.0, -d.x);
    vec2 q = vec2(sw.x, hit.y) - lip.center;
    float angle = giant_lip_angle(lip, vec2(sw.x, hit.y));
    // Metres along the arc from its root, and the share of the whole sweep.
    float flow = (angle - radians(TL_GIANT_LIP_ROOT)) * lip.radius;
    float thrown = giant_lip_along(angle);
    // The lumps tilt the surface: the gradient of |r - R| - half(angle, w)
    // is the radial direction less the half thickness's slope along the
    // arc and along the crest (by differences over a few centimetres; the
    // lumps' cells are metres).
    // On the inner side the barrel's roof thins along the arc too.
    float inner = length(vec2(q.x / TL_GIANT_LIP_THROW, q.y)) < lip.radius ? 1.0 : 0.0;
    if ((giant_lip_roughness(lip, angle) > 0.0 || inner * lip.fillet > 0.0) &&
        angle >= lip.from && angle <= lip.to) {
        const float e = 0.05;
        // The arc's speed (metres per radian) at the point's distance from
        // the centre: the ellipse's, scaled as the point lies off it.
        float r = max(length(vec2(q.x / TL_GIANT_LIP_THROW, q.y)), 1.0e-3) *
                  length(vec2(TL_GIANT_LIP_THROW * cos(angle), sin(angle)));
        float de = e / max(lip.radius, 1.0e-3);
        float h0 = giant_lip_half(lip, angle) + inner * giant_lip_fillet(lip, angle);
        float h1 = giant_lip_half_smooth(lip, angle + de) * giant_lip_lump(lip, angle + de, lip.w) +
                   inner * giant_lip_fillet(lip, angle + de);
        float dh_arc = (h1 - h0) / (de * r);
        float dh_w = giant_lip_half_smooth(lip, angle) *
                     (giant_lip_lump(lip, angle, lip.w + e) - giant_lip_lump(lip, angle, lip.w)) /
                     e;
        vec3 tangent = normalize(TL_GIANT_LIP_THROW * cos(angle) * vec3(d.x, 0.0, d.y) -
                                 vec3(0.0, sin(angle), 0.0));
        n = normalize(n - dh_arc * tangent - dh_w * across);
    }
#ifdef TL_PASS_AOV
    aov_surface(dot(n, ray) > 0.0 ? -n : n, AOV_GIANT);
#endif
    // The water is pulled up the face and over in sheets that do not stay
    // level: the surface is combed along the flow (ridges a metre or so
    // apart across the crest, metres long), which tilts the normal across
    // the crest and breaks the one clean highlight a smooth tube has.
    // Finer, shorter ripples run across the flow, tilting it along the arc.
    // The ridges wander across the crest as they run (parallel, they were
    // stripes).
    vec2 comb = vec2(sw.y * 0.8 + 2.0 * foam_noise(vec2(sw.y * 0.12, flow * 0.15)), flow * 0.12);
    float ridges = (foam_noise(comb) + 0.5 * foam_noise(comb * 2.6 + vec2(7.1, 2.9)) +
                    0.25 * foam_noise(comb * 6.3 + vec2(3.7, 8.3)) - 0.875) /
                   0.875;
    float ripple = foam_noise(vec2(sw.y * 0.4, flow * 1.6)) - 0.5;
    vec3 along_arc = normalize(cross(across, n));
    n = normalize(n + TL_GIANT_LIP_COMB * (ridges * across + ripple * along_arc));
    // The small waves ride on the thrown water too, flattened.
    float value, slope_var;
    vec3 ripples = water_normal(hit.xz, u_normal_epsilon, 0.0, value, slope_var);
    n = water_facing(ray, normalize(n + 0.6 * vec3(ripples.x, 0.0, ripples.z)));
    float sunlit = giant_sunlit(hit.xz, hit.y);
    // Light through the tube: its thickness there along the sun's ray.
    float daylight = smoothstep(-0.05, 0.1, u_sun_dir.y);
    // The combed sheet is thicker under its ridges and thinner between
    // them, so the glow through it (and the view, below) is streaked along
    // the flow too.
    float thickness = 2.0 * giant_lip_half(lip, angle) * (1.0 + TL_GIANT_LIP_THICKEN * ridges);
    float across_sun = thickness / max(abs(dot(u_sun_dir, n)), 0.25);
    float mu = dot(refract(ray, n, 1.0 / u_water_ior), u_sun_dir);
    float phase = 0.5 * (giant_hg(mu, u_giant_scatter.y) + giant_hg(mu, -u_giant_scatter.z));
    float behind = giant_water_toward_sun(hit);
    across_sun += behind;
    float foam_sun = sunlit * exp(-TL_GIANT_LIP_BEAM * behind);
    vec3 lit = u_giant_scatter_color * exp(-u_giant_sigma * across_sun) * sky_sun_light() *
               (u_giant_scatter.x * daylight);
    vec3 body = u_scatter_color * u_scatter_strength * (u_scatter_base + 0.5);
    // What it mirrors: the sky above, and below (the lip's underside faces
    // the face and the trough) the lit water of the face, not the sky
    // (TL_GIANT_LIP_UNDER_*).
    float fresnel = optics_schlick(ray, n);
    vec3 r = normalize(reflect(ray, n));
    vec3 below = layer_emit(TL_LIGHT_BODY, body + lit * (0.25 / TL_PI));
    float sky_share = smoothstep(-0.1, 0.05, r.y) *
                      smoothstep(TL_GIANT_LIP_UNDER_FROM, TL_GIANT_LIP_UNDER_TO, n.y);
    vec3 reflection = mix(below, sky_reflected(vec3(r.x, abs(r.y), r.z), sunlit), sky_share);
    // Seen through: the sheet is a metre or two of water, and what lies
    // behind it along the view shows through it, dimmed per colour by the
    // water crossed: the sky where the lip stands clear of the crest, the
    // crest itself (all its water, so nothing) where the lip lies in front
    // of the face. The water scatters into the view what it takes out of
    // it (the body's light, as much as it is opaque). Opaque everywhere,
    // the lip was one flat teal blade (judges).
    float sheet = thickness / max(abs(dot(ray, n)), 0.25);
    float beyond = giant_water_along(hit + ray * sheet, ray);
    vec3 through = exp(-u_giant_sigma * (sheet + beyond) - TL_GIANT_LIP_AERATION * sheet);
    vec3 color = fresnel * reflection +
                 (1.0 - fresnel) * (layer_emit(TL_LIGHT_BODY, (1.0 - through) * body + lit * phase) +
                                    through * sky_color(ray));
    // Aerated: the thrown sheet takes air as it goes and is white along its
    // free edge, feathered into streaks along the flow; once landed the
    // rest of it collapses into whitewater, in lace, not a solid coat (a
    // whitening by age alone put a white band across the tube).
    float edge = smoothstep(0.65, 1.0, thrown) * (0.25 + 0.75 * lip.progress);
    // As it collapses the whitewater climbs from where it landed up what
    // is left of the curtain.
    float landed = 0.85 * max(smoothstep(0.0, 0.4, lip.spent + thrown - 0.75),
                              smoothstep(0.0, TL_GIANT_LIP_ROUGHEN, lip.spent));
    // Where its top falls in (the arc's root end once it collapses) the
    // water is broken and white: a clean green cut read as a sawn pipe.
    float falling = 0.75 * smoothstep(0.0, 0.3, lip.spent) *
                    (1.0 - smoothstep(0.0, radians(90.0), angle - lip.from));
    float white = max(max(edge, TL_GIANT_LIP_STREAKS), max(landed, falling));
    // The lace in the landed whitewater; the streaks, finer, combed along
    // the flow.
    float lace = foam_lace(vec2(sw.y * 1.5, flow * 0.35));
    float streak = foam_lace(vec2(sw.y * 6.0, flow * 0.8));
    lace = mix(streak, lace, smoothstep(0.0, 0.5, max(max(landed, falling), edge)));
    float foam = smoothstep(1.05 - white, 1.2 - white, lace + 0.25 * white);
    // Whitewater (landed, falling) is thick: opaque, and its lumps' hollows
    // and undersides see less of the sky (the lace and the foam's fine
    // detail; the normal's height), or in shade it is one even blue-grey,
    // a frosted shell.
    float thick = mix(lace, 1.0, max(landed, falling));
    float fine = foam_detail(vec2(sw.y, flow), length(hit) * u_lod_angle);
    float sky = mix(0.35, 1.25, 0.5 + 0.5 * n.y) * clamp(0.3 + 0.8 * lace + 1.4 * fine, 0.15, 1.3);
    color += foam_aerated(ray, n, white, u_scatter_color, foam_sun);
    return foam_shade_sky(color, n, foam, thick, foam_sun, sky) +
           layer_emit(TL_LIGHT_FOAM, foam * lit * phase);
}
