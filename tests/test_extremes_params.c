/* Extremes (issue 15), parameters at their ends: every channel of the
 * registry at its minimum and maximum (enums and bools at each value),
 * through a timeline, so a new channel is covered without touching this
 * file; keys 1e-6 s and 1e6 s apart; boat models of one and of 500k
 * triangles. Each frame must be finite, non-negative and displayable
 * (tl_extremes.h); ctest's timeout bounds the whole. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mesh/tl_mesh.h"
#include "timeline/tl_channels.h"
#include "timeline/tl_parse.h"
#include "timeline/tl_timeline.h"
#include "tl_extremes.h"

/* ------------------------------------------------- parameters at their ends */

typedef struct setting {
    const char *name, *value;
} setting;

/* Two scenes where every channel matters: the giant wave 49 m ahead and
 * coming, the boat 25 m ahead on its path, a light fog, the sun ahead;
 * once from 3 m above the water, once from 4 m under it looking up. */
static const setting above[] = {
    {"giant.enabled", "on"},   {"giant.center", "0 60"}, {"giant.angle", "180deg"},
    {"giant.arrival", "4s"},   {"fog.density", "0.002"}, {"camera.position", "0 3 0"},
    {"camera.pitch", "-6deg"},
};
static const setting under[] = {
    {"giant.enabled", "on"},   {"giant.center", "0 60"}, {"giant.angle", "180deg"},
    {"giant.arrival", "4s"},   {"fog.density", "0.002"}, {"camera.position", "0 -4 0"},
    {"camera.pitch", "20deg"},
};
#define BASE_COUNT ((int)(sizeof above / sizeof above[0]))

static char boat_dir[] = "/tmp/tideline-extremes-XXXXXX";
static tl_mesh builtin_boat;

/* Parses `text` as a timeline in boat_dir, loads its boat (the built-in
 * one unless it names a model) onto the renderer, evaluates it at t. */
static int eval_text(tl_renderer *r, const char *text, double t, tl_scene *s, tl_timeline *keep)
{
    char name[256];
    snprintf(name, sizeof name, "%s/extreme.tl", boat_dir);
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    if (tl_timeline_parse_text(name, text, strlen(text), &tl, &diags, &err)) {
        tl_diags_write(&diags, stdout);
        return -1;
    }
    tl_mesh mesh, *m = &builtin_boat;
    if (tl.objects[0].model[0]) {
        if (tl_mesh_load(tl.objects[0].model, &mesh, &err)) {
            printf("  %s\n", err.message);
            tl_timeline_free(&tl);
            return -1;
        }
        m = &mesh;
    }
    tl_timeline_set_object_model(&tl, 0, 0, m->bounds_min, m->bounds_max);
    int rc = tl_renderer_set_mesh(r, m, &err);
    if (rc)
        printf("  mesh: %s\n", err.message);
    if (m != &builtin_boat)
        tl_mesh_free(&mesh);
    tl_timeline_eval(&tl, t, s);
    if (keep)
        *keep = tl;
    else
        tl_timeline_free(&tl);
    return rc;
}

/* The value `v` (stored units) as the language writes it. */
static void format_value(const tl_channel *ch, double v, char *out, size_t size)
{
    const char *unit = ch->unit == TL_UNIT_ANGLE ? "rad" : ch->unit == TL_UNIT_TIME ? "s" : "";
    if (ch->kind == TL_CH_INT)
        snprintf(out, size, "%d", (int)v);
    else
        snprintf(out, size, "%.17g%s", v, unit);
}

/* One timeline per channel end: the base scene with `name` set to
 * `value` (its base setting, if any, left out). */
static void channel_end(tl_renderer *r, const setting *base, const char *where,
                        const tl_channel *ch, const char *value, const double expect[3])
{
    char text[4096];
    int n = snprintf(text, sizeof text,
                     "tideline 1\nduration 10s\nsize 16x9\npath boat\n  0s 0 20\n  10s 0 30\n");
    for (int i = 0; i < BASE_COUNT; i++)
        if (strcmp(base[i].name, ch->name) != 0)
            n += snprintf(text + n, sizeof text - (size_t)n, "set %s %s\n", base[i].name,
                          base[i].value);
    snprintf(text + n, sizeof text - (size_t)n, "set %s %s\n", ch->name, value);
    char label[200];
    snprintf(label, sizeof label, "%s %s (%s)", ch->name, value, where);
    tl_scene s;
    if (eval_text(r, text, 5.0, &s, NULL)) {
        printf("  %s: the timeline is refused\n", label);
        CHECK(0);
        return;
    }
    /* The scene holds the value as written: nothing clamps a channel's
     * value inside its documented range. */
    double got[3];
    tl_channel_get(ch, &s, got);
    int same = 1;
    for (int c = 0; c < ch->components; c++)
        same &= fabs(got[c] - expect[c]) <= 1e-12 * fmax(1.0, fabs(expect[c]));
    if (!same)
        printf("  %s: the scene holds %.17g\n", label, got[0]);
    CHECK(same);
    render_checked(r, &s, label, NULL);
}

