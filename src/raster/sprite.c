/* SPDX-License-Identifier: MIT */
/* Baked round sprites, their cache, and drawing them.
 * Kinds, snapping rule and cache policy are documented in iskra/sprite.h. */
#include "iskra/sprite.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "raster/span.h"
#include "raster/sprite_rows.h"
#include "raster/sprite_loops.h"

double isk_sprite_alpha(isk_sprite_kind kind, double d, int size)
{
    if (!(size > 0) || !(d >= 0.0))
        return 0.0;
    double r = 2.0 * d / size;
    switch (kind) {
    case ISK_SPRITE_DISC: return r < 1.0 ? 1.0 : 0.0;
    case ISK_SPRITE_LINEAR: return r < 1.0 ? 1.0 - r : 0.0;
    case ISK_SPRITE_SMOOTH: return r < 1.0 ? (1.0 - r * r) * (1.0 - r * r) : 0.0;
    default: break;
    }
    return 0.0;
}

const char *const isk_sprite_kind_names[ISK_SPRITE_KIND_COUNT] = {"disc", "linear", "smooth"};

/* Mask value for q = (2 dx)^2 + (2 dy)^2 = 4 d^2, integer. */
static uint8_t mask_value(isk_sprite_kind kind, int64_t q, int64_t S)
{
    int64_t s2 = S * S;
    if (q >= s2)
        return 0;
    switch (kind) {
    case ISK_SPRITE_DISC:
        return 255;
    case ISK_SPRITE_LINEAR: {
        /* 255 (1 - sqrt(q)/S), halves up; sqrt is correctly rounded, so
         * this is the same on every IEEE machine. */
        double v = 255.0 - 255.0 * sqrt((double)q) / (double)S;
        return (uint8_t)floor(v + 0.5);
    }
    case ISK_SPRITE_SMOOTH: {
        /* 255 (s2 - q)^2 / S^4 rounded half up, exactly: S^4 <= 2^32. */
        uint64_t num = (uint64_t)(s2 - q) * (uint64_t)(s2 - q);
        uint64_t den = (uint64_t)s2 * (uint64_t)s2;
        return (uint8_t)((255u * num * 2u + den) / (2u * den));
    }
    default:
        break;
    }
    return 0;
}

static void bake_phase(isk_sprite *s, int p)
{
    int S = s->size;
    int hx = p & 1, hy = p >> 1; /* centre half a pixel right / down */
    uint8_t *m = s->mask[p];
    uint16_t *span = s->span[p];
    for (int j = 0; j < S; j++) {
        int64_t dy2 = 2 * j + 1 - S - hy; /* 2 dy */
        int first = S, last = 0;
        for (int i = 0; i < S; i++) {
            int64_t dx2 = 2 * i + 1 - S - hx;
            uint8_t v = mask_value(s->kind, dx2 * dx2 + dy2 * dy2, S);
            m[(size_t)j * (size_t)S + (size_t)i] = v;
            if (v) {
                if (i < first)
                    first = i;
                last = i + 1;
            }
        }
        if (first > last)
            first = last = 0;
        span[2 * j] = (uint16_t)first;
        span[2 * j + 1] = (uint16_t)last;
        /* The padded span: grown over zero-mask pixels of the row to a
         * multiple of 4 pixels, the row kernels' step (coverage 0 changes
         * nothing, so the bytes are the same). */
        int len = last - first, g = (len + 3) & ~3;
        if (first + g <= S)
            last = first + g;
        else if (last - g >= 0)
            first = last - g;
        else
            first = 0, last = S;
        if (len == 0)
            first = last = 0;
        s->vspan[p][2 * j] = (uint16_t)first;
        s->vspan[p][2 * j + 1] = (uint16_t)last;
    }
}

