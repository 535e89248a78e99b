/* SPDX-License-Identifier: MIT */
/* bench_peers: iskra's raster primitives against the Debian packages of
 * cairo, pixman, AGG, SDL2 (surface blits) and SDL2_gfx, per primitive, in
 * one run.
 *
 * Every library draws the same items (same random positions, same colour
 * (255,180,60,200), same blend: over or add) onto its own 800x600 opaque
 * canvas in its own pixel format; passes of all libraries are interleaved
 * (the repetitions outermost, over all primitives) and each figure is the
 * fastest of REPS passes in thread CPU time
 * (bench_cpu_now; the machine is shared and interference only slows a pass
 * down; the median is printed at the end of
 * each row for iskra and the reference peer, to show the spread).  Peers get screen
 * coordinates; iskra's batched dot also does the world->screen transform.
 * Sprites: every library blits the same S x S coverage mask (iskra's baked
 * mask) at an integer position; tinted = the mask in a colour given per call
 * (pixman/cairo: solid source through an a8 mask, AGG: blend_solid_hspan,
 * SDL2: colour/alpha modulation of a white sprite), untinted = an image
 * baked in the colour (premultiplied for pixman/cairo/AGG, ARGB for SDL2).
 *
 * Same work: before timing, each library draws a grid of 48 separated items
 * in opaque white onto opaque black and the drawn area (sum of one channel
 * / 255, in pixels per item) is compared with iskra's.  Tolerances: 2% for
 * dots, pixels and sprites (all draw exact areas or the same mask; AGG's
 * 1/256-pixel cells, premultiplication and SDL2's >>8 blend round
 * differently); 2% + 12%/r for anti-aliased discs, because AGG's default
 * circle is a polygon of about 7 (r = 1) to 18 (r = 8) sides, up to 12%
 * smaller than the disc, and cairo's is close to that at r = 1.  SDL2_gfx's
 * disc and pixel are aliased and only shown.  A check outside its tolerance
 * is printed as DIFFERS and makes the exit status 1.
 *
 *   build/bench/bench_peers [reps]
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <SDL.h>
#include <SDL2_gfxPrimitives.h>
#include <cairo.h>
#include <pixman.h>

#include "../bench_util.h"
#include "iskra/draw.h"
#include "iskra/sprite.h"
#include "iskra/view.h"
#include "peer_agg.h"

enum { W = 800, H = 600, NDOT = 1 << 17, NPIX = 1 << 17, NDISC = 1 << 12, NSPR = 1 << 13, MAXREP = 31 };
enum { LIB_ISKRA, LIB_ISKRA_CALL, LIB_CAIRO, LIB_PIXMAN, LIB_AGG, LIB_SDL, NLIB };
static const char *LIB_NAME[NLIB] = {"iskra", "iskra/call", "cairo", "pixman", "AGG", "SDL2"};

static const uint8_t COL[4] = {255, 180, 60, 200};
static const uint8_t WHITE[4] = {255, 255, 255, 255};

/* ---- the canvases ----------------------------------------------------- */

typedef struct canvases {
    uint8_t *buf[NLIB];      /* one W x H x 4 buffer per library */
    isk_canvas isk[2];
    cairo_surface_t *cs;
    cairo_t *cr;
    pixman_image_t *px;
    peer_agg *agg;
    SDL_Surface *sdl;
    SDL_Renderer *sdl_r;
} canvases;

static void fill_opaque(canvases *k, int lib, int black)
{
    uint8_t *b = k->buf[lib];
    for (size_t i = 0; i < (size_t)W * H; i++) {
        b[4 * i + 0] = black ? 0 : 20;
        b[4 * i + 1] = black ? 0 : 30;
        b[4 * i + 2] = black ? 0 : 40;
        b[4 * i + 3] = 255;
    }
    if (lib == LIB_CAIRO)
        cairo_surface_mark_dirty(k->cs);
}

/* Drawn area in pixels: channel 0 summed / 255 (white on black). */
static double area_of(canvases *k, int lib)
{
    if (lib == LIB_CAIRO)
        cairo_surface_flush(k->cs);
    double s = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        s += k->buf[lib][4 * i];
    return s / 255.0;
}

/* ---- items -------------------------------------------------------------- */

