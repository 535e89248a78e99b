/* SPDX-License-Identifier: MIT */
/* Snapshots (iskra/snapshot.h): an effect's running state, copied out and
 * put back (the exact file: snapshot_bytes.c).
 *
 * What a run depends on besides its definition is listed once, as rows:
 * the effect's clocks (isk__snap_effect_rows) and each group's random
 * streams, birth schedule, explosion under way, path and counters
 * (isk__snap_group_rows), each row a field and its type
 * (snapshot_internal.h).  The copy in memory and the
 * file both walk the rows, so a field added to a group's state is one row
 * here (and the snapshot tests fail until it is: they compare a restored
 * run with a straight one for every built-in scene).  What a row does not
 * name is compiled from the definition (the stage lists, the forces, the
 * looks) or is a cache (blocks at rest, recorded draws), rebuilt by the
 * restore.  Particles are their store's columns (isk_particles_copy);
 * sub-emitters' pending events an array of their own.  The file is
 * snapshot_bytes.c's.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "snapshot_internal.h"

/* ---- the state, as rows ------------------------------------------------------------ */

const size_t isk__snap_row_bytes[] = {sizeof(double), sizeof(uint64_t), sizeof(size_t), sizeof(int),
                                      sizeof(long),   sizeof(uint32_t), sizeof(double)};

#define GROW(f, t) {#f, offsetof(fx_group, f), t}
/* A group's running state: everything that changes as it runs and is not
 * its particles, its pending events or compiled from the definition. */
const state_row isk__snap_group_rows[] = {
    GROW(rng.z1, ROW_U32),           GROW(rng.z2, ROW_U32),         GROW(rng.z3, ROW_U32),
    GROW(rng.z4, ROW_U32),
    /* the optional attributes' own streams (effect_group.c), one row of four each */
#define STREAM_ROWS(k)                                                                                                 \
    GROW(streams[k].z1, ROW_U32), GROW(streams[k].z2, ROW_U32), GROW(streams[k].z3, ROW_U32),                          \
        GROW(streams[k].z4, ROW_U32)
    STREAM_ROWS(FX_STREAM_MASS),     STREAM_ROWS(FX_STREAM_ROTATION), STREAM_ROWS(FX_STREAM_SPIN),
    STREAM_ROWS(FX_STREAM_SIZE),     STREAM_ROWS(FX_STREAM_COLOR),    STREAM_ROWS(FX_STREAM_CHANCE),
    STREAM_ROWS(FX_STREAM_FRAME),    STREAM_ROWS(FX_STREAM_RADIAL),   STREAM_ROWS(FX_STREAM_TANGENTIAL),
    STREAM_ROWS(FX_STREAM_WIND),     STREAM_ROWS(FX_STREAM_SLOWING),
#undef STREAM_ROWS
    GROW(origin, ROW_F64),           GROW(emitted, ROW_U64),
    GROW(next_burst, ROW_F64),       GROW(dropped, ROW_U64),        GROW(removed_nonfinite, ROW_SIZE),
    GROW(mc.cx, ROW_F64),            GROW(mc.cy, ROW_F64),          GROW(mc.total, ROW_SIZE),
    GROW(mc.batch_size, ROW_SIZE),   GROW(mc.batches, ROW_SIZE),    GROW(mc.last_size, ROW_SIZE),
    GROW(mc.next, ROW_SIZE),         GROW(mc.age, ROW_F64),         GROW(mc.next_release, ROW_F64),
    GROW(mc_active, ROW_INT),        GROW(fired, ROW_INT),          GROW(frame_offset, ROW_LONG),
    GROW(clock.t0, ROW_F64),         GROW(clock.f0, ROW_LONG),      GROW(clock.step, ROW_F64),
    GROW(path_base.x, ROW_F64),      GROW(path_base.y, ROW_F64),    GROW(path_t, ROW_F64),
    GROW(path_from.x, ROW_F64),      GROW(path_from.y, ROW_F64),    GROW(path_t0, ROW_F64),
    GROW(path_t1, ROW_F64),          GROW(carried.x, ROW_F64),      GROW(carried.y, ROW_F64),
    GROW(cycle_start, ROW_F64),      GROW(cycle_births, ROW_F64),   GROW(cycle_bursts, ROW_F64),
};
#undef GROW

