/* SPDX-License-Identifier: MIT */
/* The fire's sway (src/sim/sway.h) against a frozen copy of the scalar
 * code it replaced (the lookups of iskra/sinlut.h with libm's floor, the
 * oscillate stage's loop): the same bits of x, vx, amplitude, phase and
 * offset, both builds (portable and, where the CPU has it, AVX2), every
 * sine (floor, round, lerp, libm), faithful or not, every table size
 * (16 .. 65536, shared with a stride or copied), every tail length of a
 * block, random states with the edge cases mixed in: negative phases,
 * angles exactly on and one to three ulps either side of table points,
 * angles in table steps around 2^31 (the AVX2 index's limit), 2^52, 2^62
 * (the slow reduction's), 2^63 and beyond, +-0, NaN, +-Inf, amplitudes
 * that flush.  The drift and the sway in one pass (the AVX2 build, and the
 * drift+sway stage, whose portable path runs the stages it stands for)
 * against the frozen drift stages followed by the frozen sway, for the
 * three drifts (plain, the thesis's order, the sound order's slow stage),
 * with zero accelerations of both signs, velocities of both zeros and
 * ones that flush. */
#include <criterion/criterion.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "iskra/integrate.h" /* ISK_SIM_BLOCK, ISK_FLUSH_TINY */
#include "iskra/particles.h"
#include "iskra/sinlut.h"
#include "core/cpu.h" /* isk__have_avx2 */
#include "sim/stage.h"
#include "sim/sway.h"

enum { N = ISK_SIM_BLOCK, PAD = 3 };

static uint64_t lcg(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return *s >> 11;
}

static double unit(uint64_t *s) { return (double)lcg(s) / 9007199254740992.0; } /* [0, 1) */

/* Equal bits, or both NaN (C leaves a NaN's sign and payload open). */
static int same(double a, double b)
{
    if (isnan(a) && isnan(b))
        return 1;
    return memcmp(&a, &b, sizeof a) == 0;
}

/* ---- the reference: the scalar code as it was, frozen ------------------------ */

static double ref_sine(const isk_sinlut *l, int mode, double th)
{
    if (mode == ISK_SINLUT_LIBM)
        return sin(th);
    double t = th * l->scale;
    if (!(fabs(t) < 4611686018427387904.0)) { /* 2^62 */
        t = isk_sinlut_reduce_slow(l, th);
        if (t != t)
            return NAN;
    }
    double fl = floor(t);
    uint64_t i = (uint64_t)(int64_t)fl;
    if (mode == ISK_SINLUT_ROUND)
        i += (t - fl) >= 0.5;
    const double *p = l->table + (i & l->mask) * l->stride;
    if (mode != ISK_SINLUT_LERP)
        return p[0];
    double a = p[0], b = p[l->stride];
    return a + (t - fl) * (b - a);
}

static void ref_sway(const isk_sway *w, size_t n, double *x, double *vx, double *amp, double *ph,
                     const double *om, double *off)
{
    for (size_t i = 0; i < n; i++) {
        ph[i] += om[i] * w->h;
        double s = amp[i] * ref_sine(w->table, (int)w->mode, ph[i]);
        double dx = s - off[i];
        x[i] += dx;
        if (w->faithful)
            vx[i] += dx;
        off[i] = s;
        double a = amp[i] * w->decay;
        amp[i] = isless(fabs(a), ISK_FLUSH_TINY) ? 0.0 : a;
    }
}

/* ---- states ----------------------------------------------------------------- */

typedef struct state {
    double x[N + PAD], vx[N + PAD], amp[N + PAD], ph[N + PAD], om[N + PAD], off[N + PAD];
    double y[N + PAD], vy[N + PAD]; /* the drift's (the fused pass) */
} state;

/* x ulps from v (x < 0: down). */
static double ulps(double v, int x)
{
    for (; x > 0; x--)
        v = nextafter(v, INFINITY);
    for (; x < 0; x++)
        v = nextafter(v, -INFINITY);
    return v;
}

/* An angle whose value in table steps (theta * scale) is k, or one to three
 * ulps either side of it.  wide: also |t| around 2^31, 2^52, 2^62, 2^63
 * and beyond, and the non-finite. */
