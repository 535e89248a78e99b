/* SPDX-License-Identifier: MIT */
/* PNG reading is bounded: a chunk that declares gigabytes costs nothing, a
 * tiny file declaring a huge image is refused from its header before any
 * pixel memory is taken (isk_png_read's cap, `iskra compare --max-pixels`),
 * `iskra compare` compares the headers' sizes before decoding, and every
 * truncation or corruption of a file fails cleanly. */
#include <criterion/criterion.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include "iskra/png.h"
#include "tool_cli.h"

#define DIR "out/test_png_limits"

static long max_rss_kb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

static uint32_t crc32_of(const uint8_t *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

static size_t put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
    return 4;
}

/* A chunk with its CRC; returns the bytes written. */
static size_t chunk(uint8_t *p, const char *type, const uint8_t *data, uint32_t n)
{
    size_t k = put32(p, n);
    memcpy(p + k, type, 4);
    memcpy(p + k + 4, data, n);
    put32(p + k + 4 + n, crc32_of(p + k, 4 + n));
    return k + 8 + n;
}

/* The audit's 277-byte file: a 1x1 RGBA IHDR, then a `type` chunk whose
 * length field says 2 GiB - 1, then a few bytes and the end of the file. */
static size_t hostile_chunk_file(uint8_t *buf, const char *type)
{
    static const uint8_t sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    memcpy(buf, sig, 8);
    uint8_t ihdr[13] = {0, 0, 0, 1, 0, 0, 0, 1, 8, 6, 0, 0, 0};
    size_t n = 8 + chunk(buf + 8, "IHDR", ihdr, 13);
    n += put32(buf + n, 0x7fffffffu);
    memcpy(buf + n, type, 4);
    n += 4;
    while (n < 277)
        buf[n++] = 'x';
    return n;
}

Test(png_limits, a_chunk_declaring_two_gigabytes_costs_nothing, .timeout = 20)
{
    mkdir("out", 0777);
    mkdir(DIR, 0777);
    const char *types[] = {"tEXt", "zTXt", "iTXt", "iCCP", "sPLT", "abCd", "eXIf"};
    long before = max_rss_kb();
    for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
        uint8_t buf[512];
        size_t n = hostile_chunk_file(buf, types[t]);
        cr_assert_eq(n, 277);
        char path[64];
        snprintf(path, sizeof path, DIR "/huge_%s.png", types[t]);
        FILE *f = fopen(path, "wb");
        cr_assert_not_null(f);
        fwrite(buf, 1, n, f);
        fclose(f);
        isk_canvas c;
        isk_error err;
        cr_assert_neq(isk_png_read(&c, path, &err), ISK_OK, "%s", types[t]);
        cr_assert_null(c.pixels);
        cr_assert_neq(isk_png_read_memory(&c, buf, n, types[t], ISK_PNG_MAX_PIXELS_DEFAULT, &err), ISK_OK);
        cr_assert_null(c.pixels);
    }
    long grown_mb = (max_rss_kb() - before) / 1024;
    cr_assert_lt(grown_mb, 32, "reading 277-byte files grew the peak memory by %ld MB", grown_mb);
}

/* A w x h 1-bit grey image of zeros: a few kilobytes for any size. */
static void write_sparse(const char *path, png_uint_32 w, png_uint_32 h)
{
    FILE *f = fopen(path, "wb");
    cr_assert_not_null(f, "%s", path);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png)))
        cr_assert_fail("libpng could not write %s", path);
    png_init_io(png, f);
    png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
    png_set_IHDR(png, info, w, h, 1, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_filter(png, 0, PNG_FILTER_NONE);
    png_set_compression_level(png, 9);
    png_write_info(png, info);
    png_bytep row = calloc((w + 7) / 8, 1);
    for (png_uint_32 y = 0; y < h; y++)
        png_write_row(png, row);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
    free(row);
}

/* Criterion runs tests in parallel: each test makes its own files in sub. */
static void make_files(const char *sub)
{
    char path[128];
    mkdir("out", 0777);
    mkdir(DIR, 0777);
    snprintf(path, sizeof path, DIR "/%s", sub);
    mkdir(path, 0777);
    static const struct {
        const char *name;
        png_uint_32 w, h;
    } files[] = {{"big", 16384, 16384}, {"tiny", 1, 1}, {"wide", 20000, 1}, {"hundred", 100, 100}};
    for (int i = 0; i < 4; i++) {
        snprintf(path, sizeof path, DIR "/%s/%s.png", sub, files[i].name);
        write_sparse(path, files[i].w, files[i].h);
    }
}

