/* tl_shader_lib: where shader text comes from, and how a program's source
 * is composed from small files (pure C, no GL).
 *
 * Sources are either the copies embedded at build time or files in a
 * folder (for editing shaders without rebuilding). `#include "name"` lines
 * are expanded (each file once), a `#version` line and the feature
 * #defines are prepended, and `#line` directives keep compiler messages
 * pointing at the right file and line. */
#ifndef TL_SHADER_LIB_H
#define TL_SHADER_LIB_H

#include "core/tl_error.h"

typedef struct tl_shader_file {
    const char *name;
    const char *text;
} tl_shader_file;

extern const tl_shader_file tl_embedded_shaders[];
extern const int tl_embedded_shader_count;

typedef struct tl_shader_lib {
    char dir[1024]; /* empty: use the embedded copies */
} tl_shader_lib;

#define TL_SHADER_MAX_FILES 32

/* A composed program source. files[i] names GLSL source-string number i. */
typedef struct tl_shader_source {
    char *text;
    int file_count;
    char files[TL_SHADER_MAX_FILES][64];
} tl_shader_source;

void tl_shader_lib_embedded(tl_shader_lib *lib);
/* Fails if `dir` is not a readable folder holding ocean.frag; the message
 * names the folder, and the caller prefixes the flag that gave it. */
int tl_shader_lib_from_dir(tl_shader_lib *lib, const char *dir, tl_error *err);

/* Composes `entry` with `defines` (lines of "#define ...") into out. */
int tl_shader_compose(const tl_shader_lib *lib, const char *entry, const char *defines,
                      tl_shader_source *out, tl_error *err);
void tl_shader_source_free(tl_shader_source *src);

/* The GLSL declarations of the frame's uniforms, one line per row of
 * prepare/tl_uniform_list.h: the text of "frame_uniforms.glsl"
 * (TL_FRAME_UNIFORMS_FILE), which compose serves whichever folder the
 * other files come from. malloc'd; NULL when out of memory. */
char *tl_shader_frame_uniforms(void);

/* Rewrites a driver's info log so "0:12(5)" style locations name files:
 * "water.glsl:12(5)". Returns a malloc'd string (NULL on out of memory). */
char *tl_shader_annotate_log(const tl_shader_source *src, const char *log);

#endif
