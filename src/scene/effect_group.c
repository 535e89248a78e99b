/* SPDX-License-Identifier: MIT */
/* Births and deaths of a group's particles: the thesis's explosions (at
 * create, timed, scheduled or clicked), and the frame-level stages that
 * release and cull them.  Every source's new particles go through isk__fx_adopt
 * (effect_adopt.c), so lifetimes and oscillation state follow one rule.
 * Stream births are effect_stream.c's; what exists at time 0 is effect.c's
 * (populate). */
#include <math.h>

#include "effect_internal.h"
#include "sim/store_internal.h"

uint64_t isk__fx_group_seed(uint64_t seed, int index)
{
    /* Emitter 0 uses the scene seed itself, so a one-emitter scene draws the
     * same numbers as a C program seeding one isk_system with that seed. */
    return seed + (uint64_t)index * 0x9E3779B97F4A7C15ull;
}

/* Each attribute stream's constant: its seed is the group's seed xor this
 * (isk_rng_seed mixes it through splitmix64).  Fixed forever: changing one
 * changes every scene that uses the attribute. */
static const uint64_t stream_salt[FX_STREAM_COUNT] = {
    [FX_STREAM_MASS] = 0x6d617373u,     /* "mass" */
    [FX_STREAM_ROTATION] = 0x726f7461u, /* "rota" */
    [FX_STREAM_SPIN] = 0x7370696eu,     /* "spin" */
    [FX_STREAM_SIZE] = 0x73697a65u,     /* "size" */
    [FX_STREAM_COLOR] = 0x636f6c6fu,    /* "colo" */
    [FX_STREAM_CHANCE] = 0x6368616eu,   /* "chan" */
    [FX_STREAM_FRAME] = 0x6672616du,    /* "fram" */
    [FX_STREAM_RADIAL] = 0x72616469u,   /* "radi" */
    [FX_STREAM_TANGENTIAL] = 0x74616e67u, /* "tang" */
    [FX_STREAM_WIND] = 0x77696e64u,     /* "wind" */
    [FX_STREAM_SLOWING] = 0x736c6f77u,  /* "slow" */
};

void isk__fx_seed_streams(fx_group *g, uint64_t seed)
{
    const uint64_t s = isk__fx_group_seed(seed, g->index);
    isk_rng_seed(&g->rng, s);
    for (int k = 0; k < FX_STREAM_COUNT; k++)
        isk_rng_seed(&g->streams[k], s ^ stream_salt[k]);
}

isk_status isk__fx_fire_explosion(isk_effect *e, fx_group *g, isk_explosion kind, double cx, double cy, size_t count,
                             isk_kick_target kick)
{
    const isk_emitter_def *em = g->def;
    size_t limit = em->born.limit ? em->born.limit : ISK_EXPLODE_THESIS_LIMIT;
    isk_particles *p = &g->store;
    size_t before = p->count;
    if (count > limit)
        return ISK_ERR_RANGE; /* the explosion's own limit: refused, as the thesis does */
    /* The pool bounds every source: what does not fit is dropped and counted. */
    size_t room = p->count < em->born.capacity ? em->born.capacity - p->count : 0;
    if (count > room) {
        g->dropped += count - room;
        count = room;
    }
    if (count == 0)
        return ISK_OK;
    isk_status s;
    switch (kind) {
    case ISK_EXPLOSION_RING: s = isk_explode_ring(p, cx, cy, count, limit); break;
    case ISK_EXPLOSION_UNIFORM: s = isk_explode_uniform(p, &g->rng, cx, cy, count, limit); break;
    case ISK_EXPLOSION_GAUSS: s = isk_explode_gauss(p, &g->rng, cx, cy, count, limit); break;
    case ISK_EXPLOSION_COULOMB: s = isk_explode_coulomb(p, &g->rng, cx, cy, count, limit, kick); break;
    case ISK_EXPLOSION_MULTI_COULOMB:
        if (g->mc_active && !isk_multi_coulomb_done(&g->mc))
            return ISK_ERR_FULL;
        s = isk_multi_coulomb_start(&g->mc, cx, cy, count, limit);
        if (s == ISK_OK) {
            g->mc_active = 1;
            s = isk_multi_coulomb_release(&g->mc, p, &g->rng, NULL);
        }
        break;
    default: return ISK_ERR_RANGE;
    }
    /* A Coulomb explosion that kicks every particle moves those at rest */
    isk__rest_forget(&g->rest, kind == ISK_EXPLOSION_COULOMB && kick == ISK_KICK_ALL ? 0 : before);
    if (s == ISK_OK)
        isk__fx_adopt(e, g, before);
    return s;
}

