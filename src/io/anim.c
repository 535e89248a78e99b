/* SPDX-License-Identifier: MIT */
/* Animations: the table of formats and what every format shares
 * (iskra/anim.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "io/anim_internal.h"

static const anim_format formats[ISK_ANIM_FORMAT_COUNT] = {
    [ISK_ANIM_GIF] = {"gif", ".gif", 1, isk__gif_begin, isk__gif_frame, isk__gif_end, isk__gif_release,
                      isk__gif_memory},
    [ISK_ANIM_Y4M] = {"y4m", ".y4m", 1, isk__y4m_begin, isk__y4m_frame, isk__stream_end, isk__stream_release,
                      isk__y4m_memory},
    [ISK_ANIM_RAW] = {"raw", NULL, 0, NULL, isk__raw_frame, isk__stream_end, isk__stream_release, isk__raw_memory},
};

const char *isk_anim_format_name(isk_anim_format f)
{
    return (unsigned)f < (unsigned)ISK_ANIM_FORMAT_COUNT ? formats[f].name : NULL;
}

int isk_anim_format_of_path(const char *path, isk_anim_format *f)
{
    size_t n = path ? strlen(path) : 0;
    for (int i = 0; i < ISK_ANIM_FORMAT_COUNT; i++) {
        const char *ext = formats[i].ext;
        size_t k = ext ? strlen(ext) : 0;
        if (ext && n > k && !strcasecmp(path + n - k, ext)) {
            if (f)
                *f = (isk_anim_format)i;
            return 1;
        }
    }
    return 0;
}

isk_status isk_anim_begin(isk_anim **out, FILE *f, const isk_anim_opts *o, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "animation: NULL result pointer");
    *out = NULL;
    if (!f || !o)
        return isk_error_set(err, ISK_ERR_NULL, "animation: NULL %s", !f ? "stream" : "options");
    if ((unsigned)o->format >= (unsigned)ISK_ANIM_FORMAT_COUNT)
        return isk_error_set(err, ISK_ERR_RANGE, "animation: unknown format %d", (int)o->format);
    const anim_format *fmt = &formats[o->format];
    if (o->width < 1 || o->height < 1 || o->width > ISK_CANVAS_MAX_DIM || o->height > ISK_CANVAS_MAX_DIM)
        return isk_error_set(err, ISK_ERR_SIZE, "%s: frame size %dx%d outside 1..%d", fmt->name, o->width, o->height,
                             ISK_CANVAS_MAX_DIM);
    if (fmt->needs_fps && !isfinite(o->fps))
        return isk_error_set(err, ISK_ERR_NAN, "%s: fps is not a finite number", fmt->name);
    if (fmt->needs_fps && !(o->fps >= 0.001 && o->fps <= 1000.0))
        return isk_error_set(err, ISK_ERR_RANGE, "%s: fps %g outside 0.001..1000", fmt->name, o->fps);
    isk_anim *a = calloc(1, sizeof *a);
    if (!a)
        return isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", fmt->name);
    a->fmt = fmt;
    a->f = f;
    a->o = *o;
    isk_status s = fmt->begin ? fmt->begin(a, err) : ISK_OK;
    if (s != ISK_OK) {
        isk_anim_abort(a);
        return s;
    }
    *out = a;
    return ISK_OK;
}

isk_status isk_anim_frame(isk_anim *a, const isk_canvas *c, isk_error *err)
{
    if (!a || !c)
        return isk_error_set(err, ISK_ERR_NULL, "animation: NULL %s", !a ? "writer" : "frame");
    if (!c->pixels || c->width != a->o.width || c->height != a->o.height || c->stride < (size_t)c->width * 4u)
        return isk_error_set(err, ISK_ERR_SIZE, "%s: frame %ld is %dx%d, the animation %dx%d", a->fmt->name,
                             a->frames, c->width, c->height, a->o.width, a->o.height);
    isk_status s = a->fmt->frame(a, c, err);
    if (s == ISK_OK)
        a->frames++;
    return s;
}

isk_status isk_anim_end(isk_anim *a, isk_error *err)
{
    if (!a)
        return isk_error_set(err, ISK_ERR_NULL, "animation: NULL writer");
    isk_status s = a->fmt->end(a, err);
    isk_anim_abort(a);
    return s;
}

void isk_anim_abort(isk_anim *a)
{
    if (!a)
        return;
    if (a->fmt && a->fmt->release)
        a->fmt->release(a);
    free(a);
}

size_t isk_anim_memory(const isk_anim_opts *o)
{
    if (!o || (unsigned)o->format >= (unsigned)ISK_ANIM_FORMAT_COUNT || o->width < 1 || o->height < 1 ||
        o->width > ISK_CANVAS_MAX_DIM || o->height > ISK_CANVAS_MAX_DIM)
        return 0;
    return sizeof(isk_anim) + formats[o->format].memory(o);
}

long isk_anim_count(const isk_anim *a)
{
    return a ? a->frames : 0;
}
