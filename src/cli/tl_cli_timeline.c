/* tideline check / tideline eval: validate a timeline and print what it
 * evaluates to, for authors and for tools (--json). */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "core/tl_math.h"
#include "cutscene/tl_cutscene.h"
#include "mesh/tl_mesh.h"
#include "prepare/tl_prepare.h"
#include "timeline/tl_parse.h"
#include "waves/tl_bow_spray.h"
#include "waves/tl_giant.h"
#include "waves/tl_waves.h"

static const char check_usage[] =
    "Usage: tideline check FILE.tl... [--strict]\n"
    "\n"
    "Validate timelines. For each file prints every error with file:line:column,\n"
    "or a summary: duration, fps, frame count, size, the channels that are set\n"
    "and keyed, paths, links, and the features the scene requires. Warnings\n"
    "(likely mistakes: a small bare angle meant as radians, keys past the end)\n"
    "are printed too. Exit status: the worst of the files (0 valid, 1 invalid).\n"
    "\n"
    "Options:\n"
    "  --strict     warnings count as errors (exit 1)\n"
    "  -h, --help   show this help\n";

static const char eval_usage[] =
    "Usage: tideline eval FILE.tl (--at T | --frames A-B) [--probe X,Z]... [--json]\n"
    "\n"
    "Print every channel's evaluated value. Angles are printed in degrees,\n"
    "lengths in metres, as the language writes them. Then the giant wave's\n"
    "state (crest position, distance to its centre, speed, steepness and curl\n"
    "after the height-field clamp), the crest's speed over the water (measured\n"
    "from its position 1 ms later) and the boat's distance from it along and\n"
    "across its travel, the water height under the camera, the crest and the\n"
    "boat, and whether the camera sees from under the water.\n"
    "\n"
    "Options:\n"
    "  --at T         a time: 2.5, 2.5s, 1500ms or 60f (frames at the fps); one\n"
    "                 outside the timeline is evaluated, with a warning\n"
    "  --frames A-B   every frame from A to B inclusive (frame time = frame / fps)\n"
    "  --probe X,Z    also the water at world x, z (metres): every height where a\n"
    "                 vertical line there meets the surface (the height field first,\n"
    "                 then an overhanging lip's faces), the height field's unit\n"
    "                 normal (central differences, 1 mm) and the giant wave's foam\n"
    "                 in [0, 1]; repeatable, at most 1024 points\n"
    "  --json         one JSON object: {\"file\", \"fps\", \"samples\": [{\"time\",\n"
    "                 \"frame\", \"channels\": {name: value or [x, y, z]}, \"boat\",\n"
    "                 \"giant\", \"underwater\", \"water\", \"probes\" (with --probe):\n"
    "                 [{\"x\", \"z\", \"heights\", \"normal\", \"foam\"}]}]}; \"giant\" holds\n"
    "                 \"speed\" (the model's), \"speed_over_water\" (measured) and\n"
    "                 \"to_boat\": [along, across] (null without a boat)\n"
    "  -h, --help     show this help\n";

/* --probe: at most this many points, and this many surfaces reported at
 * each (the height field and the lip's faces). */
#define TL_EVAL_MAX_PROBES   1024
#define TL_EVAL_MAX_SURFACES 8
/* The crest's speed over the water is measured from its position this many
 * seconds after the sample's time (before it, when the wave is gone then). */
#define TL_EVAL_SPEED_DT 1e-3
/* A probe's normal: central differences of the surface height, this many
 * metres either side. */
#define TL_EVAL_NORMAL_STEP 1e-3

/* The points --probe asked for, world x and z. */
typedef struct eval_probes {
    int count;
    double xz[TL_EVAL_MAX_PROBES][2];
} eval_probes;

/* The warnings of the last timeline loaded (for check --strict). */
static int last_warnings;

/* Loads a timeline with what it references, printing its diagnostics;
 * returns the exit status. */
int tl_cli_load_cutscene(const char *command, const char *path, tl_cutscene *cs)
{
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    if (tl_cutscene_load(path, cs, &diags, &err) != TL_OK) {
        char program[64];
        snprintf(program, sizeof program, "tideline %s", command);
        tl_cutscene_report(stderr, program, &diags, &err);
        return 1;
    }
    if (diags.count) /* warnings: likely mistakes; the timeline loads */
        tl_diags_write(&diags, stderr);
    last_warnings = diags.count;
    return 0;
}

