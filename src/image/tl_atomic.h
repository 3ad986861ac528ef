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
} tl_atomic_file;

/* Creates the temporary file (mode 0644 minus umask) next to `path`. */
int tl_atomic_open(tl_atomic_file *f, const char *path, tl_error *err);
/* Flushes, fsyncs, closes and renames over the target. On failure it
 * removes the temporary and leaves the target alone. */
int tl_atomic_commit(tl_atomic_file *f, tl_error *err);
/* Closes and removes the temporary (safe to call twice, or after commit). */
void tl_atomic_abort(tl_atomic_file *f);

#endif
