#include "cutscene/tl_cutscene.h"

#include <string.h>

/* Loads the mesh the timeline's boat is drawn with into *mesh. */
static int load_boat(const char *path, tl_timeline *tl, tl_mesh *mesh, tl_error *err)
{
    int rc = tl->boat_model[0] ? tl_mesh_load(tl->boat_model, mesh, err)
                               : tl_mesh_default_boat(mesh, err);
    if (rc && tl->boat_model_line) {
        /* At the line that named the model; the message names the file. */
        char message[sizeof err->message];
        snprintf(message, sizeof message, "%s", err->message);
        tl_error_set_at(err, err->status, path, tl->boat_model_line, tl->boat_model_column, "%s",
                        message);
    }
    if (!rc)
        tl_timeline_set_boat_bounds(tl, mesh->bounds_min, mesh->bounds_max);
    return rc;
}

int tl_cutscene_load(const char *path, tl_cutscene *out, tl_diags *diags, tl_error *err)
{
    memset(out, 0, sizeof *out);
    int rc = tl_timeline_parse_file(path, &out->timeline, diags, err);
    if (rc)
        return rc;
    if (!out->timeline.boat_path.present)
        return TL_OK;
    rc = load_boat(path, &out->timeline, &out->boat, err);
    if (rc) {
        tl_timeline_free(&out->timeline);
        memset(out, 0, sizeof *out);
        return rc;
    }
    out->has_boat = 1;
    return TL_OK;
}

void tl_cutscene_report(FILE *stream, const char *program, const tl_diags *diags,
                        const tl_error *err)
{
    if (diags && diags->count) {
        tl_diags_write(diags, stream);
        return;
    }
    if (!err || err->status == TL_OK)
        return;
    if (err->file[0] && err->line > 0)
        fprintf(stream, "%s:%d:%d: error: %s\n", err->file, err->line, err->column, err->message);
    else
        fprintf(stream, "%s: %s\n", program, err->message);
}

void tl_cutscene_free(tl_cutscene *cs)
{
    if (cs->has_boat)
        tl_mesh_free(&cs->boat);
    tl_timeline_free(&cs->timeline);
    memset(cs, 0, sizeof *cs);
}
