/* SPDX-License-Identifier: MIT */
/* src/view/view_transform.h — world to screen through a view: the one
 * place its arithmetic is written (internal).
 *
 * iskra/view.h gives the theses' formulas:
 *   window  X = sx*x + px             Y = sy*y + py
 *   camera  X = w/2 + a*(x + tx)      Y = h/2 - a*(y + ty)
 * Each axis of either kind is one form, an isk__view_axis:
 *   window  screen = s*u + p
 *   camera  screen = c - k*(u + t)
 * with Y's c = h/2, k = a, t = ty, s = sy, p = py, and X's c = w/2,
 * k = -a, t = tx, s = sx, p = px.  For X the camera's w/2 - (-a)*(x + tx)
 * is w/2 + a*(x + tx) bit for bit: negation is exact, rounding to nearest
 * is symmetric, and IEEE defines u - v as u + (-v) (tests/test_view.c
 * checks both forms against each other).
 *
 *     const isk__view_axis ax = isk__view_axis_x(v), ay = isk__view_axis_y(v);
 *     const int camera = isk__view_is_camera(v);
 *     for (size_t i = 0; i < n; i++) {
 *         const double X = isk__view_axis_map(ax, camera, x[i]);
 *         const double Y = isk__view_axis_map(ay, camera, y[i]);
 *         ...
 *     }
 *
 * isk_view_to_screen (view.c) and every batched kernel (world_batch.c, the
 * selects of dot_block.h) call isk__view_axis_map: the axis copied into
 * locals once (a store to the canvas could alias the view's fields and
 * reload them every point) and `camera` a constant of each inlined copy of
 * a kernel.  The kernels that map 4 or 8 points at once
 * (view/dot_block_avx2.c, dot_block_avx512.c) are its lanes: the same
 * operations in the same order (no FMA), compared with it point by point
 * in tests/test_dot_block.c. */
#ifndef ISKRA_VIEW_VIEW_TRANSFORM_H
#define ISKRA_VIEW_VIEW_TRANSFORM_H

#include "core/cpu.h" /* ISK__INLINE */
#include "iskra/view.h"

/* One axis of a view's transform (see above). */
typedef struct isk__view_axis {
    double c, k, t; /* camera: c - k*(u + t) */
    double s, p;    /* window: s*u + p */
} isk__view_axis;

static inline int isk__view_is_camera(const isk_view *v)
{
    return v->kind == ISK_VIEW_CAMERA;
}

static inline isk__view_axis isk__view_axis_x(const isk_view *v)
{
    const isk__view_axis ax = {v->width / 2.0, -v->a, v->tx, v->sx, v->px};
    return ax;
}

static inline isk__view_axis isk__view_axis_y(const isk_view *v)
{
    const isk__view_axis ay = {v->height / 2.0, v->a, v->ty, v->sy, v->py};
    return ay;
}

/* The screen coordinate of world coordinate u on the axis. */
static ISK__INLINE double isk__view_axis_map(isk__view_axis ax, int camera, double u)
{
    return camera ? ax.c - ax.k * (u + ax.t) : ax.s * u + ax.p;
}

/* Both axes of the point (x, y): isk_view_to_screen without its NULL
 * checks. */
static ISK__INLINE void isk__view_to_screen(const isk_view *v, double x, double y, double *X, double *Y)
{
    const int camera = isk__view_is_camera(v);
    *X = isk__view_axis_map(isk__view_axis_x(v), camera, x);
    *Y = isk__view_axis_map(isk__view_axis_y(v), camera, y);
}

#endif
