/* SPDX-License-Identifier: MIT */
/* Particle store: SoA arrays, geometric growth, O(1) removal. */
#include "iskra/particles.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/limits.h"
#include "sim/store_internal.h"

enum { ALIGN = 64 };

/* All arrays live in one block, each 64-byte aligned and each shifted by a
 * further 17 cache lines from the previous one.  Separate large allocations
 * come back 8 MiB (+4 KiB) apart, all at the same offset within their
 * 2 MiB regions; the stage loops then stream x[i], y[i], vx[i], vy[i] from
 * addresses that collide in DRAM banks and cache sets, and run much slower
 * than over staggered arrays (docs/performance.md, "Where the constants
 * come from"). */
enum { STAGGER = 17 * ALIGN };

static size_t round_up(size_t bytes)
{
    return (bytes + ALIGN - 1) / ALIGN * ALIGN;
}

/* Every array of the store: where its pointer lives in isk_particles, the
 * size of one element (0: the trail's, trail_len points of two doubles) and
 * the flag that asks for it (0: always there).
 * Growth, removal and culling walk this table, so a new column is one row. */
typedef struct column {
    size_t field;
    size_t elem;
    unsigned flag;
} column;

#define COL(f, type, flag) {offsetof(isk_particles, f), sizeof(type), flag}
static const column columns[] = {
    COL(x, double, 0),         COL(y, double, 0),         COL(vx, double, 0),
    COL(vy, double, 0),        COL(m, double, 0),         COL(age, double, 0),
    COL(life, double, 0),      COL(size, double, ISK_PARTICLES_SIZE),
    COL(color, isk_color, ISK_PARTICLES_COLOR),
    COL(osc_amp, double, ISK_PARTICLES_OSC),   COL(osc_phase, double, ISK_PARTICLES_OSC),
    COL(osc_omega, double, ISK_PARTICLES_OSC), COL(osc_offset, double, ISK_PARTICLES_OSC),
    /* looks */
    COL(angle, double, ISK_PARTICLES_ANGLE),   COL(spin, double, ISK_PARTICLES_ANGLE),
    /* ---- sub-emitters and trails ---- */
    COL(hit, unsigned char, ISK_PARTICLES_HIT), {offsetof(isk_particles, trail), 0, ISK_PARTICLES_TRAIL},
    /* ---- end of sub-emitters and trails ---- */
    COL(frame0, uint16_t, ISK_PARTICLES_FRAME),
    /* per-particle ranges of the motion */
    COL(radial_extra, double, ISK_PARTICLES_RADIAL), COL(tangential_extra, double, ISK_PARTICLES_TANGENTIAL),
    COL(wind_x, double, ISK_PARTICLES_WIND),         COL(wind_y, double, ISK_PARTICLES_WIND),
    COL(slowing_extra, double, ISK_PARTICLES_SLOWING),
};
#undef COL
enum { NCOLUMNS = sizeof columns / sizeof columns[0], AGE_COLUMN = 5, LIFE_COLUMN = 6 };

/* Bytes of one particle's element of column c in a store whose trail has
 * trail_len points. */
static size_t elem_of(const column *c, int trail_len)
{
    return c->elem ? c->elem : 2 * sizeof(double) * (size_t)(trail_len > 0 ? trail_len : 0);
}

/* The column's array (NULL when absent).  The pointer fields have different
 * types, so they are read and written as bytes. */
static unsigned char *col_get(const isk_particles *p, const column *c)
{
    void *a;
    memcpy(&a, (const unsigned char *)p + c->field, sizeof a);
    return a;
}

static void col_set(isk_particles *p, const column *c, void *a)
{
    memcpy((unsigned char *)p + c->field, &a, sizeof a);
}

static void free_arrays(isk_particles *p)
{
    free(p->block);
    p->block = NULL;
}

/* The bytes of one block of arrays for `cap` particles; 0 when they are
 * more than half of what size_t counts (a 32-bit system: 2^28 particles
 * with a trail of 64 points would need 2^38 bytes, which the product would
 * wrap to a small number). */