int tl_cli_load_timeline(const char *command, const char *path, tl_timeline *tl, tl_models *models)
{
    if (models)
        memset(models, 0, sizeof *models);
    tl_cutscene cs;
    if (tl_cli_load_cutscene(command, path, &cs))
        return 1;
    *tl = cs.timeline;
    if (models)
        *models = cs.models;
    else
        tl_models_free(&cs.models);
    return 0;
}

void tl_cli_warn_outside(const char *command, const char *flag, const char *given,
                         const tl_timeline *tl, double t)
{
    if (t >= 0.0 && t <= tl->duration * (1.0 + 1e-12))
        return;
    fprintf(stderr,
            "tideline %s: warning: %s %s (%.6g s) is %s the timeline (0 to %.6g s, frames "
            "0-%ld at %.6g fps); every channel holds or extrapolates its %s key there\n",
            command, flag, given, t, t < 0.0 ? "before" : "past the end of", tl->duration,
            tl_timeline_frame_count(tl) - 1, tl->fps, t < 0.0 ? "first" : "last");
}

/* The tracks in `state` (baked: only those an exporter baked). */
static void list_tracks(const tl_timeline *tl, tl_track_state state, bool baked, const char *label)
{
    int first = 1;
    for (int k = 0; k < tl->object_count; k++)
        for (int i = 0; i < tl_channel_count(); i++) {
            const tl_channel *ch = tl_channel_at(i);
            const tl_track *tr = tl_timeline_track(tl, i, k);
            if ((k > 0 && !tl_channel_is_object(ch)) || tr->state != state || (baked && !tr->baked))
                continue;
            if (k > 0) /* NAME.field */
                printf("%s%s%s", first ? label : ", ", tl->objects[k].name, ch->name + 4);
            else
                printf("%s%s", first ? label : ", ", ch->name);
            first = 0;
        }
    if (!first)
        printf("\n");
}

/* "boat", or "rescue" for the object `boat rescue` declared. */
static const char *object_name(const tl_timeline *tl, const tl_link *l)
{
    return tl->objects[l->object].name;
}

/* One file of `check`: its summary, or its errors; the exit status. */
static int check_one(const char *file, int strict)
{
    tl_timeline tl;
    int rc = tl_cli_load_timeline("check", file, &tl, NULL);
    if (rc)
        return rc;
    int warnings = last_warnings;
    printf("%s: %s\n", file,
           !warnings ? "ok"
           : strict  ? "failed (--strict: warnings count as errors)"
                     : "ok (with warnings)");
    printf("  duration  %.6g s at %.6g fps = %ld frames, %dx%d, quality %s\n", tl.duration, tl.fps,
           tl_timeline_frame_count(&tl), tl.width, tl.height, tl.quality.name);
    list_tracks(&tl, TL_TRACK_KEYED, false, "  keyed     ");
    list_tracks(&tl, TL_TRACK_SET, false, "  set       ");
    /* What an exporter could not carry as keys and sampled at every frame
     * (docs/blender.md): the comment above each says why. */
    list_tracks(&tl, TL_TRACK_KEYED, true, "  baked     ");
    const tl_path_track *paths[TL_OBJECT_MAX + 1] = {&tl.camera_path};
    const char *names[TL_OBJECT_MAX + 1] = {"camera"};
    for (int k = 0; k < tl.object_count; k++) {
        paths[k + 1] = &tl.objects[k].path;
        names[k + 1] = tl.objects[k].name;
    }
    for (int i = 0; i < tl.object_count + 1; i++)
        if (paths[i]->present)
            printf("  path      %s: %zu points, %.6g m%s%s\n", names[i], paths[i]->path.count,
                   paths[i]->path.length, paths[i]->path.constant_speed ? ", constant speed" : "",
                   paths[i]->baked ? ", baked" : "");
    /* The floating objects and the models they load (named whenever one
     * loads a file, with its real length once loaded). */
    bool models = false;
    for (int k = 0; k < tl.object_count; k++)
        models |= tl.objects[k].model[0] != '\0';
    if (tl.object_count > 1 || models) {
        printf("  objects   %d floating:", tl.object_count);
        for (int k = 0; k < tl.object_count; k++) {
            const tl_object *o = &tl.objects[k];
            const char *slash = strrchr(o->model, '/');
            printf("%s %s (%s", k ? "," : "", o->name,
                   o->model[0] ? (slash ? slash + 1 : o->model) : "built-in boat");
            if (o->model[0] && o->bounds_known) {
                tl_scene at_start;
                tl_timeline_eval(&tl, 0.0, &at_start);
                printf(", %.3g m long", tl_scene_object_const(&at_start, k)->length);
            }
            printf("%s)", o->path.present ? "" : ", no path: not drawn");
        }
        printf("\n");
    }
    if (tl.audio[0]) {
        const char *slash = strrchr(tl.audio, '/');
        printf("  audio     %s: %.3f s, %d Hz, %d channel%s, from %.6g s on the timeline",
               slash ? slash + 1 : tl.audio, tl.audio_duration, tl.audio_rate, tl.audio_channels,
               tl.audio_channels == 1 ? "" : "s", tl.audio_offset);
        /* Movies cut it to their frames; say where that happens. */
        double end = (double)tl_timeline_frame_count(&tl) / tl.fps;
        if (tl.audio_offset + tl.audio_duration > end + 1e-9)
            printf(" (its last %.3f s lie past the end: movies cut it there)",
                   fmin(tl.audio_duration, tl.audio_offset + tl.audio_duration - end));
        if (tl.audio_offset >= end)
            printf(" (it starts past the end: no movie has it)");
        printf("\n");
    }
    if (tl.camera_look.target == TL_TARGET_BOAT)
        printf("  link      camera looks at %s + %g %g %g\n", object_name(&tl, &tl.camera_look),
               tl.camera_look.offset[0], tl.camera_look.offset[1], tl.camera_look.offset[2]);
    else if (tl.camera_look.target == TL_TARGET_POINT)
        printf("  link      camera looks at %g %g %g\n", tl.camera_look.point[0],
               tl.camera_look.point[1], tl.camera_look.point[2]);
    if (tl.camera_follow.target == TL_TARGET_BOAT)
        printf("  link      camera follows %s + %g %g %g\n", object_name(&tl, &tl.camera_follow),
               tl.camera_follow.offset[0], tl.camera_follow.offset[1], tl.camera_follow.offset[2]);
    if (tl.giant_follow.target == TL_TARGET_BOAT)
        printf("  link      giant.center follows %s + %g %g\n", object_name(&tl, &tl.giant_follow),
               tl.giant_follow.offset[0], tl.giant_follow.offset[2]);
    tl_timeline_features f;
    tl_timeline_features_of(&tl, &f);
    printf("  features  ocean%s%s%s%s\n", f.giant_wave ? ", giant wave" : "",
           f.boat ? ", boat" : "", f.underwater ? ", underwater" : "", f.fog ? ", fog" : "");
    tl_timeline_free(&tl);
    return strict && warnings ? 1 : 0;
}

