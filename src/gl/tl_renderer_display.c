/* The display pass: the scene's radiance (at the render size) into the
 * planes that leave the GPU at the output size, with glare and the
 * tonemap; the window's letterboxed copy; the readback. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/tl_clock.h"
#include "gl/tl_renderer_internal.h"

GLuint tl_renderer_build_present(tl_renderer *r, int variant, tl_error *err)
{
    char defines[TL_DEFINES_SIZE];
    tl_renderer_defines(0, defines, sizeof defines);
    size_t n = strlen(defines);
    snprintf(defines + n, sizeof defines - n, "%s%s%s%s",
             (variant & TL_PRESENT_UPSCALE) ? "#define TL_PRESENT_UPSCALE 1\n" : "",
             (variant & TL_PRESENT_GLARE) ? "#define TL_PRESENT_GLARE 1\n" : "",
             (variant & TL_PRESENT_LUT) ? "#define TL_PRESENT_LUT 1\n" : "",
             (variant & TL_PRESENT_GLARE_LAYER) ? "#define TL_PRESENT_GLARE_LAYER 1\n" : "");
    return tl_renderer_build_program(r, "fullscreen.vert", "present.frag", defines, err);
}

/* The display pass's program for `variant`, built on first use. */
GLuint tl_renderer_present_program(tl_renderer *r, int variant, tl_error *err)
{
    if (!r->present_programs[variant])
        r->present_programs[variant] = tl_renderer_build_present(r, variant, err);
    return r->present_programs[variant];
}

/* Reads plane p (a TL_PLANE_*) of the last display pass into dst: a client
 * pointer, or an offset into the bound pixel-pack buffer. The display pass
 * wrote it top row first (present.frag), so its rows arrive in image order:
 * flipping GL's bottom-up rows here took as long as the transfer. */
static void read_plane(const tl_renderer *r, unsigned p, void *dst)
{
    if (p == TL_PLANE_AOV) { /* its groups one after another (tl_frame.h) */
        const size_t group = (size_t)r->aov.width * (size_t)r->aov.height * 4 * sizeof(float);
        glBindFramebuffer(GL_FRAMEBUFFER, r->aov.fbo);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        for (int i = 0; i < r->aov.attachments; i++) {
            glReadBuffer(GL_COLOR_ATTACHMENT0 + (GLenum)i);
            glReadPixels(0, 0, r->aov.width, r->aov.height, GL_RGBA, GL_FLOAT,
                         (char *)dst + (size_t)i * group);
        }
        return;
    }
    int filtered = p == TL_PLANE_DISPLAY && r->display_filtered;
    glBindFramebuffer(GL_FRAMEBUFFER, filtered ? r->filtered.fbo : r->display.fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0 + (p == TL_PLANE_COLOR ? 1u : p == TL_PLANE_DEPTH ? 2u : 0u));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, r->display.width, r->display.height, p == TL_PLANE_DEPTH ? GL_RED : GL_RGBA,
                 GL_FLOAT, dst);
}

/* A pass's RGBA32F target at w x h and its program (fragment shader `fs`,
 * built on first use). */
static int ensure_pass(tl_renderer *r, target *t, int w, int h, GLuint *program, const char *fs,
                       tl_error *err)
{
    const GLenum format = GL_RGBA32F;
    int rc = tl_renderer_target_ensure(t, w, h, 1, &format, err);
    if (!rc && !*program) {
        char defines[TL_DEFINES_SIZE];
        tl_renderer_defines(0, defines, sizeof defines);
        *program = tl_renderer_build_program(r, "fullscreen.vert", fs, defines, err);
        if (!*program)
            rc = err ? (int)err->status : TL_ERR_RUNTIME;
    }
    return rc;
}

