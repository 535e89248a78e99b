/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --only invariants`: what each integrator keeps.
 *
 * A symplectic method does not keep the energy E; it keeps a nearby
 * "modified" energy (the shadow Hamiltonian) whose first correction is
 * known in closed form.  The plain energy then swings at O(h^p) within
 * every orbit while the modified one stays flat to the next order.  Per
 * unit mass, with the acceleration a = -grad(Phi) and the Hessian
 * Phi'' of the potential:
 *
 *   semi-Euler (kick, then drift)  E~ = E + (h/2) v.a              flat to O(h^2)
 *   explicit Euler (drift, kick)   E~ = E - (h/2) v.a              (no invariant
 *                                       but under a constant force)
 *   Verlet, leapfrog (kick-drift-kick)
 *                                  E~ = E + h^2 (-|a|^2/24 + v.Phi''v/12)  to O(h^4)
 *   Strang without drag (drift-kick-drift)
 *                                  E~ = E + h^2 (|a|^2/12 - v.Phi''v/24)   to O(h^4)
 *
 * (the BCH series of the splitting; Hairer, Lubich and Wanner, Geometric
 * Numerical Integration, IX.)  The h v.a term of the Euler forms is
 * -offset h v.a with iskra's velocity offset (isk_integrator_velocity_offset):
 * their positions lie on the flight of the velocity v - offset a h, and
 * E~ is that velocity's energy up to a constant.  It is kept *exactly*
 * (to rounding) under a linear force (semi-Euler on the spring) and under a
 * constant one (both Euler forms under gravity, bounces included).
 * Yoshida's first correction is of order h^4 and has more terms; it is
 * not computed here (its plain energy is shown).
 *
 * Two measurements:
 *
 *   invariants_kepler.csv/.png   one particle on the Kepler ellipse (e 0.6,
 *       a 1, period 1 s) for 10 periods at 64 .. 8192 steps per period:
 *       the largest relative swing of E and of E~ over every step, and the
 *       period of the numerical orbit, timed between periapsis passages
 *       (r.v crossing zero upwards, located on the cubic through both ends
 *       of the step), against the exact 1 s.  invariants_period.png.
 *   invariants_euler.csv/.png    the Euler forms where E~ is exact: a
 *       closed box of 500 particles under gravity (restitution 1, 10^4
 *       frames at 1/60 s) and semi-Euler on the spring (16 particles, 10^3
 *       periods at 60 steps per period): the largest swing so far of E and
 *       of E~ after every frame.
 *
 * RK4's energy error is fifth order at everyday steps (a drift of h^5 per
 * orbit) and fourth order from about 4096 steps per period on, where a
 * bounded h^4 term under the drift takes over.
 *
 * --quick: 512 .. 8192 steps per period, 1000 frames, 100 periods. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/integrate.h"
#include "iskra/problems.h"
#include "iskra/scene.h"
#include "iskra/system.h"
#include "study.h"

/* ---- the modified energies ------------------------------------------------------ */

/* E~ = E - offset h v.a + h^2 (aa |a|^2 + vhv v.Phi''v) per unit mass. */
typedef struct shadow_terms {
    isk_integrator method;
    int has_shadow; /* 0: only the plain energy is shown */
    int order;      /* p: the plain energy's order */
    double aa, vhv; /* the h^2 coefficients */
} shadow_terms;

static const shadow_terms KEPLER_METHODS[] = {
    {ISK_INTEGRATE_SEMI_EULER, 1, 1, 0, 0},
    {ISK_INTEGRATE_VERLET, 1, 2, -1.0 / 24, 1.0 / 12},
    {ISK_INTEGRATE_LEAPFROG, 1, 2, -1.0 / 24, 1.0 / 12},
    {ISK_INTEGRATE_STRANG, 1, 2, 1.0 / 12, -1.0 / 24},
    {ISK_INTEGRATE_YOSHIDA4, 0, 4, 0, 0},
    {ISK_INTEGRATE_RK4, 0, 4, 0, 0},
};
enum { NKM = sizeof KEPLER_METHODS / sizeof KEPLER_METHODS[0], NSTEP = 8, KEPLER_PERIODS = 10 };
static const int STEPS_PER_PERIOD[NSTEP] = {64, 128, 256, 512, 1024, 2048, 4096, 8192};

/* The Kepler problem's energy per unit mass and its modified energy, for
 * mu = kQ/m: Phi = -mu/r, a = -mu r/r^3, v.Phi''v = mu (v^2/r^3 - 3 (r.v)^2/r^5). */
static void kepler_energies(double mu, const shadow_terms *t, double h, double x, double y, double vx, double vy,
                            double *E, double *Em)
{
    double r = hypot(x, y), r3 = r * r * r, rv = x * vx + y * vy, v2 = vx * vx + vy * vy;
    double ax = -mu * x / r3, ay = -mu * y / r3;
    double vhv = mu * (v2 / r3 - 3 * rv * rv / (r3 * r * r));
    *E = 0.5 * v2 - mu / r;
    *Em = *E - isk_integrator_velocity_offset(t->method) * h * (vx * ax + vy * ay) +
          h * h * (t->aa * (ax * ax + ay * ay) + t->vhv * vhv);
}

typedef struct kepler_result {
    double energy, modified, period; /* relative: max swings, |P - 1| */
    int passages;
} kepler_result;

/* The time in [0, h] where the cubic with values s0, s1 and slopes d0, d1
 * at the ends crosses zero (s0 < 0 <= s1): bisection, to rounding. */
static double cubic_root(double s0, double s1, double d0, double d1, double h)
{
    double lo = 0, hi = 1;
    for (int k = 0; k < 60; k++) {
        double u = 0.5 * (lo + hi), u2 = u * u, u3 = u2 * u;
        double s = (2 * u3 - 3 * u2 + 1) * s0 + (u3 - 2 * u2 + u) * h * d0 + (-2 * u3 + 3 * u2) * s1 +
                   (u3 - u2) * h * d1;
        if (s < 0)
            lo = u;
        else
            hi = u;
    }
    return 0.5 * (lo + hi) * h;
}

static isk_status kepler_run(isk_system *s, const shadow_terms *t, int n, int periods, kepler_result *out)
{
    isk_problem pb = isk_problem_defaults(ISK_PROBLEM_KEPLER);
    pb.count = 1;
    pb.start_min = pb.start_max = 1.0; /* a = 1: period 1 s */
    pb.T = periods;
    const double mu = pb.kq / pb.mass, h = 1.0 / n;
    const double P0 = 2 * acos(-1.0) / sqrt(mu); /* 2 pi sqrt(a^3/mu), a = 1 */
    isk_status st = isk_system_init(s, 1, 0);
    if (st == ISK_OK)
        st = isk_problem_setup(&pb, s);
    if (st == ISK_OK)
        st = isk_system_set_integrator(s, t->method);
    const isk_particles *p = &s->particles;
    double E0 = 0, M0 = 0, first = NAN, last = NAN;
    memset(out, 0, sizeof *out);
    if (st == ISK_OK)
        kepler_energies(mu, t, h, p->x[0], p->y[0], p->vx[0], p->vy[0], &E0, &M0);
    for (long k = 0; k < (long)n * periods && st == ISK_OK; k++) {
        /* r.v and its slope d(r.v)/dt = v^2 + r.a = v^2 - mu/r, before and after the step */
        double s0 = p->x[0] * p->vx[0] + p->y[0] * p->vy[0];
        double d0 = p->vx[0] * p->vx[0] + p->vy[0] * p->vy[0] - mu / hypot(p->x[0], p->y[0]);
        st = isk_system_step(s, h);
        if (st != ISK_OK)
            break;
        double r = hypot(p->x[0], p->y[0]);
        double s1 = p->x[0] * p->vx[0] + p->y[0] * p->vy[0];
        double d1 = p->vx[0] * p->vx[0] + p->vy[0] * p->vy[0] - mu / r;
        if (s0 < 0 && s1 >= 0) {
            double at = (double)k * h + cubic_root(s0, s1, d0, d1, h);
            if (out->passages++ == 0)
                first = at;
            last = at;
        }
        double E, Em;
        kepler_energies(mu, t, h, p->x[0], p->y[0], p->vx[0], p->vy[0], &E, &Em);
        out->energy = fmax(out->energy, fabs(E / E0 - 1));
        out->modified = fmax(out->modified, fabs(Em / M0 - 1));
    }
    out->period = out->passages > 1 ? fabs((last - first) / (out->passages - 1) / P0 - 1.0) : NAN;
    if (!t->has_shadow)
        out->modified = NAN;
    isk_system_free(s);
    return st;
}

/* log2 of the ratio of two errors a step halving apart (NaN if either is not
 * a positive number). */
static double order_of(double coarse, double fine)
{
    return coarse > 0 && fine > 0 && isfinite(coarse) && isfinite(fine) ? log2(coarse / fine) : NAN;
}

typedef struct kepler_table {
    int nstep, first; /* STEPS_PER_PERIOD[first .. first + nstep) */
    kepler_result r[NKM][NSTEP];
} kepler_table;

static void print_kepler(const kepler_table *K)
{
    printf("-- invariants: Kepler ellipse e = 0.6, a = 1 (period 1 s), %d periods, one particle\n"
           "  largest relative swing of the energy E and of the modified energy E~ over every step,\n"
           "  and the relative error of the orbit's period (timed between periapsis passages);\n"
           "  in brackets the order (log2 of the ratio when h halves)\n",
           KEPLER_PERIODS);
    const char *what[3] = {"energy E", "modified E~", "period"};
    for (int q = 0; q < 3; q++) {
        printf("  %s\n  %10s", what[q], "steps/per");
        for (int m = 0; m < NKM; m++)
            printf(" %19s", isk_integrator_name(KEPLER_METHODS[m].method));
        printf("\n");
        for (int j = 0; j < K->nstep; j++) {
            printf("  %10d", STEPS_PER_PERIOD[K->first + j]);
            for (int m = 0; m < NKM; m++) {
                const kepler_result *a = &K->r[m][j];
                double v = q == 0 ? a->energy : q == 1 ? a->modified : a->period;
                double o = NAN;
                if (j > 0) {
                    const kepler_result *b = &K->r[m][j - 1];
                    o = order_of(q == 0 ? b->energy : q == 1 ? b->modified : b->period, v);
                }
                if (isnan(v))
                    printf(" %19s", "-");
                else if (isnan(o))
                    printf(" %10.3e       ", v);
                else
                    printf(" %10.3e (%4.2f)", v, o);
            }
            printf("\n");
        }
    }
    printf("\n");
}

static int write_kepler(const study_opts *o, const kepler_table *K)
{
    study_buf csv = {0};
    study_printf(&csv, "integrator,steps_per_period,h,energy_swing,modified_energy_swing,period_error\n");
    for (int m = 0; m < NKM; m++)
        for (int j = 0; j < K->nstep; j++) {
            const kepler_result *a = &K->r[m][j];
            int n = STEPS_PER_PERIOD[K->first + j];
            study_printf(&csv, "%s,%d,%.10g,%.6e,%.6e,%.6e\n", isk_integrator_name(KEPLER_METHODS[m].method), n,
                         1.0 / n, a->energy, a->modified, a->period);
        }
    int rc = study_write_text(o, "invariants_kepler.csv", &csv);
    study_buf_free(&csv);

    /* the swings: plain solid, modified dashed, one colour per integrator;
     * Verlet is left out of the charts (leapfrog's numbers to rounding) */
    double xs[NSTEP], ys[2 * NKM][NSTEP], ps[NKM][NSTEP];
    char names[2 * NKM][48];
    isk_chart_series ser[2 * NKM], per[NKM];
    size_t ns = 0, np = 0;
    for (int j = 0; j < K->nstep; j++)
        xs[j] = STEPS_PER_PERIOD[K->first + j];
    for (int m = 0; m < NKM; m++) {
        const shadow_terms *t = &KEPLER_METHODS[m];
        if (t->method == ISK_INTEGRATE_VERLET)
            continue;
        isk_chart_style style = isk_chart_style_default((int)t->method);
        for (int q = 0; q < 1 + t->has_shadow; q++) {
            for (int j = 0; j < K->nstep; j++)
                ys[ns][j] = q ? K->r[m][j].modified : K->r[m][j].energy;
            snprintf(names[ns], sizeof names[ns], "%s, %s", isk_integrator_name(t->method),
                     q ? "modified energy" : "energy");
            ser[ns] = (isk_chart_series){names[ns], xs, ys[ns], (size_t)K->nstep, style};
            ser[ns].style.dash = q ? ISK_DASH_DASHED : ISK_DASH_SOLID;
            ns++;
        }
        for (int j = 0; j < K->nstep; j++)
            ps[np][j] = K->r[m][j].period;
        per[np] = (isk_chart_series){isk_integrator_name(t->method), xs, ps[np], (size_t)K->nstep, style};
        np++;
    }
    isk_chart ch;
    isk_chart_defaults(&ch);
    ch.title = "Kepler (e = 0.6): the energy swings, the modified energy stays flat";
    ch.x_label = "steps per period";
    ch.y_label = "max relative swing over 10 periods";
    ch.x_log = ch.y_log = 1;
    ch.series = ser;
    ch.nseries = ns;
    ch.legend = ISK_LEGEND_BOTTOM_LEFT;
    rc |= study_write_chart(o, "invariants_kepler.png", &ch, 1200, 800);
    ch.title = "Kepler (e = 0.6): the period of the numerical orbit";
    ch.y_label = "|P - P0| / P0 (timed between periapsis passages)";
    ch.series = per;
    ch.nseries = np;
    rc |= study_write_chart(o, "invariants_period.png", &ch, 1200, 800);
    return rc;
}

/* ---- the Euler forms: the invariant kept exactly ------------------------------ */

static const char *BOX_SCENE = "[scene]\ndt = 1/60\nintegrator = %s\nseed = 5\n"
                               "[view]\nxmin = -6\nxmax = 6\nymin = -1\nymax = 11\n"
                               "[force gravity]\ng = %.17g\n"
                               "[bounds]\nmode = reflect\nwindow = -5, 5, 0, 10\nrestitution = 1\n"
                               "[emitter box]\nsource = explosion\nexplosion = gauss\nposition = 0, 5\n"
                               "count = 500\nforces = gravity\ndraw = none\nbounded = true\n";
static const double BOX_G = 9.81;

enum { EULER_CASES = 3 };
typedef struct euler_case {
    const char *name;
    isk_integrator method;
    int box;          /* 1: the closed box, 0: the spring */
    double *plain;    /* largest swing so far after each frame */
    double *kept;
    double end;       /* |E - E0| / E0 after the last frame: what a snapshot reports */
} euler_case;

/* Sum over the box of m (v^2/2 + g y) and of the invariant, the same minus
 * offset h m v.a with a = (0, -g). */
static void box_energies(const isk_particles *p, double off, double h, double *E, double *Em)
{
    double e = 0, em = 0;
    for (size_t i = 0; i < p->count; i++) {
        double ei = p->m[i] * (0.5 * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]) + BOX_G * p->y[i]);
        e += ei;
        em += ei - off * h * p->m[i] * (p->vy[i] * -BOX_G);
    }
    *E = e;
    *Em = em;
}

static int run_box(euler_case *c, int frames)
{
    char text[1024];
    snprintf(text, sizeof text, BOX_SCENE, isk_integrator_name(c->method), BOX_G);
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    if (isk_scene_load_string(&d, text, "box", &err) != ISK_OK) {
        fprintf(stderr, "iskra bench: invariants: %s\n", err.message);
        return 1;
    }
    isk_status st = isk_effect_create(&fx, &d, &err);
    isk_effect_def_free(&d);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench: invariants: %s\n", err.message);
        return 1;
    }
    const isk_particles *p = isk_effect_particles(fx, 0);
    const double off = isk_integrator_velocity_offset(c->method), h = 1.0 / 60;
    double E0, M0, E, Em, plain = 0, kept = 0;
    box_energies(p, off, h, &E0, &M0);
    for (int f = 0; f < frames && st == ISK_OK; f++) {
        st = isk_effect_step(fx);
        box_energies(p, off, h, &E, &Em);
        c->plain[f] = plain = fmax(plain, fabs(E / E0 - 1));
        c->kept[f] = kept = fmax(kept, fabs(Em / M0 - 1));
        c->end = fabs(E / E0 - 1);
    }
    if (st == ISK_OK && p->count != 500)
        st = ISK_ERR_SIZE; /* the box must keep every particle */
    isk_effect_destroy(fx);
    if (st != ISK_OK)
        fprintf(stderr, "iskra bench: invariants: box, %s: %s\n", isk_integrator_name(c->method),
                isk_status_str(st));
    return st != ISK_OK;
}

/* Semi-Euler on the spring at 60 steps per period, one frame a step; per
 * particle E = m v^2/2 + kQ r^2/2, E~ = E - offset h m v.a, a = -(kQ/m) r. */
static int run_spring(isk_system *s, euler_case *c, int frames)
{
    isk_problem pb = isk_problem_defaults(ISK_PROBLEM_OSCILLATOR);
    pb.count = 16;
    pb.T = frames / 60.0;
    const double h = 1.0 / 60, off = isk_integrator_velocity_offset(c->method), w2 = pb.kq / pb.mass;
    isk_status st = isk_system_init(s, 1, 0);
    if (st == ISK_OK)
        st = isk_problem_setup(&pb, s);
    if (st == ISK_OK)
        st = isk_system_set_integrator(s, c->method);
    const isk_particles *p = &s->particles;
    double E0[16], M0[16], plain = 0, kept = 0;
    c->end = 0;
    for (int f = -1; f < frames && st == ISK_OK; f++) {
        if (f >= 0)
            st = isk_system_step(s, h);
        for (size_t i = 0; i < p->count && st == ISK_OK; i++) {
            double v2 = p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i], r2 = p->x[i] * p->x[i] + p->y[i] * p->y[i];
            double va = -w2 * (p->vx[i] * p->x[i] + p->vy[i] * p->y[i]);
            double E = pb.mass * 0.5 * v2 + pb.kq * 0.5 * r2, Em = E - off * h * pb.mass * va;
            if (f < 0) {
                E0[i] = E;
                M0[i] = Em;
            } else {
                plain = fmax(plain, fabs(E / E0[i] - 1));
                if (f == frames - 1)
                    c->end = fmax(c->end, fabs(E / E0[i] - 1));
                kept = fmax(kept, fabs(Em / M0[i] - 1));
            }
        }
        if (f >= 0) {
            c->plain[f] = plain;
            c->kept[f] = kept;
        }
    }
    isk_system_free(s);
    if (st != ISK_OK)
        fprintf(stderr, "iskra bench: invariants: spring: %s\n", isk_status_str(st));
    return st != ISK_OK;
}

static int study_euler(const study_opts *o, isk_system *s)
{
    const int frames = o->quick ? 1000 : 10000;
    const int spring_frames = o->quick ? 6000 : 60000;
    euler_case cases[EULER_CASES] = {
        {"closed box, semi-euler", ISK_INTEGRATE_SEMI_EULER, 1, NULL, NULL, 0},
        {"closed box, euler", ISK_INTEGRATE_EULER, 1, NULL, NULL, 0},
        {"spring, semi-euler", ISK_INTEGRATE_SEMI_EULER, 0, NULL, NULL, 0},
    };
    int rc = 0;
    for (int c = 0; c < EULER_CASES; c++) {
        int n = cases[c].box ? frames : spring_frames;
        cases[c].plain = malloc((size_t)n * sizeof(double));
        cases[c].kept = malloc((size_t)n * sizeof(double));
        if (!cases[c].plain || !cases[c].kept) {
            fprintf(stderr, "iskra bench: invariants: out of memory\n");
            rc = 1;
        }
    }
    for (int c = 0; c < EULER_CASES && !rc; c++)
        rc = cases[c].box ? run_box(&cases[c], frames) : run_spring(s, &cases[c], spring_frames);
    if (!rc) {
        printf("-- invariants: the Euler forms keep E~ = E - offset h m v.a exactly under a constant\n"
               "   or linear force (closed box: 500 particles, g %g, restitution 1, %d frames of 1/60 s;\n"
               "   spring: 16 particles, 60 steps per period, %d periods)\n"
               "  %-24s %16s %16s %16s\n",
               BOX_G, frames, spring_frames / 60, "case", "max |dE|/E", "E at the end", "max |dE~|/E~");
        study_buf csv = {0};
        study_printf(&csv, "case,integrator,frames,energy_swing,energy_error_at_end,invariant_swing\n");
        for (int c = 0; c < EULER_CASES; c++) {
            int n = cases[c].box ? frames : spring_frames;
            /* the value at the end, as a single snapshot would report it */
            printf("  %-24s %16.3e %16.3e %16.3e\n", cases[c].name, cases[c].plain[n - 1], cases[c].end,
                   cases[c].kept[n - 1]);
            study_printf(&csv, "%s,%s,%d,%.6e,%.6e,%.6e\n", cases[c].box ? "box" : "spring",
                         isk_integrator_name(cases[c].method), n, cases[c].plain[n - 1], cases[c].end,
                         cases[c].kept[n - 1]);
        }
        printf("\n");
        rc |= study_write_text(o, "invariants_euler.csv", &csv);
        study_buf_free(&csv);

        /* the swings so far against time, at about 25 frames a decade */
        enum { MAXPTS = 256 };
        double t[MAXPTS], ys[2 * EULER_CASES][MAXPTS];
        isk_chart_series ser[2 * EULER_CASES];
        char names[2 * EULER_CASES][64];
        for (int c = 0; c < EULER_CASES; c++) {
            int n = cases[c].box ? frames : spring_frames;
            size_t k = 0;
            for (int f = 1; f <= n && k < MAXPTS; f = f + 1 > (int)(f * 1.1) ? f + 1 : (int)(f * 1.1)) {
                t[k] = f / 60.0;
                ys[2 * c][k] = cases[c].plain[f - 1];
                ys[2 * c + 1][k] = cases[c].kept[f - 1];
                k++;
            }
            for (int q = 0; q < 2; q++) {
                isk_chart_series *x = &ser[2 * c + q];
                snprintf(names[2 * c + q], sizeof names[0], "%s: %s", cases[c].name, q ? "E~" : "E");
                *x = (isk_chart_series){names[2 * c + q], t, ys[2 * c + q], k, isk_chart_style_default(c)};
                x->style.dash = q ? ISK_DASH_DASHED : ISK_DASH_SOLID;
            }
        }
        isk_chart ch;
        isk_chart_defaults(&ch);
        ch.title = "Euler forms: the energy swings, E~ = E - offset h m v.a is kept";
        ch.x_label = "simulated time (s)";
        ch.y_label = "largest relative swing so far";
        ch.x_log = ch.y_log = 1;
        ch.series = ser;
        ch.nseries = 2 * EULER_CASES;
        ch.legend = ISK_LEGEND_ABOVE;
        rc |= study_write_chart(o, "invariants_euler.png", &ch, 1200, 800);
    }
    for (int c = 0; c < EULER_CASES; c++) {
        free(cases[c].plain);
        free(cases[c].kept);
    }
    return rc;
}

int study_invariants(const study_opts *o)
{
    isk_system *s = malloc(sizeof *s);
    kepler_table *K = malloc(sizeof *K);
    int rc = 0;
    if (!s || !K) {
        fprintf(stderr, "iskra bench: invariants: out of memory\n");
        rc = 1;
    } else {
        K->first = o->quick ? 3 : 0; /* quick: 512 .. 8192, where RK4's order turns from 5 to 4 */
        K->nstep = NSTEP - K->first;
        for (int m = 0; m < NKM && !rc; m++)
            for (int j = 0; j < K->nstep && !rc; j++) {
                isk_status st = kepler_run(s, &KEPLER_METHODS[m], STEPS_PER_PERIOD[K->first + j], KEPLER_PERIODS,
                                           &K->r[m][j]);
                if (st != ISK_OK) {
                    fprintf(stderr, "iskra bench: invariants: kepler, %s: %s\n",
                            isk_integrator_name(KEPLER_METHODS[m].method), isk_status_str(st));
                    rc = 1;
                }
            }
        if (!rc) {
            print_kepler(K);
            fflush(stdout);
            rc |= write_kepler(o, K);
        }
        rc |= study_euler(o, s);
    }
    free(s);
    free(K);
    return rc;
}
