/* seed002: the yardstick harness. Renders the seeds' reference ocean shader
 * (bench/seed002.frag) headless into one RGBA8 target with one readback per
 * frame, the least work a frame of that shader can cost, and reports the
 * median milliseconds per frame. Optionally writes the last frame as PNG
 * so tideline's `seed` preset can be compared with it (`tideline compare`).
 *
 *   seed002 [--size WxH] [--time SECONDS] [--repeat N] [--srgb] [--out FILE.png]
 *           [--march-octaves N] [--normal-octaves N] [--steps N] [--fixed-steps N]
 *
 * Timings: one warm-up frame, then N frames; each frame is the draw plus the
 * readback (glReadPixels waits for the draw to finish). */
#include "gl/tl_gl_context.h"

#include <epoxy/gl.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef SEED002_FRAG
#define SEED002_FRAG "seed002.frag"
#endif

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (text && fread(text, 1, (size_t)n, f) == (size_t)n) {
        text[n] = '\0';
    } else {
        free(text);
        text = NULL;
    }
    fclose(f);
    return text;
}

static GLuint compile(GLenum type, const char *const *parts, int count)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, count, parts, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "seed002: shader: %s\n", log);
        exit(1);
    }
    return s;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void usage(FILE *to)
{
    fprintf(to, "usage: seed002 [--size WxH] [--time SECONDS] [--repeat N] [--srgb] "
                "[--out FILE.png] [--shader FILE]\n"
                "               [--march-octaves N] [--normal-octaves N] [--steps N] "
                "[--fixed-steps N]\n"
                "Renders the seeds' reference ocean shader headless and prints the median\n"
                "ms per frame (draw + one RGBA8 readback) over N frames after a warm-up.\n"
                "The document's settings are 12 march octaves, 36 normal octaves and 64\n"
                "adaptive steps; --fixed-steps N marches N equal steps across the slab.\n");
}

int main(int argc, char **argv)
{
    int width = 640, height = 360, repeat = 10, srgb = 0;
    int march_octaves = 12, normal_octaves = 36, steps = 64, fixed_steps = 0;
    double t = 10.0;
    const char *out = NULL, *shader_path = SEED002_FRAG;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return 0;
        } else if (strcmp(a, "--srgb") == 0) {
            srgb = 1;
        } else if (v && strcmp(a, "--size") == 0 && sscanf(v, "%dx%d", &width, &height) == 2 &&
                   width > 0 && height > 0 && width <= 16384 && height <= 16384) {
            i++;
        } else if (v && strcmp(a, "--time") == 0 && sscanf(v, "%lf", &t) == 1) {
            i++;
        } else if (v && strcmp(a, "--repeat") == 0 && sscanf(v, "%d", &repeat) == 1 &&
                   repeat >= 1) {
            i++;
        } else if (v && strcmp(a, "--march-octaves") == 0 && sscanf(v, "%d", &march_octaves) == 1 &&
                   march_octaves >= 1) {
            i++;
        } else if (v && strcmp(a, "--normal-octaves") == 0 &&
                   sscanf(v, "%d", &normal_octaves) == 1 && normal_octaves >= 1) {
            i++;
        } else if (v && strcmp(a, "--steps") == 0 && sscanf(v, "%d", &steps) == 1 && steps >= 1) {
            i++;
        } else if (v && strcmp(a, "--fixed-steps") == 0 && sscanf(v, "%d", &fixed_steps) == 1 &&
                   fixed_steps >= 0) {
            i++;
        } else if (v && strcmp(a, "--out") == 0) {
            out = v;
            i++;
        } else if (v && strcmp(a, "--shader") == 0) {
            shader_path = v;
            i++;
        } else {
            fprintf(stderr, "seed002: bad argument '%s'\n", a);
            usage(stderr);
            return 2;
        }
    }

    tl_error err = {0};
    tl_gl_context *ctx = NULL;
    if (tl_gl_context_create_headless(&ctx, &err) != TL_OK) {
        fprintf(stderr, "seed002: %s\n", err.message);
        return 1;
    }
    char *frag = read_text(shader_path);
    if (!frag) {
        fprintf(stderr, "seed002: cannot read %s\n", shader_path);
        return 1;
    }
    /* The #version line comes first, then the transfer switch. */
    const char *fparts[] = {"#version 330 core\n", srgb ? "#define SEED_SRGB\n" : "", frag};
    const char *vert =
        "#version 330 core\n"
        "void main() {\n"
        "    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\n"
        "    gl_Position = vec4(p, 0.0, 1.0);\n"
        "}\n";
    GLuint prog = glCreateProgram();
    glAttachShader(prog, compile(GL_VERTEX_SHADER, &vert, 1));
    glAttachShader(prog, compile(GL_FRAGMENT_SHADER, fparts, 3));
    glLinkProgram(prog);
    GLint linked = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &linked);
    if (!linked) {
        fprintf(stderr, "seed002: program does not link\n");
        return 1;
    }
    free(frag);

    GLuint vao, fbo, rb;
    glGenVertexArrays(1, &vao);
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glViewport(0, 0, width, height);
    glUseProgram(prog);
    glBindVertexArray(vao);
    glUniform1f(glGetUniformLocation(prog, "iTime"), (float)t);
    glUniform3f(glGetUniformLocation(prog, "iResolution"), (float)width, (float)height, 1.0f);
    glUniform4f(glGetUniformLocation(prog, "iMouse"), 0.0f, 0.0f, 0.0f, 0.0f);
    glUniform1i(glGetUniformLocation(prog, "u_iterations_raymarch"), march_octaves);
    glUniform1i(glGetUniformLocation(prog, "u_iterations_normal"), normal_octaves);
    glUniform1i(glGetUniformLocation(prog, "u_raymarch_steps"), steps);
    glUniform1i(glGetUniformLocation(prog, "u_fixed_steps"), fixed_steps);

    unsigned char *pixels = malloc((size_t)width * height * 4);
    double *ms = malloc(sizeof(double) * (size_t)repeat);
    if (!pixels || !ms)
        return 1;
    for (int i = -1; i < repeat; i++) {
        double t0 = now_ms();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        if (i >= 0)
            ms[i] = now_ms() - t0;
    }
    qsort(ms, (size_t)repeat, sizeof *ms, cmp_double);
    printf("seed002 %dx%d t=%g: median %.1f ms/frame over %d frames (min %.1f, max %.1f) on %s\n",
           width, height, t, ms[repeat / 2], repeat, ms[0], ms[repeat - 1],
           tl_gl_context_describe(ctx));

    int status = 0;
    if (out) {
        /* GL rows run bottom-up; PNG's top-down: a negative stride flips. */
        png_image image;
        memset(&image, 0, sizeof image);
        image.version = PNG_IMAGE_VERSION;
        image.width = (png_uint_32)width;
        image.height = (png_uint_32)height;
        image.format = PNG_FORMAT_RGBA;
        png_int_32 stride = -(png_int_32)width * 4;
        if (!png_image_write_to_file(&image, out, 0, pixels, stride, NULL)) {
            fprintf(stderr, "seed002: cannot write %s: %s\n", out, image.message);
            status = 1;
        }
    }
    free(pixels);
    free(ms);
    tl_gl_context_destroy(ctx);
    return status;
}
