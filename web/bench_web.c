/* SPDX-License-Identifier: MIT */
/* The browser's side of `make bench-web`: the kernels of
 * bench/web/web_kernels.h exported for web/bench.js, which times
 * bench_web_run with performance.now().  Built as a wasm32-wasi reactor of
 * its own (build/web/bench.wasm, and bench-nosimd.wasm without -msimd128),
 * apart from the simulator's iskra.wasm.
 *
 * A kernel is a pointer into the module's memory (0: it could not be made;
 * bench_web_message says why).  Strings are NUL-terminated in that memory. */
#include <stdint.h>

#include "../bench/web/web_kernels.h"

#define WEB_EXPORT(name) __attribute__((export_name(#name)))

/* The last setup's error, for the page (a wasm instance serves one page). */
static isk_error last_error;

WEB_EXPORT(bench_web_count) int bench_web_count(void) { return WEB_KERNELS; }

static const web_kernel_info *info(int id) { return id >= 0 && id < WEB_KERNELS ? &web_kernels[id] : NULL; }

WEB_EXPORT(bench_web_name) const char *bench_web_name(int id) { return info(id) ? info(id)->name : NULL; }
WEB_EXPORT(bench_web_what) const char *bench_web_what(int id) { return info(id) ? info(id)->what : NULL; }
WEB_EXPORT(bench_web_warm) int bench_web_warm(int id) { return info(id) ? info(id)->warm : 0; }
WEB_EXPORT(bench_web_timed) int bench_web_timed(int id) { return info(id) ? info(id)->timed : 0; }

WEB_EXPORT(bench_web_setup) web_kernel *bench_web_setup(int id)
{
    web_kernel *k = NULL;
    last_error = (isk_error){0};
    if (web_kernel_setup(&k, id, &last_error) != ISK_OK)
        return NULL;
    return k;
}

WEB_EXPORT(bench_web_message) const char *bench_web_message(void) { return last_error.message; }

/* 0 when the run went well, else an isk_status. */
WEB_EXPORT(bench_web_run) int bench_web_run(web_kernel *k) { return (int)web_kernel_run(k); }

WEB_EXPORT(bench_web_hash) uint64_t bench_web_hash(web_kernel *k) { return web_kernel_hash(k); }

WEB_EXPORT(bench_web_free) void bench_web_free(web_kernel *k) { web_kernel_free(k); }
