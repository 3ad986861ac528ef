/* A triangle soup for building meshes from parts (the built-in boat): each
 * facet carries its material and a part, and turns its face outward from a
 * point given with it. tl_mesh_soup_finish gives each corner a normal
 * averaged over the facets of its part that meet there within the part's
 * crease angle: smooth where the form is smooth, hard at a chine, a
 * deck's edge or a box's corner. Not part of the mesh module's interface. */
#ifndef TL_MESH_SOUP_H
#define TL_MESH_SOUP_H

#include <stddef.h>

#include "tl_mesh.h"

typedef struct tl_mesh_facet {
    double p[3][3];
    int material; /* index into the soup's materials */
    int part;     /* index into the crease angles */
} tl_mesh_facet;

typedef struct tl_mesh_soup {
    tl_mesh_facet *facets;
    size_t count, capacity;
    int failed; /* out of memory: every later call does nothing */
    const tl_mesh_material *materials;
    const double *crease_cos; /* per part: facets meeting closer than this are smoothed */
} tl_mesh_soup;

/* Adds triangle a b c, wound so that its normal points away from `inside`
 * (a point behind the face). */
void tl_mesh_soup_triangle(tl_mesh_soup *s, const double a[3], const double b[3], const double c[3],
                           int material, int part, const double inside[3]);
/* Quad a b c d (in order round its edge) as two triangles. */
void tl_mesh_soup_quad(tl_mesh_soup *s, const double a[3], const double b[3], const double c[3],
                       const double d[3], int material, int part, const double inside[3]);
/* Cuts every facet of the parts in `parts_mask` (bit per part) that
 * crosses the plane y = h into pieces that lie on one side of it. */
void tl_mesh_soup_split_y(tl_mesh_soup *s, unsigned parts_mask, double h);
/* The mesh with creased normals; frees the soup's facets. */
int tl_mesh_soup_finish(tl_mesh_soup *s, tl_mesh *out, tl_error *err);

#endif
