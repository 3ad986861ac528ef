/* A frame with its passes as one multilayer EXR (tl_passes.h): the layers
 * and channel names Blender 3.4 writes, so that its compositor, Nuke and
 * Natron read the file as any renderer's. */
#include "passes/tl_passes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

_Static_assert(TL_FRAME_AOV_OBJECTS == TL_OBJECT_MAX,
               "the aov plane has a cover for every floating object a scene holds");

#define LAYER "ViewLayer."
/* Cryptomatte's layer: its channels are this name followed by 00, 01, 02,
 * as the header's cryptomatte/<key>/name says. */
#define CRYPTO_LAYER LAYER "CryptoObject"
/* The material Cryptomatte's, as Blender names it. */
#define MATERIAL_LAYER LAYER "CryptoMaterial"
/* The objects besides the floating ones, by their names in the timeline
 * language (none of them can name a floating object), and the materials
 * besides the floating objects' (their models'): the ocean and the giant
 * wave are both water, and the foam on them is a material of its own. */
static const char *const fixed_objects[3] = {"sky", "ocean", "giant"};
static const char *const fixed_materials[3] = {"sky", "water", "foam"};
#define COVERS (3 + TL_FRAME_AOV_OBJECTS)

/* Value c of group g of pixel i of the aov plane (tl_frame.h). */
static float aov_at(const tl_frame *f, int g, size_t i, int c)
{
    return f->aov[((size_t)g * (size_t)f->width * (size_t)f->height + i) * 4 + (size_t)c];
}

/* A cover or a mean that may leave the file: finite, held in [lo, hi]. */
static float held(float v, float lo, float hi)
{
    return isfinite(v) ? fminf(fmaxf(v, lo), hi) : 0.0f;
}

/* The object covers of pixel i: sky, ocean, giant wave, then each floating
 * object by scene index; returns their sum. */
static float object_covers(const tl_frame *f, size_t i, float cover[3 + TL_FRAME_AOV_OBJECTS])
{
    float sum = 0.0f;
    for (int k = 0; k < 3 + TL_FRAME_AOV_OBJECTS; k++) {
        int v = k < 3 ? 4 + k : TL_FRAME_AOV_OBJECT0 + (k - 3);
        cover[k] = held(aov_at(f, v / 4, i, v % 4), 0.0f, 1.0f);
        sum += cover[k];
    }
    return sum;
}

/* The material covers of pixel i from its object covers: the sky, the
 * water less the foam's share of it, the foam, then each floating object
 * (by scene index, named by its model). */
static void material_covers(const tl_frame *f, size_t i, const float object[COVERS],
                            float cover[COVERS])
{
    float water = object[1] + object[2];
    float foam = fminf(held(aov_at(f, 0, i, 3), 0.0f, 1.0f), water);
    cover[0] = object[0];
    cover[1] = water - foam;
    cover[2] = foam;
    memcpy(cover + 3, object + 3, sizeof *cover * TL_FRAME_AOV_OBJECTS);
}

/* The name of material k of the covers (material_covers). */
static const char *material_name(const tl_passes_frame *info, int k)
{
    if (k < 3)
        return fixed_materials[k];
    int o = k - 3;
    return tl_crypto_material_name(info->model && o < info->objects ? info->model[o] : NULL);
}

/* The name of object k of the covers (sky, ocean, giant, then floating). */
static const char *object_name(const tl_passes_frame *info, int k, char *buf, size_t size)
{
    if (k < 3)
        return fixed_objects[k];
    int o = k - 3;
    if (o < info->objects && info->object && info->object[o])
        return info->object[o];
    snprintf(buf, size, "object%d", o);
    return buf;
}

/* The Cryptomatte's ranks of a pixel into `out` (TL_CRYPTO_RANKS pairs of
 * ID and coverage) from its object covers (object_covers) and their sum:
 * its objects by their share of the pixel's samples, most first; the same
 * ID's shares summed. */
