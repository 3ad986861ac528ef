/* tl_gl_window: a desktop window with an OpenGL 3.3 core context (GLFW),
 * for the live preview. The renderer draws into it exactly as it draws
 * headless; only the context's origin differs. Input arrives as a queue
 * of key presses plus the state of held keys and the mouse. */
#ifndef TL_GL_WINDOW_H
#define TL_GL_WINDOW_H

#include <stdbool.h>

#include "core/tl_error.h"

typedef struct tl_gl_window tl_gl_window;

/* The keys the preview knows. */
typedef enum tl_keycode {
    TL_KEY_NONE = 0,
    TL_KEY_SPACE,
    TL_KEY_LEFT,
    TL_KEY_RIGHT,
    TL_KEY_UP,
    TL_KEY_DOWN,
    TL_KEY_HOME,
    TL_KEY_END,
    TL_KEY_BRACKET_LEFT,
    TL_KEY_BRACKET_RIGHT,
    TL_KEY_1,
    TL_KEY_2,
    TL_KEY_3,
    TL_KEY_4,
    TL_KEY_C,
    TL_KEY_P,
    TL_KEY_F,
    TL_KEY_R,
    TL_KEY_H,
    TL_KEY_L,
    TL_KEY_QUESTION,
    TL_KEY_ESCAPE,
    TL_KEY_W,
    TL_KEY_A,
    TL_KEY_S,
    TL_KEY_D,
    TL_KEY_Q,
    TL_KEY_E,
    TL_KEY_I,
    TL_KEY_O,
    TL_KEY_G,
    TL_KEY_X,
    TL_KEY_TAB,
    TL_KEY_COUNT
} tl_keycode;

typedef struct tl_key_press {
    tl_keycode key;
    bool shift;
} tl_key_press;

/* Opens a window of the given size; without a display the message names
 * DISPLAY / WAYLAND_DISPLAY and suggests `tideline render`. */
int tl_gl_window_open(tl_gl_window **out, int width, int height, const char *title, tl_error *err);
void tl_gl_window_close(tl_gl_window *w);

/* Processes events; fills up to `max` key presses since the last call. */
int tl_gl_window_poll(tl_gl_window *w, tl_key_press *presses, int max);
bool tl_gl_window_should_close(const tl_gl_window *w);
bool tl_gl_window_key_held(const tl_gl_window *w, tl_keycode key);
/* Mouse movement with the left button held since the last call, pixels. */
void tl_gl_window_drag(tl_gl_window *w, double *dx, double *dy);
/* The mouse, in framebuffer pixels from the top left: where it is, whether
 * the left button is held, where it was last pressed and whether that was
 * since the last call, and the wheel's steps since the last call. */
typedef struct tl_gl_mouse {
    double x, y;
    bool held, pressed;
    double press_x, press_y;
    double scroll;
} tl_gl_mouse;
void tl_gl_window_mouse(tl_gl_window *w, tl_gl_mouse *m);
void tl_gl_window_size(const tl_gl_window *w, int *width, int *height);
void tl_gl_window_set_title(tl_gl_window *w, const char *title);
void tl_gl_window_swap(tl_gl_window *w);
/* Seconds on a monotonic clock. */
double tl_gl_window_time(void);
/* GLFW's version string, for `--version -v`. */
const char *tl_gl_window_library_version(void);
/* "<renderer>, OpenGL <version>" of the window's context. */
const char *tl_gl_window_describe(const tl_gl_window *w);

#endif
