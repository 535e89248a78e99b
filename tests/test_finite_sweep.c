/* SPDX-License-Identifier: MIT */
/* No accepted input yields a non-finite state.  Every numeric key of the
 * key table (iskra/keys.h) is set, one at a time, to its extremes — its
 * min, its max, +-1e308 on a side its range leaves open — in a scene that
 * uses every force, source, wall and deflector, and the scene runs with
 * every integrator; whatever the table accepts must leave every particle's
 * state finite and nothing removed as non-finite.  Values the table refuses
 * are skipped (the table is what decides).  Drawings do not move particles
 * and are left out. */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <criterion/parameterized.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/scene.h"
#include "sanitized.h"

static const char *BASE =
    "[scene]\ndt = 1/60\nseed = 3\n"
    "[view]\nxmin = -10\nxmax = 10\nymin = -10\nymax = 10\n"
    "[force grav]\nkind = gravity\ng = 9.81\n"
    "[force drag]\nkind = drag\nb = 0.3\n"
    "[force wind]\nkind = wind\nacceleration = 0.5, 0\n"
    "[force pot]\nkind = potential\nk = 50\nposition = 1, 2\nmin_distance = 0.2\n"
    "[deflector seg]\nsegment = -8, -6, 8, -5\nrestitution = 0.7\n"
    "[bounds]\nmode = reflect\nwindow = -10, 10, -10, 10\nrestitution = 0.8\n"
    "[emitter one]\nsource = particle\nposition = 0, 5\nvelocity = 2, 1\nforces = grav, drag, wind, pot\n"
    "deflectors = seg\ndraw = none\n"
    "[emitter boom]\nsource = explosion\nexplosion = gauss\nposition = 2, 2\ncount = 40\n"
    "forces = grav, drag, pot\ndeflectors = seg\ndraw = none\n"
    "[emitter layer]\nsource = layer\nrect = -5, 5, -2, 2\ncount = 40\nforces = grav, wind, pot\n"
    "deflectors = seg\ndraw = none\n"
    "[emitter jet]\nsource = stream\nposition = -3, 0\nlaunch = cone\nangle = 60\nspread = 40\n"
    "speed_min = 1\nspeed_max = 3\nrate = 300\ncapacity = 150\ncount = 5\nburst_every = 0.1\nlife = 2\n"
    "life_range = 1\nosc_omega = -3, 3\nosc_amplitude = 0.1, 0.2\nosc_decay = 0.1\nslowing = 0.2\nweight = 1\n"
    "mass_range = 0.5\nforces = grav, drag, wind, pot\ndeflectors = seg\ndraw = none\n"
    "[emitter fire]\nsource = stream\nposition = 3, -3\nvelocity = 0, 2\nshape = disc\nshape_a = 0.5\nrate = 200\n"
    "capacity = 120\nlife = 1\nslowing = 0.5\nslow_faithful = true\nweight = 2\nforces = grav, wind\nintegrator = semi-euler\n"
    "draw = none\n"
    "[click]\nexplosion = coulomb\ncount = 30\nemitter = boom\nat_start = 0.5, 0.5\n";

/* The items of the base scene a row can be set on, with their kinds. */
typedef struct item {
    isk_section_kind section;
    const char *name; /* as isk_effect_set spells the section */
    int kind;         /* the section's kind (-1: none) */
} item;

static const item ITEMS[] = {
    {ISK_SECTION_SCENE, "scene", -1},
    {ISK_SECTION_VIEW, "view", ISK_VIEWDEF_WINDOW},
    {ISK_SECTION_FORCE, "force grav", ISK_FORCE_GRAVITY},
    {ISK_SECTION_FORCE, "force drag", ISK_FORCE_DRAG},
    {ISK_SECTION_FORCE, "force wind", ISK_FORCE_WIND},
    {ISK_SECTION_FORCE, "force pot", ISK_FORCE_POTENTIAL},
    {ISK_SECTION_DEFLECTOR, "deflector seg", -1},
    {ISK_SECTION_BOUNDS, "bounds", ISK_BOUNCE_REFLECT},
    {ISK_SECTION_EMITTER, "emitter one", ISK_SOURCE_PARTICLE},
    {ISK_SECTION_EMITTER, "emitter boom", ISK_SOURCE_EXPLOSION},
    {ISK_SECTION_EMITTER, "emitter layer", ISK_SOURCE_LAYER},
    {ISK_SECTION_EMITTER, "emitter jet", ISK_SOURCE_STREAM},
    {ISK_SECTION_EMITTER, "emitter fire", ISK_SOURCE_STREAM},
    {ISK_SECTION_CLICK, "click", -1},
};
enum { NITEMS = sizeof ITEMS / sizeof ITEMS[0], FRAMES = 30, MAXVALS = 8 };

