/* tl_math: small numeric helpers and constants shared by modules. */
#ifndef TL_MATH_H
#define TL_MATH_H

#include <math.h>

/* Radians per degree: scene angles are radians, people write degrees. */
#define TL_DEG (M_PI / 180.0)

/* Greatest common divisor of two non-negative numbers (gcd(a, 0) = a). */
static inline long tl_gcd(long a, long b)
{
    while (b) {
        long t = a % b;
        a = b;
        b = t;
    }
    return a;
}

#endif
