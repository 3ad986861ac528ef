/* wrong_surface: do a preset's rays meet the surface `reference` meets?
 *
 *     wrong_surface [options] TIMELINE FRAME[,FRAME...]
 *
 * Renders each frame's depth plane (distance along the view ray; the sky
 * 1e10) at `reference` and at each preset, and prints per preset the share
 * of pixels whose depth agrees with reference's: of the pixels that
 * reference puts nearer than --near (2000 m) and away from depth edges
 * (reference's depth within +-2 pixels varies by at most --edge, 1.2), the
 * share where preset / reference lies within [1/--factor, --factor]
 * (1.5). A preset pixel that sees the sky there disagrees. The rest of
 * what disagrees is split into the sky (holes), short (nearer than
 * reference: a ray that stopped in front of the surface) and long.
 *
 * Reference is drawn with one sample a pixel (--ref-spp), at the pixel's
 * centre, keeping every march knob of its own (48 octaves, 1000 steps,
 * 0.1 mm hits, refined). That is valid for depth: with N samples the depth
 * plane holds the nearest surface any sample saw, which differs from the
 * centre's only where the depth changes within the pixel, the depth edges
 * the measure leaves out; and the presets (one sample) trace that same
 * centre ray. 64 samples would cost 64 times as much for no other change.
 *
 * Options:
 *   --size WxH          render size (default 320x180)
 *   --presets LIST      comma-separated presets to check (default draft,preview,final);
 *                       a preset may change knobs: draft:march_steps=64:prepass_budget=0
 *   --set CH=V[,V,V]    override a channel after the timeline is evaluated
 *                       (camera.position=9,2.6,36, sun.elevation=2deg); repeatable
 *   --shader-dir DIR    shaders from DIR instead of the built-in copies
 *   --ref-spp N         reference's samples per pixel (default 1)
 *   --min F             exit 1 when any preset's share is below F (0..1)
 *   --dump DIR          write DIR/<preset>_<frame>.pgm: the disagreeing pixels
 *
 * scripts/wrong-surface.sh runs it over the bundled shots; test_wrong_surface
 * checks grazing frames at 99%. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/tl_math.h"
#include "cutscene/tl_cutscene.h"
#include "render/tl_render.h"
#include "scene/tl_quality.h"
#include "shader/tl_shader_lib.h"
#include "timeline/tl_channels.h"

#define MAX_SETS    16
#define MAX_PRESETS 8
#define MAX_FRAMES  16

typedef struct {
    const tl_channel *ch;
    double v[3];
} channel_set;

typedef struct {
    channel_set knobs[MAX_SETS];
    int count;
} knob_list;

typedef struct {
    int width, height, ref_spp;
    double near_m, edge, factor, min_share;
    const char *shader_dir, *dump_dir;
    char presets[MAX_PRESETS][64];
    int preset_count;
    channel_set sets[MAX_SETS];
    int set_count;
} options;

/* "CH=V[,V,V]": components in the channel's stored units (deg accepted for
 * angles, on/off for bools). */
static int parse_set(const char *arg, channel_set *out)
{
    char name[64];
    const char *eq = strchr(arg, '=');
    if (!eq || (size_t)(eq - arg) >= sizeof name)
        return 1;
    memcpy(name, arg, (size_t)(eq - arg));
    name[eq - arg] = '\0';
    out->ch = tl_channel_find(name);
    if (!out->ch) {
        fprintf(stderr, "wrong_surface: unknown channel '%s'\n", name);
        return 1;
    }
    const char *p = eq + 1;
    for (int i = 0; i < out->ch->components; i++) {
        if (out->ch->kind == TL_CH_BOOL && (!strncmp(p, "on", 2) || !strncmp(p, "off", 3))) {
            out->v[i] = p[1] == 'n';
            p += p[1] == 'n' ? 2 : 3;
        } else {
            char *end;
            out->v[i] = strtod(p, &end);
            if (end == p)
                return 1;
            p = end;
            if (!strncmp(p, "deg", 3)) {
                out->v[i] *= TL_DEG;
                p += 3;
            } else if (!strncmp(p, "rad", 3)) {
                p += 3;
            }
        }
        if (i + 1 < out->ch->components && *p++ != ',')
            return 1;
    }
    return *p != '\0';
}

static int parse_list(const char *arg, char out[][64], int max)
{
    int n = 0;
    while (*arg && n < max) {
        size_t len = strcspn(arg, ",");
        if (len == 0 || len >= 64)
            return -1;
        memcpy(out[n], arg, len);
        out[n++][len] = '\0';
        arg += len + (arg[len] == ',');
    }
    return n;
}

