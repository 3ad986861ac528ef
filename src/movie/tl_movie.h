/* tl_movie: movies through the `ffmpeg` program.
 *
 * Raw frames (8-bit RGB, rows top first) are piped to ffmpeg's standard
 * input; ffmpeg encodes H.264 (yuv420p) for .mp4 and ProRes 422 HQ for
 * .mov, at the given size and frame rate. ffmpeg writes to a hidden
 * temporary file next to the target, renamed over it only after ffmpeg
 * exits successfully, so an interrupted or failed run leaves no partial
 * movie and never damages an existing one. ffmpeg runs in its own process
 * group (a Ctrl-C in the terminal reaches tideline, which decides), with
 * `-loglevel error`: its messages go to our stderr as they come. */
#ifndef TL_MOVIE_H
#define TL_MOVIE_H

#include <stddef.h>
#include <stdint.h>

#include "core/tl_error.h"

typedef enum tl_movie_codec { TL_MOVIE_UNKNOWN = 0, TL_MOVIE_H264, TL_MOVIE_PRORES } tl_movie_codec;

/* From the extension: .mp4 = H.264, .mov = ProRes; else unknown. */
tl_movie_codec tl_movie_codec_from_path(const char *path);

/* Finds the ffmpeg program (the TIDELINE_FFMPEG environment variable, else
 * `ffmpeg` on PATH). Fails with a message saying how to install it
 * (Debian package 'ffmpeg') when missing. `out` may be NULL. */
int tl_movie_find_ffmpeg(char *out, size_t out_size, tl_error *err);

/* Checks before any rendering that `path` can become a movie: a known
 * extension, a writable existing folder, even width and height for H.264
 * (yuv420p), and ffmpeg present. */
int tl_movie_check(const char *path, int width, int height, tl_error *err);

/* The exact frame rate ffmpeg is given for `fps`, as num/den in lowest
 * terms: whole numbers as N/1, the NTSC rates (23.976, 29.97, 59.94...,
 * within 0.0005 of N*1000/1001) as N*1000/1001, anything else to the
 * nearest 1/1000 fps. Fails (non-zero) unless 0.001 <= fps <= 10000. */
int tl_movie_frame_rate(double fps, long *num, long *den);

typedef struct tl_movie tl_movie;

/* A soundtrack muxed into the movie: AAC (256 kb/s) in .mp4, 24-bit PCM in
 * .mov, ffmpeg reading the file itself. */
typedef struct tl_movie_sound {
    const char *path;
    /* Seconds into the file at the movie's first frame; negative: the movie
     * starts with that much silence, delayed to the sample. */
    double start;
    /* The movie's length in seconds (its frames / fps): the sound is cut to
     * it, or padded with silence. */
    double duration;
    int sample_rate; /* the file's, for the delay in samples */
} tl_movie_sound;

/* Starts ffmpeg for `path`. fps may be fractional (23.976 is passed to ffmpeg
 * as an exact rational, 24000/1001). `sound` may be NULL (no audio). */
int tl_movie_open(tl_movie **out, const char *path, int width, int height, double fps,
                  const tl_movie_sound *sound, tl_error *err);
/* Writes one frame: width*height*3 bytes of RGB, top row first. Fails if
 * ffmpeg has died (message includes its exit status). */
int tl_movie_write(tl_movie *m, const uint8_t *rgb, tl_error *err);
/* Closes ffmpeg's input, waits for it, and on success renames the movie
 * into place. Frees m. */
int tl_movie_finish(tl_movie *m, tl_error *err);
/* Stops ffmpeg, removes the temporary movie, frees m (NULL is fine). */
void tl_movie_abort(tl_movie *m);

#endif
