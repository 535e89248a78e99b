/* SPDX-License-Identifier: MIT */
/* Progress bar (see progress.h). */
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

#define DELAY 0.5    /* seconds before the bar appears */
#define REFRESH 0.1  /* seconds between redraws */
#define WIDTH 40

double progress_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void progress_start(progress *p, long total)
{
    p->total = total > 0 ? total : 1;
    p->start = progress_now();
    p->last_draw = 0;
    p->enabled = isatty(fileno(stderr));
    p->shown = 0;
}

static void draw(progress *p, long done, double now)
{
    int fill = (int)((double)WIDTH * (double)done / (double)p->total);
    if (fill > WIDTH)
        fill = WIDTH;
    char bar[WIDTH + 1];
    for (int i = 0; i < WIDTH; i++)
        bar[i] = i < fill ? '#' : '.';
    bar[WIDTH] = 0;
    double el = now - p->start;
    double eta = done > 0 ? el * (double)(p->total - done) / (double)done : 0;
    fprintf(stderr, "\r[%s] %3d%%  frame %ld/%ld  %.1fs, ~%.0fs left ", bar, (int)(100.0 * done / p->total), done,
            p->total, el, eta);
    fflush(stderr);
    p->shown = 1;
    p->last_draw = now;
}

void progress_update(progress *p, long done)
{
    if (!p->enabled)
        return;
    double now = progress_now();
    if (now - p->start < DELAY || now - p->last_draw < REFRESH)
        return;
    draw(p, done, now);
}

void progress_end(progress *p)
{
    if (p->shown) {
        draw(p, p->total, progress_now());
        fputc('\n', stderr);
    }
}
