#include "tl_gl_window.h"

/* epoxy must come before any other GL header. */
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define QUEUE 64

struct tl_gl_window {
    GLFWwindow *window;
    tl_key_press queue[QUEUE];
    int queued;
    double drag_x, drag_y, last_x, last_y;
    bool dragging;
    bool pressed;            /* since the last tl_gl_window_mouse */
    double press_x, press_y; /* window coordinates */
    double scroll;
    char description[256];
};

static tl_keycode key_of(int key)
{
    switch (key) {
    case GLFW_KEY_SPACE: return TL_KEY_SPACE;
    case GLFW_KEY_LEFT: return TL_KEY_LEFT;
    case GLFW_KEY_RIGHT: return TL_KEY_RIGHT;
    case GLFW_KEY_UP: return TL_KEY_UP;
    case GLFW_KEY_DOWN: return TL_KEY_DOWN;
    case GLFW_KEY_HOME: return TL_KEY_HOME;
    case GLFW_KEY_END: return TL_KEY_END;
    case GLFW_KEY_LEFT_BRACKET: return TL_KEY_BRACKET_LEFT;
    case GLFW_KEY_RIGHT_BRACKET: return TL_KEY_BRACKET_RIGHT;
    case GLFW_KEY_1: return TL_KEY_1;
    case GLFW_KEY_2: return TL_KEY_2;
    case GLFW_KEY_3: return TL_KEY_3;
    case GLFW_KEY_4: return TL_KEY_4;
    case GLFW_KEY_C: return TL_KEY_C;
    case GLFW_KEY_P: return TL_KEY_P;
    case GLFW_KEY_F: return TL_KEY_F;
    case GLFW_KEY_R: return TL_KEY_R;
    case GLFW_KEY_H: return TL_KEY_H;
    case GLFW_KEY_L: return TL_KEY_L;
    case GLFW_KEY_SLASH: return TL_KEY_QUESTION;
    case GLFW_KEY_ESCAPE: return TL_KEY_ESCAPE;
    case GLFW_KEY_W: return TL_KEY_W;
    case GLFW_KEY_A: return TL_KEY_A;
    case GLFW_KEY_S: return TL_KEY_S;
    case GLFW_KEY_D: return TL_KEY_D;
    case GLFW_KEY_Q: return TL_KEY_Q;
    case GLFW_KEY_E: return TL_KEY_E;
    case GLFW_KEY_I: return TL_KEY_I;
    case GLFW_KEY_O: return TL_KEY_O;
    case GLFW_KEY_G: return TL_KEY_G;
    case GLFW_KEY_X: return TL_KEY_X;
    case GLFW_KEY_TAB: return TL_KEY_TAB;
    default: return TL_KEY_NONE;
    }
}

static void on_key(GLFWwindow *window, int key, int scancode, int action, int mods)
{
    (void)scancode;
    tl_gl_window *w = glfwGetWindowUserPointer(window);
    tl_keycode k = key_of(key);
    if (!w || k == TL_KEY_NONE || (action != GLFW_PRESS && action != GLFW_REPEAT))
        return;
    if (w->queued < QUEUE)
        w->queue[w->queued++] = (tl_key_press){k, (mods & GLFW_MOD_SHIFT) != 0};
}

static void on_cursor(GLFWwindow *window, double x, double y)
{
    tl_gl_window *w = glfwGetWindowUserPointer(window);
    if (!w)
        return;
    if (w->dragging) {
        w->drag_x += x - w->last_x;
        w->drag_y += y - w->last_y;
    }
    w->last_x = x;
    w->last_y = y;
}

static void on_button(GLFWwindow *window, int button, int action, int mods)
{
    (void)mods;
    tl_gl_window *w = glfwGetWindowUserPointer(window);
    if (w && button == GLFW_MOUSE_BUTTON_LEFT) {
        w->dragging = action == GLFW_PRESS;
        if (action == GLFW_PRESS) {
            w->pressed = true;
            glfwGetCursorPos(window, &w->press_x, &w->press_y);
        }
    }
}

static void on_scroll(GLFWwindow *window, double dx, double dy)
{
    (void)dx;
    tl_gl_window *w = glfwGetWindowUserPointer(window);
    if (w)
        w->scroll += dy;
}

