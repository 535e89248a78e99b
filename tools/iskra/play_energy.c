/* SPDX-License-Identifier: MIT */
/* The energy of the running state, for the simulator's chart and its
 * integrators' drift: kinetic (1/2 m v^2), gravitational (m g y per gravity
 * force an emitter uses, times its gravity multiplier; a wind's -m a.r) and
 * the potentials' own.
 *
 * A potential pulls with F = kQ (r_p - r) / d^P (iskra/forces.h), which is
 * -grad of U = kQ d^(2-P) / (2-P), or kQ ln d for P = 2; inside its min
 * distance the force is the spring kQ (r_p - r) / min^P, so U = kQ d^2 /
 * (2 min^P) there, joined continuously at min.  An x multiplier other than
 * 1 makes the force non-conservative: U is then that of x multiplier 1.
 * Drag has no potential: energy it takes shows as a falling total. */
#include <math.h>

#include "play.h"

static double radial(double d, double P)
{
    return P == 2 ? log(d) : pow(d, 2 - P) / (2 - P);
}

static double potential_energy(const isk_potential *pot, double x, double y)
{
    const double kq = pot->charge * pot->k, d = hypot(pot->r.x - x, pot->r.y - y), P = pot->P;
    if (!pot->enabled || kq == 0)
        return 0;
    if (pot->min_dist > 0 && d < pot->min_dist) {
        const double m = pot->min_dist;
        return kq * (d * d / (2 * pow(m, P)) - pow(m, 2 - P) / 2 + radial(m, P));
    }
    return d > 0 ? kq * radial(d, P) : 0;
}

/* The live potential of force f (isk_effect_potentials is in force order). */
static const isk_potential *live_of(const isk_effect_def *d, const isk_potential *pots, size_t n, int f)
{
    size_t k = 0;
    for (int i = 0; i < d->nforces && k < n; i++)
        if (d->forces[i].kind == ISK_FORCE_POTENTIAL) {
            if (i == f)
                return &pots[k];
            k++;
        }
    return NULL;
}

play_energy play_energy_of(const isk_effect *fx)
{
    play_energy e = {0, 0, 0};
    const isk_effect_def *d = isk_effect_definition(fx);
    size_t npots;
    const isk_potential *pots = isk_effect_potentials(fx, &npots);
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        const isk_emitter_def *em = &d->emitters[g];
        double g_sum = 0, ax = 0, ay = 0;
        const isk_potential *used[ISK_EFFECT_MAX_FORCES];
        int nused = 0;
        for (int r = 0; r < em->nforces; r++) {
            const isk_force_def *f = &d->forces[em->forces[r]];
            if (f->kind == ISK_FORCE_GRAVITY) {
                g_sum += f->g * em->gravity_mult;
            } else if (f->kind == ISK_FORCE_WIND) {
                ax += f->accel.x;
                ay += f->accel.y;
            } else if (f->kind == ISK_FORCE_POTENTIAL) {
                const isk_potential *pot = live_of(d, pots, npots, em->forces[r]);
                if (pot)
                    used[nused++] = pot;
            }
        }
        for (size_t i = 0; i < p->count; i++) {
            const double m = p->m[i];
            e.kinetic += 0.5 * m * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]);
            e.gravity += m * (g_sum * p->y[i] - ax * p->x[i] - ay * p->y[i]);
            for (int k = 0; k < nused; k++)
                e.potential += potential_energy(used[k], p->x[i], p->y[i]);
        }
    }
    return e;
}