/* The scene colour's mip levels 1..TL_GLARE_LEVELS (fewer for a small
 * scene), each the 2x2 mean of the one above, by a pass per level
 * (shaders/mip.frag). glGenerateMipmap leaves the filter to the driver:
 * where a size is odd llvmpipe's lost most of the coarse levels' light and
 * NVIDIA's kept it, so the two drivers' frames differed visibly
 * (docs/rendering.md, "Glare"). While a level is drawn the texture's base
 * and top level are the one above it, so the pass reads no level it
 * writes. */
#define TL_GLARE_LEVELS 6
static int mip_chain(tl_renderer *r, tl_error *err)
{
    target *t = &r->scene;
    int top = 0;
    while (top < TL_GLARE_LEVELS && (t->width >> (top + 1) > 0 || t->height >> (top + 1) > 0))
        top++;
    if (!r->mip_program) {
        char defines[TL_DEFINES_SIZE];
        tl_renderer_defines(0, defines, sizeof defines);
        r->mip_program = tl_renderer_build_program(r, "fullscreen.vert", "mip.frag", defines, err);
        if (!r->mip_program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
    }
    if (!r->mip_fbo)
        glGenFramebuffers(1, &r->mip_fbo);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_2D, t->tex[0]);
    if (t->mip_levels != top) { /* a new scene target: its levels' storage */
        for (int k = 1; k <= top; k++) {
            int w = t->width >> k, h = t->height >> k;
            glTexImage2D(GL_TEXTURE_2D, k, GL_RGBA32F, w > 0 ? w : 1, h > 0 ? h : 1, 0, GL_RGBA,
                         GL_FLOAT, NULL);
        }
        t->mip_levels = top;
    }
    glBindVertexArray(r->vao);
    glBindFramebuffer(GL_FRAMEBUFFER, r->mip_fbo);
    glUseProgram(r->mip_program);
    glUniform1i(tl_renderer_loc(r->mip_program, "u_src"), TL_UNIT_INPUT);
    for (int k = 1; k <= top; k++) {
        int w = t->width >> k, h = t->height >> k;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, k - 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, k - 1);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->tex[0], k);
        glViewport(0, 0, w > 0 ? w : 1, h > 0 ? h : 1);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, top);
    return tl_renderer_check("the glare's mip levels", err);
}

/* The glare image at a quarter of the output size (shaders/glare.frag),
 * read bilinearly by the display pass; from the scene's mip chain. */
static int glare_pass(tl_renderer *r, tl_error *err)
{
    const int d = TL_GLARE_DIVISOR;
    int w = (r->display.width + d - 1) / d, h = (r->display.height + d - 1) / d;
    int rc = ensure_pass(r, &r->glare, w, h, &r->glare_program, "glare.frag", err);
    if (rc)
        return rc;
    glBindTexture(GL_TEXTURE_2D, r->glare.tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    rc = mip_chain(r, err);
    if (rc)
        return rc;
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_2D, r->scene.tex[0]);
    /* glare.frag reads whole levels (an integer lod): a blend between two
     * levels would weigh the second by 0, and llvmpipe would fetch it
     * anyway, for nothing. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    /* Level 0 too is read bilinearly (a half-size scene's first glare
     * level, u_glare_shift): at lod 0 GL magnifies, and the target's own
     * NEAREST made that level blocky. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindVertexArray(r->vao);
    glBindFramebuffer(GL_FRAMEBUFFER, r->glare.fbo);
    glViewport(0, 0, w, h);
    glUseProgram(r->glare_program);
    glUniform1i(tl_renderer_loc(r->glare_program, "u_hdr"), TL_UNIT_INPUT);
    glUniform2f(tl_renderer_loc(r->glare_program, "u_glare_size"), (float)w, (float)h);
    /* The scene at render_scale < 1: its levels are that much wider. */
    double shift = round(log2((double)r->display.height / r->scene.height));
    glUniform1f(tl_renderer_loc(r->glare_program, "u_glare_shift"),
                (float)(shift > 0.0 ? shift : 0.0));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return tl_renderer_check("the glare pass", err);
}

