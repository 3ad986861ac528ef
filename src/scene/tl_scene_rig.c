/* The camera as Blender gives it (tl_scene.h's tl_camera_rig): its
 * rotation modes and its lens, turned into tideline's camera. Blender's
 * world is Z up with Y north; tideline's is Y up with Z north, so a
 * Blender vector (x, y, z) is tideline's (x, z, y). */
#include "scene/tl_scene.h"

#include <math.h>

/* m = a * b, 3x3 row-major. */
static void mul3(const double a[9], const double b[9], double m[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m[i * 3 + j] = a[i * 3] * b[j] + a[i * 3 + 1] * b[3 + j] + a[i * 3 + 2] * b[6 + j];
}

/* The rotation by `angle` about axis 0, 1 or 2 (x, y, z). */
static void axis_rotation(int axis, double angle, double m[9])
{
    double c = cos(angle), s = sin(angle);
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int i = 0; i < 9; i++)
        m[i] = 0.0;
    m[axis * 3 + axis] = 1.0;
    m[a * 3 + a] = c;
    m[a * 3 + b] = -s;
    m[b * 3 + a] = s;
    m[b * 3 + b] = c;
}

/* The rotation of a unit quaternion (w, x, y, z). */
static void quat_rotation(double w, double x, double y, double z, double m[9])
{
    m[0] = 1 - 2 * (y * y + z * z), m[1] = 2 * (x * y - w * z), m[2] = 2 * (x * z + w * y);
    m[3] = 2 * (x * y + w * z), m[4] = 1 - 2 * (x * x + z * z), m[5] = 2 * (y * z - w * x);
    m[6] = 2 * (x * z - w * y), m[7] = 2 * (y * z + w * x), m[8] = 1 - 2 * (x * x + y * y);
}

void tl_scene_rig_rotation(const tl_camera_rig *rig, double m[9])
{
    /* Blender's Euler orders name the axes in the order they apply: XYZ
     * turns about X first, so R = Rz * Ry * Rx. */
    static const int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    switch (rig->rotation_mode) {
    case TL_ROTATION_QUATERNION: {
        double w = rig->quat_w, x = rig->quat[0], y = rig->quat[1], z = rig->quat[2];
        double n = sqrt(w * w + x * x + y * y + z * z);
        if (!(n > 0.0)) { /* Blender normalises a zero quaternion to (0, 1, 0, 0) */
            w = 0.0, x = 1.0, y = z = 0.0, n = 1.0;
        }
        quat_rotation(w / n, x / n, y / n, z / n, m);
        return;
    }
    case TL_ROTATION_AXIS_ANGLE: {
        double x = rig->axis[0], y = rig->axis[1], z = rig->axis[2];
        double n = sqrt(x * x + y * y + z * z);
        double h = n > 0.0 ? 0.5 * rig->axis_angle : 0.0; /* no axis: no rotation, as Blender */
        if (!(n > 0.0))
            n = 1.0;
        double s = sin(h) / n;
        quat_rotation(cos(h), x * s, y * s, z * s, m);
        return;
    }
    default: {
        int k = rig->rotation_mode - TL_ROTATION_XYZ;
        if (k < 0 || k > 5)
            k = 0;
        double r[3][9], t[9];
        for (int i = 0; i < 3; i++)
            axis_rotation(order[k][i], rig->euler[order[k][i]], r[i]);
        mul3(r[1], r[0], t);
        mul3(r[2], t, m);
        return;
    }
    }
}

void tl_scene_apply_rig(const tl_camera_rig *rig, int width, int height, tl_camera *camera)
{
    if (rig->rotation_mode != TL_ROTATION_YAW_PITCH_ROLL) {
        double m[9];
        tl_scene_rig_rotation(rig, m);
        /* The camera's right (its +X), and forward (its -Z), in tideline's
         * axes: Blender's (x, y, z) is (x, z, y). Column j of m is where
         * the camera's axis j points. */
        const double right[3] = {m[0], m[6], m[3]};
        const double forward[3] = {-m[2], -m[8], -m[5]};
        camera->pitch = asin(fmax(-1.0, fmin(1.0, forward[1])));
        double horizontal = hypot(forward[0], forward[2]);
        /* Straight up or down the heading is the right vector's. */
        camera->yaw =
            horizontal > 1e-12 ? atan2(forward[0], forward[2]) : atan2(-right[2], right[0]);
        /* Roll: the right vector against the unrolled one (tl_scene_camera_basis). */
        double cp = cos(camera->pitch);
        const double f[3] = {cp * sin(camera->yaw), sin(camera->pitch), cp * cos(camera->yaw)};
        const double r0[3] = {cos(camera->yaw), 0.0, -sin(camera->yaw)};
        const double u0[3] = {f[1] * r0[2] - f[2] * r0[1], f[2] * r0[0] - f[0] * r0[2],
                              f[0] * r0[1] - f[1] * r0[0]};
        camera->roll = atan2(right[0] * u0[0] + right[1] * u0[1] + right[2] * u0[2],
                             right[0] * r0[0] + right[1] * r0[1] + right[2] * r0[2]);
    }
    if (rig->focal_length > 0.0 && width > 0 && height > 0) {
        /* Blender's fit: AUTO spans the sensor's width across the frame's
         * longer side; VERTICAL spans its height down the frame. */
        double aspect = (double)width / height;
        tl_sensor_fit fit = rig->sensor_fit;
        if (fit == TL_SENSOR_AUTO)
            fit = width >= height ? TL_SENSOR_HORIZONTAL : TL_SENSOR_VERTICAL;
        double half;
        if (fit == TL_SENSOR_HORIZONTAL)
            half = 0.5 * rig->sensor_width / rig->focal_length / aspect;
        else /* AUTO on a tall frame spans the width's value; VERTICAL the height's */
            half = 0.5 *
                   (rig->sensor_fit == TL_SENSOR_AUTO ? rig->sensor_width : rig->sensor_height) /
                   rig->focal_length;
        camera->vfov = 2.0 * atan(half);
    }
}
