/* Pixel blending: replace, straight-alpha source-over, saturating add.
 * The formulas and rounding rule are documented in iskra/blend.h; the
 * arithmetic lives once, in raster/blend_px.h, shared with the primitives. */
#include "iskra/blend.h"

#include "raster/blend_px.h"

void isk_blend_pixel(uint8_t *d, isk_color s, isk_blend mode)
{
    isk__px(d, s, mode);
}

void isk_blend_pixel_cov(uint8_t *d, isk_color s, uint8_t coverage, isk_blend mode)
{
    isk__px_cov(d, s, coverage, mode);
}

const char *isk_blend_name(isk_blend mode)
{
    switch (mode) {
    case ISK_BLEND_REPLACE: return "replace";
    case ISK_BLEND_OVER: return "over";
    case ISK_BLEND_ADD: return "add";
    }
    return 0;
}
