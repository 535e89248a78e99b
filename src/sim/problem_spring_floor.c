/* SPDX-License-Identifier: MIT */
/* A spring on a floor: the energy a bounce keeps under a force that varies
 * along the path (iskra/problems.h). */
#include <math.h>

#include "iskra/limits.h"
#include "iskra/problems.h"

double isk_problem_spring_floor_energy(const isk_particles *p, size_t i)
{
    /* per unit mass: |v|^2/2 + (kQ/2) |r|^2, kQ = 4 */
    return 0.5 * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]) + 2.0 * (p->x[i] * p->x[i] + p->y[i] * p->y[i]);
}

isk_status isk_problem_spring_floor_setup(isk_system *s, size_t count, int floor)
{
    if (!s)
        return ISK_ERR_NULL;
    if (count == 0 || count > ISK_PARTICLES_MAX)
        return ISK_ERR_RANGE;
    isk_potential spring;
    isk_potential_init(&spring, 4.0, isk_vec2_make(0.0, 0.0), 1.0);
    isk_bounds walls;
    isk_status st = isk_potential_set_law(&spring, ISK_COULOMB_LAW_CODE, 0.0); /* P = 0: F = kQ (centre - r) */
    if (st == ISK_OK)
        st = isk_bounds_reflect(&walls, -10.0, 10.0, -1.0, 10.0, ISK_SIDE_BOTTOM, 0.0, 1.0);
    if (st == ISK_OK)
        st = isk_particles_reserve(&s->particles, count);
    if (st != ISK_OK)
        return st;
    if ((st = isk_system_add_potential(s, &spring, NULL)) != ISK_OK) /* appended: the old list is intact */
        return st;
    /* the spring alone: the system keeps its array of potentials */
    isk_forces f = {0};
    f.pot = s->forces.pot;
    f.pot[0] = f.pot[s->forces.npot - 1];
    f.npot = 1;
    f.centre = ISK_FIDELITY_SOUND;
    s->forces = f;
    s->particles.count = 0;
    s->bounds.sides = 0;
    s->bounce_in_step = 0;
    s->time = 0.0;
    if (floor && (st = isk_system_set_bounds(s, &walls, 1)) != ISK_OK)
        return st;
    for (size_t i = 0; i < count && st == ISK_OK; i++)
        st = isk_particles_add(&s->particles, 0.6, 2.0, 0.0, 0.0, 1.0, NULL);
    return st;
}

isk_status isk_problem_spring_floor(isk_integrator method, double dt, double seconds, int floor,
                                    isk_spring_floor *out)
{
    if (!out)
        return ISK_ERR_NULL;
    if (!isfinite(dt) || !isfinite(seconds))
        return ISK_ERR_NAN;
    if ((unsigned)method >= ISK_INTEGRATOR_COUNT || !(dt > 0.0 && dt <= ISK_DT_MAX) ||
        !(seconds > 0.0 && seconds <= 1e6))
        return ISK_ERR_RANGE;
    isk_system s;
    isk_status st = isk_system_init(&s, 1, 1);
    if (st != ISK_OK)
        return st;
    st = isk_problem_spring_floor_setup(&s, 1, floor);
    if (st == ISK_OK)
        st = isk_system_set_integrator(&s, method);
    const double e0 = isk_problem_spring_floor_energy(&s.particles, 0);
    int bounces = 0;
    const long steps = lround(seconds / dt);
    for (long k = 0; k < steps && st == ISK_OK; k++) {
        const double vy = s.particles.vy[0];
        st = isk_system_step(&s, dt);
        /* a contact: falling, then rising below the spring's centre (the
         * spring alone turns a particle round only above y = -0.6 - it
         * starts at rest at distance sqrt(4.36) - and only at rest) */
        bounces += vy < 0.0 && s.particles.vy[0] > 0.0 && s.particles.y[0] < -0.5;
    }
    if (st == ISK_OK && s.particles.count != 1)
        st = ISK_ERR_RANGE; /* (a state gone non-finite was removed) */
    if (st == ISK_OK) {
        out->change = isk_problem_spring_floor_energy(&s.particles, 0) / e0 - 1.0;
        out->bounces = floor ? bounces : 0;
    }
    isk_system_free(&s);
    return st;
}
