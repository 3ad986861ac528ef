/* The bench's reports: a Markdown table, a CSV and a gnuplot plot. */
#include <errno.h>
#include <math.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench/tl_bench.h"
#include "image/tl_atomic.h"

extern char **environ;

void tl_bench_mark_front(tl_bench_row *rows, int count)
{
    for (int i = 0; i < count; i++) {
        /* Untimed error (--time-only): no front to speak of. */
        rows[i].on_front = !rows[i].is_reference && !isnan(rows[i].psnr);
        for (int j = 0; j < count && rows[i].on_front; j++) {
            if (j == i || rows[j].is_reference)
                continue;
            int no_worse = rows[j].ms_total <= rows[i].ms_total && rows[j].psnr >= rows[i].psnr;
            int better = rows[j].ms_total < rows[i].ms_total || rows[j].psnr > rows[i].psnr;
            if (no_worse && better)
                rows[i].on_front = 0;
        }
    }
}

void tl_bench_print_table(FILE *to, const tl_bench_row *rows, int count)
{
    fprintf(to, "| preset | ms/frame | render | readback | encode | PSNR dB | SSIM | p99 "
                "| worst frame (PSNR dB) |\n");
    fprintf(to, "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n");
    for (int i = 0; i < count; i++) {
        const tl_bench_row *r = &rows[i];
        if (r->is_reference && isnan(r->ms_total)) { /* every frame from --reference-cache */
            fprintf(to, "| reference | (cached) | | | | (yardstick) | | | |\n");
            continue;
        }
        if (r->is_reference) {
            fprintf(to, "| reference | %.0f | %.0f | | | (yardstick) | | | |\n", r->ms_total,
                    r->ms_render);
            continue;
        }
        if (isnan(r->psnr)) { /* --time-only */
            fprintf(to, "| %s | %.1f | %.1f | %.1f | %.1f | | | | |\n", r->preset, r->ms_total,
                    r->ms_render, r->ms_readback, r->ms_encode);
            continue;
        }
        fprintf(to, "| %s%s | %.1f | %.1f | %.1f | %.1f | %.2f | %.4f | %.0f | %s (%.2f) |\n",
                r->preset, r->on_front ? " *" : "", r->ms_total, r->ms_render, r->ms_readback,
                r->ms_encode, r->psnr, r->ssim, r->p99, r->worst_shot, r->worst_psnr);
    }
}

void tl_bench_print_passes(FILE *to, const tl_bench_row *rows, int count)
{
    fprintf(to, "\n| preset |");
    for (int i = 0; i < TL_BENCH_PASSES; i++)
        fprintf(to, " %s |", tl_render_pass_name(i));
    fprintf(to, " all passes | render | frame |\n| --- |");
    for (int i = 0; i <= TL_BENCH_PASSES + 1; i++)
        fprintf(to, " ---: |");
    fprintf(to, " --- |\n");
    for (int k = 0; k < count; k++) {
        const tl_bench_row *r = &rows[k];
        if (!r->has_passes)
            continue;
        fprintf(to, "| %s |", r->preset);
        for (int i = 0; i <= TL_BENCH_PASSES; i++)
            fprintf(to, " %.1f |", r->ms_pass[i]);
        fprintf(to, " %.1f | %s |\n", r->ms_pass_render, r->pass_shot);
    }
}

int tl_bench_write_csv(const char *path, const tl_bench_row *rows, int count, int width, int height,
                       int frames, int repeat, tl_error *err)
{
    tl_atomic_file f;
    int rc = tl_atomic_open(&f, path, err);
    if (rc)
        return rc;
    fprintf(f.fp, "preset,width,height,frames,repeat,ms_total,ms_render,ms_readback,ms_encode,"
                  "psnr_db,ssim,p99_levels,worst_psnr_db,worst_frame,pareto\n");
    for (int i = 0; i < count; i++) {
        const tl_bench_row *r = &rows[i];
        if (r->is_reference && isnan(r->ms_total)) { /* from --reference-cache: untimed */
            fprintf(f.fp, "reference,%d,%d,%d,1,,,,,%.4f,%.6f,%.2f,%.4f,,0\n", width, height,
                    frames, r->psnr, r->ssim, r->p99, r->psnr);
            continue;
        }
        if (isnan(r->psnr)) { /* --time-only: the error columns stay empty */
            fprintf(f.fp, "%s,%d,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,,,,,,0\n", r->preset, width, height,
                    frames, repeat, r->ms_total, r->ms_render, r->ms_readback, r->ms_encode);
            continue;
        }
        fprintf(f.fp, "%s,%d,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%.4f,%.6f,%.2f,%.4f,%s,%d\n", r->preset,
                width, height, frames, r->is_reference ? 1 : repeat, r->ms_total, r->ms_render,
                r->ms_readback, r->ms_encode, r->psnr, r->ssim, r->p99,
                r->is_reference ? r->psnr : r->worst_psnr, r->is_reference ? "" : r->worst_shot,
                r->on_front);
    }
    return tl_atomic_commit(&f, err);
}

