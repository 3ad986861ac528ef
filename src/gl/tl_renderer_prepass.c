/* The march prepass (quality.march_prepass): the ocean's march alone, one
 * ray per block of pixels, in levels from coarse to fine. Each level and
 * then the frame's own passes start their rays from the distances the
 * four rays around them found (shaders/march.glsl, march_hint): over smooth
 * water a pixel then solves for its hit in a few steps instead of marching
 * from the crest plane. */
#include <string.h>

#include "gl/tl_renderer_internal.h"

int tl_renderer_split(int w, int h, const int rect[4], int bands[4][4], int *has_rect)
{
    *has_rect = rect[0] < rect[2] && rect[1] < rect[3];
    if (!*has_rect) {
        const int all[4] = {0, 0, w, h};
        memcpy(bands[0], all, sizeof all);
        return 1;
    }
    const int around[4][4] = {{0, 0, w, rect[1]},
                              {0, rect[3], w, h},
                              {0, rect[1], rect[0], rect[3]},
                              {rect[2], rect[1], w, rect[3]}};
    int n = 0;
    for (int i = 0; i < 4; i++)
        if (around[i][0] < around[i][2] && around[i][1] < around[i][3])
            memcpy(bands[n++], around[i], sizeof around[i]);
    return n;
}

int tl_renderer_sky_from(const tl_frame_uniforms *u, int scale, int h)
{
    if (u->plan.sky_rows <= 0)
        return h;
    /* A row j's ray passes through the render's row scale * (j + 0.5). */
    int from = u->height - u->plan.sky_rows;
    int j = (2 * from + scale - 1) / (2 * scale);
    return j < 0 ? 0 : j > h ? h : j;
}

/* Under water the ocean's march is another (the lens, the surface from
 * below): no prepass there. */
int tl_renderer_prepass_scope(const tl_frame_uniforms *u, unsigned features, const int rect[4])
{
    if (features & TL_FEATURE_UNDERWATER)
        return TL_PREPASS_NONE;
    if (u->plan.march_prepass)
        return TL_PREPASS_FRAME;
    int has_rect = (features & TL_FEATURE_GIANT_WAVE) && rect[0] < rect[2] && rect[1] < rect[3];
    return u->plan.giant_prepass && has_rect ? TL_PREPASS_GIANT : TL_PREPASS_NONE;
}

static void bind_hint(GLuint program, const target *coarser, float pixel)
{
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_MARCH_HINT);
    glBindTexture(GL_TEXTURE_2D, coarser->tex[0]);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glUniform1i(tl_renderer_loc(program, "u_march_hint"), TL_UNIT_MARCH_HINT);
    glUniform1f(tl_renderer_loc(program, "u_hint_pixel"), pixel);
}

/* One level: a ray per scale x scale pixels into `t`, started from
 * `coarser` when there is one; TL_PREPASS_GIANT: the giant wave's
 * rectangle alone, the rest a miss. */
static int draw_level(tl_renderer *r, const tl_frame_uniforms *u, unsigned features,
                      const int rect[4], int scope, int scale, target *t, const target *coarser,
                      tl_error *err)
{
    const int w = (u->width + scale - 1) / scale, h = (u->height + scale - 1) / scale;
    const GLenum format = GL_R32F;
    int rc = tl_renderer_target_ensure(t, w, h, 1, &format, err);
    if (rc)
        return rc;
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo);
    glViewport(0, 0, w, h);
    /* The giant wave's program over its rectangle grown by a block: every
     * pixel's four rays must have seen the wave if it can. */
    int low[4] = {0, 0, 0, 0};
    if (rect[0] < rect[2] && rect[1] < rect[3]) {
        const int grown[4] = {rect[0] / scale - 1, rect[1] / scale - 1,
                              (rect[2] + scale - 1) / scale + 1, (rect[3] + scale - 1) / scale + 1};
        for (int i = 0; i < 4; i++) {
            int limit = i % 2 ? h : w;
            low[i] = grown[i] < 0 ? 0 : grown[i] > limit ? limit : grown[i];
        }
    }
    unsigned march =
        (features & (TL_FEATURE_GIANT_WAVE | TL_FEATURE_GIANT_BREAK | TL_FEATURE_LOD)) |
        TL_PASS_PREPASS;
    if (coarser)
        march |= TL_PASS_HINTED;
    int bands[4][4], has_rect;
    int n = tl_renderer_split(w, h, low, bands, &has_rect);
    /* Above the horizon, outside the wave's rectangle, every ray misses:
     * what the march would write there (-1) without the march. */
    const int sky = tl_renderer_sky_from(u, scale, h);
    const GLfloat miss[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
    if (scope == TL_PREPASS_GIANT) {
        /* The rectangle's pixels read their hints within the grown
         * rectangle; the clear only keeps last frame's values out. */
        glScissor(0, 0, w, h);
        glClearBufferfv(GL_COLOR, 0, miss);
        n = 0;
    }
    for (int i = 0; i < n; i++)
        if (bands[i][3] > sky && bands[i][2] > bands[i][0]) {
            int y0 = bands[i][1] > sky ? bands[i][1] : sky;
            glScissor(bands[i][0], y0, bands[i][2] - bands[i][0], bands[i][3] - y0);
            glClearBufferfv(GL_COLOR, 0, miss);
            bands[i][3] = y0;
        }
    for (int pass = scope == TL_PREPASS_GIANT; pass < 2; pass++) {
        if (pass == 1 && !has_rect)
            break;
        unsigned f =
            pass == 0 ? march & ~(unsigned)(TL_FEATURE_GIANT_WAVE | TL_FEATURE_GIANT_BREAK) : march;
        GLuint program = tl_renderer_use_ocean(r, u, f, err);
        if (!program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
        glUniform1f(tl_renderer_loc(program, "u_prepass_scale"), (float)scale);
        if (coarser)
            bind_hint(program, coarser, (float)scale);
        for (int i = 0; i < (pass == 0 ? n : 1); i++) {
            const int *b = pass == 0 ? bands[i] : low;
            if (b[1] >= b[3])
                continue;
            glScissor(b[0], b[1], b[2] - b[0], b[3] - b[1]);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    return TL_OK;
}

int tl_renderer_prepass(tl_renderer *r, const tl_frame_uniforms *u, unsigned features,
                        const int rect[4], int scope, int reuse, tl_error *err)
{
    const target *finest = &r->hint[0];
    if (reuse && finest->fbo && finest->width == (u->width + 1) / 2 &&
        finest->height == (u->height + 1) / 2) {
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_MARCH_HINT);
        glBindTexture(GL_TEXTURE_2D, finest->tex[0]);
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
        return TL_OK;
    }
    glDisable(GL_DEPTH_TEST);
    glDisablei(GL_BLEND, 0);
    glEnable(GL_SCISSOR_TEST);
    int rc = TL_OK;
    for (int level = TL_PREPASS_LEVELS - 1; level >= 0 && !rc; level--)
        rc = draw_level(r, u, features, rect, scope, 2 << level, &r->hint[level],
                        level + 1 < TL_PREPASS_LEVELS ? &r->hint[level + 1] : NULL, err);
    glDisable(GL_SCISSOR_TEST);
    if (rc)
        return rc;
    /* The frame's passes start from the finest level. */
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_MARCH_HINT);
    glBindTexture(GL_TEXTURE_2D, r->hint[0].tex[0]);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    return tl_renderer_check("march prepass", err);
}
