#include "job/tl_job.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The most frames one run selects. Keeps memory bounded (80 MB of frame
 * numbers) however long the timeline is; at 24 fps it is over 100 hours. */
#define TL_FRAMES_MAX 10000000L

/* One item of a spec as a progression first, first+step, ..., last, with
 * `last` on the progression. */
typedef struct span {
    long first;
    long last;
    long step;
} span;

/* A number as typed: its text (for messages) and its value, saturated at
 * LONG_MAX when it overflows. */
typedef struct number {
    const char *text;
    int len;
    long value;
} number;

/* The part of a spec an error is about, for messages. */
typedef struct where {
    const char *flag;
    const char *spec;
    const char *item;
    int item_len;
} where;

static const char *skip_space(const char *s, const char *end)
{
    while (s < end && isspace((unsigned char)*s))
        s++;
    return s;
}

/* Reads unsigned decimal digits (no sign: frames are never negative).
 * Returns 0 when there are none. */
static int parse_number(const char **s, const char *end, number *n)
{
    const char *p = skip_space(*s, end);
    n->text = p;
    n->value = 0;
    while (p < end && *p >= '0' && *p <= '9') {
        int d = *p - '0';
        n->value = n->value > (LONG_MAX - d) / 10 ? LONG_MAX : n->value * 10 + d;
        p++;
    }
    n->len = (int)(p - n->text);
    *s = skip_space(p, end);
    return n->len > 0;
}

/* " in 'SPEC'" when the item is only part of the spec (there are commas),
 * else "". */
static const char *in_spec(const where *w, char *buf, size_t size)
{
    if (!strchr(w->spec, ','))
        return "";
    snprintf(buf, size, " in '%s'", w->spec);
    return buf;
}

static int out_of_range(const where *w, const number *n, long frame_count, tl_error *err)
{
    char range[64];
    if (frame_count > 0)
        snprintf(range, sizeof range, "the timeline's frames 0-%ld", frame_count - 1);
    else
        snprintf(range, sizeof range, "the timeline, which has no frames");
    /* Name the item and the spec only when they say more than the number. */
    char ctx[TL_ERROR_MSG_MAX];
    int item_is_spec = !strchr(w->spec, ',');
    if (n->len == w->item_len && item_is_spec)
        ctx[0] = '\0';
    else if (item_is_spec)
        snprintf(ctx, sizeof ctx, " (in '%.*s')", w->item_len, w->item);
    else if (n->len == w->item_len)
        snprintf(ctx, sizeof ctx, " (in '%s')", w->spec);
    else
        snprintf(ctx, sizeof ctx, " (item '%.*s' of '%s')", w->item_len, w->item, w->spec);
    return tl_error_set(err, TL_ERR_USAGE, "%s: frame %.*s is outside %s%s", w->flag, n->len,
                        n->text, range, ctx);
}

/* Parses one item (already trimmed, not empty) into a normalised span. */
static int parse_item(const where *w, long frame_count, span *out, tl_error *err)
{
    const char *p = w->item, *end = w->item + w->item_len;
    char ctx[TL_ERROR_MSG_MAX];
    number a, b, step = {NULL, 0, 1};
    int ok = parse_number(&p, end, &a);
    b = a;
    if (ok && p < end && *p == '-') {
        p++;
        ok = parse_number(&p, end, &b);
        if (ok && p < end && *p == ':') {
            p++;
            ok = parse_number(&p, end, &step);
        }
    }
    if (!ok || p != end)
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: '%.*s'%s is not N, A-B or A-B:STEP (frame numbers are whole "
                            "numbers from 0)",
                            w->flag, w->item_len, w->item, in_spec(w, ctx, sizeof ctx));
    if (step.value < 1)
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: '%.*s'%s has a step of %.*s; it must be 1 or more", w->flag,
                            w->item_len, w->item, in_spec(w, ctx, sizeof ctx), step.len, step.text);
    if (a.value >= frame_count)
        return out_of_range(w, &a, frame_count, err);
    if (b.value >= frame_count)
        return out_of_range(w, &b, frame_count, err);
    if (a.value > b.value)
        return tl_error_set(err, TL_ERR_USAGE, "%s: '%.*s'%s is reversed (%ld > %ld)", w->flag,
                            w->item_len, w->item, in_spec(w, ctx, sizeof ctx), a.value, b.value);
    long count = (b.value - a.value) / step.value + 1;
    if (count > TL_FRAMES_MAX)
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: '%.*s'%s selects %ld frames, more than the %ld one run renders; "
                            "split it into several runs",
                            w->flag, w->item_len, w->item, in_spec(w, ctx, sizeof ctx), count,
                            TL_FRAMES_MAX);
    out->first = a.value;
    out->last = a.value + (count - 1) * step.value;
    /* A single frame fits any step; step 1 lets it merge with plain ranges. */
    out->step = count == 1 ? 1 : step.value;
    return TL_OK;
}

