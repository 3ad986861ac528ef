/* Meshes: the glTF and OBJ loader (assimp) on small files in tests/meshes,
 * its errors, and the built-in boat. argv[1] is tests/meshes. */
#include <math.h>
#include <stdlib.h>

#include <unistd.h>

#include "mesh/tl_mesh.h"
#include "scene/tl_scene.h"
#include "tl_gltf_test.h"
#include "tl_test.h"

static const char *dir;

static const char *path_of(const char *name)
{
    static char buf[1024];
    snprintf(buf, sizeof buf, "%s/%s", dir, name);
    return buf;
}

static void check_normals(const tl_mesh *m)
{
    int unit = 1;
    for (size_t i = 0; i < m->vertex_count; i++) {
        const float *n = m->normals + 3 * i;
        unit &= fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) < 1e-3;
        for (int c = 0; c < 3; c++)
            unit &= isfinite(m->positions[3 * i + c]) != 0;
    }
    CHECK(unit);
    int in_range = 1;
    for (size_t i = 0; i < m->index_count; i++)
        in_range &= m->indices[i] < m->vertex_count;
    CHECK(in_range);
}

static void test_gltf(void)
{
    tl_mesh m;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_mesh_load(path_of("skiff.gltf"), &m, &err) == TL_OK);
    printf("skiff.gltf: %zu vertices, %zu triangles, bounds %g %g %g .. %g %g %g\n", m.vertex_count,
           m.index_count / 3, m.bounds_min[0], m.bounds_min[1], m.bounds_min[2], m.bounds_max[0],
           m.bounds_max[1], m.bounds_max[2]);
    CHECK(m.index_count == 8 * 3);
    CHECK(m.vertex_count >= 6 && m.vertex_count <= 24);
    /* The node's scale 2 and translation +1 in y are applied. */
    CHECK_NEAR(m.bounds_min[0], -1.0, 1e-6);
    CHECK_NEAR(m.bounds_max[0], 1.0, 1e-6);
    CHECK_NEAR(m.bounds_min[1], 0.2, 1e-6);
    CHECK_NEAR(m.bounds_max[1], 1.0, 1e-6);
    CHECK_NEAR(m.bounds_min[2], -2.0, 1e-6);
    CHECK_NEAR(m.bounds_max[2], 2.0, 1e-6);
    /* The glTF base colour factor. */
    CHECK_NEAR(m.colors[0], 0.8, 1e-6);
    CHECK_NEAR(m.colors[1], 0.1, 1e-6);
    CHECK_NEAR(m.colors[2], 0.05, 1e-6);
    check_normals(&m);
    tl_mesh_free(&m);
}

static void test_obj(void)
{
    tl_mesh m;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_mesh_load(path_of("crate.obj"), &m, &err) == TL_OK);
    printf("crate.obj: %zu vertices, %zu triangles\n", m.vertex_count, m.index_count / 3);
    CHECK(m.index_count == 12 * 3); /* six quads, triangulated; the line is dropped */
    CHECK(m.vertex_count >= 8 && m.vertex_count <= 24);
    /* The unit cube from 0 to 1, x mirrored into tideline's left-handed
     * world. */
    for (int c = 0; c < 3; c++) {
        CHECK_NEAR(m.bounds_min[c], c ? 0.0 : -1.0, 1e-6);
        CHECK_NEAR(m.bounds_max[c], c ? 1.0 : 0.0, 1e-6);
    }
    /* The material's Kd. */
    CHECK_NEAR(m.colors[0], 0.2, 1e-6);
    CHECK_NEAR(m.colors[1], 0.4, 1e-6);
    CHECK_NEAR(m.colors[2], 0.6, 1e-6);
    check_normals(&m);
    tl_mesh_free(&m);
}

