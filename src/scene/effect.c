/* SPDX-License-Identifier: MIT */
/* The effect runtime's lifecycle: create (check, copy, build every group,
 * prewarm), reset, destroy, the workers, and the read-only views (see
 * effect_internal.h for what lives where; the frame loop is
 * effect_frame.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect_describe.h"
#include "effect_internal.h"
#include "sim/pool.h"
#include "sim/workers.h"
#include "sim/store_internal.h"

static void free_group(fx_group *g)
{
    isk_particles_free(&g->store);
    isk__rest_free(&g->rest);
    isk__fx_retain_clear(&g->retained);
    free(g->pick);
    free(g->defl);
    free(g->draw_list);
    isk__fx_free_ramps(g);
    isk__fx_looks_free(g);
    isk__fx_events_free(g);
}

/* Room for the group's picks (its segments grow as it compiles). */
static isk_status alloc_group(isk_effect *e, fx_group *g)
{
    isk_status s = isk_particles_init(&g->store, 0,
                                      (isk__fx_emitter_oscillates(g->def) ? ISK_PARTICLES_OSC : 0) | isk__fx_looks_columns(g->def) |
                                          isk__fx_ranges_columns(g->def));
    if (s != ISK_OK || (s = isk__fx_events_columns(g)) != ISK_OK)
        return s;
    g->pick_cap = e->pots_cap;
    g->pick = calloc(g->pick_cap ? g->pick_cap : 1, sizeof *g->pick);
    return g->pick ? ISK_OK : ISK_ERR_NOMEM;
}

/* The live potentials start as the definition's, ids 1, 2, ... in force
 * order (the thesis's counter). */
static void reset_potentials(isk_effect *e)
{
    const isk_effect_def *d = &e->def;
    e->npots = 0;
    for (int i = 0; i < d->nforces; i++)
        if (d->forces[i].kind == ISK_FORCE_POTENTIAL) {
            e->pots[e->npots] = d->forces[i].pot;
            isk_potential_set_law(&e->pots[e->npots], d->forces[i].law, d->forces[i].exponent);
            e->pots[e->npots].id = (int)e->npots + 1;
            e->pot_force[e->npots] = i;
            e->npots++;
        }
}

/* Everything that exists at time 0. */
static isk_status populate(isk_effect *e, fx_group *g)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    isk_status s = ISK_OK;
    switch (em->born.source) {
    case ISK_SOURCE_PARTICLE:
        s = isk_particles_add(p, em->born.position.x, em->born.position.y, em->launch.velocity.x, em->launch.velocity.y,
                              em->launch.mass, NULL);
        if (s == ISK_OK)
            isk__fx_adopt(e, g, 0);
        break;
    case ISK_SOURCE_LAYER: {
        if (em->born.count == 0)
            break; /* an empty layer (the thesis simulator's start): clicks fill it */
        size_t limit = em->born.limit ? em->born.limit : ISK_EXPLODE_THESIS_LIMIT;
        s = isk_explode_layer(p, &g->rng, em->born.rect[0], em->born.rect[1], em->born.rect[2], em->born.rect[3],
                              em->born.count, limit);
        for (size_t i = 0; s == ISK_OK && i < p->count; i++)
            p->m[i] = em->launch.mass;
        if (s == ISK_OK)
            isk__fx_adopt(e, g, 0);
        break;
    }
    case ISK_SOURCE_EXPLOSION:
        if (em->born.start <= 0 && !em->born.active) {
            g->fired = 1; /* stopped at its time: skipped (isk_emitter_born.active) */
        } else if (em->born.start <= 0) {
            s = isk__fx_fire_explosion(e, g, em->born.explosion, em->born.position.x, em->born.position.y, em->born.count,
                                  em->born.kick);
            g->fired = 1;
        }
        break;
    case ISK_SOURCE_STREAM:
        isk__fx_stream_reset(g, 0.0);
        break;
    default:
        break;
    }
    return s;
}

/* Builds all groups from the definition, compiled, nothing born yet, every
 * clock at 0; refused if a frame or the prewarm could cost more than the
 * work budget. */
