/* The probe: one of the shaders' functions evaluated at points read from a
 * texture, one per output texel (shaders/probe.frag lists the modes), so
 * the tests can hold the GPU's heights, slopes, optics, sky and foam
 * against the CPU's or against properties. */
#include "tl_renderer.h"

#include <epoxy/gl.h>
#include <stdlib.h>
#include <string.h>

#include "gl/tl_renderer_internal.h"

int tl_renderer_probe(tl_renderer *r, const tl_frame_uniforms *u, int mode, const float *xy,
                      int count, int octaves, float *out4, tl_error *err)
{
    float *points = calloc((size_t)(count > 0 ? count : 1) * 4, sizeof(float));
    if (!points)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < count; i++) {
        points[i * 4 + 0] = xy[i * 2 + 0];
        points[i * 4 + 1] = xy[i * 2 + 1];
    }
    int rc = tl_renderer_probe4(r, u, mode, points, count, octaves, out4, err);
    free(points);
    return rc;
}

int tl_renderer_probe4(tl_renderer *r, const tl_frame_uniforms *u, int mode, const float *in4,
                       int count, int octaves, float *out4, tl_error *err)
{
    if (count < 1 || octaves < 1 || octaves > u->octaves || mode < 0 || mode > TL_PROBE_MODE_MAX)
        return tl_error_set(err, TL_ERR_RUNTIME, "probe: bad mode, point or octave count");
    /* The features that change what the probe computes. */
    unsigned features =
        u->features &
        (TL_FEATURE_GIANT_WAVE | TL_FEATURE_GIANT_BREAK | TL_FEATURE_GIANT_LIP |
         TL_FEATURE_GIANT_SPRAY | TL_FEATURE_UNDERWATER | TL_FEATURE_WATERLINE | TL_FEATURE_FOG |
         TL_FEATURE_SKY_PHYSICAL | TL_FEATURE_SUN_DISC | TL_FEATURE_WAKE | TL_FEATURE_BOW_SPRAY |
         TL_FEATURE_CAUSTICS | TL_FEATURE_SEA_FLOOR | TL_FEATURE_GIANT_CAUSTICS);
    GLuint program = 0;
    for (int i = 0; i < r->probe_count; i++)
        if (r->probes[i].features == features)
            program = r->probes[i].program;
    if (!program) {
        if (r->probe_count == MAX_PROGRAMS)
            return tl_error_set(err, TL_ERR_RUNTIME, "probe: too many feature sets");
        char defines[TL_DEFINES_SIZE];
        if (tl_renderer_defines(features, defines, sizeof defines))
            return tl_error_set(err, TL_ERR_RUNTIME, "probe: #defines do not fit");
        program = tl_renderer_build_program(r, "fullscreen.vert", "probe.frag", defines, err);
        if (!program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
        r->probes[r->probe_count++] = (cached_program){features, 0, 0, program};
    }
    int width = count < 1024 ? count : 1024;
    int height = (count + width - 1) / width;
    float *texels = calloc((size_t)width * (size_t)height * 4, sizeof(float));
    float *out = malloc((size_t)width * (size_t)height * 4 * sizeof(float));
    if (!texels || !out) {
        free(texels);
        free(out);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    memcpy(texels, in4, (size_t)count * 4 * sizeof(float));
    GLuint points;
    glGenTextures(1, &points);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_2D, points);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    target t = {0};
    const GLenum formats[1] = {GL_RGBA32F};
    int rc = tl_renderer_target_ensure(&t, width, height, 1, formats, err);
    if (!rc) {
        glBindVertexArray(r->vao);
        glViewport(0, 0, width, height);
        glUseProgram(program);
        tl_renderer_upload_uniforms(program, u);
        rc = tl_renderer_upload_objects(r, u, err);
        /* target_ensure bound its own texture to unit 0: bind the points again. */
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
        glBindTexture(GL_TEXTURE_2D, points);
        glUniform1i(tl_renderer_loc(program, "u_points"), TL_UNIT_INPUT);
        glUniform1i(tl_renderer_loc(program, "u_probe_octaves"), octaves);
        glUniform1i(tl_renderer_loc(program, "u_probe_mode"), mode);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out);
        memcpy(out4, out, (size_t)count * 4 * sizeof(float));
        if (!rc)
            rc = tl_renderer_check("probe", err);
    }
    tl_renderer_target_free(&t);
    glDeleteTextures(1, &points);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    free(texels);
    free(out);
    return rc;
}

int tl_renderer_probe_heights(tl_renderer *r, const tl_frame_uniforms *u, const float *xz,
                              int count, int octaves, float *heights, tl_error *err)
{
    float *out = malloc((size_t)(count > 0 ? count : 1) * 4 * sizeof(float));
    if (!out)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    int rc = tl_renderer_probe(r, u, 0, xz, count, octaves, out, err);
    for (int i = 0; !rc && i < count; i++)
        heights[i] = out[i * 4];
    free(out);
    return rc;
}