typedef struct items {
    isk_view view;
    double *wx, *wy;   /* dots, world */
    double *dx, *dy;   /* dots, screen */
    int *px, *py;      /* pixels */
    double *cx, *cy;   /* disc and sprite centres */
    int *sx, *sy;      /* sprite top-left for peers (per size, filled when used) */
    int n;             /* how many of them a pass draws */
} items;


/* ---- primitives --------------------------------------------------------- */

typedef enum prim_kind { P_DOT, P_PIXEL, P_DISC, P_SPRITE } prim_kind;

typedef struct prim {
    prim_kind kind;
    int add;
    double r;            /* disc radius */
    int sk, S, tinted;   /* sprite kind, size, tinted */
    isk_sprite spr;      /* baked in COL (and a white one for the checks) */
    isk_sprite spr_white;
    pixman_image_t *pm_img[2], *pm_mask; /* [0] COL, [1] white */
    cairo_surface_t *cs_img[2], *cs_mask;
    uint8_t *img[2];     /* premultiplied RGBA (AGG) */
    SDL_Surface *sdl_img[2];
    uint8_t *mask;       /* phase-0 mask, S x S */
} prim;

static int prim_has(const prim *p, int lib)
{
    switch (p->kind) {
    case P_DOT: return lib != LIB_SDL;
    case P_PIXEL: return lib != LIB_PIXMAN && !(lib == LIB_SDL && p->add);
    case P_DISC: return lib != LIB_PIXMAN && !(lib == LIB_SDL && p->add);
    case P_SPRITE: return lib != LIB_ISKRA_CALL;
    }
    return 0;
}

static void sprite_assets(prim *p)
{
    int S = p->S;
    const uint8_t *m = p->spr.mask[0];
    p->mask = malloc((size_t)S * S);
    memcpy(p->mask, m, (size_t)S * S);
    p->pm_mask = pixman_image_create_bits(PIXMAN_a8, S, S, NULL, 0);
    uint8_t *pmb = (uint8_t *)pixman_image_get_data(p->pm_mask);
    int pms = pixman_image_get_stride(p->pm_mask);
    p->cs_mask = cairo_image_surface_create(CAIRO_FORMAT_A8, S, S);
    uint8_t *csb = cairo_image_surface_get_data(p->cs_mask);
    int css = cairo_image_surface_get_stride(p->cs_mask);
    for (int j = 0; j < S; j++) {
        memcpy(pmb + (size_t)j * pms, m + (size_t)j * S, (size_t)S);
        memcpy(csb + (size_t)j * css, m + (size_t)j * S, (size_t)S);
    }
    cairo_surface_mark_dirty(p->cs_mask);
    for (int w = 0; w < 2; w++) {
        const uint8_t *c = w ? WHITE : COL;
        p->img[w] = malloc((size_t)S * S * 4);
        p->pm_img[w] = pixman_image_create_bits(PIXMAN_a8b8g8r8, S, S, NULL, 0);
        p->cs_img[w] = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, S, S);
        p->sdl_img[w] = SDL_CreateRGBSurfaceWithFormat(0, S, S, 32, SDL_PIXELFORMAT_ABGR8888);
        uint8_t *pb = (uint8_t *)pixman_image_get_data(p->pm_img[w]);
        int ps = pixman_image_get_stride(p->pm_img[w]);
        uint8_t *cb = cairo_image_surface_get_data(p->cs_img[w]);
        int cs = cairo_image_surface_get_stride(p->cs_img[w]);
        uint8_t *sb = p->sdl_img[w]->pixels;
        int ss = p->sdl_img[w]->pitch;
        for (int j = 0; j < S; j++)
            for (int i = 0; i < S; i++) {
                uint32_t a = (uint32_t)(c[3] * m[j * S + i] + 127) / 255;
                uint8_t pre[4] = {(uint8_t)((c[0] * a + 127) / 255), (uint8_t)((c[1] * a + 127) / 255),
                                  (uint8_t)((c[2] * a + 127) / 255), (uint8_t)a};
                memcpy(p->img[w] + 4 * ((size_t)j * S + i), pre, 4);
                memcpy(pb + (size_t)j * ps + 4 * i, pre, 4);
                uint32_t argb = (uint32_t)pre[3] << 24 | (uint32_t)pre[0] << 16 | (uint32_t)pre[1] << 8 | pre[2];
                memcpy(cb + (size_t)j * cs + 4 * i, &argb, 4);
                uint8_t straight[4] = {c[0], c[1], c[2], (uint8_t)a};
                memcpy(sb + (size_t)j * ss + 4 * i, straight, 4);
            }
        cairo_surface_mark_dirty(p->cs_img[w]);
        SDL_SetSurfaceBlendMode(p->sdl_img[w], p->add ? SDL_BLENDMODE_ADD : SDL_BLENDMODE_BLEND);
    }
}