static size_t block_bytes(size_t cap, unsigned flags, int trail_len)
{
    size_t total = ALIGN;
    for (int k = 0; k < NCOLUMNS; k++)
        if (!columns[k].flag || (flags & columns[k].flag)) {
            size_t elem = elem_of(&columns[k], trail_len);
            if (elem && (total > SIZE_MAX / 2 || cap > (SIZE_MAX / 2 - total) / elem))
                return 0;
            total += round_up(cap * elem) + STAGGER;
        }
    return round_up(total);
}

/* Lays the arrays of `cap` particles out in one block (NULL on failure). */
static void *alloc_arrays(isk_particles *n, size_t cap, unsigned flags)
{
    size_t bytes = block_bytes(cap, flags, n->trail_len);
    unsigned char *block = bytes ? aligned_alloc(ALIGN, bytes) : NULL;
    if (!block)
        return NULL;
    size_t off = 0;
    for (int k = 0; k < NCOLUMNS; k++) {
        const column *c = &columns[k];
        if (c->flag && !(flags & c->flag)) {
            col_set(n, c, NULL);
            continue;
        }
        col_set(n, c, block + off);
        off += round_up(cap * elem_of(c, n->trail_len)) + STAGGER;
    }
    n->block = block;
    return block;
}

isk_status isk_particles_init(isk_particles *p, size_t capacity, unsigned flags)
{
    if (!p)
        return ISK_ERR_NULL;
    memset(p, 0, sizeof *p);
    p->default_color = ISK_YELLOW;
    p->default_size = 0.1;
    if (flags & ~(unsigned)ISK_PARTICLES_FLAGS)
        return ISK_ERR_SIZE; /* the trail comes with its length: isk_particles_set_trail */
    p->flags = flags;
    return isk_particles_reserve(p, capacity);
}

void isk_particles_free(isk_particles *p)
{
    if (!p)
        return;
    free_arrays(p);
    unsigned flags = p->flags;
    isk_color dc = p->default_color;
    double ds = p->default_size;
    int tl = p->trail_len;
    memset(p, 0, sizeof *p);
    p->flags = flags;
    p->trail_len = tl;
    p->default_color = dc;
    p->default_size = ds;
}

size_t isk_particles_bytes(size_t count, unsigned flags)
{
    return isk_particles_bytes_trail(count, flags & ~(unsigned)ISK_PARTICLES_TRAIL, 0);
}

size_t isk_particles_bytes_trail(size_t count, unsigned flags, int points)
{
    if (count > ISK_PARTICLES_MAX || points < 0 || points > ISK_TRAIL_MAX)
        return 0;
    size_t cap = 64, prev = 0;
    while (cap < count) {
        prev = cap;
        cap *= 2;
    }
    if (cap > ISK_PARTICLES_MAX)
        cap = ISK_PARTICLES_MAX;
    size_t now = block_bytes(cap, flags, points), before = prev ? block_bytes(prev, flags, points) : 0;
    return !now || (prev && !before) || before > SIZE_MAX - now ? 0 : now + before;
}

isk_status isk_particles_reserve(isk_particles *p, size_t capacity)
{
    if (!p)
        return ISK_ERR_NULL;
    if (capacity > ISK_PARTICLES_MAX)
        return ISK_ERR_SIZE;
    if (capacity <= p->capacity && p->x)
        return ISK_OK;
    size_t cap = p->capacity ? p->capacity : 64;
    while (cap < capacity)
        cap *= 2;
    if (cap > ISK_PARTICLES_MAX)
        cap = ISK_PARTICLES_MAX;

    /* Allocate everything first: on failure the store is untouched. */
    isk_particles n = *p;
    if (!alloc_arrays(&n, cap, p->flags))
        return ISK_ERR_NOMEM;
    for (int k = 0; p->count && k < NCOLUMNS; k++) {
        unsigned char *dst = col_get(&n, &columns[k]);
        if (dst)
            memcpy(dst, col_get(p, &columns[k]), p->count * elem_of(&columns[k], p->trail_len));
    }
    free_arrays(p);
    n.capacity = cap;
    *p = n;
    return ISK_OK;
}

