/* SPDX-License-Identifier: MIT */
/* Snapshots (iskra/snapshot.h): an effect's running state, copied out and
 * put back, and written as exact bytes.
 *
 * What a run depends on besides its definition is listed once, as rows:
 * the effect's clocks (effect_rows) and each group's random stream, birth
 * schedule, explosion under way, path and counters (group_rows), each row a
 * field of isk_effect or fx_group and its type.  The copy in memory and the
 * file both walk the rows, so a field added to a group's state is one row
 * here (and the snapshot tests fail until it is: they compare a restored
 * run with a straight one for every built-in scene).  What a row does not
 * name is compiled from the definition (the stage lists, the forces, the
 * looks) or is a cache (blocks at rest, recorded draws), rebuilt by the
 * restore.  Particles are their store's columns (isk_particles_copy);
 * sub-emitters' pending events an array of their own.
 *
 * The file: "ISKRA-SNAPSHOT 1\n", the definition as scene text (its
 * length, then its bytes), then every number as 8 little-endian bytes (a
 * double's bits, an integer as 64 bits), then an FNV-1a checksum of all
 * that came before.  Columns of doubles are numbers too; a colour is its
 * four bytes, a hit count one. */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/limits.h"
#include "iskra/scene.h"
#include "iskra/snapshot.h"
#include "sim/store_internal.h"

/* ---- the state, as rows ------------------------------------------------------------ */

typedef enum { ROW_F64, ROW_U64, ROW_SIZE, ROW_INT, ROW_LONG, ROW_U32 } row_type;
static const size_t row_bytes[] = {sizeof(double), sizeof(uint64_t), sizeof(size_t),
                                   sizeof(int),    sizeof(long),     sizeof(uint32_t)};

typedef struct state_row {
    const char *name;
    size_t offset;
    row_type type;
} state_row;

#define GROW(f, t) {#f, offsetof(fx_group, f), t}
/* A group's running state: everything that changes as it runs and is not
 * its particles, its pending events or compiled from the definition. */
static const state_row group_rows[] = {
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
static const state_row effect_rows[] = {
    EROW(frame, ROW_LONG),     EROW(time, ROW_F64),     EROW(last_frame_time, ROW_F64),
    EROW(clock.t0, ROW_F64),   EROW(clock.f0, ROW_LONG), EROW(clock.step, ROW_F64),
};
#undef EROW

#define PROW(f, t) {#f, offsetof(isk_potential, f), t}
/* A live potential (its motion function, a C pointer, is copied in memory
 * and refused by the file). */
static const state_row potential_rows[] = {
    PROW(id, ROW_INT),      PROW(r.x, ROW_F64),      PROW(r.y, ROW_F64),      PROW(k, ROW_F64),
    PROW(charge, ROW_F64),  PROW(P, ROW_F64),        PROW(min_dist, ROW_F64), PROW(max_dist, ROW_F64),
    PROW(x_mult, ROW_F64),  PROW(enabled, ROW_INT),  PROW(vel.x, ROW_F64),    PROW(vel.y, ROW_F64),
};
#undef PROW

_Static_assert(FX_STREAM_COUNT == 11, "a new attribute stream needs its STREAM_ROWS in group_rows");

enum {
    NGROUP_ROWS = sizeof group_rows / sizeof group_rows[0],
    NEFFECT_ROWS = sizeof effect_rows / sizeof effect_rows[0],
    NPOT_ROWS = sizeof potential_rows / sizeof potential_rows[0],
};

/* The bytes the rows take in memory, packed. */
static size_t rows_size(const state_row *rows, int n)
{
    size_t total = 0;
    for (int i = 0; i < n; i++)
        total += row_bytes[rows[i].type];
    return total;
}

static void rows_out(const state_row *rows, int n, const void *from, unsigned char *to)
{
    for (int i = 0; i < n; i++) {
        memcpy(to, (const unsigned char *)from + rows[i].offset, row_bytes[rows[i].type]);
        to += row_bytes[rows[i].type];
    }
}

static void rows_in(const state_row *rows, int n, const unsigned char *from, void *to)
{
    for (int i = 0; i < n; i++) {
        memcpy((unsigned char *)to + rows[i].offset, from, row_bytes[rows[i].type]);
        from += row_bytes[rows[i].type];
    }
}

typedef struct snap_group {
    unsigned char *state; /* group_rows, packed */
    isk_particles store;
    fx_event *events;
    size_t nevents;
} snap_group;

struct isk_snapshot {
    isk_effect_def def;
    unsigned char *effect_state; /* effect_rows, packed */
    size_t npots;
    isk_potential *pots;
    int *pot_force;
    int ngroups;
    snap_group *groups;
};

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
    free(snap->pots);
    free(snap->pot_force);
    free(snap->effect_state);
    isk_effect_def_free(&snap->def);
    free(snap);
}

