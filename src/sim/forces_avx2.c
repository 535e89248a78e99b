/* SPDX-License-Identifier: MIT */
/* The Coulomb potential's loops (forces_loops.h) compiled for AVX2, for a
 * CPU that has it. */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include "sim/forces_loops.h"

#define COULOMB(kind, sound) COULOMB_AS(coulomb_avx2_##kind##sound, static ISK__AVX2_FN, kind, sound)
COULOMB(0, 0) COULOMB(0, 1) COULOMB(1, 0) COULOMB(1, 1) COULOMB(2, 0) COULOMB(2, 1)
#undef COULOMB

const coulomb_fn isk__coulomb_loops_avx2[6] = COULOMB_ROW(coulomb_avx2_);
#else
typedef int isk__forces_avx2_unused; /* ISO C wants a declaration in every file */
#endif
