/* The physical sky's sky-view table, built on the GPU (shaders/sky_view.frag)
 * from the atmosphere's two tables, which the CPU builds once per
 * atmosphere (src/sky/tl_sky.c). The table is read back too: the ambient
 * light the CPU derives from it (tl_sky_view_built) is a uniform. */
#include <stdlib.h>
#include <string.h>

#include "gl/tl_renderer_internal.h"
#include "sky/tl_sky.h"

/* An RGB float table as a bilinear, edge-clamped texture (the CPU's
 * bilinear() reads it the same way: texel centres at (i + 0.5) / w).
 * Stored RGBA: llvmpipe filters four floats faster than three. */
static int upload_table(GLuint *tex, const float *rgb, int w, int h, tl_error *err)
{
    float *rgba = malloc(sizeof(float) * 4 * (size_t)w * (size_t)h);
    if (!rgba)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < w * h; i++) {
        memcpy(rgba + 4 * i, rgb + 3 * i, 3 * sizeof(float));
        rgba[4 * i + 3] = 0.0f;
    }
    if (!*tex)
        glGenTextures(1, tex);
    glBindTexture(GL_TEXTURE_2D, *tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, rgba);
    free(rgba);
    return TL_OK;
}

static int ensure_view_pass(tl_renderer *r, tl_error *err)
{
    const GLenum format = GL_RGBA32F;
    int rc = tl_renderer_target_ensure(&r->sky_view, TL_SKY_VIEW_W, TL_SKY_VIEW_H, 1, &format, err);
    if (rc)
        return rc;
    /* The ocean's programs read it bilinearly (sky.glsl). */
    glBindTexture(GL_TEXTURE_2D, r->sky_view.tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    if (!r->sky_view_program) {
        char defines[TL_DEFINES_SIZE];
        tl_renderer_defines(0, defines, sizeof defines);
        r->sky_view_program =
            tl_renderer_build_program(r, "fullscreen.vert", "sky_view.frag", defines, err);
        if (!r->sky_view_program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
    }
    return TL_OK;
}

static void set_atmosphere(GLuint p, const tl_atmosphere *a)
{
    glUniform1f(tl_renderer_loc(p, "u_ground_radius"), (float)a->ground_radius);
    glUniform1f(tl_renderer_loc(p, "u_top_radius"), (float)a->top_radius);
    glUniform3f(tl_renderer_loc(p, "u_rayleigh"), (float)a->rayleigh[0], (float)a->rayleigh[1],
                (float)a->rayleigh[2]);
    glUniform1f(tl_renderer_loc(p, "u_rayleigh_height"), (float)a->rayleigh_height);
    glUniform1f(tl_renderer_loc(p, "u_mie_scattering"), (float)a->mie_scattering);
    glUniform1f(tl_renderer_loc(p, "u_mie_absorption"), (float)a->mie_absorption);
    glUniform1f(tl_renderer_loc(p, "u_mie_height"), (float)a->mie_height);
    glUniform1f(tl_renderer_loc(p, "u_mie_g"), (float)a->mie_g);
    glUniform3f(tl_renderer_loc(p, "u_ozone"), (float)a->ozone[0], (float)a->ozone[1],
                (float)a->ozone[2]);
    glUniform1f(tl_renderer_loc(p, "u_ozone_center"), (float)a->ozone_center);
    glUniform1f(tl_renderer_loc(p, "u_ozone_width"), (float)a->ozone_width);
    glUniform1f(tl_renderer_loc(p, "u_ground_albedo"), (float)a->ground_albedo);
}

/* Draws l's sky-view table for the sun and camera height into the
 * renderer's texture, and reads it back into l->view. */
static int build_view(tl_renderer *r, tl_sky_luts *l, double sun_elevation, double height,
                      tl_error *err)
{
    int rc = ensure_view_pass(r, err);
    if (rc)
        return rc;
    if (!r->sky_tables_valid || memcmp(&r->sky_atmosphere, &l->atmosphere, sizeof l->atmosphere)) {
        rc = upload_table(&r->sky_transmittance, &l->transmittance[0][0][0], TL_SKY_TRANSMITTANCE_W,
                          TL_SKY_TRANSMITTANCE_H, err);
        if (!rc)
            rc = upload_table(&r->sky_ms, &l->ms[0][0][0], TL_SKY_MS_SIZE, TL_SKY_MS_SIZE, err);
        if (rc)
            return rc;
        r->sky_atmosphere = l->atmosphere;
        r->sky_tables_valid = 1;
    }
    GLuint p = r->sky_view_program;
    glBindVertexArray(r->vao);
    glBindFramebuffer(GL_FRAMEBUFFER, r->sky_view.fbo);
    glViewport(0, 0, TL_SKY_VIEW_W, TL_SKY_VIEW_H);
    glUseProgram(p);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_SKY_TRANSMITTANCE);
    glBindTexture(GL_TEXTURE_2D, r->sky_transmittance);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_SKY_MULTIPLE);
    glBindTexture(GL_TEXTURE_2D, r->sky_ms);
    glUniform1i(tl_renderer_loc(p, "u_transmittance"), TL_UNIT_SKY_TRANSMITTANCE);
    glUniform1i(tl_renderer_loc(p, "u_ms"), TL_UNIT_SKY_MULTIPLE);
    glUniform2i(tl_renderer_loc(p, "u_view_size"), TL_SKY_VIEW_W, TL_SKY_VIEW_H);
    glUniform1f(tl_renderer_loc(p, "u_height"), (float)height);
    glUniform1f(tl_renderer_loc(p, "u_sun_elevation"), (float)sun_elevation);
    set_atmosphere(p, &l->atmosphere);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    /* Rows of increasing latitude, as l->view holds them. */
    float *rgba = malloc(sizeof(float) * 4 * TL_SKY_VIEW_W * TL_SKY_VIEW_H);
    if (!rgba) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, TL_SKY_VIEW_W, TL_SKY_VIEW_H, GL_RGBA, GL_FLOAT, rgba);
    float *view = &l->view[0][0][0];
    for (int i = 0; i < TL_SKY_VIEW_W * TL_SKY_VIEW_H; i++)
        memcpy(view + 3 * i, rgba + 4 * i, 3 * sizeof(float));
    free(rgba);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return tl_renderer_check("building the sky-view table", err);
}

