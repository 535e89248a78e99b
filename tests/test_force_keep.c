/* SPDX-License-Identifier: MIT */
/* The sound mode's "force representable" mask (src/sim/kernels.h,
 * isk_k_force_keep): all ones exactly when islessequal(|gx|, limit) and
 * islessequal(|gy|, limit), the quiet tests it replaces, for ordinary
 * values, values at and one ulp around the limit, signed zeros,
 * subnormals, infinities and NaNs of both signs; and isk_k_keep gives the
 * value itself or +0.0. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "sim/kernels.h"

static double with_sign(double v)
{
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    u |= (uint64_t)1 << 63;
    memcpy(&v, &u, sizeof v);
    return v;
}

Test(force_keep, matches_the_quiet_compares)
{
    const double L = ISK_FORCE_LIMIT;
    const double base[] = {0.0,  5e-324, 2.2250738585072014e-308, 1.0, 3.5e100, nextafter(L, 0), L,
                           nextafter(L, INFINITY), 1e200, 1.7976931348623157e308, INFINITY, NAN};
    enum { NB = sizeof base / sizeof base[0] };
    double v[2 * NB];
    for (int i = 0; i < NB; i++) {
        v[i] = base[i];
        v[NB + i] = with_sign(base[i]); /* -0, -subnormal, ..., -inf, a NaN with its sign bit */
    }
    int kept = 0, dropped = 0;
    for (int i = 0; i < 2 * NB; i++)
        for (int j = 0; j < 2 * NB; j++) {
            const int want = islessequal(fabs(v[i]), L) && islessequal(fabs(v[j]), L);
            const uint64_t keep = isk_k_force_keep(v[i], v[j]);
            cr_assert_eq(keep, want ? ~(uint64_t)0 : 0, "gx %a gy %a: mask %llx, quiet compares %d", v[i], v[j],
                         (unsigned long long)keep, want);
            const double k = isk_k_keep(v[i], keep);
            if (want)
                cr_assert(memcmp(&k, &v[i], sizeof k) == 0, "kept %a came back %a", v[i], k);
            else
                cr_assert(k == 0.0 && !signbit(k), "dropped %a came back %a, not +0", v[i], k);
            kept += want;
            dropped += !want;
        }
    cr_assert_gt(kept, 0);
    cr_assert_gt(dropped, 0);
}