/* One line naming the file and saying what is wrong; nothing allocated. */
static void expect_error(const char *name, const char *why)
{
    tl_mesh m;
    tl_error err;
    tl_error_clear(&err);
    const char *p = path_of(name);
    CHECK(tl_mesh_load(p, &m, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, p);
    CHECK_STR_CONTAINS(err.message, why);
    CHECK(strchr(err.message, '\n') == NULL);
    CHECK(m.positions == NULL && m.index_count == 0);
}

static void test_errors(void)
{
    expect_error("missing.glb", "no such file");
    expect_error("", "is a folder");
    expect_error("empty.obj", "the file is empty");
    expect_error("corrupt.glb", "cannot be read");
    /* A chunk that declares 1.6 GB in a 200-byte file: refused before
     * assimp, which would allocate it. */
    expect_error("oversized_chunk.glb", "a chunk declares more bytes than the file has");
    expect_error("lines_only.obj", "has no triangles");
    expect_error("crate.mtl", "unknown format (use .glb, .gltf or .obj)");
}

/* The built-in boat: a few thousand triangles at most, one unit long with
 * the bow toward +Z, the waterline crossing it, symmetric port and
 * starboard. */
static void test_default_boat(void)
{
    tl_mesh m;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_mesh_default_boat(&m, &err) == TL_OK);
    printf("default boat: %zu vertices, %zu triangles, bounds %g %g %g .. %g %g %g\n",
           m.vertex_count, m.index_count / 3, m.bounds_min[0], m.bounds_min[1], m.bounds_min[2],
           m.bounds_max[0], m.bounds_max[1], m.bounds_max[2]);
    CHECK(m.index_count / 3 >= 2000 && m.index_count / 3 <= 20000);
    CHECK_NEAR(m.bounds_min[2], -0.5, 1e-6);
    CHECK_NEAR(m.bounds_max[2], 0.5, 1e-2);
    CHECK(m.bounds_min[1] < -0.05 && m.bounds_max[1] > 0.3);
    CHECK_NEAR(m.bounds_min[0], -m.bounds_max[0], 1e-6);
    /* The nominal bounds the scene assumes before a loader reports them. */
    const double lo[3] = TL_BOAT_BUILTIN_MIN, hi[3] = TL_BOAT_BUILTIN_MAX;
    for (int c = 0; c < 3; c++) {
        CHECK_NEAR(m.bounds_min[c], lo[c], 1e-3);
        CHECK_NEAR(m.bounds_max[c], hi[c], 1e-3);
    }
    check_normals(&m);
    /* The transom (the faces at the stern whose normal points astern):
     * each triangle is one colour, red wholly below the boot stripe and
     * the rest wholly above its foot, so they meet in a straight line. A fan from a white
     * centre point blended them into a pale red X. */
    int transom = 0, mixed = 0, misplaced = 0;
    for (size_t t = 0; t + 2 < m.index_count; t += 3) {
        const uint32_t *v = m.indices + t;
        int astern = 1;
        for (int k = 0; k < 3; k++)
            astern &= m.normals[3 * v[k] + 2] < -0.99f && m.positions[3 * v[k] + 2] < -0.499f;
        if (!astern)
            continue;
        transom++;
        const float *c0 = m.colors + 3 * v[0];
        int red = c0[0] > 4.0f * c0[1]; /* the antifouling, not the rub rail's teak ends */
        for (int k = 1; k < 3; k++)
            mixed += memcmp(m.colors + 3 * v[k], c0, 3 * sizeof(float)) != 0;
        for (int k = 0; k < 3; k++) {
            float y = m.positions[3 * v[k] + 1];
            /* The black boot stripe starts 0.008 below the waterline. */
            misplaced += red ? y > 1e-6f : y < -0.008f - 1e-6f;
        }
    }
    printf("default boat's transom: %d triangles, %d mixed, %d vertices on the wrong side\n",
           transom, mixed, misplaced);
    CHECK(transom >= 10);
    CHECK(mixed == 0);
    CHECK(misplaced == 0);
    /* The side lights: red (port) at -x, green (starboard) at +x, the
     * world being left-handed (+X east of +Z north). */
    int red_port = 0, green_starboard = 0, wrong_side = 0;
    for (size_t i = 0; i < m.vertex_count; i++) {
        const float *c = m.colors + 3 * i, x = m.positions[3 * i];
        if (m.surface[4 * i + 3] < 30.0f)
            continue; /* not a lamp */
        int red = c[0] > 10.0f * c[1], green = c[1] > 10.0f * c[0];
        red_port += red && x < 0.0f;
        green_starboard += green && x > 0.0f;
        wrong_side += (red && x > 0.0f) || (green && x < 0.0f);
    }
    CHECK(red_port > 0 && green_starboard > 0 && wrong_side == 0);
    /* Its outline: the waterline at midships narrower than the widest
     * plan (the topsides flare), which stands higher; what is inside. */
    tl_mesh_outline o;
    tl_mesh_outline_of(&m, &o);
    const int mid = TL_MESH_WATERLINE_STATIONS / 2;
    printf("default boat's outline at midships: %.4f at the waterline, %.4f at y = %.4f\n",
           o.waterline[mid], o.plan[mid], o.plan_y[mid]);
    CHECK(o.waterline[mid] > 0.1 && o.plan[mid] > o.waterline[mid] && o.plan_y[mid] > 0.05);
    CHECK_NEAR(o.plan[mid], m.bounds_max[0], 0.01);
    const double zm = 0.5 * (o.waterline_z[0] + o.waterline_z[1]);
    const double w = o.waterline[mid], p = o.plan[mid], py = o.plan_y[mid];
    CHECK(tl_mesh_outline_contains(&o, (const double[]){0.0, 0.05, zm}));
    CHECK(tl_mesh_outline_contains(&o, (const double[]){0.9 * w, -0.02, zm}));
    CHECK(!tl_mesh_outline_contains(&o, (const double[]){w + 0.01, 0.0, zm}));
    CHECK(tl_mesh_outline_contains(&o, (const double[]){0.5 * (w + p), py, zm}));
    CHECK(!tl_mesh_outline_contains(&o, (const double[]){0.5 * (w + p), 0.1 * py, zm}));
    CHECK(!tl_mesh_outline_contains(&o, (const double[]){0.0, 0.05, 0.51}));
    CHECK(!tl_mesh_outline_contains(&o, (const double[]){0.0, m.bounds_max[1] + 0.01, zm}));
    tl_mesh_free(&m);
}