/* The value a new particle gets in column k (one element at dst). */
static void column_default(const isk_particles *p, int k, unsigned char *dst)
{
    if (columns[k].field == offsetof(isk_particles, color))
        memcpy(dst, &p->default_color, sizeof p->default_color);
    else if (columns[k].field == offsetof(isk_particles, size))
        memcpy(dst, &p->default_size, sizeof p->default_size);
    else
        memset(dst, 0, columns[k].elem); /* all-bits-zero is +0.0 */
}

isk_status isk_particles_add_columns(isk_particles *p, unsigned flags)
{
    if (!p)
        return ISK_ERR_NULL;
    if (flags & ~(unsigned)ISK_PARTICLES_FLAGS)
        return ISK_ERR_SIZE; /* the trail comes with its length: isk_particles_set_trail */
    unsigned want = p->flags | flags;
    if (want == p->flags && p->x)
        return ISK_OK;
    isk_particles n = *p;
    n.flags = want;
    size_t cap = p->capacity ? p->capacity : 64;
    if (!alloc_arrays(&n, cap, want))
        return ISK_ERR_NOMEM;
    for (int k = 0; k < NCOLUMNS; k++) {
        unsigned char *dst = col_get(&n, &columns[k]), *src = col_get(p, &columns[k]);
        if (!dst)
            continue;
        if (src && p->x) {
            memcpy(dst, src, p->count * elem_of(&columns[k], p->trail_len));
        } else {
            for (size_t i = 0; i < p->count; i++)
                column_default(p, k, dst + i * columns[k].elem);
        }
    }
    free_arrays(p);
    n.capacity = cap;
    *p = n;
    return ISK_OK;
}

isk_status isk__store_grow_for(isk_particles *p, size_t extra)
{
    if (extra > ISK_PARTICLES_MAX - p->count)
        return ISK_ERR_SIZE;
    return isk_particles_reserve(p, p->count + extra);
}

size_t isk__store_push(isk_particles *p, double x, double y, double vx, double vy, double m)
{
    size_t i = p->count++;
    p->x[i] = x;
    p->y[i] = y;
    p->vx[i] = vx;
    p->vy[i] = vy;
    p->m[i] = m;
    p->age[i] = 0.0;
    p->life[i] = INFINITY;
    if (p->size)
        p->size[i] = p->default_size;
    if (p->color)
        p->color[i] = p->default_color;
    if (p->osc_amp) {
        p->osc_amp[i] = 0.0;
        p->osc_phase[i] = 0.0;
        p->osc_omega[i] = 0.0;
        p->osc_offset[i] = 0.0;
    }
    if (p->angle) {
        p->angle[i] = 0.0;
        p->spin[i] = 0.0;
    }
    if (p->hit)
        p->hit[i] = 0;
    if (p->frame0)
        p->frame0[i] = 0;
    if (p->radial_extra)
        p->radial_extra[i] = 0.0;
    if (p->tangential_extra)
        p->tangential_extra[i] = 0.0;
    if (p->wind_x) {
        p->wind_x[i] = 0.0;
        p->wind_y[i] = 0.0;
    }
    if (p->slowing_extra)
        p->slowing_extra[i] = 0.0;
    if (p->trail) {
        double *t = p->trail + 2 * (size_t)p->trail_len * i;
        for (int k = 0; k < p->trail_len; k++) {
            t[2 * k] = x;
            t[2 * k + 1] = y;
        }
    }
    return i;
}

isk_status isk_particles_add(isk_particles *p, double x, double y, double vx, double vy, double m,
                             size_t *index)
{
    if (!p)
        return ISK_ERR_NULL;
    if (!isfinite(x) || !isfinite(y) || !isfinite(vx) || !isfinite(vy) || !isfinite(m))
        return ISK_ERR_NAN;
    if (!(m > 0.0))
        return ISK_ERR_RANGE;
    isk_status s = isk__store_grow_for(p, 1);
    if (s != ISK_OK)
        return s;
    size_t i = isk__store_push(p, x, y, vx, vy, m);
    if (index)
        *index = i;
    return ISK_OK;
}

