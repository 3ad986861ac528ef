// The physical sky's sky-view table, one texel per (azimuth from the sun,
// latitude): the radiance along that view ray for a sun of illuminance 1.
// The same integral as build_view_row in src/sky/tl_sky.c (which stays the
// CPU's reference of it, test_sky compares the two): 40 steps, denser near
// the eye, single scattering through the transmittance table plus the
// multiple-scattering table's psi_ms, and the ground's light where the ray
// meets it. Rebuilt whenever the sun or the camera's height step moves: on
// the CPU that was a large share of a frame on two cores, the GPU waiting.
//
// In float, radii near 6.4e6 m keep about half a metre: every quantity that
// is a small difference of radii (heights, r^2 - g^2, the distances to the
// ground and the top) is formed from the camera's height and the distance
// along the ray instead, and the smaller root of each quadratic is taken
// as c / (larger root).

#include "constants.glsl"

uniform sampler2D u_transmittance; // tl_sky_luts.transmittance (Bruneton's mapping)
uniform sampler2D u_ms;            // tl_sky_luts.ms: psi_ms over (mu_s, sqrt(h / H))
uniform ivec2 u_view_size;         // TL_SKY_VIEW_W x TL_SKY_VIEW_H
uniform float u_ground_radius;     // metres
uniform float u_top_radius;
uniform float u_height;            // the camera above the ground (tl_sky_camera_height)
uniform float u_sun_elevation;     // radians
uniform vec3 u_rayleigh;           // scattering at the ground, per metre
uniform float u_rayleigh_height;
uniform float u_mie_scattering;
uniform float u_mie_absorption;
uniform float u_mie_height;
uniform float u_mie_g;
uniform vec3 u_ozone;
uniform float u_ozone_center;
uniform float u_ozone_width;
uniform float u_ground_albedo;

layout(location = 0) out vec4 out_radiance;

const int VIEW_STEPS = 40;

// Scattering and extinction at height h above the ground.
void medium(float h, out vec3 ray_s, out float mie_s, out vec3 ext)
{
    float dr = exp(-h / u_rayleigh_height), dm = exp(-h / u_mie_height);
    float dozone = max(0.0, 1.0 - abs(h - u_ozone_center) / u_ozone_width);
    mie_s = u_mie_scattering * dm;
    ray_s = u_rayleigh * dr;
    ext = ray_s + (u_mie_scattering + u_mie_absorption) * dm + u_ozone * dozone;
}

// The transmittance table at a point of radius r, rho2 = r^2 - g^2 (given
// apart: r^2 alone has lost it), toward cos-zenith mu_s; 0 in the planet's
// shadow. tl_sky.c's lut_transmittance and transmittance_uv.
vec3 transmittance(float r, float rho2, float mu_s)
{
    float rr_mu2 = r * r * mu_s * mu_s;
    if (mu_s < 0.0 && rr_mu2 >= rho2)
        return vec3(0.0);
    float g = u_ground_radius, top = u_top_radius;
    float H2 = (top - g) * (top + g);
    float top_gap2 = H2 - rho2; // top^2 - r^2
    float root = sqrt(max(rr_mu2 + top_gap2, 0.0));
    float to_top = mu_s > 0.0 ? top_gap2 / (root + r * mu_s) : root - r * mu_s;
    float rho = sqrt(max(rho2, 0.0)), H = sqrt(H2);
    float d_min = top_gap2 / (top + r);
    float span = rho + H - d_min;
    float u = span > 0.0 ? (max(to_top, 0.0) - d_min) / span : 0.0;
    return textureLod(u_transmittance, vec2(u, rho / H), 0.0).rgb;
}

float phase_rayleigh(float c)
{
    return 3.0 / (16.0 * TL_PI) * (1.0 + c * c);
}

float phase_mie(float c, float g) // Cornette-Shanks
{
    float k = 3.0 / (8.0 * TL_PI) * (1.0 - g * g) / (2.0 + g * g);
    return k * (1.0 + c * c) / pow(1.0 + g * g - 2.0 * g * c, 1.5);
}

void main()
{
    ivec2 texel = ivec2(gl_FragCoord.xy);
    float g = u_ground_radius, top = u_top_radius, h0 = u_height;
    float r = g + h0;
    float rho2_eye = h0 * (2.0 * g + h0); // r^2 - g^2
    // The table's latitude mapping: rows crowd at the horizon.
    float l = 2.0 * (float(texel.y) + 0.5) / float(u_view_size.y) - 1.0;
    float lat = sign(l) * l * l * 0.5 * TL_PI;
    float mu = sin(lat), cos_lat = cos(lat);
    float az = TL_PI * (float(texel.x) + 0.5) / float(u_view_size.x), cos_az = cos(az);
    float sin_s = sin(u_sun_elevation), cos_s = cos(u_sun_elevation);

    // The ray's length: to the ground (the nearer root) or to the top.
    float rr_mu2 = r * r * mu * mu;
    bool ground = mu < 0.0 && rr_mu2 >= rho2_eye;
    float d;
    if (ground) {
        d = rho2_eye / (sqrt(rr_mu2 - rho2_eye) - r * mu);
    } else {
        float top_gap2 = (top - r) * (top + r);
        float root = sqrt(rr_mu2 + top_gap2);
        d = mu > 0.0 ? top_gap2 / (root + r * mu) : root - r * mu;
    }

    float cos_sun = mu * sin_s + cos_lat * cos_az * cos_s;
    float pr = phase_rayleigh(cos_sun), pm = phase_mie(cos_sun, u_mie_g);
    vec3 depth = vec3(0.0), L = vec3(0.0);
    float prev = 0.0;
    for (int i = 0; i < VIEW_STEPS; i++) {
        float x = float(i + 1) / float(VIEW_STEPS);
        float t1 = d * x * x, dt = t1 - prev;
        float t = prev + 0.5 * dt;
        prev = t1;
        float rho2 = rho2_eye + 2.0 * r * mu * t + t * t; // rp^2 - g^2
        float rp = sqrt(g * g + rho2);
        float h = rho2 / (rp + g);
        vec3 rs, ext;
        float msc;
        medium(h, rs, msc, ext);
        vec3 seg = exp(-(depth + 0.5 * ext * dt));
        depth += ext * dt;
        float mu_s = ((r + mu * t) * sin_s + cos_lat * t * cos_s * cos_az) / rp;
        vec3 ts = transmittance(rp, rho2, mu_s);
        float mu_u = 0.5 + 0.5 * sign(mu_s) * sqrt(abs(mu_s));
        vec3 psi = textureLod(u_ms, vec2(mu_u, sqrt(max(h, 0.0) / (top - g))), 0.0).rgb;
        L += seg * ((rs * pr + msc * pm) * ts + (rs + msc) * psi) * dt;
    }
    if (ground) { // the Lambertian ground's light, through the whole ray's air
        float mu_g = (d * cos_sun + r * sin_s) / g;
        vec3 ts = transmittance(g, 0.0, mu_g);
        L += exp(-depth) * ts * max(mu_g, 0.0) * u_ground_albedo / TL_PI;
    }
    out_radiance = vec4(L, 1.0);
}
