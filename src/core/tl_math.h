/* tl_math: small integer helpers shared by modules. */
#ifndef TL_MATH_H
#define TL_MATH_H

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
