/* tl_mesh: triangle meshes on the CPU: the boat the author brings (glTF
 * or OBJ through assimp's C API) or the one tideline builds itself.
 *
 * Conventions (model space): metres, +Y up, the bow toward +Z, the design
 * waterline at y = 0 (the floating pose puts it on the water). A model
 * authored otherwise is turned and scaled by boat.model_yaw and
 * boat.model_scale at render time. Colours are linear RGB. */
#ifndef TL_MESH_H
#define TL_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "core/tl_error.h"

/* A surface's material, glTF's metallic-roughness model: what the mesh
 * pass shades with (shaders/material.glsl, its CPU mirror tl_mesh_brdf). */
typedef struct tl_mesh_material {
    float color[3];  /* base colour, linear RGB */
    float roughness; /* perceptual roughness: 0 a mirror, 1 chalk */
    float metallic;  /* 0 a dielectric (paint, wood, glass), 1 a metal */
    float emission;  /* a lamp's radiance as a multiple of its colour, lit by boat.lights; 0 */
} tl_mesh_material;

/* The texture maps of glTF's metallic-roughness material (OBJ: map_Kd as
 * the base colour). */
enum tl_mesh_map {
    TL_MESH_MAP_BASE_COLOR,         /* sRGB; multiplies the base colour */
    TL_MESH_MAP_METALLIC_ROUGHNESS, /* linear; G multiplies roughness, B metallic */
    TL_MESH_MAP_NORMAL,             /* linear; tangent-space normal, scaled */
    TL_MESH_MAP_OCCLUSION,          /* linear; R, by its strength */
    TL_MESH_MAP_EMISSIVE,           /* sRGB; multiplies the emissive colour */
    TL_MESH_MAP_COUNT
};

/* A decoded texture: 8-bit RGBA, its first row the image's bottom (the
 * UV origin assimp gives both glTF and OBJ). */
typedef struct tl_mesh_image {
    int width, height;
    unsigned char *rgba;
} tl_mesh_image;

/* A run of triangles with one material's maps and the factors that go
 * with them (the per-vertex ones are in colors and surface). */
typedef struct tl_mesh_part {
    size_t first_index, index_count;
    int map[TL_MESH_MAP_COUNT]; /* an index into images, or -1 */
    float emissive[3];          /* radiance: glTF's emissive factor x TL_MESH_EMISSIVE_RADIANCE */
    float normal_scale;         /* glTF normalTexture.scale */
    float occlusion_strength;   /* glTF occlusionTexture.strength */
} tl_mesh_part;

/* The radiance of an emissive factor of 1 (glTF's emissive, the built-in
 * boat's lamps): a lamp that reads as lit against a dusk sky and feeds
 * the glare; boat.lights scales it. */
#define TL_MESH_EMISSIVE_RADIANCE 60.0f
/* The largest texture side accepted (a map over it is refused with its
 * size): what every GL 4.5 driver can hold. */
#define TL_MESH_MAX_TEXTURE 16384

typedef struct tl_mesh {
    size_t vertex_count;
    size_t index_count; /* three per triangle */
    float *positions;   /* x y z per vertex */
    float *normals;     /* unit x y z per vertex */
    float *colors;      /* linear r g b per vertex: the material's base colour */
    /* Per vertex: roughness, metallic, ambient occlusion (the share of the
     * sky the vertex sees past the mesh itself, tl_mesh_bake_occlusion;
     * 1 until baked) and emission. */
    float *surface;
    /* Only for a model with textures, else NULL: per vertex u v (the first
     * UV set), and the tangent x y z with the bitangent's sign w. */
    float *uvs;
    float *tangents;
    uint32_t *indices;
    float bounds_min[3], bounds_max[3];
    /* A loaded model's materials' runs of triangles (the built-in boat
     * has none: one run, no maps) and the images they sample. */
    size_t part_count, image_count;
    tl_mesh_part *parts;
    tl_mesh_image *images;
} tl_mesh;

/* The most a model may have (tl_mesh_load refuses more, with its counts):
 * the occlusion bake and the mesh pass stay within seconds. */
#define TL_MESH_MAX_VERTICES  2000000
#define TL_MESH_MAX_TRIANGLES 2000000

