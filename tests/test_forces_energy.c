/* SPDX-License-Identifier: MIT */
/* isk_forces_potential_energy (iskra/forces.h): for every force law, the
 * energy's negative gradient is the force isk_forces_eval applies,
 * checked by central differences at a few points; every law the library
 * names has a case here, so a new law cannot go without its energy. */
#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

#include "iskra/forces.h"

/* One law acting alone (or a variant of one). */
typedef struct law_case {
    const char *what;
    unsigned law;          /* the ISK_LAW_* bit isk_forces_laws must report */
    double P, min_dist, max_dist, charge;
    double gravity, ax, ay, drag;
    int potential;         /* 1: one potential with P, min, max, charge */
    double px[3], py[3];   /* where to check */
} law_case;

#define FAR {2.0, -1.0, 0.9}, {1.0, 3.0, -0.4}
static const law_case cases[] = {
    {"gravity", ISK_LAW_GRAVITY, 0, 0, 0, 0, 9.81, 0, 0, 0, 0, FAR},
    {"acceleration", ISK_LAW_ACCEL, 0, 0, 0, 0, 0, 1.5, -2.5, 0, 0, FAR},
    {"drag", ISK_LAW_DRAG, 0, 0, 0, 0, 0, 0, 0, 0.7, 0, FAR},
    {"power 2, attracting", ISK_LAW_POWER_2, 2, ISK_DIST_OFF, ISK_DIST_OFF, 1, 0, 0, 0, 0, 1, FAR},
    {"power 2, repelling", ISK_LAW_POWER_2, 2, ISK_DIST_OFF, ISK_DIST_OFF, -1, 0, 0, 0, 0, 1, FAR},
    {"power 1", ISK_LAW_POWER_1, 1, ISK_DIST_OFF, ISK_DIST_OFF, -1, 0, 0, 0, 0, 1, FAR},
    {"power 3.5", ISK_LAW_POWER, 3.5, ISK_DIST_OFF, ISK_DIST_OFF, 1, 0, 0, 0, 0, 1, FAR},
    {"power 0.5", ISK_LAW_POWER, 0.5, ISK_DIST_OFF, ISK_DIST_OFF, 1, 0, 0, 0, 0, 1, FAR},
    {"power -1.5", ISK_LAW_POWER, -1.5, ISK_DIST_OFF, ISK_DIST_OFF, -1, 0, 0, 0, 0, 1, FAR},
    /* inside the min distance: the spring (points 0.56, 0.81, 0.78 from it) */
    {"power 2 inside min", ISK_LAW_POWER_2, 2, 1.5, ISK_DIST_OFF, 1, 0, 0, 0, 0, 1, {1.0, 0.2, 0.9}, {0.5, -0.5, -0.4}},
    {"power 3 inside min", ISK_LAW_POWER, 3, 1.5, ISK_DIST_OFF, 1, 0, 0, 0, 0, 1, {1.0, 0.2, 0.9}, {0.5, -0.5, -0.4}},
    {"cutoff", ISK_LAW_CUTOFF, 2, ISK_DIST_OFF, 0.3, 1, 0, 0, 0, 0, 1, FAR},
};
#define NCASES (sizeof cases / sizeof cases[0])

static void setup(const law_case *c, isk_forces *f, isk_potential *pot)
{
    memset(f, 0, sizeof *f);
    f->gravity = c->gravity;
    f->ax = c->ax;
    f->ay = c->ay;
    f->drag = c->drag;
    isk_potential_init(pot, 800, isk_vec2_make(0.5, 0.25), c->charge);
    pot->P = c->P;
    pot->min_dist = c->min_dist;
    pot->max_dist = c->max_dist;
    if (c->potential) {
        f->pot = pot;
        f->npot = 1;
    }
}

static double energy_at(const isk_forces *f, double m, double x, double y)
{
    double u = NAN;
    cr_assert_eq(isk_forces_potential_energy(f, 1, &x, &y, &m, &u), ISK_OK);
    return u;
}

/* F = -grad U, by central differences, for each law at each point, for a
 * particle of mass 2 at rest (drag: moving, and its U is 0). */
