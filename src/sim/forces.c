/* SPDX-License-Identifier: MIT */
/* Force stages: gravity, linear drag, Coulomb potentials (thesis semantics). */
#include "iskra/forces.h"

#include <math.h>
#include <string.h>

#include "core/cpu.h" /* ISK__CPU_AVX2, isk__have_avx2 */
#include "sim/forces_loops.h"
#include "sim/kernels.h"
#include "sim/motion_fused.h" /* isk_forces_potentials_on */

const char *const isk_fidelity_names[ISK_FIDELITY_COUNT] = {"sound", "thesis"};
const char *const isk_coulomb_law_names[ISK_COULOMB_LAW_COUNT] = {"code", "text"};

void isk_potential_init(isk_potential *pot, double k, isk_vec2 r, double charge)
{
    if (!pot)
        return;
    memset(pot, 0, sizeof *pot);
    pot->id = 0;
    pot->r = r;
    pot->k = k;
    pot->charge = charge;
    pot->P = 2.0;
    pot->min_dist = ISK_DIST_OFF;
    pot->max_dist = ISK_DIST_OFF;
    pot->x_mult = 1.0;
    pot->enabled = 1;
    pot->vel = isk_vec2_make(0.0, 0.0);
    pot->motion = NULL;
    pot->motion_ctx = NULL;
}

isk_status isk_potential_set_law(isk_potential *pot, isk_coulomb_law law, double exponent)
{
    if (!pot)
        return ISK_ERR_NULL;
    if (!isfinite(exponent))
        return ISK_ERR_NAN;
    switch (law) {
    case ISK_COULOMB_LAW_CODE:
        pot->P = exponent;
        return ISK_OK;
    case ISK_COULOMB_LAW_TEXT:
        pot->P = exponent + 2.0;
        return ISK_OK;
    default:
        return ISK_ERR_RANGE;
    }
}

isk_status isk_potential_validate(const isk_potential *pot)
{
    if (!pot)
        return ISK_ERR_NULL;
    if (!isfinite(pot->r.x) || !isfinite(pot->r.y) || !isfinite(pot->k) || !isfinite(pot->charge) ||
        !isfinite(pot->P) || !isfinite(pot->min_dist) || !isfinite(pot->max_dist) ||
        !isfinite(pot->x_mult) || !isfinite(pot->vel.x) || !isfinite(pot->vel.y))
        return ISK_ERR_NAN;
    if (pot->enabled != 0 && pot->enabled != 1)
        return ISK_ERR_RANGE;
    /* iskra/limits.h: where the law means something, where it is placed. */
    if (!(pot->P >= ISK_P_MIN && pot->P <= ISK_P_MAX) || !(fabs(pot->r.x) <= ISK_COORD_MAX) ||
        !(fabs(pot->r.y) <= ISK_COORD_MAX) || !(fabs(pot->vel.x) <= ISK_SPEED_LIMIT) ||
        !(fabs(pot->vel.y) <= ISK_SPEED_LIMIT))
        return ISK_ERR_RANGE;
    return ISK_OK;
}

static int pw_kind_of(double P) { return P == 2.0 ? 2 : (P == 1.0 ? 1 : 0); }

isk_vec2 isk_potential_force(isk_potential *pot, double x, double y, isk_fidelity centre)
{
    isk_vec2 F = {0.0, 0.0};
    if (!pot || !pot->enabled)
        return F;
    if (pot->max_dist > isk_k_coulomb_dist(pot->r.x, pot->r.y, x, y)) {
        pot->enabled = 0; /* sticky, and already zero for this particle */
        return F;
    }
    double s = 1.0 * (pot->charge * pot->k); /* ukljuci*(naboj*k) */
    if (!isk_k_coulomb(pot->r.x, pot->r.y, x, y, s, pot->x_mult, pot->min_dist, pot->P, pw_kind_of(pot->P),
                       centre == ISK_FIDELITY_SOUND, &F.x, &F.y))
        isk_k_coulomb_saturated(pot->r.x, pot->r.y, x, y, s, pot->x_mult, &F.x, &F.y);
    return F;
}

void isk_potential_move(isk_potential *pot, double param)
{
    if (!pot)
        return;
    isk_vec2 d = pot->motion ? pot->motion(pot->motion_ctx, param)
                             : isk_vec2_make(pot->vel.x * param, pot->vel.y * param);
    pot->r = isk_vec2_add(pot->r, d);
}

void isk_force_gravity(size_t n, const double *restrict m, double g, double *restrict fy)
{
    for (size_t i = 0; i < n; i++)
        fy[i] = fy[i] + isk_k_gravity_fy(m[i], g);
}

void isk_force_drag(size_t n, const double *restrict vx, const double *restrict vy, double b,
                    double *restrict fx, double *restrict fy)
{
    for (size_t i = 0; i < n; i++) {
        fx[i] = fx[i] + isk_k_drag(vx[i], b);
        fy[i] = fy[i] + isk_k_drag(vy[i], b);
    }
}

/* One specialised loop per (power kind, centre rule), forces_loops.h's,
 * in the portable build; forces_avx2.c has the AVX2 one. */
#define COULOMB(kind, sound) COULOMB_AS(coulomb_##kind##sound, static, kind, sound)
COULOMB(0, 0) COULOMB(0, 1) COULOMB(1, 0) COULOMB(1, 1) COULOMB(2, 0) COULOMB(2, 1)
#undef COULOMB