static void test_channel_ends(tl_renderer *r)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_mesh_default_boat(&builtin_boat, &err) == 0);
    int ends = 0, channels = 0;
    for (int b = 0; b < 2; b++) {
        const setting *base = b ? under : above;
        const char *where = b ? "under water" : "above water";
        for (int i = 0; tl_channel_at(i); i++) {
            const tl_channel *ch = tl_channel_at(i);
            char value[160];
            double v[3];
            channels += b == 0;
            switch (ch->kind) {
            case TL_CH_BOOL:
                for (int k = 0; k < 2; k++) {
                    v[0] = k;
                    channel_end(r, base, where, ch, k ? "on" : "off", v);
                    ends++;
                }
                break;
            case TL_CH_ENUM:
                for (int k = 0; ch->names[k]; k++) {
                    v[0] = k;
                    channel_end(r, base, where, ch, ch->names[k], v);
                    ends++;
                }
                break;
            case TL_CH_INT:
            case TL_CH_REAL:
                for (int end = 0; end < 2; end++) {
                    double x = end ? ch->max : ch->min;
                    char one[64];
                    format_value(ch, x, one, sizeof one);
                    value[0] = '\0';
                    for (int c = 0; c < ch->components; c++) {
                        v[c] = ch->kind == TL_CH_INT ? (double)(int)x : x;
                        strcat(value, c ? " " : "");
                        strcat(value, one);
                    }
                    channel_end(r, base, where, ch, value, v);
                    ends++;
                }
                break;
            }
        }
    }
    printf("%d channels: %d ends and values rendered above and under the water\n", channels, ends);
    tl_mesh_free(&builtin_boat);
}

/* Keys a microsecond apart and a million seconds apart, with every kind of
 * segment: the curves stay finite and inside their channel's range, the
 * ones that do not overshoot by design stay between their keys (elastic
 * eases swing even a component whose keys are equal, as Blender's do; a
 * spline's Bessel tangent at a key between a 1e-6 s and a 5 s segment is
 * the short one's slope, and the long segment bulges by about that slope
 * times its length: documented in docs/precision.md), and the frames
 * between them render. */
static void test_keys(tl_renderer *r)
{
    const char *const interps[] = {
        "bezier", "linear", "spline", "ease-out-back", "ease-in-out-elastic", "ease-in-out-expo"};
    const struct {
        const char *name, *k1, *k2, *duration;
        double t[5];
    } spans[] = {
        {"1e-6 s", "0.000001s", "5s", "10s", {0.0, 2.5e-7, 5e-7, 1e-6, 3.0}},
        {"1e6 s", "1000000s", "10000000s", "10000000s", {0.0, 5e5, 1e6, 5e6, 1e7}},
    };
    const tl_channel *pos = tl_channel_find("camera.position");
    const tl_channel *sun = tl_channel_find("sun.elevation");
    for (int k = 0; k < 2; k++)
        for (size_t i = 0; i < sizeof interps / sizeof interps[0]; i++) {
            char text[1024];
            snprintf(text, sizeof text,
                     "tideline 1\nduration %s\nsize 32x18\n"
                     "key camera.position %s\n  0s 0 2 0\n  %s 0 2 1\n  %s 0 3 2\n"
                     "key sun.elevation %s\n  0s 10deg\n  %s 40deg\n  %s -10deg\n",
                     spans[k].duration, interps[i], spans[k].k1, spans[k].k2, interps[i],
                     spans[k].k1, spans[k].k2);
            int spline = strcmp(interps[i], "spline") == 0;
            int overshoots = spline || strstr(interps[i], "elastic") || strstr(interps[i], "back");
            double reach = 0.0;
            for (int j = 0; j < 5; j++) {
                tl_scene s;
                if (eval_text(r, text, spans[k].t[j], &s, NULL)) {
                    CHECK(0);
                    break;
                }
                const double *p = s.camera.position;
                int ok = isfinite(s.sun.elevation) && s.sun.elevation >= sun->min &&
                         s.sun.elevation <= sun->max;
                for (int c = 0; c < 3; c++)
                    ok &= isfinite(p[c]) && p[c] >= pos->min && p[c] <= pos->max;
                if (!overshoots)
                    ok &= p[0] == 0.0 && p[1] >= 2.0 && p[1] <= 3.0 && p[2] >= 0.0 && p[2] <= 2.0;
                else if (!spline) /* the eases swing by less than their keys' span */
                    ok &= fabs(p[0]) < 1.0 && fabs(p[1] - 2.5) < 1.5 && fabs(p[2] - 1.0) < 2.0;
                reach = fmax(reach, fabs(p[2] - 1.0));
                char label[160];
                snprintf(label, sizeof label, "keys %s apart, %s, t = %g s", spans[k].name,
                         interps[i], spans[k].t[j]);
                if (!ok)
                    printf("  %s: camera at %g %g %g, sun at %g\n", label, p[0], p[1], p[2],
                           s.sun.elevation);
                CHECK(ok);
                if (j == 1 || j == 4)
                    render_checked(r, &s, label, NULL);
            }
            if (spline)
                printf("  keys %s apart, spline: the camera's z strays up to %.3g m from the "
                       "keys' middle\n",
                       spans[k].name, reach);
        }
}

