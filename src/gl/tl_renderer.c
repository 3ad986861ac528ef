#include "tl_renderer.h"

#include <ctype.h>
#include <epoxy/gl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "color/tl_color.h"
#include "gl/tl_renderer_internal.h"
#include "mesh/tl_mesh.h"
#include "optics/tl_optics.h"
#include "prepare/tl_uniform_list.h"
#include "waves/tl_bow_spray.h"
#include "waves/tl_caustics.h"
#include "waves/tl_giant_spray.h"
#include "waves/tl_kelvin.h"
#include "waves/tl_noise.h"

int tl_renderer_check(const char *what, tl_error *err)
{
    GLenum e = glGetError();
    if (e != GL_NO_ERROR)
        return tl_error_set(err, TL_ERR_RUNTIME, "OpenGL error 0x%04x during %s", e, what);
    return TL_OK;
}

static GLuint compile_stage(GLenum stage, const tl_shader_source *src, tl_error *err)
{
    GLuint s = glCreateShader(stage);
    const char *text = src->text;
    glShaderSource(s, 1, &text, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        char *annotated = tl_shader_annotate_log(src, log);
        tl_error_set(err, TL_ERR_RUNTIME, "shader %s failed to compile:\n%s", src->files[0],
                     annotated ? annotated : log);
        free(annotated);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

/* Builds vertex `vs` + fragment `fs` with the given #defines. */
GLuint tl_renderer_build_program(tl_renderer *r, const char *vs, const char *fs,
                                 const char *defines, tl_error *err)
{
    tl_shader_source vsrc, fsrc;
    if (tl_shader_compose(&r->lib, vs, defines, &vsrc, err))
        return 0;
    if (tl_shader_compose(&r->lib, fs, defines, &fsrc, err)) {
        tl_shader_source_free(&vsrc);
        return 0;
    }
    GLuint v = compile_stage(GL_VERTEX_SHADER, &vsrc, err);
    GLuint f = v ? compile_stage(GL_FRAGMENT_SHADER, &fsrc, err) : 0;
    tl_shader_source_free(&vsrc);
    tl_shader_source_free(&fsrc);
    if (!v || !f) {
        if (v)
            glDeleteShader(v);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = "";
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        tl_error_set(err, TL_ERR_RUNTIME, "shader program %s failed to link:\n%s", fs, log);
        glDeleteProgram(p);
        return 0;
    }
    /* The floating objects' block, for the programs that declare it. */
    GLuint block = glGetUniformBlockIndex(p, "tl_objects");
    if (block != GL_INVALID_INDEX)
        glUniformBlockBinding(p, block, TL_OBJECTS_BINDING);
    return p;
}

int tl_renderer_defines(unsigned features, char *out, size_t size)
{
    static const double variation[3] = TL_GIANT_VARIATION_WEIGHTS;
    int n = snprintf(
        out, size,
        "#define TL_MAX_OCTAVES %d\n"
        "#define TL_SKY_DEPTH %.1f\n"
        "#define TL_FAR 1.0e7\n"
        "#define TL_GIANT_SLOPE_BINS %d\n"
        "#define TL_GIANT_CONVERGED %.1e\n"
        "#define TL_GIANT_SHADOW_FADE %.3f\n"
        "#define TL_NOISE_CELL_MARGIN %.17g\n"
        "#define TL_NOISE_CELL_SHIFT_X %d\n"
        "#define TL_NOISE_CELL_SHIFT_Y %d\n"
        "#define TL_GIANT_THROUGH_STEPS %d\n"
        "#define TL_GIANT_THROUGH_FIRST %.17g\n"
        "#define TL_GIANT_THROUGH_GROWTH %.17g\n"
        "#define TL_GIANT_VARIATION_WEIGHTS %.17g, %.17g, %.17g\n"
        "#define TL_GIANT_PEEL_ROUND %.17g\n"
        "#define TL_GIANT_TROUGH_LIFT %.17g\n"
        "#define TL_GIANT_BACK_FILL %.17g\n"
        "#define TL_GIANT_LIP_RADIUS %.17g\n"
        "#define TL_GIANT_LIP_THROW %.17g\n"
        "#define TL_GIANT_LIP_THICKNESS %.17g\n"
        "#define TL_GIANT_LIP_TIP %.17g\n"
        "#define TL_GIANT_LIP_GROW %.17g\n"
        "#define TL_GIANT_LIP_ANCHOR %.17g\n"
        "#define TL_GIANT_LIP_ROOT %.17g\n"
        "#define TL_GIANT_LIP_SWEEP %.17g\n"
        "#define TL_GIANT_LIP_FADE %.17g\n"
        "#define TL_GIANT_LIP_COLLAPSE %.17g\n"
        "#define TL_GIANT_LIP_SWELL %.17g\n"
        "#define TL_GIANT_LIP_LUMP %.17g\n"
        "#define TL_GIANT_LIP_LUMP_CELL %.17g\n"
        "#define TL_GIANT_LIP_TEAR %.17g\n"
        "#define TL_GIANT_LIP_ROUGHEN %.17g\n"
        "#define TL_GIANT_LIP_LOW %.17g\n"
        "#define TL_GIANT_SHORT_WAVE_GAIN_MAX %.17g\n"
        "#define TL_GIANT_TRAIL_RAGGED %.17g\n"
        "#define TL_GIANT_TRAIL_RAGGED_CELL %.17g\n"
        "#define TL_GIANT_LIP_HIGH %.17g\n"
        "#define TL_GIANT_MIRROR_SPREAD %.17g\n"
        "#define TL_GIANT_MIRROR_SPREAD_MIN %.17g\n"
        "#define TL_GIANT_FACE_FRESNEL %.17g\n"
        "#define TL_GIANT_FACE_SHARP_FROM %.17g\n"
        "#define TL_GIANT_FACE_SHARP_TO %.17g\n"
        "#define TL_GIANT_FACE_SHARP_SHARE %.17g\n"
        "#define TL_GIANT_FACET_GRAZE %.17g\n"
        "#define TL_GIANT_GLOW_WAVE_SHARE %.17g\n"
        "#define TL_SPRAY_SIGMA %.17g\n"
        "#define TL_SPRAY_FROM %.17g\n"
        "#define TL_SPRAY_FULL %.17g\n"
        "#define TL_SPRAY_LANDING_RADIUS %.17g\n"
        "#define TL_SPRAY_SPLASH_RISE %.17g\n"
        "#define TL_SPRAY_SPLASH_AHEAD %.17g\n"
        "#define TL_SPRAY_SPLASH_GROW %.17g\n"
        "#define TL_SPRAY_BOW_GAIN %.17g\n"
        "#define TL_SPRAY_LANDING_GAIN %.17g\n"
        "#define TL_SPRAY_LANDING_MEAN %.17g\n"
        "#define TL_SPRAY_TIP_RADIUS %.17g\n"
        "#define TL_SPRAY_TIP_GAIN %.17g\n"
        "#define TL_SPRAY_TIP_SCALE %.17g\n"
        "#define TL_SPRAY_TIP_START %.17g\n"
        "#define TL_SPRAY_TIP_FULL %.17g\n"
        "#define TL_SPRAY_TIP_FADE %.17g\n"
        "#define TL_SPRAY_TIP_GONE %.17g\n"
        "#define TL_BOW_SPRAY_TORN_MEAN %.17g\n"
        "#define TL_BOW_SPRAY_END %.17g\n"
        "#define TL_BOW_SPRAY_REACH %.17g\n"
        "#define TL_BOW_SPRAY_WING %.17g\n"
        "#define TL_SPRAY_LANDING_TEAR_FROM %.17g\n"
        "#define TL_SPRAY_LANDING_TEAR_TO %.17g\n"
        "#define TL_SPRAY_LANDING_CLOSE %.17g\n"
        "#define TL_SPRAY_LANDING_OPEN %.17g\n"
        "#define TL_SPRAY_LANDING_SEED %.17g\n"
        "#define TL_SPRAY_LANDING_FROM %.17g\n"
        "#define TL_SPRAY_LANDING_FINE %.17g\n"
        "#define TL_SPRAY_LANDING_FINER %.17g\n"
        "#define TL_SPRAY_LANDING_FINE_LOW %.17g\n"
        "#define TL_SPRAY_LANDING_FINE_HIGH %.17g\n"
        "#define TL_SPRAY_LANDING_EDGE_FROM %.17g\n"
        "#define TL_SPRAY_LANDING_EDGE_TO %.17g\n"
        "#define TL_SPRAY_LANDING_MIST %.17g\n"
        "#define TL_SPRAY_JET %.17g\n"
        "#define TL_SPRAY_JET_DROP %.17g\n"
        "#define TL_SPRAY_JET_FROM %.17g\n"
        "#define TL_SPRAY_JET_IN %.17g\n"
        "#define TL_SPRAY_JET_OUT %.17g\n"
        "#define TL_SPRAY_JET_END %.17g\n"
        "#define TL_SPRAY_BURY_STEP %.17g\n"
        "#define TL_SPRAY_BURY %.17g\n"
        "#define TL_SPRAY_BURY_FROM %.17g\n"
        "#define TL_SPRAY_BURY_TO %.17g\n"
        "#define TL_BOW_SPRAY_TEAR_FROM %.17g\n"
        "#define TL_BOW_SPRAY_TEAR_TO %.17g\n"
        "#define TL_BOW_SPRAY_THIN %.17g\n"
        "#define TL_SPRAY_REACHES %.17g\n"
        "#define TL_SPRAY_LIFT %.17g\n"
        "#define TL_SPRAY_RISE %.17g\n"
        "#define TL_GIANT_LIP_EDGE %.17g\n"
        "#define TL_GIANT_LIP_EDGE_ARC %.17g\n"
        "#define TL_GIANT_LIP_FILLET %.17g\n"
        "#define TL_GIANT_LIP_FILLET_ARC %.17g\n"
        "#define TL_GIANT_LIP_FILLET_FROM %.17g\n"
        "#define TL_GIANT_LIP_FILLET_TO %.17g\n"
        "#define TL_SPRAY_PLUME_GAIN %.17g\n"
        "#define TL_SPRAY_WISP_FLOOR %.17g\n"
        "#define TL_SPRAY_GUST %.17g\n"
        "#define TL_SPRAY_GUST_CELL %.17g\n"
        "#define TL_SPRAY_ROOT_GAIN %.17g\n"
        "#define TL_SPRAY_ROOT_REACH %.17g\n"
        "#define TL_SPRAY_SHELTER_IN %.17g\n"
        "#define TL_SPRAY_SHELTER_OUT %.17g\n"
        "#define TL_WAKE_POINTS %d\n"
        "#define TL_WAKE_GROUP %d\n"
        "#define TL_WAKE_GROUPS %d\n"
        "#define TL_WAKE_SPEED_NONE %.3f\n"
        "#define TL_WAKE_SPEED_FULL %.3f\n"
        "#define TL_MARCH_RELAX %g\n"
        "#define TL_COLOR_SHAPER_LO %.17g\n"
        "#define TL_COLOR_SHAPER_HI %.17g\n"
        "#define TL_BOX_STEP_COST %g\n"
        "#define TL_MIRROR_DISTORT %g\n"
        "#define TL_MIRROR_SHIFT %g\n"
        "#define TL_MIRROR_UNDER_DETAIL %g\n"
        "#define TL_MIRROR_STREAK %g\n"
        "#define TL_BOAT_SHADOW_SIZE %d\n"
        "#define TL_BOAT_SHADOW_SCATTER %.17g\n"
        "#define TL_BOAT_CONTACT_LINE %.17g\n"
        "#define TL_BOAT_BOW_WAVE %.17g\n"
        "#define TL_MESH_WATERLINE_STATIONS %d\n"
        "#define TL_KELVIN_HEIGHT %.17g\n"
        "#define TL_KELVIN_FROUDE %.17g\n"
        "#define TL_KELVIN_CUSP_GAIN %.17g\n"
        "#define TL_KELVIN_WHITECAP_CUSP %.17g\n"
        "#define TL_KELVIN_WHITECAP_LENGTHS %.17g\n"
        "#define TL_WAKE_SPREAD %.17g\n"
        "#define TL_WAKE_OLD_OPACITY %.17g\n"
        "#define TL_MESH_MIN_ALPHA %.17g\n"
        "#define TL_MESH_F0_UNDER_WATER %.17g\n"
        "#define TL_MESH_WASH_LINE %.17g\n"
        "#define TL_MESH_BOW_CLIMB %.17g\n"
        "#define TL_MESH_WASH_FILM %.17g\n"
        "#define TL_MESH_LAMPS %d\n"
        "#define TL_WASH_STATIONS %d\n"
        "#define TL_LAMP_GLINT_MIN %.17g\n"
        "#define TL_MESH_WET_LOW %.17g\n"
        "#define TL_MESH_WET_HIGH %.17g\n"
        "#define TL_MESH_WET_DARKEN %.17g\n"
        "#define TL_OBJECT_MAX %d\n"
        "#define TL_FRAME_AOV_OBJECTS %d\n"
        "#define TL_GIANT_MATTE_SHARE %.17g\n"
        "#define TL_CAUSTIC_STEP %.17g\n"
        "#define TL_CAUSTIC_BLUR %.17g\n"
        "#define TL_CAUSTIC_PEAK %.17g\n"
        "#define TL_CAUSTIC_MIN_DOWN %.17g\n"
        "#define TL_CAUSTIC_CREST_REACH %.17g\n"
        "#define TL_CAUSTIC_SUN_SPREAD %.17g\n"
        "#define TL_CAUSTIC_FOLD %.17g\n"
        "#define TL_CAUSTIC_BAND %.17g\n"
        "#define TL_CAUSTIC_FINE_BLUR %.17g\n"
        "#define TL_CAUSTIC_FINE_SHARE %.17g\n"
        "#define TL_CAUSTIC_FINE_GAP %.17g\n"
        "#define TL_SHAFT_RANGE %.17g\n"
        "#define TL_PARTICLE_CELL %.17g\n"
        "#define TL_PARTICLE_RANGE %.17g\n"
        "#define TL_PARTICLE_NEAR %.17g\n"
        "#define TL_PARTICLE_PERIOD %d\n"
        "#define TL_PARTICLE_RADIUS_MIN %.17g\n"
        "#define TL_PARTICLE_RADIUS_MAX %.17g\n"
        "#define TL_PARTICLE_EFFICIENCY %.17g\n"
        "#define TL_PARTICLE_PIXEL_SPREAD %.17g\n"
        "#define TL_PARTICLE_MAX_CELLS %d\n"
        "#define TL_PARTICLE_FOCUS %.17g\n"
        "#define TL_PARTICLE_PUPIL %.17g\n"
        "#define TL_SHAFT_FOOTPRINT %.17g\n"
        "#define TL_SHAFT_SMOOTH %.17g\n"
        "#define TL_FLOOR_PERIOD %d\n"
        "#define TL_FRESNEL_TAP %.17g\n"
        "#define TL_FRESNEL_LEAST_SHARE %.17g\n"
        "#define TL_WINDOW_PIXEL_SPREAD %.17g\n"
        "#define TL_WATER_PHASE_G %.17g\n"
        "#define TL_WATER_SKY_SCATTER %.17g\n"
        "#define TL_WATER_MIN_SUN_DOWN %.17g\n"
        "#define TL_WATER_MAX_OPTICAL %.17g\n",
        TL_MAX_OCTAVES, (double)TL_FRAME_SKY_DEPTH, TL_GIANT_SLOPE_BINS, TL_GIANT_CONVERGED,
        TL_GIANT_SHADOW_FADE, TL_NOISE_CELL_MARGIN, TL_NOISE_CELL_SHIFT_X, TL_NOISE_CELL_SHIFT_Y,
        TL_GIANT_THROUGH_STEPS, TL_GIANT_THROUGH_FIRST, TL_GIANT_THROUGH_GROWTH, variation[0],
        variation[1], variation[2], TL_GIANT_PEEL_ROUND, TL_GIANT_TROUGH_LIFT, TL_GIANT_BACK_FILL,
        TL_GIANT_LIP_RADIUS, TL_GIANT_LIP_THROW, TL_GIANT_LIP_THICKNESS, TL_GIANT_LIP_TIP,
        TL_GIANT_LIP_GROW, TL_GIANT_LIP_ANCHOR, TL_GIANT_LIP_ROOT, TL_GIANT_LIP_SWEEP,
        TL_GIANT_LIP_FADE, TL_GIANT_LIP_COLLAPSE, TL_GIANT_LIP_SWELL, TL_GIANT_LIP_LUMP,
        TL_GIANT_LIP_LUMP_CELL, TL_GIANT_LIP_TEAR, TL_GIANT_LIP_ROUGHEN, TL_GIANT_LIP_LOW,
        TL_GIANT_SHORT_WAVE_GAIN_MAX, TL_GIANT_TRAIL_RAGGED, TL_GIANT_TRAIL_RAGGED_CELL,
        TL_GIANT_LIP_HIGH, TL_GIANT_MIRROR_SPREAD, TL_GIANT_MIRROR_SPREAD_MIN,
        TL_GIANT_FACE_FRESNEL, TL_GIANT_FACE_SHARP_FROM, TL_GIANT_FACE_SHARP_TO,
        TL_GIANT_FACE_SHARP_SHARE, TL_GIANT_FACET_GRAZE, TL_GIANT_GLOW_WAVE_SHARE, TL_SPRAY_SIGMA,
        TL_SPRAY_FROM, TL_SPRAY_FULL, TL_SPRAY_LANDING_RADIUS, TL_SPRAY_SPLASH_RISE,
        TL_SPRAY_SPLASH_AHEAD, TL_SPRAY_SPLASH_GROW, TL_SPRAY_BOW_GAIN, TL_SPRAY_LANDING_GAIN,
        TL_SPRAY_LANDING_MEAN, TL_SPRAY_TIP_RADIUS, TL_SPRAY_TIP_GAIN, TL_SPRAY_TIP_SCALE,
        TL_SPRAY_TIP_START, TL_SPRAY_TIP_FULL, TL_SPRAY_TIP_FADE, TL_SPRAY_TIP_GONE,
        TL_BOW_SPRAY_TORN_MEAN, TL_BOW_SPRAY_END, TL_BOW_SPRAY_REACH, TL_BOW_SPRAY_WING,
        TL_SPRAY_LANDING_TEAR_FROM, TL_SPRAY_LANDING_TEAR_TO, TL_SPRAY_LANDING_CLOSE,
        TL_SPRAY_LANDING_OPEN, TL_SPRAY_LANDING_SEED, TL_SPRAY_LANDING_FROM, TL_SPRAY_LANDING_FINE,
        TL_SPRAY_LANDING_FINER, TL_SPRAY_LANDING_FINE_LOW, TL_SPRAY_LANDING_FINE_HIGH,
        TL_SPRAY_LANDING_EDGE_FROM, TL_SPRAY_LANDING_EDGE_TO, TL_SPRAY_LANDING_MIST, TL_SPRAY_JET,
        TL_SPRAY_JET_DROP, TL_SPRAY_JET_FROM, TL_SPRAY_JET_IN, TL_SPRAY_JET_OUT, TL_SPRAY_JET_END,
        TL_SPRAY_BURY_STEP, TL_SPRAY_BURY, TL_SPRAY_BURY_FROM, TL_SPRAY_BURY_TO,
        TL_BOW_SPRAY_TEAR_FROM, TL_BOW_SPRAY_TEAR_TO, TL_BOW_SPRAY_THIN, TL_SPRAY_REACHES,
        TL_SPRAY_LIFT, TL_SPRAY_RISE, TL_GIANT_LIP_EDGE, TL_GIANT_LIP_EDGE_ARC, TL_GIANT_LIP_FILLET,
        TL_GIANT_LIP_FILLET_ARC, TL_GIANT_LIP_FILLET_FROM, TL_GIANT_LIP_FILLET_TO,
        TL_SPRAY_PLUME_GAIN, TL_SPRAY_WISP_FLOOR, TL_SPRAY_GUST, TL_SPRAY_GUST_CELL,
        TL_SPRAY_ROOT_GAIN, TL_SPRAY_ROOT_REACH, TL_SPRAY_SHELTER_IN, TL_SPRAY_SHELTER_OUT,
        TL_WAKE_POINTS, TL_WAKE_GROUP, TL_WAKE_GROUPS, TL_WAKE_SPEED_NONE, TL_WAKE_SPEED_FULL,
        TL_QUALITY_MARCH_RELAX, TL_COLOR_SHAPER_LO, TL_COLOR_SHAPER_HI, TL_QUALITY_GIANT_STEP_COST,
        TL_MIRROR_DISTORT, TL_MIRROR_SHIFT, TL_MIRROR_UNDER_DETAIL, TL_MIRROR_STREAK,
        TL_BOAT_SHADOW_SIZE, TL_BOAT_SHADOW_SCATTER, TL_BOAT_CONTACT_LINE, TL_BOAT_BOW_WAVE,
        TL_MESH_WATERLINE_STATIONS, TL_KELVIN_HEIGHT, TL_KELVIN_FROUDE, TL_KELVIN_CUSP_GAIN,
        TL_KELVIN_WHITECAP_CUSP, TL_KELVIN_WHITECAP_LENGTHS, TL_WAKE_SPREAD, TL_WAKE_OLD_OPACITY,
        TL_MESH_MIN_ALPHA, TL_MESH_F0_UNDER_WATER, TL_MESH_WASH_LINE, TL_MESH_BOW_CLIMB,
        TL_MESH_WASH_FILM, TL_MESH_LAMPS, TL_WASH_STATIONS, TL_LAMP_GLINT_MIN, TL_MESH_WET_LOW,
        TL_MESH_WET_HIGH, TL_MESH_WET_DARKEN, TL_OBJECT_MAX, TL_FRAME_AOV_OBJECTS,
        TL_GIANT_MATTE_SHARE, TL_CAUSTIC_STEP, TL_CAUSTIC_BLUR, TL_CAUSTIC_PEAK,
        TL_CAUSTIC_MIN_DOWN, TL_CAUSTIC_CREST_REACH, TL_CAUSTIC_SUN_SPREAD, TL_CAUSTIC_FOLD,
        TL_CAUSTIC_BAND, TL_CAUSTIC_FINE_BLUR, TL_CAUSTIC_FINE_SHARE, TL_CAUSTIC_FINE_GAP,
        TL_SHAFT_RANGE, TL_PARTICLE_CELL, TL_PARTICLE_RANGE, TL_PARTICLE_NEAR, TL_PARTICLE_PERIOD,
        TL_PARTICLE_RADIUS_MIN, TL_PARTICLE_RADIUS_MAX, TL_PARTICLE_EFFICIENCY,
        TL_PARTICLE_PIXEL_SPREAD, TL_PARTICLE_MAX_CELLS, TL_PARTICLE_FOCUS, TL_PARTICLE_PUPIL,
        TL_SHAFT_FOOTPRINT, TL_SHAFT_SMOOTH, TL_FLOOR_PERIOD, TL_FRESNEL_TAP,
        TL_FRESNEL_LEAST_SHARE, TL_WINDOW_PIXEL_SPREAD, TL_WATER_PHASE_G, TL_WATER_SKY_SCATTER,
        TL_WATER_MIN_SUN_DOWN, TL_WATER_MAX_OPTICAL);
    for (int i = 0; i < TL_FEATURE_COUNT && n > 0 && (size_t)n < size; i++)
        if (features & (1u << i))
            n += snprintf(out + n, size - (size_t)n, "#define %s 1\n", tl_feature_define(i));
    /* The light layers' constants (shaders/layers.glsl), from tl_light_layer. */
    for (int k = 0; k < TL_LIGHT_SHADED && n > 0 && (size_t)n < size; k++) {
        char name[32];
        const char *s = tl_light_layer_name(k);
        size_t j = 0;
        for (; s[j] && j + 1 < sizeof name; j++)
            name[j] = (char)toupper((unsigned char)s[j]);
        name[j] = '\0';
        n += snprintf(out + n, size - (size_t)n, "#define TL_LIGHT_%s %d\n", name, k);
    }
    return n > 0 && (size_t)n < size ? 0 : -1;
}

/* The ocean program for a feature set and octave counts. The counts are
 * compiled in: a wave loop with a constant bound is unrolled and its
 * per-octave uniforms become direct loads (on llvmpipe a march costs 11%
 * less than with the counts as uniforms). A new count is a new program. */
static GLuint ocean_program(tl_renderer *r, const tl_frame_uniforms *u, unsigned features,
                            tl_error *err)
{
    cached_program key = {features, u->march_octaves, u->normal_octaves, 0};
    for (int i = 0; i < r->program_count; i++)
        if (r->programs[i].features == key.features &&
            r->programs[i].march_octaves == key.march_octaves &&
            r->programs[i].normal_octaves == key.normal_octaves)
            return r->programs[i].program;
    char defines[TL_DEFINES_SIZE];
    int fits = tl_renderer_defines(features, defines, sizeof defines) == 0;
    size_t n = strlen(defines);
    int more = snprintf(defines + n, sizeof defines - n,
                        "#define TL_MARCH_OCTAVES %d\n#define TL_NORMAL_OCTAVES %d\n%s%s%s%s%s%s%s",
                        key.march_octaves, key.normal_octaves,
                        features & TL_PASS_PREPASS ? "#define TL_MARCH_PREPASS 1\n" : "",
                        features & TL_PASS_HINTED ? "#define TL_MARCH_HINT 1\n" : "",
                        features & TL_PASS_SKY ? "#define TL_SKY_ONLY 1\n" : "",
                        features & TL_PASS_MIRROR ? "#define TL_BOAT_MIRROR 1\n" : "",
                        features & TL_PASS_AOV ? "#define TL_PASS_AOV 1\n" : "",
                        features & TL_PASS_LAYERS ? "#define TL_PASS_LAYERS 1\n" : "",
                        features & TL_PASS_GIANT_MIRROR ? "#define TL_GIANT_MIRROR 1\n" : "");
    if (!fits || more < 0 || (size_t)more >= sizeof defines - n) {
        tl_error_set(err, TL_ERR_RUNTIME, "the ocean program's #defines do not fit in %d bytes",
                     TL_DEFINES_SIZE);
        return 0;
    }
    key.program = tl_renderer_build_program(r, "fullscreen.vert", "ocean.frag", defines, err);
    if (!key.program)
        return 0;
    if (r->program_count == MAX_PROGRAMS) { /* evict the oldest */
        glDeleteProgram(r->programs[0].program);
        memmove(r->programs, r->programs + 1, sizeof r->programs[0] * (MAX_PROGRAMS - 1));
        r->program_count--;
    }
    r->programs[r->program_count++] = key;
    return key.program;
}

int tl_renderer_create(tl_renderer **out, const tl_shader_lib *lib, tl_error *err)
{
    *out = NULL;
    tl_renderer *r = calloc(1, sizeof *r);
    if (!r)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    r->lib = *lib;
    r->light_layer = -1;
    glGenVertexArrays(1, &r->vao); /* core profile draws need a bound VAO */
    if (!tl_renderer_present_program(r, 0, err)) {
        tl_renderer_destroy(r);
        return err ? (int)err->status : TL_ERR_RUNTIME;
    }
    *out = r;
    return tl_renderer_check("renderer setup", err);
}

void tl_renderer_destroy(tl_renderer *r)
{
    if (!r)
        return;
    for (int i = 0; i < r->program_count; i++)
        glDeleteProgram(r->programs[i].program);
    for (int i = 0; i < TL_PRESENT_VARIANTS; i++)
        if (r->present_programs[i])
            glDeleteProgram(r->present_programs[i]);
    if (r->display_lut)
        glDeleteTextures(1, &r->display_lut);
    for (int i = 0; i < r->probe_count; i++)
        glDeleteProgram(r->probes[i].program);
    tl_renderer_target_free(&r->scene);
    tl_renderer_target_free(&r->aov);
    tl_renderer_target_free(&r->display);
    tl_renderer_target_free(&r->boat);
    tl_renderer_target_free(&r->mirror);
    tl_renderer_target_free(&r->underside);
    tl_renderer_target_free(&r->glare);
    for (int i = 0; i < TL_PREPASS_LEVELS; i++)
        tl_renderer_target_free(&r->hint[i]);
    if (r->glare_program)
        glDeleteProgram(r->glare_program);
    if (r->mip_program)
        glDeleteProgram(r->mip_program);
    if (r->mip_fbo)
        glDeleteFramebuffers(1, &r->mip_fbo);
    tl_renderer_target_free(&r->filtered);
    if (r->filter_program)
        glDeleteProgram(r->filter_program);
    tl_renderer_target_free(&r->upscaled);
    if (r->upscale_program)
        glDeleteProgram(r->upscale_program);
    tl_renderer_free_boat(r);
    tl_renderer_free_sky(r);
    tl_renderer_free_overlay(r);
    for (int i = 0; i < TL_READBACK_SLOTS; i++)
        if (r->readback[i].buffer)
            glDeleteBuffers(1, &r->readback[i].buffer);
    glDeleteVertexArrays(1, &r->vao);
    free(r);
}

GLint tl_renderer_loc(GLuint p, const char *name)
{
    return glGetUniformLocation(p, name);
}

/* One row of the uniform table: `count` values of `kind` from `data`. */
static void upload_row(GLint loc, tl_uniform_kind kind, GLsizei count, const void *data)
{
    if (loc < 0)
        return;
    switch (kind) {
    case TL_UNIFORM_FLOAT: glUniform1fv(loc, count, data); break;
    case TL_UNIFORM_VEC2: glUniform2fv(loc, count, data); break;
    case TL_UNIFORM_VEC3: glUniform3fv(loc, count, data); break;
    case TL_UNIFORM_VEC4: glUniform4fv(loc, count, data); break;
    case TL_UNIFORM_INT:
    case TL_UNIFORM_BOOL: /* GL sets a bool from an int */ glUniform1iv(loc, count, data); break;
    case TL_UNIFORM_UINT: glUniform1uiv(loc, count, data); break;
    case TL_UNIFORM_MAT4: glUniformMatrix4fv(loc, count, GL_FALSE, data); break;
    }
}

/* Uploads the rows of tl_uniform_list.h that the frame's features use.
 * Uniforms a program does not use are optimised away and have location
 * -1, which GL ignores. */
void tl_renderer_upload_uniforms(GLuint p, const tl_frame_uniforms *u)
{
#define UPLOAD(kind, field, array, feature, doc)                                                   \
    if (!(feature) || (u->features & (unsigned)(feature)))                                         \
        upload_row(tl_renderer_loc(p, "u_" #field), TL_UNIFORM_##kind, TL_UNIFORM_COUNT(array),    \
                   &u->field);
    TL_FRAME_UNIFORMS(UPLOAD)
#undef UPLOAD
    /* The one sampler every program that shades the sky reads: the table
     * tl_renderer_prepare_sky bound. */
    if (u->features & TL_FEATURE_SKY_PHYSICAL)
        glUniform1i(tl_renderer_loc(p, "u_sky_view"), TL_UNIT_SKY_VIEW);
}

int tl_renderer_begin(tl_renderer *r, int width, int height, int out_width, int out_height,
                      tl_error *err)
{
    const GLenum scene_formats[TL_SCENE_AOV_ATTACHMENTS] = {GL_RGBA32F, GL_R32F,    GL_RGBA32F,
                                                            GL_RGBA32F, GL_RGBA32F, GL_RGBA32F,
                                                            GL_RGBA32F, GL_RGBA32F};
    const GLenum display_formats[3] = {GL_RGBA32F, GL_RGBA32F, GL_R32F};
    const int attachments = r->want_aov ? TL_SCENE_AOV_ATTACHMENTS : TL_SCENE_PLAIN_ATTACHMENTS;
    /* A new size is checked against the device first (once a size). */
    int rc = r->scene.width == width && r->scene.height == height &&
                     r->scene.attachments == attachments && r->display.width == out_width &&
                     r->display.height == out_height
                 ? TL_OK
                 : tl_renderer_check_size(width, height, out_width, out_height, r->want_aov, err);
    if (!rc)
        rc = tl_renderer_target_ensure(&r->scene, width, height, attachments, scene_formats, err);
    if (!rc)
        rc = tl_renderer_target_ensure(&r->display, out_width, out_height, 3, display_formats, err);
    if (rc)
        return rc;
    glBindFramebuffer(GL_FRAMEBUFFER, r->scene.fbo);
    glViewport(0, 0, width, height);
    const float zero[4] = {0, 0, 0, 0};
    const float sky[4] = {TL_FRAME_SKY_DEPTH, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_COLOR, 1, sky);
    for (int i = TL_SCENE_PLAIN_ATTACHMENTS; i < attachments; i++)
        glClearBufferfv(GL_COLOR, i, zero);
    tl_timers_begin_frame(&r->timers);
    return tl_renderer_check("frame setup", err);
}

void tl_renderer_want_aov(tl_renderer *r, int on)
{
    r->want_aov = on != 0;
}

void tl_renderer_light_layer(tl_renderer *r, int layer)
{
    r->light_layer = layer >= 0 && layer < TL_LIGHT_SHADED ? layer : -1;
}

void tl_renderer_drop_program(GLuint *program)
{
    if (*program)
        glDeleteProgram(*program);
    *program = 0;
}

int tl_renderer_reload_shaders(tl_renderer *r, tl_error *err)
{
    GLuint present = tl_renderer_build_present(r, 0, err);
    if (!present)
        return err ? (int)err->status : TL_ERR_RUNTIME; /* the old programs stay */
    for (int i = 0; i < TL_PRESENT_VARIANTS; i++) {
        if (r->present_programs[i])
            glDeleteProgram(r->present_programs[i]);
        r->present_programs[i] = 0;
    }
    r->present_programs[0] = present;
    tl_renderer_drop_program(&r->glare_program);
    tl_renderer_drop_program(&r->mip_program);
    tl_renderer_drop_program(&r->filter_program);
    tl_renderer_drop_program(&r->false_colour_program);
    tl_renderer_drop_program(&r->overlay_program);
    tl_renderer_drop_program(&r->upscale_program);
    tl_renderer_drop_program(&r->sky_view_program);
    for (int i = 0; i < r->program_count; i++)
        glDeleteProgram(r->programs[i].program);
    r->program_count = 0;
    for (int i = 0; i < r->probe_count; i++)
        glDeleteProgram(r->probes[i].program);
    r->probe_count = 0;
    tl_renderer_drop_boat_programs(r);
    return tl_renderer_check("reloading shaders", err);
}

int tl_renderer_use_shaders(tl_renderer *r, const tl_shader_lib *lib, tl_error *err)
{
    if (strcmp(r->lib.dir, lib->dir) == 0)
        return TL_OK;
    tl_shader_lib was = r->lib;
    r->lib = *lib;
    int rc = tl_renderer_reload_shaders(r, err);
    if (rc)
        r->lib = was;
    else
        r->sky_view_valid = 0; /* drawn by the other folder's sky_view.frag */
    return rc;
}

/* Samples per draw. Mesa's llvmpipe ends every loop of a fragment once
 * that fragment has run 65535 loop iterations in all (one "loop limiter"
 * per shader invocation, shared by every loop): past it the wave sums are
 * cut short and supersampled pixels come out wrong without any error. A
 * pixel's samples are therefore split over several draws, each kept under
 * the limit by a generous count of the loops one sample can run. On a GPU
 * this costs a few extra draws. */
static int samples_per_draw(const tl_frame_uniforms *u, unsigned features)
{
    long per_step = u->march_octaves + 1, steps = u->march_steps;
    if (features & TL_FEATURE_GIANT_WAVE) {
        per_step += u->giant_iterations + 40;                   /* its inversion and slope bins */
        steps = (long)ceil(steps / TL_QUALITY_GIANT_STEP_COST); /* box steps cost less */
    }
    long per_sample = (steps + u->refine_steps) * per_step + 3L * (u->normal_octaves + 1) +
                      (long)(TL_WAKE_POINTS + 8) * (u->object_count > 0 ? u->object_count : 1) +
                      256;
    if (features & TL_FEATURE_UNDERWATER)
        per_sample *= 2; /* the march below the surface, and the lens */
    long n = 60000 / per_sample;
    int spp = u->spp < 1 ? 1 : u->spp;
    return n < 1 ? 1 : (n > spp ? spp : (int)n);
}

/* The ocean program for `features`, bound with the frame's uniforms. */
GLuint tl_renderer_use_ocean(tl_renderer *r, const tl_frame_uniforms *u, unsigned features,
                             tl_error *err)
{
    GLuint program = ocean_program(r, u, features, err);
    if (!program)
        return 0;
    glUseProgram(program);
    tl_renderer_upload_uniforms(program, u);
    if (features & TL_FEATURE_BOAT)
        tl_renderer_bind_boat(r, program, features);
    if (features & TL_PASS_LAYERS)
        glUniform1i(tl_renderer_loc(program, "u_layer"), r->light_layer);
    if (features & TL_PASS_HINTED) { /* the prepass's finest level (tl_renderer_prepass) */
        glUniform1i(tl_renderer_loc(program, "u_march_hint"), TL_UNIT_MARCH_HINT);
        glUniform1f(tl_renderer_loc(program, "u_hint_pixel"), 1.0f);
    }
    return program;
}

/* The bound program over the pixels x0 <= x < x1, y0 <= y < y1. A pixel's
 * samples go in draws of at most `chunk`; each adds its share of the
 * average. Depth (the nearest surface any sample saw) comes from the first
 * draw's samples. `only` >= 0: that sample alone, at the full weight. */
static void draw_ocean(tl_renderer *r, GLuint program, unsigned program_features,
                       const tl_frame_uniforms *u, int chunk, float weight, int write_depth,
                       int only, int x0, int y0, int x1, int y1)
{
    if (x0 >= x1 || y0 >= y1)
        return;
    glScissor(x0, y0, x1 - x0, y1 - y0);
    int spp = u->spp < 1 ? 1 : u->spp;
    int begin = only >= 0 ? only : 0, end = only >= 0 ? only + 1 : spp;
    for (int first = begin; first < end; first += chunk) {
        int count = end - first < chunk ? end - first : chunk;
        int depth = write_depth && first == begin;
        glColorMaski(1, depth, depth, depth, depth);
        glUniform1i(tl_renderer_loc(program, "u_sample_first"), first);
        glUniform1i(tl_renderer_loc(program, "u_sample_count"), count);
        glUniform1f(tl_renderer_loc(program, "u_sample_weight"),
                    only >= 0 ? weight : weight * (float)count / (float)spp);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (r->progress) {
            glFinish();
            r->progress(r->progress_ctx, (double)(x1 - x0) * (double)(y1 - y0) * count,
                        (program_features & TL_PASS_SKY) != 0);
        }
    }
}

void tl_renderer_set_progress(tl_renderer *r, tl_renderer_progress_fn fn, void *ctx)
{
    r->progress = fn;
    r->progress_ctx = ctx;
}

/* `area` split by `rect` (x0 y0 x1 y1 each): their overlap into `in`,
 * and the rest of `area` as up to four bands around it; returns the
 * bands' count, or -1 when they do not overlap. */
static int split_area(const int area[4], const int rect[4], int in[4], int around[4][4])
{
    for (int i = 0; i < 2; i++) {
        in[i] = area[i] > rect[i] ? area[i] : rect[i];
        in[i + 2] = area[i + 2] < rect[i + 2] ? area[i + 2] : rect[i + 2];
    }
    if (in[0] >= in[2] || in[1] >= in[3])
        return -1;
    const int band[4][4] = {{area[0], area[1], area[2], in[1]},
                            {area[0], in[3], area[2], area[3]},
                            {area[0], in[1], in[0], in[3]},
                            {in[2], in[1], area[2], in[3]}};
    int n = 0;
    for (int i = 0; i < 4; i++)
        if (band[i][0] < band[i][2] && band[i][1] < band[i][3])
            memcpy(around[n++], band[i], sizeof band[i]);
    return n;
}

/* One ocean draw over `area` with the program of `features`, where the
 * wake's foam is drawn only inside u->plan.wake_rect: around that the same
 * program without the wake draws the same image (no foam reaches there),
 * and llvmpipe, which runs every `if` body of a program for every pixel
 * and every loop's body at least once, leaves the foam's work out. */
static int draw_wake_split(tl_renderer *r, const tl_frame_uniforms *u, unsigned features,
                           float weight, int write_depth, int only, const int area[4],
                           tl_error *err)
{
    int in[4], around[4][4], parts = 0, part[5][4];
    unsigned with[5];
    const unsigned without = features & ~(unsigned)TL_FEATURE_WAKE;
    int n = features & TL_FEATURE_WAKE ? split_area(area, u->plan.wake_rect, in, around) : -1;
    if (n < 0) {
        memcpy(part[0], area, sizeof part[0]);
        with[parts++] = without;
    } else {
        memcpy(part[0], in, sizeof part[0]);
        with[parts++] = features;
        for (int i = 0; i < n; i++) {
            memcpy(part[parts], around[i], sizeof part[0]);
            with[parts++] = without;
        }
    }
    for (int i = 0; i < parts; i++) {
        GLuint program = tl_renderer_use_ocean(r, u, with[i], err);
        if (!program)
            return err ? (int)err->status : TL_ERR_RUNTIME;
        draw_ocean(r, program, with[i], u, samples_per_draw(u, with[i]), weight, write_depth, only,
                   part[i][0], part[i][1], part[i][2], part[i][3]);
    }
    return TL_OK;
}

/* One ocean draw over `area` (x0 y0 x1 y1) with the program of
 * `features`. The hull's mirror image is drawn only where it can show:
 * u->plan.boat_mirror_rect, widened by the most the waves shift its look-ups
 * (TL_MIRROR_SHIFT of the height, shaders/boat.glsl) and its taps' reach; the water around that and
 * the sky's rows take the programs without it (TL_PASS_MIRROR), for the same reason as the wake. */
static int draw_area(tl_renderer *r, const tl_frame_uniforms *u, unsigned features, float weight,
                     int write_depth, int only, const int area[4], tl_error *err)
{
    if (area[0] >= area[2] || area[1] >= area[3])
        return TL_OK;
    const int *m = u->plan.boat_mirror_rect,
              reach = (int)ceil((TL_MIRROR_SHIFT + TL_MIRROR_STREAK) * u->height) + 3;
    const int wide[4] = {m[0] - reach, m[1] - reach, m[2] + reach, m[3] + reach};
    int in[4], around[4][4], n = -1;
    if ((features & TL_FEATURE_BOAT) && !(features & TL_PASS_SKY) && m[0] < m[2] && m[1] < m[3])
        n = split_area(area, wide, in, around);
    if (n < 0)
        return draw_wake_split(r, u, features, weight, write_depth, only, area, err);
    int rc = draw_wake_split(r, u, features | TL_PASS_MIRROR, weight, write_depth, only, in, err);
    for (int i = 0; i < n && !rc; i++)
        rc = draw_wake_split(r, u, features, weight, write_depth, only, around[i], err);
    return rc;
}

/* The frame's passes into the float target with the blending the caller
 * set: the boat's, then the ocean's (all samples, or sample `only`). */
static int draw_passes(tl_renderer *r, const tl_frame_uniforms *u, float weight, int write_depth,
                       int only, tl_error *err)
{
    if (u->width != r->scene.width || u->height != r->scene.height)
        return tl_error_set(err, TL_ERR_RUNTIME, "pass size does not match the frame");
    /* No mesh, no boat pass (a library user may not have given one). */
    unsigned features = u->features;
    if (!r->mesh_count)
        features &= ~(unsigned)(TL_FEATURE_BOAT | TL_FEATURE_BOAT_SHADOW);
    int rc0 = tl_renderer_upload_objects(r, u, err);
    if (rc0)
        return rc0;
    if (features & TL_FEATURE_BOAT) {
        tl_timers_start(&r->timers, TL_TIMED_BOAT);
        int rc = tl_renderer_draw_boat(r, u, only > 0, err);
        tl_timers_stop(&r->timers);
        if (rc)
            return rc;
    }
    glBindVertexArray(r->vao);
    /* The giant wave's program only over the pixels that can see its box
     * (u->plan.giant_rect), the lean program, the same image there, around it. */
    const int w = u->width, h = u->height;
    int rect[4] = {0, 0, 0, 0};
    unsigned lean = features & ~(unsigned)(TL_FEATURE_GIANT_WAVE | TL_FEATURE_GIANT_BREAK |
                                           TL_FEATURE_GIANT_LIP | TL_FEATURE_GIANT_SPRAY |
                                           TL_FEATURE_GIANT_GLOW);
    if (features & TL_FEATURE_GIANT_WAVE) {
        memcpy(rect, u->plan.giant_rect, sizeof rect);
        /* The water around the rectangle still mirrors the wave's face
         * where its crest hides the sky: the crest line, with the break's
         * settling as the wave's program has it. */
        lean |= TL_PASS_GIANT_MIRROR | (features & TL_FEATURE_GIANT_BREAK);
    }
    int rc = TL_OK;
    const int scope = tl_renderer_prepass_scope(u, features, rect);
    if (scope != TL_PREPASS_NONE) {
        /* A later sample of the same pass (a per-sample boat pass, the
         * preview's refinement) starts from the prepass its first ran. */
        tl_timers_start(&r->timers, TL_TIMED_PREPASS);
        rc = tl_renderer_prepass(r, u, features, rect, scope, only > 0, err);
        tl_timers_stop(&r->timers);
        if (rc)
            return rc;
        if (scope == TL_PREPASS_FRAME)
            lean |= TL_PASS_HINTED;
        features |= TL_PASS_HINTED;
    }
    /* The passes' data beside the radiance (the prepass has none). */
    if (tl_renderer_aov_on(r)) {
        features |= TL_PASS_AOV;
        lean |= TL_PASS_AOV;
    }
    /* One light layer alone (shaders/layers.glsl). */
    if (r->light_layer >= 0) {
        features |= TL_PASS_LAYERS;
        lean |= TL_PASS_LAYERS;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, r->scene.fbo);
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    /* Radiance blends as the caller set; a distance keeps the nearest any
     * pass wrote (the target starts at TL_SKY_DEPTH). */
    glEnablei(GL_BLEND, 0);
    glEnablei(GL_BLEND, 1);
    glBlendEquationi(0, GL_FUNC_ADD);
    glBlendEquationi(1, GL_MIN);
    /* The passes' data blend as the radiance does. */
    for (int i = TL_SCENE_PLAIN_ATTACHMENTS; i < r->scene.attachments; i++) {
        glEnablei(GL_BLEND, (GLuint)i);
        glBlendEquationi((GLuint)i, GL_FUNC_ADD);
    }
    glEnable(GL_SCISSOR_TEST);
    int bands[4][4], has_rect;
    int n = tl_renderer_split(w, h, rect, bands, &has_rect);
    /* Above the horizon, outside the wave's rectangle, the sky alone. */
    const int sky = tl_renderer_sky_from(u, 1, h);
    tl_timers_start(&r->timers, TL_TIMED_OCEAN);
    /* The sky's rows first: a long frame's progress then counts the water
     * alone from its first report on (tl_renderer_set_progress). Each
     * pixel is in one area, so the order changes no pixel. */
    for (int k = 0; k < 2 && !rc; k++) {
        const int part = 1 - k;
        if (part == 1 && sky >= h)
            continue;
        /* The sky's rays meet no water: no wake there either. */
        unsigned f =
            part == 0 ? lean : (lean & ~(unsigned)(TL_PASS_HINTED | TL_FEATURE_WAKE)) | TL_PASS_SKY;
        for (int i = 0; i < n && !rc; i++) {
            const int *b = bands[i];
            const int area[4] = {b[0], part == 0 ? b[1] : (b[1] > sky ? b[1] : sky), b[2],
                                 part == 0 ? (b[3] < sky ? b[3] : sky) : b[3]};
            rc = draw_area(r, u, f, weight, write_depth, only, area, err);
        }
    }
    tl_timers_stop(&r->timers);
    if (!rc && has_rect) {
        tl_timers_start(&r->timers, TL_TIMED_GIANT);
        rc = draw_area(r, u, features, weight, write_depth, only, rect, err);
        tl_timers_stop(&r->timers);
    }
    glDisable(GL_SCISSOR_TEST);
    glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    for (int i = 0; i < r->scene.attachments; i++)
        glDisablei(GL_BLEND, (GLuint)i);
    glBlendEquation(GL_FUNC_ADD);
    if (rc)
        return rc;
    return tl_renderer_check("rendering", err);
}

int tl_renderer_accumulate(tl_renderer *r, const tl_frame_uniforms *u, float weight,
                           int write_depth, tl_error *err)
{
    glBlendFunc(GL_ONE, GL_ONE); /* radiance adds up across passes */
    return draw_passes(r, u, weight, write_depth, -1, err);
}

int tl_renderer_accumulate_sample(tl_renderer *r, const tl_frame_uniforms *u, float weight,
                                  int write_depth, int sample, tl_error *err)
{
    int spp = u->spp < 1 ? 1 : u->spp;
    if (sample < 0 || sample >= spp)
        return tl_error_set(err, TL_ERR_RUNTIME, "pass of sample %d of %d", sample, spp);
    glBlendFunc(GL_ONE, GL_ONE);
    return draw_passes(r, u, weight, write_depth, sample, err);
}

int tl_renderer_refine(tl_renderer *r, const tl_frame_uniforms *u, int sample, tl_error *err)
{
    int spp = u->spp < 1 ? 1 : u->spp;
    if (sample <= 0 || sample >= spp) /* sample 0 goes into the cleared target */
        return tl_renderer_accumulate_sample(r, u, 1.0f, 1, sample, err);
    /* The running mean: old * (1 - a) + new * a, a = 1 / (samples so far). */
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / (float)(sample + 1));
    return draw_passes(r, u, 1.0f, 1, sample, err);
}

int tl_renderer_render(tl_renderer *r, const tl_frame_uniforms *u, tl_frame *frame, tl_error *err)
{
    int rc = tl_renderer_begin(r, u->width, u->height, u->out_width, u->out_height, err);
    if (!rc)
        rc = tl_renderer_accumulate(r, u, 1.0f, 1, err);
    const tl_display_settings display = tl_display_of(u);
    if (!rc)
        rc = tl_renderer_finish(r, &display, TL_PLANES_ALL, frame, err);
    return rc;
}
