/* SPDX-License-Identifier: MIT */
/* PNG files (iskra/png.h).  Writing: libpng's simplified API into an
 * isk_outfile.  Reading: libpng's full API, so the limits, the skipped
 * chunks and the conversion to RGBA8 (no gamma, 16 bits scaled by 1/257)
 * are ours to choose.  No printing: messages end up in isk_error. */
#include "iskra/png.h"

#include <errno.h>
#include <png.h>
#ifdef PNG_SETJMP_SUPPORTED
#include <setjmp.h>
#endif
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/outfile.h"
#include "io/png_own.h"

/* libpng's own allocations per chunk (we keep no ancillary chunk, so only
 * PLTE and tRNS, at most 768 bytes, are ever stored). */
#define CHUNK_MALLOC_MAX (1u << 20)
#define CHUNK_CACHE_MAX 64u

/* ---- writing ---------------------------------------------------------------- */

static isk_status check_canvas(const isk_canvas *c, const char *what, isk_error *err)
{
    if (!c)
        return isk_error_set(err, ISK_ERR_NULL, "png %s: NULL canvas", what);
    if (!c->pixels || c->width <= 0 || c->height <= 0 || c->width > ISK_CANVAS_MAX_DIM ||
        c->height > ISK_CANVAS_MAX_DIM)
        return isk_error_set(err, ISK_ERR_SIZE, "png %s: empty or malformed canvas (%dx%d)", what, c->width,
                             c->height);
    if (c->stride < (size_t)c->width * 4u || c->stride > 0x7fffffff)
        return isk_error_set(err, ISK_ERR_SIZE, "png %s: stride %zu does not fit rows of %d pixels", what,
                             c->stride, c->width);
    return ISK_OK;
}

/* Writing: libpng's write struct; every failure (a short write, memory)
 * comes back through write_failed's longjmp.  Targets whose libpng has no
 * setjmp (the browser's) abort on such a failure instead: only running out
 * of memory can cause one there, as their files live in memory. */
typedef struct png_writer {
    FILE *f;
    char msg[200];
} png_writer;

static void write_failed(png_structp png, png_const_charp msg)
{
    png_writer *w = png_get_error_ptr(png);
    snprintf(w->msg, sizeof w->msg, "%s", msg);
    png_longjmp(png, 1);
}

static void write_bytes(png_structp png, png_bytep data, size_t n)
{
    png_writer *w = png_get_io_ptr(png);
    if (fwrite(data, 1, n, w->f) != n)
        png_error(png, errno ? strerror(errno) : "write failed");
}

static void flush_bytes(png_structp png)
{
    png_writer *w = png_get_io_ptr(png);
    if (fflush(w->f) != 0)
        png_error(png, errno ? strerror(errno) : "write failed");
}

/* What libpng's simplified writer (png_image_write_to_stdio, RGBA8) writes,
 * call for call, so the files' bytes are those it gave: an sRGB chunk,
 * default filters and compression, one row at a time.  Returns 0 after a
 * longjmp (w->msg says why). */
static int write_rows(png_structp png, png_infop pi, const isk_canvas *c)
{
#ifdef PNG_SETJMP_SUPPORTED
    if (setjmp(png_jmpbuf(png)))
        return 0;
#endif
    png_set_benign_errors(png, 0);
    png_set_IHDR(png, pi, (png_uint_32)c->width, (png_uint_32)c->height, 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_set_sRGB(png, pi, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, pi);
    for (int y = 0; y < c->height; y++)
        png_write_row(png, c->pixels + (size_t)y * c->stride);
    png_write_end(png, pi);
    return 1;
}

/* zlib's deflate at the default window and memLevel takes 256 KiB and an
 * 8 KiB output buffer; libpng's handles are a few KiB: room to spare. */
#define PNG_WRITER_BYTES ((size_t)512 << 10)
/* libpng's row buffers while writing: the row, the previous row and the
 * filters' trial rows, each a filter byte longer. */
#define PNG_WRITER_ROWS 5

size_t isk_png_write_memory(int width)
{
    if (width < 1)
        return 0;
    return PNG_WRITER_ROWS * ((size_t)width * 4u + 1u) + PNG_WRITER_BYTES;
}

isk_status isk_png_write_stream(const isk_canvas *c, FILE *f, const char *name, isk_error *err)
{
    isk_status s = check_canvas(c, "write", err);
    if (s != ISK_OK)
        return s;
    if (!f)
        return isk_error_set(err, ISK_ERR_NULL, "png write: NULL stream");
    png_writer w = {f, ""};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w, write_failed, NULL);
    png_infop pi = png ? png_create_info_struct(png) : NULL;
    if (!pi) {
        png_destroy_write_struct(&png, NULL);
        return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", name ? name : "png");
    }
    png_set_write_fn(png, &w, write_bytes, flush_bytes);
    int ok = write_rows(png, pi, c);
    png_destroy_write_struct(&png, &pi);
    if (!ok)
        return isk_error_set(err, ISK_ERR_IO, "%s: %s", name ? name : "png", w.msg[0] ? w.msg : "write failed");
    return ISK_OK;
}

