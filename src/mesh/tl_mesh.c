#include "tl_mesh.h"

#include "tl_mesh_maps.h"

#include <assimp/cimport.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static int grow(void **array, size_t *capacity, size_t needed, size_t item)
{
    if (needed <= *capacity)
        return 1;
    size_t cap = *capacity ? *capacity : 256;
    while (cap < needed)
        cap *= 2;
    void *p = realloc(*array, cap * item);
    if (!p)
        return 0;
    *array = p;
    *capacity = cap;
    return 1;
}

uint32_t tl_mesh_add_vertex(tl_mesh_builder *b, const float p[3], const float n[3],
                            const tl_mesh_material *material)
{
    tl_mesh *m = &b->mesh;
    size_t need = m->vertex_count + 1, cap = b->vertex_capacity;
    if (b->failed || m->vertex_count >= UINT32_MAX ||
        !grow((void **)&m->positions, &cap, need, 3 * sizeof(float))) {
        b->failed = 1;
        return 0;
    }
    cap = b->vertex_capacity;
    if (!grow((void **)&m->normals, &cap, need, 3 * sizeof(float))) {
        b->failed = 1;
        return 0;
    }
    cap = b->vertex_capacity;
    if (!grow((void **)&m->colors, &cap, need, 3 * sizeof(float))) {
        b->failed = 1;
        return 0;
    }
    cap = b->vertex_capacity;
    if (!grow((void **)&m->surface, &cap, need, 4 * sizeof(float))) {
        b->failed = 1;
        return 0;
    }
    b->vertex_capacity = cap;
    memcpy(m->positions + 3 * m->vertex_count, p, 3 * sizeof(float));
    memcpy(m->normals + 3 * m->vertex_count, n, 3 * sizeof(float));
    memcpy(m->colors + 3 * m->vertex_count, material->color, 3 * sizeof(float));
    float *s = m->surface + 4 * m->vertex_count;
    s[0] = material->roughness;
    s[1] = material->metallic;
    s[2] = 1.0f; /* unoccluded until baked */
    s[3] = material->emission;
    return (uint32_t)m->vertex_count++;
}

void tl_mesh_add_triangle(tl_mesh_builder *b, uint32_t i0, uint32_t i1, uint32_t i2)
{
    tl_mesh *m = &b->mesh;
    if (b->failed ||
        !grow((void **)&m->indices, &b->index_capacity, m->index_count + 3, sizeof(uint32_t))) {
        b->failed = 1;
        return;
    }
    m->indices[m->index_count++] = i0;
    m->indices[m->index_count++] = i1;
    m->indices[m->index_count++] = i2;
}

int tl_mesh_builder_finish(tl_mesh_builder *b, tl_mesh *out, tl_error *err)
{
    tl_mesh *m = &b->mesh;
    if (b->failed) {
        tl_mesh_free(m);
        memset(b, 0, sizeof *b);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory building a mesh");
    }
    for (int c = 0; c < 3; c++) {
        m->bounds_min[c] = FLT_MAX;
        m->bounds_max[c] = -FLT_MAX;
    }
    for (size_t i = 0; i < m->vertex_count; i++)
        for (int c = 0; c < 3; c++) {
            float v = m->positions[3 * i + c];
            m->bounds_min[c] = v < m->bounds_min[c] ? v : m->bounds_min[c];
            m->bounds_max[c] = v > m->bounds_max[c] ? v : m->bounds_max[c];
        }
    *out = *m;
    memset(b, 0, sizeof *b);
    return TL_OK;
}

/* The points where triangle t's edges cross y = 0 (x z pairs), up to 2. */
static int waterline_crossings(const tl_mesh *m, size_t t, double out[2][2])
{
    int n = 0;
    for (int e = 0; e < 3 && n < 2; e++) {
        const float *a = m->positions + 3 * m->indices[t + e];
        const float *b = m->positions + 3 * m->indices[t + (e + 1) % 3];
        if ((a[1] < 0.0f) == (b[1] < 0.0f))
            continue;
        double f = (double)a[1] / ((double)a[1] - b[1]);
        out[n][0] = a[0] + (b[0] - a[0]) * f;
        out[n][1] = a[2] + (b[2] - a[2]) * f;
        n++;
    }
    return n;
}

