/* Baked round sprites, their cache, and drawing them.
 * Kinds, snapping rule and cache policy are documented in iskra/sprite.h. */
#include "iskra/sprite.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "raster/span_simd.h"

double isk_sprite_alpha(isk_sprite_kind kind, double d, int size)
{
    if (!(size > 0) || !(d >= 0.0))
        return 0.0;
    double r = 2.0 * d / size;
    switch (kind) {
    case ISK_SPRITE_DISC: return r < 1.0 ? 1.0 : 0.0;
    case ISK_SPRITE_LINEAR: return r < 1.0 ? 1.0 - r : 0.0;
    case ISK_SPRITE_SMOOTH: return r < 1.0 ? (1.0 - r * r) * (1.0 - r * r) : 0.0;
    }
    return 0.0;
}

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
    /* one block: four span tables first (alignment), then four masks, then
     * four increment images */
    uint8_t *block = malloc(4u * (span_bytes + area + 4u * area));
    if (!block)
        return ISK_ERR_NOMEM;
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->size = size;
    s->color = color;
    for (int p = 0; p < 4; p++) {
        s->span[p] = (uint16_t *)(void *)(block + (size_t)p * span_bytes);
        s->mask[p] = block + 4u * span_bytes + (size_t)p * area;
        s->inc[p] = block + 4u * (span_bytes + area) + (size_t)p * 4u * area;
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
 * rounding of 2v + 0.5; NaN/Inf pass through. */
static double twice_snapped(double v)
{
    double t = 2.0 * v;
    double h = floor(t);
    if (t - h >= 0.5)
        h += 1.0;
    return h;
}

/* Where the sprite lands: mask phase, origin and the clipped row/column
 * ranges.  0 when nothing is visible (or the input is NaN/Inf/huge). */
typedef struct placement {
    int p, x0, y0, jb, je, ib, ie;
} placement;

static int place(const isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode, placement *pl)
{
    if (!c || !c->pixels || !s || !s->mask[0])
        return 0;
    if (mode != ISK_BLEND_REPLACE && mode != ISK_BLEND_OVER && mode != ISK_BLEND_ADD)
        return 0;
    int S = s->size;
    double tx = twice_snapped(cx) - S, ty = twice_snapped(cy) - S; /* 2 * mask origin */
    double ox = floor(0.5 * tx), oy = floor(0.5 * ty);
    /* Rejects NaN, Inf and anything off-canvas before converting to int. */
    if (!(ox > -S && ox < c->width && oy > -S && oy < c->height))
        return 0;
    pl->x0 = (int)ox;
    pl->y0 = (int)oy;
    pl->p = (tx - 2.0 * ox != 0.0) + 2 * (ty - 2.0 * oy != 0.0);
    pl->jb = pl->y0 < 0 ? -pl->y0 : 0;
    pl->je = c->height - pl->y0 < S ? c->height - pl->y0 : S;
    pl->ib = pl->x0 < 0 ? -pl->x0 : 0;
    pl->ie = c->width - pl->x0 < S ? c->width - pl->x0 : S;
    return 1;
}

/* Rows of a sprite are a canvas stride apart, too far for the hardware
 * prefetcher: start loading the row a few ahead while blending this one. */
#define ROW_AHEAD 3

static inline void prefetch_row(const isk_canvas *c, const placement *pl, const uint16_t *span, int j)
{
#if defined(__GNUC__)
    if (j < pl->je) {
        int b = span[2 * j] > pl->ib ? span[2 * j] : pl->ib;
        int e = span[2 * j + 1] < pl->ie ? span[2 * j + 1] : pl->ie;
        if (b < e) {
            __builtin_prefetch(isk_canvas_at(c, pl->x0 + b, pl->y0 + j), 1);
            __builtin_prefetch(isk_canvas_at(c, pl->x0 + e - 1, pl->y0 + j), 1);
        }
    }
#else
    (void)c; (void)pl; (void)span; (void)j;
#endif
}

/* Each row is one span of the mask, blended by the row kernels of
 * raster/span_simd.h with the mode fixed for the whole sprite.  The baked
 * colour's additive increments are premade (inc), so an untinted additive
 * sprite is a saturating byte add of two arrays. */
void isk_draw_sprite_tinted(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_color color,
                            isk_blend mode)
{
    placement pl;
    if (!place(c, s, cx, cy, mode, &pl))
        return;
    const size_t S = (size_t)s->size;
    const uint8_t *mask = s->mask[pl.p];
    const uint16_t *span = s->span[pl.p];
    for (int j = pl.jb; j < pl.jb + ROW_AHEAD; j++)
        prefetch_row(c, &pl, span, j);
    for (int j = pl.jb; j < pl.je; j++) {
        prefetch_row(c, &pl, span, j + ROW_AHEAD);
        int b = span[2 * j] > pl.ib ? span[2 * j] : pl.ib;
        int e = span[2 * j + 1] < pl.ie ? span[2 * j + 1] : pl.ie;
        if (b >= e)
            continue;
        uint8_t *d = isk_canvas_at(c, pl.x0 + b, pl.y0 + j);
        isk__span_cov(d, mask + (size_t)j * S + (size_t)b, e - b, color, mode);
    }
}

void isk_draw_sprite(isk_canvas *c, const isk_sprite *s, double cx, double cy, isk_blend mode)
{
    if (mode != ISK_BLEND_ADD) { /* over and replace: the baked colour through the mask */
        if (s)
            isk_draw_sprite_tinted(c, s, cx, cy, s->color, mode);
        return;
    }
    placement pl;
    if (!place(c, s, cx, cy, mode, &pl))
        return;
    const size_t S = (size_t)s->size;
    const uint8_t *inc = s->inc[pl.p];
    const uint16_t *span = s->span[pl.p];
    for (int j = pl.jb; j < pl.jb + ROW_AHEAD; j++)
        prefetch_row(c, &pl, span, j);
    for (int j = pl.jb; j < pl.je; j++) {
        prefetch_row(c, &pl, span, j + ROW_AHEAD);
        int b = span[2 * j] > pl.ib ? span[2 * j] : pl.ib;
        int e = span[2 * j + 1] < pl.ie ? span[2 * j + 1] : pl.ie;
        if (b >= e)
            continue;
        uint8_t *d = isk_canvas_at(c, pl.x0 + b, pl.y0 + j);
        isk__span_add_bytes(d, inc + 4u * ((size_t)j * S + (size_t)b), 4 * (e - b));
    }
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
