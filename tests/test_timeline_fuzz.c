/* Randomised robustness of the timeline parser and evaluator: mutated
 * timelines either parse, and then evaluate to finite in-range values, or
 * fail with 1..20 located diagnostics; pathological inputs (huge lines,
 * huge key counts, nothing at all) end in a clean error. The PRNG has a
 * fixed seed, so every run sees the same inputs. */
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#include "timeline/tl_parse.h"
#include "tl_test.h"

#define ITERATIONS  20000
#define MAX_REPORTS 5 /* failing inputs printed in full */

/* ---- PRNG (splitmix64) and a growable byte buffer ---- */

static uint64_t rng_state = 0x7469646531696e65ull;

static uint64_t rng(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static size_t rnd(size_t n)
{
    return n ? (size_t)(rng() % n) : 0;
}

typedef struct buf {
    char *d;
    size_t n, cap;
} buf;

static void buf_reserve(buf *b, size_t extra)
{
    if (b->n + extra + 1 <= b->cap)
        return;
    size_t cap = b->cap ? b->cap : 256;
    while (cap < b->n + extra + 1)
        cap *= 2;
    char *d = realloc(b->d, cap);
    if (!d) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    b->d = d;
    b->cap = cap;
}

static void buf_insert(buf *b, size_t at, const char *s, size_t len)
{
    buf_reserve(b, len);
    memmove(b->d + at + len, b->d + at, b->n - at);
    memcpy(b->d + at, s, len);
    b->n += len;
}

static void buf_erase(buf *b, size_t at, size_t len)
{
    memmove(b->d + at, b->d + at + len, b->n - at - len);
    b->n -= len;
}

static void buf_append(buf *b, const char *s)
{
    buf_insert(b, b->n, s, strlen(s));
}

/* ---- seeds: valid timelines covering every statement ---- */

static const char *const seeds[] = {
    /* calm.tl */
    "tideline 1\n# A slow sunrise pan.\nfps 24\nduration 10s\nsize 1280x720\nquality final\n\n"
    "set ocean.drag 0.3\nset ocean.depth 0.8\nset render.exposure 2.2\n\n"
    "key sun.elevation\n  0s    2deg\n  10s   9deg    ease-in-out-sine\n\n"
    "set sun.azimuth -10deg\n\nkey camera.position\n  0s    0 1.8 0\n  10s   0 2.1 6\n\n"
    "key camera.yaw shortest\n  0s    -35deg\n  10s   -8deg\n\n"
    "key camera.pitch\n  0s    -4deg\n  10s   -2deg\n",
    /* Every statement and key option. */
    "tideline 1\nfps 30\nduration 12s\nsize 640x360\nquality preview\n"
    "set ocean.drag 0.3\nset quality.march_steps 80\nset fog.color 0.5 0.6 0.7\n"
    "key sun.elevation linear extrapolate ping-pong\n"
    "  0s 5deg ease-out-quad\n  6s 12deg\n  12s 8deg\n"
    "key camera.fov bezier\n  0s 60deg auto\n  2s 35deg right 1s 0 left -0.5s 0\n"
    "  4s 50deg aligned\n  150f 40deg vector\n"
    "key giant.fade spline extrapolate cycle\n  0 0\n  3 1\n  6 0.5\n"
    "key giant.enabled\n  0s off\n  2s on\n"
    "key underwater.mode\n  0s auto\n  5s off\n"
    "key fog.density linear\n  0s 0\n  6s 0.01 ease-in-out-elastic\n  12s 0\n"
    "key camera.roll shortest\n  0s 0\n  5s cut 10deg\n  10s 350deg step\n  10s 20deg\n"
    "key giant.phase linear extrapolate cycle-offset\n  0s 0rad\n  1500ms 3.14rad\n"
    "path boat constant-speed\n  0s 0 0    # TIME X Z\n  8s 20 30\n  12s 0 48m\n"
    "look camera at boat + 0 1.5 0\nfollow camera boat + 0 3 -12\n"
    "follow giant.center boat + 0 20\n",
    /* A camera path and a fixed look-at point. */
    "tideline 1\nfps 24\nduration 8s\n"
    "path camera\n  0s 0 2 0\n  3s 5 3 10\n  8s 0 2.5 20\n"
    "look camera at 0 0 100\n"
    "key boat.size linear\n  0s 8\n  8s 12\n"
    "key ocean.depth step\n  0s 1\n  4s 2\n"
    "key water.absorption linear extrapolate linear\n  0s 0.3 0.05 0.01\n  8s 0.4 0.06 0.02\n"
    "set giant.enabled on\nset underwater.mode on\n",
    /* Following a boat on a timed path, aim keyed by hand. */
    "tideline 1\r\nduration 6s\r\npath boat\r\n  0s 5 5\r\n  2s 6 20\r\n  6s -10 40\r\n"
    "follow camera boat + 0 4 -15\r\n"
    "key camera.yaw shortest\r\n  0s 170deg\r\n  6s -170deg\r\n"
    "key camera.pitch\r\n\t0s -10deg\r\n\t6s 5deg\r\n"
    "key giant.center linear\r\n  0s 0 0\r\n  6s 10 100\r\n"
    "set camera.roll 2deg # \xc3\xa9\xc2\xa0\r\n",
};
#define SEED_COUNT (sizeof seeds / sizeof seeds[0])

static const char *const words[] = {
    "tideline",
    "fps",
    "duration",
    "size",
    "quality",
    "set",
    "key",
    "path",
    "look",
    "follow",
    "camera",
    "boat",
    "at",
    "+",
    "giant.center",
    "cut",
    "constant",
    "step",
    "linear",
    "bezier",
    "spline",
    "ease",
    "auto-clamped",
    "auto",
    "vector",
    "aligned",
    "free",
    "left",
    "right",
    "ease-in-sine",
    "ease-out-back",
    "ease-in-out-elastic",
    "ease-out-bounce",
    "ease-in-expo",
    "extrapolate",
    "cycle",
    "cycle-offset",
    "ping-pong",
    "shortest",
    "constant-speed",
    "on",
    "off",
    "auto",
    "draft",
    "final",
    "reference",
    "seed",
    "1280x720",
    "1x1",
    "16384x16384",
    "0x0",
    "#",
    "##",
    "\t",
    "  ",
    "x",
    "-",
    "--",
    ".",
    "e",
    "deg",
    "rad",
    "ms",
    "s",
    "f",
    "m",
    "passes",
    "working_space",
    "all",
    "none",
    "masks",
    "depth,vector",
    "cryptomatte,",
    "rec709",
    "acescg",
};
#define WORD_COUNT (sizeof words / sizeof words[0])

static const char *const numbers[] = {
    "0",
    "-0",
    "1",
    "-1",
    "0.5",
    "1e308",
    "-1e308",
    "1e309",
    "1e-320",
    "5e-324",
    "nan",
    "-nan",
    "inf",
    "-inf",
    "infinity",
    "NaN",
    "1e9",
    "-1e9",
    "1e9m",
    "1000000001",
    "1e7s",
    "1e9s",
    "2e10s",
    "1e6s",
    "1000000.000001s",
    "-5s",
    "36f",
    "1e30f",
    "1500ms",
    "90deg",
    "-720deg",
    "1e12rad",
    "3.14159rad",
    "4294967296",
    "-2147483649",
    "9223372036854775808",
    "1e-9",
    "0x1p4",
    "1.",
    ".5",
    "+2",
    "1e",
    "e5",
    "--1",
    "1..2",
    "12345678901234567890123456789",
};
#define NUMBER_COUNT (sizeof numbers / sizeof numbers[0])

/* ---- mutations ---- */

/* Start and length of a random line (without its newline). */
static void pick_line(const buf *b, size_t *start, size_t *len)
{
    size_t at = rnd(b->n + 1);
    size_t s = at;
    while (s > 0 && b->d[s - 1] != '\n')
        s--;
    size_t e = at;
    while (e < b->n && b->d[e] != '\n')
        e++;
    *start = s;
    *len = e - s;
}

static void random_number(char *out, size_t size)
{
    static const char *const units[] = {"", "", "", "s", "ms", "f", "deg", "rad", "m", "x"};
    switch (rnd(3)) {
    case 0: snprintf(out, size, "%s", numbers[rnd(NUMBER_COUNT)]); break;
    case 1: {
        double mant = (double)(int64_t)(rng() % 2000001) / 1000.0 - 1000.0;
        int exp = (int)rnd(80) - 40;
        snprintf(out, size, "%.*ge%d%s", (int)rnd(17) + 1, mant, exp, units[rnd(10)]);
        break;
    }
    default: snprintf(out, size, "%d%s", (int)rnd(200) - 20, units[rnd(10)]); break;
    }
}

/* Replaces one number of the text with a random one: mostly still valid,
 * so evaluation sees extreme values. */
static void mutate_number(buf *b)
{
    size_t starts[512], n = 0;
    for (size_t i = 0; i < b->n && n < 512; i++) {
        char c = b->d[i], prev = i ? b->d[i - 1] : ' ';
        if ((prev == ' ' || prev == '\t') &&
            ((c >= '0' && c <= '9') ||
             (c == '-' && i + 1 < b->n && b->d[i + 1] >= '0' && b->d[i + 1] <= '9')))
            starts[n++] = i;
    }
    if (!n)
        return;
    size_t a = starts[rnd(n)], e = a;
    while (e < b->n && b->d[e] != ' ' && b->d[e] != '\t' && b->d[e] != '\n' && b->d[e] != '\r')
        e++;
    char tmp[96];
    random_number(tmp, sizeof tmp);
    buf_erase(b, a, e - a);
    buf_insert(b, a, tmp, strlen(tmp));
}

static void mutate(buf *b)
{
    char tmp[96];
    size_t s, len;
    switch (rnd(12)) {
    case 0: /* flip a bit */
        if (b->n)
            b->d[rnd(b->n)] ^= (char)(1u << rnd(8));
        break;
    case 1: /* set a byte to a printable one */
        if (b->n)
            b->d[rnd(b->n)] = (char)(0x20 + rnd(0x5f));
        break;
    case 2: /* delete a line */
        pick_line(b, &s, &len);
        buf_erase(b, s, len + (s + len < b->n));
        break;
    case 3: { /* duplicate a line (copied out: inserting may move the buffer) */
        pick_line(b, &s, &len);
        char *copy = malloc(len + 1);
        if (copy) {
            memcpy(copy, b->d + s, len);
            copy[len] = '\n';
            buf_insert(b, s, copy, len + 1);
        }
        free(copy);
        break;
    }
    case 4: { /* swap two lines */
        size_t s2, len2;
        pick_line(b, &s, &len);
        pick_line(b, &s2, &len2);
        if (s == s2)
            break;
        if (s > s2) {
            size_t t = s;
            s = s2;
            s2 = t;
            t = len;
            len = len2;
            len2 = t;
        }
        char *first = malloc(len + 1), *second = malloc(len2 + 1);
        if (first && second) {
            memcpy(first, b->d + s, len);
            memcpy(second, b->d + s2, len2);
            buf_erase(b, s2, len2);
            buf_insert(b, s2, first, len);
            buf_erase(b, s, len);
            buf_insert(b, s, second, len2);
        }
        free(first);
        free(second);
        break;
    }
    case 5: /* insert a word of the language */
        snprintf(tmp, sizeof tmp, "%s%s ", rnd(2) ? " " : "", words[rnd(WORD_COUNT)]);
        buf_insert(b, rnd(b->n + 1), tmp, strlen(tmp));
        break;
    case 6: /* insert a number */
        tmp[0] = ' ';
        random_number(tmp + 1, sizeof tmp - 2);
        strcat(tmp, " ");
        buf_insert(b, rnd(b->n + 1), tmp, strlen(tmp));
        break;
    case 7: { /* replace a word with a word or a number */
        pick_line(b, &s, &len);
        size_t a = s + rnd(len + 1), e = a;
        while (a > s && b->d[a - 1] != ' ')
            a--;
        while (e < s + len && b->d[e] != ' ')
            e++;
        if (rnd(2))
            random_number(tmp, sizeof tmp);
        else
            snprintf(tmp, sizeof tmp, "%s", words[rnd(WORD_COUNT)]);
        buf_erase(b, a, e - a);
        buf_insert(b, a, tmp, strlen(tmp));
        break;
    }
    case 8: /* truncate */ b->n = rnd(b->n + 1); break;
    case 9: { /* binary bytes, NUL and CR included */
        size_t count = 1 + rnd(8);
        for (size_t i = 0; i < count; i++) {
            static const char special[] = {'\0', '\r', '\t', '\x7f', '\xff', '\x80', '\x1b'};
            tmp[i] = rnd(2) ? special[rnd(sizeof special)] : (char)rng();
        }
        buf_insert(b, rnd(b->n + 1), tmp, count);
        break;
    }
    case 10: /* change indentation */
        pick_line(b, &s, &len);
        if (len && (b->d[s] == ' ' || b->d[s] == '\t') && rnd(2)) {
            while (len && (b->d[s] == ' ' || b->d[s] == '\t')) {
                buf_erase(b, s, 1);
                len--;
            }
        } else {
            static const char *const indents[] = {" ", "  ", "\t", " \t", "        "};
            const char *in = indents[rnd(5)];
            buf_insert(b, s, in, strlen(in));
        }
        break;
    default: /* line endings: CRLF or none */
        pick_line(b, &s, &len);
        if (s + len < b->n)
            buf_insert(b, s + len, "\r", 1);
        else
            buf_erase(b, s, len);
        break;
    }
}

/* ---- checks ---- */

static int failures = 0;

/* The reason for every failing input; the input itself for the first few. */
static void report_input(const char *why, const char *text, size_t len)
{
    if (failures++ >= MAX_REPORTS) {
        if (failures <= 50)
            fprintf(stderr, "--- %s\n", why);
        return;
    }
    fprintf(stderr, "--- %s; input (%zu bytes):\n", why, len);
    for (size_t i = 0; i < len && i < 3000; i++) {
        unsigned char c = (unsigned char)text[i];
        if (c == '\n' || (c >= 0x20 && c < 0x7f))
            fputc(c, stderr);
        else
            fprintf(stderr, "\\x%02x", c);
    }
    fprintf(stderr, "\n---\n");
}

/* Every channel finite and inside its range; the camera basis finite. */
static int scene_ok(const tl_scene *s, char *why, size_t size)
{
    for (int i = 0; i < tl_channel_count(); i++) {
        const tl_channel *ch = tl_channel_at(i);
        double v[3];
        tl_channel_get(ch, s, v);
        for (int c = 0; c < ch->components; c++)
            if (!isfinite(v[c]) || v[c] < ch->min || v[c] > ch->max) {
                snprintf(why, size, "t=%.17g: %s[%d] = %.17g outside %g..%g", s->time, ch->name, c,
                         v[c], ch->min, ch->max);
                return 0;
            }
    }
    double r[3], u[3], f[3];
    tl_scene_camera_basis(&s->camera, r, u, f);
    for (int k = 0; k < 3; k++)
        if (!isfinite(r[k]) || !isfinite(u[k]) || !isfinite(f[k]) ||
            !isfinite(s->boat.position[k])) {
            snprintf(why, size, "t=%.17g: camera basis or boat position not finite", s->time);
            return 0;
        }
    return 1;
}

static int diags_ok(const tl_diags *d, char *why, size_t size)
{
    if (d->count < 1 || d->count > TL_PARSE_MAX_ERRORS) {
        snprintf(why, size, "failed with %d diagnostics", d->count);
        return 0;
    }
    for (int i = 0; i < d->count; i++)
        if (d->items[i].line < 1 || d->items[i].message[0] == '\0') {
            snprintf(why, size, "diagnostic %d: line %d, message '%s'", i, d->items[i].line,
                     d->items[i].message);
            return 0;
        }
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) {
        snprintf(why, size, "open_memstream failed");
        return 0;
    }
    tl_diags_write(d, f);
    int closed = fclose(f);
    int ok = closed == 0 && len > 0 && text && strlen(text) == len;
    if (!ok)
        snprintf(why, size, "tl_diags_write: fclose %d, %zu bytes", closed, len);
    free(text);
    return ok;
}

