/* SPDX-License-Identifier: MIT */
/* tests/alloc_fail.c — allocation failure injection for a test build of the
 * iskra tool (linked with -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,
 * --wrap=aligned_alloc: every allocation iskra's own code makes goes
 * through here; the C library's and libpng's own do not).
 *
 *   ISKRA_ALLOC_FAIL=N   the N-th allocation (1, 2, ...) returns NULL, the
 *                        others succeed
 *   ISKRA_ALLOC_COUNT=1  print "allocations: N" on stderr at exit
 *
 * tests/test_alloc_fail.c runs `iskra render` on every shipped scene with
 * each allocation failing in turn. */
#include <stdio.h>
#include <stdlib.h>

void *__real_malloc(size_t n);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t n);
void *__real_aligned_alloc(size_t align, size_t n);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t n, size_t size);
void *__wrap_realloc(void *p, size_t n);
void *__wrap_aligned_alloc(size_t align, size_t n);

static long calls, fail_at = -1;
static int counting = -1;

static void report(void)
{
    fprintf(stderr, "allocations: %ld\n", calls);
}

/* 1 when this call is the one to fail. */
static int fails(void)
{
    if (counting < 0) {
        const char *f = getenv("ISKRA_ALLOC_FAIL"), *c = getenv("ISKRA_ALLOC_COUNT");
        fail_at = f ? atol(f) : -1;
        counting = c && *c == '1';
        if (counting)
            atexit(report);
    }
    return ++calls == fail_at;
}

void *__wrap_malloc(size_t n) { return fails() ? NULL : __real_malloc(n); }
void *__wrap_calloc(size_t n, size_t size) { return fails() ? NULL : __real_calloc(n, size); }
void *__wrap_realloc(void *p, size_t n) { return fails() ? NULL : __real_realloc(p, n); }
void *__wrap_aligned_alloc(size_t align, size_t n) { return fails() ? NULL : __real_aligned_alloc(align, n); }
