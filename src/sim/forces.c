/* SPDX-License-Identifier: MIT */
/* Force stages: gravity, linear drag, Coulomb potentials (thesis semantics). */
#include "iskra/forces.h"

#include <math.h>
#include <string.h>

#include "core/cpu.h" /* ISK__CPU_AVX2, isk__have_avx2 */
#include "sim/forces_loops.h"
#include "sim/kernels.h"
#include "sim/motion_fused.h" /* isk__forces_potentials_on */

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
    if (!m || !fy)
        return;
    for (size_t i = 0; i < n; i++)
        fy[i] = fy[i] + isk_k_gravity_fy(m[i], g);
}

void isk_force_drag(size_t n, const double *restrict vx, const double *restrict vy, double b,
                    double *restrict fx, double *restrict fy)
{
    if (!vx || !vy || !fx || !fy)
        return;
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
    if (!pot || !pot->enabled || n == 0 || !x || !y || !px || !py)
        return; /* nothing to act on (NULL arrays: the caller's contract broken; do nothing) */
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
    if (!m || !fx || !fy)
        return;
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

int isk__forces_potentials_on(const isk_forces *f)
{
    const size_t np = f->pick ? f->npick : f->npot;
    int any = 0;
    for (size_t k = 0; k < np; k++)
        any |= f->pot[f->pick ? f->pick[k] : k].enabled;
    return any;
}

/* ---- the laws, as rows ------------------------------------------------------
 * Each row: the laws it stands for, which of them act in f, and how it adds
 * its force into (fx, fy).  isk_forces_eval_step runs the rows in this
 * order, and that order is the sum's (the thesis's: gravity, then the
 * constant acceleration, drag, then the potentials summed on their own
 * and added last); isk_forces_laws is the union of what acts. */
typedef struct law_args {
    isk_forces *f;
    size_t n;
    const double *x, *y, *m;
    double *vx, *vy, *fx, *fy, *px, *py;
    double h;
} law_args;

typedef struct law_row {
    unsigned laws;                          /* the ISK_LAW_* bits this row evaluates */
    const char *names[4];                   /* their names, bit by bit */
    unsigned (*acts)(const isk_forces *f); /* which of them act in f */
    int (*runs)(const isk_forces *f);      /* whether add runs; NULL: when something acts */
    int drag;                               /* left out when the integrator takes the drag itself */
    void (*add)(const law_args *a);
} law_row;

static unsigned gravity_acts(const isk_forces *f) { return f->gravity != 0.0 ? ISK_LAW_GRAVITY : 0u; }
static void gravity_add(const law_args *a) { isk_force_gravity(a->n, a->m, a->f->gravity, a->fy); }

static unsigned accel_acts(const isk_forces *f) { return f->ax != 0.0 || f->ay != 0.0 ? ISK_LAW_ACCEL : 0u; }
static void accel_add(const law_args *a) { isk_force_accel(a->n, a->m, a->f->ax, a->f->ay, a->fx, a->fy); }

static unsigned drag_acts(const isk_forces *f) { return f->drag != 0.0 ? ISK_LAW_DRAG : 0u; }
static void drag_add(const law_args *a) { drag_stage(a->n, a->vx, a->vy, a->m, a->f->drag, a->h, a->fx, a->fy); }

/* What one enabled potential is, by the laws (k*charge == 0: nothing). */
static unsigned potential_law(const isk_potential *pot)
{
    if (!pot->enabled || 1.0 * (pot->charge * pot->k) == 0.0)
        return 0u;
    const unsigned power = pot->P == 2.0 ? ISK_LAW_POWER_2 : pot->P == 1.0 ? ISK_LAW_POWER_1 : ISK_LAW_POWER;
    return power | (pot->max_dist > 0.0 ? ISK_LAW_CUTOFF : 0u);
}

static unsigned potentials_acts(const isk_forces *f)
{
    const size_t np = f->pick ? f->npick : f->npot;
    unsigned laws = 0;
    for (size_t k = 0; k < np; k++)
        laws |= potential_law(&f->pot[f->pick ? f->pick[k] : k]);
    return laws;
}

/* Every enabled potential in list order into (px, py) from +0, then added:
 * a potential of zero strength adds +0 there, as here (it is run, not
 * skipped, whenever one potential is on: the bits of the sum). */
static void potentials_add(const law_args *a)
{
    isk_forces *f = a->f;
    const size_t np = f->pick ? f->npick : f->npot;
    memset(a->px, 0, a->n * sizeof *a->px);
    memset(a->py, 0, a->n * sizeof *a->py);
    for (size_t k = 0; k < np; k++)
        isk_force_potential(&f->pot[f->pick ? f->pick[k] : k], a->n, a->x, a->y, a->px, a->py, f->centre);
    add_into(a->n, a->fx, a->fy, a->px, a->py);
}

static const law_row law_rows[] = {
    {ISK_LAW_GRAVITY, {"gravity"}, gravity_acts, NULL, 0, gravity_add},
    {ISK_LAW_ACCEL, {"acceleration"}, accel_acts, NULL, 0, accel_add},
    {ISK_LAW_DRAG, {"drag"}, drag_acts, NULL, 1, drag_add},
    /* run whenever a potential is on, even of zero strength: its +0 turns
     * a -0 sum into +0, and the bits are the thesis's */
    {ISK_LAW_POWER_2 | ISK_LAW_POWER_1 | ISK_LAW_POWER | ISK_LAW_CUTOFF,
     {"power 2", "power 1", "power P", "cutoff"},
     potentials_acts,
     isk__forces_potentials_on,
     0,
     potentials_add},
};

unsigned isk_forces_laws(const isk_forces *f)
{
    unsigned laws = 0;
    for (size_t r = 0; f && r < sizeof law_rows / sizeof law_rows[0]; r++)
        laws |= law_rows[r].acts(f);
    return laws;
}

const char *isk_force_law_name(unsigned law)
{
    for (size_t r = 0; r < sizeof law_rows / sizeof law_rows[0]; r++) {
        int k = 0;
        for (unsigned bit = 1; bit; bit <<= 1)
            if (law_rows[r].laws & bit) {
                if (bit == law)
                    return law_rows[r].names[k];
                k++;
            }
    }
    return NULL;
}

void isk_forces_eval_step(isk_forces *f, size_t n, const double *x, const double *y, double *vx, double *vy,
                          const double *m, double *fx, double *fy, double *px, double *py, int with_drag, double h)
{
    if (!f || n == 0 || !x || !y || !vx || !vy || !m || !fx || !fy)
        return; /* px, py may be NULL without potentials (isk_force_potential checks) */
    memset(fx, 0, n * sizeof *fx); /* all-bits-zero is +0.0 */
    memset(fy, 0, n * sizeof *fy);
    const law_args a = {f, n, x, y, m, vx, vy, fx, fy, px, py, h};
    for (size_t r = 0; r < sizeof law_rows / sizeof law_rows[0]; r++) {
        const law_row *row = &law_rows[r];
        if (row->drag && !with_drag)
            continue; /* the exact drag integrator takes the drag itself */
        if (row->runs ? row->runs(f) : row->acts(f) != 0u)
            row->add(&a);
    }
}

void isk_forces_eval(isk_forces *f, size_t n, const double *x, const double *y, double *vx, double *vy,
                     const double *m, double *fx, double *fy, double *px, double *py, int with_drag)
{
    isk_forces_eval_step(f, n, x, y, vx, vy, m, fx, fy, px, py, with_drag, 0.0);
}

/* ---- potential energy (isk_forces_potential_energy) ---------------------------
 * Kept apart from the force stages above: it reads f, never the kernels'
 * fast paths, and runs once per chart sample, not per step.  Each row
 * gives the energy of the laws it stands for, in the order the forces are
 * summed; a law with no row makes the function refuse (a new force law
 * must bring its energy, or say it has none as drag does). */

/* U of one potential's law at distance d from it, outside its min distance
 * (the zero where the law has a natural one: far away for P > 2, at the
 * centre for P < 2). */
static double power_energy(double kq, double P, double d)
{
    if (P == 2.0)
        return kq * log(d);
    if (P == 1.0)
        return kq * d;
    return kq * (pow(d, 2.0 - P) / (2.0 - P));
}

static double one_potential_energy(const isk_potential *pot, double x, double y)
{
    const double kq = 1.0 * (pot->charge * pot->k), P = pot->P, mn = pot->min_dist;
    const double d = isk_k_coulomb_dist(pot->r.x, pot->r.y, x, y);
    if (mn > d) { /* the force's own test: inside, F = kQ n / min^P */
        const double mnP = P == 2.0 ? mn * mn : P == 1.0 ? mn : pow(mn, P);
        return kq * ((d * d - mn * mn) / (2.0 * mnP)) + power_energy(kq, P, mn);
    }
    return power_energy(kq, P, d);
}

static double gravity_energy(const isk_forces *f, double m, double x, double y)
{
    (void)x;
    return (m * f->gravity) * y;
}

/* Written so that a weight w and a gravity g = -w give the same bits:
 * (m*0)*x adds a zero, and -((m*ay)*y) is (m*g)*y exactly. */
static double accel_energy(const isk_forces *f, double m, double x, double y)
{
    return -((m * f->ax) * x + (m * f->ay) * y);
}

static double potentials_energy(const isk_forces *f, double m, double x, double y)
{
    (void)m; /* the potentials' force does not scale with the mass */
    const size_t np = f->pick ? f->npick : f->npot;
    double u = 0.0;
    for (size_t k = 0; k < np; k++) {
        const isk_potential *pot = &f->pot[f->pick ? f->pick[k] : k];
        if (potential_law(pot))
            u = u + one_potential_energy(pot, x, y);
    }
    return u;
}

typedef struct energy_row {
    unsigned laws;                                                    /* the ISK_LAW_* bits of the row */
    double (*energy)(const isk_forces *f, double m, double x, double y); /* NULL: no potential energy */
} energy_row;

static const energy_row energy_rows[] = {
    {ISK_LAW_GRAVITY, gravity_energy},
    {ISK_LAW_ACCEL, accel_energy},
    {ISK_LAW_DRAG, NULL}, /* F = -b v: no potential */
    {ISK_LAW_POWER_2 | ISK_LAW_POWER_1 | ISK_LAW_POWER | ISK_LAW_CUTOFF, potentials_energy},
};

isk_status isk_forces_potential_energy(const isk_forces *f, size_t n, const double *x, const double *y,
                                       const double *m, double *energy)
{
    if (!f || !energy || (n > 0 && (!x || !y || !m)) || ((f->pick ? f->npick : f->npot) > 0 && !f->pot))
        return ISK_ERR_NULL;
    const unsigned laws = isk_forces_laws(f);
    unsigned known = 0;
    for (size_t r = 0; r < sizeof energy_rows / sizeof energy_rows[0]; r++)
        known |= energy_rows[r].laws;
    if (laws & ~known)
        return ISK_ERR_UNSUPPORTED;
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        double u = 0.0;
        for (size_t r = 0; r < sizeof energy_rows / sizeof energy_rows[0]; r++)
            if (energy_rows[r].energy && (laws & energy_rows[r].laws))
                u = u + energy_rows[r].energy(f, m[i], x[i], y[i]);
        sum = sum + u;
    }
    *energy = sum;
    return ISK_OK;
}
