/* SPDX-License-Identifier: MIT */
/* src/sim/motion_fused_loops.h — the fused motion loops (internal), which
 * motion_fused.c compiles for every CPU and motion_fused_avx2.c,
 * motion_fused_avx512.c for AVX2 and AVX-512 (see motion_fused.h):
 *
 *     MOTION_FUSED_LOOPS(fused_, pot_, static)
 *     static const fused_fn fused[2][16] = FUSED_TABLE(fused_);
 *     static const pot_fn pot[POT_MAX][8] = POT_TABLE(pot_);
 *
 * defines one function per combination of the compile-time flags, tabled
 * [K][G*8 + A*4 + D*2 + E] and [NP - 1][A*4 + D*2 + E].  Every build does
 * the same IEEE operations in the same order (no FMA: -ffp-contract=off
 * holds in target functions too), so the same bits.  The wider builds pay
 * in the loops with potentials: their sqrt and two divisions keep many
 * values alive, and the AVX2 build spills a third of its operands to the
 * stack where AVX-512's 32 registers do not (docs/vectorization.md). */
#ifndef ISKRA_SIM_MOTION_FUSED_LOOPS_H
#define ISKRA_SIM_MOTION_FUSED_LOOPS_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "core/cpu.h"
#include "sim/kernels.h"
#include "sim/motion_fused.h"

/* One particle-step as the general path computes it, specialised by the
 * compile-time flags G (gravity), A (constant acceleration), D (linear drag,
 * saturated at m/|dt|) and E (explicit Euler, else semi-implicit).  Each
 * force is added to the sums in forces.c's order: gravity, acceleration,
 * drag.  K (compile-time too): store the state each particle starts from
 * in kx..kvy as it is read (the contact stages' start, isk_motion_start),
 * in the same pass, so the arithmetic overlaps the reads from memory; the
 * Makefile keeps gcc from hoisting these stores out as memcpy calls
 * (GCC_NO_COPY_IDIOM), which made them a pass of their own again.
 * Returns the or-ed non-finite bits of the four new values. */
static ISK__INLINE uint64_t fused_loop(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                                       double *restrict vy, const double *restrict m, double *restrict kx,
                                       double *restrict ky, double *restrict kvx, double *restrict kvy, double g,
                                       double ax, double ay, double b, double inv_h, double dt, const int K,
                                       const int G, const int A, const int D, const int E)
{
    uint64_t acc = 0;
    for (size_t i = 0; i < n; i++) {
        const double mi = m[i];
        double ux = vx[i], uy = vy[i];
        double px = x[i], py = y[i];
        if (K) {
            kx[i] = px;
            ky[i] = py;
            kvx[i] = ux;
            kvy[i] = uy;
        }
        double fx = 0.0, fy = 0.0; /* memset's +0.0 */
        if (G)
            fy = fy + isk_k_gravity_fy(mi, g);
        if (A) {
            fx = fx + mi * ax;
            fy = fy + mi * ay;
        }
        if (D) {
            ux = isk_k_flush(ux);
            uy = isk_k_flush(uy);
            const double lim = mi * inv_h, be = isless(lim, b) ? lim : b;
            fx = fx + isk_k_drag(ux, be);
            fy = fy + isk_k_drag(uy, be);
        }
        if (E)
            isk_k_euler(&px, &py, &ux, &uy, mi, fx, fy, dt);
        else
            isk_k_semi_euler(&px, &py, &ux, &uy, mi, fx, fy, dt);
        x[i] = px;
        y[i] = py;
        vx[i] = ux;
        vy[i] = uy;
        acc |= (isk_k_nonfinite_bits(px) | isk_k_nonfinite_bits(py)) |
               (isk_k_nonfinite_bits(ux) | isk_k_nonfinite_bits(uy));
    }
    return acc;
}

typedef uint64_t (*fused_fn)(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                             double *restrict vy, const double *restrict m, const isk_motion_start *restrict sv,
                             double g, double ax, double ay, double b, double inv_h, double dt);

#define FUSED_AS(name, attr, K, G, A, D, E)                                                                     \
    attr uint64_t name(size_t n, double *restrict x, double *restrict y, double *restrict vx,                  \
                       double *restrict vy, const double *restrict m, const isk_motion_start *restrict sv,     \
                       double g, double ax, double ay, double b, double inv_h, double dt)                     \
    {                                                                                                            \
        return fused_loop(n, x, y, vx, vy, m, K ? sv->x : NULL, K ? sv->y : NULL, K ? sv->vx : NULL,            \
                          K ? sv->vy : NULL, g, ax, ay, b, inv_h, dt, K, G, A, D, E);                           \
    }
