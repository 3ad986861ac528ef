#include "tl_noise.h"

#include <math.h>
#include <stdint.h>

/* shaders/foam_noise.glsl's foam_hash: the same integers, so the same noise. */
static double hash(int32_t x, int32_t y)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    return (double)(h & 0xffffu) / 65535.0;
}

double tl_noise_value(double x, double y)
{
    double ix = floor(x), iy = floor(y), fx = x - ix, fy = y - iy;
    fx = fx * fx * (3.0 - 2.0 * fx);
    fy = fy * fy * (3.0 - 2.0 * fy);
    int32_t cx = (int32_t)ix, cy = (int32_t)iy;
    double a = hash(cx, cy), b = hash(cx + 1, cy), d = hash(cx, cy + 1), e = hash(cx + 1, cy + 1);
    return (a + (b - a) * fx) + ((d + (e - d) * fx) - (a + (b - a) * fx)) * fy;
}

double tl_noise_cells(double x, double y)
{
    double ix = floor(x), iy = floor(y), fx = x - ix, fy = y - iy;
    int32_t cx = (int32_t)ix, cy = (int32_t)iy;
    double f1 = 8.0, f2 = 8.0;
    const double span = 1.0 - 2.0 * TL_NOISE_CELL_MARGIN;
    for (int j = -1; j <= 1; j++)
        for (int i = -1; i <= 1; i++) {
            int32_t hx = cx + i, hy = cy + j;
            double px = i + TL_NOISE_CELL_MARGIN + span * hash(hx, hy);
            double py = j + TL_NOISE_CELL_MARGIN +
                        span * hash(hx + TL_NOISE_CELL_SHIFT_X, hy + TL_NOISE_CELL_SHIFT_Y);
            double d = hypot(px - fx, py - fy);
            if (d < f1) {
                f2 = f1;
                f1 = d;
            } else if (d < f2) {
                f2 = d;
            }
        }
    return f2 - f1;
}
