/* The timeline parser: a file, line by line, into a tl_timeline; its
 * directives and the `key` and `path` blocks (options of `key` lines in
 * tl_parse_keys.c, values in tl_parse_values.c, `look` and `follow` in
 * tl_parse_links.c, diagnostics in tl_parse_diag.c, whole-file checks in
 * tl_parse_checks.c). */
#include "tl_parse.h"
#include "tl_parse_internal.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "color/tl_color.h"
#include "passes/tl_passes.h"

static const char *const directives[] = {
    "tideline", "fps",  "duration", "size", "quality", "passes", "working_space", "set", "key",
    "path",     "look", "follow",   "boat", "audio",   NULL};
static const char *const key_words[] = {
    "cut",           "constant",         "step",    "linear",    "bezier", "spline", "auto-clamped",
    "auto",          "vector",           "aligned", "free",      "left",   "right",  "ease-in-sine",
    "ease-out-sine", "ease-in-out-sine", "back",    "amplitude", "period", NULL};

static int parse_time(parser *p, const token *t, double *out)
{
    return tl_parse_quantity(p, t, TL_UNIT_TIME, out);
}

/* ---- blocks ---- */

static int remember_key_line(parser *p, const token *first)
{
    if (p->key_count == p->key_cap) {
        size_t cap = p->key_cap ? p->key_cap * 2 : 64;
        struct key_source *k = realloc(p->key_lines, cap * sizeof *k);
        if (!k)
            return 1;
        p->key_lines = k;
        p->key_cap = cap;
    }
    p->key_lines[p->key_count++] =
        (struct key_source){p->line_no, p->line_text, p->line_len, first->col};
    return 0;
}

/* Skips "key N: " / "point N: " prefixes of engine messages: the
 * diagnostic already points at the line. */
static const char *strip_index_prefix(const char *msg)
{
    const char *colon = strstr(msg, ": ");
    if (colon && (strncmp(msg, "key ", 4) == 0 || strncmp(msg, "point ", 6) == 0))
        return colon + 2;
    return msg;
}

static void finish_block(parser *p)
{
    if (p->block == BLOCK_KEY && !p->block_failed) {
        tl_track *tr = p->block_track;
        if (tr->curve[0].count == 0) {
            tl_parse_diag_at_line(p, p->block_line, NULL,
                                  "%s has no keys (indent key lines under it)", p->block_ch->name);
        } else {
            for (int c = 0; c < p->block_ch->components; c++) {
                size_t bad = 0;
                tl_error e;
                tl_error_clear(&e);
                if (tl_curve_validate(&tr->curve[c], &bad, &e)) {
                    const struct key_source *src = bad < p->key_count ? &p->key_lines[bad] : NULL;
                    tl_parse_diag_at_line(p, src ? src->line : p->block_line, src, "%s",
                                          strip_index_prefix(e.message));
                    break;
                }
                if (p->block_shortest)
                    tl_curve_unwrap(&tr->curve[c], 2.0 * M_PI);
                tl_curve_prepare(&tr->curve[c]);
            }
        }
    } else if (p->block == BLOCK_PATH && !p->block_failed) {
        tl_path *path = &p->block_path->path;
        size_t bad = 0;
        tl_error e;
        tl_error_clear(&e);
        if (path->count == 0) {
            tl_parse_diag_at_line(p, p->block_line, NULL, "%s",
                                  "path has no points (indent them under it)");
        } else if (tl_path_validate(path, &bad, &e)) {
            const struct key_source *src = bad < p->key_count ? &p->key_lines[bad] : NULL;
            tl_parse_diag_at_line(p, src ? src->line : p->block_line, src, "%s",
                                  strip_index_prefix(e.message));
        } else if (tl_path_prepare(path, &e)) {
            tl_parse_diag_at_line(p, p->block_line, NULL, "%s", e.message);
        }
    }
    p->block = BLOCK_NONE;
    p->key_count = 0;
    p->block_failed = 0;
}

static int count_key(parser *p, const token *t)
{
    if (++p->keys_total > TL_PARSE_MAX_KEYS) {
        ERR_AT(t, "more than %d keys and path points; split the timeline", TL_PARSE_MAX_KEYS);
        p->stopped = 1;
        return 1;
    }
    return 0;
}

