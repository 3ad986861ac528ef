#include "cli/tl_cli_overlay.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb/stb_easy_font.h>

static const float panel[4] = {0.0f, 0.0f, 0.0f, 0.5f}, track[4] = {0.12f, 0.12f, 0.14f, 0.85f},
                   wave[4] = {0.30f, 0.55f, 0.80f, 0.75f}, loop[4] = {0.95f, 0.70f, 0.20f, 0.30f},
                   loop_edge[4] = {0.95f, 0.70f, 0.20f, 0.95f},
                   cut[4] = {1.0f, 0.85f, 0.20f, 0.95f}, key[4] = {0.85f, 0.85f, 0.85f, 0.85f},
                   playhead[4] = {1.0f, 1.0f, 1.0f, 1.0f}, text[4] = {0.95f, 0.95f, 0.95f, 1.0f},
                   warn[4] = {1.0f, 0.35f, 0.30f, 1.0f}, safe[4] = {1.0f, 1.0f, 1.0f, 0.55f},
                   aspect[4] = {0.30f, 0.90f, 1.0f, 0.8f};

/* Font pixels to window pixels (stb_easy_font's glyphs are 7 tall): 1.5
 * in a window 540 pixels tall or more, down to 1 in a small one, so that
 * the overlay keeps to the frame's foot. Set per overlay. */
static double text_scale = 1.5;
#define TEXT_LINE (10.0 * text_scale)

void tl_overlay_clear(tl_overlay *o)
{
    o->count = 0;
}

void tl_overlay_free(tl_overlay *o)
{
    free(o->vertex);
    memset(o, 0, sizeof *o);
}

static void vertex(tl_overlay *o, double x, double y, const float rgba[4])
{
    if (o->count == o->capacity) {
        int cap = o->capacity ? 2 * o->capacity : 4096;
        float *v = realloc(o->vertex, (size_t)cap * 6 * sizeof *v);
        if (!v)
            return; /* out of memory: the overlay is incomplete, the frame unharmed */
        o->vertex = v;
        o->capacity = cap;
    }
    float *v = o->vertex + (size_t)o->count++ * 6;
    v[0] = (float)x;
    v[1] = (float)y;
    memcpy(v + 2, rgba, 4 * sizeof *v);
}

void tl_overlay_rect(tl_overlay *o, double x0, double y0, double x1, double y1, const float rgba[4])
{
    vertex(o, x0, y0, rgba);
    vertex(o, x1, y0, rgba);
    vertex(o, x1, y1, rgba);
    vertex(o, x0, y0, rgba);
    vertex(o, x1, y1, rgba);
    vertex(o, x0, y1, rgba);
}

void tl_overlay_frame(tl_overlay *o, double x0, double y0, double x1, double y1, double thick,
                      const float rgba[4])
{
    tl_overlay_rect(o, x0, y0, x1, y0 + thick, rgba);
    tl_overlay_rect(o, x0, y1 - thick, x1, y1, rgba);
    tl_overlay_rect(o, x0, y0 + thick, x0 + thick, y1 - thick, rgba);
    tl_overlay_rect(o, x1 - thick, y0 + thick, x1, y1 - thick, rgba);
}

void tl_overlay_text(tl_overlay *o, double x, double y, double scale, const char *s,
                     const float rgba[4])
{
    /* stb_easy_font lays quads of 4 vertices (x, y, z, 4 bytes) at unit
     * scale from the origin; each becomes two triangles here. */
    static char quads[64 * 1024];
    char copy[512];
    snprintf(copy, sizeof copy, "%s", s);
    int n = stb_easy_font_print(0.0f, 0.0f, copy, NULL, quads, sizeof quads);
    for (int q = 0; q < n; q++) {
        const float *a = (const float *)(quads + (size_t)q * 64);
        double px[4], py[4];
        for (int k = 0; k < 4; k++) {
            px[k] = x + a[k * 4] * scale;
            py[k] = y + a[k * 4 + 1] * scale;
        }
        vertex(o, px[0], py[0], rgba);
        vertex(o, px[1], py[1], rgba);
        vertex(o, px[2], py[2], rgba);
        vertex(o, px[0], py[0], rgba);
        vertex(o, px[2], py[2], rgba);
        vertex(o, px[3], py[3], rgba);
    }
}

double tl_overlay_text_width(const char *s, double scale)
{
    char copy[512];
    snprintf(copy, sizeof copy, "%s", s);
    return stb_easy_font_width(copy) * scale;
}

