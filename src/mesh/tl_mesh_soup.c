/* The triangle soup the built-in boat is built from (tl_mesh_soup.h). */
#include "tl_mesh_soup.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static void sub3(const double a[3], const double b[3], double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] - b[k];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void face_normal(const tl_mesh_facet *f, double n[3])
{
    double e1[3], e2[3];
    sub3(f->p[1], f->p[0], e1);
    sub3(f->p[2], f->p[0], e2);
    cross3(e1, e2, n);
    double l = sqrt(dot3(n, n));
    for (int k = 0; k < 3; k++)
        n[k] = l > 0.0 ? n[k] / l : 0.0;
}

static tl_mesh_facet *push(tl_mesh_soup *s)
{
    if (s->failed)
        return NULL;
    if (s->count == s->capacity) {
        size_t cap = s->capacity ? 2 * s->capacity : 1024;
        tl_mesh_facet *f = realloc(s->facets, cap * sizeof *f);
        if (!f) {
            s->failed = 1;
            return NULL;
        }
        s->facets = f;
        s->capacity = cap;
    }
    return &s->facets[s->count++];
}

void tl_mesh_soup_triangle(tl_mesh_soup *s, const double a[3], const double b[3], const double c[3],
                           int material, int part, const double inside[3])
{
    double e1[3], e2[3], n[3], out[3];
    sub3(b, a, e1);
    sub3(c, a, e2);
    cross3(e1, e2, n);
    if (dot3(n, n) < 1e-30)
        return; /* degenerate: where a section closes at the stem */
    tl_mesh_facet *f = push(s);
    if (!f)
        return;
    for (int k = 0; k < 3; k++)
        out[k] = (a[k] + b[k] + c[k]) / 3.0 - inside[k];
    int flip = dot3(n, out) < 0.0;
    memcpy(f->p[0], a, sizeof f->p[0]);
    memcpy(f->p[1], flip ? c : b, sizeof f->p[1]);
    memcpy(f->p[2], flip ? b : c, sizeof f->p[2]);
    f->material = material;
    f->part = part;
}

void tl_mesh_soup_quad(tl_mesh_soup *s, const double a[3], const double b[3], const double c[3],
                       const double d[3], int material, int part, const double inside[3])
{
    tl_mesh_soup_triangle(s, a, b, c, material, part, inside);
    tl_mesh_soup_triangle(s, a, c, d, material, part, inside);
}

/* The point on edge a b at height h, from the lower end, so that the two
 * facets that share the edge cut it at the same point. */
static void cut(const double a[3], const double b[3], double h, double out[3])
{
    const double *lo = a[1] <= b[1] ? a : b, *hi = a[1] <= b[1] ? b : a;
    double t = (h - lo[1]) / (hi[1] - lo[1]);
    for (int k = 0; k < 3; k++)
        out[k] = lo[k] + (hi[k] - lo[k]) * t;
    out[1] = h;
}

static void add_piece(tl_mesh_soup *s, const tl_mesh_facet *from, const double a[3],
                      const double b[3], const double c[3])
{
    tl_mesh_facet f = *from;
    memcpy(f.p[0], a, sizeof f.p[0]);
    memcpy(f.p[1], b, sizeof f.p[1]);
    memcpy(f.p[2], c, sizeof f.p[2]);
    tl_mesh_facet *slot = push(s);
    if (slot)
        *slot = f;
}

void tl_mesh_soup_split_y(tl_mesh_soup *s, unsigned parts_mask, double h)
{
    size_t n = s->count;
    for (size_t i = 0; i < n && !s->failed; i++) {
        tl_mesh_facet f = s->facets[i];
        if (!(parts_mask & (1u << f.part)))
            continue;
        int above[3], count = 0;
        for (int k = 0; k < 3; k++) {
            above[k] = f.p[k][1] > h;
            count += above[k];
        }
        if (count == 0 || count == 3)
            continue;
        /* The corner alone on its side, in the facet's winding. */
        int lone = 0;
        for (int k = 0; k < 3; k++)
            if (above[k] == (count == 1))
                lone = k;
        const double *a = f.p[lone], *b = f.p[(lone + 1) % 3], *c = f.p[(lone + 2) % 3];
        double ab[3], ac[3];
        cut(a, b, h, ab);
        cut(a, c, h, ac);
        /* The lone corner's piece replaces the facet; the other side's
         * quad is added as two. */
        memcpy(s->facets[i].p[0], a, sizeof ab);
        memcpy(s->facets[i].p[1], ab, sizeof ab);
        memcpy(s->facets[i].p[2], ac, sizeof ac);
        add_piece(s, &f, ab, b, c);
        add_piece(s, &f, ab, c, ac);
    }
}

/* A corner: its facet and which of its points, keyed by its position
 * rounded to a grid finer than any feature, and its part. */
typedef struct corner {
    int64_t key[3];
    int part;
    uint32_t facet;
    int k;
} corner;

static int corner_order(const void *pa, const void *pb)
{
    const corner *a = pa, *b = pb;
    for (int k = 0; k < 3; k++)
        if (a->key[k] != b->key[k])
            return a->key[k] < b->key[k] ? -1 : 1;
    return a->part - b->part;
}

