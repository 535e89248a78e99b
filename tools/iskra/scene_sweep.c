/* SPDX-License-Identifier: MIT */
/* Running one scene under other settings (see scene_sweep.h). */
#include "scene_sweep.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iskra/stability.h"
#include "scene_args.h"

int sweep_load(const char *cmd, const char *scene, int threads, isk_effect_def *def)
{
    char name[32];
    snprintf(name, sizeof name, "bench %s", cmd);
    scene_args a = {.cmd = name, .scene = scene, .threads = threads};
    isk_effect *fx = NULL;
    int rc = scene_args_open(&a, def, &fx);
    if (rc == 0)
        isk_effect_destroy(fx);
    return rc;
}

/* What a setting replaces, kept to be put back. */
typedef struct saved {
    isk_integrator method, own_method[ISK_EFFECT_MAX_EMITTERS];
    int substeps, own_substeps[ISK_EFFECT_MAX_EMITTERS];
    double dt;
} saved;

static void apply(isk_effect_def *def, const sweep_setting *s, saved *keep)
{
    keep->method = def->integrator;
    keep->substeps = def->substeps;
    keep->dt = def->dt;
    def->integrator = s->method;
    def->substeps = s->substeps;
    def->dt = s->dt;
    for (int i = 0; i < def->nemitters; i++) {
        keep->own_method[i] = def->emitters[i].motion.integrator;
        keep->own_substeps[i] = def->emitters[i].motion.substeps;
        def->emitters[i].motion.integrator = ISK_INTEGRATE_INHERIT;
        def->emitters[i].motion.substeps = 0;
    }
}

static void restore(isk_effect_def *def, const saved *keep)
{
    for (int i = 0; i < def->nemitters; i++) {
        def->emitters[i].motion.integrator = keep->own_method[i];
        def->emitters[i].motion.substeps = keep->own_substeps[i];
    }
    def->integrator = keep->method;
    def->substeps = keep->substeps;
    def->dt = keep->dt;
}

int sweep_create(const char *cmd, isk_effect_def *def, const sweep_setting *s, isk_effect **fx)
{
    saved keep;
    apply(def, s, &keep);
    isk_error err;
    isk_status st = isk_effect_create(fx, def, &err);
    restore(def, &keep);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench %s: %s, %d substeps, dt %g: %s\n", cmd, isk_integrator_name(s->method),
                s->substeps, s->dt, err.message);
        return 1;
    }
    return 0;
}

double sweep_ratio(isk_effect_def *def, const sweep_setting *s, double (*of_emitter)(const isk_effect_def *, int))
{
    saved keep;
    apply(def, s, &keep);
    double x = 0.0;
    for (int i = 0; i < def->nemitters; i++)
        x = fmax(x, of_emitter(def, i));
    restore(def, &keep);
    return x;
}

isk_integrator sweep_reference(const isk_effect_def *def, const char **why)
{
    const char *rough = NULL;
    if (def->bounds.sides != 0)
        rough = "walls";
    for (int i = 0; !rough && i < def->nemitters; i++)
        if (def->emitters[i].motion.ndeflectors > 0)
            rough = "deflectors";
    for (int i = 0; !rough && i < def->nforces; i++) {
        const isk_force_def *f = &def->forces[i];
        if (f->kind == ISK_FORCE_TURBULENCE && f->strength != 0)
            rough = "turbulence";
        else if (f->kind == ISK_FORCE_POTENTIAL && f->pot.max_dist > 0)
            rough = "potentials that switch off";
    }
    *why = rough ? rough : "smooth forces";
    return rough ? ISK_INTEGRATE_RK4 : ISK_INTEGRATE_YOSHIDA4;
}

size_t sweep_live(const isk_effect *fx)
{
    size_t n = 0;
    for (int e = 0; e < isk_effect_emitter_count(fx); e++)
        n += isk_effect_particles(fx, e)->count;
    return n;
}

double sweep_kinetic(const isk_effect *fx)
{
    double k = 0.0;
    for (int e = 0; e < isk_effect_emitter_count(fx); e++) {
        const isk_particles *p = isk_effect_particles(fx, e);
        for (size_t i = 0; i < p->count; i++)
            k += 0.5 * p->m[i] * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]);
    }
    return k;
}

size_t sweep_removed(const isk_effect *fx)
{
    size_t n = 0;
    for (int e = 0; e < isk_effect_emitter_count(fx); e++)
        n += isk_effect_removed_nonfinite(fx, e);
    return n;
}

void sweep_stem(const char *scene, char *out, size_t n)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    size_t len = strlen(base);
    if (len > 4 && !strcmp(base + len - 4, ".ini"))
        len -= 4;
    snprintf(out, n, "%.*s", (int)len, base);
}
