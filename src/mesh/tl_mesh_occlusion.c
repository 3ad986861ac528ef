/* Ambient occlusion baked per vertex at load: how much of the sky each
 * vertex sees past the mesh itself. The mesh pass scales the sky's light
 * by it, so a deck darkens where the wheelhouse and bulwarks stand over it
 * and a hull under its rub rail, and no screen-space pass is needed. Rays
 * are cast through a uniform grid of the triangles, from fixed directions
 * (a spiral over the hemisphere, turned per vertex by a hash of its
 * index): the same mesh bakes the same everywhere. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tl_mesh.h"

/* Rays over the whole mesh, shared out among its vertices within these
 * bounds: a small model gets smooth occlusion, a large one a bake that
 * stays within seconds. */
#define RAY_BUDGET 1000000.0
#define RAYS_MOST  32
#define RAYS_LEAST 4
#define GRID_MOST  128 /* cells along an axis */

typedef struct grid {
    double lo[3];
    double cell;
    int n[3];
    uint32_t *start; /* per cell, its first entry in tris; one more at the end */
    uint32_t *tris;
} grid;

static int cell_of(const grid *g, double v, int axis)
{
    int i = (int)floor((v - g->lo[axis]) / g->cell);
    return i < 0 ? 0 : (i >= g->n[axis] ? g->n[axis] - 1 : i);
}

/* Each triangle listed in every cell its bounding box touches. */
static int grid_build(grid *g, const tl_mesh *m, double reach)
{
    double extent = 0.0;
    for (int c = 0; c < 3; c++) {
        g->lo[c] = m->bounds_min[c];
        extent = fmax(extent, (double)m->bounds_max[c] - m->bounds_min[c]);
    }
    g->cell = fmax(fmax(0.25 * reach, extent / GRID_MOST), 1e-9);
    size_t cells = 1;
    for (int c = 0; c < 3; c++) {
        g->n[c] = (int)((m->bounds_max[c] - m->bounds_min[c]) / g->cell) + 1;
        g->n[c] = g->n[c] > GRID_MOST ? GRID_MOST : g->n[c];
        cells *= (size_t)g->n[c];
    }
    size_t triangles = m->index_count / 3;
    g->start = calloc(cells + 1, sizeof *g->start);
    if (!g->start)
        return 0;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t t = 0; t < triangles; t++) {
            int lo[3], hi[3];
            for (int c = 0; c < 3; c++) {
                double a = m->positions[3 * m->indices[3 * t] + c], b = a;
                for (int k = 1; k < 3; k++) {
                    double v = m->positions[3 * m->indices[3 * t + k] + c];
                    a = fmin(a, v);
                    b = fmax(b, v);
                }
                lo[c] = cell_of(g, a, c);
                hi[c] = cell_of(g, b, c);
            }
            for (int z = lo[2]; z <= hi[2]; z++)
                for (int y = lo[1]; y <= hi[1]; y++)
                    for (int x = lo[0]; x <= hi[0]; x++) {
                        size_t cell = ((size_t)z * g->n[1] + y) * g->n[0] + x;
                        if (pass == 0)
                            g->start[cell + 1]++;
                        else
                            g->tris[g->start[cell]++] = (uint32_t)t;
                    }
        }
        if (pass == 0) {
            for (size_t c = 0; c < cells; c++)
                g->start[c + 1] += g->start[c];
            g->tris = malloc((g->start[cells] + 1) * sizeof *g->tris);
            if (!g->tris)
                return 0;
        } else {
            /* The fill moved each start to the next cell's: move them back. */
            memmove(g->start + 1, g->start, cells * sizeof *g->start);
            g->start[0] = 0;
        }
    }
    return 1;
}

/* Möller-Trumbore: the distance along the ray to triangle t, or -1. */
static double hit_triangle(const tl_mesh *m, size_t t, const double o[3], const double d[3])
{
    const float *a = m->positions + 3 * m->indices[3 * t];
    const float *b = m->positions + 3 * m->indices[3 * t + 1];
    const float *c = m->positions + 3 * m->indices[3 * t + 2];
    double e1[3], e2[3], s[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)b[k] - a[k];
        e2[k] = (double)c[k] - a[k];
        s[k] = o[k] - a[k];
    }
    double p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2],
                   d[0] * e2[1] - d[1] * e2[0]};
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (fabs(det) < 1e-18)
        return -1.0;
    double inv = 1.0 / det;
    double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv;
    if (u < 0.0 || u > 1.0)
        return -1.0;
    double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2],
                   s[0] * e1[1] - s[1] * e1[0]};
    double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) * inv;
    if (v < 0.0 || u + v > 1.0)
        return -1.0;
    return (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv;
}