static int same_point(const corner *a, const corner *b)
{
    return !memcmp(a->key, b->key, sizeof a->key) && a->part == b->part;
}

/* The facet's angle at corner k: the weight of its normal there, so that a
 * fan of thin triangles counts no more than one wide one. */
static double corner_angle(const tl_mesh_facet *f, int k)
{
    double e1[3], e2[3];
    sub3(f->p[(k + 1) % 3], f->p[k], e1);
    sub3(f->p[(k + 2) % 3], f->p[k], e2);
    double l = sqrt(dot3(e1, e1) * dot3(e2, e2));
    return l > 0.0 ? acos(fmax(-1.0, fmin(1.0, dot3(e1, e2) / l))) : 0.0;
}

int tl_mesh_soup_finish(tl_mesh_soup *s, tl_mesh *out, tl_error *err)
{
    size_t n = 3 * s->count;
    corner *corners = s->failed ? NULL : malloc((n ? n : 1) * sizeof *corners);
    double *normals = corners ? malloc((n ? n : 1) * 3 * sizeof *normals) : NULL;
    double *faces = normals ? malloc((s->count ? s->count : 1) * 3 * sizeof *faces) : NULL;
    if (!faces) {
        free(corners);
        free(normals);
        free(s->facets);
        memset(s, 0, sizeof *s);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory building a mesh");
    }
    for (size_t f = 0; f < s->count; f++) {
        face_normal(&s->facets[f], faces + 3 * f);
        for (int k = 0; k < 3; k++) {
            corner *c = &corners[3 * f + k];
            for (int a = 0; a < 3; a++)
                c->key[a] = llround(s->facets[f].p[k][a] * 1e7);
            c->part = s->facets[f].part;
            c->facet = (uint32_t)f;
            c->k = k;
        }
    }
    qsort(corners, n, sizeof *corners, corner_order);
    for (size_t i = 0; i < n;) {
        size_t end = i + 1;
        while (end < n && same_point(&corners[end], &corners[i]))
            end++;
        double crease = s->crease_cos[corners[i].part];
        for (size_t a = i; a < end; a++) {
            const double *na = faces + 3 * corners[a].facet;
            double sum[3] = {0, 0, 0};
            for (size_t b = i; b < end; b++) {
                const double *nb = faces + 3 * corners[b].facet;
                double d = dot3(na, nb);
                /* Facets wound either way count alike. */
                if (b != a && fabs(d) < crease)
                    continue;
                double w = corner_angle(&s->facets[corners[b].facet], corners[b].k) *
                           (d < 0.0 ? -1.0 : 1.0);
                for (int k = 0; k < 3; k++)
                    sum[k] += w * nb[k];
            }
            double l = sqrt(dot3(sum, sum));
            double *dst = normals + 3 * (3 * corners[a].facet + corners[a].k);
            for (int k = 0; k < 3; k++)
                dst[k] = l > 1e-12 ? sum[k] / l : na[k];
        }
        i = end;
    }
    /* One vertex per point, part, material and normal: the corners that
     * share all four are welded. */
    tl_mesh_builder b = {0};
    uint32_t *vertex_of = malloc((n ? n : 1) * sizeof *vertex_of);
    if (!vertex_of)
        b.failed = 1;
    for (size_t i = 0; i < n && vertex_of;) {
        size_t end = i + 1;
        while (end < n && same_point(&corners[end], &corners[i]))
            end++;
        for (size_t a = i; a < end; a++) {
            size_t ca = 3 * corners[a].facet + corners[a].k;
            const double *na = normals + 3 * ca;
            int material = s->facets[corners[a].facet].material;
            size_t found = a;
            for (size_t b2 = i; b2 < a && found == a; b2++) {
                size_t cb = 3 * corners[b2].facet + corners[b2].k;
                const double *nb = normals + 3 * cb;
                if (s->facets[corners[b2].facet].material == material &&
                    fabs(na[0] - nb[0]) + fabs(na[1] - nb[1]) + fabs(na[2] - nb[2]) < 1e-6)
                    found = b2;
            }
            if (found != a) {
                vertex_of[ca] = vertex_of[3 * corners[found].facet + corners[found].k];
                continue;
            }
            const double *p = s->facets[corners[a].facet].p[corners[a].k];
            const float pf[3] = {(float)p[0], (float)p[1], (float)p[2]};
            const float nf[3] = {(float)na[0], (float)na[1], (float)na[2]};
            vertex_of[ca] = tl_mesh_add_vertex(&b, pf, nf, &s->materials[material]);
        }
        i = end;
    }
    for (size_t f = 0; f < s->count && vertex_of; f++)
        tl_mesh_add_triangle(&b, vertex_of[3 * f], vertex_of[3 * f + 1], vertex_of[3 * f + 2]);
    free(vertex_of);
    free(corners);
    free(normals);
    free(faces);
    free(s->facets);
    memset(s, 0, sizeof *s);
    return tl_mesh_builder_finish(&b, out, err);
}
