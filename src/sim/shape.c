/* SPDX-License-Identifier: MIT */
/* Spawn shapes and velocity generators (iskra/shape.h documents the draws). */
#include "iskra/shape.h"

#include <math.h>

static const double TWO_PI = 6.283185307179586;

/* ---- constructors --------------------------------------------------------- */

const char *const isk_shape_names[ISK_SHAPE_COUNT] = {
    "point", "disc", "circle", "ring", "segment", "rect", "ellipse", "gaussian", "rect_border", "ellipse_border"};
const char *const isk_velgen_names[ISK_VELGEN_COUNT] = {"constant", "disc", "direction", "cone"};

static isk_shape shape(isk_shape_kind k, double cx, double cy, double a, double b)
{
    isk_shape s = {k, cx, cy, a, b, 0.0, ISK_ELLIPSE_UNIFORM};
    return s;
}

isk_shape isk_shape_point(double x, double y) { return shape(ISK_SHAPE_POINT, x, y, 0, 0); }
isk_shape isk_shape_disc(double cx, double cy, double r) { return shape(ISK_SHAPE_DISC, cx, cy, r, 0); }
isk_shape isk_shape_circle(double cx, double cy, double r) { return shape(ISK_SHAPE_CIRCLE, cx, cy, r, 0); }
isk_shape isk_shape_ring(double cx, double cy, double r_in, double r_out)
{
    return shape(ISK_SHAPE_RING, cx, cy, r_in, r_out);
}
isk_shape isk_shape_segment(double x0, double y0, double dx, double dy)
{
    return shape(ISK_SHAPE_SEGMENT, x0, y0, dx, dy);
}
isk_shape isk_shape_rect(double cx, double cy, double half_w, double half_h)
{
    return shape(ISK_SHAPE_RECT, cx, cy, half_w, half_h);
}
isk_shape isk_shape_ellipse(double cx, double cy, double a, double b, isk_ellipse_mode mode)
{
    isk_shape s = shape(ISK_SHAPE_ELLIPSE, cx, cy, a, b);
    s.ellipse_mode = mode;
    return s;
}

isk_shape isk_shape_gaussian(double cx, double cy, double sigma_x, double sigma_y)
{
    return shape(ISK_SHAPE_GAUSSIAN, cx, cy, sigma_x, sigma_y);
}
isk_shape isk_shape_rect_border(double cx, double cy, double half_w, double half_h)
{
    return shape(ISK_SHAPE_RECT_BORDER, cx, cy, half_w, half_h);
}
isk_shape isk_shape_ellipse_border(double cx, double cy, double a, double b)
{
    return shape(ISK_SHAPE_ELLIPSE_BORDER, cx, cy, a, b);
}

int isk_shape_uses_b(isk_shape_kind k)
{
    return k == ISK_SHAPE_RING || k == ISK_SHAPE_SEGMENT || k == ISK_SHAPE_RECT || k == ISK_SHAPE_ELLIPSE ||
           k == ISK_SHAPE_GAUSSIAN || k == ISK_SHAPE_RECT_BORDER || k == ISK_SHAPE_ELLIPSE_BORDER;
}

static isk_velgen velgen(isk_velgen_kind k)
{
    isk_velgen v = {k, 0, 0, 0, 0, 0, 0};
    return v;
}

isk_velgen isk_velgen_constant(double vx, double vy)
{
    isk_velgen v = velgen(ISK_VELGEN_CONSTANT);
    v.vx = vx;
    v.vy = vy;
    return v;
}

isk_velgen isk_velgen_disc(double radius)
{
    isk_velgen v = velgen(ISK_VELGEN_DISC);
    v.max = radius;
    return v;
}

isk_velgen isk_velgen_direction(double angle, double min_speed, double max_speed)
{
    isk_velgen v = velgen(ISK_VELGEN_DIRECTION);
    v.angle = angle;
    v.min = min_speed;
    v.max = max_speed;
    return v;
}

isk_velgen isk_velgen_cone(double angle, double spread, double min_speed, double max_speed)
{
    isk_velgen v = isk_velgen_direction(angle, min_speed, max_speed);
    v.kind = ISK_VELGEN_CONE;
    v.spread = spread;
    return v;
}

