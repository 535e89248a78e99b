/* SPDX-License-Identifier: MIT */
/* src/raster/text.c — measuring and drawing strings in the built-in fonts.
 *
 * Layout (see iskra/text.h): every byte except '\n' advances the pen by one
 * cell (cell_w x cell_h of the font's metrics, times scale; 6x9 for the 5x8
 * font); the glyph's box sits at the cell's top-left and the rest of the
 * cell is spacing.  '\n' moves the pen to the start x of the next line.
 *
 *     int w = isk_text_width("FPS: 60", 2), h = isk_text_height("FPS: 60", 2);
 *     isk_draw_text(&c, 15, 30, "FPS: 60", 2, ISK_WHITE, ISK_BLEND_OVER);
 *
 * All position arithmetic is done in 64 bits and the pen stops as soon as it
 * leaves the canvas to the right or below, so any int x, y and scale (up to
 * INT_MAX) is safe: the pen never runs further than one cell past the canvas.
 * Each canvas pixel is blended at most once per call (cells never overlap),
 * so translucent colours give an even tint.
 */
#include "iskra/text.h"

#include <limits.h>
#include <stddef.h>
#include <stdint.h>

#include "font_bitmaps.h"

/* Each font's bitmaps and metrics, from its own file. */
static const isk__font_bitmaps *const fonts[ISK_FONT_COUNT] = {
    [ISK_FONT_5X8] = &isk__font_5x8,
    [ISK_FONT_6X13] = &isk__font_6x13,
};

const isk_font_metrics *isk_font_metrics_of(isk_font font)
{
    return (unsigned)font < ISK_FONT_COUNT ? &fonts[font]->metrics : NULL;
}

const uint8_t *isk_font_rows(isk_font font, unsigned char ch)
{
    if ((unsigned)font >= ISK_FONT_COUNT)
        return NULL;
    const isk__font_bitmaps *f = fonts[font];
    if (ch < ISK__FONT_FIRST || ch > ISK__FONT_LAST)
        return f->box;
    return f->glyphs + (size_t)(ch - ISK__FONT_FIRST) * (size_t)f->metrics.glyph_h;
}

const uint8_t *isk_font_glyph(unsigned char ch) { return isk_font_rows(ISK_FONT_5X8, ch); }

/* n * unit, saturated at INT_MAX (unit > 0). */
static int saturated_product(unsigned long long n, long long unit)
{
    if (n == 0u)
        return 0;
    if (n > (unsigned long long)(INT_MAX / unit))
        return INT_MAX;
    return (int)((long long)n * unit);
}

int isk_font_text_width(isk_font font, const char *s, int scale)
{
    const isk_font_metrics *m = isk_font_metrics_of(font);
    if (!m || !s || scale < 1)
        return 0;
    unsigned long long widest = 0, cur = 0;
    for (; *s; s++) {
        if (*s == '\n') {
            cur = 0;
        } else if (++cur > widest) {
            widest = cur;
        }
    }
    return saturated_product(widest, (long long)m->cell_w * scale);
}

int isk_font_text_height(isk_font font, const char *s, int scale)
{
    const isk_font_metrics *m = isk_font_metrics_of(font);
    if (!m || !s || scale < 1 || !*s)
        return 0;
    unsigned long long lines = 1;
    for (; *s; s++)
        if (*s == '\n')
            lines++;
    return saturated_product(lines, (long long)m->cell_h * scale);
}

int isk_text_width(const char *s, int scale) { return isk_font_text_width(ISK_FONT_5X8, s, scale); }

int isk_text_height(const char *s, int scale) { return isk_font_text_height(ISK_FONT_5X8, s, scale); }

/* Blends the rectangle [x0, x0+w) x [y0, y0+h), clipped to the canvas. */
static void fill_block(isk_canvas *c, long long x0, long long y0, long long w, long long h,
                       isk_color color, isk_blend mode)
{
    long long x1 = x0 + w, y1 = y0 + h;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > c->width) x1 = c->width;
    if (y1 > c->height) y1 = c->height;
    if (x0 >= x1 || y0 >= y1)
        return; /* wholly off the canvas: not even an address is formed */
    for (long long y = y0; y < y1; y++) {
        uint8_t *p = isk_canvas_at(c, (int)x0, (int)y);
        for (long long x = x0; x < x1; x++, p += 4)
            isk_blend_pixel(p, color, mode);
    }
}

/* Draws one glyph whose box (m->glyph_w x m->glyph_h) has its top-left at (x, y). */
static void draw_glyph(isk_canvas *c, const isk_font_metrics *m, long long x, long long y, const uint8_t *rows,
                       long long scale, isk_color color, isk_blend mode)
{
    const unsigned left = 1u << (m->glyph_w - 1); /* the bit of the leftmost pixel */
    for (int r = 0; r < m->glyph_h; r++) {
        long long py = y + r * scale;
        if (py >= c->height || py + scale <= 0 || rows[r] == 0u)
            continue;
        for (int col = 0; col < m->glyph_w; col++) {
            if (!(rows[r] & (left >> col)))
                continue;
            /* Merge a horizontal run of ink into one block: fewer clip
             * computations at large scales, same pixels. */
            int end = col + 1;
            while (end < m->glyph_w && (rows[r] & (left >> end)))
                end++;
            fill_block(c, x + col * scale, py, (end - col) * scale, scale, color, mode);
            col = end;
        }
    }
}

void isk_font_draw_text(isk_canvas *c, isk_font font, int x, int y, const char *s, int scale, isk_color color,
                        isk_blend mode)
{
    const isk_font_metrics *m = isk_font_metrics_of(font);
    if (!m || !c || !c->pixels || c->width <= 0 || c->height <= 0 || !s || scale < 1)
        return;
    if (!isk_blend_name(mode))
        return; /* unknown mode: draw nothing rather than guess */
    const long long k = scale;
    const long long cell_w = m->cell_w * k, cell_h = m->cell_h * k;
    long long pen_x = x, pen_y = y;
    while (*s) {
        if (pen_y >= c->height)
            return; /* this and every later line is below the canvas */
        int line_visible = pen_y + cell_h > 0;
        for (; *s && *s != '\n'; s++) {
            /* Past the right edge: skip the rest of the line unread. */
            if (!line_visible || pen_x >= c->width)
                continue;
            if (pen_x + cell_w > 0) {
                unsigned char ch = (unsigned char)*s;
                draw_glyph(c, m, pen_x, pen_y, isk_font_rows(font, ch), k, color, mode);
            }
            pen_x += cell_w;
        }
        if (*s == '\n') {
            s++;
            pen_x = x;
            pen_y += cell_h;
        }
    }
}

void isk_draw_text(isk_canvas *c, int x, int y, const char *s, int scale, isk_color color, isk_blend mode)
{
    isk_font_draw_text(c, ISK_FONT_5X8, x, y, s, scale, color, mode);
}
