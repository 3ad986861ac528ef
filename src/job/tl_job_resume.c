/* Resuming a run: which frames are already complete, and the temporaries
 * an interrupted run left. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "image/tl_atomic.h"
#include "image/tl_image_io.h"
#include "job/tl_job.h"

int tl_job_frame_complete(const char *path, int width, int height, const char *passes,
                          const char *space)
{
    if (access(path, R_OK) != 0)
        return 0;
    tl_frame f = {0};
    tl_error err;
    int rc = tl_image_format_from_path(path) == TL_IMAGE_EXR ? tl_exr_read(path, &f, &err)
                                                             : tl_png_read(path, &f, NULL, &err);
    int ok = rc == TL_OK && f.width == width && f.height == height;
    tl_frame_free(&f);
    if (ok && tl_image_format_from_path(path) == TL_IMAGE_EXR) {
        /* Room for far more than every pass's name (a longer attribute
         * is an error, read as no passes). */
        char got[4096];
        int layered = tl_exr_read_attr_string(path, "tideline/passes", got, sizeof got, &err) == 0;
        ok = passes && passes[0] ? layered && strcmp(got, passes) == 0 : !layered;
        char in[64];
        if (tl_exr_read_attr_string(path, "tideline/working_space", in, sizeof in, &err))
            snprintf(in, sizeof in, "rec709");
        ok = ok && strcmp(in, space ? space : "rec709") == 0;
    }
    return ok;
}

/* The frames of this run, for recognising their stale temporaries. */
typedef struct owned_frames {
    const char *pattern;
    const tl_frame_list *frames;
} owned_frames;

static int owns_frame(const char *target, void *ctx)
{
    const owned_frames *o = ctx;
    char path[4096];
    tl_error ignored;
    for (size_t i = 0; i < o->frames->count; i++) {
        if (tl_pattern_format(o->pattern, o->frames->frames[i], o->frames->count == 1, path,
                              sizeof path, &ignored))
            continue;
        const char *slash = strrchr(path, '/');
        if (strcmp(slash ? slash + 1 : path, target) == 0)
            return 1;
    }
    return 0;
}

int tl_job_remove_stale_temporaries(const char *pattern, const tl_frame_list *frames,
                                    const char *first_path)
{
    char dir[4096];
    const char *slash = strrchr(first_path, '/');
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else
        snprintf(dir, sizeof dir, "%.*s", slash == first_path ? 1 : (int)(slash - first_path),
                 first_path);
    owned_frames owned = {pattern, frames};
    return tl_atomic_remove_stale(dir, owns_frame, &owned);
}
