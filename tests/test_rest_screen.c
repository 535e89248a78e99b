/* SPDX-License-Identifier: MIT */
/* The walls' resting screen (src/sim/rest_screen.h) on every build this
 * CPU runs: the portable one and AVX2 give the same verdicts, and every
 * particle a build says rests is one the walls themselves rest, bit for
 * bit (isk_bounds_apply_step on that particle alone puts it on the wall
 * with the integrator's offset velocity).  Inputs: the end states resting
 * particles of many masses make, states a little off them (hopping,
 * falling, deeper, faster), masses whose drag rates the series does not
 * cover (0, tiny, huge, negative, infinite, NaN), non-finite states,
 * gravity down, up and along x, with and without drag, every group
 * length. */
#include <criterion/criterion.h>
#include <criterion/logging.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "iskra/bounds.h"
#include "sim/rest_screen.h"
#include "sim/wall_screen.h"

static uint64_t lcg(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return *s >> 11;
}

static double unit(uint64_t *s)
{
    return (double)lcg(s) / 9007199254740992.0; /* 53 bits */
}

static double mass(uint64_t *s)
{
    static const double odd[] = {0.0, 1e-300, 1e300, -1.0, INFINITY, NAN, 1e-3};
    if (lcg(s) % 8 == 0)
        return odd[lcg(s) % (sizeof odd / sizeof odd[0])];
    return 0.5 + 2.0 * unit(s);
}

/* What semi-implicit Euler with linear drag makes of a particle resting on
 * the wall `wall` (velocity delta) in one step: v1 = v0 + h (a - k v0),
 * p1 = wall + h v1; and, now and then, a state a little off it: around the
 * thresholds of impact_axis's resting test (a start speed of |a| h / 64, a
 * start |a| h^2 / 64 off the wall), up to twenty times past them (where
 * the walls' answer is no longer a rest: below that, the few hops left fit
 * in the step and it rests all the same), and far from them.  Returns 1
 * for the resting state itself. */
static int end_state(uint64_t *s, double wall, double a, double delta, double k, double h, double *p1, double *v1)
{
    const double slow = fabs(a) * h / 64.0, near = fabs(a) * h * h / 64.0, away = a < 0.0 ? 1.0 : -1.0;
    double v = delta + h * (a - k * delta), p = wall + h * v;
    int resting = 0;
    switch (lcg(s) % 12) {
    case 0: v *= 1.0 + 1e-3 * (unit(s) - 0.5); break;           /* a little faster or slower */
    case 1: p = wall + (p - wall) * (1.0 + unit(s)); break;     /* deeper */
    case 2: v = -v; break;                                      /* moving off the wall */
    case 3: v = v * 40.0; p = wall + h * v; break;              /* a real fall */
    case 4: p = NAN; break;
    case 5: v = lcg(s) % 2 ? INFINITY : -INFINITY; break;
    case 6: v += (4.0 * unit(s) - 2.0) * slow * (lcg(s) % 2 ? 1.0 : 20.0); p = wall + h * v; break; /* fast */
    case 7: p += away * 2.0 * unit(s) * near * (lcg(s) % 2 ? 1.0 : 20.0); break;                    /* far */
    default: resting = 1; break;
    }
    *p1 = p;
    *v1 = v;
    return resting;
}

Test(rest_screen, builds_agree_and_their_rests_are_the_walls_own)
{
    static const char *const name[3] = {"portable", "avx2", "avx512"};
    isk_rest_screen_fn all[3] = {isk__rest_screen_portable, isk__rest_screen_avx2(), isk__rest_screen_avx512()}, build[3];
    int nb = 0;
    const char *bname[3];
    for (int b = 0; b < 3; b++)
        if (all[b]) {
            bname[nb] = name[b];
            build[nb++] = all[b];
        }
    cr_log_info("builds: %d", nb);
    const double h = 1.0 / 60;
    uint64_t s = 11;
    long rested = 0, looked = 0;
    for (int round = 0; round < 4000; round++) {
        const int axis = (int)(lcg(&s) % 3); /* 0: gravity down, 1: up, 2: along x to the right */
        const double g = 9.81 * (0.5 + unit(&s));
        const double a = axis == 0 ? -g : g, drag = lcg(&s) % 4 ? 0.5 * unit(&s) : 0.0;
        const double offset = -0.5, delta = offset * a * h;
        const double lo = -3.0 + unit(&s), hi = 3.0 + unit(&s);
        const double wall = a < 0.0 ? lo : hi;
        const size_t n = 1 + lcg(&s) % ISK_WALL_SCREEN;
        double pos[ISK_WALL_SCREEN], vel[ISK_WALL_SCREEN], m[ISK_WALL_SCREEN], rest[3][ISK_WALL_SCREEN];
        int resting[ISK_WALL_SCREEN];
        for (size_t j = 0; j < n; j++) {
            m[j] = mass(&s);
            resting[j] = end_state(&s, wall, a, delta, drag > 0.0 ? drag / m[j] : 0.0, h, &pos[j], &vel[j]);
        }
        const isk_rest_axis ax = {a, delta, h, lo, hi, 0.5}; /* the walls' restitution below */
        for (int b = 0; b < nb; b++)
            build[b](n, pos, vel, drag > 0.0 ? m : NULL, drag, &ax, rest[b]);
        for (size_t j = 0; j < n; j++) {
            for (int b = 1; b < nb; b++)
                cr_assert(!memcmp(&rest[0][j], &rest[b][j], sizeof rest[0][j]),
                          "round %d, particle %zu: portable %g, %s %g", round, j, rest[0][j], bname[b], rest[b][j]);
            looked++;
            /* a resting particle of an ordinary mass is the case the screen is
             * for (with k = b/m above ~1/(64 h) the Euler step's drag makes it
             * start a hop of more than the walls' |a| h / 64, and it is not
             * resting at once: here, k <= 0.25) */
            if (resting[j] && m[j] >= 0.5 && m[j] <= 2.5 && drag / m[j] <= 0.25)
                cr_assert(rest[0][j] != 0.0, "round %d: a resting particle of mass %g not rested", round, m[j]);
            if (rest[0][j] == 0.0)
                continue;
            cr_assert(rest[0][j] == (a < 0.0 ? 1.0 : 2.0), "round %d: rests on the wall it is pulled from", round);
            rested++;
            /* the walls on this particle alone */
            double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
            double *p = axis == 2 ? &x : &y, *v = axis == 2 ? &vx : &vy;
            *p = pos[j];
            *v = vel[j];
            isk_bounds walls;
            cr_assert_eq(axis == 2 ? isk_bounds_reflect(&walls, lo, hi, -1e9, 1e9, ISK_SIDE_LEFT | ISK_SIDE_RIGHT, 0, 0.5)
                                   : isk_bounds_reflect(&walls, -1e9, 1e9, lo, hi, ISK_SIDE_BOTTOM | ISK_SIDE_TOP, 0, 0.5),
                         ISK_OK);
            const isk_step_motion mo = {NULL, NULL, NULL, NULL, m + j, drag, h, axis == 2 ? a : 0.0,
                                        axis == 2 ? 0.0 : a, offset};
            isk_bounds_apply_step(&walls, &mo, 1, &x, &y, &vx, &vy);
            cr_assert(*p == wall && !memcmp(v, &delta, sizeof delta),
                      "round %d: the screen rests (%a, %a) of mass %a, the walls give (%a, %a)", round, pos[j], vel[j],
                      m[j], *p, *v);
        }
    }
    cr_log_info("%ld of %ld rested", rested, looked);
    cr_assert_gt(rested, looked / 3, "the screen rested only %ld of %ld", rested, looked);
}