#define FUSED(P, attr, K, G, A, D, E) FUSED_AS(P##K##G##A##D##E, attr, K, G, A, D, E)
#define FUSED_K(P, attr, K)                                                                                      \
    FUSED(P, attr, K, 0, 0, 0, 0) FUSED(P, attr, K, 0, 0, 0, 1) FUSED(P, attr, K, 0, 0, 1, 0)                   \
    FUSED(P, attr, K, 0, 0, 1, 1) FUSED(P, attr, K, 0, 1, 0, 0) FUSED(P, attr, K, 0, 1, 0, 1)                   \
    FUSED(P, attr, K, 0, 1, 1, 0) FUSED(P, attr, K, 0, 1, 1, 1) FUSED(P, attr, K, 1, 0, 0, 0)                   \
    FUSED(P, attr, K, 1, 0, 0, 1) FUSED(P, attr, K, 1, 0, 1, 0) FUSED(P, attr, K, 1, 0, 1, 1)                   \
    FUSED(P, attr, K, 1, 1, 0, 0) FUSED(P, attr, K, 1, 1, 0, 1) FUSED(P, attr, K, 1, 1, 1, 0)                   \
    FUSED(P, attr, K, 1, 1, 1, 1)
#define FUSED_ROW(p, K)                                                                                          \
    {                                                                                                            \
        p##K##0000, p##K##0001, p##K##0010, p##K##0011, p##K##0100, p##K##0101, p##K##0110, p##K##0111,          \
            p##K##1000, p##K##1001, p##K##1010, p##K##1011, p##K##1100, p##K##1101, p##K##1110, p##K##1111,      \
    }
#define FUSED_TABLE(p) {FUSED_ROW(p, 0), FUSED_ROW(p, 1)}

/* ---- with potentials ----------------------------------------------------- */

/* Up to four potentials act in the fused loop (the thesis's scenes have at
 * most four: figure 29); more are left to the general path. */
enum { POT_MAX = 4 };

/* Everything the loops with potentials read besides the columns, fixed for
 * the call.  Masks instead of more copies of the loop: gravity's term is
 * and-ed with gm (+0.0 when g == 0: a term the general path leaves out, but
 * +0.0 added to these sums changes nothing, see pot_step), the sound
 * centre rule's test with sm, and each potential's exponent (2 or 1) is
 * its clamp (lo, hi) of kernels.h's ISK_K_PW_12. */
typedef struct pot_par {
    double g, ax, ay, b, inv_h, dt;
    uint64_t gm, sm;
    double cx[POT_MAX], cy[POT_MAX], s[POT_MAX], xm[POT_MAX], minv[POT_MAX], lo[POT_MAX], hi[POT_MAX];
} pot_par;

/* One particle-step with np potentials, the general path's operations:
 * F = (gravity + accel + drag) + P in forces.c's order, with
 * P = (+0.0 + pot_1) + pot_2 ..., then the integrator; the new x, y, vx, vy
 * in o.  One liberty, exact: F's sums start from their first term instead
 * of from +0.0.  A sum a + b is -0.0 only when a and b both are (IEEE,
 * round to nearest), so a chain of sums started from its first term has
 * the bits of the same chain started from +0.0 unless every term is -0.0;
 * F's last term, P, is never -0.0 (its own sum starts from +0.0), so F's
 * bits are the same and two additions go.
 * FIX = 0 (the vector loop): the law's forces as they are; returns a word
 * whose top bit is set when the sound rule (sm) would replace some force,
 * and then o is not the general path's.  FIX = 1 (pot_fixup): the sound
 * rule applied as the general path does: the force replaced by +0.0 and,
 * right after it, the saturated force added (that path's second pass). */
static ISK__INLINE uint64_t pot_step(const pot_par *restrict p, double x0, double y0, double vx0, double vy0,
                                     double mi, double o[4], const int np, const int A, const int D, const int E,
                                     const int FIX)
{
    double ux = vx0, uy = vy0;
    double fx = 0.0, fy = isk_k_keep(isk_k_gravity_fy(mi, p->g), p->gm);
    if (A) {
        fx = mi * p->ax;
        fy = fy + mi * p->ay;
    }
    if (D) {
        ux = isk_k_flush(ux);
        uy = isk_k_flush(uy);
        const double lim = mi * p->inv_h, be = isless(lim, p->b) ? lim : p->b;
        fx = A ? fx + isk_k_drag(ux, be) : isk_k_drag(ux, be);
        fy = fy + isk_k_drag(uy, be);
    }
    double sx = 0.0, sy = 0.0; /* the potentials' sums (the general path's memset) */
    uint64_t over = 0;
    for (int k = 0; k < np; k++) {
        double gx, gy;
        isk_k_coulomb_law(p->cx[k], p->cy[k], x0, y0, p->s[k], p->xm[k], p->minv[k], 0.0, ISK_K_PW_12, p->lo[k],
                          p->hi[k], &gx, &gy);
        if (!FIX) {
            over |= isk_k_force_over(gx, gy);
            sx = sx + gx;
            sy = sy + gy;
            continue;
        }
        const uint64_t keep = isk_k_force_keep(gx, gy) | ~p->sm;
        sx = sx + isk_k_keep(gx, keep);
        sy = sy + isk_k_keep(gy, keep);
        if (!(keep & 1u)) {
            isk_k_coulomb_saturated(p->cx[k], p->cy[k], x0, y0, p->s[k], p->xm[k], &gx, &gy);
            sx = sx + gx;
            sy = sy + gy;
        }
    }
    fx = A || D ? fx + sx : sx;
    fy = fy + sy;
    double px = x0, py = y0;
    if (E)
        isk_k_euler(&px, &py, &ux, &uy, mi, fx, fy, p->dt);
    else
        isk_k_semi_euler(&px, &py, &ux, &uy, mi, fx, fy, p->dt);
    o[0] = px;
    o[1] = py;
    o[2] = ux;
    o[3] = uy;
    return over & p->sm;
}