isk_status isk_sprite_init(isk_sprite *s, isk_sprite_kind kind, int size, isk_color color)
{
    if (!s)
        return ISK_ERR_NULL;
    if (kind != ISK_SPRITE_DISC && kind != ISK_SPRITE_LINEAR && kind != ISK_SPRITE_SMOOTH)
        return ISK_ERR_RANGE;
    if (size < 1 || size > ISK_SPRITE_MAX_SIZE)
        return ISK_ERR_SIZE;
    size_t area = (size_t)size * (size_t)size;
    size_t span_bytes = 2u * (size_t)size * sizeof(uint16_t);
    /* one block: four span and four padded-span tables first (alignment),
     * then four masks, then four increment images */
    uint8_t *block = malloc(4u * (2u * span_bytes + area + 4u * area));
    if (!block)
        return ISK_ERR_NOMEM;
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->size = size;
    s->color = color;
    for (int p = 0; p < 4; p++) {
        s->span[p] = (uint16_t *)(void *)(block + (size_t)p * span_bytes);
        s->vspan[p] = (uint16_t *)(void *)(block + (size_t)(4 + p) * span_bytes);
        s->mask[p] = block + 8u * span_bytes + (size_t)p * area;
        s->inc[p] = block + 4u * (2u * span_bytes + area) + (size_t)p * 4u * area;
        bake_phase(s, p);
    }
    for (uint32_t m = 0; m < 256u; m++) {
        uint32_t a = isk_div255((uint32_t)color.a * m);
        s->lut[m][0] = (uint8_t)isk_div255((uint32_t)color.r * a);
        s->lut[m][1] = (uint8_t)isk_div255((uint32_t)color.g * a);
        s->lut[m][2] = (uint8_t)isk_div255((uint32_t)color.b * a);
        s->lut[m][3] = (uint8_t)a;
    }
    for (int p = 0; p < 4; p++)
        for (size_t k = 0; k < area; k++)
            memcpy(s->inc[p] + 4u * k, s->lut[s->mask[p][k]], 4);
    return ISK_OK;
}

void isk_sprite_free(isk_sprite *s)
{
    if (!s)
        return;
    free(s->span[0]); /* the block starts with span[0] */
    memset(s, 0, sizeof *s);
}

/* 2 * (nearest multiple of 1/2 to v), halves up, computed without the
 * rounding of 2v + 0.5, for |v| < 2^20 (so floor is an int conversion). */
static inline int twice_snapped(double v)
{
    double t = 2.0 * v;
    int h = (int)t;
    h -= (double)h > t;  /* floor */
    return h + (t - h >= 0.5);
}

/* Where the sprite lands (sprite_loops.h's placement). */
static inline int place(const isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode,
                        placement *pl)
{
    if (!c || !c->pixels || !s || !s->mask[0])
        return 0;
    if (mode != ISK_BLEND_REPLACE && mode != ISK_BLEND_OVER && mode != ISK_BLEND_ADD)
        return 0;
    /* Anything this far out is off every canvas (<= 16384 px, S <= 256);
     * the test also rejects NaN and Inf before any conversion. */
    if (!(cx > -1e6 && cx < 1e6 && cy > -1e6 && cy < 1e6))
        return 0;
    int S = s->size;
    int tx = twice_snapped(cx) - S, ty = twice_snapped(cy) - S; /* 2 * mask origin */
    int ox = tx >> 1, oy = ty >> 1; /* floor(tx / 2): arithmetic shift */
    if (!(ox > -S && ox < c->width && oy > -S && oy < c->height))
        return 0;
    pl->x0 = ox;
    pl->y0 = oy;
    pl->p = (tx & 1) + 2 * (ty & 1);
    pl->jb = pl->y0 < 0 ? -pl->y0 : 0;
    pl->je = c->height - pl->y0 < S ? c->height - pl->y0 : S;
    pl->ib = pl->x0 < 0 ? -pl->x0 : 0;
    pl->ie = c->width - pl->x0 < S ? c->width - pl->x0 : S;
    return 1;
}

/* The rows in the portable build (raster/sprite_loops.h); sprite_avx2.c
 * has the AVX2 one. */
SPRITE_ROWS(rows_base, static, isk__span_cov, isk__span_add_bytes, isk__span_add_bytes16, NULL, NULL, SRC_MASK)

static void rows(const isk_canvas *c, const isk_sprite *s, const placement *pl, isk_color col, int kind,
                 isk_blend mode)
{
#if ISK__CPU_AVX2
    if (isk__have_avx2()) { /* 8 pixels a step (sprite_avx2.c) */
        isk__sprite_rows_avx2(c, s, pl, col, kind, mode);
        return;
    }
#endif
    rows_base(c, s, pl, col, kind, mode);
}

/* The sprite cut to the rows [r0, r1): the placement on the whole canvas,
 * then its row range narrowed (raster/sprite_rows.h). */
void isk__draw_sprite_rows(isk_canvas *c, const isk_sprite *s, double cx, double cy, const isk_color *tint,
                           isk_blend mode, int r0, int r1)
{
    placement pl;
    if (!place(c, s, cx, cy, mode, &pl))
        return;
    if (r0 - pl.y0 > pl.jb)
        pl.jb = r0 - pl.y0;
    if (r1 - pl.y0 < pl.je)
        pl.je = r1 - pl.y0;
    if (pl.jb >= pl.je)
        return;
    if (tint)
        rows(c, s, &pl, *tint, SRC_MASK, mode);
    else
        rows(c, s, &pl, s->color,
             mode == ISK_BLEND_ADD ? SRC_INC_ADD : mode == ISK_BLEND_OVER ? SRC_INC_OVER : SRC_MASK, mode);
}

