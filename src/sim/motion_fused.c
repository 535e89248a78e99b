/* SPDX-License-Identifier: MIT */
/* Forces + integrator in one pass for the common case (see motion_fused.h). */
#include "sim/motion_fused.h"

#include <math.h>
#include <stdint.h>

#include "raster/span_simd.h" /* ISK__SPAN_AVX2, ISK__AVX2_FN, isk__have_avx2 */
#include "sim/kernels.h"

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

/* Each combination in three builds: baseline x86-64 (SSE2, two lanes) and,
 * chosen at run time, AVX2 (four lanes) and AVX-512 (eight lanes and 32
 * registers).  The same IEEE operations in the same order in each (no FMA:
 * -ffp-contract=off holds in target functions too), so the same bits.  The
 * AVX-512 build pays in the loops with potentials: their sqrt and two
 * divisions keep many values alive, and the AVX2 build spills a third of
 * its operands to the stack (Coulomb 2.7 -> 2.1 ns a particle-step on a
 * Zen 4, bench_walls; docs/vectorization.md). */
#define FUSED_AS(name, attr, K, G, A, D, E)                                                                     \
    static attr uint64_t name(size_t n, double *restrict x, double *restrict y, double *restrict vx,           \
                              double *restrict vy, const double *restrict m,                                   \
                              const isk_motion_start *restrict sv, double g, double ax, double ay, double b,   \
                              double inv_h, double dt)                                                         \
    {                                                                                                            \
        return fused_loop(n, x, y, vx, vy, m, K ? sv->x : NULL, K ? sv->y : NULL, K ? sv->vx : NULL,            \
                          K ? sv->vy : NULL, g, ax, ay, b, inv_h, dt, K, G, A, D, E);                           \
    }
