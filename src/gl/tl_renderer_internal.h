/* What the renderer's files share (not part of its interface): the
 * renderer's state and the GL helpers. tl_renderer.c draws the scene,
 * tl_renderer_prepass.c the march prepass its rays start from,
 * tl_renderer_display.c turns it into the planes that leave the GPU,
 * tl_renderer_sky.c draws the physical sky's sky-view table. */
#ifndef TL_RENDERER_INTERNAL_H
#define TL_RENDERER_INTERNAL_H

#include <epoxy/gl.h>
#include <stddef.h>

#include "gl/tl_renderer.h"
#include "mesh/tl_mesh.h"
#include "sky/tl_sky.h"

#define MAX_PROGRAMS        48
#define TL_PRESENT_VARIANTS 16
/* Mesh programs: one per set of the features that light the hull
 * (MESH_FEATURES in tl_renderer_boat.c), with and without the model's
 * texture maps. */
#define TL_MESH_LIGHT_FEATURES 6
#define TL_MESH_PROGRAMS       (2 << TL_MESH_LIGHT_FEATURES)
/* Levels of the march prepass: 1 / 4, then 1 / 2 of the render size. */
#define TL_PREPASS_LEVELS 2
/* How far the waves shift the hull's mirror image, as a share of the
 * frame's height per unit of the water's slope (at 0.15 the image of a
 * white hull on a choppy sea was a soft, milky smear, not broken up by
 * the facets; judge), and the most they shift it: boat.glsl holds its
 * look-ups to it, and the program with the image runs that far around
 * the image's rectangle. */
#define TL_MIRROR_DISTORT 0.25
#define TL_MIRROR_SHIFT   0.08
/* How far up and down, as a share of the frame's height, ripples finer
 * than a pixel smear the mirror image (boat.glsl's taps). */
#define TL_MIRROR_STREAK 0.012
/* Seen from under the water, the hull's image in the surface's underside
 * wobbles with the waves at this footprint's detail (metres): the
 * ripples' own normal broke its edge into a serrated, burnt-paper fringe
 * along the hull (judges). */
#define TL_MIRROR_UNDER_DETAIL 1.0

/* Texture units, one name for each sampler's. The ocean's programs take
 * 1 to 5 (unit 0 is where the other passes bind their input, and where
 * textures are bound to be set up); the sky-view table's pass and the
 * display pass number their own inputs from 0. */
enum {
    TL_UNIT_INPUT = 0,           /* a post pass's one input; the probe's points */
    TL_UNIT_BOAT_COLOR = 1,      /* the ocean's: the hull's radiance, */
    TL_UNIT_BOAT_DISTANCE = 2,   /* its distance along the ray, */
    TL_UNIT_BOAT_REFLECTION = 3, /* its mirror image, */
    TL_UNIT_SKY_VIEW = 4,        /* the physical sky's sky-view table, */
    TL_UNIT_MARCH_HINT = 5,      /* the march prepass's distances, */
    TL_UNIT_BOAT_SHADOW = 6,     /* the objects' shadow maps (the mesh pass's too) */
    TL_UNIT_MESH_MAPS = 7,       /* the mesh pass's maps, 7 to 11 in tl_mesh_map order */
    TL_UNIT_BOAT_SURFACE = 12,   /* the ocean's with the passes: the hull's normal and object */
    TL_UNIT_BOAT_UNDERSIDE = 13, /* under water: the hull mirrored in the surface's underside, */
    TL_UNIT_BOAT_UNDERSIDE_DISTANCE = 14, /* its path's length */
    TL_UNIT_SKY_TRANSMITTANCE = 0,        /* the sky-view pass's: transmittance, */
    TL_UNIT_SKY_MULTIPLE = 1,             /* multiple scattering */
    TL_UNIT_DISPLAY_HDR = 0,              /* the display pass's: the scene, */
    TL_UNIT_DISPLAY_DISTANCE = 1,         /* its distances, */
    TL_UNIT_DISPLAY_GLARE = 2,            /* the glare, */
    TL_UNIT_DISPLAY_LUT = 3               /* the display table */
};

/* Ocean program variants beyond the frame's features (bits above them):
 * a march prepass level, a pass that starts from a coarser level's
 * distances, the sky alone (the rows above the horizon,
 * tl_frame_uniforms.plan.sky_rows), and the water that can mirror the boat's
 * hull (tl_frame_uniforms.plan.boat_mirror_rect), and the compositing
 * passes' outputs beside the radiance (tl_renderer_want_aov). */
