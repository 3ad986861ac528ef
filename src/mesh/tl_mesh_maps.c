#include "tl_mesh_maps.h"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <stb_image.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Where assimp 5 puts each of glTF's maps (its glTF 2 importer), with a
 * second place for formats that have only the older slots: OBJ's map_Kd
 * is the diffuse map. */
static const struct {
    enum aiTextureType type, fallback;
    const char *what;
} SLOTS[TL_MESH_MAP_COUNT] = {
    [TL_MESH_MAP_BASE_COLOR] = {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE, "base colour"},
    [TL_MESH_MAP_METALLIC_ROUGHNESS] = {aiTextureType_UNKNOWN, aiTextureType_NONE,
                                        "metallic-roughness"},
    [TL_MESH_MAP_NORMAL] = {aiTextureType_NORMALS, aiTextureType_NONE, "normal"},
    [TL_MESH_MAP_OCCLUSION] = {aiTextureType_LIGHTMAP, aiTextureType_AMBIENT_OCCLUSION,
                               "occlusion"},
    [TL_MESH_MAP_EMISSIVE] = {aiTextureType_EMISSIVE, aiTextureType_NONE, "emissive"},
};

/* Turns rows over: decoders give the top row first; GL and assimp's UVs
 * put v = 0 at the image's bottom. */
static void flip_rows(unsigned char *rgba, int width, int height)
{
    size_t row = (size_t)width * 4;
    unsigned char *tmp = malloc(row);
    if (!tmp)
        return;
    for (int y = 0; y < height / 2; y++) {
        unsigned char *a = rgba + row * (size_t)y, *b = rgba + row * (size_t)(height - 1 - y);
        memcpy(tmp, a, row);
        memcpy(a, b, row);
        memcpy(b, tmp, row);
    }
    free(tmp);
}

/* The image file `name` refers to, beside the model unless absolute. */
static void resolve(const char *model, const char *name, char *out, size_t size)
{
    const char *slash = strrchr(model, '/');
    if (name[0] == '/' || !slash)
        snprintf(out, size, "%s", name);
    else
        snprintf(out, size, "%.*s/%s", (int)(slash - model), model, name);
}

/* Decodes the image `name` (a file, or "*N": the scene's embedded texture
 * N) into *out. Errors name the model, the material and the image. */
static int decode(const struct aiScene *scene, const char *model, const char *material,
                  const char *what, const char *name, tl_mesh_image *out, tl_error *err)
{
    int w = 0, h = 0, channels = 0;
    unsigned char *rgba = NULL;
    char path[4096];
    if (name[0] == '*') {
        char *end = NULL;
        long n = strtol(name + 1, &end, 10);
        if (!end || *end || n < 0 || (unsigned long)n >= scene->mNumTextures)
            return tl_error_set(err, TL_ERR_USAGE,
                                "boat model %s: material '%s': %s texture %s: no such embedded "
                                "image",
                                model, material, what, name);
        const struct aiTexture *tex = scene->mTextures[n];
        if (tex->mHeight == 0) { /* compressed: mWidth bytes of PNG, JPEG, ... */
            if (tex->mWidth > 0x7fffffffu)
                return tl_error_set(err, TL_ERR_USAGE,
                                    "boat model %s: material '%s': %s texture %s: too large", model,
                                    material, what, name);
            rgba = stbi_load_from_memory((const unsigned char *)tex->pcData, (int)tex->mWidth, &w,
                                         &h, &channels, 4);
        } else if (tex->mWidth > TL_MESH_MAX_TEXTURE || tex->mHeight > TL_MESH_MAX_TEXTURE) {
            return tl_error_set(err, TL_ERR_USAGE,
                                "boat model %s: material '%s': %s texture %s: %u x %u texels, "
                                "over the limit of %d a side",
                                model, material, what, name, tex->mWidth, tex->mHeight,
                                TL_MESH_MAX_TEXTURE);
        } else {
            w = (int)tex->mWidth;
            h = (int)tex->mHeight;
            rgba = malloc((size_t)w * (size_t)h * 4);
            for (size_t i = 0; rgba && i < (size_t)w * (size_t)h; i++) {
                const struct aiTexel *t = &tex->pcData[i];
                rgba[4 * i + 0] = t->r;
                rgba[4 * i + 1] = t->g;
                rgba[4 * i + 2] = t->b;
                rgba[4 * i + 3] = t->a;
            }
            if (!rgba)
                return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
        }
        snprintf(path, sizeof path, "(embedded image %ld)", n);
        name = path;
    } else {
        resolve(model, name, path, sizeof path);
        struct stat st;
        if (stat(path, &st) != 0 || S_ISDIR(st.st_mode))
            return tl_error_set(err, TL_ERR_USAGE,
                                "boat model %s: material '%s': %s texture %s: no such file", model,
                                material, what, path);
        rgba = stbi_load(path, &w, &h, &channels, 4);
        name = path;
    }
    if (!rgba) {
        const char *why = stbi_failure_reason();
        return tl_error_set(err, TL_ERR_USAGE,
                            "boat model %s: material '%s': %s texture %s: cannot be decoded: %s",
                            model, material, what, name, why ? why : "unknown format");
    }
    if (w > TL_MESH_MAX_TEXTURE || h > TL_MESH_MAX_TEXTURE) {
        free(rgba);
        return tl_error_set(err, TL_ERR_USAGE,
                            "boat model %s: material '%s': %s texture %s: %d x %d texels, over "
                            "the limit of %d a side",
                            model, material, what, name, w, h, TL_MESH_MAX_TEXTURE);
    }
    flip_rows(rgba, w, h);
    *out = (tl_mesh_image){w, h, rgba};
    return TL_OK;
}