int tl_gl_window_open(tl_gl_window **out, int width, int height, const char *title, tl_error *err)
{
    *out = NULL;
    if (!glfwInit()) {
        const char *why = NULL;
        glfwGetError(&why);
        return tl_error_set(
            err, TL_ERR_RUNTIME,
            "cannot open a window: no display (DISPLAY=%s, WAYLAND_DISPLAY=%s%s%s); "
            "use 'tideline render' or 'tideline still' without a display, or "
            "xvfb-run",
            getenv("DISPLAY") ? getenv("DISPLAY") : "unset",
            getenv("WAYLAND_DISPLAY") ? getenv("WAYLAND_DISPLAY") : "unset", why ? ": " : "",
            why ? why : "");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    tl_gl_window *w = calloc(1, sizeof *w);
    if (!w) {
        glfwTerminate();
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    w->window = glfwCreateWindow(width, height, title, NULL, NULL);
    if (!w->window) {
        const char *why = NULL;
        glfwGetError(&why);
        free(w);
        glfwTerminate();
        return tl_error_set(err, TL_ERR_RUNTIME, "cannot open a %dx%d OpenGL 3.3 window: %s", width,
                            height, why ? why : "unknown reason");
    }
    glfwSetWindowUserPointer(w->window, w);
    glfwSetKeyCallback(w->window, on_key);
    glfwSetCursorPosCallback(w->window, on_cursor);
    glfwSetMouseButtonCallback(w->window, on_button);
    glfwSetScrollCallback(w->window, on_scroll);
    glfwMakeContextCurrent(w->window);
    glfwSwapInterval(0); /* the preview paces itself by the clock */
    snprintf(w->description, sizeof w->description, "GLFW %s: %s, OpenGL %s",
             glfwGetVersionString(), (const char *)glGetString(GL_RENDERER),
             (const char *)glGetString(GL_VERSION));
    *out = w;
    return TL_OK;
}

void tl_gl_window_close(tl_gl_window *w)
{
    if (!w)
        return;
    glfwDestroyWindow(w->window);
    free(w);
    glfwTerminate();
}

int tl_gl_window_poll(tl_gl_window *w, tl_key_press *presses, int max)
{
    glfwPollEvents();
    int n = w->queued < max ? w->queued : max;
    memcpy(presses, w->queue, sizeof *presses * (size_t)n);
    w->queued = 0;
    return n;
}

bool tl_gl_window_should_close(const tl_gl_window *w)
{
    return glfwWindowShouldClose(w->window);
}

bool tl_gl_window_key_held(const tl_gl_window *w, tl_keycode key)
{
    static const int glfw_keys[TL_KEY_COUNT] = {
        [TL_KEY_W] = GLFW_KEY_W, [TL_KEY_A] = GLFW_KEY_A, [TL_KEY_S] = GLFW_KEY_S,
        [TL_KEY_D] = GLFW_KEY_D, [TL_KEY_Q] = GLFW_KEY_Q, [TL_KEY_E] = GLFW_KEY_E};
    int k = key > 0 && key < TL_KEY_COUNT ? glfw_keys[key] : 0;
    return k && glfwGetKey(w->window, k) == GLFW_PRESS;
}

void tl_gl_window_drag(tl_gl_window *w, double *dx, double *dy)
{
    *dx = w->drag_x;
    *dy = w->drag_y;
    w->drag_x = w->drag_y = 0.0;
}

void tl_gl_window_size(const tl_gl_window *w, int *width, int *height)
{
    glfwGetFramebufferSize(w->window, width, height);
}

void tl_gl_window_set_title(tl_gl_window *w, const char *title)
{
    glfwSetWindowTitle(w->window, title);
}

void tl_gl_window_swap(tl_gl_window *w)
{
    glfwSwapBuffers(w->window);
}

double tl_gl_window_time(void)
{
    return glfwGetTime();
}

const char *tl_gl_window_describe(const tl_gl_window *w)
{
    return w->description;
}

const char *tl_gl_window_library_version(void)
{
    return glfwGetVersionString();
}

void tl_gl_window_mouse(tl_gl_window *w, tl_gl_mouse *m)
{
    /* Window coordinates to framebuffer pixels (they differ on HiDPI). */
    int ww, wh, fw, fh;
    glfwGetWindowSize(w->window, &ww, &wh);
    glfwGetFramebufferSize(w->window, &fw, &fh);
    double sx = ww > 0 ? (double)fw / ww : 1.0, sy = wh > 0 ? (double)fh / wh : 1.0;
    double x, y;
    glfwGetCursorPos(w->window, &x, &y);
    m->x = x * sx;
    m->y = y * sy;
    m->held = w->dragging;
    m->pressed = w->pressed;
    m->press_x = w->press_x * sx;
    m->press_y = w->press_y * sy;
    m->scroll = w->scroll;
    w->pressed = false;
    w->scroll = 0.0;
}
