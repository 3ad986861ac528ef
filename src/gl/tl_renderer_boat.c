/* The floating objects' passes (tl_renderer_internal.h): their meshes on
 * the GPU, the sun's shadow map of each, the lit hulls and their distance,
 * and their mirror images in the water, for the ocean pass to composite
 * (shaders/boat.glsl); the uniform block the ocean pass reads them from. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "tl_renderer_internal.h"

/* Frees the mesh's buffers and textures. */
static void drop_mesh(gpu_mesh *g)
{
    if (g->vao) {
        glDeleteVertexArrays(1, &g->vao);
        glDeleteBuffers(1, &g->vbo);
        glDeleteBuffers(1, &g->ibo);
    }
    for (size_t i = 0; i < g->texture_count; i++) {
        if (g->textures[i])
            glDeleteTextures(1, &g->textures[i]);
        if (g->srgb[i])
            glDeleteTextures(1, &g->srgb[i]);
    }
    free(g->textures);
    free(g->srgb);
    free(g->parts);
    memset(g, 0, sizeof *g);
}

/* An image as a mipmapped, repeating texture. */
static GLuint upload_image(const tl_mesh_image *image, int srgb)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image->width, image->height,
                 0, GL_RGBA, GL_UNSIGNED_BYTE, image->rgba);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    return tex;
}

/* The colour maps (base colour, emissive) are sRGB, as glTF has them. */
static int map_is_srgb(int k)
{
    return k == TL_MESH_MAP_BASE_COLOR || k == TL_MESH_MAP_EMISSIVE;
}

/* The model's parts and their maps' textures, each image uploaded in the
 * encodings its maps read it in. */
static int upload_maps(gpu_mesh *g, const tl_mesh *mesh, tl_error *err)
{
    g->parts = malloc(mesh->part_count * sizeof *g->parts);
    g->textures = calloc(mesh->image_count ? mesh->image_count : 1, sizeof *g->textures);
    g->srgb = calloc(mesh->image_count ? mesh->image_count : 1, sizeof *g->srgb);
    if (!g->parts || !g->textures || !g->srgb)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    memcpy(g->parts, mesh->parts, mesh->part_count * sizeof *g->parts);
    g->part_count = mesh->part_count;
    g->texture_count = mesh->image_count;
    GLint most = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &most);
    for (size_t p = 0; p < mesh->part_count; p++)
        for (int k = 0; k < TL_MESH_MAP_COUNT; k++) {
            int i = mesh->parts[p].map[k];
            if (i < 0)
                continue;
            const tl_mesh_image *image = &mesh->images[i];
            if (image->width > most || image->height > most)
                return tl_error_set(err, TL_ERR_USAGE,
                                    "the boat's texture of %d x %d texels is over the GPU's "
                                    "limit of %d a side",
                                    image->width, image->height, (int)most);
            GLuint *slot = map_is_srgb(k) ? &g->srgb[i] : &g->textures[i];
            if (!*slot)
                *slot = upload_image(image, map_is_srgb(k));
        }
    g->maps = 1;
    return TL_OK;
}