isk_status isk_png_write(const isk_canvas *c, const char *path, isk_error *err)
{
    isk_status s = check_canvas(c, "write", err);
    if (s != ISK_OK)
        return s;
    if (!path)
        return isk_error_set(err, ISK_ERR_NULL, "png write: NULL path");
    isk_outfile o;
    if ((s = isk_outfile_open(&o, path, err)) != ISK_OK)
        return s;
    if ((s = isk_png_write_stream(c, o.f, path, err)) != ISK_OK) {
        isk_outfile_abort(&o);
        return s;
    }
    return isk_outfile_commit(&o, err);
}

/* ---- reading ---------------------------------------------------------------- */

typedef struct png_source {
    FILE *f;                 /* a file, or */
    const uint8_t *data;     /* bytes in memory */
    size_t size, pos;
    int io_errno;            /* a read failed (not merely ended) */
} png_source;

/* Everything the decoder changes lives here, outside the function that
 * calls setjmp, so it is all well defined after libpng's longjmp. */
typedef struct png_job {
    png_source *src;
    long long max_pixels;    /* 0: the header only */
    isk_png_info info;
    isk_canvas *out;
    int have_canvas;
    png_bytep *rows;
    isk_status status;       /* set before each step that can fail */
    int own;                 /* iskra's own bytes (isk__png_read_own) */
    char msg[200];
} png_job;

static void on_error(png_structp png, png_const_charp msg)
{
    png_job *j = png_get_error_ptr(png);
    snprintf(j->msg, sizeof j->msg, "%s", msg);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* benign (extra data, bad ancillary CRC): the image stands */
}

static void read_bytes(png_structp png, png_bytep out, size_t n)
{
    png_job *j = png_get_io_ptr(png);
    png_source *s = j->src;
    if (s->f) {
        if (fread(out, 1, n, s->f) != n) {
            if (ferror(s->f)) {
                s->io_errno = errno ? errno : EIO;
                png_error(png, strerror(s->io_errno));
            }
            png_error(png, "file is truncated");
        }
        return;
    }
    if (s->size - s->pos < n) {
        s->pos = s->size;
        png_error(png, "file is truncated");
    }
    memcpy(out, s->data + s->pos, n);
    s->pos += n;
}

