/* tl_clock: a monotonic clock for timings (progress, -v logs, the bench). */
#ifndef TL_CLOCK_H
#define TL_CLOCK_H

/* Seconds since an arbitrary fixed point; never goes backwards. */
double tl_clock_seconds(void);

#endif