/* The pixel filter (shaders/filter.frag): the display image through a 3x3
 * Gaussian of `sigma` pixels into `filtered`. */
static int filter_pass(tl_renderer *r, float sigma, tl_error *err)
{
    int w = r->display.width, h = r->display.height;
    int rc = ensure_pass(r, &r->filtered, w, h, &r->filter_program, "filter.frag", err);
    if (rc)
        return rc;
    /* The Gaussian's weight one pixel off the centre, per axis, over the
     * three taps' sum: a. The shader's bilinear taps sit 2a texels out. */
    double side = exp(-0.5 / ((double)sigma * sigma));
    glBindFramebuffer(GL_FRAMEBUFFER, r->filtered.fbo);
    glViewport(0, 0, w, h);
    glUseProgram(r->filter_program);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_2D, r->display.tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glUniform1i(tl_renderer_loc(r->filter_program, "u_display"), TL_UNIT_INPUT);
    glUniform1f(tl_renderer_loc(r->filter_program, "u_filter_offset"),
                (float)(2.0 * side / (1.0 + 2.0 * side)));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    r->display_filtered = 1;
    return tl_renderer_check("the pixel filter", err);
}

/* The first axis of the upscale (shaders/upscale.frag): the scene's
 * radiance along x to the output's width, at the scene's height. */
static int upscale_rows(tl_renderer *r, tl_error *err)
{
    int w = r->display.width, h = r->scene.height;
    int rc = ensure_pass(r, &r->upscaled, w, h, &r->upscale_program, "upscale.frag", err);
    if (rc)
        return rc;
    glBindVertexArray(r->vao);
    glBindFramebuffer(GL_FRAMEBUFFER, r->upscaled.fbo);
    glViewport(0, 0, w, h);
    glUseProgram(r->upscale_program);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_2D, r->scene.tex[0]);
    glUniform1i(tl_renderer_loc(r->upscale_program, "u_hdr"), TL_UNIT_INPUT);
    glUniform1i(tl_renderer_loc(r->upscale_program, "u_out_width"), w);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return tl_renderer_check("the upscale's rows", err);
}

/* The compositing passes' data at the output size, top row first, nearest
 * (a coverage or a normal is not interpolated): a flipped blit of each of
 * the scene's attachments past its radiance and distance. */
static int aov_pass(tl_renderer *r, tl_error *err)
{
    if (!tl_renderer_aov_on(r))
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "the compositing passes were not drawn (tl_renderer_want_aov)");
    int w = r->display.width, h = r->display.height;
    enum { GROUPS = TL_SCENE_AOV_ATTACHMENTS - TL_SCENE_PLAIN_ATTACHMENTS };
    GLenum formats[GROUPS];
    for (int i = 0; i < GROUPS; i++)
        formats[i] = GL_RGBA32F;
    int rc = tl_renderer_target_ensure(&r->aov, w, h, GROUPS, formats, err);
    if (rc)
        return rc;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r->scene.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r->aov.fbo);
    for (int i = 0; i < GROUPS; i++) {
        glReadBuffer(GL_COLOR_ATTACHMENT0 + (GLenum)(TL_SCENE_PLAIN_ATTACHMENTS + i));
        glDrawBuffer(GL_COLOR_ATTACHMENT0 + (GLenum)i);
        glBlitFramebuffer(0, 0, r->scene.width, r->scene.height, 0, h, w, 0, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
    }
    GLenum draw[GROUPS];
    for (int i = 0; i < GROUPS; i++)
        draw[i] = GL_COLOR_ATTACHMENT0 + (GLenum)i;
    glDrawBuffers(GROUPS, draw);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return tl_renderer_check("the compositing passes' copy", err);
}

/* The display pass, writing only the planes in `planes` (the display image
 * always: the window shows it). */
