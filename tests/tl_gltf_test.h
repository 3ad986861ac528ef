/* glTF models the tests write for themselves: a quad with one material and
 * its texture maps, as a .gltf beside its .bin and images, or as one .glb
 * with everything embedded. The quad is 2 m square, standing in the plane
 * z = 0 facing +z, from y = 1 to 3 (above a model's waterline), turned by
 * `turn` radians about its vertical centre line; its UV origin (glTF's:
 * the image's top left) at its top left corner seen from +z. */
#ifndef TL_GLTF_TEST_H
#define TL_GLTF_TEST_H

#include <math.h>
#include <stb_image_write.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/tl_mesh.h"

typedef struct gltf_map {
    int width, height;
    const unsigned char *rgba; /* rows from the image's top */
    int jpeg;                  /* encode as JPEG (quality 95), else PNG */
} gltf_map;

typedef struct gltf_quad {
    double turn;
    double base_color[3], roughness, metallic, emissive[3];
    double normal_scale, occlusion_strength;
    gltf_map map[TL_MESH_MAP_COUNT]; /* width 0: no map */
    const char *material;            /* its name */
    /* A map file named in the .gltf and not written (external only). */
    const char *missing_base_color;
    /* Bytes written in place of the base colour map's image. */
    const char *garbage_base_color;
} gltf_quad;

typedef struct gltf_bytes {
    unsigned char *data;
    size_t size, capacity;
} gltf_bytes;

static void gltf_append(gltf_bytes *b, const void *p, size_t n)
{
    if (b->size + n > b->capacity) {
        size_t cap = b->capacity ? b->capacity : 1024;
        while (cap < b->size + n)
            cap *= 2;
        unsigned char *q = realloc(b->data, cap);
        if (!q)
            abort();
        b->data = q;
        b->capacity = cap;
    }
    memcpy(b->data + b->size, p, n);
    b->size += n;
}

static void gltf_pad4(gltf_bytes *b, unsigned char with)
{
    while (b->size % 4)
        gltf_append(b, &with, 1);
}

static void gltf_write_cb(void *ctx, void *data, int size)
{
    gltf_append(ctx, data, (size_t)size);
}

static void gltf_encode(const gltf_map *m, gltf_bytes *out)
{
    if (m->jpeg)
        stbi_write_jpg_to_func(gltf_write_cb, out, m->width, m->height, 4, m->rgba, 95);
    else
        stbi_write_png_to_func(gltf_write_cb, out, m->width, m->height, 4, m->rgba, m->width * 4);
}

static int gltf_write_file(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    size_t n = fwrite(data, 1, size, f);
    return fclose(f) == 0 && n == size ? 0 : -1;
}