static char tmp[] = "/tmp/tideline-mesh-XXXXXX";

static const char *tmp_of(const char *name)
{
    static char buf[2][1024];
    static int which;
    which ^= 1;
    snprintf(buf[which], sizeof buf[which], "%s/%s", tmp, name);
    return buf[which];
}

/* The quad with all five maps, and what the loader must make of it. */
static gltf_quad full_quad(unsigned char *checker, unsigned char *mr, unsigned char *normal,
                           unsigned char *occlusion, unsigned char *emissive)
{
    gltf_quad q = {0};
    q.base_color[0] = q.base_color[1] = q.base_color[2] = 1.0;
    q.roughness = 0.8;
    q.metallic = 1.0;
    q.emissive[0] = 0.5;
    q.emissive[1] = 0.25;
    q.normal_scale = 0.7;
    q.occlusion_strength = 0.5;
    q.material = "hull";
    q.map[TL_MESH_MAP_BASE_COLOR] = (gltf_map){8, 8, checker, 0};
    q.map[TL_MESH_MAP_METALLIC_ROUGHNESS] = (gltf_map){4, 4, mr, 0};
    q.map[TL_MESH_MAP_NORMAL] = (gltf_map){4, 4, normal, 0};
    q.map[TL_MESH_MAP_OCCLUSION] = (gltf_map){4, 4, occlusion, 0};
    q.map[TL_MESH_MAP_EMISSIVE] = (gltf_map){16, 16, emissive, 1};
    return q;
}

