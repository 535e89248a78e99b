/* SPDX-License-Identifier: MIT */
/* The fused motion loops (motion_fused_loops.h) compiled for AVX-512 (eight lanes, 32 registers),
 * for a CPU that has it. */
#include "core/cpu.h"

#if ISK__CPU_AVX512
#include "sim/motion_fused_loops.h"

MOTION_FUSED_LOOPS(fused_avx512_, pot_avx512_, static ISK__AVX512_FN)

const fused_fn isk__fused_loops_avx512[2][16] = FUSED_TABLE(fused_avx512_);
const pot_fn isk__pot_loops_avx512[POT_MAX][8] = POT_TABLE(pot_avx512_);
#else
typedef int isk__motion_fused_avx512_unused; /* ISO C wants a declaration in every file */
#endif
