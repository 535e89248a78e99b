/* SPDX-License-Identifier: MIT */
/* Segment deflectors, one at a time: the constructor, the check of a
 * definition, and the velocity map M that a bounce applies
 * (iskra/deflector.h documents them).  The exact geometry of a segment is
 * src/sim/segment_exact.h; the contact pass that moves particles against
 * the segments (and the walls) is src/sim/contact_pass.c, which calls
 * isk__seg_reflect and isk__speed_cap below (src/sim/contact_pass.h). */
#include "iskra/deflector.h"

#include <math.h>

#include "iskra/limits.h" /* ISK_COORD_MAX, ISK_SPEED_LIMIT */
#include "sim/contact_pass.h"
#include "sim/segment_exact.h"

const char *const isk_deflect_reaction_names[ISK_DEFLECT_REACTION_COUNT] = {"bounce", "kill", "stick"};
const char *const isk_restitution_mode_names[ISK_RESTITUTION_MODE_COUNT] = {"uniform", "normal"};

isk_deflector isk_deflector_segment(double x0, double y0, double x1, double y1)
{
    isk_deflector d = {x0, y0, x1, y1, 1.0, 1.0, ISK_DEFLECT_BOUNCE, ISK_RESTITUTION_UNIFORM};
    return d;
}

isk_status isk_deflector_check(const isk_deflector *d)
{
    if (!d)
        return ISK_ERR_NULL;
    if (!isfinite(d->x0) || !isfinite(d->y0) || !isfinite(d->x1) || !isfinite(d->y1) || !isfinite(d->restitution) ||
        !isfinite(d->probability))
        return ISK_ERR_NAN;
    if (d->x0 == d->x1 && d->y0 == d->y1)
        return ISK_ERR_RANGE;
    if (!(fabs(d->x0) <= ISK_COORD_MAX && fabs(d->y0) <= ISK_COORD_MAX &&
          fabs(d->x1) <= ISK_COORD_MAX && fabs(d->y1) <= ISK_COORD_MAX))
        return ISK_ERR_RANGE;
    if (d->restitution < 0.0 || d->restitution > ISK_DEFLECT_RESTITUTION_MAX || d->probability < 0.0 ||
        d->probability > 1.0)
        return ISK_ERR_RANGE;
    if (d->reaction != ISK_DEFLECT_BOUNCE && d->reaction != ISK_DEFLECT_KILL && d->reaction != ISK_DEFLECT_STICK)
        return ISK_ERR_RANGE;
    if (d->mode != ISK_RESTITUTION_UNIFORM && d->mode != ISK_RESTITUTION_NORMAL)
        return ISK_ERR_RANGE;
    return ISK_OK;
}

/* The velocity map M (iskra/deflector.h): uniform restitution scales the
 * mirrored velocity, normal restitution only its normal part. */
void isk__seg_reflect(const isk_deflector *d, const isk__seg *s, double *vx, double *vy)
{
    double nx = s->nx, ny = s->ny;
    double vn = *vx * nx + *vy * ny;
    double c = d->restitution;
    if (d->mode == ISK_RESTITUTION_UNIFORM) {
        *vx = c * (*vx - 2.0 * vn * nx);
        *vy = c * (*vy - 2.0 * vn * ny);
    } else {
        double tx = *vx - vn * nx, ty = *vy - vn * ny; /* v_t */
        *vx = tx - c * (vn * nx);
        *vy = ty - c * (vn * ny);
    }
}

/* A bumper (c > 1) never leaves a speed above ISK_SPEED_LIMIT. */
void isk__speed_cap(double *vx, double *vy)
{
    double v = hypot(*vx, *vy);
    if (v > ISK_SPEED_LIMIT) {
        double f = ISK_SPEED_LIMIT / v;
        *vx *= f;
        *vy *= f;
    }
}

void isk_deflector_reflect(const isk_deflector *d, double *vx, double *vy)
{
    isk__seg s = isk__seg_canon(d);
    isk__seg_reflect(d, &s, vx, vy);
}
