/* SPDX-License-Identifier: MIT */
/* Shared pieces of `iskra bench accuracy` (see study.h). */
#include "study.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cleanup.h"
#include "iskra/canvas.h"

double study_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double study_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return v[n / 2];
}

void study_printf(study_buf *b, const char *fmt, ...)
{
    if (b->failed)
        return;
    for (;;) {
        size_t room = b->cap - b->len;
        va_list ap;
        va_start(ap, fmt);
        int n = vsnprintf(b->text ? b->text + b->len : NULL, room, fmt, ap);
        va_end(ap);
        if (n < 0) {
            b->failed = 1;
            return;
        }
        if ((size_t)n < room) {
            b->len += (size_t)n;
            return;
        }
        size_t cap = b->cap ? b->cap : 4096;
        while (cap - b->len <= (size_t)n)
            cap *= 2;
        char *t = realloc(b->text, cap);
        if (!t) {
            b->failed = 1;
            return;
        }
        b->text = t;
        b->cap = cap;
    }
}

void study_buf_free(study_buf *b)
{
    free(b->text);
    memset(b, 0, sizeof *b);
}

static int make_dir(const char *dir)
{
    if (mkdir(dir, 0777) == 0 || errno == EEXIST)
        return 0;
    fprintf(stderr, "iskra bench: cannot create %s: %s\n", dir, strerror(errno));
    return 1;
}

static int join(const study_opts *o, const char *name, char *path, size_t cap)
{
    int n = snprintf(path, cap, "%s/%s", o->out_dir, name);
    if (n < 0 || (size_t)n >= cap) {
        fprintf(stderr, "iskra bench: output path too long: %s/%s\n", o->out_dir, name);
        return 1;
    }
    return make_dir(o->out_dir);
}

int study_write_text(const study_opts *o, const char *name, const study_buf *b)
{
    char path[4096];
    if (join(o, name, path, sizeof path))
        return 1;
    if (b->failed) {
        fprintf(stderr, "iskra bench: %s: out of memory while formatting\n", path);
        return 1;
    }
    isk_outfile out;
    if (cleanup_outfile_open(&out, path))
        return 1;
    if (b->len != 0 && fwrite(b->text, 1, b->len, out.f) != b->len) {
        fprintf(stderr, "iskra bench: %s: write failed: %s\n", path, strerror(errno ? errno : EIO));
        cleanup_outfile_abort(&out);
        return 1;
    }
    return cleanup_outfile_commit(&out);
}

int study_write_chart(const study_opts *o, const char *name, const isk_chart *ch, int w, int h)
{
    char path[4096];
    if (join(o, name, path, sizeof path))
        return 1;
    isk_canvas c;
    isk_status st = isk_canvas_init(&c, w, h);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench: %s: %s\n", path, isk_status_str(st));
        return 1;
    }
    st = isk_chart_draw(ch, &c);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench: %s: chart: %s\n", path, isk_status_str(st));
        isk_canvas_free(&c);
        return 1;
    }
    int rc = cleanup_png_write(&c, path);
    isk_canvas_free(&c);
    return rc;
}
