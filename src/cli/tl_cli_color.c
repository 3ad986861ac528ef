/* The colour flags render and still share: the EXR's working space and an
 * OpenColorIO display transform for the display image (tl_cli.h). */
#include <stdio.h>
#include <stdlib.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "color/tl_color.h"
#include "ocio/tl_ocio.h"
#include "render/tl_render.h"

int tl_cli_color_flag(tl_args *a, tl_cli_color *c, tl_error *err)
{
    if (tl_args_match(a, "--working-space", NULL, true, err)) {
        if (a->value && tl_color_working_parse(a->value, &c->space)) {
            tl_error_set(err, TL_ERR_USAGE, "--working-space: '%s' is not rec709 or acescg",
                         a->value);
            return -1;
        }
        c->has_space = 1;
    } else if (tl_args_match(a, "--ocio", NULL, true, err)) {
        c->ocio = a->value;
    } else if (tl_args_match(a, "--display", NULL, true, err)) {
        c->display = a->value;
    } else if (tl_args_match(a, "--view", NULL, true, err)) {
        c->view = a->value;
    } else {
        return 0;
    }
    return err->status ? -1 : 1;
}

int tl_cli_color_prepare(tl_cli_color *c, int timeline_space, int shows, tl_error *err)
{
    if (!c->has_space)
        c->space = (tl_working_space)timeline_space;
    if (c->space != TL_WORKING_REC709) {
        int rc = tl_ocio_working_matrix(c->space, c->matrix, err);
        if (rc)
            return rc;
        c->convert = 1;
    }
    /* $OCIO alone sets the display of the images a run shows; a run that
     * writes only EXRs shows none, and does not need the config to load. */
    const char *env = getenv("OCIO");
    if (!c->ocio && !c->display && !c->view && (!(env && env[0]) || !shows))
        return TL_OK; /* the ACES fit */
    int rc = tl_ocio_display_open(c->ocio, c->display, c->view, &c->transform, err);
    if (rc) {
        if (c->ocio)
            tl_error_prefix(err, "--ocio");
        return rc;
    }
    c->lut = malloc(sizeof(float) * 3 * TL_COLOR_LUT_SIZE * TL_COLOR_LUT_SIZE * TL_COLOR_LUT_SIZE);
    if (!c->lut)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    return tl_ocio_display_bake(c->transform, TL_COLOR_LUT_SIZE, c->lut, err);
}

int tl_cli_color_use(const tl_cli_color *c, struct tl_render *render, tl_error *err)
{
    return c->lut ? tl_render_set_display_lut(render, c->lut, TL_COLOR_LUT_SIZE, err) : TL_OK;
}

const char *tl_cli_color_describe(const tl_cli_color *c)
{
    return c->transform ? tl_ocio_display_describe(c->transform) : "ACES fit (tideline's own)";
}

void tl_cli_color_free(tl_cli_color *c)
{
    if (c->transform)
        tl_ocio_display_close(c->transform);
    free(c->lut);
    c->transform = NULL;
    c->lut = NULL;
}