#define EROW(f, t) {#f, offsetof(isk_effect, f), t}
/* The effect's own: its frame and clocks. */
const state_row isk__snap_effect_rows[] = {
    EROW(frame, ROW_LONG),     EROW(time, ROW_F64),     EROW(last_frame_time, ROW_F64),
    EROW(clock.t0, ROW_F64),   EROW(clock.f0, ROW_LONG), EROW(clock.step, ROW_F64),
};
#undef EROW

#define PROW(f, t) {#f, offsetof(isk_potential, f), t}
/* A live potential (its motion function, a C pointer, is copied in memory
 * and refused by the file). */
const state_row isk__snap_potential_rows[] = {
    PROW(id, ROW_INT),      PROW(r.x, ROW_F64),      PROW(r.y, ROW_F64),      PROW(k, ROW_F64),
    PROW(charge, ROW_F64),  PROW(P, ROW_F64),        PROW(min_dist, ROW_F64), PROW(max_dist, ROW_F64),
    PROW(x_mult, ROW_F64),  PROW(enabled, ROW_INT),  PROW(vel.x, ROW_F64),    PROW(vel.y, ROW_F64),
};
#undef PROW

_Static_assert(FX_STREAM_COUNT == 11, "a new attribute stream needs its STREAM_ROWS in isk__snap_group_rows");

#define RROW(f, t) {#f, offsetof(isk_probe_reading, f), t}
/* A probe's latest reading (its name, kind and bins come from the
 * definition); a gate's window of crossings follows it. */
const state_row isk__snap_reading_rows[] = {
    RROW(frame, ROW_LONG),       RROW(forward, ROW_U64),      RROW(backward, ROW_U64),
    RROW(rate_forward, ROW_F64), RROW(rate_backward, ROW_F64), RROW(count, ROW_SIZE),
    RROW(mean_speed, ROW_F64),   RROW(kinetic, ROW_F64),      RROW(under, ROW_SIZE),
    RROW(over, ROW_SIZE),        RROW(px, ROW_F64),           RROW(py, ROW_F64),
    RROW(potential, ROW_F64N),
};
#undef RROW

const int isk__snap_nreading_rows = sizeof isk__snap_reading_rows / sizeof isk__snap_reading_rows[0];
const int isk__snap_ngroup_rows = sizeof isk__snap_group_rows / sizeof isk__snap_group_rows[0];
const int isk__snap_neffect_rows = sizeof isk__snap_effect_rows / sizeof isk__snap_effect_rows[0];
const int isk__snap_npot_rows = sizeof isk__snap_potential_rows / sizeof isk__snap_potential_rows[0];

/* The bytes the rows take in memory, packed. */
size_t isk__snap_rows_size(const state_row *rows, int n)
{
    size_t total = 0;
    for (int i = 0; i < n; i++)
        total += isk__snap_row_bytes[rows[i].type];
    return total;
}

void isk__snap_rows_out(const state_row *rows, int n, const void *from, unsigned char *to)
{
    for (int i = 0; i < n; i++) {
        memcpy(to, (const unsigned char *)from + rows[i].offset, isk__snap_row_bytes[rows[i].type]);
        to += isk__snap_row_bytes[rows[i].type];
    }
}

void isk__snap_rows_in(const state_row *rows, int n, const unsigned char *from, void *to)
{
    for (int i = 0; i < n; i++) {
        memcpy((unsigned char *)to + rows[i].offset, from, isk__snap_row_bytes[rows[i].type]);
        from += isk__snap_row_bytes[rows[i].type];
    }
}

void isk_snapshot_free(isk_snapshot *snap)
{
    if (!snap)
        return;
    for (int i = 0; snap->groups && i < snap->ngroups; i++) {
        free(snap->groups[i].state);
        isk_particles_free(&snap->groups[i].store);
        free(snap->groups[i].events);
    }
    free(snap->groups);
    for (int i = 0; snap->probes && i < snap->nprobes; i++) {
        free(snap->probes[i].ring);
        free(snap->probes[i].ring_t);
    }
    free(snap->probes);
    free(snap->pots);
    free(snap->pot_force);
    free(snap->effect_state);
    isk_effect_def_free(&snap->def);
    free(snap);
}

