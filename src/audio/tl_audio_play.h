/* tl_audio_play: the preview's soundtrack through the default audio
 * device (SDL2), following the preview's playhead. Its own library,
 * linked by the preview alone: headless programs never open a device.
 *
 * The device pulls samples from the clip on its own thread; the preview
 * says each frame where the sound should be. When the two drift apart by
 * more than TL_AUDIO_SYNC (a scrub, a jump, the loop's wrap) the device
 * jumps there; while the playhead moves at any speed but 1, or stands, the
 * device plays silence. */
#ifndef TL_AUDIO_PLAY_H
#define TL_AUDIO_PLAY_H

#include "audio/tl_audio.h"
#include "core/tl_error.h"

/* Seconds the device may drift from the playhead before it jumps to it. */
#define TL_AUDIO_SYNC 0.08

typedef struct tl_audio_player tl_audio_player;

/* Opens the default output device for `clip` (which must outlive the
 * player, or be replaced first with tl_audio_player_use). Fails with the
 * audio system's reason where there is no device. */
int tl_audio_player_open(tl_audio_player **out, const tl_audio_clip *clip, tl_error *err);
/* Plays another clip (NULL: silence) from now on; reopens the device when
 * its rate or channels differ. */
int tl_audio_player_use(tl_audio_player *p, const tl_audio_clip *clip, tl_error *err);
/* The sound should be at `at` seconds into the clip, playing or not. */
void tl_audio_player_follow(tl_audio_player *p, double at, int playing);
void tl_audio_player_close(tl_audio_player *p);

#endif