/* `TIME [cut] V... [interp] [handle type] [left DT V...] [right DT V...]` */
static void key_line(parser *p, token *tok, int n)
{
    const tl_channel *ch = p->block_ch;
    int i = 0;
    double t;
    if (tl_parse_unit_after_space(p, tok, n, 0) || count_key(p, &tok[0]) ||
        parse_time(p, &tok[i++], &t)) {
        p->block_failed = 1;
        return;
    }
    if (p->saw_duration && t > p->tl->duration * (1.0 + 1e-12) && !p->block_track->past_end)
        tl_parse_warn_past_end(p, &tok[0], t);
    int cut = 0;
    if (i < n && strcmp(tok[i].s, "cut") == 0) {
        cut = 1;
        i++;
    }
    double v[3];
    for (int c = 0; c < ch->components; c++, i++) {
        if (i >= n) {
            tl_parse_diag(p, tok[n - 1].col + tok[n - 1].len, 1, NULL,
                          "%s needs %d value%s per key, found %d", ch->name, ch->components,
                          ch->components > 1 ? "s" : "", c);
            p->block_failed = 1;
            return;
        }
        if (tl_parse_channel_value(p, ch, &tok[i], &v[c])) {
            p->block_failed = 1;
            return;
        }
    }
    tl_interp interp = p->block_interp;
    tl_ease_family family = p->block_family;
    tl_ease_dir dir = p->block_dir;
    tl_handle_type htype = TL_HANDLE_AUTO_CLAMPED;
    int has_htype = 0;
    tl_handle_side left = {0}, right = {0};
    tl_ease_params ease = p->block_ease;
    for (; i < n; i++) {
        tl_handle_type h;
        int got;
        if (tl_interp_from_name(tok[i].s, &interp) || strcmp(tok[i].s, "step") == 0) {
            if (strcmp(tok[i].s, "step") == 0)
                interp = TL_INTERP_CONSTANT;
        } else if (tl_ease_from_name(tok[i].s, &family, &dir)) {
            interp = TL_INTERP_EASE;
        } else if (tl_handle_type_from_name(tok[i].s, &h)) {
            htype = h;
            has_htype = 1;
        } else if ((got = tl_parse_handle_side(p, ch, tok, n, &i, &left, &right)) != 0 ||
                   (got = tl_parse_ease_setting(p, ch, tok, n, &i, &ease)) != 0) {
            if (got < 0) {
                p->block_failed = 1;
                return;
            }
        } else if (strcmp(tok[i].s, "cut") == 0) {
            ERR_AT(&tok[i], "'cut' goes right after the key's time");
            p->block_failed = 1;
            return;
        } else if (isdigit((unsigned char)tok[i].s[0]) || tok[i].s[0] == '-' ||
                   tok[i].s[0] == '+' || tok[i].s[0] == '.') {
            ERR_AT(&tok[i], "%s takes %d value%s per key; '%s' is one too many", ch->name,
                   ch->components, ch->components > 1 ? "s" : "", tok[i].s);
            p->block_failed = 1;
            return;
        } else {
            const char *words[sizeof key_words / sizeof key_words[0] + TL_EASE_NAME_COUNT];
            tl_parse_diag(p, tok[i].col, tok[i].len,
                          tl_suggest(tok[i].s, tl_parse_with_ease_names(key_words, words)),
                          "unknown key option '%s'", tok[i].s);
            p->block_failed = 1;
            return;
        }
    }
    if (ch->kind != TL_CH_REAL && interp != TL_INTERP_CONSTANT) {
        if (interp != p->block_interp) {
            ERR_AT(&tok[0], "%s changes in steps; its keys take no interpolation", ch->name);
            p->block_failed = 1;
            return;
        }
        interp = TL_INTERP_CONSTANT;
    }
    /* An offset without a named type makes the handles free; a type named
     * for one side overrides the key's type there. */
    if ((left.has_offset || right.has_offset) && !has_htype)
        htype = TL_HANDLE_FREE;
    if (remember_key_line(p, &tok[0])) {
        ERR_AT(&tok[0], "out of memory");
        p->stopped = 1;
        return;
    }
    for (int c = 0; c < ch->components; c++) {
        tl_key k = tl_key_make(t, v[c], interp);
        k.ease_family = family;
        k.ease_dir = dir;
        k.left_type = left.has_type ? left.type : htype;
        k.right_type = right.has_type ? right.type : htype;
        k.cut = cut;
        k.ease = ease;
        if (left.has_offset)
            k.left = (tl_curve_point){t + left.offset[0], v[c] + left.offset[1 + c]};
        if (right.has_offset)
            k.right = (tl_curve_point){t + right.offset[0], v[c] + right.offset[1 + c]};
        tl_error e;
        if (tl_curve_add_key(&p->block_track->curve[c], &k, &e)) {
            ERR_AT(&tok[0], "%s", e.message);
            p->stopped = 1;
            return;
        }
    }
}