static pixman_color_t pm_color(const uint8_t c[4])
{
    /* premultiplied, 16 bits per channel */
    pixman_color_t pc = {(uint16_t)(c[0] * c[3] / 255 * 257), (uint16_t)(c[1] * c[3] / 255 * 257),
                         (uint16_t)(c[2] * c[3] / 255 * 257), (uint16_t)(c[3] * 257)};
    return pc;
}

/* Draws items [0, it->n) of primitive p with library lib in colour col. */
/* iskra's pixel loops, each in a function of its own as AGG's is
 * (peer_agg_pixels, in another file), not inlined into draw() either:
 * isk_draw_pixel as a program writes it (the macro of
 * iskra/draw.h, inlined here), and the function called for each pixel. */
__attribute__((noinline)) static void iskra_pixels(isk_canvas *c, int n, const int *x, const int *y, isk_color col, isk_blend mode)
{
    for (int i = 0; i < n; i++)
        isk_draw_pixel(c, x[i], y[i], col, mode);
}

__attribute__((noinline)) static void iskra_pixels_called(isk_canvas *c, int n, const int *x, const int *y, isk_color col, isk_blend mode)
{
    for (int i = 0; i < n; i++)
        (isk_draw_pixel)(c, x[i], y[i], col, mode);
}

static void draw(canvases *k, const items *it, const prim *p, int lib, const uint8_t col[4])
{
    const int n = it->n, white = col == WHITE;
    isk_color ic = {col[0], col[1], col[2], col[3]};
    isk_blend mode = p->add ? ISK_BLEND_ADD : ISK_BLEND_OVER;
    isk_canvas *ik = &k->isk[lib == LIB_ISKRA_CALL];
    cairo_t *cr = k->cr;
    if (lib == LIB_CAIRO) {
        cairo_set_operator(cr, p->add ? CAIRO_OPERATOR_ADD : CAIRO_OPERATOR_OVER);
        cairo_set_source_rgba(cr, col[0] / 255.0, col[1] / 255.0, col[2] / 255.0, col[3] / 255.0);
    }
    pixman_op_t pop = p->add ? PIXMAN_OP_ADD : PIXMAN_OP_OVER;
    switch (p->kind) {
    case P_DOT:
        if (lib == LIB_ISKRA) {
            isk_draw_dots(ik, &it->view, (size_t)n, it->wx, it->wy, ic, mode);
        } else if (lib == LIB_ISKRA_CALL) {
            for (int i = 0; i < n; i++)
                isk_draw_dot(ik, it->dx[i], it->dy[i], ic, mode);
        } else if (lib == LIB_CAIRO) {
            for (int i = 0; i < n; i++) {
                cairo_rectangle(cr, it->dx[i], it->dy[i], 1, 1);
                cairo_fill(cr);
            }
        } else if (lib == LIB_PIXMAN) {
            pixman_color_t pc = pm_color(col);
            pixman_image_t *src = pixman_image_create_solid_fill(&pc);
            for (int i = 0; i < n; i++) {
                pixman_fixed_t l = pixman_double_to_fixed(it->dx[i]), t = pixman_double_to_fixed(it->dy[i]);
                pixman_fixed_t r = l + pixman_int_to_fixed(1), b = t + pixman_int_to_fixed(1);
                pixman_trapezoid_t tr = {t, b, {{l, t}, {l, b}}, {{r, t}, {r, b}}};
                pixman_composite_trapezoids(pop, src, k->px, PIXMAN_a8, 0, 0, 0, 0, 1, &tr);
            }
            pixman_image_unref(src);
        } else if (lib == LIB_AGG) {
            peer_agg_dots(k->agg, n, it->dx, it->dy, col, p->add);
        }
        break;
    case P_PIXEL:
        if (lib == LIB_ISKRA) {
            iskra_pixels(ik, n, it->px, it->py, ic, mode);
        } else if (lib == LIB_ISKRA_CALL) {
            iskra_pixels_called(ik, n, it->px, it->py, ic, mode);
        } else if (lib == LIB_CAIRO) {
            for (int i = 0; i < n; i++) {
                cairo_rectangle(cr, it->px[i], it->py[i], 1, 1);
                cairo_fill(cr);
            }
        } else if (lib == LIB_AGG) {
            peer_agg_pixels(k->agg, n, it->px, it->py, col, p->add);
        } else if (lib == LIB_SDL) {
            for (int i = 0; i < n; i++)
                pixelRGBA(k->sdl_r, (Sint16)it->px[i], (Sint16)it->py[i], col[0], col[1], col[2], col[3]);
        }
        break;
    case P_DISC:
        if (lib == LIB_ISKRA || lib == LIB_ISKRA_CALL) {
            for (int i = 0; i < n; i++)
                isk_fill_circle_aa(ik, it->cx[i], it->cy[i], p->r, ic, mode);
        } else if (lib == LIB_CAIRO) {
            for (int i = 0; i < n; i++) {
                cairo_arc(cr, it->cx[i], it->cy[i], p->r, 0, 2 * 3.14159265358979323846);
                cairo_fill(cr);
            }
        } else if (lib == LIB_AGG) {
            peer_agg_discs(k->agg, n, it->cx, it->cy, p->r, col, p->add);
        } else if (lib == LIB_SDL) {
            for (int i = 0; i < n; i++)
                filledCircleRGBA(k->sdl_r, (Sint16)lround(it->cx[i]), (Sint16)lround(it->cy[i]),
                                 (Sint16)lround(p->r), col[0], col[1], col[2], col[3]);
        }
        break;
    case P_SPRITE: {
        const int S = p->S;
        if (lib == LIB_ISKRA) {
            const isk_sprite *s = white ? &p->spr_white : &p->spr;
            if (p->tinted)
                for (int i = 0; i < n; i++)
                    isk_draw_sprite_tinted(ik, s, it->cx[i], it->cy[i], ic, mode);
            else
                for (int i = 0; i < n; i++)
                    isk_draw_sprite(ik, s, it->cx[i], it->cy[i], mode);
        } else if (lib == LIB_PIXMAN) {
            if (p->tinted) {
                pixman_color_t pc = pm_color(col);
                pixman_image_t *src = pixman_image_create_solid_fill(&pc);
                for (int i = 0; i < n; i++)
                    pixman_image_composite32(pop, src, p->pm_mask, k->px, 0, 0, 0, 0, it->sx[i], it->sy[i], S, S);
                pixman_image_unref(src);
            } else {
                for (int i = 0; i < n; i++)
                    pixman_image_composite32(pop, p->pm_img[white], NULL, k->px, 0, 0, 0, 0, it->sx[i], it->sy[i], S,
                                             S);
            }
        } else if (lib == LIB_CAIRO) {
            for (int i = 0; i < n; i++) {
                if (p->tinted) {
                    cairo_mask_surface(cr, p->cs_mask, it->sx[i], it->sy[i]);
                } else {
                    cairo_set_source_surface(cr, p->cs_img[white], it->sx[i], it->sy[i]);
                    cairo_rectangle(cr, it->sx[i], it->sy[i], S, S);
                    cairo_fill(cr);
                }
            }
        } else if (lib == LIB_AGG) {
            if (p->tinted)
                peer_agg_masks(k->agg, n, it->sx, it->sy, p->mask, S, col, p->add);
            else
                peer_agg_images(k->agg, n, it->sx, it->sy, p->img[white], S, p->add);
        } else if (lib == LIB_SDL) {
            SDL_Surface *img = p->sdl_img[p->tinted ? 1 : white];
            for (int i = 0; i < n; i++) {
                if (p->tinted) { /* a white sprite modulated per call */
                    SDL_SetSurfaceColorMod(img, col[0], col[1], col[2]);
                    SDL_SetSurfaceAlphaMod(img, col[3]);
                }
                SDL_Rect r = {it->sx[i], it->sy[i], S, S};
                SDL_BlitSurface(img, NULL, k->sdl, &r);
            }
            SDL_SetSurfaceColorMod(img, 255, 255, 255);
            SDL_SetSurfaceAlphaMod(img, 255);
        }
        break;
    }
    }
}