/* Loads every triangle of a glTF 2.0 (.glb, .gltf) or Wavefront OBJ file,
 * its node transforms applied, with smooth normals where the file has
 * none, and its materials' textures (PNG or JPEG, embedded or beside the
 * file). A missing, empty or unreadable file, a folder, another format, a
 * file assimp cannot parse, one without triangles and a texture that is
 * missing or cannot be decoded each fail with a one-line message naming
 * the file (and the material and texture) (TL_ERR_USAGE). */
int tl_mesh_load(const char *path, tl_mesh *out, tl_error *err);

/* The built-in fishing boat, one unit long: scale it by the hull length.
 * A lofted hull (sheer, flare, a hard chine, a keel and skeg), a rub rail,
 * bulwarks and a deck, a wheelhouse with windows, a mast with its lights
 * and rails; painted topsides, a boot stripe, antifouling, stainless,
 * glass; creased normals and baked occlusion. */
int tl_mesh_default_boat(tl_mesh *out, tl_error *err);
/* The same with its topsides (the hull above the boot stripe) and its
 * wheelhouse painted in other linear RGB colours (NULL: its own off-white
 * and light grey, tl_scene.h's TL_BOAT_PAINT and TL_BOAT_CABIN_PAINT). */
int tl_mesh_builtin_boat(tl_mesh *out, const double topsides[3], const double cabin[3],
                         tl_error *err);

/* Bakes ambient occlusion into m->surface: from each vertex, rays over the
 * hemisphere of its normal, out to `reach` model units, find how much of
 * the sky the mesh itself hides. Deterministic. */
int tl_mesh_bake_occlusion(tl_mesh *m, double reach, tl_error *err);
/* The reach of the occlusion as a share of the model's longest side. */
#define TL_MESH_OCCLUSION_REACH 0.1

void tl_mesh_free(tl_mesh *m);

/* Whether any part samples a map or glows: the mesh pass then draws the
 * model part by part with its maps. */
int tl_mesh_has_maps(const tl_mesh *m);

/* The hull's outline, for the water around it: where it meets the water
 * (the design waterline, y = 0: the contact foam follows it) and its
 * widest plan (what keeps the sea out of the hull when it sits low).
 * Half widths at TL_MESH_WATERLINE_STATIONS evenly spaced z, model units. */
#define TL_MESH_WATERLINE_STATIONS 32
typedef struct tl_mesh_outline {
    /* At the waterline, from z = waterline_z[0] (aft) to [1] (forward),
     * from the triangles that cross the plane; all 0 for a mesh that does
     * not reach it. */
    float waterline[TL_MESH_WATERLINE_STATIONS], waterline_z[2];
    /* The widest half width over the mesh's whole height and the model y
     * where it is, from z = plan_z[0] to [1] (the bounds). */
    float plan[TL_MESH_WATERLINE_STATIONS], plan_y[TL_MESH_WATERLINE_STATIONS], plan_z[2];
    float top;    /* the mesh's highest y */
    float bottom; /* its lowest y (the keel): water below it does not touch the hull */
} tl_mesh_outline;
void tl_mesh_outline_of(const tl_mesh *m, tl_mesh_outline *out);

/* The lamps of a mesh: its emissive vertices gathered into clusters (a
 * vertex within TL_MESH_LAMP_GATHER of the mesh's length of a cluster's
 * first joins it), the TL_MESH_LAMPS brightest kept. Each: its centre
 * and size (model units; the radius of the disc of its bounding box's mean
 * projected area) in `where`, its radiance at full boat.lights (colour x
 * emission, linear r g b) and w its side for a side light (-1 port, at -x;
 * 1 starboard; 0 all round: a lamp within 0.3 of the half beam of the
 * centre line) in `light`. The water mirrors them (shaders/lamps.glsl).
 * Returns how many. */
#define TL_MESH_LAMPS       4
#define TL_MESH_LAMP_GATHER 0.03
int tl_mesh_lamps(const tl_mesh *m, float where[TL_MESH_LAMPS][4], float light[TL_MESH_LAMPS][4]);
/* Whether model point p is inside the hull: below its top, and within
 * the waterline's half width at or below y = 0, widening linearly to the
 * plan's at the plan's height (the flare) above. The CPU mirror of
 * boat_contains in shaders/boat.glsl. */