int tl_cli_check(int argc, char **argv)
{
    tl_args a;
    tl_args_init(&a, argc, argv);
    a.index = 1;
    tl_error err;
    tl_error_clear(&err);
    const char *files[256];
    int count = 0, strict = 0;
    while (!tl_args_done(&a)) {
        const char *pos;
        if (tl_args_match(&a, "--help", "-h", false, &err)) {
            fputs(check_usage, stdout);
            return 0;
        } else if (tl_args_match(&a, "--strict", NULL, false, &err)) {
            strict = 1;
        } else if (count < 256 && tl_args_positional(&a, &pos)) {
            files[count++] = pos;
        } else {
            if (count == 256)
                tl_error_set(&err, TL_ERR_USAGE, "at most 256 files at once");
            else
                tl_args_unknown(&a, "check", &err);
            tl_cli_print_error("check", &err);
            return 2;
        }
    }
    if (!count) {
        fprintf(stderr, "tideline check: no timeline file given (see 'tideline check --help')\n");
        return 2;
    }
    int worst = 0;
    for (int i = 0; i < count; i++) {
        int rc = check_one(files[i], strict);
        worst = rc > worst ? rc : worst;
    }
    return worst;
}

/* The shortest text of v / scale that reads back (times scale) to exactly
 * v, so 60deg, stored as radians, prints 60 and not 59.99999999999999.
 * Values within 1e-12 of zero after the division (rounding residue of a
 * unit conversion, such as -1.7e-15 deg) print as 0. Eight buffers, used
 * in turn, so one printf can hold several. */
static const char *shortest(double v, double scale)
{
    static char bufs[8][32];
    static int next;
    char *b = bufs[next++ & 7];
    double shown = fabs(v / scale) < 1e-12 ? 0.0 : v / scale;
    for (int p = 1; p <= 17; p++) {
        snprintf(b, 32, "%.*g", p, shown);
        /* %.1g of 60 is "6e+01": exact, but not how anyone writes it. */
        int plain = fabs(shown) < 1e-4 || fabs(shown) >= 1e15 || !strchr(b, 'e');
        if (plain && (shown == 0.0 || strtod(b, NULL) * scale == v))
            return b;
    }
    /* No degree text reads back to exactly these radians: the shortest
     * text of the degrees themselves (at scale 1 the loop always ends). */
    return shortest(shown, 1.0);
}

