/* tl_parse: reads the timeline language (docs/timeline.md) into a
 * tl_timeline, reporting every error of the file (up to a limit) with its
 * line and column.
 *
 * The parser is bounded whatever its input: files over TL_PARSE_MAX_BYTES,
 * lines over TL_PARSE_MAX_LINE characters, more than TL_PARSE_MAX_KEYS keys
 * or TL_PARSE_MAX_ERRORS errors stop it with a clean error; it never reads
 * past its buffer, and memory grows at most linearly with the file. */
#ifndef TL_PARSE_H
#define TL_PARSE_H

#include <stdio.h>

#include "timeline/tl_timeline.h"

#define TL_PARSE_MAX_BYTES  (16 * 1024 * 1024)
#define TL_PARSE_MAX_LINE   4096
#define TL_PARSE_MAX_KEYS   200000 /* key lines plus path points, whole file */
#define TL_PARSE_MAX_ERRORS 20

typedef struct tl_diag {
    int line, column;  /* 1-based; column 0: the whole line */
    int length;        /* characters to underline (at least 1) */
    char message[512]; /* room for a list of the valid names */
    char hint[160];    /* "did you mean 'x'?" or empty */
    char text[200];    /* the source line (truncated) */
    int warning;       /* a likely mistake, not an error: the file still loads */
} tl_diag;

typedef struct tl_diags {
    char file[512];
    tl_diag items[TL_PARSE_MAX_ERRORS];
    int count;
    int errors; /* of `count`, the errors (the rest are warnings) */
    int more;   /* diagnostics beyond the limit (not kept) */
} tl_diags;

/* Parses a file. Returns 0 when valid (`diags` may still hold warnings:
 * likely unit mistakes, keys past the end); otherwise `diags` holds the
 * errors and warnings (err gets the first error) and `out` is freed. */
int tl_timeline_parse_file(const char *path, tl_timeline *out, tl_diags *diags, tl_error *err);
/* Parses text held in memory; `name` labels the diagnostics. */
int tl_timeline_parse_text(const char *name, const char *text, size_t length, tl_timeline *out,
                           tl_diags *diags, tl_error *err);

/* Parses a time as the language writes it ("2.5", "2.5s", "1500ms", "36f")
 * with `fps` for frames. */
int tl_parse_time_text(const char *text, double fps, double *out, tl_error *err);

/* Writes each diagnostic as "file:line:col: error: message" (or
 * "warning:"), the line with a caret under the column, and the hint. */
void tl_diags_write(const tl_diags *diags, FILE *out);

#endif