static void crypto_ranks(const float cover[3 + TL_FRAME_AOV_OBJECTS], float total, const float *ids,
                         float *out)
{
    float id[3 + TL_FRAME_AOV_OBJECTS], share[3 + TL_FRAME_AOV_OBJECTS];
    int n = 0;
    for (int k = 0; k < 3 + TL_FRAME_AOV_OBJECTS; k++) {
        if (!(cover[k] > 0.0f))
            continue;
        int j = 0;
        while (j < n && memcmp(&id[j], &ids[k], sizeof(float)) != 0)
            j++;
        if (j == n) {
            id[n] = ids[k];
            share[n++] = 0.0f;
        }
        share[j] += cover[k] / total;
    }
    for (int r = 0; r < TL_CRYPTO_RANKS; r++) {
        int best = -1;
        for (int j = 0; j < n; j++)
            if (share[j] > 0.0f && (best < 0 || share[j] > share[best]))
                best = j;
        out[2 * r] = best < 0 ? 0.0f : id[best];
        out[2 * r + 1] = best < 0 ? 0.0f : share[best];
        if (best >= 0)
            share[best] = 0.0f;
    }
}

/* The manifest: each name once and its ID's hex digits, as JSON (the
 * names of the covers, `count` of them, `materials` or objects'). */
static int crypto_manifest(const tl_passes_frame *info, int materials, char *out, size_t size)
{
    size_t n = (size_t)snprintf(out, size, "{");
    const int count =
        3 + (info->objects < TL_FRAME_AOV_OBJECTS ? info->objects : TL_FRAME_AOV_OBJECTS);
    for (int k = 0; k < count; k++) {
        char buf[32], earlier_buf[32];
        uint32_t bits;
        const char *name =
            materials ? material_name(info, k) : object_name(info, k, buf, sizeof buf);
        int seen = 0;
        for (int j = 0; j < k && !seen; j++)
            seen = strcmp(name, materials
                                    ? material_name(info, j)
                                    : object_name(info, j, earlier_buf, sizeof earlier_buf)) == 0;
        if (seen)
            continue;
        tl_crypto_id(name, &bits);
        /* The name as a JSON string: quotes and backslashes escaped (a
         * model's file name may hold them), control characters dropped. */
        n += (size_t)snprintf(out + n, n < size ? size - n : 0, "%s\"", n > 1 ? "," : "");
        for (const char *c = name; *c; c++) {
            if ((unsigned char)*c < 0x20)
                continue;
            n += (size_t)snprintf(out + n, n < size ? size - n : 0, "%s%c",
                                  *c == '"' || *c == '\\' ? "\\" : "", *c);
        }
        n += (size_t)snprintf(out + n, n < size ? size - n : 0, "\":\"%08x\"", (unsigned)bits);
    }
    n += (size_t)snprintf(out + n, n < size ? size - n : 0, "}");
    return n < size ? 0 : -1;
}

enum { MAX_CHANNELS = 4 + 1 + 3 + 3 + 6 + 2 * 4 * (TL_CRYPTO_RANKS / 2) + 4 + 3 * TL_FRAME_LAYERS };

