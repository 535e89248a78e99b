/* SPDX-License-Identifier: MIT */
/* Integrators: thesis semi-implicit Euler, explicit Euler, velocity Verlet,
 * RK4, exact linear-drag update, leapfrog, Yoshida's fourth order, Strang
 * splitting with exact drag. */
#include "iskra/integrate.h"

#include <math.h>
#include <string.h>

#include "sim/flight.h"
#include "sim/kernels.h"

void isk_integrate_semi_euler(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                              double *restrict vy, const double *restrict m, const double *restrict fx,
                              const double *restrict fy, double dt)
{
    for (size_t i = 0; i < n; i++)
        isk_k_semi_euler(&x[i], &y[i], &vx[i], &vy[i], m[i], fx[i], fy[i], dt);
}

void isk_integrate_euler(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                         double *restrict vy, const double *restrict m, const double *restrict fx,
                         const double *restrict fy, double dt)
{
    for (size_t i = 0; i < n; i++)
        isk_k_euler(&x[i], &y[i], &vx[i], &vy[i], m[i], fx[i], fy[i], dt);
}

void isk_integrate_exact_drag(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                              double *restrict vy, const double *restrict m, const double *restrict fx,
                              const double *restrict fy, double b, double dt)
{
    double dt2 = dt * dt;
    for (size_t i = 0; i < n; i++) {
        double k = b / m[i];
        double h = k * dt;
        double em = expm1(-h);          /* e^-h - 1, accurate for small h */
        double e = 1.0 + em;            /* e^-h */
        double g1 = h > 0.0 ? -em / h : 1.0;
        double g2 = h < 0.1 ? isk__fl_phi2_series(h) : (h + em) / (h * h);
        double ax = fx[i] / m[i], ay = fy[i] / m[i];
        double ovx = vx[i], ovy = vy[i];
        x[i] = x[i] + ovx * (dt * g1) + ax * (dt2 * g2);
        y[i] = y[i] + ovy * (dt * g1) + ay * (dt2 * g2);
        vx[i] = isk_k_flush(ovx * e + ax * (dt * g1));
        vy[i] = isk_k_flush(ovy * e + ay * (dt * g1));
    }
}

static void verlet_drift(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                         double *restrict vy, const double *restrict m, const double *restrict fx,
                         const double *restrict fy, double dt)
{
    double hdt = 0.5 * dt, hdt2 = 0.5 * dt * dt;
    for (size_t i = 0; i < n; i++) {
        double ax = fx[i] / m[i], ay = fy[i] / m[i];
        x[i] = x[i] + dt * vx[i] + hdt2 * ax;
        y[i] = y[i] + dt * vy[i] + hdt2 * ay;
        vx[i] = vx[i] + hdt * ax;
        vy[i] = vy[i] + hdt * ay;
    }
}

static void verlet_kick(size_t n, double *restrict vx, double *restrict vy, const double *restrict m,
                        const double *restrict fx, const double *restrict fy, double dt)
{
    double hdt = 0.5 * dt;
    for (size_t i = 0; i < n; i++) {
        vx[i] = vx[i] + hdt * (fx[i] / m[i]);
        vy[i] = vy[i] + hdt * (fy[i] / m[i]);
    }
}

/* RK4 stage bookkeeping: accumulate w*k into the sums and (unless last)
 * move the state to the next stage point r0 + a*k, v0 + a*k_v. */