static isk_status build_groups(isk_effect *e, isk_error *err)
{
    const isk_effect_def *d = &e->def;
    reset_potentials(e);
    e->last_frame_time = 0;
    for (int gi = 0; gi < e->ngroups; gi++) {
        fx_group *g = &e->groups[gi];
        free_group(g);
        memset(g, 0, sizeof *g);
        g->index = gi;
        g->def = &d->emitters[gi];
        g->keep_prev = isk__fx_probes_need_prev(d, gi);
        const isk_emitter_def *em = g->def;
        isk_status s = alloc_group(e, g);
        if (s != ISK_OK)
            return isk_error_set(err, s, "emitter '%s': %s", em->name, isk_status_str(s));
        isk__fx_seed_streams(g, d->seed);
        if ((s = isk__fx_bake_ramps(g, err)) != ISK_OK || (s = isk__fx_looks_prepare(e, g, err)) != ISK_OK)
            return s;
        if ((s = isk__fx_compile(e, g)) != ISK_OK)
            return isk_error_set(err, s, "emitter '%s': cannot compile: %s", em->name, isk_status_str(s));
    }
    /* compiled, nothing born yet: what a frame and the prewarm could cost */
    isk_status ws = isk__fx_work_fits(e, err);
    if (ws != ISK_OK)
        return ws;
    isk__fx_start_clocks(e, d->dt / d->speed_divisor);
    if (isk__fx_probes_reset(e) != ISK_OK)
        return isk_error_set(err, ISK_ERR_NOMEM, "probes: out of memory");
    return ISK_OK;
}

/* What exists at time 0, the prewarm, a click at the start: the state
 * right after create. */
static isk_status populate_all(isk_effect *e, isk_error *err)
{
    const isk_effect_def *d = &e->def;
    for (int gi = 0; gi < e->ngroups; gi++) {
        fx_group *g = &e->groups[gi];
        isk_status s = populate(e, g);
        if (s != ISK_OK)
            return isk_error_set(err, s, "emitter '%s': cannot create its particles: %s", g->def->name,
                                 isk_status_str(s));
    }
    isk_status s = isk__fx_prewarm(e);
    if (s != ISK_OK)
        return isk_error_set(err, s, "prewarm: %s", isk_status_str(s));
    if (d->click.at_start && d->click.after_frames == 0) {
        s = isk__fx_click(e, d->click.x, d->click.y);
        if (s != ISK_OK)
            return isk_error_set(err, s, "click: %s", isk_status_str(s));
    }
    return ISK_OK;
}

static isk_status build(isk_effect *e, isk_error *err)
{
    isk_status s = build_groups(e, err);
    return s != ISK_OK ? s : populate_all(e, err);
}

/* Draw order: by `order`, ties by definition order (insertion sort: stable). */
void isk__fx_sort_draw_order(isk_effect *e)
{
    const isk_effect_def *d = &e->def;
    for (int i = 0; i < e->ngroups; i++) {
        int j = i;
        while (j > 0 && d->emitters[e->draw_order[j - 1]].look.order > d->emitters[i].look.order) {
            e->draw_order[j] = e->draw_order[j - 1];
            j--;
        }
        e->draw_order[j] = i;
    }
}