tl_bar tl_overlay_bar(int width, int height)
{
    return (tl_bar){12.0, height - 32.0, width - 12.0, height - 10.0};
}

long tl_overlay_bar_frame(const tl_bar *bar, double x, long frames)
{
    double u = (x - bar->x0) / (bar->x1 - bar->x0);
    long f = (long)floor(u * (double)frames);
    return f < 0 ? 0 : f >= frames ? frames - 1 : f;
}

double tl_overlay_bar_x(const tl_bar *bar, double f, long frames)
{
    return bar->x0 + (f + 0.5) / (double)frames * (bar->x1 - bar->x0);
}

/* The letterboxed frame's rectangle in the window (as the renderer
 * presents it). */
static void frame_rect(const tl_overlay_state *s, double r[4])
{
    double scale = fmin((double)s->width / s->frame_w, (double)s->height / s->frame_h);
    double w = s->frame_w * scale, h = s->frame_h * scale;
    r[0] = (s->width - w) / 2;
    r[1] = (s->height - h) / 2;
    r[2] = r[0] + w;
    r[3] = r[1] + h;
}

/* G: action safe (93 %) and title safe (90 %), and where the output's
 * aspect differs from the frame's, the output's frame fitted inside. */
static void safe_frame(tl_overlay *o, const tl_overlay_state *s)
{
    double r[4];
    frame_rect(s, r);
    double w = r[2] - r[0], h = r[3] - r[1];
    const double insets[2] = {0.035, 0.05};
    for (int k = 0; k < 2; k++)
        tl_overlay_frame(o, r[0] + insets[k] * w, r[1] + insets[k] * h, r[2] - insets[k] * w,
                         r[3] - insets[k] * h, 1.0, safe);
    double frame_aspect = w / h;
    if (s->output_aspect > 0.0 && fabs(s->output_aspect / frame_aspect - 1.0) > 0.005) {
        double ow = fmin(w, h * s->output_aspect), oh = ow / s->output_aspect;
        double cx = (r[0] + r[2]) / 2, cy = (r[1] + r[3]) / 2;
        tl_overlay_frame(o, cx - ow / 2, cy - oh / 2, cx + ow / 2, cy + oh / 2, 2.0, aspect);
    }
}

/* X: the false colour's key, top left. */
static void false_colour_key(tl_overlay *o, const tl_overlay_state *s)
{
    static const struct {
        float rgba[4];
        const char *name;
    } zones[] = {
        {{0.45f, 0.10f, 0.55f, 1}, "crushed"},    {{0.10f, 0.30f, 0.85f, 1}, "shadow"},
        {{0.20f, 0.75f, 0.25f, 1}, "mid-grey"},   {{0.95f, 0.55f, 0.65f, 1}, "+1 stop"},
        {{0.95f, 0.85f, 0.15f, 1}, "near white"}, {{0.90f, 0.10f, 0.10f, 1}, "clipped"},
    };
    double x = 12.0, y = 12.0;
    (void)s;
    tl_overlay_rect(o, x - 6, y - 6, x + 110, y + 6 * TEXT_LINE + 2, panel);
    for (size_t i = 0; i < sizeof zones / sizeof *zones; i++) {
        tl_overlay_rect(o, x, y + i * TEXT_LINE, x + 12, y + i * TEXT_LINE + 10, zones[i].rgba);
        tl_overlay_text(o, x + 18, y + i * TEXT_LINE, text_scale, zones[i].name, text);
    }
}

