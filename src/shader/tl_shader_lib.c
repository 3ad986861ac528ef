#include "tl_shader_lib.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "prepare/tl_uniform_list.h"

#define MAX_INCLUDE_DEPTH     8
#define MAX_SHADER_FILE_BYTES (1 << 20)

typedef struct buffer {
    char *data;
    size_t len, cap;
    int failed;
} buffer;

static void buf_append(buffer *b, const char *s, size_t n)
{
    if (b->failed)
        return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (cap < b->len + n + 1)
            cap *= 2;
        char *d = realloc(b->data, cap);
        if (!d) {
            b->failed = 1;
            return;
        }
        b->data = d;
        b->cap = cap;
    }
    memcpy(b->data + b->len, s, n);
    b->len += n;
    b->data[b->len] = '\0';
}

static void buf_printf(buffer *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void buf_printf(buffer *b, const char *fmt, ...)
{
    char tmp[256];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    if (n > 0)
        buf_append(b, tmp, (size_t)n < sizeof tmp ? (size_t)n : sizeof tmp - 1);
}

void tl_shader_lib_embedded(tl_shader_lib *lib)
{
    lib->dir[0] = '\0';
}

int tl_shader_lib_from_dir(tl_shader_lib *lib, const char *dir, tl_error *err)
{
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
        return tl_error_set(err, TL_ERR_USAGE, "'%s' is not a folder", dir);
    char probe[1200];
    snprintf(probe, sizeof probe, "%s/ocean.frag", dir);
    if (stat(probe, &st) != 0)
        return tl_error_set(err, TL_ERR_USAGE, "'%s' holds no ocean.frag", dir);
    snprintf(lib->dir, sizeof lib->dir, "%s", dir);
    return TL_OK;
}

char *tl_shader_frame_uniforms(void)
{
    buffer b = {0};
    buf_printf(&b, "// The frame's uniforms, written by tl_shader_frame_uniforms from\n"
                   "// src/prepare/tl_uniform_list.h (edit that table, not this text).\n");
    /* The array's length is the table's text: the TL_* names in it are
     * #defines in every program (tl_renderer_defines). */
#define DECLARE(kind, field, array, feature, doc)                                                  \
    {                                                                                              \
        int single = strcmp(#array, "0") == 0;                                                     \
        buf_printf(&b, "uniform %s u_%s%s%s%s;%s%s\n", TL_UNIFORM_GLSL_##kind, #field,             \
                   single ? "" : "[", single ? "" : #array, single ? "" : "]",                     \
                   doc[0] ? " // " : "", doc);                                                     \
    }
    TL_FRAME_UNIFORMS(DECLARE)
#undef DECLARE
    if (b.failed) {
        free(b.data);
        return NULL;
    }
    return b.data;
}

/* Returns a malloc'd copy of the named file's text. */
static char *load_text(const tl_shader_lib *lib, const char *name, tl_error *err)
{
    if (strcmp(name, TL_FRAME_UNIFORMS_FILE) == 0) {
        char *text = tl_shader_frame_uniforms();
        if (!text)
            tl_error_set(err, TL_ERR_RUNTIME, "out of memory writing '%s'", name);
        return text;
    }
    if (!lib->dir[0]) {
        for (int i = 0; i < tl_embedded_shader_count; i++)
            if (strcmp(tl_embedded_shaders[i].name, name) == 0)
                return strdup(tl_embedded_shaders[i].text);
        tl_error_set(err, TL_ERR_RUNTIME, "shader '%s' is not embedded in this build", name);
        return NULL;
    }
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", lib->dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) {
        tl_error_set(err, TL_ERR_RUNTIME, "cannot open shader '%s'", path);
        return NULL;
    }
    buffer b = {0};
    char chunk[8192];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0 && b.len < MAX_SHADER_FILE_BYTES)
        buf_append(&b, chunk, n);
    int bad = ferror(f) || b.failed || b.len >= MAX_SHADER_FILE_BYTES;
    fclose(f);
    if (bad) {
        free(b.data);
        tl_error_set(err, TL_ERR_RUNTIME, "cannot read shader '%s' (unreadable or over 1 MiB)",
                     path);
        return NULL;
    }
    return b.data ? b.data : strdup("");
}