/* ---- validation ----------------------------------------------------------- */

isk_status isk_shape_check(const isk_shape *s)
{
    if (!s)
        return ISK_ERR_NULL;
    if (!isfinite(s->cx) || !isfinite(s->cy) || !isfinite(s->angle))
        return ISK_ERR_NAN;
    int uses_a = s->kind != ISK_SHAPE_POINT;
    int uses_b = isk_shape_uses_b(s->kind);
    if ((uses_a && !isfinite(s->a)) || (uses_b && !isfinite(s->b)))
        return ISK_ERR_NAN;
    switch (s->kind) {
    case ISK_SHAPE_POINT:
    case ISK_SHAPE_SEGMENT:
        return ISK_OK;
    case ISK_SHAPE_DISC:
    case ISK_SHAPE_CIRCLE:
        return s->a >= 0.0 ? ISK_OK : ISK_ERR_RANGE;
    case ISK_SHAPE_RING:
        return (s->a >= 0.0 && s->a <= s->b) ? ISK_OK : ISK_ERR_RANGE;
    case ISK_SHAPE_RECT:
    case ISK_SHAPE_GAUSSIAN:
    case ISK_SHAPE_RECT_BORDER:
    case ISK_SHAPE_ELLIPSE_BORDER:
        return (s->a >= 0.0 && s->b >= 0.0) ? ISK_OK : ISK_ERR_RANGE;
    case ISK_SHAPE_ELLIPSE:
        if (s->ellipse_mode != ISK_ELLIPSE_UNIFORM && s->ellipse_mode != ISK_ELLIPSE_THESIS)
            return ISK_ERR_RANGE;
        return (s->a >= 0.0 && s->b >= 0.0) ? ISK_OK : ISK_ERR_RANGE;
    default:
        return ISK_ERR_RANGE;
    }
}

isk_status isk_velgen_check(const isk_velgen *v)
{
    if (!v)
        return ISK_ERR_NULL;
    switch (v->kind) {
    case ISK_VELGEN_CONSTANT:
        return (isfinite(v->vx) && isfinite(v->vy)) ? ISK_OK : ISK_ERR_NAN;
    case ISK_VELGEN_DISC:
        if (!isfinite(v->max))
            return ISK_ERR_NAN;
        return v->max >= 0.0 ? ISK_OK : ISK_ERR_RANGE;
    case ISK_VELGEN_DIRECTION:
    case ISK_VELGEN_CONE:
        if (!isfinite(v->angle) || !isfinite(v->min) || !isfinite(v->max) ||
            (v->kind == ISK_VELGEN_CONE && !isfinite(v->spread)))
            return ISK_ERR_NAN;
        if (v->min < 0.0 || v->min > v->max)
            return ISK_ERR_RANGE;
        if (v->kind == ISK_VELGEN_CONE && (v->spread < 0.0 || v->spread > TWO_PI))
            return ISK_ERR_RANGE;
        return ISK_OK;
    default:
        return ISK_ERR_RANGE;
    }
}

/* ---- sampling ------------------------------------------------------------- */

/* Unit-disc point, area-uniform: 2 draws (radius, then angle). */
static inline void unit_disc(isk_rng *r, double *x, double *y)
{
    double rho = sqrt(isk_rng_uniform(r));
    double phi = TWO_PI * isk_rng_uniform(r);
    *x = rho * cos(phi);
    *y = rho * sin(phi);
}

/* The point at fraction u of the way round the outline of the rectangle of
 * half sizes a, b, counter-clockwise from its bottom-right corner: the
 * right side up, the top leftwards, the left side down, the bottom
 * rightwards.  Each side is clamped to its own length, so rounding never
 * leaves the outline. */
static inline void rect_border(double a, double b, double u, double *lx, double *ly)
{
    double d = u * 4.0 * (a + b); /* the distance walked */
    if (d < 2.0 * b) {
        *lx = a;
        *ly = -b + d;
    } else if ((d -= 2.0 * b) < 2.0 * a) {
        *lx = a - d;
        *ly = b;
    } else if ((d -= 2.0 * a) < 2.0 * b) {
        *lx = -a;
        *ly = b - d;
    } else {
        d -= 2.0 * b;
        *lx = -a + (d < 2.0 * a ? d : 2.0 * a);
        *ly = -b;
    }
}

