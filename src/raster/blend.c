/* Pixel blending: replace, straight-alpha source-over, saturating add.
 * The formulas and rounding rule are documented in iskra/blend.h. */
#include "iskra/blend.h"

static inline void blend_over(uint8_t *d, isk_color s)
{
    uint32_t sa = s.a;
    if (sa == 255u) {
        d[0] = s.r; d[1] = s.g; d[2] = s.b; d[3] = 255;
        return;
    }
    if (sa == 0u)
        return;
    uint32_t da = d[3];
    uint32_t inv = 255u - sa;
    if (da == 255u) {
        /* Opaque destination: the common case, no division by A. */
        d[0] = (uint8_t)isk_div255(s.r * sa + d[0] * inv);
        d[1] = (uint8_t)isk_div255(s.g * sa + d[1] * inv);
        d[2] = (uint8_t)isk_div255(s.b * sa + d[2] * inv);
        return;
    }
    uint32_t wd = da * inv;              /* destination weight, scaled by 255 */
    uint32_t A = 255u * sa + wd;         /* 255 * output alpha */
    uint32_t half = A / 2u;
    d[0] = (uint8_t)((255u * s.r * sa + d[0] * wd + half) / A);
    d[1] = (uint8_t)((255u * s.g * sa + d[1] * wd + half) / A);
    d[2] = (uint8_t)((255u * s.b * sa + d[2] * wd + half) / A);
    d[3] = (uint8_t)isk_div255(A);
}

static inline uint8_t sat_add(uint32_t a, uint32_t b)
{
    uint32_t s = a + b;
    return (uint8_t)(s > 255u ? 255u : s);
}

void isk_blend_pixel(uint8_t *d, isk_color s, isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_REPLACE:
        d[0] = s.r; d[1] = s.g; d[2] = s.b; d[3] = s.a;
        break;
    case ISK_BLEND_OVER:
        blend_over(d, s);
        break;
    case ISK_BLEND_ADD:
        d[0] = sat_add(d[0], isk_div255((uint32_t)s.r * s.a));
        d[1] = sat_add(d[1], isk_div255((uint32_t)s.g * s.a));
        d[2] = sat_add(d[2], isk_div255((uint32_t)s.b * s.a));
        d[3] = sat_add(d[3], s.a);
        break;
    default: /* not a mode: nothing is drawn */
        break;
    }
}

void isk_blend_pixel_cov(uint8_t *d, isk_color s, uint8_t coverage, isk_blend mode)
{
    if (coverage == 0u) /* untouched, whatever the mode */
        return;
    s.a = (uint8_t)isk_div255((uint32_t)s.a * coverage);
    isk_blend_pixel(d, s, mode);
}

const char *const isk_blend_names[ISK_BLEND_COUNT] = {"replace", "over", "add"};

const char *isk_blend_name(isk_blend mode)
{
    return (unsigned)mode < ISK_BLEND_COUNT ? isk_blend_names[mode] : (const char *)0;
}
