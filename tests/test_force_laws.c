/* SPDX-License-Identifier: MIT */
/* The force laws as a set (iskra/forces.h's isk_forces_laws): every law
 * the library evaluates has a bit and a name, and the fused motion pass
 * (src/sim/motion_fused.h) runs only when every law that acts is one it
 * knows.  For every law there is a case here that makes it act: a law the
 * pass does not know is declined and stepped by the general path, the
 * reference's bytes; one it knows gives the same bytes.  A law added to
 * the library without a case here fails the first test, so the second
 * always covers every law. */
#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

#include "iskra/forces.h"
#include "iskra/integrate.h"
#include "sim/kernels.h"
#include "sim/motion_fused.h"
#include "sim/stage.h"

enum { N = 3 * ISK_SIM_BLOCK / 2 };

typedef struct law_case {
    unsigned law;
    void (*make)(isk_forces *f, isk_potential *pot);
} law_case;

static void gravity(isk_forces *f, isk_potential *pot) { (void)pot, f->gravity = 9.81; }
static void accel(isk_forces *f, isk_potential *pot) { (void)pot, f->ax = 0.5, f->ay = -2.0; }
static void drag(isk_forces *f, isk_potential *pot) { (void)pot, f->drag = 0.3; }
static void one_potential(isk_forces *f, isk_potential *pot, double P, double max_dist)
{
    isk_potential_init(pot, 2.0, isk_vec2_make(0.3, -0.2), 1.5);
    pot->P = P;
    pot->max_dist = max_dist;
    f->pot = pot;
    f->npot = 1;
}
static void power_2(isk_forces *f, isk_potential *pot) { one_potential(f, pot, 2.0, ISK_DIST_OFF); }
static void power_1(isk_forces *f, isk_potential *pot) { one_potential(f, pot, 1.0, ISK_DIST_OFF); }
static void power_p(isk_forces *f, isk_potential *pot) { one_potential(f, pot, 2.5, ISK_DIST_OFF); }
static void cutoff(isk_forces *f, isk_potential *pot) { one_potential(f, pot, 2.0, 0.05); }

static const law_case cases[] = {
    {ISK_LAW_GRAVITY, gravity}, {ISK_LAW_ACCEL, accel},     {ISK_LAW_DRAG, drag},     {ISK_LAW_POWER_2, power_2},
    {ISK_LAW_POWER_1, power_1}, {ISK_LAW_POWER, power_p}, {ISK_LAW_CUTOFF, cutoff},
};

static const law_case *case_of(unsigned law)
{
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++)
        if (cases[k].law == law)
            return &cases[k];
    return NULL;
}

Test(force_laws, every_law_has_a_name_and_a_case_here)
{
    int laws = 0;
    for (unsigned bit = 1; bit; bit <<= 1) {
        const char *name = isk_force_law_name(bit);
        if (!name)
            continue;
        laws++;
        cr_expect_not_null(case_of(bit), "the law '%s' has no case in this test: add one", name);
    }
    cr_expect_eq(laws, 7);
    cr_expect_null(isk_force_law_name(ISK_LAW_GRAVITY | ISK_LAW_DRAG));
    cr_expect_null(isk_force_law_name(0));
    cr_expect_str_eq(isk_force_law_name(ISK_LAW_POWER_2), "power 2");
    cr_expect_str_eq(isk_force_law_name(ISK_LAW_CUTOFF), "cutoff");
}

Test(force_laws, the_set_is_what_acts)
{
    isk_forces f = {0};
    isk_potential pot;
    cr_expect_eq(isk_forces_laws(&f), 0u);
    cr_expect_eq(isk_forces_laws(NULL), 0u);
    gravity(&f, &pot);
    drag(&f, &pot);
    cr_expect_eq(isk_forces_laws(&f), ISK_LAW_GRAVITY | ISK_LAW_DRAG);
    cutoff(&f, &pot);
    cr_expect_eq(isk_forces_laws(&f), ISK_LAW_GRAVITY | ISK_LAW_DRAG | ISK_LAW_POWER_2 | ISK_LAW_CUTOFF);
    pot.enabled = 0;
    cr_expect_eq(isk_forces_laws(&f), ISK_LAW_GRAVITY | ISK_LAW_DRAG, "a potential switched off is no law");
    pot.enabled = 1;
    pot.charge = 0.0;
    cr_expect_eq(isk_forces_laws(&f), ISK_LAW_GRAVITY | ISK_LAW_DRAG, "nor one of zero strength");
}

