/* A timeline's camera, sun and floating objects sampled every frame, into
 * glTF's axes (tl_export.h), written atomically. */
#include "export/tl_export.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "image/tl_atomic.h"

void tl_export_point(const double world[3], double gltf[3])
{
    gltf[0] = world[0];
    gltf[1] = world[1];
    gltf[2] = -world[2];
}

/* The unit quaternion (x y z w) of the rotation whose columns are the
 * local axes x, y and z in glTF's world. */
static void quaternion(const double x[3], const double y[3], const double z[3], float q[4])
{
    const double m[3][3] = {{x[0], y[0], z[0]}, {x[1], y[1], z[1]}, {x[2], y[2], z[2]}};
    double trace = m[0][0] + m[1][1] + m[2][2], r[4];
    if (trace > 0.0) {
        double s = 2.0 * sqrt(1.0 + trace);
        r[3] = 0.25 * s;
        r[0] = (m[2][1] - m[1][2]) / s;
        r[1] = (m[0][2] - m[2][0]) / s;
        r[2] = (m[1][0] - m[0][1]) / s;
    } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
        double s = 2.0 * sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        r[3] = (m[2][1] - m[1][2]) / s;
        r[0] = 0.25 * s;
        r[1] = (m[0][1] + m[1][0]) / s;
        r[2] = (m[0][2] + m[2][0]) / s;
    } else if (m[1][1] > m[2][2]) {
        double s = 2.0 * sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
        r[3] = (m[0][2] - m[2][0]) / s;
        r[0] = (m[0][1] + m[1][0]) / s;
        r[1] = 0.25 * s;
        r[2] = (m[1][2] + m[2][1]) / s;
    } else {
        double s = 2.0 * sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
        r[3] = (m[1][0] - m[0][1]) / s;
        r[0] = (m[0][2] + m[2][0]) / s;
        r[1] = (m[1][2] + m[2][1]) / s;
        r[2] = 0.25 * s;
    }
    double n = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    for (int i = 0; i < 4; i++)
        q[i] = (float)(r[i] / n);
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalise(double v[3])
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3 && n > 0.0; i++)
        v[i] /= n;
}

/* A node's pose at one frame: its position, and its local axes given as
 * tideline world vectors (x, y, z), each mirrored into glTF's world. */
static void pose(const double position[3], const double x[3], const double y[3], const double z[3],
                 float *translation, float *rotation)
{
    double p[3], gx[3], gy[3], gz[3];
    tl_export_point(position, p);
    tl_export_point(x, gx);
    tl_export_point(y, gy);
    tl_export_point(z, gz);
    for (int i = 0; i < 3; i++)
        translation[i] = (float)p[i];
    quaternion(gx, gy, gz, rotation);
}

int tl_export_check_path(const char *path, tl_error *err)
{
    const char *dot = strrchr(path, '.');
    if (!dot || (strcasecmp(dot, ".glb") != 0 && strcasecmp(dot, ".gltf") != 0))
        return tl_error_set(err, TL_ERR_USAGE, "%s: unknown format (use .gltf or .glb)", path);
    return TL_OK;
}