static double special_phase(uint64_t *s, const isk_sinlut *l, int wide)
{
    static const double near[] = {0.0, 1.0, 2.0, 3.0, 0.5, 1.5, 15.0, 16.0, 4095.0, 4096.0, 65535.0, 65536.0,
                                  65537.0, 1e6, 123456789.0, 2147483647.0, 2147483648.0, 2147483646.5};
    static const double far[] = {2147483648.0, 2147483649.0, 4294967296.0, 4503599627370495.5,
                                 4503599627370496.0, 9007199254740992.0, 4611686018427387904.0,
                                 4611686018427387904.0 * 0.75, 9223372036854775808.0, 1e19, 1e300, DBL_MAX};
    const unsigned pick = (unsigned)(lcg(s) % (wide ? 10u : 6u));
    const double sign = lcg(s) & 1 ? -1.0 : 1.0;
    switch (pick) {
    case 0: /* on or beside a table point, small |t| */
    case 1: {
        double k = floor(unit(s) * 4.0 * (double)l->n) - 2.0 * (double)l->n;
        return ulps(k / l->scale, (int)(lcg(s) % 7) - 3);
    }
    case 2: /* on or beside k * 2pi/N as a double */
        return ulps(sign * floor(unit(s) * 1e4) * (6.283185307179586 / (double)l->n), (int)(lcg(s) % 7) - 3);
    case 3: return ulps(sign * near[lcg(s) % (sizeof near / sizeof near[0])] / l->scale, (int)(lcg(s) % 7) - 3);
    case 4: return lcg(s) & 1 ? -0.0 : 0.0;
    case 5: return sign * 5e-324;
    case 6:
    case 7: return ulps(sign * far[lcg(s) % (sizeof far / sizeof far[0])] / l->scale, (int)(lcg(s) % 7) - 3);
    case 8: return sign * INFINITY;
    default: return NAN;
    }
}

static double special_amp(uint64_t *s, double decay)
{
    static const double a[] = {0.0, -0.0, 1e-200, -1e-200, 5e-324, 1e300, -0.3, INFINITY, -INFINITY, NAN};
    const unsigned k = (unsigned)(lcg(s) % 12u);
    if (k < 10)
        return a[k];
    /* just either side of flushing after the decay */
    const double edge = decay > 0.0 ? ISK_FLUSH_TINY / decay : ISK_FLUSH_TINY;
    return ulps(k == 10 ? edge : -edge, (int)(lcg(s) % 5) - 2);
}

/* wide: the phases' specials include angles the AVX2 groups hand back. */
static void fill(state *st, uint64_t *s, const isk_sinlut *l, double decay, int wide)
{
    for (size_t i = 0; i < N + PAD; i++) {
        int special = lcg(s) % 4 == 0;
        st->ph[i] = special ? special_phase(s, l, wide) : (unit(s) - 0.5) * 40.0;
        /* the phase lands on the special angle when omega*h adds a zero of its sign */
        st->om[i] = special ? (signbit(st->ph[i]) ? -0.0 : 0.0) : (unit(s) - 0.5) * 18.0;
        if (lcg(s) % 16 == 0)
            st->om[i] = wide && lcg(s) % 2 ? (lcg(s) & 1 ? NAN : -INFINITY) : 1e6 * (unit(s) - 0.5);
        st->amp[i] = lcg(s) % 5 == 0 ? special_amp(s, decay) : 0.1 + 0.2 * unit(s);
        st->off[i] = lcg(s) % 9 == 0 ? (lcg(s) & 1 ? -0.0 : (wide ? NAN : 0.0)) : (unit(s) - 0.5) * 0.6;
        st->x[i] = lcg(s) % 11 == 0 ? -0.0 : (unit(s) - 0.5) * 20.0;
        st->vx[i] = lcg(s) % 11 == 0 ? (wide ? INFINITY : 0.0) : (unit(s) - 0.5) * 10.0;
        /* velocities of both zeros and ones that flush once slowed */
        static const double v_special[] = {0.0, -0.0, 1e-200, -1.0000001e-200, 5e-324, 1e300, INFINITY, NAN};
        if (lcg(s) % 8 == 0)
            st->vx[i] = v_special[lcg(s) % (wide ? 8 : 6)];
        st->y[i] = (unit(s) - 0.5) * 20.0;
        st->vy[i] = lcg(s) % 8 == 0 ? v_special[lcg(s) % (wide ? 8 : 6)] : (unit(s) - 0.5) * 10.0;
    }
}

/* ---- the comparison ----------------------------------------------------------- */

static int compared_avx2;