int tl_passes_write_exr(const char *path, const tl_frame *frame, const tl_passes_frame *info,
                        const tl_image_options *opt, tl_error *err)
{
    const unsigned passes = info->passes | TL_PASSES_COMBINED;
    if (!frame->color || !frame->depth)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no frame to write", path);
    if (tl_passes_need_aov(passes) && !frame->aov)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: the frame has no data for its passes", path);
    const unsigned layers = tl_passes_light_layers(passes);
    if ((tl_frame_layers(frame) & layers) != layers)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: the frame has no light layers to write",
                            path);
    const int w = frame->width, h = frame->height;
    const size_t px = (size_t)w * (size_t)h;
    /* Position, the planar depth, the masks and the Cryptomattes' ranks
     * (objects, materials) are computed here, interleaved per pixel:
     * 3 + 1 + 6 + 2 * 2 * ranks floats. */
    enum {
        POS = 0,
        DEPTH = 3,
        MASK = 4,
        CRYPTO = 10,
        CRYPTO_MATERIAL = CRYPTO + 2 * TL_CRYPTO_RANKS,
        PER_PIXEL = CRYPTO_MATERIAL + 2 * TL_CRYPTO_RANKS
    };
    double right[3], up[3], forward[3];
    tl_scene_camera_basis(info->camera, right, up, forward);
    float *data = malloc(px * PER_PIXEL * sizeof *data);
    if (!data)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory for the passes", path);
    float ids[COVERS], material_ids[COVERS];
    for (int k = 0; k < COVERS; k++) {
        char buf[32];
        ids[k] = tl_crypto_id(object_name(info, k, buf, sizeof buf), NULL);
        material_ids[k] = tl_crypto_id(material_name(info, k), NULL);
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            float *d = data + i * PER_PIXEL;
            /* Position: camera-relative (tideline/position_origin in the
             * header), 0 where the ray met nothing, as Blender's. */
            double ray[3];
            tl_passes_pixel_ray(info->camera, w, h, x, y, ray);
            double dist = frame->depth[i];
            int hit = isfinite(dist) && dist < TL_FRAME_SKY_DEPTH;
            for (int c = 0; c < 3; c++)
                d[POS + c] = hit ? (float)(ray[c] * dist) : 0.0f;
            /* Depth as Blender's: along the camera's axis, not the ray. */
            d[DEPTH] = hit ? (float)(dist * (ray[0] * forward[0] + ray[1] * forward[1] +
                                             ray[2] * forward[2]))
                           : TL_FRAME_SKY_DEPTH;
            if (!frame->aov)
                continue;
            float cover[3 + TL_FRAME_AOV_OBJECTS];
            float total = object_covers(frame, i, cover);
            float boats = 0.0f;
            for (int k = 3; k < 3 + TL_FRAME_AOV_OBJECTS; k++)
                boats += cover[k];
            d[MASK + 0] = held(cover[1] + cover[2], 0.0f, 1.0f);    /* water */
            d[MASK + 1] = held(aov_at(frame, 0, i, 3), 0.0f, 1.0f); /* foam */
            d[MASK + 2] = cover[2];                                 /* giant wave */
            d[MASK + 3] = held(boats, 0.0f, 1.0f);                  /* boats */
            d[MASK + 4] = cover[0];                                 /* sky */
            d[MASK + 5] = held(aov_at(frame, 1, i, 3), 0.0f, 1.0f); /* under water */
            crypto_ranks(cover, total, ids, d + CRYPTO);
            float by_material[COVERS];
            material_covers(frame, i, cover, by_material);
            crypto_ranks(by_material, total, material_ids, d + CRYPTO_MATERIAL);
        }
    /* The normal, a mean of unit vectors, finite and within [-1, 1]. */
    float *normal = NULL;
    if (passes & TL_PASSES_NORMAL) {
        normal = malloc(px * 3 * sizeof *normal);
        if (!normal) {
            free(data);
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory for the passes", path);
        }
        for (size_t i = 0; i < px; i++)
            for (int c = 0; c < 3; c++)
                normal[i * 3 + (size_t)c] = held(aov_at(frame, 0, i, c), -1.0f, 1.0f);
    }

    float *vector = NULL;
    if (passes & TL_PASSES_VECTOR) {
        vector = malloc(px * 4 * sizeof *vector);
        if (!vector) {
            free(normal);
            free(data);
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory for the passes", path);
        }
        tl_passes_vectors(frame, info, vector);
    }

    tl_exr_channel ch[MAX_CHANNELS];
    int n = 0;
    static const char *const rgba[4] = {LAYER "Combined.R", LAYER "Combined.G", LAYER "Combined.B",
                                        LAYER "Combined.A"};
    for (int c = 0; c < 4; c++)
        ch[n++] = (tl_exr_channel){rgba[c], 1, frame->color + c, 4};
    if (passes & TL_PASSES_DEPTH)
        ch[n++] = (tl_exr_channel){LAYER "Depth.Z", 0, data + DEPTH, PER_PIXEL};
    static const char *const xyz[2][3] = {
        {LAYER "Normal.X", LAYER "Normal.Y", LAYER "Normal.Z"},
        {LAYER "Position.X", LAYER "Position.Y", LAYER "Position.Z"}};
    for (int c = 0; normal && c < 3; c++)
        ch[n++] = (tl_exr_channel){xyz[0][c], 1, normal + c, 3};
    for (int c = 0; (passes & TL_PASSES_POSITION) && c < 3; c++)
        ch[n++] = (tl_exr_channel){xyz[1][c], 0, data + POS + c, PER_PIXEL};
    static const struct {
        unsigned pass;
        const char *name;
    } masks[6] = {{TL_PASSES_MASK_WATER, LAYER "mask_water.X"},
                  {TL_PASSES_MASK_FOAM, LAYER "mask_foam.X"},
                  {TL_PASSES_MASK_GIANT, LAYER "mask_giant.X"},
                  {TL_PASSES_MASK_BOAT, LAYER "mask_boat.X"},
                  {TL_PASSES_MASK_SKY, LAYER "mask_sky.X"},
                  {TL_PASSES_MASK_UNDERWATER, LAYER "mask_underwater.X"}};
    for (int m = 0; m < 6; m++)
        if (passes & masks[m].pass)
            ch[n++] = (tl_exr_channel){masks[m].name, 1, data + MASK + m, PER_PIXEL};
    static const char *const xyzw[4] = {LAYER "Vector.X", LAYER "Vector.Y", LAYER "Vector.Z",
                                        LAYER "Vector.W"};
    for (int c = 0; vector && c < 4; c++)
        ch[n++] = (tl_exr_channel){xyzw[c], 0, vector + c, 4};
    /* The light layers, half as Combined (ViewLayer.light_sky.R, ...). */
    char light_names[TL_FRAME_LAYERS][3][48];
    for (int k = 0; k < TL_FRAME_LAYERS; k++)
        for (int c = 0; (layers & (1u << k)) && c < 3; c++) {
            snprintf(light_names[k][c], sizeof light_names[k][c], LAYER "light_%s.%c",
                     tl_light_layer_name(k), "RGB"[c]);
            ch[n++] = (tl_exr_channel){light_names[k][c], 1, frame->layer[k] + c, 3};
        }
    /* Cryptomatte: IDs and coverage in 32-bit float (a half ID matches
     * nothing), lower-case rgba as Blender writes them. */
    static const char *const crypto[2][TL_CRYPTO_RANKS / 2][4] = {
        {{CRYPTO_LAYER "00.r", CRYPTO_LAYER "00.g", CRYPTO_LAYER "00.b", CRYPTO_LAYER "00.a"},
         {CRYPTO_LAYER "01.r", CRYPTO_LAYER "01.g", CRYPTO_LAYER "01.b", CRYPTO_LAYER "01.a"},
         {CRYPTO_LAYER "02.r", CRYPTO_LAYER "02.g", CRYPTO_LAYER "02.b", CRYPTO_LAYER "02.a"}},
        {{MATERIAL_LAYER "00.r", MATERIAL_LAYER "00.g", MATERIAL_LAYER "00.b",
          MATERIAL_LAYER "00.a"},
         {MATERIAL_LAYER "01.r", MATERIAL_LAYER "01.g", MATERIAL_LAYER "01.b",
          MATERIAL_LAYER "01.a"},
         {MATERIAL_LAYER "02.r", MATERIAL_LAYER "02.g", MATERIAL_LAYER "02.b",
          MATERIAL_LAYER "02.a"}}};
    const unsigned crypto_pass[2] = {TL_PASSES_CRYPTOMATTE, TL_PASSES_CRYPTO_MATERIAL};
    const int crypto_at[2] = {CRYPTO, CRYPTO_MATERIAL};
    for (int m = 0; m < 2; m++)
        for (int l = 0; (passes & crypto_pass[m]) && l < TL_CRYPTO_RANKS / 2; l++)
            for (int c = 0; c < 4; c++)
                ch[n++] = (tl_exr_channel){crypto[m][l][c], 0, data + crypto_at[m] + 4 * l + c,
                                           PER_PIXEL};

    /* The caller's metadata, and the Cryptomattes'. */
    int given = opt && opt->meta ? opt->meta_count : 0;
    tl_meta *meta = malloc(sizeof *meta * (size_t)(given + 8));
    char manifest[2][4096], keys[2][4][64];
    int rc = TL_OK;
    if (!meta)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory for the passes", path);
    else if (((passes & TL_PASSES_CRYPTOMATTE) &&
              crypto_manifest(info, 0, manifest[0], sizeof manifest[0])) ||
             ((passes & TL_PASSES_CRYPTO_MATERIAL) &&
              crypto_manifest(info, 1, manifest[1], sizeof manifest[1])))
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: the Cryptomatte's manifest is too long", path);
    if (!rc) {
        if (given)
            memcpy(meta, opt->meta, sizeof *meta * (size_t)given);
        int m = given;
        static const char *const layer_name[2] = {CRYPTO_LAYER, MATERIAL_LAYER};
        for (int l = 0; l < 2; l++) {
            if (!(passes & crypto_pass[l]))
                continue;
            char key[8];
            tl_crypto_key(layer_name[l], key);
            static const char *const field[4] = {"name", "hash", "conversion", "manifest"};
            const char *value[4] = {layer_name[l], "MurmurHash3_32", "uint32_to_float32",
                                    manifest[l]};
            for (int k = 0; k < 4; k++) {
                snprintf(keys[l][k], sizeof keys[l][k], "cryptomatte/%s/%s", key, field[k]);
                meta[m++] = (tl_meta){keys[l][k], TL_META_STRING, value[k], 0, 0, NULL};
            }
        }
        tl_image_options o = opt ? *opt : (tl_image_options){0};
        o.meta = meta;
        o.meta_count = m;
        rc = tl_exr_write_channels(path, w, h, ch, n, &o, err);
    }
    free(meta);
    free(vector);
    free(normal);
    free(data);
    return rc;
}

