/* SPDX-License-Identifier: MIT */
/* iskra/limits.h — the largest numbers iskra accepts, and why: no accepted
 * input may ever give a NaN or an infinity.
 *
 * Each quantity either has a range (scene keys read these constants into
 * their rows of the key table, iskra/keys.h; the C setters and
 * isk_system_step check the same ones) or saturates where the law itself
 * would overflow:
 *
 *   quantity                          decision
 *   --------------------------------  ------------------------------------------
 *   step dt                           range (0, ISK_DT_MAX], substeps 1..ISK_SUBSTEPS_MAX,
 *                                     speed divisor [ISK_SPEED_DIVISOR_MIN, _MAX]
 *   accelerations (gravity, wind,     range |a| <= ISK_STRENGTH_MAX; gravity multipliers
 *   buoyancy), drag b, oscillation    and |omega| too
 *   frequencies
 *   drag at a long step               saturates: b*h/m is capped at 1, so drag can stop a
 *                                     particle within a step but never reverse it (the
 *                                     explicit integrators' (1 - b h/m)^n no longer grows;
 *                                     exact drag and the splitting are exact and need no cap)
 *   mass                              range [ISK_MASS_MIN, ISK_MASS_MAX]
 *   positions of anything placed      range |x| <= ISK_COORD_MAX (emitters, layers, shapes,
 *   (emitters, potentials, segments)  amplitudes, potentials, deflector endpoints, clicks)
 *   launch speeds, velocities         range |v| <= ISK_SPEED_LIMIT
 *   a potential's force               saturates at ISK_FORCE_LIMIT (iskra/forces.h)
 *   a potential's exponent P          range [ISK_P_MIN, ISK_P_MAX]: |F| ~ d^(1-P), from a
 *                                     spring's force growing as d (P = 0) to d^-16 (P = 17).
 *                                     A force that grows faster than d pulls the farthest
 *                                     particles hardest: no step is stable, every particle
 *                                     is flung to the saturation limit within a few frames
 *                                     (P = -15: out to 1e146 in three), and the motion means
 *                                     nothing; past d^-16 the force changes by more than
 *                                     10^96 over six decades of distance
 *   a bounce with restitution > 1     saturates: the speed is capped at ISK_SPEED_LIMIT
 *                                     (iskra/impact.h)
 *   prewarm (simulated before         range 0..ISK_PREWARM_MAX seconds, and at most
 *   frame 0, at create and reset)     ISK_PREWARM_MAX_STEPS substeps of the emitter's own:
 *                                     create and reset run them before returning, so their
 *                                     time must stay bounded (10^5 substeps of a full
 *                                     10^4-particle fire are a few seconds); a longer
 *                                     warm-up is a mistake, not a wish
 *   turbulence scale                  range [ISK_TURBULENCE_SCALE_MIN, ISK_COORD_MAX]: x/scale
 *                                     stays finite; where x/scale or y/scale is beyond
 *                                     2^52 (a double has no fraction left) there is no
 *                                     turbulence; time beyond it freezes the pattern
 *   stream duration                   range 0..ISK_DURATION_MAX seconds
 *   a trail's points (trail = N)      range 0..ISK_TRAIL_MAX: the history costs 16 bytes per
 *                                     point per particle (64 points: 1 KiB, so a pool of
 *                                     10^5 trailed particles holds 100 MiB), and drawing a
 *                                     trail visits every point's segment; 64 frames are over
 *                                     a second of history at 60 frames/s
 *   a sub-emitter's children          each event adds at most the pool's room (the rest are
 *                                     dropped and counted), and the events waiting in a frame
 *                                     are at most the child's capacity: a chain or a cycle of
 *                                     sub-emitters never grows without bound
 *
 * With these, every sum and product the simulation forms stays finite for
 * any run of up to 10^8 frames of the longest step (10^14 simulated
 * seconds): the worst case, 64 saturated potentials on the lightest
 * particle, moves it by at most ~1e195 units.  A state that still goes
 * non-finite (the thesis fidelity modes reproduce the thesis's NaN at a
 * potential's centre) is removed by the block runner and counted
 * (isk_effect_removed_nonfinite, isk_system.removed_nonfinite; `iskra
 * render` reports it): nothing non-finite is drawn or kept in silence.
 *
 * Example: the limits, and a step iskra refuses:
 *
 *     printf("coordinates up to %g, speeds up to %g, dt up to %g s\n",
 *            ISK_COORD_MAX, ISK_SPEED_LIMIT, ISK_DT_MAX);
 *     isk_system sys;
 *     if (isk_system_init(&sys, 1, 16) != ISK_OK) return 1;
 *     isk_status s = isk_system_step(&sys, 1e300);   // beyond ISK_DT_MAX
 *     printf("dt = 1e300: %s\n", isk_status_str(s));  // refused, nothing moved
 *     isk_system_free(&sys);
 *     return s == ISK_OK;
 */
