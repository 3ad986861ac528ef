/* tl_cli_overlay: what the preview window draws over the frame, laid out
 * as coloured triangles (tl_render_view's overlay): the timeline bar with
 * its playhead, the shots' cuts, the keys, the loop range and the
 * soundtrack's waveform; the time, frame, speed and scale as text
 * (stb_easy_font, from libstb-dev: a bitmap font drawn as quads, no font
 * file); the safe-frame guides. GL-free: the window layer draws it. */
#ifndef TL_CLI_OVERLAY_H
#define TL_CLI_OVERLAY_H

#include <stddef.h>

typedef struct tl_overlay {
    float *vertex; /* 6 floats a vertex: x, y (pixels, from the top left), RGBA */
    int count, capacity;
} tl_overlay;

void tl_overlay_clear(tl_overlay *o);
void tl_overlay_free(tl_overlay *o);
/* A filled rectangle. */
void tl_overlay_rect(tl_overlay *o, double x0, double y0, double x1, double y1,
                     const float rgba[4]);
/* An outline `thick` pixels wide. */
void tl_overlay_frame(tl_overlay *o, double x0, double y0, double x1, double y1, double thick,
                      const float rgba[4]);
/* Text with its top left at x, y, each font pixel `scale` pixels. */
void tl_overlay_text(tl_overlay *o, double x, double y, double scale, const char *text,
                     const float rgba[4]);
double tl_overlay_text_width(const char *text, double scale);

/* The timeline bar: where it lies in a window, and which frame a point of
 * it stands for (the frames share its width equally, frame 0 at the left
 * edge; outside it the nearer end). */
typedef struct tl_bar {
    double x0, y0, x1, y1;
} tl_bar;
tl_bar tl_overlay_bar(int width, int height);
long tl_overlay_bar_frame(const tl_bar *bar, double x, long frames);
/* The x of frame f's centre on the bar. */
double tl_overlay_bar_x(const tl_bar *bar, double f, long frames);

/* What the preview's overlay shows. */
typedef struct tl_overlay_state {
    int width, height;    /* the window, pixels */
    int frame_w, frame_h; /* the frame, letterboxed into the window */
    long frame, frames;   /* the frame shown, of how many */
    double t;             /* its time, seconds */
    double duration;      /* frames / fps: the bar's length in seconds */
    const long *cuts;     /* the first frame of each shot after the first */
    int cut_count;
    const double *keys;             /* key times, seconds */
    const char *const *key_channel; /* each key's channel */
    int key_count;
    long loop_in, loop_out; /* the loop range's frames, -1 where not set */
    const float *wave;      /* the soundtrack's peak per bar pixel column, 0..1 */
    int wave_columns;
    double fps_shown, scale; /* measured frames a second, render scale */
    const char *quality;
    int playing, refined, free_cam;
    double camera_speed;     /* the free camera's, m/s */
    int safe_frame;          /* G */
    int false_colour;        /* X: the legend */
    double output_aspect;    /* the output's width / height (G shows it when the frame's differs) */
    double mouse_x, mouse_y; /* for the key under the cursor */
    const char *problem;     /* the last error, or "" */
} tl_overlay_state;

void tl_overlay_preview(tl_overlay *o, const tl_overlay_state *s);

#endif
