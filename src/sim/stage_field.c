/* SPDX-License-Identifier: MIT */
/* The field stage (src/sim/field.h, src/sim/stage.h): v += a(x, y, t)*h for
 * the accelerations that depend on where a particle is, before the move.
 *
 * It runs first in the list, ahead of the forces and the integrator, so
 * the particle moves with the kicked velocity: for the field's part this
 * is the semi-implicit (symplectic) Euler step, which keeps an orbit
 * around a radial pull closed where a kick after the move would spiral
 * outwards.  Before the remember stage too: walls and deflectors see a
 * step that starts from the kicked velocity, as their flight assumes. */
#include <math.h>

#include "sim/field.h"
#include "sim/stage.h"

isk_field_turb isk__field_turbulence(double strength, double scale, double speed, uint64_t key)
{
    isk_field_turb t = {strength, 1.0 / scale, speed, key};
    return t;
}

/* The unit vector from the centre; none (zero) exactly on it, and a
 * length that overflows is measured by hypot. */
static void direction(double dx, double dy, double *ux, double *uy)
{
    double r = sqrt(dx * dx + dy * dy);
    if (!(r < INFINITY))
        r = hypot(dx, dy);
    if (r > 0.0 && r < INFINITY) {
        *ux = dx / r;
        *uy = dy / r;
    } else {
        *ux = *uy = 0.0;
    }
}

/* The direction from the centre; exactly on it, the direction the particle
 * leaves it in (where it is an instant later: its velocity's), so a
 * particle born on the emitter feels the pull from its first moment. */
static void from_centre(const isk_field *f, double x, double y, double vx, double vy, double *ux, double *uy)
{
    if (x == f->cx && y == f->cy)
        direction(vx, vy, ux, uy);
    else
        direction(x - f->cx, y - f->cy, ux, uy);
}

/* The acceleration at (x, y) with radial and tangential parts of these
 * sizes (the field's, or a particle's own). */
static void accel_with(const isk_field *f, double radial, double tangential, double x, double y, double vx,
                       double vy, double *ax, double *ay)
{
    double a = 0.0, b = 0.0;
    if (radial != 0.0 || tangential != 0.0) {
        double ux, uy;
        from_centre(f, x, y, vx, vy, &ux, &uy);
        a = radial * ux - tangential * uy;
        b = radial * uy + tangential * ux;
    }
    for (int k = 0; k < f->nturb; k++) {
        const isk_field_turb *t = &f->turb[k];
        double pu, pv;
        isk__noise3(t->key, x * t->inv_scale, y * t->inv_scale, t->speed * f->t, &pu, &pv);
        /* the curl of a stream function: (dpsi/dy, -dpsi/dx), divergence-free */
        a += t->strength * pv;
        b -= t->strength * pu;
    }
    *ax = a;
    *ay = b;
}

static void accel(const isk_field *f, double x, double y, double vx, double vy, double *ax, double *ay)
{
    accel_with(f, f->radial, f->tangential, x, y, vx, vy, ax, ay);
}

void isk__field_accel(const isk_field *f, double x, double y, double vx, double vy, double *ax, double *ay)
{
    accel(f, x, y, vx, vy, ax, ay);
}

/* The per-particle ranges: each particle's own parts added to the field's
 * (a column that is not there adds nothing). */
static void run_field_own(const isk_field *f, isk_block *b, double h)
{
    const isk_particles *p = b->p;
    const double *rad = p->radial_extra ? p->radial_extra + b->first : NULL;
    const double *tng = p->tangential_extra ? p->tangential_extra + b->first : NULL;
    const double *wx = p->wind_x ? p->wind_x + b->first : NULL, *wy = p->wind_y ? p->wind_y + b->first : NULL;
    for (size_t i = 0; i < b->n; i++) {
        double ax, ay;
        accel_with(f, f->radial + (rad ? rad[i] : 0.0), f->tangential + (tng ? tng[i] : 0.0), b->x[i], b->y[i],
                   b->vx[i], b->vy[i], &ax, &ay);
        if (wx) {
            ax += wx[i];
            ay += wy[i];
        }
        b->vx[i] += ax * h;
        b->vy[i] += ay * h;
    }
}

static void run_field(const isk_stage *st, isk_block *b, double h)
{
    const isk_field *f = st->u.field.f;
    if (f->own) {
        run_field_own(f, b, h);
        return;
    }
    for (size_t i = 0; i < b->n; i++) {
        double ax, ay;
        accel(f, b->x[i], b->y[i], b->vx[i], b->vy[i], &ax, &ay);
        b->vx[i] += ax * h;
        b->vy[i] += ay * h;
    }
}

static void describe_field(const isk_stage *st, FILE *out)
{
    const isk_field *f = st->u.field.f;
    int any = 0;
    if (f->radial != 0)
        fprintf(out, "%sradial %g", any++ ? ", " : "", f->radial);
    if (f->tangential != 0)
        fprintf(out, "%stangential %g (counter-clockwise)", any++ ? ", " : "", f->tangential);
    if (f->own)
        fprintf(out, "%seach particle's own radial, tangential and wind parts (the ranges)", any++ ? ", " : "");
    for (int k = 0; k < f->nturb; k++)
        fprintf(out, "%sturbulence strength %g scale %g speed %g", any++ ? ", " : "", f->turb[k].strength,
                1.0 / f->turb[k].inv_scale, f->turb[k].speed);
    if (!any)
        fprintf(out, "none");
}

/* The emitter-centred terms, and a gradient noise's curl per turbulence. */
static double cost_field(const isk_stage *st) { return 2.0 + 6.0 * (double)st->u.field.f->nturb; }

const isk_stage_kind isk__stage_field = {
    .name = "field", .run = run_field, .describe = describe_field, .rest = NULL /* a clock */, .cost = cost_field};
