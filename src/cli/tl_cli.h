/* The commands. Each takes its own argv (argv[0] is the command name),
 * prints its errors as "tideline CMD: message" and returns the process
 * exit status: 0 success, 1 runtime failure, 2 usage error. */
#ifndef TL_CLI_H
#define TL_CLI_H

#include "core/tl_error.h"

int tl_cli_still(int argc, char **argv);
int tl_cli_render(int argc, char **argv);
int tl_cli_check(int argc, char **argv);
int tl_cli_eval(int argc, char **argv);
int tl_cli_preview(int argc, char **argv);
int tl_cli_compare(int argc, char **argv);
int tl_cli_movie(int argc, char **argv);
int tl_cli_bench(int argc, char **argv);
int tl_cli_export_camera(int argc, char **argv);

/* Parses a timeline file, printing every diagnostic, and loads its boat's
 * mesh (the timeline's model, or the built-in boat) into *boat, or only
 * checks it when boat is NULL. Returns the exit status (0, or 1 when the
 * file or its model is invalid or unreadable; the timeline is then freed). */
struct tl_timeline;
struct tl_models;
struct tl_cutscene;
int tl_cli_load_timeline(const char *command, const char *path, struct tl_timeline *tl,
                         struct tl_models *models);
/* The same, keeping the cutscene whole (tl_cutscene_free frees it). */
int tl_cli_load_cutscene(const char *command, const char *path, struct tl_cutscene *cs);

/* Warns on stderr when time t (seconds; `flag` `given` on the command
 * line) lies outside the timeline: a frame past the end is most often a
 * typo or the wrong fps, and what it renders only repeats the keys' ends. */
void tl_cli_warn_outside(const char *command, const char *flag, const char *given,
                         const struct tl_timeline *tl, double t);

/* SIGINT and SIGTERM to `handler` (a long run's stop flag), the actions
 * before kept in `saved` for tl_cli_restore_stop. */
#include <signal.h>
typedef struct tl_cli_signals {
    struct sigaction old_int, old_term;
} tl_cli_signals;
void tl_cli_catch_stop(void (*handler)(int), tl_cli_signals *saved);
void tl_cli_restore_stop(const tl_cli_signals *saved);

/* ", with the sound of FILE from S s into it" or ", with the sound of
 * FILE, its start S s into the movie": where a movie's soundtrack lies. */
struct tl_movie_sound;
void tl_cli_describe_sound(FILE *to, const struct tl_movie_sound *sound);

/* mkdir -p of the folder part of `path` (status 2 when it cannot). */
int tl_cli_make_parent_dirs(const char *path, tl_error *err);
/* A time left for progress lines: "48s", "3m05s", "2h10m"; "--" when not
 * known (negative or not finite). */
void tl_cli_format_duration(double seconds, char *out, size_t size);
/* Seconds a frame draws before still shows its progress line; progress
 * lines (still's, bench's) come at most every half of it. 1, or
 * TIDELINE_PROGRESS_DELAY when that is a number >= 0 (0: every update,
 * which the tests use so as not to depend on a slow frame). */
double tl_cli_progress_delay(void);

/* The colour flags of render and still (tl_cli_color.c): --working-space,
 * --ocio, --display, --view; their help lines TL_CLI_COLOR_USAGE. */
#include "color/tl_color.h"
struct tl_args;
struct tl_render;
struct tl_ocio_display;
typedef struct tl_cli_color {
    tl_working_space space; /* the EXR colour's */
    int has_space;          /* --working-space given */
    const char *ocio, *display, *view;
    /* After tl_cli_color_prepare: */
    int convert; /* space is not the radiance's: matrix takes it there */
    double matrix[9];
    struct tl_ocio_display *transform; /* the display transform, or NULL: the ACES fit */
    float *lut;                        /* its table (tl_color.h's layout) */
} tl_cli_color;
#define TL_CLI_DISPLAY_USAGE                                                                       \
    "  --ocio CONFIG          display images through this OpenColorIO config's display\n"          \
    "                         and view (default $OCIO; without either the ACES fit,\n"             \
    "                         unless --display or --view asks for tideline's own config)\n"        \
    "  --display NAME         the config's display (default: its default display)\n"               \
    "  --view NAME            the display's view (default: its default view)\n"
#define TL_CLI_COLOR_USAGE                                                                         \
    "  --working-space rec709|acescg\n"                                                            \
    "                         the EXR colour's space (default: the timeline's\n"                   \
    "                         `working_space` line, else rec709); its chromaticities\n"            \
    "                         are the file's\n" TL_CLI_DISPLAY_USAGE
/* One of the colour flags into c: 1 matched, 0 not one of them, -1 an
 * error (err filled). */
int tl_cli_color_flag(struct tl_args *a, tl_cli_color *c, tl_error *err);
/* The working space (the flag over the timeline's `timeline_space`), its
 * matrix, and the display transform when a config (--ocio, or $OCIO when
 * the run `shows` display images: PNGs, a movie, a window) or --display /
 * --view asks for one, baked into its table. Errors name the config,
 * display or view (usage errors, 2). */
int tl_cli_color_prepare(tl_cli_color *c, int timeline_space, int shows, tl_error *err);
/* Hands the display table to the renderer (nothing for the ACES fit). */
int tl_cli_color_use(const tl_cli_color *c, struct tl_render *render, tl_error *err);
const char *tl_cli_color_describe(const tl_cli_color *c);
void tl_cli_color_free(tl_cli_color *c);

/* --passes LIST (`flag` its name) into *passes (TL_PASSES_*): a usage
 * error naming the unknown pass and listing the valid ones. */
int tl_cli_passes(const char *flag, const char *value, unsigned *passes, tl_error *err);

/* Prints err as one line (with file:line:col when it has one). */
void tl_cli_print_error(const char *command, const tl_error *err);

#endif