/* Writes an OBJ of `rings` x `segments` quads (two triangles each) on an
 * ellipsoid 8 m long, 3 m wide and 2 m high, its middle on the
 * waterline; rings = 0 writes one triangle. */
static int write_obj(const char *path, int rings, int segments)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    if (rings == 0) {
        fprintf(f, "v -1 0 -2\nv 1 0 -2\nv 0 1 2\nf 1 2 3\n");
    } else {
        for (int i = 0; i <= rings; i++) {
            double th = M_PI * i / rings;
            for (int j = 0; j < segments; j++) {
                double ph = 2.0 * M_PI * j / segments;
                fprintf(f, "v %.6f %.6f %.6f\n", 1.5 * sin(th) * cos(ph), 1.0 * sin(th) * sin(ph),
                        4.0 * cos(th));
            }
        }
        for (int i = 0; i < rings; i++)
            for (int j = 0; j < segments; j++) {
                int a = i * segments + j + 1, b = i * segments + (j + 1) % segments + 1;
                int c = a + segments, d = b + segments;
                fprintf(f, "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d);
            }
    }
    return fclose(f);
}

static void test_boats(tl_renderer *r)
{
    const struct {
        const char *file;
        int rings, segments;
        long triangles;
    } boats[] = {{"one.obj", 0, 0, 1}, {"many.obj", 500, 500, 500000}};
    for (int b = 0; b < 2; b++) {
        char path[256];
        snprintf(path, sizeof path, "%s/%s", boat_dir, boats[b].file);
        double t0 = now();
        CHECK(write_obj(path, boats[b].rings, boats[b].segments) == 0);
        char text[1024];
        snprintf(text, sizeof text,
                 "tideline 1\nduration 10s\nsize 64x36\npath boat\n  0s 0 20\n  10s 0 30\n"
                 "set boat.model %s\nset camera.position 0 3 0\nset camera.pitch -6deg\n",
                 boats[b].file);
        tl_scene s;
        tl_timeline tl;
        if (eval_text(r, text, 5.0, &s, &tl)) {
            CHECK(0);
            continue;
        }
        tl_timeline_free(&tl);
        tl_mesh mesh;
        tl_error err;
        tl_error_clear(&err);
        if (tl_mesh_load(path, &mesh, &err) == 0) {
            CHECK((long)mesh.index_count == 3 * boats[b].triangles);
            int finite = 1;
            for (size_t i = 0; i < mesh.vertex_count * 3; i++)
                finite &= isfinite(mesh.positions[i]) && isfinite(mesh.normals[i]);
            CHECK(finite);
            tl_mesh_free(&mesh);
        } else {
            CHECK(0);
        }
        /* The boat is in view: the frame draws it. */
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &w, &u);
        CHECK(u.features & TL_FEATURE_BOAT);
        char label[160];
        snprintf(label, sizeof label, "a boat of %ld triangles", boats[b].triangles);
        render_checked(r, &s, label, NULL);
        printf("  %s: written, loaded, floated and rendered in %.1f s\n", label, now() - t0);
        CHECK(isfinite(s.boat.position[1]) && isfinite(s.boat.pitch) && isfinite(s.boat.roll));
        remove(path);
    }
    tl_renderer_set_mesh(r, NULL, NULL);
}

/* argv[1], when given, runs half the cases: `channels` (every channel at
 * its ends) or `keys` (keys far apart and close, boats small and large).
 * ctest runs the halves as two tests, so that neither is a slow test. */
int main(int argc, char **argv)
{
    const char *part = argc > 1 ? argv[1] : "all";
    int channels = !strcmp(part, "all") || !strcmp(part, "channels");
    int keys = !strcmp(part, "all") || !strcmp(part, "keys");
    if (!channels && !keys) {
        fprintf(stderr, "usage: test_extremes_params [channels|keys]\n");
        return 2;
    }
    double start = now();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    if (mkdtemp(boat_dir)) {
        double t0 = now();
        if (channels) {
            test_channel_ends(r);
            printf("[channel ends: %.1f s]\n", now() - t0);
        }
        t0 = now();
        if (keys) {
            test_keys(r);
            test_boats(r);
            printf("[keys and boats: %.1f s]\n", now() - t0);
        }
        rmdir(boat_dir);
    } else {
        CHECK(0);
    }
    printf("%d frames; slowest %.2f s (%s); %.1f s in all\n", renders, slowest_render,
           slowest_label, now() - start);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
