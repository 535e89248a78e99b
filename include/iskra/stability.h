/* SPDX-License-Identifier: MIT */
/* iskra/stability.h — the stability edges iskra knows analytically, and
 * where a scene sits against them.
 *
 * Under linear drag alone (F = -b v) one step of h multiplies a velocity by
 * the method's amplification R(x) of x = b*h/m.  The step is stable while
 * |R(x)| <= 1; the edge is the smallest x > 0 where that stops:
 *
 *   semi-euler, euler   R = 1 - x                       edge 2
 *   verlet              R = (1 - x/2)^2                 edge 4
 *   rk4                 R = 1 - x + x^2/2 - x^3/6 + x^4/24
 *                       edge 2.785293563405282, the real root of
 *                       x^3 - 4x^2 + 12x - 24 = 0 (where R = 1 again)
 *   yoshida4            three leapfrog steps of w1 h, w0 h, w1 h, each
 *                       R = (1 - z/2)/(1 + z/2), z = w x; w0 < 0 gives a
 *                       pole at x = -2/w0 = 1.1748: unstable in the band
 *                       1.134424004107524 < x < 1.200628953668564 (beyond
 *                       it |R| < 1 again); the edge is the band's start
 *   leapfrog            R = (1 - x/2)/(1 + x/2)          none (|R| < 1 for all x)
 *   exact-drag, strang  R = e^-x (the flight is solved)  none
 *
 * A linear spring, F = -m w^2 r (a potential of code exponent P = 0
 * everywhere, any potential inside its min distance: F = kQ (r_pot - r) /
 * min^P, so w^2 = kQ/(m min^P)), is stable while w*h stays below the
 * method's spring edge: 2 for semi-euler, verlet, leapfrog and strang
 * (each is Stormer-Verlet there), 2 sqrt 2 for rk4 (where |R(i w h)| = 1),
 * 1.5734019474345398 for yoshida4 (where its step's trace reaches 2),
 * and 0 for euler and exact-drag (exact drag freezes the spring over the
 * step): their energy grows at every step.
 *
 * iskra itself caps the drag of every step at b*h/m = ISK_DRAG_SATURATION
 * (iskra/forces.h, iskra/limits.h): past it the explicit methods' drag
 * stops a particle within the step instead of reversing it, so no edge
 * above is ever crossed in iskra; what changes at the cap is accuracy (a
 * drag that stops everything at once), not stability.  The edges say
 * where the textbook method would fail, and how far a scene is from that.
 *
 * Example: where a drag of b = 90 at 1/60 s puts a particle of mass 1:
 *
 *     isk_effect_def d;
 *     isk_effect_def_init(&d);                        // dt 1/60, semi-implicit Euler
 *     int drag = isk_effect_def_add_force(&d, "drag", ISK_FORCE_DRAG);
 *     isk_emitter_def *e = isk_effect_def_add_emitter(&d, "p");
 *     if (drag < 0 || !e || isk_emitter_use_force(e, drag) != ISK_OK) { isk_effect_def_free(&d); return 1; }
 *     d.forces[drag].b = 90;
 *     double x = isk_effect_def_drag_ratio(&d, 0);    // 90 * (1/60) / 1 = 1.5
 *     isk_integrator m = isk_effect_def_emitter_integrator(&d, 0);
 *     printf("b*h/m = %.2f: %s\n", x,
 *            x > isk_integrator_drag_edge(m) ? "past the method's edge"
 *            : x > ISK_DRAG_SATURATION       ? "drag saturated (stops particles within a step)"
 *                                            : "below the cap");
 *     isk_effect_def_free(&d);
 */
#ifndef ISKRA_STABILITY_H
#define ISKRA_STABILITY_H

#include "iskra/effect.h"
#include "iskra/integrate.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The largest b*h/m the drag of a step ever has (iskra/forces.h). */
#define ISK_DRAG_SATURATION 1.0

/* The method's drag edge in b*h/m (see the top); INFINITY where the
 * method has none, NAN for an unknown method. */
double isk_integrator_drag_edge(isk_integrator method);

/* The method's spring edge in w*h (see the top); 0 where every step
 * grows, NAN for an unknown method. */
double isk_integrator_spring_edge(isk_integrator method);

/* The integrator emitter `i` of d steps with (its own, or the scene's),
 * and its substeps per frame; ISK_INTEGRATE_INHERIT / 0 for no such
 * emitter. */
isk_integrator isk_effect_def_emitter_integrator(const isk_effect_def *d, int i);
int isk_effect_def_emitter_substeps(const isk_effect_def *d, int i);

/* b*h/m of emitter `i`: the drag of the forces it references, times its
 * step h = dt / substeps / speed_divisor, over its lightest particle's
 * mass (launch.mass); 0 without drag or for no such emitter. */
double isk_effect_def_drag_ratio(const isk_effect_def *d, int i);

/* w*h of emitter `i`'s stiffest linear spring: of the potentials it
 * references that are enabled and attract (k*charge > 0), those linear
 * somewhere (P = 0 everywhere, or inside a min distance > 0), w^2 =
 * kQ max(1, |x_multiplier|) / (m min^P) (min^P = 1 for P = 0), m its
 * launch.mass; 0 without one or for no such emitter. */
double isk_effect_def_spring_ratio(const isk_effect_def *d, int i);

#ifdef __cplusplus
}
#endif

#endif