static void check_full_quad(const char *name, const tl_mesh *m)
{
    printf("%s: %zu parts, %zu images\n", name, m->part_count, m->image_count);
    CHECK(m->part_count == 1 && m->image_count == 5);
    CHECK(tl_mesh_has_maps(m));
    if (m->part_count != 1 || m->image_count != 5)
        return;
    const tl_mesh_part *p = &m->parts[0];
    for (int k = 0; k < TL_MESH_MAP_COUNT; k++)
        CHECK(p->map[k] >= 0 && p->map[k] < 5);
    CHECK(p->first_index == 0 && p->index_count == 6);
    CHECK_NEAR(p->normal_scale, 0.7, 1e-6);
    CHECK_NEAR(p->occlusion_strength, 0.5, 1e-6);
    CHECK_NEAR(p->emissive[0], 0.5 * TL_MESH_EMISSIVE_RADIANCE, 1e-4);
    CHECK_NEAR(p->emissive[1], 0.25 * TL_MESH_EMISSIVE_RADIANCE, 1e-4);
    CHECK_NEAR(p->emissive[2], 0.0, 1e-6);
    /* The checker, its rows turned over: the first row is the image's
     * bottom, whose left square is dark. */
    const tl_mesh_image *c = &m->images[p->map[TL_MESH_MAP_BASE_COLOR]];
    CHECK(c->width == 8 && c->height == 8);
    CHECK(c->rgba[0] == 40 && c->rgba[4 * 7] == 230);
    CHECK(c->rgba[4 * (7 * 8)] == 230 && c->rgba[4 * (7 * 8 + 7)] == 40);
    const tl_mesh_image *mr = &m->images[p->map[TL_MESH_MAP_METALLIC_ROUGHNESS]];
    CHECK(mr->rgba[1] == 128 && mr->rgba[2] == 255);
    const tl_mesh_image *e = &m->images[p->map[TL_MESH_MAP_EMISSIVE]];
    CHECK(e->width == 16 && abs(e->rgba[0] - 200) <= 3); /* JPEG: near */
    /* UVs in GL's convention (v up the image); x mirrored into tideline's
     * left-handed world, so u runs along -x, and the tangent with it, its
     * bitangent (+y, along v) now on the other side of n x t. */
    CHECK(m->uvs != NULL && m->tangents != NULL);
    for (size_t i = 0; m->uvs && i < m->vertex_count; i++) {
        const float *pos = m->positions + 3 * i, *uv = m->uvs + 2 * i, *t = m->tangents + 4 * i;
        CHECK_NEAR(uv[0], (1.0 - pos[0]) / 2.0, 1e-6);
        CHECK_NEAR(uv[1], (pos[1] - 1.0) / 2.0, 1e-6);
        CHECK_NEAR(t[0], -1.0, 1e-4);
        CHECK_NEAR(t[1], 0.0, 1e-4);
        CHECK_NEAR(t[3], -1.0, 0.0);
        CHECK_NEAR(m->normals[3 * i + 2], 1.0, 1e-6);
    }
}

/* Every map of glTF's material, from files beside the model and embedded
 * in a .glb; OBJ's map_Kd; a model without maps has none. */
static void test_maps(void)
{
    unsigned char *checker = gltf_checker(8, 230, 40), *mr = gltf_solid(4, 0, 128, 255),
                  *normal = gltf_solid(4, 128, 128, 255), *occlusion = gltf_solid(4, 64, 64, 64),
                  *emissive = gltf_solid(16, 200, 200, 200);
    gltf_quad q = full_quad(checker, mr, normal, occlusion, emissive);
    tl_error err;
    tl_error_clear(&err);
    const char *names[2] = {"quad.gltf", "quad.glb"};
    for (int i = 0; i < 2; i++) {
        CHECK(gltf_write_quad(tmp_of(names[i]), &q) == 0);
        tl_mesh m;
        int rc = tl_mesh_load(tmp_of(names[i]), &m, &err);
        if (rc)
            printf("%s\n", err.message);
        CHECK(rc == TL_OK);
        if (!rc) {
            check_full_quad(names[i], &m);
            tl_mesh_free(&m);
        }
    }
    /* OBJ: the diffuse map is the base colour. */
    const char *obj = "mtllib quad.mtl\nv -1 1 0\nv 1 1 0\nv 1 3 0\nv -1 3 0\n"
                      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nusemtl deck\n"
                      "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
    const char *mtl = "newmtl deck\nKd 1 1 1\nmap_Kd quad_map0.png\n";
    CHECK(gltf_write_file(tmp_of("quad.obj"), obj, strlen(obj)) == 0);
    CHECK(gltf_write_file(tmp_of("quad.mtl"), mtl, strlen(mtl)) == 0);
    tl_mesh m;
    CHECK(tl_mesh_load(tmp_of("quad.obj"), &m, &err) == TL_OK);
    CHECK(m.part_count == 1 && m.image_count == 1);
    if (m.part_count == 1 && m.image_count == 1) {
        CHECK(m.parts[0].map[TL_MESH_MAP_BASE_COLOR] == 0);
        CHECK(m.images[0].width == 8 && m.images[0].rgba[0] == 40);
    }
    tl_mesh_free(&m);
    /* The skiff has factors only: no maps, no UVs kept. */
    CHECK(tl_mesh_load(path_of("skiff.gltf"), &m, &err) == TL_OK);
    CHECK(!tl_mesh_has_maps(&m) && m.uvs == NULL && m.image_count == 0);
    tl_mesh_free(&m);
    free(checker);
    free(mr);
    free(normal);
    free(occlusion);
    free(emissive);
}

