/* tl_cutscene: a timeline with everything it references, loaded as one.
 *
 * A timeline names files of its own: the floating objects' models (and
 * their textures) and the soundtrack. Programs that render a timeline load it through here, so
 * that a library user draws the same frame as `tideline still`: the CLI's
 * commands and examples/render_frame.c both do.
 *
 *     tl_cutscene cs;
 *     tl_diags diags;
 *     if (tl_cutscene_load(path, &cs, &diags, &err))
 *         tl_cutscene_report(stderr, "myprog", &diags, &err);   // and fail
 *     ...  tl_render_use_cutscene(render, &cs, &err);  ...
 *     tl_cutscene_free(&cs);
 */
#ifndef TL_CUTSCENE_H
#define TL_CUTSCENE_H

#include <stdio.h>

#include "core/tl_error.h"
#include "mesh/tl_mesh.h"
#include "timeline/tl_parse.h"
#include "timeline/tl_timeline.h"

/* The meshes a timeline's floating objects are drawn with: one per
 * distinct model among the objects that have a path (NAME.model, or the
 * built-in boat), in the order the objects first name them; each object's
 * tl_boat.model indexes them. */
typedef struct tl_models {
    int count;
    tl_mesh mesh[TL_OBJECT_MAX];
} tl_models;

void tl_models_free(tl_models *models);

typedef struct tl_cutscene {
    tl_timeline timeline;
    tl_models models; /* none when no object has a path */
} tl_cutscene;

/* Parses the timeline at `path` and loads every file it references. On
 * success (TL_OK) `diags` may still hold warnings (likely mistakes; the
 * timeline loads) and the timeline knows its objects' models and bounds. On failure
 * nothing is left allocated: `diags` holds the parser's errors, or `err`
 * the failure, a model's at the timeline's line that named it. */
int tl_cutscene_load(const char *path, tl_cutscene *out, tl_diags *diags, tl_error *err);

/* Prints what a load said to `stream`: every diagnostic with its line and
 * a caret (tl_diags_write); when there are none and err holds a failure,
 * "file:line:col: error: message", or "program: message" without a
 * location. */
void tl_cutscene_report(FILE *stream, const char *program, const tl_diags *diags,
                        const tl_error *err);

void tl_cutscene_free(tl_cutscene *cs);

#endif