static void compare(const isk_sway *w, const state *in, size_t at, size_t n, const char *what)
{
    static state a, b;
    a = *in;
    ref_sway(w, n, a.x + at, a.vx + at, a.amp + at, a.ph + at, a.om + at, a.off + at);
    for (int avx2 = 0; avx2 <= isk__have_avx2(); avx2++) {
        b = *in;
        isk__sway_build(avx2, w, n, b.x + at, b.vx + at, b.amp + at, b.ph + at, b.om + at, b.off + at);
        compared_avx2 += avx2;
        const double *const ra[5] = {a.x, a.vx, a.amp, a.ph, a.off}, *const ga[5] = {b.x, b.vx, b.amp, b.ph, b.off};
        static const char *const col[5] = {"x", "vx", "amp", "phase", "offset"};
        for (int c = 0; c < 5; c++)
            for (size_t i = 0; i < N + PAD; i++) /* the block, and nothing beside it */
                if (!same(ga[c][i], ra[c][i]))
                    cr_assert_fail("%s, n %zu at %zu, avx2 %d: %s of particle %ld is %a, the reference %a (phase in %a, "
                             "omega %a, amp %a)",
                             what, n, at, avx2, col[c], (long)i - (long)at, ga[c][i], ra[c][i],
                             in->ph[i], in->om[i], in->amp[i]);
    }
}

static const double STEPS[] = {1.0 / 600, 1.0 / 60, 0.25, -1.0 / 600};
static const double DECAYS[] = {1.0 - 0.2 / 600, 0.5, 0.0, 1.0};
static const char *const MODE_NAME[ISK_SINLUT_MODE_COUNT] = {"floor", "round", "lerp", "libm"};

/* One table, every sine and faithful, a few tail lengths each. */
static void table_cases(const isk_sinlut *l, const char *kind, uint64_t *seed, int rounds)
{
    static state in;
    for (int r = 0; r < rounds; r++) {
        const double decay = DECAYS[r % 4], h = STEPS[(r / 2) % 4];
        fill(&in, seed, l, decay, r % 2);
        for (int mode = 0; mode < ISK_SINLUT_MODE_COUNT; mode++)
            for (int faithful = 0; faithful < 2; faithful++) {
                const isk_sway w = {l, (isk_sinlut_mode)mode, faithful, decay, h};
                char what[128];
                snprintf(what, sizeof what, "N %d %s, %s, faithful %d, round %d", l->n, kind, MODE_NAME[mode],
                         faithful, r);
                static const size_t len[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 13, N - 1, N};
                for (size_t k = 0; k < sizeof len / sizeof len[0]; k++)
                    compare(&w, &in, len[k] == N ? 0 : lcg(seed) % (PAD + 1), len[k], what);
                compare(&w, &in, lcg(seed) % (PAD + 1), 10 + lcg(seed) % (N - 10), what);
            }
    }
}

Test(sway, same_bits_every_table_sine_and_tail)
{
    uint64_t seed = 2024;
    static double copy[ISK_SINLUT_MAX_N + 1];
    compared_avx2 = 0;
    for (int n = ISK_SINLUT_MIN_N; n <= ISK_SINLUT_MAX_N; n *= 2) {
        isk_sinlut shared, own;
        cr_assert_eq(isk_sinlut_init(&shared, n), ISK_OK);
        cr_assert_eq(isk_sinlut_init_copy(&own, n, copy, sizeof copy / sizeof copy[0]), ISK_OK);
        table_cases(&shared, "shared", &seed, 8);
        table_cases(&own, "copied", &seed, 4);
    }
    cr_assert(!isk__have_avx2() || compared_avx2 > 1000, "the AVX2 loops ran %d times", compared_avx2);
}

/* Every block length 0 .. N (all the AVX2 loop's tails and group counts). */
Test(sway, same_bits_every_length)
{
    uint64_t seed = 77;
    static state in;
    isk_sinlut l;
    cr_assert_eq(isk_sinlut_init(&l, 4096), ISK_OK);
    for (int r = 0; r < 2; r++) {
        fill(&in, &seed, &l, DECAYS[0], r);
        for (int mode = 0; mode < ISK_SINLUT_LIBM; mode++)
            for (int faithful = 0; faithful < 2; faithful++) {
                const isk_sway w = {&l, (isk_sinlut_mode)mode, faithful, DECAYS[0], STEPS[0]};
                for (size_t n = 0; n <= N; n++)
                    compare(&w, &in, n == N ? 0 : n % (PAD + 1), n, MODE_NAME[mode]);
            }
    }
}

