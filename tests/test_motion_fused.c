/* SPDX-License-Identifier: MIT */
/* The fused motion pass (src/sim/motion_fused.h) against the general path
 * (isk_integrate_block, then the runner's non-finite checks): the same bits
 * of x, y, vx, vy and the same non-finite flag, for semi-implicit and
 * explicit Euler under every combination of gravity, constant acceleration
 * and linear drag, on random states with the edge cases mixed in: signed
 * zeros, velocities that flush (below ISK_FLUSH_TINY) or just escape it,
 * masses tiny enough to saturate the drag at m/|dt|, huge and zero masses,
 * infinities and NaNs; steps of both signs; every tail length of a block.
 * Both builds (portable and, where the CPU has it, AVX2).  Also: it declines (and touches nothing) where it does not apply.
 *
 * With potentials (the loops that sum up to four Coulomb potentials, P = 2
 * or 1, in the same pass): 1 to 4 acting potentials among disabled ones and
 * ones whose k*Q is 0, all of them or a pick list (in its order, one picked
 * twice), both centre rules, with and without a min distance, x_mult != 1,
 * charges of both signs, particles exactly on a centre and so near one that
 * the sound rule saturates the force (the general path's second pass,
 * redone here by the fix-up), huge k*Q (every force saturates); more than a
 * block at once (the fix-up of a later block).  What it leaves to the
 * general path (other exponents, a max distance, a fifth potential) it
 * declines, touching nothing. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "core/cpu.h" /* isk__simd_level */
#include "iskra/integrate.h"
#include "sim/kernels.h"
#include "sim/motion_fused.h"

enum { N = ISK_SIM_BLOCK };

static uint64_t lcg(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return *s >> 11;
}

static double unit(uint64_t *s) { return (double)lcg(s) / 9007199254740992.0; } /* [0, 1) */

/* Mostly ordinary, sometimes one of `special` (a value from the list). */
static double pick(uint64_t *s, double lo, double hi, const double *special, size_t nspecial)
{
    if (lcg(s) % 4 == 0)
        return special[lcg(s) % nspecial];
    return lo + (hi - lo) * unit(s);
}

static const double POS_SPECIAL[] = {0.0, -0.0, 1e300, -1e300, 5e-324, INFINITY, -INFINITY, NAN};
static const double VEL_SPECIAL[] = {0.0,     -0.0,    1e-200, -1e-200, 9.9e-201, -9.9e-201, 1.0000001e-200,
                                     5e-324,  -5e-324, 1e-300, 1e250,   -1e250,   INFINITY,  -INFINITY, NAN};
static const double MASS_SPECIAL[] = {1e-300, 1e-5, 1e-3, 1e300, 0.0, -0.0, 5e-324, INFINITY, NAN};

typedef struct state {
    double x[N], y[N], vx[N], vy[N], m[N];
} state;

static void fill(state *st, uint64_t *s, int finite)
{
    const size_t np = finite ? 6 : 8, nv = finite ? 12 : 15, nm = finite ? 4 : 9;
    for (size_t i = 0; i < N; i++) {
        st->x[i] = pick(s, -10, 10, POS_SPECIAL, np);
        st->y[i] = pick(s, -10, 10, POS_SPECIAL, np);
        st->vx[i] = pick(s, -5, 5, VEL_SPECIAL, nv);
        st->vy[i] = pick(s, -5, 5, VEL_SPECIAL, nv);
        st->m[i] = pick(s, 0.5, 2, MASS_SPECIAL, nm);
    }
}

/* Equal bits, or both NaN: C leaves a NaN's sign and payload open, and the
 * compiler may swap the operands of a commutative operation (which NaN
 * wins), so only "not a number" is part of the contract. */
static int same(double a, double b)
{
    if (isnan(a) && isnan(b))
        return 1;
    return memcmp(&a, &b, sizeof a) == 0;
}

static isk_scratch scratch;

