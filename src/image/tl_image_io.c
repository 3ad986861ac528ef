#include "tl_image_io.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tl_atomic.h"

#define TL_SUPPORTED_EXTENSIONS ".exr, .png"

tl_image_format tl_image_format_from_path(const char *path)
{
    if (!path)
        return TL_IMAGE_UNKNOWN;
    /* The extension of the last path component only ("a.exr/b" has none). */
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    if (!dot)
        return TL_IMAGE_UNKNOWN;
    if (strcasecmp(dot, ".exr") == 0)
        return TL_IMAGE_EXR;
    if (strcasecmp(dot, ".png") == 0)
        return TL_IMAGE_PNG;
    return TL_IMAGE_UNKNOWN;
}

static int unknown_format(const char *path, tl_error *err)
{
    return tl_error_set(
        err, TL_ERR_USAGE,
        "%s: unknown image format (supported extensions: " TL_SUPPORTED_EXTENSIONS ")", path);
}

/* The folder part of path: "." for a bare name, "/" for a file in the root. */
static void folder_of(const char *path, char *dir, size_t size)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, size, ".");
    else if (slash == path)
        snprintf(dir, size, "/");
    else
        snprintf(dir, size, "%.*s", (int)(slash - path), path);
}

/* Errors here are the user's output path, hence TL_ERR_USAGE. */
int tl_image_check_writable(const char *path, tl_error *err)
{
    if (!path || !path[0])
        return tl_error_set(err, TL_ERR_USAGE, "empty output path");
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return tl_error_set(err, TL_ERR_USAGE, "%s: is a folder, not an image file name", path);
    if (tl_image_format_from_path(path) == TL_IMAGE_UNKNOWN)
        return unknown_format(path, err);

    char dir[4096];
    folder_of(path, dir, sizeof dir);
    if (stat(dir, &st) != 0) {
        if (errno == ENOENT)
            return tl_error_set(err, TL_ERR_USAGE, "%s: folder '%s' does not exist", path, dir);
        return tl_error_set(err, TL_ERR_USAGE, "%s: cannot use folder '%s': %s", path, dir,
                            strerror(errno));
    }
    if (!S_ISDIR(st.st_mode))
        return tl_error_set(err, TL_ERR_USAGE, "%s: '%s' is not a folder", path, dir);
    /* Creating the temporary file and renaming it need write and search
     * permission on the folder; the target's own mode does not matter. */
    if (access(dir, W_OK | X_OK) != 0)
        return tl_error_set(err, TL_ERR_USAGE, "%s: folder '%s' is not writable: %s", path, dir,
                            strerror(errno));
    /* access() says yes to root everywhere and knows nothing of /proc-like
     * folders: create (and remove) the temporary a write would. */
    tl_atomic_file probe;
    tl_error why;
    if (tl_atomic_open(&probe, path, &why) != 0) {
        const char *reason = strrchr(why.message, ':'); /* "...: strerror" */
        return tl_error_set(err, TL_ERR_USAGE, "%s: folder '%s' is not writable: %s", path, dir,
                            reason ? reason + 2 : why.message);
    }
    tl_atomic_abort(&probe);
    return TL_OK;
}

int tl_meta_values(tl_meta_type type)
{
    switch (type) {
    case TL_META_M44F: return 16;
    case TL_META_V3D: return 3;
    case TL_META_CHROMATICITIES: return 8;
    case TL_META_RATIONAL: return 2;
    default: return 0;
    }
}

int tl_image_check_meta(const char *path, const tl_image_options *opt, tl_error *err)
{
    int n = opt && opt->meta ? opt->meta_count : 0;
    for (int i = 0; i < n; i++) {
        const tl_meta *m = &opt->meta[i];
        /* 255 bytes is the longest attribute name an EXR can hold. */
        if (!m->name || !m->name[0] || strlen(m->name) > 255)
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: metadata entry %d has no valid name",
                                path, i);
        if ((int)m->type < TL_META_STRING || m->type > TL_META_RATIONAL)
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: metadata '%s' has an unknown type", path,
                                m->name);
        if (tl_meta_values(m->type) && !m->v)
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: metadata '%s' has no values", path,
                                m->name);
        if (m->type == TL_META_STRING && !m->s)
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: metadata '%s' has no string value", path,
                                m->name);
    }
    return TL_OK;
}

int tl_image_write(const char *path, const tl_frame *frame, const tl_image_options *opt,
                   tl_error *err)
{
    switch (tl_image_format_from_path(path)) {
    case TL_IMAGE_EXR: return tl_exr_write(path, frame, opt, err);
    case TL_IMAGE_PNG: return tl_png_write(path, frame, opt, err);
    case TL_IMAGE_UNKNOWN: break;
    }
    return unknown_format(path, err);
}
