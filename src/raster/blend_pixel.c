/* SPDX-License-Identifier: MIT */
/* Pixel blending: replace, straight-alpha source-over, saturating add.
 * The formulas and rounding rule are documented in iskra/blend.h; the
 * arithmetic lives once, in raster/blend_px.h, shared with the primitives. */
#include "iskra/blend.h"

#include "raster/blend_px.h"

void isk_blend_pixel(uint8_t *d, isk_color s, isk_blend mode)
{
    if (!d) /* the public entry checks; the primitives call isk__blend_px directly */
        return;
    isk__blend_px(d, s, mode);
}

void isk_blend_pixel_cov(uint8_t *d, isk_color s, uint8_t coverage, isk_blend mode)
{
    if (!d)
        return;
    isk__px_cov(d, s, coverage, mode);
}

const char *const isk_blend_names[ISK_BLEND_COUNT] = {"replace", "over", "add"};

const char *isk_blend_name(isk_blend mode)
{
    return (unsigned)mode < ISK_BLEND_COUNT ? isk_blend_names[mode] : (const char *)0;
}
