/* SPDX-License-Identifier: MIT */
/* tests/fast_paths_skip.h — a test of a fast path's own work (that it ran,
 * how often, what it kept) skips in the reference build, where that fast
 * path is compiled out (src/core/fast_paths.h).  The byte comparisons of
 * every other test still run there.  Include after <criterion/criterion.h>:
 *
 *     SKIP_WITHOUT(ISK__FAST_REST, "blocks at rest");   // first line of the test */
#ifndef ISKRA_TESTS_FAST_PATHS_SKIP_H
#define ISKRA_TESTS_FAST_PATHS_SKIP_H

#include "core/fast_paths.h"

#define SKIP_WITHOUT(on, what)                                                                                   \
    do {                                                                                                         \
        if (!(on))                                                                                               \
            cr_skip_test("%s: compiled out in the reference build (src/core/fast_paths.h)", what);              \
    } while (0)

#endif
