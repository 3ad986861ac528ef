/* tl_cli_writer: writes a rendered frame's files on a second thread while
 * the next frame renders (render's pipeline). One frame is in flight at a
 * time: submitting the next waits for the one before, so frames are
 * written in order and an error stops the run one frame later at most.
 * The writer never touches GL; it owns the frame buffer it writes, which
 * submit swaps with the caller's. */
#ifndef TL_CLI_WRITER_H
#define TL_CLI_WRITER_H

#include <pthread.h>

#include "core/tl_error.h"
#include "image/tl_frame.h"
#include "scene/tl_scene.h"

/* Writes one frame (files, movie); runs on the writer thread. */
typedef int (*tl_writer_fn)(void *ctx, long frame, const tl_scene *scene, const tl_frame *f,
                            const char *path, tl_error *err);

typedef struct tl_writer {
    tl_writer_fn write;
    void *ctx;
    pthread_t thread;
    int busy;       /* a frame is in flight */
    tl_frame frame; /* the frame being written (the writer's buffer) */
    long number;
    tl_scene scene;
    char path[4096];
    char done_path[4096]; /* the path of the frame last waited for */
    int rc;               /* its result, and */
    tl_error err;
} tl_writer;

void tl_writer_init(tl_writer *w, tl_writer_fn write, void *ctx);
/* Waits for the frame in flight; *written (may be NULL) gets its number,
 * or -1 when none was in flight. Returns its status (err filled). */
int tl_writer_wait(tl_writer *w, long *written, tl_error *err);
/* Waits for the frame in flight (as tl_writer_wait), then swaps *frame
 * with the writer's buffer and starts writing frame `number`. On an error
 * of the earlier frame nothing new is started. The writer's thread starts
 * with SIGINT and SIGTERM blocked: the main thread handles them. */
int tl_writer_submit(tl_writer *w, tl_frame *frame, long number, const tl_scene *scene,
                     const char *path, long *written, tl_error *err);
/* The path of the frame last waited for. */
const char *tl_writer_path(const tl_writer *w);
/* Waits for any frame in flight and frees the writer's buffer. */
void tl_writer_free(tl_writer *w);

#endif