static int span_order(const void *pa, const void *pb)
{
    const span *a = pa, *b = pb;
    if (a->step != b->step)
        return a->step < b->step ? -1 : 1;
    long ra = a->first % a->step, rb = b->first % b->step;
    if (ra != rb)
        return ra < rb ? -1 : 1;
    return (a->first > b->first) - (a->first < b->first);
}

/* Merges spans on the same progression (same step and remainder) that
 * overlap or touch, so that "0-99,0-99,..." costs no more than "0-99"
 * below. Returns the new count. */
static size_t merge_spans(span *s, size_t n)
{
    if (n == 0)
        return 0;
    qsort(s, n, sizeof *s, span_order);
    size_t k = 0;
    for (size_t i = 1; i < n; i++) {
        span *cur = &s[k];
        if (s[i].step == cur->step && s[i].first % s[i].step == cur->first % cur->step &&
            s[i].first - s[i].step <= cur->last) {
            if (s[i].last > cur->last)
                cur->last = s[i].last;
        } else {
            s[++k] = s[i];
        }
    }
    return k + 1;
}

/* A binary min-heap of spans keyed on `first` (the next frame each gives). */
static void heap_down(span *h, size_t n, size_t i)
{
    for (;;) {
        size_t l = 2 * i + 1, r = l + 1, m = i;
        if (l < n && h[l].first < h[m].first)
            m = l;
        if (r < n && h[r].first < h[m].first)
            m = r;
        if (m == i)
            return;
        span t = h[i];
        h[i] = h[m];
        h[m] = t;
        i = m;
    }
}

/* Writes the sorted union of the spans into `out` (room for `cap`).
 * Returns the count, or cap + 1 when the union holds more than cap. */
static size_t union_spans(span *h, size_t n, long *out, size_t cap)
{
    for (size_t i = n; i-- > 0;)
        heap_down(h, n, i);
    size_t count = 0;
    while (n > 0) {
        long f = h[0].first;
        if (count == 0 || out[count - 1] != f) {
            if (count == cap)
                return cap + 1;
            out[count++] = f;
        }
        if (h[0].first < h[0].last)
            h[0].first += h[0].step;
        else
            h[0] = h[--n];
        heap_down(h, n, 0);
    }
    return count;
}

