/* SPDX-License-Identifier: MIT */
/* Explosion generators of the thesis, and the multi-Coulomb scheduler. */
#include "iskra/explode.h"

#include <math.h>

#include "sim/kernels.h"
#include "sim/store_internal.h"

const char *const isk_explosion_names[ISK_EXPLOSION_COUNT] = {"ring", "uniform", "gauss", "coulomb",
                                                               "multi-coulomb"};
const char *const isk_kick_names[ISK_KICK_COUNT] = {"all", "new"};

static isk_status check_count(size_t count, size_t limit)
{
    if (limit == 0)
        limit = ISK_EXPLODE_THESIS_LIMIT;
    return (count >= 1 && count <= limit) ? ISK_OK : ISK_ERR_RANGE;
}

/* Common prologue: arguments, then room for all particles (all-or-nothing). */
static isk_status prepare(isk_particles *p, const void *rng_or_1, double cx, double cy, size_t count,
                          size_t limit)
{
    if (!p || !rng_or_1)
        return ISK_ERR_NULL;
    if (!isfinite(cx) || !isfinite(cy))
        return ISK_ERR_NAN;
    isk_status s = check_count(count, limit);
    if (s != ISK_OK)
        return s;
    return isk__store_grow_for(p, count);
}

isk_vec2 isk_ring_velocity(size_t i, size_t count)
{
    /* (i*360)/count: i*360 is an exact integer in JS (and here, in double). */
    double deg = ((double)i * 360.0) / (double)count;
    return isk_vec2_rotate_thesis(isk_vec2_make(4.0, 4.0), deg);
}

isk_status isk_explode_ring(isk_particles *p, double cx, double cy, size_t count, size_t limit)
{
    isk_status s = prepare(p, p, cx, cy, count, limit);
    if (s != ISK_OK)
        return s;
    for (size_t i = 0; i < count; i++) {
        isk_vec2 v = isk_ring_velocity(i, count);
        isk__store_push(p, cx, cy, v.x, v.y, 2.0);
    }
    return ISK_OK;
}

isk_status isk_explode_uniform(isk_particles *p, isk_rng *r, double cx, double cy, size_t count,
                               size_t limit)
{
    isk_status s = prepare(p, r, cx, cy, count, limit);
    if (s != ISK_OK)
        return s;
    for (size_t i = 0; i < count; i++) {
        double vx = isk_rng_uniform(r) * 20.0 - 10.0;
        double vy = isk_rng_uniform(r) * 20.0 - 10.0;
        isk__store_push(p, cx, cy, vx, vy, 2.0);
    }
    return ISK_OK;
}

isk_status isk_explode_gauss(isk_particles *p, isk_rng *r, double cx, double cy, size_t count,
                             size_t limit)
{
    isk_status s = prepare(p, r, cx, cy, count, limit);
    if (s != ISK_OK)
        return s;
    for (size_t i = 0; i < count; i++) {
        double z1, z2;
        isk_rng_normal2(r, &z1, &z2);
        double m = 2.0 + isk_rng_uniform(r);
        isk__store_push(p, cx, cy, z1 * 3.0, z2 * 3.0, m);
    }
    return ISK_OK;
}

/* The sigma-0.02 cloud at rest (no kick yet). */
static void coulomb_cloud(isk_particles *p, isk_rng *r, double cx, double cy, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        double z1, z2;
        isk_rng_normal2(r, &z1, &z2);
        double m = 2.0 + isk_rng_uniform(r);
        isk__store_push(p, z1 / 50.0 + cx, z2 / 50.0 + cy, 0.0, 0.0, m);
    }
}

void isk_coulomb_kick(isk_particles *p, size_t begin, size_t end, double cx, double cy, double k)
{
    if (!p)
        return;
    if (end > p->count)
        end = p->count;
    const double s = 1.0 * ((-1.0) * k); /* ukljuci*(naboj*k), naboj = -1 */
    double *restrict x = p->x, *restrict y = p->y, *restrict vx = p->vx, *restrict vy = p->vy;
    const double *restrict m = p->m;
    for (size_t i = begin; i < end; i++) {
        double fx, fy;
        isk_k_coulomb(cx, cy, x[i], y[i], s, 1.0, 0.06, 2.0, 2, 0, &fx, &fy);
        isk_k_semi_euler(&x[i], &y[i], &vx[i], &vy[i], m[i], fx, fy, 0.01);
    }
}

isk_status isk_explode_coulomb(isk_particles *p, isk_rng *r, double cx, double cy, size_t count,
                               size_t limit, isk_kick_target target)
{
    if (target != ISK_KICK_ALL && target != ISK_KICK_NEW)
        return ISK_ERR_RANGE;
    isk_status s = prepare(p, r, cx, cy, count, limit);
    if (s != ISK_OK)
        return s;
    size_t first = p->count;
    coulomb_cloud(p, r, cx, cy, count);
    isk_coulomb_kick(p, target == ISK_KICK_ALL ? 0 : first, p->count, cx, cy, 150.0);
    return ISK_OK;
}