int tl_renderer_prepare_sky(tl_renderer *r, tl_sky_luts *luts, double sun_elevation,
                            double altitude, tl_error *err)
{
    /* Both the texture and luts->view (the ambient's source) must be this
     * frame's: a table kept from a frame before, or built by another
     * renderer into the same luts, is built again. */
    int stale = !r->sky_tables_valid ||
                memcmp(&r->sky_atmosphere, &luts->atmosphere, sizeof luts->atmosphere) != 0 ||
                !r->sky_view_valid || r->sky_view_sun != sun_elevation ||
                r->sky_view_altitude != altitude ||
                tl_sky_view_stale(luts, sun_elevation, altitude);
    if (stale) {
        r->sky_view_valid = 0;
        int rc = build_view(r, luts, sun_elevation,
                            tl_sky_camera_height(&luts->atmosphere, altitude), err);
        if (rc)
            return rc;
        tl_sky_view_built(luts, sun_elevation, altitude);
        r->sky_view_sun = sun_elevation;
        r->sky_view_altitude = altitude;
        r->sky_view_valid = 1;
    }
    /* Bound every frame, built or not: texture units belong to the
     * context, which another renderer may share. */
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_SKY_VIEW);
    glBindTexture(GL_TEXTURE_2D, r->sky_view.tex[0]);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    return TL_OK;
}

void tl_renderer_free_sky(tl_renderer *r)
{
    tl_renderer_target_free(&r->sky_view);
    tl_renderer_drop_program(&r->sky_view_program);
    if (r->sky_transmittance)
        glDeleteTextures(1, &r->sky_transmittance);
    if (r->sky_ms)
        glDeleteTextures(1, &r->sky_ms);
    r->sky_transmittance = r->sky_ms = 0;
    r->sky_tables_valid = 0;
    r->sky_view_valid = 0;
}