int tl_export_camera(const tl_timeline *tl, const char *path, tl_error *err)
{
    int rc0 = tl_export_check_path(path, err);
    if (rc0)
        return rc0;
    const char *dot = strrchr(path, '.');
    int binary = strcasecmp(dot, ".glb") == 0;
    long frames = tl_timeline_frame_count(tl);
    if (frames < 1)
        return tl_error_set(err, TL_ERR_USAGE, "%s: the timeline has no frame", path);
    /* glTF's key times are 32-bit floats: each frame's must be a float of
     * its own, after the one before. */
    if (frames > TL_EXPORT_MAX_FRAMES || (float)tl_timeline_frame_time(tl, frames - 1) <=
                                             (float)tl_timeline_frame_time(tl, frames - 2))
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: %ld frames are more than a glTF animation holds (its key times "
                            "are 32-bit floats; at most %d frames)",
                            path, frames, TL_EXPORT_MAX_FRAMES);
    /* The camera, the sun, then each floating object with a path. */
    int objects = tl->object_count;
    int nodes = 2 + objects;
    float *data = calloc((size_t)frames * (size_t)nodes * 7 + (size_t)frames, sizeof *data);
    tl_gltf_node *node = calloc((size_t)nodes, sizeof *node);
    tl_scene *scene = malloc(sizeof *scene);
    if (!data || !node || !scene) {
        free(data);
        free(node);
        free(scene);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    float *yfov = data + (size_t)frames * (size_t)nodes * 7;
    for (int n = 0; n < nodes; n++) {
        node[n].translation = data + (size_t)n * (size_t)frames * 7;
        node[n].rotation = node[n].translation + (size_t)frames * 3;
    }
    int used[TL_OBJECT_MAX] = {0};
    for (long k = 0; k < frames; k++) {
        tl_timeline_eval(tl, tl_timeline_frame_time(tl, k), scene);
        /* The camera: glTF's looks along its -z, x right, y up. */
        const tl_camera *c = &scene->camera;
        double right[3], up[3], forward[3], back[3];
        tl_scene_camera_basis(c, right, up, forward);
        for (int i = 0; i < 3; i++)
            back[i] = -forward[i];
        /* The mirror turns x y z into a right-handed frame only with one
         * axis flipped: right, up, back are mirrored, and glTF's z is
         * their x cross y there. */
        float *t = (float *)node[0].translation + k * 3, *r = (float *)node[0].rotation + k * 4;
        pose(c->position, right, up, back, t, r);
        yfov[k] = (float)c->vfov;
        if (k == 0) {
            node[0].yfov = c->vfov;
            node[0].aspect = (double)scene->width / scene->height;
        }
        /* The sun: a directional light shines along its -z. */
        double to_sun[3], east[3] = {1.0, 0.0, 0.0}, side[3], top[3];
        tl_scene_sun_direction(&scene->sun, to_sun);
        cross((double[3]){0.0, 1.0, 0.0}, to_sun, side);
        if (hypot(side[0], side[2]) < 1e-9)
            memcpy(side, east, sizeof side);
        normalise(side);
        cross(to_sun, side, top);
        /* In the mirrored world the frame side, top, to_sun flips its
         * handedness: glTF's x is the mirrored side turned round. */
        double flipped[3] = {-side[0], -side[1], -side[2]};
        t = (float *)node[1].translation + k * 3;
        r = (float *)node[1].rotation + k * 4;
        pose((double[3]){0.0, 0.0, 0.0}, flipped, top, to_sun, t, r);
        /* The floating objects: x to port, y up, z along the bow. */
        for (int o = 0; o < objects && o < TL_OBJECT_MAX; o++) {
            const tl_boat *b = tl_scene_object_const(scene, o);
            used[o] |= b->enabled;
            double h = b->heading, p = -b->pitch, q = -b->roll;
            /* R = Ry(heading) Rx(-pitch) Rz(-roll), as tl_prepare places
             * the hull; its columns are the hull's axes. */
            double ch = cos(h), sh = sin(h), cp = cos(p), sp = sin(p), cq = cos(q), sq = sin(q);
            const double rx[3][3] = {{1, 0, 0}, {0, cp, -sp}, {0, sp, cp}};
            const double ry[3][3] = {{ch, 0, sh}, {0, 1, 0}, {-sh, 0, ch}};
            const double rz[3][3] = {{cq, -sq, 0}, {sq, cq, 0}, {0, 0, 1}};
            double a[3][3], m[3][3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) {
                    a[i][j] = 0.0;
                    for (int l = 0; l < 3; l++)
                        a[i][j] += ry[i][l] * rx[l][j];
                }
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) {
                    m[i][j] = 0.0;
                    for (int l = 0; l < 3; l++)
                        m[i][j] += a[i][l] * rz[l][j];
                }
            double ax[3] = {m[0][0], m[1][0], m[2][0]}, ay[3] = {m[0][1], m[1][1], m[2][1]},
                   az[3] = {m[0][2], m[1][2], m[2][2]}, mx[3] = {-ax[0], -ax[1], -ax[2]};
            t = (float *)node[2 + o].translation + k * 3;
            r = (float *)node[2 + o].rotation + k * 4;
            pose(b->position, mx, ay, az, t, r);
        }
    }
    /* q and -q are one rotation: each key takes the sign nearer the key
     * before, so that a package interpolating the components does not swing
     * the long way round between two frames. */
    for (int n = 0; n < nodes; n++)
        for (long k = 1; k < frames; k++) {
            float *q = (float *)node[n].rotation + k * 4;
            const float *before = q - 4;
            if (q[0] * before[0] + q[1] * before[1] + q[2] * before[2] + q[3] * before[3] < 0.0f)
                for (int i = 0; i < 4; i++)
                    q[i] = -q[i];
        }
    node[0].name = "camera";
    node[0].kind = TL_GLTF_CAMERA;
    node[0].yfov_keys = yfov;
    node[1].name = "sun";
    node[1].kind = TL_GLTF_SUN;
    int count = 2;
    for (int o = 0; o < objects && o < TL_OBJECT_MAX; o++)
        if (used[o]) {
            node[count] = node[2 + o];
            node[count].name = tl->objects[o].name;
            node[count].kind = TL_GLTF_EMPTY;
            count++;
        }
    unsigned char *bytes = NULL;
    size_t size = 0;
    char why[256] = "";
    int rc = TL_OK;
    if (tl_gltf_encode(node, count, (int)frames, tl->fps, binary, &bytes, &size, why, sizeof why))
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: %s", path, why);
    tl_atomic_file file;
    if (!rc)
        rc = tl_atomic_open(&file, path, err);
    if (!rc) {
        size_t done = 0;
        while (done < size) {
            ssize_t n = write(file.fd, bytes + done, size - done);
            if (n <= 0)
                break;
            done += (size_t)n;
        }
        if (done < size) {
            tl_atomic_abort(&file);
            rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot write", path);
        } else {
            rc = tl_atomic_commit(&file, err);
        }
    }
    free(bytes);
    free(scene);
    free(node);
    free(data);
    return rc;
}
