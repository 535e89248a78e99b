/* SPDX-License-Identifier: MIT */
/* iskra/refimg.h — pixel-exact tests of your own rendered buffers.
 *
 * Compare a canvas with a reference PNG, byte for byte by default; on a
 * mismatch leave the actual image and a picture of the differences where
 * you can look at them; regenerate references on purpose.
 *
 * Example: the first check writes the reference, as ISKRA_REFIMG_UPDATE=1 would:
 *
 *     isk_canvas canvas;
 *     if (isk_canvas_init(&canvas, 64, 32) != ISK_OK) return 1;
 *     isk_canvas_fill(&canvas, isk_rgba(250, 120, 40, 255));      // ...render the picture...
 *     isk_error err;
 *     isk_refimg_opts first = {0};
 *     first.update = ISK_REFIMG_UPDATE_ALWAYS;
 *     isk_status s = isk_refimg_check(&canvas, "tests/ref/sunset.png", &first, &err);
 *     isk_refimg_opts opts = {0};          // exact, ISKRA_REFIMG_UPDATE honoured
 *     opts.out_dir = "out/refimg";         // where NAME.actual/.diff.png go
 *     if (s == ISK_OK) s = isk_refimg_check(&canvas, "tests/ref/sunset.png", &opts, &err);
 *     if (s != ISK_OK) fprintf(stderr, "%s\n", err.message);   // or cr_assert_eq(s, ISK_OK, ...)
 *     isk_canvas_free(&canvas);
 *     return s != ISK_OK;
 *
 * Outcomes (NAME is the reference's file name without ".png"):
 *   same pixels          ISK_OK.
 *   different pixels     ISK_ERR_MISMATCH; writes OUT/NAME.actual.png (the
 *     or sizes           canvas) and OUT/NAME.diff.png (differing pixels,
 *                        and pixels outside either image, opaque magenta; the
 *                        rest a dimmed copy), and says in err how many pixels
 *                        differ and by how much (isk_refimg_summary's words)
 *                        and where the two files are.
 *   no reference         ISK_ERR_IO; writes OUT/NAME.actual.png and says how
 *                        to create the reference.
 *   update mode          (re)writes the reference from the canvas (creating
 *                        its directory) and returns ISK_OK: then look at it.
 *   bad arguments        ISK_ERR_NULL, ISK_ERR_SIZE (malformed canvas),
 *                        ISK_ERR_RANGE (a tolerance without a reason).
 *
 * OUT is opts->out_dir (created if missing), or the reference's own
 * directory when that is NULL.  Writing the actual and diff images goes
 * through iskra/outfile.h; a reference is never touched except in update
 * mode.
 *
 * Update mode is chosen per call by opts->update.  The default,
 * ISK_REFIMG_UPDATE_FROM_ENV, reads the environment variable
 * ISKRA_REFIMG_UPDATE at this call (never cached: nothing is remembered
 * between calls): set and not "0", it means update.  So
 *     ISKRA_REFIMG_UPDATE=1 ./my_tests
 * regenerates every reference your tests check.  A program that must not
 * depend on its environment says ISK_REFIMG_UPDATE_NEVER (or _ALWAYS).
 *
 * Tolerances are off by default.  A pixel counts as within tolerance when
 * none of its channels differs by more than max_channel_diff; the check
 * passes when at most max_differing pixels are outside it (the count is
 * isk_canvas_count_beyond's, iskra/canvas.h).  Setting either
 * requires `reason` (why exactness cannot hold here: "libm's exp differs
 * across platforms"), which failure messages repeat.
 */
#ifndef ISKRA_REFIMG_H
#define ISKRA_REFIMG_H

#include <stddef.h>

#include "iskra/canvas.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_refimg_update {
    ISK_REFIMG_UPDATE_FROM_ENV = 0, /* ISKRA_REFIMG_UPDATE, read at each call */
    ISK_REFIMG_UPDATE_NEVER,
    ISK_REFIMG_UPDATE_ALWAYS
} isk_refimg_update;

/* What a check found (fill opts->result to get it). */
typedef struct isk_refimg_result {
    int same_size;            /* 1 when the canvas and the reference have one size */
    int ref_width, ref_height; /* 0 when there was no reference */
    isk_canvas_diff diff;     /* all pixels compared (zero when sizes differ) */
    long beyond_tolerance;    /* pixels differing by more than max_channel_diff */
    int updated;              /* 1: update mode wrote the reference */
} isk_refimg_result;

typedef struct isk_refimg_opts {
    const char *out_dir;          /* NULL: the reference's directory */
    int max_channel_diff;         /* 0..255; 0: exact */
    long max_differing;           /* >= 0; pixels allowed beyond max_channel_diff */
    const char *reason;           /* required when a tolerance is set */
    isk_refimg_update update;     /* default: from the environment, per call */
    isk_refimg_result *result;    /* optional: receives the figures */
} isk_refimg_opts;

/* opts may be NULL (exact, out_dir = the reference's directory, update from
 * the environment).  See the top of this header for what happens. */
isk_status isk_refimg_check(const isk_canvas *c, const char *ref_path, const isk_refimg_opts *opts,
                            isk_error *err);

/* "N of M pixels differ, max channel difference D, mean absolute difference
 * F" — the words isk_refimg_check and `iskra compare` use.  Returns buf. */
char *isk_refimg_summary(const isk_canvas_diff *d, char *buf, size_t n);

#ifdef __cplusplus
}
#endif

#endif
