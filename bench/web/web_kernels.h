/* SPDX-License-Identifier: MIT */
/* bench/web/web_kernels.h — the work `make bench-web` times, the same C on
 * both sides: natively (bench/web/bench_web_native.c) and in the browser
 * (web/bench_web.c, a wasm module built with and without -msimd128).
 * There is no clock here: each side times web_kernel_run with its own
 * (clock_gettime, performance.now()), so both time exactly this code.
 *
 *     const web_kernel_info *info = &web_kernels[id];
 *     web_kernel *k;
 *     isk_error err = {0};
 *     if (web_kernel_setup(&k, id, &err) != ISK_OK) ...   (err.message says why)
 *     for (int r = 0; r < info->warm + info->timed; r++)
 *         ... time web_kernel_run(k) when r >= info->warm ...
 *     uint64_t h = web_kernel_hash(k);
 *     web_kernel_free(k);
 *
 * After warm + timed runs the hash is that of the kernel's bytes (the
 * particles' x, y, vx, vy and the canvas; a control's numbers): equal on
 * both sides when the same work gave the same bytes.  It is defined for
 * that run count only. */
#ifndef ISKRA_BENCH_WEB_KERNELS_H
#define ISKRA_BENCH_WEB_KERNELS_H

#include <stdint.h>

#include "iskra/status.h"

typedef struct web_kernel_info {
    const char *name; /* what the tables call it */
    const char *what; /* one line for the reader */
    int warm;         /* runs before the timed ones (caches, the first touch of memory) */
    int timed;        /* runs timed; each side reports their median */
} web_kernel_info;

enum { WEB_KERNELS = 6 };
extern const web_kernel_info web_kernels[WEB_KERNELS];

typedef struct web_kernel web_kernel;

/* Kernel `id` (0 .. WEB_KERNELS-1) made ready to run.  Errors:
 * ISK_ERR_RANGE (no such kernel), ISK_ERR_NOMEM, or the effect's. */
isk_status web_kernel_setup(web_kernel **out, int id, isk_error *err);

/* One run: the work timed. */
isk_status web_kernel_run(web_kernel *k);

/* A 64-bit FNV-1a of the kernel's bytes. */
uint64_t web_kernel_hash(const web_kernel *k);

void web_kernel_free(web_kernel *k);

#endif
