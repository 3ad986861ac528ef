/* The preview's view over its frames (tideline preview): the timeline
 * bar's keys, the overlay and false colour, and the frames it saves. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "audio/tl_audio_play.h"
#include "cli/tl_cli_preview.h"
#include "image/tl_image_io.h"
#include "passes/tl_passes.h"

/* Every key of every keyed channel (the boat's and the other objects'
 * too), for the timeline bar's ticks. */
void tl_preview_find_keys(preview *p)
{
    free(p->key_times);
    free(p->key_channels);
    p->key_times = NULL;
    p->key_channels = NULL;
    p->key_count = 0;
    int cap = 0;
    for (int k = 0; k < p->tl.object_count; k++)
        for (int c = 0; c < tl_channel_count(); c++) {
            const tl_channel *ch = tl_channel_at(c);
            if (k > 0 && strncmp(ch->name, "boat.", 5) != 0)
                continue;
            const tl_track *tr = tl_timeline_track(&p->tl, c, k);
            if (tr->state != TL_TRACK_KEYED)
                continue;
            for (size_t i = 0; i < tr->curve[0].count; i++) {
                if (p->key_count == cap) {
                    cap = cap ? 2 * cap : 64;
                    double *t = realloc(p->key_times, sizeof *t * (size_t)cap);
                    const char **n = t ? realloc(p->key_channels, sizeof *n * (size_t)cap) : NULL;
                    if (t)
                        p->key_times = t;
                    if (!t || !n)
                        return;
                    p->key_channels = n;
                }
                p->key_times[p->key_count] = tr->curve[0].keys[i].t;
                p->key_channels[p->key_count++] = ch->name;
            }
        }
}

/* A frame the preview saves (F, --screenshot): an EXR carries the camera
 * and the timeline's floating objects as render's do (tl_passes), in the
 * radiance's Rec.709; a PNG as it shows. */
int tl_preview_write_saved(const preview *p, const char *path, const tl_frame *f,
                           const tl_render_settings *settings, long frame, tl_error *err)
{
    tl_image_options opt = {0};
    if (tl_image_format_from_path(path) != TL_IMAGE_EXR)
        return tl_image_write(path, f, &opt, err);
    tl_scene scene;
    tl_render_frame_scene(&p->tl, tl_timeline_frame_time(&p->tl, frame), settings, &scene);
    const tl_meta meta[2] = {
        {"tideline/timeline", TL_META_STRING, p->o->timeline, 0, 0, NULL},
        {"tideline/time", TL_META_DOUBLE, NULL, scene.time, 0, NULL},
    };
    opt.meta = meta;
    opt.meta_count = 2;
    const char *names[TL_OBJECT_MAX];
    for (int k = 0; k < p->tl.object_count && k < TL_OBJECT_MAX; k++)
        names[k] = p->tl.objects[k].name;
    const tl_passes_frame info = {0,      &scene.camera, names, p->tl.object_count, p->tl.fps,
                                  &scene, NULL,          NULL,  TL_WORKING_REC709,  NULL,
                                  NULL};
    return tl_passes_write_frame(path, f, &info, &opt, err);
}

/* F: the frame at full size and quality as EXR + PNG next to the timeline,
 * under a name that is not taken. */
void tl_preview_save_frame(preview *p)
{
    char base[1024], exr[1100], png[1100];
    snprintf(base, sizeof base, "%s", p->o->timeline);
    char *dot = strrchr(base, '.');
    if (dot && !strchr(dot, '/'))
        *dot = '\0';
    long frame = frame_of(p);
    for (int n = 1; n < 10000; n++) {
        snprintf(exr, sizeof exr, "%s_frame%04ld_%d.exr", base, frame, n);
        snprintf(png, sizeof png, "%s_frame%04ld_%d.png", base, frame, n);
        struct stat st;
        if (stat(exr, &st) != 0 && stat(png, &st) != 0)
            break;
    }
    tl_render_settings settings = {
        .quality = &p->quality, .camera = p->free_cam ? &p->cam : NULL, .meter = &p->meters};
    if (p->o->has_size) {
        settings.width = p->o->width;
        settings.height = p->o->height;
    }
    tl_frame f = {0};
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_render_timeline_frame(p->render, &p->tl, frame, &settings, &f, NULL, &err);
    /* That frame took the renderer's targets: refinement starts again. */
    p->refined = 0;
    if (!rc)
        rc = tl_preview_write_saved(p, exr, &f, &settings, frame, &err);
    if (!rc)
        rc = tl_preview_write_saved(p, png, &f, &settings, frame, &err);
    if (rc)
        tl_cli_print_error("preview", &err);
    else
        printf("tideline preview: saved %s and %s\n", exr, png);
    fflush(stdout);
    tl_frame_free(&f);
}