enum {
    TL_PASS_PREPASS = 1u << 30,
    TL_PASS_HINTED = 1u << 29,
    TL_PASS_SKY = 1u << 28,
    TL_PASS_MIRROR = 1u << 27,
    TL_PASS_AOV = 1u << 26,
    TL_PASS_LAYERS = 1u << 25
};
/* The lean program of a frame with the giant wave: its crest line alone,
 * which the water outside the wave's rectangle mirrors (a #define: an
 * enumerator must fit an int). */
#define TL_PASS_GIANT_MIRROR (1u << 31)
/* The scene target's attachments: radiance, distance, and with the
 * compositing passes the normal and foam, the covers, and the objects'
 * covers in four (tl_frame.h's aov plane, in that order). */
#define TL_SCENE_PLAIN_ATTACHMENTS 2
#define TL_SCENE_AOV_ATTACHMENTS   (TL_SCENE_PLAIN_ATTACHMENTS + TL_FRAME_AOV_FLOATS / 4)

typedef struct cached_program {
    unsigned features;
    int march_octaves, normal_octaves; /* compiled in (ocean programs; 0 in probes) */
    GLuint program;
} cached_program;

/* A framebuffer with float colour attachments of one size, and a depth
 * buffer when it is asked for. */
#define TL_TARGET_ATTACHMENTS 8
typedef struct target {
    GLuint fbo;
    GLuint tex[TL_TARGET_ATTACHMENTS];
    GLuint depth; /* renderbuffer, 0 when none */
    int attachments;
    int width, height;
    int mip_levels; /* levels past 0 allocated for tex[0] (the scene's, for the glare) */
} target;

/* The frame's passes, timed (tl_renderer_timers.c). */
typedef struct pass_timers {
    int on;         /* tl_renderer_time_passes */
    int open;       /* the TL_TIMED_* pass being timed, -1 when none */
    int valid;      /* seconds hold a whole frame (tl_renderer_finish collected them) */
    double started; /* when the open pass started */
    double seconds[TL_TIMED_COUNT];
} pass_timers;

/* A frame's planes in transit to the CPU (tl_renderer_finish_begin): a
 * pixel-pack buffer of `bytes`, the planes and their size. */
typedef struct readback_slot {
    GLuint buffer;
    size_t bytes;
    unsigned planes;
    int width, height;
} readback_slot;

/* The uniform block binding of the floating objects (shaders/objects.glsl):
 * every program that declares the block reads it there. */
#define TL_OBJECTS_BINDING 0

/* A floating object's mesh on the GPU: interleaved position, normal, colour,
 * surface, UV and tangent; a loaded model's maps as textures. */
typedef struct gpu_mesh {
    GLuint vao, vbo, ibo;
    GLsizei indices;
    /* Drawn part by part with their maps when `maps` (tl_mesh_has_maps). */
    int maps;
    size_t part_count, texture_count;
    tl_mesh_part *parts;
    GLuint *textures; /* per image, as RGBA8 */
    GLuint *srgb;     /* per image, as sRGB8_ALPHA8 (colour maps), or 0 */
    /* Its outline (tl_mesh_outline_of): the water's contact foam follows
     * its waterline, and its plan keeps the sea out of it. */
    tl_mesh_outline outline;
    /* Its lamps (tl_mesh_lamps), model units: the water mirrors them. */
    int lamp_count;
    float lamp[TL_MESH_LAMPS][4], lamp_light[TL_MESH_LAMPS][4];
} gpu_mesh;

