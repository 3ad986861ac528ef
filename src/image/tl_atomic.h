/* tl_atomic: write-to-temporary-then-rename, so that a reader (or a render
 * resumed with --skip-existing) never sees a partial file and a good file is
 * only ever replaced by a complete new one. */
#ifndef TL_ATOMIC_H
#define TL_ATOMIC_H

#include <stdio.h>

#include "core/tl_error.h"

typedef struct tl_atomic_file {
    char path[4096];     /* the final name */
    char tmp_path[4096]; /* hidden temporary in the same folder */
    int fd;              /* -1 when closed */
    FILE *fp;            /* stdio view of fd, or NULL */
    int lock_fd;         /* holds the temporary's flock until it is renamed or removed */
} tl_atomic_file;

/* Creates the temporary file (mode 0644 minus umask) next to `path`, named
 * `.NAME.tmp-XXXXXX`, and holds an exclusive flock on it until it is renamed
 * or removed: a temporary nobody holds was left by a killed writer. */
int tl_atomic_open(tl_atomic_file *f, const char *path, tl_error *err);
/* Flushes, fsyncs, closes and renames over the target. On failure it
 * removes the temporary and leaves the target alone. */
int tl_atomic_commit(tl_atomic_file *f, tl_error *err);
/* Closes and removes the temporary (safe to call twice, or after commit). */
void tl_atomic_abort(tl_atomic_file *f);

/* Whether `target` (a file name without folder) is one a stale temporary may
 * be removed for. */
typedef int (*tl_atomic_owns_fn)(const char *target, void *ctx);
/* Removes the temporaries in folder `dir` that no live writer holds (left by
 * a process killed mid-write, e.g. SIGKILL) and whose target `owns` accepts.
 * Returns how many were removed. */
int tl_atomic_remove_stale(const char *dir, tl_atomic_owns_fn owns, void *ctx);

#endif
