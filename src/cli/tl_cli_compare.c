/* tideline compare: how far one rendered image is from another (PSNR,
 * SSIM, 99th-percentile and largest pixel error), for checking a preset
 * against a reference or a render against the seed shader's. */
#include <stdio.h>
#include <stdlib.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "image/tl_image_io.h"
#include "metrics/tl_metrics.h"

static const char usage[] =
    "Usage: tideline compare A.png B.png [--min-psnr DB] [--diff FILE.png]\n"
    "\n"
    "Compare two display images of the same size (8- or 16-bit PNG, as\n"
    "tideline writes them) and print, on one line:\n"
    "  PSNR   over R, G, B in dB (peak 1; 200 when identical)\n"
    "  SSIM   mean structural similarity of luma (11-tap Gaussian window)\n"
    "  p99    99% of pixels are at most this many 8-bit levels off\n"
    "  max    the largest error of any channel, 8-bit levels\n"
    "\n"
    "Options:\n"
    "  --min-psnr DB    exit 1 when the PSNR is below DB (for scripts)\n"
    "  --diff FILE.png  write |A - B| x 10 (the differences made visible)\n"
    "  -h, --help       show this help\n"
    "\n"
    "Exit status: 0 compared (and at least --min-psnr), 1 below --min-psnr or\n"
    "an unreadable file or different sizes, 2 usage error.\n";

static int write_diff(const char *path, const tl_frame *a, const tl_frame *b, tl_error *err)
{
    tl_frame d = {0};
    if (tl_frame_alloc(&d, a->width, a->height, err))
        return TL_ERR_RUNTIME;
    size_t n = (size_t)a->width * (size_t)a->height;
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) {
            float v = 10.0f * (a->display[4 * i + c] - b->display[4 * i + c]);
            v = v < 0.0f ? -v : v;
            d.display[4 * i + c] = v > 1.0f ? 1.0f : v;
        }
        d.display[4 * i + 3] = 1.0f;
    }
    int rc = tl_cli_make_parent_dirs(path, err);
    if (!rc)
        rc = tl_png_write(path, &d, NULL, err);
    tl_frame_free(&d);
    return rc;
}

int tl_cli_compare(int argc, char **argv)
{
    tl_error err;
    tl_error_clear(&err);
    tl_args a;
    tl_args_init(&a, argc - 1, argv + 1);
    const char *paths[2] = {NULL, NULL}, *diff = NULL, *positional;
    int count = 0, rc = 0, has_min = 0;
    double min_psnr = 0.0;
    while (!rc && !tl_args_done(&a)) {
        if (tl_args_match(&a, "--help", "-h", false, &err)) {
            fputs(usage, stdout);
            return 0;
        } else if (tl_args_match(&a, "--min-psnr", NULL, true, &err)) {
            rc = tl_args_double(a.flag, a.value, &min_psnr, &err);
            has_min = 1;
        } else if (tl_args_match(&a, "--diff", NULL, true, &err)) {
            diff = a.value;
            if (tl_image_format_from_path(diff) != TL_IMAGE_PNG)
                rc = tl_error_set(&err, TL_ERR_USAGE, "--diff: '%s' is not a .png file", diff);
        } else if (!err.status && tl_args_positional(&a, &positional)) {
            if (count == 2)
                rc = tl_error_set(&err, TL_ERR_USAGE, "a third image '%s' (compare takes two)",
                                  positional);
            else
                paths[count++] = positional;
        } else {
            rc = err.status ? (int)err.status : tl_args_unknown(&a, "compare", &err);
        }
    }
    if (!rc && count < 2)
        rc = tl_error_set(&err, TL_ERR_USAGE, "two images are needed (see --help)");
    if (rc) {
        tl_cli_print_error("compare", &err);
        return 2;
    }

    tl_frame img[2] = {{0}, {0}};
    for (int i = 0; !rc && i < 2; i++)
        rc = tl_png_read(paths[i], &img[i], NULL, &err);
    if (!rc && (img[0].width != img[1].width || img[0].height != img[1].height))
        rc = tl_error_set(&err, TL_ERR_RUNTIME, "%s is %dx%d but %s is %dx%d", paths[0],
                          img[0].width, img[0].height, paths[1], img[1].width, img[1].height);
    tl_metrics m = {0};
    if (!rc && tl_metrics_compare(img[0].display, img[1].display, img[0].width, img[0].height, &m))
        rc = tl_error_set(&err, TL_ERR_RUNTIME, "out of memory");
    if (!rc && diff)
        rc = write_diff(diff, &img[0], &img[1], &err);
    if (!rc)
        printf("PSNR %.2f dB  SSIM %.5f  p99 %.1f levels  max %.1f levels  (%dx%d)\n", m.psnr,
               m.ssim, m.p99, m.max_error, img[0].width, img[0].height);
    tl_frame_free(&img[0]);
    tl_frame_free(&img[1]);
    if (rc) {
        tl_cli_print_error("compare", &err);
        return 1;
    }
    if (has_min && m.psnr < min_psnr) {
        fprintf(stderr, "tideline compare: PSNR %.2f dB is below --min-psnr %.2f\n", m.psnr,
                min_psnr);
        return 1;
    }
    return 0;
}
