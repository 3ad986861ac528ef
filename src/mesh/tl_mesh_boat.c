/* The built-in boat: a small fishing boat lofted from cross-sections, one
 * unit long (bow at z = +0.5, stern at -0.5, waterline at y = 0), so that
 * no asset file or licence is needed. Scaled by boat.size when drawn. */
#include <math.h>
#include <string.h>

#include "tl_mesh.h"

#define STATIONS 28 /* cross-sections from stern to bow */
#define ROWS     11 /* points per half-section, keel to gunwale */

static const float HULL_TOP[3] = {0.78f, 0.78f, 0.74f};    /* topsides: off-white */
static const float HULL_BOTTOM[3] = {0.30f, 0.04f, 0.03f}; /* antifouling red */
static const float DECK[3] = {0.32f, 0.20f, 0.11f};        /* oiled wood */
static const float CABIN[3] = {0.80f, 0.80f, 0.78f};
static const float ROOF[3] = {0.18f, 0.26f, 0.40f}; /* blue */
static const float GLASS[3] = {0.02f, 0.03f, 0.04f};
static const float MAST[3] = {0.06f, 0.06f, 0.06f};

/* Hull lines along u in [0, 1] (stern to bow): half beam, keel depth
 * below the waterline, sheer height above it. */
static void lines(double u, double *beam, double *keel, double *sheer)
{
    if (u < 0.45)
        *beam = 0.125 + 0.045 * sin(0.5 * M_PI * u / 0.45);
    else
        *beam = 0.17 * sqrt(fmax(0.0, 1.0 - pow((u - 0.45) / 0.55, 2.0)));
    *keel = u < 0.5 ? 0.07 + 0.03 * sin(M_PI * u) : 0.1 - 0.075 * pow((u - 0.5) / 0.5, 2.0);
    *sheer = 0.1 + 0.07 * u * u;
}

/* Section parameter t in [0, 1] of row r: rows 0-5 from the keel to the
 * waterline, row 6 the waterline again (red below, white above), rows
 * 7-10 up to the gunwale. */
static double row_t(int r, double t_water)
{
    static const double below[6] = {0.0, 0.15, 0.35, 0.6, 0.85, 1.0};
    if (r <= 5)
        return below[r] * t_water;
    return t_water + (1.0 - t_water) * (r - 6) / 4.0;
}

static void hull_point(double u, int r, double p[3])
{
    double beam, keel, sheer;
    lines(u, &beam, &keel, &sheer);
    double tw = keel / (keel + sheer);
    double t = fmin(fmax(row_t(r, tw), 0.0), 1.0); /* rounding can step past 1 */
    p[0] = beam * pow(1.0 - pow(1.0 - t, 2.2), 0.55);
    p[1] = -keel + (keel + sheer) * t;
    p[2] = u - 0.5;
}

static void normalize3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0)
        for (int i = 0; i < 3; i++)
            v[i] /= l;
}

static uint32_t vertex(tl_mesh_builder *b, const double p[3], const double n[3], const float *rgb)
{
    const float pf[3] = {(float)p[0], (float)p[1], (float)p[2]};
    const float nf[3] = {(float)n[0], (float)n[1], (float)n[2]};
    return tl_mesh_add_vertex(b, pf, nf, rgb);
}

/* Both sides of the hull, smooth: normals from the grid's tangents. Row 5
 * and 6 coincide on the waterline so the colour changes sharply there. */
static void hull(tl_mesh_builder *b)
{
    for (int side = -1; side <= 1; side += 2) {
        uint32_t idx[STATIONS + 1][ROWS];
        for (int i = 0; i <= STATIONS; i++) {
            double u = (double)i / STATIONS, du = 1e-3;
            for (int r = 0; r < ROWS; r++) {
                double p[3], pu[3], pm[3], pt[3], pb[3];
                hull_point(u, r, p);
                hull_point(fmin(u + du, 1.0), r, pu);
                hull_point(fmax(u - du, 0.0), r, pm);
                hull_point(u, r < ROWS - 1 ? r + 1 : r, pt);
                hull_point(u, r > 0 ? r - 1 : r, pb);
                double a[3], c[3], n[3];
                for (int k = 0; k < 3; k++) {
                    a[k] = pu[k] - pm[k]; /* toward the bow */
                    c[k] = pt[k] - pb[k]; /* up the section */
                }
                /* At the keel the section tangent is horizontal: aim down. */
                if (r == 0) {
                    c[0] = 1.0;
                    c[1] = 0.0;
                    c[2] = 0.0;
                }
                n[0] = c[1] * a[2] - c[2] * a[1];
                n[1] = c[2] * a[0] - c[0] * a[2];
                n[2] = c[0] * a[1] - c[1] * a[0];
                normalize3(n);
                p[0] *= side;
                n[0] *= side;
                idx[i][r] = vertex(b, p, n, r <= 5 ? HULL_BOTTOM : HULL_TOP);
            }
        }
        for (int i = 0; i < STATIONS; i++)
            for (int r = 0; r < ROWS - 1; r++) {
                if (r == 5)
                    continue; /* rows 5 and 6 are the same points */
                uint32_t a = idx[i][r], c = idx[i + 1][r], d = idx[i + 1][r + 1], e = idx[i][r + 1];
                if (side > 0) {
                    tl_mesh_add_triangle(b, a, e, d);
                    tl_mesh_add_triangle(b, a, d, c);
                } else {
                    tl_mesh_add_triangle(b, a, d, e);
                    tl_mesh_add_triangle(b, a, c, d);
                }
            }
    }
}

