/* SPDX-License-Identifier: MIT */
/* Textures made from a canvas or a sprite kind: premultiplied frames with a
 * transparent border and mip levels (the layout is in iskra/texture.h), and
 * the rules an image must meet, with their messages.  Drawing is
 * texture_draw.c, the cache texture_cache.c; PNG files are src/io's
 * (iskra/texture_png.h). */
#include "iskra/texture.h"

#include <stdlib.h>
#include <string.h>

#include "raster/texture_cache.h"
#include "raster/texture_rows.h"

/* Level sizes of a w x h frame, their offsets in a frame's block, and the
 * block's size; the number of levels. */
static int plan_levels(isk_texture *t)
{
    int w = t->frame_w, h = t->frame_h, n = 0;
    size_t at = 0;
    for (;;) {
        t->level[n].w = w;
        t->level[n].h = h;
        t->level[n].offset = at;
        at += 4u * (size_t)(w + 2) * (size_t)(h + 2);
        n++;
        if (w == 1 && h == 1)
            break;
        w = (w + 1) / 2;
        h = (h + 1) / 2;
    }
    t->frame_bytes = at;
    return n;
}

static inline uint8_t *level_texel(uint8_t *base, const isk_texture_level *lv, int x, int y)
{
    return base + lv->offset + 4u * ((size_t)(y + 1) * (size_t)(lv->w + 2) + (size_t)(x + 1));
}

/* Level l + 1 from level l: 2x2 averages of premultiplied texels, an odd
 * side repeating its last texel.  Monotone rounding keeps p <= a. */
static void halve(uint8_t *frame, const isk_texture_level *src, const isk_texture_level *dst)
{
    for (int y = 0; y < dst->h; y++) {
        int y0 = 2 * y, y1 = 2 * y + 1 < src->h ? 2 * y + 1 : src->h - 1;
        for (int x = 0; x < dst->w; x++) {
            int x0 = 2 * x, x1 = 2 * x + 1 < src->w ? 2 * x + 1 : src->w - 1;
            const uint8_t *a = level_texel(frame, src, x0, y0), *b = level_texel(frame, src, x1, y0);
            const uint8_t *c = level_texel(frame, src, x0, y1), *d = level_texel(frame, src, x1, y1);
            uint8_t *o = level_texel(frame, dst, x, y);
            for (int k = 0; k < 4; k++)
                o[k] = (uint8_t)((a[k] + b[k] + c[k] + d[k] + 2u) / 4u);
        }
    }
}

size_t isk_texture_bytes(int width, int height, int cols, int rows)
{
    if (width < 1 || height < 1 || width > ISK_TEXTURE_MAX_DIM || height > ISK_TEXTURE_MAX_DIM || cols < 1 ||
        cols > ISK_TEXTURE_MAX_GRID || rows < 1 || rows > ISK_TEXTURE_MAX_GRID || width % cols || height % rows)
        return 0;
    isk_texture t;
    memset(&t, 0, sizeof t);
    t.frame_w = width / cols;
    t.frame_h = height / rows;
    plan_levels(&t);
    return sizeof(isk_texture) + (size_t)cols * (size_t)rows * t.frame_bytes + ISK__TEXTURE_SLACK;
}

static int canvas_ok(const isk_canvas *c)
{
    return c->pixels && c->width > 0 && c->height > 0 && c->stride >= 4u * (size_t)c->width;
}