static int upload_mesh(gpu_mesh *g, GLuint vao, const tl_mesh *mesh, tl_error *err)
{
    drop_mesh(g);
    if (!mesh || mesh->index_count == 0)
        return TL_OK;
    if (mesh->index_count > 0x7fffffff)
        return tl_error_set(err, TL_ERR_RUNTIME, "the boat mesh has too many triangles");
    /* Interleaved per vertex: position, normal, colour (3 each), then
     * roughness, metallic, occlusion, emission, then u v and the tangent
     * with its bitangent's sign (zero without maps). */
    enum { STRIDE = 19 };
    static const GLint SIZES[6] = {3, 3, 3, 4, 2, 4}, OFFSETS[6] = {0, 3, 6, 9, 13, 15};
    size_t n = mesh->vertex_count;
    float *interleaved = calloc(n * STRIDE, sizeof(float));
    if (!interleaved)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    for (size_t i = 0; i < n; i++) {
        float *v = interleaved + STRIDE * i;
        memcpy(v, mesh->positions + 3 * i, 3 * sizeof(float));
        memcpy(v + 3, mesh->normals + 3 * i, 3 * sizeof(float));
        memcpy(v + 6, mesh->colors + 3 * i, 3 * sizeof(float));
        if (mesh->surface)
            memcpy(v + 9, mesh->surface + 4 * i, 4 * sizeof(float));
        else
            memcpy(v + 9, (const float[]){0.5f, 0.0f, 1.0f, 0.0f}, 4 * sizeof(float));
        if (mesh->uvs)
            memcpy(v + 13, mesh->uvs + 2 * i, 2 * sizeof(float));
        if (mesh->tangents)
            memcpy(v + 15, mesh->tangents + 4 * i, 4 * sizeof(float));
    }
    glGenVertexArrays(1, &g->vao);
    glBindVertexArray(g->vao);
    glGenBuffers(1, &g->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, g->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * STRIDE * sizeof(float)), interleaved,
                 GL_STATIC_DRAW);
    free(interleaved);
    glGenBuffers(1, &g->ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(mesh->index_count * sizeof(uint32_t)),
                 mesh->indices, GL_STATIC_DRAW);
    for (GLuint a = 0; a < 6; a++) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, SIZES[a], GL_FLOAT, GL_FALSE, STRIDE * sizeof(float),
                              (const void *)(uintptr_t)(OFFSETS[a] * sizeof(float)));
    }
    glBindVertexArray(vao);
    g->indices = (GLsizei)mesh->index_count;
    tl_mesh_outline_of(mesh, &g->outline);
    g->lamp_count = tl_mesh_lamps(mesh, g->lamp, g->lamp_light);
    int rc = tl_mesh_has_maps(mesh) ? upload_maps(g, mesh, err) : TL_OK;
    if (rc) {
        drop_mesh(g);
        return rc;
    }
    return tl_renderer_check("uploading the boat mesh", err);
}

int tl_renderer_set_meshes(tl_renderer *r, const tl_mesh *meshes, int count, tl_error *err)
{
    for (int i = 0; i < TL_OBJECT_MAX; i++)
        drop_mesh(&r->meshes[i]);
    r->mesh_count = 0;
    if (count > TL_OBJECT_MAX)
        return tl_error_set(err, TL_ERR_USAGE, "at most %d models, not %d", TL_OBJECT_MAX, count);
    for (int i = 0; i < count; i++) {
        int rc = upload_mesh(&r->meshes[i], r->vao, &meshes[i], err);
        if (rc) {
            for (int j = 0; j <= i; j++)
                drop_mesh(&r->meshes[j]);
            return rc;
        }
    }
    r->mesh_count = count;
    return TL_OK;
}

int tl_renderer_set_mesh(tl_renderer *r, const tl_mesh *mesh, tl_error *err)
{
    return tl_renderer_set_meshes(r, mesh, mesh ? 1 : 0, err);
}

/* The mesh slot `pass` is drawn with: its model, or the first. */
static const gpu_mesh *mesh_of(const tl_renderer *r, const tl_object_pass *pass)
{
    const gpu_mesh *g =
        pass->mesh >= 0 && pass->mesh < r->mesh_count ? &r->meshes[pass->mesh] : &r->meshes[0];
    return g->vao ? g : NULL;
}

