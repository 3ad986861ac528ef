/* tideline preview: plays a timeline in a window with the same renderer as
 * the headless path, follows the file as it is edited, and trades
 * resolution for frame rate while it plays (sharpening to exactly the
 * `still` frame while paused). */
#include <dirent.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "audio/tl_audio_play.h"
#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "cli/tl_cli_overlay.h"
#include "cli/tl_cli_preview.h"
#include "core/tl_math.h"
#include "gl/tl_gl_window.h"
#include "image/tl_image_io.h"
#include "mesh/tl_mesh.h"
#include "passes/tl_passes.h"
#include "prepare/tl_prepare.h"
#include "render/tl_render.h"
#include "render/tl_render_window.h"
#include "shader/tl_shader_lib.h"
#include "timeline/tl_parse.h"

static const char usage[] =
    "Usage: tideline preview FILE.tl [options]\n"
    "\n"
    "Play a timeline in a window and follow the file as it is edited. It renders\n"
    "with the same renderer and shaders as 'still' and 'render'; while playing it\n"
    "lowers the resolution to hold the frame rate, and while paused it sharpens to\n"
    "exactly the frame 'tideline still' renders, then refines it one sample per\n"
    "pixel a frame until it is the frame 'tideline still --spp N' renders.\n"
    "\n"
    "Options:\n"
    "  --time T               start at this time (2.5, 2.5s, 60f); default 0\n"
    "  --paused               start paused\n"
    "  --quality PRESET       draft, preview (default), final, reference, seed\n"
    "  --size WxH             frame size (default: the timeline's, at most 1280x720)\n"
    "  --scale S              fixed render scale in (0, 1] (default: adapt to --target-fps)\n"
    "  --target-fps F         frame rate to hold while playing (default 24)\n"
    "  --refine N             samples per pixel a paused frame refines to, 1..1024\n"
    "                         (default 16; 1: no refinement)\n"
    "  --screenshot PATH      write PATH (PNG or EXR, atomically) each time the displayed\n"
    "                         frame has fully sharpened and refined\n"
    "  --exit-after-frames N  quit after N displayed frames\n"
    "  --keys LIST            play keys and clicks on the timeline bar, one per frame:\n"
    "                         " TL_PREVIEW_KEY_NAMES "\n"
    "  --watch-interval S     seconds between checks of the files (default 0.25)\n"
    "  --shader-dir DIR       load shaders from DIR and reload them when they "
    "change\n" TL_CLI_DISPLAY_USAGE
    "  -v, --verbose          log the GL renderer and every reload\n"
    "  -h, --help             show this help\n"
    "\n"
    "Keys: space play/pause; left/right one frame; shift+left/right one second;\n"
    "Home/End; [ ] playback speed; 1-4 quality draft/preview/final/reference;\n"
    "L loop or hold at the end; I / O set the loop range's start / end at the\n"
    "frame shown, Shift+L clears it; C free camera (WASD, Q/E down/up, drag to\n"
    "look, the mouse wheel its speed, which grows with its height; P prints its\n"
    "pose as timeline keys); F saves the frame at full size and quality as EXR +\n"
    "PNG next to the timeline; R reloads; Tab hides the overlay; G safe frames\n"
    "and the output's aspect; X false colour (exposure zones); H or ? this help;\n"
    "Esc quits. Click or drag on the timeline bar to go to a frame.\n"
    "The overlay (the bar with its cuts, keys, loop and soundtrack, the time and\n"
    "frame) is drawn in the window only, never in a saved frame.\n";

static volatile sig_atomic_t stop_signal = 0;

static void on_signal(int sig)
{
    stop_signal = sig;
}

