#include "tl_atomic.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#define TMP_TAIL ".tmp-XXXXXX"

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

/* Drops the lock (after the temporary is renamed or removed). */
static void unlock(tl_atomic_file *f)
{
    if (f->lock_fd >= 0)
        (void)close(f->lock_fd);
    f->lock_fd = -1;
}

/* mkstemp, then the lock. A cleaner may have locked and removed the new file
 * between the two (it looked stale): then it is unlinked and we try again. */
static int create_locked(char *tmp_path, size_t size, int *lock_fd)
{
    char pattern[4096];
    snprintf(pattern, sizeof pattern, "%s", tmp_path);
    for (int attempt = 0; attempt < 8; attempt++) {
        snprintf(tmp_path, size, "%s", pattern);
        int fd = mkstemp(tmp_path);
        if (fd < 0)
            return -1;
        struct stat st;
        if (flock(fd, LOCK_EX) != 0 || fstat(fd, &st) != 0) {
            int e = errno;
            (void)close(fd);
            (void)unlink(tmp_path);
            errno = e;
            return -1;
        }
        if (st.st_nlink == 0) {
            (void)close(fd);
            continue;
        }
        /* A second descriptor on the same open file keeps the lock after
         * the stream is closed, until the rename. */
        *lock_fd = fcntl(fd, F_DUPFD_CLOEXEC, 0);
        if (*lock_fd < 0) {
            int e = errno;
            (void)close(fd);
            (void)unlink(tmp_path);
            errno = e;
            return -1;
        }
        return fd;
    }
    errno = EAGAIN;
    return -1;
}

int tl_atomic_open(tl_atomic_file *f, const char *path, tl_error *err)
{
    f->path[0] = '\0';
    f->tmp_path[0] = '\0';
    f->fd = -1;
    f->fp = NULL;
    f->lock_fd = -1;

    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    int dir_len = slash ? (int)(slash - path + 1) : 0;
    if (*base == '\0')
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: not a file name", path);
    int n = snprintf(f->tmp_path, sizeof f->tmp_path, "%.*s.%s" TMP_TAIL, dir_len, path, base);
    if (strlen(path) >= sizeof f->path || n < 0 || (size_t)n >= sizeof f->tmp_path) {
        f->tmp_path[0] = '\0';
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: path too long", path);
    }
    memcpy(f->path, path, strlen(path) + 1);

    /* Same folder as the target, so that the final rename cannot cross
     * file systems and is atomic. */
    int fd = create_locked(f->tmp_path, sizeof f->tmp_path, &f->lock_fd);
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
    unlock(f);
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
    unlock(f);
}

/* The target name of a temporary ".NAME.tmp-XXXXXX", or 0 if `entry` is not
 * one. */
static int temp_target(const char *entry, char *target, size_t size)
{
    size_t n = strlen(entry), tail = strlen(TMP_TAIL);
    if (entry[0] != '.' || n < tail + 2 || strncmp(entry + n - tail, ".tmp-", 5) != 0)
        return 0;
    size_t len = n - tail - 1;
    if (len >= size)
        return 0;
    memcpy(target, entry + 1, len);
    target[len] = '\0';
    return 1;
}

int tl_atomic_remove_stale(const char *dir, tl_atomic_owns_fn owns, void *ctx)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int removed = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        char target[256], path[4096 + 256];
        if (!temp_target(e->d_name, target, sizeof target) || !owns(target, ctx))
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        int fd = open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0)
            continue;
        /* Locked: a live writer. Unlocked: its writer is gone. The name must
         * still be the file we locked (a writer may have renamed it). */
        struct stat held, named;
        if (flock(fd, LOCK_EX | LOCK_NB) == 0 && fstat(fd, &held) == 0 &&
            lstat(path, &named) == 0 && S_ISREG(named.st_mode) && held.st_ino == named.st_ino &&
            held.st_dev == named.st_dev && unlink(path) == 0)
            removed++;
        (void)close(fd);
    }
    closedir(d);
    return removed;
}