#define FUSED(K, G, A, D, E)                                                                                     \
    FUSED_AS(fused_##K##G##A##D##E, , K, G, A, D, E)                                                             \
    ISK__IF_AVX2(FUSED_AS(fused_avx2_##K##G##A##D##E, ISK__AVX2_FN, K, G, A, D, E))                              \
    ISK__IF_AVX512(FUSED_AS(fused_avx512_##K##G##A##D##E, ISK__AVX512_FN, K, G, A, D, E))
#define FUSED_K(K)                                                                                               \
    FUSED(K, 0, 0, 0, 0) FUSED(K, 0, 0, 0, 1) FUSED(K, 0, 0, 1, 0) FUSED(K, 0, 0, 1, 1)                         \
    FUSED(K, 0, 1, 0, 0) FUSED(K, 0, 1, 0, 1) FUSED(K, 0, 1, 1, 0) FUSED(K, 0, 1, 1, 1)                         \
    FUSED(K, 1, 0, 0, 0) FUSED(K, 1, 0, 0, 1) FUSED(K, 1, 0, 1, 0) FUSED(K, 1, 0, 1, 1)                         \
    FUSED(K, 1, 1, 0, 0) FUSED(K, 1, 1, 0, 1) FUSED(K, 1, 1, 1, 0) FUSED(K, 1, 1, 1, 1)
FUSED_K(0) FUSED_K(1)
#undef FUSED_K
#undef FUSED
#undef FUSED_AS

/* Indexed by [build][K][G*8 + A*4 + D*2 + E], build as isk__simd_level. */
#define ROW(p, K)                                                                                                \
    {                                                                                                            \
        p##K##0000, p##K##0001, p##K##0010, p##K##0011, p##K##0100, p##K##0101, p##K##0110, p##K##0111,          \
            p##K##1000, p##K##1001, p##K##1010, p##K##1011, p##K##1100, p##K##1101, p##K##1110, p##K##1111,      \
    }
static const fused_fn fused_table[1 + ISK__SPAN_AVX2 + ISK__SPAN_AVX512][2][16] = {
    {ROW(fused_, 0), ROW(fused_, 1)},
    ISK__IF_AVX2({ROW(fused_avx2_, 0), ROW(fused_avx2_, 1)},)
    ISK__IF_AVX512({ROW(fused_avx512_, 0), ROW(fused_avx512_, 1)},)
};
#undef ROW

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
 * the columns and left the loop scalar (14.6 ns a particle-step instead of
 * 3 with a Coulomb potential).  Stores in *over
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

/* The whole block stepped again from its old state, the sound rule as the
 * general path applies it (scalar code, one copy for every combination:
 * rare, a particle on or very near a potential, or a k*Q near the force
 * limit).  Returns the non-finite flag in bit 63 as the loops do. */
static uint64_t pot_fixup(size_t n, double *x, double *y, double *vx, double *vy, const double *m, const pot_par *p,
                          const isk_motion_start *sv, int np, int A, int D, int E)
{
    for (size_t i = 0; i < n; i++) {
        double o[4];
        pot_step(p, sv->x[i], sv->y[i], sv->vx[i], sv->vy[i], m[i], o, np, A, D, E, 1);
        x[i] = o[0];
        y[i] = o[1];
        vx[i] = o[2];
        vy[i] = o[3];
    }
    return (uint64_t)(isk_k_any_nonfinite2(n, x, y) | isk_k_any_nonfinite2(n, vx, vy)) << 63;
}

typedef uint64_t (*pot_fn)(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                           double *restrict vy, const double *restrict m, const pot_par *restrict p,
                           const isk_motion_start *restrict sv, uint64_t *over);

/* Each (NP, A, D, E) in each build, as the loops above. */
#define POT_AS(name, attr, NP, A, D, E)                                                                          \
    static attr uint64_t name(size_t n, double *restrict x, double *restrict y, double *restrict vx,           \
                              double *restrict vy, const double *restrict m, const pot_par *restrict p,        \
                              const isk_motion_start *restrict sv, uint64_t *over)                             \
    {                                                                                                            \
        return pot_loop(n, x, y, vx, vy, m, p, sv->x, sv->y, sv->vx, sv->vy, over, NP, A, D, E);                \
    }
#define POT(NP, A, D, E)                                                                                         \
    POT_AS(pot_##NP##A##D##E, , NP, A, D, E)                                                                     \
    ISK__IF_AVX2(POT_AS(pot_avx2_##NP##A##D##E, ISK__AVX2_FN, NP, A, D, E))                                      \
    ISK__IF_AVX512(POT_AS(pot_avx512_##NP##A##D##E, ISK__AVX512_FN, NP, A, D, E))
#define POT_NP(NP)                                                                                               \
    POT(NP, 0, 0, 0) POT(NP, 0, 0, 1) POT(NP, 0, 1, 0) POT(NP, 0, 1, 1)                                         \
    POT(NP, 1, 0, 0) POT(NP, 1, 0, 1) POT(NP, 1, 1, 0) POT(NP, 1, 1, 1)
POT_NP(1) POT_NP(2) POT_NP(3) POT_NP(4)
#undef POT_NP
#undef POT
#undef POT_AS

/* Indexed by [build][NP - 1][A*4 + D*2 + E], build as isk__simd_level. */
#define ROW(p, NP) {p##NP##000, p##NP##001, p##NP##010, p##NP##011, p##NP##100, p##NP##101, p##NP##110, p##NP##111}
#define ROWS(p) {ROW(p, 1), ROW(p, 2), ROW(p, 3), ROW(p, 4)}
static const pot_fn pot_table[1 + ISK__SPAN_AVX2 + ISK__SPAN_AVX512][POT_MAX][8] = {
    ROWS(pot_),
    ISK__IF_AVX2(ROWS(pot_avx2_),)
    ISK__IF_AVX512(ROWS(pot_avx512_),)
};
#undef ROWS
#undef ROW

/* The potentials that act, in the general path's order (forces.c's
 * isk_forces_eval_step and isk_force_potential): a disabled potential or
 * one with k*Q == 0 is skipped there and here.  Returns their number, or
 * -1 when the fused loop does not cover one of them (an exponent other
 * than 1 or 2: pow(); a max-distance switch, which depends on the order of
 * the particles and may switch the potential off; more than POT_MAX). */
static int pot_collect(const isk_forces *f, pot_par *p)
{
    const size_t np = f->pick ? f->npick : f->npot;
    int k = 0;
    for (size_t j = 0; j < np; j++) {
        const isk_potential *pot = &f->pot[f->pick ? f->pick[j] : j];
        if (!pot->enabled)
            continue;
        if (pot->max_dist > 0.0)
            return -1;
        const double s = 1.0 * (pot->charge * pot->k); /* isk_force_potential's s */
        if (s == 0.0)
            continue;
        if ((pot->P != 2.0 && pot->P != 1.0) || k == POT_MAX)
            return -1;
        p->cx[k] = pot->r.x;
        p->cy[k] = pot->r.y;
        p->s[k] = s;
        p->xm[k] = pot->x_mult;
        p->minv[k] = pot->min_dist;
        p->lo[k] = pot->P == 2.0 ? -INFINITY : 1.0; /* ISK_K_PW_12 */
        p->hi[k] = pot->P == 2.0 ? INFINITY : 1.0;
        k++;
    }
    return k;
}

/* The loop with potentials over n particles, a block at a time (the
 * size of the state kept for the fix-up: the caller's, or one here). */
static uint64_t pot_run(int simd, int np, int A, int D, int E, size_t n, double *x, double *y, double *vx,
                        double *vy, const double *m, const pot_par *p, const isk_motion_start *start)
{
    const pot_fn loop = pot_table[isk__simd_level(simd)][np - 1][A * 4 + D * 2 + E];
    double own[4][ISK_SIM_BLOCK];
    uint64_t acc = 0;
    for (size_t o = 0; o < n; o += ISK_SIM_BLOCK) {
        const size_t c = n - o < ISK_SIM_BLOCK ? n - o : ISK_SIM_BLOCK;
        const isk_motion_start sv = start ? (isk_motion_start){start->x + o, start->y + o, start->vx + o, start->vy + o}
                                          : (isk_motion_start){own[0], own[1], own[2], own[3]};
        uint64_t over;
        uint64_t a = loop(c, x + o, y + o, vx + o, vy + o, m + o, p, &sv, &over);
        if (over >> 63)
            a = pot_fixup(c, x + o, y + o, vx + o, vy + o, m + o, p, &sv, np, A, D, E);
        acc |= a;
    }
    return acc;
}

int isk__motion_fused_build(int simd, isk_integrator method, const isk_forces *f, size_t n, double *x, double *y,
                           double *vx, double *vy, const double *m, double dt, const isk_motion_start *start,
                           int *nonfinite)
{
    const int E = method == ISK_INTEGRATE_EULER;
    if (!E && method != ISK_INTEGRATE_SEMI_EULER)
        return 0;
    if (isk_forces_laws(f) & ~ISK__FUSED_LAWS)
        return 0; /* a law it does not know: the general path sums every law */
    pot_par p;
    const int np = pot_collect(f, &p);
    if (np < 0)
        return 0;
    /* The tests isk_forces_eval_step makes, with the step h = |dt|. */
    const int G = f->gravity != 0.0, A = f->ax != 0.0 || f->ay != 0.0, D = f->drag != 0.0;
    const double h = fabs(dt);
    if (D && !(h > 0.0))
        return 0; /* the unsaturated drag of a zero step: left to the general path */
    const double inv_h = D ? 1.0 / h : 0.0;
    uint64_t acc;
    if (np == 0) {
        /* No potential acts (or each one's k*Q is 0): the general path then
         * adds P = +0.0 at most, which changes no sum (never -0.0). */
        const fused_fn loop = fused_table[isk__simd_level(simd)][start != NULL][G * 8 + A * 4 + D * 2 + E];
        acc = loop(n, x, y, vx, vy, m, start, f->gravity, f->ax, f->ay, f->drag, inv_h, dt);
    } else {
        p.g = f->gravity;
        p.gm = G ? ~(uint64_t)0 : 0;
        p.ax = f->ax;
        p.ay = f->ay;
        p.b = f->drag;
        p.inv_h = inv_h;
        p.dt = dt;
        p.sm = f->centre == ISK_FIDELITY_SOUND ? ~(uint64_t)0 : 0;
        acc = pot_run(simd, np, A, D, E, n, x, y, vx, vy, m, &p, start);
    }
    *nonfinite = (int)(acc >> 63);
    return 1;
}

int isk__motion_fused(isk_integrator method, const isk_forces *f, size_t n, double *x, double *y, double *vx,
                     double *vy, const double *m, double dt, const isk_motion_start *start, int *nonfinite)
{
    return isk__motion_fused_build(2, method, f, n, x, y, vx, vy, m, dt, start, nonfinite);
}