static int parse(int argc, char **argv, options *o, int *help, tl_error *err)
{
    tl_args a;
    tl_args_init(&a, argc, argv);
    a.index = 1;
    o->target_fps = 24.0;
    o->watch_interval = 0.25;
    o->exit_after = -1;
    o->refine = 16;
    tl_quality_preset("preview", &o->quality, err);
    while (!tl_args_done(&a)) {
        const char *pos;
        int rc = 0;
        int color = tl_cli_color_flag(&a, &o->color, err);
        if (color < 0)
            return err->status ? (int)err->status : TL_ERR_USAGE;
        if (color > 0 && o->color.has_space)
            return tl_error_set(err, TL_ERR_USAGE,
                                "--working-space: the preview shows its frames; give it to "
                                "render or still");
        if (color > 0)
            continue;
        if (tl_args_match(&a, "--help", "-h", false, err)) {
            *help = 1;
            return 0;
        } else if (tl_args_match(&a, "--verbose", "-v", false, err)) {
            o->verbose = 1;
        } else if (tl_args_match(&a, "--paused", NULL, false, err)) {
            o->paused = 1;
        } else if (tl_args_match(&a, "--time", NULL, true, err)) {
            o->time_text = a.value;
            rc = a.value ? 0 : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--quality", NULL, true, err)) {
            rc = a.value ? tl_quality_preset(a.value, &o->quality, err) : TL_ERR_USAGE;
            if (rc)
                tl_error_prefix(err, "--quality");
            o->has_quality = 1;
        } else if (tl_args_match(&a, "--size", NULL, true, err)) {
            rc = a.value ? tl_args_size("--size", a.value, &o->width, &o->height, err)
                         : TL_ERR_USAGE;
            o->has_size = 1;
        } else if (tl_args_match(&a, "--scale", NULL, true, err)) {
            rc = a.value ? tl_args_double("--scale", a.value, &o->scale, err) : TL_ERR_USAGE;
            if (!rc && !(o->scale > 0.0 && o->scale <= 1.0))
                rc = tl_error_set(err, TL_ERR_USAGE, "--scale: '%s' is outside (0, 1]", a.value);
        } else if (tl_args_match(&a, "--target-fps", NULL, true, err)) {
            rc = a.value ? tl_args_double("--target-fps", a.value, &o->target_fps, err)
                         : TL_ERR_USAGE;
            if (!rc && !(o->target_fps >= 0.1 && o->target_fps <= 1000.0))
                rc = tl_error_set(err, TL_ERR_USAGE, "--target-fps: '%s' is outside 0.1..1000",
                                  a.value);
        } else if (tl_args_match(&a, "--refine", NULL, true, err)) {
            double n = 0;
            rc = a.value ? tl_args_double("--refine", a.value, &n, err) : TL_ERR_USAGE;
            if (!rc && !(n >= 1 && n <= TL_MAX_SPP && n == floor(n)))
                rc =
                    tl_error_set(err, TL_ERR_USAGE, "--refine: '%s' is not a sample count in 1..%d",
                                 a.value, TL_MAX_SPP);
            o->refine = (int)n;
        } else if (tl_args_match(&a, "--watch-interval", NULL, true, err)) {
            rc = a.value ? tl_args_double("--watch-interval", a.value, &o->watch_interval, err)
                         : TL_ERR_USAGE;
            if (!rc && !(o->watch_interval >= 0.01 && o->watch_interval <= 60.0))
                rc = tl_error_set(err, TL_ERR_USAGE, "--watch-interval: '%s' is outside 0.01..60 s",
                                  a.value);
        } else if (tl_args_match(&a, "--screenshot", NULL, true, err)) {
            o->screenshot = a.value;
            rc = a.value ? 0 : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--keys", NULL, true, err)) {
            o->keys = a.value;
            rc = a.value ? 0 : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--shader-dir", NULL, true, err)) {
            o->shader_dir = a.value;
            rc = a.value ? 0 : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--exit-after-frames", NULL, true, err)) {
            double n = 0;
            rc = a.value ? tl_args_double("--exit-after-frames", a.value, &n, err) : TL_ERR_USAGE;
            if (!rc && !(n >= 1 && n <= 1e9 && n == floor(n)))
                rc = tl_error_set(err, TL_ERR_USAGE,
                                  "--exit-after-frames: '%s' is not a count of frames", a.value);
            o->exit_after = (long)n;
        } else if (!o->timeline && tl_args_positional(&a, &pos)) {
            o->timeline = pos;
        } else {
            rc = tl_args_unknown(&a, "preview", err);
        }
        if (rc)
            return rc;
    }
    if (!o->timeline)
        return tl_error_set(err, TL_ERR_USAGE, "no timeline file given");
    if (o->screenshot && tl_image_check_writable(o->screenshot, err))
        return TL_ERR_USAGE;
    return TL_OK;
}

/* ---- the watched files ---- */