/* An empty snapshot for ngroups groups and npots potentials (NULL: no memory). */
isk_snapshot *isk__snap_new(int ngroups, size_t npots)
{
    isk_snapshot *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    isk_effect_def_init(&s->def);
    s->ngroups = ngroups;
    s->npots = npots;
    s->groups = calloc((size_t)(ngroups ? ngroups : 1), sizeof *s->groups);
    s->pots = calloc(npots ? npots : 1, sizeof *s->pots);
    s->pot_force = calloc(npots ? npots : 1, sizeof *s->pot_force);
    s->effect_state = malloc(isk__snap_rows_size(isk__snap_effect_rows, isk__snap_neffect_rows));
    int ok = s->groups && s->pots && s->pot_force && s->effect_state;
    for (int i = 0; ok && i < ngroups; i++)
        ok = (s->groups[i].state = malloc(isk__snap_rows_size(isk__snap_group_rows, isk__snap_ngroup_rows))) != NULL;
    if (!ok) {
        isk_snapshot_free(s);
        return NULL;
    }
    return s;
}

/* Room for n probes with rings of ring_n[i] frames (gates), all zero. */
isk_status isk__snap_probes_new(isk_snapshot *s, int n, const int *ring_n)
{
    s->nprobes = n;
    if (n == 0)
        return ISK_OK;
    if (!(s->probes = calloc((size_t)n, sizeof *s->probes)))
        return ISK_ERR_NOMEM;
    for (int i = 0; i < n; i++) {
        snap_probe *q = &s->probes[i];
        q->ring_n = ring_n[i];
        if (q->ring_n && (!(q->ring = calloc((size_t)q->ring_n * 2, sizeof *q->ring)) ||
                          !(q->ring_t = calloc((size_t)q->ring_n, sizeof *q->ring_t))))
            return ISK_ERR_NOMEM;
    }
    return ISK_OK;
}

static isk_status probes_out(const isk_effect *e, isk_snapshot *s)
{
    const int n = e->probes ? e->def.nprobes : 0;
    int ring_n[ISK_EFFECT_MAX_PROBES] = {0};
    for (int i = 0; i < n; i++)
        ring_n[i] = e->probes[i].ring ? e->probes[i].ring_n : 0;
    isk_status st = isk__snap_probes_new(s, n, ring_n);
    for (int i = 0; st == ISK_OK && i < n; i++) {
        const fx_probe *p = &e->probes[i];
        snap_probe *q = &s->probes[i];
        q->r = p->r;
        q->ring_head = p->ring_head;
        q->ring_used = p->ring_used;
        if (q->ring_n) {
            memcpy(q->ring, p->ring, sizeof *q->ring * 2 * (size_t)q->ring_n);
            memcpy(q->ring_t, p->ring_t, sizeof *q->ring_t * (size_t)q->ring_n);
        }
    }
    return st;
}

/* Into an effect built from the same definition (its probes made alike). */
static isk_status probes_in(isk_effect *e, const isk_snapshot *s)
{
    const int n = e->probes ? e->def.nprobes : 0;
    if (n != s->nprobes)
        return ISK_ERR_FORMAT;
    for (int i = 0; i < n; i++) {
        fx_probe *p = &e->probes[i];
        const snap_probe *q = &s->probes[i];
        if ((p->ring ? p->ring_n : 0) != q->ring_n || q->r.kind != p->r.kind)
            return ISK_ERR_FORMAT;
        const char *name = p->r.name;
        const int bins = p->r.bins;
        p->r = q->r;
        p->r.name = name;
        p->r.bins = bins;
        p->ring_head = q->ring_head;
        p->ring_used = q->ring_used;
        if (q->ring_n) {
            memcpy(p->ring, q->ring, sizeof *q->ring * 2 * (size_t)q->ring_n);
            memcpy(p->ring_t, q->ring_t, sizeof *q->ring_t * (size_t)q->ring_n);
        }
    }
    return ISK_OK;
}

isk_status isk_effect_snapshot(const isk_effect *e, isk_snapshot **out, isk_error *err)
{
    if (!e || !out)
        return isk_error_set(err, ISK_ERR_NULL, "isk_effect_snapshot: NULL argument");
    *out = NULL;
    isk_snapshot *s = isk__snap_new(e->ngroups, e->npots);
    isk_status st = s ? isk__fx_def_copy(&s->def, &e->def) : ISK_ERR_NOMEM;
    for (int i = 0; st == ISK_OK && i < e->ngroups; i++) {
        const fx_group *g = &e->groups[i];
        snap_group *sg = &s->groups[i];
        isk__snap_rows_out(isk__snap_group_rows, isk__snap_ngroup_rows, g, sg->state);
        st = isk_particles_copy(&sg->store, &g->store);
        if (st == ISK_OK && g->pending.n) {
            sg->events = malloc(sizeof *sg->events * g->pending.n);
            if (!sg->events)
                st = ISK_ERR_NOMEM;
            else
                memcpy(sg->events, g->pending.ev, sizeof *sg->events * g->pending.n);
            sg->nevents = g->pending.n;
        }
    }
    if (st != ISK_OK) {
        isk_snapshot_free(s);
        return isk_error_set(err, st, "isk_effect_snapshot: out of memory");
    }
    if (st == ISK_OK)
        st = probes_out(e, s);
    if (st != ISK_OK) {
        isk_snapshot_free(s);
        return isk_error_set(err, st, "isk_effect_snapshot: out of memory");
    }
    isk__snap_rows_out(isk__snap_effect_rows, isk__snap_neffect_rows, e, s->effect_state);
    memcpy(s->pots, e->pots, sizeof *s->pots * e->npots);
    memcpy(s->pot_force, e->pot_force, sizeof *s->pot_force * e->npots);
    *out = s;
    return ISK_OK;
}

