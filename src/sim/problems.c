/* SPDX-License-Identifier: MIT */
/* Reference problems with closed forms (see iskra/problems.h). */
#include "iskra/problems.h"

#include <math.h>

static const double PI = 3.141592653589793;
static const double TWO_PI = 6.283185307179586;
static const double INV_GOLDEN = 0.6180339887498949; /* 1/phi */

/* (2 pi)^2: the oscillator's and the ellipse's kq, one period a second. */
#define FOUR_PI_SQ (6.283185307179586 * 6.283185307179586)

/* Each problem's name and defaults, by kind (count and mass are every
 * problem's: isk_problem_defaults adds them). */
static const struct {
    const char *name;
    isk_problem p;
} PROBLEMS[ISK_PROBLEM_COUNT] = {
    [ISK_PROBLEM_PROJECTILE] = {"projectile", {.T = 2.0, .gravity = 9.81, .drag = 0.8, .start_min = 5.0,
                                                .start_max = 15.0}},
    [ISK_PROBLEM_OSCILLATOR] = {"oscillator", {.T = 10.25, .kq = FOUR_PI_SQ, .start_min = 0.5, .start_max = 2.0}},
    [ISK_PROBLEM_RADIAL] = {"radial", {.T = 5.0, .kq = 4.0, .min_dist = 0.1, .start_min = 0.5, .start_max = 2.0}},
    [ISK_PROBLEM_BOUNCE] = {"bounce", {.T = 10.0, .gravity = 9.81, .restitution = 1.0, .start_min = 1.0,
                                        .start_max = 4.0}},
    [ISK_PROBLEM_KEPLER] = {"kepler", {.T = 10.25, .kq = FOUR_PI_SQ, .eccentricity = 0.6, .start_min = 0.8,
                                        .start_max = 1.25}},
};

isk_problem isk_problem_defaults(isk_problem_kind kind)
{
    if ((unsigned)kind >= ISK_PROBLEM_COUNT) {
        isk_problem none = {0};
        none.kind = kind;
        none.mass = 1.0;
        return none; /* count 0 */
    }
    isk_problem p = PROBLEMS[kind].p;
    p.kind = kind;
    p.count = 1024;
    p.mass = 1.0;
    return p;
}

const char *isk_problem_name(isk_problem_kind kind)
{
    return (unsigned)kind < ISK_PROBLEM_COUNT ? PROBLEMS[kind].name : "?";
}

/* ISK_OK, ISK_ERR_NAN or ISK_ERR_RANGE for a value that must be > 0. */
static isk_status positive(double v)
{
    if (!isfinite(v))
        return ISK_ERR_NAN;
    return v > 0.0 ? ISK_OK : ISK_ERR_RANGE;
}

/* The first failing status of a list, in order (NaN before range, so a NaN
 * anywhere reads as a NaN). */
static isk_status first_error(const isk_status *st, int n)
{
    for (int i = 0; i < n; i++)
        if (st[i] == ISK_ERR_NAN)
            return ISK_ERR_NAN;
    for (int i = 0; i < n; i++)
        if (st[i] != ISK_OK)
            return st[i];
    return ISK_OK;
}

