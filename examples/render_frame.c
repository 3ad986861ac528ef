/* Using tideline as a library: load a timeline, render one frame headless
 * and write it to a file.
 *
 *   render_frame TIMELINE.tl FRAME OUTPUT.(exr|png) [WIDTHxHEIGHT]
 */
#include <stdio.h>
#include <stdlib.h>

#include "tideline.h"

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: %s TIMELINE.tl FRAME OUTPUT.(exr|png) [WIDTHxHEIGHT]\n", argv[0]);
        return 2;
    }
    tl_error err;
    tl_error_clear(&err);

    tl_timeline timeline;
    tl_diags diags;
    if (tl_timeline_parse_file(argv[1], &timeline, &diags, &err)) {
        if (diags.count)
            tl_diags_write(&diags, stderr); /* file:line:col errors with carets */
        else
            fprintf(stderr, "%s\n", err.message);
        return 1;
    }

    tl_render_settings settings = {0}; /* the timeline's size and quality */
    if (argc > 4 && sscanf(argv[4], "%dx%d", &settings.width, &settings.height) != 2) {
        fprintf(stderr, "bad size '%s'\n", argv[4]);
        tl_timeline_free(&timeline);
        return 2;
    }
    long frame_number = strtol(argv[2], NULL, 10);

    tl_shader_lib shaders;
    tl_shader_lib_embedded(&shaders);
    tl_render *render = NULL;
    tl_frame frame = {0};
    tl_scene scene;
    int rc = tl_render_open(&render, &shaders, &err);
    if (!rc)
        rc = tl_render_timeline_frame(render, &timeline, frame_number, &settings, &frame, &scene,
                                      &err);
    if (!rc)
        rc = tl_image_write(argv[3], &frame, NULL, &err);
    if (rc)
        fprintf(stderr, "render_frame: %s\n", err.message);
    else
        printf("frame %ld (t = %.4f s) -> %s\n", frame_number, scene.time, argv[3]);

    tl_frame_free(&frame);
    tl_render_close(render);
    tl_timeline_free(&timeline);
    return rc ? 1 : 0;
}