/* Parses `#include "name"`; returns 1 and fills name on a match. */
static int parse_include(const char *line, size_t len, char *name, size_t name_size)
{
    size_t i = 0;
    while (i < len && (line[i] == ' ' || line[i] == '\t'))
        i++;
    if (len - i < 8 || strncmp(line + i, "#include", 8) != 0)
        return 0;
    i += 8;
    while (i < len && isspace((unsigned char)line[i]))
        i++;
    if (i >= len || line[i] != '"')
        return 0;
    size_t start = ++i;
    while (i < len && line[i] != '"')
        i++;
    if (i >= len || i - start == 0 || i - start >= name_size)
        return 0;
    memcpy(name, line + start, i - start);
    name[i - start] = '\0';
    return 1;
}

static int expand(const tl_shader_lib *lib, const char *name, int depth, buffer *b,
                  tl_shader_source *out, tl_error *err)
{
    for (int i = 0; i < out->file_count; i++)
        if (strcmp(out->files[i], name) == 0)
            return TL_OK; /* each file once, like #pragma once */
    if (depth > MAX_INCLUDE_DEPTH)
        return tl_error_set(err, TL_ERR_RUNTIME, "shader includes nest deeper than %d at '%s'",
                            MAX_INCLUDE_DEPTH, name);
    if (out->file_count >= TL_SHADER_MAX_FILES)
        return tl_error_set(err, TL_ERR_RUNTIME, "more than %d shader files in one program",
                            TL_SHADER_MAX_FILES);
    int index = out->file_count++;
    snprintf(out->files[index], sizeof out->files[index], "%s", name);

    char *text = load_text(lib, name, err);
    if (!text)
        return err ? (int)err->status : TL_ERR_RUNTIME;
    buf_printf(b, "#line 1 %d\n", index);
    int line_no = 1;
    const char *p = text;
    while (*p) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        char inc[64];
        if (parse_include(p, len, inc, sizeof inc)) {
            int rc = expand(lib, inc, depth + 1, b, out, err);
            if (rc) {
                tl_error_prefix(err, "%s:%d", name, line_no);
                free(text);
                return rc;
            }
            buf_printf(b, "#line %d %d\n", line_no + 1, index);
        } else {
            buf_append(b, p, len);
            buf_append(b, "\n", 1);
        }
        line_no++;
        p = eol ? eol + 1 : p + len;
    }
    free(text);
    return TL_OK;
}

int tl_shader_compose(const tl_shader_lib *lib, const char *entry, const char *defines,
                      tl_shader_source *out, tl_error *err)
{
    memset(out, 0, sizeof *out);
    buffer b = {0};
    buf_append(&b, "#version 330 core\n", 18);
    /* Fine derivatives, where the driver has them (core from GL 4.5): the
     * shafts share their samples across each 2 x 2 quad of pixels. */
    static const char derivative_control[] = "#extension GL_ARB_derivative_control : enable\n";
    buf_append(&b, derivative_control, sizeof derivative_control - 1);
    if (defines)
        buf_append(&b, defines, strlen(defines));
    int rc = expand(lib, entry, 0, &b, out, err);
    if (!rc && b.failed)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "out of memory composing shader '%s'", entry);
    if (rc) {
        free(b.data);
        return rc;
    }
    out->text = b.data;
    return TL_OK;
}

void tl_shader_source_free(tl_shader_source *src)
{
    free(src->text);
    src->text = NULL;
}

char *tl_shader_annotate_log(const tl_shader_source *src, const char *log)
{
    buffer b = {0};
    const char *p = log;
    while (*p) {
        /* Drivers print "<string>:<line>" at the start of a message line
         * (Mesa: "0:12(5): error"; NVIDIA: "0(12) : error", rewritten to
         * Mesa's "name:12: error" so every message reads file:line). */
        char *end = NULL;
        long index = strtol(p, &end, 10);
        if (end != p && (*end == ':' || *end == '(') && index >= 0 && index < src->file_count) {
            buf_append(&b, src->files[index], strlen(src->files[index]));
            p = end;
            char *close = NULL;
            long line = *p == '(' ? strtol(p + 1, &close, 10) : -1;
            if (line >= 0 && close != p + 1 && strncmp(close, ") : ", 4) == 0) {
                buf_printf(&b, ":%ld: ", line);
                p = close + 4;
            }
        }
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) + 1 : strlen(p);
        buf_append(&b, p, len);
        p += len;
    }
    if (b.failed) {
        free(b.data);
        return NULL;
    }
    return b.data ? b.data : strdup("");
}