struct tl_renderer {
    tl_shader_lib lib;
    GLuint vao;
    cached_program programs[MAX_PROGRAMS];
    int program_count;
    /* The display pass per variant: bit 0 upscales (render scale < 1), bit
     * 1 adds glare, bit 2 displays through a table (an OpenColorIO display
     * transform) in place of the ACES fit. Each is its own program:
     * llvmpipe runs the code of an `if` for every pixel, taken or not, so
     * code a frame does not use must not be compiled in (the upscale's
     * code was most of the pass). */
    GLuint present_programs[TL_PRESENT_VARIANTS];
    GLuint display_lut; /* the display table, a 3D texture (tl_renderer_set_display_lut), or 0 */
    cached_program probes[MAX_PROGRAMS]; /* per feature set that changes the probe */
    int probe_count;
    target scene; /* colour RGBA32F + depth R32F (+ the passes' data, TL_SCENE_AOV_ATTACHMENTS) */
    int want_aov; /* the next begin's target carries the passes' data (tl_renderer_want_aov) */
    int light_layer; /* the light layer the ocean draws keep (tl_renderer_light_layer), or -1 */
    int glare_layer; /* the display pass writes the glare into the colour plane (finish_glare) */
    target aov;      /* the passes' data at the output size, top row first (finish) */
    target display;  /* at the output size: tonemapped RGBA32F, colour RGBA32F, distance R32F */
    target boat;   /* the lit hull RGBA32F + its distance R32F + depth (+ its normal and object) */
    target mirror; /* the hull reflected in the water RGBA32F + depth */
    /* Under water: the hulls' part below the water mirrored in the
     * surface's underside RGBA32F + its path's length R32F + depth. */
    target underside;
    /* The march prepass's distances R32F, level i at 1 / 2^(i+1) of the
     * render size (tl_renderer_prepass.c). */
    target hint[TL_PREPASS_LEVELS];
    target glare; /* glare RGBA32F at 1 / TL_GLARE_DIVISOR of the output size (render.bloom) */
    GLuint glare_program;
    GLuint mip_program; /* the scene's mip levels (mip.frag) */
    GLuint mip_fbo;     /* one level of the scene's colour at a time */
    target upscaled;    /* radiance upscaled along x only (upscale.frag; render_scale < 1) */
    GLuint upscale_program;
    target filtered; /* the display image after the pixel filter (quality.pixel_filter) */
    GLuint filter_program;
    int display_filtered;   /* the last display pass left its image in `filtered` */
    float display_exposure; /* the last display pass's (the false colour's) */
    /* The preview window's view (tl_renderer_overlay.c). */
    GLuint false_colour_program, overlay_program, overlay_vao, overlay_vbo;
    GLuint mesh_program[TL_MESH_PROGRAMS]; /* per feature set that lights it (tl_renderer_boat.c) */
    GLuint shadow_program;                 /* the sun's depth view of an object */
    /* The objects' shadow maps: an array of shadow_layers layers,
     * TL_BOAT_SHADOW_SIZE square, one per object in view that casts one. */
    GLuint shadow_fbo, shadow_tex;
    int shadow_layers;
    GLuint objects_ubo; /* the floating objects' uniform block (tl_object_uniforms) */
    /* The physical sky (tl_renderer_sky.c): the sky-view table, drawn
     * here for the sun and altitude below, and the atmosphere's two tables
     * it is drawn from, uploaded for sky_atmosphere. */
    target sky_view;
    GLuint sky_view_program;
    GLuint sky_transmittance, sky_ms;
    tl_atmosphere sky_atmosphere;
    int sky_tables_valid, sky_view_valid;
    double sky_view_sun, sky_view_altitude;
    gpu_mesh meshes[TL_OBJECT_MAX]; /* the floating objects' models (tl_renderer_set_meshes) */
    int mesh_count;
    double readback_seconds; /* of the last tl_renderer_finish or finish_end */
    /* Frames whose planes are on their way (finish_begin), oldest first
     * from readback_head. */
    readback_slot readback[TL_READBACK_SLOTS];
    int readback_head, readback_queued;
    pass_timers timers;
    tl_renderer_progress_fn progress; /* tl_renderer_set_progress, NULL when off */
    void *progress_ctx;
};

/* Whether the frame begun last carries the compositing passes' data. */
static inline int tl_renderer_aov_on(const tl_renderer *r)
{
    return r->scene.attachments == TL_SCENE_AOV_ATTACHMENTS;
}

/* The boat (tl_renderer_boat.c): its passes for the frame (the shadow map,
 * the lit hull, its mirror image); the textures they leave bound for an
 * ocean program; its programs dropped (built again on next use); all of
 * it freed. */
/* `reuse`: a later sample of the same frame, whose shadow map still holds. */
int tl_renderer_draw_boat(tl_renderer *r, const tl_frame_uniforms *u, int reuse, tl_error *err);
void tl_renderer_bind_boat(const tl_renderer *r, GLuint program, unsigned features);
/* Uploads the frame's floating objects in view into the uniform block,
 * their meshes' outlines filled in, and binds it (TL_OBJECTS_BINDING). */
int tl_renderer_upload_objects(tl_renderer *r, const tl_frame_uniforms *u, tl_error *err);
void tl_renderer_drop_boat_programs(tl_renderer *r);
void tl_renderer_free_boat(tl_renderer *r);
/* (Re)creates `t` as tl_renderer_target_ensure, with a depth buffer if
 * `depth`. */
