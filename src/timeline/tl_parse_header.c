/* The header lines of a timeline: `tideline`, `fps`, `duration`, `size`,
 * `quality`, `working_space` and `passes`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "color/tl_color.h"
#include "passes/tl_passes.h"
#include "timeline/tl_parse_internal.h"

void tl_parse_dir_header(parser *p, token *tok, int n)
{
    const char *d = tok[0].s;
    tl_timeline *tl = p->tl;
    if (strcmp(d, "tideline") == 0) {
        if (tl_parse_expect_args(p, tok, n, 1, 1, "a version number (1)"))
            return;
        if (p->saw_header) {
            ERR_AT(&tok[0], "'tideline' appears twice");
            return;
        }
        p->saw_header = 1; /* even with a wrong version: report that alone */
        if (strcmp(tok[1].s, "1") != 0) {
            ERR_AT(&tok[1], "unsupported timeline version '%s' (this tideline reads version 1)",
                   tok[1].s);
            return;
        }
    } else if (strcmp(d, "fps") == 0) {
        double fps;
        if (tl_parse_expect_args(p, tok, n, 1, 1, "frames per second") ||
            tl_parse_quantity(p, &tok[1], TL_UNIT_NONE, &fps))
            return;
        if (!(fps >= 1.0 && fps <= 1000.0)) {
            ERR_AT(&tok[1], "fps %s is outside 1..1000", tok[1].s);
            return;
        }
        if (p->frame_units_line) {
            ERR_AT(&tok[0], "fps must come before line %d, which gives a time in frames",
                   p->frame_units_line);
            return;
        }
        if (p->first_key_line) {
            ERR_AT(&tok[0],
                   "fps must come before line %d: keys measure aligned handles and elastic "
                   "periods in frames",
                   p->first_key_line);
            return;
        }
        tl->fps = fps;
    } else if (strcmp(d, "duration") == 0) {
        double dur;
        if (tl_parse_expect_args(p, tok, n, 1, 1, "a time (e.g. 12s)") ||
            tl_parse_quantity(p, &tok[1], TL_UNIT_TIME, &dur))
            return;
        if (!(dur > 0.0) || dur > 1e7) {
            ERR_AT(&tok[1], "duration %s is outside (0, 1e7 s]", tok[1].s);
            return;
        }
        if (p->saw_duration) { /* keys before it were checked against the first */
            ERR_AT(&tok[0], "'duration' is given twice (first on line %d)", p->saw_duration);
            return;
        }
        tl->duration = dur;
        p->saw_duration = p->line_no;
    } else if (strcmp(d, "size") == 0) {
        if (tl_parse_expect_args(p, tok, n, 1, 1, "WIDTHxHEIGHT"))
            return;
        char *end = NULL;
        long w = strtol(tok[1].s, &end, 10), h = -1;
        if (end != tok[1].s && (*end == 'x' || *end == 'X')) {
            const char *second = end + 1;
            h = strtol(second, &end, 10);
            if (end == second || *end != '\0')
                h = -1;
        } else {
            w = -1;
        }
        if (w < 1 || h < 1 || w > 16384 || h > 16384) {
            ERR_AT(&tok[1], "size '%s' is not WIDTHxHEIGHT with each side 1..16384", tok[1].s);
            return;
        }
        tl->width = (int)w;
        tl->height = (int)h;
    } else if (strcmp(d, "quality") == 0) {
        if (tl_parse_expect_args(p, tok, n, 1, 1, "a preset name"))
            return;
        tl_error e;
        if (tl_quality_preset(tok[1].s, &tl->quality, &e)) {
            static const char *const names[] = {"draft",     "preview", "final",
                                                "reference", "seed",    NULL};
            tl_parse_diag(p, tok[1].col, tok[1].len, tl_suggest(tok[1].s, names), "%s", e.message);
        }
    } else if (strcmp(d, "working_space") == 0) {
        if (tl_parse_expect_args(p, tok, n, 1, 1, "rec709 or acescg"))
            return;
        tl_working_space space;
        if (tl_color_working_parse(tok[1].s, &space)) {
            static const char *const names[] = {"rec709", "acescg", NULL};
            tl_parse_diag(p, tok[1].col, tok[1].len, tl_suggest(tok[1].s, names),
                          "unknown working space '%s' (rec709 or acescg)", tok[1].s);
            return;
        }
        tl->working_space = (int)space;
    } else if (strcmp(d, "passes") == 0) {
        if (tl_parse_expect_args(p, tok, n, 1, MAX_TOKENS, "pass names (e.g. depth,normal or all)"))
            return;
        tl->passes = 0;
        for (int i = 1; i < n; i++) {
            size_t at, len;
            unsigned passes = 0;
            int bad = tl_passes_parse(tok[i].s, &passes, &at, &len);
            if (!bad && passes) {
                tl->passes |= passes;
            } else if (!bad && n == 2) {
                tl->passes = 0; /* `passes none`: the plain file */
            } else if (!bad || (len == 4 && strncmp(tok[i].s + at, "none", 4) == 0)) {
                tl_parse_diag(p, tok[i].col + (bad ? (int)at : 0), bad ? 4 : tok[i].len, NULL,
                              "'none' stands alone on a passes line");
            } else {
                char name[64];
                snprintf(name, sizeof name, "%.*s", (int)len, tok[i].s + at);
                tl_parse_diag(p, tok[i].col + (int)at, len ? (int)len : 1,
                              tl_suggest(name, tl_passes_name_list()),
                              "unknown pass '%s' (passes: %s)", name, tl_passes_valid_names());
            }
        }
    }
}
