/* SPDX-License-Identifier: MIT */
/* src/core/cpu.h — which instruction sets this build compiles, and which
 * of them the CPU running it has (internal; the one place that decides).
 *
 * Every kernel of iskra is first a plain C loop, the one a student reads.
 * A few also have fast twins written for an instruction set, each in a
 * file named for it next to its portable file:
 *
 *   name_sse2.h    SSE2 intrinsics: every x86-64 CPU has them, so they
 *                  are chosen when the file is compiled;
 *   name_vector.h  GCC / Clang vector extensions: other targets, which the
 *                  compiler lowers to NEON, AltiVec, ... or scalar code;
 *   name_avx2.c    AVX2 (and name_avx512.c AVX-512 F, VL, BW, DQ): their
 *                  functions are compiled for it by a target attribute
 *                  (ISK__AVX2_FN), the rest of the build stays baseline
 *                  x86-64, and they run only when the CPU says it has it;
 *   name_loops.h   a loop the portable file and its AVX2 / AVX-512 files
 *                  compile alike (each for its own target).
 *
 * The portable file calls its twin from one place (its dispatch point).
 * A twin gives the plain loop's bytes: integer arithmetic, or the same
 * IEEE operations in the same order lane by lane (no FMA: the build's
 * -ffp-contract=off holds in target functions too); tests compare them.
 *
 * The switches, 1 where this build compiles the twins of that kind:
 *   ISK__CPU_SSE2     x86-64 (SSE2 is part of it; the twins use its 64-bit
 *                     moves)
 *   ISK__CPU_VECTOR   otherwise, GCC >= 9 or Clang on a little-endian
 *                     target (the byte-packing of the span kernels), but
 *                     not 32-bit x86 without SSE2, where the vectors would
 *                     be scalar code and change the functions' ABI
 *   ISK__CPU_AVX2     SSE2, and a compiler with target("avx2")
 *   ISK__CPU_AVX512   AVX2, and a compiler with the AVX-512 targets
 * With ISKRA_REFERENCE defined (make test REFERENCE=1, or
 * CFLAGS=-DISKRA_REFERENCE=1) every switch is 0: no intrinsics header is
 * included anywhere and only the plain loops are compiled, which pass the
 * same tests with the same reference images.  Tests may define
 * ISK__CPU_NO_SSE2 (the vector-extension twins on x86-64),
 * ISK__CPU_NO_AVX2 or ISK__CPU_NO_AVX512 before any include.
 *
 * At run time:
 *   isk__have_avx2(), isk__have_avx512()   1 when this build has the twin
 *                                          and the CPU and the OS run it
 *   isk__simd_level(most)                  the widest of 0 (baseline),
 *                                          1 (AVX2), 2 (AVX-512) that is
 *                                          at most `most` and runs here
 *
 *     #if ISK__CPU_AVX2
 *         if (isk__have_avx2()) {                        // the twin (circle_avx2.c)
 *             isk__circle_aa_rows_small_avx2(c, ...);
 *             return;
 *         }
 *     #endif
 *         aa_rows_small(c, ...);                         // the plain loop
 */
#ifndef ISKRA_CORE_CPU_H
#define ISKRA_CORE_CPU_H

/* inline, and always inlined by GCC and Clang: for the small kernels a
 * loop is made of.  The public headers define it the same way
 * (iskra/blend_inline.h: they cannot include this file). */
#ifndef ISK__INLINE
#if defined(__GNUC__)
#define ISK__INLINE inline __attribute__((always_inline))
#else
#define ISK__INLINE inline
#endif
#endif

#if defined(ISKRA_REFERENCE)
#define ISK__CPU_SSE2 0
#define ISK__CPU_VECTOR 0
#elif defined(__x86_64__) && defined(__SSE2__) && !defined(ISK__CPU_NO_SSE2)
#define ISK__CPU_SSE2 1
#define ISK__CPU_VECTOR 0
#elif defined(__GNUC__) && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && \
    (defined(__clang__) || __GNUC__ >= 9) && (!defined(__i386__) || defined(__SSE2__))
#define ISK__CPU_SSE2 0
#define ISK__CPU_VECTOR 1
#else
#define ISK__CPU_SSE2 0
#define ISK__CPU_VECTOR 0
#endif

#if ISK__CPU_SSE2 && defined(__GNUC__) && !defined(ISK__CPU_NO_AVX2) && (defined(__clang__) || __GNUC__ >= 6)
#define ISK__CPU_AVX2 1
#define ISK__AVX2_FN __attribute__((target("avx2")))
#else
#define ISK__CPU_AVX2 0
#endif

#if ISK__CPU_AVX2 && !defined(ISK__CPU_NO_AVX512) && (defined(__clang__) || __GNUC__ >= 8)
#define ISK__CPU_AVX512 1
#define ISK__AVX512_FN __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq")))
#else
#define ISK__CPU_AVX512 0
#endif

/* 1 or 0 (a table index), whatever __builtin_cpu_supports returns. */
static inline int isk__have_avx2(void)
{
#if ISK__CPU_AVX2
    return __builtin_cpu_supports("avx2") != 0;
#else
    return 0;
#endif
}

static inline int isk__have_avx512(void)
{
#if ISK__CPU_AVX512
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
#else
    return 0;
#endif
}

/* The widest build a caller may take, at most `most` (0 baseline, 1 AVX2,
 * 2 AVX-512), and what this CPU runs: the index of a table with a row per
 * build (1 + ISK__CPU_AVX2 + ISK__CPU_AVX512 rows).  Tests pass each
 * `most` in turn to compare the builds' bits. */
static inline int isk__simd_level(int most)
{
    if (most >= 2 && isk__have_avx512())
        return 2;
    return most >= 1 && isk__have_avx2();
}

/* Its arguments where this build has AVX2 (AVX-512), else nothing: a
 * table's row for that build without an #if around it. */
#if ISK__CPU_AVX2
#define ISK__IF_AVX2(...) __VA_ARGS__
#else
#define ISK__IF_AVX2(...)
#endif
#if ISK__CPU_AVX512
#define ISK__IF_AVX512(...) __VA_ARGS__
#else
#define ISK__IF_AVX512(...)
#endif

#endif
