/* SPDX-License-Identifier: MIT */
/* iskra/color.h — the straight (non-premultiplied) RGBA8 colour every layer
 * shares: the rasterizer draws it, particles carry it, ramps bake it.
 *
 * Example:
 *
 *     isk_color c = isk_rgba(255, 128, 0, 255);   // opaque orange
 *     isk_color k = ISK_YELLOW;
 *     printf("orange %d %d %d %d, yellow %d %d %d %d\n", c.r, c.g, c.b, c.a, k.r, k.g, k.b, k.a);
 *
 * A core type (no dependencies), so the simulation can hold colours without
 * knowing about canvases.  How colours combine is iskra/blend.h.
 */
#ifndef ISKRA_COLOR_H
#define ISKRA_COLOR_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct isk_color {
    uint8_t r, g, b, a;
} isk_color;

static inline isk_color isk_rgba(uint8_t r, uint8_t g, uint8_t b, uint8_t a)
{
    isk_color c;
    c.r = r;
    c.g = g;
    c.b = b;
    c.a = a;
    return c;
}

/* Compound literals are C99, not C++: the named colours go through isk_rgba
 * there. */
#ifdef __cplusplus
#define ISK_COLOR_(r, g, b, a) isk_rgba(r, g, b, a)
#else
#define ISK_COLOR_(r, g, b, a) ((isk_color){r, g, b, a})
#endif

#define ISK_BLACK       ISK_COLOR_(0, 0, 0, 255)
#define ISK_WHITE       ISK_COLOR_(255, 255, 255, 255)
#define ISK_TRANSPARENT ISK_COLOR_(0, 0, 0, 0)
#define ISK_YELLOW      ISK_COLOR_(255, 255, 0, 255)
#define ISK_RED         ISK_COLOR_(255, 0, 0, 255)
#define ISK_GREEN       ISK_COLOR_(0, 128, 0, 255) /* CSS "green" */
#define ISK_BLUE        ISK_COLOR_(0, 0, 255, 255)

#ifdef __cplusplus
}
#endif

#endif