/* An empty snapshot for ngroups groups and npots potentials (NULL: no memory). */
static isk_snapshot *snapshot_new(int ngroups, size_t npots)
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
    s->effect_state = malloc(rows_size(effect_rows, NEFFECT_ROWS));
    int ok = s->groups && s->pots && s->pot_force && s->effect_state;
    for (int i = 0; ok && i < ngroups; i++)
        ok = (s->groups[i].state = malloc(rows_size(group_rows, NGROUP_ROWS))) != NULL;
    if (!ok) {
        isk_snapshot_free(s);
        return NULL;
    }
    return s;
}

isk_status isk_effect_snapshot(const isk_effect *e, isk_snapshot **out, isk_error *err)
{
    if (!e || !out)
        return isk_error_set(err, ISK_ERR_NULL, "isk_effect_snapshot: NULL argument");
    *out = NULL;
    isk_snapshot *s = snapshot_new(e->ngroups, e->npots);
    isk_status st = s ? isk__fx_def_copy(&s->def, &e->def) : ISK_ERR_NOMEM;
    for (int i = 0; st == ISK_OK && i < e->ngroups; i++) {
        const fx_group *g = &e->groups[i];
        snap_group *sg = &s->groups[i];
        rows_out(group_rows, NGROUP_ROWS, g, sg->state);
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
    rows_out(effect_rows, NEFFECT_ROWS, e, s->effect_state);
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
    rows_in(effect_rows, NEFFECT_ROWS, snap->effect_state, bare);
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
        rows_in(group_rows, NGROUP_ROWS, sg->state, g);
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
    memcpy(&frame, snap->effect_state, sizeof frame); /* effect_rows[0] */
    return frame;
}

size_t isk_snapshot_bytes(const isk_snapshot *snap)
{
    if (!snap)
        return 0;
    size_t total = sizeof *snap + snap->npots * (sizeof *snap->pots + sizeof *snap->pot_force);
    for (int i = 0; i < snap->ngroups; i++) {
        const snap_group *sg = &snap->groups[i];
        total += sizeof *sg + rows_size(group_rows, NGROUP_ROWS) + sg->nevents * sizeof *sg->events;
        total += isk_particles_bytes(sg->store.count, sg->store.flags) / 2; /* one copy, not a growing store */
    }
    return total;
}

/* ---- the file ---------------------------------------------------------------------- */

#define MAGIC "ISKRA-SNAPSHOT 1\n"

typedef struct writer {
    unsigned char *b;
    size_t n, cap;
    int failed;
} writer;

static void put(writer *w, const void *p, size_t n)
{
    if (w->failed)
        return;
    if (n > w->cap - w->n) {
        size_t cap = w->cap ? w->cap : 4096;
        while (cap - w->n < n) {
            if (cap > SIZE_MAX / 2) {
                w->failed = 1;
                return;
            }
            cap *= 2;
        }
        unsigned char *b = realloc(w->b, cap);
        if (!b) {
            w->failed = 1;
            return;
        }
        w->b = b;
        w->cap = cap;
    }
    memcpy(w->b + w->n, p, n);
    w->n += n;
}

static void put_u64(writer *w, uint64_t v)
{
    unsigned char b[8];
    for (int i = 0; i < 8; i++)
        b[i] = (unsigned char)(v >> (8 * i));
    put(w, b, 8);
}

static void put_f64(writer *w, double d)
{
    uint64_t v;
    memcpy(&v, &d, sizeof v);
    put_u64(w, v);
}

/* One row's value (in memory at p) as 8 bytes. */
static void put_row(writer *w, row_type t, const unsigned char *p)
{
    switch (t) {
    case ROW_F64: { double d; memcpy(&d, p, sizeof d); put_f64(w, d); break; }
    case ROW_U64: { uint64_t v; memcpy(&v, p, sizeof v); put_u64(w, v); break; }
    case ROW_SIZE: { size_t v; memcpy(&v, p, sizeof v); put_u64(w, (uint64_t)v); break; }
    case ROW_INT: { int v; memcpy(&v, p, sizeof v); put_u64(w, (uint64_t)(int64_t)v); break; }
    case ROW_LONG: { long v; memcpy(&v, p, sizeof v); put_u64(w, (uint64_t)(int64_t)v); break; }
    case ROW_U32: { uint32_t v; memcpy(&v, p, sizeof v); put_u64(w, v); break; }
    }
}

static void put_rows(writer *w, const state_row *rows, int n, const unsigned char *packed)
{
    for (int i = 0; i < n; i++) {
        put_row(w, rows[i].type, packed);
        packed += row_bytes[rows[i].type];
    }
}

static uint64_t fnv1a(const unsigned char *b, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

static void put_store(writer *w, const isk_particles *p)
{
    put_u64(w, p->count);
    put_u64(w, p->flags);
    put_u64(w, (uint64_t)(int64_t)p->trail_len);
    put_u64(w, (uint64_t)(int64_t)p->trail_head);
    put(w, &p->default_color, sizeof p->default_color);
    put_f64(w, p->default_size);
    isk__store_column col[ISK__STORE_COLUMNS];
    const size_t nc = isk__store_columns(p, col);
    for (size_t c = 0; c < nc; c++) {
        if (!col[c].doubles) {
            put(w, col[c].bytes, p->count * col[c].elem);
            continue;
        }
        const size_t nd = p->count * (col[c].elem / sizeof(double));
        for (size_t i = 0; i < nd; i++) {
            double d;
            memcpy(&d, col[c].bytes + i * sizeof d, sizeof d);
            put_f64(w, d);
        }
    }
}

isk_status isk_snapshot_encode(const isk_snapshot *snap, unsigned char **bytes, size_t *size, isk_error *err)
{
    if (!snap || !bytes || !size)
        return isk_error_set(err, ISK_ERR_NULL, "isk_snapshot_encode: NULL argument");
    *bytes = NULL;
    *size = 0;
    for (size_t k = 0; k < snap->npots; k++)
        if (snap->pots[k].motion)
            return isk_error_set(err, ISK_ERR_FORMAT, "snapshot: potential %d is moved by a C function, which a "
                                                      "file cannot hold",
                                 snap->pots[k].id);
    char *text;
    isk_status s = isk_scene_write(&snap->def, &text, err);
    if (s != ISK_OK)
        return s;
    writer w = {0};
    put(&w, MAGIC, strlen(MAGIC));
    const size_t tl = strlen(text);
    put_u64(&w, tl);
    put(&w, text, tl);
    free(text);
    put_rows(&w, effect_rows, NEFFECT_ROWS, snap->effect_state);
    put_u64(&w, snap->npots);
    for (size_t k = 0; k < snap->npots; k++) {
        for (int i = 0; i < NPOT_ROWS; i++)
            put_row(&w, potential_rows[i].type, (const unsigned char *)&snap->pots[k] + potential_rows[i].offset);
        put_u64(&w, (uint64_t)(int64_t)snap->pot_force[k]);
    }
    put_u64(&w, (uint64_t)snap->ngroups);
    for (int i = 0; i < snap->ngroups; i++) {
        const snap_group *sg = &snap->groups[i];
        put_rows(&w, group_rows, NGROUP_ROWS, sg->state);
        put_store(&w, &sg->store);
        put_u64(&w, sg->nevents);
        for (size_t k = 0; k < sg->nevents; k++) {
            const fx_event *ev = &sg->events[k];
            put_f64(&w, ev->x);
            put_f64(&w, ev->y);
            put_f64(&w, ev->vx);
            put_f64(&w, ev->vy);
            put_f64(&w, ev->t);
        }
    }
    if (!w.failed)
        put_u64(&w, fnv1a(w.b, w.n));
    if (w.failed) {
        free(w.b);
        return isk_error_set(err, ISK_ERR_NOMEM, "snapshot: out of memory");
    }
    *bytes = w.b;
    *size = w.n;
    return ISK_OK;
}

/* ---- reading it back: every number checked ------------------------------------------ */

typedef struct reader {
    const unsigned char *b;
    size_t n, at;
    const char *name;
    isk_error *err;
    int failed;
} reader;

static int fail(reader *r, const char *what)
{
    if (!r->failed)
        isk_error_set(r->err, ISK_ERR_FORMAT, "%s: not a snapshot iskra can use: %s", r->name, what);
    r->failed = 1;
    return 0;
}

static int get(reader *r, void *p, size_t n)
{
    if (r->failed)
        return 0;
    if (n > r->n - r->at)
        return fail(r, "it ends too soon");
    memcpy(p, r->b + r->at, n);
    r->at += n;
    return 1;
}

static uint64_t get_u64(reader *r)
{
    unsigned char b[8] = {0};
    get(r, b, 8);
    uint64_t v = 0;
    for (int i = 0; i < 8; i++)
        v |= (uint64_t)b[i] << (8 * i);
    return v;
}

/* A double that is a number (infinities only where `inf_ok`). */
static double get_f64(reader *r, int inf_ok)
{
    uint64_t v = get_u64(r);
    double d;
    memcpy(&d, &v, sizeof d);
    if (isnan(d) || (!inf_ok && isinf(d))) {
        fail(r, "a number that is NaN or infinite");
        return 0.0;
    }
    return d;
}

/* A count no larger than `most`. */
static uint64_t get_count(reader *r, uint64_t most, const char *what)
{
    uint64_t v = get_u64(r);
    if (v > most) {
        fail(r, what);
        return 0;
    }
    return v;
}

/* One row into packed memory at p (schedules may be infinite: a burst never
 * due, a path never moved). */
static void get_row(reader *r, row_type t, unsigned char *p)
{
    uint64_t v;
    switch (t) {
    case ROW_F64: { double d = get_f64(r, 1); memcpy(p, &d, sizeof d); break; }
    case ROW_U64: v = get_u64(r); memcpy(p, &v, sizeof v); break;
    case ROW_SIZE: { size_t z = (size_t)get_count(r, SIZE_MAX, "a count too large"); memcpy(p, &z, sizeof z); break; }
    case ROW_INT: {
        int64_t x = (int64_t)get_u64(r);
        if (x < INT_MIN || x > INT_MAX)
            fail(r, "an integer out of range");
        int i = (int)x;
        memcpy(p, &i, sizeof i);
        break;
    }
    case ROW_LONG: {
        int64_t x = (int64_t)get_u64(r);
        if (x < LONG_MIN || x > LONG_MAX)
            fail(r, "a frame number out of range");
        long l = (long)x;
        memcpy(p, &l, sizeof l);
        break;
    }
    case ROW_U32: {
        uint32_t u = (uint32_t)get_count(r, UINT32_MAX, "a random state out of range");
        memcpy(p, &u, sizeof u);
        break;
    }
    }
}

static void get_rows(reader *r, const state_row *rows, int n, unsigned char *packed)
{
    for (int i = 0; i < n; i++) {
        get_row(r, rows[i].type, packed);
        packed += row_bytes[rows[i].type];
    }
}

static void get_store(reader *r, isk_particles *p, size_t capacity)
{
    const size_t count = (size_t)get_count(r, capacity, "more particles than the emitter's capacity");
    const unsigned flags = (unsigned)get_count(r, ISK_PARTICLES_FLAGS | ISK_PARTICLES_TRAIL, "unknown columns");
    const int trail_len = (int)get_count(r, ISK_TRAIL_MAX, "a trail too long");
    const int trail_head = (int)get_count(r, ISK_TRAIL_MAX, "a trail's head out of range");
    isk_color dc = {0, 0, 0, 0};
    get(r, &dc, sizeof dc);
    const double ds = get_f64(r, 0);
    if (r->failed)
        return;
    if (!(flags & ISK_PARTICLES_TRAIL) != !trail_len || (trail_len && trail_head >= trail_len)) {
        fail(r, "a trail that does not match its column");
        return;
    }
    /* the particles' bytes must be there before memory is taken for them */
    const size_t per = 7 * 8 + (flags & ISK_PARTICLES_TRAIL ? 16 * (size_t)trail_len : 0);
    if (count > (r->n - r->at) / per) {
        fail(r, "it ends too soon");
        return;
    }
    if (isk_particles_init(p, count, flags & ISK_PARTICLES_FLAGS) != ISK_OK ||
        (trail_len && isk_particles_set_trail(p, trail_len) != ISK_OK)) {
        isk_error_set(r->err, ISK_ERR_NOMEM, "%s: out of memory", r->name);
        r->failed = 1;
        return;
    }
    p->count = count;
    p->trail_head = trail_head;
    p->default_color = dc;
    p->default_size = ds;
    isk__store_column col[ISK__STORE_COLUMNS];
    const size_t nc = isk__store_columns(p, col);
    for (size_t c = 0; c < nc && !r->failed; c++) {
        if (!col[c].doubles) {
            get(r, col[c].bytes, count * col[c].elem);
            continue;
        }
        const size_t nd = count * (col[c].elem / sizeof(double));
        for (size_t i = 0; i < nd && !r->failed; i++) {
            const double d = get_f64(r, col[c].life);
            memcpy(col[c].bytes + i * sizeof d, &d, sizeof d);
        }
    }
}

/* The rows that must hold what the library would have made: a plan of a
 * multi-Coulomb explosion the library would make, a potential's fields a
 * scene could give. */
static void check_group(reader *r, const isk_emitter_def *em, const unsigned char *packed)
{
    fx_group g;
    memset(&g, 0, sizeof g);
    rows_in(group_rows, NGROUP_ROWS, packed, &g);
    if (g.mc_active) {
        isk_multi_coulomb plan;
        const size_t limit = em->born.limit ? em->born.limit : ISK_EXPLODE_THESIS_LIMIT;
        if (isk_multi_coulomb_start(&plan, g.mc.cx, g.mc.cy, g.mc.total, limit) != ISK_OK ||
            plan.batch_size != g.mc.batch_size || plan.batches != g.mc.batches || plan.last_size != g.mc.last_size ||
            g.mc.next > g.mc.batches + 1 || !isfinite(g.mc.age) || !isfinite(g.mc.next_release))
            fail(r, "an explosion under way that iskra would not have made");
    }
    if (g.frame_offset < 0 || !isfinite(g.clock.t0) || !isfinite(g.clock.step) || !(g.clock.step > 0))
        fail(r, "a clock out of range");
}

static void check_potential(reader *r, const isk_potential *p)
{
    const double v[] = {p->r.x, p->r.y, p->k, p->charge, p->P, p->min_dist, p->max_dist, p->x_mult, p->vel.x, p->vel.y};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i]) || fabs(v[i]) > ISK_COORD_MAX)
            fail(r, "a potential's number out of range");
    if (p->id < 1 || (p->enabled != 0 && p->enabled != 1))
        fail(r, "a potential's id or switch out of range");
}