Test(forces_energy, the_force_is_minus_the_gradient_for_every_law)
{
    for (size_t k = 0; k < NCASES; k++) {
        const law_case *c = &cases[k];
        isk_forces f;
        isk_potential pot;
        setup(c, &f, &pot);
        cr_assert(isk_forces_laws(&f) & c->law, "%s: law not acting", c->what);
        for (int i = 0; i < 3; i++) {
            double x = c->px[i], y = c->py[i], vx = 0.3, vy = -1.1, m = 2.0;
            double fx, fy, sx, sy;
            isk_forces_eval(&f, 1, &x, &y, &vx, &vy, &m, &fx, &fy, &sx, &sy, 1);
            if (c->law == ISK_LAW_DRAG) {
                cr_expect(fx != 0.0 && fy != 0.0);
                cr_expect_eq(energy_at(&f, m, x, y), 0.0, "drag has no potential energy");
                continue;
            }
            const double h = 1e-5;
            double gx = -(energy_at(&f, m, x + h, y) - energy_at(&f, m, x - h, y)) / (2 * h);
            double gy = -(energy_at(&f, m, x, y + h) - energy_at(&f, m, x, y - h)) / (2 * h);
            double size = hypot(fx, fy), err = hypot(gx - fx, gy - fy);
            cr_log_info("%s at (%g, %g): F (%.9g, %.9g), -grad U (%.9g, %.9g)", c->what, x, y, fx, fy, gx, gy);
            cr_expect_gt(size, 0.0, "%s: no force at (%g, %g)", c->what, x, y);
            cr_expect_leq(err, 1e-6 * size, "%s at (%g, %g): F (%.9g, %.9g) but -grad U (%.9g, %.9g)", c->what, x, y,
                          fx, fy, gx, gy);
        }
    }
}

/* Every law the library names (isk_force_law_name) has a case above, and
 * isk_forces_potential_energy accepts it. */
Test(forces_energy, every_named_law_has_a_case)
{
    int named = 0;
    for (unsigned bit = 1; bit; bit <<= 1) {
        if (!isk_force_law_name(bit))
            continue;
        named++;
        int found = 0;
        for (size_t k = 0; k < NCASES; k++)
            found |= cases[k].law == bit;
        cr_expect(found, "law \"%s\" has no energy case", isk_force_law_name(bit));
    }
    cr_expect_geq(named, 7);
}

/* Inside the min distance the spring joins the law continuously, for P = 2
 * and another P; the zeros are where iskra/forces.h says. */
Test(forces_energy, continuous_at_the_min_distance_with_its_zeros)
{
    static const double Ps[2] = {2.0, 3.0};
    for (int k = 0; k < 2; k++) {
        isk_forces f;
        isk_potential pot;
        setup(&cases[9], &f, &pot);
        pot.P = Ps[k];
        const double mn = pot.min_dist, x0 = pot.r.x + mn;
        double in = energy_at(&f, 1, x0 * (1 - 1e-12), pot.r.y), out = energy_at(&f, 1, x0 * (1 + 1e-12), pot.r.y);
        cr_expect_leq(fabs(in - out), 1e-8 * fabs(out) + 1e-9, "P %g: %.15g inside, %.15g outside", Ps[k], in, out);
    }
    isk_forces f;
    isk_potential pot;
    setup(&cases[3], &f, &pot);
    cr_expect_eq(energy_at(&f, 1, pot.r.x + 1.0, pot.r.y), 0.0, "P = 2: zero at distance 1");
    pot.P = 3.0;
    double far = energy_at(&f, 1, pot.r.x + 1e8, pot.r.y);
    cr_expect(far < 0 && far > -1e-5, "P > 2: zero far away (%g at 1e8)", far);
    pot.P = 1.5;
    cr_expect_eq(energy_at(&f, 1, pot.r.x, pot.r.y), 0.0, "P < 2: zero at the centre");
}

/* What counts: picked, enabled potentials of non-zero strength; x_mult
 * does not change U; at the centre, the law's limit. */