static void compare(isk_integrator method, const isk_forces *f, const state *in, size_t n, double dt,
                    const char *what)
{
    static state a, b;
    a = *in;
    isk_forces fg = *f;
    isk_integrate_block(method, &fg, &scratch, n, a.x, a.y, a.vx, a.vy, a.m, dt);
    const int want = isk_k_any_nonfinite2(n, a.x, a.y) | isk_k_any_nonfinite2(n, a.vx, a.vy);
    /* keep = 1: the start state stored on the way (the remember stage's
     * copy in the same pass), the bits of the input, and the step's bits
     * unchanged by it */
    for (int run = 0; run < 2 * (1 + isk__simd_level(2)); run++) {
        const int simd = run >> 1, keep = run & 1;
        static state kept;
        memset(&kept, 0x5a, sizeof kept);
        const isk_motion_start start = {kept.x, kept.y, kept.vx, kept.vy};
        b = *in;
        int got = -1;
        cr_assert_eq(isk__motion_fused_build(simd, method, f, n, b.x, b.y, b.vx, b.vy, b.m, dt, keep ? &start : NULL,
                                            &got),
                     1, "%s: declined", what);
        cr_assert_eq(got, want, "%s, n %zu, simd %d: non-finite flag %d, general path %d", what, n, simd, got, want);
        if (keep)
            cr_assert(memcmp(kept.x, in->x, n * sizeof *kept.x) == 0 && memcmp(kept.y, in->y, n * sizeof *kept.y) == 0 &&
                          memcmp(kept.vx, in->vx, n * sizeof *kept.vx) == 0 &&
                          memcmp(kept.vy, in->vy, n * sizeof *kept.vy) == 0,
                      "%s, n %zu, simd %d: the kept start state is not the input", what, n, simd);
        const double *const ga[4] = {a.x, a.y, a.vx, a.vy}, *const fa[4] = {b.x, b.y, b.vx, b.vy};
        for (int c = 0; c < 4; c++)
            for (size_t i = 0; i < n; i++)
                cr_assert(same(fa[c][i], ga[c][i]), "%s, n %zu, dt %g, simd %d: column %d particle %zu: %a, general %a",
                          what, n, dt, simd, c, i, fa[c][i], ga[c][i]);
        for (size_t i = n; i < N; i++) /* nothing beyond the block */
            cr_assert(same(b.x[i], in->x[i]) && same(b.vy[i], in->vy[i]), "%s: wrote past n", what);
    }
}

Test(motion_fused, same_bits_as_the_general_path)
{
    static const isk_integrator methods[2] = {ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_EULER};
    static const double dts[] = {1.0 / 600, -1.0 / 600, 0.1, 1e-3, 0.0};
    static const double drags[] = {0.47, 5.0, -0.3};
    static state in;
    uint64_t seed = 12;
    int runs = 0;
    for (int round = 0; round < 6; round++) {
        fill(&in, &seed, round % 2 == 0);
        for (int mi = 0; mi < 2; mi++)
            for (int combo = 0; combo < 8; combo++)
                for (size_t di = 0; di < sizeof dts / sizeof dts[0]; di++) {
                    const int G = combo >> 2 & 1, A = combo >> 1 & 1, D = combo & 1;
                    if (D && dts[di] == 0.0)
                        continue; /* declined: below */
                    isk_forces f = {0};
                    f.gravity = G ? (round == 3 ? -9.81 : 9.81) : 0.0;
                    f.ax = A ? (round == 1 ? 0.0 : 0.7) : 0.0; /* (0, ay): the acceleration's y alone */
                    f.ay = A ? -2.5 : 0.0;
                    f.drag = D ? drags[round % 3] : 0.0;
                    char what[96];
                    snprintf(what, sizeof what, "%s G%d A%d D%d round %d", isk_integrator_name(methods[mi]), G, A,
                             D, round);
                    compare(methods[mi], &f, &in, N, dts[di], what);
                    compare(methods[mi], &f, &in, 1 + (size_t)(lcg(&seed) % 37), dts[di], what);
                    runs++;
                }
    }
    cr_assert_gt(runs, 300);
}

