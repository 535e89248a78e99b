/* SPDX-License-Identifier: MIT */
/* The fire's sway, and the drift then the sway in one pass, in AVX2 (see
 * sway.h), for a CPU that has it: four particles a step for the three
 * table sines.  floor by vroundpd (exact, as floor()); the index from a
 * 32-bit conversion, whose bits mod N are the 64-bit conversion's while
 * every |t| < 2^31 (t the angle in table steps); the entries by gathers.
 * A group with a larger, infinite or NaN angle, and the last particles,
 * take sway_loops.h's per-particle code.  The same IEEE operations in the
 * same order (no FMA). */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include <immintrin.h>
#include <stdint.h>

#include "sim/sway_loops.h"

/* The constants of a block's AVX2 loop, broadcast once. */
typedef struct sway_k4 {
    __m256d h, scale, decay, sign, two31, half, tiny;
    __m128i mask, stride;
    const double *tab;
    size_t step; /* the stride, for the lerp's second entry */
} sway_k4;

static ISK__INLINE ISK__AVX2_FN sway_k4 sway_k4_of(const isk_sway *w)
{
    sway_k4 k;
    k.h = _mm256_set1_pd(w->h);
    k.scale = _mm256_set1_pd(w->table->scale);
    k.decay = _mm256_set1_pd(w->decay);
    k.sign = _mm256_set1_pd(-0.0);
    k.two31 = _mm256_set1_pd(2147483648.0);
    k.half = _mm256_set1_pd(0.5);
    k.tiny = _mm256_set1_pd(ISK_FLUSH_TINY);
    k.mask = _mm_set1_epi32((int)w->table->mask);
    k.stride = _mm_set1_epi32((int)w->table->stride);
    k.tab = w->table->table;
    k.step = w->table->stride;
    return k;
}

/* The low 32 bits of each 64-bit lane of v, in order. */
static ISK__INLINE ISK__AVX2_FN __m128i sway_low32(__m256i v)
{
    return _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
}

/* The sine of four angles t in table steps, every |t| < 2^31, as
 * iskra/sinlut.h's lookup of `mode` computes it: fl = floor(t) (exact), the
 * index (int64)fl mod N (+1 where round goes up) from its 32-bit
 * conversion (the same low bits), the entry at index*stride, and for lerp
 * a + (t - fl)*(b - a). */
