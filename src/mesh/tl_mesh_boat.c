/* The built-in boat: a small fishing boat built at run time from its
 * lines, so that no asset file or licence is needed. One unit long (the
 * bow's stem at z = +0.5, the transom at -0.5, the design waterline at
 * y = 0), scaled by boat.size when drawn; its bounds are
 * TL_BOAT_BUILTIN_MIN and _MAX (test_mesh checks them).
 *
 * The hull is lofted along u (0 at the transom, 1 at the stem): a V bottom
 * from the keel's root to a hard chine that rises toward the bow, flared
 * topsides up to the sheer, a keel and skeg below. Paint is chosen by
 * height after the hull is cut at the waterline and the boot stripe's top,
 * so the colours meet in straight lines whatever the triangles. */
#include <math.h>
#include <string.h>

#include "tl_mesh.h"
#include "tl_mesh_soup.h"

#define STATIONS 64 /* sections from the transom to the stem */

/* The boot stripe straddles the design waterline, as a real boot top
 * does: the band the water alternately wets and leaves, so that the red
 * antifouling shows only in a deep trough or as the boat rolls. */
#define BOOT_BOTTOM (-0.008)
#define BOOT_TOP    0.014
/* The bulwark: its height above the deck, its thickness. */
#define BULWARK    0.03
#define BULWARK_IN 0.006

enum {
    HULL_PAINT, /* resolved by height: antifouling, boot stripe, topsides */
    SHEER_BAND,
    TOPSIDES,
    BOOT_STRIPE,
    ANTIFOULING,
    DECK,
    BULWARK_INSIDE,
    WOOD, /* the rub rail and the bulwark's cap */
    CABIN,
    ROOF,
    DOOR,
    GLASS,
    FRAME,  /* the windows' frames */
    BRONZE, /* the propeller */
    STEEL,
    LAMP_PORT,
    LAMP_STARBOARD,
    LAMP_WHITE,
    MATERIAL_COUNT
};

/* Colours linear; roughness perceptual. The lamps are lit by boat.lights
 * (their emission a multiple of their colour). */
static const tl_mesh_material MATERIALS[MATERIAL_COUNT] = {
    [HULL_PAINT] = {{0.60f, 0.58f, 0.53f}, 0.35f, 0.0f, 0.0f},
    [TOPSIDES] = {{0.60f, 0.58f, 0.53f}, 0.35f, 0.0f, 0.0f},   /* off-white gloss */
    [SHEER_BAND] = {{0.02f, 0.05f, 0.13f}, 0.35f, 0.0f, 0.0f}, /* navy */
    [BOOT_STRIPE] = {{0.015f, 0.015f, 0.018f}, 0.3f, 0.0f, 0.0f},
    [ANTIFOULING] = {{0.21f, 0.03f, 0.02f}, 0.75f, 0.0f, 0.0f}, /* matt red */
    [DECK] = {{0.17f, 0.17f, 0.15f}, 0.85f, 0.0f, 0.0f},        /* grey non-slip */
    [BULWARK_INSIDE] = {{0.55f, 0.55f, 0.52f}, 0.45f, 0.0f, 0.0f},
    [WOOD] = {{0.10f, 0.045f, 0.018f}, 0.35f, 0.0f, 0.0f}, /* varnished teak */
    [CABIN] = {{0.66f, 0.66f, 0.62f}, 0.35f, 0.0f, 0.0f},
    [ROOF] = {{0.50f, 0.51f, 0.50f}, 0.55f, 0.0f, 0.0f},
    [DOOR] = {{0.05f, 0.10f, 0.20f}, 0.4f, 0.0f, 0.0f},
    /* Glass over the wheelhouse's dim interior: its diffuse is what shows
     * through (by day a fraction of the light outside, off a warm wooden
     * inside; with boat.lights a dim amber lamp), the gloss the sky's
     * reflection. A night shot is exposed for the navigation lights, and
     * at twice this emission, neutral, the panes came out white, blown
     * out beside them. */
    [GLASS] = {{0.016f, 0.012f, 0.008f}, 0.05f, 0.0f, 0.02f},
    [FRAME] = {{0.05f, 0.05f, 0.05f}, 0.4f, 0.0f, 0.0f}, /* black rubber and paint */
    [BRONZE] = {{0.78f, 0.50f, 0.28f}, 0.35f, 1.0f, 0.0f},
    [STEEL] = {{0.60f, 0.60f, 0.58f}, 0.3f, 1.0f, 0.0f}, /* stainless */
    /* The side lights' lenses are dark coloured glass by day (a pale
     * saturated diffuse read as a sticker), bright when lit: the same
     * radiance as before, colour x emission. */
    [LAMP_PORT] = {{0.08f, 0.003f, 0.002f}, 0.1f, 0.0f, 600.0f},
    [LAMP_STARBOARD] = {{0.002f, 0.08f, 0.015f}, 0.1f, 0.0f, 600.0f},
    [LAMP_WHITE] = {{0.80f, 0.78f, 0.70f}, 0.1f, 0.0f, 60.0f},
};

