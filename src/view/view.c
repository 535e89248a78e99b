/* SPDX-License-Identifier: MIT */
/* World <-> screen transforms: the explosion thesis's window mapping and the
 * fire thesis's camera.  Formulas are evaluated in exactly the order the
 * theses write them, so results match their code bit for bit. */
#include "iskra/view.h"

#include <math.h>

#include "view/view_transform.h"

static int bad_size(int w, int h)
{
    return w <= 0 || h <= 0 || w > ISK_CANVAS_MAX_DIM || h > ISK_CANVAS_MAX_DIM;
}

isk_status isk_view_window(isk_view *v, int width, int height, double xmin, double xmax, double ymin,
                           double ymax)
{
    if (!v)
        return ISK_ERR_NULL;
    if (bad_size(width, height))
        return ISK_ERR_SIZE;
    if (!isfinite(xmin) || !isfinite(xmax) || !isfinite(ymin) || !isfinite(ymax))
        return ISK_ERR_NAN;
    if (!(xmin < xmax) || !(ymin < ymax))
        return ISK_ERR_RANGE;
    double sx = width / (xmax - xmin);
    double sy = -height / (ymax - ymin);
    /* A window so small or so large that the scale over/underflows is as
     * unusable as an empty one. */
    if (!isfinite(sx) || !isfinite(sy) || sx == 0.0 || sy == 0.0)
        return ISK_ERR_RANGE;
    isk_view r = {0};
    r.kind = ISK_VIEW_WINDOW;
    r.width = width;
    r.height = height;
    r.xmin = xmin; r.xmax = xmax; r.ymin = ymin; r.ymax = ymax;
    r.sx = sx;
    r.sy = sy;
    r.px = -sx * xmin;
    r.py = -sy * ymax;
    if (!isfinite(r.px) || !isfinite(r.py))
        return ISK_ERR_RANGE;
    *v = r;
    return ISK_OK;
}

isk_status isk_view_camera(isk_view *v, int width, int height, double zoom, double tx, double ty)
{
    if (!v)
        return ISK_ERR_NULL;
    if (bad_size(width, height))
        return ISK_ERR_SIZE;
    if (!isfinite(zoom) || !isfinite(tx) || !isfinite(ty))
        return ISK_ERR_NAN;
    if (!(zoom > 0.0))
        return ISK_ERR_RANGE;
    double a = (width + height) / (2.0 * zoom);
    if (!isfinite(a) || a == 0.0)
        return ISK_ERR_RANGE;
    isk_view r = {0};
    r.kind = ISK_VIEW_CAMERA;
    r.width = width;
    r.height = height;
    r.zoom = zoom; r.tx = tx; r.ty = ty; r.a = a;
    /* Equivalent affine form, for code that wants one (and the bounds). */
    r.sx = a;
    r.sy = -a;
    r.px = width / 2.0 + a * tx;
    r.py = height / 2.0 - a * ty;
    r.xmin = -width / 2.0 / a - tx;
    r.xmax = width / 2.0 / a - tx;
    r.ymin = -height / 2.0 / a - ty;
    r.ymax = height / 2.0 / a - ty;
    if (!isfinite(r.px) || !isfinite(r.py) || !isfinite(r.xmin) || !isfinite(r.xmax))
        return ISK_ERR_RANGE;
    *v = r;
    return ISK_OK;
}

/* view_transform.h's arithmetic, which every batched kernel shares. */
void isk_view_to_screen(const isk_view *v, double x, double y, double *sx, double *sy)
{
    double X = 0.0, Y = 0.0;
    if (v)
        isk__view_to_screen(v, x, y, &X, &Y);
    if (sx) *sx = X;
    if (sy) *sy = Y;
}

void isk_view_to_world(const isk_view *v, double sx, double sy, double *x, double *y)
{
    double X, Y;
    if (!v) {
        X = Y = 0.0;
    } else if (v->kind == ISK_VIEW_CAMERA) {
        X = (sx - v->width / 2.0) / v->a - v->tx;
        Y = (v->height / 2.0 - sy) / v->a - v->ty;
    } else {
        /* The thesis's transformirajPiksele. */
        X = (sx - v->px) / v->sx;
        Y = (sy - v->py) / v->sy;
    }
    if (x) *x = X;
    if (y) *y = Y;
}
