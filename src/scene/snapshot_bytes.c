/* SPDX-License-Identifier: MIT */
/* A snapshot as exact bytes (iskra/snapshot.h): isk_snapshot_encode and
 * isk_snapshot_decode.
 *
 * The file: "ISKRA-SNAPSHOT 1\n", the definition as scene text (its
 * length, then its bytes), then every number as 8 little-endian bytes (a
 * double's bits, an integer as 64 bits) in the order of the rows
 * (snapshot_internal.h), then an FNV-1a checksum of all that came before.
 * Columns of doubles are numbers too; a colour is its four bytes, a hit
 * count one.  Reading checks everything it can: counts against the pools
 * and the file's length, no NaN where a scene allows none, an explosion's
 * plan against what the library would make; the definition is checked
 * again when the snapshot is restored. */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/limits.h"
#include "iskra/scene.h"
#include "sim/store_internal.h"
#include "snapshot_internal.h"

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
    case ROW_F64:
    case ROW_F64N: { double d; memcpy(&d, p, sizeof d); put_f64(w, d); break; }
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
        packed += isk__snap_row_bytes[rows[i].type];
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
    put_rows(&w, isk__snap_effect_rows, isk__snap_neffect_rows, snap->effect_state);
    put_u64(&w, snap->npots);
    for (size_t k = 0; k < snap->npots; k++) {
        for (int i = 0; i < isk__snap_npot_rows; i++)
            put_row(&w, isk__snap_potential_rows[i].type, (const unsigned char *)&snap->pots[k] + isk__snap_potential_rows[i].offset);
        put_u64(&w, (uint64_t)(int64_t)snap->pot_force[k]);
    }
    put_u64(&w, (uint64_t)snap->ngroups);
    for (int i = 0; i < snap->ngroups; i++) {
        const snap_group *sg = &snap->groups[i];
        put_rows(&w, isk__snap_group_rows, isk__snap_ngroup_rows, sg->state);
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
    put_u64(&w, (uint64_t)snap->nprobes);
    for (int i = 0; i < snap->nprobes; i++) {
        const snap_probe *q = &snap->probes[i];
        put_u64(&w, (uint64_t)q->r.kind);
        for (int k = 0; k < isk__snap_nreading_rows; k++)
            put_row(&w, isk__snap_reading_rows[k].type, (const unsigned char *)&q->r + isk__snap_reading_rows[k].offset);
        for (int k = 0; k < ISK_PROBE_MAX_BINS; k++)
            put_u64(&w, q->r.bin[k]);
        put_u64(&w, (uint64_t)q->ring_n);
        put_u64(&w, (uint64_t)q->ring_head);
        put_u64(&w, (uint64_t)q->ring_used);
        for (int k = 0; k < 2 * q->ring_n; k++)
            put_u64(&w, q->ring[k]);
        for (int k = 0; k < q->ring_n; k++)
            put_f64(&w, q->ring_t[k]);
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

/* A signed integer in [lo, hi] (0 after a failure). */
static int64_t get_signed(reader *r, int64_t lo, int64_t hi)
{
    const int64_t x = (int64_t)get_u64(r);
    if (x < lo || x > hi) {
        fail(r, "an integer out of range");
        return 0;
    }
    return x;
}

/* One row into packed memory at p (schedules may be infinite: a burst never
 * due, a path never moved). */
static void get_row(reader *r, row_type t, unsigned char *p)
{
    uint64_t v;
    switch (t) {
    case ROW_F64: { double d = get_f64(r, 1); memcpy(p, &d, sizeof d); break; }
    case ROW_F64N: { /* any bits: a NaN means "no energy" */
        v = get_u64(r);
        memcpy(p, &v, sizeof v);
        break;
    }
    case ROW_U64: v = get_u64(r); memcpy(p, &v, sizeof v); break;
    case ROW_SIZE: { size_t z = (size_t)get_count(r, SIZE_MAX, "a count too large"); memcpy(p, &z, sizeof z); break; }
    case ROW_INT: {
        int i = (int)get_signed(r, INT_MIN, INT_MAX);
        memcpy(p, &i, sizeof i);
        break;
    }
    case ROW_LONG: {
        long l = (long)get_signed(r, LONG_MIN, LONG_MAX);
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
        packed += isk__snap_row_bytes[rows[i].type];
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
    isk__snap_rows_in(isk__snap_group_rows, isk__snap_ngroup_rows, packed, &g);
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

/* The probes: as many as the scene has, each ring within the file. */
static void get_probes(reader *r, isk_snapshot *snap, int nprobes)
{
    if (r->failed)
        return;
    if (get_u64(r) != (uint64_t)nprobes) {
        fail(r, "its probes do not match its scene");
        return;
    }
    int ring_n[ISK_EFFECT_MAX_PROBES] = {0};
    isk_probe_reading reading[ISK_EFFECT_MAX_PROBES];
    int head[ISK_EFFECT_MAX_PROBES], used[ISK_EFFECT_MAX_PROBES];
    size_t ring_at[ISK_EFFECT_MAX_PROBES];
    for (int i = 0; i < nprobes && !r->failed; i++) {
        memset(&reading[i], 0, sizeof reading[i]);
        reading[i].kind = (isk_probe_kind)get_count(r, ISK_PROBE_KIND_COUNT - 1, "a probe of no kind");
        for (int k = 0; k < isk__snap_nreading_rows; k++)
            get_row(r, isk__snap_reading_rows[k].type, (unsigned char *)&reading[i] + isk__snap_reading_rows[k].offset);
        for (int k = 0; k < ISK_PROBE_MAX_BINS; k++)
            reading[i].bin[k] = (size_t)get_count(r, SIZE_MAX, "a count too large");
        ring_n[i] = (int)get_count(r, (r->n - r->at) / 24, "a probe's window beyond the file");
        head[i] = (int)get_count(r, ring_n[i] ? (uint64_t)ring_n[i] - 1 : 0, "a probe's window out of range");
        used[i] = (int)get_count(r, (uint64_t)ring_n[i], "a probe's window out of range");
        ring_at[i] = r->at;
        r->at += (size_t)ring_n[i] * 24 <= r->n - r->at ? (size_t)ring_n[i] * 24 : 0;
    }
    if (r->failed || isk__snap_probes_new(snap, nprobes, ring_n) != ISK_OK) {
        if (!r->failed) {
            isk_error_set(r->err, ISK_ERR_NOMEM, "%s: out of memory", r->name);
            r->failed = 1;
        }
        return;
    }
    const size_t end = r->at;
    for (int i = 0; i < nprobes && !r->failed; i++) {
        snap_probe *q = &snap->probes[i];
        q->r = reading[i];
        q->ring_head = head[i];
        q->ring_used = used[i];
        r->at = ring_at[i];
        for (int k = 0; k < 2 * q->ring_n; k++)
            q->ring[k] = get_u64(r);
        for (int k = 0; k < q->ring_n && !r->failed; k++)
            if (!((q->ring_t[k] = get_f64(r, 0)) >= 0))
                fail(r, "a frame of negative length");
    }
    r->at = end;
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
    unsigned char effect_state[64]; /* isk__snap_effect_rows, packed: 2 longs and 4 doubles */
    get_rows(&r, isk__snap_effect_rows, isk__snap_neffect_rows, effect_state);
    size_t npots_def = 0;
    for (int i = 0; i < def.nforces; i++)
        npots_def += def.forces[i].kind == ISK_FORCE_POTENTIAL;
    const size_t npots = (size_t)get_count(&r, npots_def, "more potentials than its scene has");
    isk_snapshot *snap = r.failed ? NULL : isk__snap_new(def.nemitters, npots);
    if (!snap) {
        isk_effect_def_free(&def);
        return r.failed ? ISK_ERR_FORMAT : isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", name);
    }
    isk_effect_def_free(&snap->def);
    snap->def = def;
    memcpy(snap->effect_state, effect_state, isk__snap_rows_size(isk__snap_effect_rows, isk__snap_neffect_rows));
    for (size_t k = 0; k < npots && !r.failed; k++) {
        isk_potential *p = &snap->pots[k];
        for (int i = 0; i < isk__snap_npot_rows; i++)
            get_row(&r, isk__snap_potential_rows[i].type, (unsigned char *)p + isk__snap_potential_rows[i].offset);
        snap->pot_force[k] = (int)get_count(&r, (uint64_t)(def.nforces - 1), "a potential of no force");
        if (!r.failed && def.forces[snap->pot_force[k]].kind != ISK_FORCE_POTENTIAL)
            fail(&r, "a potential of a force that is not one");
        check_potential(&r, p);
    }
    if (get_u64(&r) != (uint64_t)def.nemitters)
        fail(&r, "its emitters do not match its scene");
    for (int i = 0; i < def.nemitters && !r.failed; i++) {
        snap_group *sg = &snap->groups[i];
        get_rows(&r, isk__snap_group_rows, isk__snap_ngroup_rows, sg->state);
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
    get_probes(&r, snap, def.nprobes);
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