/* `TIME X Z` (boat) or `TIME X Y Z` (camera). */
static void path_line(parser *p, token *tok, int n)
{
    double t, pos[3] = {0, 0, 0};
    if (count_key(p, &tok[0]) || parse_time(p, &tok[0], &t)) {
        p->block_failed = 1;
        return;
    }
    if (n - 1 != p->block_dims) {
        tl_parse_diag(p, tok[n - 1].col, tok[n - 1].len, NULL,
                      "a %s path point is TIME %s, found %d "
                      "value%s",
                      p->block_dims == 2 ? "boat" : "camera", p->block_dims == 2 ? "X Z" : "X Y Z",
                      n - 1, n - 1 == 1 ? "" : "s");
        p->block_failed = 1;
        return;
    }
    int axis[3] = {0, 2, 1}; /* boat: x z; camera: x y z */
    for (int i = 0; i < p->block_dims; i++) {
        int a = p->block_dims == 2 ? axis[i] : i;
        if (tl_parse_quantity(p, &tok[1 + i], TL_UNIT_LENGTH, &pos[a])) {
            p->block_failed = 1;
            return;
        }
        if (fabs(pos[a]) > 1e9) {
            ERR_AT(&tok[1 + i], "position '%s' is out of range (|x| <= 1e9 m)", tok[1 + i].s);
            p->block_failed = 1;
            return;
        }
    }
    tl_error e;
    if (remember_key_line(p, &tok[0]) || tl_path_add_point(&p->block_path->path, t, pos, &e)) {
        ERR_AT(&tok[0], "out of memory");
        p->stopped = 1;
    }
}

/* ---- directives ---- */

int tl_parse_expect_args(parser *p, token *tok, int n, int min, int max, const char *usage)
{
    if (n - 1 < min) {
        tl_parse_diag(p, tok[n - 1].col + tok[n - 1].len, 1, NULL, "'%s' expects %s", tok[0].s,
                      usage);
        return 1;
    }
    if (n - 1 > max) {
        tl_parse_diag(p, tok[max + 1].col, tok[max + 1].len, NULL,
                      "unexpected '%s': '%s' expects %s", tok[max + 1].s, tok[0].s, usage);
        return 1;
    }
    return 0;
}

/* The floating object a channel or path names: `NAME` of `NAME.field`
 * (len characters of t), -1 when it is none. */
static int object_named(const parser *p, const char *name, size_t len)
{
    char word[TL_OBJECT_NAME_MAX];
    if (len == 0 || len >= sizeof word)
        return -1;
    memcpy(word, name, len);
    word[len] = '\0';
    return tl_timeline_object(p->tl, word);
}

/* The object names, for suggestions. */
static void object_names(const parser *p, const char *names[TL_OBJECT_MAX + 1])
{
    for (int k = 0; k < p->tl->object_count; k++)
        names[k] = p->tl->objects[k].name;
    names[p->tl->object_count] = NULL;
}

/* A channel: a scene channel, or `NAME.field` of a floating object, which
 * is the `boat.field` channel of object *object. */