static stamp stamp_of(const char *path)
{
    struct stat st;
    stamp s = {0, 0, 0, 0};
    if (stat(path, &st) == 0) {
        s.mtime_ns = (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec;
        s.size = (long long)st.st_size;
        s.inode = (long long)st.st_ino;
        s.exists = 1;
    }
    return s;
}

/* The newest change among the files of a folder (the shaders). */
static long long newest_in(const char *dir)
{
    DIR *d = opendir(dir);
    long long newest = 0;
    if (!d)
        return 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        stamp s = stamp_of(path);
        if (s.exists && s.mtime_ns + s.size > newest)
            newest = s.mtime_ns + s.size;
    }
    closedir(d);
    return newest;
}

/* ---- the preview's state ---- */

/* The shots: a new one starts at every frame a cut falls before. */
static void find_shots(preview *p)
{
    free(p->shot_starts);
    long frames = tl_timeline_frame_count(&p->tl);
    p->shot_starts = malloc(sizeof(long) * 64);
    p->shots = 0;
    if (!p->shot_starts)
        return;
    p->shot_starts[p->shots++] = 0;
    for (long f = 1; f < frames && p->shots < 64; f++)
        if (tl_timeline_has_cut_between(&p->tl, tl_timeline_frame_time(&p->tl, f - 1),
                                        tl_timeline_frame_time(&p->tl, f)))
            p->shot_starts[p->shots++] = f;
}

static int shot_of(const preview *p, long frame)
{
    int shot = 1;
    for (int i = 1; i < p->shots; i++)
        if (frame >= p->shot_starts[i])
            shot = i + 1;
    return shot;
}

/* Loads (or reloads) the timeline and its objects' models; keeps the last good one
 * on failure, reporting at file:line:col. */
static int load(preview *p)
{
    tl_timeline fresh;
    tl_models models;
    if (tl_cli_load_timeline("preview", p->o->timeline, &fresh, &models)) {
        snprintf(p->problem, sizeof p->problem, "%s does not load (see the terminal)",
                 p->o->timeline);
        return 1;
    }
    tl_error err;
    tl_error_clear(&err);
    if (models.count && p->render && tl_render_set_models(p->render, &models, &err)) {
        tl_cli_print_error("preview", &err);
        tl_models_free(&models);
        tl_timeline_free(&fresh);
        return 1;
    }
    tl_models_free(&models);
    if (p->have_tl)
        tl_timeline_free(&p->tl);
    p->tl = fresh;
    p->have_tl = 1;
    p->problem[0] = '\0';
    p->version++;
    p->broken = 0;
    tl_meter_cache_reset(&p->meters);
    find_shots(p);
    tl_preview_find_keys(p);
    tl_preview_load_audio(p);
    long frames = tl_timeline_frame_count(&p->tl);
    if (p->loop_in >= frames || p->loop_out >= frames)
        p->loop_in = p->loop_out = -1; /* a shorter timeline: the range is gone */
    return 0;
}

static void preview_free(preview *p)
{
    if (p->have_tl)
        tl_timeline_free(&p->tl);
    p->have_tl = 0;
    free(p->shot_starts);
    free(p->key_times);
    free(p->key_channels);
    tl_overlay_free(&p->drawn);
    tl_audio_player_close(p->player);
    p->player = NULL;
    tl_audio_free(&p->clip);
    free(p->wave);
    p->wave = NULL;
}

static void set_time(preview *p, double t)
{
    double end = (tl_timeline_frame_count(&p->tl) - 1) / p->tl.fps;
    p->t = t < 0.0 ? 0.0 : t > end ? end : t;
    p->anchor_t = p->t;
    p->anchor_clock = tl_gl_window_time();
}

static void print_pose(const preview *p)
{
    const tl_camera *c = &p->cam;
    printf("key camera.position\n  %.3fs  %.3f %.3f %.3f\n", p->t, c->position[0], c->position[1],
           c->position[2]);
    printf("key camera.yaw\n  %.3fs  %.2fdeg\n", p->t, c->yaw / TL_DEG);
    printf("key camera.pitch\n  %.3fs  %.2fdeg\n", p->t, c->pitch / TL_DEG);
    fflush(stdout);
}

