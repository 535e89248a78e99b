/* The fire's sway over a block, portable and AVX2 (see sway.h). */
#include "sim/sway.h"

#include <math.h>
#include <stdint.h>

#include "raster/span_simd.h" /* ISK__SPAN_AVX2, ISK__AVX2_FN, isk__have_avx2 */
#include "sim/kernels.h"

/* The sine of the sway, read as the emitter asks: `mode` is a constant at
 * every call below, so the loops have no per-particle branch on it. */
static inline double sway_sine(const isk_sinlut *t, const int mode, double ph)
{
    switch (mode) {
    case ISK_SINLUT_FLOOR: return isk_sinlut_floor(t, ph);
    case ISK_SINLUT_ROUND: return isk_sinlut_round(t, ph);
    case ISK_SINLUT_LERP: return isk_sinlut_lerp(t, ph);
    default: return sin(ph);
    }
}

/* Particle i, sway.h's operations in their order. */
static inline void sway_one(size_t i, double *restrict x, double *restrict vx, double *restrict amp,
                            double *restrict ph, const double *restrict om, double *restrict off,
                            const isk_sway *w, const int mode, const int faithful)
{
    ph[i] += om[i] * w->h;
    double s = amp[i] * sway_sine(w->table, mode, ph[i]);
    double dx = s - off[i];
    x[i] += dx;
    if (faithful)
        vx[i] += dx;
    off[i] = s;
    amp[i] = isk_k_flush(amp[i] * w->decay);
}

static inline void sway_loop(size_t n, double *restrict x, double *restrict vx, double *restrict amp,
                             double *restrict ph, const double *restrict om, double *restrict off,
                             const isk_sway *w, const int mode, const int faithful)
{
    for (size_t i = 0; i < n; i++)
        sway_one(i, x, vx, amp, ph, om, off, w, mode, faithful);
}

typedef void (*sway_fn)(size_t, double *, double *, double *, double *, const double *, double *, const isk_sway *);

#define SWAY_AS(name, mode, faithful)                                                                            \
    static void name(size_t n, double *x, double *vx, double *amp, double *ph, const double *om, double *off,   \
                     const isk_sway *w)                                                                          \
    {                                                                                                            \
        sway_loop(n, x, vx, amp, ph, om, off, w, mode, faithful);                                               \
    }
SWAY_AS(sway_00, 0, 0) SWAY_AS(sway_01, 0, 1) SWAY_AS(sway_10, 1, 0) SWAY_AS(sway_11, 1, 1)
SWAY_AS(sway_20, 2, 0) SWAY_AS(sway_21, 2, 1) SWAY_AS(sway_30, 3, 0) SWAY_AS(sway_31, 3, 1)
#undef SWAY_AS

#if ISK__SPAN_AVX2
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

/* Particles i .. i+3, or 0 with nothing written when some angle is beyond
 * the 32-bit index (|t| >= 2^31, infinite or NaN). */
static ISK__INLINE ISK__AVX2_FN int sway4_avx2(size_t i, double *restrict x, double *restrict vx,
                                               double *restrict amp, double *restrict ph,
                                               const double *restrict om, double *restrict off, const sway_k4 *k,
                                               const int mode, const int faithful)
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
    _mm256_storeu_pd(x + i, _mm256_add_pd(_mm256_loadu_pd(x + i), dx));
    if (faithful)
        _mm256_storeu_pd(vx + i, _mm256_add_pd(_mm256_loadu_pd(vx + i), dx));
    _mm256_storeu_pd(off + i, s);
    /* flush: +0.0 where |amp*decay| < ISK_FLUSH_TINY (quiet: NaN stays) */
    const __m256d na = _mm256_mul_pd(A, k->decay);
    const __m256d tiny = _mm256_cmp_pd(_mm256_andnot_pd(k->sign, na), k->tiny, _CMP_LT_OQ);
    _mm256_storeu_pd(amp + i, _mm256_andnot_pd(tiny, na));
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
#endif

/* [avx2][mode][faithful], modes in isk_sinlut_mode order; libm's sin has
 * no AVX2 loop. */
static const sway_fn sway_loops[1 + ISK__SPAN_AVX2][ISK_SINLUT_MODE_COUNT][2] = {
    {{sway_00, sway_01}, {sway_10, sway_11}, {sway_20, sway_21}, {sway_30, sway_31}},
#if ISK__SPAN_AVX2
    {{sway_avx2_00, sway_avx2_01}, {sway_avx2_10, sway_avx2_11}, {sway_avx2_20, sway_avx2_21}, {sway_30, sway_31}},
#endif
};

/* 1 when every index*stride of the table, +stride, is an int32 (always,
 * for the tables isk_sinlut_init makes: at most 65536). */
static int gatherable(const isk_sinlut *t)
{
    return t && t->mask < (uint64_t)INT32_MAX && t->stride <= (uint64_t)INT32_MAX / (t->mask + 1u);
}

void isk_sway_build(int avx2, const isk_sway *w, size_t n, double *x, double *vx, double *amp, double *phase,
                    const double *omega, double *offset)
{
    const unsigned mode = (unsigned)w->mode < ISK_SINLUT_MODE_COUNT ? (unsigned)w->mode : ISK_SINLUT_LIBM;
    const int fast = avx2 && mode != ISK_SINLUT_LIBM && gatherable(w->table) && isk__have_avx2();
    sway_loops[fast][mode][w->faithful != 0](n, x, vx, amp, phase, omega, offset, w);
}

void isk_sway_run(const isk_sway *w, size_t n, double *x, double *vx, double *amp, double *phase,
                  const double *omega, double *offset)
{
    isk_sway_build(1, w, n, x, vx, amp, phase, omega, offset);
}