static const tl_channel *lookup_channel(parser *p, const token *t, int *object)
{
    *object = 0;
    const char *dot = strchr(t->s, '.');
    int k = dot ? object_named(p, t->s, (size_t)(dot - t->s)) : -1;
    if (k > 0) {
        char name[128];
        snprintf(name, sizeof name, "boat%s", dot);
        const tl_channel *ch = tl_channel_find(name);
        if (!ch) {
            const char *hint = tl_channel_suggest(name);
            char suggestion[128];
            if (hint && strncmp(hint, "boat.", 5) == 0)
                snprintf(suggestion, sizeof suggestion, "%s%s", p->tl->objects[k].name, hint + 4);
            tl_parse_diag(p, t->col, t->len,
                          hint && strncmp(hint, "boat.", 5) == 0 ? suggestion : NULL,
                          "'%s' has no channel '%s' (floating objects have the boat.* channels)",
                          p->tl->objects[k].name, dot + 1);
        }
        *object = k;
        return ch;
    }
    const tl_channel *ch = tl_channel_find(t->s);
    if (!ch)
        tl_parse_diag(p, t->col, t->len, tl_channel_suggest(t->s), "unknown channel '%s'", t->s);
    return ch;
}

static tl_track *claim_track(parser *p, const tl_channel *ch, int object, const token *t)
{
    tl_track *tr = tl_timeline_track(p->tl, tl_channel_index(ch), object);
    if (tr->state != TL_TRACK_DEFAULT) {
        ERR_AT(t, "%s is already %s on line %d", t->s, tr->state == TL_TRACK_SET ? "set" : "keyed",
               tr->line);
        return NULL;
    }
    tr->line = p->line_no;
    return tr;
}

/* `set NAME.model PATH` (`boat.model` for the boat): the file is loaded
 * by the commands that need it (check, eval, still, render), which report
 * its errors at this line. */
static void set_object_model(parser *p, token *tok, int n, int object)
{
    if (n != 3) {
        ERR_AT(&tok[n - 1], "%s takes one path (no spaces), found %d words", tok[1].s, n - 2);
        return;
    }
    tl_object *o = &p->tl->objects[object];
    if (o->model_line) {
        ERR_AT(&tok[1], "%s is already set on line %d", tok[1].s, o->model_line);
        return;
    }
    if (tl_parse_file_path(p, &tok[2], tok[1].s, o->model, sizeof o->model))
        return;
    o->model_line = p->line_no;
    o->model_column = tok[2].col;
}

static void dir_set(parser *p, token *tok, int n)
{
    if (tl_parse_expect_args(p, tok, n, 2, MAX_TOKENS, "a channel and its value"))
        return;
    const char *dot = strchr(tok[1].s, '.');
    int named = dot ? object_named(p, tok[1].s, (size_t)(dot - tok[1].s)) : -1;
    if (named >= 0 && strcmp(dot, ".model") == 0) {
        set_object_model(p, tok, n, named);
        return;
    }
    int object;
    const tl_channel *ch = lookup_channel(p, &tok[1], &object);
    if (!ch)
        return;
    if (tl_parse_unit_after_space(p, tok, n, 2))
        return;
    /* `set render.exposure auto`: the metered exposure at full strength
     * (render.auto_exposure 1; its track, so that setting both is caught). */
    if (strcmp(ch->name, "render.exposure") == 0 && n == 3 && strcmp(tok[2].s, "auto") == 0) {
        const tl_channel *strength = tl_channel_find("render.auto_exposure");
        tl_track *tr = tl_timeline_track(p->tl, tl_channel_index(strength), object);
        if (tr->state != TL_TRACK_DEFAULT) {
            ERR_AT(&tok[2], "render.auto_exposure is already %s on line %d",
                   tr->state == TL_TRACK_SET ? "set" : "keyed", tr->line);
            return;
        }
        tr->line = p->line_no;
        tr->state = TL_TRACK_SET;
        tr->value[0] = 1.0;
        return;
    }
    char *number_end = NULL;
    if (strcmp(ch->name, "render.exposure") == 0 && n == 3 && isalpha((unsigned char)tok[2].s[0]) &&
        (strtod(tok[2].s, &number_end), number_end) == tok[2].s) {
        /* a word, not nan or inf (the number's own messages) */
        static const char *const words[] = {"auto", NULL};
        tl_parse_diag(p, tok[2].col, tok[2].len, tl_suggest(tok[2].s, words),
                      "render.exposure takes a number or 'auto', got '%s'", tok[2].s);
        return;
    }
    if (n - 2 != ch->components) {
        tl_parse_diag(p, tok[n - 1].col, tok[n - 1].len, NULL, "%s takes %d value%s, found %d",
                      tok[1].s, ch->components, ch->components > 1 ? "s" : "", n - 2);
        return;
    }
    double v[3] = {0, 0, 0};
    for (int c = 0; c < ch->components; c++)
        if (tl_parse_channel_value(p, ch, &tok[2 + c], &v[c]))
            return;
    tl_track *tr = claim_track(p, ch, object, &tok[1]);
    if (!tr)
        return;
    /* Render-setting channels (quality.*) apply on top of the preset at
     * evaluation, wherever the `quality` line is. */
    tr->state = TL_TRACK_SET;
    memcpy(tr->value, v, sizeof v);
}

