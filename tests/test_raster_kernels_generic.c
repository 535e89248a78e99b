/* SPDX-License-Identifier: MIT */
/* The row kernels' vector-extension path (what non-x86 GCC / Clang targets
 * build), forced here on x86-64 by ISK__CPU_NO_SSE2, against the per-pixel
 * reference; see tests/raster_kernels_body.h. */
#define ISK__CPU_NO_SSE2 1
#define KERNEL_SUITE raster_kernels_generic
#include "raster_kernels_body.h"
