/* SPDX-License-Identifier: MIT */
/* src/sim/kernels.h — per-particle update rules, internal.
 *
 * Every rule the thesis applies to one particle lives here once, as a static
 * inline function on plain doubles.  The store stages (forces.c, integrate.c,
 * bounds.c) call them inside their tight loops over the SoA arrays, and the
 * teaching API (src/teach/teach.c) calls the very same functions on one
 * particle; so a single-particle example and a million-particle system give
 * identical bits.
 *
 * Nothing here branches on scene-level choices except through arguments that
 * are compile-time constants at the call sites (the callers specialise the
 * loop and switch outside it); the remaining ?: are data selects the
 * vectorizer turns into blends.
 */
#ifndef ISKRA_SIM_KERNELS_H
#define ISKRA_SIM_KERNELS_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "iskra/forces.h"
#include "iskra/integrate.h"

/* These rules must give the thesis's bits (the trajectories and the
 * reference images are compared exactly): no reassociation, no reciprocal
 * for a division, NaN and infinity kept.  gcc and clang announce the flags
 * that give those up by macros, whatever build turns them on (the
 * Makefile's flags, -Ofast, a project that compiles these sources with its
 * own); the Makefile refuses the few that leave no trace (VALUE_CHANGING_FLAGS). */
#if defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)
#error "iskra needs IEEE arithmetic: build it without fast math or finite-math-only (its results are compared bit for bit)"
#endif

/* MaterijalnaTocka.pomakni(dt, F): semi-implicit (symplectic) Euler exactly as
 * the thesis code: c = dt/m first, v += c*F per component (product first,
 * dodajCputaV), then r += dt*v with the NEW velocity. */
static inline void isk_k_semi_euler(double *x, double *y, double *vx, double *vy, double m,
                                    double fx, double fy, double dt)
{
    double c = dt / m;
    double nvx = *vx + c * fx;
    double nvy = *vy + c * fy;
    *vx = nvx;
    *vy = nvy;
    *x = *x + dt * nvx;
    *y = *y + dt * nvy;
}

/* Explicit (forward) Euler as the thesis TEXT derives it:
 * r(t+dt) = r + dt*v(t), v(t+dt) = v + (dt/m)*F. */
static inline void isk_k_euler(double *x, double *y, double *vx, double *vy, double m, double fx,
                               double fy, double dt)
{
    double c = dt / m;
    double ovx = *vx, ovy = *vy;
    *x = *x + dt * ovx;
    *y = *y + dt * ovy;
    *vx = ovx + c * fx;
    *vy = ovy + c * fy;
}

/* SilaTeza(g).F: (0, m*(-g)), added to the y accumulator. */
static inline double isk_k_gravity_fy(double m, double g) { return m * (-g); }

/* Otpor(b).F: (-b*vx, -b*vy). */
static inline double isk_k_drag(double v, double b) { return (-b) * v; }

/* A word whose top bit is set exactly when !islessequal(|gx|,
 * ISK_FORCE_LIMIT) or the same for gy (a NaN fails too); computed on the
 * bit patterns: without its sign a double's pattern orders as its value
 * and a NaN's lies above the infinity's, so (limit - |g|) has its top bit
 * set exactly when the test fails.  Integer operations only: a
 * compare-and-select here made gcc sink the force's multiplication behind
 * a branch, which it cannot if-convert (a multiply may trap), and the
 * sound-mode loops did not vectorize. */
static inline uint64_t isk_k_force_over(double gx, double gy)
{
    const double limit = ISK_FORCE_LIMIT;
    uint64_t ux, uy, lim;
    memcpy(&ux, &gx, sizeof ux);
    memcpy(&uy, &gy, sizeof uy);
    memcpy(&lim, &limit, sizeof lim);
    const uint64_t mag = 0x7FFFFFFFFFFFFFFFull;
    return (lim - (ux & mag)) | (lim - (uy & mag));
}

/* All ones when both components are within ISK_FORCE_LIMIT (the test
 * above passes), else 0. */
static inline uint64_t isk_k_force_keep(double gx, double gy) { return (isk_k_force_over(gx, gy) >> 63) - 1u; }

