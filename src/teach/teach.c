/* SPDX-License-Identifier: MIT */
/* The teaching API (iskra/teach.h): the thesis's classes, one particle at
 * a time.  A module above the simulation and the view: a particle moves
 * and bounces by the particle store's own kernels (src/sim/kernels.h), so
 * one particle and a million give the same bits, and it is drawn through
 * the view (iskra/view.h) as the thesis's browser draws a point.  The
 * simulation itself knows nothing of views and pixels. */
#include "iskra/teach.h"

#include "sim/kernels.h"

/* A NULL particle or view is a no-op (or a zero force): the teaching API
 * never dereferences what it was not given. */
void isk_mp_move(isk_material_point *mp, double dt, isk_vec2 F)
{
    if (!mp)
        return;
    isk_k_semi_euler(&mp->r.x, &mp->r.y, &mp->v.x, &mp->v.y, mp->m, F.x, F.y, dt);
}

void isk_mp_move_explicit(isk_material_point *mp, double dt, isk_vec2 F)
{
    if (!mp)
        return;
    isk_k_euler(&mp->r.x, &mp->r.y, &mp->v.x, &mp->v.y, mp->m, F.x, F.y, dt);
}

isk_vec2 isk_gravity_force(const isk_material_point *mp, double g)
{
    if (!mp)
        return isk_vec2_make(0.0, 0.0);
    return isk_vec2_make(0.0, isk_k_gravity_fy(mp->m, g));
}

isk_vec2 isk_drag_force(const isk_material_point *mp, double o)
{
    if (!mp)
        return isk_vec2_make(0.0, 0.0);
    return isk_vec2_make(isk_k_drag(mp->v.x, o), isk_k_drag(mp->v.y, o));
}

isk_vec2 isk_potential_force_on(isk_potential *pot, const isk_material_point *mp, isk_fidelity centre)
{
    if (!mp)
        return isk_vec2_make(0.0, 0.0);
    return isk_potential_force(pot, mp->r.x, mp->r.y, centre);
}

void isk_particle_init(isk_particle *c, double m, isk_vec2 r, isk_vec2 v)
{
    if (!c)
        return;
    c->diameter = 0.1;
    c->mp.m = m;
    c->mp.r = r;
    c->mp.v = v;
    c->color = ISK_YELLOW;
}

void isk_particle_draw(const isk_particle *c, isk_canvas *canvas, const isk_view *view)
{
    if (!c || !canvas || !view)
        return;
    isk_world_dot_browser(canvas, view, c->mp.r.x, c->mp.r.y, c->color, ISK_BLEND_OVER);
}

void isk_particle_zarobi_box(isk_particle *c, double xmin, double xmax, double ymin, double ymax,
                             int top, int right, int bottom, int left)
{
    if (!c)
        return;
    double *x = &c->mp.r.x, *y = &c->mp.r.y, *vx = &c->mp.v.x, *vy = &c->mp.v.y;
    double p = c->diameter;
    if (left)
        *vx = isk_k_flip_below(*x, xmin + p, *vx);
    if (right)
        *vx = isk_k_flip_above(*x, xmax - p, *vx);
    if (bottom)
        *vy = isk_k_flip_below(*y, ymin + p, *vy);
    if (top)
        *vy = isk_k_flip_above(*y, ymax - p, *vy);
    if (bottom)
        *y = isk_k_clamp_below(*y, ymin + p);
}

void isk_particle_zarobi(isk_particle *c, const isk_view *view, int top, int right, int bottom, int left)
{
    if (!c || !view)
        return;
    isk_particle_zarobi_box(c, view->xmin, view->xmax, view->ymin, view->ymax, top, right, bottom, left);
}
