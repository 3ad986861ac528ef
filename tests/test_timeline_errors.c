/* Golden error messages: `tideline check NAME.tl` on every broken timeline
 * in the folder must print exactly NAME.err on stderr and exit 1; files
 * named ok_*.tl are valid (CRLF line endings, a UTF-8 byte-order mark,
 * UTF-8 comments) and must exit 0 with nothing on stderr. The binary runs inside the folder with
 * the bare file name, so the messages do not depend on where the repo lives. argv[1] is the
 * tideline binary, argv[2] the folder. */
#include <dirent.h>
#include <fcntl.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tl_test.h"

#define MAX_FILES  256
#define MIN_BROKEN 20

static const char *binary;
static const char *folder;

static char *read_all_fd(int fd, size_t *len)
{
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap + 1);
    ssize_t got;
    while (buf && (got = read(fd, buf + n, cap - n)) > 0) {
        n += (size_t)got;
        if (n == cap) {
            char *bigger = realloc(buf, 2 * cap + 1);
            if (!bigger) {
                free(buf);
                return NULL;
            }
            buf = bigger;
            cap *= 2;
        }
    }
    if (buf)
        buf[n] = '\0';
    *len = n;
    return buf;
}

static char *read_file(const char *name, size_t *len)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    int fd = open(path, O_RDONLY);
    if (fd < 0)
        return NULL;
    char *text = read_all_fd(fd, len);
    close(fd);
    return text;
}

/* Runs `tideline check NAME` in the folder; returns the exit status and
 * the captured stderr (stdout, the summary of a valid file, is dropped). */
