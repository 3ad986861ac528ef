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