static int parse_items(const char *spec, long frame_count, const char *flag, tl_frame_list *out,
                       tl_error *err)
{
    size_t items = 1;
    for (const char *c = spec; *c; c++)
        items += *c == ',';
    span *spans = malloc(items * sizeof *spans);
    if (!spans)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", flag);

    size_t n = 0;
    const char *p = spec;
    for (;;) {
        const char *comma = strchr(p, ',');
        const char *end = comma ? comma : p + strlen(p);
        const char *b = skip_space(p, end), *e = end;
        while (e > b && isspace((unsigned char)e[-1]))
            e--;
        if (b == e) {
            free(spans);
            return tl_error_set(err, TL_ERR_USAGE, "%s: empty item in '%s' (between commas)", flag,
                                spec);
        }
        where w = {flag, spec, b, (int)(e - b)};
        if (parse_item(&w, frame_count, &spans[n], err)) {
            free(spans);
            return TL_ERR_USAGE;
        }
        n++;
        if (!comma)
            break;
        p = comma + 1;
    }

    n = merge_spans(spans, n);
    size_t total = 0;
    for (size_t i = 0; i < n; i++) {
        total += (size_t)((spans[i].last - spans[i].first) / spans[i].step + 1);
        if (total > (size_t)TL_FRAMES_MAX) {
            total = (size_t)TL_FRAMES_MAX;
            break;
        }
    }
    long *frames = malloc(total * sizeof *frames);
    if (!frames) {
        free(spans);
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", flag);
    }
    size_t count = union_spans(spans, n, frames, total);
    free(spans);
    if (count > total) {
        free(frames);
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: '%s' selects more than the %ld frames one run renders; split "
                            "it into several runs",
                            flag, spec, TL_FRAMES_MAX);
    }
    out->frames = frames;
    out->count = count;
    return TL_OK;
}

int tl_frame_list_parse(const char *spec, long frame_count, const char *flag, tl_frame_list *out,
                        tl_error *err)
{
    out->frames = NULL;
    out->count = 0;
    if (!flag)
        flag = "frames";
    if (spec && *skip_space(spec, spec + strlen(spec)) != '\0')
        return parse_items(spec, frame_count, flag, out, err);

    /* No spec: the whole timeline. */
    if (frame_count <= 0)
        return TL_OK;
    if (frame_count > TL_FRAMES_MAX)
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: the timeline has %ld frames, more than the %ld one run "
                            "renders; pick a part of it",
                            flag, frame_count, TL_FRAMES_MAX);
    out->frames = malloc((size_t)frame_count * sizeof *out->frames);
    if (!out->frames)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", flag);
    for (long i = 0; i < frame_count; i++)
        out->frames[i] = i;
    out->count = (size_t)frame_count;
    return TL_OK;
}

void tl_frame_list_free(tl_frame_list *list)
{
    if (!list)
        return;
    free(list->frames);
    list->frames = NULL;
    list->count = 0;
}

/* floor(a * b / c) for 0 <= a < c without overflow: long multiplication one
 * bit of b at a time, keeping the remainder below c. */
static uint64_t mul_div(uint64_t a, uint64_t b, uint64_t c)
{
    uint64_t q = 0, r = 0;
    for (int bit = 63; bit >= 0; bit--) {
        q <<= 1;
        r <<= 1; /* r < c <= 2^63, so no overflow */
        if (r >= c) {
            r -= c;
            q++;
        }
        if ((b >> bit) & 1) {
            r += a;
            if (r >= c) {
                r -= c;
                q++;
            }
        }
    }
    return q;
}

int tl_frame_list_chunk(tl_frame_list *list, const char *spec, const char *flag, tl_error *err)
{
    if (!flag)
        flag = "chunk";
    const char *s = spec ? spec : "";
    const char *p = s, *end = s + strlen(s);
    number index, count;
    int ok = parse_number(&p, end, &index) && p < end && *p == '/';
    if (ok) {
        p++;
        ok = parse_number(&p, end, &count) && p == end && count.value < LONG_MAX &&
             index.value < count.value;
    }
    if (!ok)
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: expected INDEX/COUNT with 0 <= INDEX < COUNT, got '%s'", flag, s);

    uint64_t n = list->count, i = (uint64_t)index.value, c = (uint64_t)count.value;
    size_t lo = (size_t)mul_div(i, n, c);
    size_t hi = i + 1 == c ? (size_t)n : (size_t)mul_div(i + 1, n, c);
    if (lo > 0 && hi > lo)
        memmove(list->frames, list->frames + lo, (hi - lo) * sizeof *list->frames);
    list->count = hi - lo;
    return TL_OK;
}