/* The frame's depth plane at `quality` (spp > 0 overrides its samples). */
static int render_depth(tl_render *r, const tl_cutscene *cs, long frame, const options *o,
                        const tl_quality *quality, const knob_list *knobs, int spp, tl_frame *out)
{
    tl_render_settings settings = {
        .width = o->width, .height = o->height, .quality = quality, .spp = spp};
    tl_scene scene;
    tl_render_frame_scene(&cs->timeline, tl_timeline_frame_time(&cs->timeline, frame), &settings,
                          &scene);
    for (int i = 0; i < o->set_count; i++)
        tl_channel_set(o->sets[i].ch, &scene, o->sets[i].v);
    for (int i = 0; knobs && i < knobs->count; i++)
        tl_channel_set(knobs->knobs[i].ch, &scene, knobs->knobs[i].v);
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_scene_validate(&scene, &err);
    if (!rc)
        rc = tl_render_frame(r, &scene, out, &err);
    if (rc)
        fprintf(stderr, "wrong_surface: %s\n", err.message);
    return rc;
}

/* Reference's depth at (x, y) is away from depth edges: within +-2 pixels
 * it varies by at most a factor `edge` (the sky counts as an edge). */
static int smooth_at(const float *z, int w, int h, int x, int y, double edge)
{
    float lo = INFINITY, hi = 0.0f;
    for (int j = y - 2; j <= y + 2; j++)
        for (int i = x - 2; i <= x + 2; i++) {
            if (i < 0 || j < 0 || i >= w || j >= h)
                continue;
            float d = z[(size_t)j * w + i];
            lo = d < lo ? d : lo;
            hi = d > hi ? d : hi;
        }
    return lo > 0.0f && hi < 0.5f * TL_FRAME_SKY_DEPTH && hi <= edge * lo;
}

typedef struct {
    long counted, agree, sky, shorter, longer;
} tally;

static tally compare(const float *ref, const tl_frame *f, const options *o, unsigned char *mask)
{
    tally t = {0};
    const int w = f->width, h = f->height;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (mask)
                mask[i] = ref[i] < o->near_m ? 128 : 0;
            if (!(ref[i] < o->near_m) || !smooth_at(ref, w, h, x, y, o->edge))
                continue;
            t.counted++;
            double ratio = f->depth[i] / ref[i];
            if (f->depth[i] >= 0.5f * TL_FRAME_SKY_DEPTH) {
                t.sky++;
            } else if (ratio < 1.0 / o->factor) {
                t.shorter++;
            } else if (ratio > o->factor) {
                t.longer++;
            } else {
                t.agree++;
                continue;
            }
            if (mask)
                mask[i] = 255;
        }
    return t;
}

static void write_pgm(const char *path, const unsigned char *mask, int w, int h)
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return;
    fprintf(fp, "P5\n%d %d\n255\n", w, h);
    fwrite(mask, 1, (size_t)w * h, fp);
    fclose(fp);
}

static int usage(void)
{
    fputs("usage: wrong_surface [--size WxH] [--presets LIST] [--set CH=V]... [--shader-dir DIR]\n"
          "                     [--ref-spp N] [--min F] [--dump DIR] TIMELINE FRAME[,FRAME...]\n",
          stderr);
    return 2;
}