int tl_renderer_upload_objects(tl_renderer *r, const tl_frame_uniforms *u, tl_error *err)
{
    if (u->object_count <= 0)
        return TL_OK;
    if (!r->objects_ubo) {
        GLint most = 0;
        glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &most);
        if ((size_t)most < sizeof u->objects)
            return tl_error_set(err, TL_ERR_RUNTIME,
                                "the GPU's uniform blocks hold %d bytes; the floating objects' "
                                "need %zu",
                                (int)most, sizeof u->objects);
        /* Zeroed whole: a frame uploads only its slots, and the driver
         * may read the rest. */
        static const tl_object_uniforms zero[TL_OBJECT_MAX];
        glGenBuffers(1, &r->objects_ubo);
        glBindBuffer(GL_UNIFORM_BUFFER, r->objects_ubo);
        glBufferData(GL_UNIFORM_BUFFER, (GLsizeiptr)sizeof zero, zero, GL_DYNAMIC_DRAW);
    }
    tl_object_uniforms objects[TL_OBJECT_MAX];
    memcpy(objects, u->objects, (size_t)u->object_count * sizeof *objects);
    for (int i = 0; i < u->object_count; i++) {
        const gpu_mesh *g = mesh_of(r, &u->object_pass[i]);
        if (!g)
            continue;
        const tl_mesh_outline *o = &g->outline;
        tl_object_uniforms *b = &objects[i];
        memcpy(b->waterline, o->waterline, sizeof b->waterline);
        memcpy(b->plan, o->plan, sizeof b->plan);
        memcpy(b->plan_y, o->plan_y, sizeof b->plan_y);
        b->outline_z[0] = o->waterline_z[0];
        b->outline_z[1] = o->waterline_z[1];
        b->outline_z[2] = o->plan_z[0];
        b->outline_z[3] = o->plan_z[1];
        b->shadow_map[2] = o->bottom;
        /* Its lamps, camera-relative, lit by boat.lights (the model matrix
         * is column-major, its scale uniform). */
        const float *mm = u->object_pass[i].model;
        float scale = sqrtf(mm[0] * mm[0] + mm[1] * mm[1] + mm[2] * mm[2]);
        memset(b->lamp, 0, sizeof b->lamp);
        memset(b->lamp_light, 0, sizeof b->lamp_light);
        for (int k = 0; k < g->lamp_count && u->object_pass[i].lights > 0.0f; k++) {
            const float *p = g->lamp[k];
            for (int c = 0; c < 3; c++) {
                b->lamp[k][c] = mm[c] * p[0] + mm[4 + c] * p[1] + mm[8 + c] * p[2] + mm[12 + c];
                b->lamp_light[k][c] = g->lamp_light[k][c] * u->object_pass[i].lights;
            }
            b->lamp[k][3] = p[3] * scale;
            b->lamp_light[k][3] = g->lamp_light[k][3];
        }
    }
    glBindBuffer(GL_UNIFORM_BUFFER, r->objects_ubo);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, (GLsizeiptr)((size_t)u->object_count * sizeof *objects),
                    objects);
    glBindBufferBase(GL_UNIFORM_BUFFER, TL_OBJECTS_BINDING, r->objects_ubo);
    return tl_renderer_check("uploading the floating objects", err);
}

/* Binds part p's maps and factors for the mesh program (TL_MESH_MAPS). */
static void bind_part(const gpu_mesh *g, GLuint program, size_t p)
{
    static const char *const SAMPLERS[TL_MESH_MAP_COUNT] = {
        "u_map_base_color", "u_map_metallic_roughness", "u_map_normal", "u_map_occlusion",
        "u_map_emissive"};
    const tl_mesh_part *part = &g->parts[p];
    int mask = 0;
    for (int k = 0; k < TL_MESH_MAP_COUNT; k++) {
        int i = part->map[k];
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_MESH_MAPS + (GLenum)k);
        glBindTexture(GL_TEXTURE_2D, i < 0 ? 0 : (map_is_srgb(k) ? g->srgb[i] : g->textures[i]));
        glUniform1i(tl_renderer_loc(program, SAMPLERS[k]), TL_UNIT_MESH_MAPS + k);
        mask |= i < 0 ? 0 : 1 << k;
    }
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glUniform1i(tl_renderer_loc(program, "u_maps"), mask);
    glUniform3fv(tl_renderer_loc(program, "u_emissive"), 1, part->emissive);
    glUniform1f(tl_renderer_loc(program, "u_normal_scale"), part->normal_scale);
    glUniform1f(tl_renderer_loc(program, "u_occlusion_strength"), part->occlusion_strength);
}

/* Draws the mesh: at once, or part by part with each one's maps. */
static void draw_elements(const gpu_mesh *g, GLuint program)
{
    glBindVertexArray(g->vao);
    if (!g->maps || !program) {
        glDrawElements(GL_TRIANGLES, g->indices, GL_UNSIGNED_INT, NULL);
        return;
    }
    for (size_t p = 0; p < g->part_count; p++) {
        if (!g->parts[p].index_count)
            continue;
        bind_part(g, program, p);
        glDrawElements(GL_TRIANGLES, (GLsizei)g->parts[p].index_count, GL_UNSIGNED_INT,
                       (const void *)(uintptr_t)(g->parts[p].first_index * sizeof(uint32_t)));
    }
}

/* How draw_meshes draws: as seen, mirrored in each object's water plane
 * and clipped to what stands above it (the reflection seen from above),
 * or mirrored and clipped to what lies below (seen from under the water
 * in the surface's underside). */
enum { DRAW_DIRECT, DRAW_MIRROR_ABOVE, DRAW_MIRROR_BELOW };

/* Draws every object in view into `t` (cleared first), `scale` samples a
 * pixel along each axis, as `how` says. */
