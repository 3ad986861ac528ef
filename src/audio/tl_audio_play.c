#include "audio/tl_audio_play.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <SDL2/SDL.h>

struct tl_audio_player {
    SDL_AudioDeviceID device;
    int rate, channels;
    /* Shared with the device's thread, under SDL_LockAudioDevice. */
    const tl_audio_clip *clip;
    double position; /* sample frames into the clip; may lie outside it */
    int playing;
};

/* The device's thread: the clip from `position` on, silence outside it or
 * while not playing. */
static void pull(void *ctx, Uint8 *stream, int bytes)
{
    tl_audio_player *p = ctx;
    float *out = (float *)stream;
    const int frames = bytes / (int)(sizeof(float) * (size_t)p->channels);
    memset(stream, 0, (size_t)bytes);
    if (!p->playing || !p->clip || !p->clip->samples)
        return;
    const long long first = (long long)floor(p->position), n = p->clip->info.frames;
    for (int i = 0; i < frames; i++) {
        long long at = first + i;
        if (at >= 0 && at < n)
            memcpy(out + (size_t)i * p->channels, p->clip->samples + at * p->channels,
                   sizeof(float) * (size_t)p->channels);
    }
    p->position += frames;
}

static int open_device(tl_audio_player *p, const tl_audio_clip *clip, tl_error *err)
{
    SDL_AudioSpec want = {0}, got;
    want.freq = clip->info.sample_rate;
    want.format = AUDIO_F32SYS;
    want.channels = (Uint8)clip->info.channels;
    want.samples = 1024; /* about 20 ms a pull at 48 kHz: a scrub is heard at once */
    want.callback = pull;
    want.userdata = p;
    p->device = SDL_OpenAudioDevice(NULL, 0, &want, &got, 0);
    if (!p->device)
        return tl_error_set(err, TL_ERR_RUNTIME, "no audio device (%s)", SDL_GetError());
    p->rate = clip->info.sample_rate;
    p->channels = clip->info.channels;
    SDL_PauseAudioDevice(p->device, 0);
    return TL_OK;
}

int tl_audio_player_open(tl_audio_player **out, const tl_audio_clip *clip, tl_error *err)
{
    *out = NULL;
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "no audio device (%s)", SDL_GetError());
    tl_audio_player *p = calloc(1, sizeof *p);
    if (!p) {
        SDL_Quit();
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    p->clip = clip;
    int rc = open_device(p, clip, err);
    if (rc) {
        free(p);
        SDL_Quit();
        return rc;
    }
    *out = p;
    return TL_OK;
}

int tl_audio_player_use(tl_audio_player *p, const tl_audio_clip *clip, tl_error *err)
{
    if (clip && (clip->info.sample_rate != p->rate || clip->info.channels != p->channels)) {
        SDL_CloseAudioDevice(p->device);
        p->clip = clip;
        p->playing = 0;
        return open_device(p, clip, err);
    }
    SDL_LockAudioDevice(p->device);
    p->clip = clip;
    SDL_UnlockAudioDevice(p->device);
    return TL_OK;
}

void tl_audio_player_follow(tl_audio_player *p, double at, int playing)
{
    SDL_LockAudioDevice(p->device);
    double want = at * p->rate;
    if (!playing || !p->playing || fabs(p->position - want) > TL_AUDIO_SYNC * p->rate)
        p->position = want;
    p->playing = playing;
    SDL_UnlockAudioDevice(p->device);
}

void tl_audio_player_close(tl_audio_player *p)
{
    if (!p)
        return;
    SDL_CloseAudioDevice(p->device);
    free(p);
    SDL_Quit();
}
