/* The renderer's float framebuffers (tl_renderer_internal.h's `target`):
 * a size, up to TL_TARGET_ATTACHMENTS colour attachments and an optional
 * depth buffer, made again only when one of those changes. */
#include <string.h>
#include <unistd.h>

#include "gl/tl_renderer_internal.h"

/* The bytes of float targets a frame holds per pixel of its render size
 * (the scene's colour and distance, with the passes' six more; the boat's
 * lit hull, distance, surface and depth, and its mirror) and per pixel of
 * its output (the display pass's three planes, the passes' copy): a bound
 * on what a frame of that size asks of the device. */
#define TARGET_BYTES_RENDER     (16 + 4 + 16 + 4 + 16 + 4 + 16 + 4)
#define TARGET_BYTES_RENDER_AOV (6 * 16)
#define TARGET_BYTES_OUTPUT     (16 + 16 + 4)
#define TARGET_BYTES_OUTPUT_AOV (6 * 16)

/* The device's memory in bytes: NVIDIA's own count where the driver has
 * GL_NVX_gpu_memory_info; else, for a CPU renderer (llvmpipe) or a driver
 * that does not say, the machine's memory; 0 when unknown. */
static double device_memory(void)
{
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint kib = 0;
        glGetIntegerv(0x9048 /* GL_GPU_MEMORY_INFO_TOTAL_AVAILABLE_MEMORY_NVX */, &kib);
        if (kib > 0)
            return (double)kib * 1024.0;
    }
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? (double)pages * (double)page : 0.0;
}

int tl_renderer_check_size(int width, int height, int out_width, int out_height, int aov,
                           tl_error *err)
{
    GLint most = 0, viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &most);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    int side = most;
    for (int k = 0; k < 2; k++)
        if (viewport[k] > 0 && viewport[k] < side)
            side = viewport[k];
    int big = width > out_width ? width : out_width,
        tall = height > out_height ? height : out_height;
    if (side > 0 && (big > side || tall > side))
        return tl_error_set(err, TL_ERR_USAGE,
                            "a %dx%d frame is larger than the GPU holds: at most %d pixels a "
                            "side (GL_MAX_TEXTURE_SIZE, GL_MAX_VIEWPORT_DIMS)",
                            big, tall, side);
    /* The driver's own answer for the largest texture a frame makes: a
     * proxy texture takes no memory and comes back 0 wide when the real one
     * could not be made (a CPU renderer caps a texture's bytes). */
    const int sizes[2][2] = {{width, height}, {out_width, out_height}};
    for (int k = 0; k < 2; k++) {
        GLint got = 0;
        glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA32F, sizes[k][0], sizes[k][1], 0, GL_RGBA,
                     GL_FLOAT, NULL);
        /* Within GL_MAX_TEXTURE_SIZE (checked above) a proxy that does not
         * fit raises no GL error: none is left pending. */
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &got);
        if (got == 0)
            return tl_error_set(err, TL_ERR_USAGE,
                                "a %dx%d frame is larger than the GPU holds: the driver cannot "
                                "make a %dx%d float image (%.1f GiB)",
                                out_width, out_height, sizes[k][0], sizes[k][1],
                                (double)sizes[k][0] * sizes[k][1] * 16.0 / 1073741824.0);
    }
    double need =
        (double)width * height * (TARGET_BYTES_RENDER + (aov ? TARGET_BYTES_RENDER_AOV : 0)) +
        (double)out_width * out_height *
            (TARGET_BYTES_OUTPUT + (aov ? TARGET_BYTES_OUTPUT_AOV : 0));
    double have = device_memory();
    if (have > 0.0 && need > have)
        return tl_error_set(err, TL_ERR_USAGE,
                            "a %dx%d frame needs %.1f GiB of float framebuffers; the device "
                            "has %.1f GiB",
                            out_width, out_height, need / 1073741824.0, have / 1073741824.0);
    return TL_OK;
}

void tl_renderer_target_free(target *t)
{
    if (t->fbo)
        glDeleteFramebuffers(1, &t->fbo);
    if (t->attachments)
        glDeleteTextures(t->attachments, t->tex);
    if (t->depth)
        glDeleteRenderbuffers(1, &t->depth);
    memset(t, 0, sizeof *t);
}

/* (Re)creates `t` at the size with the given internal formats, with a
 * 32-bit float depth buffer when `depth` is set. */
int tl_renderer_target_ensure(target *t, int width, int height, int attachments,
                              const GLenum *formats, tl_error *err)
{
    return tl_renderer_target_ensure_depth(t, width, height, attachments, formats, 0, err);
}

int tl_renderer_target_ensure_depth(target *t, int width, int height, int attachments,
                                    const GLenum *formats, int depth, tl_error *err)
{
    if (t->fbo && t->width == width && t->height == height && t->attachments == attachments)
        return TL_OK;
    if (attachments < 1 || attachments > TL_TARGET_ATTACHMENTS)
        return tl_error_set(err, TL_ERR_RUNTIME, "a framebuffer of %d attachments", attachments);
    tl_renderer_target_free(t);
    glGenFramebuffers(1, &t->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo);
    glGenTextures(attachments, t->tex);
    t->attachments = attachments;
    GLenum draw[TL_TARGET_ATTACHMENTS];
    for (int i = 0; i < attachments; i++) {
        glBindTexture(GL_TEXTURE_2D, t->tex[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[i], width, height, 0,
                     formats[i] == GL_R32F ? GL_RED : GL_RGBA, GL_FLOAT, NULL);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        /* Clamped: the glare's wide taps must not wrap the top of the image
         * (a bright sun) onto its bottom. */
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)i, GL_TEXTURE_2D,
                               t->tex[i], 0);
        draw[i] = GL_COLOR_ATTACHMENT0 + (GLenum)i;
    }
    glDrawBuffers(attachments, draw);
    if (depth) {
        glGenRenderbuffers(1, &t->depth);
        glBindRenderbuffer(GL_RENDERBUFFER, t->depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t->depth);
    }
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        tl_renderer_target_free(t);
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "cannot create a %dx%d float framebuffer (status 0x%04x)", width,
                            height, status);
    }
    t->width = width;
    t->height = height;
    return tl_renderer_check("framebuffer creation", err);
}
