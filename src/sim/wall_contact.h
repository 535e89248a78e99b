/* SPDX-License-Identifier: MIT */
/* src/sim/wall_contact.h — the pieces of the sound walls (src/sim/bounds.c)
 * that the contact pass of walls and deflectors together (iskra/contacts.h,
 * src/sim/deflector.c) shares, so one rule lives in one place (internal).
 *
 *     int wall;
 *     double tau = isk__wall_time(P, U, a, k, s, lo, hi, &wall);  // INFINITY: stays inside
 *     if (tau <= s) ... bounce on lo (wall = -1) or hi (wall = +1) at tau
 *
 * A missing wall is at -INFINITY / +INFINITY. */
#ifndef ISKRA_SIM_WALL_CONTACT_H
#define ISKRA_SIM_WALL_CONTACT_H

/* When the flight of one axis, p(t) = P + U D1(t) + a D2(t) with drag rate
 * k (src/sim/flight.h), started inside [lo, hi], first meets a wall within
 * [0, s]: at its end or at its turning point it must be outside (a path
 * that leaves and comes back within the time is seen by its turning point;
 * iskra/impact.h).  Returns the time, and in *wall which wall (-1: lo,
 * +1: hi), or INFINITY when the flight stays inside. */
double isk__wall_time(double P, double U, double a, double k, double s, double lo, double hi, int *wall);

/* A particle outside [lo, hi] with no crossing to find (it started the step
 * outside): mirrored in about the wall, reflection by reflection, with the
 * closed-form fold for very fast ones, and a position or velocity that is
 * not finite clamped onto the wall (iskra/bounds.h). */
void isk__wall_settle(double *pos, double *vel, double lo, double hi, double c);

#endif