static ISK__INLINE ISK__AVX2_FN __m256d sway_sine4(const sway_k4 *k, __m256d t, const int mode)
{
    const __m256d fl = _mm256_round_pd(t, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    __m128i j = _mm256_cvttpd_epi32(fl);
    if (mode == ISK_SINLUT_ROUND) { /* up = (t - fl) >= 0.5: all ones, i.e. -1, where it holds */
        const __m256d up = _mm256_cmp_pd(_mm256_sub_pd(t, fl), k->half, _CMP_GE_OQ);
        j = _mm_sub_epi32(j, sway_low32(_mm256_castpd_si256(up)));
    }
    const __m128i at = _mm_mullo_epi32(_mm_and_si128(j, k->mask), k->stride);
    const __m256d a = _mm256_i32gather_pd(k->tab, at, 8);
    if (mode != ISK_SINLUT_LERP)
        return a;
    const __m256d b = _mm256_i32gather_pd(k->tab + k->step, at, 8); /* entry n exists: no wrap */
    return _mm256_add_pd(a, _mm256_mul_pd(_mm256_sub_pd(t, fl), _mm256_sub_pd(b, a)));
}

/* +0.0 where |v| < ISK_FLUSH_TINY, else v (kernels.h's isk_k_flush: a
 * quiet compare, so NaN stays). */
static ISK__INLINE ISK__AVX2_FN __m256d sway_flush4(const sway_k4 *k, __m256d v)
{
    return _mm256_andnot_pd(_mm256_cmp_pd(_mm256_andnot_pd(k->sign, v), k->tiny, _CMP_LT_OQ), v);
}

/* The sway of particles i .. i+3, their x and vx in *X and *VX (the
 * caller loads and stores those two; VX is read only when faithful), the
 * other columns loaded and stored here.  0 with nothing changed when some
 * angle is beyond the 32-bit index (|t| >= 2^31, infinite or NaN). */
static ISK__INLINE ISK__AVX2_FN int sway4_core(size_t i, __m256d *X, __m256d *VX, double *restrict amp,
                                               double *restrict ph, const double *restrict om,
                                               double *restrict off, const sway_k4 *k, const int mode,
                                               const int faithful)
{
    const __m256d p = _mm256_add_pd(_mm256_loadu_pd(ph + i), _mm256_mul_pd(_mm256_loadu_pd(om + i), k->h));
    const __m256d t = _mm256_mul_pd(p, k->scale);
    const __m256d in = _mm256_cmp_pd(_mm256_andnot_pd(k->sign, t), k->two31, _CMP_LT_OQ);
    if (_mm256_movemask_pd(in) != 0xF)
        return 0;
    const __m256d A = _mm256_loadu_pd(amp + i);
    const __m256d s = _mm256_mul_pd(A, sway_sine4(k, t, mode));
    const __m256d dx = _mm256_sub_pd(s, _mm256_loadu_pd(off + i));
    _mm256_storeu_pd(ph + i, p);
    *X = _mm256_add_pd(*X, dx);
    if (faithful)
        *VX = _mm256_add_pd(*VX, dx);
    _mm256_storeu_pd(off + i, s);
    _mm256_storeu_pd(amp + i, sway_flush4(k, _mm256_mul_pd(A, k->decay)));
    return 1;
}

/* Particles i .. i+3, or 0 with nothing written (sway4_core). */
static ISK__INLINE ISK__AVX2_FN int sway4_avx2(size_t i, double *restrict x, double *restrict vx,
                                               double *restrict amp, double *restrict ph,
                                               const double *restrict om, double *restrict off, const sway_k4 *k,
                                               const int mode, const int faithful)
{
    __m256d X = _mm256_loadu_pd(x + i), VX = faithful ? _mm256_loadu_pd(vx + i) : X;
    if (!sway4_core(i, &X, &VX, amp, ph, om, off, k, mode, faithful))
        return 0;
    _mm256_storeu_pd(x + i, X);
    if (faithful)
        _mm256_storeu_pd(vx + i, VX);
    return 1;
}

static ISK__INLINE ISK__AVX2_FN void sway_loop_avx2(size_t n, double *restrict x, double *restrict vx,
                                                    double *restrict amp, double *restrict ph,
                                                    const double *restrict om, double *restrict off,
                                                    const isk_sway *w, const int mode, const int faithful)
{
    const sway_k4 k = sway_k4_of(w);
    size_t i = 0;
    for (; i + 4 <= n; i += 4)
        if (!sway4_avx2(i, x, vx, amp, ph, om, off, &k, mode, faithful))
            for (size_t j = i; j < i + 4; j++)
                sway_one(j, x, vx, amp, ph, om, off, w, mode, faithful);
    for (; i < n; i++)
        sway_one(i, x, vx, amp, ph, om, off, w, mode, faithful);
}

#define SWAY_AVX2(name, mode, faithful)                                                                          \
    static ISK__AVX2_FN void name(size_t n, double *x, double *vx, double *amp, double *ph, const double *om,   \
                                  double *off, const isk_sway *w)                                                \
    {                                                                                                            \
        sway_loop_avx2(n, x, vx, amp, ph, om, off, w, mode, faithful);                                          \
    }
SWAY_AVX2(sway_avx2_00, 0, 0) SWAY_AVX2(sway_avx2_01, 0, 1) SWAY_AVX2(sway_avx2_10, 1, 0)
SWAY_AVX2(sway_avx2_11, 1, 1) SWAY_AVX2(sway_avx2_20, 2, 0) SWAY_AVX2(sway_avx2_21, 2, 1)
#undef SWAY_AVX2
/* [mode][faithful], the three table sines */
const sway_fn isk__sway_loops_avx2[ISK_SINLUT_LIBM][2] = {
    {sway_avx2_00, sway_avx2_01}, {sway_avx2_10, sway_avx2_11}, {sway_avx2_20, sway_avx2_21}};

/* ---- the drift, then the sway, in one pass ------------------------------------ */

typedef struct drift_k4 {
    __m256d dvx, dvy, f, keep_vx; /* keep_vx: all ones or all zeros */
} drift_k4;

/* Particles i .. i+3: drift_one's operations; y and vy stored, the new x
 * and vx in *X and *VX for the sway. */
static ISK__INLINE ISK__AVX2_FN void drift4_avx2(size_t i, double *restrict x, double *restrict y,
                                                 double *restrict vx, double *restrict vy, const sway_k4 *k,
                                                 const drift_k4 *d, const int order, __m256d *X, __m256d *VX)
{
    const __m256d ux = _mm256_loadu_pd(vx + i), uy = _mm256_loadu_pd(vy + i);
    __m256d wx, wy;
    if (order == ISK_DRIFT_THESIS) {
        wx = sway_flush4(k, _mm256_mul_pd(_mm256_add_pd(ux, d->dvx), d->f));
        wy = sway_flush4(k, _mm256_mul_pd(_mm256_add_pd(uy, d->dvy), d->f));
    } else {
        wx = _mm256_blendv_pd(_mm256_add_pd(ux, d->dvx), ux, d->keep_vx);
        wy = _mm256_add_pd(uy, d->dvy);
    }
    *X = _mm256_add_pd(_mm256_loadu_pd(x + i), _mm256_mul_pd(k->h, wx));
    _mm256_storeu_pd(y + i, _mm256_add_pd(_mm256_loadu_pd(y + i), _mm256_mul_pd(k->h, wy)));
    if (order == ISK_DRIFT_SOUND) {
        wx = sway_flush4(k, _mm256_mul_pd(wx, d->f));
        wy = sway_flush4(k, _mm256_mul_pd(wy, d->f));
    }
    _mm256_storeu_pd(vy + i, wy);
    *VX = wx;
}

static ISK__INLINE ISK__AVX2_FN void drift_sway_avx2(size_t n, double *restrict x, double *restrict y,
                                                     double *restrict vx, double *restrict vy,
                                                     double *restrict amp, double *restrict ph,
                                                     const double *restrict om, double *restrict off,
                                                     const drift_c *c, const isk_sway *w, const int order,
                                                     const int mode, const int faithful)
{
    const sway_k4 k = sway_k4_of(w);
    const drift_k4 d = {_mm256_set1_pd(c->dvx), _mm256_set1_pd(c->dvy), _mm256_set1_pd(c->f),
                        _mm256_castsi256_pd(_mm256_set1_epi64x(c->keep_vx ? -1 : 0))};
    /* vx unchanged (the plain drift with ax == 0, no coupling) is not
     * stored, as the drift's loop does not: its cache lines stay clean */
    const int store_vx = faithful || order != ISK_DRIFT_PLAIN || !c->keep_vx;
    size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        __m256d X, VX;
        drift4_avx2(i, x, y, vx, vy, &k, &d, order, &X, &VX);
        const int swayed = sway4_core(i, &X, &VX, amp, ph, om, off, &k, mode, faithful);
        _mm256_storeu_pd(x + i, X);
        if (store_vx)
            _mm256_storeu_pd(vx + i, VX);
        if (!swayed) /* the drift is done: the sway one by one */
            for (size_t j = i; j < i + 4; j++)
                sway_one(j, x, vx, amp, ph, om, off, w, mode, faithful);
    }
    for (; i < n; i++) {
        drift_one(i, x, y, vx, vy, c, order);
        sway_one(i, x, vx, amp, ph, om, off, w, mode, faithful);
    }
}