/* A whole block of in-range angles, none special: every AVX2 group takes
 * the vector path (the cases above hand many groups to the scalar code). */
Test(sway, same_bits_ordinary_block)
{
    uint64_t seed = 5;
    static state in;
    isk_sinlut l;
    cr_assert_eq(isk_sinlut_init(&l, 4096), ISK_OK);
    for (int r = 0; r < 16; r++) {
        for (size_t i = 0; i < N + PAD; i++) {
            in.ph[i] = (unit(&seed) - 0.5) * (r < 8 ? 40.0 : 4e8); /* t up to ~1e11 (> 2^31) in the later */
            in.om[i] = (unit(&seed) - 0.5) * 18.0;
            in.amp[i] = 0.1 + 0.2 * unit(&seed);
            in.off[i] = (unit(&seed) - 0.5) * 0.6;
            in.x[i] = (unit(&seed) - 0.5) * 20.0;
            in.vx[i] = (unit(&seed) - 0.5) * 10.0;
        }
        for (int mode = 0; mode < ISK_SINLUT_MODE_COUNT; mode++)
            for (int faithful = 0; faithful < 2; faithful++) {
                const isk_sway w = {&l, (isk_sinlut_mode)mode, faithful, DECAYS[r % 4], STEPS[r % 4]};
                compare(&w, &in, 0, N, MODE_NAME[mode]);
            }
    }
}

/* ---- the drift, then the sway, in one pass ------------------------------------ */

/* The drift stages as they are (stage_motion.c's drift_loop,
 * stage_fire.c's run_drift_slow and run_slow), frozen: factor f is the
 * slowing's max(0, 1 - slowing*h). */
static void ref_drift(int order, double ax, double ay, double f, double h, size_t n, double *x, double *y,
                      double *vx, double *vy)
{
    const double dvx = ax * h, dvy = ay * h;
    for (size_t i = 0; i < n; i++) {
        if (order == ISK_DRIFT_THESIS) {
            double a = (vx[i] + dvx) * f, b = (vy[i] + dvy) * f;
            vx[i] = isless(fabs(a), ISK_FLUSH_TINY) ? 0.0 : a;
            vy[i] = isless(fabs(b), ISK_FLUSH_TINY) ? 0.0 : b;
            x[i] = x[i] + h * vx[i];
            y[i] = y[i] + h * vy[i];
            continue;
        }
        if (ax != 0.0) /* with ax == 0 the drift leaves vx as it is (a -0 stays -0) */
            vx[i] = vx[i] + dvx;
        vy[i] = vy[i] + dvy;
        x[i] = x[i] + h * vx[i];
        y[i] = y[i] + h * vy[i];
        if (order == ISK_DRIFT_SOUND) {
            double a = vx[i] * f, b = vy[i] * f;
            vx[i] = isless(fabs(a), ISK_FLUSH_TINY) ? 0.0 : a;
            vy[i] = isless(fabs(b), ISK_FLUSH_TINY) ? 0.0 : b;
        }
    }
}

/* The stages' factors: max(0, 1 - rate*h). */
static double factor(double rate, double h)
{
    double f = 1.0 - rate * h;
    return f > 0.0 ? f : 0.0;
}

typedef struct drift_case {
    int order;
    double ax, ay, slowing;
} drift_case;

static const char *const ORDER_NAME[3] = {"plain", "thesis", "sound"};

/* The stage kinds' run on a store holding `in`'s first n particles. */
static void run_stages(const isk_pipeline *pl, const state *in, size_t n, double h, state *out)
{
    static isk_scratch scratch;
    isk_particles p;
    cr_assert_eq(isk_particles_init(&p, N, ISK_PARTICLES_OSC), ISK_OK);
    for (size_t i = 0; i < n; i++) /* then the columns as they are (the store refuses a NaN) */
        cr_assert_eq(isk_particles_add(&p, 0, 0, 0, 0, 1.0, NULL), ISK_OK);
    memcpy(p.x, in->x, n * sizeof *p.x);
    memcpy(p.y, in->y, n * sizeof *p.y);
    memcpy(p.vx, in->vx, n * sizeof *p.vx);
    memcpy(p.vy, in->vy, n * sizeof *p.vy);
    memcpy(p.osc_amp, in->amp, n * sizeof *p.osc_amp);
    memcpy(p.osc_phase, in->ph, n * sizeof *p.osc_phase);
    memcpy(p.osc_omega, in->om, n * sizeof *p.osc_omega);
    memcpy(p.osc_offset, in->off, n * sizeof *p.osc_offset);
    isk__pipeline_run(pl, &p, 0, n, h, &scratch, NULL);
    *out = *in;
    memcpy(out->x, p.x, n * sizeof *p.x);
    memcpy(out->y, p.y, n * sizeof *p.y);
    memcpy(out->vx, p.vx, n * sizeof *p.vx);
    memcpy(out->vy, p.vy, n * sizeof *p.vy);
    memcpy(out->amp, p.osc_amp, n * sizeof *p.osc_amp);
    memcpy(out->ph, p.osc_phase, n * sizeof *p.osc_phase);
    memcpy(out->off, p.osc_offset, n * sizeof *p.osc_offset);
    isk_particles_free(&p);
}

