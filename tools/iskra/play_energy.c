/* SPDX-License-Identifier: MIT */
/* The energy of the running state, for the simulator's chart and its
 * integrators' drift (isk_effect_energy, iskra/probes.h): the kinetic
 * energy 1/2 m v^2 of every particle, and the potential energy the library
 * gives for the forces each emitter's
 * particles feel (isk_forces_potential_energy of isk_effect_forces: its
 * gravity forces times gravity_multiplier, its winds and its weight, the
 * potentials it picks; iskra/forces.h has the laws).  So the chart shows
 * the energy of the forces that act, never a copy of them.
 *
 * Forces with no potential energy change the total, as they should: drag,
 * slowing, an emitter's radial, tangential and turbulent accelerations
 * (they depend on the velocity, the emitter or the time), and walls that
 * lose energy. */
#include "iskra/probes.h"
#include "play.h"

/* The library's isk_effect_energy: the totals probe reads the same
 * function, so the chart and the probe show one number. */
play_energy play_energy_of(const isk_effect *fx)
{
    play_energy e = {0, 0};
    isk_effect_energy(fx, &e.kinetic, &e.potential);
    return e;
}