/* A flag that must come on: one NaN velocity, or a step that overflows. */
Test(motion_fused, flags_the_non_finite)
{
    static state in;
    for (size_t i = 0; i < N; i++) {
        in.x[i] = (double)i / 32;
        in.y[i] = 10 - (double)i / 32;
        in.vx[i] = (double)(i % 11) - 5;
        in.vy[i] = (double)(i % 7) - 3;
        in.m[i] = 1 + (double)(i % 5) / 4;
    }
    isk_forces f = {.gravity = 9.81, .drag = 0.47};
    int nf = -1;
    static state b;
    b = in;
    cr_assert(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 1.0 / 600, NULL, &nf));
    cr_assert_eq(nf, 0, "a finite state of ordinary masses stays finite");
    b = in;
    b.vy[77] = NAN;
    cr_assert(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 1.0 / 600, NULL, &nf));
    cr_assert_eq(nf, 1);
    b = in;
    b.x[N * 25 / 32] = 1.7e308; /* some particle in the last quarter */
    b.vx[N * 25 / 32] = 1e308;
    cr_assert(isk__motion_fused(ISK_INTEGRATE_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.1, NULL, &nf));
    cr_assert_eq(nf, 1, "x + dt*vx overflows to infinity");
}

/* Other integrators, a zero step with drag: 0, and the block is
 * untouched.  A potential (P = 2, no max distance) is fused; a disabled
 * potential, or a pick of none, does not act: fused too.  (The declines
 * that potentials bring: potentials_declined_or_taken below.) */
Test(motion_fused, declines_what_it_does_not_cover)
{
    static state in, b;
    uint64_t seed = 9;
    fill(&in, &seed, 1);
    isk_potential pot;
    isk_potential_init(&pot, 1.0, (isk_vec2){1, 1}, 1.0);
    isk_forces f = {.gravity = 9.81, .drag = 0.47};
    int nf;
    for (int m = ISK_INTEGRATE_VERLET; m < ISK_INTEGRATOR_COUNT; m++) {
        b = in;
        cr_assert_eq(isk__motion_fused((isk_integrator)m, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.01, NULL, &nf), 0);
        cr_assert(memcmp(&b, &in, sizeof b) == 0);
    }
    cr_assert_eq(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.0, NULL, &nf), 0);
    cr_assert(memcmp(&b, &in, sizeof b) == 0);
    f.pot = &pot;
    f.npot = 1;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "one potential");
    const size_t none = 0;
    f.pick = &none; /* picks no potential: none acts */
    f.npick = 0;
    cr_assert_eq(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.01, NULL, &nf), 1);
    f.pick = NULL;
    pot.enabled = 0;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "disabled potential");
}

/* ---- with potentials ------------------------------------------------------- */

enum { NPOT = 6 }; /* room for 4 acting + disabled / k*Q == 0 ones */

typedef struct pot_case {
    isk_potential pot[NPOT];
    size_t npot, pick[8], npick;
    int use_pick;
} pot_case;

/* A random potential: k*Q of both signs (sometimes huge: every force
 * saturates under the sound rule), P 2 or 1, min distance off (-1 or 0) or
 * on, x_mult 1 or not, its centre in the box or on particle `on` of st. */
static void random_pot(isk_potential *pot, uint64_t *s, const state *st)
{
    static const double K[] = {1.0, 0.5, 3.0, 1e300};
    static const double Q[] = {1.0, -2.0, 0.25, -1.0};
    static const double MIN[] = {ISK_DIST_OFF, ISK_DIST_OFF, 0.0, 0.5, 1e-3};
    static const double XM[] = {1.0, 1.0, 0.3, -2.0};
    isk_vec2 r = {-10 + 20 * unit(s), -10 + 20 * unit(s)};
    if (lcg(s) % 3 == 0) { /* on a particle (ordinary or special) */
        size_t i = (size_t)(lcg(s) % N);
        if (isfinite(st->x[i]) && isfinite(st->y[i]) && fabs(st->x[i]) < 1e6 && fabs(st->y[i]) < 1e6)
            r = (isk_vec2){st->x[i], st->y[i]};
    }
    isk_potential_init(pot, K[lcg(s) % 4], r, Q[lcg(s) % 4]);
    pot->P = lcg(s) % 2 ? 2.0 : 1.0;
    pot->min_dist = MIN[lcg(s) % 5];
    pot->x_mult = XM[lcg(s) % 4];
}