static void same_state(const state *got, const state *want, size_t n, const state *in, const char *what)
{
    const double *const ga[7] = {got->x, got->y, got->vx, got->vy, got->amp, got->ph, got->off};
    const double *const wa[7] = {want->x, want->y, want->vx, want->vy, want->amp, want->ph, want->off};
    static const char *const col[7] = {"x", "y", "vx", "vy", "amp", "phase", "offset"};
    for (int c = 0; c < 7; c++)
        for (size_t i = 0; i < n; i++)
            if (!same(ga[c][i], wa[c][i]))
                cr_assert_fail("%s, n %zu: %s of particle %zu is %a, the reference %a (vx %a, phase %a, amp %a)", what,
                               n, col[c], i, ga[c][i], wa[c][i], in->vx[i], in->ph[i], in->amp[i]);
}

/* One case: the reference, then isk__sway_drift_build (AVX2), the fused
 * stage and the unfused stages, on the first n particles. */
static void compare_drift(const drift_case *dc, const isk_sinlut *l, int mode, int faithful, double decay_rate,
                          double h, const state *in, size_t n, const char *what)
{
    static state want, got;
    const isk_sway w = {l, (isk_sinlut_mode)mode, faithful, factor(decay_rate, h), h};
    want = *in;
    ref_drift(dc->order, dc->ax, dc->ay, factor(dc->slowing, h), h, n, want.x, want.y, want.vx, want.vy);
    ref_sway(&w, n, want.x, want.vx, want.amp, want.ph, want.om, want.off);

    const isk_sway_drift d = {dc->ax, dc->ay, factor(dc->slowing, h), (isk_drift_order)dc->order};
    got = *in;
    const int ran = isk__sway_drift_build(1, &d, &w, n, got.x, got.y, got.vx, got.vy, got.amp, got.ph, got.om, got.off);
    cr_assert_eq(ran, isk__have_avx2() && mode != ISK_SINLUT_LIBM, "%s: ran %d", what, ran);
    if (ran) {
        same_state(&got, &want, N + PAD, in, what); /* nothing beside the n either */
        compared_avx2++;
    } else {
        cr_assert(!memcmp(&got, in, sizeof got), "%s: declined but changed the columns", what);
    }
    got = *in;
    cr_assert_eq(isk__sway_drift_build(0, &d, &w, n, got.x, got.y, got.vx, got.vy, got.amp, got.ph, got.om, got.off),
                 0);
    cr_assert(!memcmp(&got, in, sizeof got), "%s: the portable build changed the columns", what);

    isk_pipeline fused, apart;
    isk__pipeline_init(&fused);
    isk_stage *st = isk__pipeline_add(&fused, &isk__stage_drift_sway);
    st->u.drift_sway.ax = dc->ax;
    st->u.drift_sway.ay = dc->ay;
    st->u.drift_sway.slowing = dc->slowing;
    st->u.drift_sway.order = (isk_drift_order)dc->order;
    isk_stage_osc osc = {decay_rate, l, (isk_sinlut_mode)mode, faithful, 0, 0, 0, 0};
    st->u.drift_sway.osc = osc;
    run_stages(&fused, in, n, h, &got);
    same_state(&got, &want, n, in, what);

    isk__pipeline_init(&apart); /* the stages it stands for */
    if (dc->order == ISK_DRIFT_THESIS) {
        st = isk__pipeline_add(&apart, &isk__stage_drift_slow);
        st->u.drift_slow.ax = dc->ax, st->u.drift_slow.ay = dc->ay, st->u.drift_slow.slowing = dc->slowing;
    } else {
        st = isk__pipeline_add(&apart, &isk__stage_drift);
        st->u.drift.ax = dc->ax, st->u.drift.ay = dc->ay;
        if (dc->order == ISK_DRIFT_SOUND)
            isk__pipeline_add(&apart, &isk__stage_slow)->u.slow.slowing = dc->slowing;
    }
    isk__pipeline_add(&apart, &isk__stage_oscillate)->u.osc = osc;
    run_stages(&apart, in, n, h, &got);
    same_state(&got, &want, n, in, what);
}

