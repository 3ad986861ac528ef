/* The frame's uniform table (prepare/tl_uniform_list.h) against the GLSL
 * the shader library writes from it: every row declared once, with its
 * type and array length; no shader file declares a row itself (the
 * program would not compile); the composed ocean program holds the
 * declarations once. GL-free. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "prepare/tl_prepare.h"
#include "prepare/tl_uniform_list.h"
#include "shader/tl_shader_lib.h"
#include "tl_test.h"

/* How many times `needle` occurs in `text`. */
static int count(const char *text, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(text, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

/* Whether `text` declares `name` (as "uniform TYPE name" followed by "[" or
 * ";"), whatever the type. */
static int declares(const char *text, const char *name)
{
    int n = 0;
    for (const char *p = strstr(text, "uniform "); p; p = strstr(p + 1, "uniform ")) {
        const char *type_end = strchr(p + 8, ' ');
        if (!type_end)
            break;
        size_t len = strlen(name);
        if (strncmp(type_end + 1, name, len) == 0 &&
            (type_end[1 + len] == '[' || type_end[1 + len] == ';'))
            n++;
    }
    return n;
}

static void test_generated(void)
{
    char *glsl = tl_shader_frame_uniforms();
    CHECK(glsl != NULL);
    if (!glsl)
        return;
    int rows = 0;
#define ROW(kind, field, array, feature, doc)                                                      \
    {                                                                                              \
        char want[160];                                                                            \
        int single = strcmp(#array, "0") == 0;                                                     \
        snprintf(want, sizeof want, "uniform %s u_%s%s%s%s;", TL_UNIFORM_GLSL_##kind, #field,      \
                 single ? "" : "[", single ? "" : #array, single ? "" : "]");                      \
        if (count(glsl, want) != 1 || declares(glsl, "u_" #field) != 1)                            \
            printf("  u_%s: want one \"%s\"\n", #field, want);                                     \
        CHECK(count(glsl, want) == 1);                                                             \
        CHECK(declares(glsl, "u_" #field) == 1);                                                   \
        rows++;                                                                                    \
    }
    TL_FRAME_UNIFORMS(ROW)
#undef ROW
    CHECK(rows == TL_FRAME_UNIFORM_ROWS);
    /* Nothing but the rows. */
    CHECK(count(glsl, "uniform ") == rows);
    printf("frame_uniforms.glsl: %d rows, each declared once\n", rows);
    free(glsl);
}

/* The shader files leave the rows to frame_uniforms.glsl. */
static void test_files_leave_rows_alone(void)
{
    for (int i = 0; i < tl_embedded_shader_count; i++) {
        const tl_shader_file *f = &tl_embedded_shaders[i];
        CHECK(strcmp(f->name, TL_FRAME_UNIFORMS_FILE) != 0);
#define ROW(kind, field, array, feature, doc)                                                      \
    if (declares(f->text, "u_" #field))                                                            \
        printf("  %s declares u_%s, a row of tl_uniform_list.h\n", f->name, #field);               \
    CHECK(declares(f->text, "u_" #field) == 0);
        TL_FRAME_UNIFORMS(ROW)
#undef ROW
    }
}

/* A composed program, from the embedded files and from a folder, holds
 * each row once. */
static void test_composed(const char *dir)
{
    tl_shader_lib libs[2];
    tl_shader_lib_embedded(&libs[0]);
    int have_dir = dir && tl_shader_lib_from_dir(&libs[1], dir, NULL) == 0;
    for (int l = 0; l < 1 + have_dir; l++) {
        const char *entries[] = {"ocean.frag", "probe.frag", "mesh.frag"};
        for (int e = 0; e < 3; e++) {
            tl_shader_source src;
            tl_error err;
            CHECK(tl_shader_compose(&libs[l], entries[e], "", &src, &err) == 0);
            if (!src.text)
                continue;
#define ROW(kind, field, array, feature, doc) CHECK(declares(src.text, "u_" #field) == 1);
            TL_FRAME_UNIFORMS(ROW)
#undef ROW
            tl_shader_source_free(&src);
        }
    }
    printf("composed programs (%s): every row declared once\n",
           have_dir ? "embedded and folder" : "embedded");
}

int main(int argc, char **argv)
{
    test_generated();
    test_files_leave_rows_alone();
    test_composed(argc > 1 ? argv[1] : NULL);
    TEST_END();
}