/* A texture that is missing or cannot be decoded: one line naming the
 * model, the material, the map and the image. */
static void test_map_errors(void)
{
    unsigned char *checker = gltf_checker(8, 230, 40);
    gltf_quad q = {0};
    q.base_color[0] = q.base_color[1] = q.base_color[2] = 1.0;
    q.roughness = 0.5;
    q.material = "topsides";
    q.map[TL_MESH_MAP_BASE_COLOR] = (gltf_map){8, 8, checker, 0};
    q.missing_base_color = "paint.png";
    tl_mesh m;
    tl_error err;
    tl_error_clear(&err);
    CHECK(gltf_write_quad(tmp_of("missing.gltf"), &q) == 0);
    CHECK(tl_mesh_load(tmp_of("missing.gltf"), &m, &err) == TL_ERR_USAGE);
    printf("%s\n", err.message);
    CHECK_STR_CONTAINS(err.message, tmp_of("missing.gltf"));
    CHECK_STR_CONTAINS(err.message, "material 'topsides': base colour texture");
    CHECK_STR_CONTAINS(err.message, tmp_of("paint.png"));
    CHECK_STR_CONTAINS(err.message, "no such file");
    CHECK(m.positions == NULL && m.image_count == 0);
    q.missing_base_color = NULL;
    q.garbage_base_color = "this is not an image";
    const char *names[2] = {"garbage.gltf", "garbage.glb"};
    for (int i = 0; i < 2; i++) {
        CHECK(gltf_write_quad(tmp_of(names[i]), &q) == 0);
        tl_error_clear(&err);
        CHECK(tl_mesh_load(tmp_of(names[i]), &m, &err) == TL_ERR_USAGE);
        printf("%s\n", err.message);
        CHECK_STR_CONTAINS(err.message, tmp_of(names[i]));
        CHECK_STR_CONTAINS(err.message, "material 'topsides': base colour texture");
        CHECK_STR_CONTAINS(err.message, "cannot be decoded");
        CHECK(strchr(err.message, '\n') == NULL);
    }
    free(checker);
}

/* The normal map's CPU mirror: a flat texel keeps the normal, a tilted one
 * turns it toward the tangent (or the bitangent) by its angle, scaled. */
static void test_normal_map(void)
{
    const double n[3] = {0, 0, 1}, t[4] = {1, 0, 0, 1}, t_flipped[4] = {1, 0, 0, -1};
    double out[3];
    tl_mesh_normal_map(n, t, (const double[]){0.5, 0.5, 1.0}, 1.0, out);
    CHECK_NEAR(out[2], 1.0, 1e-12);
    const double a = 0.5; /* radians */
    const double tilted[3] = {0.5 + 0.5 * sin(a), 0.5, 0.5 + 0.5 * cos(a)};
    tl_mesh_normal_map(n, t, tilted, 1.0, out);
    CHECK_NEAR(out[0], sin(a), 1e-12);
    CHECK_NEAR(out[2], cos(a), 1e-12);
    const double up[3] = {0.5, 0.5 + 0.5 * sin(a), 0.5 + 0.5 * cos(a)};
    tl_mesh_normal_map(n, t, up, 1.0, out);
    CHECK_NEAR(out[1], sin(a), 1e-12);
    tl_mesh_normal_map(n, t_flipped, up, 1.0, out);
    CHECK_NEAR(out[1], -sin(a), 1e-12);
    tl_mesh_normal_map(n, t, tilted, 0.0, out); /* scale 0: flat */
    CHECK_NEAR(out[2], 1.0, 1e-12);
    /* A tangent not square to n is made so; none at all leaves n. */
    tl_mesh_normal_map(n, (const double[]){1, 0, 5, 1}, tilted, 1.0, out);
    CHECK_NEAR(out[0], sin(a), 1e-12);
    tl_mesh_normal_map(n, (const double[]){0, 0, 2, 1}, tilted, 1.0, out);
    CHECK_NEAR(out[2], 1.0, 1e-12);
}

