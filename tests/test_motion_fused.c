/* The fused motion pass (src/sim/motion_fused.h) against the general path
 * (isk_integrate_block, then the runner's non-finite checks): the same bits
 * of x, y, vx, vy and the same non-finite flag, for semi-implicit and
 * explicit Euler under every combination of gravity, constant acceleration
 * and linear drag, on random states with the edge cases mixed in: signed
 * zeros, velocities that flush (below ISK_FLUSH_TINY) or just escape it,
 * masses tiny enough to saturate the drag at m/|dt|, huge and zero masses,
 * infinities and NaNs; steps of both signs; every tail length of a block.
 * Both builds (portable and, where the CPU has it, AVX2).  Also: it declines (and touches nothing) where it does not apply. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "raster/span_simd.h" /* isk__have_avx2 */
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
    for (int avx2 = 0; avx2 <= isk__have_avx2(); avx2++) {
        b = *in;
        int got = -1;
        cr_assert_eq(isk_motion_fused_build(avx2, method, f, n, b.x, b.y, b.vx, b.vy, b.m, dt, &got), 1,
                     "%s: declined", what);
        cr_assert_eq(got, want, "%s, n %zu, avx2 %d: non-finite flag %d, general path %d", what, n, avx2, got, want);
        const double *const ga[4] = {a.x, a.y, a.vx, a.vy}, *const fa[4] = {b.x, b.y, b.vx, b.vy};
        for (int c = 0; c < 4; c++)
            for (size_t i = 0; i < n; i++)
                cr_assert(same(fa[c][i], ga[c][i]), "%s, n %zu, dt %g, avx2 %d: column %d particle %zu: %a, general %a",
                          what, n, dt, avx2, c, i, fa[c][i], ga[c][i]);
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
    cr_assert(isk_motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, N, b.x, b.y, b.vx, b.vy, b.m, 1.0 / 600, &nf));
    cr_assert_eq(nf, 0, "a finite state of ordinary masses stays finite");
    b = in;
    b.vy[77] = NAN;
    cr_assert(isk_motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, N, b.x, b.y, b.vx, b.vy, b.m, 1.0 / 600, &nf));
    cr_assert_eq(nf, 1);
    b = in;
    b.x[200] = 1.7e308;
    b.vx[200] = 1e308;
    cr_assert(isk_motion_fused(ISK_INTEGRATE_EULER, &f, N, b.x, b.y, b.vx, b.vy, b.m, 0.1, &nf));
    cr_assert_eq(nf, 1, "x + dt*vx overflows to infinity");
}

/* Other integrators, an enabled potential, a zero step with drag: 0, and
 * the block is untouched.  A disabled potential does not act: fused. */
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
        cr_assert_eq(isk_motion_fused((isk_integrator)m, &f, N, b.x, b.y, b.vx, b.vy, b.m, 0.01, &nf), 0);
        cr_assert(memcmp(&b, &in, sizeof b) == 0);
    }
    cr_assert_eq(isk_motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, N, b.x, b.y, b.vx, b.vy, b.m, 0.0, &nf), 0);
    cr_assert(memcmp(&b, &in, sizeof b) == 0);
    f.pot = &pot;
    f.npot = 1;
    cr_assert_eq(isk_motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, N, b.x, b.y, b.vx, b.vy, b.m, 0.01, &nf), 0);
    cr_assert(memcmp(&b, &in, sizeof b) == 0);
    const size_t none = 0;
    f.pick = &none; /* picks no potential: none acts */
    f.npick = 0;
    cr_assert_eq(isk_motion_fused(ISK_INTEGRATE_SEMI_EULER, &f, N, b.x, b.y, b.vx, b.vy, b.m, 0.01, &nf), 1);
    f.pick = NULL;
    pot.enabled = 0;
    compare(ISK_INTEGRATE_SEMI_EULER, &f, &in, N, 0.01, "disabled potential");
}
