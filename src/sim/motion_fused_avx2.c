/* SPDX-License-Identifier: MIT */
/* The fused motion loops (motion_fused_loops.h) compiled for AVX2 (four lanes),
 * for a CPU that has it. */
#include "core/cpu.h"

#if ISK__CPU_AVX2
#include "sim/motion_fused_loops.h"

MOTION_FUSED_LOOPS(fused_avx2_, pot_avx2_, static ISK__AVX2_FN)

const fused_fn isk__fused_loops_avx2[2][16] = FUSED_TABLE(fused_avx2_);
const pot_fn isk__pot_loops_avx2[POT_MAX][8] = POT_TABLE(pot_avx2_);
#else
typedef int isk__motion_fused_avx2_unused; /* ISO C wants a declaration in every file */
#endif
