/* tl_run: run the tideline binary from a test and capture what it prints.
 * Header-only: each test executable includes it once. */
#ifndef TL_RUN_H
#define TL_RUN_H

#include <dirent.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct tl_run_opts {
    const char *env;      /* "NAME=VALUE" added to the environment, or NULL */
    long file_size_limit; /* RLIMIT_FSIZE in bytes (SIGXFSZ ignored), or 0 */
} tl_run_opts;

static const char *tl_run_binary;
static char tl_run_output[65536];

/* Runs tl_run_binary with the NULL-terminated arguments; returns the exit
 * status (128 + signal when killed) and leaves stdout+stderr in
 * tl_run_output. */
static inline int tl_run_argv(const tl_run_opts *opts, const char *const *args)
{
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], 1);
        dup2(fds[1], 2);
        close(fds[0]);
        if (opts && opts->env)
            putenv((char *)opts->env);
        if (opts && opts->file_size_limit > 0) {
            signal(SIGXFSZ, SIG_IGN); /* writes then fail with EFBIG, like a full disk */
            struct rlimit rl = {(rlim_t)opts->file_size_limit, (rlim_t)opts->file_size_limit};
            setrlimit(RLIMIT_FSIZE, &rl);
        }
        execv(tl_run_binary, (char *const *)args);
        _exit(127);
    }
    close(fds[1]);
    size_t len = 0;
    ssize_t got;
    while ((got = read(fds[0], tl_run_output + len, sizeof tl_run_output - 1 - len)) > 0)
        len += (size_t)got;
    tl_run_output[len] = '\0';
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* tl_run(opts, "arg", ..., NULL) */
static inline int tl_run(const tl_run_opts *opts, ...)
{
    const char *args[48] = {tl_run_binary};
    int n = 1;
    va_list ap;
    va_start(ap, opts);
    const char *a;
    while ((a = va_arg(ap, const char *)) != NULL && n < 47)
        args[n++] = a;
    va_end(ap);
    args[n] = NULL;
    return tl_run_argv(opts, args);
}

/* Entries in a folder other than . and .. (-1 if it cannot be opened);
 * only hidden ones (temporaries) when hidden_only is set. */
static inline int tl_dir_count(const char *path, int hidden_only)
{
    DIR *d = opendir(path);
    if (!d)
        return -1;
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0 &&
            (!hidden_only || e->d_name[0] == '.'))
            count++;
    closedir(d);
    return count;
}

static inline int tl_dir_entries(const char *path)
{
    return tl_dir_count(path, 0);
}

static inline int tl_dir_hidden_entries(const char *path)
{
    return tl_dir_count(path, 1);
}

/* Whether two files hold the same bytes (both must be readable). */
static inline int tl_same_bytes(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    int same = fa && fb;
    while (same) {
        int ca = fgetc(fa), cb = fgetc(fb);
        same = ca == cb;
        if (ca == EOF || cb == EOF)
            break;
    }
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
    return same;
}

#endif
