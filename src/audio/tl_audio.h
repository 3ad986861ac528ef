/* tl_audio: a timeline's soundtrack, decoded by libsndfile.
 *
 * WAV, FLAC, Ogg Vorbis and the other formats libsndfile reads. The
 * loader (tl_cutscene_load) probes the file so that a missing or
 * undecodable one is an error at the timeline's `audio` line before any
 * frame renders; movies get the file itself (ffmpeg reads it), the
 * preview decodes it whole (tl_audio_read) for playback and the
 * waveform. */
#ifndef TL_AUDIO_H
#define TL_AUDIO_H

#include "core/tl_error.h"

typedef struct tl_audio_info {
    int sample_rate; /* samples a second, per channel */
    int channels;
    long long frames; /* samples per channel */
    double duration;  /* seconds: frames / sample_rate */
    char format[64];  /* libsndfile's name of the container, e.g. "WAV (Microsoft)" */
} tl_audio_info;

/* Opens `path` and reads its header: fails (TL_ERR_RUNTIME) with a
 * message naming the file when it is missing, unreadable, not a sound
 * libsndfile decodes, or empty. */
int tl_audio_probe(const char *path, tl_audio_info *info, tl_error *err);

/* A whole sound as interleaved floats in [-1, 1]. */
typedef struct tl_audio_clip {
    tl_audio_info info;
    float *samples; /* info.frames * info.channels */
} tl_audio_clip;

/* Decodes `path` whole; clips longer than TL_AUDIO_MAX_SECONDS are
 * refused (the preview holds the sound in memory). */
#define TL_AUDIO_MAX_SECONDS (4.0 * 3600.0)
int tl_audio_read(const char *path, tl_audio_clip *clip, tl_error *err);
void tl_audio_free(tl_audio_clip *clip);

/* The loudest sample magnitude over all channels in [t0, t1) seconds of
 * the clip (0 outside it): one column of a waveform. */
float tl_audio_peak(const tl_audio_clip *clip, double t0, double t1);

#endif
