#include "movie/tl_movie.h"

#include "core/tl_math.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "image/tl_atomic.h"

extern char **environ;

#define TL_FFMPEG_HINT "install the Debian package 'ffmpeg' (or set TIDELINE_FFMPEG)"

struct tl_movie {
    pid_t pid;
    int fd;          /* write end of ffmpeg's stdin; -1 once closed */
    int reaped;      /* waited for: never signal the pid again (it may be reused) */
    int have_status; /* `status` is ffmpeg's wait status */
    int status;
    size_t frame_bytes;
    long frames;        /* written so far, for messages */
    tl_atomic_file out; /* the hidden temporary ffmpeg writes, renamed on success */
};

static const char *file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

tl_movie_codec tl_movie_codec_from_path(const char *path)
{
    if (!path)
        return TL_MOVIE_UNKNOWN;
    const char *dot = strrchr(file_name(path), '.');
    if (!dot)
        return TL_MOVIE_UNKNOWN;
    if (strcasecmp(dot, ".mp4") == 0)
        return TL_MOVIE_H264;
    if (strcasecmp(dot, ".mov") == 0)
        return TL_MOVIE_PRORES;
    return TL_MOVIE_UNKNOWN;
}

static int executable_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode) && access(path, X_OK) == 0;
}

/* Looks `name` up in $PATH like the shell does; fills `found`. */
static int search_path(const char *name, char *found, size_t size)
{
    const char *path = getenv("PATH");
    if (!path)
        path = "/usr/local/bin:/usr/bin:/bin";
    for (const char *p = path;;) {
        const char *colon = strchr(p, ':');
        size_t len = colon ? (size_t)(colon - p) : strlen(p);
        /* An empty entry means the current folder. */
        int n = len ? snprintf(found, size, "%.*s/%s", (int)len, p, name)
                    : snprintf(found, size, "./%s", name);
        if (n > 0 && (size_t)n < size && executable_file(found))
            return 1;
        if (!colon)
            return 0;
        p = colon + 1;
    }
}

int tl_movie_find_ffmpeg(char *out, size_t out_size, tl_error *err)
{
    char found[4096];
    const char *env = getenv("TIDELINE_FFMPEG");
    if (env && *env) {
        int ok = strchr(env, '/') ? snprintf(found, sizeof found, "%s", env) < (int)sizeof found &&
                                        executable_file(found)
                                  : search_path(env, found, sizeof found);
        if (!ok)
            return tl_error_set(err, TL_ERR_RUNTIME,
                                "ffmpeg not found: TIDELINE_FFMPEG is '%s', which is not an "
                                "executable program; " TL_FFMPEG_HINT,
                                env);
    } else if (!search_path("ffmpeg", found, sizeof found)) {
        return tl_error_set(err, TL_ERR_RUNTIME, "ffmpeg not found: " TL_FFMPEG_HINT);
    }
    if (out) {
        if (strlen(found) >= out_size)
            return tl_error_set(err, TL_ERR_RUNTIME, "ffmpeg's path is too long: %s", found);
        memcpy(out, found, strlen(found) + 1);
    }
    return TL_OK;
}