/* A copy of a plane of `channels` floats a pixel (colour first, then alpha,
 * kept) through the row-major 3x3 matrix m; NULL when out of memory. */
static float *working_copy(const float *plane, int channels, const tl_frame *frame, const double *m)
{
    size_t px = (size_t)frame->width * (size_t)frame->height;
    float *out = malloc(px * (size_t)channels * sizeof *out);
    for (size_t i = 0; out && i < px; i++) {
        const float *c = plane + i * (size_t)channels;
        float *d = out + i * (size_t)channels;
        for (int r = 0; r < 3; r++)
            d[r] = (float)(m[r * 3] * c[0] + m[r * 3 + 1] * c[1] + m[r * 3 + 2] * c[2]);
        for (int r = 3; r < channels; r++)
            d[r] = c[r];
    }
    return out;
}

int tl_passes_write_frame(const char *path, const tl_frame *frame, const tl_passes_frame *info,
                          const tl_image_options *opt, tl_error *err)
{
    int given = opt && opt->meta ? opt->meta_count : 0;
    tl_meta *meta = malloc(sizeof *meta * (size_t)(given + TL_PASSES_CAMERA_META + 2));
    if (!meta)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", path);
    if (given)
        memcpy(meta, opt->meta, sizeof *meta * (size_t)given);
    tl_passes_meta camera;
    int n = tl_passes_camera_meta(info->camera, frame->width, frame->height, info->fps, info->space,
                                  &camera);
    memcpy(meta + given, camera.meta, sizeof *meta * (size_t)n);
    tl_image_options o = opt ? *opt : (tl_image_options){0};
    o.meta = meta;
    o.meta_count = given + n;
    meta[o.meta_count++] = (tl_meta){
        "tideline/working_space", TL_META_STRING, tl_color_working_name(info->space), 0, 0, NULL};
    /* The colour and the light layers in the working space: copies, the
     * frame is the caller's. */
    tl_frame converted = *frame;
    int rc = TL_OK;
    if (info->working) {
        converted.color = working_copy(frame->color, 4, frame, info->working);
        rc = converted.color ? TL_OK : TL_ERR_RUNTIME;
        for (int k = 0; k < TL_FRAME_LAYERS; k++)
            if (frame->layer[k] && !rc) {
                converted.layer[k] = working_copy(frame->layer[k], 3, frame, info->working);
                rc = converted.layer[k] ? TL_OK : TL_ERR_RUNTIME;
            } else {
                converted.layer[k] = NULL;
            }
    }
    const tl_frame *out = info->working ? &converted : frame;
    char names[TL_PASSES_NAMES_SIZE];
    if (rc) {
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", path);
    } else if (!info->passes) {
        rc = tl_exr_write(path, out, &o, err);
    } else {
        tl_passes_format(info->passes | TL_PASSES_COMBINED, names, sizeof names);
        meta[o.meta_count++] = (tl_meta){"tideline/passes", TL_META_STRING, names, 0, 0, NULL};
        rc = tl_passes_write_exr(path, out, info, &o, err);
    }
    if (info->working) {
        free(converted.color);
        for (int k = 0; k < TL_FRAME_LAYERS; k++)
            free(converted.layer[k]);
    }
    free(meta);
    return rc;
}
