/* Where a frame's time goes: each pass fenced with glFinish on both sides
 * and timed by the clock between the fences, summed per kind of pass
 * (tideline bench --passes). Not timer queries: llvmpipe runs a pass's
 * draws when a later pass reads its target, so its GL_TIME_ELAPSED gives
 * a long pass as near zero even fenced. A GPU idles
 * at each fence, so a frame takes a little longer while timing is on. */
#include "core/tl_clock.h"
#include "gl/tl_renderer_internal.h"

static const char *const pass_names[TL_TIMED_COUNT] = {"boat",  "prepass", "ocean", "giant wave",
                                                       "glare", "display", "filter"};

const char *tl_renderer_pass_name(int pass)
{
    return pass >= 0 && pass < TL_TIMED_COUNT ? pass_names[pass] : "?";
}

void tl_timers_begin_frame(pass_timers *t)
{
    t->open = -1;
    t->valid = 0;
    for (int i = 0; i < TL_TIMED_COUNT; i++)
        t->seconds[i] = 0.0;
}

void tl_timers_start(pass_timers *t, int pass)
{
    if (!t->on)
        return;
    if (t->open >= 0)
        tl_timers_stop(t);
    glFinish(); /* what came before is not this pass's */
    t->open = pass;
    t->started = tl_clock_seconds();
}

void tl_timers_stop(pass_timers *t)
{
    if (!t->on || t->open < 0)
        return;
    glFinish();
    t->seconds[t->open] += tl_clock_seconds() - t->started;
    t->open = -1;
}

void tl_timers_collect(pass_timers *t)
{
    tl_timers_stop(t);
    t->valid = t->on;
}

void tl_renderer_time_passes(tl_renderer *r, int on)
{
    tl_timers_stop(&r->timers);
    r->timers.on = on != 0;
    r->timers.open = -1; /* none until a pass starts (a new renderer's is 0) */
    r->timers.valid = 0;
}

int tl_renderer_pass_seconds(const tl_renderer *r, double out[TL_TIMED_COUNT])
{
    int ok = r->timers.on && r->timers.valid;
    for (int i = 0; i < TL_TIMED_COUNT; i++)
        out[i] = ok ? r->timers.seconds[i] : 0.0;
    return ok;
}