static void rk4_stage(size_t n, isk_scratch *restrict s, double *restrict x, double *restrict y,
                      double *restrict vx, double *restrict vy, const double *restrict m, double w,
                      double a, int last)
{
    const double *restrict fx = s->fx, *restrict fy = s->fy;
    double *restrict sx = s->sx, *restrict sy = s->sy, *restrict svx = s->svx, *restrict svy = s->svy;
    const double *restrict x0 = s->x0, *restrict y0 = s->y0, *restrict vx0 = s->vx0,
                           *restrict vy0 = s->vy0;
    if (!last) {
        for (size_t i = 0; i < n; i++) {
            double kx = vx[i], ky = vy[i];
            double kvx = fx[i] / m[i], kvy = fy[i] / m[i];
            sx[i] = sx[i] + w * kx;
            sy[i] = sy[i] + w * ky;
            svx[i] = svx[i] + w * kvx;
            svy[i] = svy[i] + w * kvy;
            x[i] = x0[i] + a * kx;
            y[i] = y0[i] + a * ky;
            vx[i] = vx0[i] + a * kvx;
            vy[i] = vy0[i] + a * kvy;
        }
    } else {
        double c = a / 6.0;
        for (size_t i = 0; i < n; i++) {
            double tx = sx[i] + vx[i], ty = sy[i] + vy[i];
            double tvx = svx[i] + fx[i] / m[i], tvy = svy[i] + fy[i] / m[i];
            x[i] = x0[i] + c * tx;
            y[i] = y0[i] + c * ty;
            vx[i] = vx0[i] + c * tvx;
            vy[i] = vy0[i] + c * tvy;
        }
    }
}

/* ---- leapfrog and its compositions --------------------------------------- */

/* One kick-drift-kick step of tau (which may be negative inside Yoshida's
 * composition) for every force but the drag, whose linear term is split
 * symmetrically: explicit in the opening half kick, solved for the new
 * velocity in the closing one,
 *     v_half = v + (tau/2) (a(x) - k v)
 *     x'     = x + tau v_half
 *     v'     = (v_half + (tau/2) a(x')) / (1 + (tau/2) k)
 * The two halves are each other's adjoints, so the step is symmetric and
 * second order with drag too (velocity Verlet is first order there).  k is
 * b/m saturated at 1/H for the whole step H (forces.h), so 1 + (tau/2) k
 * stays above 0.14 even at Yoshida's negative substep.  (fx, fy) holds a
 * m = F(x) without drag on entry and F(x') on return: consecutive steps
 * share it, so leapfrog costs one force evaluation per step plus the
 * first, and Yoshida's three substeps four. */
static void kdk(isk_forces *f, isk_scratch *s, size_t n, double *restrict x, double *restrict y,
                double *restrict vx, double *restrict vy, const double *restrict m, double tau, double H)
{
    const double ht = 0.5 * tau, b = f->drag, inv_H = 1.0 / H;
    double *restrict fx = s->fx, *restrict fy = s->fy;
    for (size_t i = 0; i < n; i++) {
        double lim = m[i] * inv_H, be = isless(lim, b) ? lim : b; /* saturated drag */
        double k = be / m[i];
        double hvx = vx[i] + ht * (fx[i] / m[i] - k * vx[i]);
        double hvy = vy[i] + ht * (fy[i] / m[i] - k * vy[i]);
        x[i] = x[i] + tau * hvx;
        y[i] = y[i] + tau * hvy;
        vx[i] = hvx;
        vy[i] = hvy;
    }
    isk_forces_eval_step(f, n, x, y, vx, vy, m, fx, fy, s->px, s->py, 0, H);
    if (b == 0.0) {
        for (size_t i = 0; i < n; i++) {
            vx[i] = vx[i] + ht * (fx[i] / m[i]);
            vy[i] = vy[i] + ht * (fy[i] / m[i]);
        }
        return;
    }
    for (size_t i = 0; i < n; i++) {
        double lim = m[i] * inv_H, be = isless(lim, b) ? lim : b;
        double d = 1.0 + ht * (be / m[i]);
        vx[i] = isk_k_flush((vx[i] + ht * (fx[i] / m[i])) / d);
        vy[i] = isk_k_flush((vy[i] + ht * (fy[i] / m[i])) / d);
    }
}

/* Yoshida's fourth-order triple jump: w1, w0, w1 with 2 w1 + w0 = 1 and
 * 2 w1^3 + w0^3 = 0 (w1 = 1/(2 - 2^(1/3)), w0 = -2^(1/3) w1). */
static const double YOSHIDA_W1 = 1.3512071919596578, YOSHIDA_W0 = -1.7024143839193153;

/* ---- Strang splitting with exact drag ------------------------------------- */

/* e = e^-z and D = (1 - e^-z)/z for z >= 0 (so the drag flow over t is
 * v -> e v, x -> x + t D v).  Below 0.1 by their series (12 terms: < 2e-22
 * relative), so a block of ordinary drags has no libm call and vectorizes. */