/* The decoder proper.  Returns 0 after a longjmp (j->msg says why). */
static int run(png_structp png, png_infop pi, png_job *j)
{
#ifdef PNG_SETJMP_SUPPORTED
    if (setjmp(png_jmpbuf(png)))
        return 0;
#endif
    j->status = ISK_ERR_FORMAT;
    png_set_read_fn(png, j, read_bytes);
    png_set_user_limits(png, 1000000, 1000000); /* ours are below; this bounds libpng's own parsing */
    png_set_chunk_malloc_max(png, CHUNK_MALLOC_MAX);
    png_set_chunk_cache_max(png, CHUNK_CACHE_MAX);
    /* Skip every ancillary chunk but tRNS unread and unstored (text,
     * profiles, gamma...): nothing in them changes our pixels. */
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, NULL, -1);
    png_read_info(png, pi);
    png_uint_32 w, h;
    int depth, type, interlace;
    png_get_IHDR(png, pi, &w, &h, &depth, &type, &interlace, NULL, NULL);
    j->info.width = (int)(w > 0x7fffffff ? 0x7fffffff : w);
    j->info.height = (int)(h > 0x7fffffff ? 0x7fffffff : h);
    j->info.bit_depth = depth;
    j->info.color_type = type;
    j->info.interlaced = interlace != PNG_INTERLACE_NONE;
    j->status = ISK_ERR_SIZE;
    if (w > ISK_CANVAS_MAX_DIM || h > ISK_CANVAS_MAX_DIM) {
        snprintf(j->msg, sizeof j->msg, "image size %lux%lu is above the largest canvas, %dx%d", (unsigned long)w,
                 (unsigned long)h, ISK_CANVAS_MAX_DIM, ISK_CANVAS_MAX_DIM);
        return 0;
    }
    if (j->max_pixels == 0)
        return 1;
    long long npix = (long long)w * (long long)h;
    if (npix > j->max_pixels) {
        snprintf(j->msg, sizeof j->msg, "%lux%lu = %lld pixels, more than the limit of %lld", (unsigned long)w,
                 (unsigned long)h, npix, j->max_pixels);
        return 0;
    }
    j->status = ISK_ERR_FORMAT;
    /* To RGBA8, as the specification and common readers do. */
    if (type == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (type == PNG_COLOR_TYPE_GRAY && depth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    int alpha = (type & PNG_COLOR_MASK_ALPHA) != 0;
    if (png_get_valid(png, pi, PNG_INFO_tRNS)) {
        png_set_tRNS_to_alpha(png);
        alpha = 1;
    }
    if (depth == 16)
        png_set_scale_16(png); /* round(v / 257), exact */
    if (!(type & PNG_COLOR_MASK_COLOR))
        png_set_gray_to_rgb(png);
    if (!alpha)
        png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, pi);
    if (png_get_rowbytes(png, pi) != (size_t)w * 4u || png_get_bit_depth(png, pi) != 8 ||
        png_get_channels(png, pi) != 4) {
        snprintf(j->msg, sizeof j->msg, "cannot convert this PNG to RGBA8");
        return 0;
    }
    j->status = isk_canvas_init(j->out, (int)w, (int)h);
    if (j->status != ISK_OK) {
        snprintf(j->msg, sizeof j->msg, "%s", isk_status_str(j->status));
        return 0;
    }
    j->have_canvas = 1;
    j->status = ISK_ERR_NOMEM;
    j->rows = malloc((size_t)h * sizeof *j->rows);
    if (!j->rows) {
        snprintf(j->msg, sizeof j->msg, "out of memory");
        return 0;
    }
    for (png_uint_32 y = 0; y < h; y++)
        j->rows[y] = j->out->pixels + (size_t)y * j->out->stride;
    j->status = ISK_ERR_FORMAT;
    png_read_image(png, j->rows);
    png_read_end(png, NULL);
    j->status = ISK_OK;
    return 1;
}

static isk_status decode(png_job *j, const char *name, isk_error *err)
{
    uint8_t sig[8];
    png_source *s = j->src;
    size_t got = 0;
    if (s->f) {
        got = fread(sig, 1, sizeof sig, s->f);
        if (got < sizeof sig && ferror(s->f))
            return isk_error_set(err, ISK_ERR_IO, "%s: %s", name, strerror(errno ? errno : EIO));
    } else {
        got = s->size < sizeof sig ? s->size : sizeof sig;
        memcpy(sig, s->data, got);
        s->pos = got;
    }
    if (got < sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0)
        return isk_error_set(err, ISK_ERR_FORMAT, "%s: not a PNG file", name);
#ifndef PNG_SETJMP_SUPPORTED
    /* libpng reports a malformed file by longjmp: without setjmp it could
     * only abort the program, so such targets read only iskra's own PNGs. */
    if (!j->own)
        return isk_error_set(err, ISK_ERR_UNSUPPORTED,
                             "%s: this build reads no PNG file but iskra's own (its libpng has no setjmp)", name);
#endif
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, j, on_error, on_warning);
    png_infop pi = png ? png_create_info_struct(png) : NULL;
    if (!pi) {
        png_destroy_read_struct(&png, NULL, NULL);
        return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", name);
    }
    png_set_sig_bytes(png, (int)sizeof sig);
    int ok = run(png, pi, j);
    png_destroy_read_struct(&png, &pi, NULL);
    free(j->rows);
    j->rows = NULL;
    if (ok)
        return ISK_OK;
    if (j->have_canvas)
        isk_canvas_free(j->out);
    isk_status st = s->io_errno ? ISK_ERR_IO : j->status == ISK_OK ? ISK_ERR_FORMAT : j->status;
    return isk_error_set(err, st, "%s: %s", name, j->msg[0] ? j->msg : "malformed PNG");
}

