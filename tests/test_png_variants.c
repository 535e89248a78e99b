/* SPDX-License-Identifier: MIT */
/* isk_png_read against known pixel values: every colour type and bit depth
 * (grey 1/2/4/8/16, grey+alpha, RGB, RGBA, palette 1/2/4/8), tRNS colour
 * keys and palette alpha, Adam7 interlacing, and gAMA / sRGB / cHRM /
 * iCCP / text chunks that must not change a pixel.  The files are made
 * here with libpng from raw samples; the expected RGBA8 is computed from
 * the same samples by the PNG specification's rules, independently of the
 * reader: n-bit grey scaled by 255 / (2^n - 1), 16-bit samples by 1/257
 * rounded (no gamma), tRNS keys compared at full depth. */
#include <criterion/criterion.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "iskra/png.h"

#define DIR "out/test_png_variants"

enum { EXTRA_GAMMA = 1, EXTRA_SRGB = 2, EXTRA_CHRM = 4, EXTRA_ICCP = 8, EXTRA_TEXT = 16 };

typedef struct variant {
    int w, h;
    int type, depth, interlace;
    uint16_t *samples;            /* w * h * channels, each < 2^depth */
    png_color pal[256];
    int npal;
    png_byte pal_alpha[256];
    int npal_alpha;
    int have_key;                 /* tRNS colour key (grey or RGB) */
    png_color_16 key;
    unsigned extras;
} variant;

static int channels(int type)
{
    switch (type) {
    case PNG_COLOR_TYPE_GRAY: return 1;
    case PNG_COLOR_TYPE_GRAY_ALPHA: return 2;
    case PNG_COLOR_TYPE_RGB: return 3;
    case PNG_COLOR_TYPE_RGB_ALPHA: return 4;
    default: return 1; /* palette index */
    }
}

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* Samples covering the range, with the extremes first. */
static void fill(variant *v, uint32_t seed)
{
    int n = v->w * v->h * channels(v->type);
    unsigned max = v->type == PNG_COLOR_TYPE_PALETTE ? (unsigned)v->npal - 1u : (1u << v->depth) - 1u;
    v->samples = malloc((size_t)n * sizeof *v->samples);
    cr_assert_not_null(v->samples);
    for (int i = 0; i < n; i++)
        v->samples[i] = (uint16_t)(i == 0 ? 0 : i == 1 ? max : lcg(&seed) % (max + 1u));
}

static void make_palette(variant *v, int n, int nalpha)
{
    uint32_t s = 99;
    v->npal = n;
    for (int i = 0; i < n; i++)
        v->pal[i] = (png_color){(png_byte)lcg(&s), (png_byte)lcg(&s), (png_byte)lcg(&s)};
    v->npal_alpha = nalpha;
    for (int i = 0; i < nalpha; i++)
        v->pal_alpha[i] = (png_byte)(i * 37 % 256);
}

