/* Internal to the timeline parser (tl_parse.c and the files it is split
 * into): the parser's state, tokens and the helpers they share. */
#ifndef TL_PARSE_INTERNAL_H
#define TL_PARSE_INTERNAL_H

#include "core/tl_math.h"
#include "timeline/tl_parse.h"

#define MAX_TOKENS 64
#define MAX_TIME   1.0e9 /* seconds: ~31 years, far past any cutscene */

typedef struct token {
    char *s; /* NUL-terminated copy inside the line buffer */
    int col; /* 1-based */
    int len;
} token;

/* BLOCK_SKIP: a `key` or `path` line that was rejected; its indented lines
 * are skipped silently rather than reported as strays. */
typedef enum block_kind { BLOCK_NONE, BLOCK_KEY, BLOCK_PATH, BLOCK_SKIP } block_kind;

typedef struct parser {
    const char *name;
    const char *source; /* the whole text, for excerpts of earlier lines */
    size_t source_len;
    tl_timeline *tl;
    tl_diags *diags;
    int warning; /* diagnostics added now are warnings */
    int line_no;
    const char *line_text; /* the current line, for diagnostics */
    size_t line_len;
    int saw_header;
    int frame_units_line; /* first line that used a time in frames */
    long keys_total;
    int stopped;

    /* The open `key` or `path` block. */
    block_kind block;
    int block_line;
    const tl_channel *block_ch;
    tl_track *block_track;
    tl_interp block_interp;
    tl_ease_family block_family;
    tl_ease_dir block_dir;
    int block_shortest;
    tl_path_track *block_path;
    int block_dims;
    struct key_source {
        int line;
        const char *text;
        size_t len;
        int col;
    } * key_lines; /* where each key/point of the block was written */
    size_t key_count, key_cap;
    int block_failed;
    int first_key_line;              /* the first `key` block: fps must come before it */
    int saw_duration;                /* the `duration` line (0: none yet): keys past it warn */
    tl_ease_params block_ease;       /* back, amplitude, period (frames) from the `key` line */
    char buf[TL_PARSE_MAX_LINE + 1]; /* the current line, split into tokens */
} parser;

/* Adds an error (or a warning while p->warning) at the current line. */
void tl_parse_diag(parser *p, int col, int len, const char *hint, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
#define ERR_AT(tok, ...) tl_parse_diag(p, (tok)->col, (tok)->len, NULL, __VA_ARGS__)

/* ---- tl_parse_lex.c ---- */

/* A file that is not text: four or more control bytes no text editor
 * writes (NUL, DEL and the C0 codes but tab, line feed, vertical tab, form
 * feed and carriage return), outside comments (which may hold anything),
 * in its first 4 KiB, reported once where they begin ("not a timeline
 * (binary data at byte N)"; `bom`: bytes skipped before `text`) and the
 * parse stopped. Fewer are stray bytes, each an error at its line. */
void tl_parse_check_binary(parser *p, const char *text, size_t length, size_t bom);
/* Splits `buf` (a copy of the line) into tokens; returns the count, or -1
 * after reporting a bad byte or too many tokens. */
int tl_parse_tokenize(parser *p, char *buf, size_t len, token *tok);
/* A unit word standing alone after a number from tok[first] on (`0.004 m`),
 * reported at the space; 1 when found. */
int tl_parse_unit_after_space(parser *p, const token *tok, int n, int first);

/* ---- tl_parse_checks.c (the key past the end, at its line) ---- */

/* The first key of a block past the timeline's end, warned about at its
 * own line and column (with what a bare number would be as frames). */
void tl_parse_warn_past_end(parser *p, const token *time, double t);

/* ---- tl_parse_keys.c (suggestions) ---- */

/* `list` (NULL-terminated) and every easing's name, into `out` (room for
 * both and the NULL), for "did you mean". */
const char *const *tl_parse_with_ease_names(const char *const *list, const char **out);

/* ---- tl_parse_diag.c ---- */

/* A diagnostic about an earlier line (a key found bad when its block
 * closes, or a conflict found at the end); `src` may be NULL when only the
 * line number is known. */
void tl_parse_diag_at_line(parser *p, int line, const struct key_source *src, const char *fmt,
                           const char *msg);

/* ---- tl_parse_values.c ---- */

/* A number with an optional unit suffix of the given kind; 0 on success. */
int tl_parse_quantity(parser *p, const token *t, tl_unit unit, double *out);

/* One component of a channel's value (on/off, a name, or a number in the
 * channel's unit), range-checked; 0 on success. */
int tl_parse_channel_value(parser *p, const tl_channel *ch, const token *t, double *out);

/* ---- tl_parse_links.c: `look` and `follow` ---- */

/* `look camera at boat [+ X Y Z]` or `look camera at X Y Z`. */
void tl_parse_dir_look(parser *p, token *tok, int n);
/* `follow camera|giant.center boat [+ offset]`. */
void tl_parse_dir_follow(parser *p, token *tok, int n);

/* ---- tl_parse.c: shared by the directives ---- */
/* Reports (and returns 1) when a line has fewer than `min` or more than
 * `max` arguments after its directive; `usage` says what it takes. */
int tl_parse_expect_args(parser *p, token *tok, int n, int min, int max, const char *usage);

/* ---- tl_parse_header.c: tideline, fps, duration, size, quality,
 * working_space, passes ---- */
void tl_parse_dir_header(parser *p, token *tok, int n);

/* ---- tl_parse_files.c: lines that name files ---- */
/* Token t's path, relative to the timeline's folder, into out; 1 after
 * reporting one too long for it (`what` names the line's setting). */
int tl_parse_file_path(parser *p, const token *t, const char *what, char *out, size_t size);
/* `audio PATH [OFFSET]`: the soundtrack, its start at timeline time OFFSET. */
void tl_parse_dir_audio(parser *p, token *tok, int n);

/* ---- tl_parse_checks.c: the whole timeline, once read ---- */

/* Conflicts between what drives the camera, and links to a missing boat. */
void tl_parse_check_links(parser *p);

/* Warnings for keys and path points past the timeline's end. */
void tl_parse_check_times(parser *p);

/* ---- tl_parse_keys.c: options of `key` blocks ---- */

/* One side's handle on a key line: `left [TYPE] [DT V...]`. */
typedef struct tl_handle_side {
    int has_type, has_offset;
    tl_handle_type type;
    double offset[4]; /* dt, then one value per component */
} tl_handle_side;

/* `back S`, `amplitude A`, `period T` at tok[*i] (Blender's easing
 * settings; the period is stored in frames). Returns 1 when consumed (*i on
 * its value), 0 when tok[*i] is none of them, -1 after an error. */
int tl_parse_ease_setting(parser *p, const tl_channel *ch, token *tok, int n, int *i,
                          tl_ease_params *ease);

/* `left ...` or `right ...` at tok[*i]: an optional handle type, then an
 * optional offset. Same returns. */
int tl_parse_handle_side(parser *p, const tl_channel *ch, token *tok, int n, int *i,
                         tl_handle_side *left, tl_handle_side *right);

/* `extrapolate MODE [N]`, `before MODE [N]`, `after MODE [N]` and
 * `smoothing none|continuous` on a `key` line, into shape's before, after,
 * counts and smoothing. Same returns. */
int tl_parse_curve_option(parser *p, token *tok, int n, int *i, tl_curve *shape);

#endif