static inline void drag_flow_series(double z, double *e, double *D)
{
    static const double inv_fact[12] = {
        1.0,         1.0 / 2,      1.0 / 6,       1.0 / 24,       1.0 / 120,       1.0 / 720,
        1.0 / 5040,  1.0 / 40320,  1.0 / 362880,  1.0 / 3628800,  1.0 / 39916800,  1.0 / 479001600,
    };
    double acc = inv_fact[11];
    for (int j = 10; j >= 0; j--)
        acc = inv_fact[j] - z * acc;
    *D = acc;
    *e = 1.0 - z * acc;
}

/* The exact flight under the drag alone over t on the block: v *= e^{-kt},
 * x += t D v (b = 0: the straight drift x += t v). */
static void drag_flow(size_t n, double *restrict x, double *restrict y, double *restrict vx, double *restrict vy,
                      const double *restrict m, double b, double t)
{
    int small = 1;
    for (size_t i = 0; i < n; i++)
        small &= isless(b / m[i] * t, 0.1);
    for (size_t i = 0; i < n; i++) {
        double z = b / m[i] * t, e, D;
        if (small) {
            drag_flow_series(z, &e, &D);
        } else {
            double em = expm1(-z);
            e = 1.0 + em;
            D = z > 0.0 ? -em / z : 1.0;
        }
        double ovx = vx[i], ovy = vy[i];
        x[i] = x[i] + (t * D) * ovx;
        y[i] = y[i] + (t * D) * ovy;
        vx[i] = isk_k_flush(ovx * e);
        vy[i] = isk_k_flush(ovy * e);
    }
}

/* The forces of a step of dt (drag saturated for that step: forces.h). */
static void eval(isk_forces *f, isk_scratch *s, size_t n, const double *x, const double *y, double *vx,
                 double *vy, const double *m, int with_drag, double dt)
{
    isk_forces_eval_step(f, n, x, y, vx, vy, m, s->fx, s->fy, s->px, s->py, with_drag, fabs(dt));
}

void isk_integrate_block(isk_integrator method, isk_forces *f, isk_scratch *s, size_t n, double *x,
                         double *y, double *vx, double *vy, const double *m, double dt)
{
    switch (method) {
    case ISK_INTEGRATE_SEMI_EULER:
        eval(f, s, n, x, y, vx, vy, m, 1, dt);
        isk_integrate_semi_euler(n, x, y, vx, vy, m, s->fx, s->fy, dt);
        break;
    case ISK_INTEGRATE_EULER:
        eval(f, s, n, x, y, vx, vy, m, 1, dt);
        isk_integrate_euler(n, x, y, vx, vy, m, s->fx, s->fy, dt);
        break;
    case ISK_INTEGRATE_VERLET:
        eval(f, s, n, x, y, vx, vy, m, 1, dt);
        verlet_drift(n, x, y, vx, vy, m, s->fx, s->fy, dt);
        eval(f, s, n, x, y, vx, vy, m, 1, dt);
        verlet_kick(n, vx, vy, m, s->fx, s->fy, dt);
        break;
    case ISK_INTEGRATE_RK4: {
        memcpy(s->x0, x, n * sizeof *x);
        memcpy(s->y0, y, n * sizeof *y);
        memcpy(s->vx0, vx, n * sizeof *vx);
        memcpy(s->vy0, vy, n * sizeof *vy);
        memset(s->sx, 0, n * sizeof *x);
        memset(s->sy, 0, n * sizeof *x);
        memset(s->svx, 0, n * sizeof *x);
        memset(s->svy, 0, n * sizeof *x);
        static const double w[4] = {1.0, 2.0, 2.0, 1.0};
        const double a[4] = {0.5 * dt, 0.5 * dt, dt, dt};
        for (int k = 0; k < 4; k++) {
            eval(f, s, n, x, y, vx, vy, m, 1, dt);
            rk4_stage(n, s, x, y, vx, vy, m, w[k], a[k], k == 3);
        }
        break;
    }
    case ISK_INTEGRATE_EXACT_DRAG:
        eval(f, s, n, x, y, vx, vy, m, 0, dt);
        isk_integrate_exact_drag(n, x, y, vx, vy, m, s->fx, s->fy, f->drag, dt);
        break;
    case ISK_INTEGRATE_LEAPFROG:
        eval(f, s, n, x, y, vx, vy, m, 0, dt);
        kdk(f, s, n, x, y, vx, vy, m, dt, fabs(dt));
        break;
    case ISK_INTEGRATE_YOSHIDA4:
        eval(f, s, n, x, y, vx, vy, m, 0, dt);
        kdk(f, s, n, x, y, vx, vy, m, YOSHIDA_W1 * dt, fabs(dt));
        kdk(f, s, n, x, y, vx, vy, m, YOSHIDA_W0 * dt, fabs(dt));
        kdk(f, s, n, x, y, vx, vy, m, YOSHIDA_W1 * dt, fabs(dt));
        break;
    case ISK_INTEGRATE_STRANG:
        /* the exact flight with drag for dt/2, a kick by every other force,
         * the flight again (drift-kick-drift with the drift solved exactly) */
        drag_flow(n, x, y, vx, vy, m, f->drag, 0.5 * dt);
        eval(f, s, n, x, y, vx, vy, m, 0, dt);
        for (size_t i = 0; i < n; i++) {
            vx[i] = vx[i] + dt * (s->fx[i] / m[i]);
            vy[i] = vy[i] + dt * (s->fy[i] / m[i]);
        }
        drag_flow(n, x, y, vx, vy, m, f->drag, 0.5 * dt);
        break;
    default:
        break;
    }
}