void isk_particles_remove(isk_particles *p, size_t i)
{
    if (!p || i >= p->count)
        return;
    size_t last = p->count - 1;
    for (int k = 0; i != last && k < NCOLUMNS; k++) {
        unsigned char *a = col_get(p, &columns[k]);
        size_t e = elem_of(&columns[k], p->trail_len);
        if (a)
            memcpy(a + i * e, a + last * e, e);
    }
    p->count = last;
}

/* What a compaction removes: dead particles (age >= life) or particles
 * whose state is not finite. */
enum { DROP_DEAD = 0, DROP_NONFINITE = 1 };

static int drops(const isk_particles *p, size_t r, const int what)
{
    if (what == DROP_DEAD)
        return p->age[r] >= p->life[r]; /* NaN ages and lives are kept, as a live particle's */
    return !(isfinite(p->x[r]) && isfinite(p->y[r]) && isfinite(p->vx[r]) && isfinite(p->vy[r]) &&
             isfinite(p->m[r]) && isfinite(p->age[r]) && !isnan(p->life[r]));
}

/* Removes the particles `drops` picks, keeping the order of the others:
 * column by column from the first one removed. */
static inline size_t compact(isk_particles *p, const int what, size_t *first_moved)
{
    const size_t n = p->count;
    size_t first = 0;
    while (first < n && !drops(p, first, what))
        first++;
    *first_moved = first;
    if (first == n)
        return 0;
    /* Every present column, gathered once: the double columns (age and life
     * last, since they decide who stays) and any other. */
    double *dcol[NCOLUMNS];
    unsigned char *ocol[NCOLUMNS];
    size_t oel[NCOLUMNS];
    int nd = 0, no = 0;
    for (int k = 0; k < NCOLUMNS; k++) {
        unsigned char *a = col_get(p, &columns[k]);
        if (!a || k == AGE_COLUMN || k == LIFE_COLUMN)
            continue;
        if (columns[k].elem == sizeof(double)) {
            dcol[nd++] = (double *)(void *)a;
        } else {
            oel[no] = elem_of(&columns[k], p->trail_len);
            ocol[no++] = a;
        }
    }
    double *pa = p->age, *pl = p->life;
    size_t w = first;
    for (size_t r = first; r < n; r++) {
        if (drops(p, r, what))
            continue;
        for (int k = 0; k < nd; k++)
            dcol[k][w] = dcol[k][r];
        for (int k = 0; k < no; k++)
            memcpy(ocol[k] + w * oel[k], ocol[k] + r * oel[k], oel[k] == 4 ? 4 : oel[k]);
        pa[w] = pa[r];
        pl[w] = pl[r];
        w++;
    }
    p->count = w;
    return n - w;
}

size_t isk_particles_cull(isk_particles *p)
{
    size_t first;
    return p ? compact(p, DROP_DEAD, &first) : 0;
}

size_t isk_particles_remove_nonfinite(isk_particles *p)
{
    size_t first;
    return p ? compact(p, DROP_NONFINITE, &first) : 0;
}

size_t isk__store_remove_nonfinite(isk_particles *p, size_t *first_moved)
{
    return compact(p, DROP_NONFINITE, first_moved);
}

/* Moves particle r into slot w, every present column. */
static void move_row(isk_particles *p, size_t w, size_t r)
{
    for (int k = 0; k < NCOLUMNS; k++) {
        unsigned char *a = col_get(p, &columns[k]);
        size_t e = elem_of(&columns[k], p->trail_len);
        if (a)
            memcpy(a + w * e, a + r * e, e);
    }
}

static size_t cull_unordered(isk_particles *p, size_t *first_moved)
{
    const double *age = p->age, *life = p->life;
    size_t n = p->count, i = 0;
    *first_moved = n;
    while (i < n) {
        if (!(age[i] >= life[i])) { /* NaN ages and lives are kept, as a live particle's */
            i++;
            continue;
        }
        if (*first_moved == p->count)
            *first_moved = i;
        while (n > i + 1 && age[n - 1] >= life[n - 1])
            n--; /* dead at the end: dropped where they lie */
        if (n > i + 1)
            move_row(p, i, n - 1);
        n--;
        i++;
    }
    size_t removed = p->count - n;
    p->count = n;
    return removed;
}

size_t isk_particles_cull_unordered(isk_particles *p)
{
    size_t first;
    return p ? cull_unordered(p, &first) : 0;
}

