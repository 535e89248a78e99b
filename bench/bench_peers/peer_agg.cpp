/* SPDX-License-Identifier: MIT */
// The AGG side of bench_peers (see peer_agg.h): AGG 2.6 as Debian ships it,
// used the way its examples do (rasterizer_scanline_aa + scanline_p8 +
// render_scanlines_aa_solid for shapes, renderer_base for spans and images).
#include "peer_agg.h"

#include <agg_basics.h>
#include <agg_ellipse.h>
#include <agg_pixfmt_rgba.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_p.h>

typedef agg::pixfmt_rgba32 pf_over;
typedef agg::pixfmt_custom_blend_rgba<agg::comp_op_adaptor_rgba<agg::rgba8, agg::order_rgba>,
                                      agg::rendering_buffer>
    pf_custom;
typedef agg::pixfmt_rgba32_pre pf_pre;
typedef agg::pixfmt_custom_blend_rgba<agg::comp_op_adaptor_rgba_pre<agg::rgba8, agg::order_rgba>,
                                      agg::rendering_buffer>
    pf_custom_pre;

struct peer_agg {
    agg::rendering_buffer rb;
    pf_over over;
    pf_custom custom;
    agg::renderer_base<pf_over> rb_over;
    agg::renderer_base<pf_custom> rb_add;
    pf_pre pre;
    agg::renderer_base<pf_pre> rb_pre; /* images are premultiplied: blended as such */
    pf_custom_pre custom_pre;
    agg::renderer_base<pf_custom_pre> rb_add_pre;
    agg::rasterizer_scanline_aa<> ras;
    agg::scanline_p8 sl;
    peer_agg(uint8_t *p, int w, int h, int stride)
        : rb(p, (unsigned)w, (unsigned)h, stride), over(rb), custom(rb, agg::comp_op_plus), rb_over(over),
          rb_add(custom), pre(rb), rb_pre(pre),
          custom_pre(rb, agg::comp_op_plus), rb_add_pre(custom_pre)
    {
    }
};

extern "C" peer_agg *peer_agg_create(uint8_t *rgba, int width, int height, int stride)
{
    return new peer_agg(rgba, width, height, stride);
}

extern "C" void peer_agg_destroy(peer_agg *a)
{
    delete a;
}

static agg::rgba8 colour(const uint8_t c[4])
{
    return agg::rgba8(c[0], c[1], c[2], c[3]);
}

template <class RB> static void dots(peer_agg *a, RB &rb, int n, const double *x, const double *y, agg::rgba8 c)
{
    for (int i = 0; i < n; i++) {
        a->ras.reset();
        a->ras.move_to_d(x[i], y[i]);
        a->ras.line_to_d(x[i] + 1.0, y[i]);
        a->ras.line_to_d(x[i] + 1.0, y[i] + 1.0);
        a->ras.line_to_d(x[i], y[i] + 1.0);
        a->ras.close_polygon();
        agg::render_scanlines_aa_solid(a->ras, a->sl, rb, c);
    }
}

extern "C" void peer_agg_dots(peer_agg *a, int n, const double *x, const double *y, const uint8_t col[4], int add)
{
    if (add)
        dots(a, a->rb_add, n, x, y, colour(col));
    else
        dots(a, a->rb_over, n, x, y, colour(col));
}

extern "C" void peer_agg_pixels(peer_agg *a, int n, const int *x, const int *y, const uint8_t col[4], int add)
{
    agg::rgba8 c = colour(col);
    if (add)
        for (int i = 0; i < n; i++)
            a->rb_add.blend_pixel(x[i], y[i], c, agg::cover_full);
    else
        for (int i = 0; i < n; i++)
            a->rb_over.blend_pixel(x[i], y[i], c, agg::cover_full);
}

template <class RB>
static void discs(peer_agg *a, RB &rb, int n, const double *cx, const double *cy, double r, agg::rgba8 c)
{
    for (int i = 0; i < n; i++) {
        agg::ellipse e(cx[i], cy[i], r, r);
        a->ras.reset();
        a->ras.add_path(e);
        agg::render_scanlines_aa_solid(a->ras, a->sl, rb, c);
    }
}

extern "C" void peer_agg_discs(peer_agg *a, int n, const double *cx, const double *cy, double r,
                               const uint8_t col[4], int add)
{
    if (add)
        discs(a, a->rb_add, n, cx, cy, r, colour(col));
    else
        discs(a, a->rb_over, n, cx, cy, r, colour(col));
}

template <class RB>
static void masks(RB &rb, int n, const int *x, const int *y, const uint8_t *mask, int S, agg::rgba8 c)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < S; j++)
            rb.blend_solid_hspan(x[i], y[i] + j, S, c, mask + j * S);
}

extern "C" void peer_agg_masks(peer_agg *a, int n, const int *x, const int *y, const uint8_t *mask, int S,
                               const uint8_t col[4], int add)
{
    if (add)
        masks(a->rb_add, n, x, y, mask, S, colour(col));
    else
        masks(a->rb_over, n, x, y, mask, S, colour(col));
}

extern "C" void peer_agg_images(peer_agg *a, int n, const int *x, const int *y, const uint8_t *img, int S, int add)
{
    agg::rendering_buffer src(const_cast<uint8_t *>(img), (unsigned)S, (unsigned)S, S * 4);
    pf_pre spr(src);
    for (int i = 0; i < n; i++) {
        if (add)
            a->rb_add_pre.blend_from(spr, 0, x[i], y[i]);
        else
            a->rb_pre.blend_from(spr, 0, x[i], y[i]);
    }
}