isk_status isk_problem_validate(const isk_problem *p)
{
    if (!p)
        return ISK_ERR_NULL;
    if ((unsigned)p->kind >= ISK_PROBLEM_COUNT)
        return ISK_ERR_RANGE;
    if (p->count == 0 || p->count > ISK_PARTICLES_MAX)
        return ISK_ERR_SIZE;
    isk_status st[8];
    int n = 0;
    st[n++] = positive(p->T);
    st[n++] = positive(p->mass);
    st[n++] = positive(p->start_min);
    st[n++] = !isfinite(p->start_max) ? ISK_ERR_NAN
              : (p->start_max >= p->start_min ? ISK_OK : ISK_ERR_RANGE);
    if (p->kind == ISK_PROBLEM_PROJECTILE) {
        st[n++] = isfinite(p->gravity) ? ISK_OK : ISK_ERR_NAN;
        st[n++] = !isfinite(p->drag) ? ISK_ERR_NAN : (p->drag >= 0.0 ? ISK_OK : ISK_ERR_RANGE);
    } else if (p->kind == ISK_PROBLEM_BOUNCE) {
        st[n++] = positive(p->gravity);
        st[n++] = !isfinite(p->restitution) ? ISK_ERR_NAN
                  : (p->restitution >= 0.0 && p->restitution <= 1.0 ? ISK_OK : ISK_ERR_RANGE);
    } else {
        st[n++] = positive(p->kq);
        if (p->kind == ISK_PROBLEM_RADIAL)
            st[n++] = positive(p->min_dist);
        if (p->kind == ISK_PROBLEM_KEPLER)
            st[n++] = !isfinite(p->eccentricity) ? ISK_ERR_NAN
                      : (p->eccentricity >= 0.0 && p->eccentricity < 1.0 ? ISK_OK : ISK_ERR_RANGE);
    }
    return first_error(st, n);
}

/* The two spreads of particle i (see the header): u even in (0, 1), w the
 * golden-ratio sequence, so sizes and angles do not line up. */
static void spreads(const isk_problem *p, size_t i, double *u, double *w)
{
    *u = ((double)i + 0.5) / (double)p->count;
    double g = 0.5 + (double)i * INV_GOLDEN;
    *w = g - floor(g);
}

static double omega(const isk_problem *p) { return sqrt(p->kq / p->mass); }

/* The Kepler ellipse of particle i at time t (see the header). */
static void kepler_at(const isk_problem *p, size_t i, double t, isk_problem_state *out)
{
    double u, w;
    spreads(p, i, &u, &w);
    const double a = p->start_min + (p->start_max - p->start_min) * w, e = p->eccentricity;
    const double mu = p->kq / p->mass, n = sqrt(mu / (a * a * a)), b = a * sqrt(1.0 - e * e);
    double M = fmod(TWO_PI * w + n * t, TWO_PI);
    /* Newton on E - e sin E = M from E = M + e sin M (e < 1: it converges,
     * quadratically once close); stop when a step no longer changes E. */
    double E = M + e * sin(M);
    for (int it = 0; it < 60; it++) {
        double dE = (E - e * sin(E) - M) / (1.0 - e * cos(E));
        E -= dE;
        if (fabs(dE) <= 1e-16 * (1.0 + fabs(E)))
            break;
    }
    const double c = cos(E), s = sin(E), Ed = n / (1.0 - e * c);
    const double xo = a * (c - e), yo = b * s, vxo = -a * s * Ed, vyo = b * c * Ed;
    const double th = TWO_PI * u, ct = cos(th), st = sin(th);
    out->r = isk_vec2_make(ct * xo - st * yo, st * xo + ct * yo);
    out->v = isk_vec2_make(ct * vxo - st * vyo, st * vxo + ct * vyo);
}

/* The bouncing ball dropped from h0 at time t: its height, vertical speed
 * and how many bounces it has made (see the header). */
static void bounce_at(const isk_problem *p, double h0, double t, double *y, double *v, int *bounces)
{
    const double g = p->gravity, c = p->restitution, V0 = sqrt(2.0 * g * h0), tf = V0 / g;
    *bounces = 0;
    if (t <= tf) {
        *y = h0 - 0.5 * g * t * t;
        *v = -g * t;
        return;
    }
    double tau = t - tf, V = c * V0;
    int k = 1;
    if (c == 1.0) { /* periodic: the same hop every 2 V0/g */
        double per = 2.0 * V0 / g, hops = floor(tau / per);
        tau -= hops * per;
        k = 1 + (int)fmin(hops, 1e9);
    } else {
        while (V > 0.0 && tau >= 2.0 * V / g && k < 100000) {
            tau -= 2.0 * V / g;
            V *= c;
            k++;
        }
        if (!(V > 0.0) || k >= 100000) { /* the hops have ended: at rest on the floor */
            *y = 0.0;
            *v = 0.0;
            *bounces = k;
            return;
        }
    }
    *y = V * tau - 0.5 * g * tau * tau;
    *v = V - g * tau;
    *bounces = k;
}