/* `acting` potentials that act (1..4), in random order among up to two
 * that do not (disabled, or charge 0); every third case through a pick list
 * that names one of the acting potentials twice when there is room. */
static void random_case(pot_case *c, uint64_t *s, const state *st, int acting)
{
    memset(c, 0, sizeof *c);
    const int idle = (int)(lcg(s) % 3);
    int a = 0, b = 0;
    while (a < acting || b < idle) {
        isk_potential *pot = &c->pot[c->npot++];
        random_pot(pot, s, st);
        if (b < idle && (a == acting || lcg(s) % 2)) {
            if (lcg(s) % 2)
                pot->enabled = 0;
            else
                pot->charge = 0.0;
            if (lcg(s) % 2)
                pot->P = 3.0; /* not acting, so not a reason to decline */
            b++;
        } else {
            a++;
        }
    }
    c->use_pick = lcg(s) % 3 == 0;
    if (c->use_pick) {
        for (size_t k = c->npot; k-- > 0;) /* reverse order */
            c->pick[c->npick++] = k;
        if (acting < 4) { /* an acting one twice */
            for (size_t k = 0; k < c->npot; k++)
                if (c->pot[k].enabled && c->pot[k].charge != 0.0) {
                    c->pick[c->npick++] = k;
                    break;
                }
        }
    }
}

/* Some particles onto the centres: exactly, or offset by a hair (the law's
 * force overflows or is far beyond ISK_FORCE_LIMIT for P = 2; 0/0 on the
 * centre without a min distance). */
static void onto_centres(state *st, uint64_t *s, const pot_case *c)
{
    static const double HAIR[] = {0.0, 0.0, 1e-160, -1e-300, 5e-324, 1e-7};
    for (int j = 0; j < 6; j++) {
        const isk_potential *pot = &c->pot[lcg(s) % c->npot];
        const size_t i = (size_t)(lcg(s) % N);
        st->x[i] = pot->r.x + HAIR[lcg(s) % 6];
        st->y[i] = pot->r.y + (lcg(s) % 2 ? 0.0 : HAIR[lcg(s) % 6]);
    }
}

static void apply_case(isk_forces *f, pot_case *c)
{
    f->pot = c->pot;
    f->npot = c->npot;
    f->pick = c->use_pick ? c->pick : NULL;
    f->npick = c->use_pick ? c->npick : 0;
}

Test(motion_fused, potentials_same_bits_as_the_general_path)
{
    static const isk_integrator methods[2] = {ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_EULER};
    static const double dts[] = {1.0 / 600, -1.0 / 600, 0.1, 0.0};
    static state in;
    static pot_case pc;
    uint64_t seed = 29;
    int runs = 0;
    for (int round = 0; round < 16; round++) {
        fill(&in, &seed, round % 2 == 0);
        random_case(&pc, &seed, &in, 1 + round % 4);
        onto_centres(&in, &seed, &pc);
        for (int centre = 0; centre < 2; centre++)
            for (int mi = 0; mi < 2; mi++)
                for (int combo = 0; combo < 8; combo++)
                    for (size_t di = 0; di < sizeof dts / sizeof dts[0]; di++) {
                        const int G = combo >> 2 & 1, A = combo >> 1 & 1, D = combo & 1;
                        if (D && dts[di] == 0.0)
                            continue;
                        isk_forces f = {0};
                        f.gravity = G ? 9.81 : 0.0;
                        f.ax = A ? (round % 3 == 0 ? 0.0 : 0.7) : 0.0;
                        f.ay = A ? -2.5 : 0.0;
                        f.drag = D ? (round % 4 == 1 ? 5.0 : 0.47) : 0.0;
                        f.centre = centre ? ISK_FIDELITY_THESIS : ISK_FIDELITY_SOUND;
                        apply_case(&f, &pc);
                        char what[128];
                        snprintf(what, sizeof what, "%s G%d A%d D%d %s, %zu potentials%s, round %d",
                                 isk_integrator_name(methods[mi]), G, A, D, isk_fidelity_names[f.centre], pc.npot,
                                 pc.use_pick ? " (picked)" : "", round);
                        compare(methods[mi], &f, &in, N, dts[di], what);
                        compare(methods[mi], &f, &in, 1 + (size_t)(lcg(&seed) % 37), dts[di], what);
                        runs++;
                    }
    }
    cr_assert_gt(runs, 1500);
}

