/* The row kernels as this build compiles them (SSE2 on x86-64, AVX2 when the
 * CPU has it, else the vector-extension or per-pixel path) against the
 * per-pixel reference; see tests/raster_kernels_body.h. */
#define KERNEL_SUITE raster_kernels
#include "raster_kernels_body.h"
