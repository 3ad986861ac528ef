/* The timeline's lexical layer: whether a file is text at all, a line
 * split into words, and a unit written apart from its number. Split from
 * tl_parse.c to keep it readable. */
#include "tl_parse_internal.h"

#include <ctype.h>
#include <string.h>

/* Binary data: tl_parse_internal.h says what counts as binary, and why
 * four bytes (fewer are stray bytes, each an error at its line). */
void tl_parse_check_binary(parser *p, const char *text, size_t length, size_t bom)
{
    size_t first_binary = length, binary = 0;
    int comment = 0;
    for (size_t i = 0; i < length && i < 4096; i++) {
        unsigned char c = (unsigned char)text[i];
        if (c == '\n')
            comment = 0;
        else if (c == '#')
            comment = 1;
        if (!comment &&
            ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') ||
             c == 0x7f)) {
            if (first_binary == length)
                first_binary = i;
            binary++;
        }
    }
    if (binary >= 4) {
        size_t line_start = 0;
        p->line_no = 1;
        for (size_t i = 0; i < first_binary; i++)
            if (text[i] == '\n') {
                p->line_no++;
                line_start = i + 1;
            }
        tl_parse_diag(p, (int)(first_binary - line_start) + 1, 1, NULL,
                      "not a timeline (binary data at byte %zu)", first_binary + bom);
        p->stopped = 1;
    }
}

/* Splits `buf` (a copy of the line) into tokens; returns the count, or -1
 * after reporting a bad byte or too many tokens. */
int tl_parse_tokenize(parser *p, char *buf, size_t len, token *tok)
{
    int n = 0;
    size_t i = 0;
    while (i < len) {
        unsigned char c = (unsigned char)buf[i];
        if (c == '#')
            break;
        if (c == ' ' || c == '\t' || c == '\r') {
            buf[i++] = '\0';
            continue;
        }
        if (c < 0x20 || c >= 0x7f) {
            tl_parse_diag(p, (int)i + 1, 1, NULL,
                          "unexpected byte 0x%02x (outside comments a timeline is plain ASCII)", c);
            return -1;
        }
        if (n == MAX_TOKENS) {
            tl_parse_diag(p, (int)i + 1, 1, NULL, "more than %d words on one line", MAX_TOKENS);
            return -1;
        }
        tok[n].s = buf + i;
        tok[n].col = (int)i + 1;
        while (i < len && buf[i] != ' ' && buf[i] != '\t' && buf[i] != '\r' && buf[i] != '#' &&
               (unsigned char)buf[i] >= 0x20 && (unsigned char)buf[i] < 0x7f)
            i++;
        tok[n].len = (int)(buf + i - tok[n].s);
        n++;
        if (i < len && buf[i] == '#') {
            buf[i] = '\0';
            break;
        }
    }
    if (i <= len)
        buf[i < len ? i : len] = '\0';
    return n;
}

/* A unit word standing alone after a number from tok[first] on (`0.004 m`):
 * reported at the space, with the number and unit written together. */
int tl_parse_unit_after_space(parser *p, const token *tok, int n, int first)
{
    static const char *const units[] = {"m", "s", "ms", "f", "deg", "rad", NULL};
    for (int i = first + 1; i < n; i++)
        for (int u = 0; units[u]; u++) {
            const token *num = &tok[i - 1];
            char last = num->len > 0 ? num->s[num->len - 1] : '\0';
            if (strcmp(tok[i].s, units[u]) != 0 || !(isdigit((unsigned char)last) || last == '.'))
                continue;
            int gap = num->col + num->len;
            tl_parse_diag(p, gap, tok[i].col - gap, NULL,
                          "a unit goes right after its number, without a space: '%.*s%s'", num->len,
                          num->s, tok[i].s);
            return 1;
        }
    return 0;
}