isk_status isk_snapshot_decode(isk_snapshot **out, const unsigned char *bytes, size_t size, const char *name,
                               isk_error *err)
{
    if (!out || !bytes)
        return isk_error_set(err, ISK_ERR_NULL, "isk_snapshot_decode: NULL argument");
    *out = NULL;
    if (!name)
        name = "<snapshot>";
    reader r = {bytes, size, 0, name, err, 0};
    const size_t ml = strlen(MAGIC);
    if (size < ml + 8 || memcmp(bytes, MAGIC, ml) != 0)
        return isk_error_set(err, ISK_ERR_FORMAT, "%s: not an iskra snapshot (it does not start with \"%.16s\")",
                             name, MAGIC);
    uint64_t sum = 0;
    for (int i = 0; i < 8; i++)
        sum |= (uint64_t)bytes[size - 8 + (size_t)i] << (8 * i);
    if (fnv1a(bytes, size - 8) != sum)
        return isk_error_set(err, ISK_ERR_FORMAT, "%s: the snapshot is damaged (its checksum does not match)", name);
    r.n = size - 8;
    r.at = ml;
    const size_t tl = (size_t)get_count(&r, r.n - r.at, "it ends too soon");
    if (r.failed)
        return ISK_ERR_FORMAT;
    char *text = malloc(tl + 1);
    if (!text)
        return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", name);
    get(&r, text, tl);
    text[tl] = 0;
    isk_effect_def def;
    isk_status s = memchr(text, 0, tl) ? isk_error_set(err, ISK_ERR_FORMAT, "%s: a NUL byte in its scene", name)
                                       : isk_scene_load_string(&def, text, name, err);
    free(text);
    if (s != ISK_OK)
        return s;
    unsigned char effect_state[64]; /* effect_rows, packed: 2 longs and 4 doubles */
    get_rows(&r, effect_rows, NEFFECT_ROWS, effect_state);
    size_t npots_def = 0;
    for (int i = 0; i < def.nforces; i++)
        npots_def += def.forces[i].kind == ISK_FORCE_POTENTIAL;
    const size_t npots = (size_t)get_count(&r, npots_def, "more potentials than its scene has");
    isk_snapshot *snap = r.failed ? NULL : snapshot_new(def.nemitters, npots);
    if (!snap) {
        isk_effect_def_free(&def);
        return r.failed ? ISK_ERR_FORMAT : isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", name);
    }
    isk_effect_def_free(&snap->def);
    snap->def = def;
    memcpy(snap->effect_state, effect_state, rows_size(effect_rows, NEFFECT_ROWS));
    for (size_t k = 0; k < npots && !r.failed; k++) {
        isk_potential *p = &snap->pots[k];
        for (int i = 0; i < NPOT_ROWS; i++)
            get_row(&r, potential_rows[i].type, (unsigned char *)p + potential_rows[i].offset);
        snap->pot_force[k] = (int)get_count(&r, (uint64_t)(def.nforces - 1), "a potential of no force");
        if (!r.failed && def.forces[snap->pot_force[k]].kind != ISK_FORCE_POTENTIAL)
            fail(&r, "a potential of a force that is not one");
        check_potential(&r, p);
    }
    if (get_u64(&r) != (uint64_t)def.nemitters)
        fail(&r, "its emitters do not match its scene");
    for (int i = 0; i < def.nemitters && !r.failed; i++) {
        snap_group *sg = &snap->groups[i];
        get_rows(&r, group_rows, NGROUP_ROWS, sg->state);
        check_group(&r, &def.emitters[i], sg->state);
        get_store(&r, &sg->store, def.emitters[i].born.capacity);
        sg->nevents = (size_t)get_count(&r, (r.n - r.at) / 40, "it ends too soon");
        if (sg->nevents && !r.failed) {
            sg->events = malloc(sizeof *sg->events * sg->nevents);
            if (!sg->events) {
                isk_snapshot_free(snap);
                return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", name);
            }
        }
        for (size_t k = 0; k < sg->nevents && !r.failed; k++) {
            fx_event *ev = &sg->events[k];
            ev->x = get_f64(&r, 0);
            ev->y = get_f64(&r, 0);
            ev->vx = get_f64(&r, 0);
            ev->vy = get_f64(&r, 0);
            ev->t = get_f64(&r, 0);
        }
    }
    long frame;
    memcpy(&frame, effect_state, sizeof frame);
    double time;
    memcpy(&time, effect_state + sizeof(long), sizeof time);
    if (!r.failed && (frame < 0 || !isfinite(time)))
        fail(&r, "a frame or time out of range");
    if (!r.failed && r.at != r.n)
        fail(&r, "bytes after its end");
    if (r.failed) {
        isk_snapshot_free(snap);
        return ISK_ERR_FORMAT;
    }
    *out = snap;
    return ISK_OK;
}
