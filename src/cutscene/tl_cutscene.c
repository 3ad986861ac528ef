#include "cutscene/tl_cutscene.h"

#include "audio/tl_audio.h"

#include <stdio.h>
#include <string.h>

/* Object k's built-in boat's paint (boat.paint, boat.cabin_paint: set
 * only, so their tracks hold them), or the scene's defaults. */
static void paint_of(const tl_timeline *tl, int k, double paint[6])
{
    tl_scene defaults;
    tl_scene_defaults(&defaults);
    const char *names[2] = {"boat.paint", "boat.cabin_paint"};
    for (int c = 0; c < 2; c++) {
        const tl_channel *ch = tl_channel_find(names[c]);
        const tl_track *tr = tl_timeline_track(tl, tl_channel_index(ch), k);
        double v[3];
        tl_channel_get(ch, &defaults, v);
        for (int i = 0; i < 3; i++)
            paint[3 * c + i] = tr->state == TL_TRACK_SET ? tr->value[i] : v[i];
    }
}

/* Loads the mesh object k is drawn with into the models, unless an
 * earlier object named the same file (or the built-in boat in the same
 * paint). */
static int load_model(const char *path, tl_timeline *tl, int k, tl_models *models, tl_error *err)
{
    const tl_object *o = &tl->objects[k];
    double paint[6], other[6];
    paint_of(tl, k, paint);
    for (int j = 0; j < k; j++) {
        if (!tl->objects[j].path.present || strcmp(tl->objects[j].model, o->model) != 0)
            continue;
        paint_of(tl, j, other);
        if (!o->model[0] && memcmp(paint, other, sizeof paint) != 0)
            continue;
        const tl_mesh *m = &models->mesh[tl->objects[j].mesh];
        tl_timeline_set_object_model(tl, k, tl->objects[j].mesh, m->bounds_min, m->bounds_max);
        return TL_OK;
    }
    tl_mesh *mesh = &models->mesh[models->count];
    int rc = o->model[0] ? tl_mesh_load(o->model, mesh, err)
                         : tl_mesh_builtin_boat(mesh, paint, paint + 3, err);
    if (rc && o->model_line) {
        /* At the line that named the model; the message names the file. */
        char message[sizeof err->message];
        snprintf(message, sizeof message, "%s", err->message);
        tl_error_set_at(err, err->status, path, o->model_line, o->model_column, "%s", message);
    }
    if (rc)
        return rc;
    tl_timeline_set_object_model(tl, k, models->count, mesh->bounds_min, mesh->bounds_max);
    models->count++;
    return TL_OK;
}

/* The soundtrack is opened now, so that a missing or undecodable file
 * stops the run at its line before any frame renders. */
static int probe_audio(const char *path, tl_timeline *tl, tl_error *err)
{
    tl_audio_info info;
    int rc = tl_audio_probe(tl->audio, &info, err);
    if (rc) {
        char message[sizeof err->message];
        snprintf(message, sizeof message, "%s", err->message);
        return tl_error_set_at(err, err->status, path, tl->audio_line, tl->audio_column, "%s",
                               message);
    }
    tl->audio_duration = info.duration;
    tl->audio_rate = info.sample_rate;
    tl->audio_channels = info.channels;
    return TL_OK;
}

void tl_models_free(tl_models *models)
{
    for (int i = 0; i < models->count; i++)
        tl_mesh_free(&models->mesh[i]);
    memset(models, 0, sizeof *models);
}

int tl_cutscene_load(const char *path, tl_cutscene *out, tl_diags *diags, tl_error *err)
{
    memset(out, 0, sizeof *out);
    int rc = tl_timeline_parse_file(path, &out->timeline, diags, err);
    if (rc)
        return rc;
    for (int k = 0; k < out->timeline.object_count && !rc; k++)
        if (out->timeline.objects[k].path.present)
            rc = load_model(path, &out->timeline, k, &out->models, err);
    if (!rc && out->timeline.audio[0])
        rc = probe_audio(path, &out->timeline, err);
    if (rc) {
        tl_models_free(&out->models);
        tl_timeline_free(&out->timeline);
        memset(out, 0, sizeof *out);
        return rc;
    }
    return TL_OK;
}

void tl_cutscene_report(FILE *stream, const char *program, const tl_diags *diags,
                        const tl_error *err)
{
    if (diags && diags->count) {
        tl_diags_write(diags, stream);
        /* Warnings alone: the failure came after the parse (a boat model). */
        if (diags->errors > 0)
            return;
    }
    if (!err || err->status == TL_OK)
        return;
    if (!tl_error_write_located(stream, err))
        fprintf(stream, "%s: %s\n", program, err->message);
}

void tl_cutscene_free(tl_cutscene *cs)
{
    tl_models_free(&cs->models);
    tl_timeline_free(&cs->timeline);
    memset(cs, 0, sizeof *cs);
}
