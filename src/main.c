/* tideline: renders ocean cutscenes from plain-text timelines.
 * This file only dispatches to the commands in src/cli/. */
#include <stdio.h>
#include <string.h>

#include "cli/tl_cli.h"
#include "gl/tl_gl_context.h"
#include "gl/tl_gl_window.h"

static const char usage[] =
    "Usage: tideline COMMAND [options]\n"
    "\n"
    "Commands:\n"
    "  render    render a timeline's frames headless to EXR/PNG files and movies\n"
    "  still     render one frame headless to EXR and/or PNG\n"
    "  movie     make a movie (with the soundtrack) from frames rendered earlier\n"
    "  preview   play a timeline in a window and follow the file as it is edited\n"
    "  check     validate a timeline and summarise it\n"
    "  eval      print a timeline's channel values at a time or frames\n"
    "  compare   how far one image is from another (PSNR, SSIM, pixel error)\n"
    "  bench     measure each quality preset's time and error against reference\n"
    "  export-camera\n"
    "            write the camera, sun and boats' animation as glTF for a 3D package\n"
    "\n"
    "Options:\n"
    "  -h, --help       show this help ('tideline COMMAND --help' for a command)\n"
    "  --version        print the version ('--version -v' adds library versions)\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure or invalid timeline, 2 usage error.\n";

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs(usage, stderr);
        return 2;
    }
    const char *cmd = argv[1];
    char *help[] = {argv[0], argc > 2 ? argv[2] : NULL, "--help", NULL};
    if (strcmp(cmd, "help") == 0 && argc > 2) { /* `tideline help render`: its --help */
        argv = help;
        argc = 3;
        cmd = argv[1];
    }
    if (strcmp(cmd, "-h") == 0 || strcmp(cmd, "--help") == 0 || strcmp(cmd, "help") == 0) {
        fputs(usage, stdout);
        return 0;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("tideline %s\n", TL_VERSION);
        if (argc > 2 && (strcmp(argv[2], "-v") == 0 || strcmp(argv[2], "--verbose") == 0)) {
            char libs[256];
            tl_gl_library_versions(libs, sizeof libs);
            printf("%s; GLFW %s\n", libs, tl_gl_window_library_version());
        }
        return 0;
    }
    if (strcmp(cmd, "render") == 0)
        return tl_cli_render(argc - 1, argv + 1);
    if (strcmp(cmd, "still") == 0)
        return tl_cli_still(argc - 1, argv + 1);
    if (strcmp(cmd, "preview") == 0)
        return tl_cli_preview(argc - 1, argv + 1);
    if (strcmp(cmd, "check") == 0)
        return tl_cli_check(argc - 1, argv + 1);
    if (strcmp(cmd, "eval") == 0)
        return tl_cli_eval(argc - 1, argv + 1);
    if (strcmp(cmd, "bench") == 0)
        return tl_cli_bench(argc - 1, argv + 1);
    if (strcmp(cmd, "movie") == 0)
        return tl_cli_movie(argc - 1, argv + 1);
    if (strcmp(cmd, "compare") == 0)
        return tl_cli_compare(argc - 1, argv + 1);
    if (strcmp(cmd, "export-camera") == 0)
        return tl_cli_export_camera(argc - 1, argv + 1);
    fprintf(stderr, "tideline: unknown command '%s' (see 'tideline --help')\n", cmd);
    return 2;
}