static void write_variant(const variant *v, const char *path)
{
    FILE *f = fopen(path, "wb");
    cr_assert_not_null(f, "%s", path);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    cr_assert(png && info);
    if (setjmp(png_jmpbuf(png)))
        cr_assert_fail("libpng could not write %s", path);
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)v->w, (png_uint_32)v->h, v->depth, v->type, v->interlace,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (v->type == PNG_COLOR_TYPE_PALETTE)
        png_set_PLTE(png, info, v->pal, v->npal);
    if (v->npal_alpha)
        png_set_tRNS(png, info, v->pal_alpha, v->npal_alpha, NULL);
    if (v->have_key)
        png_set_tRNS(png, info, NULL, 0, &v->key);
    png_write_info(png, info);
    /* Colour chunks as raw bytes (libpng's setters refuse contradictory
     * ones, which a reader must survive anyway), before IDAT. */
    if (v->extras & EXTRA_GAMMA) {
        static const png_byte gama[] = {0, 1, 0x86, 0xa0}; /* 100000: gamma 1.0, a "linear" file */
        png_write_chunk(png, (png_const_bytep) "gAMA", gama, sizeof gama);
    }
    if (v->extras & EXTRA_SRGB) {
        static const png_byte srgb[] = {0};
        png_write_chunk(png, (png_const_bytep) "sRGB", srgb, sizeof srgb);
    }
    if (v->extras & EXTRA_CHRM) {
        static const png_byte chrm[32] = {0, 0, 0x7a, 0x26, 0, 0, 0x80, 0x84, 0, 0, 0xfa, 0, 0, 0, 0x80, 0xe8,
                                          0, 0, 0x75, 0x30, 0, 0, 0xea, 0x60, 0, 0, 0x3a, 0x98, 0, 0, 0x17, 0x70};
        png_write_chunk(png, (png_const_bytep) "cHRM", chrm, sizeof chrm);
    }
    if (v->extras & EXTRA_ICCP) {
        /* raw chunk bytes: a profile name, compression 0, and junk "data" */
        static const png_byte iccp[] = {'p', 'r', 'o', 'f', 0, 0, 0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01};
        png_write_chunk(png, (png_const_bytep) "iCCP", iccp, sizeof iccp);
    }
    if (v->extras & EXTRA_TEXT) {
        static const png_byte text[] = "Comment\0made by test_png_variants";
        png_write_chunk(png, (png_const_bytep) "tEXt", text, sizeof text - 1);
    }
    int ch = channels(v->type), bits = ch * v->depth;
    size_t rowbytes = ((size_t)v->w * (size_t)bits + 7u) / 8u;
    png_bytep *rows = malloc((size_t)v->h * sizeof *rows);
    png_bytep data = calloc((size_t)v->h, rowbytes);
    cr_assert(rows && data);
    for (int y = 0; y < v->h; y++) {
        rows[y] = data + (size_t)y * rowbytes;
        for (int x = 0; x < v->w * ch; x++) {
            unsigned s = v->samples[(size_t)y * (size_t)(v->w * ch) + (size_t)x];
            if (v->depth == 16) {
                rows[y][2 * x] = (png_byte)(s >> 8);
                rows[y][2 * x + 1] = (png_byte)s;
            } else if (v->depth == 8) {
                rows[y][x] = (png_byte)s;
            } else { /* packed, leftmost pixel in the high bits */
                int bit = x * v->depth;
                rows[y][bit / 8] |= (png_byte)(s << (8 - v->depth - bit % 8));
            }
        }
    }
    if (v->interlace == PNG_INTERLACE_ADAM7)
        png_set_interlace_handling(png);
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
    free(rows);
    free(data);
}

/* The specification's conversion of one sample to 8 bits. */
static uint8_t to8(unsigned s, int depth)
{
    if (depth == 16)
        return (uint8_t)((2u * s + 257u) / 514u); /* round(s / 257) */
    return (uint8_t)(s * 255u / ((1u << depth) - 1u));
}

static void expected(const variant *v, int x, int y, uint8_t px[4])
{
    int ch = channels(v->type);
    const uint16_t *s = v->samples + ((size_t)y * (size_t)v->w + (size_t)x) * (size_t)ch;
    switch (v->type) {
    case PNG_COLOR_TYPE_PALETTE:
        px[0] = v->pal[s[0]].red;
        px[1] = v->pal[s[0]].green;
        px[2] = v->pal[s[0]].blue;
        px[3] = s[0] < v->npal_alpha ? v->pal_alpha[s[0]] : 255;
        return;
    case PNG_COLOR_TYPE_GRAY:
    case PNG_COLOR_TYPE_GRAY_ALPHA:
        px[0] = px[1] = px[2] = to8(s[0], v->depth);
        px[3] = ch == 2 ? to8(s[1], v->depth) : (v->have_key && s[0] == v->key.gray) ? 0 : 255;
        return;
    default:
        for (int k = 0; k < 3; k++)
            px[k] = to8(s[k], v->depth);
        px[3] = ch == 4 ? to8(s[3], v->depth)
                        : (v->have_key && s[0] == v->key.red && s[1] == v->key.green && s[2] == v->key.blue) ? 0
                                                                                                             : 255;
    }
}