static const char *num(double v)
{
    return shortest(v, 1.0);
}

/* A channel's value as the language writes it: angles in degrees. */
static const char *value_text(const tl_channel *ch, double v)
{
    return shortest(v, ch->unit == TL_UNIT_ANGLE ? TL_DEG : 1.0);
}

static const char *unit_suffix(tl_unit unit)
{
    return unit == TL_UNIT_ANGLE    ? " deg"
           : unit == TL_UNIT_LENGTH ? " m"
           : unit == TL_UNIT_TIME   ? " s"
                                    : "";
}

/* What the surface does at this moment: the giant wave's state after its
 * clamps, how its crest moves over the water and where the boat is from
 * it, and the water height (ocean + giant wave, the march's octaves) under
 * the camera and under the crest. */
typedef struct surface_report {
    tl_giant giant;
    double crest[2];         /* world x, z of the crest's top on the centre line */
    double crest_height;     /* water height there */
    double to_center;        /* crest's signed distance past the centre, metres */
    bool speed_known;        /* the wave is there TL_EVAL_SPEED_DT before or after */
    double speed_over_water; /* the crest's speed along its travel, measured, m/s */
    double to_boat[2];       /* boat - crest along and across the travel, metres */
    double under_camera;     /* water height under the camera */
    double under_boat;       /* water height under the boat's centre (when there is one) */
    tl_water_side side;      /* where the camera sees from (underwater.mode) */
} surface_report;

/* The crest's top on the centre line (w = 0), world x z: where the surface
 * point that started at s0 = 0 sits, bow(0) + lambda(0)·D(0) along. */
static void crest_of(const tl_giant *g, double crest[2])
{
    double y, dy, d, dd, dl, db;
    tl_giant_profile(g, 0.0, &y, &dy, &d, &dd);
    double top = tl_giant_bow(g, 0.0, &db) + tl_giant_lambda(g, 0.0, &dl) * d;
    crest[0] = g->origin[0] + g->dir[0] * top;
    crest[1] = g->origin[1] + g->dir[1] * top;
}

/* The crest's speed over the water, measured: its displacement along the
 * travel direction between the scene's time and TL_EVAL_SPEED_DT later
 * (or earlier, when the wave is gone then or a cut lies between), over
 * that time. Whatever moves the crest (its speed, a keyed phase, a centre
 * that follows the boat) counts; a crest sliding along its own line does
 * not. */
static bool measure_speed(const tl_timeline *tl, const tl_scene *s, const tl_giant *g,
                          const double crest[2], double *speed)
{
    for (int sign = 1; sign >= -1; sign -= 2) {
        double dt = sign * TL_EVAL_SPEED_DT;
        if (tl_timeline_has_cut_between(tl, fmin(s->time, s->time + dt),
                                        fmax(s->time, s->time + dt)))
            continue;
        tl_scene then;
        tl_timeline_eval(tl, s->time + dt, &then);
        tl_giant g2;
        tl_giant_prepare(&g2, &then.giant, then.time);
        if (!g2.active)
            continue;
        double c2[2];
        crest_of(&g2, c2);
        *speed = (g->dir[0] * (c2[0] - crest[0]) + g->dir[1] * (c2[1] - crest[1])) / dt;
        return true;
    }
    return false;
}

static void surface_report_of(const tl_timeline *tl, const tl_scene *s, surface_report *r)
{
    memset(r, 0, sizeof *r);
    tl_waves waves;
    tl_waves_init(&waves, &s->ocean);
    tl_giant *g = &r->giant;
    tl_giant_prepare(g, &s->giant, s->time);
    const int oct = s->quality.march_octaves, it = s->quality.giant_iterations;
    r->under_camera = tl_waves_surface_height(&waves, g, s->camera.position[0],
                                              s->camera.position[2], s->time, oct, it);
    r->under_boat = tl_waves_surface_height(&waves, g, s->boat.position[0], s->boat.position[2],
                                            s->time, oct, it);
    r->side = tl_prepare_water_side(s, &waves, g, NULL);
    if (!g->active)
        return;
    crest_of(g, r->crest);
    r->crest_height =
        tl_waves_surface_height(&waves, g, r->crest[0], r->crest[1], s->time, oct, it);
    r->to_center = g->dir[0] * (g->origin[0] - s->giant.center[0]) +
                   g->dir[1] * (g->origin[1] - s->giant.center[1]);
    r->speed_known = measure_speed(tl, s, g, r->crest, &r->speed_over_water);
    double bx = s->boat.position[0] - r->crest[0], bz = s->boat.position[2] - r->crest[1];
    r->to_boat[0] = g->dir[0] * bx + g->dir[1] * bz;
    r->to_boat[1] = g->across[0] * bx + g->across[1] * bz;
}

