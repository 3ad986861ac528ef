/* The Vector pass (tl_passes.h): where the point each pixel shows was a
 * frame before and will be a frame after, on screen, in double. */
#include "passes/tl_passes.h"

#include <math.h>
#include <string.h>

#include "waves/tl_giant.h"
#include "waves/tl_waves.h"

/* What a pixel shows, by the largest of its covers (tl_frame.h), and the
 * sea floor (an ocean pixel whose point lies well under the surface: the
 * sand stays where it is). */
enum { SHOWS_FLOOR = -1, SHOWS_SKY = 0, SHOWS_OCEAN = 1, SHOWS_GIANT = 2, SHOWS_OBJECT = 3 };

static int shows(const tl_frame *f, size_t i)
{
    const size_t plane = (size_t)f->width * (size_t)f->height * 4;
    int best = SHOWS_SKY;
    float most = -1.0f;
    for (int k = 0; k < 3 + TL_FRAME_AOV_OBJECTS; k++) {
        int v = k < 3 ? 4 + k : TL_FRAME_AOV_OBJECT0 + (k - 3);
        float c = f->aov[(size_t)(v / 4) * plane + i * 4 + (size_t)(v % 4)];
        if (c > most) {
            most = c;
            best = k;
        }
    }
    return best;
}

/* A camera's view: its position, axes and the image's scale. */
typedef struct view {
    double position[3], right[3], up[3], forward[3];
    double fx, fy; /* pixels per unit of tan across and up */
    int width, height;
} view;

