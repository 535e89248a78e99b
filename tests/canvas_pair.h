/* SPDX-License-Identifier: MIT */
/* tests/canvas_pair.h — two identical random canvases for tests that draw
 * the same thing two ways and compare every byte (header-only; include it
 * after <criterion/criterion.h>).
 *
 *     canvas_pair p = canvas_pair_make(&rng, w, h);
 *     // draw one way on p.c[0], the other on p.c[1]
 *     size_t at;
 *     cr_assert(canvas_pair_equal(&p, &at), "byte %zu differs", at);
 *     canvas_pair_free(&p);
 *
 * Each canvas views a larger buffer (a margin of sentinel bytes around it,
 * a stride up to 2 bytes wider than the row), so a write outside the canvas
 * shows as a difference too; the pixels are random, their alpha opaque,
 * mixed or random (one style per pair), so every blend rule's branches are
 * reached. */
#ifndef ISKRA_TESTS_CANVAS_PAIR_H
#define ISKRA_TESTS_CANVAS_PAIR_H

#include <stdlib.h>
#include <string.h>

#include "iskra/canvas.h"
#include "iskra/rng.h"

typedef struct canvas_pair {
    uint8_t *buf[2];
    isk_canvas c[2];
    size_t bytes;
} canvas_pair;

enum { CANVAS_PAIR_MARGIN = 3 };

static inline canvas_pair canvas_pair_make(isk_rng *r, int w, int h)
{
    canvas_pair p;
    const size_t m = CANVAS_PAIR_MARGIN;
    size_t stride = (size_t)(w + 2 * CANVAS_PAIR_MARGIN) * 4u + isk_rng_below(r, 3);
    p.bytes = stride * (size_t)(h + 2 * CANVAS_PAIR_MARGIN);
    int style = (int)isk_rng_below(r, 3); /* 0 opaque, 1 mixed alpha, 2 random alpha */
    for (int k = 0; k < 2; k++) {
        p.buf[k] = malloc(p.bytes);
        cr_assert(p.buf[k]);
    }
    for (size_t b = 0; b < p.bytes; b++)
        p.buf[0][b] = (uint8_t)isk_rng_below(r, 256);
    for (size_t b = 3; b < p.bytes; b += 4)
        if (style == 0 || (style == 1 && isk_rng_below(r, 2)))
            p.buf[0][b] = 255;
    memcpy(p.buf[1], p.buf[0], p.bytes);
    for (int k = 0; k < 2; k++)
        cr_assert_eq(isk_canvas_wrap(&p.c[k], p.buf[k] + m * stride + m * 4u, w, h, stride), ISK_OK);
    return p;
}

/* 1 when the two buffers (margins included) are equal; *at is the first
 * differing byte (p->bytes when none). */
static inline int canvas_pair_equal(const canvas_pair *p, size_t *at)
{
    size_t k = 0;
    while (k < p->bytes && p->buf[0][k] == p->buf[1][k])
        k++;
    *at = k;
    return k == p->bytes;
}

static inline void canvas_pair_free(canvas_pair *p)
{
    free(p->buf[0]);
    free(p->buf[1]);
}

/* A random byte that is 0 or 255 a third of the time (the blend rules'
 * edge cases), and a colour of random channels with such an alpha. */
static inline uint8_t canvas_pair_rnd_byte(isk_rng *r)
{
    switch (isk_rng_below(r, 6)) {
    case 0: return 0;
    case 1: return 255;
    default: return (uint8_t)isk_rng_below(r, 256);
    }
}

static inline isk_color canvas_pair_rnd_color(isk_rng *r)
{
    isk_color c; /* one draw a statement: an initializer list's order is unspecified */
    c.r = (uint8_t)isk_rng_below(r, 256);
    c.g = (uint8_t)isk_rng_below(r, 256);
    c.b = (uint8_t)isk_rng_below(r, 256);
    c.a = canvas_pair_rnd_byte(r);
    return c;
}

#endif