static int run_check(const char *name, char **err_text, size_t *err_len)
{
    int fds[2];
    *err_text = NULL;
    if (pipe(fds) != 0)
        return -1;
    pid_t pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (chdir(folder) != 0 || null < 0)
            _exit(126);
        dup2(null, 1);
        dup2(fds[1], 2);
        close(fds[0]);
        execl(binary, binary, "check", name, (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    *err_text = read_all_fd(fds[0], err_len);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* One line of output with control and non-ASCII bytes made visible. */
static void print_line(const char *prefix, const char *s, size_t len)
{
    fprintf(stderr, "    %s", prefix);
    for (size_t i = 0; i < len && i < 240; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c >= 0x20 && c < 0x7f)
            fputc(c, stderr);
        else
            fprintf(stderr, "\\x%02x", c);
    }
    fprintf(stderr, "%s\n", len > 240 ? "..." : "");
}

/* Next line of [*pos, end): sets *line and *len; false at the end. */
static int next_line(const char **pos, const char *end, const char **line, size_t *len)
{
    if (*pos >= end)
        return 0;
    const char *nl = memchr(*pos, '\n', (size_t)(end - *pos));
    *line = *pos;
    *len = nl ? (size_t)(nl - *pos) : (size_t)(end - *pos);
    *pos = nl ? nl + 1 : end;
    return 1;
}

/* A line-by-line diff: every line that differs, as - expected / + actual. */
static void print_diff(const char *name, const char *want, size_t want_len, const char *got,
                       size_t got_len)
{
    fprintf(stderr, "%s: stderr differs from the golden file (- expected, + actual):\n", name);
    const char *a = want, *b = got;
    const char *a_end = want + want_len, *b_end = got + got_len;
    int shown = 0;
    for (int line = 1; shown < 20; line++) {
        const char *la = NULL, *lb = NULL;
        size_t na = 0, nb = 0;
        int has_a = next_line(&a, a_end, &la, &na);
        int has_b = next_line(&b, b_end, &lb, &nb);
        if (!has_a && !has_b)
            break;
        if (has_a && has_b && na == nb && memcmp(la, lb, na) == 0)
            continue;
        fprintf(stderr, "  line %d:\n", line);
        if (has_a)
            print_line("- ", la, na);
        if (has_b)
            print_line("+ ", lb, nb);
        shown++;
    }
    if ((want_len && want[want_len - 1] != '\n') != (got_len && got[got_len - 1] != '\n'))
        fprintf(stderr, "  (the two differ in the final newline)\n");
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The inputs that must stay byte-exact for their case to mean anything
 * (an editor or a checkout could normalise them). */
static void check_input_bytes(const char *name, const char *text, size_t len)
{
    if (strcmp(name, "ok_crlf.tl") == 0) {
        int crlf = 0;
        for (size_t i = 0; i + 1 < len; i++)
            crlf |= text[i] == '\r' && text[i + 1] == '\n';
        CHECK(crlf);
    } else if (strcmp(name, "ok_utf8_comment.tl") == 0) {
        int high = 0;
        for (size_t i = 0; i < len; i++)
            high |= (unsigned char)text[i] >= 0x80;
        CHECK(high);
    } else if (strcmp(name, "ok_bom.tl") == 0) {
        CHECK(len > 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0);
    } else if (strcmp(name, "utf16.tl") == 0) {
        CHECK(len > 2 && memcmp(text, "\xff\xfe", 2) == 0);
    } else if (strcmp(name, "empty_file.tl") == 0) {
        CHECK(len == 0);
    } else if (strcmp(name, "nul_byte.tl") == 0) {
        CHECK(memchr(text, '\0', len) != NULL);
    } else if (strcmp(name, "long_line.tl") == 0) {
        size_t longest = 0, run = 0;
        for (size_t i = 0; i < len; i++) {
            run = text[i] == '\n' ? 0 : run + 1;
            longest = run > longest ? run : longest;
        }
        CHECK(longest > 4096);
    }
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: test_timeline_errors TIDELINE FOLDER\n");
        return 2;
    }
    /* Absolute, since the child runs inside the folder. */
    static char binary_path[4096];
    if (!realpath(argv[1], binary_path)) {
        fprintf(stderr, "cannot find the tideline binary %s\n", argv[1]);
        return 1;
    }
    binary = binary_path;
    folder = argv[2];

    DIR *d = opendir(folder);
    CHECK(d != NULL);
    if (!d)
        TEST_END();
    char *names[MAX_FILES];
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL && count < MAX_FILES) {
        size_t n = strlen(e->d_name);
        if (n > 3 && strcmp(e->d_name + n - 3, ".tl") == 0)
            names[count++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)count, sizeof names[0], by_name);

    int broken = 0, valid = 0, mismatched = 0;
    for (int i = 0; i < count; i++) {
        const char *name = names[i];
        int expect_ok = strncmp(name, "ok_", 3) == 0;
        broken += !expect_ok;
        valid += expect_ok;

        size_t in_len = 0;
        char *input = read_file(name, &in_len);
        CHECK(input != NULL);
        if (input)
            check_input_bytes(name, input, in_len);
        free(input);

        char golden_name[512];
        snprintf(golden_name, sizeof golden_name, "%.*s.err", (int)strlen(name) - 3, name);
        size_t want_len = 0;
        char *want = read_file(golden_name, &want_len);
        if (!want) {
            fprintf(stderr, "%s: missing golden file %s\n", name, golden_name);
            CHECK(want != NULL);
            continue;
        }
        if (expect_ok)
            CHECK(want_len == 0); /* a valid file prints nothing on stderr */

        char *got = NULL;
        size_t got_len = 0;
        int status = run_check(name, &got, &got_len);
        if (status == 126 || status == 127)
            fprintf(stderr, "%s: could not run %s check in %s\n", name, binary, folder);
        if (status != (expect_ok ? 0 : 1)) {
            fprintf(stderr, "%s: exit status %d, expected %d\n", name, status, expect_ok ? 0 : 1);
            CHECK(status == (expect_ok ? 0 : 1));
        }
        CHECK(got != NULL);
        if (got && (got_len != want_len || memcmp(got, want, want_len) != 0)) {
            print_diff(name, want, want_len, got, got_len);
            mismatched++;
            CHECK(!"stderr matches the golden file");
        }
        free(got);
        free(want);
    }
    printf("%d broken and %d valid timelines, %d golden mismatches\n", broken, valid, mismatched);
    CHECK(broken >= MIN_BROKEN);
    CHECK(valid >= 2);
    for (int i = 0; i < count; i++)
        free(names[i]);
    TEST_END();
}