/* The local offset of one sample, before rotation.  `kind` is passed apart
 * from s so that callers with a constant kind get the switch folded away. */
static inline void local_sample(const isk_shape *s, isk_shape_kind kind, isk_rng *r, double *lx, double *ly)
{
    switch (kind) {
    case ISK_SHAPE_POINT:
        *lx = *ly = 0.0;
        break;
    case ISK_SHAPE_DISC:
        unit_disc(r, lx, ly);
        *lx *= s->a;
        *ly *= s->a;
        break;
    case ISK_SHAPE_CIRCLE: {
        double phi = TWO_PI * isk_rng_uniform(r);
        *lx = s->a * cos(phi);
        *ly = s->a * sin(phi);
        break;
    }
    case ISK_SHAPE_RING: {
        double a2 = s->a * s->a, b2 = s->b * s->b;
        double rho = sqrt(a2 + isk_rng_uniform(r) * (b2 - a2));
        rho = rho < s->a ? s->a : rho > s->b ? s->b : rho; /* rounding of the sum */
        double phi = TWO_PI * isk_rng_uniform(r);
        *lx = rho * cos(phi);
        *ly = rho * sin(phi);
        break;
    }
    case ISK_SHAPE_SEGMENT: {
        double u = isk_rng_uniform(r);
        *lx = u * s->a;
        *ly = u * s->b;
        break;
    }
    case ISK_SHAPE_RECT: {
        double u1 = isk_rng_uniform(r), u2 = isk_rng_uniform(r);
        *lx = s->a * (2.0 * u1 - 1.0);
        *ly = s->b * (2.0 * u2 - 1.0);
        break;
    }
    case ISK_SHAPE_ELLIPSE:
        if (s->ellipse_mode == ISK_ELLIPSE_THESIS) {
            double u1 = isk_rng_uniform(r), u2 = isk_rng_uniform(r);
            double q = 2.0 * u1 - 1.0; /* x / a */
            *lx = s->a * q;
            *ly = s->b * (2.0 * u2 - 1.0) * sqrt(1.0 - q * q);
        } else {
            unit_disc(r, lx, ly);
            *lx *= s->a;
            *ly *= s->b;
        }
        break;
    case ISK_SHAPE_GAUSSIAN: { /* Box-Muller; 1 - u1 is in (0, 1], so the log is finite */
        double rho = sqrt(-2.0 * log(1.0 - isk_rng_uniform(r)));
        double phi = TWO_PI * isk_rng_uniform(r);
        *lx = s->a * rho * cos(phi);
        *ly = s->b * rho * sin(phi);
        break;
    }
    case ISK_SHAPE_RECT_BORDER:
        rect_border(s->a, s->b, isk_rng_uniform(r), lx, ly);
        break;
    case ISK_SHAPE_ELLIPSE_BORDER: {
        double phi = TWO_PI * isk_rng_uniform(r);
        *lx = s->a * cos(phi);
        *ly = s->b * sin(phi);
        break;
    }
    default: /* checked by the callers */
        *lx = *ly = 0.0;
        break;
    }
}

static inline void place(const isk_shape *s, double c, double sn, double lx, double ly, double *x, double *y)
{
    if (s->angle != 0.0) {
        double rx = c * lx - sn * ly, ry = sn * lx + c * ly;
        lx = rx;
        ly = ry;
    }
    *x = s->cx + lx;
    *y = s->cy + ly;
}

void isk_shape_sample(const isk_shape *s, isk_rng *r, double *x, double *y)
{
    if (!s || !r || !x || !y) {
        if (x)
            *x = 0.0;
        if (y)
            *y = 0.0;
        return;
    }
    double lx = 0.0, ly = 0.0;
    local_sample(s, s->kind, r, &lx, &ly);
    double c = 1.0, sn = 0.0;
    if (s->angle != 0.0) {
        c = cos(s->angle);
        sn = sin(s->angle);
    }
    place(s, c, sn, lx, ly, x, y);
}

