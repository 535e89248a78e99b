/* SPDX-License-Identifier: MIT */
/* bench/bench_util.h — the clock and the median every benchmark uses.
 * Header-only (static functions) so each benchmark stays one program. */
#ifndef ISKRA_BENCH_UTIL_H
#define ISKRA_BENCH_UTIL_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* A benchmark's one optional argument.  --help (or -h) prints `usage` and
 * exits 0; an argument refused is named, with the usage, and exits 2 (a
 * mistyped flag must not start a run of several minutes). */
static inline void bench_usage_exit(const char *prog, const char *refused, const char *why, const char *usage)
{
    if (!refused) {
        printf("%s", usage);
        exit(0);
    }
    fprintf(stderr, "%s: '%s': %s\n%s", prog, refused, why, usage);
    exit(2);
}

static inline int bench_wants_help(int argc, char **argv)
{
    return argc > 1 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"));
}

/* 1 for --quick, 0 for no argument. */
static inline int bench_quick_arg(int argc, char **argv, const char *usage)
{
    if (bench_wants_help(argc, argv))
        bench_usage_exit(argv[0], NULL, NULL, usage);
    if (argc > 1 && strcmp(argv[1], "--quick"))
        bench_usage_exit(argv[0], argv[1], "unexpected argument", usage);
    if (argc > 2)
        bench_usage_exit(argv[0], argv[2], "unexpected argument", usage);
    return argc == 2;
}

/* A repetition count: a whole number in [1, max], `fallback` without one. */
static inline int bench_reps_arg(int argc, char **argv, int fallback, int max, const char *usage)
{
    if (bench_wants_help(argc, argv))
        bench_usage_exit(argv[0], NULL, NULL, usage);
    if (argc > 2)
        bench_usage_exit(argv[0], argv[2], "unexpected argument", usage);
    if (argc == 1)
        return fallback;
    char *end = NULL;
    errno = 0;
    const long v = strtol(argv[1], &end, 10);
    if (end == argv[1] || *end || errno || v < 1 || v > max) {
        char why[64];
        snprintf(why, sizeof why, "the repetitions must be a whole number from 1 to %d", max);
        bench_usage_exit(argv[0], argv[1], why, usage);
    }
    return (int)v;
}

/* Monotonic seconds. */
static inline double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* CPU seconds of the calling thread: on a machine shared with other work it
 * leaves out the time the thread was not running (cache interference
 * remains), so short single-threaded kernels compare more steadily. */
static inline double bench_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* A uniform double in [0, 1) from a 64-bit LCG state: the same random
 * items in every benchmark that asks for them (no libc rand). */
static inline double bench_urand(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

static inline int bench_cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of n timings (sorts v in place). */
static inline double bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp);
    return v[n / 2];
}

#endif