void tl_overlay_preview(tl_overlay *o, const tl_overlay_state *s)
{
    text_scale = fmin(1.5, fmax(1.0, s->height / 360.0));
    if (s->safe_frame)
        safe_frame(o, s);
    if (s->false_colour)
        false_colour_key(o, s);
    const tl_bar bar = tl_overlay_bar(s->width, s->height);
    const long n = s->frames > 0 ? s->frames : 1;
    const double cell = (bar.x1 - bar.x0) / (double)n;
    tl_overlay_rect(o, 0, bar.y0 - TEXT_LINE - 10, s->width, s->height, panel);
    tl_overlay_rect(o, bar.x0, bar.y0, bar.x1, bar.y1, track);
    /* The waveform, one column a pixel, about the bar's middle. */
    double mid = (bar.y0 + bar.y1) / 2, half = (bar.y1 - bar.y0) / 2 - 2;
    for (int c = 0; s->wave && c < s->wave_columns && bar.x0 + c < bar.x1; c++) {
        double a = s->wave[c] * half;
        if (a > 0.25)
            tl_overlay_rect(o, bar.x0 + c, mid - a, bar.x0 + c + 1, mid + a, wave);
    }
    if (s->loop_in >= 0 || s->loop_out >= 0) {
        long in = s->loop_in >= 0 ? s->loop_in : 0, out = s->loop_out >= 0 ? s->loop_out : n - 1;
        double x0 = bar.x0 + in * cell, x1 = bar.x0 + (out + 1) * cell;
        tl_overlay_rect(o, x0, bar.y0, x1, bar.y1, loop);
        tl_overlay_rect(o, x0, bar.y0 - 3, x0 + 2, bar.y1 + 3, loop_edge);
        tl_overlay_rect(o, x1 - 2, bar.y0 - 3, x1, bar.y1 + 3, loop_edge);
    }
    for (int i = 0; i < s->cut_count; i++) {
        double x = bar.x0 + s->cuts[i] * cell;
        tl_overlay_rect(o, x - 1, bar.y0, x + 1, bar.y1, cut);
    }
    /* Keys: ticks along the bar's foot; the one under the cursor named. */
    const char *hover = NULL;
    double hover_t = 0.0, hover_x = 0.0;
    for (int i = 0; i < s->key_count; i++) {
        double x = bar.x0 + s->keys[i] / s->duration * (bar.x1 - bar.x0);
        if (x < bar.x0 || x > bar.x1)
            continue;
        tl_overlay_rect(o, x - 0.5, bar.y1 - 6, x + 0.5, bar.y1, key);
        if (fabs(s->mouse_x - x) < 3.0 && s->mouse_y > bar.y0 - 4 && s->mouse_y < bar.y1 + 4 &&
            !hover) {
            hover = s->key_channel[i];
            hover_t = s->keys[i];
            hover_x = x;
        }
    }
    double px = tl_overlay_bar_x(&bar, (double)s->frame, n);
    tl_overlay_rect(o, px - 1, bar.y0 - 4, px + 1, bar.y1 + 4, playhead);

    /* Where the playhead is on the left; how the preview draws on the
     * right (a second line above when the window is too narrow). */
    char where[160], how[200], loop_text[64] = "", cam[48] = "", refined[32] = "";
    if (s->loop_in >= 0 || s->loop_out >= 0)
        snprintf(loop_text, sizeof loop_text, "  loop %ld-%ld", s->loop_in >= 0 ? s->loop_in : 0,
                 s->loop_out >= 0 ? s->loop_out : n - 1);
    if (s->free_cam)
        snprintf(cam, sizeof cam, "  camera %.1f m/s", s->camera_speed);
    if (s->refined > 0)
        snprintf(refined, sizeof refined, "  %d spp", s->refined);
    snprintf(where, sizeof where, "%.3f s  frame %ld/%ld%s", s->t, s->frame, n, loop_text);
    snprintf(how, sizeof how, "%s%s  %.1f fps  scale %.2f  %s%s", s->playing ? "" : "paused  ",
             s->quality ? s->quality : "", s->fps_shown, s->scale, refined, cam);
    double left_w = tl_overlay_text_width(where, text_scale),
           right_w = tl_overlay_text_width(how, text_scale);
    double y = bar.y0 - TEXT_LINE - 2;
    tl_overlay_text(o, bar.x0, y, text_scale, where, text);
    if (bar.x0 + left_w + 16 + right_w > bar.x1) {
        y -= TEXT_LINE;
        tl_overlay_rect(o, 0, y - 4, s->width, y + TEXT_LINE - 4, panel);
    }
    tl_overlay_text(o, fmax(bar.x0, bar.x1 - right_w), y, text_scale, how, text);
    if (hover) {
        char label[160];
        snprintf(label, sizeof label, "%s key at %.3f s", hover, hover_t);
        double w = tl_overlay_text_width(label, text_scale);
        double x = fmin(fmax(hover_x - w / 2, 4.0), s->width - w - 4.0);
        tl_overlay_rect(o, x - 4, bar.y0 - 2 * TEXT_LINE - 8, x + w + 4, bar.y0 - TEXT_LINE - 6,
                        panel);
        tl_overlay_text(o, x, bar.y0 - 2 * TEXT_LINE - 6, text_scale, label, text);
    }
    if (s->problem && s->problem[0])
        tl_overlay_text(o, 12.0, s->false_colour ? 12.0 + 7 * TEXT_LINE : 12.0, text_scale,
                        s->problem, warn);
}