/* `boat NAME`: declares a floating object, whose channels are then
 * NAME.size, NAME.wake ... (the boat.* channels), with `path NAME`. */
static void dir_boat(parser *p, token *tok, int n)
{
    if (tl_parse_expect_args(p, tok, n, 1, 1, "a name for the floating object"))
        return;
    const token *t = &tok[1];
    int valid = isalpha((unsigned char)t->s[0]) && t->len < TL_OBJECT_NAME_MAX;
    for (int i = 0; valid && t->s[i]; i++)
        valid = isalnum((unsigned char)t->s[i]) || t->s[i] == '_';
    if (!valid) {
        ERR_AT(t,
               "'%s' is not a name for a floating object: letters, digits and '_', starting "
               "with a letter, at most %d characters",
               t->s, TL_OBJECT_NAME_MAX - 1);
        return;
    }
    /* Not a name the language gives another meaning. */
    static const char *const taken[] = {"camera",     "sun",   "ocean",   "water",  "sky", "fog",
                                        "underwater", "giant", "quality", "render", "at",  NULL};
    for (int i = 0; taken[i]; i++)
        if (strcmp(t->s, taken[i]) == 0) {
            ERR_AT(t, "'%s' names the %s channels; choose another name for the object", t->s, t->s);
            return;
        }
    if (tl_channel_find(t->s)) {
        ERR_AT(t, "'%s' is a channel; choose another name for the object", t->s);
        return;
    }
    int k = tl_timeline_object(p->tl, t->s);
    if (k == 0) {
        ERR_AT(t, "'boat' is the timeline's boat, there from the start: name the other objects");
        return;
    }
    if (k > 0) {
        ERR_AT(t, "a floating object named '%s' is already declared on line %d", t->s,
               p->tl->objects[k].line);
        return;
    }
    if (p->tl->object_count >= TL_OBJECT_MAX) {
        ERR_AT(t, "a timeline holds at most %d floating objects (the boat and %d more)",
               TL_OBJECT_MAX, TL_OBJECT_MAX - 1);
        return;
    }
    if (tl_timeline_add_object(p->tl, t->s, p->line_no, t->col) < 0)
        ERR_AT(t, "out of memory");
}