/* The same over more than a block in one call (the fused pass steps it a
 * block at a time: a fix-up in the second or third block), against the
 * general path block by block. */
Test(motion_fused, potentials_beyond_a_block)
{
    enum { M = 2 * N + 77 };
    static double x[M], y[M], vx[M], vy[M], m[M], gx[M], gy[M], gvx[M], gvy[M];
    static pot_case pc;
    static state one;
    uint64_t seed = 31;
    for (int round = 0; round < 4; round++) {
        for (size_t o = 0; o < M; o += N) { /* three blocks' worth of random state */
            fill(&one, &seed, 1);
            const size_t c = M - o < N ? M - o : N;
            memcpy(x + o, one.x, c * sizeof *x);
            memcpy(y + o, one.y, c * sizeof *y);
            memcpy(vx + o, one.vx, c * sizeof *vx);
            memcpy(vy + o, one.vy, c * sizeof *vy);
            memcpy(m + o, one.m, c * sizeof *m);
        }
        random_case(&pc, &seed, &one, 1 + round);
        /* on a centre: in the second block, then the third (N + 3 ... M - 1 for any N) */
        const size_t on = N + 3 + (size_t)round * ((M - N - 4) / 3);
        x[on] = pc.pot[0].r.x;
        y[on] = pc.pot[0].r.y;
        isk_forces f = {.gravity = 9.81, .drag = 0.47, .centre = ISK_FIDELITY_SOUND};
        apply_case(&f, &pc);
        memcpy(gx, x, sizeof x);
        memcpy(gy, y, sizeof y);
        memcpy(gvx, vx, sizeof vx);
        memcpy(gvy, vy, sizeof vy);
        int want = 0;
        for (size_t o = 0; o < M; o += N) {
            const size_t c = M - o < N ? M - o : N;
            isk_integrate_block(ISK_INTEGRATE_SEMI_EULER, &f, &scratch, c, gx + o, gy + o, gvx + o, gvy + o, m + o,
                                1.0 / 600);
            want |= isk_k_any_nonfinite2(c, gx + o, gy + o) | isk_k_any_nonfinite2(c, gvx + o, gvy + o);
        }
        for (int run = 0; run < 2 * (1 + isk__simd_level(2)); run++) {
            const int simd = run >> 1, keep = run & 1; /* keep: the fix-up reads the caller's start state */
            static double a[4][M], k[4][M];
            memcpy(a[0], x, sizeof x);
            memcpy(a[1], y, sizeof y);
            memcpy(a[2], vx, sizeof vx);
            memcpy(a[3], vy, sizeof vy);
            memset(k, 0x5a, sizeof k);
            const isk_motion_start start = {k[0], k[1], k[2], k[3]};
            int got = -1;
            cr_assert(isk__motion_fused_build(simd, ISK_INTEGRATE_SEMI_EULER, &f, M, a[0], a[1], a[2], a[3], m,
                                             1.0 / 600, keep ? &start : NULL, &got));
            if (keep)
                cr_assert(memcmp(k[0], x, sizeof x) == 0 && memcmp(k[1], y, sizeof y) == 0 &&
                              memcmp(k[2], vx, sizeof vx) == 0 && memcmp(k[3], vy, sizeof vy) == 0,
                          "round %d simd %d: the kept start state is not the input", round, simd);
            cr_assert_eq(got, want, "round %d simd %d: non-finite flag", round, simd);
            const double *const g[4] = {gx, gy, gvx, gvy};
            for (int col = 0; col < 4; col++)
                for (size_t i = 0; i < M; i++)
                    cr_assert(same(a[col][i], g[col][i]), "round %d simd %d: column %d particle %zu: %a, general %a",
                              round, simd, col, i, a[col][i], g[col][i]);
        }
    }
}

/* What the fused loops leave to the general path: declined, the block
 * untouched.  What they take although it looks close: taken. */
