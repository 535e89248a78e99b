/* SPDX-License-Identifier: MIT */
/* Animated GIF through giflib (iskra/anim.h): GIF89a, looping forever, a
 * local palette per frame (src/io/quantize.h), delays in centiseconds. */
#include <errno.h>
#include <gif_lib.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/anim_internal.h"
#include "io/quantize.h"

#define MIN_DELAY_CS 2 /* browsers play 0 and 1 as 10 */
/* giflib's own while writing: its handle, the LZW hash table (8192 32-bit
 * entries) and a colour map per frame, with room to spare. */
#define GIFLIB_BYTES ((size_t)64 << 10)

typedef struct gif_state {
    GifFileType *gif;
    isk__quant quant;
    uint8_t *indices;
    int write_failed;  /* the stream refused bytes: why (errno), or -1 if unknown */
    int discard;       /* aborting: giflib's trailer goes nowhere */
    long cs_done;      /* centiseconds shown up to the end of the last frame */
    FILE *f;
} gif_state;

static int write_bytes(GifFileType *g, const GifByteType *p, int n)
{
    gif_state *s = g->UserData;
    if (s->discard)
        return n;
    if (n < 0 || fwrite(p, 1, (size_t)n, s->f) != (size_t)n) {
        s->write_failed = n >= 0 && errno ? errno : -1;
        return 0;
    }
    return n;
}

static isk_status gif_failed(const gif_state *s, int code, const char *what, isk_error *err)
{
    if (s->write_failed)
        return isk_error_set(err, ISK_ERR_IO, "gif: write failed: %s",
                             s->write_failed > 0 ? strerror(s->write_failed) : "disk full, or the reader went away?");
    isk_status st = code == E_GIF_ERR_NOT_ENOUGH_MEM ? ISK_ERR_NOMEM : ISK_ERR_IO;
    const char *msg = GifErrorString(code);
    return isk_error_set(err, st, "gif: %s: %s", what, msg ? msg : "giflib error");
}

isk_status isk__gif_begin(isk_anim *a, isk_error *err)
{
    gif_state *s = calloc(1, sizeof *s);
    if (!s)
        return isk_error_set(err, ISK_ERR_NOMEM, "gif: out of memory");
    a->state = s;
    s->f = a->f;
    size_t npix = (size_t)a->o.width * (size_t)a->o.height;
    s->indices = malloc(npix);
    if (!s->indices || isk__quant_init(&s->quant, npix) != ISK_OK)
        return isk_error_set(err, ISK_ERR_NOMEM, "gif: out of memory for %dx%d frames", a->o.width, a->o.height);
    int code = 0;
    s->gif = EGifOpen(s, write_bytes, &code);
    if (!s->gif)
        return gif_failed(s, code, "open", err);
    EGifSetGifVersion(s->gif, true);
    if (EGifPutScreenDesc(s->gif, a->o.width, a->o.height, 8, 0, NULL) == GIF_ERROR)
        return gif_failed(s, s->gif->Error, "screen", err);
    /* NETSCAPE2.0 application extension: loop forever (count 0). */
    static const unsigned char loop[3] = {1, 0, 0};
    if (EGifPutExtensionLeader(s->gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
        EGifPutExtensionBlock(s->gif, 11, "NETSCAPE2.0") == GIF_ERROR ||
        EGifPutExtensionBlock(s->gif, 3, loop) == GIF_ERROR || EGifPutExtensionTrailer(s->gif) == GIF_ERROR)
        return gif_failed(s, s->gif->Error, "loop extension", err);
    return ISK_OK;
}

/* Frame i ends at round(100 (i+1) / fps) cs, but lasts at least 2 cs. */
static int next_delay(gif_state *s, long i, double fps)
{
    double end = floor(100.0 * (double)(i + 1) / fps + 0.5);
    long d = (long)(end > 1e9 ? 1e9 : end) - s->cs_done;
    if (d < MIN_DELAY_CS)
        d = MIN_DELAY_CS;
    if (d > 65535)
        d = 65535;
    s->cs_done += d;
    return (int)d;
}

isk_status isk__gif_frame(isk_anim *a, const isk_canvas *c, isk_error *err)
{
    gif_state *s = a->state;
    uint8_t pal[256 * 3];
    int n;
    isk_status st = isk__quant_frame(&s->quant, c, pal, &n, s->indices);
    if (st != ISK_OK)
        return isk_error_set(err, st, "gif: frame %ld: %s", a->frames, isk_status_str(st));
    int size = 2; /* a power of two, at least 2 */
    while (size < n)
        size *= 2;
    GifColorType colors[256];
    memset(colors, 0, sizeof colors);
    for (int i = 0; i < n; i++)
        colors[i] = (GifColorType){pal[3 * i], pal[3 * i + 1], pal[3 * i + 2]};
    ColorMapObject *map = GifMakeMapObject(size, colors);
    if (!map)
        return isk_error_set(err, ISK_ERR_NOMEM, "gif: out of memory");
    GraphicsControlBlock gcb = {DISPOSE_DO_NOT, false, next_delay(s, a->frames, a->o.fps), NO_TRANSPARENT_COLOR};
    GifByteType ext[4];
    EGifGCBToExtension(&gcb, ext);
    int ok = EGifPutExtension(s->gif, GRAPHICS_EXT_FUNC_CODE, 4, ext) != GIF_ERROR &&
             EGifPutImageDesc(s->gif, 0, 0, c->width, c->height, false, map) != GIF_ERROR;
    for (int y = 0; ok && y < c->height; y++)
        ok = EGifPutLine(s->gif, s->indices + (size_t)y * (size_t)c->width, c->width) != GIF_ERROR;
    GifFreeMapObject(map);
    if (!ok)
        return gif_failed(s, s->gif->Error, "frame", err);
    return ISK_OK;
}

isk_status isk__gif_end(isk_anim *a, isk_error *err)
{
    gif_state *s = a->state;
    int code = 0;
    int ok = EGifCloseFile(s->gif, &code) != GIF_ERROR; /* writes the trailer, frees the handle */
    s->gif = NULL;
    if (!ok || s->write_failed)
        return gif_failed(s, code, "close", err);
    if (fflush(a->f) != 0 || ferror(a->f))
        return isk_error_set(err, ISK_ERR_IO, "gif: write failed: %s",
                             errno ? strerror(errno) : "disk full, or the reader went away?");
    return ISK_OK;
}

size_t isk__gif_memory(const isk_anim_opts *o)
{
    const size_t npix = (size_t)o->width * (size_t)o->height;
    return sizeof(gif_state) + npix /* indices */ + isk__quant_bytes(npix) + GIFLIB_BYTES;
}

void isk__gif_release(isk_anim *a)
{
    gif_state *s = a->state;
    if (!s)
        return;
    if (s->gif) {
        s->discard = 1; /* no trailer for an aborted stream */
        EGifCloseFile(s->gif, NULL);
    }
    isk__quant_free(&s->quant);
    free(s->indices);
    free(s);
    a->state = NULL;
}