/* Timed explosions (start > 0) fire at the first frame at or after their
 * time; a multi-Coulomb explosion releases its due batches. */
static isk_status run_release(isk_effect *e, fx_group *g, double t0, double h)
{
    (void)t0;
    (void)h;
    const isk_emitter_def *em = g->def;
    /* one due while the emitter is stopped is skipped, never fired later */
    if (em->born.source == ISK_SOURCE_EXPLOSION && !g->fired && isk__fx_group_time(e, g) >= em->born.start) {
        g->fired = 1;
        isk_status s = em->born.active ? isk__fx_fire_explosion(e, g, em->born.explosion, em->born.position.x,
                                                                em->born.position.y, em->born.count, em->born.kick)
                                       : ISK_OK;
        if (s != ISK_OK)
            return s;
    }
    if (g->mc_active && !isk_multi_coulomb_done(&g->mc)) {
        size_t before = g->store.count;
        isk_multi_coulomb *mc = &g->mc;
        /* Batches that no longer fit the pool (streams share it) are dropped
         * with the rest of the explosion. */
        if (before + isk_multi_coulomb_due(mc) > em->born.capacity) {
            g->dropped += mc->last_size + (mc->batches - mc->next) * mc->batch_size;
            mc->next = mc->batches + 1;
            return ISK_OK;
        }
        isk_status s = isk_multi_coulomb_release(&g->mc, &g->store, &g->rng, NULL);
        if (s != ISK_OK)
            return s;
        isk__fx_adopt(e, g, before);
    }
    return ISK_OK;
}

static void describe_release(const isk_effect *e, const fx_group *g, FILE *out)
{
    (void)e;
    const isk_emitter_def *em = g->def;
    fprintf(out, "%s explosion of %zu at t=%g s", isk_explosion_names[em->born.explosion], em->born.count,
            em->born.start);
}

const fx_step_kind isk__fx_step_release = {"release", run_release, describe_release};

/* draw_before_bounce: the thesis examples draw, then bounce, so the walls of
 * frame N run at the start of frame N + 1 (never before the first frame). */
static isk_status run_late_walls(isk_effect *e, fx_group *g, double t0, double h)
{
    (void)t0;
    (void)h;
    if (e->frame > 0)
        isk_bounds_apply(&e->def.bounds, &g->store, 0, g->store.count);
    return ISK_OK;
}

static void describe_late_walls(const isk_effect *e, const fx_group *g, FILE *out)
{
    (void)g;
    fprintf(out, "%s (after drawing: at the start of the next frame)", isk_bounce_mode_names[e->def.bounds.mode]);
}

const fx_step_kind isk__fx_step_late_walls = {"walls", run_late_walls, describe_late_walls};

static isk_status run_cull(isk_effect *e, fx_group *g, double t0, double h)
{
    if (g->def->events.on_death >= 0) { /* sub-emitters: the deaths as events first (effect_events.c) */
        isk_status s = isk__fx_events_deaths(e, g, t0 + h);
        if (s != ISK_OK)
            return s;
    }
    /* What the blocks at rest must forget: with the holes filled from the
     * end, the blocks of the dead and the new end; in order, everything
     * from the first dead on. */
    size_t first;
    if (g->cull_unordered)
        isk__rest_wake_dying(&g->rest, &g->store);
    isk__store_cull(&g->store, g->cull_unordered, &first);
    isk__rest_forget(&g->rest, g->cull_unordered ? g->store.count : first);
    return ISK_OK;
}

static void describe_cull(const isk_effect *e, const fx_group *g, FILE *out)
{
    fprintf(out, "age >= life%s", g->cull_unordered ? " (the last live particles fill the holes: nothing sees the order)" : "");
    if (g->def->events.on_death >= 0)
        fprintf(out, "; deaths -> events of %s", e->def.emitters[g->def->events.on_death].name);
}

const fx_step_kind isk__fx_step_cull = {"cull", run_cull, describe_cull};