/* The water at one probe: every surface height a vertical line there
 * meets (the height field first), the height field's unit normal and the
 * giant wave's foam coverage. */
typedef struct probe_report {
    int count;
    double heights[TL_EVAL_MAX_SURFACES];
    double normal[3];
    double foam;
} probe_report;

static void probe_of(const tl_scene *s, const tl_waves *waves, const tl_giant *g, double x,
                     double z, probe_report *p)
{
    const int oct = s->quality.march_octaves, it = s->quality.giant_iterations;
    const double t = s->time, e = TL_EVAL_NORMAL_STEP;
    p->count = tl_waves_surfaces(waves, g, x, z, t, oct, it, p->heights, TL_EVAL_MAX_SURFACES);
    double gx = (tl_waves_surface_height(waves, g, x + e, z, t, oct, it) -
                 tl_waves_surface_height(waves, g, x - e, z, t, oct, it)) /
                (2.0 * e);
    double gz = (tl_waves_surface_height(waves, g, x, z + e, t, oct, it) -
                 tl_waves_surface_height(waves, g, x, z - e, t, oct, it)) /
                (2.0 * e);
    double n = sqrt(gx * gx + 1.0 + gz * gz);
    p->normal[0] = -gx / n;
    p->normal[1] = 1.0 / n;
    p->normal[2] = -gz / n;
    tl_giant_sample smp;
    tl_giant_sample_at(g, x, z, it, &smp);
    p->foam = tl_giant_foam_coverage(g, &smp, s->water.foam, s->giant.foam_compression,
                                     s->giant.foam_trail);
}

static void print_probes_text(const tl_scene *s, const eval_probes *probes)
{
    if (!probes->count)
        return;
    tl_waves waves;
    tl_waves_init(&waves, &s->ocean);
    tl_giant g;
    tl_giant_prepare(&g, &s->giant, s->time);
    for (int i = 0; i < probes->count; i++) {
        probe_report p;
        probe_of(s, &waves, &g, probes->xz[i][0], probes->xz[i][1], &p);
        char label[64];
        snprintf(label, sizeof label, "probe %.6g %.6g", probes->xz[i][0], probes->xz[i][1]);
        printf("  %-26s water %.6g m", label, p.heights[0]);
        for (int k = 1; k < p.count; k++)
            printf("%s%.6g m%s", k == 1 ? " (and " : ", ", p.heights[k],
                   k + 1 == p.count ? " above: the lip)" : "");
        printf(", normal %.6g %.6g %.6g, foam %.6g\n", p.normal[0], p.normal[1], p.normal[2],
               p.foam);
    }
}

static void print_probes_json(const tl_scene *s, const eval_probes *probes)
{
    if (!probes->count)
        return;
    tl_waves waves;
    tl_waves_init(&waves, &s->ocean);
    tl_giant g;
    tl_giant_prepare(&g, &s->giant, s->time);
    printf(", \"probes\": [");
    for (int i = 0; i < probes->count; i++) {
        probe_report p;
        probe_of(s, &waves, &g, probes->xz[i][0], probes->xz[i][1], &p);
        printf("%s{\"x\": %.17g, \"z\": %.17g, \"heights\": [", i ? ", " : "", probes->xz[i][0],
               probes->xz[i][1]);
        for (int k = 0; k < p.count; k++)
            printf("%s%.17g", k ? ", " : "", p.heights[k]);
        printf("], \"normal\": [%.17g, %.17g, %.17g], \"foam\": %.17g}", p.normal[0], p.normal[1],
               p.normal[2], p.foam);
    }
    printf("]");
}

/* "no", "yes", or "at the surface" (each pixel decides): the frame's side. */
static const char *side_word(tl_water_side side)
{
    return side == TL_WATER_BELOW ? "yes" : side == TL_WATER_ABOVE ? "no" : "at the surface";
}

