#include "tl_atomic.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The process umask. umask() can only be read by setting it, which would race
 * with other threads creating files, so read it from /proc where possible. */
static mode_t current_umask(void)
{
    FILE *fp = fopen("/proc/self/status", "r");
    if (fp) {
        char line[256];
        unsigned int mask;
        while (fgets(line, sizeof line, fp)) {
            if (sscanf(line, "Umask: %o", &mask) == 1) {
                fclose(fp);
                return (mode_t)mask;
            }
        }
        fclose(fp);
    }
    mode_t mask = umask(022);
    umask(mask);
    return mask;
}

/* Records errno before cleaning up (cleanup may change it), removes the
 * temporary and reports `what` for the final path. */
static int fail(tl_atomic_file *f, tl_error *err, const char *what)
{
    int e = errno;
    tl_atomic_abort(f);
    return tl_error_set(err, TL_ERR_RUNTIME, "%s: %s: %s", f->path, what, strerror(e));
}

/* fsync the folder so that the rename itself survives a crash. The new file
 * is complete and in place by now, so a failure here only weakens durability
 * and is deliberately not reported. */
static void sync_folder(const char *path)
{
    char dir[4096];
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else if (slash == path)
        snprintf(dir, sizeof dir, "/");
    else
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return;
    (void)fsync(fd);
    close(fd);
}

int tl_atomic_open(tl_atomic_file *f, const char *path, tl_error *err)
{
    f->path[0] = '\0';
    f->tmp_path[0] = '\0';
    f->fd = -1;
    f->fp = NULL;

    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    int dir_len = slash ? (int)(slash - path + 1) : 0;
    if (*base == '\0')
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: not a file name", path);
    int n = snprintf(f->tmp_path, sizeof f->tmp_path, "%.*s.%s.tmp-XXXXXX", dir_len, path, base);
    if (strlen(path) >= sizeof f->path || n < 0 || (size_t)n >= sizeof f->tmp_path) {
        f->tmp_path[0] = '\0';
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: path too long", path);
    }
    memcpy(f->path, path, strlen(path) + 1);

    /* Same folder as the target, so that the final rename cannot cross
     * file systems and is atomic. */
    int fd = mkstemp(f->tmp_path);
    if (fd < 0) {
        int e = errno;
        f->tmp_path[0] = '\0';
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "%s: cannot create a temporary file in its folder: %s", path,
                            strerror(e));
    }
    f->fd = fd;
    /* Keep the descriptor out of any child process the renderer starts. */
    if (fcntl(fd, F_SETFD, FD_CLOEXEC) != 0)
        return fail(f, err, "cannot set close-on-exec on the temporary file");
    /* mkstemp creates mode 0600; give the file the mode a plain open() would. */
    if (fchmod(fd, 0644 & ~current_umask()) != 0)
        return fail(f, err, "cannot set the temporary file's mode");
    f->fp = fdopen(fd, "wb");
    if (!f->fp)
        return fail(f, err, "cannot open a stream on the temporary file");
    return TL_OK;
}

int tl_atomic_commit(tl_atomic_file *f, tl_error *err)
{
    if (f->fd < 0 || f->tmp_path[0] == '\0')
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no temporary file to commit", f->path);
    /* A full disk shows up at any of these steps, not only at write(). */
    if (f->fp && fflush(f->fp) != 0)
        return fail(f, err, "cannot write");
    if (fsync(f->fd) != 0)
        return fail(f, err, "cannot write (fsync)");
    int rc = f->fp ? fclose(f->fp) : close(f->fd);
    /* The descriptor is gone even when closing fails; never close it twice. */
    f->fp = NULL;
    f->fd = -1;
    if (rc != 0)
        return fail(f, err, "cannot write (close)");
    if (rename(f->tmp_path, f->path) != 0)
        return fail(f, err, "cannot rename the temporary file over it");
    f->tmp_path[0] = '\0';
    sync_folder(f->path);
    return TL_OK;
}

void tl_atomic_abort(tl_atomic_file *f)
{
    /* The contents are being discarded, so errors from closing do not matter. */
    if (f->fp)
        (void)fclose(f->fp);
    else if (f->fd >= 0)
        (void)close(f->fd);
    f->fp = NULL;
    f->fd = -1;
    if (f->tmp_path[0] != '\0') {
        (void)unlink(f->tmp_path);
        f->tmp_path[0] = '\0';
    }
}