static int applies(const isk_key *k, int kind)
{
    return kind < 0 || k->applies == 0 || (k->applies >> kind & 1u);
}

/* The extremes of one number of a row: bounds (just inside an exclusive
 * one), +-1e308 where open.  Counts stay small: their size is not what this
 * is about (and 4 million particles per value would make the test slow). */
static int extremes(const isk_key *k, double *v)
{
    int n = 0;
    if (k->lo_bound)
        v[n++] = k->lo_bound == ISK_BOUND_EXCL ? nextafter(k->min, INFINITY) : k->min;
    else
        v[n++] = -1e308;
    if (k->hi_bound)
        v[n++] = k->hi_bound == ISK_BOUND_EXCL ? nextafter(k->max, -INFINITY) : k->max;
    else
        v[n++] = 1e308;
    if (k->type == ISK_KEY_COUNT || k->type == ISK_KEY_WHOLE || k->type == ISK_KEY_LONG)
        for (int i = 0; i < n; i++) {
            double lim = k->type == ISK_KEY_COUNT ? 300 : 1000;
            v[i] = v[i] > lim ? lim : (v[i] < -lim ? -lim : v[i]);
        }
    return n;
}

/* The values to try for a row, in its own syntax; 0 when it is not a
 * number this sweep covers. */
static int values(const isk_key *k, char vals[MAXVALS][160])
{
    double v[2];
    int n = extremes(k, v), m = 0;
    switch (k->type) {
    case ISK_KEY_NUMBER:
    case ISK_KEY_ANGLE:
        for (int i = 0; i < n; i++)
            snprintf(vals[m++], 160, "%.17g", v[i]);
        break;
    case ISK_KEY_WHOLE:
    case ISK_KEY_LONG:
    case ISK_KEY_COUNT:
        for (int i = 0; i < n; i++)
            snprintf(vals[m++], 160, "%.0f", v[i]);
        break;
    case ISK_KEY_VECTOR:
    case ISK_KEY_POINT:
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                snprintf(vals[m++], 160, "%.17g, %.17g", v[i], v[j]);
        break;
    case ISK_KEY_PAIR:
        snprintf(vals[m++], 160, "%.17g, %.17g", v[0], v[0]);
        snprintf(vals[m++], 160, "%.17g, %.17g", v[1], v[1]);
        snprintf(vals[m++], 160, "%.17g, %.17g", v[0], v[1]);
        break;
    case ISK_KEY_NUMBERS4: /* a window, a rect or a segment: as wide as allowed, and collapsed at an edge */
        snprintf(vals[m++], 160, "%.17g, %.17g, %.17g, %.17g", v[0], v[1], v[0], v[1]);
        snprintf(vals[m++], 160, "%.17g, %.17g, %.17g, %.17g", v[1] * 0.5, v[1], v[1] * 0.5, v[1]);
        snprintf(vals[m++], 160, "%.17g, %.17g, %.17g, %.17g", v[0], v[0] * 0.5, v[0], v[0] * 0.5);
        break;
    default:
        break;
    }
    return m;
}

/* The sanitizer builds (-O1, every access instrumented: 80 s for the whole
 * matrix) run each value with one integrator, taken in turn, so every
 * integrator still meets every key; the plain build runs them all. */
#if TEST_SANITIZED
enum { INTEGRATOR_STRIDE = ISK_INTEGRATOR_COUNT };
#else
enum { INTEGRATOR_STRIDE = 1 };
#endif

