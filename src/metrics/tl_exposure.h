/* tl_exposure: exposure that meters itself (render.auto_exposure), the
 * GL-free half: the meter over a frame, the eye's adaptation over time,
 * and the exposure they give. tl_render_meter.c draws the small frames
 * the meter reads.
 *
 * The meter is a camera's centre-weighted average of log luminance over a
 * small frame of the scene's linear light. The exposure adapts to it as an
 * eye does: its log follows the meter through a first-order lag of time
 * constant render.adapt_time, so that a cut or a dive adapts over a second
 * rather than at once. The lag is integrated over meters taken on a fixed
 * grid of times (multiples of a quarter of the time constant, plus the
 * frame's own time), so that a frame's exposure depends on the timeline
 * and its time alone: the same in `still`, in any chunk of a farm render
 * and in the preview, and consecutive frames share their meters. */
#ifndef TL_EXPOSURE_H
#define TL_EXPOSURE_H

/* The scene luminance the meter's average is brought to before the
 * tonemap: photographic mid-grey. */
#define TL_EXPOSURE_KEY 0.18
/* A pixel darker than this counts as this (log of black is -inf). */
#define TL_EXPOSURE_FLOOR 1.0e-6
/* The metered exposure stays within this many stops of 1 (a black frame
 * would ask for infinite gain). */
#define TL_EXPOSURE_MAX_STOPS 20.0
/* The meters' grid: a quarter of the time constant apart, over the last
 * TL_EXPOSURE_WINDOW time constants (what lies before weighs e^-4 and is
 * taken as the oldest meter). */
#define TL_EXPOSURE_STEPS_PER_TAU 4
#define TL_EXPOSURE_WINDOW        4
#define TL_EXPOSURE_NODES         (TL_EXPOSURE_STEPS_PER_TAU * TL_EXPOSURE_WINDOW + 2)

/* The centre-weighted mean of log2 luminance (Rec. 709 weights) of an RGBA
 * image, rows of `width` pixels: each pixel weighs 0.25 + exp(-2 r^2),
 * r^2 = u^2 + v^2 with u, v in [-1, 1] across the frame, so the centre
 * counts about four and a half times a corner. */
double tl_exposure_meter(const float *rgba, int width, int height);

/* The times whose meters the adapted value at time t is made of, and
 * their weights (summing to 1): the frame's own time, then the grid's
 * multiples of tau/4 at or below it down to max(0, t - 4 tau) (the start
 * of the timeline: the eye is adapted to the first frame). Returns the
 * count (1 when tau <= 0: the meter at t alone). The adapted log
 * luminance is sum(weight_i * meter(time_i)). */
int tl_exposure_nodes(double t, double tau, double times[TL_EXPOSURE_NODES],
                      double weights[TL_EXPOSURE_NODES]);

/* The display's linear exposure for render.exposure `exposure`, metered
 * strength `strength` in [0, 1] and adapted log2 luminance `adapted`:
 * exposure^(1 - strength) * (KEY / 2^adapted)^strength, the metered part
 * within TL_EXPOSURE_MAX_STOPS. render.ev applies on top. */
double tl_exposure_scale(double exposure, double strength, double adapted);

#endif