static void dir_key(parser *p, token *tok, int n)
{
    if (n < 2) {
        tl_parse_diag(p, tok[0].col + tok[0].len, 1, NULL, "'key' expects a channel name");
        return;
    }
    int object;
    const tl_channel *ch = lookup_channel(p, &tok[1], &object);
    if (!ch)
        return;
    if (!ch->keyable) {
        ERR_AT(&tok[1], "%s is a render setting: use 'set', not 'key'", ch->name);
        return;
    }
    tl_interp interp = TL_INTERP_BEZIER;
    tl_ease_family family = TL_EASE_SINE;
    tl_ease_dir dir = TL_EASE_IN_OUT;
    tl_curve shape; /* extrapolation and smoothing for every component */
    tl_curve_init(&shape);
    tl_ease_params ease = tl_key_make(0.0, 0.0, TL_INTERP_EASE).ease;
    int shortest = 0;
    bool baked = false; /* keys an exporter sampled at every frame (tideline check lists them) */
    for (int i = 2; i < n; i++) {
        int got;
        if (tl_interp_from_name(tok[i].s, &interp)) {
        } else if (strcmp(tok[i].s, "step") == 0) {
            interp = TL_INTERP_CONSTANT;
        } else if (tl_ease_from_name(tok[i].s, &family, &dir)) {
            interp = TL_INTERP_EASE;
        } else if ((got = tl_parse_curve_option(p, tok, n, &i, &shape)) != 0 ||
                   (got = tl_parse_ease_setting(p, ch, tok, n, &i, &ease)) != 0) {
            if (got < 0)
                return;
        } else if (strcmp(tok[i].s, "baked") == 0) {
            baked = true;
        } else if (strcmp(tok[i].s, "shortest") == 0) {
            if (ch->unit != TL_UNIT_ANGLE) {
                ERR_AT(&tok[i], "'shortest' applies to angle channels; %s is not one", ch->name);
                return;
            }
            shortest = 1;
        } else {
            static const char *const opts[] = {"extrapolate", "before", "after",  "smoothing",
                                               "shortest",    "linear", "bezier", "spline",
                                               "constant",    "step",   "back",   "amplitude",
                                               "period",      "baked",  "ease",   NULL};
            const char *words[sizeof opts / sizeof opts[0] + TL_EASE_NAME_COUNT];
            tl_parse_diag(p, tok[i].col, tok[i].len,
                          tl_suggest(tok[i].s, tl_parse_with_ease_names(opts, words)),
                          "unknown option '%s' for 'key'", tok[i].s);
            return;
        }
    }
    if (ch->kind != TL_CH_REAL)
        interp = TL_INTERP_CONSTANT;
    tl_track *tr = claim_track(p, ch, object, &tok[1]);
    if (!tr)
        return;
    tr->state = TL_TRACK_KEYED;
    tr->baked = baked;
    for (int c = 0; c < ch->components; c++) {
        tl_curve *cv = &tr->curve[c];
        cv->before = shape.before;
        cv->after = shape.after;
        cv->before_cycles = shape.before_cycles;
        cv->after_cycles = shape.after_cycles;
        cv->smoothing = shape.smoothing;
        cv->fps = p->tl->fps;
    }
    if (!p->first_key_line)
        p->first_key_line = p->line_no;
    p->block_ease = ease;
    p->block = BLOCK_KEY;
    p->block_line = p->line_no;
    p->block_ch = ch;
    p->block_track = tr;
    p->block_interp = interp;
    p->block_family = family;
    p->block_dir = dir;
    p->block_shortest = shortest;
}

static void dir_path(parser *p, token *tok, int n)
{
    if (tl_parse_expect_args(
            p, tok, n, 1, 3,
            "boat, camera or a floating object's name, then optionally constant-speed "
            "and baked"))
        return;
    tl_path_track *pt;
    int dims;
    int object = tl_timeline_object(p->tl, tok[1].s);
    if (object >= 0) {
        pt = &p->tl->objects[object].path;
        dims = 2;
    } else if (strcmp(tok[1].s, "camera") == 0) {
        pt = &p->tl->camera_path;
        dims = 3;
    } else {
        const char *names[TL_OBJECT_MAX + 2];
        object_names(p, names);
        names[p->tl->object_count] = "camera";
        names[p->tl->object_count + 1] = NULL;
        tl_parse_diag(p, tok[1].col, tok[1].len, tl_suggest(tok[1].s, names),
                      "paths are for 'camera', 'boat' or a floating object declared before "
                      "them with 'boat NAME', not '%s'",
                      tok[1].s);
        return;
    }
    bool constant_speed = false, baked = false;
    for (int i = 2; i < n; i++) {
        if (strcmp(tok[i].s, "constant-speed") == 0) {
            constant_speed = true;
        } else if (strcmp(tok[i].s, "baked") == 0) {
            baked = true;
        } else {
            static const char *const opts[] = {"constant-speed", "baked", NULL};
            tl_parse_diag(p, tok[i].col, tok[i].len, tl_suggest(tok[i].s, opts),
                          "unknown path option '%s'", tok[i].s);
            return;
        }
    }
    if (pt->present) {
        ERR_AT(&tok[1], "the %s already has a path on line %d", tok[1].s, pt->line);
        return;
    }
    pt->present = true;
    pt->path.constant_speed = constant_speed;
    pt->baked = baked;
    pt->line = p->line_no;
    p->block = BLOCK_PATH;
    p->block_line = p->line_no;
    p->block_path = pt;
    p->block_dims = dims;
}