isk_status isk_effect_restore(isk_effect *e, const isk_snapshot *snap, isk_error *err)
{
    if (!e || !snap)
        return isk_error_set(err, ISK_ERR_NULL, "isk_effect_restore: NULL argument");
    isk_effect *bare;
    isk_status s = isk__fx_create_bare(&bare, &snap->def, err);
    if (s != ISK_OK)
        return s;
    if (bare->npots != snap->npots || bare->ngroups != snap->ngroups) {
        isk_effect_destroy(bare);
        return isk_error_set(err, ISK_ERR_FORMAT, "isk_effect_restore: the snapshot's potentials or emitters do "
                                                  "not match its definition");
    }
    memcpy(bare->pots, snap->pots, sizeof *snap->pots * snap->npots);
    memcpy(bare->pot_force, snap->pot_force, sizeof *snap->pot_force * snap->npots);
    isk__snap_rows_in(isk__snap_effect_rows, isk__snap_neffect_rows, snap->effect_state, bare);
    for (int i = 0; s == ISK_OK && i < snap->ngroups; i++) {
        fx_group *g = &bare->groups[i];
        const snap_group *sg = &snap->groups[i];
        /* the stages read the columns the definition asks for: they must be there */
        const unsigned need = g->store.flags, have = sg->store.flags;
        if ((need & ~have) || (g->store.trail_len && g->store.trail_len != sg->store.trail_len)) {
            s = isk_error_set(err, ISK_ERR_FORMAT, "isk_effect_restore: emitter '%s': its particles lack columns "
                                                   "its definition needs",
                              g->def->name);
            break;
        }
        isk__snap_rows_in(isk__snap_group_rows, isk__snap_ngroup_rows, sg->state, g);
        s = isk_particles_copy(&g->store, &sg->store);
        g->pending.n = 0;
        if (s == ISK_OK && sg->nevents) {
            fx_event *ev = realloc(g->pending.ev, sizeof *ev * sg->nevents);
            if (!ev) {
                s = ISK_ERR_NOMEM;
                break;
            }
            memcpy(ev, sg->events, sizeof *ev * sg->nevents);
            g->pending.ev = ev;
            g->pending.n = g->pending.cap = sg->nevents;
        }
    }
    if (s == ISK_OK && probes_in(bare, snap) != ISK_OK)
        s = isk_error_set(err, ISK_ERR_FORMAT, "isk_effect_restore: the snapshot's probes do not match its definition");
    if (s == ISK_ERR_FORMAT) {
        isk_effect_destroy(bare);
        return s;
    }
    if (s == ISK_OK)
        s = isk__fx_take_state(e, bare);
    isk_effect_destroy(bare); /* after a take: what e held before */
    return s == ISK_OK ? ISK_OK : isk_error_set(err, s, "isk_effect_restore: %s", isk_status_str(s));
}

long isk_snapshot_frame(const isk_snapshot *snap)
{
    if (!snap)
        return 0;
    long frame;
    memcpy(&frame, snap->effect_state, sizeof frame); /* isk__snap_effect_rows[0] */
    return frame;
}

size_t isk_snapshot_bytes(const isk_snapshot *snap)
{
    if (!snap)
        return 0;
    size_t total = sizeof *snap + snap->npots * (sizeof *snap->pots + sizeof *snap->pot_force);
    for (int i = 0; i < snap->ngroups; i++) {
        const snap_group *sg = &snap->groups[i];
        total += sizeof *sg + isk__snap_rows_size(isk__snap_group_rows, isk__snap_ngroup_rows) + sg->nevents * sizeof *sg->events;
        total += isk_particles_bytes(sg->store.count, sg->store.flags) / 2; /* one copy, not a growing store */
    }
    return total;
}