static isk_status read_file(const char *path, isk_canvas *out, isk_png_info *info, long long max_pixels,
                            isk_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return isk_error_set(err, ISK_ERR_IO, "%s: %s", path, *path ? strerror(errno) : "empty file name");
    png_source src = {f, NULL, 0, 0, 0};
    png_job j;
    memset(&j, 0, sizeof j);
    j.src = &src;
    j.max_pixels = max_pixels;
    j.out = out;
    isk_status s = decode(&j, path, err);
    fclose(f);
    if (info)
        *info = j.info;
    return s;
}

isk_status isk_png_read_info(const char *path, isk_png_info *info, isk_error *err)
{
    if (!path || !info)
        return isk_error_set(err, ISK_ERR_NULL, "png info: NULL %s", !path ? "path" : "info");
    memset(info, 0, sizeof *info);
    isk_status s = read_file(path, NULL, info, 0, err);
    if (s == ISK_OK && (info->width == 0 || info->height == 0))
        return isk_error_set(err, ISK_ERR_SIZE, "%s: empty image", path);
    return s;
}

static isk_status check_read_args(isk_canvas *out, const void *src, long long max_pixels, isk_error *err)
{
    if (!out || !src) {
        if (out)
            memset(out, 0, sizeof *out);
        return isk_error_set(err, ISK_ERR_NULL, "png read: NULL %s", !out ? "canvas" : "source");
    }
    memset(out, 0, sizeof *out);
    if (max_pixels < 1 || max_pixels > (long long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM)
        return isk_error_set(err, ISK_ERR_RANGE, "png read: pixel limit %lld outside 1..%lld", max_pixels,
                             (long long)ISK_CANVAS_MAX_DIM * ISK_CANVAS_MAX_DIM);
    return ISK_OK;
}

isk_status isk_png_read_max(isk_canvas *out, const char *path, long long max_pixels, isk_error *err)
{
    isk_status s = check_read_args(out, path, max_pixels, err);
    if (s != ISK_OK)
        return s;
    return read_file(path, out, NULL, max_pixels, err);
}

isk_status isk_png_read(isk_canvas *out, const char *path, isk_error *err)
{
    return isk_png_read_max(out, path, ISK_PNG_MAX_PIXELS_DEFAULT, err);
}

static isk_status read_memory(isk_canvas *out, const void *data, size_t size, const char *name,
                              long long max_pixels, int own, isk_error *err)
{
    static const uint8_t none = 0;
    isk_status s = check_read_args(out, data ? data : (size == 0 ? &none : NULL), max_pixels, err);
    if (s != ISK_OK)
        return s;
    png_source src = {NULL, data ? data : &none, size, 0, 0};
    png_job j;
    memset(&j, 0, sizeof j);
    j.src = &src;
    j.max_pixels = max_pixels;
    j.out = out;
    j.own = own;
    return decode(&j, name ? name : "PNG in memory", err);
}

isk_status isk_png_read_memory(isk_canvas *out, const void *data, size_t size, const char *name,
                               long long max_pixels, isk_error *err)
{
    return read_memory(out, data, size, name, max_pixels, 0, err);
}

isk_status isk__png_read_own(isk_canvas *out, const void *data, size_t size, const char *name, long long max_pixels,
                             isk_error *err)
{
    return read_memory(out, data, size, name, max_pixels, 1, err);
}