static void waterline(const tl_mesh *m, float half[TL_MESH_WATERLINE_STATIONS], float z[2])
{
    memset(half, 0, TL_MESH_WATERLINE_STATIONS * sizeof *half);
    z[0] = z[1] = 0.0f;
    double lo = INFINITY, hi = -INFINITY;
    for (size_t t = 0; t + 2 < m->index_count; t += 3) {
        double c[2][2];
        int n = waterline_crossings(m, t, c);
        for (int k = 0; k < n; k++) {
            lo = fmin(lo, c[k][1]);
            hi = fmax(hi, c[k][1]);
        }
    }
    if (!(hi > lo))
        return;
    /* Each crossing segment widens the stations it spans. */
    const int n_st = TL_MESH_WATERLINE_STATIONS;
    double step = (hi - lo) / (n_st - 1);
    for (size_t t = 0; t + 2 < m->index_count; t += 3) {
        double c[2][2];
        int n = waterline_crossings(m, t, c);
        if (n < 2)
            continue;
        for (int i = 0; i < n_st; i++) {
            double zs = lo + step * i;
            double z0 = fmin(c[0][1], c[1][1]), z1 = fmax(c[0][1], c[1][1]);
            if (zs < z0 - 0.5 * step || zs > z1 + 0.5 * step)
                continue;
            double f = z1 > z0 ? fmin(fmax((zs - c[0][1]) / (c[1][1] - c[0][1]), 0.0), 1.0) : 0.5;
            double x = fabs(c[0][0] + (c[1][0] - c[0][0]) * f);
            if (x > half[i])
                half[i] = (float)x;
        }
    }
    z[0] = (float)lo;
    z[1] = (float)hi;
}

/* The widest section of each triangle at each station within half a
 * step of it (so no corner slips between stations). */
static void plan(const tl_mesh *m, tl_mesh_outline *o)
{
    const int n_st = TL_MESH_WATERLINE_STATIONS;
    memset(o->plan, 0, sizeof o->plan);
    memset(o->plan_y, 0, sizeof o->plan_y);
    double lo = m->bounds_min[2], hi = m->bounds_max[2];
    o->plan_z[0] = (float)lo;
    o->plan_z[1] = (float)hi;
    if (!(hi > lo))
        return;
    double step = (hi - lo) / (n_st - 1);
    for (size_t t = 0; t + 2 < m->index_count; t += 3) {
        const float *v[3];
        double z0 = INFINITY, z1 = -INFINITY;
        for (int k = 0; k < 3; k++) {
            v[k] = m->positions + 3 * m->indices[t + k];
            z0 = fmin(z0, v[k][2]);
            z1 = fmax(z1, v[k][2]);
        }
        int first = (int)ceil((z0 - lo) / step - 0.5), last = (int)floor((z1 - lo) / step + 0.5);
        for (int i = first < 0 ? 0 : first; i <= last && i < n_st; i++) {
            double zs = fmin(fmax(lo + step * i, z0), z1);
            /* Where the edges cross the plane z = zs (or touch it). */
            for (int e = 0; e < 3; e++) {
                const float *a = v[e], *b = v[(e + 1) % 3];
                double za = a[2], zb = b[2];
                if ((zs < fmin(za, zb)) || (zs > fmax(za, zb)))
                    continue;
                double f = zb != za ? (zs - za) / (zb - za) : 0.0;
                double x = fabs(a[0] + (b[0] - a[0]) * f), y = a[1] + (b[1] - a[1]) * f;
                if (x > o->plan[i]) {
                    o->plan[i] = (float)x;
                    o->plan_y[i] = (float)y;
                }
            }
        }
    }
}

void tl_mesh_outline_of(const tl_mesh *m, tl_mesh_outline *out)
{
    memset(out, 0, sizeof *out);
    waterline(m, out->waterline, out->waterline_z);
    plan(m, out);
    out->top = m->bounds_max[1];
    out->bottom = m->bounds_min[1];
}