isk_status isk_texture_from_canvas(isk_texture *t, const isk_canvas *img, int cols, int rows)
{
    if (!t)
        return ISK_ERR_NULL;
    memset(t, 0, sizeof *t);
    if (!img)
        return ISK_ERR_NULL;
    if (!canvas_ok(img) || img->width > ISK_TEXTURE_MAX_DIM || img->height > ISK_TEXTURE_MAX_DIM)
        return ISK_ERR_SIZE;
    if (cols < 1 || cols > ISK_TEXTURE_MAX_GRID || rows < 1 || rows > ISK_TEXTURE_MAX_GRID ||
        img->width % cols != 0 || img->height % rows != 0)
        return ISK_ERR_RANGE;
    isk_texture n;
    memset(&n, 0, sizeof n);
    n.width = img->width;
    n.height = img->height;
    n.cols = cols;
    n.rows = rows;
    n.frames = cols * rows;
    n.frame_w = img->width / cols;
    n.frame_h = img->height / rows;
    n.levels = plan_levels(&n);
    n.bytes = (size_t)n.frames * n.frame_bytes;
    /* the borders are the zeros; the slack lets the drawing kernels read a
     * whole vector at a row's end */
    n.texels = calloc(1, n.bytes + ISK__TEXTURE_SLACK);
    if (!n.texels)
        return ISK_ERR_NOMEM;
    for (int f = 0; f < n.frames; f++) {
        uint8_t *frame = n.texels + (size_t)f * n.frame_bytes;
        int fx = (f % cols) * n.frame_w, fy = (f / cols) * n.frame_h;
        for (int y = 0; y < n.frame_h; y++) {
            const uint8_t *s = img->pixels + (size_t)(fy + y) * img->stride + 4u * (size_t)fx;
            uint8_t *d = level_texel(frame, &n.level[0], 0, y);
            for (int x = 0; x < n.frame_w; x++, s += 4, d += 4) {
                uint32_t a = s[3];
                d[0] = (uint8_t)isk_div255(s[0] * a);
                d[1] = (uint8_t)isk_div255(s[1] * a);
                d[2] = (uint8_t)isk_div255(s[2] * a);
                d[3] = (uint8_t)a;
            }
        }
        for (int l = 1; l < n.levels; l++)
            halve(frame, &n.level[l - 1], &n.level[l]);
    }
    *t = n;
    return ISK_OK;
}

isk_status isk_texture_check_size(const char *name, int width, int height, int cols, int rows, isk_error *err)
{
    if (!name)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL name");
    if (cols < 1 || cols > ISK_TEXTURE_MAX_GRID || rows < 1 || rows > ISK_TEXTURE_MAX_GRID)
        return isk_error_set(err, ISK_ERR_RANGE, "texture %s: a grid of %d x %d frames (cols and rows must be 1..%d)",
                             name, cols, rows, ISK_TEXTURE_MAX_GRID);
    if (width < 1 || height < 1)
        return isk_error_set(err, ISK_ERR_SIZE, "texture %s: %d x %d pixels (an empty image)", name, width, height);
    if (width > ISK_TEXTURE_MAX_DIM || height > ISK_TEXTURE_MAX_DIM)
        return isk_error_set(err, ISK_ERR_SIZE, "texture %s: %d x %d pixels, larger than %d a side", name, width,
                             height, ISK_TEXTURE_MAX_DIM);
    if (width % cols != 0 || height % rows != 0)
        return isk_error_set(err, ISK_ERR_RANGE,
                             "texture %s: %d x %d pixels do not divide into %d x %d frames (cols must divide the "
                             "width, rows the height)",
                             name, width, height, cols, rows);
    return ISK_OK;
}

isk_status isk__texture_from_image(isk_texture *t, const isk_canvas *img, const char *name, int cols, int rows,
                                   isk_error *err)
{
    if (t)
        memset(t, 0, sizeof *t);
    if (!t || !img || !name)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", !t ? "texture" : !img ? "image" : "name");
    isk_status st = isk_texture_check_size(name, img->width, img->height, cols, rows, err);
    if (st == ISK_OK && (st = isk_texture_from_canvas(t, img, cols, rows)) != ISK_OK)
        isk_error_set(err, st, "texture %s: %s", name, isk_status_str(st));
    return st;
}

void isk_texture_free(isk_texture *t)
{
    if (!t)
        return;
    free(t->texels);
    memset(t, 0, sizeof *t);
}

isk_status isk_texture_from_sprite(isk_texture *t, isk_sprite_kind kind, int size)
{
    if (!t)
        return ISK_ERR_NULL;
    memset(t, 0, sizeof *t);
    isk_sprite s;
    isk_status st = isk_sprite_init(&s, kind, size, ISK_WHITE);
    if (st != ISK_OK)
        return st;
    isk_canvas img;
    st = isk_canvas_init(&img, size, size);
    if (st == ISK_OK) {
        for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++) {
                uint8_t *p = isk_canvas_at(&img, x, y);
                p[0] = p[1] = p[2] = 255;
                p[3] = s.mask[0][(size_t)y * (size_t)size + (size_t)x];
            }
        st = isk_texture_from_canvas(t, &img, 1, 1);
        isk_canvas_free(&img);
    }
    isk_sprite_free(&s);
    return st;
}