static void print_report_text(const tl_timeline *tl, const tl_scene *s)
{
    surface_report r;
    surface_report_of(tl, s, &r);
    const tl_giant *g = &r.giant;
    if (g->active) {
        printf("  %-26s crest at %.6g %.6g m, %.6g m %s the centre", "giant wave", r.crest[0],
               r.crest[1], fabs(r.to_center), r.to_center < 0.0 ? "before" : "past");
        if (g->speed > 0.0 && r.to_center < 0.0)
            printf(" (arrives in %.6g s)", -r.to_center / g->speed);
        printf(", %.6g m/s\n", g->speed);
        if (r.speed_known)
            printf("  %-26s %.6g m/s along its travel (measured over %g ms)\n",
                   "crest over the water", r.speed_over_water, 1e3 * TL_EVAL_SPEED_DT);
        if (s->boat.enabled)
            printf("  %-26s %.6g m %s it, %.6g m to its %s\n", "boat from the crest",
                   fabs(r.to_boat[0]), r.to_boat[0] < 0.0 ? "behind" : "ahead of",
                   fabs(r.to_boat[1]), r.to_boat[1] < 0.0 ? "left" : "right");
        printf("  %-26s steepness %.6g, curve strength %.6g (after the height-field clamp), "
               "min jacobian %.4g, slope <= %.4g\n",
               "giant wave shape", g->steepness, g->curl, g->min_jacobian, g->max_slope);
        printf("  %-26s %.6g m\n", "water under crest", r.crest_height);
    } else {
        printf("  %-26s off\n", "giant wave");
    }
    printf("  %-26s %.6g m (camera %.6g m above it)\n", "water under camera", r.under_camera,
           s->camera.position[1] - r.under_camera);
    printf("  %-26s %s (%s)\n", "underwater", side_word(r.side),
           tl_channel_find("underwater.mode")->names[s->underwater.mode]);
    if (s->boat.enabled)
        printf("  %-26s %.6g m (the boat's waterline %.6g m above it)\n", "water under boat",
               r.under_boat, s->boat.position[1] - r.under_boat);
}

static void print_report_json(const tl_timeline *tl, const tl_scene *s)
{
    surface_report r;
    surface_report_of(tl, s, &r);
    const tl_giant *g = &r.giant;
    printf(", \"giant\": ");
    if (g->active) {
        printf("{\"crest\": [%.17g, %.17g], \"past_center\": %.17g, \"speed\": %.17g, "
               "\"steepness\": %.17g, \"curve_strength\": %.17g, \"min_jacobian\": %.17g, "
               "\"max_slope\": %.17g, \"speed_over_water\": ",
               r.crest[0], r.crest[1], r.to_center, g->speed, g->steepness, g->curl,
               g->min_jacobian, g->max_slope);
        if (r.speed_known)
            printf("%.17g", r.speed_over_water);
        else
            printf("null");
        printf(", \"to_boat\": ");
        if (s->boat.enabled)
            printf("[%.17g, %.17g]}", r.to_boat[0], r.to_boat[1]);
        else
            printf("null}");
    } else
        printf("null");
    printf(", \"underwater\": \"%s\"", side_word(r.side));
    printf(", \"water\": {\"under_camera\": %.17g, \"under_crest\": ", r.under_camera);
    if (g->active)
        printf("%.17g", r.crest_height);
    else
        printf("null");
    printf(", \"under_boat\": ");
    if (s->boat.enabled)
        printf("%.17g}", r.under_boat);
    else
        printf("null}");
}

