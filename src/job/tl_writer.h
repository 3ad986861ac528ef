/* tl_writer: writes rendered frames' files on writer threads while the
 * next frame renders (render's pipeline). Up to `count` frames are in
 * flight, each on its own thread: on a GPU the encoding of one frame (PNG,
 * EXR) takes longer than rendering it, so several encode side by side.
 * Submitting a frame when all writers are busy waits for the oldest, so
 * frames are reported in order and an error stops the run `count` frames
 * later at most. The ordered step (the movie) runs for one frame at a time
 * in submission order, whatever order the writers finish in. Writers never
 * touch GL; each owns the frame buffer it writes, which submit swaps with
 * the caller's. */
#ifndef TL_WRITER_H
#define TL_WRITER_H

#include <pthread.h>

#include "core/tl_error.h"
#include "image/tl_frame.h"
#include "scene/tl_scene.h"

/* Most writer threads (each holds one frame's buffers). */
#define TL_WRITER_MAX 8

/* Writes one frame (its files, or its movie frame); runs on a writer
 * thread. */
typedef int (*tl_writer_fn)(void *ctx, long frame, const tl_scene *scene, const tl_frame *f,
                            const char *path, tl_error *err);

typedef struct tl_writer_slot {
    pthread_t thread;
    int busy;       /* a frame is in flight */
    long sequence;  /* submission order, for the ordered step */
    tl_frame frame; /* the frame being written (the writer's buffer) */
    long number;
    tl_scene scene;
    char path[4096];
    int rc; /* its result, and */
    tl_error err;
    struct tl_writer *owner;
} tl_writer_slot;

typedef struct tl_writer {
    tl_writer_fn write;   /* in parallel */
    tl_writer_fn ordered; /* one at a time in submission order; may be NULL */
    void *ctx;
    int count; /* writer threads, 1..TL_WRITER_MAX */
    int next;  /* the slot the next frame goes to */
    long submitted;
    long turn; /* the sequence number whose ordered step may run */
    pthread_mutex_t lock;
    pthread_cond_t turn_changed;
    tl_writer_slot slots[TL_WRITER_MAX];
    char done_path[4096]; /* the path of the frame last waited for */
} tl_writer;

/* count: writer threads, clamped to 1..TL_WRITER_MAX. */
void tl_writer_init(tl_writer *w, tl_writer_fn write, tl_writer_fn ordered, void *ctx, int count);
/* Writers to use by default on this machine: half the processors (the
 * renderer and, on llvmpipe, the GPU work use the rest), 1 to
 * TL_WRITER_MAX. On a 16-core GPU machine 1920x1080 EXRs came out at 768
 * ms a frame with one writer, 215 with four, 94 with eight. */
int tl_writer_default_count(void);
/* Waits for the oldest frame in flight; *written (may be NULL) gets its
 * number, or -1 when none was in flight. Returns its status (err filled). */
int tl_writer_wait(tl_writer *w, long *written, tl_error *err);
/* When every writer is busy, waits for the oldest (as tl_writer_wait);
 * then swaps *frame with a free writer's buffer and starts writing frame
 * `number`. On an error of the frame waited for nothing new is started.
 * Writer threads start with SIGINT and SIGTERM blocked: the main thread
 * handles them. */
int tl_writer_submit(tl_writer *w, tl_frame *frame, long number, const tl_scene *scene,
                     const char *path, long *written, tl_error *err);
/* The path of the frame last waited for. */
const char *tl_writer_path(const tl_writer *w);
/* Waits for every frame in flight and frees the writers' buffers. */
void tl_writer_free(tl_writer *w);

#endif