#undef DIR
#define DIR "out/test_png_limits/header"
Test(png_limits, a_huge_image_is_refused_from_its_header, .timeout = 60)
{
    make_files("header");
    struct stat st;
    cr_assert_eq(stat(DIR "/big.png", &st), 0);
    cr_assert_lt(st.st_size, 64 * 1024, "the 16384x16384 file is %lld bytes", (long long)st.st_size);
    long before = max_rss_kb();
    isk_png_info info;
    isk_error err;
    cr_assert_eq(isk_png_read_info(DIR "/big.png", &info, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(info.width, 16384);
    cr_assert_eq(info.height, 16384);
    cr_assert_eq(info.bit_depth, 1);
    isk_canvas c;
    cr_assert_eq(isk_png_read(&c, DIR "/big.png", &err), ISK_ERR_SIZE);
    cr_assert_str_eq(err.message, DIR "/big.png: 16384x16384 = 268435456 pixels, more than the limit of 67108864");
    cr_assert_null(c.pixels);
    cr_assert_eq(isk_png_read_max(&c, DIR "/hundred.png", 9999, &err), ISK_ERR_SIZE);
    cr_assert_eq(isk_png_read_max(&c, DIR "/hundred.png", 10000, &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&c);
    cr_assert_eq(isk_png_read_max(&c, DIR "/hundred.png", 0, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_png_read_max(&c, DIR "/hundred.png", 16384LL * 16384 + 1, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_png_read(&c, DIR "/wide.png", &err), ISK_ERR_SIZE);
    cr_assert_not_null(strstr(err.message, "20000x1 is above the largest canvas, 16384x16384"), "%s", err.message);
    cr_assert_eq(isk_png_read_info(DIR "/wide.png", &info, &err), ISK_ERR_SIZE);
    long grown_mb = (max_rss_kb() - before) / 1024;
    cr_assert_lt(grown_mb, 32, "refusing grew the peak memory by %ld MB", grown_mb);
}

#undef DIR
#define DIR "out/test_png_limits/compare"
Test(png_limits, compare_checks_the_headers_before_decoding, .timeout = 60)
{
    make_files("compare");
    const char *log = DIR "/cli";
    cli_fresh(log);
    /* Different sizes: known from the headers; decoding the 16384x16384
     * image would have hit the limit instead. */
    cr_assert_eq(cli_run(log, "compare " DIR "/big.png " DIR "/tiny.png"), 1);
    char *out = cli_slurp(DIR "/cli/stdout.txt");
    cr_assert_str_eq(out, "size differs: 16384x16384 vs 1x1\n");
    free(out);
    char *err = cli_slurp(DIR "/cli/stderr.txt");
    cr_assert_str_eq(err, "");
    free(err);
    /* Same size, too big to decode: refused (exit 2, as unreadable) with
     * the limit and the option */
    cr_assert_eq(cli_run(log, "compare " DIR "/big.png " DIR "/big.png"), 2);
    err = cli_slurp(DIR "/cli/stderr.txt");
    cr_assert_not_null(strstr(err, "16384x16384 = 268435456 pixels, more than the limit of 67108864 (see --max-pixels)"),
                       "%s", err);
    free(err);
    cr_assert_eq(cli_run(log, "compare " DIR "/hundred.png " DIR "/hundred.png --max-pixels 9999"), 2);
    cr_assert_eq(cli_run(log, "compare " DIR "/hundred.png " DIR "/hundred.png --max-pixels 10000"), 0);
    /* a diff image of mismatched sizes is bounded too */
    cr_assert_eq(cli_run(log, "compare " DIR "/big.png " DIR "/tiny.png --diff " DIR "/cli/d.png"), 2);
    cr_assert_not(cli_exists(DIR "/cli/d.png"));
    const char *bad[] = {"--max-pixels 0", "--max-pixels -5", "--max-pixels 268435457", "--max-pixels x",
                         "--max-pixels"};
    for (int i = 0; i < 5; i++) {
        char args[256];
        snprintf(args, sizeof args, "compare " DIR "/tiny.png " DIR "/tiny.png %s", bad[i]);
        cr_assert_eq(cli_run(log, args), 2, "%s", args);
    }
}

/* Every prefix of a valid file, and every single-byte corruption of it,
 * is refused or read, never a crash or a leak (ASan in the sanitizer run). */
#undef DIR
#define DIR "out/test_png_limits"
Test(png_limits, every_truncation_and_corruption_fails_cleanly, .timeout = 120)
{
    mkdir("out", 0777);
    mkdir(DIR, 0777);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 9, 7), ISK_OK);
    for (int y = 0; y < 7; y++)
        for (int x = 0; x < 9; x++) {
            uint8_t *p = isk_canvas_at(&c, x, y);
            p[0] = (uint8_t)(x * 30);
            p[1] = (uint8_t)(y * 40);
            p[2] = (uint8_t)(x ^ y);
            p[3] = (uint8_t)(200 + x);
        }
    cr_assert_eq(isk_png_write(&c, DIR "/small.png", NULL), ISK_OK);
    FILE *f = fopen(DIR "/small.png", "rb");
    static uint8_t buf[4096];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    cr_assert_lt(n, sizeof buf);
    isk_canvas r;
    isk_error err;
    for (size_t k = 0; k < n; k++) {
        isk_status s = isk_png_read_memory(&r, buf, k, "prefix", ISK_PNG_MAX_PIXELS_DEFAULT, &err);
        cr_assert_neq(s, ISK_OK, "a %zu-byte prefix of %zu was accepted", k, n);
        cr_assert_null(r.pixels);
    }
    cr_assert_eq(isk_png_read_memory(&r, buf, n, "whole", ISK_PNG_MAX_PIXELS_DEFAULT, &err), ISK_OK, "%s",
                 err.message);
    cr_assert(isk_canvas_equal(&r, &c));
    isk_canvas_free(&r);
    static uint8_t bad[4096];
    for (size_t k = 0; k < n; k++)
        for (int bit = 0; bit < 8; bit += 3) {
            memcpy(bad, buf, n);
            bad[k] ^= (uint8_t)(1u << bit);
            if (isk_png_read_memory(&r, bad, n, "flipped", ISK_PNG_MAX_PIXELS_DEFAULT, &err) == ISK_OK) {
                cr_assert_eq(r.width, 9); /* only an ancillary-chunk or benign flip can pass */
                isk_canvas_free(&r);
            } else {
                cr_assert_null(r.pixels);
            }
        }
    isk_canvas_free(&c);
}