int main(int argc, char **argv)
{
    options o = {.width = 320,
                 .height = 180,
                 .ref_spp = 1,
                 .near_m = 2000.0,
                 .edge = 1.2,
                 .factor = 1.5,
                 .min_share = -1.0};
    o.preset_count = parse_list("draft,preview,final", o.presets, MAX_PRESETS);
    const char *positional[2] = {NULL, NULL};
    int npos = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--size") && v) {
            if (sscanf(v, "%dx%d", &o.width, &o.height) != 2 || o.width < 8 || o.height < 8)
                return usage();
            i++;
        } else if (!strcmp(a, "--presets") && v) {
            if ((o.preset_count = parse_list(v, o.presets, MAX_PRESETS)) <= 0)
                return usage();
            i++;
        } else if (!strcmp(a, "--set") && v) {
            if (o.set_count == MAX_SETS || parse_set(v, &o.sets[o.set_count++]))
                return usage();
            i++;
        } else if (!strcmp(a, "--shader-dir") && v) {
            o.shader_dir = v;
            i++;
        } else if (!strcmp(a, "--ref-spp") && v) {
            o.ref_spp = atoi(v);
            i++;
        } else if (!strcmp(a, "--min") && v) {
            o.min_share = atof(v);
            i++;
        } else if (!strcmp(a, "--dump") && v) {
            o.dump_dir = v;
            i++;
        } else if (a[0] == '-' || npos == 2) {
            return usage();
        } else {
            positional[npos++] = a;
        }
    }
    if (npos != 2)
        return usage();
    long frames[MAX_FRAMES];
    int frame_count = 0;
    for (const char *p = positional[1]; *p && frame_count < MAX_FRAMES;) {
        char *end;
        frames[frame_count++] = strtol(p, &end, 10);
        if (end == p)
            return usage();
        p = end + (*end == ',');
    }

    tl_error err;
    tl_error_clear(&err);
    tl_quality ref_q, q[MAX_PRESETS];
    knob_list knobs[MAX_PRESETS] = {0};
    if (tl_quality_preset("reference", &ref_q, &err))
        goto fail;
    for (int k = 0; k < o.preset_count; k++) {
        /* PRESET[:KNOB=V...]: the knobs are quality.KNOB channels. */
        char spec[64], *save = NULL;
        memcpy(spec, o.presets[k], sizeof spec);
        char *part = strtok_r(spec, ":", &save);
        if (tl_quality_preset(part, &q[k], &err))
            goto fail;
        while ((part = strtok_r(NULL, ":", &save))) {
            char full[80];
            snprintf(full, sizeof full, "quality.%s", part);
            if (knobs[k].count == MAX_SETS || parse_set(full, &knobs[k].knobs[knobs[k].count++]))
                return usage();
        }
    }
    tl_cutscene cs;
    tl_diags diags;
    if (tl_cutscene_load(positional[0], &cs, &diags, &err)) {
        tl_cutscene_report(stderr, "wrong_surface", &diags, &err);
        return 2;
    }
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    tl_render *r = NULL;
    if ((o.shader_dir && tl_shader_lib_from_dir(&lib, o.shader_dir, &err)) ||
        tl_render_open(&r, &lib, &err) || tl_render_use_cutscene(r, &cs, &err)) {
        tl_cutscene_free(&cs);
        if (r)
            tl_render_close(r);
        goto fail;
    }

    int below = 0, failed = 0;
    const char *name =
        strrchr(positional[0], '/') ? strrchr(positional[0], '/') + 1 : positional[0];
    size_t n = (size_t)o.width * o.height;
    unsigned char *mask = o.dump_dir ? malloc(n) : NULL;
    for (int fi = 0; fi < frame_count && !failed; fi++) {
        tl_frame ref = {0};
        if (render_depth(r, &cs, frames[fi], &o, &ref_q, NULL, o.ref_spp, &ref)) {
            failed = 1;
            break;
        }
        long near = 0;
        for (size_t i = 0; i < n; i++)
            near += ref.depth[i] < o.near_m;
        for (int k = 0; k < o.preset_count && !failed; k++) {
            tl_frame f = {0};
            if (render_depth(r, &cs, frames[fi], &o, &q[k], &knobs[k], 0, &f)) {
                failed = 1;
                break;
            }
            tally t = compare(ref.depth, &f, &o, mask);
            double share = t.counted ? (double)t.agree / (double)t.counted : 1.0;
            printf("%s:%ld %-10s %6.2f%%  of %ld (of %ld nearer than %g m); disagree: sky %ld, "
                   "short %ld, long %ld\n",
                   name, frames[fi], o.presets[k], 100.0 * share, t.counted, near, o.near_m, t.sky,
                   t.shorter, t.longer);
            below |= share < o.min_share;
            if (mask) {
                char path[1024];
                snprintf(path, sizeof path, "%s/%s_%ld.pgm", o.dump_dir, o.presets[k], frames[fi]);
                for (char *c = strrchr(path, '/') + 1; *c; c++)
                    *c = *c == ':' || *c == '=' ? '_' : *c;
                write_pgm(path, mask, f.width, f.height);
            }
            tl_frame_free(&f);
        }
        tl_frame_free(&ref);
    }
    free(mask);
    tl_render_close(r);
    tl_cutscene_free(&cs);
    if (failed)
        return 1;
    if (below)
        fprintf(stderr, "wrong_surface: a preset agrees with reference on less than %g%%\n",
                100.0 * o.min_share);
    return below;
fail:
    fprintf(stderr, "wrong_surface: %s\n", err.message);
    return 1;
}