isk_status isk_integrate_range(isk_integrator method, isk_forces *f, isk_scratch *s, isk_particles *p,
                               size_t begin, size_t end, double dt)
{
    if (!f || !s || !p)
        return ISK_ERR_NULL;
    if ((unsigned)method >= ISK_INTEGRATOR_COUNT || begin > end || end > p->count)
        return ISK_ERR_RANGE;
    if (!isfinite(dt))
        return ISK_ERR_NAN;
    if (!(fabs(dt) <= ISK_DT_MAX))
        return ISK_ERR_RANGE;
    for (size_t o = begin; o < end; o += ISK_SIM_BLOCK) {
        size_t n = end - o < ISK_SIM_BLOCK ? end - o : ISK_SIM_BLOCK;
        isk_integrate_block(method, f, s, n, p->x + o, p->y + o, p->vx + o, p->vy + o, p->m + o, dt);
    }
    return ISK_OK;
}

const char *const isk_integrator_names[ISK_INTEGRATOR_COUNT] = {
    [ISK_INTEGRATE_SEMI_EULER] = "semi-euler", [ISK_INTEGRATE_EULER] = "euler",
    [ISK_INTEGRATE_VERLET] = "verlet",         [ISK_INTEGRATE_RK4] = "rk4",
    [ISK_INTEGRATE_EXACT_DRAG] = "exact-drag", [ISK_INTEGRATE_LEAPFROG] = "leapfrog",
    [ISK_INTEGRATE_YOSHIDA4] = "yoshida4",     [ISK_INTEGRATE_STRANG] = "strang",
};

const char *isk_integrator_name(isk_integrator method)
{
    return (unsigned)method < ISK_INTEGRATOR_COUNT ? isk_integrator_names[method] : "?";
}

/* x_n lies on the parabola whose velocity at t_n is v_n - offset*a*dt
 * (semi-implicit: x_{n+1} = x_n + dt (v_n + a dt), the parabola of
 * v_n + a dt/2; explicit: x_{n+1} = x_n + dt v_n, of v_n - a dt/2). */
static const double velocity_offsets[ISK_INTEGRATOR_COUNT] = {
    [ISK_INTEGRATE_SEMI_EULER] = -0.5,
    [ISK_INTEGRATE_EULER] = 0.5,
};

double isk_integrator_velocity_offset(isk_integrator method)
{
    return (unsigned)method < ISK_INTEGRATOR_COUNT ? velocity_offsets[method] : 0.0;
}
