/* Numbers with units, and channel values range-checked against their
 * channel, for the parser (and `--time` on the command line). Split from
 * tl_parse.c to keep it readable. */
#include "tl_parse_internal.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static double display_value(tl_unit unit, double v)
{
    return unit == TL_UNIT_ANGLE ? v / TL_DEG : v;
}

static const char *display_unit(tl_unit unit)
{
    switch (unit) {
    case TL_UNIT_ANGLE: return " deg";
    case TL_UNIT_LENGTH: return " m";
    case TL_UNIT_TIME: return " s";
    default: return "";
    }
}

/* Parses a number with an optional unit suffix; returns 0 on success. */
int tl_parse_quantity(parser *p, const token *t, tl_unit unit, double *out)
{
    char *end = NULL;
    errno = 0;
    double v = strtod(t->s, &end);
    const char *word = t->s + (t->s[0] == '-' || t->s[0] == '+');
    if (strncasecmp(word, "nan", 3) == 0 || strncasecmp(word, "inf", 3) == 0) {
        ERR_AT(t, "'%s' is not a finite number", t->s);
        return 1;
    }
    if (end == t->s ||
        !(isdigit((unsigned char)t->s[0]) || t->s[0] == '-' || t->s[0] == '+' || t->s[0] == '.')) {
        ERR_AT(t, "expected a number, got '%s'", t->s);
        return 1;
    }
    if (word[0] == '0' && (word[1] == 'x' || word[1] == 'X')) {
        ERR_AT(t, "'%s': numbers are decimal", t->s);
        return 1;
    }
    /* ERANGE on a tiny number is underflow: the value rounds to (almost) 0,
     * which is fine. On a large one it is overflow. */
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0)) {
        ERR_AT(t, "'%s' is too large", t->s);
        return 1;
    }
    const char *suffix = end;
    double scale = 1.0;
    int ok = *suffix == '\0';
    switch (unit) {
    case TL_UNIT_TIME:
        if (strcmp(suffix, "s") == 0) {
            ok = 1;
        } else if (strcmp(suffix, "ms") == 0) {
            ok = 1;
            scale = 1e-3;
        } else if (strcmp(suffix, "f") == 0) {
            ok = 1;
            scale = 1.0 / p->tl->fps;
            if (!p->frame_units_line)
                p->frame_units_line = p->line_no;
        }
        if (!ok) {
            ERR_AT(t, "unknown time unit '%s' (use s, ms or f)", suffix);
            return 1;
        }
        break;
    case TL_UNIT_ANGLE:
        scale = TL_DEG; /* bare numbers are degrees */
        if (strcmp(suffix, "deg") == 0) {
            ok = 1;
        } else if (strcmp(suffix, "rad") == 0) {
            ok = 1;
            scale = 1.0;
        }
        if (!ok) {
            ERR_AT(t, "unknown angle unit '%s' (use deg or rad)", suffix);
            return 1;
        }
        break;
    case TL_UNIT_LENGTH:
        ok |= strcmp(suffix, "m") == 0;
        if (!ok) {
            ERR_AT(t, "unknown length unit '%s' (use m)", suffix);
            return 1;
        }
        break;
    case TL_UNIT_NONE:
        if (!ok) {
            ERR_AT(t, "'%s' takes no unit here", t->s);
            return 1;
        }
        break;
    }
    v *= scale;
    if (unit == TL_UNIT_TIME && fabs(v) > MAX_TIME) {
        ERR_AT(t, "time '%s' is out of range (|t| <= 1e9 s)", t->s);
        return 1;
    }
    *out = v;
    return 0;
}

/* One component of a channel value, range-checked. */
int tl_parse_channel_value(parser *p, const tl_channel *ch, const token *t, double *out)
{
    if (ch->kind == TL_CH_BOOL) {
        static const char *const yes[] = {"on", "true", "yes", "1", NULL};
        static const char *const no[] = {"off", "false", "no", "0", NULL};
        for (int i = 0; yes[i]; i++) {
            if (strcmp(t->s, yes[i]) == 0) {
                *out = 1.0;
                return 0;
            }
            if (strcmp(t->s, no[i]) == 0) {
                *out = 0.0;
                return 0;
            }
        }
        ERR_AT(t, "%s is on or off, got '%s'", ch->name, t->s);
        return 1;
    }
    if (ch->kind == TL_CH_ENUM) {
        for (int i = 0; ch->names[i]; i++)
            if (strcmp(t->s, ch->names[i]) == 0) {
                *out = i;
                return 0;
            }
        char values[256];
        size_t used = 0;
        values[0] = '\0';
        for (int i = 0; ch->names[i] && used < sizeof values; i++)
            used += (size_t)snprintf(values + used, sizeof values - used, "%s%s", i ? ", " : "",
                                     ch->names[i]);
        tl_parse_diag(p, t->col, t->len, tl_suggest(t->s, ch->names),
                      "%s has no value '%s' (values: %s)", ch->name, t->s, values);
        return 1;
    }
    double v;
    if (tl_parse_quantity(p, t, ch->unit, &v))
        return 1;
    /* A bare angle is degrees; a small one was likely meant as radians. */
    char last = t->len > 0 ? t->s[t->len - 1] : '\0';
    int bare = (last >= '0' && last <= '9') || last == '.';
    double deg = fabs(v) / TL_DEG;
    int fov = strcmp(ch->name, "camera.fov") == 0;
    if (ch->unit == TL_UNIT_ANGLE && bare && deg > 0.0 && deg < (fov ? 5.0 : 3.0)) {
        p->warning = 1;
        ERR_AT(t, "%s %s is read as degrees (%s deg); write %sdeg to keep it, or %srad for radians",
               ch->name, t->s, t->s, t->s, t->s);
        p->warning = 0;
    }
    if (ch->kind == TL_CH_INT && v != floor(v)) {
        ERR_AT(t, "%s takes a whole number, got '%s'", ch->name, t->s);
        return 1;
    }
    if (v < ch->min || v > ch->max) {
        ERR_AT(t, "%s = %s is outside its range %.6g..%.6g%s", ch->name, t->s,
               display_value(ch->unit, ch->min), display_value(ch->unit, ch->max),
               display_unit(ch->unit));
        return 1;
    }
    *out = v;
    return 0;
}

int tl_parse_time_text(const char *text, double fps, double *out, tl_error *err)
{
    tl_timeline tl;
    memset(&tl, 0, sizeof tl);
    tl.fps = fps;
    tl_diags diags;
    memset(&diags, 0, sizeof diags);
    parser p = {0};
    p.tl = &tl;
    p.diags = &diags;
    char copy[128];
    snprintf(copy, sizeof copy, "%s", text);
    token t = {copy, 1, (int)strlen(copy)};
    if (strlen(text) >= sizeof copy || tl_parse_quantity(&p, &t, TL_UNIT_TIME, out))
        return tl_error_set(err, TL_ERR_USAGE, "%s",
                            diags.count ? diags.items[0].message : "time is too long");
    return TL_OK;
}