Test(sway, drift_then_sway_same_bits)
{
    static const drift_case cases[] = {
        {ISK_DRIFT_PLAIN, 0.0, 0.5, 0.0},    {ISK_DRIFT_PLAIN, -0.0, -9.81, 0.0}, {ISK_DRIFT_PLAIN, 0.7, 0.5, 0.0},
        {ISK_DRIFT_THESIS, 0.0, 0.5, 0.5},   {ISK_DRIFT_THESIS, -1.5, 2.0, 2.0}, {ISK_DRIFT_THESIS, 0.3, 0.0, 1e4},
        {ISK_DRIFT_SOUND, 0.0, 3.5, 0.9},    {ISK_DRIFT_SOUND, 0.2, -3.0, 0.25}, {ISK_DRIFT_SOUND, 0.0, 1.0, 1e4},
    };
    uint64_t seed = 99;
    static state in;
    static double copy[ISK_SINLUT_MAX_N + 1];
    compared_avx2 = 0;
    for (int r = 0; r < 8; r++) {
        isk_sinlut l;
        const int tn = 16 << (r * 2 % 13);
        if (r % 2)
            cr_assert_eq(isk_sinlut_init_copy(&l, tn, copy, sizeof copy / sizeof copy[0]), ISK_OK);
        else
            cr_assert_eq(isk_sinlut_init(&l, tn), ISK_OK);
        const double h = STEPS[r % 4], decay = r % 3 ? 0.2 : 1e4;
        fill(&in, &seed, &l, factor(decay, h), r % 2);
        for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
            for (int mode = 0; mode < ISK_SINLUT_MODE_COUNT; mode++)
                for (int faithful = 0; faithful < 2; faithful++) {
                    char what[160];
                    snprintf(what, sizeof what, "%s drift (ax %g, ay %g, slowing %g), N %d, %s, faithful %d, round %d",
                             ORDER_NAME[cases[c].order], cases[c].ax, cases[c].ay, cases[c].slowing, tn,
                             MODE_NAME[mode], faithful, r);
                    static const size_t len[] = {0, 1, 3, 4, 5, 7, 8, 11, N - 1, N};
                    for (size_t k = 0; k < sizeof len / sizeof len[0]; k++)
                        compare_drift(&cases[c], &l, mode, faithful, decay, h, &in, len[k], what);
                }
    }
    cr_assert(!isk__have_avx2() || compared_avx2 > 1000, "the fused AVX2 loops ran %d times", compared_avx2);
}

/* The plain drift with ax = +0 leaves a -0 velocity as it is (its loop
 * does not store vx; -0 + 0 would be +0).  The sign survives the sway
 * only where its dx is -0 too (a zero amplitude at a negative sine, a +0
 * offset), so the random states above hardly ever show it: a block of
 * exactly that. */
Test(sway, drift_keeps_a_negative_zero_velocity)
{
    static state in;
    isk_sinlut l;
    cr_assert_eq(isk_sinlut_init(&l, 4096), ISK_OK);
    uint64_t seed = 3;
    for (size_t i = 0; i < N + PAD; i++) {
        in.x[i] = -0.0, in.vx[i] = -0.0, in.y[i] = 1.0, in.vy[i] = 2.0;
        in.amp[i] = 0.0, in.off[i] = 0.0;
        in.ph[i] = -1.0 - unit(&seed), in.om[i] = unit(&seed); /* sin < 0 */
    }
    const drift_case plain = {ISK_DRIFT_PLAIN, 0.0, 0.5, 0.0};
    for (int mode = 0; mode < ISK_SINLUT_MODE_COUNT; mode++)
        for (int faithful = 0; faithful < 2; faithful++)
            for (size_t n = 0; n <= 9; n++)
                compare_drift(&plain, &l, mode, faithful, 0.2, STEPS[0], &in, n == 9 ? N : n, MODE_NAME[mode]);
}
