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
 * that flush. */
#include <criterion/criterion.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "iskra/integrate.h" /* ISK_SIM_BLOCK, ISK_FLUSH_TINY */
#include "iskra/sinlut.h"
#include "raster/span_simd.h" /* isk__have_avx2 */
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
        isk_sway_build(avx2, w, n, b.x + at, b.vx + at, b.amp + at, b.ph + at, b.om + at, b.off + at);
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
