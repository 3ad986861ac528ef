/* The passes' names and the camera's attributes (tl_passes.h). */
#include "passes/tl_passes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/tl_math.h"

/* The names `--passes` takes, each with the passes it asks for: the passes
 * one by one, then the groups (tl_passes_format names passes only). */
static const char *const pass_names[] = {"combined",
                                         "depth",
                                         "normal",
                                         "position",
                                         "mask_water",
                                         "mask_foam",
                                         "mask_giant",
                                         "mask_boat",
                                         "mask_sky",
                                         "mask_underwater",
                                         "cryptomatte",
                                         "vector",
                                         "light_sky",
                                         "light_reflection",
                                         "light_body",
                                         "light_glitter",
                                         "light_foam",
                                         "light_spray",
                                         "light_boat",
                                         "light_glare",
                                         "cryptomatte_material",
                                         "masks",
                                         "lights",
                                         "all",
                                         "none",
                                         NULL};
static const unsigned pass_bits[] = {TL_PASSES_COMBINED,
                                     TL_PASSES_DEPTH,
                                     TL_PASSES_NORMAL,
                                     TL_PASSES_POSITION,
                                     TL_PASSES_MASK_WATER,
                                     TL_PASSES_MASK_FOAM,
                                     TL_PASSES_MASK_GIANT,
                                     TL_PASSES_MASK_BOAT,
                                     TL_PASSES_MASK_SKY,
                                     TL_PASSES_MASK_UNDERWATER,
                                     TL_PASSES_CRYPTOMATTE,
                                     TL_PASSES_VECTOR,
                                     TL_PASSES_LIGHT_SKY,
                                     TL_PASSES_LIGHT_REFLECTION,
                                     TL_PASSES_LIGHT_BODY,
                                     TL_PASSES_LIGHT_GLITTER,
                                     TL_PASSES_LIGHT_FOAM,
                                     TL_PASSES_LIGHT_SPRAY,
                                     TL_PASSES_LIGHT_BOAT,
                                     TL_PASSES_LIGHT_GLARE,
                                     TL_PASSES_CRYPTO_MATERIAL,
                                     TL_PASSES_MASKS,
                                     TL_PASSES_LIGHTS,
                                     TL_PASSES_ALL,
                                     0};
#define PASS_NAMES ((int)(sizeof pass_bits / sizeof pass_bits[0]))
_Static_assert(sizeof pass_names / sizeof pass_names[0] == PASS_NAMES + 1,
               "a name for every set of passes");

const char *tl_passes_valid_names(void)
{
    return "combined, depth, normal, position, mask_water, mask_foam, mask_giant, mask_boat, "
           "mask_sky, mask_underwater, cryptomatte, vector, light_sky, light_reflection, "
           "light_body, light_glitter, light_foam, light_spray, light_boat, light_glare, "
           "cryptomatte_material, masks (every mask), lights (every light layer), all, none "
           "(alone: the plain file)";
}

const char *const *tl_passes_name_list(void)
{
    return pass_names;
}

int tl_passes_parse(const char *list, unsigned *passes, size_t *bad_at, size_t *bad_len)
{
    unsigned found = TL_PASSES_COMBINED;
    size_t at = 0;
    for (;;) {
        size_t len = strcspn(list + at, ",");
        int k = 0;
        while (k < PASS_NAMES &&
               !(strlen(pass_names[k]) == len && strncmp(list + at, pass_names[k], len) == 0))
            k++;
        /* "none" stands alone. */
        if (k == PASS_NAMES || (!pass_bits[k] && (at > 0 || list[at + len]))) {
            *bad_at = at;
            *bad_len = len;
            return -1;
        }
        if (!pass_bits[k])
            found = 0;
        found |= pass_bits[k];
        if (!list[at + len])
            break;
        at += len + 1;
    }
    *passes = found;
    return 0;
}

void tl_passes_format(unsigned passes, char *out, size_t size)
{
    size_t n = 0;
    if (size)
        out[0] = '\0';
    for (int k = 0; k < PASS_NAMES && n < size; k++) {
        unsigned p = pass_bits[k];
        if ((p & (p - 1)) == 0 && (passes & p)) /* one pass, not a group */
            n += (size_t)snprintf(out + n, size - n, "%s%s", n ? "," : "", pass_names[k]);
    }
}

int tl_passes_need_aov(unsigned passes)
{
    return (passes & (TL_PASSES_NORMAL | TL_PASSES_MASKS | TL_PASSES_CRYPTOMATTE |
                      TL_PASSES_CRYPTO_MATERIAL | TL_PASSES_VECTOR)) != 0;
}

unsigned tl_passes_light_layers(unsigned passes)
{
    return (passes & TL_PASSES_LIGHTS) >> TL_PASSES_LIGHT0;
}

/* ---- the camera ---- */

