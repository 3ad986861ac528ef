/* tl_metrics: how far one display image is from another, as a person
 * would judge the difference: PSNR, SSIM and the 99th-percentile pixel
 * error. `tideline compare` and `tideline bench` report them.
 *
 * Images are display-referred (tonemapped, sRGB-encoded) RGBA planes of
 * floats in [0, 1], four floats a pixel (tl_frame.display); alpha is
 * ignored. */
#ifndef TL_METRICS_H
#define TL_METRICS_H

#include <stddef.h>

/* PSNR reported for identical images (the MSE is 0): a finite cap, so
 * tables, CSVs and plots never hold Inf. Any real difference of 8-bit
 * images scores below it (one level in one channel of a 16384² image is
 * about 143 dB; the cap is above that). */
#define TL_METRICS_PSNR_MAX 200.0

typedef struct tl_metrics {
    double psnr;      /* dB over R, G and B; TL_METRICS_PSNR_MAX when identical */
    double ssim;      /* mean SSIM of luma (Wang et al. 2004), 1 when identical */
    double p99;       /* 99th percentile of each pixel's largest channel error, 8-bit levels */
    double max_error; /* the largest channel error anywhere, 8-bit levels */
} tl_metrics;

/* PSNR of RGB over `pixels` pixels, peak 1. */
double tl_metrics_psnr(const float *a, const float *b, size_t pixels);

/* Mean SSIM of the luma Y = 0.2126 R + 0.7152 G + 0.0722 B of the encoded
 * values, with an 11-tap Gaussian window (sigma 1.5), edges replicated, and
 * C1 = (0.01)^2, C2 = (0.03)^2. Returns -2 when out of memory. */
double tl_metrics_ssim(const float *a, const float *b, int width, int height);

/* The nearest-rank 99th percentile and the maximum of each pixel's largest
 * |a - b| over R, G, B, in 8-bit levels (x 255). Returns 0, or -1 when out
 * of memory. */
int tl_metrics_pixel_error(const float *a, const float *b, size_t pixels, double *p99,
                           double *max_error);

/* All of the above. Returns 0, or -1 when out of memory. */
int tl_metrics_compare(const float *a, const float *b, int width, int height, tl_metrics *out);

#endif