/* [power kind * 2 + sound]. */
static const coulomb_fn coulomb_loops[6] = COULOMB_ROW(coulomb_);

/* First particle that trips the max-distance switch, or n. */
static size_t first_within(size_t n, const double *restrict x, const double *restrict y, double cx,
                           double cy, double maxd)
{
    for (size_t i = 0; i < n; i++)
        if (maxd > isk_k_coulomb_dist(cx, cy, x[i], y[i]))
            return i;
    return n;
}

void isk_force_potential(isk_potential *pot, size_t n, const double *x, const double *y, double *px,
                         double *py, isk_fidelity centre)
{
    if (!pot->enabled || n == 0)
        return;
    double cx = pot->r.x, cy = pot->r.y;
    size_t cut = n;
    if (pot->max_dist > 0.0) {
        /* The thesis switches the potential off inside its per-particle
         * loop: particles before the first one within max_dist still feel
         * it, that one and all later ones do not. */
        cut = first_within(n, x, y, cx, cy, pot->max_dist);
        if (cut < n)
            pot->enabled = 0;
    }
    double s = 1.0 * (pot->charge * pot->k);
    if (s == 0.0 || cut == 0)
        return;
    double xm = pot->x_mult, minv = pot->min_dist, P = pot->P;
    const int sound = centre == ISK_FIDELITY_SOUND;
    const int k = pw_kind_of(P) * 2 + sound;
#if ISK__CPU_AVX2
    if (isk__have_avx2()) {
        isk__coulomb_loops_avx2[k](cut, x, y, px, py, cx, cy, s, xm, minv, P);
        return;
    }
#endif
    coulomb_loops[k](cut, x, y, px, py, cx, cy, s, xm, minv, P);
}

static void add_into(size_t n, double *restrict fx, double *restrict fy, const double *restrict px,
                     const double *restrict py)
{
    for (size_t i = 0; i < n; i++) {
        fx[i] = fx[i] + px[i];
        fy[i] = fy[i] + py[i];
    }
}

void isk_force_accel(size_t n, const double *m, double ax, double ay, double *fx, double *fy)
{
    for (size_t i = 0; i < n; i++) {
        fx[i] += m[i] * ax;
        fy[i] += m[i] * ay;
    }
}

/* The pipeline's drag stage: flush decayed components (isk_k_flush), then
 * add -b*v; one pass over the velocities.  With a step h > 0 the drag
 * saturates at m/h (iskra/limits.h): b*h/m never exceeds 1, so an explicit
 * step can stop a particle but never reverse it; below that it is b itself
 * (the same bits as without a step). */
static void drag_stage(size_t n, double *restrict vx, double *restrict vy, const double *restrict m, double b,
                       double h, double *restrict fx, double *restrict fy)
{
    if (!(h > 0.0)) {
        for (size_t i = 0; i < n; i++) {
            double ux = isk_k_flush(vx[i]), uy = isk_k_flush(vy[i]);
            vx[i] = ux;
            vy[i] = uy;
            fx[i] = fx[i] + isk_k_drag(ux, b);
            fy[i] = fy[i] + isk_k_drag(uy, b);
        }
        return;
    }
    const double inv_h = 1.0 / h;
    for (size_t i = 0; i < n; i++) {
        double ux = isk_k_flush(vx[i]), uy = isk_k_flush(vy[i]);
        double lim = m[i] * inv_h;
        double be = isless(lim, b) ? lim : b;
        vx[i] = ux;
        vy[i] = uy;
        fx[i] = fx[i] + isk_k_drag(ux, be);
        fy[i] = fy[i] + isk_k_drag(uy, be);
    }
}

int isk_forces_potentials_on(const isk_forces *f)
{
    const size_t np = f->pick ? f->npick : f->npot;
    int any = 0;
    for (size_t k = 0; k < np; k++)
        any |= f->pot[f->pick ? f->pick[k] : k].enabled;
    return any;
}

void isk_forces_eval_step(isk_forces *f, size_t n, const double *x, const double *y, double *vx, double *vy,
                          const double *m, double *fx, double *fy, double *px, double *py, int with_drag, double h)
{
    memset(fx, 0, n * sizeof *fx); /* all-bits-zero is +0.0 */
    memset(fy, 0, n * sizeof *fy);
    if (f->gravity != 0.0)
        isk_force_gravity(n, m, f->gravity, fy);
    if (f->ax != 0.0 || f->ay != 0.0)
        isk_force_accel(n, m, f->ax, f->ay, fx, fy);
    if (with_drag && f->drag != 0.0)
        drag_stage(n, vx, vy, m, f->drag, h, fx, fy);
    if (!isk_forces_potentials_on(f))
        return;
    const size_t np = f->pick ? f->npick : f->npot;
    memset(px, 0, n * sizeof *px);
    memset(py, 0, n * sizeof *py);
    for (size_t k = 0; k < np; k++)
        isk_force_potential(&f->pot[f->pick ? f->pick[k] : k], n, x, y, px, py, f->centre);
    add_into(n, fx, fy, px, py);
}

void isk_forces_eval(isk_forces *f, size_t n, const double *x, const double *y, double *vx, double *vy,
                     const double *m, double *fx, double *fy, double *px, double *py, int with_drag)
{
    isk_forces_eval_step(f, n, x, y, vx, vy, m, fx, fy, px, py, with_drag, 0.0);
}