Test(motion_fused, potentials_declined_or_taken)
{
    static state in, b;
    uint64_t seed = 37;
    fill(&in, &seed, 1);
    isk_potential pot[6];
    for (int k = 0; k < 6; k++)
        isk_potential_init(&pot[k], 1.0, (isk_vec2){k, 1}, 1.0);
    isk_forces f = {.gravity = 9.81, .drag = 0.47, .pot = pot, .npot = 1};
    int nf;
    /* an exponent other than 2 or 1 */
    b = in;
    pot[0].P = 3.0;
    cr_assert_eq(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.01, NULL, &nf), 0, "P = 3");
    cr_assert(memcmp(&b, &in, sizeof b) == 0);
    /* ... but not when it does not act */
    pot[0].enabled = 0;
    f.npot = 2;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "a disabled P = 3 before an acting one");
    pot[0].enabled = 1;
    pot[0].charge = 0.0;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "k*Q = 0 with P = 3 before an acting one");
    pot[0].charge = 1.0;
    pot[0].P = 2.0;
    /* a max-distance switch, even with k*Q = 0 (it may still switch) */
    pot[1].max_dist = 0.1;
    b = in;
    cr_assert_eq(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.01, NULL, &nf), 0,
                 "max distance");
    cr_assert(memcmp(&b, &in, sizeof b) == 0);
    pot[1].charge = 0.0;
    cr_assert_eq(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.01, NULL, &nf), 0,
                 "max distance, k*Q = 0");
    cr_assert(memcmp(&b, &in, sizeof b) == 0);
    pot[1].charge = 1.0;
    pot[1].max_dist = ISK_DIST_OFF;
    /* four acting: taken; a fifth: declined; a fifth disabled: taken */
    f.npot = 4;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "four potentials");
    f.npot = 5;
    b = in;
    cr_assert_eq(isk__motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.01, NULL, &nf), 0,
                 "five potentials");
    cr_assert(memcmp(&b, &in, sizeof b) == 0);
    pot[2].enabled = 0;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "five, one disabled");
    /* the other integrators, with a potential */
    f.npot = 1;
    for (int m = ISK_INTEGRATE_VERLET; m < ISK_INTEGRATOR_COUNT; m++) {
        b = in;
        cr_assert_eq(isk__motion_fused((isk_integrator)m, &f, isk_forces_laws(&f), N, b.x, b.y, b.vx, b.vy, b.m, 0.01, NULL, &nf), 0);
        cr_assert(memcmp(&b, &in, sizeof b) == 0);
    }
    /* every potential's k*Q is 0: the loops without potentials, the same bits */
    pot[0].k = 0.0;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "k = 0");
}

/* The exponent as a clamp (ISK_K_PW_12): the bits of d'*d' and d' for every
 * kind of d', min distance on and off. */
Test(motion_fused, exponent_clamp_matches_the_kinds)
{
    static const double off[] = {0.0, -0.0, 5e-324, 1e-160, 0.3, 1.0, 7.5, 1e160, 1e300, INFINITY, NAN};
    static const double mins[] = {ISK_DIST_OFF, 0.0, 0.5};
    enum { NO = sizeof off / sizeof off[0] };
    for (int i = 0; i < NO; i++)
        for (int j = 0; j < NO; j++)
            for (int k = 0; k < 3; k++)
                for (int P = 1; P <= 2; P++) {
                    double ax, ay, bx, by;
                    const double lo = P == 2 ? -INFINITY : 1.0, hi = P == 2 ? INFINITY : 1.0;
                    isk_k_coulomb_law(1.0, -2.0, 1.0 - off[i], -2.0 + off[j], -3.0, 0.3, mins[k], 0.0, P, 0.0, 0.0,
                                      &ax, &ay);
                    isk_k_coulomb_law(1.0, -2.0, 1.0 - off[i], -2.0 + off[j], -3.0, 0.3, mins[k], 0.0, ISK_K_PW_12,
                                      lo, hi, &bx, &by);
                    cr_assert(same(ax, bx) && same(ay, by), "P %d, offset (%a, %a), min %g: (%a, %a) for (%a, %a)",
                              P, off[i], off[j], mins[k], bx, by, ax, ay);
                }
}