isk_status isk__fx_create_bare(isk_effect **out, const isk_effect_def *def, isk_error *err)
{
    if (!out || !def)
        return isk_error_set(err, ISK_ERR_NULL, "effect: NULL argument");
    *out = NULL;
    isk_status s = isk__fx_check(def, err);
    if (s != ISK_OK)
        return s;
    isk_effect *e = calloc(1, sizeof *e);
    if (!e)
        return isk_error_set(err, ISK_ERR_NOMEM, "effect: out of memory");
    isk__workers_init(&e->workers);
    e->band_min_work = FX_BAND_MIN_WORK;
    e->update_min_work = FX_UPDATE_MIN_WORK;
    s = isk__fx_def_copy(&e->def, def);
    if (s != ISK_OK) {
        free(e);
        return isk_error_set(err, s, "effect: out of memory");
    }
    const isk_effect_def *d = &e->def;
    s = d->view_kind == ISK_VIEWDEF_CAMERA ? isk_view_camera(&e->view, d->width, d->height, d->zoom, d->tx, d->ty)
                                           : isk_view_window(&e->view, d->width, d->height, d->xmin, d->xmax,
                                                             d->ymin, d->ymax);
    if (s != ISK_OK) {
        isk_effect_destroy(e);
        return isk_error_set(err, s, "view: %s (window needs finite min < max; camera needs zoom > 0)",
                             isk_status_str(s));
    }
    e->ngroups = d->nemitters;
    e->pots_cap = (size_t)(d->nforces ? d->nforces : 1);
    e->groups = calloc((size_t)(d->nemitters ? d->nemitters : 1), sizeof *e->groups);
    e->draw_order = calloc((size_t)(d->nemitters ? d->nemitters : 1), sizeof *e->draw_order);
    e->pots = calloc(e->pots_cap, sizeof *e->pots);
    e->pot_force = calloc(e->pots_cap, sizeof *e->pot_force);
    if (!e->groups || !e->draw_order || !e->pots || !e->pot_force ||
        isk_sprite_cache_create(&e->sprites, 256) != ISK_OK || isk_sinlut_init(&e->sin_table, 4096) != ISK_OK) {
        isk_effect_destroy(e);
        return isk_error_set(err, ISK_ERR_NOMEM, "effect: out of memory");
    }
    isk__fx_sort_draw_order(e);
    if ((s = build_groups(e, err)) != ISK_OK) {
        isk_effect_destroy(e);
        return s;
    }
    *out = e;
    return ISK_OK;
}

isk_status isk__fx_take_state(isk_effect *e, isk_effect *bare)
{
    /* e keeps its workers (their threads know its address) and the tests'
     * knobs; everything else is bare's, and bare is left with e's old
     * state for the caller to destroy. */
    isk_effect old = *e;
    *e = *bare;
    e->workers = old.workers;
    e->no_rest = old.no_rest;
    e->update_min_work = old.update_min_work;
    e->band_min_work = old.band_min_work;
    e->no_retain = old.no_retain;
    e->split_always = old.split_always;
    e->edits = old.edits; /* a restore is not an edit: a timeline's caller sees no change */
    old.workers = bare->workers;
    *bare = old;
    /* the stage lists point into the definition, which moved with the
     * struct: compiled again, from e's */
    for (int gi = 0; gi < e->ngroups; gi++)
        e->groups[gi].def = &e->def.emitters[gi];
    return isk__fx_compile_all(e);
}

isk_status isk_effect_create(isk_effect **out, const isk_effect_def *def, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "effect: NULL argument");
    isk_effect *e;
    isk_status s = isk__fx_create_bare(&e, def, err);
    if (s != ISK_OK)
        return s;
    if ((s = isk_effect_set_threads(e, e->def.threads)) != ISK_OK) {
        isk_effect_destroy(e);
        return isk_error_set(err, s, "effect: cannot start its threads: %s", isk_status_str(s));
    }
    if ((s = populate_all(e, err)) != ISK_OK) {
        isk_effect_destroy(e);
        return s;
    }
    *out = e;
    return ISK_OK;
}

void isk_effect_destroy(isk_effect *e)
{
    if (!e)
        return;
    for (int i = 0; e->groups && i < e->ngroups; i++)
        free_group(&e->groups[i]);
    free(e->groups);
    free(e->draw_order);
    free(e->pots);
    free(e->pot_force);
    isk_sprite_cache_destroy(e->sprites);
    isk_texture_cache_destroy(e->textures);
    isk__fx_bins_free(&e->bins);
    isk__fx_probes_free(e);
    isk__workers_free(&e->workers);
    isk_effect_def_free(&e->def);
    free(e);
}

/* ISKRA_THREADS if the environment sets a valid number, else the cores. */
static int default_threads(void)
{
    const int n = isk_threads_from_text(getenv("ISKRA_THREADS"));
    return n > 0 ? n : isk__pool_online_cores();
}

int isk_effect_threads(const isk_effect *e)
{
    return e ? isk__workers_count(&e->workers) : 1;
}

isk_status isk_effect_set_threads(isk_effect *e, int threads)
{
    if (!e)
        return ISK_ERR_NULL;
    if (threads < 0 || threads > ISK_TASKS_MAX_WORKERS)
        return ISK_ERR_RANGE;
    int n = threads ? threads : default_threads();
    if (e->workers.pool && isk__workers_count(&e->workers) == n)
        return ISK_OK;
    return isk__workers_start(&e->workers, n);
}

