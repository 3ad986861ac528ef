/* The meshes' shading in double: the CPU mirror of shaders/material.glsl
 * and of the wetness in shaders/mesh.frag, for the tests to probe the GPU
 * against. */
#include <math.h>

#include "tl_mesh.h"

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void tl_mesh_brdf(const double n[3], const double v[3], const double l[3], const double base[3],
                  double roughness, double metallic, double out[3])
{
    double nl = dot3(n, l);
    if (nl <= 0.0) {
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    double nv = fmax(dot3(n, v), 1e-4), h[3];
    for (int k = 0; k < 3; k++)
        h[k] = l[k] + v[k];
    double hl = sqrt(dot3(h, h));
    for (int k = 0; k < 3; k++)
        h[k] /= hl;
    double nh = fmax(dot3(n, h), 0.0), vh = fmax(dot3(v, h), 0.0);
    double a = fmax(roughness * roughness, TL_MESH_MIN_ALPHA), a2 = a * a;
    double d = nh * nh * (a2 - 1.0) + 1.0;
    double distribution = a2 / (M_PI * d * d);
    double kk = 0.5 * a;
    double visibility = 0.25 / ((nv * (1.0 - kk) + kk) * (nl * (1.0 - kk) + kk));
    for (int k = 0; k < 3; k++) {
        double f0 = 0.04 + (base[k] - 0.04) * metallic;
        double fresnel = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
        double diffuse = (1.0 - fresnel) * (1.0 - metallic) * base[k] / M_PI;
        out[k] = (diffuse + distribution * visibility * fresnel) * nl;
    }
}

void tl_mesh_env_brdf(const double f0[3], double roughness, double nv, double out[3])
{
    const double c0[4] = {-1.0, -0.0275, -0.572, 0.022}, c1[4] = {1.0, 0.0425, 1.04, -0.04};
    double r[4];
    for (int k = 0; k < 4; k++)
        r[k] = roughness * c0[k] + c1[k];
    double a004 = fmin(r[0] * r[0], exp2(-9.28 * fmax(nv, 0.0))) * r[0] + r[1];
    double a = -1.04 * a004 + r[2], b = 1.04 * a004 + r[3];
    for (int k = 0; k < 3; k++)
        out[k] = f0[k] * a + b;
}

static double smoothstep(double e0, double e1, double x)
{
    double t = fmin(fmax((x - e0) / (e1 - e0), 0.0), 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double tl_mesh_wash_top(double along, double speed)
{
    return TL_MESH_WASH_LINE +
           TL_MESH_BOW_CLIMB * speed * speed / (2.0 * 9.81) * smoothstep(0.5, 0.97, along);
}

double tl_mesh_wash_cover(double height, double top, double lace)
{
    double edge = top * (0.75 + 0.5 * lace);
    return (1.0 - smoothstep(0.7 * edge, edge, height)) * smoothstep(-edge, -0.5 * edge, height);
}

double tl_mesh_wetness(double height, double streak)
{
    double top = TL_MESH_WET_LOW + (TL_MESH_WET_HIGH - TL_MESH_WET_LOW) * streak;
    return 1.0 - smoothstep(TL_MESH_WET_LOW * 0.5, top, height);
}

void tl_mesh_wet_surface(double wet, double base[3], double *roughness)
{
    /* Water fills a rough surface's pores and darkens it by up to half
     * (light is trapped under the film); gloss paint darkens less
     * (TL_MESH_WET_DARKEN). The film is smooth. */
    double porous = smoothstep(0.3, 0.8, *roughness);
    for (int k = 0; k < 3; k++)
        base[k] *= 1.0 - wet * (TL_MESH_WET_DARKEN + (0.5 - TL_MESH_WET_DARKEN) * porous);
    *roughness += (fmin(*roughness, 0.1) - *roughness) * wet;
}

void tl_mesh_normal_map(const double n[3], const double t[4], const double texel[3], double scale,
                        double out[3])
{
    /* glTF: the texel's xy tilt scaled, in the frame (t, b, n), b = w n x t,
     * t made square to n first (it is interpolated across the triangle). */
    double tt[3], nt = dot3(n, t), tlen = 0.0;
    for (int i = 0; i < 3; i++) {
        tt[i] = t[i] - n[i] * nt;
        tlen += tt[i] * tt[i];
    }
    tlen = sqrt(tlen);
    if (!(tlen > 1e-12)) { /* no tangent: no map */
        for (int i = 0; i < 3; i++)
            out[i] = n[i];
        return;
    }
    for (int i = 0; i < 3; i++)
        tt[i] /= tlen;
    const double x = (2.0 * texel[0] - 1.0) * scale, y = (2.0 * texel[1] - 1.0) * scale,
                 z = 2.0 * texel[2] - 1.0;
    const double w = t[3] < 0.0 ? -1.0 : 1.0;
    const double b[3] = {w * (n[1] * tt[2] - n[2] * tt[1]), w * (n[2] * tt[0] - n[0] * tt[2]),
                         w * (n[0] * tt[1] - n[1] * tt[0])};
    double len = 0.0;
    for (int i = 0; i < 3; i++) {
        out[i] = tt[i] * x + b[i] * y + n[i] * z;
        len += out[i] * out[i];
    }
    len = sqrt(len);
    for (int i = 0; i < 3; i++)
        out[i] = len > 0.0 ? out[i] / len : n[i];
}
