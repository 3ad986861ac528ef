/* Checks of the whole timeline once it is read: what drives the camera
 * and the links to the boat, and keys past the timeline's end. Split from
 * tl_parse.c to keep it readable. */
#include "tl_parse_internal.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>

/* Conflicts between what drives the camera and the boat links, found once
 * the whole file is read; each is reported at the later of its lines. */
void tl_parse_check_links(parser *p)
{
    tl_timeline *tl = p->tl;
    const tl_track *pos = &tl->tracks[tl_channel_index(tl_channel_find("camera.position"))];
    const tl_track *yaw = &tl->tracks[tl_channel_index(tl_channel_find("camera.yaw"))];
    const tl_track *pitch = &tl->tracks[tl_channel_index(tl_channel_find("camera.pitch"))];
    char msg[256];
    struct {
        int line, active;
        const char *what;
    } drivers[3] = {
        {pos->line, pos->state != TL_TRACK_DEFAULT, "camera.position"},
        {tl->camera_path.line, tl->camera_path.present, "path camera"},
        {tl->camera_follow.line, tl->camera_follow.target != TL_TARGET_NONE, "follow camera"}};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (drivers[i].active && drivers[j].active) {
                int later = drivers[i].line > drivers[j].line ? i : j;
                int earlier = later == i ? j : i;
                snprintf(msg, sizeof msg, "the camera position comes from both %s (line %d) and %s",
                         drivers[earlier].what, drivers[earlier].line, drivers[later].what);
                tl_parse_diag_at_line(p, drivers[later].line, NULL, "%s", msg);
            }
    if (tl->camera_look.target != TL_TARGET_NONE) {
        const tl_track *aim[2] = {yaw, pitch};
        const char *names[2] = {"camera.yaw", "camera.pitch"};
        for (int i = 0; i < 2; i++)
            if (aim[i]->state != TL_TRACK_DEFAULT) {
                int line =
                    aim[i]->line > tl->camera_look.line ? aim[i]->line : tl->camera_look.line;
                snprintf(msg, sizeof msg,
                         "the camera looks at a target (line %d), so %s (line %d) cannot be set "
                         "or keyed",
                         tl->camera_look.line, names[i], aim[i]->line);
                tl_parse_diag_at_line(p, line, NULL, "%s", msg);
            }
    }
    const tl_link *needs_boat[3] = {&tl->camera_look, &tl->camera_follow, &tl->giant_follow};
    for (int i = 0; i < 3; i++) {
        const tl_link *l = needs_boat[i];
        if (l->target != TL_TARGET_BOAT || tl->objects[l->object].path.present)
            continue;
        if (l->object == 0)
            snprintf(msg, sizeof msg,
                     "this refers to the boat, but the timeline has no 'path boat'");
        else
            snprintf(msg, sizeof msg, "this refers to '%s', but the timeline has no 'path %s'",
                     tl->objects[l->object].name, tl->objects[l->object].name);
        tl_parse_diag_at_line(p, l->line, NULL, "%s", msg);
    }
    for (int k = 0; k < tl->object_count; k++) {
        const tl_object *o = &tl->objects[k];
        if (o->model_line && !o->path.present) {
            if (k == 0)
                snprintf(msg, sizeof msg,
                         "boat.model names the boat's mesh, but the timeline has no 'path boat'");
            else
                snprintf(msg, sizeof msg,
                         "%s.model names its mesh, but the timeline has no 'path %s'", o->name,
                         o->name);
            tl_parse_diag_at_line(p, o->model_line, NULL, "%s", msg);
        } else if (k > 0 && !o->path.present) {
            snprintf(msg, sizeof msg,
                     "'%s' is declared, but the timeline has no 'path %s': it is not drawn",
                     o->name, o->name);
            p->warning = 1;
            tl_parse_diag_at_line(p, o->line, NULL, "%s", msg);
            p->warning = 0;
        }
    }
}