/* ---- same-work check ----------------------------------------------------- */

/* A grid of separated items, 48 of them, replacing it's positions. */
static void grid_items(items *g, const prim *p)
{
    int pitch = p->kind == P_SPRITE ? p->S + 4 : p->kind == P_DISC ? (int)(2 * p->r) + 6 : 4;
    unsigned long long seed = 99;
    for (int i = 0; i < 48; i++) {
        double ox = 8 + (i % 8) * pitch, oy = 8 + (i / 8) * pitch;
        double fx = bench_urand(&seed), fy = bench_urand(&seed);
        g->dx[i] = ox + fx;
        g->dy[i] = oy + fy;
        isk_view_to_world(&g->view, g->dx[i], g->dy[i], &g->wx[i], &g->wy[i]);
        g->px[i] = (int)ox;
        g->py[i] = (int)oy;
        g->cx[i] = ox + p->r + 1 + fx;
        g->cy[i] = oy + p->r + 1 + fy;
        if (p->kind == P_SPRITE) {
            /* integer-ish centres so iskra uses the phase-0 mask the peers get */
            g->cx[i] = ox + p->S / 2.0;
            g->cy[i] = oy + p->S / 2.0;
            g->sx[i] = (int)ox;
            g->sy[i] = (int)oy;
        }
    }
    g->n = 48;
}

