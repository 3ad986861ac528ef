/* tl_channels: the table of every scene parameter a timeline can address.
 *
 * One row per channel: its name, how many components it has, the unit its
 * numbers are written in, its valid range, and where it lives in tl_scene.
 * The parser, `tideline check`, `tideline eval` and docs/timeline.md all
 * read this table, so a new scene parameter is one new row. Defaults are
 * not repeated here: they are whatever tl_scene_defaults sets. */
#ifndef TL_CHANNELS_H
#define TL_CHANNELS_H

#include <stdbool.h>
#include <stddef.h>

#include "scene/tl_scene.h"

typedef enum tl_channel_kind {
    TL_CH_REAL, /* double[components] */
    TL_CH_BOOL, /* bool: on/off, true/false, 1/0; keys step */
    TL_CH_ENUM, /* a C enum (int-sized) named by `names`; keys step */
    TL_CH_INT,  /* int; set only */
} tl_channel_kind;

typedef enum tl_unit {
    TL_UNIT_NONE,   /* a plain number */
    TL_UNIT_LENGTH, /* metres: bare number or `m` */
    TL_UNIT_ANGLE,  /* bare number or `deg` = degrees, `rad` = radians; stored in radians */
    TL_UNIT_TIME,   /* bare number or `s` = seconds, `ms`, `f` = frames at the fps */
} tl_unit;

typedef struct tl_channel {
    const char *name;
    tl_channel_kind kind;
    int components; /* 1..3 */
    tl_unit unit;
    double min, max; /* valid range of each component, in stored units */
    bool keyable;
    size_t offset;            /* into tl_scene */
    const char *const *names; /* TL_CH_ENUM: value names, NULL-terminated */
    const char *doc;
} tl_channel;

int tl_channel_count(void);
const tl_channel *tl_channel_at(int index);
/* NULL when unknown. */
const tl_channel *tl_channel_find(const char *name);
int tl_channel_index(const tl_channel *ch);

/* Reads/writes a channel's components in a scene as doubles (bools and
 * enums as 0/1/index). */
void tl_channel_get(const tl_channel *ch, const tl_scene *scene, double out[3]);
void tl_channel_set(const tl_channel *ch, tl_scene *scene, const double in[3]);

/* The `boat.*` channels are every floating object's: a timeline's
 * `rescue.wake` is boat.wake of the object it declared as `boat rescue`. */
bool tl_channel_is_object(const tl_channel *ch);
/* As tl_channel_get/set, for floating object k (0: the boat; other
 * channels ignore k). */
void tl_channel_get_object(const tl_channel *ch, const tl_scene *scene, int object, double out[3]);
void tl_channel_set_object(const tl_channel *ch, tl_scene *scene, int object, const double in[3]);

/* Closest of `candidates` (NULL-terminated) to `word`, or NULL when none is
 * close enough to be a likely typo. */
const char *tl_suggest(const char *word, const char *const *candidates);
/* Closest channel name, or NULL. */
const char *tl_channel_suggest(const char *word);

#endif
