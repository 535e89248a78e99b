/* SPDX-License-Identifier: MIT */
/* tests/refimg.h — reference-image checks for the test suite (olive.c/cairo style).
 *
 *     Test(refimg, fill_circle) {
 *         isk_canvas c; ...draw...
 *         cr_assert(refimg_check("fill_circle", &c));
 *         isk_canvas_free(&c);
 *     }
 *
 * refimg_check compares `c` with refimg/<name>.png exactly (every byte of
 * every pixel) through the library's isk_refimg_check (iskra/refimg.h),
 * with out/refimg/ as the output directory: on a mismatch it leaves
 * out/refimg/<name>.actual.png and <name>.diff.png (differing pixels
 * magenta, the rest a dimmed copy), prints how many pixels differ and by
 * how much, and how to update the reference on purpose.  A missing
 * reference fails with the same hint.
 *
 * With ISKRA_REFIMG_UPDATE=1 in the environment it (re)writes the reference
 * instead and passes.  tools/refimg wraps this: `tools/refimg run [name]`,
 * `tools/refimg update [name]`, `tools/refimg list`.
 *
 * Paths are relative to the repository root; tests/run_all.sh runs every
 * test binary from there.
 */
#ifndef ISKRA_TESTS_REFIMG_H
#define ISKRA_TESTS_REFIMG_H

#include "iskra/canvas.h"

/* Exact comparison; returns 1 on match (or after an update), 0 otherwise. */
int refimg_check(const char *name, const isk_canvas *c);

/* Tolerant comparison: passes when at most `max_pixels` pixels have a
 * channel that differs by more than `max_channel_diff` (the library's
 * rule).  `reason` must say why a tolerance is needed (it is printed on
 * failure). */
int refimg_check_tol(const char *name, const isk_canvas *c, int max_channel_diff, long max_pixels,
                     const char *reason);

/* Path of the build directory (ISKRA_BUILD, default "build"), for tests that
 * run built programs. */
const char *refimg_build_dir(void);

#endif