static int display_pass(tl_renderer *r, const tl_display_settings *d, unsigned planes,
                        tl_error *err)
{
    int w = r->display.width, h = r->display.height;
    const float bloom = d->bloom;
    if (bloom > 0.0f) {
        tl_timers_start(&r->timers, TL_TIMED_GLARE);
        int rc = glare_pass(r, err);
        tl_timers_stop(&r->timers);
        if (rc)
            return rc;
    }
    int upscale = r->scene.width != w || r->scene.height != h;
    tl_timers_start(&r->timers, TL_TIMED_DISPLAY);
    if (upscale) {
        int rc = upscale_rows(r, err);
        if (rc)
            return rc;
    }
    glBindVertexArray(r->vao);
    glBindFramebuffer(GL_FRAMEBUFFER, r->display.fbo);
    const GLenum draw[3] = {GL_COLOR_ATTACHMENT0,
                            (planes & TL_PLANE_COLOR) ? GL_COLOR_ATTACHMENT1 : GL_NONE,
                            (planes & TL_PLANE_DEPTH) ? GL_COLOR_ATTACHMENT2 : GL_NONE};
    glDrawBuffers(3, draw);
    glViewport(0, 0, w, h);
    GLuint program = tl_renderer_present_program(
        r,
        (upscale ? TL_PRESENT_UPSCALE : 0) | (bloom > 0.0f ? TL_PRESENT_GLARE : 0) |
            (r->display_lut ? TL_PRESENT_LUT : 0) |
            (r->glare_layer && bloom > 0.0f ? TL_PRESENT_GLARE_LAYER : 0),
        err);
    if (!program)
        return err ? (int)err->status : TL_ERR_RUNTIME;
    glUseProgram(program);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_DISPLAY_GLARE);
    glBindTexture(GL_TEXTURE_2D, bloom > 0.0f ? r->glare.tex[0] : 0);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_DISPLAY_DISTANCE);
    glBindTexture(GL_TEXTURE_2D, r->scene.tex[1]);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_DISPLAY_HDR);
    glBindTexture(GL_TEXTURE_2D, upscale ? r->upscaled.tex[0] : r->scene.tex[0]);
    glUniform1i(tl_renderer_loc(program, "u_hdr"), TL_UNIT_DISPLAY_HDR);
    glUniform1i(tl_renderer_loc(program, "u_distance"), TL_UNIT_DISPLAY_DISTANCE);
    glUniform1i(tl_renderer_loc(program, "u_glare"), TL_UNIT_DISPLAY_GLARE);
    if (r->display_lut) {
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_DISPLAY_LUT);
        glBindTexture(GL_TEXTURE_3D, r->display_lut);
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_DISPLAY_HDR);
        glUniform1i(tl_renderer_loc(program, "u_display_lut"), TL_UNIT_DISPLAY_LUT);
    }
    glUniform2i(tl_renderer_loc(program, "u_out_size"), w, h);
    glUniform1f(tl_renderer_loc(program, "u_exposure"), d->exposure);
    glUniform3fv(tl_renderer_loc(program, "u_white_gain"), 1, d->white_gain);
    r->display_exposure = d->exposure;
    glUniform1f(tl_renderer_loc(program, "u_bloom"), bloom);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    tl_timers_stop(&r->timers);
    int rc = tl_renderer_check("the display pass", err);
    /* The pixel filter, in output pixels (after any upscale). */
    r->display_filtered = 0;
    if (!rc && d->pixel_filter > 0.0f) {
        tl_timers_start(&r->timers, TL_TIMED_FILTER);
        rc = filter_pass(r, d->pixel_filter, err);
        tl_timers_stop(&r->timers);
    }
    if (!rc && (planes & TL_PLANE_AOV))
        rc = aov_pass(r, err);
    return rc;
}

