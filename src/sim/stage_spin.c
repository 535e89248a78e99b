/* SPDX-License-Identifier: MIT */
/* The looks' spin stage: each particle's angle turns by its own
 * angular speed, wrapped into [-pi, pi) so that a spin kept up for hours
 * keeps the precision of a small angle (see stage.h). */
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

static void describe_spin(const isk_stage *st, FILE *out)
{
    fprintf(out, "angle += (%g + U*%g) deg/s * dt, wrapped into [-180, 180) deg", st->u.spin.spin * (180.0 / PI),
            st->u.spin.spin_range * (180.0 / PI));
}

const isk_stage_kind isk__stage_spin = {
    .name = "spin", .run = run_spin, .describe = describe_spin, .rest = isk__rest_beside};
