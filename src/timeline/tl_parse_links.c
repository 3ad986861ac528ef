/* The `look` and `follow` directives: links from the camera and the giant
 * wave's centre to the boat or a point. Split from tl_parse.c. */
#include "tl_parse_internal.h"

#include <ctype.h>
#include <math.h>
#include <string.h>

/* Parses `NAME [+ X Y Z]` (the boat, or a floating object the timeline
 * declared) or `X Y Z` (dims values) into a link. */
static int parse_target(parser *p, token *tok, int n, int first, int dims, int allow_point,
                        tl_link *link)
{
    if (first >= n) {
        tl_parse_diag(p, tok[n - 1].col + tok[n - 1].len, 1, NULL, "expected %s",
                      allow_point ? "'boat' or a point X Y Z" : "'boat'");
        return 1;
    }
    double *dst;
    int i = first;
    int object = tl_timeline_object(p->tl, tok[i].s);
    const char *names[TL_OBJECT_MAX + 1];
    for (int k = 0; k < p->tl->object_count; k++)
        names[k] = p->tl->objects[k].name;
    names[p->tl->object_count] = NULL;
    if (object >= 0) {
        link->target = TL_TARGET_BOAT;
        link->object = object;
        dst = link->offset;
        i++;
        if (i == n)
            return 0;
        if (strcmp(tok[i].s, "+") != 0) {
            ERR_AT(&tok[i], "expected '+' and an offset after '%s', got '%s'", tok[i - 1].s,
                   tok[i].s);
            return 1;
        }
        i++;
    } else if (allow_point && (isdigit((unsigned char)tok[i].s[0]) || tok[i].s[0] == '-' ||
                               tok[i].s[0] == '+' || tok[i].s[0] == '.')) {
        link->target = TL_TARGET_POINT;
        dst = link->point;
    } else if (p->tl->object_count > 1) {
        tl_parse_diag(p, tok[i].col, tok[i].len, tl_suggest(tok[i].s, names),
                      "no floating object is named '%s' (the boat, or one declared with 'boat "
                      "NAME' before this line)",
                      tok[i].s);
        return 1;
    } else if (allow_point) {
        link->target = TL_TARGET_POINT;
        dst = link->point;
    } else {
        tl_parse_diag(p, tok[i].col, tok[i].len, tl_suggest(tok[i].s, names),
                      "only the boat can be followed, not '%s'", tok[i].s);
        return 1;
    }
    if (n - i != dims) {
        tl_parse_diag(p, tok[n - 1].col, tok[n - 1].len, NULL, "expected %d numbers (%s), found %d",
                      dims, dims == 2 ? "X Z" : "X Y Z", n - i);
        return 1;
    }
    int axis2[2] = {0, 2};
    for (int c = 0; c < dims; c++) {
        double *v = &dst[dims == 2 ? axis2[c] : c];
        if (tl_parse_quantity(p, &tok[i + c], TL_UNIT_LENGTH, v))
            return 1;
        if (fabs(*v) > 1e9) {
            ERR_AT(&tok[i + c], "'%s' is out of range (|x| <= 1e9 m)", tok[i + c].s);
            return 1;
        }
    }
    return 0;
}

void tl_parse_dir_look(parser *p, token *tok, int n)
{
    if (n < 3 || strcmp(tok[1].s, "camera") != 0 || strcmp(tok[2].s, "at") != 0) {
        const token *t = n > 1 ? &tok[1] : &tok[0];
        ERR_AT(t, "expected 'look camera at boat [+ X Y Z]' or 'look camera at X Y Z'");
        return;
    }
    tl_link link = {0};
    if (parse_target(p, tok, n, 3, 3, 1, &link))
        return;
    if (p->tl->camera_look.target != TL_TARGET_NONE) {
        ERR_AT(&tok[0], "the camera already looks somewhere (line %d)", p->tl->camera_look.line);
        return;
    }
    link.line = p->line_no;
    p->tl->camera_look = link;
}

void tl_parse_dir_follow(parser *p, token *tok, int n)
{
    static const char *const who[] = {"camera", "giant.center", NULL};
    if (n < 2) {
        tl_parse_diag(p, tok[0].col + tok[0].len, 1, NULL,
                      "'follow' expects camera or giant.center");
        return;
    }
    tl_link *link;
    int dims;
    if (strcmp(tok[1].s, "camera") == 0) {
        link = &p->tl->camera_follow;
        dims = 3;
    } else if (strcmp(tok[1].s, "giant.center") == 0) {
        link = &p->tl->giant_follow;
        dims = 2;
    } else {
        tl_parse_diag(p, tok[1].col, tok[1].len, tl_suggest(tok[1].s, who),
                      "only camera and giant.center can follow, not '%s'", tok[1].s);
        return;
    }
    if (link->target != TL_TARGET_NONE) {
        ERR_AT(&tok[1], "%s already follows %s (line %d)", tok[1].s,
               link->object ? p->tl->objects[link->object].name : "the boat", link->line);
        return;
    }
    tl_link l = {0};
    if (parse_target(p, tok, n, 2, dims, 0, &l))
        return;
    l.line = p->line_no;
    *link = l;
}