static void view_of(const tl_camera *c, int width, int height, view *v)
{
    memcpy(v->position, c->position, sizeof v->position);
    tl_scene_camera_basis(c, v->right, v->up, v->forward);
    double ty = tan(0.5 * c->vfov), tx = ty * width / height;
    v->fx = 0.5 * width / tx;
    v->fy = 0.5 * height / ty;
    v->width = width;
    v->height = height;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Where direction d (camera-relative, any length) lands on v's image, in
 * pixels from the bottom-left corner, y up (Blender's raster); 0 when it
 * points behind the camera. */
static int raster(const view *v, const double d[3], double out[2])
{
    double z = dot3(d, v->forward);
    if (!(z > 1e-9))
        return 0;
    out[0] = 0.5 * v->width + v->fx * dot3(d, v->right) / z;
    out[1] = 0.5 * v->height + v->fy * dot3(d, v->up) / z;
    return 1;
}

/* A floating object's placement: model -> world is position + L·model,
 * L its rotation (heading, then pitch bow up, roll starboard down, then
 * the model's yaw) times its scale, as tl_prepare places the hull. */
typedef struct placement {
    double position[3];
    double linear[3][3];
} placement;

static void mat3_mul(const double a[3][3], const double b[3][3], double out[3][3])
{
    double r[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    memcpy(out, r, sizeof r);
}

/* Rotation about axis 0 (x), 1 (y) or 2 (z) by `angle`, right-handed. */
static void rotation(int axis, double angle, double out[3][3])
{
    double c = cos(angle), s = sin(angle);
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    memset(out, 0, sizeof(double) * 9);
    out[axis][axis] = 1.0;
    out[a][a] = c;
    out[a][b] = -s;
    out[b][a] = s;
    out[b][b] = c;
}

static void placement_of(const tl_boat *o, placement *p)
{
    memcpy(p->position, o->position, sizeof p->position);
    double m[3][3], r[3][3];
    rotation(1, o->heading, m);
    rotation(0, -o->pitch, r);
    mat3_mul(m, r, m);
    rotation(2, -o->roll, r);
    mat3_mul(m, r, m);
    rotation(1, o->model_yaw, r);
    mat3_mul(m, r, m);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            p->linear[i][j] = m[i][j] * o->scale;
}

/* World point w on the object placed at `from`, carried to where it is
 * when the object is placed at `to`. */
static void carry(const placement *from, const placement *to, const double w[3], double out[3])
{
    double d[3] = {w[0] - from->position[0], w[1] - from->position[1], w[2] - from->position[2]};
    double model[3];
    /* L's inverse: the rotation's transpose over the scale squared. */
    double s2 = 0.0;
    for (int i = 0; i < 3; i++)
        s2 += from->linear[i][0] * from->linear[i][0];
    for (int j = 0; j < 3; j++)
        model[j] =
            (from->linear[0][j] * d[0] + from->linear[1][j] * d[1] + from->linear[2][j] * d[2]) /
            (s2 > 0.0 ? s2 : 1.0);
    for (int i = 0; i < 3; i++)
        out[i] = to->position[i] + to->linear[i][0] * model[0] + to->linear[i][1] * model[1] +
                 to->linear[i][2] * model[2];
}

/* One side of the motion: the scene a frame away and what moves with it. */
typedef struct side {
    const tl_scene *scene; /* NULL: no motion that way */
    view camera;
    tl_giant giant;
    placement objects[TL_OBJECT_MAX];
} side;

static void side_of(const tl_scene *s, int width, int height, side *out)
{
    out->scene = s;
    if (!s)
        return;
    view_of(&s->camera, width, height, &out->camera);
    tl_giant_prepare(&out->giant, &s->giant, s->time);
    for (int k = 0; k < s->objects && k < TL_OBJECT_MAX; k++)
        placement_of(tl_scene_object_const(s, k), &out->objects[k]);
}

/* Where world point p (or, for the sky, direction p) of what `what` names
 * is on side `to`'s image, from side `now`; 0 when it is behind the camera
 * then. `surface`: the water's height under p now (the ocean's points). */
static int moved(const side *now, const side *to, const tl_waves *waves, int what,
                 const double p[3], double surface, int sky, double out[2])
{
    const tl_scene *s = now->scene;
    double q[3] = {p[0], p[1], p[2]};
    if (sky)
        return raster(&to->camera, p, out); /* at infinity: the camera's turn alone */
    if (what == SHOWS_OCEAN) {
        /* The water rises and falls where it is. */
        int octaves = s->quality.march_octaves;
        int iterations = s->quality.giant_iterations;
        q[1] += tl_waves_surface_height(waves, &to->giant, p[0], p[2], to->scene->time, octaves,
                                        iterations) -
                surface;
    } else if (what == SHOWS_GIANT) {
        /* The wave's shape travels with its crest. */
        q[0] += to->giant.origin[0] - now->giant.origin[0];
        q[2] += to->giant.origin[1] - now->giant.origin[1];
    } else if (what >= SHOWS_OBJECT) {
        int k = what - SHOWS_OBJECT;
        if (k < s->objects && k < to->scene->objects)
            carry(&now->objects[k], &to->objects[k], p, q);
    }
    double d[3] = {q[0] - to->camera.position[0], q[1] - to->camera.position[1],
                   q[2] - to->camera.position[2]};
    return raster(&to->camera, d, out);
}

void tl_passes_vectors(const tl_frame *frame, const tl_passes_frame *info, float *out)
{
    const int w = frame->width, h = frame->height;
    memset(out, 0, sizeof(float) * 4 * (size_t)w * (size_t)h);
    if (!info->scene || !frame->aov || (!info->prev && !info->next))
        return;
    side now, before, after;
    side_of(info->scene, w, h, &now);
    side_of(info->prev, w, h, &before);
    side_of(info->next, w, h, &after);
    tl_waves waves;
    tl_waves_init(&waves, &info->scene->ocean);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            double ray[3];
            tl_passes_pixel_ray(info->camera, w, h, x, y, ray);
            int what = shows(frame, i);
            double dist = frame->depth[i];
            int sky = what == SHOWS_SKY || !(dist < TL_FRAME_SKY_DEPTH);
            /* The sky's direction, or the point on the surface. */
            double p[3], here[2], there[2];
            for (int c = 0; c < 3; c++)
                p[c] = sky ? ray[c] : now.camera.position[c] + ray[c] * dist;
            /* Below the surface by more than a pixel's slip: the floor. */
            double surface = 0.0;
            if (what == SHOWS_OCEAN && !sky) {
                surface = tl_waves_surface_height(&waves, &now.giant, p[0], p[2], info->scene->time,
                                                  info->scene->quality.march_octaves,
                                                  info->scene->quality.giant_iterations);
                if (p[1] < surface - fmax(0.5, 0.02 * dist))
                    what = SHOWS_FLOOR;
            }
            if (!raster(&now.camera, ray, here))
                continue;
            float *v = out + i * 4;
            /* Blender's layout: x y = before - now, z w = now - after. */
            if (before.scene && moved(&now, &before, &waves, what, p, surface, sky, there)) {
                v[0] = (float)(there[0] - here[0]);
                v[1] = (float)(there[1] - here[1]);
            }
            if (after.scene && moved(&now, &after, &waves, what, p, surface, sky, there)) {
                v[2] = (float)(here[0] - there[0]);
                v[3] = (float)(here[1] - there[1]);
            }
        }
}
