/* The bench's cache of `reference` frames (--reference-cache DIR): the
 * converged frames take 15-20 s each at 640x360 on llvmpipe, most of a
 * bench run, and they only change when something that draws them does.
 * A frame's file is named by a hash of everything that does: this very
 * program (its bytes hold the reference preset, the renderer and the
 * built-in shaders), the shaders of --shader-dir, the renderer's
 * description (another driver rounds differently), the timeline's text,
 * the boat model it loads, the frame and the size. Any change is a new
 * name, never a stale hit; old files are left for the user to delete. */
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bench/tl_bench.h"
#include "image/tl_atomic.h"

#define CACHE_MAGIC "tideline reference frame 1\n"

/* FNV-1a, 64 bits: a file name, not a defence against forgery. */
static uint64_t hash_bytes(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

static uint64_t hash_text(uint64_t h, const char *s)
{
    return hash_bytes(h, s, strlen(s) + 1); /* with its terminator: "ab","c" != "a","bc" */
}

/* The file's bytes, or a marker when it cannot be read (a later run that
 * can read it then keys differently, which is safe). */
static uint64_t hash_file(uint64_t h, const char *path, int *readable)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        *readable = 0;
        return hash_text(h, "(unreadable)");
    }
    unsigned char buf[65536];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) != 0) {
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            *readable = 0;
            break;
        }
        h = hash_bytes(h, buf, (size_t)n);
    }
    close(fd);
    return h;
}

int tl_bench_cache_open(tl_bench_cache *c, const char *dir, const tl_shader_lib *lib, tl_error *err)
{
    memset(c, 0, sizeof *c);
    if (snprintf(c->dir, sizeof c->dir, "%s", dir) >= (int)sizeof c->dir)
        return tl_error_set(err, TL_ERR_USAGE, "--reference-cache: the folder name is too long");
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return tl_error_set(err, TL_ERR_USAGE, "--reference-cache: cannot create folder '%s': %s",
                            dir, strerror(errno));
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode) || access(dir, W_OK | X_OK) != 0)
        return tl_error_set(err, TL_ERR_USAGE, "--reference-cache: '%s' is not a writable folder",
                            dir);
    int readable = 1;
    uint64_t h = hash_text(0xcbf29ce484222325ull, CACHE_MAGIC);
    h = hash_file(h, "/proc/self/exe", &readable);
    if (!readable)
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "--reference-cache: cannot read this program (/proc/self/exe) to key "
                            "the cache");
    if (lib->dir[0]) {
        char path[2048];
        for (int i = 0; i < tl_embedded_shader_count; i++) {
            const char *name = tl_embedded_shaders[i].name;
            snprintf(path, sizeof path, "%s/%s", lib->dir, name);
            h = hash_file(hash_text(h, name), path, &readable);
        }
    }
    c->base = h;
    return TL_OK;
}

uint64_t tl_bench_cache_key(const tl_bench_cache *c, const char *renderer, const char *timeline,
                            const char *model, long frame, int width, int height)
{
    int readable = 1;
    uint64_t h = hash_file(hash_text(c->base, renderer), timeline, &readable);
    h = model && model[0] ? hash_file(hash_text(h, model), model, &readable) : hash_text(h, "");
    long long numbers[3] = {frame, width, height};
    return hash_bytes(h, numbers, sizeof numbers);
}

static void cache_path(const tl_bench_cache *c, uint64_t key, char *out, size_t size)
{
    snprintf(out, size, "%s/%016llx.tlref", c->dir, (unsigned long long)key);
}

/* The header: the magic, then the key and the size as text, so that a
 * file renamed by hand or cut short is a miss. */
static int header(char *out, size_t size, uint64_t key, int width, int height)
{
    return snprintf(out, size, "%s%016llx %d %d\n", CACHE_MAGIC, (unsigned long long)key, width,
                    height);
}

int tl_bench_cache_load(const tl_bench_cache *c, uint64_t key, int width, int height, float *pixels)
{
    char path[4200], want[128], got[128];
    cache_path(c, key, path, sizeof path);
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    int len = header(want, sizeof want, key, width, height);
    size_t count = (size_t)width * (size_t)height * 4;
    int hit = fread(got, 1, (size_t)len, f) == (size_t)len && memcmp(got, want, (size_t)len) == 0 &&
              fread(pixels, sizeof(float), count, f) == count && fgetc(f) == EOF;
    fclose(f);
    return hit;
}

int tl_bench_cache_store(const tl_bench_cache *c, uint64_t key, int width, int height,
                         const float *pixels, tl_error *err)
{
    char path[4200], head[128];
    cache_path(c, key, path, sizeof path);
    tl_atomic_file f;
    int rc = tl_atomic_open(&f, path, err);
    if (rc)
        return rc;
    int len = header(head, sizeof head, key, width, height);
    size_t count = (size_t)width * (size_t)height * 4;
    if (fwrite(head, 1, (size_t)len, f.fp) != (size_t)len ||
        fwrite(pixels, sizeof(float), count, f.fp) != count) {
        tl_atomic_abort(&f);
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: %s", path, strerror(errno));
    }
    return tl_atomic_commit(&f, err);
}
