/* SPDX-License-Identifier: MIT */
/* The row kernels as this build compiles them (SSE2 on x86-64, AVX2 when the
 * CPU has it, else the vector-extension or per-pixel path) against the
 * per-pixel reference; see tests/raster_kernels_body.h. */
#define KERNEL_SUITE raster_kernels
#include "raster_kernels_body.h"

#include <math.h>

/* src/raster/circle.c writes asin(+-1) in as this constant for the column
 * edges a small disc clamps to +-r (the AA disc's bytes rest on it). */
Test(raster_kernels, asin_of_one_is_the_constant_the_disc_writes_in)
{
    volatile double one = 1.0; /* computed at run time, by this libm */
    cr_assert(asin(one) == 1.5707963267948966);
    cr_assert(asin(-one) == -1.5707963267948966);
}