/* The index in mesh->images of the image `name`, decoded if new; -1 and
 * err set when it cannot be. */
static int image_index(const struct aiScene *scene, const char *model, const char *material,
                       const char *what, const char *name, tl_mesh *mesh, tl_mesh_map_cache *cache,
                       tl_error *err)
{
    for (size_t i = 0; i < mesh->image_count; i++)
        if (!strcmp(cache->keys[i], name))
            return (int)i;
    tl_mesh_image image;
    if (decode(scene, model, material, what, name, &image, err))
        return -1;
    size_t n = mesh->image_count + 1;
    tl_mesh_image *images = realloc(mesh->images, n * sizeof *images);
    if (images)
        mesh->images = images;
    char **keys = realloc(cache->keys, n * sizeof *keys);
    if (keys)
        cache->keys = keys;
    char *key = strdup(name);
    if (!images || !keys || !key) {
        free(key);
        free(image.rgba); /* stb_image allocates with malloc */
        tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
        return -1;
    }
    mesh->images[mesh->image_count] = image;
    cache->keys[mesh->image_count] = key;
    mesh->image_count = n;
    return (int)(n - 1);
}

int tl_mesh_read_maps(const struct aiScene *scene, unsigned index, const char *model, tl_mesh *mesh,
                      tl_mesh_map_cache *cache, tl_mesh_part *part, tl_error *err)
{
    for (int k = 0; k < TL_MESH_MAP_COUNT; k++)
        part->map[k] = -1;
    part->emissive[0] = part->emissive[1] = part->emissive[2] = 0.0f;
    part->normal_scale = 1.0f;
    part->occlusion_strength = 1.0f;
    if (index >= scene->mNumMaterials)
        return TL_OK;
    const struct aiMaterial *mat = scene->mMaterials[index];
    struct aiString name;
    char material[128] = "unnamed";
    if (aiGetMaterialString(mat, AI_MATKEY_NAME, &name) == aiReturn_SUCCESS && name.length)
        snprintf(material, sizeof material, "%.*s", (int)sizeof material - 1, name.data);
    for (int k = 0; k < TL_MESH_MAP_COUNT; k++) {
        struct aiString file;
        enum aiTextureType type = SLOTS[k].type;
        if (aiGetMaterialTextureCount(mat, type) == 0)
            type = SLOTS[k].fallback;
        if (type == aiTextureType_NONE || aiGetMaterialTextureCount(mat, type) == 0 ||
            aiGetMaterialTexture(mat, type, 0, &file, NULL, NULL, NULL, NULL, NULL, NULL) !=
                aiReturn_SUCCESS ||
            file.length == 0)
            continue;
        part->map[k] =
            image_index(scene, model, material, SLOTS[k].what, file.data, mesh, cache, err);
        if (part->map[k] < 0)
            return err ? (int)err->status : TL_ERR_USAGE;
    }
    struct aiColor4D c;
    if (aiGetMaterialColor(mat, AI_MATKEY_COLOR_EMISSIVE, &c) == aiReturn_SUCCESS) {
        const float e[3] = {c.r, c.g, c.b};
        for (int i = 0; i < 3; i++)
            part->emissive[i] = (e[i] > 0.0f ? e[i] : 0.0f) * TL_MESH_EMISSIVE_RADIANCE;
    }
    ai_real v;
    if (aiGetMaterialFloatArray(mat, AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), &v,
                                NULL) == aiReturn_SUCCESS)
        part->normal_scale = (float)v;
    if (aiGetMaterialFloatArray(mat, AI_MATKEY_GLTF_TEXTURE_STRENGTH(aiTextureType_LIGHTMAP, 0), &v,
                                NULL) == aiReturn_SUCCESS)
        part->occlusion_strength = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : (float)v);
    return TL_OK;
}

void tl_mesh_map_cache_free(tl_mesh_map_cache *cache, size_t count)
{
    for (size_t i = 0; cache->keys && i < count; i++)
        free(cache->keys[i]);
    free(cache->keys);
    cache->keys = NULL;
}