/* ---- main --------------------------------------------------------------- */

static const char *SK_NAME[3] = {"disc", "linear", "smooth"};

int main(int argc, char **argv)
{
    int reps = argc > 1 ? atoi(argv[1]) : 7;
    if (reps < 1 || reps > MAXREP) {
        fprintf(stderr, "bench_peers: reps must be 1..%d\n", MAXREP);
        return 1;
    }
    static canvases k;
    for (int l = 0; l < NLIB; l++)
        if (!(k.buf[l] = malloc((size_t)W * H * 4)))
            return 1;
    for (int i = 0; i < 2; i++)
        if (isk_canvas_wrap(&k.isk[i], k.buf[i], W, H, (size_t)W * 4) != ISK_OK)
            return 1;
    k.cs = cairo_image_surface_create_for_data(k.buf[LIB_CAIRO], CAIRO_FORMAT_ARGB32, W, H, W * 4);
    k.cr = cairo_create(k.cs);
    k.px = pixman_image_create_bits(PIXMAN_a8b8g8r8, W, H, (uint32_t *)(void *)k.buf[LIB_PIXMAN], W * 4);
    k.agg = peer_agg_create(k.buf[LIB_AGG], W, H, W * 4);
    k.sdl = SDL_CreateRGBSurfaceWithFormatFrom(k.buf[LIB_SDL], W, H, 32, W * 4, SDL_PIXELFORMAT_ABGR8888);
    k.sdl_r = k.sdl ? SDL_CreateSoftwareRenderer(k.sdl) : NULL;
    if (!k.cr || !k.px || !k.agg || !k.sdl || !k.sdl_r) {
        fprintf(stderr, "bench_peers: could not set up the peer canvases (%s)\n", SDL_GetError());
        return 1;
    }

    static items it, grid;
    int nmax = NDOT;
    if (isk_view_window(&it.view, W, H, -4, 4, -3, 3) != ISK_OK)
        return 1;
    grid.view = it.view;
    items *both[2] = {&it, &grid};
    for (int b = 0; b < 2; b++) {
        items *t = both[b];
        t->wx = malloc(nmax * sizeof(double)); t->wy = malloc(nmax * sizeof(double));
        t->dx = malloc(nmax * sizeof(double)); t->dy = malloc(nmax * sizeof(double));
        t->cx = malloc(nmax * sizeof(double)); t->cy = malloc(nmax * sizeof(double));
        t->px = malloc(nmax * sizeof(int)); t->py = malloc(nmax * sizeof(int));
        t->sx = malloc(nmax * sizeof(int)); t->sy = malloc(nmax * sizeof(int));
        if (!t->wx || !t->wy || !t->dx || !t->dy || !t->cx || !t->cy || !t->px || !t->py || !t->sx || !t->sy)
            return 1;
    }
    unsigned long long seed = 12;
    for (int i = 0; i < nmax; i++) {
        it.wx[i] = -4.0 + 8.0 * bench_urand(&seed);
        it.wy[i] = -3.0 + 6.0 * bench_urand(&seed);
        isk_view_to_screen(&it.view, it.wx[i], it.wy[i], &it.dx[i], &it.dy[i]);
        it.px[i] = (int)(bench_urand(&seed) * W);
        it.py[i] = (int)(bench_urand(&seed) * H);
        it.cx[i] = 20 + bench_urand(&seed) * (W - 40);
        it.cy[i] = 20 + bench_urand(&seed) * (H - 40);
    }

    /* the primitives */
    static prim ps[64];
    int np = 0;
    for (int add = 0; add < 2; add++) {
        ps[np++] = (prim){.kind = P_DOT, .add = add};
    }
    for (int add = 0; add < 2; add++)
        ps[np++] = (prim){.kind = P_PIXEL, .add = add};
    static const double radii[3] = {1, 3, 8};
    for (int r = 0; r < 3; r++)
        ps[np++] = (prim){.kind = P_DISC, .r = radii[r]};
    static const int sizes[3] = {8, 12, 32};
    for (int sk = 0; sk < 3; sk++)
        for (int d = 0; d < 3; d++)
            for (int t = 0; t < 2; t++)
                for (int add = 0; add < 2; add++) {
                    prim *p = &ps[np++];
                    *p = (prim){.kind = P_SPRITE, .add = add, .sk = sk, .S = sizes[d], .tinted = t};
                    isk_color ic = {COL[0], COL[1], COL[2], COL[3]};
                    if (isk_sprite_init(&p->spr, (isk_sprite_kind)sk, p->S, t ? ISK_WHITE : ic) != ISK_OK ||
                        isk_sprite_init(&p->spr_white, (isk_sprite_kind)sk, p->S, ISK_WHITE) != ISK_OK)
                        return 1;
                    sprite_assets(p);
                }

    printf("bench_peers: %dx%d opaque canvases, colour (255,180,60,200), fastest of %d interleaved passes, ns per "
           "item\n",
           W, H, reps);
    printf("%-30s", "primitive");
    for (int l = 0; l < NLIB; l++)
        printf(" %10s", LIB_NAME[l]);
    printf("   %-28s %s\n", "iskra / peer", "same work (px per item; iskra, then peers)");
    /* Every primitive's same-work check first, then the timed passes: the
     * repetitions are the outer loop, so each primitive's passes are spread
     * over the whole run and a burst of load elsewhere on the machine
     * cannot spoil all of them. */
    static double area[64][NLIB], t[64][NLIB][MAXREP];
    for (int pi = 0; pi < np; pi++) {
        prim *p = &ps[pi];
        grid_items(&grid, p);
        for (int l = 0; l < NLIB; l++) {
            if (!prim_has(p, l))
                continue;
            fill_opaque(&k, l, 1);
            draw(&k, &grid, p, l, WHITE);
            area[pi][l] = area_of(&k, l) / grid.n;
        }
    }
    for (int rep = 0; rep < reps; rep++)
        for (int pi = 0; pi < np; pi++) {
            prim *p = &ps[pi];
            /* sprites at integer top-left for the peers */
            it.n = p->kind == P_DOT ? NDOT : p->kind == P_PIXEL ? NPIX : p->kind == P_DISC ? NDISC : NSPR;
            if (p->kind == P_SPRITE)
                for (int i = 0; i < it.n; i++) {
                    it.sx[i] = (int)floor(it.cx[i] - p->S / 2.0);
                    it.sy[i] = (int)floor(it.cy[i] - p->S / 2.0);
                }
            for (int l = 0; l < NLIB; l++) {
                if (!prim_has(p, l))
                    continue;
                fill_opaque(&k, l, 0);
                double t0 = bench_cpu_now();
                draw(&k, &it, p, l, COL);
                t[pi][l][rep] = bench_cpu_now() - t0;
            }
        }
    int bad = 0;
    for (int pi = 0; pi < np; pi++) {
        prim *p = &ps[pi];
        char name[64];
        switch (p->kind) {
        case P_DOT: snprintf(name, sizeof name, "coverage dot, %s", p->add ? "add" : "over"); break;
        case P_PIXEL: snprintf(name, sizeof name, "single pixel, %s", p->add ? "add" : "over"); break;
        case P_DISC: snprintf(name, sizeof name, "AA disc r=%g, over", p->r); break;
        case P_SPRITE:
            snprintf(name, sizeof name, "sprite %s d=%d%s, %s", SK_NAME[p->sk], p->S, p->tinted ? " tint" : "",
                     p->add ? "add" : "over");
            break;
        }
        const int n = p->kind == P_DOT ? NDOT : p->kind == P_PIXEL ? NPIX : p->kind == P_DISC ? NDISC : NSPR;
        double med[NLIB], mid[NLIB];
        printf("%-30s", name);
        for (int l = 0; l < NLIB; l++) {
            if (!prim_has(p, l)) {
                printf(" %10s", "-");
                continue;
            }
            mid[l] = bench_median(t[pi][l], reps) * 1e9 / n; /* sorts: t[pi][l][0] is the fastest */
            med[l] = t[pi][l][0] * 1e9 / n;
            printf(" %10.1f", med[l]);
        }
        /* the ratio the target is stated against */
        int ref = p->kind == P_SPRITE ? LIB_PIXMAN : LIB_AGG;
        printf("   %-6s %5.2fx (median %4.2fx)", LIB_NAME[ref], med[LIB_ISKRA] / med[ref], mid[LIB_ISKRA] / mid[ref]);
        double tol = p->kind == P_DISC ? 0.02 + 0.12 / p->r : 0.02;
        printf(" %.3g", area[pi][LIB_ISKRA]);
        for (int l = 0; l < NLIB; l++) {
            if (l == LIB_ISKRA || !prim_has(p, l))
                continue;
            int compared = !(p->kind == P_DISC && l == LIB_SDL) && !(p->kind == P_PIXEL && l == LIB_SDL);
            double rel = fabs(area[pi][l] - area[pi][LIB_ISKRA]) / area[pi][LIB_ISKRA];
            int ok = !compared || rel <= tol;
            bad |= !ok;
            printf(" %s %.3g%s", LIB_NAME[l], area[pi][l], !compared ? "(aliased)" : ok ? "" : " DIFFERS");
        }
        printf("\n");
    }
    printf("targets: coverage dot >= 10x faster than AGG (ratio <= 0.10); AA disc <= 0.5x AGG;\n"
           "                    sprites <= 0.7x pixman; dot vs the touch floor and single pixel: bench_raster\n");
    printf("same work: %s (drawn area per item against iskra's: within 2%%, discs 2%% + 12%%/r)\n",
           bad ? "DIFFERS" : "ok");

    for (int pi = 0; pi < np; pi++) {
        prim *p = &ps[pi];
        if (p->kind != P_SPRITE)
            continue;
        isk_sprite_free(&p->spr);
        isk_sprite_free(&p->spr_white);
        pixman_image_unref(p->pm_mask);
        cairo_surface_destroy(p->cs_mask);
        for (int w = 0; w < 2; w++) {
            pixman_image_unref(p->pm_img[w]);
            cairo_surface_destroy(p->cs_img[w]);
            SDL_FreeSurface(p->sdl_img[w]);
            free(p->img[w]);
        }
        free(p->mask);
    }
    for (int b = 0; b < 2; b++) {
        items *tt = both[b];
        free(tt->wx); free(tt->wy); free(tt->dx); free(tt->dy); free(tt->cx); free(tt->cy);
        free(tt->px); free(tt->py); free(tt->sx); free(tt->sy);
    }
    SDL_DestroyRenderer(k.sdl_r);
    SDL_FreeSurface(k.sdl);
    peer_agg_destroy(k.agg);
    pixman_image_unref(k.px);
    cairo_destroy(k.cr);
    cairo_surface_destroy(k.cs);
    for (int l = 0; l < NLIB; l++)
        free(k.buf[l]);
    return bad;
}