int tl_renderer_set_display_lut(tl_renderer *r, const float *rgb, int n, tl_error *err)
{
    if (!rgb) {
        if (r->display_lut)
            glDeleteTextures(1, &r->display_lut);
        r->display_lut = 0;
        return TL_OK;
    }
    if (!r->display_lut)
        glGenTextures(1, &r->display_lut);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_3D, r->display_lut);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB32F, n, n, n, 0, GL_RGB, GL_FLOAT, rgb);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_3D, 0);
    return tl_renderer_check("the display table", err);
}

int tl_renderer_display(tl_renderer *r, const tl_display_settings *display, tl_error *err)
{
    return display_pass(r, display, TL_PLANE_DISPLAY, err);
}

int tl_renderer_present(tl_renderer *r, int width, int height, tl_error *err)
{
    int w = r->display.width, h = r->display.height;
    /* Letterboxed: the frame keeps its aspect in the window. */
    double scale = fmin((double)width / w, (double)height / h);
    int dw = (int)(w * scale + 0.5), dh = (int)(h * scale + 0.5);
    int x0 = (width - dw) / 2, y0 = (height - dh) / 2;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r->display_filtered ? r->filtered.fbo : r->display.fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    /* The display image is stored top row first (present.frag): the blit
     * turns it the window's way up. */
    glBlitFramebuffer(0, 0, w, h, x0, y0 + dh, x0 + dw, y0, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return tl_renderer_check("presenting", err);
}

int tl_renderer_finish(tl_renderer *r, const tl_display_settings *display, unsigned planes,
                       tl_frame *frame, tl_error *err)
{
    int w = r->display.width, h = r->display.height;
    if (frame->width != w || frame->height != h)
        return tl_error_set(err, TL_ERR_RUNTIME, "frame buffer size does not match the render");
    int rc = display_pass(r, display, planes, err);
    if (rc)
        return rc;
    /* Wait for the GPU here (the readback would anyway), so the time the
     * transfers take can be told from the time the drawing took. */
    glFinish();
    tl_timers_collect(&r->timers);
    double t0 = tl_clock_seconds();
    /* Each plane is a transfer: only the ones asked for.
     * All three come from the display pass, at the output size. */
    if ((planes & TL_PLANE_AOV) && !frame->aov)
        return tl_error_set(err, TL_ERR_RUNTIME, "the frame has no plane for the passes' data");
    float *dst[4] = {frame->color, frame->depth, frame->display, frame->aov};
    for (int k = 0; k < 4; k++)
        if (planes & (1u << k))
            read_plane(r, 1u << k, dst[k]);
    r->readback_seconds = tl_clock_seconds() - t0;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return tl_renderer_check("reading the frame back", err);
}

int tl_renderer_finish_glare(tl_renderer *r, const tl_display_settings *display, tl_frame *frame,
                             tl_error *err)
{
    if (!(display->bloom > 0.0f)) { /* no glare: none to add */
        memset(frame->color, 0,
               sizeof *frame->color * 4 * (size_t)frame->width * (size_t)frame->height);
        return TL_OK;
    }
    r->glare_layer = 1;
    int rc = tl_renderer_finish(r, display, TL_PLANE_COLOR, frame, err);
    r->glare_layer = 0;
    return rc;
}

/* ---- the readback in two halves (tideline render) ---- */

/* A queued frame's planes in its pixel-pack buffer: colour, distance and
 * display, those asked for, one after another. */
static size_t plane_bytes(unsigned plane, int w, int h)
{
    size_t px = (size_t)w * (size_t)h;
    return px * sizeof(float) *
           (plane == TL_PLANE_DEPTH ? 1
            : plane == TL_PLANE_AOV ? TL_FRAME_AOV_FLOATS
                                    : 4);
}

int tl_renderer_finish_begin(tl_renderer *r, const tl_display_settings *display, unsigned planes,
                             tl_error *err)
{
    if (r->readback_queued == TL_READBACK_SLOTS)
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "%d frames already wait for their readback: collect one first",
                            TL_READBACK_SLOTS);
    int w = r->display.width, h = r->display.height;
    int rc = display_pass(r, display, planes, err);
    if (rc)
        return rc;
    tl_timers_collect(&r->timers);
    readback_slot *slot = &r->readback[(r->readback_head + r->readback_queued) % TL_READBACK_SLOTS];
    size_t need = 0;
    for (unsigned p = TL_PLANE_COLOR; p <= TL_PLANE_AOV; p <<= 1)
        if (planes & p)
            need += plane_bytes(p, w, h);
    if (!slot->buffer)
        glGenBuffers(1, &slot->buffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot->buffer);
    if (slot->bytes < need) {
        glBufferData(GL_PIXEL_PACK_BUFFER, (GLsizeiptr)need, NULL, GL_STREAM_READ);
        slot->bytes = need;
    }
    size_t offset = 0;
    for (unsigned p = TL_PLANE_COLOR; p <= TL_PLANE_AOV; p <<= 1) {
        if (!(planes & p))
            continue;
        read_plane(r, p, (void *)(uintptr_t)offset);
        offset += plane_bytes(p, w, h);
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glFlush(); /* the GPU starts on it now, while the caller draws on */
    slot->planes = planes;
    slot->width = w;
    slot->height = h;
    r->readback_queued++;
    return tl_renderer_check("queueing the readback", err);
}

int tl_renderer_queued_size(const tl_renderer *r, int *width, int *height)
{
    if (!r->readback_queued)
        return 0;
    *width = r->readback[r->readback_head].width;
    *height = r->readback[r->readback_head].height;
    return r->readback_queued;
}

unsigned tl_renderer_queued_planes(const tl_renderer *r)
{
    return r->readback_queued ? r->readback[r->readback_head].planes : 0;
}

int tl_renderer_finish_end(tl_renderer *r, tl_frame *frame, tl_error *err)
{
    if (!r->readback_queued)
        return tl_error_set(err, TL_ERR_RUNTIME, "no frame waits for its readback");
    readback_slot *slot = &r->readback[r->readback_head];
    r->readback_head = (r->readback_head + 1) % TL_READBACK_SLOTS;
    r->readback_queued--;
    if (frame->width != slot->width || frame->height != slot->height)
        return tl_error_set(err, TL_ERR_RUNTIME, "frame buffer size does not match the render");
    double t0 = tl_clock_seconds();
    size_t need = 0;
    for (unsigned p = TL_PLANE_COLOR; p <= TL_PLANE_AOV; p <<= 1)
        if (slot->planes & p)
            need += plane_bytes(p, slot->width, slot->height);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot->buffer);
    /* Waits for the transfers queued by finish_begin. */
    const char *src = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, (GLsizeiptr)need, GL_MAP_READ_BIT);
    int rc = TL_OK;
    if (!src) {
        rc = tl_renderer_check("mapping the readback", err);
        if (!rc)
            rc = tl_error_set(err, TL_ERR_RUNTIME, "the readback buffer could not be mapped");
    } else {
        float *dst[4] = {frame->color, frame->depth, frame->display, frame->aov};
        size_t offset = 0;
        for (int k = 0; k < 4; k++) {
            unsigned p = 1u << k;
            if (!(slot->planes & p))
                continue;
            if (!dst[k]) {
                rc = tl_error_set(err, TL_ERR_RUNTIME,
                                  "the frame has no plane for the passes' data");
                break;
            }
            size_t n = plane_bytes(p, slot->width, slot->height);
            memcpy(dst[k], src + offset, n);
            offset += n;
        }
        if (!glUnmapBuffer(GL_PIXEL_PACK_BUFFER))
            rc = tl_error_set(err, TL_ERR_RUNTIME, "the readback buffer was lost while mapped");
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    r->readback_seconds = tl_clock_seconds() - t0;
    return rc;
}

double tl_renderer_last_readback(const tl_renderer *r)
{
    return r->readback_seconds;
}
