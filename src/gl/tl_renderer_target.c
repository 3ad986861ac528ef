/* The renderer's float framebuffers (tl_renderer_internal.h's `target`):
 * a size, up to TL_TARGET_ATTACHMENTS colour attachments and an optional
 * depth buffer, made again only when one of those changes. */
#include <string.h>

#include "gl/tl_renderer_internal.h"

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