/* Warnings for keys and path points past the end of the timeline (or all
 * before its start): times written in frames without the `f`, usually. */
void tl_parse_check_times(parser *p)
{
    tl_timeline *tl = p->tl;
    const double end = tl->duration * (1.0 + 1e-12);
    char msg[256];
    p->warning = 1;
    for (int j = 0; j < tl_channel_count() * tl->object_count; j++) {
        int i = j % tl_channel_count(), object = j / tl_channel_count();
        if (object > 0 && !tl_channel_is_object(tl_channel_at(i)))
            continue;
        const tl_track *tr = tl_timeline_track(tl, i, object);
        if (tr->state != TL_TRACK_KEYED || tr->past_end)
            continue;
        char label[96];
        if (object > 0)
            snprintf(label, sizeof label, "%s%s", tl->objects[object].name,
                     tl_channel_at(i)->name + 4);
        else
            snprintf(label, sizeof label, "%s", tl_channel_at(i)->name);
        double lo = INFINITY, hi = -INFINITY;
        for (int c = 0; c < tl_channel_at(i)->components; c++)
            if (tr->curve[c].count) {
                lo = fmin(lo, tr->curve[c].keys[0].t);
                hi = fmax(hi, tr->curve[c].keys[tr->curve[c].count - 1].t);
            }
        if (hi > end && lo > end)
            snprintf(msg, sizeof msg,
                     "all keys of %s lie after the end of the timeline (%.6g s), from %.6g s: "
                     "frames written without 'f'?",
                     label, tl->duration, lo);
        else if (hi < 0.0)
            snprintf(msg, sizeof msg, "all keys of %s lie before the timeline's start", label);
        else if (hi > end)
            snprintf(msg, sizeof msg,
                     "%s has keys past the end of the timeline (%.6g s), the last at %.6g s", label,
                     tl->duration, hi);
        else
            continue;
        tl_parse_diag_at_line(p, tr->line, NULL, "%s", msg);
    }
    const tl_path_track *paths[TL_OBJECT_MAX + 1] = {&tl->camera_path};
    const char *names[TL_OBJECT_MAX + 1] = {"camera"};
    for (int k = 0; k < tl->object_count; k++) {
        paths[k + 1] = &tl->objects[k].path;
        names[k + 1] = tl->objects[k].name;
    }
    for (int i = 0; i < tl->object_count + 1; i++) {
        const tl_path *path = &paths[i]->path;
        if (!paths[i]->present || path->count == 0 || path->points[path->count - 1].t <= end)
            continue;
        snprintf(msg, sizeof msg,
                 "path %s has points past the end of the timeline (%.6g s), the last at %.6g s",
                 names[i], tl->duration, path->points[path->count - 1].t);
        tl_parse_diag_at_line(p, paths[i]->line, NULL, "%s", msg);
    }
    p->warning = 0;
}

/* The first key of a block past the timeline's end, at its own line and
 * column (a warning): a bare number that fits as frames was likely meant
 * as frames, and the warning says what it would be. The end-of-file check
 * (tl_parse_check_times) leaves the channel alone then. */
void tl_parse_warn_past_end(parser *p, const token *time, double t)
{
    const tl_timeline *tl = p->tl;
    char hint[160] = "";
    int bare = 1;
    for (int k = 0; k < time->len; k++)
        bare &= isdigit((unsigned char)time->s[k]) != 0;
    if (bare && t / tl->fps <= tl->duration)
        snprintf(hint, sizeof hint, "; %s is read as seconds: %sf is frame %s = %.6g s", time->s,
                 time->s, time->s, t / tl->fps);
    p->warning = 1;
    tl_parse_diag(p, time->col, time->len, NULL,
                  "key at %.6g s lies past the end of the timeline (%.6g s)%s", t, tl->duration,
                  hint);
    p->warning = 0;
    p->block_track->past_end = true;
}
