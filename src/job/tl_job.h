/* tl_job: which frames a render run writes, and where.
 *
 * Pure functions of the command line and the timeline (never of the clock),
 * so a render farm can split one shot into chunks that run anywhere, in any
 * order, and produce the same files as one run. */
#ifndef TL_JOB_H
#define TL_JOB_H

#include <stddef.h>

#include "core/tl_error.h"

/* A sorted list of distinct frame numbers. */
typedef struct tl_frame_list {
    long *frames;
    size_t count;
} tl_frame_list;

/* Parses a frame spec against a timeline of `frame_count` frames (valid
 * frames are 0..frame_count-1): comma-separated items, each `N`, `A-B`
 * (inclusive) or `A-B:STEP`, e.g. "1-3,5,7-20:2". Duplicates are merged and
 * the result sorted. NULL or "" selects every frame. Errors (TL_ERR_USAGE)
 * quote the spec and name the item: malformed, reversed (A > B), a step < 1,
 * or a frame outside 0..frame_count-1. `flag` (e.g. "--frames") prefixes
 * messages. */
int tl_frame_list_parse(const char *spec, long frame_count, const char *flag, tl_frame_list *out,
                        tl_error *err);
void tl_frame_list_free(tl_frame_list *list);

/* Parses "INDEX/COUNT" (0 <= INDEX < COUNT, COUNT >= 1) and keeps only
 * chunk INDEX of `list`, split evenly in order: chunk i holds items
 * [floor(i*n/COUNT), floor((i+1)*n/COUNT)). A chunk may be empty when there
 * are fewer frames than chunks. */
int tl_frame_list_chunk(tl_frame_list *list, const char *spec, const char *flag, tl_error *err);

/* Output name patterns (Blender's convention): the last run of '#' in the
 * file name becomes the zero-padded frame number, as wide as the run (wider
 * numbers are not truncated). A pattern without '#' gets "_####" inserted
 * before the extension -- unless `single_frame` is set, in which case the
 * name is used as it is. Fails if the result does not fit `out_size`. */
int tl_pattern_has_frame(const char *pattern);
int tl_pattern_format(const char *pattern, long frame, int single_frame, char *out, size_t out_size,
                      tl_error *err);
/* The lowest and highest frame numbers among the files in the pattern's
 * folder that it names (its '#' run as digits, as tl_pattern_format
 * writes them); fails when the pattern has no '#' or names no file. */
int tl_pattern_scan(const char *pattern, long *first, long *last, tl_error *err);

/* Resuming a run (--skip-existing): 1 when `path` holds a complete,
 * readable frame of width x height and, for an EXR, the run's compositing
 * passes (`passes`: its tideline/passes attribute, tl_passes_format's
 * names; NULL or "" for the plain file) in the run's working space
 * (`space`: its tideline/working_space, "rec709" when a file has none;
 * NULL: "rec709"). A file cut short, of another size, with other passes
 * or in another space is rendered again. */
int tl_job_frame_complete(const char *path, int width, int height, const char *passes,
                          const char *space);
/* A process killed mid-write (SIGKILL, a node lost) leaves its hidden
 * temporary behind: removes those of `frames` (named by `pattern`, in the
 * folder of `first_path`) that no live writer holds, so that a resumed run
 * ends with the files alone. Returns how many were removed. */
int tl_job_remove_stale_temporaries(const char *pattern, const tl_frame_list *frames,
                                    const char *first_path);

#endif
