/* Options of `key` blocks that Blender authors reach for: per-side handle
 * types, easing settings, extrapolation per side with repeat counts, and
 * auto-handle smoothing. Split from tl_parse.c to keep it readable. */
#include "tl_parse_internal.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int starts_number(const char *s)
{
    return isdigit((unsigned char)s[0]) || s[0] == '-' || s[0] == '+' || s[0] == '.';
}

int tl_parse_ease_setting(parser *p, const tl_channel *ch, token *tok, int n, int *i,
                          tl_ease_params *ease)
{
    static const char *const names[] = {"back", "amplitude", "period"};
    const char *w = tok[*i].s;
    int which = -1;
    for (int k = 0; k < 3; k++)
        if (strcmp(w, names[k]) == 0)
            which = k;
    if (which < 0)
        return 0;
    if (*i + 1 >= n) {
        ERR_AT(&tok[*i], "'%s' expects %s", w,
               which == 0   ? "an overshoot (e.g. 1.70158)"
               : which == 1 ? "an amplitude in the channel's unit"
                            : "a time (e.g. 4.1f)");
        return -1;
    }
    token *v = &tok[++*i];
    tl_unit unit = which == 0 ? TL_UNIT_NONE : which == 1 ? ch->unit : TL_UNIT_TIME;
    double x;
    if (tl_parse_quantity(p, v, unit, &x))
        return -1;
    if (x < 0.0) {
        ERR_AT(v, "%s cannot be negative, got '%s'", w, v->s);
        return -1;
    }
    if (which == 0)
        ease->back = x;
    else if (which == 1)
        ease->amplitude = x;
    else
        ease->period = x * p->tl->fps; /* Blender keeps it in frames */
    return 1;
}

int tl_parse_handle_side(parser *p, const tl_channel *ch, token *tok, int n, int *i,
                         tl_handle_side *left, tl_handle_side *right)
{
    const token *word = &tok[*i];
    if (strcmp(word->s, "left") != 0 && strcmp(word->s, "right") != 0)
        return 0;
    tl_handle_side *side = word->s[0] == 'l' ? left : right;
    if (*i + 1 < n && tl_handle_type_from_name(tok[*i + 1].s, &side->type)) {
        side->has_type = 1;
        ++*i;
    }
    if (*i + 1 < n && starts_number(tok[*i + 1].s)) {
        if (n - 1 - *i < 1 + ch->components) {
            ERR_AT(word, "'%s' needs a time offset and %d value%s", word->s, ch->components,
                   ch->components > 1 ? "s" : "");
            return -1;
        }
        if (tl_parse_quantity(p, &tok[++*i], TL_UNIT_TIME, &side->offset[0]))
            return -1;
        for (int c = 0; c < ch->components; c++)
            if (tl_parse_quantity(p, &tok[++*i], ch->unit, &side->offset[1 + c]))
                return -1;
        side->has_offset = 1;
    } else if (!side->has_type) {
        static const char *const types[] = {"auto-clamped", "auto", "vector",
                                            "aligned",      "free", NULL};
        const token *next = *i + 1 < n ? &tok[*i + 1] : NULL;
        const char *hint = next ? tl_suggest(next->s, types) : NULL;
        if (hint) {
            tl_parse_diag(p, next->col, next->len, hint, "unknown handle type '%s'", next->s);
            return -1;
        }
        ERR_AT(word,
               "'%s' expects a handle type (auto-clamped, auto, vector, aligned, free) or "
               "a time offset and %d value%s",
               word->s, ch->components, ch->components > 1 ? "s" : "");
        return -1;
    }
    return 1;
}

static const char *const extrap_modes[] = {"constant",     "linear",    "cycle",
                                           "cycle-offset", "ping-pong", NULL};

/* MODE [N] after `extrapolate`, `before` or `after` at tok[*i]; 0 or -1. */
static int parse_extrap(parser *p, token *tok, int n, int *i, tl_extrap *mode, unsigned *count)
{
    const token *word = &tok[*i];
    if (*i + 1 >= n) {
        ERR_AT(word, "'%s' expects constant, linear, cycle, cycle-offset or ping-pong", word->s);
        return -1;
    }
    token *m = &tok[++*i];
    if (!tl_extrap_from_name(m->s, mode)) {
        tl_parse_diag(p, m->col, m->len, tl_suggest(m->s, extrap_modes),
                      "unknown extrapolation '%s'", m->s);
        return -1;
    }
    *count = 0;
    if (*i + 1 < n && starts_number(tok[*i + 1].s)) {
        token *c = &tok[++*i];
        char *end = NULL;
        long k = strtol(c->s, &end, 10);
        if (*mode != TL_EXTRAP_CYCLE && *mode != TL_EXTRAP_CYCLE_OFFSET &&
            *mode != TL_EXTRAP_PINGPONG) {
            ERR_AT(c, "a repeat count applies to cycle, cycle-offset and ping-pong, not %s", m->s);
            return -1;
        }
        if (end == c->s || *end != '\0' || k < 1 || k > 1000000) {
            ERR_AT(c,
                   "repeat count '%s' is not a whole number 1..1000000 (leave it out to "
                   "repeat forever)",
                   c->s);
            return -1;
        }
        *count = (unsigned)k;
    }
    return 0;
}

int tl_parse_curve_option(parser *p, token *tok, int n, int *i, tl_curve *shape)
{
    const char *w = tok[*i].s;
    tl_extrap mode;
    unsigned count;
    if (strcmp(w, "smoothing") == 0) {
        static const char *const names[] = {"none", "continuous", NULL};
        if (*i + 1 >= n) {
            ERR_AT(&tok[*i], "'smoothing' expects none or continuous");
            return -1;
        }
        token *v = &tok[++*i];
        if (!tl_smoothing_from_name(v->s, &shape->smoothing)) {
            tl_parse_diag(p, v->col, v->len, tl_suggest(v->s, names),
                          "unknown smoothing '%s' (none or continuous)", v->s);
            return -1;
        }
        return 1;
    }
    int side = strcmp(w, "extrapolate") == 0 ? 2
               : strcmp(w, "before") == 0    ? 0
               : strcmp(w, "after") == 0     ? 1
                                             : -1;
    if (side < 0)
        return 0;
    if (parse_extrap(p, tok, n, i, &mode, &count))
        return -1;
    if (side != 1) {
        shape->before = mode;
        shape->before_cycles = count;
    }
    if (side != 0) {
        shape->after = mode;
        shape->after_cycles = count;
    }
    return 1;
}

/* `list` (NULL-terminated) and every easing's name, into `out` (room for
 * both), for "did you mean". */
const char *const *tl_parse_with_ease_names(const char *const *list, const char **out)
{
    int n = 0;
    for (; list[n]; n++)
        out[n] = list[n];
    for (int f = 0; f < TL_EASE_FAMILY_COUNT; f++)
        for (int d = 0; d < TL_EASE_DIR_COUNT; d++)
            out[n++] = tl_ease_name((tl_ease_family)f, (tl_ease_dir)d);
    out[n] = NULL;
    return out;
}
