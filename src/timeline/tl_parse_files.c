/* The lines that name files beside the timeline: `set NAME.model PATH`
 * and `audio PATH [OFFSET]`. A path is one word, relative to the
 * timeline's folder; the file itself is opened by the commands that need
 * it (tl_cutscene_load), which report its errors at the naming line. */
#include <stdio.h>
#include <string.h>

#include "timeline/tl_parse_internal.h"

int tl_parse_file_path(parser *p, const token *t, const char *what, char *out, size_t size)
{
    const char *slash = strrchr(p->name, '/');
    int dir_len = t->s[0] == '/' || !slash ? 0 : (int)(slash - p->name) + 1;
    int len = snprintf(out, size, "%.*s%s", dir_len, p->name, t->s);
    if (len < 0 || (size_t)len >= size) {
        out[0] = '\0';
        ERR_AT(t, "%s: the path is too long", what);
        return 1;
    }
    return 0;
}

void tl_parse_dir_audio(parser *p, token *tok, int n)
{
    tl_timeline *tl = p->tl;
    if (n < 2 || n > 3) {
        tl_parse_diag(p, tok[n > 3 ? 3 : 0].col, tok[n > 3 ? 3 : 0].len, NULL,
                      "audio takes a sound file and an optional offset "
                      "(e.g. audio score.wav 2s), found %d words",
                      n - 1);
        return;
    }
    if (tl->audio_line) {
        ERR_AT(&tok[0], "audio is already given on line %d (a timeline has one soundtrack)",
               tl->audio_line);
        return;
    }
    double offset = 0.0;
    if (n == 3) {
        if (tl_parse_quantity(p, &tok[2], TL_UNIT_TIME, &offset))
            return;
        if (!(offset >= -MAX_TIME && offset <= MAX_TIME)) {
            ERR_AT(&tok[2], "audio offset %s is outside +-1e9 s", tok[2].s);
            return;
        }
    }
    if (tl_parse_file_path(p, &tok[1], "audio", tl->audio, sizeof tl->audio))
        return;
    tl->audio_offset = offset;
    tl->audio_line = p->line_no;
    tl->audio_column = tok[1].col;
}
