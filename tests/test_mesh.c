/* Meshes: the glTF and OBJ loader (assimp) on small files in tests/meshes,
 * its errors, and the built-in boat. argv[1] is tests/meshes. */
#include <math.h>
#include <stdlib.h>

#include "mesh/tl_mesh.h"
#include "scene/tl_scene.h"
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
    for (int c = 0; c < 3; c++) {
        CHECK_NEAR(m.bounds_min[c], 0.0, 1e-6);
        CHECK_NEAR(m.bounds_max[c], 1.0, 1e-6);
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
     * each triangle is one colour, red wholly below the waterline and white
     * wholly above, so they meet in a straight line. A fan from a white
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
        int red = c0[0] > 2.0f * c0[1];
        for (int k = 1; k < 3; k++)
            mixed += memcmp(m.colors + 3 * v[k], c0, 3 * sizeof(float)) != 0;
        for (int k = 0; k < 3; k++) {
            float y = m.positions[3 * v[k] + 1];
            misplaced += red ? y > 1e-6f : y < -1e-6f;
        }
    }
    printf("default boat's transom: %d triangles, %d mixed, %d vertices on the wrong side\n",
           transom, mixed, misplaced);
    CHECK(transom >= 10);
    CHECK(mixed == 0);
    CHECK(misplaced == 0);
    tl_mesh_free(&m);
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
    TEST_END();
}
