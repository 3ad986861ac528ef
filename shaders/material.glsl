// Materials of the meshes (the boat): glTF's metallic-roughness model.
// The sun is a GGX microfacet lobe (Trowbridge-Reitz distribution,
// Smith-Schlick shadowing, Schlick's Fresnel) over a Lambert base; the sky
// and the sea around are an environment, its specular share from Karis's
// analytic fit of the split-sum integral. src/mesh/tl_mesh_shading.c holds
// the same formulas in double (tl_mesh_brdf, tl_mesh_env_brdf,
// tl_mesh_normal_map).

// GGX's alpha from perceptual roughness, held off zero: a perfect mirror
// would reflect the sun as a single sample-sized point.
float material_alpha(float roughness)
{
    return max(roughness * roughness, TL_MESH_MIN_ALPHA);
}

// The reflectance at normal incidence: 4% for a dielectric, the base
// colour for a metal.
vec3 material_f0(vec3 base, float metallic)
{
    return mix(vec3(0.04), base, metallic);
}

// The light from direction l reflected toward v per unit of the light's
// irradiance on a surface facing it: BRDF x cos(l). Unit vectors, n the
// normal facing v.
vec3 material_brdf(vec3 n, vec3 v, vec3 l, vec3 base, float roughness, float metallic)
{
    float nl = dot(n, l);
    if (nl <= 0.0)
        return vec3(0.0);
    float nv = max(dot(n, v), 1.0e-4);
    vec3 h = normalize(l + v);
    float nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);
    float a = material_alpha(roughness), a2 = a * a;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float distribution = a2 / (TL_PI * d * d);
    float k = 0.5 * a;
    float visibility = 0.25 / ((nv * (1.0 - k) + k) * (nl * (1.0 - k) + k));
    vec3 f0 = material_f0(base, metallic);
    vec3 fresnel = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
    vec3 diffuse = (1.0 - fresnel) * (1.0 - metallic) * base / TL_PI;
    return (diffuse + distribution * visibility * fresnel) * nl;
}

// The share of an even environment a surface reflects specularly toward
// v at cos nv (Karis, "Physically based shading on mobile", 2014).
vec3 material_env_brdf(vec3 f0, float roughness, float nv)
{
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * max(nv, 0.0))) * r.x + r.y;
    vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
    return f0 * ab.x + ab.y;
}

// What a surface above the water sees in direction dir: the sky (without
// the sun's disc: the sun is the BRDF's direct term), or the sea, which
// mirrors the sky by the water's Fresnel factor (bright toward the
// horizon, dark looking down) and sends up the light it scatters.
// `upwelling`: that light.
vec3 material_environment(vec3 dir, vec3 upwelling)
{
    if (dir.y >= 0.0)
        return sky_atmosphere(dir, u_sun_dir);
    float fresnel = optics_fresnel(-dir.y, 1.0, u_water_ior);
    vec3 mirrored = sky_atmosphere(vec3(dir.x, -dir.y, dir.z), u_sun_dir);
    return fresnel * mirrored + (1.0 - fresnel) * upwelling;
}

// The normal a tangent-space normal map's texel gives a surface of unit
// normal n and tangent t (t.w: the bitangent's side of n x t), its tilt
// scaled (glTF's normalTexture). The interpolated tangent is made square
// to n first; without one the map does nothing (tl_mesh_normal_map).
vec3 material_normal_map(vec3 n, vec4 t, vec3 texel, float scale)
{
    vec3 tt = t.xyz - n * dot(n, t.xyz);
    float len = length(tt);
    if (!(len > 1.0e-12))
        return n;
    tt /= len;
    vec3 b = (t.w < 0.0 ? -1.0 : 1.0) * cross(n, tt);
    vec3 m = (2.0 * texel - 1.0) * vec3(scale, scale, 1.0);
    vec3 mapped = tt * m.x + b * m.y + n * m.z;
    float l = length(mapped);
    return l > 0.0 ? mapped / l : n;
}

// Where runs of water dried, the wet line stands higher: a smooth value
// noise along the hull, in [0, 1] (the streak tl_material_wetness takes).
float material_streak(float s)
{
    float i = floor(s), f = fract(s);
    float a = fract(sin(i * 12.9898) * 43758.5453),
          b = fract(sin((i + 1.0) * 12.9898) * 43758.5453);
    return mix(a, b, f * f * (3.0 - 2.0 * f));
}

// How wet a point `height` metres above the design waterline is
// (tl_mesh_wetness).
float material_wetness(float height, float streak)
{
    float top = TL_MESH_WET_LOW + (TL_MESH_WET_HIGH - TL_MESH_WET_LOW) * streak;
    return 1.0 - smoothstep(TL_MESH_WET_LOW * 0.5, top, height);
}