static void directive(parser *p, token *tok, int n)
{
    const char *d = tok[0].s;
    if (!p->saw_header && strcmp(d, "tideline") != 0) {
        ERR_AT(&tok[0], "a timeline starts with the line 'tideline 1'");
        p->saw_header = 1; /* report it once, then read on */
    }
    if (strcmp(d, "tideline") == 0 || strcmp(d, "fps") == 0 || strcmp(d, "duration") == 0 ||
        strcmp(d, "size") == 0 || strcmp(d, "quality") == 0 || strcmp(d, "passes") == 0 ||
        strcmp(d, "working_space") == 0)
        tl_parse_dir_header(p, tok, n);
    else if (strcmp(d, "set") == 0)
        dir_set(p, tok, n);
    else if (strcmp(d, "key") == 0)
        dir_key(p, tok, n);
    else if (strcmp(d, "path") == 0)
        dir_path(p, tok, n);
    else if (strcmp(d, "look") == 0)
        tl_parse_dir_look(p, tok, n);
    else if (strcmp(d, "follow") == 0)
        tl_parse_dir_follow(p, tok, n);
    else if (strcmp(d, "boat") == 0)
        dir_boat(p, tok, n);
    else if (strcmp(d, "audio") == 0)
        tl_parse_dir_audio(p, tok, n);
    else
        tl_parse_diag(p, tok[0].col, tok[0].len, tl_suggest(d, directives),
                      "unknown directive '%s'", d);
}

/* ---- lines ---- */