/* A half-width table's value at model z, 0 outside its range. */
static double station_half(const float *half, const float z[2], double at)
{
    if (!(z[1] > z[0]) || at < z[0] || at > z[1])
        return 0.0;
    double f = (at - z[0]) / ((double)z[1] - z[0]) * (TL_MESH_WATERLINE_STATIONS - 1);
    int i = (int)f < TL_MESH_WATERLINE_STATIONS - 2 ? (int)f : TL_MESH_WATERLINE_STATIONS - 2;
    return half[i] + (half[i + 1] - half[i]) * (f - i);
}

int tl_mesh_outline_contains(const tl_mesh_outline *o, const double p[3])
{
    if (!(p[1] < o->top))
        return 0;
    double water = station_half(o->waterline, o->waterline_z, p[2]);
    double half = water;
    if (p[1] > 0.0) {
        double wide = station_half(o->plan, o->plan_z, p[2]);
        double high = station_half(o->plan_y, o->plan_z, p[2]);
        double f = high > 1e-9 ? fmin(p[1] / high, 1.0) : 1.0;
        half = water + (fmax(wide, water) - water) * f;
    }
    return fabs(p[0]) < half;
}

void tl_mesh_free(tl_mesh *m)
{
    if (!m)
        return;
    free(m->positions);
    free(m->normals);
    free(m->colors);
    free(m->surface);
    free(m->indices);
    free(m->uvs);
    free(m->tangents);
    for (size_t i = 0; m->images && i < m->image_count; i++)
        free(m->images[i].rgba);
    free(m->images);
    free(m->parts);
    memset(m, 0, sizeof *m);
}

int tl_mesh_has_maps(const tl_mesh *m)
{
    for (size_t i = 0; i < m->part_count; i++) {
        const tl_mesh_part *p = &m->parts[i];
        if (p->emissive[0] > 0.0f || p->emissive[1] > 0.0f || p->emissive[2] > 0.0f)
            return 1;
        for (int k = 0; k < TL_MESH_MAP_COUNT; k++)
            if (p->map[k] >= 0)
                return 1;
    }
    return 0;
}

static float clamp01(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; /* NaN -> 0 */
}

/* The mesh's material: glTF's base colour, metallic and roughness factors;
 * for OBJ, the diffuse colour (Kd) and a roughness from the shininess
 * (Ns, a Phong exponent: s = 2 / r^4 - 2). Without a material: light grey
 * paint. */
static void material_of(const struct aiScene *scene, unsigned index, tl_mesh_material *out)
{
    *out = (tl_mesh_material){{0.7f, 0.7f, 0.7f}, 0.5f, 0.0f, 0.0f};
    if (index >= scene->mNumMaterials)
        return;
    const struct aiMaterial *mat = scene->mMaterials[index];
    struct aiColor4D c;
    if (aiGetMaterialColor(mat, AI_MATKEY_BASE_COLOR, &c) == aiReturn_SUCCESS ||
        aiGetMaterialColor(mat, AI_MATKEY_COLOR_DIFFUSE, &c) == aiReturn_SUCCESS) {
        out->color[0] = c.r < 0.0f ? 0.0f : c.r;
        out->color[1] = c.g < 0.0f ? 0.0f : c.g;
        out->color[2] = c.b < 0.0f ? 0.0f : c.b;
    }
    ai_real v;
    if (aiGetMaterialFloatArray(mat, AI_MATKEY_ROUGHNESS_FACTOR, &v, NULL) == aiReturn_SUCCESS)
        out->roughness = clamp01((float)v);
    else if (aiGetMaterialFloatArray(mat, AI_MATKEY_SHININESS, &v, NULL) == aiReturn_SUCCESS &&
             v > 0.0f)
        out->roughness = clamp01((float)pow(2.0 / (v + 2.0), 0.25));
    if (aiGetMaterialFloatArray(mat, AI_MATKEY_METALLIC_FACTOR, &v, NULL) == aiReturn_SUCCESS)
        out->metallic = clamp01((float)v);
}

