/* Using tideline as a library: load a timeline with everything it
 * references (its boat's model), render one frame headless and write it to
 * a file: the frame `tideline still TIMELINE.tl --frame FRAME` draws.
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

    tl_cutscene cutscene;
    tl_diags diags;
    if (tl_cutscene_load(argv[1], &cutscene, &diags, &err)) {
        /* file:line:col errors with carets, or the model's failure */
        tl_cutscene_report(stderr, "render_frame", &diags, &err);
        return 1;
    }
    if (diags.count)
        tl_diags_write(&diags, stderr); /* warnings: the timeline still loads */

    tl_render_settings settings = {0}; /* the timeline's size and quality */
    if (argc > 4 && sscanf(argv[4], "%dx%d", &settings.width, &settings.height) != 2) {
        fprintf(stderr, "bad size '%s'\n", argv[4]);
        tl_cutscene_free(&cutscene);
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
        rc = tl_render_use_cutscene(render, &cutscene, &err);
    if (!rc)
        rc = tl_render_timeline_frame(render, &cutscene.timeline, frame_number, &settings, &frame,
                                      &scene, &err);
    if (!rc)
        rc = tl_image_write(argv[3], &frame, NULL, &err);
    if (rc)
        fprintf(stderr, "render_frame: %s\n", err.message);
    else {
        char features[512]; /* what the frame drew: "ocean, ..., boat, ..." */
        tl_feature_describe(tl_render_last_features(render), features, sizeof features);
        printf("frame %ld (t = %.4f s) -> %s\nfeatures: %s\n", frame_number, scene.time, argv[3],
               features);
    }

    tl_frame_free(&frame);
    tl_render_close(render);
    tl_cutscene_free(&cutscene);
    return rc ? 1 : 0;
}