/* The waveform for a bar of `columns` pixels: the loudest sample under
 * each column, the timeline's time mapped to the clip's by the offset. */
static void make_wave(preview *p, int columns)
{
    if (p->wave_columns == columns || !p->clip.samples || columns <= 0)
        return;
    float *w = realloc(p->wave, sizeof *w * (size_t)columns);
    if (!w)
        return;
    p->wave = w;
    p->wave_columns = columns;
    /* Drawn to the clip's loudest sample, as an editor's waveform view is,
     * so that a quiet track still shows its shape. */
    const double span = duration(p) / columns;
    float loudest = tl_audio_peak(&p->clip, 0.0, p->clip.info.duration);
    for (int c = 0; c < columns; c++) {
        double t0 = c * span - p->tl.audio_offset;
        p->wave[c] = loudest > 0.0f ? tl_audio_peak(&p->clip, t0, t0 + span) / loudest : 0.0f;
    }
}

/* The window's view over the frame: the false colour, and the overlay
 * when shown (Tab). */
void tl_preview_build_view(preview *p, int ww, int wh, int width, int height, const tl_gl_mouse *m,
                           tl_render_view *view)
{
    *view = (tl_render_view){p->false_colour, NULL, 0};
    tl_overlay_clear(&p->drawn);
    if (!p->overlay)
        return;
    tl_overlay_state s = {.width = ww,
                          .height = wh,
                          .frame_w = width,
                          .frame_h = height,
                          .frame = frame_of(p),
                          .frames = tl_timeline_frame_count(&p->tl),
                          .t = p->t,
                          .duration = duration(p),
                          .cuts = p->shot_starts + 1,
                          .cut_count = p->shots > 1 ? p->shots - 1 : 0,
                          .keys = p->key_times,
                          .key_channel = p->key_channels,
                          .key_count = p->key_count,
                          .loop_in = p->loop_in,
                          .loop_out = p->loop_out,
                          .fps_shown = p->fps,
                          .scale = p->scale,
                          .quality = p->quality.name,
                          .playing = p->playing,
                          .refined = p->refined,
                          .free_cam = p->free_cam,
                          .camera_speed = camera_speed(p),
                          .safe_frame = p->safe_frame,
                          .false_colour = p->false_colour,
                          .output_aspect = (double)p->tl.width / p->tl.height,
                          .mouse_x = m->x,
                          .mouse_y = m->y,
                          .problem = p->problem};
    const tl_bar bar = tl_overlay_bar(ww, wh);
    make_wave(p, (int)(bar.x1 - bar.x0));
    if (p->clip.samples && p->wave_columns > 0) {
        s.wave = p->wave;
        s.wave_columns = p->wave_columns;
    }
    tl_overlay_preview(&p->drawn, &s);
    view->overlay = p->drawn.vertex;
    view->overlay_vertices = p->drawn.count;
}

/* What the view over a still frame depends on, beyond the frame: drawn
 * again when it changes. */
void tl_preview_describe_view(const preview *p, const tl_gl_mouse *m, const tl_bar *bar, char *out,
                              size_t size)
{
    int over_bar = m->y >= bar->y0 - 8 && m->y <= bar->y1 + 8;
    snprintf(out, size, "%d %d %d %ld %ld %d %.0f %s", p->overlay, p->safe_frame, p->false_colour,
             p->loop_in, p->loop_out, p->refined, over_bar ? m->x : -1.0, p->problem);
}

void tl_preview_load_audio(preview *p)
{
    tl_error err;
    tl_error_clear(&err);
    if (p->player)
        tl_audio_player_use(p->player, NULL, &err); /* the old clip is about to go */
    tl_audio_free(&p->clip);
    p->wave_columns = 0;
    if (!p->tl.audio[0])
        return;
    if (tl_audio_read(p->tl.audio, &p->clip, &err)) {
        tl_cli_print_error("preview", &err);
        return;
    }
    int rc = p->player       ? tl_audio_player_use(p->player, &p->clip, &err)
             : p->audio_said ? TL_OK
                             : tl_audio_player_open(&p->player, &p->clip, &err);
    if (rc && !p->audio_said) {
        fprintf(stderr, "tideline preview: %s: the soundtrack plays silently\n", err.message);
        p->audio_said = 1;
    }
}

void tl_preview_follow_audio(preview *p)
{
    if (p->player)
        tl_audio_player_follow(p->player, p->t - p->tl.audio_offset,
                               p->playing && !p->scrubbing && p->speed == 1.0 &&
                                   p->clip.samples != NULL);
}