static const char *file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

int tl_pattern_has_frame(const char *pattern)
{
    return pattern && strchr(file_name(pattern), '#') != NULL;
}

int tl_pattern_format(const char *pattern, long frame, int single_frame, char *out, size_t out_size,
                      tl_error *err)
{
    if (!pattern || !out || out_size == 0)
        return tl_error_set(err, TL_ERR_USAGE, "no output name to format");
    const char *name = file_name(pattern);
    const char *run_end = NULL; /* one past the last '#' of the file name */
    for (const char *c = name; *c; c++)
        if (*c == '#')
            run_end = c + 1;

    int n;
    if (run_end) {
        const char *run = run_end;
        while (run > name && run[-1] == '#')
            run--;
        n = snprintf(out, out_size, "%.*s%0*ld%s", (int)(run - pattern), pattern,
                     (int)(run_end - run), frame, run_end);
    } else if (single_frame) {
        n = snprintf(out, out_size, "%s", pattern);
    } else {
        /* "name.exr" -> "name_0007.exr"; a leading dot is not an extension. */
        const char *dot = strrchr(name, '.');
        if (!dot || dot == name)
            dot = name + strlen(name);
        n = snprintf(out, out_size, "%.*s_%04ld%s", (int)(dot - pattern), pattern, frame, dot);
    }
    if (n < 0 || (size_t)n >= out_size) {
        out[0] = '\0';
        return tl_error_set(err, TL_ERR_USAGE,
                            "output name for frame %ld from '%s' is longer than %zu bytes", frame,
                            pattern, out_size - 1);
    }
    return TL_OK;
}

int tl_pattern_scan(const char *pattern, long *first, long *last, tl_error *err)
{
    if (!tl_pattern_has_frame(pattern))
        return tl_error_set(err, TL_ERR_USAGE,
                            "'%s' has no '#' for the frame number (e.g. out/shot_####.png)",
                            pattern ? pattern : "");
    const char *name = file_name(pattern);
    const char *run_end = NULL;
    for (const char *c = name; *c; c++)
        if (*c == '#')
            run_end = c + 1;
    const char *run = run_end;
    while (run > name && run[-1] == '#')
        run--;
    size_t prefix = (size_t)(run - name), width = (size_t)(run_end - run);
    size_t suffix = strlen(run_end);
    char dir[4096];
    if (name == pattern)
        snprintf(dir, sizeof dir, ".");
    else if (snprintf(dir, sizeof dir, "%.*s", (int)(name - pattern), pattern) >= (int)sizeof dir)
        return tl_error_set(err, TL_ERR_USAGE, "'%s': path too long", pattern);
    DIR *d = opendir(dir);
    if (!d)
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s': cannot read the folder '%s': %s", pattern,
                            dir, strerror(errno));
    long lo = LONG_MAX, hi = -1;
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        const char *f = e->d_name;
        size_t len = strlen(f);
        /* prefix, at least `width` digits, suffix: what tl_pattern_format writes */
        if (len < prefix + width + suffix || strncmp(f, name, prefix) != 0 ||
            strcmp(f + len - suffix, run_end) != 0)
            continue;
        size_t digits = len - prefix - suffix;
        if (digits > 18)
            continue;
        long v = 0;
        size_t i = 0;
        for (; i < digits && f[prefix + i] >= '0' && f[prefix + i] <= '9'; i++)
            v = v * 10 + (f[prefix + i] - '0');
        /* A wider number never starts with 0 (the run pads, it does not cut). */
        if (i != digits || (digits > width && f[prefix] == '0'))
            continue;
        lo = v < lo ? v : lo;
        hi = v > hi ? v : hi;
    }
    closedir(d);
    if (hi < 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "no frames match '%s'", pattern);
    *first = lo;
    *last = hi;
    return TL_OK;
}