static void handle_key(preview *p, tl_key_press k, int *quit)
{
    double step = 1.0 / p->tl.fps;
    switch (k.key) {
    case TL_KEY_SPACE:
        p->playing = !p->playing;
        set_time(p, p->t);
        break;
    case TL_KEY_LEFT:
    case TL_KEY_RIGHT: {
        double dir = k.key == TL_KEY_LEFT ? -1.0 : 1.0;
        p->playing = 0;
        if (k.shift)
            set_time(p, p->t + dir);
        else
            set_time(p, (frame_of(p) + dir) / p->tl.fps);
        break;
    }
    case TL_KEY_HOME: set_time(p, 0.0); break;
    case TL_KEY_END: set_time(p, duration(p) - step); break;
    case TL_KEY_BRACKET_LEFT:
    case TL_KEY_BRACKET_RIGHT:
        set_time(p, p->t);
        p->speed *= k.key == TL_KEY_BRACKET_LEFT ? 0.5 : 2.0;
        p->speed = p->speed < 1.0 / 64 ? 1.0 / 64 : p->speed > 64 ? 64 : p->speed;
        break;
    case TL_KEY_1:
    case TL_KEY_2:
    case TL_KEY_3:
    case TL_KEY_4: {
        static const char *const names[4] = {"draft", "preview", "final", "reference"};
        tl_quality_preset(names[k.key - TL_KEY_1], &p->quality, NULL);
        break;
    }
    case TL_KEY_C:
        p->free_cam = !p->free_cam;
        if (p->free_cam) { /* start from where the timeline's camera is */
            tl_scene s;
            tl_timeline_eval(&p->tl, p->t, &s);
            p->cam = s.camera;
        }
        break;
    case TL_KEY_P: print_pose(p); break;
    case TL_KEY_F: tl_preview_save_frame(p); break;
    case TL_KEY_R: load(p); break;
    case TL_KEY_L:
        if (k.shift)
            p->loop_in = p->loop_out = -1;
        else
            p->loop = !p->loop;
        break;
    case TL_KEY_I:
    case TL_KEY_O: {
        long f = frame_of(p);
        long *end = k.key == TL_KEY_I ? &p->loop_in : &p->loop_out;
        *end = f;
        /* An end set past the other moves the other with it. */
        if (p->loop_in >= 0 && p->loop_out >= 0 && p->loop_in > p->loop_out)
            *(k.key == TL_KEY_I ? &p->loop_out : &p->loop_in) = f;
        break;
    }
    case TL_KEY_TAB: p->overlay = !p->overlay; break;
    case TL_KEY_G: p->safe_frame = !p->safe_frame; break;
    case TL_KEY_X: p->false_colour = !p->false_colour; break;
    case TL_KEY_H:
    case TL_KEY_QUESTION: fputs(usage, stdout); break;
    case TL_KEY_ESCAPE: *quit = 1; break;
    default: break;
    }
}

/* WASD/QE and dragging move the free camera, in metres per second. */
static void fly(preview *p, tl_gl_window *w, double dt)
{
    double dx, dy;
    tl_gl_window_drag(w, &dx, &dy);
    if (!p->free_cam || p->scrubbing)
        return;
    p->cam.yaw += dx * 0.003;
    p->cam.pitch = fmax(-89.0 * TL_DEG, fmin(89.0 * TL_DEG, p->cam.pitch - dy * 0.003));
    double speed = camera_speed(p) * dt, fx = sin(p->cam.yaw), fz = cos(p->cam.yaw);
    double move[3] = {0, 0, 0};
    if (tl_gl_window_key_held(w, TL_KEY_W))
        move[0] += fx, move[2] += fz;
    if (tl_gl_window_key_held(w, TL_KEY_S))
        move[0] -= fx, move[2] -= fz;
    if (tl_gl_window_key_held(w, TL_KEY_D))
        move[0] += fz, move[2] -= fx;
    if (tl_gl_window_key_held(w, TL_KEY_A))
        move[0] -= fz, move[2] += fx;
    if (tl_gl_window_key_held(w, TL_KEY_E))
        move[1] += 1.0;
    if (tl_gl_window_key_held(w, TL_KEY_Q))
        move[1] -= 1.0;
    for (int i = 0; i < 3; i++)
        p->cam.position[i] += move[i] * speed;
}

/* Samples per pixel a paused frame refines to: --refine, when that is more
 * than the quality takes in one frame (0: no refinement). */
static int refine_target(const preview *p)
{
    int spp = p->quality.spp < 1 ? 1 : p->quality.spp;
    return p->o->refine > spp ? p->o->refine : 0;
}

