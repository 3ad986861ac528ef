/* The parser's diagnostics: adding one at the current line or at an
 * earlier one, and writing them out as file:line:column with an excerpt
 * and a caret. Split from tl_parse.c to keep it readable. */
#include "tl_parse_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void tl_parse_diag(parser *p, int col, int len, const char *hint, const char *fmt, ...)
{
    tl_diags *d = p->diags;
    if (d->count >= TL_PARSE_MAX_ERRORS) {
        d->more++; /* counted, not kept: parsing goes on (it is linear) */
        d->errors += !p->warning;
        return;
    }
    tl_diag *g = &d->items[d->count++];
    memset(g, 0, sizeof *g);
    g->warning = p->warning;
    d->errors += !p->warning;
    g->line = p->line_no;
    g->column = col;
    g->length = len > 0 ? len : 1;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(g->message, sizeof g->message, fmt, ap);
    va_end(ap);
    if (hint)
        snprintf(g->hint, sizeof g->hint, "did you mean '%s'?", hint);
    size_t n = p->line_len < sizeof g->text - 1 ? p->line_len : sizeof g->text - 1;
    if (!p->line_text)
        n = 0;
    /* The excerpt is shown on a terminal: control and non-ASCII bytes
     * become '?' (tabs stay, so the caret lines up). */
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)p->line_text[i];
        g->text[i] = (c == '\t' || (c >= 0x20 && c < 0x7f)) ? (char)c : '?';
    }
    while (n > 0 && g->text[n - 1] == '\r')
        n--;
    g->text[n] = '\0';
}

/* The text of line `line` (1-based) and its first word's column; a scan
 * from the start, which is fine for the few errors found after parsing. */
static int find_line(const parser *p, int line, struct key_source *out)
{
    if (!p->source || line < 1)
        return 0;
    const char *s = p->source, *end = p->source + p->source_len;
    for (int n = 1; n < line; n++) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        if (!nl)
            return 0;
        s = nl + 1;
    }
    const char *nl = memchr(s, '\n', (size_t)(end - s));
    size_t len = nl ? (size_t)(nl - s) : (size_t)(end - s);
    if (len > TL_PARSE_MAX_LINE)
        return 0;
    int col = 1;
    while ((size_t)(col - 1) < len && (s[col - 1] == ' ' || s[col - 1] == '\t'))
        col++;
    *out = (struct key_source){line, s, len, col};
    return 1;
}

/* A diagnostic about an earlier line (a key found bad when its block
 * closes, or a conflict found at the end). `src` may be NULL when only the
 * line number is known. */
void tl_parse_diag_at_line(parser *p, int line, const struct key_source *src, const char *fmt,
                           const char *msg)
{
    int saved_line = p->line_no;
    const char *saved_text = p->line_text;
    size_t saved_len = p->line_len;
    struct key_source found = {line, NULL, 0, 1};
    if (!src && find_line(p, line, &found))
        src = &found;
    p->line_no = line;
    p->line_text = src ? src->text : NULL;
    p->line_len = src ? src->len : 0;
    tl_parse_diag(p, src ? src->col : 0, 1, NULL, fmt, msg);
    p->line_no = saved_line;
    p->line_text = saved_text;
    p->line_len = saved_len;
}

void tl_diags_write(const tl_diags *d, FILE *out)
{
    for (int i = 0; i < d->count; i++) {
        const tl_diag *g = &d->items[i];
        const char *kind = g->warning ? "warning" : "error";
        if (g->column > 0)
            fprintf(out, "%s:%d:%d: %s: %s\n", d->file, g->line, g->column, kind, g->message);
        else
            fprintf(out, "%s:%d: %s: %s\n", d->file, g->line, kind, g->message);
        if (g->text[0] && g->column > 0) {
            fprintf(out, "%6d | %s\n", g->line, g->text);
            fprintf(out, "       | ");
            /* Tabs stay tabs so the caret lines up under the same column. */
            for (int c = 1; c < g->column && c <= (int)strlen(g->text); c++)
                fputc(g->text[c - 1] == '\t' ? '\t' : ' ', out);
            fputc('^', out);
            for (int c = 1; c < g->length && c < 80; c++)
                fputc('~', out);
            fputc('\n', out);
        }
        if (g->hint[0])
            fprintf(out, "       = %s\n", g->hint);
    }
    if (d->more)
        fprintf(out, "%s: %d more error%s not shown\n", d->file, d->more, d->more > 1 ? "s" : "");
}
