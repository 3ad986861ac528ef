/* tl_movie_frames: a movie from frames already on disk.
 *
 * What `tideline movie` and `render --movie --skip-existing` run: every
 * frame is checked to exist before ffmpeg starts, then each PNG (8 or 16
 * bits, the display image) is read and piped to ffmpeg as `render --movie`
 * pipes a frame it draws, through the same 8-bit conversion: an 8-bit
 * frame goes in exactly as written, so the movie equals the one a single
 * `render --movie` run makes. EXR frames hold scene-linear light, not a
 * picture to show, and are refused with what to do instead. */
#ifndef TL_MOVIE_FRAMES_H
#define TL_MOVIE_FRAMES_H

#include <signal.h>
#include <stddef.h>

#include "core/tl_error.h"
#include "movie/tl_movie.h"

typedef struct tl_movie_frames {
    const char *pattern; /* e.g. out/shot_####.png (tl_pattern_format) */
    const long *frames;  /* the frame numbers, in the movie's order */
    size_t count;
    const char *movie; /* .mp4 or .mov */
    double fps;
    const tl_movie_sound *sound; /* NULL: no audio */
    int dither;                  /* 16-bit frames to 8 bits dithered (tl_frame_display_row8) */
    /* Called after each frame (may be NULL). */
    void (*progress)(void *ctx, size_t done, size_t total);
    void *progress_ctx;
    /* Set (by a signal handler) to stop: the movie is discarded. */
    volatile sig_atomic_t *stop;
} tl_movie_frames;

/* Encodes the frames into the movie, or fails leaving no movie (an
 * earlier file is untouched): a missing frame (named, with how many more
 * are missing), one not a PNG, or one of another size than the first. */
int tl_movie_from_frames(const tl_movie_frames *job, tl_error *err);

#endif