static int known_format(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash))
        return 0;
    return !strcasecmp(dot, ".glb") || !strcasecmp(dot, ".gltf") || !strcasecmp(dot, ".obj");
}

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* A binary glTF's header and chunk lengths against the file's size, before
 * assimp reads it: assimp 5.2 allocates a chunk's declared length first,
 * so 20 bytes that declare 1.6 GB exhausted the memory (a fuzzer's find).
 * Returns NULL when they fit, else what is wrong. */
static const char *binary_gltf_problem(const char *path, long long file_size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return "cannot be opened";
    unsigned char head[12];
    const char *why = NULL;
    if (fread(head, 1, 12, f) != 12 || memcmp(head, "glTF", 4) != 0)
        why = "not a binary glTF file: no 'glTF' header";
    else if (le32(head + 8) > file_size)
        why = "its header declares more bytes than the file has";
    /* Every chunk: 8 bytes of length and type, then its data. */
    for (long long at = 12; !why && at < file_size;) {
        unsigned char chunk[8];
        if (fseek(f, (long)at, SEEK_SET) != 0 || fread(chunk, 1, 8, f) != 8)
            why = "a chunk's header is cut short";
        else if ((long long)le32(chunk) > file_size - at - 8)
            why = "a chunk declares more bytes than the file has";
        else
            at += 8 + (long long)le32(chunk);
    }
    fclose(f);
    return why;
}

int tl_mesh_load(const char *path, tl_mesh *out, tl_error *err)
{
    memset(out, 0, sizeof *out);
    struct stat st;
    if (stat(path, &st) != 0)
        return tl_error_set(err, TL_ERR_USAGE, "boat model %s: no such file", path);
    if (S_ISDIR(st.st_mode))
        return tl_error_set(err, TL_ERR_USAGE, "boat model %s: is a folder, not a file", path);
    if (!known_format(path))
        return tl_error_set(err, TL_ERR_USAGE,
                            "boat model %s: unknown format (use .glb, .gltf or .obj)", path);
    if (st.st_size == 0)
        return tl_error_set(err, TL_ERR_USAGE, "boat model %s: the file is empty", path);
    const char *dot = strrchr(path, '.');
    const char *bad =
        !strcasecmp(dot, ".glb") ? binary_gltf_problem(path, (long long)st.st_size) : NULL;
    if (bad)
        return tl_error_set(err, TL_ERR_USAGE, "boat model %s: cannot be read: %s", path, bad);

    /* Triangles only (points and lines dropped), one flat list of meshes
     * with their node transforms applied. */
    const struct aiScene *scene = aiImportFile(
        path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                  aiProcess_PreTransformVertices | aiProcess_SortByPType |
                  aiProcess_FindInvalidData | aiProcess_CalcTangentSpace);
    if (!scene) {
        const char *why = aiGetErrorString();
        /* assimp's messages can run over several lines: keep the first. */
        char first[256];
        snprintf(first, sizeof first, "%s", why && *why ? why : "unreadable");
        first[strcspn(first, "\r\n")] = '\0';
        return tl_error_set(err, TL_ERR_USAGE, "boat model %s: cannot be read: %s", path, first);
    }
    size_t vertices = 0, triangles = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; i++) {
        vertices += scene->mMeshes[i]->mNumVertices;
        triangles += scene->mMeshes[i]->mNumFaces;
    }
    if (vertices > TL_MESH_MAX_VERTICES || triangles > TL_MESH_MAX_TRIANGLES) {
        aiReleaseImport(scene);
        return tl_error_set(err, TL_ERR_USAGE,
                            "boat model %s: %zu vertices and %zu triangles, over the limit of "
                            "%d and %d",
                            path, vertices, triangles, TL_MESH_MAX_VERTICES, TL_MESH_MAX_TRIANGLES);
    }
    tl_mesh_builder b = {0};
    tl_mesh_map_cache cache = {0};
    tl_mesh maps = {0}; /* the images and parts, moved into *out at the end */
    float *uvs = calloc(vertices ? vertices : 1, 2 * sizeof(float));
    float *tangents = calloc(vertices ? vertices : 1, 4 * sizeof(float));
    maps.parts = calloc(scene->mNumMeshes ? scene->mNumMeshes : 1, sizeof *maps.parts);
    int rc =
        uvs && tangents && maps.parts ? TL_OK : tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    for (unsigned i = 0; !rc && i < scene->mNumMeshes; i++) {
        const struct aiMesh *m = scene->mMeshes[i];
        if (!(m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || !m->mNormals)
            continue;
        tl_mesh_material material;
        material_of(scene, m->mMaterialIndex, &material);
        tl_mesh_part *part = &maps.parts[maps.part_count++];
        rc = tl_mesh_read_maps(scene, m->mMaterialIndex, path, &maps, &cache, part, err);
        if (rc)
            break;
        if (!m->mTextureCoords[0]) /* nothing to sample them at */
            for (int k = 0; k < TL_MESH_MAP_COUNT; k++)
                part->map[k] = -1;
        part->first_index = b.mesh.index_count;
        uint32_t base = (uint32_t)b.mesh.vertex_count;
        /* glTF and OBJ are right-handed, tideline's world is left-handed
         * (+X east of +Z north): x is mirrored, so that the model reads as
         * authored (lettering the right way round, starboard to
         * starboard). Tangents turn with it, and their bitangent's side. */
        for (unsigned v = 0; v < m->mNumVertices; v++) {
            const float p[3] = {-m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z};
            const float n[3] = {-m->mNormals[v].x, m->mNormals[v].y, m->mNormals[v].z};
            tl_mesh_add_vertex(&b, p, n, &material);
            if (m->mTextureCoords[0]) {
                uvs[2 * ((size_t)base + v)] = m->mTextureCoords[0][v].x;
                uvs[2 * ((size_t)base + v) + 1] = m->mTextureCoords[0][v].y;
            }
            if (m->mTangents && m->mBitangents) {
                const struct aiVector3D t = m->mTangents[v], bt = m->mBitangents[v];
                const struct aiVector3D fn = m->mNormals[v];
                /* The bitangent's side of n x t (glTF's tangent w), in the
                 * file's axes; mirrored, it changes side. */
                const double c[3] = {fn.y * t.z - fn.z * t.y, fn.z * t.x - fn.x * t.z,
                                     fn.x * t.y - fn.y * t.x};
                float *out_t = tangents + 4 * ((size_t)base + v);
                out_t[0] = -t.x;
                out_t[1] = t.y;
                out_t[2] = t.z;
                out_t[3] = c[0] * bt.x + c[1] * bt.y + c[2] * bt.z < 0.0 ? 1.0f : -1.0f;
            }
        }
        for (unsigned f = 0; f < m->mNumFaces; f++) {
            const struct aiFace *face = &m->mFaces[f];
            if (face->mNumIndices == 3)
                tl_mesh_add_triangle(&b, base + face->mIndices[0], base + face->mIndices[1],
                                     base + face->mIndices[2]);
        }
        part->index_count = b.mesh.index_count - part->first_index;
    }
    aiReleaseImport(scene);
    tl_mesh_map_cache_free(&cache, maps.image_count);
    if (!rc && !b.failed && b.mesh.index_count == 0)
        rc = tl_error_set(err, TL_ERR_USAGE, "boat model %s: has no triangles", path);
    if (!rc)
        rc = tl_mesh_builder_finish(&b, out, err);
    if (rc) {
        tl_mesh_free(&b.mesh);
        tl_mesh_free(&maps);
        free(uvs);
        free(tangents);
        return rc;
    }
    out->parts = maps.parts;
    out->part_count = maps.part_count;
    out->images = maps.images;
    out->image_count = maps.image_count;
    if (tl_mesh_has_maps(out)) {
        out->uvs = uvs;
        out->tangents = tangents;
    } else {
        free(uvs);
        free(tangents);
    }
    for (size_t i = 0; i < out->vertex_count; i++) {
        float *p = out->positions + 3 * i, *n = out->normals + 3 * i;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) {
            tl_mesh_free(out);
            return tl_error_set(err, TL_ERR_USAGE, "boat model %s: has non-finite vertices", path);
        }
        /* Degenerate triangles leave no normal: point it up. */
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(len > 1e-12f) || !isfinite(len)) {
            n[0] = n[2] = 0.0f;
            n[1] = 1.0f;
        } else {
            for (int c = 0; c < 3; c++)
                n[c] /= len;
        }
        /* A UV or tangent a file left non-finite samples the map's corner
         * and leaves the normal unmapped (the shader skips a zero tangent). */
        for (int c = 0; out->uvs && c < 2; c++)
            if (!isfinite(out->uvs[2 * i + c]))
                out->uvs[2 * i + c] = 0.0f;
        float *t = out->tangents ? out->tangents + 4 * i : NULL;
        if (t && !(isfinite(t[0]) && isfinite(t[1]) && isfinite(t[2])))
            t[0] = t[1] = t[2] = 0.0f;
    }
    /* Occlusion out to a tenth of the model's longest side: the reach of a
     * wheelhouse's shade on its deck. */
    double extent = 0.0;
    for (int c = 0; c < 3; c++)
        extent = fmax(extent, (double)out->bounds_max[c] - out->bounds_min[c]);
    rc = tl_mesh_bake_occlusion(out, TL_MESH_OCCLUSION_REACH * extent, err);
    if (rc)
        tl_mesh_free(out);
    return rc;
}

