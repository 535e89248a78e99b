/* SPDX-License-Identifier: MIT */
/* iskra/shape.h — where particles are born and how fast they start.
 *
 * Spawn shapes (the fire thesis §5.5's point / circle / segment and the
 * particle-engine thesis's Fig. 2.1 shapes) and velocity generators, as
 * tagged plain structs with one sample function each.  Every random number
 * comes from the isk_rng passed in, as isk_rng_uniform() draws in the order
 * listed below, so a seed reproduces the same particles.  Check a struct once
 * with isk_shape_check / isk_velgen_check; the _sample functions then trust
 * it, and the _sample_n functions check, switch on the kind once and run a
 * tight loop.
 *
 * Example: 100 births in a tilted ellipse, launched upwards:
 *
 *     isk_rng rng;
 *     isk_rng_seed(&rng, 7);
 *     double x[100], y[100], vx[100], vy[100];
 *     size_t n = 100;
 *     isk_shape sh = isk_shape_ellipse(0, 0, 2, 1, ISK_ELLIPSE_UNIFORM);
 *     sh.angle = 0.3;                                   // radians, about (cx, cy)
 *     isk_velgen vg = isk_velgen_cone(1.5707963, 0.5, 2.0, 3.0);  // up +-0.25 rad
 *     if (isk_shape_sample_n(&sh, &rng, n, x, y) != ISK_OK) return 1;
 *     if (isk_velgen_sample_n(&vg, &rng, n, vx, vy) != ISK_OK) return 1;
 *     printf("first at (%g, %g), moving (%g, %g)\n", x[0], y[0], vx[0], vy[0]);
 *
 * Shapes (offsets from the centre (cx, cy) before rotation; u1, u2 are the
 * first and second uniform draws in [0, 1)):
 *   POINT    (cx, cy)                                       0 draws
 *   DISC     radius a, area-uniform: rho = a sqrt(u1),      2 draws
 *            phi = 2 pi u2
 *   CIRCLE   outline of radius a: phi = 2 pi u1             1 draw
 *   RING     a <= r <= b, area-uniform:                     2 draws
 *            rho = sqrt(a^2 + u1 (b^2 - a^2)), phi = 2 pi u2
 *   SEGMENT  from (cx, cy) along the vector (a, b): u1 (a, b)   1 draw
 *   RECT     half-width a, half-height b:                   2 draws
 *            (a (2 u1 - 1), b (2 u2 - 1))
 *   ELLIPSE  semi-axes a (x) and b (y).                     2 draws
 *            ISK_ELLIPSE_UNIFORM (default): the unit disc sample scaled,
 *            area-uniform.  ISK_ELLIPSE_THESIS: the particle-engine
 *            thesis's method x = a (2 u1 - 1), y = b (2 u2 - 1) sqrt(1 - (x/a)^2):
 *            inside, but crowded towards the ends of the major axis (the
 *            fraction with |x| > 0.9a is 0.100 instead of 0.0374).
 *   GAUSSIAN standard deviations a (x) and b (y), a normal   2 draws
 *            distribution by Box-Muller (LÖVE's `normal` area):
 *            rho = sqrt(-2 ln(1 - u1)), phi = 2 pi u2,
 *            (a rho cos phi, b rho sin phi); unbounded, 99.7% within 3a, 3b
 *   RECT_BORDER the outline of the RECT, uniform along it:   1 draw
 *            s = u1 * 4 (a + b) walked counter-clockwise from (a, -b):
 *            right side up, top leftwards, left side down, bottom rightwards
 *   ELLIPSE_BORDER the outline of the ELLIPSE at a uniform    1 draw
 *            parameter: phi = 2 pi u1, (a cos phi, b sin phi) (LÖVE's
 *            `borderellipse`: denser per unit length towards the ends of
 *            the major axis; a circle when a = b)
 * Then the offset is rotated by `angle` (skipped when angle is 0, so
 * unrotated samples are exact) and added to (cx, cy).  Polar samples use
 * libm sqrt (exact), cos and sin.
 *
 * Velocity generators:
 *   CONSTANT   (vx, vy)                                     0 draws
 *   DISC       a random vector in a disc of radius max,     2 draws
 *              area-uniform (as the DISC shape)
 *   DIRECTION  speed min + u1 (max - min) along `angle`     1 draw
 *   CONE       direction angle + spread (u1 - 1/2), then    2 draws
 *              speed min + u2 (max - min)
 *
 * Validation (ISK_ERR_NAN for any non-finite field used by the kind,
 * ISK_ERR_RANGE for negative radii/sizes/speeds, r_in > r_out, min > max,
 * spread outside [0, 2 pi], an unknown kind or mode; ISK_ERR_NULL).
 */