static void draw_meshes(tl_renderer *r, GLuint program, const target *t, const tl_frame_uniforms *u,
                        int how, int scale)
{
    const int mirrored = how != DRAW_DIRECT;
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo);
    glViewport(0, 0, u->width * scale, u->height * scale);
    const float zero[4] = {0, 0, 0, 0};
    const float sky[4] = {TL_FRAME_SKY_DEPTH, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    if (t->attachments > 1)
        glClearBufferfv(GL_COLOR, 1, sky);
    if (t->attachments > 2)
        glClearBufferfv(GL_COLOR, 2, zero);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
    if (mirrored)
        glEnable(GL_CLIP_DISTANCE0);
    for (int i = 0; i < u->object_count; i++) {
        const tl_object_pass *pass = &u->object_pass[i];
        const gpu_mesh *g = mesh_of(r, pass);
        if (!pass->drawn || !g)
            continue;
        /* Reflection about y = h: y -> 2h - y (column-major). */
        float h = u->objects[i].hull[1];
        const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        const float mirror[16] = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 2 * h, 0, 1};
        glUniformMatrix4fv(tl_renderer_loc(program, "u_mirror"), 1, GL_FALSE,
                           mirrored ? mirror : identity);
        glUniform3f(tl_renderer_loc(program, "u_eye"), 0.0f, mirrored ? 2 * h : 0.0f, 0.0f);
        /* The direct pass clips nothing, whatever the clip-distance state. */
        glUniform1f(tl_renderer_loc(program, "u_clip_height"), mirrored ? h : -1.0e30f);
        glUniform1f(tl_renderer_loc(program, "u_clip_sign"),
                    how == DRAW_MIRROR_BELOW ? -1.0f : 1.0f);
        glUniformMatrix4fv(tl_renderer_loc(program, "u_boat_model"), 1, GL_FALSE, pass->model);
        glUniform1i(tl_renderer_loc(program, "u_object"), i);
        glUniform1i(tl_renderer_loc(program, "u_scene_object"), pass->object);
        glUniform1f(tl_renderer_loc(program, "u_sunlit"), pass->sunlit);
        glUniform1f(tl_renderer_loc(program, "u_lights"), pass->lights);
        draw_elements(g, program);
    }
    glBindVertexArray(r->vao);
    glDisable(GL_CLIP_DISTANCE0);
}

/* The sun's view of each object that casts a shadow into its layer of the
 * shadow maps: depth alone, pushed a little away from the sun (polygon
 * offset) so that lit faces do not shadow themselves. */
static int draw_shadows(tl_renderer *r, const tl_frame_uniforms *u, tl_error *err)
{
    int layers = 0;
    for (int i = 0; i < u->object_count; i++)
        layers += u->object_pass[i].shadow_size > 0;
    if (layers > r->shadow_layers) {
        if (r->shadow_tex)
            glDeleteTextures(1, &r->shadow_tex);
        glGenTextures(1, &r->shadow_tex);
        glBindTexture(GL_TEXTURE_2D_ARRAY, r->shadow_tex);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, TL_BOAT_SHADOW_SIZE,
                     TL_BOAT_SHADOW_SIZE, layers, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        /* Compared in the lookup: bilinear percentage-closer filtering. */
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        r->shadow_layers = layers;
        if (!r->shadow_fbo)
            glGenFramebuffers(1, &r->shadow_fbo);
    }
    if (!r->shadow_program) {
        char defines[TL_DEFINES_SIZE];
        tl_renderer_defines(TL_FEATURE_BOAT | TL_FEATURE_BOAT_SHADOW, defines, sizeof defines);
        r->shadow_program =
            tl_renderer_build_program(r, "mesh_shadow.vert", "mesh_shadow.frag", defines, err);
        if (!r->shadow_program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, r->shadow_fbo);
    glDrawBuffer(GL_NONE);
    glUseProgram(r->shadow_program);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    int rc = TL_OK;
    for (int i = 0, layer = 0; i < u->object_count && !rc; i++) {
        const tl_object_pass *pass = &u->object_pass[i];
        const gpu_mesh *g = mesh_of(r, pass);
        if (pass->shadow_size <= 0)
            continue;
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, r->shadow_tex, 0, layer++);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            rc = tl_error_set(err, TL_ERR_RUNTIME, "the boat's shadow map is not supported");
            break;
        }
        /* Only the corner the frame uses: clearing and drawing all of it
         * for a boat a few pixels across cost a small frame four times
         * over. Cleared a texel past it: the lookup's filtered taps at its
         * edge read there, not what a larger map left. */
        const int size = pass->shadow_size;
        glViewport(0, 0, size, size);
        const int cleared = size + 2 < TL_BOAT_SHADOW_SIZE ? size + 2 : TL_BOAT_SHADOW_SIZE;
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, cleared, cleared);
        glClearDepth(1.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        if (!g)
            continue;
        glUniform1f(tl_renderer_loc(r->shadow_program, "u_boat_shadow_extent"),
                    u->objects[i].shadow_map[1]);
        glUniformMatrix4fv(tl_renderer_loc(r->shadow_program, "u_boat_model"), 1, GL_FALSE,
                           pass->model);
        glUniformMatrix4fv(tl_renderer_loc(r->shadow_program, "u_boat_shadow"), 1, GL_FALSE,
                           u->objects[i].shadow);
        draw_elements(g, 0); /* depth alone: no maps */
    }
    glBindVertexArray(r->vao);
    glDisable(GL_POLYGON_OFFSET_FILL);
    return rc;
}