static void initial(const isk_problem *p, size_t i, isk_problem_state *out)
{
    double u, w;
    spreads(p, i, &u, &w);
    double s = p->start_min + (p->start_max - p->start_min) * w;
    switch (p->kind) {
    case ISK_PROBLEM_PROJECTILE: {
        double th = 0.2 + 1.2 * u;
        out->r = isk_vec2_make(0.0, 0.0);
        out->v = isk_vec2_make(s * cos(th), s * sin(th));
        break;
    }
    case ISK_PROBLEM_OSCILLATOR: {
        double ph = TWO_PI * u, om = omega(p), c = cos(ph), sn = sin(ph);
        out->r = isk_vec2_make(s * c, 0.5 * s * sn);
        out->v = isk_vec2_make(-s * om * sn, 0.5 * s * om * c);
        break;
    }
    case ISK_PROBLEM_BOUNCE:
        out->r = isk_vec2_make(0.0, s);
        out->v = isk_vec2_make(0.0, 0.0);
        break;
    case ISK_PROBLEM_KEPLER:
        kepler_at(p, i, 0.0, out);
        break;
    default: { /* radial */
        double th = TWO_PI * u;
        out->r = isk_vec2_make(s * cos(th), s * sin(th));
        out->v = isk_vec2_make(0.0, 0.0);
        break;
    }
    }
}

isk_status isk_problem_initial(const isk_problem *p, size_t i, isk_problem_state *out)
{
    isk_status st = isk_problem_validate(p);
    if (st != ISK_OK)
        return st;
    if (!out)
        return ISK_ERR_NULL;
    if (i >= p->count)
        return ISK_ERR_RANGE;
    initial(p, i, out);
    return ISK_OK;
}

/* (h - 1 + e^-h)/h^2 for 0 <= h < 0.1 by its Taylor series
 * sum_{j>=0} (-h)^j/(j+2)!: the direct form loses every digit as h -> 0. */
static double phi2_series(double h)
{
    double term = 0.5, sum = 0.0;
    for (int j = 0; j < 12; j++) {
        sum += term;
        term *= -h / (double)(j + 3);
    }
    return sum;
}

static void exact_projectile(const isk_problem *p, const isk_problem_state *s0, double t,
                             isk_problem_state *out)
{
    double h = p->drag / p->mass * t;
    double em = expm1(-h); /* e^-h - 1 */
    double phi1 = h > 0.0 ? -em / h : 1.0;
    double phi2 = h < 0.1 ? phi2_series(h) : (h + em) / (h * h);
    double ay = -p->gravity;
    out->v = isk_vec2_make(s0->v.x * (1.0 + em), s0->v.y * (1.0 + em) + ay * t * phi1);
    out->r = isk_vec2_make(s0->r.x + s0->v.x * t * phi1,
                           s0->r.y + s0->v.y * t * phi1 + ay * t * t * phi2);
}

static void exact_oscillator(const isk_problem *p, const isk_problem_state *s0, double t,
                             isk_problem_state *out)
{
    double om = omega(p), c = cos(om * t), s = sin(om * t);
    out->r = isk_vec2_make(s0->r.x * c + s0->v.x / om * s, s0->r.y * c + s0->v.y / om * s);
    out->v = isk_vec2_make(s0->v.x * c - s0->r.x * om * s, s0->v.y * c - s0->r.y * om * s);
}