/* Parts: facets are smoothed only within their part, and only where they
 * meet closer than its crease angle. */
enum { P_BOTTOM, P_TOPSIDES, P_TRANSOM, P_KEEL, P_DECK, P_RAIL, P_BOX, P_TUBE, PART_COUNT };
static const double CREASE_DEG[PART_COUNT] = {
    [P_BOTTOM] = 30, [P_TOPSIDES] = 30, [P_TRANSOM] = 1, [P_KEEL] = 30,
    [P_DECK] = 20,   [P_RAIL] = 80,     [P_BOX] = 1,     [P_TUBE] = 70,
};

/* Station i's u: closer together toward the stem, where the sections
 * narrow and turn fastest (evenly spaced, the bow's flare showed flat
 * facets in a close-up). */
static double station_u(int i)
{
    double t = (double)i / STATIONS;
    return 1.0 - pow(1.0 - t, 1.5);
}

static double smooth01(double a, double b, double x)
{
    double t = fmin(fmax((x - a) / (b - a), 0.0), 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/* The hull's lines at u: half beam at the sheer and at the chine, the
 * heights of the sheer, the chine and the bottom's root at the keel. */
typedef struct lines {
    double beam, chine_beam, sheer, chine, root, keel;
} lines;

static lines lines_at(double u)
{
    lines l;
    if (u < 0.45)
        l.beam = 0.128 + 0.034 * sin(0.5 * M_PI * u / 0.45);
    else
        /* To a stem with a finite entry (33 deg each side at the sheer):
         * a root of this with its infinite slope at the stem drew a round
         * tub's nose, seen bow-on. */
        l.beam = 0.162 * fmax(0.0, 1.0 - pow((u - 0.45) / 0.55, 2.2));
    l.chine_beam = l.beam * (0.88 - 0.1 * u);
    l.sheer = 0.1 + 0.07 * u * u;
    l.chine = -0.015 + 0.075 * pow(fmax(0.0, (u - 0.5) / 0.5), 1.7);
    if (u <= 0.75)
        l.root = -0.03 - 0.03 * sin(0.5 * M_PI * fmin(u / 0.5, 1.0));
    else
        l.root = -0.06 + (l.chine + 0.06) * pow((u - 0.75) / 0.25, 1.8);
    l.keel = -0.1 + (l.root + 0.1) * smooth01(0.55, 0.95, u);
    return l;
}

/* z of a hull point at u and height y: the stem rakes, its forefoot
 * standing back from the sheer's end. */
static double hull_z(double u, double y)
{
    double h = fmin(fmax((y + 0.1) / 0.27, 0.0), 1.0);
    return -0.5 + u * (1.0 - 0.08 * (1.0 - h));
}

/* Section rows: the V bottom (root to chine), then the topsides (chine to
 * sheer) with a row where the navy sheer band starts. */
#define BOTTOM_ROWS      6
#define SIDE_ROWS        7
#define SHEER_BAND_DEPTH 0.05

static void section(double u, double bottom[BOTTOM_ROWS][3], double side[SIDE_ROWS][3])
{
    lines l = lines_at(u);
    for (int r = 0; r < BOTTOM_ROWS; r++) {
        double s = (double)r / (BOTTOM_ROWS - 1);
        bottom[r][0] = l.chine_beam * s;
        bottom[r][1] = l.root + (l.chine - l.root) * pow(s, 1.3);
    }
    double band = fmax(0.05, 1.0 - SHEER_BAND_DEPTH / fmax(l.sheer - l.chine, 1e-6));
    static const double below[5] = {0.0, 0.25, 0.5, 0.75, 1.0};
    double flare = 1.2 + 0.5 * u;
    for (int r = 0; r < SIDE_ROWS; r++) {
        double t = r < 5 ? below[r] * band : band + (1.0 - band) * (r - 4) / 2.0;
        side[r][0] = l.chine_beam + (l.beam - l.chine_beam) * pow(t, flare);
        side[r][1] = l.chine + (l.sheer - l.chine) * t;
    }
    for (int r = 0; r < BOTTOM_ROWS; r++)
        bottom[r][2] = hull_z(u, bottom[r][1]);
    for (int r = 0; r < SIDE_ROWS; r++)
        side[r][2] = hull_z(u, side[r][1]);
}

static void mirror_x(const double p[3], double out[3])
{
    out[0] = -p[0];
    out[1] = p[1];
    out[2] = p[2];
}

/* A point inside the hull at the height of the waterline, level with p:
 * the hull's faces turn away from it. */
static void hull_inside(const double p[3], double out[3])
{
    out[0] = 0.0;
    out[1] = 0.02;
    out[2] = p[2];
}

static void hull(tl_mesh_soup *s)
{
    static double bottom[STATIONS + 1][BOTTOM_ROWS][3], side[STATIONS + 1][SIDE_ROWS][3];
    for (int i = 0; i <= STATIONS; i++)
        section(station_u(i), bottom[i], side[i]);
    for (int sx = 0; sx < 2; sx++)
        for (int i = 0; i < STATIONS; i++) {
            for (int r = 0; r + 1 < BOTTOM_ROWS; r++) {
                double a[3], b[3], c[3], d[3], in[3];
                memcpy(a, bottom[i][r], sizeof a);
                memcpy(b, bottom[i + 1][r], sizeof b);
                memcpy(c, bottom[i + 1][r + 1], sizeof c);
                memcpy(d, bottom[i][r + 1], sizeof d);
                if (sx) {
                    mirror_x(a, a), mirror_x(b, b), mirror_x(c, c), mirror_x(d, d);
                }
                hull_inside(a, in);
                in[1] = 0.1; /* above the bottom: its faces look down */
                tl_mesh_soup_quad(s, a, b, c, d, HULL_PAINT, P_BOTTOM, in);
            }
            for (int r = 0; r + 1 < SIDE_ROWS; r++) {
                double a[3], b[3], c[3], d[3], in[3];
                memcpy(a, side[i][r], sizeof a);
                memcpy(b, side[i + 1][r], sizeof b);
                memcpy(c, side[i + 1][r + 1], sizeof c);
                memcpy(d, side[i][r + 1], sizeof d);
                if (sx) {
                    mirror_x(a, a), mirror_x(b, b), mirror_x(c, c), mirror_x(d, d);
                }
                hull_inside(a, in);
                tl_mesh_soup_quad(s, a, b, c, d, r >= 4 ? SHEER_BAND : HULL_PAINT, P_TOPSIDES, in);
            }
        }
    /* The transom: the section at u = 0 closed across in strips between
     * its rows, each strip one paint (cut at the waterline later like the
     * rest), so the colours meet in straight lines. */
    double outline[BOTTOM_ROWS + SIDE_ROWS - 1][3];
    int count = 0;
    for (int r = 0; r < BOTTOM_ROWS; r++)
        memcpy(outline[count++], bottom[0][r], sizeof outline[0]);
    for (int r = 1; r < SIDE_ROWS; r++)
        memcpy(outline[count++], side[0][r], sizeof outline[0]);
    const double ahead[3] = {0.0, 0.05, 0.0};
    for (int k = 0; k + 1 < count; k++) {
        double a[3], b[3];
        mirror_x(outline[k], a);
        mirror_x(outline[k + 1], b);
        int material = k >= BOTTOM_ROWS + 3 ? SHEER_BAND : HULL_PAINT;
        tl_mesh_soup_quad(s, outline[k], outline[k + 1], b, a, material, P_TRANSOM, ahead);
    }
}

/* The keel ends this far aft (u), leaving the aperture where the propeller
 * turns ahead of the rudder. */
#define KEEL_AFT 0.09

/* The keel and skeg: a thin fin under the bottom's root, from ahead of
 * the propeller's aperture to the forefoot, where it fairs into the stem. */
static void keel(tl_mesh_soup *s)
{
    const double half = 0.006, u0 = KEEL_AFT, u1 = 0.95;
    const int n = 24;
    double prev[4][3];
    for (int i = 0; i <= n; i++) {
        double u = u0 + (u1 - u0) * i / n;
        lines l = lines_at(u);
        double top = l.root + 0.004; /* into the bottom: no gap at its root */
        double pts[4][3] = {{half, l.keel, 0}, {half, top, 0}, {-half, top, 0}, {-half, l.keel, 0}};
        for (int k = 0; k < 4; k++)
            pts[k][2] = hull_z(u, pts[k][1]);
        if (i == 0) {
            const double ahead[3] = {0.0, 0.5 * (l.keel + top), pts[0][2] + 1.0};
            tl_mesh_soup_quad(s, pts[0], pts[1], pts[2], pts[3], ANTIFOULING, P_BOX, ahead);
        } else {
            for (int side = 0; side < 2; side++) {
                const double in[3] = {0.0, prev[0][1], prev[0][2]};
                int a = side ? 2 : 0, b = side ? 3 : 1;
                tl_mesh_soup_quad(s, prev[a], pts[a], pts[b], prev[b], ANTIFOULING, P_KEEL, in);
            }
            const double above[3] = {0.0, 0.0, prev[0][2]};
            tl_mesh_soup_quad(s, prev[0], pts[0], pts[3], prev[3], ANTIFOULING, P_KEEL, above);
        }
        memcpy(prev, pts, sizeof prev);
    }
}

/* The deck (with a little camber), the bulwark's inside and its cap, the
 * inside of the transom, and the rub rail along the sheer. */
static void deck(tl_mesh_soup *s)
{
    enum { ACROSS = 4 };
    double prev_deck[ACROSS + 1][3], prev_edge[2][2][3], prev_rail[2][5][3];
    for (int i = 0; i <= STATIONS; i++) {
        double u = station_u(i);
        lines l = lines_at(u);
        double inner = fmax(l.beam - BULWARK_IN, 0.0), y = l.sheer - BULWARK;
        double z = hull_z(u, l.sheer);
        double dk[ACROSS + 1][3], edge[2][2][3], rail[2][5][3];
        for (int k = 0; k <= ACROSS; k++) {
            double x = inner * (2.0 * k / ACROSS - 1.0);
            double r = inner > 0.0 ? x / inner : 0.0;
            dk[k][0] = x;
            /* The camber runs out toward the stem, where the deck narrows
             * to a point (kept whole, it rose there into a ridge). */
            dk[k][1] = y + 0.005 * (1.0 - r * r) * (1.0 - smooth01(0.85, 1.0, u));
            dk[k][2] = z;
        }
        for (int sx = 0; sx < 2; sx++) {
            double sign = sx ? -1.0 : 1.0;
            /* The bulwark's inner face, bottom and top; the cap meets the
             * hull's sheer. */
            edge[sx][0][0] = sign * inner, edge[sx][0][1] = y, edge[sx][0][2] = z;
            edge[sx][1][0] = sign * inner, edge[sx][1][1] = l.sheer, edge[sx][1][2] = z;
            /* The rub rail's half-round: from the hull up and out and back. */
            static const double prof[5][2] = {{-0.001, -0.019},
                                              {0.006, -0.017},
                                              {0.008, -0.011},
                                              {0.006, -0.005},
                                              {-0.001, -0.003}};
            /* On the hull's sheer to the stem (drawn inboard there, with
             * the bow's finer entry it showed through the bulwark). */
            double rail_beam = l.beam;
            for (int k = 0; k < 5; k++) {
                double grow = smooth01(1.0, 0.96, u); /* the rail ends at the stem */
                rail[sx][k][0] = sign * (rail_beam + prof[k][0] * grow);
                rail[sx][k][1] = l.sheer + prof[k][1];
                rail[sx][k][2] = hull_z(u, rail[sx][k][1]);
            }
        }
        if (i > 0) {
            for (int k = 0; k < ACROSS; k++) {
                double below[3] = {0.5 * (dk[k][0] + dk[k + 1][0]), y - 1.0, z};
                tl_mesh_soup_quad(s, prev_deck[k], dk[k], dk[k + 1], prev_deck[k + 1], DECK, P_DECK,
                                  below);
            }
            for (int sx = 0; sx < 2; sx++) {
                double sign = sx ? -1.0 : 1.0;
                double outboard[3] = {sign * 1.0, y, z};
                tl_mesh_soup_quad(s, prev_edge[sx][0], edge[sx][0], edge[sx][1], prev_edge[sx][1],
                                  BULWARK_INSIDE, P_BOX, outboard);
                /* The cap, from the inner top edge to the sheer. */
                double a[3] = {sign * lines_at(station_u(i - 1)).beam, prev_edge[sx][1][1],
                               prev_edge[sx][1][2]};
                double b[3] = {sign * l.beam, l.sheer, z};
                double under[3] = {sign * inner, l.sheer - 1.0, z};
                tl_mesh_soup_quad(s, prev_edge[sx][1], edge[sx][1], b, a, WOOD, P_BOX, under);
                for (int k = 0; k < 4; k++) {
                    double in[3] = {0.0, rail[sx][k][1], rail[sx][k][2]};
                    tl_mesh_soup_quad(s, prev_rail[sx][k], rail[sx][k], rail[sx][k + 1],
                                      prev_rail[sx][k + 1], WOOD, P_RAIL, in);
                }
            }
        } else {
            /* The transom's inside, from the deck to the cap, and its cap. */
            double ahead[3] = {0.0, y, z - 1.0};
            double a[3] = {-inner, y, z + BULWARK_IN}, b[3] = {inner, y, z + BULWARK_IN};
            double c[3] = {inner, l.sheer, z + BULWARK_IN},
                   d[3] = {-inner, l.sheer, z + BULWARK_IN};
            tl_mesh_soup_quad(s, a, b, c, d, BULWARK_INSIDE, P_BOX, ahead);
            double e[3] = {l.beam, l.sheer, z}, f[3] = {-l.beam, l.sheer, z};
            double down[3] = {0.0, l.sheer - 1.0, z};
            tl_mesh_soup_quad(s, d, c, e, f, WOOD, P_BOX, down);
            /* The rub rail's ends at the transom, closed (open, they read
             * as a cut tube): a fan over its half-round. */
            for (int sx = 0; sx < 2; sx++) {
                double mid[3] = {0, 0, 0};
                for (int k = 0; k < 5; k++)
                    for (int c3 = 0; c3 < 3; c3++)
                        mid[c3] += rail[sx][k][c3] / 5.0;
                double forward[3] = {mid[0], mid[1], mid[2] + 1.0};
                for (int k = 0; k < 4; k++)
                    tl_mesh_soup_triangle(s, mid, rail[sx][k], rail[sx][k + 1], WOOD, P_BOX,
                                          forward);
            }
        }
        memcpy(prev_deck, dk, sizeof dk);
        memcpy(prev_edge, edge, sizeof edge);
        memcpy(prev_rail, rail, sizeof rail);
    }
}

/* A box with flat faces between corners lo and hi. */
static void box(tl_mesh_soup *s, const double lo[3], const double hi[3], int material)
{
    double c[3];
    for (int k = 0; k < 3; k++)
        c[k] = 0.5 * (lo[k] + hi[k]);
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            double q[4][3];
            for (int k = 0; k < 4; k++) {
                q[k][axis] = side ? hi[axis] : lo[axis];
                q[k][u] = (k == 1 || k == 2) ? hi[u] : lo[u];
                q[k][v] = k >= 2 ? hi[v] : lo[v];
            }
            tl_mesh_soup_quad(s, q[0], q[1], q[2], q[3], material, P_BOX, c);
        }
}

/* A tube of radius r from a to b, `sides` faces round, ends open (they sit
 * in other parts or are too small to see). */
static void tube(tl_mesh_soup *s, const double a[3], const double b[3], double r, int sides,
                 int material)
{
    double d[3], t1[3], t2[3];
    for (int k = 0; k < 3; k++)
        d[k] = b[k] - a[k];
    double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (l <= 0.0)
        return;
    for (int k = 0; k < 3; k++)
        d[k] /= l;
    double up[3] = {fabs(d[1]) < 0.9 ? 0.0 : 1.0, fabs(d[1]) < 0.9 ? 1.0 : 0.0, 0.0};
    t1[0] = d[1] * up[2] - d[2] * up[1];
    t1[1] = d[2] * up[0] - d[0] * up[2];
    t1[2] = d[0] * up[1] - d[1] * up[0];
    double l1 = sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (int k = 0; k < 3; k++)
        t1[k] /= l1;
    t2[0] = d[1] * t1[2] - d[2] * t1[1];
    t2[1] = d[2] * t1[0] - d[0] * t1[2];
    t2[2] = d[0] * t1[1] - d[1] * t1[0];
    for (int i = 0; i < sides; i++) {
        double p0 = 2.0 * M_PI * i / sides, p1 = 2.0 * M_PI * (i + 1) / sides;
        double q[4][3];
        for (int k = 0; k < 3; k++) {
            double o0 = r * (cos(p0) * t1[k] + sin(p0) * t2[k]);
            double o1 = r * (cos(p1) * t1[k] + sin(p1) * t2[k]);
            q[0][k] = a[k] + o0;
            q[1][k] = a[k] + o1;
            q[2][k] = b[k] + o1;
            q[3][k] = b[k] + o0;
        }
        /* Away from the axis at the face's own position along it. */
        double axis_pt[3];
        double along = 0.0;
        for (int k = 0; k < 3; k++)
            along += (0.25 * (q[0][k] + q[1][k] + q[2][k] + q[3][k]) - a[k]) * d[k];
        for (int k = 0; k < 3; k++)
            axis_pt[k] = a[k] + d[k] * along;
        tl_mesh_soup_quad(s, q[0], q[1], q[2], q[3], material, P_TUBE, axis_pt);
    }
}

/* Aft of the keel: the rudder hung behind the propeller's aperture, the
 * shoe that carries its foot from the keel, and a three-bladed propeller
 * on a hub at the keel's aft end (from below a hull read as a board cut
 * square at its aft end). All within the hull's length. */
static void running_gear(tl_mesh_soup *s)
{
    lines keel_end = lines_at(KEEL_AFT);
    const double bottom = keel_end.keel, root = keel_end.root;
    const double z_keel = hull_z(KEEL_AFT, bottom);
    const double rudder_z0 = -0.495, rudder_z1 = rudder_z0 + 0.036;
    const double rudder_top = lines_at(0.02).root;
    box(s, (double[]){-0.002, bottom + 0.002, rudder_z0},
        (double[]){0.002, rudder_top + 0.004, rudder_z1}, ANTIFOULING);
    box(s, (double[]){-0.004, bottom, rudder_z0}, (double[]){0.004, bottom + 0.005, z_keel},
        ANTIFOULING);
    /* The propeller: a hub on the shaft's line and three blades pitched
     * 35 degrees, between the keel's end and the rudder. */
    const double hub[3] = {0.0, 0.5 * (bottom + root) - 0.005, 0.5 * (z_keel + rudder_z1)};
    const double hub_a[3] = {hub[0], hub[1], hub[2] + 0.008},
                 hub_b[3] = {hub[0], hub[1], hub[2] - 0.008};
    tube(s, hub_a, hub_b, 0.004, 8, BRONZE);
    const double reach = 0.8 * (0.5 * (root - bottom)), chord = 0.011, pitch = 35.0 * M_PI / 180.0;
    for (int b = 0; b < 3; b++) {
        double a = 2.0 * M_PI * b / 3.0 + 0.4;
        double radial[3] = {cos(a), sin(a), 0.0}, round[3] = {-sin(a), cos(a), 0.0};
        /* The blade's chord, turned out of the disc's plane by the pitch. */
        double across[3] = {round[0] * cos(pitch), round[1] * cos(pitch), sin(pitch)};
        double q[4][3];
        for (int k = 0; k < 3; k++) {
            q[0][k] = hub[k] + 0.004 * radial[k] - 0.5 * chord * across[k];
            q[1][k] = hub[k] + reach * radial[k] - 0.3 * chord * across[k];
            q[2][k] = hub[k] + reach * radial[k] + 0.3 * chord * across[k];
            q[3][k] = hub[k] + 0.004 * radial[k] + 0.5 * chord * across[k];
        }
        double behind[3] = {hub[0], hub[1], hub[2] - 1.0};
        tl_mesh_soup_quad(s, q[0], q[1], q[2], q[3], BRONZE, P_BOX, behind);
    }
}

/* A quad on a plane, `lift` out from it along `out`. */
static void flat_quad(tl_mesh_soup *s, const double corner[3], const double du[3],
                      const double dv[3], const double out[3], double lift, int material)
{
    double q[4][3], in[3];
    for (int k = 0; k < 3; k++) {
        double o = corner[k] + lift * out[k];
        q[0][k] = o;
        q[1][k] = o + du[k];
        q[2][k] = o + du[k] + dv[k];
        q[3][k] = o + dv[k];
        in[k] = o + 0.5 * (du[k] + dv[k]) - out[k];
    }
    tl_mesh_soup_quad(s, q[0], q[1], q[2], q[3], material, P_BOX, in);
}

/* A window pane a hair out from its wall, in a frame a little wider all
 * round (without, the glass read as a flat card stuck on the wall). The
 * door's panel is a pane without a frame. */
#define FRAME_WIDTH 0.004
static void pane(tl_mesh_soup *s, const double corner[3], const double du[3], const double dv[3],
                 const double out[3], int material)
{
    if (material == GLASS) {
        double lu = sqrt(du[0] * du[0] + du[1] * du[1] + du[2] * du[2]);
        double lv = sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
        double fc[3], fu[3], fv[3];
        for (int k = 0; k < 3; k++) {
            fu[k] = du[k] * (1.0 + 2.0 * FRAME_WIDTH / lu);
            fv[k] = dv[k] * (1.0 + 2.0 * FRAME_WIDTH / lv);
            fc[k] = corner[k] - du[k] * FRAME_WIDTH / lu - dv[k] * FRAME_WIDTH / lv;
        }
        flat_quad(s, fc, fu, fv, out, 0.001, FRAME);
    }
    flat_quad(s, corner, du, dv, out, 0.0015, material);
}

/* The wheelhouse: walls with a raked front, windows all round, a door
 * aft, a roof with an overhang, and the side lights at its front corners. */
static void wheelhouse(tl_mesh_soup *s, double deck_y)
{
    const double x = 0.085, z0 = -0.16, z1 = 0.05, rake = 0.022;
    const double y0 = deck_y - 0.012, y1 = deck_y + 0.15;
    double c[8][3] = {{-x, y0, z0}, {x, y0, z0}, {x, y0, z1},        {-x, y0, z1},
                      {-x, y1, z0}, {x, y1, z0}, {x, y1, z1 - rake}, {-x, y1, z1 - rake}};
    const double centre[3] = {0.0, 0.5 * (y0 + y1), 0.5 * (z0 + z1)};
    tl_mesh_soup_quad(s, c[0], c[1], c[5], c[4], CABIN, P_BOX, centre); /* aft */
    tl_mesh_soup_quad(s, c[3], c[2], c[6], c[7], CABIN, P_BOX, centre); /* front */
    tl_mesh_soup_quad(s, c[1], c[2], c[6], c[5], CABIN, P_BOX, centre); /* port */
    tl_mesh_soup_quad(s, c[0], c[3], c[7], c[4], CABIN, P_BOX, centre); /* starboard */
    /* Windows: three in the raked front, two a side; a door aft. */
    const double wy0 = deck_y + 0.093, wy1 = deck_y + 0.138;
    double front_n[3] = {0.0, rake, y1 - y0};
    double fl = sqrt(front_n[1] * front_n[1] + front_n[2] * front_n[2]);
    front_n[1] /= fl, front_n[2] /= fl;
    for (int k = 0; k < 3; k++) {
        double xa = -0.075 + k * 0.051, xb = xa + 0.046;
        double za = z1 - rake * (wy0 - y0) / (y1 - y0), zb = z1 - rake * (wy1 - y0) / (y1 - y0);
        double corner[3] = {xa, wy0, za}, du[3] = {xb - xa, 0, 0}, dv[3] = {0, wy1 - wy0, zb - za};
        pane(s, corner, du, dv, front_n, GLASS);
    }
    for (int side = 0; side < 2; side++) {
        double sx = side ? -1.0 : 1.0, out[3] = {sx, 0, 0};
        const double spans[2][2] = {{-0.075, -0.012}, {0.0, 0.032}};
        for (int k = 0; k < 2; k++) {
            double corner[3] = {sx * x, wy0, spans[k][0]},
                   du[3] = {0, 0, spans[k][1] - spans[k][0]};
            double dv[3] = {0, wy1 - wy0, 0};
            pane(s, corner, du, dv, out, GLASS);
        }
    }
    const double aft[3] = {0, 0, -1};
    double door[3] = {-0.028, deck_y + 0.004, z0}, du[3] = {0.056, 0, 0}, dv[3] = {0, 0.128, 0};
    pane(s, door, du, dv, aft, DOOR);
    double door_glass[3] = {-0.018, deck_y + 0.09, z0 - 0.0015}, gu[3] = {0.036, 0, 0},
           gv[3] = {0, 0.03, 0};
    pane(s, door_glass, gu, gv, aft, GLASS);
    const double aft_win[2][2] = {{-0.075, -0.038}, {0.038, 0.075}};
    for (int k = 0; k < 2; k++) {
        double corner[3] = {aft_win[k][0], wy0, z0}, u[3] = {aft_win[k][1] - aft_win[k][0], 0, 0},
               v[3] = {0, wy1 - wy0, 0};
        pane(s, corner, u, v, aft, GLASS);
    }
    box(s, (double[]){-x - 0.008, y1, z0 - 0.008},
        (double[]){x + 0.008, y1 + 0.012, z1 - rake + 0.012}, ROOF);
    /* Side lights: red to port, green to starboard (+x: the world is
     * left-handed, +X east of +Z north, so facing the bow at +z starboard
     * is +x). */
    box(s, (double[]){x, y1 - 0.02, z1 - rake - 0.016},
        (double[]){x + 0.006, y1 - 0.008, z1 - rake}, LAMP_STARBOARD);
    box(s, (double[]){-x - 0.006, y1 - 0.02, z1 - rake - 0.016},
        (double[]){-x, y1 - 0.008, z1 - rake}, LAMP_PORT);
}

/* Stanchions along the deck's edge between u0 and u1, joined by a rail at
 * their tops; `bow`: the two sides' rails meet at the stem (a pulpit). */
static void rails(tl_mesh_soup *s, double u0, double u1, int posts, int bow)
{
    const double height = 0.05, r = 0.0022;
    for (int side = 0; side < 2; side++) {
        double sign = side ? -1.0 : 1.0, prev[3] = {0, 0, 0};
        for (int i = 0; i < posts; i++) {
            double u = u0 + (u1 - u0) * i / (posts - 1);
            lines l = lines_at(u);
            double z = hull_z(u, l.sheer);
            double foot[3] = {sign * (l.beam - 0.5 * BULWARK_IN), l.sheer, z};
            double top[3] = {foot[0], l.sheer + height, z};
            tube(s, foot, top, r, 5, STEEL);
            if (i > 0)
                tube(s, prev, top, r, 5, STEEL);
            memcpy(prev, top, sizeof prev);
        }
        if (bow) {
            lines l = lines_at(0.985);
            double tip[3] = {0.0, l.sheer + height, hull_z(0.985, l.sheer)};
            tube(s, prev, tip, r, 5, STEEL);
        }
    }
}

/* The deck's height (its centre line, under the camber) and z at u. */
static void deck_at(double u, double *y, double *z)
{
    lines l = lines_at(u);
    *y = l.sheer - BULWARK;
    *z = hull_z(u, l.sheer);
}

/* A hatch on the deck at u: a coaming `half_x` by `half_z` standing
 * `height` above the deck (its foot sunk under the camber) with a teak lid
 * overhanging it a little. */
static void hatch(tl_mesh_soup *s, double u, double half_x, double half_z, double height)
{
    double y, z;
    deck_at(u, &y, &z);
    box(s, (double[]){-half_x, y - 0.004, z - half_z}, (double[]){half_x, y + height, z + half_z},
        BULWARK_INSIDE);
    box(s, (double[]){-half_x - 0.003, y + height, z - half_z - 0.003},
        (double[]){half_x + 0.003, y + height + 0.004, z + half_z + 0.003}, WOOD);
}

/* A mooring cleat on the deck at u, `x` out from the centre line: two feet
 * and a horn along the hull. */
static void cleat(tl_mesh_soup *s, double u, double x)
{
    double y, z;
    deck_at(u, &y, &z);
    for (int k = -1; k <= 1; k += 2)
        box(s, (double[]){x - 0.002, y - 0.002, z + 0.006 * k - 0.002},
            (double[]){x + 0.002, y + 0.008, z + 0.006 * k + 0.002}, STEEL);
    tube(s, (double[]){x, y + 0.009, z - 0.014}, (double[]){x, y + 0.009, z + 0.014}, 0.0022, 6,
         STEEL);
}

/* What a working deck carries, seen in a close-up from it: the fish
 * hold's hatch aft, a forward hatch, and mooring cleats at the bow and the
 * quarters (a bare deck read as a flat grey floor; judge). Their baked
 * occlusion darkens the deck round their feet. */
static void deck_gear(tl_mesh_soup *s)
{
    hatch(s, 0.2, 0.05, 0.045, 0.012);
    hatch(s, 0.79, 0.032, 0.03, 0.01);
    for (int side = -1; side <= 1; side += 2) {
        cleat(s, 0.88, side * 0.045);
        cleat(s, 0.07, side * 0.105);
    }
}

/* The mast with its spreader, a derrick boom and the forestay, and its
 * white masthead light. */
static void mast(tl_mesh_soup *s, double deck_y)
{
    const double z = 0.167, top = deck_y + 0.42;
    tube(s, (double[]){0.0, deck_y - 0.02, z}, (double[]){0.0, top, z}, 0.0055, 8, STEEL);
    tube(s, (double[]){-0.055, deck_y + 0.32, z}, (double[]){0.055, deck_y + 0.32, z}, 0.003, 6,
         STEEL);
    tube(s, (double[]){0.0, deck_y + 0.09, z + 0.005}, (double[]){0.0, deck_y + 0.17, 0.37}, 0.004,
         6, STEEL);
    lines bow = lines_at(0.985);
    tube(s, (double[]){0.0, top - 0.01, z},
         (double[]){0.0, bow.sheer + 0.004, hull_z(0.985, bow.sheer)}, 0.0012, 4, STEEL);
    box(s, (double[]){-0.0045, deck_y + 0.37, z + 0.0055},
        (double[]){0.0045, deck_y + 0.385, z + 0.012}, LAMP_WHITE);
}

int tl_mesh_default_boat(tl_mesh *out, tl_error *err)
{
    return tl_mesh_builtin_boat(out, NULL, NULL, err);
}

int tl_mesh_builtin_boat(tl_mesh *out, const double topsides[3], const double cabin[3],
                         tl_error *err)
{
    double crease[PART_COUNT];
    for (int p = 0; p < PART_COUNT; p++)
        crease[p] = cos(CREASE_DEG[p] * M_PI / 180.0);
    tl_mesh_material materials[MATERIAL_COUNT];
    memcpy(materials, MATERIALS, sizeof materials);
    /* A wheelhouse in a paint of its own has its roof in it too, a shade
     * darker; in the boat's own paint the roof keeps its grey. */
    int own_cabin = 1;
    for (int i = 0; cabin && i < 3; i++)
        own_cabin &= (float)cabin[i] == MATERIALS[CABIN].color[i];
    for (int i = 0; i < 3; i++) {
        if (topsides)
            materials[TOPSIDES].color[i] = (float)topsides[i];
        if (cabin)
            materials[CABIN].color[i] = (float)cabin[i];
        if (cabin && !own_cabin)
            materials[ROOF].color[i] = (float)(0.8 * cabin[i]);
    }
    tl_mesh_soup s = {0};
    s.materials = materials;
    s.crease_cos = crease;
    hull(&s);
    /* The boot stripe's edges cut the hull: paint by height. */
    const unsigned painted = 1u << P_BOTTOM | 1u << P_TOPSIDES | 1u << P_TRANSOM;
    tl_mesh_soup_split_y(&s, painted, BOOT_BOTTOM);
    tl_mesh_soup_split_y(&s, painted, BOOT_TOP);
    for (size_t i = 0; i < s.count; i++) {
        tl_mesh_facet *f = &s.facets[i];
        if (f->material != HULL_PAINT)
            continue;
        double y = (f->p[0][1] + f->p[1][1] + f->p[2][1]) / 3.0;
        f->material = y < BOOT_BOTTOM ? ANTIFOULING : (y < BOOT_TOP ? BOOT_STRIPE : TOPSIDES);
    }
    keel(&s);
    running_gear(&s);
    deck(&s);
    /* The wheelhouse stands on the deck at u = 0.4, the mast before it. */
    lines l = lines_at(0.4);
    double deck_y = l.sheer - BULWARK;
    wheelhouse(&s, deck_y);
    mast(&s, deck_y);
    deck_gear(&s);
    rails(&s, 0.56, 0.94, 7, 1);
    rails(&s, 0.03, 0.3, 5, 0);
    /* The stern light, on the transom's cap. */
    lines stern = lines_at(0.0);
    box(&s, (double[]){-0.005, stern.sheer, -0.4985}, (double[]){0.005, stern.sheer + 0.01, -0.492},
        LAMP_WHITE);
    int rc = tl_mesh_soup_finish(&s, out, err);
    if (!rc)
        rc = tl_mesh_bake_occlusion(out, TL_MESH_OCCLUSION_REACH, err);
    if (rc)
        tl_mesh_free(out);
    return rc;
}
