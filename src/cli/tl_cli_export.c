/* tideline export-camera: a timeline's camera, sun and floating objects as
 * an animated glTF scene, so that a 3D package can match the shot. */
#include <stdio.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "cutscene/tl_cutscene.h"
#include "export/tl_export.h"
#include "timeline/tl_timeline.h"

static const char usage[] =
    "Usage: tideline export-camera TIMELINE.tl -o FILE.gltf|FILE.glb\n"
    "\n"
    "Write the timeline's animation as a glTF 2.0 scene, a key per frame at\n"
    "its time: the camera (with its lens), the sun (a directional light along\n"
    "its rays) and each floating object by its name. Axes are glTF's (y up;\n"
    "tideline's north is -z), which Blender and other packages import as they\n"
    "import any glTF camera (docs/compositing.md).\n"
    "\n"
    "Options:\n"
    "  -o, --output FILE  .gltf (JSON, data embedded) or .glb (binary)\n"
    "  -h, --help         show this help\n"
    "\n"
    "Exit status: 0 written, 1 invalid timeline or failure, 2 usage error.\n";

int tl_cli_export_camera(int argc, char **argv)
{
    tl_error err;
    tl_error_clear(&err);
    tl_args a;
    tl_args_init(&a, argc - 1, argv + 1);
    const char *timeline = NULL, *out = NULL, *positional;
    int rc = 0;
    while (!rc && !tl_args_done(&a)) {
        if (tl_args_match(&a, "--help", "-h", false, &err)) {
            fputs(usage, stdout);
            return 0;
        } else if (tl_args_match(&a, "--output", "-o", true, &err)) {
            out = a.value;
            rc = err.status; /* the flag without its value */
        } else if (!err.status && !timeline && tl_args_positional(&a, &positional)) {
            timeline = positional;
        } else {
            rc = err.status ? (int)err.status : tl_args_unknown(&a, "export-camera", &err);
        }
    }
    if (!rc && !timeline)
        rc = tl_error_set(&err, TL_ERR_USAGE, "no timeline file given");
    if (!rc && !out)
        rc = tl_error_set(&err, TL_ERR_USAGE, "nothing to write: give -o FILE.gltf");
    if (!rc)
        rc = tl_export_check_path(out, &err);
    if (!rc)
        rc = tl_cli_make_parent_dirs(out, &err);
    if (rc) {
        tl_cli_print_error("export-camera", &err);
        return 2;
    }
    tl_timeline tl;
    tl_models models;
    if (tl_cli_load_timeline("export-camera", timeline, &tl, &models))
        return 1;
    tl_models_free(&models);
    rc = tl_export_camera(&tl, out, &err);
    tl_timeline_free(&tl);
    if (rc) {
        tl_cli_print_error("export-camera", &err);
        return rc == TL_ERR_USAGE ? 2 : 1;
    }
    return 0;
}
