/* SPDX-License-Identifier: MIT */
/* Reference-image checks for anyone's tests (iskra/refimg.h). */
#include "iskra/refimg.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/outfile.h"
#include "iskra/png.h"

char *isk_refimg_summary(const isk_canvas_diff *d, char *buf, size_t n)
{
    if (!buf || n == 0)
        return buf;
    if (!d)
        snprintf(buf, n, "no comparison");
    else
        snprintf(buf, n, "%ld of %ld pixels differ, max channel difference %d, mean absolute difference %.4f",
                 d->differing, d->pixels, d->max_channel, d->mean_abs);
    return buf;
}

/* Read at this call, every call (see the header): no state is kept. */
static int update_requested(const isk_refimg_opts *o)
{
    if (o->update == ISK_REFIMG_UPDATE_ALWAYS)
        return 1;
    if (o->update != ISK_REFIMG_UPDATE_FROM_ENV)
        return 0;
    const char *u = getenv("ISKRA_REFIMG_UPDATE");
    return u && *u && strcmp(u, "0") != 0;
}

/* The paths a check uses; the names are cut if absurdly long. */
typedef struct refimg_paths {
    char name[256];
    char actual[1024], diff[1024];
} refimg_paths;

static isk_status make_paths(const char *ref, const char *out_dir, refimg_paths *p, isk_error *err)
{
    const char *slash = strrchr(ref, '/');
    const char *base = slash ? slash + 1 : ref;
    size_t n = strlen(base);
    if (n > 4 && !strcmp(base + n - 4, ".png"))
        n -= 4;
    if (n == 0 || n >= sizeof p->name)
        return isk_error_set(err, ISK_ERR_RANGE, "refimg: %s: cannot make a name from this path", ref);
    memcpy(p->name, base, n);
    p->name[n] = 0;
    int dn = out_dir ? (int)strlen(out_dir) : slash ? (int)(slash - ref) : 0;
    const char *dir = out_dir ? out_dir : ref;
    int a = snprintf(p->actual, sizeof p->actual, "%.*s%s%s.actual.png", dn, dir, dn ? "/" : "", p->name);
    int d = snprintf(p->diff, sizeof p->diff, "%.*s%s%s.diff.png", dn, dir, dn ? "/" : "", p->name);
    if (a < 0 || d < 0 || (size_t)a >= sizeof p->actual || (size_t)d >= sizeof p->diff)
        return isk_error_set(err, ISK_ERR_RANGE, "refimg: %s: output path too long", ref);
    return ISK_OK;
}

/* Writes the canvas as OUT/NAME.actual.png; "" or why it could not. */
static void write_actual(const isk_canvas *c, const refimg_paths *p, char *why, size_t n)
{
    isk_error e;
    why[0] = 0;
    if (isk_make_parent_dirs(p->actual, &e) != ISK_OK || isk_png_write(c, p->actual, &e) != ISK_OK)
        snprintf(why, n, " (could not write it: %s)", e.message);
}

static void write_diff(const isk_canvas *c, const isk_canvas *ref, const refimg_paths *p, char *why, size_t n)
{
    int w = c->width > ref->width ? c->width : ref->width;
    int h = c->height > ref->height ? c->height : ref->height;
    isk_canvas d;
    isk_error e;
    why[0] = 0;
    if (isk_canvas_init(&d, w, h) != ISK_OK) {
        snprintf(why, n, " (no memory for it)");
        return;
    }
    isk_canvas_compare(c, ref, NULL, &d);
    if (isk_png_write(&d, p->diff, &e) != ISK_OK)
        snprintf(why, n, " (could not write it: %s)", e.message);
    isk_canvas_free(&d);
}

