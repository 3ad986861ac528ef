#include "audio/tl_audio.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sys/stat.h>

#include <sndfile.h>

static int open_sound(const char *path, SNDFILE **out, SF_INFO *sf, tl_error *err)
{
    memset(sf, 0, sizeof *sf);
    /* A folder, a pipe or a device is refused before it is opened (a pipe
     * would wait for a writer). */
    struct stat st;
    if (stat(path, &st) != 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "sound file '%s': %s", path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return tl_error_set(err, TL_ERR_RUNTIME, "sound file '%s' is not a regular file", path);
    FILE *probe = fopen(path, "rb");
    if (!probe)
        return tl_error_set(err, TL_ERR_RUNTIME, "sound file '%s': %s", path, strerror(errno));
    fclose(probe);
    *out = sf_open(path, SFM_READ, sf);
    if (!*out)
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "sound file '%s' cannot be decoded: %s (WAV, FLAC, Ogg Vorbis, MP3 "
                            "and the other formats libsndfile reads are)",
                            path, sf_strerror(NULL));
    if (sf->frames <= 0 || sf->samplerate <= 0 || sf->channels <= 0) {
        sf_close(*out);
        *out = NULL;
        return tl_error_set(err, TL_ERR_RUNTIME, "sound file '%s' holds no samples", path);
    }
    return TL_OK;
}

static void fill_info(const SF_INFO *sf, tl_audio_info *info)
{
    memset(info, 0, sizeof *info);
    info->sample_rate = sf->samplerate;
    info->channels = sf->channels;
    info->frames = (long long)sf->frames;
    info->duration = (double)sf->frames / (double)sf->samplerate;
    SF_FORMAT_INFO fi = {.format = sf->format & SF_FORMAT_TYPEMASK};
    if (sf_command(NULL, SFC_GET_FORMAT_INFO, &fi, sizeof fi) == 0 && fi.name)
        snprintf(info->format, sizeof info->format, "%s", fi.name);
}

int tl_audio_probe(const char *path, tl_audio_info *info, tl_error *err)
{
    SNDFILE *f;
    SF_INFO sf;
    int rc = open_sound(path, &f, &sf, err);
    if (rc)
        return rc;
    fill_info(&sf, info);
    sf_close(f);
    return TL_OK;
}

int tl_audio_read(const char *path, tl_audio_clip *clip, tl_error *err)
{
    memset(clip, 0, sizeof *clip);
    SNDFILE *f;
    SF_INFO sf;
    int rc = open_sound(path, &f, &sf, err);
    if (rc)
        return rc;
    fill_info(&sf, &clip->info);
    if (clip->info.duration > TL_AUDIO_MAX_SECONDS) {
        sf_close(f);
        return tl_error_set(err, TL_ERR_RUNTIME, "sound file '%s' is %.0f s long; at most %.0f s",
                            path, clip->info.duration, TL_AUDIO_MAX_SECONDS);
    }
    size_t n = (size_t)sf.frames * (size_t)sf.channels;
    clip->samples = malloc(n * sizeof *clip->samples);
    if (!clip->samples) {
        sf_close(f);
        return tl_error_set(err, TL_ERR_RUNTIME, "sound file '%s': out of memory", path);
    }
    sf_count_t got = sf_readf_float(f, clip->samples, sf.frames);
    sf_close(f);
    if (got <= 0) {
        tl_audio_free(clip);
        return tl_error_set(err, TL_ERR_RUNTIME, "sound file '%s': no samples could be decoded",
                            path);
    }
    /* A file cut short decodes fewer frames than its header says. */
    clip->info.frames = (long long)got;
    clip->info.duration = (double)got / (double)sf.samplerate;
    return TL_OK;
}

void tl_audio_free(tl_audio_clip *clip)
{
    free(clip->samples);
    memset(clip, 0, sizeof *clip);
}

float tl_audio_peak(const tl_audio_clip *clip, double t0, double t1)
{
    if (!clip->samples || !(t1 > t0))
        return 0.0f;
    double rate = clip->info.sample_rate;
    double a = fmax(0.0, floor(t0 * rate)), b = fmin((double)clip->info.frames, ceil(t1 * rate));
    float peak = 0.0f;
    for (long long i = (long long)a; i < (long long)b; i++)
        for (int c = 0; c < clip->info.channels; c++) {
            float v = fabsf(clip->samples[i * clip->info.channels + c]);
            peak = v > peak ? v : peak;
        }
    return peak;
}
