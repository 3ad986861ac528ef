/* Fuzz entry point: the boat model loader (tl_mesh_load, assimp's C API
 * underneath). The first byte picks the file's extension, the rest is the
 * file: byte % 3 == 0 .obj ('o'), 1 .gltf ('g'), 2 .glb ('b'), the formats
 * tideline accepts. The file lives in a folder of its own, so references
 * inside it (an OBJ's mtllib, a glTF's buffer uri) find nothing else.
 *
 * The contract: a load fails with a message, or gives a mesh whose indices
 * are in range, whose vertices are finite, normals unit length and bounds
 * right; a breach aborts. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mesh/tl_mesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char folder[64];

static void remove_folder(void)
{
    rmdir(folder);
}

static void breach(const char *what)
{
    fprintf(stderr, "fuzz_mesh: contract broken: %s\n", what);
    abort();
}

static void check_mesh(const tl_mesh *m)
{
    if (m->index_count == 0 || m->index_count % 3)
        breach("no triangles, or a partial one");
    for (size_t i = 0; i < m->index_count; i++)
        if (m->indices[i] >= m->vertex_count)
            breach("an index past the vertices");
    for (size_t v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * v, *n = m->normals + 3 * v;
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(fabsf(len - 1.0f) < 1e-3f))
            breach("a normal that is not unit length");
        for (int c = 0; c < 3; c++)
            if (!isfinite(p[c]) || p[c] < m->bounds_min[c] || p[c] > m->bounds_max[c])
                breach("a vertex non-finite or outside the bounds");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const ext[3] = {"obj", "gltf", "glb"};
    if (size < 1)
        return 0;
    if (!folder[0]) {
        const char *tmp = getenv("TMPDIR");
        snprintf(folder, sizeof folder, "%s/tl_fuzz_mesh_XXXXXX", tmp && *tmp ? tmp : "/tmp");
        if (strlen(folder) >= sizeof folder - 1 || !mkdtemp(folder)) {
            perror("fuzz_mesh: mkdtemp");
            abort();
        }
        atexit(remove_folder);
    }
    char path[96];
    snprintf(path, sizeof path, "%s/boat.%s", folder, ext[data[0] % 3]);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data + 1, 1, size - 1, f) != size - 1 || fclose(f) != 0) {
        perror("fuzz_mesh: writing the input");
        abort();
    }
    tl_mesh m;
    tl_error err;
    tl_error_clear(&err);
    if (tl_mesh_load(path, &m, &err) == TL_OK) {
        check_mesh(&m);
        tl_mesh_free(&m);
    } else if (!err.message[0]) {
        breach("a failed load without a message");
    }
    unlink(path);
    return 0;
}
