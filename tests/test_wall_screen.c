/* The walls' screen (src/sim/wall_screen.h): the portable build flags
 * the groups with a particle outside the box (the only false alarm for
 * finite values: a -0 on a +0 wall), and the AVX2 build (when this CPU has
 * it) gives the same flags as the portable one for
 * every input: inside, outside, on a wall, signed zeros, subnormals,
 * infinities, NaNs of both signs, missing walls at +-inf, and every
 * length of tail. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "sim/wall_screen.h"

enum { N = ISK_WALL_SCREEN_SPAN };

/* The exact rule for finite coordinates, group by group. */
static uint64_t reference(size_t n, const double *x, const double *y, const isk_wall_box *w)
{
    uint64_t flags = 0;
    for (size_t i = 0; i < n; i++)
        if (!(x[i] >= w->left && x[i] <= w->right && y[i] >= w->bottom && y[i] <= w->top))
            flags |= (uint64_t)1 << (i / ISK_WALL_SCREEN);
    return flags;
}

/* Groups holding a zero: -0 - (+0) is -0, so a -0 on a +0 wall is flagged
 * though it is inside (a false alarm, dismissed by the exact test). */
static uint64_t zero_groups(size_t n, const double *x, const double *y)
{
    uint64_t flags = 0;
    for (size_t i = 0; i < n; i++)
        if (x[i] == 0.0 || y[i] == 0.0)
            flags |= (uint64_t)1 << (i / ISK_WALL_SCREEN);
    return flags;
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

Test(wall_screen, portable_flags_the_groups_with_a_particle_outside)
{
    static double x[N], y[N];
    for (size_t b = 0; b < sizeof BOXES / sizeof BOXES[0]; b++)
        for (uint64_t seed = 1; seed <= 20; seed++) {
            fill(seed * 7919 + b, x, y, &BOXES[b], 1);
            for (size_t n = 0; n <= N; n += n < 40 ? 1 : 37) {
                const uint64_t got = isk_wall_screen_portable(n, x, y, &BOXES[b]), want = reference(n, x, y, &BOXES[b]);
                const uint64_t zero = zero_groups(n, x, y);
                cr_assert_eq(got & want, want, "box %zu seed %llu n %zu: a group outside not flagged", b,
                             (unsigned long long)seed, n);
                cr_assert_eq(got & ~zero, want & ~zero, "box %zu seed %llu n %zu: a false alarm", b,
                             (unsigned long long)seed, n);
            }
        }
}

Test(wall_screen, one_outlier_flags_its_own_group_only)
{
    static double x[N], y[N];
    const isk_wall_box *w = &BOXES[0];
    for (size_t i = 0; i < N; i++)
        x[i] = y[i] = 5.0;
    x[0] = 0.0, y[N - 1] = 10.0; /* on the walls: inside */
    cr_assert_eq(isk_wall_screen_portable(N, x, y, w), 0);
    for (size_t i = 0; i < N; i += 13) {
        double *axis = i % 2 ? y : x, keep = axis[i];
        axis[i] = i % 4 < 2 ? nextafter(0.0, -1.0) : nextafter(10.0, 11.0);
        cr_assert_eq(isk_wall_screen_portable(N, x, y, w), (uint64_t)1 << (i / ISK_WALL_SCREEN), "particle %zu", i);
        axis[i] = keep;
    }
}

Test(wall_screen, avx2_and_avx512_give_the_portable_flags_for_every_input)
{
    const isk_wall_screen_fn avx2 = isk_wall_screen_avx2(), avx512 = isk_wall_screen_avx512();
    if (!avx2) {
        cr_log_warn("no AVX2 on this CPU or in this build: only the portable screen is checked");
        return;
    }
    cr_assert_eq(isk_wall_screen_pick(), avx512 ? avx512 : avx2, "the pick is the widest build");
    const isk_wall_screen_fn builds[2] = {avx2, avx512};
    static double x[N], y[N];
    for (int k = 0; k < 2 && builds[k]; k++)
        for (size_t b = 0; b < sizeof BOXES / sizeof BOXES[0]; b++)
            for (uint64_t seed = 1; seed <= 40; seed++) {
                fill(seed * 104729 + b, x, y, &BOXES[b], seed % 2);
                for (size_t n = 0; n <= N; n += n < 40 ? 1 : 37)
                    cr_assert_eq(builds[k](n, x, y, &BOXES[b]), isk_wall_screen_portable(n, x, y, &BOXES[b]),
                                 "%s: box %zu seed %llu n %zu", k ? "avx512" : "avx2", b, (unsigned long long)seed,
                                 n);
                /* every group with its special values */
                cr_assert_eq(builds[k](N, x, y, &BOXES[b]), isk_wall_screen_portable(N, x, y, &BOXES[b]));
            }
}
