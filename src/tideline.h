/* tideline as a library: one include for programs that load timelines and
 * render frames themselves. Link the `tideline_gl` CMake target (which
 * brings `tideline_core`). See examples/render_frame.c.
 *
 *   tl_cutscene_load()         file -> timeline + the files it references
 *                              (located diagnostics: tl_cutscene_report)
 *   tl_timeline_eval()         timeline + time -> scene (pure, double)
 *   tl_render_open()           headless EGL context + renderer
 *   tl_render_use_cutscene()   uploads the cutscene's boat
 *   tl_render_timeline_frame() timeline + frame number -> tl_frame
 *   tl_image_write()           tl_frame -> .exr / .png, atomically
 */
#ifndef TIDELINE_H
#define TIDELINE_H

#include "core/tl_error.h"
#include "cutscene/tl_cutscene.h"
#include "image/tl_frame.h"
#include "image/tl_image_io.h"
#include "prepare/tl_prepare.h"
#include "render/tl_render.h"
#include "scene/tl_scene.h"
#include "timeline/tl_parse.h"
#include "timeline/tl_timeline.h"

#endif
