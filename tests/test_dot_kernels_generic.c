/* SPDX-License-Identifier: MIT */
/* The coverage dot's 2x2 blends in their vector-extension twins (what
 * non-x86 GCC / Clang targets build, wasm among them), forced here on
 * x86-64 by ISK__CPU_NO_SSE2, against the per-pixel reference; see
 * tests/dot_kernels_body.h. */
#define ISK__CPU_NO_SSE2 1
#define DOT_SUITE dot_kernels_generic
#include "dot_kernels_body.h"

/* Without the vector twins this program would check the plain code twice
 * and the twins never (the reference build compiles neither). */
#if !ISK__CPU_VECTOR && !defined(ISKRA_REFERENCE)
#error "ISK__CPU_NO_SSE2 did not select the vector-extension twins (src/core/cpu.h)"
#endif
