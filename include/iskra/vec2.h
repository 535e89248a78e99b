/* SPDX-License-Identifier: MIT */
/* iskra/vec2.h — a 2D vector of doubles, the thesis's Vektor2D.
 *
 * Header-only value type used by the teaching API (iskra/teach.h), the
 * potentials (iskra/forces.h) and anyone who wants to write the thesis's
 * single-particle examples line by line.  Every operation performs exactly
 * the floating-point operations of the thesis's JavaScript, in the same
 * order, so results are bit-identical under -ffp-contract=off:
 *
 * Example:
 *
 *     isk_vec2 r = isk_vec2_make(-4, -4), v = isk_vec2_make(1, -2);
 *     isk_vec2_add_scaled(&r, 0.25, v);          // dodajCputaV: r += 0.25*v
 *     isk_vec2 g = isk_vec2_make(0, -0.25), drag = isk_vec2_scale(v, -0.1);
 *     isk_vec2 F = isk_vec2_add(g, drag);        // zbroji
 *     double d = isk_vec2_dist(r, isk_vec2_make(0, 0));   // udaljenost
 *     isk_vec2 w = isk_vec2_rotate_thesis(isk_vec2_make(4, 4), 45);
 *     printf("r (%g, %g)  F (%g, %g)  d %g  w (%g, %g)\n", r.x, r.y, F.x, F.y, d, w.x, w.y);
 *
 * Thesis name  ->  here
 *   zbroji(v2)            isk_vec2_add(a, b)        new (a.x+b.x, a.y+b.y)
 *   oduzmi(v2)            isk_vec2_sub(a, b)        new (a.x-b.x, a.y-b.y)
 *   pomnoziSkalarom(s)    isk_vec2_scale(a, s)      new (a.x*s, a.y*s)
 *   dodajCputaV(c, v)     isk_vec2_add_scaled(&a, c, v)   a.x += c*v.x (product first)
 *   udaljenost(v2)        isk_vec2_dist(a, b)       sqrt((a.x-b.x)^2 + (a.y-b.y)^2)
 *   rotirajOkoPocetka(d)  isk_vec2_rotate_thesis(a, d)   the buggy formula, see below
 */
#ifndef ISKRA_VEC2_H
#define ISKRA_VEC2_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_vec2 {
    double x, y;
} isk_vec2;

static inline isk_vec2 isk_vec2_make(double x, double y)
{
    isk_vec2 v = {x, y};
    return v;
}

static inline isk_vec2 isk_vec2_add(isk_vec2 a, isk_vec2 b) { return isk_vec2_make(a.x + b.x, a.y + b.y); }
static inline isk_vec2 isk_vec2_sub(isk_vec2 a, isk_vec2 b) { return isk_vec2_make(a.x - b.x, a.y - b.y); }
static inline isk_vec2 isk_vec2_scale(isk_vec2 a, double s) { return isk_vec2_make(a.x * s, a.y * s); }

/* a += c*v, the product c*v formed first (dodajCputaV). */
static inline void isk_vec2_add_scaled(isk_vec2 *a, double c, isk_vec2 v)
{
    a->x = a->x + c * v.x;
    a->y = a->y + c * v.y;
}

/* Euclidean distance, squares as plain products (V8's x**2 is exactly x*x). */
static inline double isk_vec2_dist(isk_vec2 a, isk_vec2 b)
{
    double dx = a.x - b.x, dy = a.y - b.y;
    return sqrt(dx * dx + dy * dy);
}

static inline double isk_vec2_len(isk_vec2 a) { return sqrt(a.x * a.x + a.y * a.y); }

/* The thesis's rotirajOkoPocetka(deg): builds the CCW rotation matrix but
 * multiplies row 0 by x twice and row 1 by y twice:
 *     x' = (0 + x*cos) + x*(-sin),   y' = (0 + y*sin) + y*cos
 * with rad = deg*(pi/180).  Equal to a true rotation only when x == y (the
 * thesis only ever rotates (4,4)).  Kept for bit-exact reproduction; use
 * isk_vec2_rotate for a real rotation. */
static inline isk_vec2 isk_vec2_rotate_thesis(isk_vec2 a, double deg)
{
    double rad = deg * (3.141592653589793 / 180.0);
    double c = cos(rad), s = sin(rad);
    double zx = 0.0, zy = 0.0;
    zx = zx + a.x * c;
    zx = zx + a.x * (-s);
    zy = zy + a.y * s;
    zy = zy + a.y * c;
    return isk_vec2_make(zx, zy);
}

/* A correct counter-clockwise rotation by deg degrees. */
static inline isk_vec2 isk_vec2_rotate(isk_vec2 a, double deg)
{
    double rad = deg * (3.141592653589793 / 180.0);
    double c = cos(rad), s = sin(rad);
    return isk_vec2_make(a.x * c - a.y * s, a.x * s + a.y * c);
}

#ifdef __cplusplus
}
#endif

#endif