isk_status isk_problem_exact(const isk_problem *p, size_t i, double t, isk_problem_state *out)
{
    isk_status st = isk_problem_initial(p, i, out);
    if (st != ISK_OK)
        return st;
    if (!isfinite(t))
        return ISK_ERR_NAN;
    if (t < 0.0)
        return ISK_ERR_RANGE;
    isk_problem_state s0 = *out;
    int k;
    switch (p->kind) {
    case ISK_PROBLEM_PROJECTILE: exact_projectile(p, &s0, t, out); return ISK_OK;
    case ISK_PROBLEM_OSCILLATOR: exact_oscillator(p, &s0, t, out); return ISK_OK;
    case ISK_PROBLEM_BOUNCE: bounce_at(p, s0.r.y, t, &out->r.y, &out->v.y, &k); return ISK_OK;
    case ISK_PROBLEM_KEPLER: kepler_at(p, i, t, out); return ISK_OK;
    default: return ISK_ERR_UNSUPPORTED;
    }
}

static double energy(const isk_problem *p, const isk_problem_state *st)
{
    double kin = 0.5 * p->mass * (st->v.x * st->v.x + st->v.y * st->v.y);
    double d2 = st->r.x * st->r.x + st->r.y * st->r.y;
    if (p->kind == ISK_PROBLEM_OSCILLATOR)
        return kin + 0.5 * p->kq * d2;
    if (p->kind == ISK_PROBLEM_BOUNCE)
        return kin + p->mass * p->gravity * st->r.y;
    if (p->kind == ISK_PROBLEM_KEPLER)
        return kin - p->kq / sqrt(d2);
    double mn = p->min_dist, d = sqrt(d2);
    double U = d <= mn ? p->kq * d2 / (2.0 * mn * mn) : p->kq * (0.5 + log(d / mn));
    return kin + U;
}

isk_status isk_problem_energy(const isk_problem *p, const isk_problem_state *st, double *E)
{
    isk_status s = isk_problem_validate(p);
    if (s != ISK_OK)
        return s;
    if (!st || !E)
        return ISK_ERR_NULL;
    if (p->kind == ISK_PROBLEM_PROJECTILE)
        return ISK_ERR_UNSUPPORTED;
    *E = energy(p, st);
    return ISK_OK;
}

isk_status isk_problem_setup(const isk_problem *p, isk_system *s)
{
    isk_status st = isk_problem_validate(p);
    if (st != ISK_OK)
        return st;
    if (!s)
        return ISK_ERR_NULL;
    /* Everything that can fail first, so a failure leaves s untouched. */
    st = isk_particles_reserve(&s->particles, p->count);
    if (st != ISK_OK)
        return st;
    size_t npot = 0;
    if (p->kind != ISK_PROBLEM_PROJECTILE && p->kind != ISK_PROBLEM_BOUNCE) {
        isk_potential pot;
        isk_potential_init(&pot, p->kq, isk_vec2_make(0.0, 0.0), 1.0);
        pot.P = p->kind == ISK_PROBLEM_OSCILLATOR ? 0.0 : (p->kind == ISK_PROBLEM_KEPLER ? 3.0 : 2.0);
        pot.min_dist = p->kind == ISK_PROBLEM_RADIAL ? p->min_dist : ISK_DIST_OFF;
        st = isk_system_add_potential(s, &pot, NULL); /* appended: the old list is intact */
        if (st != ISK_OK)
            return st;
        s->forces.pot[0] = s->forces.pot[s->forces.npot - 1];
        npot = 1;
    }
    isk_forces f = {0};
    f.pot = s->forces.pot;
    f.npot = npot;
    f.centre = ISK_FIDELITY_SOUND;
    if (p->kind == ISK_PROBLEM_PROJECTILE || p->kind == ISK_PROBLEM_BOUNCE) {
        f.gravity = p->gravity;
        f.drag = p->kind == ISK_PROBLEM_PROJECTILE ? p->drag : 0.0;
    }
    s->forces = f;
    s->bounds.sides = 0;
    s->bounce_in_step = 0;
    if (p->kind == ISK_PROBLEM_BOUNCE) {
        /* the floor alone (the window's other sides are off) */
        isk_bounds floor;
        isk_bounds_reflect(&floor, -1.0, 1.0, 0.0, 2.0 * p->start_max, ISK_SIDE_BOTTOM, 0.0, p->restitution);
        s->bounds = floor;
        s->bounce_in_step = 1;
    }
    s->ageing = 0;
    s->njobs = 0;
    s->time = 0.0;
    isk_particles_clear(&s->particles);
    for (size_t i = 0; i < p->count; i++) {
        isk_problem_state s0;
        initial(p, i, &s0);
        /* Cannot fail: room is reserved and every value is finite. */
        isk_particles_add(&s->particles, s0.r.x, s0.r.y, s0.v.x, s0.v.y, p->mass, NULL);
    }
    return ISK_OK;
}

