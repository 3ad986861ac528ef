/* tl_timeline: a parsed cutscene and its evaluation into scenes.
 *
 * A timeline holds render settings, one track per channel (default, a
 * constant from `set`, or keyed curves from `key`), paths for the boat and
 * the camera, and links (look at, follow). tl_timeline_eval is a pure
 * function of time: the same t always gives the same scene. The language is
 * described in docs/timeline.md; tl_timeline_parse reads it. */
#ifndef TL_TIMELINE_H
#define TL_TIMELINE_H

#include <stdbool.h>

#include "scene/tl_scene.h"
#include "timeline/tl_channels.h"
#include "timeline/tl_curve.h"
#include "timeline/tl_path.h"

typedef enum tl_track_state { TL_TRACK_DEFAULT, TL_TRACK_SET, TL_TRACK_KEYED } tl_track_state;

typedef struct tl_track {
    tl_track_state state;
    double value[3];   /* TL_TRACK_SET */
    tl_curve curve[3]; /* TL_TRACK_KEYED: one per component */
    int line;          /* where it was set or keyed (0: default) */
    bool baked;        /* `key ... baked`: sampled at every frame by an exporter */
    bool past_end;     /* a key past the end was warned about at its line */
} tl_track;

typedef enum tl_target { TL_TARGET_NONE, TL_TARGET_POINT, TL_TARGET_BOAT } tl_target;

/* `look camera at ...`, `follow camera boat`, `follow giant.center NAME`. */
typedef struct tl_link {
    tl_target target;
    int object;       /* TL_TARGET_BOAT: which floating object (0: the boat) */
    double point[3];  /* TL_TARGET_POINT */
    double offset[3]; /* added to the object's position */
    int line;
} tl_link;

typedef struct tl_path_track {
    bool present;
    bool baked; /* `path ... baked`: a point at every frame, from an exporter */
    tl_path path;
    int line;
} tl_path_track;

/* A floating object's name: letters, digits and '_', starting with a
 * letter, shorter than this. */
#define TL_OBJECT_NAME_MAX 32

/* A floating object: the boat (object 0, always there, drawn once it has
 * a path) or one a timeline declares with `boat NAME`. */
typedef struct tl_object {
    char name[TL_OBJECT_NAME_MAX]; /* "boat" for object 0 */
    int line, column;              /* where `boat NAME` declared it (0 for the boat) */
    tl_path_track path;            /* `path NAME`: points x 0 z */
    /* `set NAME.model PATH`: the file, resolved against the timeline's
     * folder ("" = the built-in boat), and where it was named. */
    char model[1024];
    int model_line, model_column;
    /* The loaded model's bounds in model units, and which of the loaded
     * models it is (tl_timeline_set_object_model); until then the built-in
     * boat's. */
    bool bounds_known;
    double model_min[3], model_max[3];
    int mesh;
    /* Its `boat.*` channels' tracks, one per channel as tl->tracks: the
     * boat's are tl->tracks themselves (NULL here). */
    tl_track *tracks;
} tl_object;

typedef struct tl_timeline {
    char file[512];
    int version;
    double fps;
    double duration; /* seconds */
    int width, height;
    tl_quality quality;
    /* The `passes` line: the compositing passes its EXR frames carry
     * (TL_PASSES_* of src/passes; 0: none, the plain RGBA + Z file). */
    unsigned passes;
    /* The `working_space` line: the EXR colour's space (tl_working_space). */
    int working_space;
    tl_track *tracks;          /* tl_channel_count() entries */
    tl_path_track camera_path; /* points x y z */
    tl_link camera_look;
    tl_link camera_follow;
    tl_link giant_follow;
    /* The floating objects: objects[0] is the boat, the others are
     * declared with `boat NAME`, in order. */
    tl_object objects[TL_OBJECT_MAX];
    int object_count;
    /* The `audio PATH [OFFSET]` line: the soundtrack ("" = none), resolved
     * against the timeline's folder; its first sample plays at timeline
     * time audio_offset (negative: the file starts before the timeline). */
    char audio[1024];
    double audio_offset;
    int audio_line, audio_column;
    /* The file as tl_cutscene_load found it (0 until then). */
    double audio_duration;
    int audio_rate, audio_channels;
} tl_timeline;

/* Object k's track of channel `channel` (a tl_channel_index): its own for
 * a `boat.*` channel, the timeline's for any other. */
tl_track *tl_timeline_track(const tl_timeline *tl, int channel, int object);

/* The object named `name` (0 for "boat"), or -1. */
int tl_timeline_object(const tl_timeline *tl, const char *name);