static void update_title(preview *p, tl_gl_window *w)
{
    char title[1024], refine[48] = "";
    long frame = frame_of(p);
    if (!p->playing && p->refined > 0)
        snprintf(refine, sizeof refine, "  %d/%d spp", p->refined, refine_target(p));
    snprintf(title, sizeof title,
             "tideline preview - %s  t %.3f s  frame %ld/%ld  shot %d/%d  %.1f fps  scale %.2f  "
             "%s%s%s%s%s%s",
             p->o->timeline, p->t, frame, tl_timeline_frame_count(&p->tl), shot_of(p, frame),
             p->shots, p->fps, p->scale, p->quality.name, p->playing ? "" : "  [paused]", refine,
             p->free_cam ? "  [free camera]" : "", p->problem[0] ? "  ERROR: " : "", p->problem);
    tl_gl_window_set_title(w, title);
}

int tl_cli_preview(int argc, char **argv)
{
    options o = {0};
    tl_error err;
    tl_error_clear(&err);
    int help = 0;
    int rc = parse(argc, argv, &o, &help, &err);
    if (help) {
        fputs(usage, stdout);
        return 0;
    }
    enum { MAX_SCRIPT = 4096 };
    static tl_preview_input script[MAX_SCRIPT];
    int script_len = 0;
    if (!rc && o.keys &&
        (script_len = tl_cli_preview_parse_keys(o.keys, script, MAX_SCRIPT, &err)) < 0)
        rc = TL_ERR_USAGE;
    if (rc) {
        tl_cli_print_error("preview", &err);
        return 2;
    }
    preview p = {0};
    p.o = &o;
    p.speed = 1.0;
    p.loop = 1;
    p.overlay = 1;
    p.loop_in = p.loop_out = -1;
    p.quality = o.quality;
    if (load(&p))
        return 1;
    double t0 = 0.0;
    if (o.time_text && tl_parse_time_text(o.time_text, p.tl.fps, &t0, &err)) {
        tl_error_prefix(&err, "--time");
        tl_cli_print_error("preview", &err);
        preview_free(&p);
        return 2;
    }
    int width = o.has_size ? o.width : p.tl.width, height = o.has_size ? o.height : p.tl.height;
    if (!o.has_size && (width > 1280 || height > 720)) {
        double fit = fmin(1280.0 / width, 720.0 / height);
        width = (int)(width * fit);
        height = (int)(height * fit);
    }
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    if (o.shader_dir && tl_shader_lib_from_dir(&lib, o.shader_dir, &err)) {
        tl_error_prefix(&err, "--shader-dir");
        tl_cli_print_error("preview", &err);
        preview_free(&p);
        return 2;
    }
    int crc = tl_cli_color_prepare(&o.color, 0, 1, &err);
    if (crc) {
        tl_cli_color_free(&o.color);
        tl_cli_print_error("preview", &err);
        preview_free(&p);
        return crc == TL_ERR_USAGE ? 2 : 1;
    }
    if (tl_render_open_window(&p.render, &lib, width, height, "tideline preview", &err) ||
        tl_cli_color_use(&o.color, p.render, &err)) {
        tl_cli_print_error("preview", &err);
        tl_render_close(p.render); /* NULL when it did not open */
        tl_cli_color_free(&o.color);
        preview_free(&p);
        return 1;
    }
    load(&p); /* again, now that the boat can be uploaded */
    if (o.verbose)
        fprintf(stderr, "tideline preview: %s\n", tl_render_describe(p.render));
    tl_gl_window *win = tl_render_window(p.render);
    tl_cli_signals signals;
    tl_cli_catch_stop(on_signal, &signals);

    p.playing = !o.paused;
    p.scale = o.scale > 0.0 ? o.scale : 1.0;
    set_time(&p, t0);
    p.tl_stamp = stamp_of(o.timeline);
    long long shaders_seen = o.shader_dir ? newest_in(o.shader_dir) : 0;
    double next_watch = tl_gl_window_time() + o.watch_interval, last = tl_gl_window_time();
    int quit = 0, script_pos = 0;
    char shown_state[96] = "", shown_view[800] = "";
    tl_frame shot = {0};
    while (!quit && !stop_signal && !tl_gl_window_should_close(win)) {
        tl_key_press keys[64];
        int n = tl_gl_window_poll(win, keys, 64);
        for (int i = 0; i < n && !quit; i++)
            handle_key(&p, keys[i], &quit);
        tl_gl_mouse mouse;
        tl_gl_window_mouse(win, &mouse);
        int ww, wh;
        tl_gl_window_size(win, &ww, &wh);
        const tl_bar bar = tl_overlay_bar(ww, wh);
        const long frames = tl_timeline_frame_count(&p.tl);
        /* A press on the bar scrubs while it is held (the overlay shown). */
        if (mouse.pressed && p.overlay && mouse.press_x >= bar.x0 - 4 &&
            mouse.press_x <= bar.x1 + 4 && mouse.press_y >= bar.y0 - 6 &&
            mouse.press_y <= bar.y1 + 6)
            p.scrubbing = 1;
        if (!mouse.held && !mouse.pressed)
            p.scrubbing = 0;
        if (p.scrubbing)
            set_time(&p, (double)tl_overlay_bar_frame(&bar, mouse.x, frames) / p.tl.fps);
        if (p.free_cam)
            p.wheel = fmax(-16.0, fmin(16.0, p.wheel + mouse.scroll));
        if (script_pos < script_len) {
            const tl_preview_input *in = &script[script_pos++];
            if (in->is_click)
                set_time(&p, (double)tl_overlay_bar_frame(
                                 &bar, bar.x0 + in->click * (bar.x1 - bar.x0), frames) /
                                 p.tl.fps);
            else
                handle_key(&p, in->key, &quit);
        }
        double now = tl_gl_window_time();
        fly(&p, win, now - last);
        if (now >= next_watch) { /* follow the file (editors that save by rename too) */
            next_watch = now + o.watch_interval;
            stamp s = stamp_of(o.timeline);
            /* Field by field: the struct's padding is not part of it. */
            if (s.exists && (s.mtime_ns != p.tl_stamp.mtime_ns || s.size != p.tl_stamp.size ||
                             s.inode != p.tl_stamp.inode || !p.tl_stamp.exists)) {
                p.tl_stamp = s;
                if (!load(&p) && o.verbose)
                    fprintf(stderr, "tideline preview: reloaded %s\n", o.timeline);
            }
            long long shaders = o.shader_dir ? newest_in(o.shader_dir) : 0;
            if (shaders != shaders_seen) {
                shaders_seen = shaders;
                if (tl_render_reload_shaders(p.render, &err)) {
                    tl_cli_print_error("preview", &err);
                    snprintf(p.problem, sizeof p.problem, "a shader does not compile");
                } else {
                    p.broken = 0;
                    p.problem[0] = '\0';
                    p.version++;
                    if (o.verbose)
                        fprintf(stderr, "tideline preview: reloaded the shaders\n");
                }
            }
        }
        if (p.playing && !p.scrubbing) {
            double t = p.anchor_t + (now - p.anchor_clock) * p.speed;
            double start = 0.0, end = (tl_timeline_frame_count(&p.tl) - 1) / p.tl.fps;
            if (p.loop_in >= 0) /* the loop range: from I's frame to O's */
                start = (double)p.loop_in / p.tl.fps;
            if (p.loop_out >= 0)
                end = (double)p.loop_out / p.tl.fps;
            if (t >= end + (p.loop_out >= 0 ? 1.0 / p.tl.fps : 1e-9)) {
                if (p.loop) {
                    set_time(&p, start);
                    t = start;
                } else {
                    p.playing = 0;
                    set_time(&p, end);
                    t = end;
                }
            }
            p.t = t;
        }
        tl_preview_follow_audio(&p);
        /* Paused: sharpen toward scale 1; nothing new to show: rest. */
        char state[96];
        snprintf(state, sizeof state, "%ld %ld %s %d %.6f %.6f %.6f %.6f %.6f", frame_of(&p),
                 p.version, p.quality.name, p.free_cam, p.cam.position[0], p.cam.position[1],
                 p.cam.position[2], p.cam.yaw, p.cam.pitch);
        if (!p.playing && o.scale <= 0.0 && p.scale < 1.0)
            p.scale = fmin(1.0, p.scale * 1.6);
        /* Paused and sharp: add a sample per pixel each frame until the
         * refinement's target (progressive refinement). */
        int still = !p.playing && p.sharp && strcmp(state, shown_state) == 0;
        int target = refine_target(&p);
        int refining = still && !p.broken && p.refined < target && script_pos >= script_len;
        if (((still && !refining) || p.broken) && script_pos >= script_len) {
            /* The same frame stays on screen: it counts as shown. Only
             * the view over it changed (a key, the cursor on the bar): it
             * is drawn again over the same frame. */
            char view_state[800];
            tl_preview_describe_view(&p, &mouse, &bar, view_state, sizeof view_state);
            if (!p.broken && strcmp(view_state, shown_view) != 0) {
                tl_render_view view;
                tl_preview_build_view(&p, ww, wh, width, height, &mouse, &view);
                if (tl_render_present(p.render, &view, &err))
                    tl_cli_print_error("preview", &err);
                snprintf(shown_view, sizeof shown_view, "%s", view_state);
            }
            struct timespec rest = {0, 10000000};
            nanosleep(&rest, NULL);
            last = tl_gl_window_time();
            if (o.exit_after > 0 && ++p.shown >= o.exit_after)
                break;
            continue;
        }
        tl_render_settings settings = {
            .quality = &p.quality, .camera = p.free_cam ? &p.cam : NULL, .meter = &p.meters};
        settings.width = (int)fmax(16.0, floor(width * p.scale + 0.5));
        settings.height = (int)fmax(9.0, floor(height * p.scale + 0.5));
        int sharp = settings.width == width && settings.height == height;
        /* The screenshot is the frame once it is final: sharp, and refined. */
        int want_shot = o.screenshot && sharp && strcmp(state, p.last_shot) != 0 &&
                        (refining ? p.refined == target - 1 : target == 0);
        tl_error_clear(&err);
        double start = tl_gl_window_time();
        if (refining)
            rc = tl_render_timeline_refine(p.render, &p.tl, frame_of(&p), &settings, p.refined,
                                           target, want_shot ? &shot : NULL, &err);
        else
            rc = tl_render_timeline_frame(p.render, &p.tl, frame_of(&p), &settings,
                                          want_shot ? &shot : NULL, NULL, &err);
        p.refined = refining ? p.refined + 1 : 0;
        if (!rc) {
            tl_render_view view;
            tl_preview_build_view(&p, ww, wh, width, height, &mouse, &view);
            tl_preview_describe_view(&p, &mouse, &bar, shown_view, sizeof shown_view);
            if (!rc)
                rc = tl_render_present(p.render, &view, &err);
        }
        if (rc) { /* a shader that does not compile: say so, keep the last frame */
            tl_cli_print_error("preview", &err);
            snprintf(p.problem, sizeof p.problem, "rendering failed (see the terminal)");
            p.broken = 1;
            update_title(&p, win);
            continue;
        }
        if (!rc && want_shot) {
            if (tl_preview_write_saved(&p, o.screenshot, &shot, &settings, frame_of(&p), &err))
                tl_cli_print_error("preview", &err);
            snprintf(p.last_shot, sizeof p.last_shot, "%s", state);
        }
        snprintf(shown_state, sizeof shown_state, "%s", state);
        p.sharp = sharp;
        p.shown++;
        double end = tl_gl_window_time(), dt = end - last;
        last = end;
        p.fps = p.fps > 0.0 ? 0.8 * p.fps + 0.2 / fmax(dt, 1e-6) : 1.0 / fmax(dt, 1e-6);
        /* Dynamic resolution: the render's own time against the target. */
        double took = end - start, budget = 1.0 / o.target_fps;
        if (p.playing && o.scale <= 0.0) {
            if (took > 1.1 * budget)
                p.scale = fmax(0.1, p.scale * 0.8);
            else if (took < 0.6 * budget)
                p.scale = fmin(1.0, p.scale * 1.1);
        }
        update_title(&p, win);
        if (o.exit_after > 0 && p.shown >= o.exit_after)
            break;
    }
    printf("tideline preview: stopped at frame %ld (%.6g s, shot %d of %d); %ld frames shown, "
           "%.1f fps, render scale %.2f\n",
           frame_of(&p), p.t, shot_of(&p, frame_of(&p)), p.shots, p.shown, p.fps, p.scale);
    if (p.loop_in >= 0 || p.loop_out >= 0) {
        long in = p.loop_in >= 0 ? p.loop_in : 0,
             out = p.loop_out >= 0 ? p.loop_out : tl_timeline_frame_count(&p.tl) - 1;
        printf("tideline preview: loop range frames %ld-%ld (%.6g s to %.6g s)\n", in, out,
               in / p.tl.fps, (out + 1) / p.tl.fps);
    } else {
        printf("tideline preview: no loop range\n");
    }
    tl_cli_restore_stop(&signals);
    tl_frame_free(&shot);
    tl_render_close(p.render);
    tl_cli_color_free(&o.color);
    preview_free(&p);
    return 0;
}