int tl_movie_check(const char *path, int width, int height, tl_error *err)
{
    tl_movie_codec codec = tl_movie_codec_from_path(path);
    if (codec == TL_MOVIE_UNKNOWN)
        return tl_error_set(err, TL_ERR_USAGE,
                            "'%s': unknown movie type; use .mp4 (H.264) or .mov (ProRes 422 HQ)",
                            path ? path : "");
    if (width <= 0 || height <= 0)
        return tl_error_set(err, TL_ERR_USAGE, "'%s': the movie size must be positive, got %dx%d",
                            path, width, height);
    if (codec == TL_MOVIE_H264 && (width % 2 != 0 || height % 2 != 0))
        return tl_error_set(err, TL_ERR_USAGE,
                            "'%s': H.264 (yuv420p) needs an even width and height, got %dx%d "
                            "(or write .mov)",
                            path, width, height);

    char dir[4096];
    const char *name = file_name(path);
    if (name == path)
        snprintf(dir, sizeof dir, ".");
    else if (name == path + 1)
        snprintf(dir, sizeof dir, "/");
    else if (snprintf(dir, sizeof dir, "%.*s", (int)(name - path - 1), path) >= (int)sizeof dir)
        return tl_error_set(err, TL_ERR_USAGE, "'%s': path too long", path);
    struct stat st;
    if (stat(dir, &st) != 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s': the folder '%s' does not exist", path, dir);
    if (!S_ISDIR(st.st_mode))
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s': '%s' is not a folder", path, dir);
    if (access(dir, W_OK | X_OK) != 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s': the folder '%s' is not writable", path,
                            dir);
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s' is a folder", path);
    return tl_movie_find_ffmpeg(NULL, 0, err);
}

int tl_movie_frame_rate(double fps, long *num, long *den)
{
    if (!(fps >= 0.001 && fps <= 10000.0))
        return 1;
    double whole = round(fps);
    if (fabs(fps - whole) < 1e-9) {
        *num = (long)whole;
        *den = 1;
        return 0;
    }
    /* 23.976 means 24000/1001: ffmpeg would otherwise drift from NTSC. */
    double ntsc = round(fps * 1.001);
    if (ntsc >= 1.0 && fabs(fps - ntsc * 1000.0 / 1001.0) < 0.0005 && fabs(fps - whole) > 0.0005) {
        *num = (long)ntsc * 1000;
        *den = 1001;
        return 0;
    }
    long n = (long)round(fps * 1000.0), g = tl_gcd(n, 1000);
    *num = n / g;
    *den = 1000 / g;
    return 0;
}

/* Leaves SIGPIPE to a handler the program installed, else ignores it, so
 * that writing to a dead ffmpeg fails with EPIPE instead of killing us. */
static void ignore_sigpipe(void)
{
    struct sigaction sa;
    if (sigaction(SIGPIPE, NULL, &sa) == 0 && !(sa.sa_flags & SA_SIGINFO) &&
        sa.sa_handler == SIG_DFL)
        signal(SIGPIPE, SIG_IGN);
}

static void close_pipe(tl_movie *m)
{
    if (m->fd >= 0)
        (void)close(m->fd);
    m->fd = -1;
}

/* Waits for ffmpeg (blocking when `ms` < 0, else for at most `ms`). */
static void reap(tl_movie *m, int ms)
{
    for (int waited = 0; !m->reaped; waited += 10) {
        pid_t r = waitpid(m->pid, &m->status, ms < 0 ? 0 : WNOHANG);
        if (r == m->pid) {
            m->reaped = m->have_status = 1;
        } else if (r < 0 && errno != EINTR) {
            m->reaped = 1; /* already reaped elsewhere (SIGCHLD ignored?): status unknown */
        } else if (r == 0) {
            if (waited >= ms)
                return;
            struct timespec ts = {0, 10 * 1000 * 1000};
            nanosleep(&ts, NULL);
        }
    }
}

static const char *describe_status(const tl_movie *m, char *buf, size_t size)
{
    if (!m->have_status)
        snprintf(buf, size, "exit status unknown");
    else if (WIFEXITED(m->status))
        snprintf(buf, size, "exit status %d", WEXITSTATUS(m->status));
    else if (WIFSIGNALED(m->status))
        snprintf(buf, size, "killed by signal %d, %s", WTERMSIG(m->status),
                 strsignal(WTERMSIG(m->status)));
    else
        snprintf(buf, size, "wait status %d", m->status);
    return buf;
}

static int ffmpeg_failed(tl_movie *m, tl_error *err)
{
    char how[128];
    return tl_error_set(err, TL_ERR_RUNTIME,
                        "ffmpeg stopped (%s) after %ld frame%s; no movie written to '%s' "
                        "(ffmpeg's messages, if any, are above)",
                        describe_status(m, how, sizeof how), m->frames, m->frames == 1 ? "" : "s",
                        m->out.path);
}

int tl_movie_open(tl_movie **out, const char *path, int width, int height, double fps,
                  const tl_movie_sound *sound, tl_error *err)
{
    *out = NULL;
    int rc = tl_movie_check(path, width, height, err);
    if (rc)
        return rc;
    long num, den;
    if (tl_movie_frame_rate(fps, &num, &den))
        return tl_error_set(err, TL_ERR_USAGE, "'%s': frame rate %g is outside 0.001-10000 fps",
                            path, fps);
    if (sound && !(sound->duration > 0.0 && sound->sample_rate > 0 && isfinite(sound->start)))
        return tl_error_set(err, TL_ERR_USAGE, "'%s': the soundtrack's placement is not valid",
                            path);
    char ffmpeg[4096];
    rc = tl_movie_find_ffmpeg(ffmpeg, sizeof ffmpeg, err);
    if (rc)
        return rc;

    tl_movie *m = calloc(1, sizeof *m);
    if (!m)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    m->fd = -1;
    m->frame_bytes = (size_t)width * (size_t)height * 3;
    /* ffmpeg writes by name into the temporary (-y), the same file tl_atomic
     * created, so tl_atomic's fsync and rename commit what ffmpeg wrote. */
    rc = tl_atomic_open(&m->out, path, err);
    if (rc) {
        free(m);
        return rc;
    }

    char size[64], rate[64], seek[64], audio_filter[128], length[64];
    snprintf(size, sizeof size, "%dx%d", width, height);
    snprintf(rate, sizeof rate, "%ld/%ld", num, den);
    int h264 = tl_movie_codec_from_path(path) == TL_MOVIE_H264;
    char *argv[64];
    int argc = 0;
#define ARGS(...)                                                                                  \
    do {                                                                                           \
        const char *list_[] = {__VA_ARGS__};                                                       \
        for (size_t i_ = 0; i_ < sizeof list_ / sizeof *list_; i_++)                               \
            argv[argc++] = (char *)list_[i_];                                                      \
    } while (0)
    ARGS(ffmpeg, "-hide_banner", "-loglevel", "error", "-nostats", "-y", "-f", "rawvideo",
         "-pix_fmt", "rgb24", "-s", size, "-framerate", rate, "-i", "-");
    if (sound) {
        /* The file from `start` seconds in; a negative start is silence
         * first, delayed to the sample. The sound is padded with silence
         * and the movie cut to the frames' length (-t), so that the audio
         * stream is exactly as long as the picture. */
        if (sound->start > 0.0) {
            snprintf(seek, sizeof seek, "%.9f", sound->start);
            ARGS("-ss", seek);
        }
        ARGS("-i", sound->path, "-map", "0:v:0", "-map", "1:a:0");
        long long delay = sound->start < 0.0 ? llround(-sound->start * sound->sample_rate) : 0;
        if (delay > 0)
            snprintf(audio_filter, sizeof audio_filter, "adelay=delays=%lldS:all=1,apad", delay);
        else
            snprintf(audio_filter, sizeof audio_filter, "apad");
        snprintf(length, sizeof length, "%.9f", sound->duration);
        ARGS("-af", audio_filter, "-t", length);
        if (h264)
            ARGS("-c:a", "aac", "-b:a", "256k");
        else
            ARGS("-c:a", "pcm_s24le");
    }
    if (h264)
        ARGS("-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-preset", "medium",
             "-movflags", "+faststart", "-f", "mp4");
    else
        ARGS("-c:v", "prores_ks", "-profile:v", "3", "-pix_fmt", "yuv422p10le", "-f", "mov");
#undef ARGS
    argv[argc++] = m->out.tmp_path;
    argv[argc] = NULL;

    ignore_sigpipe();
    int p[2];
    if (pipe(p) != 0) {
        int e = errno;
        tl_atomic_abort(&m->out);
        free(m);
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s': cannot create a pipe: %s", path,
                            strerror(e));
    }
    /* Only the child's stdin may stay open across exec (dup2 clears the flag
     * on fd 0; fd 0 itself, if stdin was closed, must keep it off). */
    fcntl(p[1], F_SETFD, FD_CLOEXEC);
    if (p[0] != STDIN_FILENO)
        fcntl(p[0], F_SETFD, FD_CLOEXEC);

    posix_spawn_file_actions_t fa;
    posix_spawnattr_t attr;
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE); /* we ignore it; ffmpeg should not inherit that */
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, p[0], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawnattr_init(&attr);
    /* Its own process group: a Ctrl-C reaches tideline only, which decides. */
    posix_spawnattr_setpgroup(&attr, 0);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK |
                                        POSIX_SPAWN_SETSIGDEF);
    int e = posix_spawn(&m->pid, ffmpeg, &fa, &attr, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&attr);
    close(p[0]);
    if (e != 0) {
        close(p[1]);
        tl_atomic_abort(&m->out);
        free(m);
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s': cannot start %s: %s", path, ffmpeg,
                            strerror(e));
    }
    m->fd = p[1];
    *out = m;
    return TL_OK;
}