static void parse_line(parser *p, const char *text, size_t len)
{
    char *buf = p->buf;
    token tok[MAX_TOKENS];
    p->line_text = text;
    p->line_len = len;
    if (len > TL_PARSE_MAX_LINE) {
        p->line_text = NULL; /* no excerpt: the caret would sit past its end */
        p->line_len = 0;
        tl_parse_diag(p, TL_PARSE_MAX_LINE + 1, 1, NULL, "line is longer than %d characters",
                      TL_PARSE_MAX_LINE);
        return;
    }
    memcpy(buf, text, len);
    buf[len] = '\0';
    int n = tl_parse_tokenize(p, buf, len, tok);
    if (n <= 0)
        return;
    int indented = text[0] == ' ' || text[0] == '\t';
    if (indented) {
        if (p->block == BLOCK_SKIP)
            return;
        if (p->block == BLOCK_KEY)
            key_line(p, tok, n);
        else if (p->block == BLOCK_PATH)
            path_line(p, tok, n);
        else
            ERR_AT(&tok[0], "indented line outside a 'key' or 'path' block");
        return;
    }
    finish_block(p);
    /* A rejected key/path line still owns the indented lines below it. */
    if (strcmp(tok[0].s, "key") == 0 || strcmp(tok[0].s, "path") == 0)
        p->block = BLOCK_SKIP;
    directive(p, tok, n);
}
int tl_timeline_parse_text(const char *name, const char *text, size_t length, tl_timeline *out,
                           tl_diags *diags, tl_error *err)
{
    memset(diags, 0, sizeof *diags);
    snprintf(diags->file, sizeof diags->file, "%s", name);
    if (tl_timeline_init(out, err))
        return err ? (int)err->status : TL_ERR_RUNTIME;
    snprintf(out->file, sizeof out->file, "%s", name);
    parser p = {0}; /* ~4 KiB: the line buffer */
    p.name = name;
    p.source = text;
    p.source_len = length;
    p.tl = out;
    p.diags = diags;
    size_t pos = 0;
    /* Windows editors start UTF-8 files with a byte-order mark: skip it, so
     * that columns on line 1 count from the first visible character. */
    size_t bom = 0; /* bytes skipped: offsets in messages count the file's */
    if (length >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0) {
        bom = 3;
        text += 3;
        length -= 3;
        p.source = text;
        p.source_len = length;
    }
    if (length >= 2 && ((unsigned char)text[0] == 0xff || (unsigned char)text[0] == 0xfe) &&
        (unsigned char)text[1] == ((unsigned char)text[0] ^ 0x01)) {
        p.line_no = 1;
        tl_parse_diag(&p, 1, 2, NULL,
                      "the file is UTF-16 (byte-order mark 0x%02x 0x%02x); save it "
                      "as UTF-8 or ASCII",
                      (unsigned char)text[0], (unsigned char)text[1]);
        p.stopped = 1;
    }
    /* A file that is not text (a program, an image, a .blend) is told so
     * once, where its binary data begins, instead of an error a line. */
    if (!p.stopped)
        tl_parse_check_binary(&p, text, length, bom);
    while (pos < length && !p.stopped) {
        const char *eol = memchr(text + pos, '\n', length - pos);
        size_t len = eol ? (size_t)(eol - (text + pos)) : length - pos;
        p.line_no++;
        parse_line(&p, text + pos, len);
        pos += len + (eol ? 1 : 0);
    }
    if (!p.stopped) {
        p.line_text = NULL;
        p.line_len = 0;
        finish_block(&p);
        if (!p.saw_header) {
            p.line_no = 1;
            tl_parse_diag(&p, 0, 1, NULL, "%sa timeline starts with the line 'tideline 1'",
                          length == 0 ? "the file is empty: " : "");
        }
        tl_parse_check_links(&p);
        if (diags->errors == 0)
            tl_parse_check_times(&p);
    }
    free(p.key_lines);
    /* Conflicts are found after the whole file: show everything in line
     * order (insertion sort keeps equal lines in the order found). */
    for (int i = 1; i < diags->count; i++) {
        tl_diag d = diags->items[i];
        int j = i - 1;
        while (j >= 0 && diags->items[j].line > d.line) {
            diags->items[j + 1] = diags->items[j];
            j--;
        }
        diags->items[j + 1] = d;
    }
    if (diags->errors == 0)
        return TL_OK; /* warnings only: the timeline loads */
    const tl_diag *first = &diags->items[0];
    for (int i = 0; i < diags->count; i++)
        if (!diags->items[i].warning) {
            first = &diags->items[i];
            break;
        }
    tl_error_set_at(err, TL_ERR_RUNTIME, name, first->line, first->column, "%s", first->message);
    tl_timeline_free(out);
    return TL_ERR_RUNTIME;
}

int tl_timeline_parse_file(const char *path, tl_timeline *out, tl_diags *diags, tl_error *err)
{
    memset(diags, 0, sizeof *diags);
    memset(out, 0, sizeof *out);
    struct stat st;
    if (stat(path, &st) != 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot open timeline: %s", path,
                            strerror(errno));
    if (!S_ISREG(st.st_mode))
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: not a regular file", path);
    if (st.st_size > TL_PARSE_MAX_BYTES)
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "%s: %.1f MiB is too large for a timeline (the limit is %d MiB)", path,
                            (double)st.st_size / (1 << 20), TL_PARSE_MAX_BYTES >> 20);
    FILE *f = fopen(path, "rb");
    if (!f)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot open timeline: %s", path,
                            strerror(errno));
    size_t cap = (size_t)st.st_size + 1;
    char *text = malloc(cap);
    if (!text) {
        fclose(f);
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", path);
    }
    /* Read at most the limit even if the file grew since stat. */
    size_t len = fread(text, 1, cap, f);
    int bad = ferror(f) || len > (size_t)st.st_size;
    fclose(f);
    if (bad) {
        free(text);
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot read timeline (changed while read?)",
                            path);
    }
    int rc = tl_timeline_parse_text(path, text, len, out, diags, err);
    free(text);
    return rc;
}
