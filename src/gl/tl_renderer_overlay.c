/* The preview window's view of a presented frame: the false colour
 * (shaders/false_colour.frag) in place of the display image, and the
 * overlay's triangles blended over it (shaders/overlay.*). Both are drawn
 * into the window only, after the frame's planes were made: nothing here
 * reaches a frame that is read back. */
#include <epoxy/gl.h>
#include <stdio.h>

#include "color/tl_color.h"
#include "gl/tl_renderer.h"
#include "gl/tl_renderer_internal.h"

/* The letterboxed rectangle the frame takes in a window (GL's origin,
 * bottom left), as tl_renderer_present draws it. */
static void frame_rect(const tl_renderer *r, int width, int height, int rect[4])
{
    int w = r->display.width, h = r->display.height;
    double scale = (double)width / w < (double)height / h ? (double)width / w : (double)height / h;
    rect[2] = (int)(w * scale + 0.5);
    rect[3] = (int)(h * scale + 0.5);
    rect[0] = (width - rect[2]) / 2;
    rect[1] = (height - rect[3]) / 2;
}

static int draw_false_colour(tl_renderer *r, int width, int height, tl_error *err)
{
    if (!r->false_colour_program) {
        char defines[512];
        snprintf(defines, sizeof defines,
                 "#define TL_FALSE_COLOUR_BLACK %.17g\n#define TL_FALSE_COLOUR_SHADOW %.17g\n"
                 "#define TL_FALSE_COLOUR_BAND %.17g\n#define TL_FALSE_COLOUR_HIGHLIGHT %.17g\n"
                 "#define TL_FALSE_COLOUR_CLIP %.17g\n",
                 TL_FALSE_COLOUR_BLACK, TL_FALSE_COLOUR_SHADOW, TL_FALSE_COLOUR_BAND,
                 TL_FALSE_COLOUR_HIGHLIGHT, TL_FALSE_COLOUR_CLIP);
        r->false_colour_program =
            tl_renderer_build_program(r, "fullscreen.vert", "false_colour.frag", defines, err);
        if (!r->false_colour_program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
    }
    int rect[4];
    frame_rect(r, width, height, rect);
    GLuint p = r->false_colour_program;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(rect[0], rect[1], rect[2], rect[3]);
    glUseProgram(p);
    glBindVertexArray(r->vao);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_2D, r->scene.tex[0]);
    glUniform1i(glGetUniformLocation(p, "u_hdr"), TL_UNIT_INPUT);
    glUniform1f(glGetUniformLocation(p, "u_exposure"), r->display_exposure);
    glUniform4i(glGetUniformLocation(p, "u_frame"), rect[0], rect[1], rect[2], rect[3]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glViewport(0, 0, width, height);
    return tl_renderer_check("the false colour", err);
}

static int draw_overlay(tl_renderer *r, int width, int height, const float *vertices, int count,
                        tl_error *err)
{
    if (!r->overlay_program) {
        r->overlay_program = tl_renderer_build_program(r, "overlay.vert", "overlay.frag", "", err);
        if (!r->overlay_program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
    }
    if (!r->overlay_vao) {
        glGenVertexArrays(1, &r->overlay_vao);
        glGenBuffers(1, &r->overlay_vbo);
        glBindVertexArray(r->overlay_vao);
        glBindBuffer(GL_ARRAY_BUFFER, r->overlay_vbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void *)0);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                              (void *)(2 * sizeof(float)));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glUseProgram(r->overlay_program);
    glUniform2f(glGetUniformLocation(r->overlay_program, "u_window"), (float)width, (float)height);
    glBindVertexArray(r->overlay_vao);
    glBindBuffer(GL_ARRAY_BUFFER, r->overlay_vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)count * 6 * sizeof(float)), vertices,
                 GL_STREAM_DRAW);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArrays(GL_TRIANGLES, 0, count);
    glDisable(GL_BLEND);
    glBindVertexArray(r->vao);
    return tl_renderer_check("the overlay", err);
}

int tl_renderer_present_view(tl_renderer *r, int width, int height, int false_colour,
                             const float *overlay, int overlay_vertices, tl_error *err)
{
    int rc = tl_renderer_present(r, width, height, err);
    if (!rc && false_colour)
        rc = draw_false_colour(r, width, height, err);
    if (!rc && overlay && overlay_vertices > 0)
        rc = draw_overlay(r, width, height, overlay, overlay_vertices, err);
    return rc;
}

void tl_renderer_free_overlay(tl_renderer *r)
{
    tl_renderer_drop_program(&r->false_colour_program);
    tl_renderer_drop_program(&r->overlay_program);
    if (r->overlay_vbo)
        glDeleteBuffers(1, &r->overlay_vbo);
    if (r->overlay_vao)
        glDeleteVertexArrays(1, &r->overlay_vao);
    r->overlay_vbo = r->overlay_vao = 0;
}