static void print_sample_text(const tl_timeline *tl, double t, long frame,
                              const eval_probes *probes)
{
    tl_scene s;
    tl_timeline_eval(tl, t, &s);
    if (frame >= 0)
        printf("frame %ld, time %s s\n", frame, num(t));
    else
        printf("time %s s\n", num(t));
    /* Every channel, then the other floating objects' as NAME.field. */
    for (int k = 0; k < tl->object_count; k++)
        for (int i = 0; i < tl_channel_count(); i++) {
            const tl_channel *ch = tl_channel_at(i);
            if (k > 0 && !tl_channel_is_object(ch))
                continue;
            double v[3];
            tl_channel_get_object(ch, &s, k, v);
            char name[64];
            snprintf(name, sizeof name, "%s%s", k ? tl->objects[k].name : "",
                     k ? ch->name + 4 : ch->name);
            printf("  %-26s", name);
            if (ch->kind == TL_CH_BOOL)
                printf(" %s", v[0] >= 0.5 ? "on" : "off");
            else if (ch->kind == TL_CH_ENUM)
                printf(" %s", ch->names[(int)v[0]]);
            else
                for (int c = 0; c < ch->components; c++)
                    printf(" %s", value_text(ch, v[c]));
            printf("%s\n", unit_suffix(ch->unit));
        }
    for (int k = 0; k < tl->object_count; k++) {
        const tl_boat *b = tl_scene_object_const(&s, k);
        const char *name = tl->objects[k].name;
        if (!b->enabled)
            continue;
        char label[64];
        snprintf(label, sizeof label, "%s.position", name);
        printf("  %-26s %s %s %s m\n", label, num(b->position[0]), num(b->position[1]),
               num(b->position[2]));
        snprintf(label, sizeof label, "%s pose", name);
        printf("  %-26s pitch %.6g deg, roll %.6g deg (%.6g m long, %.6g m beam)\n", label,
               b->pitch / TL_DEG, b->roll / TL_DEG, b->length, b->beam);
        if (k == 0)
            snprintf(label, sizeof label, "water rising at the bow");
        else
            snprintf(label, sizeof label, "water rising at %s's bow", name);
        printf("  %-26s %.6g m/s (the bow's spray from %g m/s, all of it from %g)\n", label,
               b->impact, TL_BOW_SPRAY_FROM, TL_BOW_SPRAY_FULL);
    }
    print_report_text(tl, &s);
    print_probes_text(&s, probes);
}

/* A channel's value in JSON: a boolean, a name, a number or an array. */
static void print_value_json(const tl_channel *ch, const double v[3])
{
    if (ch->kind == TL_CH_BOOL) {
        printf("%s", v[0] >= 0.5 ? "true" : "false");
    } else if (ch->kind == TL_CH_ENUM) {
        printf("\"%s\"", ch->names[(int)v[0]]);
    } else if (ch->components == 1) {
        printf("%s", value_text(ch, v[0]));
    } else {
        printf("[");
        for (int c = 0; c < ch->components; c++)
            printf("%s%s", c ? ", " : "", value_text(ch, v[c]));
        printf("]");
    }
}

/* A floating object's pose in JSON, or null when it is not on the water. */
static void print_pose_json(const tl_boat *b)
{
    if (b->enabled)
        printf("{\"position\": [%.17g, %.17g, %.17g], \"heading\": %.17g, \"pitch\": %.17g, "
               "\"roll\": %.17g, \"length\": %.17g, \"beam\": %.17g, \"impact\": %.17g}",
               b->position[0], b->position[1], b->position[2], b->heading / TL_DEG,
               b->pitch / TL_DEG, b->roll / TL_DEG, b->length, b->beam, b->impact);
    else
        printf("null");
}

static void print_sample_json(const tl_timeline *tl, double t, long frame, int first,
                              const eval_probes *probes)
{
    tl_scene s;
    tl_timeline_eval(tl, t, &s);
    printf("%s{\"time\": %s, \"frame\": ", first ? "" : ", ", num(t));
    if (frame >= 0)
        printf("%ld", frame);
    else
        printf("null");
    printf(", \"channels\": {");
    for (int i = 0; i < tl_channel_count(); i++) {
        const tl_channel *ch = tl_channel_at(i);
        double v[3];
        tl_channel_get(ch, &s, v);
        printf("%s\"%s\": ", i ? ", " : "", ch->name);
        print_value_json(ch, v);
    }
    printf("}, \"boat\": ");
    print_pose_json(&s.boat);
    /* Every floating object, the boat first: its name, its boat.* channels
     * and its pose (null without a path). */
    printf(", \"objects\": [");
    for (int k = 0; k < tl->object_count; k++) {
        printf("%s{\"name\": \"%s\", \"channels\": {", k ? ", " : "", tl->objects[k].name);
        int first = 1;
        for (int i = 0; i < tl_channel_count(); i++) {
            const tl_channel *ch = tl_channel_at(i);
            if (!tl_channel_is_object(ch))
                continue;
            double v[3];
            tl_channel_get_object(ch, &s, k, v);
            printf("%s\"%s\": ", first ? "" : ", ", ch->name + 5);
            first = 0;
            print_value_json(ch, v);
        }
        printf("}, \"pose\": ");
        print_pose_json(tl_scene_object_const(&s, k));
        printf("}");
    }
    printf("]");
    print_report_json(tl, &s);
    print_probes_json(&s, probes);
    printf("}");
}

