/* Internal to `tideline preview` (tl_cli_preview*.c). */
#ifndef TL_CLI_PREVIEW_H
#define TL_CLI_PREVIEW_H

#include "core/tl_error.h"
#include "gl/tl_gl_window.h"

/* One step of a --keys script: a key, or a click on the timeline bar at a
 * share of its width (`click:0.5`). */
typedef struct tl_preview_input {
    tl_key_press key;
    int is_click;
    double click; /* 0..1 along the bar */
} tl_preview_input;

/* Parses "space,right,click:0.5,F" into steps; returns the count, or -1
 * with the error naming the bad word. */
int tl_cli_preview_parse_keys(const char *text, tl_preview_input *out, int max, tl_error *err);

/* The key names --keys takes, for the help. */
#define TL_PREVIEW_KEY_NAMES                                                                       \
    "space,left,right,shift+left,shift+right,home,end,[,],1,2,3,4,c,p,f,r,l,shift+l,i,o,g,x,"      \
    "tab,h,esc, and click:F (a click at F of the timeline bar, 0..1)"

#include <math.h>

#include "audio/tl_audio.h"
#include "cli/tl_cli.h"
#include "cli/tl_cli_overlay.h"
#include "image/tl_frame.h"
#include "render/tl_render.h"
#include "render/tl_render_window.h"
#include "timeline/tl_timeline.h"

typedef struct options {
    const char *timeline, *screenshot, *keys, *shader_dir, *time_text;
    int paused, verbose, has_quality, has_size;
    tl_quality quality;
    int width, height;
    double scale, target_fps, watch_interval;
    long exit_after;
    int refine;         /* samples per pixel a paused frame refines to */
    tl_cli_color color; /* --ocio, --display, --view */
} options;

typedef struct stamp {
    long long mtime_ns, size, inode;
    int exists;
} stamp;

typedef struct preview {
    options *o;
    tl_render *render;
    tl_timeline tl;
    int have_tl;
    stamp tl_stamp;
    char problem[512]; /* the last reload's error, for the title; "" when fine */
    double t;          /* the time shown, seconds */
    int playing, loop;
    double speed, anchor_clock, anchor_t;
    tl_quality quality;
    double scale;
    int free_cam;
    tl_camera cam;
    long version;       /* bumps on every reload: the screenshot follows it */
    long shown;         /* frames displayed */
    double fps;         /* measured */
    char last_shot[96]; /* the state of the last screenshot */
    int sharp;          /* the displayed frame is fully sharpened */
    int broken;         /* rendering failed: wait for a change before trying again */
    int refined;        /* samples per pixel the paused frame holds so far (0: not refining) */
    long *shot_starts;  /* the first frame of each shot (cuts), for the title */
    int shots;
    tl_meter_cache meters; /* auto exposure's, for this version of the timeline */
    /* The window's view (tl_cli_overlay): Tab, G, X. */
    int overlay, safe_frame, false_colour;
    long loop_in, loop_out; /* I / O: the loop range's frames, -1 where not set */
    int scrubbing;          /* a press on the bar is being dragged */
    double wheel;           /* the free camera's speed: steps of the mouse wheel */
    double *key_times;      /* every key of the timeline, for the bar */
    const char **key_channels;
    int key_count;
    tl_overlay drawn;
    /* The soundtrack: decoded at each load, played while the playhead
     * moves at speed 1 (tl_audio_play), drawn on the bar. */
    tl_audio_clip clip;
    struct tl_audio_player *player;
    int audio_said;   /* the lack of a device was reported (once) */
    float *wave;      /* the bar's waveform, a peak a pixel column */
    int wave_columns; /* for a bar this wide (0: to be made) */
} preview;

static inline long frame_of(const preview *p)
{
    return (long)floor(p->t * p->tl.fps + 1e-6);
}

static inline double duration(const preview *p)
{
    return tl_timeline_frame_count(&p->tl) / p->tl.fps;
}

/* The free camera's speed, m/s: a walk near the water, faster the higher
 * it flies (half its height a second, so a view from 100 m crosses its
 * own distance in a few seconds), times 2 for every two steps of the
 * mouse wheel. */
static inline double camera_speed(const preview *p)
{
    return fmax(4.0, 0.5 * fabs(p->cam.position[1])) * exp2(0.5 * p->wheel);
}

/* tl_cli_preview_view.c: the timeline bar's keys (at every load), the
 * window's view over the frame, what that view depends on (drawn again
 * when it changes), and the frames it saves (F, --screenshot). */
void tl_preview_find_keys(preview *p);
void tl_preview_build_view(preview *p, int ww, int wh, int width, int height, const tl_gl_mouse *m,
                           tl_render_view *view);
void tl_preview_describe_view(const preview *p, const tl_gl_mouse *m, const tl_bar *bar, char *out,
                              size_t size);
int tl_preview_write_saved(const preview *p, const char *path, const tl_frame *f,
                           const tl_render_settings *settings, long frame, tl_error *err);
void tl_preview_save_frame(preview *p);
/* The soundtrack at a load: decoded (a failure is reported, the preview
 * goes on silent); the device opened the first time (its lack said once). */
void tl_preview_load_audio(preview *p);
/* Each frame: the device follows the playhead. */
void tl_preview_follow_audio(preview *p);

#endif
