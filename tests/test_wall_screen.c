/* SPDX-License-Identifier: MIT */
/* The walls' screen (src/sim/wall_screen.h): the portable build flags
 * exactly the groups with a finite particle outside the box and gives the
 * walls' own per-particle masks (no false alarm, not even a -0 on a +0
 * wall), and the AVX2 and AVX-512 builds (when this CPU has them) give the
 * same flags and masks as the portable one for every input: inside,
 * outside, on a wall, signed zeros, subnormals, infinities, NaNs of both
 * signs, missing walls at +-inf, and every length of tail. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "sim/wall_screen.h"

enum { N = ISK_WALL_SCREEN_SPAN };

/* The walls' rule, particle by particle: the flags, and the masks of every
 * group the call covers. */
static uint64_t reference(size_t n, const double *x, const double *y, const isk_wall_box *w, isk_wall_outside *out)
{
    memset(out, 0, sizeof *out);
    uint64_t flags = 0;
    for (size_t i = 0; i < n; i++) {
        const size_t g = i / ISK_WALL_SCREEN, j = i % ISK_WALL_SCREEN;
        if (!(x[i] >= w->left && x[i] <= w->right))
            out->x[g] |= (uint16_t)(1u << j);
        if (!(y[i] >= w->bottom && y[i] <= w->top))
            out->y[g] |= (uint16_t)(1u << j);
        if (out->x[g] | out->y[g])
            flags |= (uint64_t)1 << g;
    }
    return flags;
}

/* The groups a call covers. */
static size_t groups_of(size_t n)
{
    return (n + ISK_WALL_SCREEN - 1) / ISK_WALL_SCREEN;
}

static uint64_t lcg(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return *s >> 11;
}

