/* SPDX-License-Identifier: MIT */
/* The native side of `make bench-web`: the kernels of web_kernels.h timed
 * with clock_gettime (wall clock, as the browser's performance.now()),
 * each the median of its timed runs after its warm-up runs, on one thread.
 * One line a kernel: its name, median ms, and the hash of its bytes, which
 * the browser's runs of the same kernel must give too (tools/web_bench.py
 * runs this and the page in turn and prints them side by side).
 *
 *     build/bench/bench_web_native */
#include <inttypes.h>
#include <stdio.h>

#include "../bench_util.h"
#include "web_kernels.h"

enum { MAX_TIMED = 64 };

int main(int argc, char **argv)
{
    if (argc > 1)
        bench_usage_exit(argv[0], bench_wants_help(argc, argv) ? NULL : argv[1], "unexpected argument",
                         "usage: bench_web_native\n"
                         "  the kernels of make bench-web, natively on one thread: median ms and the hash of\n"
                         "  their bytes, a line each\n");
    printf("%-8s %10s %-16s %5s  %s\n", "kernel", "median ms", "hash", "runs", "what");
    for (int id = 0; id < WEB_KERNELS; id++) {
        const web_kernel_info *info = &web_kernels[id];
        web_kernel *k = NULL;
        isk_error err = {0};
        if (info->timed > MAX_TIMED || web_kernel_setup(&k, id, &err) != ISK_OK) {
            fprintf(stderr, "bench_web_native: %s: %s\n", info->name,
                    err.message[0] ? err.message : "too many timed runs");
            return 1;
        }
        double t[MAX_TIMED];
        for (int r = 0; r < info->warm + info->timed; r++) {
            const double t0 = bench_now();
            const isk_status s = web_kernel_run(k);
            const double t1 = bench_now();
            if (s != ISK_OK) {
                fprintf(stderr, "bench_web_native: %s: %s\n", info->name, isk_status_str(s));
                web_kernel_free(k);
                return 1;
            }
            if (r >= info->warm)
                t[r - info->warm] = 1e3 * (t1 - t0);
        }
        printf("%-8s %10.3f %016" PRIx64 " %5d  %s\n", info->name, bench_median(t, info->timed),
               web_kernel_hash(k), info->timed, info->what);
        fflush(stdout);
        web_kernel_free(k);
    }
    return 0;
}