#ifndef ISKRA_SHAPE_H
#define ISKRA_SHAPE_H

#include <stddef.h>

#include "iskra/rng.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_shape_kind {
    ISK_SHAPE_POINT = 0,
    ISK_SHAPE_DISC,
    ISK_SHAPE_CIRCLE,
    ISK_SHAPE_RING,
    ISK_SHAPE_SEGMENT,
    ISK_SHAPE_RECT,
    ISK_SHAPE_ELLIPSE,
    ISK_SHAPE_GAUSSIAN,
    ISK_SHAPE_RECT_BORDER,
    ISK_SHAPE_ELLIPSE_BORDER,
    ISK_SHAPE_COUNT
} isk_shape_kind;

typedef enum isk_ellipse_mode {
    ISK_ELLIPSE_UNIFORM = 0, /* area-uniform (default) */
    ISK_ELLIPSE_THESIS = 1,  /* particle-engine thesis, eq. 5.1 (faithful) */
    ISK_ELLIPSE_MODE_COUNT
} isk_ellipse_mode;

/* The kinds whose b is used (RING's r_out, SEGMENT's dy, RECT, ELLIPSE,
 * GAUSSIAN and the borders' second size). */
int isk_shape_uses_b(isk_shape_kind kind);

typedef struct isk_shape {
    isk_shape_kind kind;
    double cx, cy;  /* centre; the SEGMENT's start */
    double a, b;    /* radius (a); r_in, r_out; vector; half sizes; semi-axes */
    double angle;   /* rotation of the offset about (cx, cy), radians */
    isk_ellipse_mode ellipse_mode;
} isk_shape;

typedef enum isk_velgen_kind {
    ISK_VELGEN_CONSTANT = 0,
    ISK_VELGEN_DISC,
    ISK_VELGEN_DIRECTION,
    ISK_VELGEN_CONE,
    ISK_VELGEN_COUNT
} isk_velgen_kind;

/* Names as scene files spell them (`shape`, `launch`), indexed by kind. */
extern const char *const isk_shape_names[ISK_SHAPE_COUNT];   /* point disc circle ring segment rect ellipse
                                                                gaussian rect_border ellipse_border */
extern const char *const isk_velgen_names[ISK_VELGEN_COUNT]; /* constant disc direction cone */

typedef struct isk_velgen {
    isk_velgen_kind kind;
    double vx, vy;     /* CONSTANT */
    double angle;      /* DIRECTION, CONE: radians (0 = +x) */
    double spread;     /* CONE: full opening angle, 0..2 pi */
    double min, max;   /* speed range; DISC: max is the radius */
} isk_velgen;

isk_shape isk_shape_point(double x, double y);
isk_shape isk_shape_disc(double cx, double cy, double r);
isk_shape isk_shape_circle(double cx, double cy, double r);
isk_shape isk_shape_ring(double cx, double cy, double r_in, double r_out);
isk_shape isk_shape_segment(double x0, double y0, double dx, double dy);
isk_shape isk_shape_rect(double cx, double cy, double half_w, double half_h);
isk_shape isk_shape_ellipse(double cx, double cy, double a, double b, isk_ellipse_mode mode);
isk_shape isk_shape_gaussian(double cx, double cy, double sigma_x, double sigma_y);
isk_shape isk_shape_rect_border(double cx, double cy, double half_w, double half_h);
isk_shape isk_shape_ellipse_border(double cx, double cy, double a, double b);

isk_velgen isk_velgen_constant(double vx, double vy);
isk_velgen isk_velgen_disc(double radius);
isk_velgen isk_velgen_direction(double angle, double min_speed, double max_speed);
isk_velgen isk_velgen_cone(double angle, double spread, double min_speed, double max_speed);

isk_status isk_shape_check(const isk_shape *s);
isk_status isk_velgen_check(const isk_velgen *v);

/* One sample (no validation: check the struct once first). */
void isk_shape_sample(const isk_shape *s, isk_rng *rng, double *x, double *y);
void isk_velgen_sample(const isk_velgen *v, isk_rng *rng, double *vx, double *vy);

/* n samples into arrays (x[i], y[i]), in index order; validates first and
 * writes nothing on error (NULL arrays with n > 0, NULL rng: ISK_ERR_NULL). */
isk_status isk_shape_sample_n(const isk_shape *s, isk_rng *rng, size_t n, double *x, double *y);
isk_status isk_velgen_sample_n(const isk_velgen *v, isk_rng *rng, size_t n, double *vx, double *vy);

#ifdef __cplusplus
}
#endif

#endif
