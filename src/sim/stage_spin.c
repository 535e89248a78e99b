/* SPDX-License-Identifier: MIT */
/* The looks' spin stages: each particle's angle turns by its own
 * angular speed, wrapped into [-pi, pi) so that a spin kept up for hours
 * keeps the precision of a small angle (see stage.h).  With spin_end the
 * speed changes linearly over the life, w(t) = spin_i + change * t at
 * normalised age t = age/life (clamped to [0, 1]; 0 for the immortal), and
 * a step turns by the mean of w at its two ends times h: exact for a speed
 * linear in time, so the angle does not depend on the step size. */
#include <math.h>

#include "sim/stage.h"

#define PI 3.14159265358979323846
#define TWO_PI 6.28318530717958647692

/* a wrapped into [-pi, pi): one subtraction of whole turns, then at most
 * one correction for the rounding of the quotient. */
static inline double wrap_angle(double a)
{
    if (a >= -PI && a < PI)
        return a;
    a -= TWO_PI * floor((a + PI) / TWO_PI);
    if (a >= PI)
        a -= TWO_PI;
    else if (a < -PI)
        a += TWO_PI;
    return a;
}

static void run_spin(const isk_stage *st, isk_block *b, double h)
{
    (void)st;
    double *restrict angle = b->p->angle + b->first;
    const double *restrict spin = b->p->spin + b->first;
    for (size_t i = 0; i < b->n; i++)
        angle[i] = wrap_angle(angle[i] + spin[i] * h);
}

/* Normalised age, clamped to [0, 1]; 0 for an immortal particle (and a
 * NaN). */
static inline double life_t(double age, double life)
{
    const double t = age / life;
    return t >= 1.0 ? 1.0 : t > 0.0 ? t : 0.0;
}

static void run_spin_life(const isk_stage *st, isk_block *b, double h)
{
    const double change = st->u.spin.change;
    double *restrict angle = b->p->angle + b->first;
    const double *restrict spin = b->p->spin + b->first;
    const double *restrict age = b->p->age + b->first, *restrict life = b->p->life + b->first;
    for (size_t i = 0; i < b->n; i++) {
        const double t0 = life_t(age[i], life[i]), t1 = life_t(age[i] + h, life[i]);
        angle[i] = wrap_angle(angle[i] + (spin[i] + change * (0.5 * (t0 + t1))) * h);
    }
}

static void describe_spin_life(const isk_stage *st, FILE *out)
{
    fprintf(out, "angle += (%g + U*%g + %g*t) deg/s * dt at normalised age t, wrapped into [-180, 180) deg",
            st->u.spin.spin * (180.0 / PI), st->u.spin.spin_range * (180.0 / PI), st->u.spin.change * (180.0 / PI));
}

static void describe_spin(const isk_stage *st, FILE *out)
{
    fprintf(out, "angle += (%g + U*%g) deg/s * dt, wrapped into [-180, 180) deg", st->u.spin.spin * (180.0 / PI),
            st->u.spin.spin_range * (180.0 / PI));
}

const isk_stage_kind isk__stage_spin = {
    .name = "spin", .run = run_spin, .describe = describe_spin, .rest = isk__rest_beside};

const isk_stage_kind isk__stage_spin_life = {
    .name = "spin", .run = run_spin_life, .describe = describe_spin_life, .rest = isk__rest_beside};
