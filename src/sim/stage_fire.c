/* The fire thesis's stages: slowing (in both orders) and the horizontal
 * oscillation (see stage.h). */
#include <math.h>

#include "sim/kernels.h"
#include "sim/stage.h"

/* The fire thesis's 1 - slowing*dt, clamped so a long frame can stop a
 * particle but never reverse it. */
static double slow_factor(double slowing, double h)
{
    double f = 1.0 - slowing * h;
    return f > 0.0 ? f : 0.0;
}

static void run_slow(const isk_stage *st, isk_block *b, double h)
{
    const double f = slow_factor(st->u.slow.slowing, h);
    double *restrict vx = b->vx, *restrict vy = b->vy;
    for (size_t i = 0; i < b->n; i++) {
        vx[i] = isk_k_flush(vx[i] * f);
        vy[i] = isk_k_flush(vy[i] * f);
    }
}

static void describe_slow(const isk_stage *st, FILE *out)
{
    fprintf(out, "v *= max(0, 1 - %g*dt)", st->u.slow.slowing);
}

const isk_stage_kind isk_stage_slow = {"slow", run_slow, describe_slow};

/* The fire thesis's Emitter::Advance: v -= F*dt; v *= slow; p += v*dt (F in
 * its sign is -a), slow clamped at 0. */
static void run_drift_slow(const isk_stage *st, isk_block *b, double h)
{
    const double dvx = st->u.drift_slow.ax * h, dvy = st->u.drift_slow.ay * h;
    const double f = slow_factor(st->u.drift_slow.slowing, h);
    double *restrict x = b->x, *restrict y = b->y, *restrict vx = b->vx, *restrict vy = b->vy;
    for (size_t i = 0; i < b->n; i++) {
        double nvx = isk_k_flush((vx[i] + dvx) * f), nvy = isk_k_flush((vy[i] + dvy) * f);
        vx[i] = nvx;
        vy[i] = nvy;
        x[i] = x[i] + h * nvx;
        y[i] = y[i] + h * nvy;
    }
}

static void describe_drift_slow(const isk_stage *st, FILE *out)
{
    fprintf(out, "thesis order: v += (%g, %g)*dt; v *= max(0, 1 - %g*dt); p += v*dt", st->u.drift_slow.ax,
            st->u.drift_slow.ay, st->u.drift_slow.slowing);
}

const isk_stage_kind isk_stage_drift_slow = {"drift", run_drift_slow, describe_drift_slow};

/* One loop per (table, faithful) choice: `use_table` and `faithful` are
 * constants at each call below, so no loop branches per particle. */
static inline void osc_loop(size_t n, double *restrict x, double *restrict vx, double *restrict amp,
                            double *restrict ph, const double *restrict om, double *restrict off, double decay,
                            const isk_sinlut *table, const int use_table, const int faithful, double h)
{
    for (size_t i = 0; i < n; i++) {
        ph[i] += om[i] * h;
        double s = amp[i] * (use_table ? isk_sinlut_floor(table, ph[i]) : sin(ph[i]));
        double dx = s - off[i];
        x[i] += dx;
        if (faithful)
            vx[i] += dx;
        off[i] = s;
        amp[i] = isk_k_flush(amp[i] * decay);
    }
}

static void run_oscillate(const isk_stage *st, isk_block *b, double h)
{
    isk_particles *p = b->p;
    const size_t o = b->first;
    double decay = 1.0 - st->u.osc.decay * h;
    if (!(decay > 0.0))
        decay = 0.0;
    double *amp = p->osc_amp + o, *ph = p->osc_phase + o, *om = p->osc_omega + o, *off = p->osc_offset + o;
    const isk_sinlut *t = st->u.osc.table;
    if (t && st->u.osc.faithful)
        osc_loop(b->n, b->x, b->vx, amp, ph, om, off, decay, t, 1, 1, h);
    else if (t)
        osc_loop(b->n, b->x, b->vx, amp, ph, om, off, decay, t, 1, 0, h);
    else if (st->u.osc.faithful)
        osc_loop(b->n, b->x, b->vx, amp, ph, om, off, decay, NULL, 0, 1, h);
    else
        osc_loop(b->n, b->x, b->vx, amp, ph, om, off, decay, NULL, 0, 0, h);
}

static void describe_oscillate(const isk_stage *st, FILE *out)
{
    fprintf(out, "x, omega %g..%g rad/s, amplitude %g..%g, decay %g/s%s%s", st->u.osc.omega_min, st->u.osc.omega_max,
            st->u.osc.amp_min, st->u.osc.amp_max, st->u.osc.decay, st->u.osc.faithful ? ", thesis vx coupling" : "",
            st->u.osc.table ? ", sine table" : ", libm sin");
}

const isk_stage_kind isk_stage_oscillate = {"oscillate", run_oscillate, describe_oscillate};