size_t isk__store_cull(isk_particles *p, int unordered, size_t *first_moved)
{
    return unordered ? cull_unordered(p, first_moved) : compact(p, DROP_DEAD, first_moved);
}

void isk_particles_age(isk_particles *p, size_t begin, size_t end, double dt)
{
    if (!p)
        return;
    if (end > p->count)
        end = p->count; /* never past the particles there are */
    double *restrict age = p->age;
    for (size_t i = begin; i < end; i++)
        age[i] = age[i] + dt;
}

void isk_particles_clear(isk_particles *p)
{
    if (p)
        p->count = 0;
}

/* ---- sub-emitters and trails ---------------------------------------- */

isk_status isk_particles_set_trail(isk_particles *p, int points)
{
    if (!p)
        return ISK_ERR_NULL;
    if (points < 0 || points > ISK_TRAIL_MAX)
        return ISK_ERR_RANGE;
    if (points == p->trail_len && (points == 0 || p->trail))
        return ISK_OK;
    isk_particles n = *p;
    n.flags = points ? p->flags | ISK_PARTICLES_TRAIL : p->flags & ~(unsigned)ISK_PARTICLES_TRAIL;
    n.trail_len = points;
    n.trail_head = 0;
    size_t cap = p->capacity ? p->capacity : 64;
    if (!alloc_arrays(&n, cap, n.flags))
        return ISK_ERR_NOMEM;
    for (int k = 0; k < NCOLUMNS; k++) {
        unsigned char *dst = col_get(&n, &columns[k]), *src = col_get(p, &columns[k]);
        if (dst && src && columns[k].elem && p->x)
            memcpy(dst, src, p->count * columns[k].elem);
    }
    for (size_t i = 0; n.trail && i < p->count; i++)
        for (int k = 0; k < points; k++) {
            n.trail[2 * (size_t)points * i + 2 * (size_t)k] = p->x[i];
            n.trail[2 * (size_t)points * i + 2 * (size_t)k + 1] = p->y[i];
        }
    free_arrays(p);
    n.capacity = cap;
    *p = n;
    return ISK_OK;
}

void isk_particles_record_trail(isk_particles *p)
{
    if (!p || !p->trail || p->trail_len <= 0)
        return;
    const size_t len = (size_t)p->trail_len;
    p->trail_head = (p->trail_head + 1) % p->trail_len;
    double *t = p->trail + 2 * (size_t)p->trail_head;
    for (size_t i = 0; i < p->count; i++, t += 2 * len) {
        t[0] = p->x[i];
        t[1] = p->y[i];
    }
}

isk_status isk_particles_copy(isk_particles *dst, const isk_particles *src)
{
    if (!dst || !src)
        return ISK_ERR_NULL;
    isk_particles n;
    isk_status s = isk_particles_init(&n, src->count, src->flags & ISK_PARTICLES_FLAGS);
    if (s == ISK_OK && src->trail_len > 0)
        s = isk_particles_set_trail(&n, src->trail_len);
    if (s != ISK_OK) {
        isk_particles_free(&n);
        return s;
    }
    for (int k = 0; src->count && k < NCOLUMNS; k++) {
        unsigned char *to = col_get(&n, &columns[k]);
        const unsigned char *from = col_get(src, &columns[k]);
        if (to && from)
            memcpy(to, from, src->count * elem_of(&columns[k], src->trail_len));
    }
    n.count = src->count;
    n.trail_head = src->trail_head;
    n.default_color = src->default_color;
    n.default_size = src->default_size;
    isk_particles_free(dst);
    *dst = n;
    return ISK_OK;
}

size_t isk__store_columns(const isk_particles *p, isk__store_column *out)
{
    size_t n = 0;
    for (int k = 0; k < NCOLUMNS; k++) {
        unsigned char *a = col_get(p, &columns[k]);
        if (!a)
            continue;
        out[n].bytes = a;
        out[n].elem = elem_of(&columns[k], p->trail_len);
        out[n].doubles = columns[k].elem == 0 || columns[k].elem == sizeof(double);
        out[n].life = k == LIFE_COLUMN;
        n++;
    }
    return n;
}
