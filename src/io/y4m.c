/* SPDX-License-Identifier: MIT */
/* YUV4MPEG2 and raw RGBA frames (iskra/anim.h). */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/anim_internal.h"

typedef struct y4m_state {
    uint8_t *row; /* one plane row */
} y4m_state;

static long long gcd(long long a, long long b)
{
    while (b) {
        long long t = a % b;
        a = b;
        b = t;
    }
    return a;
}

static isk_status write_failed(const isk_anim *a, isk_error *err)
{
    /* just after the failed fwrite or fflush: errno says why (EFBIG past
     * ulimit -f, ENOSPC, EPIPE) */
    return isk_error_set(err, ISK_ERR_IO, "%s: write failed: %s", a->fmt->name,
                         errno ? strerror(errno) : "disk full, or the reader went away?");
}

size_t isk__y4m_memory(const isk_anim_opts *o)
{
    return sizeof(y4m_state) + (size_t)o->width; /* one plane's row */
}

size_t isk__raw_memory(const isk_anim_opts *o)
{
    (void)o;
    return 0; /* the rows go out as they are */
}

isk_status isk__y4m_begin(isk_anim *a, isk_error *err)
{
    y4m_state *s = calloc(1, sizeof *s);
    if (s)
        s->row = malloc((size_t)a->o.width);
    if (!s || !s->row) {
        free(s);
        return isk_error_set(err, ISK_ERR_NOMEM, "y4m: out of memory");
    }
    a->state = s;
    /* fps in thousandths, as a reduced fraction: 60 -> 60:1, 29.97 -> 2997:100 */
    long long num = llround(a->o.fps * 1000.0), den = 1000, g = gcd(num, den);
    if (fprintf(a->f, "YUV4MPEG2 W%d H%d F%lld:%lld Ip A1:1 C444\n", a->o.width, a->o.height, num / g, den / g) < 0)
        return write_failed(a, err);
    return ISK_OK;
}

/* BT.601 limited range in 8.8 fixed point; the offsets keep every sum
 * positive, so the shifts are plain divisions. */
static uint8_t plane_value(int plane, uint32_t r, uint32_t g, uint32_t b)
{
    switch (plane) {
    case 0: return (uint8_t)(((66u * r + 129u * g + 25u * b + 128u) >> 8) + 16u);
    case 1: return (uint8_t)((112u * b + 128u + (128u << 8) - 38u * r - 74u * g) >> 8);
    default: return (uint8_t)((112u * r + 128u + (128u << 8) - 94u * g - 18u * b) >> 8);
    }
}

isk_status isk__y4m_frame(isk_anim *a, const isk_canvas *c, isk_error *err)
{
    y4m_state *s = a->state;
    if (fputs("FRAME\n", a->f) < 0)
        return write_failed(a, err);
    for (int plane = 0; plane < 3; plane++)
        for (int y = 0; y < c->height; y++) {
            const uint8_t *p = c->pixels + (size_t)y * c->stride;
            for (int x = 0; x < c->width; x++, p += 4) {
                uint32_t al = p[3]; /* over black */
                uint32_t r = (p[0] * al + 127u) / 255u, g = (p[1] * al + 127u) / 255u, b = (p[2] * al + 127u) / 255u;
                s->row[x] = plane_value(plane, r, g, b);
            }
            if (fwrite(s->row, 1, (size_t)c->width, a->f) != (size_t)c->width)
                return write_failed(a, err);
        }
    return ISK_OK;
}

isk_status isk__raw_frame(isk_anim *a, const isk_canvas *c, isk_error *err)
{
    size_t n = (size_t)c->width * 4u;
    for (int y = 0; y < c->height; y++)
        if (fwrite(c->pixels + (size_t)y * c->stride, 1, n, a->f) != n)
            return write_failed(a, err);
    return ISK_OK;
}

isk_status isk__stream_end(isk_anim *a, isk_error *err)
{
    if (fflush(a->f) != 0 || ferror(a->f))
        return write_failed(a, err);
    return ISK_OK;
}

void isk__stream_release(isk_anim *a)
{
    y4m_state *s = a->state;
    if (s)
        free(s->row);
    free(s);
    a->state = NULL;
}