/* A block of particles spread around the potential's centre. */
static void fill(double *x, double *y, double *vx, double *vy, double *m)
{
    for (int i = 0; i < N; i++) {
        x[i] = -1.0 + 2.0 * i / N;
        y[i] = 0.7 * sin(0.37 * i);
        vx[i] = 0.2 * cos(0.11 * i);
        vy[i] = -0.4 + 0.01 * i;
        m[i] = 1.0 + 0.5 * (i % 7);
    }
}

/* Each law alone and with gravity and drag: the motion stage (which tries
 * the fused pass first) against the general path, byte for byte; the fused
 * pass declines exactly the laws it does not know. */
Test(force_laws, a_law_the_fused_pass_does_not_know_gives_the_reference_bytes)
{
    static const isk_integrator methods[] = {ISK_INTEGRATE_SEMI_EULER, ISK_INTEGRATE_EULER};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (int with_others = 0; with_others < 2; with_others++)
            for (int k = 0; k < 2; k++) {
                isk_forces f = {0};
                isk_potential pot;
                cases[c].make(&f, &pot);
                if (with_others) {
                    gravity(&f, &pot);
                    drag(&f, &pot);
                }
                const unsigned laws = isk_forces_laws(&f);
                cr_assert(laws & cases[c].law, "the case does not make its law act");
                static double x[N], y[N], vx[N], vy[N], m[N], rx[N], ry[N], rvx[N], rvy[N], rm[N];
                fill(x, y, vx, vy, m);
                fill(rx, ry, rvx, rvy, rm);
                isk_potential ref_pot = pot;
                isk_forces ref = f;
                if (ref.pot)
                    ref.pot = &ref_pot;
                static isk_scratch s;
                const double h = 1.0 / 60.0;
                for (size_t o = 0; o < N; o += ISK_SIM_BLOCK) { /* the general path, as the runner calls it */
                    const size_t n = N - o < ISK_SIM_BLOCK ? N - o : ISK_SIM_BLOCK;
                    isk_integrate_block(methods[k], &ref, &s, n, rx + o, ry + o, rvx + o, rvy + o, rm + o, h);
                }
                isk_particles p = {0};
                p.x = x, p.y = y, p.vx = vx, p.vy = vy, p.m = m, p.count = N;
                isk_pipeline pl;
                isk__pipeline_init(&pl);
                isk_stage *st = isk__pipeline_add(&pl, &isk__stage_motion);
                st->u.motion.method = methods[k];
                st->u.motion.forces = &f;
                isk__pipeline_run(&pl, &p, 0, N, h, &s, NULL);
                const size_t b = N * sizeof(double);
                cr_expect(!memcmp(x, rx, b) && !memcmp(y, ry, b) && !memcmp(vx, rvx, b) && !memcmp(vy, rvy, b),
                          "law '%s'%s, %s: not the general path's bytes", isk_force_law_name(cases[c].law),
                          with_others ? " with gravity and drag" : "", isk_integrator_name(methods[k]));
                /* and the pass's own decision */
                fill(x, y, vx, vy, m);
                isk_forces again = {0}; /* afresh: the run may have switched the potential off */
                isk_potential again_pot;
                cases[c].make(&again, &again_pot);
                if (with_others) {
                    gravity(&again, &again_pot);
                    drag(&again, &again_pot);
                }
                int nonfinite = 0;
                const int fused = isk__motion_fused(methods[k], &again, isk_forces_laws(&again), ISK_SIM_BLOCK, x, y, vx, vy, m, h, NULL,
                                                   &nonfinite);
                cr_expect_eq(fused, (laws & ~ISK__FUSED_LAWS) == 0, "law '%s': the fused pass %s it",
                             isk_force_law_name(cases[c].law), fused ? "ran" : "declined");
            }
}
