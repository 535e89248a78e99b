/* SPDX-License-Identifier: MIT */
/* The energy of the running state, for the simulator's chart and its
 * integrators' drift: the kinetic energy 1/2 m v^2 of every particle, and
 * the potential energy the library gives for the forces each emitter's
 * particles feel (isk_forces_potential_energy of isk_effect_forces: its
 * gravity forces times gravity_multiplier, its winds and its weight, the
 * potentials it picks; iskra/forces.h has the laws).  So the chart shows
 * the energy of the forces that act, never a copy of them.
 *
 * Forces with no potential energy change the total, as they should: drag,
 * slowing, an emitter's radial, tangential and turbulent accelerations
 * (they depend on the velocity, the emitter or the time), and walls that
 * lose energy. */
#include <math.h>

#include "play.h"

play_energy play_energy_of(const isk_effect *fx)
{
    play_energy e = {0, 0};
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        for (size_t i = 0; i < p->count; i++)
            e.kinetic += 0.5 * p->m[i] * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]);
        double u;
        if (isk_forces_potential_energy(isk_effect_forces(fx, g), p->count, p->x, p->y, p->m, &u) != ISK_OK)
            u = NAN; /* a law without an energy: no number rather than a wrong one */
        e.potential += u;
    }
    return e;
}