/* Writes the quad to `path` (.gltf or .glb); 0 on success. */
static int gltf_write_quad(const char *path, const gltf_quad *q)
{
    const char *dot = strrchr(path, '.');
    const int glb = dot && !strcmp(dot, ".glb");
    const double c = cos(q->turn), s = sin(q->turn);
    /* Corners: top left, top right, bottom right, bottom left (from +z). */
    const double corner[4][2] = {{-1, 3}, {1, 3}, {1, 1}, {-1, 1}};
    const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    float positions[12], normals[12];
    for (int i = 0; i < 4; i++) {
        positions[3 * i + 0] = (float)(corner[i][0] * c);
        positions[3 * i + 1] = (float)corner[i][1];
        positions[3 * i + 2] = (float)(-corner[i][0] * s);
        normals[3 * i + 0] = (float)s;
        normals[3 * i + 1] = 0.0f;
        normals[3 * i + 2] = (float)c;
    }
    const unsigned short indices[6] = {0, 3, 2, 0, 2, 1};
    gltf_bytes bin = {0};
    gltf_append(&bin, positions, sizeof positions); /* 0: 48 bytes */
    gltf_append(&bin, normals, sizeof normals);     /* 48 */
    gltf_append(&bin, uv, sizeof uv);               /* 96: 32 bytes */
    gltf_append(&bin, indices, sizeof indices);     /* 128: 12 bytes */
    gltf_pad4(&bin, 0);
    size_t image_at[TL_MESH_MAP_COUNT] = {0}, image_size[TL_MESH_MAP_COUNT] = {0};
    char image_uri[TL_MESH_MAP_COUNT][300];
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    int stem = (int)(dot ? dot - base : (long)strlen(base));
    for (int k = 0; k < TL_MESH_MAP_COUNT; k++) {
        if (!q->map[k].width)
            continue;
        gltf_bytes img = {0};
        if (k == TL_MESH_MAP_BASE_COLOR && q->garbage_base_color)
            gltf_append(&img, q->garbage_base_color, strlen(q->garbage_base_color));
        else
            gltf_encode(&q->map[k], &img);
        const char *ext = q->map[k].jpeg ? "jpg" : "png";
        snprintf(image_uri[k], sizeof image_uri[k], "%.*s_map%d.%s", stem, base, k, ext);
        if (k == TL_MESH_MAP_BASE_COLOR && q->missing_base_color)
            snprintf(image_uri[k], sizeof image_uri[k], "%s", q->missing_base_color);
        if (glb) {
            image_at[k] = bin.size;
            image_size[k] = img.size;
            gltf_append(&bin, img.data, img.size);
            gltf_pad4(&bin, 0);
        } else if (!(k == TL_MESH_MAP_BASE_COLOR && q->missing_base_color)) {
            char file[4096];
            snprintf(file, sizeof file, "%.*s%s", (int)(slash ? slash + 1 - path : 0), path,
                     image_uri[k]);
            if (gltf_write_file(file, img.data, img.size)) {
                free(img.data);
                free(bin.data);
                return -1;
            }
        }
        free(img.data);
    }
    char bin_uri[300];
    snprintf(bin_uri, sizeof bin_uri, "%.*s.bin", stem, base);

    char json[16384];
    int n = 0;
#define J(...) n += snprintf(json + n, sizeof json - (size_t)n, __VA_ARGS__)
    J("{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
      "\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,"
      "\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]}],");
    J("\"materials\":[{\"name\":\"%s\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[%g,%g,%g,1],"
      "\"roughnessFactor\":%g,\"metallicFactor\":%g",
      q->material ? q->material : "quad", q->base_color[0], q->base_color[1], q->base_color[2],
      q->roughness, q->metallic);
    int texture = 0, tex_of[TL_MESH_MAP_COUNT];
    for (int k = 0; k < TL_MESH_MAP_COUNT; k++)
        tex_of[k] = q->map[k].width ? texture++ : -1;
    if (tex_of[TL_MESH_MAP_BASE_COLOR] >= 0)
        J(",\"baseColorTexture\":{\"index\":%d}", tex_of[TL_MESH_MAP_BASE_COLOR]);
    if (tex_of[TL_MESH_MAP_METALLIC_ROUGHNESS] >= 0)
        J(",\"metallicRoughnessTexture\":{\"index\":%d}", tex_of[TL_MESH_MAP_METALLIC_ROUGHNESS]);
    J("}");
    if (tex_of[TL_MESH_MAP_NORMAL] >= 0)
        J(",\"normalTexture\":{\"index\":%d,\"scale\":%g}", tex_of[TL_MESH_MAP_NORMAL],
          q->normal_scale);
    if (tex_of[TL_MESH_MAP_OCCLUSION] >= 0)
        J(",\"occlusionTexture\":{\"index\":%d,\"strength\":%g}", tex_of[TL_MESH_MAP_OCCLUSION],
          q->occlusion_strength);
    if (tex_of[TL_MESH_MAP_EMISSIVE] >= 0)
        J(",\"emissiveTexture\":{\"index\":%d}", tex_of[TL_MESH_MAP_EMISSIVE]);
    J(",\"emissiveFactor\":[%g,%g,%g]}],", q->emissive[0], q->emissive[1], q->emissive[2]);
    if (texture) {
        J("\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987}],\"textures\":[");
        for (int k = 0, first = 1; k < TL_MESH_MAP_COUNT; k++)
            if (tex_of[k] >= 0) {
                J("%s{\"source\":%d,\"sampler\":0}", first ? "" : ",", tex_of[k]);
                first = 0;
            }
        J("],\"images\":[");
        int view = 4;
        for (int k = 0, first = 1; k < TL_MESH_MAP_COUNT; k++)
            if (tex_of[k] >= 0) {
                if (glb)
                    J("%s{\"bufferView\":%d,\"mimeType\":\"image/%s\"}", first ? "" : ",", view++,
                      q->map[k].jpeg ? "jpeg" : "png");
                else
                    J("%s{\"uri\":\"%s\"}", first ? "" : ",", image_uri[k]);
                first = 0;
            }
        J("],");
    }
    J("\"accessors\":["
      "{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\","
      "\"min\":[%g,1,%g],\"max\":[%g,3,%g]},"
      "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
      "{\"bufferView\":2,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
      "{\"bufferView\":3,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],",
      -fabs(c), -fabs(s), fabs(c), fabs(s));
    J("\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":48},"
      "{\"buffer\":0,\"byteOffset\":48,\"byteLength\":48},"
      "{\"buffer\":0,\"byteOffset\":96,\"byteLength\":32},"
      "{\"buffer\":0,\"byteOffset\":128,\"byteLength\":12}");
    for (int k = 0; glb && k < TL_MESH_MAP_COUNT; k++)
        if (tex_of[k] >= 0)
            J(",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", image_at[k], image_size[k]);
    J("],\"buffers\":[{\"byteLength\":%zu%s%s%s}]}", bin.size, glb ? "" : ",\"uri\":\"",
      glb ? "" : bin_uri, glb ? "" : "\"");