isk_status isk_explode_layer(isk_particles *p, isk_rng *r, double xmin, double xmax, double ymin,
                             double ymax, size_t count, size_t limit)
{
    if (!p || !r)
        return ISK_ERR_NULL;
    if (!isfinite(xmin) || !isfinite(xmax) || !isfinite(ymin) || !isfinite(ymax))
        return ISK_ERR_NAN;
    if (xmin > xmax || ymin > ymax)
        return ISK_ERR_RANGE;
    isk_status s = prepare(p, r, 0.0, 0.0, count, limit);
    if (s != ISK_OK)
        return s;
    for (size_t i = 0; i < count; i++) {
        double x = isk_rng_uniform(r) * (xmax - xmin) + xmin;
        double y = isk_rng_uniform(r) * (ymax - ymin) + ymin;
        isk__store_push(p, x, y, 0.0, 0.0, 1.0);
    }
    return ISK_OK;
}

/* ---- multiple Coulomb ---- */

double isk_multi_coulomb_k(size_t batch) { return 80.0 * (log((double)batch) + 0.5); }

void isk_multi_coulomb_plan(size_t n, size_t *batch_size, size_t *batches, size_t *last_size)
{
    size_t s = (size_t)floor((double)n * 0.06);
    if (s == 0)
        s = 1;
    size_t b = n / s + 1;
    size_t rest = n % s;
    if (rest == 0)
        b -= 1;
    if (batch_size)
        *batch_size = s;
    if (batches)
        *batches = b;
    if (last_size)
        *last_size = rest ? rest : s;
}

/* The sum is added term by term, in order (the thesis's bits), up to this
 * batch; an explosion has at most a few dozen batches.  Past it the
 * harmonic number's expansion ln n + gamma + 1/2n - 1/12n^2 (its error is
 * below 1/120n^4) gives the value in constant time: a hostile
 * batch = SIZE_MAX must not loop 10^19 times. */
#define RELEASE_SUM_MAX ((size_t)1 << 20)

double isk_multi_coulomb_release_time(size_t batch)
{
    if (batch > RELEASE_SUM_MAX) {
        const double n = (double)(batch - 1);
        return 0.010 * (log(n) + 0.57721566490153286061 + 1.0 / (2.0 * n) - 1.0 / (12.0 * n * n));
    }
    double t = 0.0;
    for (size_t j = 1; j < batch; j++)
        t += 0.010 / (double)j;
    return t;
}

isk_status isk_multi_coulomb_start(isk_multi_coulomb *mc, double cx, double cy, size_t count,
                                   size_t limit)
{
    if (!mc)
        return ISK_ERR_NULL;
    if (!isfinite(cx) || !isfinite(cy))
        return ISK_ERR_NAN;
    isk_status s = check_count(count, limit);
    if (s != ISK_OK)
        return s;
    mc->cx = cx;
    mc->cy = cy;
    mc->total = count;
    isk_multi_coulomb_plan(count, &mc->batch_size, &mc->batches, &mc->last_size);
    mc->next = 1;
    mc->age = 0.0;
    mc->next_release = 0.0;
    return ISK_OK;
}

isk_status isk_multi_coulomb_release(isk_multi_coulomb *mc, isk_particles *p, isk_rng *r,
                                     size_t *released)
{
    if (released)
        *released = 0;
    if (!mc || !p || !r)
        return ISK_ERR_NULL;
    while (mc->next <= mc->batches && mc->age >= mc->next_release) {
        size_t n = mc->next == mc->batches ? mc->last_size : mc->batch_size;
        isk_status s = isk__store_grow_for(p, n);
        if (s != ISK_OK)
            return s;
        size_t first = p->count;
        coulomb_cloud(p, r, mc->cx, mc->cy, n);
        isk_coulomb_kick(p, first, p->count, mc->cx, mc->cy, isk_multi_coulomb_k(mc->next));
        if (released)
            *released += n;
        mc->next_release += 0.010 / (double)mc->next; /* sleep(10/i ms) */
        mc->next++;
    }
    return ISK_OK;
}

void isk_multi_coulomb_advance(isk_multi_coulomb *mc, double dt)
{
    if (mc)
        mc->age += dt;
}

size_t isk_multi_coulomb_due(const isk_multi_coulomb *mc)
{
    size_t n = 0;
    double t = mc ? mc->next_release : 0.0;
    for (size_t b = mc ? mc->next : 1; mc && b <= mc->batches && mc->age >= t; b++) {
        n += b == mc->batches ? mc->last_size : mc->batch_size;
        t += 0.010 / (double)b; /* as the release's schedule */
    }
    return n;
}

int isk_multi_coulomb_done(const isk_multi_coulomb *mc) { return !mc || mc->next > mc->batches; }