#define DRIFT_SWAY(order, mode, faithful)                                                                        \
    static ISK__AVX2_FN void drift_sway_##order##mode##faithful(size_t n, double *x, double *y, double *vx,       \
                                                                double *vy, double *amp, double *ph,             \
                                                                const double *om, double *off, const drift_c *c, \
                                                                const isk_sway *w)                               \
    {                                                                                                            \
        drift_sway_avx2(n, x, y, vx, vy, amp, ph, om, off, c, w, order, mode, faithful);                        \
    }
#define DRIFT_SWAY_ORDER(order)                                                                                  \
    DRIFT_SWAY(order, 0, 0) DRIFT_SWAY(order, 0, 1) DRIFT_SWAY(order, 1, 0) DRIFT_SWAY(order, 1, 1)             \
    DRIFT_SWAY(order, 2, 0) DRIFT_SWAY(order, 2, 1)
DRIFT_SWAY_ORDER(0) DRIFT_SWAY_ORDER(1) DRIFT_SWAY_ORDER(2)
#undef DRIFT_SWAY_ORDER
#undef DRIFT_SWAY

/* [order][mode * 2 + faithful], the three table sines. */
#define ROW(o) {drift_sway_##o##00, drift_sway_##o##01, drift_sway_##o##10, drift_sway_##o##11, \
                drift_sway_##o##20, drift_sway_##o##21}
const drift_sway_fn isk__drift_sway_loops_avx2[3][2 * ISK_SINLUT_LIBM] = {ROW(0), ROW(1), ROW(2)};
#undef ROW
#else
typedef int isk__sway_avx2_unused; /* ISO C wants a declaration in every file */
#endif