static void bind_shadow(const tl_renderer *r, GLuint program)
{
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_BOAT_SHADOW);
    glBindTexture(GL_TEXTURE_2D_ARRAY, r->shadow_tex);
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glUniform1i(tl_renderer_loc(program, "u_boat_shadow_map"), TL_UNIT_BOAT_SHADOW);
}

/* The features that change how the hull is lit: the sun, the sky, the
 * water around it from below, its shadows, the caustics on it, the sand
 * under it (seen from below only). Each combination, with or without
 * maps, is a program (TL_MESH_PROGRAMS). */
static const unsigned MESH_FEATURES[TL_MESH_LIGHT_FEATURES] = {
    TL_FEATURE_SUN_DISC,    TL_FEATURE_SKY_PHYSICAL, TL_FEATURE_UNDERWATER,
    TL_FEATURE_BOAT_SHADOW, TL_FEATURE_CAUSTICS,     TL_FEATURE_SEA_FLOOR};

int tl_renderer_draw_boat(tl_renderer *r, const tl_frame_uniforms *u, int reuse, tl_error *err)
{
    /* With the compositing passes the hull's normal and object too. */
    const GLenum formats[3] = {GL_RGBA32F, GL_R32F, GL_RGBA32F};
    /* The hulls at n x n samples a pixel (quality.mesh_scale): the ocean
     * pass composites each over the water (boat_composite), so their
     * silhouettes and paint lines are antialiased. The mirror image is
     * smeared by the ripples anyway: one sample. */
    int scale = u->mesh_scale > 1 ? u->mesh_scale : 1;
    int rc = tl_renderer_target_ensure_depth(&r->boat, u->width * scale, u->height * scale,
                                             tl_renderer_aov_on(r) ? 3 : 2, formats, 1, err);
    if (!rc)
        rc = tl_renderer_target_ensure_depth(&r->mirror, u->width, u->height, 1, formats, 1, err);
    const int under = (u->features & TL_FEATURE_UNDERWATER) != 0;
    if (!rc && under)
        rc =
            tl_renderer_target_ensure_depth(&r->underside, u->width, u->height, 2, formats, 1, err);
    if (rc)
        return rc;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE); /* models may be open or wound either way */
    glDisable(GL_BLEND);
    unsigned features = 0;
    int variant = 0;
    unsigned lit_by = u->features;
    if (!(lit_by & TL_FEATURE_UNDERWATER)) /* the hull takes the sand's light under water alone */
        lit_by &= ~(unsigned)TL_FEATURE_SEA_FLOOR;
    for (int i = 0; i < TL_MESH_LIGHT_FEATURES; i++)
        if (lit_by & MESH_FEATURES[i]) {
            features |= MESH_FEATURES[i];
            variant |= 1 << i;
        }
    /* Compiled in only for models that have maps (a program with them
     * draws a model without any as well). */
    for (int i = 0; i < u->object_count; i++) {
        const gpu_mesh *g = mesh_of(r, &u->object_pass[i]);
        if (u->object_pass[i].drawn && g && g->maps)
            variant |= 1 << TL_MESH_LIGHT_FEATURES;
    }
    /* The sun's view does not move with a sample's offset: one map a frame. */
    if ((features & TL_FEATURE_BOAT_SHADOW) && !(reuse && r->shadow_fbo)) {
        rc = draw_shadows(r, u, err);
        if (rc) {
            glDisable(GL_DEPTH_TEST);
            return rc;
        }
    }
    GLuint *program = &r->mesh_program[variant];
    if (!*program) {
        char defines[TL_DEFINES_SIZE];
        tl_renderer_defines(features | TL_FEATURE_BOAT, defines, sizeof defines);
        if (variant & (1 << TL_MESH_LIGHT_FEATURES))
            strncat(defines, "#define TL_MESH_MAPS\n", sizeof defines - strlen(defines) - 1);
        *program = tl_renderer_build_program(r, "mesh.vert", "mesh.frag", defines, err);
        if (!*program) {
            glDisable(GL_DEPTH_TEST);
            return err ? (int)err->status : TL_ERR_RUNTIME;
        }
    }
    glUseProgram(*program);
    tl_renderer_upload_uniforms(*program, u);
    glUniformMatrix4fv(tl_renderer_loc(*program, "u_view_proj"), 1, GL_FALSE, u->view_proj);
    if (features & TL_FEATURE_BOAT_SHADOW)
        bind_shadow(r, *program);
    draw_meshes(r, *program, &r->boat, u, DRAW_DIRECT, scale);
    draw_meshes(r, *program, &r->mirror, u, DRAW_MIRROR_ABOVE, 1);
    if (under)
        draw_meshes(r, *program, &r->underside, u, DRAW_MIRROR_BELOW, 1);
    glDisable(GL_DEPTH_TEST);
    return tl_renderer_check("drawing the boat", err);
}

