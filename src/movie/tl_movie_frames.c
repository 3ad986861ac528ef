#include "movie/tl_movie_frames.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "image/tl_frame.h"
#include "image/tl_image_io.h"
#include "job/tl_job.h"

static int frame_path(const tl_movie_frames *job, size_t i, char *out, size_t size, tl_error *err)
{
    return tl_pattern_format(job->pattern, job->frames[i], job->count == 1, out, size, err);
}

/* Every frame is there before ffmpeg starts: a farm that has not finished
 * is told which frame is missing, not handed half a movie. */
static int check_frames(const tl_movie_frames *job, tl_error *err)
{
    char path[4096], first_missing[4096] = "";
    size_t missing = 0;
    for (size_t i = 0; i < job->count; i++) {
        int rc = frame_path(job, i, path, sizeof path, err);
        if (rc)
            return rc;
        struct stat st;
        if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
            continue;
        if (!missing++)
            snprintf(first_missing, sizeof first_missing, "%s", path);
    }
    if (missing)
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "frame file '%s' is missing%s%zu more of the %zu frames are); no "
                            "movie written",
                            first_missing, missing > 1 ? " (and " : " (", missing - 1, job->count);
    return TL_OK;
}

int tl_movie_from_frames(const tl_movie_frames *job, tl_error *err)
{
    if (!job->count)
        return tl_error_set(err, TL_ERR_USAGE, "no frames to make a movie of");
    char path[4096];
    int rc = frame_path(job, 0, path, sizeof path, err);
    if (rc)
        return rc;
    if (tl_image_format_from_path(path) != TL_IMAGE_PNG)
        return tl_error_set(err, TL_ERR_USAGE,
                            "'%s': a movie is made from PNG frames (EXR frames hold "
                            "scene-linear light, not the display image): render -o with a "
                            ".png pattern as well",
                            job->pattern);
    if ((rc = check_frames(job, err)) != 0)
        return rc;

    tl_frame frame;
    if ((rc = tl_png_read(path, &frame, NULL, err)) != 0)
        return rc;
    const int width = frame.width, height = frame.height;
    uint8_t *rgb = malloc((size_t)width * (size_t)height * 3);
    tl_movie *movie = NULL;
    if (!rgb)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    if (!rc)
        rc = tl_movie_open(&movie, job->movie, width, height, job->fps, job->sound, err);
    for (size_t i = 0; !rc && i < job->count; i++) {
        if (job->stop && *job->stop) {
            rc = tl_error_set(err, TL_ERR_RUNTIME, "interrupted after %zu of %zu frames", i,
                              job->count);
            break;
        }
        if (i > 0) {
            tl_frame_free(&frame);
            rc = frame_path(job, i, path, sizeof path, err);
            if (!rc)
                rc = tl_png_read(path, &frame, NULL, err);
            if (!rc && (frame.width != width || frame.height != height))
                rc = tl_error_set(err, TL_ERR_RUNTIME,
                                  "frame file '%s' is %dx%d; the first frame is %dx%d", path,
                                  frame.width, frame.height, width, height);
            if (rc)
                break;
        }
        for (int y = 0; y < height; y++)
            tl_frame_display_row8(&frame, y, job->dither, rgb + (size_t)y * (size_t)width * 3);
        rc = tl_movie_write(movie, rgb, err);
        if (!rc && job->progress)
            job->progress(job->progress_ctx, i + 1, job->count);
    }
    tl_frame_free(&frame);
    free(rgb);
    if (movie) {
        if (!rc)
            rc = tl_movie_finish(movie, err);
        else
            tl_movie_abort(movie);
    }
    return rc;
}