/* The loop: NP potentials, A constant acceleration, D drag, E explicit
 * Euler, all compile-time.  Stores the state a particle starts the step
 * from in kx..kvy as it reads it: for the fix-up, and as the contact
 * stages' start state when the caller asks for it (isk_motion_start: the
 * remember stage's copy without a pass of its own).  As four restrict
 * parameters: through a struct's pointers gcc could not tell the copy from
 * the columns and left the loop scalar (docs/performance.md, "Where the constants come from").  Stores in *over
 * the or of pot_step's words: when its top bit is set some force did not
 * survive the sound rule, and the caller redoes the block (pot_fixup).
 * Returns the or-ed non-finite bits: of the four new values for explicit
 * Euler; of x and y alone for semi-implicit Euler, where x' = x + dt*v' is
 * not finite whenever v' is not (dt*inf is infinite, or NaN for dt = 0),
 * so the two say what the four would. */
static ISK__INLINE uint64_t pot_loop(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                                     double *restrict vy, const double *restrict m, const pot_par *restrict p,
                                     double *restrict kx, double *restrict ky, double *restrict kvx,
                                     double *restrict kvy, uint64_t *over, const int NP, const int A, const int D,
                                     const int E)
{
    uint64_t acc = 0, ov = 0;
    for (size_t i = 0; i < n; i++) {
        const double x0 = x[i], y0 = y[i], vx0 = vx[i], vy0 = vy[i];
        kx[i] = x0;
        ky[i] = y0;
        kvx[i] = vx0;
        kvy[i] = vy0;
        double o[4];
        ov |= pot_step(p, x0, y0, vx0, vy0, m[i], o, NP, A, D, E, 0);
        x[i] = o[0];
        y[i] = o[1];
        vx[i] = o[2];
        vy[i] = o[3];
        acc |= isk_k_nonfinite_bits(o[0]) | isk_k_nonfinite_bits(o[1]);
        if (E)
            acc |= isk_k_nonfinite_bits(o[2]) | isk_k_nonfinite_bits(o[3]);
    }
    *over = ov;
    return acc;
}

typedef uint64_t (*pot_fn)(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                           double *restrict vy, const double *restrict m, const pot_par *restrict p,
                           const isk_motion_start *restrict sv, uint64_t *over);

#define POT_AS(name, attr, NP, A, D, E)                                                                          \
    attr uint64_t name(size_t n, double *restrict x, double *restrict y, double *restrict vx,                  \
                       double *restrict vy, const double *restrict m, const pot_par *restrict p,               \
                       const isk_motion_start *restrict sv, uint64_t *over)                                    \
    {                                                                                                            \
        return pot_loop(n, x, y, vx, vy, m, p, sv->x, sv->y, sv->vx, sv->vy, over, NP, A, D, E);                \
    }
#define POT(P, attr, NP, A, D, E) POT_AS(P##NP##A##D##E, attr, NP, A, D, E)
#define POT_NP(P, attr, NP)                                                                                      \
    POT(P, attr, NP, 0, 0, 0) POT(P, attr, NP, 0, 0, 1) POT(P, attr, NP, 0, 1, 0) POT(P, attr, NP, 0, 1, 1)     \
    POT(P, attr, NP, 1, 0, 0) POT(P, attr, NP, 1, 0, 1) POT(P, attr, NP, 1, 1, 0) POT(P, attr, NP, 1, 1, 1)
#define POT_ROW(p, NP) {p##NP##000, p##NP##001, p##NP##010, p##NP##011, p##NP##100, p##NP##101, p##NP##110, p##NP##111}
#define POT_TABLE(p) {POT_ROW(p, 1), POT_ROW(p, 2), POT_ROW(p, 3), POT_ROW(p, 4)}

/* Every loop of one build: the fused ones named FP.., those with
 * potentials PP.., each function declared with attr. */
#define MOTION_FUSED_LOOPS(FP, PP, attr)                                                                         \
    FUSED_K(FP, attr, 0) FUSED_K(FP, attr, 1)                                                                    \
    POT_NP(PP, attr, 1) POT_NP(PP, attr, 2) POT_NP(PP, attr, 3) POT_NP(PP, attr, 4)

#if ISK__CPU_AVX2
/* motion_fused_avx2.c's tables, for a CPU that has AVX2 */
extern const fused_fn isk__fused_loops_avx2[2][16];
extern const pot_fn isk__pot_loops_avx2[POT_MAX][8];
#endif
#if ISK__CPU_AVX512
/* motion_fused_avx512.c's tables, for a CPU that has AVX-512 */
extern const fused_fn isk__fused_loops_avx512[2][16];
extern const pot_fn isk__pot_loops_avx512[POT_MAX][8];
#endif

#endif