/* v where keep is all ones, +0.0 (all bits zero) where it is 0. */
static inline double isk_k_keep(double v, uint64_t keep)
{
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    u &= keep;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* pw_kind of isk_k_coulomb_law for an exponent known to be 2 or 1 but
 * chosen at run time (the fused motion pass: one loop for any mix of
 * potentials): d'^P = d' * e with e = d' clamped to [lo, hi].  (lo, hi) =
 * (-inf, +inf) leaves e = d', so d'*d' (P = 2); (1, 1) makes e = 1, and
 * d'*1 is d' exactly (P = 1); a NaN d' gives NaN either way.  Two quiet
 * min/max, no select: the same bits as kinds 2 and 1. */
#define ISK_K_PW_12 3

/* CoulombovPotencijal.F for one particle, the thesis's operations in order:
 *   n = r_pot - r;  n.x *= xm;  d = |r_pot - r| (Euclidean, unaffected by xm)
 *   d' = (min > d) ? min : d            (min <= 0 never triggers: "off";
 *                                        isgreater is the quiet '>', same result)
 *   mult = s / d'^P   with s = enabled*(Q*k) precomputed by the caller
 *   F = n * mult
 * pw_kind is a compile-time constant at every call site: 2 -> d'*d' (exactly
 * V8's d**2), 1 -> d', 0 -> pow(d', P), ISK_K_PW_12 -> by lo and hi (above).
 * The law's force, no centre rule: (gx, gy) may be NaN or infinite. */
static inline void isk_k_coulomb_law(double cx, double cy, double x, double y, double s, double xm, double minv,
                                     double P, int pw_kind, double lo, double hi, double *gx, double *gy)
{
    double dx = cx - x, dy = cy - y;
    double d = sqrt(dx * dx + dy * dy);
    double nx = dx * xm;
    double dd = isgreater(minv, d) ? minv : d;
    double pw;
    if (pw_kind == ISK_K_PW_12) {
        double e = isless(dd, hi) ? dd : hi;
        e = isgreater(e, lo) ? e : lo;
        pw = dd * e;
    } else {
        pw = pw_kind == 2 ? dd * dd : (pw_kind == 1 ? dd : pow(dd, P));
    }
    double mult = s / pw;
    *gx = nx * mult;
    *gy = dy * mult;
}

/* The law with the centre rule: returns 1 when (fx, fy) is the law's
 * force.  With sound != 0 a result that is not finite or has a component
 * beyond ISK_FORCE_LIMIT (the particle exactly on a potential without min
 * distance: 0*inf = NaN in the thesis; d'^P underflowing; a huge force
 * close to the centre) is replaced by (0, 0) and the function returns 0:
 * the caller then asks isk_k_coulomb_saturated for the force (a rare
 * fix-up, in a second pass). */
static inline int isk_k_coulomb(double cx, double cy, double x, double y, double s, double xm,
                                double minv, double P, int pw_kind, int sound, double *fx, double *fy)
{
    double gx, gy;
    isk_k_coulomb_law(cx, cy, x, y, s, xm, minv, P, pw_kind, 0.0, 0.0, &gx, &gy);
    if (!sound) {
        *fx = gx;
        *fy = gy;
        return 1;
    }
    const uint64_t keep = isk_k_force_keep(gx, gy);
    *fx = isk_k_keep(gx, keep);
    *fy = isk_k_keep(gy, keep);
    return (int)(keep & 1u);
}

/* The sound mode's force where isk_k_coulomb returned 0: the law's
 * direction n = (xm*(cx - x), cy - y) with the larger component exactly
 * +-ISK_FORCE_LIMIT (towards the potential when s > 0).  Dividing by the
 * larger component instead of |n| keeps the direction exact even when
 * |n|^2 would underflow.  No direction exists exactly at the centre (n = 0)
 * or for a non-finite offset: the force is then (0, 0). */
static inline void isk_k_coulomb_saturated(double cx, double cy, double x, double y, double s, double xm,
                                           double *fx, double *fy)
{
    double nx = (cx - x) * xm, ny = cy - y;
    double c = fmax(fabs(nx), fabs(ny));
    if (!(c > 0.0 && c < INFINITY) || s == 0.0) {
        *fx = 0.0;
        *fy = 0.0;
        return;
    }
    double lim = copysign(ISK_FORCE_LIMIT, s);
    *fx = (nx / c) * lim;
    *fy = (ny / c) * lim;
}

/* Components of a speed (or an amplitude) that only decays are flushed to
 * zero below ISK_FLUSH_TINY (see iskra/integrate.h): quiet compare, so the
 * loops stay vectorized. */
static inline double isk_k_flush(double v) { return isless(fabs(v), ISK_FLUSH_TINY) ? 0.0 : v; }

/* Non-finite detection that vectorizes: the exponent field of an infinity
 * or a NaN is all ones, so adding one to it carries into the sign bit.
 * Or-ing these words over a loop and testing bit 63 says whether any value
 * was not finite (integer operations only, no compare, no branch). */
static inline uint64_t isk_k_nonfinite_bits(double v)
{
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    return (u & 0x7FF0000000000000ull) + 0x0010000000000000ull;
}

/* 1 when some value of the n in a or b is not finite. */
static inline int isk_k_any_nonfinite2(size_t n, const double *restrict a, const double *restrict b)
{
    uint64_t acc = 0;
    for (size_t i = 0; i < n; i++)
        acc |= isk_k_nonfinite_bits(a[i]) | isk_k_nonfinite_bits(b[i]);
    return (int)(acc >> 63);
}

/* The distance the max-distance switch tests (same operations as above). */
static inline double isk_k_coulomb_dist(double cx, double cy, double x, double y)
{
    double dx = cx - x, dy = cy - y;
    return sqrt(dx * dx + dy * dy);
}

/* Thesis zarobi pieces: an unconditional sign flip when strictly beyond a
 * wall, and the floor's position clamp.  isless/isgreater are the quiet
 * forms of < and > (same result, NaN compares false either way); being
 * non-trapping they let gcc turn the selects into vector blends under the
 * default -ftrapping-math, where a plain < keeps a branch. */
static inline double isk_k_flip_below(double pos, double wall, double v) { return isless(pos, wall) ? -v : v; }
static inline double isk_k_flip_above(double pos, double wall, double v) { return isgreater(pos, wall) ? -v : v; }
static inline double isk_k_clamp_below(double pos, double wall) { return isless(pos, wall) ? wall : pos; }

/* Sound reflection about a wall, split in two so loops vectorize: the
 * candidates (pure arithmetic, computed for every particle), then the
 * selects.  Low wall (the particle is below `wall`): the overshoot is
 * mirrored and scaled by the restitution c, exactly what a particle moving at
 * the reflected speed c*|v| would have travelled after the hit; the velocity
 * is reflected (and scaled) only if it points outward, so a particle already
 * moving back inside is never turned around (no sticking). */
static inline double isk_k_mirror_lo(double pos, double wall, double c) { return wall + c * (wall - pos); }
static inline double isk_k_mirror_hi(double pos, double wall, double c) { return wall - c * (pos - wall); }
static inline double isk_k_rebound(double v, double c) { return -c * v; }

static inline void isk_k_select_lo(double *pos, double *v, double wall, double mirrored, double rebound)
{
    double p = *pos, u = *v;
    double nu = isless(u, 0.0) ? rebound : u;
    double rv = isless(p, wall) ? nu : u;
    double rp = isless(p, wall) ? mirrored : p;
    *v = rv; /* compute everything, then store: gcc if-converts only then */
    *pos = rp;
}

static inline void isk_k_select_hi(double *pos, double *v, double wall, double mirrored, double rebound)
{
    double p = *pos, u = *v;
    double nu = isgreater(u, 0.0) ? rebound : u;
    double rv = isgreater(p, wall) ? nu : u;
    double rp = isgreater(p, wall) ? mirrored : p;
    *v = rv;
    *pos = rp;
}

/* Both walls of an axis at once (lo < hi, so at most one applies to the
 * incoming position; a mirrored point beyond the other wall is left for the
 * caller's next pass). */
static inline void isk_k_select_box(double *pos, double *v, double lo, double hi, double mirrored_lo,
                                    double mirrored_hi, double rebound)
{
    double p = *pos, u = *v;
    double nul = isless(u, 0.0) ? rebound : u;
    double nuh = isgreater(u, 0.0) ? rebound : u;
    double rp = isgreater(p, hi) ? mirrored_hi : p;
    double ru = isgreater(p, hi) ? nuh : u;
    rp = isless(p, lo) ? mirrored_lo : rp;
    ru = isless(p, lo) ? nul : ru;
    *v = ru;
    *pos = rp;
}

/* Both halves at once, for scalar code. */
static inline void isk_k_reflect_lo(double *pos, double *v, double wall, double c)
{
    isk_k_select_lo(pos, v, wall, isk_k_mirror_lo(*pos, wall, c), isk_k_rebound(*v, c));
}

static inline void isk_k_reflect_hi(double *pos, double *v, double wall, double c)
{
    isk_k_select_hi(pos, v, wall, isk_k_mirror_hi(*pos, wall, c), isk_k_rebound(*v, c));
}

#endif
