/* SPDX-License-Identifier: MIT */
/* The coverage dot's 2x2 blends as this build compiles them (the SSE2
 * twins on x86-64, the vector-extension twins on other GCC / Clang
 * targets, the plain code in the reference build) against the per-pixel
 * reference; see tests/dot_kernels_body.h. */
#define DOT_SUITE dot_kernels
#include "dot_kernels_body.h"
