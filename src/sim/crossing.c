/* SPDX-License-Identifier: MIT */
/* Gates: the deflectors' exact crossing test (src/sim/segment_exact.h),
 * counted per direction for the probes (src/sim/crossing.h says how). */
#include "sim/crossing.h"

#include "sim/segment_exact.h"

void isk__segment_crossings(const isk_deflector *gate, size_t n, const double *x, const double *y,
                            const double *prev, size_t stride, uint64_t *forward, uint64_t *backward)
{
    const isk__seg s = isk__seg_canon(gate);
    /* canon may have swapped the end points: the given direction's left is
     * then the canonical right */
    const int swapped = !isk__seg_in_order(gate);
    uint64_t f = 0, b = 0;
    for (size_t i = 0; i < n; i++) {
        const double *p = prev + stride * i;
        if (isk__seg_crossing(&s, p[0], p[1], x[i], y[i]) < 0.0)
            continue;
        const int from_left = (isk__seg_side(&s, p[0], p[1]) > 0.0) != swapped;
        f += (uint64_t)from_left;
        b += (uint64_t)!from_left;
    }
    *forward += f;
    *backward += b;
}
