/* `tideline preview --keys`: a script of key presses and clicks on the
 * timeline bar, one a displayed frame, for tests and demos. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/tl_cli_preview.h"

static const struct {
    const char *name;
    tl_keycode key;
    bool shift;
} key_names[] = {
    {"space", TL_KEY_SPACE, false},
    {"left", TL_KEY_LEFT, false},
    {"right", TL_KEY_RIGHT, false},
    {"shift+left", TL_KEY_LEFT, true},
    {"shift+right", TL_KEY_RIGHT, true},
    {"home", TL_KEY_HOME, false},
    {"end", TL_KEY_END, false},
    {"[", TL_KEY_BRACKET_LEFT, false},
    {"]", TL_KEY_BRACKET_RIGHT, false},
    {"1", TL_KEY_1, false},
    {"2", TL_KEY_2, false},
    {"3", TL_KEY_3, false},
    {"4", TL_KEY_4, false},
    {"c", TL_KEY_C, false},
    {"p", TL_KEY_P, false},
    {"f", TL_KEY_F, false},
    {"r", TL_KEY_R, false},
    {"l", TL_KEY_L, false},
    {"shift+l", TL_KEY_L, true},
    {"i", TL_KEY_I, false},
    {"o", TL_KEY_O, false},
    {"g", TL_KEY_G, false},
    {"x", TL_KEY_X, false},
    {"tab", TL_KEY_TAB, false},
    {"h", TL_KEY_H, false},
    {"?", TL_KEY_QUESTION, false},
    {"esc", TL_KEY_ESCAPE, false},
};

int tl_cli_preview_parse_keys(const char *text, tl_preview_input *out, int max, tl_error *err)
{
    int n = 0;
    const char *p = text;
    while (*p) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        char word[32];
        if (len == 0 || len >= sizeof word) {
            tl_error_set(err, TL_ERR_USAGE, "--keys: empty or overlong key name in '%s'", text);
            return -1;
        }
        for (size_t i = 0; i < len; i++)
            word[i] = (char)(p[i] >= 'A' && p[i] <= 'Z' ? p[i] - 'A' + 'a' : p[i]);
        word[len] = '\0';
        if (n >= max) {
            tl_error_set(err, TL_ERR_USAGE, "--keys: more than %d steps", max);
            return -1;
        }
        int found = 0;
        if (strncmp(word, "click:", 6) == 0) {
            char *stop = NULL;
            double at = strtod(word + 6, &stop);
            if (stop == word + 6 || *stop != '\0' || !(at >= 0.0 && at <= 1.0)) {
                tl_error_set(err, TL_ERR_USAGE,
                             "--keys: '%s': a click takes a share of the bar, 0..1 "
                             "(click:0.5 is its middle)",
                             word);
                return -1;
            }
            out[n++] = (tl_preview_input){.is_click = 1, .click = at};
            found = 1;
        }
        for (size_t k = 0; !found && k < sizeof key_names / sizeof key_names[0]; k++)
            if (strcmp(word, key_names[k].name) == 0) {
                out[n++] = (tl_preview_input){.key = {key_names[k].key, key_names[k].shift}};
                found = 1;
            }
        if (!found) {
            tl_error_set(err, TL_ERR_USAGE,
                         "--keys: unknown key '%s' (see 'tideline preview --help')", word);
            return -1;
        }
        p += len + (end ? 1 : 0);
    }
    return n;
}