static int state_finite(const isk_problem_state *st)
{
    return isfinite(st->r.x) && isfinite(st->r.y) && isfinite(st->v.x) && isfinite(st->v.y);
}

/* Phase error of one coordinate: arg(z / z_exact) with z = c - i v/w. */
static double phase_error(double c, double v, double ce, double ve, double om)
{
    double a = c, b = -v / om, ae = ce, be = -ve / om;
    /* z * conj(z_exact) */
    double re = a * ae + b * be, im = b * ae - a * be;
    double ph = atan2(im, re);
    return ph == -PI ? PI : ph; /* (-pi, pi]: atan2 gives -pi only for im = -0 */
}

static double max_of(double acc, double v) { return v > acc ? v : acc; }

/* Particle i's conserved references without an exact solve: E0 (and for
 * the ellipse L0 = m sqrt(mu a (1 - e^2)), counterclockwise). */
static void references(const isk_problem *p, size_t i, double *E0, double *L0)
{
    double u, w;
    spreads(p, i, &u, &w);
    const double s = p->start_min + (p->start_max - p->start_min) * w;
    *L0 = 0.0;
    if (p->kind == ISK_PROBLEM_KEPLER) {
        *E0 = -p->kq / (2.0 * s);
        *L0 = p->mass * sqrt(p->kq / p->mass * s * (1.0 - p->eccentricity * p->eccentricity));
    } else if (p->kind == ISK_PROBLEM_BOUNCE) {
        *E0 = p->mass * p->gravity * s;
    } else {
        isk_problem_state s0;
        initial(p, i, &s0);
        *E0 = energy(p, &s0);
    }
}

isk_status isk_problem_track(const isk_problem *p, const isk_system *s, isk_problem_error *acc)
{
    isk_status st = isk_problem_validate(p);
    if (st != ISK_OK)
        return st;
    if (!s || !acc)
        return ISK_ERR_NULL;
    if (p->kind == ISK_PROBLEM_PROJECTILE)
        return ISK_ERR_UNSUPPORTED;
    if (s->particles.count != p->count)
        return ISK_ERR_SIZE;
    if (!isfinite(s->time))
        return ISK_ERR_NAN;
    const isk_particles *q = &s->particles;
    const int kepler = p->kind == ISK_PROBLEM_KEPLER;
    for (size_t i = 0; i < p->count; i++) {
        isk_problem_state now = {{q->x[i], q->y[i]}, {q->vx[i], q->vy[i]}};
        if (!state_finite(&now)) {
            acc->energy = acc->angular_momentum = acc->period = INFINITY;
            continue;
        }
        double E0, L0;
        references(p, i, &E0, &L0);
        double Ek = E0;
        if (p->kind == ISK_PROBLEM_BOUNCE && p->restitution != 1.0) {
            double y, v;
            int k;
            bounce_at(p, E0 / (p->mass * p->gravity), s->time, &y, &v, &k);
            Ek = E0 * pow(p->restitution, 2.0 * k);
        }
        double E = energy(p, &now);
        acc->energy = max_of(acc->energy, fabs(E - Ek) / fabs(E0));
        if (kepler) {
            double L = p->mass * (now.r.x * now.v.y - now.r.y * now.v.x);
            acc->angular_momentum = max_of(acc->angular_momentum, fabs(L - L0) / fabs(L0));
            acc->period = max_of(acc->period, E < 0.0 ? fabs(pow(E0 / E, 1.5) - 1.0) : INFINITY);
        }
    }
    return ISK_OK;
}