#undef J
    int rc = 0;
    if (glb) {
        gltf_bytes out = {0};
        gltf_bytes js = {0};
        gltf_append(&js, json, (size_t)n);
        gltf_pad4(&js, ' ');
        uint32_t head[3] = {0x46546c67u, 2u, (uint32_t)(12 + 8 + js.size + 8 + bin.size)};
        uint32_t jc[2] = {(uint32_t)js.size, 0x4e4f534au},
                 bc[2] = {(uint32_t)bin.size, 0x004e4942u};
        gltf_append(&out, head, sizeof head);
        gltf_append(&out, jc, sizeof jc);
        gltf_append(&out, js.data, js.size);
        gltf_append(&out, bc, sizeof bc);
        gltf_append(&out, bin.data, bin.size);
        rc = gltf_write_file(path, out.data, out.size);
        free(out.data);
        free(js.data);
    } else {
        char file[4096];
        snprintf(file, sizeof file, "%.*s%s", (int)(slash ? slash + 1 - path : 0), path, bin_uri);
        rc = gltf_write_file(file, bin.data, bin.size) || gltf_write_file(path, json, (size_t)n);
    }
    free(bin.data);
    return rc;
}

/* A 2 x 2 checker, `size` texels a side: `light` in the top left and
 * bottom right squares, `dark` in the others (sRGB bytes, opaque). */
static unsigned char *gltf_checker(int size, unsigned char light, unsigned char dark)
{
    unsigned char *p = malloc((size_t)size * (size_t)size * 4);
    for (int y = 0; p && y < size; y++)
        for (int x = 0; x < size; x++) {
            unsigned char v = ((x < size / 2) == (y < size / 2)) ? light : dark;
            unsigned char *t = p + 4 * ((size_t)y * (size_t)size + (size_t)x);
            t[0] = t[1] = t[2] = v;
            t[3] = 255;
        }
    return p;
}

/* A map of one opaque RGB value, `size` texels a side. */
static unsigned char *gltf_solid(int size, unsigned char r, unsigned char g, unsigned char b)
{
    unsigned char *p = malloc((size_t)size * (size_t)size * 4);
    for (int i = 0; p && i < size * size; i++) {
        p[4 * i] = r;
        p[4 * i + 1] = g;
        p[4 * i + 2] = b;
        p[4 * i + 3] = 255;
    }
    return p;
}

#endif