Test(forces_energy, which_potentials_count)
{
    isk_potential pots[2];
    isk_potential_init(&pots[0], 800, isk_vec2_make(0.5, 0.25), 1);
    isk_potential_init(&pots[1], 300, isk_vec2_make(-2, 1), -1);
    isk_forces both = {.pot = pots, .npot = 2}, first = {.pot = pots, .npot = 1};
    const size_t pick[1] = {1};
    isk_forces second = {.pot = pots, .npot = 2, .pick = pick, .npick = 1};
    const double x = 1.7, y = 2.2;
    double u0 = energy_at(&first, 1, x, y), u01 = energy_at(&both, 1, x, y), u1 = energy_at(&second, 1, x, y);
    cr_expect_eq(u01, u0 + u1);
    pots[1].enabled = 0;
    cr_expect_eq(energy_at(&both, 1, x, y), u0, "switched off: not counted");
    pots[1].enabled = 1;
    pots[1].k = 0;
    cr_expect_eq(energy_at(&both, 1, x, y), u0, "k = 0: not counted");
    pots[0].x_mult = 3;
    cr_expect_eq(energy_at(&first, 1, x, y), u0, "x_mult: U of x_mult 1");
    pots[0].x_mult = 1;
    /* exactly at the centre, no min distance */
    pots[0].P = 1;
    cr_expect_eq(energy_at(&first, 1, 0.5, 0.25), 0.0, "P < 2: 0");
    pots[0].P = 2;
    cr_expect(isinf(energy_at(&first, 1, 0.5, 0.25)) && energy_at(&first, 1, 0.5, 0.25) < 0);
    pots[0].P = 3;
    cr_expect(isinf(energy_at(&first, 1, 0.5, 0.25)) && energy_at(&first, 1, 0.5, 0.25) < 0);
}

/* An emitter's weight w is the acceleration (0, w): the same energy, bit
 * for bit, as a gravity g = -w; and n particles sum in order. */
Test(forces_energy, weight_as_gravity_and_sums)
{
    isk_forces g = {.gravity = 3.25}, w = {.ay = -3.25};
    const double x[4] = {0.5, -7, 3e3, 1e-3}, y[4] = {2, -4.5, 0.125, 1e5}, m[4] = {1, 2.5, 1e-3, 7};
    double sum = 0;
    for (int i = 0; i < 4; i++) {
        cr_expect_eq(energy_at(&g, m[i], x[i], y[i]), energy_at(&w, m[i], x[i], y[i]));
        cr_expect_eq(energy_at(&g, m[i], x[i], y[i]), m[i] * 3.25 * y[i]);
        sum = sum + energy_at(&g, m[i], x[i], y[i]);
    }
    double all;
    cr_assert_eq(isk_forces_potential_energy(&g, 4, x, y, m, &all), ISK_OK);
    cr_expect_eq(all, sum);
    cr_assert_eq(isk_forces_potential_energy(&g, 0, NULL, NULL, NULL, &all), ISK_OK);
    cr_expect_eq(all, 0.0);
}

Test(forces_energy, bad_arguments)
{
    isk_forces f = {.gravity = 1};
    double x = 0, y = 0, m = 1, u = 5;
    cr_expect_eq(isk_forces_potential_energy(NULL, 1, &x, &y, &m, &u), ISK_ERR_NULL);
    cr_expect_eq(isk_forces_potential_energy(&f, 1, &x, &y, &m, NULL), ISK_ERR_NULL);
    cr_expect_eq(isk_forces_potential_energy(&f, 1, NULL, &y, &m, &u), ISK_ERR_NULL);
    cr_expect_eq(isk_forces_potential_energy(&f, 1, &x, NULL, &m, &u), ISK_ERR_NULL);
    cr_expect_eq(isk_forces_potential_energy(&f, 1, &x, &y, NULL, &u), ISK_ERR_NULL);
    f.npot = 2;
    cr_expect_eq(isk_forces_potential_energy(&f, 1, &x, &y, &m, &u), ISK_ERR_NULL, "potentials NULL with a count");
    cr_expect_eq(u, 5, "nothing written on error");
}