/* Declares floating object `name` (checked by the parser: a new, valid
 * name, room for one more); its index, or -1 when out of memory. */
int tl_timeline_add_object(tl_timeline *tl, const char *name, int line, int column);

/* Floating (tl_float.c): sets s->boat's height, pitch and roll at time t
 * from the scene's boat position, heading, length and beam. The waterline
 * never sits more than TL_FLOAT_MAX_SINK × length below the water at the
 * boat's centre, and it tilts less than TL_FLOAT_MAX_TILT. */
#define TL_FLOAT_MAX_SINK 0.05
/* Pitch and roll are limited softly to TL_FLOAT_MAX_TILT radians: as they
 * are up to TL_FLOAT_TILT_KNEE, then bent smoothly (a tanh, with slope 1 at
 * the knee) toward the limit. The five points' fit across a crest sharper
 * than the hull, or onto the giant wave's lip, stood the boat on its stern,
 * where a hull's weight and inertia carry it over; at 35° a hull climbing
 * the giant wave's steep face hung its stern in the air above it. */
#define TL_FLOAT_MAX_TILT  (50.0 * 3.14159265358979323846 / 180.0)
#define TL_FLOAT_TILT_KNEE (25.0 * 3.14159265358979323846 / 180.0)
/* The giant wave's slope reaches pitch and roll through a spring of this
 * response time, seconds (or boat.float_time, if shorter), not the
 * chop's: its face steepens under a climbing hull within a second, and
 * lagging boat.float_time behind it the hull pitched 39° on a 64° face,
 * its bow metres inside the face and its stern in the air (judges).
 * Followed directly, the pitch flipped by 17° in a frame as the crest
 * passed under the hull. */
#define TL_FLOAT_GIANT_TIME 0.15
void tl_timeline_float_boat(const tl_timeline *tl, int object, double t, int heading_from_path,
                            tl_scene *s);

/* The water's height at the boat's stem (half its length ahead of its
 * centre) less the stem's at its waterline, metres, for the scene's
 * floated pose: its change over time is how fast the water rises against
 * the bow (tl_boat.impact). */
double tl_timeline_bow_gap(const tl_scene *s, int object);
/* The interval over which tl_boat.impact is taken: long enough that a
 * ripple's quick rise and fall at the stem does not flicker the spray
 * from frame to frame, short against a wave that the bow slams into. */
#define TL_BOW_IMPACT_DT 0.25

/* Records which loaded model object k is drawn with and its bounds: its
 * hull length and beam (which floating samples) and its extent on screen. */
void tl_timeline_set_object_model(tl_timeline *tl, int object, int mesh, const float bounds_min[3],
                                  const float bounds_max[3]);

/* A timeline with no keys: render defaults (24 fps, 10 s, 1280x720, final). */
int tl_timeline_init(tl_timeline *tl, tl_error *err);
void tl_timeline_free(tl_timeline *tl);

/* Number of frames: floor(duration * fps + 0.5), at least 1. */
long tl_timeline_frame_count(const tl_timeline *tl);
/* A frame's time: frame / fps, from the integer frame, never accumulated. */
double tl_timeline_frame_time(const tl_timeline *tl, long frame);

/* The scene at time t (seconds). Evaluated values stay inside each
 * channel's range (an overshooting ease is clamped to it). */
void tl_timeline_eval(const tl_timeline *tl, double t, tl_scene *scene);

/* True if any keyed channel jumps at a cut in (t0, t1]. */
bool tl_timeline_has_cut_between(const tl_timeline *tl, double t0, double t1);

/* Frame `frame`'s shutter interval (tl_shutter.c): centred on its time,
 * `shutter_deg`/360 of a frame long, cut short at any cut inside it so
 * that motion blur never mixes two shots (a cut's own time belongs to the
 * shot after it). */
void tl_timeline_shutter_interval(const tl_timeline *tl, long frame, double shutter_deg,
                                  double *open, double *close);
/* The times of frame `frame`'s `samples` shutter samples into `times`:
 * the centres of `samples` equal slices of its shutter interval, in
 * order; without a shutter (shutter_deg <= 0, or one sample) the frame's
 * own time alone. Returns the index of the sample nearest the frame's
 * time (the first of two as near). */
int tl_timeline_shutter_times(const tl_timeline *tl, long frame, double shutter_deg, int samples,
                              double *times);

/* Features the timeline needs over its whole duration (for `check`). */
typedef struct tl_timeline_features {
    bool giant_wave, boat, underwater, fog;
    int objects; /* floating objects with a path */
} tl_timeline_features;
void tl_timeline_features_of(const tl_timeline *tl, tl_timeline_features *out);

#endif