void tl_renderer_bind_boat(const tl_renderer *r, GLuint program, unsigned features)
{
    const GLuint textures[3] = {r->boat.tex[0], r->boat.tex[1], r->mirror.tex[0]};
    for (int i = 0; i < 3; i++) {
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_BOAT_COLOR + (GLenum)i);
        glBindTexture(GL_TEXTURE_2D, textures[i]);
    }
    glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
    glUniform1i(tl_renderer_loc(program, "u_boat_color"), TL_UNIT_BOAT_COLOR);
    glUniform1i(tl_renderer_loc(program, "u_boat_distance"), TL_UNIT_BOAT_DISTANCE);
    glUniform1i(tl_renderer_loc(program, "u_boat_reflection"), TL_UNIT_BOAT_REFLECTION);
    if (features & TL_PASS_AOV) {
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_BOAT_SURFACE);
        glBindTexture(GL_TEXTURE_2D, r->boat.tex[2]);
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
        glUniform1i(tl_renderer_loc(program, "u_boat_surface"), TL_UNIT_BOAT_SURFACE);
    }
    if (features & TL_FEATURE_UNDERWATER) {
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_BOAT_UNDERSIDE);
        glBindTexture(GL_TEXTURE_2D, r->underside.tex[0]);
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_BOAT_UNDERSIDE_DISTANCE);
        glBindTexture(GL_TEXTURE_2D, r->underside.tex[1]);
        glActiveTexture(GL_TEXTURE0 + TL_UNIT_INPUT);
        glUniform1i(tl_renderer_loc(program, "u_boat_underside"), TL_UNIT_BOAT_UNDERSIDE);
        glUniform1i(tl_renderer_loc(program, "u_boat_underside_distance"),
                    TL_UNIT_BOAT_UNDERSIDE_DISTANCE);
    }
    if (features & TL_FEATURE_BOAT_SHADOW)
        bind_shadow(r, program);
}

void tl_renderer_drop_boat_programs(tl_renderer *r)
{
    for (int i = 0; i < TL_MESH_PROGRAMS; i++)
        tl_renderer_drop_program(&r->mesh_program[i]);
    tl_renderer_drop_program(&r->shadow_program);
}

void tl_renderer_free_boat(tl_renderer *r)
{
    tl_renderer_set_meshes(r, NULL, 0, NULL);
    tl_renderer_drop_boat_programs(r);
    if (r->shadow_fbo)
        glDeleteFramebuffers(1, &r->shadow_fbo);
    if (r->shadow_tex)
        glDeleteTextures(1, &r->shadow_tex);
    if (r->objects_ubo)
        glDeleteBuffers(1, &r->objects_ubo);
    r->shadow_fbo = r->shadow_tex = r->objects_ubo = 0;
    r->shadow_layers = 0;
}
