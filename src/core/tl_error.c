#include "tl_error.h"

#include <stdio.h>
#include <string.h>

void tl_error_clear(tl_error *err)
{
    if (err)
        memset(err, 0, sizeof *err);
}

int tl_error_setv(tl_error *err, tl_status status, const char *fmt, va_list ap)
{
    if (err) {
        err->status = status;
        vsnprintf(err->message, sizeof err->message, fmt, ap);
    }
    return (int)status;
}

int tl_error_set(tl_error *err, tl_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    tl_error_setv(err, status, fmt, ap);
    va_end(ap);
    return (int)status;
}

int tl_error_set_at(tl_error *err, tl_status status, const char *file, int line, int column,
                    const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    tl_error_setv(err, status, fmt, ap);
    va_end(ap);
    if (err) {
        snprintf(err->file, sizeof err->file, "%s", file ? file : "");
        err->line = line;
        err->column = column;
    }
    return (int)status;
}

void tl_error_prefix(tl_error *err, const char *fmt, ...)
{
    if (!err)
        return;
    char prefix[TL_ERROR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(prefix, sizeof prefix - 2, fmt, ap);
    va_end(ap);
    if (n < 0)
        return;
    size_t plen = strlen(prefix);
    memcpy(prefix + plen, ": ", 3);
    plen += 2;
    size_t mlen = strlen(err->message);
    size_t cap = sizeof err->message - 1;
    if (plen > cap)
        plen = cap;
    if (plen + mlen > cap)
        mlen = cap - plen; /* keep the prefix; truncate the old message */
    memmove(err->message + plen, err->message, mlen);
    memcpy(err->message, prefix, plen);
    err->message[plen + mlen] = '\0';
}

int tl_error_write_located(FILE *out, const tl_error *err)
{
    if (!err || !err->file[0] || err->line <= 0)
        return 0;
    fprintf(out, "%s:%d:%d: error: %s\n", err->file, err->line, err->column, err->message);
    FILE *f = err->column > 0 ? fopen(err->file, "rb") : NULL;
    if (!f)
        return 1;
    char text[4097];
    int line = 0, found = 0;
    while (!found && fgets(text, sizeof text, f)) {
        size_t n = strlen(text);
        int whole = n > 0 && text[n - 1] == '\n';
        if (++line == err->line)
            found = 1;
        while (!whole && !found && fgets(text, sizeof text, f)) { /* the rest of a long line */
            n = strlen(text);
            whole = n > 0 && text[n - 1] == '\n';
        }
    }
    fclose(f);
    if (!found)
        return 1;
    text[strcspn(text, "\r\n")] = '\0';
    size_t len = strlen(text), col = (size_t)err->column - 1;
    if (col > len)
        return 1;
    /* The source line as printed, tabs kept so that the caret lines up,
     * bytes a terminal would act on shown as '?' (as tl_diags_write). */
    for (size_t i = 0; i < len; i++)
        if (((unsigned char)text[i] < 0x20 && text[i] != '\t') || (unsigned char)text[i] >= 0x7f)
            text[i] = '?';
    fprintf(out, "%6d | %s\n       | ", err->line, text);
    for (size_t i = 0; i < col; i++)
        fputc(text[i] == '\t' ? '\t' : ' ', out);
    size_t word = strcspn(text + col, " \t");
    fputc('^', out);
    for (size_t i = 1; i < word; i++)
        fputc('~', out);
    fputc('\n', out);
    return 1;
}