static isk_effect *base(void)
{
    isk_effect_def d;
    isk_error err;
    isk_effect *fx = NULL;
    cr_assert_eq(isk_scene_load_string(&d, BASE, "sweep", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

/* Every particle of every emitter finite (life may be +inf: immortal). */
static int finite_state(const isk_effect *fx, char *why, size_t n)
{
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        for (size_t i = 0; i < p->count; i++)
            if (!isfinite(p->x[i]) || !isfinite(p->y[i]) || !isfinite(p->vx[i]) || !isfinite(p->vy[i]) ||
                !isfinite(p->m[i]) || !isfinite(p->age[i]) || isnan(p->life[i])) {
                snprintf(why, n, "emitter %d particle %zu: (%g, %g) v (%g, %g) m %g", g, i, p->x[i], p->y[i],
                         p->vx[i], p->vy[i], p->m[i]);
                return 0;
            }
        if (isk_effect_removed_nonfinite(fx, g) != 0) {
            snprintf(why, n, "emitter %d: %zu removed as non-finite", g, isk_effect_removed_nonfinite(fx, g));
            return 0;
        }
    }
    return 1;
}

/* One row at one value on every item it applies to, with one integrator:
 * 1 when accepted and run, 0 when the table refused it. */
static int run_case(const isk_key *k, const char *value, int method, long *failures)
{
    isk_effect *fx = base();
    isk_error err;
    cr_assert_eq(isk_effect_set(fx, "scene", "integrator", isk_integrator_names[method], &err), ISK_OK, "%s",
                 err.message);
    int accepted = 0;
    for (int i = 0; i < NITEMS; i++) {
        if (ITEMS[i].section != k->section || !applies(k, ITEMS[i].kind))
            continue;
        if (isk_effect_set(fx, ITEMS[i].name, k->name, value, &err) == ISK_OK)
            accepted = 1;
    }
    if (accepted && k->live == 0)
        cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    char why[300] = "";
    int ok = 1;
    for (int f = 0; accepted && ok && f < FRAMES; f++) {
        isk_status s = isk_effect_step(fx);
        if (s != ISK_OK) {
            snprintf(why, sizeof why, "step %d: %s", f, isk_status_str(s));
            ok = 0;
        } else
            ok = finite_state(fx, why, sizeof why);
    }
    if (!ok) {
        (*failures)++;
        cr_log_error("[%s] %s = %s, %s: %s", isk_section_name(k->section), k->name, value,
                     isk_integrator_names[method], why);
    }
    isk_effect_destroy(fx);
    return accepted;
}

/* The rows are shared out (row r to share r % SHARES) so Criterion runs
 * the shares on every core at once: the matrix is the suite's longest
 * test. */
enum { SHARES = 4 };

ParameterizedTestParameters(finite_sweep, every_numeric_key_at_its_extremes_with_every_integrator)
{
    static int share[SHARES];
    for (int i = 0; i < SHARES; i++)
        share[i] = i;
    return cr_make_param_array(int, share, SHARES);
}

ParameterizedTest(int *share, finite_sweep, every_numeric_key_at_its_extremes_with_every_integrator,
                  .timeout = 600)
{
    long failures = 0, runs = 0;
    int rows = 0;
    for (int r = 0; r < isk_key_count(); r++) {
        const isk_key *k = isk_key_at(r);
        if (k->section == ISK_SECTION_DRAWING || k->create_only)
            continue;
        char vals[MAXVALS][160];
        int nv = values(k, vals);
        rows += nv > 0;
        if (r % SHARES != *share)
            continue;
        for (int v = 0; v < nv; v++)
            for (int m = (r + v) % INTEGRATOR_STRIDE; m < ISK_INTEGRATOR_COUNT; m += INTEGRATOR_STRIDE)
                runs += run_case(k, vals[v], m, &failures);
    }
    cr_log_info("share %d: %d numeric rows in all, %ld accepted runs of %d frames", *share, rows, runs, FRAMES);
    cr_assert_gt(rows, 40);
    cr_assert_gt(runs, 10, "share %d ran almost nothing", *share);
    cr_assert_eq(failures, 0, "%ld accepted settings produced a non-finite state (see the log)", failures);
}

/* A view of +-1.7e308 is refused for its width, which
 * overflows, with the line of the key (it used to say "value out of range"
 * with no line). */
Test(finite_sweep, a_window_whose_width_overflows_names_its_line)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_neq(isk_scene_load_string(&d,
                                        "[scene]\ndt = 1/60\n[view]\nxmin = -1.7e308\nxmax = 1.7e308\n"
                                        "ymin = -1\nymax = 1\n[emitter e]\nsource = particle\n",
                                        "wide", &err),
                  ISK_OK);
    cr_assert(strstr(err.message, "wide:5:"), "%s", err.message);
    cr_assert(strstr(err.message, "too large"), "%s", err.message);
    cr_assert(strstr(err.message, "overflows"), "%s", err.message);
}