void tl_passes_world_to_camera(const tl_camera *camera, double m[16])
{
    double axis[3][3]; /* right, up, forward */
    tl_scene_camera_basis(camera, axis[0], axis[1], axis[2]);
    /* Row i takes the point's coordinate i; column j gives axis j's. */
    for (int j = 0; j < 3; j++) {
        for (int i = 0; i < 3; i++)
            m[i * 4 + j] = axis[j][i];
        m[12 + j] = -(axis[j][0] * camera->position[0] + axis[j][1] * camera->position[1] +
                      axis[j][2] * camera->position[2]);
        m[j * 4 + 3] = 0.0;
    }
    m[15] = 1.0;
}

void tl_passes_world_to_ndc(const tl_camera *camera, int width, int height, double m[16])
{
    double to_camera[16];
    tl_passes_world_to_camera(camera, to_camera);
    double ty = tan(0.5 * camera->vfov), tx = ty * width / height;
    /* Camera (x, y, z, 1) to (x / (2 tx) + z / 2, -y / (2 ty) + z / 2, z, z):
     * after the division by w = z, x and y run 0..1 across the image, y
     * down. z / w is 1 everywhere (OpenEXR drops it). */
    const double projection[16] = {0.5 / tx, 0.0, 0.0, 0.0, 0.0, -0.5 / ty, 0.0, 0.0,
                                   0.5,      0.5, 1.0, 1.0, 0.0, 0.0,       0.0, 0.0};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++)
                sum += to_camera[i * 4 + k] * projection[k * 4 + j];
            m[i * 4 + j] = sum;
        }
}

void tl_passes_pixel_ray(const tl_camera *camera, int width, int height, int x, int y,
                         double ray[3])
{
    double right[3], up[3], forward[3];
    tl_scene_camera_basis(camera, right, up, forward);
    double ty = tan(0.5 * camera->vfov), aspect = (double)width / height;
    double nx = (x + 0.5) / width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / height * 2.0;
    double len = 0.0;
    for (int i = 0; i < 3; i++) {
        ray[i] = forward[i] + nx * aspect * ty * right[i] + ny * ty * up[i];
        len += ray[i] * ray[i];
    }
    len = sqrt(len);
    for (int i = 0; i < 3; i++)
        ray[i] /= len;
}

/* The frame rate as a ratio of integers: whole rates exact, others (23.976)
 * to a thousandth. */
static void fps_ratio(double fps, double out[2])
{
    long den = fabs(fps - round(fps)) < 1e-9 ? 1 : 1000;
    long num = lround(fps * (double)den);
    long g = tl_gcd(num, den);
    out[0] = (double)(num / g);
    out[1] = (double)(den / g);
}

int tl_passes_camera_meta(const tl_camera *camera, int width, int height, double fps,
                          tl_working_space space, tl_passes_meta *m)
{
    tl_passes_world_to_camera(camera, m->world_to_camera);
    tl_passes_world_to_ndc(camera, width, height, m->world_to_ndc);
    tl_color_working_chromaticities(space, m->chromaticities);
    memcpy(m->origin, camera->position, sizeof m->origin);
    double ty = tan(0.5 * camera->vfov), tx = ty * width / height;
    double focal = 0.5 * TL_PASSES_SENSOR_WIDTH_MM / tx;
    int n = 0;
    m->meta[n++] = (tl_meta){"worldToCamera", TL_META_M44F, NULL, 0, 0, m->world_to_camera};
    m->meta[n++] = (tl_meta){"worldToNDC", TL_META_M44F, NULL, 0, 0, m->world_to_ndc};
    m->meta[n++] =
        (tl_meta){"chromaticities", TL_META_CHROMATICITIES, NULL, 0, 0, m->chromaticities};
    m->meta[n++] = (tl_meta){"tideline/focal_length_mm", TL_META_DOUBLE, NULL, focal, 0, NULL};
    m->meta[n++] = (tl_meta){
        "tideline/sensor_width_mm", TL_META_DOUBLE, NULL, TL_PASSES_SENSOR_WIDTH_MM, 0, NULL};
    m->meta[n++] = (tl_meta){"tideline/sensor_height_mm",
                             TL_META_DOUBLE,
                             NULL,
                             TL_PASSES_SENSOR_WIDTH_MM * height / width,
                             0,
                             NULL};
    m->meta[n++] = (tl_meta){
        "tideline/fov_horizontal_deg", TL_META_DOUBLE, NULL, 2.0 * atan(tx) / TL_DEG, 0, NULL};
    m->meta[n++] = (tl_meta){
        "tideline/fov_vertical_deg", TL_META_DOUBLE, NULL, camera->vfov / TL_DEG, 0, NULL};
    m->meta[n++] = (tl_meta){"tideline/position_origin", TL_META_V3D, NULL, 0, 0, m->origin};
    if (fps > 0.0) {
        fps_ratio(fps, m->fps);
        m->meta[n++] = (tl_meta){"framesPerSecond", TL_META_RATIONAL, NULL, 0, 0, m->fps};
    }
    return n;
}
