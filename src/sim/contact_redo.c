/* SPDX-License-Identifier: MIT */
/* The rest of a step flown by the integrator (iskra/contacts.h), for the
 * contact pass (src/sim/contact_pass.h): where a force changes along the
 * path (a spring, a potential), the flight fitted to the step's ends is
 * only an approximation, so after a contact the pass asks the integrator
 * itself for the state at the contact and for the rest of the step.  A
 * bounce then changes the energy by the integrator's own error and no
 * more (docs/accuracy.md). */
#include <math.h>

#include "sim/contact_pass.h"

/* One step of the integrator of c->redo over t from st. */
static isk__state redo_step(const isk__contact_ctx *c, isk__state st, double m, double t)
{
    if (t > 0.0)
        isk_integrate_block(c->redo->method, c->redo->forces, c->scratch, 1, &st.x, &st.y, &st.vx, &st.vy, &m, t);
    return st;
}

/* The integrator's state at the contact the flight puts at *tau after the
 * start st0 (at most s_max): one step of the integrator over *tau, its
 * time refined by a Newton step on the signed distance nx x + ny y - off
 * to the wall or the segment's line, so that the contact is where the
 * integrator's own path meets it.  The flight is fitted to the ends of
 * that path, so one step brings the distance down to rounding. */
isk__state isk__redo_contact(const isk__contact_ctx *c, isk__state st0, double m, double *tau, double s_max,
                             double nx, double ny, double off)
{
    isk__state st = redo_step(c, st0, m, *tau);
    const double g = nx * st.x + ny * st.y - off, gp = nx * st.vx + ny * st.vy;
    const double t1 = gp != 0.0 ? *tau - g / gp : *tau;
    if (t1 != *tau && t1 > 0.0 && t1 <= s_max && isfinite(t1)) {
        st = redo_step(c, st0, m, t1);
        *tau = t1;
    }
    return st;
}

/* At a contact resolved with the integrator, the velocity reflected is the
 * integrator's own (its state at the contact), not the flight's: the
 * flight's offset from it (which a potential makes of the order of the
 * force's change over the step) is dropped, or it would be added to the
 * reflected velocity and change the energy at every bounce. */
void isk__redo_own_velocity(isk__flight *f)
{
    f->delx = f->dely = 0.0;
}

/* After a contact resolved with the integrator: the rest of the step, from
 * the flight's new start (its velocity plus the offset, the integrator's
 * form: *start), is one step of the integrator; its end becomes the
 * particle's and the flight is fitted to it (to find the next contact).
 * Returns the integrator's end state. */
isk__state isk__redo_rest(const isk__contact_ctx *c, isk__flight *f, double m, isk__state *start)
{
    const isk__state st0 = {f->sx, f->sy, f->ux + f->delx, f->uy + f->dely};
    *start = st0;
    if (!(f->s > 0.0))
        return st0;
    const isk__state end = redo_step(c, st0, m, f->s);
    isk__flight g = *f;
    isk__fl_fit(st0.x, st0.vx, end.x, end.vx, f->k, f->s, &g.ux, &g.ax, &g.delx);
    isk__fl_fit(st0.y, st0.vy, end.y, end.vy, f->k, f->s, &g.uy, &g.ay, &g.dely);
    if (isfinite(g.ux) && isfinite(g.uy) && isfinite(g.ax) && isfinite(g.ay) && isfinite(g.delx) &&
        isfinite(g.dely))
        *f = g;
    return end;
}