/* boat.paint and boat.cabin_paint: the built-in boat in its own paint is
 * the default boat, vertex for vertex (TL_BOAT_PAINT and
 * TL_BOAT_CABIN_PAINT are its colours); in an orange and a blue, its
 * topsides and wheelhouse take them, its roof the blue a shade darker, and
 * nothing else changes. */
static void test_paint(void)
{
    tl_mesh plain, own, painted;
    tl_error err;
    tl_error_clear(&err);
    const double paint[3] = TL_BOAT_PAINT, cabin[3] = TL_BOAT_CABIN_PAINT;
    const double orange[3] = {0.8, 0.15, 0.02}, blue[3] = {0.02, 0.05, 0.3};
    CHECK(tl_mesh_default_boat(&plain, &err) == TL_OK);
    CHECK(tl_mesh_builtin_boat(&own, paint, cabin, &err) == TL_OK);
    CHECK(tl_mesh_builtin_boat(&painted, orange, blue, &err) == TL_OK);
    CHECK(own.vertex_count == plain.vertex_count && painted.vertex_count == plain.vertex_count);
    if (own.vertex_count != plain.vertex_count || painted.vertex_count != plain.vertex_count)
        goto done;
    CHECK(memcmp(own.colors, plain.colors, 3 * sizeof(float) * plain.vertex_count) == 0);
    size_t topsides = 0, wheelhouse = 0, roof = 0, other = 0;
    for (size_t v = 0; v < plain.vertex_count; v++) {
        const float *a = plain.colors + 3 * v, *b = painted.colors + 3 * v;
        int was_topsides =
            a[0] == (float)paint[0] && a[1] == (float)paint[1] && a[2] == (float)paint[2];
        int was_cabin =
            a[0] == (float)cabin[0] && a[1] == (float)cabin[1] && a[2] == (float)cabin[2];
        if (was_topsides) {
            topsides++;
            CHECK(b[0] == (float)orange[0] && b[1] == (float)orange[1] && b[2] == (float)orange[2]);
        } else if (was_cabin) {
            wheelhouse++;
            CHECK(b[0] == (float)blue[0] && b[1] == (float)blue[1] && b[2] == (float)blue[2]);
        } else if (memcmp(a, b, 3 * sizeof(float)) != 0) {
            roof++;
            CHECK(b[0] == (float)(0.8 * blue[0]) && b[1] == (float)(0.8 * blue[1]) &&
                  b[2] == (float)(0.8 * blue[2]));
        } else {
            other++;
        }
    }
    printf("paint: %zu topsides vertices, %zu wheelhouse, %zu roof, %zu unchanged\n", topsides,
           wheelhouse, roof, other);
    CHECK(topsides > 100 && wheelhouse >= 8 && roof >= 4 && other > 100);
done:
    tl_mesh_free(&plain);
    tl_mesh_free(&own);
    tl_mesh_free(&painted);
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return 1;
    dir = argv[1];
    test_gltf();
    test_obj();
    test_errors();
    test_default_boat();
    test_paint();
    test_normal_map();
    if (!mkdtemp(tmp))
        return 1;
    test_maps();
    test_map_errors();
    const char *files[] = {"quad.gltf",     "quad.bin",      "quad.glb",      "quad_map0.png",
                           "quad_map1.png", "quad_map2.png", "quad_map3.png", "quad_map4.jpg",
                           "quad.obj",      "quad.mtl",      "missing.gltf",  "missing.bin",
                           "garbage.gltf",  "garbage.bin",   "garbage.glb",   "garbage_map0.png"};
    for (size_t i = 0; i < sizeof files / sizeof *files; i++)
        unlink(tmp_of(files[i]));
    rmdir(tmp);
    TEST_END();
}
