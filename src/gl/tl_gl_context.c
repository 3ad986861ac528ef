#include "tl_gl_context.h"

/* epoxy must come before any other GL header. */
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct tl_gl_context {
    EGLDisplay display;
    EGLContext context;
    char description[512];
};

typedef enum platform { PLATFORM_DEVICE, PLATFORM_SURFACELESS, PLATFORM_DEFAULT } platform;
static const char *const platform_names[] = {"device", "surfaceless", "default"};

static int has_word(const char *list, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = list; p && (p = strstr(p, word)) != NULL; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return 1;
    return 0;
}

static const char *egl_error_name(EGLint code)
{
    switch (code) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error";
    }
}

/* Initialises `dpy` and makes a 3.3+ core context current on it. Fills
 * `why` on failure. */
static int make_context(struct tl_gl_context *c, EGLDisplay dpy, char *why, size_t why_size)
{
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY) {
        snprintf(why, why_size, "no display (%s)", egl_error_name(eglGetError()));
        return 0;
    }
    if (!eglInitialize(dpy, &major, &minor)) {
        snprintf(why, why_size, "eglInitialize failed (%s)", egl_error_name(eglGetError()));
        return 0;
    }
    const char *exts = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!has_word(exts, "EGL_KHR_surfaceless_context")) {
        snprintf(why, why_size, "EGL %d.%d lacks EGL_KHR_surfaceless_context", major, minor);
        eglTerminate(dpy);
        return 0;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        snprintf(why, why_size, "desktop OpenGL not supported (%s)", egl_error_name(eglGetError()));
        eglTerminate(dpy);
        return 0;
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has_word(exts, "EGL_KHR_no_config_context")) {
        const EGLint attrs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                EGL_DONT_CARE, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(dpy, attrs, &config, 1, &count) || count < 1) {
            snprintf(why, why_size, "no OpenGL-capable EGL config");
            eglTerminate(dpy);
            return 0;
        }
    }
    const EGLint ctx_attrs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                3,
                                EGL_CONTEXT_MINOR_VERSION,
                                3,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attrs);
    if (ctx == EGL_NO_CONTEXT) {
        snprintf(why, why_size, "no OpenGL 3.3 core context (%s)", egl_error_name(eglGetError()));
        eglTerminate(dpy);
        return 0;
    }
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        snprintf(why, why_size, "eglMakeCurrent failed (%s)", egl_error_name(eglGetError()));
        eglDestroyContext(dpy, ctx);
        eglTerminate(dpy);
        return 0;
    }
    c->display = dpy;
    c->context = ctx;
    return 1;
}

int tl_gl_egl_lists_devices(const char *client_exts)
{
    /* EGL_EXT_device_base is device_enumeration and device_query in one
     * name; NVIDIA's driver lists only that one. */
    return has_word(client_exts, "EGL_EXT_platform_device") &&
           (has_word(client_exts, "EGL_EXT_device_enumeration") ||
            has_word(client_exts, "EGL_EXT_device_base"));
}

static int try_platform(struct tl_gl_context *c, platform p, const char *client_exts, char *why,
                        size_t why_size)
{
    switch (p) {
    case PLATFORM_DEVICE: {
        if (!tl_gl_egl_lists_devices(client_exts)) {
            snprintf(why, why_size, "EGL_EXT_platform_device not supported");
            return 0;
        }
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (!eglQueryDevicesEXT(16, devices, &count) || count < 1) {
            snprintf(why, why_size, "no EGL devices found");
            return 0;
        }
        for (EGLint i = 0; i < count; i++) {
            EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], NULL);
            if (make_context(c, dpy, why, why_size))
                return 1;
        }
        return 0; /* why holds the last device's reason */
    }
    case PLATFORM_SURFACELESS:
        if (!has_word(client_exts, "EGL_MESA_platform_surfaceless")) {
            snprintf(why, why_size, "EGL_MESA_platform_surfaceless not supported");
            return 0;
        }
        return make_context(
            c, eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL),
            why, why_size);
    case PLATFORM_DEFAULT:
        return make_context(c, eglGetDisplay(EGL_DEFAULT_DISPLAY), why, why_size);
    }
    return 0;
}

int tl_gl_context_create_headless(tl_gl_context **out, tl_error *err)
{
    *out = NULL;
    struct tl_gl_context *c = calloc(1, sizeof *c);
    if (!c)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    int first = PLATFORM_DEVICE, last = PLATFORM_DEFAULT;
    const char *forced = getenv("TIDELINE_EGL_PLATFORM");
    if (forced && *forced) {
        first = -1;
        for (int p = PLATFORM_DEVICE; p <= PLATFORM_DEFAULT; p++)
            if (strcmp(forced, platform_names[p]) == 0)
                first = last = p;
        if (first < 0) {
            free(c);
            return tl_error_set(err, TL_ERR_USAGE,
                                "TIDELINE_EGL_PLATFORM='%s' is not one of device, surfaceless, "
                                "default",
                                forced);
        }
    }
    /* Client extensions are queried without a display; NULL means EGL 1.4
     * without client extensions, where only the default display exists. */
    const char *client_exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    char tried[900] = "";
    for (int p = first; p <= last; p++) {
        char why[200] = "unknown failure";
        if (try_platform(c, (platform)p, client_exts ? client_exts : "", why, sizeof why)) {
            snprintf(c->description, sizeof c->description, "EGL %s: %s, OpenGL %s",
                     platform_names[p], (const char *)glGetString(GL_RENDERER),
                     (const char *)glGetString(GL_VERSION));
            *out = c;
            return TL_OK;
        }
        size_t used = strlen(tried);
        snprintf(tried + used, sizeof tried - used, "%s%s: %s", used ? "; " : "", platform_names[p],
                 why);
    }
    free(c);
    return tl_error_set(err, TL_ERR_RUNTIME,
                        "no headless OpenGL 3.3 context (tried %s). Install Mesa's EGL and "
                        "llvmpipe (libegl-mesa0, libgl1-mesa-dri) or a GPU driver",
                        tried);
}

void tl_gl_context_destroy(tl_gl_context *c)
{
    if (!c)
        return;
    eglMakeCurrent(c->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(c->display, c->context);
    eglTerminate(c->display);
    free(c);
}

const char *tl_gl_context_describe(const tl_gl_context *c)
{
    return c->description;
}

void tl_gl_library_versions(char *out, int out_size)
{
    const char *egl = eglQueryString(EGL_NO_DISPLAY, EGL_VERSION);
    snprintf(out, (size_t)out_size, "EGL client %s", egl ? egl : "1.4");
}