int tl_mesh_lamps(const tl_mesh *m, float where[TL_MESH_LAMPS][4], float light[TL_MESH_LAMPS][4])
{
    enum { MOST = 32 };
    double first[MOST][3], sum[MOST][3], glow[MOST][3], lo[MOST][3], hi[MOST][3];
    int members[MOST], count = 0;
    double length = 0.0;
    for (int k = 0; k < 3; k++)
        length = fmax(length, (double)m->bounds_max[k] - m->bounds_min[k]);
    const double gather = TL_MESH_LAMP_GATHER * length;
    for (size_t v = 0; v < m->vertex_count; v++) {
        double emission = m->surface[4 * v + 3];
        if (!(emission > 0.0))
            continue;
        const float *p = m->positions + 3 * v, *c = m->colors + 3 * v;
        int at = -1;
        for (int i = 0; i < count && at < 0; i++) {
            double d2 = 0.0;
            for (int k = 0; k < 3; k++)
                d2 += (p[k] - first[i][k]) * (p[k] - first[i][k]);
            if (d2 <= gather * gather)
                at = i;
        }
        if (at < 0) {
            if (count == MOST)
                continue; /* past the most clusters: a model of many lamps keeps the first */
            at = count++;
            members[at] = 0;
            for (int k = 0; k < 3; k++) {
                first[at][k] = lo[at][k] = hi[at][k] = p[k];
                sum[at][k] = glow[at][k] = 0.0;
            }
        }
        members[at]++;
        for (int k = 0; k < 3; k++) {
            sum[at][k] += p[k];
            glow[at][k] += c[k] * emission;
            lo[at][k] = fmin(lo[at][k], p[k]);
            hi[at][k] = fmax(hi[at][k], p[k]);
        }
    }
    /* Centres and radiance; each lamp's size is the radius of the disc of
     * its box's mean projected area (a quarter of its surface: Cauchy),
     * not its half diagonal, which took half again its light. */
    double radius[MOST];
    for (int i = 0; i < count; i++) {
        for (int k = 0; k < 3; k++) {
            sum[i][k] /= members[i];
            glow[i][k] /= members[i];
        }
        double a = hi[i][0] - lo[i][0], b = hi[i][1] - lo[i][1], c = hi[i][2] - lo[i][2];
        radius[i] = sqrt(2.0 * (a * b + b * c + c * a) / (4.0 * M_PI));
    }
    /* The brightest TL_MESH_LAMPS (by luminance), in that order. */
    int kept = 0;
    int used[MOST] = {0};
    while (kept < TL_MESH_LAMPS) {
        int best = -1;
        double best_y = 0.0;
        for (int i = 0; i < count; i++) {
            double y = 0.2126 * glow[i][0] + 0.7152 * glow[i][1] + 0.0722 * glow[i][2];
            if (!used[i] && y > best_y) {
                best = i;
                best_y = y;
            }
        }
        if (best < 0)
            break;
        used[best] = 1;
        for (int k = 0; k < 3; k++) {
            where[kept][k] = (float)sum[best][k];
            light[kept][k] = (float)glow[best][k];
        }
        where[kept][3] = (float)radius[best];
        /* A side light shines to its own side only (port or starboard,
         * ahead to abaft the beam): a lamp well off the centre line is
         * taken as one, w its side (-1: -x, 1: +x; 0: all round). */
        double half_beam = 0.5 * ((double)m->bounds_max[0] - m->bounds_min[0]);
        light[kept][3] =
            fabs(sum[best][0]) > 0.3 * half_beam ? (sum[best][0] < 0.0 ? -1.0f : 1.0f) : 0.0f;
        kept++;
    }
    return kept;
}