int tl_movie_write(tl_movie *m, const uint8_t *rgb, tl_error *err)
{
    if (!m || m->fd < 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "the movie is not open");
    size_t done = 0;
    while (done < m->frame_bytes) {
        ssize_t n = write(m->fd, rgb + done, m->frame_bytes - done);
        if (n >= 0) {
            done += (size_t)n;
            continue;
        }
        if (errno == EINTR)
            continue;
        int e = errno;
        close_pipe(m);
        if (e != EPIPE)
            kill(-m->pid, SIGTERM);
        reap(m, -1);
        /* Only once ffmpeg has exited: it may still reopen the file by name. */
        tl_atomic_abort(&m->out);
        if (e == EPIPE)
            return ffmpeg_failed(m, err);
        return tl_error_set(err, TL_ERR_RUNTIME, "'%s': writing to ffmpeg: %s", m->out.path,
                            strerror(e));
    }
    m->frames++;
    return TL_OK;
}

int tl_movie_finish(tl_movie *m, tl_error *err)
{
    if (!m)
        return tl_error_set(err, TL_ERR_RUNTIME, "the movie is not open");
    close_pipe(m); /* end of input: ffmpeg finishes the file and exits */
    reap(m, -1);
    int rc;
    if (m->out.tmp_path[0] == '\0' || !m->have_status || !WIFEXITED(m->status) ||
        WEXITSTATUS(m->status) != 0) {
        tl_atomic_abort(&m->out);
        rc = ffmpeg_failed(m, err);
    } else {
        rc = tl_atomic_commit(&m->out, err);
    }
    free(m);
    return rc;
}

void tl_movie_abort(tl_movie *m)
{
    if (!m)
        return;
    if (!m->reaped)
        kill(-m->pid, SIGTERM);
    close_pipe(m);
    reap(m, 2000);
    if (!m->reaped) {
        kill(-m->pid, SIGKILL); /* ffmpeg did not stop on SIGTERM */
        reap(m, -1);
    }
    tl_atomic_abort(&m->out);
    free(m);
}
