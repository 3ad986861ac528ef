/* tl_fixture: expected values a reference script wrote into a checked-in
 * file (tests/fixtures/), one "NAME VALUE" line each, "#" lines and blank
 * lines skipped. The test gets the file's path as an argument; a file that
 * cannot be read, a malformed line or a name it lacks fails the test, so
 * a fixture cut short cannot pass by checking less. Header-only. */
#ifndef TL_FIXTURE_H
#define TL_FIXTURE_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tl_test.h"

#define TL_FIXTURE_MAX 512

static struct {
    char name[112];
    double value;
} tl_fixture_entries[TL_FIXTURE_MAX];
static int tl_fixture_count;

/* Reads `path`; returns the number of values (0 on failure, a failed check). */
static inline int tl_fixture_load(const char *path)
{
    FILE *f = path ? fopen(path, "r") : NULL;
    if (!f)
        fprintf(stderr, "cannot read the fixture %s\n", path ? path : "(none given)");
    CHECK(f != NULL);
    char line[512];
    int number = 0;
    while (f && fgets(line, sizeof line, f)) {
        number++;
        char *p = line + strspn(line, " \t");
        if (*p == '#' || *p == '\n' || *p == '\0')
            continue;
        char name[112], *end = NULL;
        int used = 0;
        int ok = sscanf(p, "%111s %n", name, &used) == 1 && used > 0 &&
                 tl_fixture_count < TL_FIXTURE_MAX;
        double v = ok ? strtod(p + used, &end) : 0.0;
        ok = ok && end != p + used && strspn(end, " \t\r\n") == strlen(end);
        if (!ok)
            fprintf(stderr, "%s:%d: not a NAME VALUE line: %s", path, number, line);
        CHECK(ok);
        if (ok) {
            snprintf(tl_fixture_entries[tl_fixture_count].name, sizeof tl_fixture_entries[0].name,
                     "%s", name);
            tl_fixture_entries[tl_fixture_count++].value = v;
        }
    }
    if (f)
        fclose(f);
    CHECK(tl_fixture_count > 0);
    return tl_fixture_count;
}

/* The value named by the printf-style format; a missing name fails the
 * test and gives NaN, which no CHECK_NEAR accepts. */
static inline double tl_fixture(const char *format, ...)
{
    char name[112];
    va_list ap;
    va_start(ap, format);
    vsnprintf(name, sizeof name, format, ap);
    va_end(ap);
    for (int i = 0; i < tl_fixture_count; i++)
        if (strcmp(tl_fixture_entries[i].name, name) == 0)
            return tl_fixture_entries[i].value;
    fprintf(stderr, "the fixture has no value '%s'\n", name);
    CHECK(0 && "the fixture has the value");
    return NAN;
}

#endif