int tl_mesh_outline_contains(const tl_mesh_outline *o, const double p[3]);

/* The meshes' shading in double: the CPU mirror of shaders/material.glsl
 * (test_mesh_shading probes the GPU against it). */
/* GGX's least alpha (roughness squared): a perfect mirror would show the
 * sun as a point a sample wide. A documented clamp. */
#define TL_MESH_MIN_ALPHA 0.002
/* A dielectric's reflectance at normal incidence in the water, not air:
 * ((1.5 - 1.333) / (1.5 + 1.333))^2 for paint of index 1.5 (0.04 in air).
 * At 0.04 a hull seen from below mirrored the bright water above as one
 * even sheen that hid its form. */
#define TL_MESH_F0_UNDER_WATER 0.0035
/* The hull is wet up to TL_MESH_WET_LOW metres above its design waterline
 * and dry from TL_MESH_WET_HIGH, where spray and the waves reach: a band
 * above the boot stripe (wet only to 0.1 m, it lay inside the stripe). */
#define TL_MESH_WET_LOW  0.25
#define TL_MESH_WET_HIGH 0.7
/* The normal a tangent-space normal map's texel (r g b in [0, 1]) gives a
 * surface of unit normal n and unit tangent t (t[3]: the bitangent's sign,
 * b = sign * n x t), its tilt scaled by `scale` (glTF's normal map). */
void tl_mesh_normal_map(const double n[3], const double t[4], const double texel[3], double scale,
                        double out[3]);
/* The white water on a hull at the waterline (shaders/hull_wash.glsl): a
 * wash TL_MESH_WASH_LINE metres high all round, and the bow wave climbing
 * the stem to TL_MESH_BOW_CLIMB of the stagnation height U^2 / 2g (a fine
 * bow parts the water below that). */
#define TL_MESH_WASH_LINE 0.06
#define TL_MESH_BOW_CLIMB 0.35
/* How much of the sea's own colour the sheet of water lays over the
 * paint (the rest: the paint seen through it). */
#define TL_MESH_WASH_FILM 0.6
/* How high the wash reaches above the water beside the hull (m) at
 * `along` (0 at the waterline's aft end, 1 at the stem) for a hull at
 * `speed` m/s. */
double tl_mesh_wash_top(double along, double speed);
/* Its cover at `height` m above that water under the top `top`, the edge
 * moved by `lace` in [0, 1]. */
double tl_mesh_wash_cover(double height, double top, double lace);
/* How much darker wet gloss paint is (a rough, porous surface: half). */
#define TL_MESH_WET_DARKEN 0.25
/* BRDF x cos(l) of a surface with normal n (facing v) for light from l
 * toward v, unit vectors: Lambert under a GGX lobe. */
void tl_mesh_brdf(const double n[3], const double v[3], const double l[3], const double base[3],
                  double roughness, double metallic, double out[3]);
/* The share of an even environment reflected specularly at cos nv. */
void tl_mesh_env_brdf(const double f0[3], double roughness, double nv, double out[3]);
/* How wet a point `height` metres above the design waterline is, 0 to 1;
 * `streak` in [0, 1] moves the wet line up and down where runs of water
 * dried. */
double tl_mesh_wetness(double height, double streak);
/* A wet surface: base colour darker where it is porous (rough), and
 * glossier, wet in [0, 1]. */
void tl_mesh_wet_surface(double wet, double base[3], double *roughness);

/* A mesh under construction: vertices and triangles appended, arrays grown
 * as needed. tl_mesh_builder_finish computes the bounds. */
typedef struct tl_mesh_builder {
    tl_mesh mesh;
    size_t vertex_capacity, index_capacity;
    int failed; /* out of memory: every later call does nothing */
} tl_mesh_builder;

uint32_t tl_mesh_add_vertex(tl_mesh_builder *b, const float p[3], const float n[3],
                            const tl_mesh_material *material);
void tl_mesh_add_triangle(tl_mesh_builder *b, uint32_t i0, uint32_t i1, uint32_t i2);
int tl_mesh_builder_finish(tl_mesh_builder *b, tl_mesh *out, tl_error *err);

#endif