static void check(variant *v, const char *name)
{
    mkdir("out", 0777);
    mkdir(DIR, 0777);
    char path[256];
    snprintf(path, sizeof path, DIR "/%s.png", name);
    write_variant(v, path);
    isk_canvas c, m;
    isk_error err;
    cr_assert_eq(isk_png_read(&c, path, &err), ISK_OK, "%s: %s", name, err.message);
    cr_assert_eq(c.width, v->w, "%s", name);
    cr_assert_eq(c.height, v->h, "%s", name);
    for (int y = 0; y < v->h; y++)
        for (int x = 0; x < v->w; x++) {
            uint8_t want[4];
            expected(v, x, y, want);
            const uint8_t *got = isk_canvas_at(&c, x, y);
            cr_assert(!memcmp(got, want, 4), "%s (%d,%d): got %d,%d,%d,%d, want %d,%d,%d,%d", name, x, y, got[0],
                      got[1], got[2], got[3], want[0], want[1], want[2], want[3]);
        }
    /* the same bytes from memory decode the same */
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f);
    static uint8_t buf[1 << 20];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    cr_assert_eq(isk_png_read_memory(&m, buf, n, name, ISK_PNG_MAX_PIXELS_DEFAULT, &err), ISK_OK, "%s",
                 err.message);
    cr_assert(isk_canvas_equal(&c, &m), "%s: memory and file reads differ", name);
    isk_png_info info;
    cr_assert_eq(isk_png_read_info(path, &info, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(info.width, v->w);
    cr_assert_eq(info.bit_depth, v->depth);
    cr_assert_eq(info.color_type, v->type);
    cr_assert_eq(info.interlaced, v->interlace == PNG_INTERLACE_ADAM7);
    isk_canvas_free(&c);
    isk_canvas_free(&m);
    free(v->samples);
    v->samples = NULL;
}

static variant plain(int type, int depth, int w, int h)
{
    variant v;
    memset(&v, 0, sizeof v);
    v.w = w;
    v.h = h;
    v.type = type;
    v.depth = depth;
    v.interlace = PNG_INTERLACE_NONE;
    return v;
}

Test(png_variants, grey_at_every_depth)
{
    const int depths[] = {1, 2, 4, 8, 16};
    for (int i = 0; i < 5; i++) {
        variant v = plain(PNG_COLOR_TYPE_GRAY, depths[i], 37, 5);
        fill(&v, (uint32_t)depths[i]);
        char name[32];
        snprintf(name, sizeof name, "grey%d", depths[i]);
        check(&v, name);
    }
}

/* The reliability audit's case: 16-bit grey without colour information,
 * sample 37 * 257 = 9509, read as 106 by a gamma-encoding reader. */
Test(png_variants, sixteen_bit_is_scaled_by_1_over_257_without_gamma)
{
    const unsigned values[] = {0, 37u * 257u, 65535, 128, 129, 32768, 51528, 51529, 1000};
    const unsigned extras[] = {0, EXTRA_GAMMA, EXTRA_SRGB | EXTRA_CHRM, EXTRA_ICCP | EXTRA_TEXT};
    for (int e = 0; e < 4; e++) {
        variant v = plain(PNG_COLOR_TYPE_GRAY, 16, 9, 1);
        v.extras = extras[e];
        v.samples = malloc(9 * sizeof *v.samples);
        for (int i = 0; i < 9; i++)
            v.samples[i] = (uint16_t)values[i];
        char name[32];
        snprintf(name, sizeof name, "grey16_known_%d", e);
        check(&v, name);
        isk_canvas c;
        char path[64];
        snprintf(path, sizeof path, DIR "/grey16_known_%d.png", e);
        cr_assert_eq(isk_png_read(&c, path, NULL), ISK_OK);
        const uint8_t want[9] = {0, 37, 255, 0, 1, 128, 200, 201, 4};
        for (int i = 0; i < 9; i++)
            cr_assert_eq(isk_canvas_at(&c, i, 0)[0], want[i], "sample %u -> %d, want %d", values[i],
                         isk_canvas_at(&c, i, 0)[0], want[i]);
        isk_canvas_free(&c);
    }
}

Test(png_variants, grey_alpha_rgb_rgba_8_and_16)
{
    const int types[] = {PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    for (int t = 0; t < 3; t++)
        for (int d = 8; d <= 16; d += 8) {
            variant v = plain(types[t], d, 23, 7);
            fill(&v, (uint32_t)(t * 100 + d));
            char name[32];
            snprintf(name, sizeof name, "type%d_%d", types[t], d);
            check(&v, name);
        }
}

Test(png_variants, palette_at_every_depth_with_trns_alpha)
{
    const int depths[] = {1, 2, 4, 8};
    for (int i = 0; i < 4; i++) {
        variant v = plain(PNG_COLOR_TYPE_PALETTE, depths[i], 19, 6);
        int n = 1 << depths[i];
        make_palette(&v, n > 200 ? 200 : n, n > 2 ? n / 2 : 1); /* some entries without alpha: opaque */
        fill(&v, (uint32_t)(7 + depths[i]));
        char name[32];
        snprintf(name, sizeof name, "palette%d", depths[i]);
        check(&v, name);
        variant o = plain(PNG_COLOR_TYPE_PALETTE, depths[i], 19, 6);
        make_palette(&o, n > 200 ? 200 : n, 0); /* no tRNS: all opaque */
        fill(&o, (uint32_t)(70 + depths[i]));
        snprintf(name, sizeof name, "palette%d_opaque", depths[i]);
        check(&o, name);
    }
}

Test(png_variants, trns_colour_keys_compare_at_full_depth)
{
    variant g = plain(PNG_COLOR_TYPE_GRAY, 8, 16, 16);
    fill(&g, 5);
    g.have_key = 1;
    g.key.gray = g.samples[7];
    check(&g, "grey8_key");
    /* 16-bit: 1000 is transparent, 1001 (also 4 in 8 bits) is not */
    variant g16 = plain(PNG_COLOR_TYPE_GRAY, 16, 4, 1);
    g16.samples = malloc(4 * sizeof *g16.samples);
    g16.samples[0] = 1000;
    g16.samples[1] = 1001;
    g16.samples[2] = 999;
    g16.samples[3] = 1000;
    g16.have_key = 1;
    g16.key.gray = 1000;
    check(&g16, "grey16_key");
    variant rgb = plain(PNG_COLOR_TYPE_RGB, 8, 16, 16);
    fill(&rgb, 11);
    rgb.have_key = 1;
    rgb.key.red = rgb.samples[30];
    rgb.key.green = rgb.samples[31];
    rgb.key.blue = rgb.samples[32];
    check(&rgb, "rgb8_key");
    variant rgb16 = plain(PNG_COLOR_TYPE_RGB, 16, 8, 8);
    fill(&rgb16, 12);
    rgb16.have_key = 1;
    rgb16.key.red = rgb16.samples[3];
    rgb16.key.green = rgb16.samples[4];
    rgb16.key.blue = rgb16.samples[5];
    check(&rgb16, "rgb16_key");
}

Test(png_variants, adam7_interlacing_reads_like_the_plain_file)
{
    static const struct {
        int type, depth;
    } kinds[] = {{PNG_COLOR_TYPE_RGB_ALPHA, 8}, {PNG_COLOR_TYPE_GRAY, 16}, {PNG_COLOR_TYPE_PALETTE, 4},
                 {PNG_COLOR_TYPE_GRAY, 1}, {PNG_COLOR_TYPE_RGB, 16}};
    const int sizes[][2] = {{1, 1}, {13, 11}, {3, 9}};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        for (int s = 0; s < 3; s++) {
            variant v = plain(kinds[k].type, kinds[k].depth, sizes[s][0], sizes[s][1]);
            v.interlace = PNG_INTERLACE_ADAM7;
            if (v.type == PNG_COLOR_TYPE_PALETTE)
                make_palette(&v, 16, 5);
            fill(&v, (uint32_t)(k * 10 + (size_t)s));
            char name[48];
            snprintf(name, sizeof name, "adam7_%zu_%d", k, s);
            check(&v, name);
        }
}

Test(png_variants, colour_and_text_chunks_change_no_pixel)
{
    const unsigned extras[] = {EXTRA_GAMMA, EXTRA_SRGB, EXTRA_CHRM | EXTRA_GAMMA, EXTRA_ICCP, EXTRA_TEXT,
                               EXTRA_GAMMA | EXTRA_SRGB | EXTRA_CHRM | EXTRA_ICCP | EXTRA_TEXT};
    for (int e = 0; e < 6; e++) {
        variant v = plain(e % 2 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, e < 3 ? 8 : 16, 11, 4);
        v.extras = extras[e];
        fill(&v, (uint32_t)(300 + e));
        char name[32];
        snprintf(name, sizeof name, "chunks_%d", e);
        check(&v, name);
    }
}