/* Parses and checks one input; returns the parser's status. */
static int check_input(const char *text, size_t len, tl_diags *diags)
{
    tl_timeline tl;
    tl_error err;
    tl_error_clear(&err);
    char why[512] = "";
    int rc = tl_timeline_parse_text("fuzz.tl", text, len, &tl, diags, &err);
    int ok;
    if (rc == 0) {
        /* A valid file may carry warnings, never errors. */
        ok = diags->errors == 0;
        for (int i = 0; ok && i < diags->count; i++)
            ok = diags->items[i].warning;
        if (!ok)
            snprintf(why, sizeof why, "parsed, yet %d errors", diags->errors);
        double times[] = {0.0, tl.duration,       -5.0,
                          1e6, tl.duration * 0.5, tl.duration * (double)rnd(1000) / 1000.0};
        for (size_t i = 0; ok && i < sizeof times / sizeof times[0]; i++) {
            tl_scene s;
            tl_timeline_eval(&tl, times[i], &s);
            ok = scene_ok(&s, why, sizeof why);
        }
        tl_timeline_free(&tl);
    } else {
        ok = diags_ok(diags, why, sizeof why);
    }
    if (!ok)
        report_input(why, text, len);
    return rc;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void test_seeds_valid(void)
{
    for (size_t i = 0; i < SEED_COUNT; i++) {
        tl_diags d;
        int rc = check_input(seeds[i], strlen(seeds[i]), &d);
        CHECK(rc == 0);
        if (rc != 0)
            tl_diags_write(&d, stderr);
    }
}

static void test_mutations(void)
{
    buf b = {0};
    int parsed = 0;
    for (int it = 0; it < ITERATIONS; it++) {
        b.n = 0;
        buf_append(&b, seeds[rnd(SEED_COUNT)]);
        int count = 1 + (int)rnd(4);
        int numbers_only = rnd(3) == 0;
        for (int m = 0; m < count; m++) {
            if (numbers_only)
                mutate_number(&b);
            else
                mutate(&b);
        }
        tl_diags d;
        parsed += check_input(b.d, b.n, &d) == 0;
    }
    free(b.d);
    printf("%d mutations, %d still valid\n", ITERATIONS, parsed);
    /* Both outcomes must be exercised for the run to mean anything. */
    CHECK(parsed > ITERATIONS / 50);
    CHECK(parsed < ITERATIONS - ITERATIONS / 50);
}

static int has_message(const tl_diags *d, const char *needle)
{
    for (int i = 0; i < d->count; i++)
        if (strstr(d->items[i].message, needle))
            return 1;
    return 0;
}

static void test_pathological(void)
{
    tl_diags d;
    buf b = {0};

    /* A 1,000,000-character line: a statement, then a comment, then the
     * last line of the file without a newline. */
    const char *prefixes[] = {"tideline 1\nset render.exposure 2 ", "tideline 1\n# ",
                              "tideline 1\nkey render.exposure\n  0s 1"};
    for (int k = 0; k < 3; k++) {
        b.n = 0;
        buf_append(&b, prefixes[k]);
        buf_reserve(&b, 1000000);
        memset(b.d + b.n, k == 2 ? ' ' : 'x', 1000000);
        b.n += 1000000;
        if (k < 2)
            buf_append(&b, "\nset render.exposure 2\n");
        CHECK(check_input(b.d, b.n, &d) != 0);
        CHECK(has_message(&d, "longer than 4096"));
    }

    /* 300,000 keys of one channel: stops at the key limit. */
    b.n = 0;
    buf_append(&b, "tideline 1\nkey render.exposure linear\n");
    for (int i = 0; i < 300000; i++) {
        char line[64];
        snprintf(line, sizeof line, "  %dms %d\n", i, i % 7);
        buf_append(&b, line);
    }
    CHECK(check_input(b.d, b.n, &d) != 0);
    CHECK(has_message(&d, "more than 200000 keys"));
    CHECK(d.count == 1);

    /* 100,000 repeated `key` statements, flush and ever deeper indented. */
    for (int k = 0; k < 2; k++) {
        b.n = 0;
        buf_append(&b, "tideline 1\n");
        for (int i = 0; i < 100000; i++) {
            char line[128];
            snprintf(line, sizeof line, "%*skey camera.yaw shortest\n", k ? i % 60 : 0, "");
            buf_append(&b, line);
        }
        CHECK(check_input(b.d, b.n, &d) != 0);
        CHECK(d.count == TL_PARSE_MAX_ERRORS);
        CHECK(d.more >= 1);
    }

    /* Nothing to read: each says where a timeline starts. */
    const char *empty[] = {"", " ", "   \n\t\n \r\n\n", "# only\n# comments\n", "#", "\n\n\n"};
    for (size_t k = 0; k < sizeof empty / sizeof empty[0]; k++) {
        CHECK(check_input(empty[k], strlen(empty[k]), &d) != 0);
        CHECK(d.count == 1 && d.items[0].line == 1);
        CHECK(has_message(&d, "tideline 1"));
    }

    /* No newline at the end of the file. */
    const char *last = "tideline 1\nkey render.exposure linear\n  0s 1\n  2s 3";
    tl_timeline tl;
    tl_error err;
    CHECK(tl_timeline_parse_text("eof.tl", last, strlen(last), &tl, &d, &err) == 0);
    if (d.count == 0) {
        tl_scene s;
        tl_timeline_eval(&tl, 2.0, &s);
        CHECK(s.exposure == 3.0);
        tl_timeline_free(&tl);
    }

    /* A NUL inside the given length is a bad byte, not the end of text. */
    static const char nul[] = "tideline 1\nset render.exposure 2\0\nset bogus 1\n";
    CHECK(check_input(nul, sizeof nul - 1, &d) != 0);
    CHECK(d.count == 2);
    free(b.d);
}

int main(void)
{
    double t0 = now();
    test_seeds_valid();
    test_mutations();
    double t1 = now();
    test_pathological();
    double t2 = now();
    printf("mutations %.2f s, pathological inputs %.2f s\n", t1 - t0, t2 - t1);
    if (failures)
        fprintf(stderr, "%d inputs broke the contract (reasons above)\n", failures);
    CHECK(failures == 0);
    TEST_END();
}
