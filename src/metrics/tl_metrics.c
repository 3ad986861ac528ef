#include "tl_metrics.h"

#include <math.h>
#include <stdlib.h>

double tl_metrics_psnr(const float *a, const float *b, size_t pixels)
{
    double sum = 0.0;
    for (size_t i = 0; i < pixels; i++)
        for (int c = 0; c < 3; c++) {
            double d = (double)a[4 * i + c] - (double)b[4 * i + c];
            sum += d * d;
        }
    double mse = pixels > 0 ? sum / (3.0 * (double)pixels) : 0.0;
    if (mse <= 0.0)
        return TL_METRICS_PSNR_MAX;
    double psnr = -10.0 * log10(mse);
    return psnr < TL_METRICS_PSNR_MAX ? psnr : TL_METRICS_PSNR_MAX;
}

static double luma(const float *rgba)
{
    return 0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2];
}

#define SSIM_RADIUS 5

/* Separable Gaussian blur of `in` into `out` (edges replicated); `tmp`
 * holds the horizontal pass. */
static void blur(const double *in, double *out, double *tmp, int w, int h, const double *k)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double s = 0.0;
            for (int i = -SSIM_RADIUS; i <= SSIM_RADIUS; i++) {
                int xi = x + i < 0 ? 0 : (x + i >= w ? w - 1 : x + i);
                s += k[i + SSIM_RADIUS] * in[(size_t)y * w + xi];
            }
            tmp[(size_t)y * w + x] = s;
        }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double s = 0.0;
            for (int i = -SSIM_RADIUS; i <= SSIM_RADIUS; i++) {
                int yi = y + i < 0 ? 0 : (y + i >= h ? h - 1 : y + i);
                s += k[i + SSIM_RADIUS] * tmp[(size_t)yi * w + x];
            }
            out[(size_t)y * w + x] = s;
        }
}

double tl_metrics_ssim(const float *a, const float *b, int width, int height)
{
    size_t n = (size_t)width * (size_t)height;
    if (n == 0)
        return 1.0;
    /* Planes: ya, yb, then the products, then their blurred versions. */
    double *buf = malloc(sizeof(double) * n * 11);
    if (!buf)
        return -2.0;
    double *ya = buf, *yb = buf + n, *aa = buf + 2 * n, *bb = buf + 3 * n, *ab = buf + 4 * n;
    double *ma = buf + 5 * n, *mb = buf + 6 * n, *maa = buf + 7 * n, *mbb = buf + 8 * n,
           *mab = buf + 9 * n, *tmp = buf + 10 * n;
    for (size_t i = 0; i < n; i++) {
        ya[i] = luma(a + 4 * i);
        yb[i] = luma(b + 4 * i);
        aa[i] = ya[i] * ya[i];
        bb[i] = yb[i] * yb[i];
        ab[i] = ya[i] * yb[i];
    }
    double k[2 * SSIM_RADIUS + 1], ksum = 0.0;
    for (int i = -SSIM_RADIUS; i <= SSIM_RADIUS; i++)
        ksum += k[i + SSIM_RADIUS] = exp(-(double)(i * i) / (2.0 * 1.5 * 1.5));
    for (int i = 0; i < 2 * SSIM_RADIUS + 1; i++)
        k[i] /= ksum;
    blur(ya, ma, tmp, width, height, k);
    blur(yb, mb, tmp, width, height, k);
    blur(aa, maa, tmp, width, height, k);
    blur(bb, mbb, tmp, width, height, k);
    blur(ab, mab, tmp, width, height, k);
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        double va = maa[i] - ma[i] * ma[i], vb = mbb[i] - mb[i] * mb[i];
        double cov = mab[i] - ma[i] * mb[i];
        sum += (2.0 * ma[i] * mb[i] + c1) * (2.0 * cov + c2) /
               ((ma[i] * ma[i] + mb[i] * mb[i] + c1) * (va + vb + c2));
    }
    free(buf);
    return sum / (double)n;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

int tl_metrics_pixel_error(const float *a, const float *b, size_t pixels, double *p99,
                           double *max_error)
{
    *p99 = *max_error = 0.0;
    if (pixels == 0)
        return 0;
    double *err = malloc(sizeof(double) * pixels);
    if (!err)
        return -1;
    for (size_t i = 0; i < pixels; i++) {
        double e = 0.0;
        for (int c = 0; c < 3; c++) {
            double d = fabs((double)a[4 * i + c] - (double)b[4 * i + c]);
            e = d > e ? d : e;
        }
        err[i] = e * 255.0;
    }
    qsort(err, pixels, sizeof *err, cmp_double);
    /* Nearest rank: the smallest value at or above 99% of the pixels. */
    size_t rank = (size_t)ceil(0.99 * (double)pixels);
    *p99 = err[rank > 0 ? rank - 1 : 0];
    *max_error = err[pixels - 1];
    free(err);
    return 0;
}

int tl_metrics_compare(const float *a, const float *b, int width, int height, tl_metrics *out)
{
    size_t n = (size_t)width * (size_t)height;
    out->psnr = tl_metrics_psnr(a, b, n);
    out->ssim = tl_metrics_ssim(a, b, width, height);
    if (out->ssim < -1.5)
        return -1;
    return tl_metrics_pixel_error(a, b, n, &out->p99, &out->max_error);
}