/* The nearest hit within (near, far) along the ray, walking the grid's
 * cells in order (Amanatides and Woo); far when there is none. */
static double trace(const grid *g, const tl_mesh *m, const double o[3], const double d[3],
                    double near, double far)
{
    int cell[3], step[3];
    double next[3], delta[3];
    for (int c = 0; c < 3; c++) {
        cell[c] = cell_of(g, o[c], c);
        step[c] = d[c] >= 0.0 ? 1 : -1;
        double edge = g->lo[c] + (cell[c] + (step[c] > 0 ? 1 : 0)) * g->cell;
        delta[c] = fabs(d[c]) > 1e-12 ? g->cell / fabs(d[c]) : INFINITY;
        next[c] = fabs(d[c]) > 1e-12 ? (edge - o[c]) / d[c] : INFINITY;
    }
    double best = far, t_cell = 0.0;
    while (t_cell < best) {
        size_t at = ((size_t)cell[2] * g->n[1] + cell[1]) * g->n[0] + cell[0];
        for (uint32_t i = g->start[at]; i < g->start[at + 1]; i++) {
            double t = hit_triangle(m, g->tris[i], o, d);
            if (t > near && t < best)
                best = t;
        }
        int axis = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        t_cell = next[axis];
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= g->n[axis])
            break;
        next[axis] += delta[axis];
    }
    return best;
}

int tl_mesh_bake_occlusion(tl_mesh *m, double reach, tl_error *err)
{
    if (m->vertex_count == 0 || m->index_count == 0 || !(reach > 0.0))
        return TL_OK;
    grid g = {0};
    if (!grid_build(&g, m, reach)) {
        free(g.start);
        free(g.tris);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory baking a mesh's occlusion");
    }
    int rays = (int)(RAY_BUDGET / (double)m->vertex_count);
    rays = rays > RAYS_MOST ? RAYS_MOST : (rays < RAYS_LEAST ? RAYS_LEAST : rays);
    const double golden = M_PI * (3.0 - sqrt(5.0));
    for (size_t v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * v, *nf = m->normals + 3 * v;
        double n[3] = {nf[0], nf[1], nf[2]};
        /* A frame around the normal. */
        double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
        double t1[3] = {a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2],
                        a[0] * n[1] - a[1] * n[0]};
        double l = sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
        for (int k = 0; k < 3; k++)
            t1[k] /= l;
        double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                        n[0] * t1[1] - n[1] * t1[0]};
        /* Start just off the surface, so the vertex's own faces are missed. */
        double o[3];
        for (int k = 0; k < 3; k++)
            o[k] = p[k] + n[k] * 1e-3 * reach;
        /* Turned by a hash of the position: the corners of the facets
         * that meet at a point bake alike, with no seam between them. */
        uint32_t h = 2166136261u;
        for (int k = 0; k < 3; k++) {
            h ^= (uint32_t)(int32_t)lrint(p[k] * 1e6);
            h *= 16777619u;
        }
        double turn = (double)h / 4294967296.0 * 2.0 * M_PI;
        double hidden = 0.0;
        for (int i = 0; i < rays; i++) {
            /* Cosine-weighted: the mean of the rays is the diffuse light. */
            double r = sqrt((i + 0.5) / rays), phi = i * golden + turn;
            double x = r * cos(phi), y = r * sin(phi), z = sqrt(fmax(0.0, 1.0 - r * r));
            double d[3];
            for (int k = 0; k < 3; k++)
                d[k] = t1[k] * x + t2[k] * y + n[k] * z;
            double t = trace(&g, m, o, d, 1e-3 * reach, reach);
            /* Nearer occluders hide more: the falloff keeps the reach's
             * edge from showing as a line. */
            if (t < reach)
                hidden += 1.0 - t / reach;
        }
        m->surface[4 * v + 2] = (float)(1.0 - hidden / rays);
    }
    free(g.start);
    free(g.tris);
    return TL_OK;
}