static isk_status check_args(const isk_canvas *c, const char *ref_path, const isk_refimg_opts *o, isk_error *err)
{
    if (!c || !ref_path)
        return isk_error_set(err, ISK_ERR_NULL, "refimg: NULL %s", !c ? "canvas" : "reference path");
    if (!c->pixels || c->width <= 0 || c->height <= 0 || c->width > ISK_CANVAS_MAX_DIM ||
        c->height > ISK_CANVAS_MAX_DIM || c->stride < (size_t)c->width * 4u)
        return isk_error_set(err, ISK_ERR_SIZE, "refimg: %s: empty or malformed canvas (%dx%d)", ref_path,
                             c->width, c->height);
    if (o->max_channel_diff < 0 || o->max_channel_diff > 255 || o->max_differing < 0)
        return isk_error_set(err, ISK_ERR_RANGE, "refimg: %s: tolerances must be 0..255 and >= 0 (got %d, %ld)",
                             ref_path, o->max_channel_diff, o->max_differing);
    if ((o->max_channel_diff || o->max_differing) && (!o->reason || !*o->reason))
        return isk_error_set(err, ISK_ERR_RANGE, "refimg: %s: a tolerance needs a written reason", ref_path);
    if ((unsigned)o->update > (unsigned)ISK_REFIMG_UPDATE_ALWAYS)
        return isk_error_set(err, ISK_ERR_RANGE, "refimg: %s: unknown update mode %d", ref_path, (int)o->update);
    return ISK_OK;
}

isk_status isk_refimg_check(const isk_canvas *c, const char *ref_path, const isk_refimg_opts *opts,
                            isk_error *err)
{
    static const isk_refimg_opts defaults = {0};
    const isk_refimg_opts *o = opts ? opts : &defaults;
    isk_refimg_result res;
    memset(&res, 0, sizeof res);
    if (o->result)
        *o->result = res;
    isk_status s = check_args(c, ref_path, o, err);
    if (s != ISK_OK)
        return s;
    refimg_paths p;
    if ((s = make_paths(ref_path, o->out_dir, &p, err)) != ISK_OK)
        return s;
    isk_error e;
    if (update_requested(o)) {
        if ((s = isk_make_parent_dirs(ref_path, &e)) != ISK_OK || (s = isk_png_write(c, ref_path, &e)) != ISK_OK)
            return isk_error_set(err, s, "refimg %s: cannot write the reference: %s", p.name, e.message);
        res.updated = 1;
        res.same_size = 1;
        if (o->result)
            *o->result = res;
        return ISK_OK;
    }
    const char *hint = o->update == ISK_REFIMG_UPDATE_FROM_ENV ? "; if it is right, rerun with ISKRA_REFIMG_UPDATE=1"
                                                               : "";
    char why_a[600], why_d[600];
    /* The reference may be larger than the canvas (then it differs), but
     * never more than the PNG reader's default cap above the canvas. */
    long long cap = (long long)c->width * c->height;
    if (cap < ISK_PNG_MAX_PIXELS_DEFAULT)
        cap = ISK_PNG_MAX_PIXELS_DEFAULT;
    isk_canvas ref;
    if ((s = isk_png_read_max(&ref, ref_path, cap, &e)) != ISK_OK) {
        write_actual(c, &p, why_a, sizeof why_a);
        return isk_error_set(err, s == ISK_ERR_NOMEM ? s : ISK_ERR_IO,
                             "refimg %s: no usable reference (%s); actual: %s%s%s", p.name, e.message, p.actual,
                             why_a, hint);
    }
    res.ref_width = ref.width;
    res.ref_height = ref.height;
    res.same_size = isk_canvas_compare(c, &ref, &res.diff, NULL);
    if (res.same_size)
        res.beyond_tolerance = isk_canvas_count_beyond(c, &ref, o->max_channel_diff);
    if (o->result)
        *o->result = res;
    if (res.same_size && res.beyond_tolerance <= o->max_differing) {
        isk_canvas_free(&ref);
        return ISK_OK;
    }
    write_actual(c, &p, why_a, sizeof why_a);
    write_diff(c, &ref, &p, why_d, sizeof why_d);
    isk_canvas_free(&ref);
    char what[300];
    if (!res.same_size)
        snprintf(what, sizeof what, "size %dx%d, reference %dx%d", c->width, c->height, res.ref_width,
                 res.ref_height);
    else
        isk_refimg_summary(&res.diff, what, sizeof what);
    char tol[300] = "";
    if (res.same_size && (o->max_channel_diff || o->max_differing))
        snprintf(tol, sizeof tol, " (%ld beyond the tolerance of %d per channel, %ld allowed: %s)",
                 res.beyond_tolerance, o->max_channel_diff, o->max_differing, o->reason);
    return isk_error_set(err, ISK_ERR_MISMATCH, "refimg %s: %s%s; actual: %s%s; diff: %s%s%s", p.name, what, tol,
                         p.actual, why_a, p.diff, why_d, hint);
}
