#include "tl_cli_writer.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

void tl_writer_init(tl_writer *w, tl_writer_fn write, void *ctx)
{
    memset(w, 0, sizeof *w);
    w->write = write;
    w->ctx = ctx;
    w->number = -1;
}

static void *write_main(void *arg)
{
    tl_writer *w = arg;
    tl_error_clear(&w->err);
    w->rc = w->write(w->ctx, w->number, &w->scene, &w->frame, w->path, &w->err);
    return NULL;
}

int tl_writer_wait(tl_writer *w, long *written, tl_error *err)
{
    if (written)
        *written = -1;
    if (!w->busy)
        return TL_OK;
    pthread_join(w->thread, NULL);
    w->busy = 0;
    if (w->rc) {
        *err = w->err;
        return w->rc;
    }
    if (written)
        *written = w->number;
    memcpy(w->done_path, w->path, sizeof w->path);
    return TL_OK;
}

int tl_writer_submit(tl_writer *w, tl_frame *frame, long number, const tl_scene *scene,
                     const char *path, long *written, tl_error *err)
{
    int rc = tl_writer_wait(w, written, err);
    if (rc)
        return rc;
    tl_frame mine = w->frame;
    w->frame = *frame;
    *frame = mine;
    w->number = number;
    w->scene = *scene;
    snprintf(w->path, sizeof w->path, "%s", path ? path : "");
    /* SIGINT and SIGTERM stay with the main thread, which stops the run;
     * the writer finishes its frame undisturbed (no EINTR mid-write). */
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    int failed = pthread_create(&w->thread, NULL, write_main, w);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (failed)
        return tl_error_set(err, TL_ERR_RUNTIME, "cannot start the writer thread");
    w->busy = 1;
    return TL_OK;
}

const char *tl_writer_path(const tl_writer *w)
{
    return w->done_path;
}

void tl_writer_free(tl_writer *w)
{
    tl_error ignored;
    tl_writer_wait(w, NULL, &ignored);
    tl_frame_free(&w->frame);
}
