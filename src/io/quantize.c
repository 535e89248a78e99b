/* SPDX-License-Identifier: MIT */
/* Per-frame palettes by exact colours or median cut (src/io/quantize.h). */
#include "io/quantize.h"

#include <stdlib.h>
#include <string.h>

#define MAX_COLORS 256
#define MAX_SLOTS ((size_t)1 << 25) /* > 2 x 2^24 distinct colours at most */

/* The hash table's slots: a power of two, at least twice the pixels. */
static size_t slots_for(size_t max_pixels)
{
    size_t slots = 1024;
    while (slots < 2 * max_pixels && slots < MAX_SLOTS)
        slots *= 2;
    return slots;
}

/* At most one entry per pixel, and there are 2^24 colours. */
static size_t entries_for(size_t max_pixels)
{
    return max_pixels < ((size_t)1 << 24) ? max_pixels : ((size_t)1 << 24);
}

isk_status isk__quant_init(isk__quant *q, size_t max_pixels)
{
    if (!q)
        return ISK_ERR_NULL;
    memset(q, 0, sizeof *q);
    if (max_pixels == 0 || max_pixels > (size_t)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM)
        return ISK_ERR_SIZE;
    size_t slots = slots_for(max_pixels), max_entries = entries_for(max_pixels);
    q->slots = malloc(slots * sizeof *q->slots);
    q->entries = malloc(max_entries * sizeof *q->entries);
    q->rgb = malloc(max_pixels * sizeof *q->rgb);
    if (!q->slots || !q->entries || !q->rgb) {
        isk__quant_free(q);
        return ISK_ERR_NOMEM;
    }
    q->nslots = slots;
    q->max_pixels = max_pixels;
    return ISK_OK;
}

void isk__quant_free(isk__quant *q)
{
    if (!q)
        return;
    free(q->slots);
    free(q->entries);
    free(q->rgb);
    memset(q, 0, sizeof *q);
}

static size_t slot_of(const isk__quant *q, uint32_t rgb)
{
    size_t mask = q->nslots - 1, h = (size_t)((rgb * 2654435761u) ^ (rgb >> 13)) & mask;
    while (q->slots[h] && q->entries[q->slots[h] - 1].rgb != rgb)
        h = (h + 1) & mask;
    return h;
}

/* Composited over black, rounded: r * a / 255. */
static uint32_t opaque_rgb(const uint8_t *p)
{
    uint32_t a = p[3];
    if (a == 255)
        return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
    uint32_t r = (p[0] * a + 127) / 255, g = (p[1] * a + 127) / 255, b = (p[2] * a + 127) / 255;
    return r << 16 | g << 8 | b;
}

static int channel(uint32_t rgb, int k)
{
    return (int)((rgb >> (16 - 8 * k)) & 0xffu);
}

/* Entries sorted by one channel (ch 0..2) or by colour (ch < 0): a copy
 * with a 64-bit key, so the comparator needs no context; ties are
 * impossible, since every key ends with the colour itself. */
typedef struct keyed {
    uint64_t key;
    isk__quant_entry e;
} keyed;

size_t isk__quant_bytes(size_t max_pixels)
{
    const size_t entries = entries_for(max_pixels);
    return slots_for(max_pixels) * sizeof(uint32_t) + entries * sizeof(isk__quant_entry) +
           max_pixels * sizeof(uint32_t) + entries * sizeof(keyed);
}

static int cmp_keyed(const void *a, const void *b)
{
    uint64_t x = ((const keyed *)a)->key, y = ((const keyed *)b)->key;
    return (x > y) - (x < y);
}

static isk_status sort_by(isk__quant_entry *e, size_t n, int ch)
{
    keyed *k = malloc(n * sizeof *k);
    if (!k)
        return ISK_ERR_NOMEM;
    for (size_t i = 0; i < n; i++) {
        k[i].key = ch < 0 ? e[i].rgb : ((uint64_t)channel(e[i].rgb, ch) << 24 | e[i].rgb);
        k[i].e = e[i];
    }
    qsort(k, n, sizeof *k, cmp_keyed);
    for (size_t i = 0; i < n; i++)
        e[i] = k[i].e;
    free(k);
    return ISK_OK;
}

typedef struct box {
    size_t lo, hi;      /* entries[lo..hi) */
    uint64_t count;     /* pixels */
    int ch, range;      /* the longest channel and its range */
} box;

