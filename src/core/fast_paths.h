/* SPDX-License-Identifier: MIT */
/* src/core/fast_paths.h — every fast path of the library, declared in one
 * place (internal).
 *
 * A fast path gives exactly the bytes of a plain reference path, only
 * sooner; the tests compare the two.  Each has one switch here, and the
 * code tests it where the fast path leaves the plain one (a seam):
 *
 *     if (ISK__FAST_FUSED && isk__motion_fused(...)) return;   // the fast path
 *     ...                                                      // the reference
 *
 * `make test REFERENCE=1` builds with ISKRA_REFERENCE defined: every switch
 * is 0, no fast path runs, and the whole suite passes against the same
 * reference images.  That build is the one to read first:
 * docs/architecture.md has the reading guide, and docs/performance.md what
 * each fast path buys.
 *
 *   switch              what runs with it (file)                        the reference
 *   ISK__FAST_WORKERS   blocks and bands on several threads, or a       everything on the caller,
 *                       caller's job system (sim/workers.c)             in order
 *   ISK__FAST_BANDS     a draw cut into bands of rows or columns,       each group drawn whole
 *                       sorted, split, in copies (scene/effect_bands.c)
 *   ISK__FAST_RETAIN    a group at rest drawn from recorded blends      drawn again
 *                       (scene/effect_retain.c)
 *   ISK__FAST_REST      blocks at rest skip their motion (sim/rest.c)   every stage on every block
 *   ISK__FAST_BATCH     coverage dots in blocks of 8 with a coverage    one dot at a time
 *                       table (view/world_batch.c)
 *   ISK__FAST_FUSED     forces and integrator in one pass               the force sum, then the
 *                       (sim/motion_fused.c); drift, slow and sway in   integrator; one stage each
 *                       one stage (sim/stage_fire.c)
 *   ISK__FAST_CULL      a wide trail's tiles skip the segments that     every segment at every
 *                       are nearest to none of their pixels             pixel
 *                       (raster/trail.c)
 * Instruction-set code (SSE2, AVX2, AVX-512 twins of portable loops) has
 * its own switch in the same spirit: src/core/cpu.h. */
#ifndef ISKRA_CORE_FAST_PATHS_H
#define ISKRA_CORE_FAST_PATHS_H

#if defined(ISKRA_REFERENCE)
#define ISK__FAST 0
#else
#define ISK__FAST 1
#endif

#define ISK__FAST_WORKERS ISK__FAST
#define ISK__FAST_BANDS ISK__FAST
#define ISK__FAST_RETAIN ISK__FAST
#define ISK__FAST_REST ISK__FAST
#define ISK__FAST_BATCH ISK__FAST
#define ISK__FAST_FUSED ISK__FAST
#define ISK__FAST_CULL ISK__FAST

#endif
