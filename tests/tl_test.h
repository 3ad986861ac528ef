/* tl_test: a minimal assertion harness. Each test file is one ctest
 * executable; it prints every failed check with file:line and exits
 * non-zero if any check failed. */
#ifndef TL_TEST_H
#define TL_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int tl_test_failures = 0;
static int tl_test_checks = 0;

#define CHECK(cond)                                                                                \
    do {                                                                                           \
        tl_test_checks++;                                                                          \
        if (!(cond)) {                                                                             \
            tl_test_failures++;                                                                    \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);               \
        }                                                                                          \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                                      \
    do {                                                                                           \
        double tl_a_ = (double)(a), tl_b_ = (double)(b), tl_t_ = (double)(tol);                    \
        tl_test_checks++;                                                                          \
        if (!(fabs(tl_a_ - tl_b_) <= tl_t_)) {                                                     \
            tl_test_failures++;                                                                    \
            fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.17g, %s = %.17g, tol %g\n",          \
                    __FILE__, __LINE__, #a, tl_a_, #b, tl_b_, tl_t_);                              \
        }                                                                                          \
    } while (0)

#define CHECK_STR_CONTAINS(haystack, needle)                                                       \
    do {                                                                                           \
        const char *tl_h_ = (haystack), *tl_n_ = (needle);                                         \
        tl_test_checks++;                                                                          \
        if (!tl_h_ || !strstr(tl_h_, tl_n_)) {                                                     \
            tl_test_failures++;                                                                    \
            fprintf(stderr, "%s:%d: expected \"%s\" in \"%s\"\n", __FILE__, __LINE__, tl_n_,       \
                    tl_h_ ? tl_h_ : "(null)");                                                     \
        }                                                                                          \
    } while (0)

#define CHECK_STR_EQ(got, want)                                                                    \
    do {                                                                                           \
        const char *tl_g_ = (got), *tl_w_ = (want);                                                \
        tl_test_checks++;                                                                          \
        if (!tl_g_ || strcmp(tl_g_, tl_w_) != 0) {                                                 \
            tl_test_failures++;                                                                    \
            fprintf(stderr, "%s:%d: expected \"%s\", got \"%s\"\n", __FILE__, __LINE__, tl_w_,     \
                    tl_g_ ? tl_g_ : "(null)");                                                     \
        }                                                                                          \
    } while (0)

/* Writes `text` to `path` (a test's input file); a failure is a failed
 * check. */
static inline void tl_test_write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* Runs a shell command and returns its standard output (NUL-terminated,
 * malloc'd; its length in *len when len is not NULL), or NULL when it
 * could not run or exited non-zero. */
static inline char *tl_test_output(const char *cmd, size_t *len)
{
    FILE *fp = popen(cmd, "r");
    if (!fp)
        return NULL;
    size_t cap = 1 << 16, n = 0, got;
    char *buf = malloc(cap + 1);
    while (buf && (got = fread(buf + n, 1, cap - n, fp)) > 0) {
        n += got;
        if (n == cap) {
            char *more = realloc(buf, 2 * cap + 1);
            if (!more)
                break;
            buf = more;
            cap *= 2;
        }
    }
    int status = pclose(fp);
    if (!buf || status != 0) {
        free(buf);
        return NULL;
    }
    buf[n] = '\0';
    if (len)
        *len = n;
    return buf;
}

/* Ends main(): prints a summary and returns the process status. */
#define TEST_END()                                                                                 \
    do {                                                                                           \
        printf("%d checks, %d failed\n", tl_test_checks, tl_test_failures);                        \
        return tl_test_failures ? 1 : 0;                                                           \
    } while (0)

#endif
