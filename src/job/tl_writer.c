#include "job/tl_writer.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

void tl_writer_init(tl_writer *w, tl_writer_fn write, tl_writer_fn ordered, void *ctx, int count)
{
    memset(w, 0, sizeof *w);
    w->write = write;
    w->ordered = ordered;
    w->ctx = ctx;
    w->count = count < 1 ? 1 : count > TL_WRITER_MAX ? TL_WRITER_MAX : count;
    pthread_mutex_init(&w->lock, NULL);
    pthread_cond_init(&w->turn_changed, NULL);
    for (int i = 0; i < TL_WRITER_MAX; i++) {
        w->slots[i].number = -1;
        w->slots[i].owner = w;
    }
}

int tl_writer_default_count(void)
{
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    long n = cpus / 2;
    return n < 1 ? 1 : n > TL_WRITER_MAX ? TL_WRITER_MAX : (int)n;
}

static void *write_main(void *arg)
{
    tl_writer_slot *s = arg;
    tl_writer *w = s->owner;
    tl_error_clear(&s->err);
    s->rc = w->write ? w->write(w->ctx, s->number, &s->scene, &s->frame, s->path, &s->err) : 0;
    if (!w->ordered)
        return NULL;
    /* The ordered step waits for every earlier frame's, and always passes
     * the turn on, even after a failure, so no later writer waits forever. */
    pthread_mutex_lock(&w->lock);
    while (w->turn != s->sequence)
        pthread_cond_wait(&w->turn_changed, &w->lock);
    pthread_mutex_unlock(&w->lock);
    if (!s->rc)
        s->rc = w->ordered(w->ctx, s->number, &s->scene, &s->frame, s->path, &s->err);
    pthread_mutex_lock(&w->lock);
    w->turn++;
    pthread_cond_broadcast(&w->turn_changed);
    pthread_mutex_unlock(&w->lock);
    return NULL;
}

int tl_writer_wait(tl_writer *w, long *written, tl_error *err)
{
    if (written)
        *written = -1;
    tl_writer_slot *oldest = NULL;
    for (int i = 0; i < w->count; i++)
        if (w->slots[i].busy && (!oldest || w->slots[i].sequence < oldest->sequence))
            oldest = &w->slots[i];
    if (!oldest)
        return TL_OK;
    pthread_join(oldest->thread, NULL);
    oldest->busy = 0;
    if (oldest->rc) {
        *err = oldest->err;
        return oldest->rc;
    }
    if (written)
        *written = oldest->number;
    memcpy(w->done_path, oldest->path, sizeof oldest->path);
    return TL_OK;
}

int tl_writer_submit(tl_writer *w, tl_frame *frame, long number, const tl_scene *scene,
                     const char *path, long *written, tl_error *err)
{
    if (written)
        *written = -1;
    /* Slots are taken in turn, so when the next one is busy every one is,
     * and it holds the oldest frame. */
    tl_writer_slot *s = &w->slots[w->next];
    if (s->busy) {
        int rc = tl_writer_wait(w, written, err);
        if (rc)
            return rc;
    }
    tl_frame mine = s->frame;
    s->frame = *frame;
    *frame = mine;
    s->number = number;
    s->sequence = w->submitted;
    s->scene = *scene;
    snprintf(s->path, sizeof s->path, "%s", path ? path : "");
    /* SIGINT and SIGTERM stay with the main thread, which stops the run;
     * the writers finish their frames undisturbed (no EINTR mid-write). */
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    int failed = pthread_create(&s->thread, NULL, write_main, s);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (failed) {
        /* Give the frame back; its sequence number is not used. */
        *frame = s->frame;
        s->frame = mine;
        return tl_error_set(err, TL_ERR_RUNTIME, "cannot start a writer thread");
    }
    s->busy = 1;
    w->submitted++;
    w->next = (w->next + 1) % w->count;
    return TL_OK;
}

const char *tl_writer_path(const tl_writer *w)
{
    return w->done_path;
}

void tl_writer_free(tl_writer *w)
{
    tl_error ignored;
    for (int i = 0; i < w->count; i++)
        tl_writer_wait(w, NULL, &ignored);
    for (int i = 0; i < TL_WRITER_MAX; i++)
        tl_frame_free(&w->slots[i].frame);
    pthread_mutex_destroy(&w->lock);
    pthread_cond_destroy(&w->turn_changed);
}
