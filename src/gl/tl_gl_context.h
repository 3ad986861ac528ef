/* tl_gl_context: a headless OpenGL context through EGL (no window, no X).
 *
 * Platforms are tried in order: EGL_EXT_platform_device (GPU servers and
 * render farms), EGL_MESA_platform_surfaceless (Mesa, llvmpipe), then the
 * default display. TIDELINE_EGL_PLATFORM=device|surfaceless|default tries
 * only that one. The context is OpenGL 3.3 core or newer and is made
 * current without a surface: rendering goes to framebuffer objects. */
#ifndef TL_GL_CONTEXT_H
#define TL_GL_CONTEXT_H

#include "core/tl_error.h"

typedef struct tl_gl_context tl_gl_context;

/* On failure the message lists every platform tried and why it failed. */
int tl_gl_context_create_headless(tl_gl_context **out, tl_error *err);
void tl_gl_context_destroy(tl_gl_context *ctx);

/* Whether EGL's client extensions (a space-separated list) let the device
 * platform enumerate GPUs: EGL_EXT_platform_device with either
 * EGL_EXT_device_enumeration (Mesa) or EGL_EXT_device_base (NVIDIA). */
int tl_gl_egl_lists_devices(const char *client_exts);

/* "EGL <platform>: <GL renderer>, OpenGL <version>" for -v logs. */
const char *tl_gl_context_describe(const tl_gl_context *ctx);

/* The EGL client's version for `--version -v` ("EGL client 1.5"). */
void tl_gl_library_versions(char *out, int out_size);

#endif