isk_status isk_effect_set_tasks(isk_effect *e, const isk_tasks *tasks)
{
    if (!e)
        return ISK_ERR_NULL;
    if (!tasks)
        return isk__workers_start(&e->workers, default_threads());
    return isk__workers_use(&e->workers, tasks);
}

isk_status isk_effect_reset(isk_effect *e)
{
    if (!e)
        return ISK_ERR_NULL;
    return build(e, NULL);
}

/* ---- inspection ------------------------------------------------------------ */

/* The canvas and view, then each emitter's lists, then the drawings (so a
 * scene that only draws says what it draws), then the settings no list
 * shows (effect_describe.c). */
void isk_effect_describe(const isk_effect *e, FILE *out)
{
    if (!e || !out)
        return;
    const isk_effect_def *d = &e->def;
    fprintf(out, "scene: %dx%d canvas, ", d->width, d->height);
    if (d->view_kind == ISK_VIEWDEF_CAMERA)
        fprintf(out, "camera zoom %g pan (%g, %g)", d->zoom, d->tx, d->ty);
    else
        fprintf(out, "view x %g..%g, y %g..%g", d->xmin, d->xmax, d->ymin, d->ymax);
    fprintf(out, ", dt %g s, %d substep%s of %s%s\n", d->dt, d->substeps, d->substeps == 1 ? "" : "s",
            isk_integrator_name(d->integrator), d->clear ? "" : ", trails");
    for (int gi = 0; gi < e->ngroups; gi++)
        isk__fx_describe_group(e, &e->groups[gi], out);
    if (d->ndrawings)
        fprintf(out, "drawings (before the particles):\n");
    for (int i = 0; i < d->ndrawings; i++) {
        const isk_drawing_def *g = &d->drawings[i];
        fprintf(out, "  %-9s %s", isk_drawing_kind_names[g->kind], g->name);
        if (g->kind == ISK_DRAWING_POLYLINE || g->kind == ISK_DRAWING_POLYGON)
            fprintf(out, ", %d points%s%s", g->npoints, g->closed ? ", closed" : "", g->hairline ? ", hairline" : "");
        if (g->kind == ISK_DRAWING_TEXT)
            fprintf(out, ", \"%s\"", g->text);
        fprintf(out, ", %s, %s%s\n", isk_blend_names[g->blend], isk_units_names[g->pixels ? 1 : 0],
                g->pixels ? "" : " units");
    }
    isk__fx_probes_describe(e, out);
    isk__fx_describe_settings(d, out);
}

size_t isk_effect_particle_count(const isk_effect *e)
{
    size_t n = 0;
    for (int i = 0; e && i < e->ngroups; i++)
        n += e->groups[i].store.count;
    return n;
}

double isk_effect_time(const isk_effect *e) { return e ? e->time : 0.0; }
long isk_effect_frame(const isk_effect *e) { return e ? e->frame : 0; }
const isk_view *isk_effect_view(const isk_effect *e) { return e ? &e->view : NULL; }
const isk_effect_def *isk_effect_definition(const isk_effect *e) { return e ? &e->def : NULL; }
int isk_effect_emitter_count(const isk_effect *e) { return e ? e->ngroups : 0; }

const isk_particles *isk_effect_particles(const isk_effect *e, int emitter)
{
    return e && emitter >= 0 && emitter < e->ngroups ? &e->groups[emitter].store : NULL;
}

const isk_forces *isk_effect_forces(const isk_effect *e, int emitter)
{
    return e && emitter >= 0 && emitter < e->ngroups ? &e->groups[emitter].forces : NULL;
}

uint64_t isk_effect_dropped(const isk_effect *e, int emitter)
{
    return e && emitter >= 0 && emitter < e->ngroups ? e->groups[emitter].dropped : 0;
}

size_t isk_effect_removed_nonfinite(const isk_effect *e, int emitter)
{
    return e && emitter >= 0 && emitter < e->ngroups ? e->groups[emitter].removed_nonfinite : 0;
}