int tl_renderer_target_ensure_depth(target *t, int width, int height, int attachments,
                                    const GLenum *formats, int depth, tl_error *err);

/* Deletes *program if there is one and zeroes it: built again on next use. */
void tl_renderer_drop_program(GLuint *program);
/* Frees the overlay's and the false colour's programs and buffers. */
void tl_renderer_free_overlay(tl_renderer *r);
/* Frees the sky's textures and program (tl_renderer_sky.c). */
void tl_renderer_free_sky(tl_renderer *r);

/* An OpenGL error since the last check, as an error naming `what`. */
int tl_renderer_check(const char *what, tl_error *err);
/* Builds vertex `vs` + fragment `fs` with the given #defines. */
GLuint tl_renderer_build_program(tl_renderer *r, const char *vs, const char *fs,
                                 const char *defines, tl_error *err);
/* The #defines every program shares, plus one per feature bit. */
/* Room for the shared #defines (every constant the shaders share with the
 * CPU, one line each), one line per feature and a program's own lines,
 * with room to spare: a full buffer is refused with an error (a frame with
 * every feature under water found the last limit), never cut short. */
#define TL_DEFINES_SIZE 12288
/* The shared #defines and one per feature bit into out; 0, or -1 when they
 * do not fit (the caller then fails rather than compile a cut-off line). */
int tl_renderer_defines(unsigned features, char *out, size_t size);
GLint tl_renderer_loc(GLuint p, const char *name);
/* Sets every frame uniform `p` uses (the ocean's, the probe's). */
void tl_renderer_upload_uniforms(GLuint p, const tl_frame_uniforms *u);
/* (Re)creates `t` at the size with the given internal formats. */
int tl_renderer_target_ensure(target *t, int width, int height, int attachments,
                              const GLenum *formats, tl_error *err);
void tl_renderer_target_free(target *t);

/* Pass timing, no-ops while it is off: begin_frame empties the sums,
 * start/stop time one pass of kind TL_TIMED_* (start stops a running one),
 * collect ends the frame's timing. */
void tl_timers_begin_frame(pass_timers *t);
void tl_timers_start(pass_timers *t, int pass);
void tl_timers_stop(pass_timers *t);
void tl_timers_collect(pass_timers *t);

/* The ocean program for `features` (frame features and TL_PASS_* bits),
 * bound, with the frame's uniforms uploaded. */
GLuint tl_renderer_use_ocean(tl_renderer *r, const tl_frame_uniforms *u, unsigned features,
                             tl_error *err);
/* The frame split around `rect` (x0 y0 x1 y1): up to four bands around it
 * (below, above, left, right), returned with their count, and whether
 * `rect` itself holds any pixel (without one, the one band is the frame). */
int tl_renderer_split(int w, int h, const int rect[4], int bands[4][4], int *has_rect);
/* The first row (GL's y) of a target `h` rows high, each row standing for
 * `scale` of the render's, whose rays all rise (u->plan.sky_rows); h if none. */
int tl_renderer_sky_from(const tl_frame_uniforms *u, int scale, int h);

/* Which of the frame's ocean passes start from the march prepass: none,
 * all (quality.march_prepass), or the giant wave's alone over `rect`
 * (quality.giant_prepass without march_prepass). */
enum { TL_PREPASS_NONE, TL_PREPASS_FRAME, TL_PREPASS_GIANT };
int tl_renderer_prepass_scope(const tl_frame_uniforms *u, unsigned features, const int rect[4]);
/* Runs the march prepass for the frame over `scope` (the giant wave's
 * program over `rect`) and binds its finest level for the passes with
 * TL_PASS_HINTED. `reuse`: the frame's last prepass still holds (another
 * sample of the same pass); only bound again, unless its size does not
 * match. */
int tl_renderer_prepass(tl_renderer *r, const tl_frame_uniforms *u, unsigned features,
                        const int rect[4], int scope, int reuse, tl_error *err);

/* The display pass's program for `variant` (TL_PRESENT_*), built on first
 * use; tl_renderer_build_present builds one afresh. */
enum {
    TL_PRESENT_UPSCALE = 1,
    TL_PRESENT_GLARE = 2,
    TL_PRESENT_LUT = 4,
    TL_PRESENT_GLARE_LAYER = 8
};
GLuint tl_renderer_present_program(tl_renderer *r, int variant, tl_error *err);
GLuint tl_renderer_build_present(tl_renderer *r, int variant, tl_error *err);

#endif