/* The flat transom at the stern: a strip across it between each pair of
 * section rows, each strip its rows' colour, so the red bottom meets the
 * white topsides in a straight line at the waterline (rows 5 and 6
 * coincide). A fan from one white centre point blended the colours
 * across its triangles into a pale red X (dusk.tl, the boat seen from
 * astern). */
static void transom(tl_mesh_builder *b)
{
    const double n[3] = {0.0, 0.0, -1.0};
    uint32_t left = 0, right = 0;
    for (int r = 0; r < ROWS; r++) {
        if (r == 6)
            continue; /* the same points as row 5 */
        double p[3], q[3];
        hull_point(0.0, r, p);
        memcpy(q, p, sizeof q);
        q[0] = -p[0];
        /* Rows 5 and 6 meet at the waterline: the strip above it starts
         * there in white. */
        const float *rgb = r <= 4 ? HULL_BOTTOM : HULL_TOP;
        uint32_t l = vertex(b, q, n, rgb), rt = vertex(b, p, n, rgb);
        if (r == 5) {
            /* the red strip below ends here: close it with red vertices */
            uint32_t lr = vertex(b, q, n, HULL_BOTTOM), rr = vertex(b, p, n, HULL_BOTTOM);
            tl_mesh_add_triangle(b, left, rr, right);
            tl_mesh_add_triangle(b, left, lr, rr);
        } else if (r > 0) {
            tl_mesh_add_triangle(b, left, rt, right);
            tl_mesh_add_triangle(b, left, l, rt);
        }
        left = l;
        right = rt;
    }
}

/* The deck, 3% below the sheer, and the inside of the bulwark above it. */
static void deck(tl_mesh_builder *b)
{
    const double up[3] = {0.0, 1.0, 0.0};
    const double inboard[2][3] = {{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}}; /* port, starboard */
    uint32_t prev_d[2] = {0, 0}, prev_e[2] = {0, 0}, prev_t[2] = {0, 0};
    for (int i = 0; i <= STATIONS; i++) {
        double u = (double)i / STATIONS, beam, keel, sheer;
        lines(u, &beam, &keel, &sheer);
        double inner = beam * 0.96, y = sheer - 0.03, z = u - 0.5;
        uint32_t d[2], e[2], t[2];
        for (int k = 0; k < 2; k++) {
            double sx = k ? 1.0 : -1.0;
            double edge[3] = {sx * inner, y, z}, top[3] = {sx * beam, sheer, z};
            d[k] = vertex(b, edge, up, DECK);
            e[k] = vertex(b, edge, inboard[k], HULL_TOP);
            t[k] = vertex(b, top, inboard[k], HULL_TOP);
        }
        if (i > 0) {
            tl_mesh_add_triangle(b, prev_d[0], d[0], d[1]);
            tl_mesh_add_triangle(b, prev_d[0], d[1], prev_d[1]);
            tl_mesh_add_triangle(b, prev_e[0], t[0], e[0]);
            tl_mesh_add_triangle(b, prev_e[0], prev_t[0], t[0]);
            tl_mesh_add_triangle(b, prev_e[1], e[1], t[1]);
            tl_mesh_add_triangle(b, prev_e[1], t[1], prev_t[1]);
        }
        memcpy(prev_d, d, sizeof d);
        memcpy(prev_e, e, sizeof e);
        memcpy(prev_t, t, sizeof t);
    }
}

/* An axis-aligned box with flat faces. */
static void box(tl_mesh_builder *b, const double lo[3], const double hi[3], const float *rgb)
{
    for (int axis = 0; axis < 3; axis++)
        for (int s = 0; s < 2; s++) {
            double n[3] = {0, 0, 0};
            n[axis] = s ? 1.0 : -1.0;
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            uint32_t q[4];
            for (int k = 0; k < 4; k++) {
                double p[3];
                p[axis] = s ? hi[axis] : lo[axis];
                p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
                p[v] = (k >= 2) ? hi[v] : lo[v];
                q[k] = vertex(b, p, n, rgb);
            }
            if (s) {
                tl_mesh_add_triangle(b, q[0], q[1], q[2]);
                tl_mesh_add_triangle(b, q[0], q[2], q[3]);
            } else {
                tl_mesh_add_triangle(b, q[0], q[2], q[1]);
                tl_mesh_add_triangle(b, q[0], q[3], q[2]);
            }
        }
}

int tl_mesh_default_boat(tl_mesh *out, tl_error *err)
{
    tl_mesh_builder b = {0};
    hull(&b);
    transom(&b);
    deck(&b);
    double beam, keel, sheer;
    lines(0.4, &beam, &keel, &sheer);
    double deck_y = sheer - 0.03;
    /* Wheelhouse with a window band, a roof and a mast. */
    box(&b, (double[]){-0.085, deck_y, -0.16}, (double[]){0.085, deck_y + 0.15, 0.05}, CABIN);
    box(&b, (double[]){-0.0855, deck_y + 0.09, -0.1605}, (double[]){0.0855, deck_y + 0.13, 0.0505},
        GLASS);
    box(&b, (double[]){-0.095, deck_y + 0.15, -0.17}, (double[]){0.095, deck_y + 0.165, 0.06},
        ROOF);
    box(&b, (double[]){-0.007, deck_y, 0.16}, (double[]){0.007, deck_y + 0.42, 0.174}, MAST);
    box(&b, (double[]){-0.004, deck_y + 0.3, 0.02}, (double[]){0.004, deck_y + 0.308, 0.17}, MAST);
    return tl_mesh_builder_finish(&b, out, err);
}