static double negative_nan(void)
{
    double v = NAN;
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    u |= (uint64_t)1 << 63;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* A coordinate near the box [lo, hi], mostly inside, sometimes on or past
 * a wall, sometimes a special value (only when `finite` is 0). */
static double pick(uint64_t *s, double lo, double hi, int finite)
{
    const double special[] = {0.0, -0.0, 5e-324, -5e-324, INFINITY, -INFINITY, NAN, negative_nan(), 1e308, -1e308};
    const uint64_t r = lcg(s) % 1000;
    if (r < 3)
        return lo;
    if (r < 6)
        return hi;
    if (r < 8)
        return nextafter(lo, -INFINITY);
    if (r < 10)
        return nextafter(hi, INFINITY);
    if (r < 20 && !finite)
        return special[lcg(s) % (sizeof special / sizeof special[0])];
    if (r < 20)
        return special[lcg(s) % 4];
    const double u = (double)(lcg(s) >> 1) / 4503599627370496.0; /* [0, 1) */
    const double pad = isfinite(hi - lo) ? 0.001 * (hi - lo) : 1.0;
    return r < 990 ? lo + u * (hi - lo) : lo - pad + u * pad;
}

static void fill(uint64_t seed, double *x, double *y, const isk_wall_box *w, int finite)
{
    uint64_t s = seed;
    for (size_t i = 0; i < N; i++) {
        x[i] = pick(&s, isfinite(w->left) ? w->left : -10, isfinite(w->right) ? w->right : 10, finite);
        y[i] = pick(&s, isfinite(w->bottom) ? w->bottom : -10, isfinite(w->top) ? w->top : 10, finite);
    }
}

static const isk_wall_box BOXES[] = {
    {0, 10, 0, 10},
    {-5, 5, 0, 10},
    {-INFINITY, INFINITY, 0, 10}, /* floor and ceiling only */
    {0, 10, -INFINITY, INFINITY}, /* side walls only */
    {-INFINITY, 3, 1e-300, INFINITY},
    {-1e300, 1e300, -1e-300, 1e-300},
};

Test(wall_screen, portable_gives_the_walls_own_masks_for_finite_values)
{
    static double x[N], y[N];
    for (size_t b = 0; b < sizeof BOXES / sizeof BOXES[0]; b++)
        for (uint64_t seed = 1; seed <= 20; seed++) {
            fill(seed * 7919 + b, x, y, &BOXES[b], 1);
            for (size_t n = 0; n <= N; n += n < 40 ? 1 : 37) {
                isk_wall_outside got, want;
                memset(&got, 0xa5, sizeof got);
                const uint64_t fg = isk__wall_screen_portable(n, x, y, &BOXES[b], &got);
                const uint64_t fw = reference(n, x, y, &BOXES[b], &want);
                cr_assert_eq(fg, fw, "box %zu seed %llu n %zu: flags %llx, want %llx", b, (unsigned long long)seed, n,
                             (unsigned long long)fg, (unsigned long long)fw);
                for (size_t g = 0; g < groups_of(n); g++)
                    cr_assert(got.x[g] == want.x[g] && got.y[g] == want.y[g],
                              "box %zu seed %llu n %zu group %zu: masks %x %x, want %x %x", b,
                              (unsigned long long)seed, n, g, got.x[g], got.y[g], want.x[g], want.y[g]);
            }
        }
}

Test(wall_screen, one_outlier_flags_its_own_group_and_bit_only)
{
    static double x[N], y[N];
    const isk_wall_box *w = &BOXES[0];
    isk_wall_outside out;
    for (size_t i = 0; i < N; i++)
        x[i] = y[i] = 5.0;
    x[0] = 0.0, y[N - 1] = 10.0, x[1] = -0.0; /* on the walls: inside (-0 too) */
    cr_assert_eq(isk__wall_screen_portable(N, x, y, w, &out), 0);
    for (size_t i = 2; i < N; i += 13) {
        double *axis = i % 2 ? y : x, keep = axis[i];
        axis[i] = i % 4 < 2 ? nextafter(0.0, -1.0) : nextafter(10.0, 11.0);
        const size_t g = i / ISK_WALL_SCREEN;
        cr_assert_eq(isk__wall_screen_portable(N, x, y, w, &out), (uint64_t)1 << g, "particle %zu", i);
        const uint16_t bit = (uint16_t)(1u << (i % ISK_WALL_SCREEN));
        cr_assert(out.x[g] == (i % 2 ? 0 : bit) && out.y[g] == (i % 2 ? bit : 0), "particle %zu: masks %x %x", i,
                  out.x[g], out.y[g]);
        axis[i] = keep;
    }
}

Test(wall_screen, avx2_and_avx512_give_the_portable_flags_and_masks_for_every_input)
{
    const isk_wall_screen_fn avx2 = isk__wall_screen_avx2(), avx512 = isk__wall_screen_avx512();
    if (!avx2) {
        /* info, not a warning: Criterion fails a run that logs one */
        cr_log_info("no AVX2 on this CPU or in this build: only the portable screen is checked");
        return;
    }
    cr_assert_eq(isk__wall_screen_pick(), avx512 ? avx512 : avx2, "the pick is the widest build");
    const isk_wall_screen_fn builds[2] = {avx2, avx512};
    static double x[N], y[N];
    for (int k = 0; k < 2 && builds[k]; k++)
        for (size_t b = 0; b < sizeof BOXES / sizeof BOXES[0]; b++)
            for (uint64_t seed = 1; seed <= 40; seed++) {
                fill(seed * 104729 + b, x, y, &BOXES[b], seed % 2);
                for (size_t n = 0; n <= N; n += n < 40 ? 1 : 37) {
                    isk_wall_outside got, want;
                    memset(&got, 0xa5, sizeof got);
                    memset(&want, 0x5a, sizeof want);
                    cr_assert_eq(builds[k](n, x, y, &BOXES[b], &got), isk__wall_screen_portable(n, x, y, &BOXES[b], &want),
                                 "%s: box %zu seed %llu n %zu", k ? "avx512" : "avx2", b, (unsigned long long)seed,
                                 n);
                    for (size_t g = 0; g < groups_of(n); g++)
                        cr_assert(got.x[g] == want.x[g] && got.y[g] == want.y[g],
                                  "%s: box %zu seed %llu n %zu group %zu", k ? "avx512" : "avx2", b,
                                  (unsigned long long)seed, n, g);
                }
            }
}