#ifndef ISKRA_LIMITS_H
#define ISKRA_LIMITS_H

#ifdef __cplusplus
extern "C" {
#endif

#define ISK_DT_MAX 1000.0            /* seconds per frame (or per isk_system_step) */
#define ISK_SUBSTEPS_MAX 1000
#define ISK_SPEED_DIVISOR_MIN 1e-3   /* at most a thousand times faster than real time */
#define ISK_SPEED_DIVISOR_MAX 1e6
#define ISK_STRENGTH_MAX 1e12        /* |acceleration|, drag b, |gravity multiplier|, |omega| */
#define ISK_MASS_MIN 1e-12
#define ISK_MASS_MAX 1e12
#define ISK_COORD_MAX 1e150          /* |coordinate| of anything placed in the world */
#define ISK_SPEED_LIMIT 1e150        /* |launch velocity|; no bounce leaves a particle faster */
#define ISK_FORCE_LIMIT 1e150        /* a potential's force saturates here (iskra/forces.h) */
#define ISK_P_MIN 0.0                /* a potential's P: |F| ~ d^(1-P), at most a spring's d */
#define ISK_P_MAX 17.0               /* ... at least d^-16 */
#define ISK_PRESET_SCALE_MAX 1e6     /* a preset's scale (iskra/presets.h): its largest length, speed
                                        or acceleration, 300 cocos2d points x 1e4, stays far inside
                                        every limit above */
/* motion: prewarm and turbulence */
#define ISK_PREWARM_MAX 3600.0       /* seconds of prewarm ... */
#define ISK_PREWARM_MAX_STEPS 100000 /* ... and at most this many of the emitter's substeps */
#define ISK_TURBULENCE_SCALE_MIN 1e-9 /* world units */
#define ISK_DURATION_MAX 1e9         /* seconds a stream's emission cycle may last */
/* burst_every below this many seconds (down to 5e-324) is read as this:
 * either is finer than any clock, and a cycle of ISK_DURATION_MAX or a
 * step of ISK_DT_MAX then still counts a finite number of bursts. */
#define ISK_BURST_EVERY_MIN 1e-290
/* |spin| and spin_range, degrees per second: a thousand turns a second, far
 * past any visible spin.  One step turns by at most 2 * 6284 rad/s *
 * ISK_DT_MAX < 1.3e7 rad, which the spin stage's wrap into [-pi, pi)
 * reduces, so an angle never grows: it keeps the resolution of a small
 * angle however long the particle lives.  Its phase is not exact: the
 * turn is rounded at its own size and wrapped with a rounded 2 pi, a
 * drift of at most 1.4e-9 rad a step at these bounds (6.6e-10 at 1000
 * turns a second and a step of 1000 s: 6.6e-4 rad after 10^6 steps),
 * 2.3e-14 at 1/60 s: one rounding at the size of the turn. */
#define ISK_SPIN_MAX 360000.0
#define ISK_TRAIL_MAX 64             /* points of a particle's trail (sub-emitters and trails) */

#ifdef __cplusplus
}
#endif

#endif