static void measure(box *b, const isk__quant_entry *e)
{
    int mn[3] = {255, 255, 255}, mx[3] = {0, 0, 0};
    b->count = 0;
    for (size_t i = b->lo; i < b->hi; i++) {
        for (int k = 0; k < 3; k++) {
            int v = channel(e[i].rgb, k);
            mn[k] = v < mn[k] ? v : mn[k];
            mx[k] = v > mx[k] ? v : mx[k];
        }
        b->count += e[i].count;
    }
    b->ch = 0;
    for (int k = 1; k < 3; k++)
        if (mx[k] - mn[k] > mx[b->ch] - mn[b->ch])
            b->ch = k;
    b->range = mx[b->ch] - mn[b->ch];
}

static isk_status median_cut(isk__quant_entry *e, size_t n, uint8_t *palette, int *ncolors)
{
    box boxes[MAX_COLORS];
    int nb = 1;
    boxes[0].lo = 0;
    boxes[0].hi = n;
    measure(&boxes[0], e);
    while (nb < MAX_COLORS) {
        int best = -1;
        uint64_t best_p = 0;
        for (int i = 0; i < nb; i++) {
            uint64_t p = (uint64_t)boxes[i].range * boxes[i].count;
            if (boxes[i].hi - boxes[i].lo >= 2 && p > best_p) {
                best_p = p;
                best = i;
            }
        }
        if (best < 0)
            break;
        box *b = &boxes[best];
        isk_status s = sort_by(e + b->lo, b->hi - b->lo, b->ch);
        if (s != ISK_OK)
            return s;
        uint64_t half = b->count / 2, run = 0;
        size_t m = b->lo;
        while (m < b->hi - 1 && run + e[m].count <= half)
            run += e[m++].count;
        if (m == b->lo)
            m++; /* both halves keep at least one colour */
        boxes[nb].lo = m;
        boxes[nb].hi = b->hi;
        b->hi = m;
        measure(b, e);
        measure(&boxes[nb], e);
        nb++;
    }
    for (int i = 0; i < nb; i++) {
        uint64_t sum[3] = {0, 0, 0};
        for (size_t j = boxes[i].lo; j < boxes[i].hi; j++) {
            for (int k = 0; k < 3; k++)
                sum[k] += (uint64_t)channel(e[j].rgb, k) * e[j].count;
            e[j].index = (uint32_t)i;
        }
        for (int k = 0; k < 3; k++)
            palette[3 * i + k] = (uint8_t)((sum[k] + boxes[i].count / 2) / boxes[i].count);
    }
    *ncolors = nb;
    return ISK_OK;
}

isk_status isk__quant_frame(isk__quant *q, const isk_canvas *c, uint8_t palette[256 * 3], int *n, uint8_t *indices)
{
    if (!q || !c || !palette || !n || !indices || !q->slots)
        return ISK_ERR_NULL;
    if (!c->pixels || c->width <= 0 || c->height <= 0 || (size_t)c->width * (size_t)c->height > q->max_pixels)
        return ISK_ERR_SIZE;
    memset(q->slots, 0, q->nslots * sizeof *q->slots);
    q->nentries = 0;
    size_t p = 0;
    for (int y = 0; y < c->height; y++) {
        const uint8_t *row = c->pixels + (size_t)y * c->stride;
        for (int x = 0; x < c->width; x++, p++) {
            uint32_t rgb = opaque_rgb(row + 4 * x);
            q->rgb[p] = rgb;
            size_t h = slot_of(q, rgb);
            if (!q->slots[h]) {
                q->entries[q->nentries] = (isk__quant_entry){rgb, 0, 0};
                q->slots[h] = (uint32_t)++q->nentries;
            }
            q->entries[q->slots[h] - 1].count++;
        }
    }
    isk_status s = sort_by(q->entries, q->nentries, -1);
    if (s != ISK_OK)
        return s;
    if (q->nentries <= MAX_COLORS) {
        for (size_t i = 0; i < q->nentries; i++) {
            for (int k = 0; k < 3; k++)
                palette[3 * i + k] = (uint8_t)channel(q->entries[i].rgb, k);
            q->entries[i].index = (uint32_t)i;
        }
        *n = (int)q->nentries;
    } else if ((s = median_cut(q->entries, q->nentries, palette, n)) != ISK_OK) {
        return s;
    }
    /* The entries moved while sorting: index the table afresh. */
    memset(q->slots, 0, q->nslots * sizeof *q->slots);
    for (size_t i = 0; i < q->nentries; i++)
        q->slots[slot_of(q, q->entries[i].rgb)] = (uint32_t)(i + 1);
    for (size_t i = 0; i < p; i++)
        indices[i] = (uint8_t)q->entries[q->slots[slot_of(q, q->rgb[i])] - 1].index;
    return ISK_OK;
}
