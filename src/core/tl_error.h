/* tl_error: the one error type every fallible function fills.
 *
 * Functions that can fail return an int status (0 = ok, non-zero = failure)
 * and fill a tl_error. The command layer prints it; nothing below main()
 * prints errors itself or calls exit(). */
#ifndef TL_ERROR_H
#define TL_ERROR_H

#include <stdarg.h>
#include <stdio.h>

#define TL_ERROR_MSG_MAX  1024
#define TL_ERROR_PATH_MAX 512

typedef enum tl_status {
    TL_OK = 0,
    TL_ERR_USAGE = 2,   /* bad flag, bad value: exit status 2 */
    TL_ERR_RUNTIME = 1, /* GL, I/O, parse failures: exit status 1 */
} tl_status;

typedef struct tl_error {
    tl_status status;
    char message[TL_ERROR_MSG_MAX];
    char file[TL_ERROR_PATH_MAX]; /* empty when the error has no source file */
    int line;                     /* 1-based, 0 when unknown */
    int column;                   /* 1-based, 0 when unknown */
} tl_error;

void tl_error_clear(tl_error *err);

/* Fills err (which may be NULL) and returns status, so callers can write
 * `return tl_error_set(err, TL_ERR_RUNTIME, "...", ...);`. */
int tl_error_set(tl_error *err, tl_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int tl_error_setv(tl_error *err, tl_status status, const char *fmt, va_list ap);

/* Like tl_error_set, and records a source location. */
int tl_error_set_at(tl_error *err, tl_status status, const char *file, int line, int column,
                    const char *fmt, ...) __attribute__((format(printf, 6, 7)));

/* Writes an error with a source location as the timeline's diagnostics
 * look: `FILE:LINE:COLUMN: error: MESSAGE`, then the line and a caret
 * under the word at the column (the line read again from the file; left
 * out when it cannot be). Nothing when err has no location (returns 0). */
int tl_error_write_located(FILE *out, const tl_error *err);

/* Prepends "context: " to an existing message (e.g. a file name). */
void tl_error_prefix(tl_error *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
