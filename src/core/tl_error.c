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
