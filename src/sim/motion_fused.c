/* SPDX-License-Identifier: MIT */
/* Forces + integrator in one pass for the common case (see motion_fused.h):
 * motion_fused_loops.h's loops in the portable build, the choice of a
 * build, and the sound centre rule's fix-up. */
#include "sim/motion_fused.h"

#include <math.h>
#include <stdint.h>

#include "core/cpu.h" /* ISK__IF_AVX2, isk__simd_level */
#include "sim/kernels.h"
#include "sim/motion_fused_loops.h"

MOTION_FUSED_LOOPS(fused_, pot_, static)

/* Each build's tables, indexed by isk__simd_level: the portable loops,
 * then motion_fused_avx2.c's and motion_fused_avx512.c's where this build
 * has them. */
static const fused_fn fused_portable[2][16] = FUSED_TABLE(fused_);
static const pot_fn pot_portable[POT_MAX][8] = POT_TABLE(pot_);
static const fused_fn (*const fused_table[])[16] = {
    fused_portable, ISK__IF_AVX2(isk__fused_loops_avx2, ) ISK__IF_AVX512(isk__fused_loops_avx512, )};
static const pot_fn (*const pot_table[])[8] = {
    pot_portable, ISK__IF_AVX2(isk__pot_loops_avx2, ) ISK__IF_AVX512(isk__pot_loops_avx512, )};

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

/* The pass for forces whose laws it knows (the callers below check). */
static int fused(int simd, isk_integrator method, const isk_forces *f, size_t n, double *x, double *y, double *vx,
                 double *vy, const double *m, double dt, const isk_motion_start *start, int *nonfinite)
{
    const int E = method == ISK_INTEGRATE_EULER;
    if (!E && method != ISK_INTEGRATE_SEMI_EULER)
        return 0;
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

int isk__motion_fused_build(int simd, isk_integrator method, const isk_forces *f, size_t n, double *x, double *y,
                            double *vx, double *vy, const double *m, double dt, const isk_motion_start *start,
                            int *nonfinite)
{
    if (isk_forces_laws(f) & ~ISK__FUSED_LAWS)
        return 0; /* a law it does not know: the general path sums every law */
    return fused(simd, method, f, n, x, y, vx, vy, m, dt, start, nonfinite);
}

int isk__motion_fused(isk_integrator method, const isk_forces *f, unsigned laws, size_t n, double *x, double *y,
                      double *vx, double *vy, const double *m, double dt, const isk_motion_start *start,
                      int *nonfinite)
{
    if (laws & ~ISK__FUSED_LAWS)
        return 0; /* a law it does not know: the general path sums every law */
    return fused(2, method, f, n, x, y, vx, vy, m, dt, start, nonfinite);
}