isk_status isk_problem_measure(const isk_problem *p, const isk_system *s, isk_problem_error *out)
{
    isk_status st = isk_problem_validate(p);
    if (st != ISK_OK)
        return st;
    if (!s || !out)
        return ISK_ERR_NULL;
    if (s->particles.count != p->count)
        return ISK_ERR_SIZE;
    const double t = s->time;
    if (!isfinite(t))
        return ISK_ERR_NAN;
    const int has_exact = p->kind != ISK_PROBLEM_RADIAL;
    const int has_energy = p->kind != ISK_PROBLEM_PROJECTILE;
    const int has_phase = p->kind == ISK_PROBLEM_OSCILLATOR;
    const int kepler = p->kind == ISK_PROBLEM_KEPLER;
    isk_problem_error e = {t, NAN, NAN, NAN, NAN, 0, NAN, NAN};
    if (has_exact)
        e.position = e.velocity = 0.0;
    if (has_energy)
        e.energy = 0.0;
    if (has_phase)
        e.phase = 0.0;
    if (kepler)
        e.angular_momentum = e.period = 0.0;
    const isk_particles *q = &s->particles;
    const double om = has_phase ? omega(p) : 1.0;
    for (size_t i = 0; i < p->count; i++) {
        isk_problem_state now = {{q->x[i], q->y[i]}, {q->vx[i], q->vy[i]}}, s0, ex;
        if (!state_finite(&now)) {
            e.nonfinite++;
            continue;
        }
        initial(p, i, &s0);
        int bounces = 0;
        if (has_exact) {
            ex = s0;
            if (p->kind == ISK_PROBLEM_PROJECTILE)
                exact_projectile(p, &s0, t, &ex);
            else if (p->kind == ISK_PROBLEM_OSCILLATOR)
                exact_oscillator(p, &s0, t, &ex);
            else if (p->kind == ISK_PROBLEM_BOUNCE)
                bounce_at(p, s0.r.y, t, &ex.r.y, &ex.v.y, &bounces);
            else
                kepler_at(p, i, t, &ex);
            e.position = max_of(e.position, hypot(now.r.x - ex.r.x, now.r.y - ex.r.y));
            e.velocity = max_of(e.velocity, hypot(now.v.x - ex.v.x, now.v.y - ex.v.y));
        }
        if (has_energy) {
            double E0 = energy(p, &s0), E = energy(p, &now);
            /* the bouncing ball's energy is c^2k of its start after k bounces */
            double Ek = p->kind == ISK_PROBLEM_BOUNCE ? E0 * pow(p->restitution, 2.0 * bounces) : E0;
            e.energy = max_of(e.energy, fabs(E - Ek) / fabs(E0));
            if (kepler) {
                double L0 = s0.r.x * s0.v.y - s0.r.y * s0.v.x, L = now.r.x * now.v.y - now.r.y * now.v.x;
                e.angular_momentum = max_of(e.angular_momentum, fabs(L - L0) / fabs(L0));
                e.period = max_of(e.period, E < 0.0 ? fabs(pow(E0 / E, 1.5) - 1.0) : INFINITY);
            }
        }
        if (has_phase) {
            double px = phase_error(now.r.x, now.v.x, ex.r.x, ex.v.x, om);
            double py = phase_error(now.r.y, now.v.y, ex.r.y, ex.v.y, om);
            e.phase = max_of(e.phase, fmax(fabs(px), fabs(py)));
        }
    }
    if (e.nonfinite > 0) {
        /* A diverged particle has no meaningful error: say infinite. */
        if (has_exact)
            e.position = e.velocity = INFINITY;
        if (has_energy)
            e.energy = INFINITY;
        if (has_phase)
            e.phase = INFINITY;
        if (kepler)
            e.angular_momentum = e.period = INFINITY;
    }
    *out = e;
    return ISK_OK;
}