static inline void fill(const isk_shape *s, isk_shape_kind kind, isk_rng *r, size_t n, double *x, double *y,
                        double c, double sn)
{
    for (size_t i = 0; i < n; i++) {
        double lx = 0.0, ly = 0.0;
        local_sample(s, kind, r, &lx, &ly);
        place(s, c, sn, lx, ly, &x[i], &y[i]);
    }
}

isk_status isk_shape_sample_n(const isk_shape *s, isk_rng *r, size_t n, double *x, double *y)
{
    isk_status st = isk_shape_check(s);
    if (st != ISK_OK)
        return st;
    if (!r || (n > 0 && (!x || !y)))
        return ISK_ERR_NULL;
    double c = 1.0, sn = 0.0;
    if (s->angle != 0.0) {
        c = cos(s->angle);
        sn = sin(s->angle);
    }
    switch (s->kind) { /* the switch outside the loop: each case is its own loop */
    case ISK_SHAPE_POINT: fill(s, ISK_SHAPE_POINT, r, n, x, y, c, sn); break;
    case ISK_SHAPE_DISC: fill(s, ISK_SHAPE_DISC, r, n, x, y, c, sn); break;
    case ISK_SHAPE_CIRCLE: fill(s, ISK_SHAPE_CIRCLE, r, n, x, y, c, sn); break;
    case ISK_SHAPE_RING: fill(s, ISK_SHAPE_RING, r, n, x, y, c, sn); break;
    case ISK_SHAPE_SEGMENT: fill(s, ISK_SHAPE_SEGMENT, r, n, x, y, c, sn); break;
    case ISK_SHAPE_RECT: fill(s, ISK_SHAPE_RECT, r, n, x, y, c, sn); break;
    case ISK_SHAPE_ELLIPSE: fill(s, ISK_SHAPE_ELLIPSE, r, n, x, y, c, sn); break;
    case ISK_SHAPE_GAUSSIAN: fill(s, ISK_SHAPE_GAUSSIAN, r, n, x, y, c, sn); break;
    case ISK_SHAPE_RECT_BORDER: fill(s, ISK_SHAPE_RECT_BORDER, r, n, x, y, c, sn); break;
    case ISK_SHAPE_ELLIPSE_BORDER: fill(s, ISK_SHAPE_ELLIPSE_BORDER, r, n, x, y, c, sn); break;
    default: break; /* checked above */
    }
    return ISK_OK;
}

void isk_velgen_sample(const isk_velgen *v, isk_rng *r, double *vx, double *vy)
{
    if (!v || !r || !vx || !vy) {
        if (vx)
            *vx = 0.0;
        if (vy)
            *vy = 0.0;
        return;
    }
    switch (v->kind) {
    case ISK_VELGEN_CONSTANT:
        *vx = v->vx;
        *vy = v->vy;
        return;
    case ISK_VELGEN_DISC:
        unit_disc(r, vx, vy);
        *vx *= v->max;
        *vy *= v->max;
        return;
    case ISK_VELGEN_DIRECTION: {
        double speed = v->min + isk_rng_uniform(r) * (v->max - v->min);
        *vx = speed * cos(v->angle);
        *vy = speed * sin(v->angle);
        return;
    }
    case ISK_VELGEN_CONE: {
        double ang = v->angle + v->spread * (isk_rng_uniform(r) - 0.5);
        double speed = v->min + isk_rng_uniform(r) * (v->max - v->min);
        *vx = speed * cos(ang);
        *vy = speed * sin(ang);
        return;
    }
    default:
        *vx = *vy = 0.0;
        return;
    }
}

isk_status isk_velgen_sample_n(const isk_velgen *v, isk_rng *r, size_t n, double *vx, double *vy)
{
    isk_status st = isk_velgen_check(v);
    if (st != ISK_OK)
        return st;
    if (!r || (n > 0 && (!vx || !vy)))
        return ISK_ERR_NULL;
    for (size_t i = 0; i < n; i++)
        isk_velgen_sample(v, r, &vx[i], &vy[i]);
    return ISK_OK;
}