void isk_draw_sprite_tinted(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_color color,
                            isk_blend mode)
{
    isk__draw_sprite_rows(c, s, cx, cy, &color, mode, 0, c ? c->height : 0);
}

void isk_draw_sprite(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode)
{
    /* additive: the premade increments; over and replace: the baked colour
     * through the mask */
    isk__draw_sprite_rows(c, s, cx, cy, NULL, mode, 0, c ? c->height : 0);
}

/* ---- cache ------------------------------------------------------------- */

typedef struct slot {
    uint64_t key;
    isk_sprite *sprite; /* NULL: empty */
} slot;

struct isk_sprite_cache {
    int capacity;
    int count;
    long bakes;
    size_t nslots;    /* power of two >= 2 * capacity */
    slot *slots;
    isk_sprite *items; /* capacity entries, never moved: pointers stay valid */
};

static uint64_t make_key(isk_sprite_kind kind, int size, isk_color c)
{
    uint64_t rgba = (uint64_t)c.r | (uint64_t)c.g << 8 | (uint64_t)c.b << 16 | (uint64_t)c.a << 24;
    return (uint64_t)kind | (uint64_t)size << 2 | rgba << 11;
}

static size_t hash_key(uint64_t k, size_t mask)
{
    k ^= k >> 29;
    k *= 0x9E3779B97F4A7C15ull;
    return (size_t)(k >> 32) & mask;
}

isk_status isk_sprite_cache_create(isk_sprite_cache **out, int capacity)
{
    if (!out)
        return ISK_ERR_NULL;
    *out = NULL;
    if (capacity < 1 || capacity > ISK_SPRITE_CACHE_MAX)
        return ISK_ERR_SIZE;
    isk_sprite_cache *c = calloc(1, sizeof *c);
    if (!c)
        return ISK_ERR_NOMEM;
    size_t n = 4;
    while (n < 2u * (size_t)capacity)
        n *= 2;
    c->slots = calloc(n, sizeof *c->slots);
    c->items = calloc((size_t)capacity, sizeof *c->items);
    if (!c->slots || !c->items) {
        free(c->slots);
        free(c->items);
        free(c);
        return ISK_ERR_NOMEM;
    }
    c->capacity = capacity;
    c->nslots = n;
    *out = c;
    return ISK_OK;
}

void isk_sprite_cache_clear(isk_sprite_cache *c)
{
    if (!c)
        return;
    for (int i = 0; i < c->count; i++)
        isk_sprite_free(&c->items[i]);
    memset(c->slots, 0, c->nslots * sizeof *c->slots);
    c->count = 0;
}

void isk_sprite_cache_destroy(isk_sprite_cache *c)
{
    if (!c)
        return;
    isk_sprite_cache_clear(c);
    free(c->slots);
    free(c->items);
    free(c);
}

isk_status isk_sprite_cache_get(isk_sprite_cache *c, isk_sprite_kind kind, int size, isk_color color,
                                const isk_sprite **out)
{
    if (!c || !out)
        return ISK_ERR_NULL;
    if (kind != ISK_SPRITE_DISC && kind != ISK_SPRITE_LINEAR && kind != ISK_SPRITE_SMOOTH)
        return ISK_ERR_RANGE;
    if (size < 1 || size > ISK_SPRITE_MAX_SIZE)
        return ISK_ERR_SIZE;
    uint64_t key = make_key(kind, size, color);
    size_t mask = c->nslots - 1u, h = hash_key(key, mask);
    while (c->slots[h].sprite) { /* load <= 1/2, so an empty slot exists */
        if (c->slots[h].key == key) {
            *out = c->slots[h].sprite;
            return ISK_OK;
        }
        h = (h + 1u) & mask;
    }
    if (c->count >= c->capacity)
        return ISK_ERR_FULL;
    isk_sprite *s = &c->items[c->count];
    isk_status st = isk_sprite_init(s, kind, size, color);
    if (st != ISK_OK)
        return st;
    c->count++;
    c->bakes++;
    c->slots[h].key = key;
    c->slots[h].sprite = s;
    *out = s;
    return ISK_OK;
}

int isk_sprite_cache_count(const isk_sprite_cache *c)
{
    return c ? c->count : 0;
}

long isk_sprite_cache_bakes(const isk_sprite_cache *c)
{
    return c ? c->bakes : 0;
}