/* Runs `gnuplot script`; returns its exit status, 127 when it cannot run. */
static int run_gnuplot(const char *script)
{
    char *argv[] = {"gnuplot", (char *)script, NULL};
    pid_t pid;
    if (posix_spawnp(&pid, "gnuplot", NULL, NULL, argv, environ) != 0)
        return 127;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return 127;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

static void write_plot_script(FILE *s, const char *out, const tl_bench_row *rows, int count,
                              int width, int height)
{
    double ref_ms = 0.0;
    for (int i = 0; i < count; i++)
        if (rows[i].is_reference)
            ref_ms = rows[i].ms_total;
    fprintf(s, "set terminal pngcairo size 960,600 font 'sans,11'\n");
    fprintf(s, "set output '%s'\n", out);
    if (isnan(ref_ms)) /* its frames came from --reference-cache */
        fprintf(s, "set title 'tideline bench, %dx%d: error against reference'\n", width, height);
    else
        fprintf(s, "set title 'tideline bench, %dx%d: error against reference (%.0f ms/frame)'\n",
                width, height, ref_ms);
    fprintf(s, "set xlabel 'median ms per frame (render + readback + PNG encode)'\n");
    fprintf(s, "set ylabel 'PSNR against reference (dB, higher is closer)'\n");
    fprintf(s, "set grid\nset key below\nset offsets graph 0.1, graph 0.15, graph 0.1, "
               "graph 0.1\n");
    fprintf(s, "$points << EOD\n");
    for (int i = 0; i < count; i++)
        if (!rows[i].is_reference)
            fprintf(s, "%.3f %.4f %s\n", rows[i].ms_total, rows[i].psnr, rows[i].preset);
    fprintf(s, "EOD\n$front << EOD\n");
    /* The front in order of time (insertion sort over a handful of rows). */
    int order[TL_BENCH_MAX_PRESETS + 1], n = 0;
    for (int i = 0; i < count; i++) {
        if (!rows[i].on_front)
            continue;
        int j = n++;
        while (j > 0 && rows[order[j - 1]].ms_total > rows[i].ms_total) {
            order[j] = order[j - 1];
            j--;
        }
        order[j] = i;
    }
    for (int k = 0; k < n; k++)
        fprintf(s, "%.3f %.4f\n", rows[order[k]].ms_total, rows[order[k]].psnr);
    fprintf(s, "EOD\n");
    fprintf(s, "plot $front using 1:2 with linespoints lw 2 pt 6 ps 2.5 lc rgb '#d95f02' title "
               "'Pareto front', \\\n"
               "     $points using 1:2 with points pt 7 ps 1.5 lc rgb '#1b9e77' title 'preset', "
               "\\\n"
               "     $points using 1:2:3 with labels offset 1.2,0.8 left notitle\n");
}

int tl_bench_write_plot(const char *path, const tl_bench_row *rows, int count, int width,
                        int height, tl_error *err)
{
    if (strchr(path, '\'') || strchr(path, '\n'))
        return tl_error_set(err, TL_ERR_RUNTIME, "--plot: the name %s has a quote or newline",
                            path);
    /* gnuplot writes into the atomic temporary; committing renames it. */
    tl_atomic_file out;
    int rc = tl_atomic_open(&out, path, err);
    if (rc)
        return rc;
    char script[] = "/tmp/tideline-plot-XXXXXX";
    int fd = mkstemp(script);
    FILE *s = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!s) {
        if (fd >= 0) {
            close(fd);
            unlink(script);
        }
        tl_atomic_abort(&out);
        return tl_error_set(err, TL_ERR_RUNTIME, "cannot write a gnuplot script in /tmp");
    }
    write_plot_script(s, out.tmp_path, rows, count, width, height);
    int written = fclose(s) == 0;
    int status = written ? run_gnuplot(script) : 1;
    unlink(script);
    if (status != 0) {
        tl_atomic_abort(&out);
        if (status == 127)
            return tl_error_set(err, TL_ERR_RUNTIME,
                                "no plot written: gnuplot is not installed (Debian package "
                                "gnuplot-nox; scripts/setup.sh installs it)");
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: gnuplot failed (status %d)", path, status);
    }
    return tl_atomic_commit(&out, err);
}