/* "A-B" with 0 <= A <= B; returns 0 on success. */
static int parse_frame_range(const char *text, long *a, long *b, tl_error *err)
{
    char *end = NULL;
    long x = strtol(text, &end, 10);
    if (end == text || *end != '-')
        return tl_error_set(err, TL_ERR_USAGE, "--frames: expected A-B, got '%s'", text);
    const char *second = end + 1;
    long y = strtol(second, &end, 10);
    if (end == second || *end != '\0')
        return tl_error_set(err, TL_ERR_USAGE, "--frames: expected A-B, got '%s'", text);
    if (x < 0 || y < x)
        return tl_error_set(err, TL_ERR_USAGE, "--frames: '%s' must satisfy 0 <= A <= B", text);
    *a = x;
    *b = y;
    return TL_OK;
}

/* --probe X,Z: two finite numbers, world metres; returns 0 on success. */
static int parse_probe(const char *text, double out[2], tl_error *err)
{
    const char *p = text;
    for (int i = 0; i < 2; i++) {
        char *end = NULL;
        errno = 0;
        double v = strtod(p, &end);
        if (end == p || *end != (i == 0 ? ',' : '\0'))
            return tl_error_set(err, TL_ERR_USAGE, "--probe: expected X,Z, got '%s'", text);
        if (!isfinite(v) || errno == ERANGE)
            return tl_error_set(err, TL_ERR_USAGE, "--probe: '%s' holds a non-finite number", text);
        out[i] = v;
        p = end + 1;
    }
    return TL_OK;
}

int tl_cli_eval(int argc, char **argv)
{
    tl_args a;
    tl_args_init(&a, argc, argv);
    a.index = 1;
    tl_error err;
    tl_error_clear(&err);
    const char *file = NULL, *at = NULL, *frames = NULL;
    int json = 0, rc = 0;
    static eval_probes probes; /* 16 KiB: off the stack */
    probes.count = 0;
    while (!rc && !tl_args_done(&a)) {
        const char *pos;
        if (tl_args_match(&a, "--help", "-h", false, &err)) {
            fputs(eval_usage, stdout);
            return 0;
        } else if (tl_args_match(&a, "--json", NULL, false, &err)) {
            json = 1;
        } else if (tl_args_match(&a, "--at", NULL, true, &err)) {
            at = a.value;
            rc = at ? 0 : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--frames", NULL, true, &err)) {
            frames = a.value;
            rc = frames ? 0 : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--probe", NULL, true, &err)) {
            if (!a.value)
                rc = TL_ERR_USAGE;
            else if (probes.count == TL_EVAL_MAX_PROBES)
                rc = tl_error_set(&err, TL_ERR_USAGE, "--probe: at most %d points at once",
                                  TL_EVAL_MAX_PROBES);
            else
                rc = parse_probe(a.value, probes.xz[probes.count++], &err);
        } else if (!file && tl_args_positional(&a, &pos)) {
            file = pos;
        } else {
            rc = tl_args_unknown(&a, "eval", &err);
        }
    }
    if (!rc && !file)
        rc = tl_error_set(&err, TL_ERR_USAGE, "no timeline file given");
    if (!rc && !at == !frames)
        rc = tl_error_set(&err, TL_ERR_USAGE, "give exactly one of --at T and --frames A-B");
    long first = 0, last = -1;
    if (!rc && frames)
        rc = parse_frame_range(frames, &first, &last, &err);
    if (rc) {
        tl_cli_print_error("eval", &err);
        return 2;
    }
    tl_timeline tl;
    rc = tl_cli_load_timeline("eval", file, &tl, NULL);
    if (rc)
        return rc;
    double t = 0.0;
    if (at && tl_parse_time_text(at, tl.fps, &t, &err)) {
        tl_error_prefix(&err, "--at");
        tl_cli_print_error("eval", &err);
        tl_timeline_free(&tl);
        return 2;
    }
    if (at)
        tl_cli_warn_outside("eval", "--at", at, &tl, t);
    if (frames && last - first >= 1000000) {
        fprintf(stderr, "tideline eval: --frames: at most 1000000 frames at once\n");
        tl_timeline_free(&tl);
        return 2;
    }
    if (json)
        printf("{\"file\": \"%s\", \"fps\": %.17g, \"samples\": [", file, tl.fps);
    for (long f = at ? -1 : first; at ? f == -1 : f <= last; f++) {
        double time = at ? t : tl_timeline_frame_time(&tl, f);
        if (json)
            print_sample_json(&tl, time, f, at ? 1 : f == first, &probes);
        else
            print_sample_text(&tl, time, f, &probes);
        if (at)
            break;
    }
    if (json)
        printf("]}\n");
    tl_timeline_free(&tl);
    return 0;
}
