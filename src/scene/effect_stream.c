/* SPDX-License-Identifier: MIT */
/* Stream emitters: continuous emission and bursts (the fire thesis's
 * emitters, with the particle-engine thesis's back-dated births).
 *
 * Births happen at exact times.  In the default accumulator mode the k-th
 * particle of a stream is born at start + k/rate, whatever the frame rate;
 * a particle born inside a step is created at the end of that step and
 * advanced by its age through the emitter's own stages, so stepping at 30
 * or at 144 steps per second gives the same particles (positions up to the
 * integrator's error for the different step sizes).  A particle whose age
 * already exceeds its life is never created (particle-engine thesis).
 *
 * Random draws per new particle, in this order: position (the shape's
 * draws, iskra/shape.h), velocity (the generator's), life (one, only with
 * a life range), oscillation (omega then amplitude, then the phase with
 * osc_random_phase; only with oscillation), jitter (one, only in the thesis
 * jitter mode).  A mass range draws from a stream of its own (fx_stream),
 * as the looks do.
 *
 * Moving emitters: the emitter's path is position(t) = base +
 * emitter_velocity*(t - t_base), computed directly at every birth time,
 * never accumulated, so a birth at time tb is placed around position(tb)
 * whatever the frame rate.  A live change of the position starts a segment
 * from where the emitter is to the new position over the next frame, so
 * an emitter dragged around leaves no gaps.  In local space the particles
 * are carried by the emitter's motion (isk__fx_step_carry) and are born around
 * its position at the end of the step.  A stream with a duration emits in
 * cycles (run_cycles). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "effect_internal.h"
#include "iskra/shape.h"

static isk_shape shape_of(const isk_emitter_def *em)
{
    isk_shape s = {0};
    s.kind = em->born.shape;
    s.cx = em->born.position.x;
    s.cy = em->born.position.y;
    s.a = em->born.shape_a;
    s.b = em->born.shape_b;
    s.angle = em->born.shape_angle;
    s.ellipse_mode = em->born.shape_faithful ? ISK_ELLIPSE_THESIS : ISK_ELLIPSE_UNIFORM;
    return s;
}

static isk_velgen velgen_of(const isk_emitter_def *em)
{
    switch (em->launch.kind) {
    case ISK_VELGEN_DISC: return isk_velgen_disc(em->launch.speed_max);
    case ISK_VELGEN_DIRECTION:
        return isk_velgen_direction(em->launch.angle, em->launch.speed_min, em->launch.speed_max);
    case ISK_VELGEN_CONE:
        return isk_velgen_cone(em->launch.angle, em->launch.spread, em->launch.speed_min, em->launch.speed_max);
    default: return isk_velgen_constant(em->launch.velocity.x, em->launch.velocity.y);
    }
}

void isk__fx_stream_reset(fx_group *g, double time)
{
    g->dropped = 0;
    g->next_burst = g->def->born.count > 0 ? g->def->born.start + time : INFINITY;
    g->origin = g->def->born.start + time;
    g->emitted = 0;
    g->path_base = g->def->born.position;
    g->path_t = time;
    g->path_t0 = g->path_t1 = -INFINITY;
    g->carried = g->def->born.position;
    g->cycle_start = g->def->born.start + time;
    g->cycle_births = g->cycle_bursts = 0;
}

/* ---- the emitter's path -------------------------------------------------------- */

static isk_vec2 on_path(const fx_group *g, const isk_emitter_def *em, double t)
{
    const isk_vec2 v = em->born.emitter_velocity;
    if (v.x == 0 && v.y == 0)
        return g->path_base;
    isk_vec2 p = {g->path_base.x + v.x * (t - g->path_t), g->path_base.y + v.y * (t - g->path_t)};
    return p;
}

isk_vec2 isk__fx_emitter_pos(const fx_group *g, const isk_emitter_def *em, double t)
{
    if (em->born.source != ISK_SOURCE_STREAM)
        return em->born.position;
    if (t < g->path_t1) {
        const isk_vec2 a = g->path_from, b = on_path(g, em, g->path_t1);
        double f = (t - g->path_t0) / (g->path_t1 - g->path_t0);
        if (!(f > 0))
            return a;
        isk_vec2 p = {a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f};
        return p;
    }
    return on_path(g, em, t);
}

void isk__fx_field_clock(fx_group *g, double t)
{
    const isk_vec2 c = isk__fx_emitter_pos(g, g->def, t);
    g->field.t = t;
    g->field.cx = c.x;
    g->field.cy = c.y;
}

void isk__fx_path_changed(isk_effect *e, fx_group *g, const isk_emitter_def *old, const char *key)
{
    const double now = isk__fx_group_time(e, g);
    const isk_vec2 here = isk__fx_emitter_pos(g, old, now);
    if (!strcmp(key, "position")) {
        /* the new position is reached at the end of the next frame */
        const double t1 = now + e->def.dt / e->def.speed_divisor;
        g->path_from = here;
        g->path_t0 = now;
        g->path_t1 = t1;
        g->path_base = g->def->born.position;
        g->path_t = t1;
    } else if (!strcmp(key, "emitter_velocity")) {
        /* the path goes on from here with the new velocity (a live move
         * under way keeps its end point) */
        if (now < g->path_t1) {
            g->path_base = on_path(g, old, g->path_t1);
            g->path_t = g->path_t1;
        } else {
            g->path_base = here;
            g->path_t = now;
        }
    }
}

/* The emitter moves, or has been moved live (its path is then no longer
 * its definition's position alone). */
static int moving(const fx_group *g, const isk_emitter_def *em)
{
    return em->born.emitter_velocity.x != 0 || em->born.emitter_velocity.y != 0 || g->path_t1 > -INFINITY;
}

/* One axis of the carry: every particle moves by d; one that a closed wall
 * ahead (at `wall`, in d's direction) would be pushed through stops on it,
 * its velocity through the wall turned back with the restitution c, as
 * at a bounce.  A particle already beyond the wall before the carry (the
 * thesis's walls let some be) is carried as it is. */
static void carry_axis(size_t n, double *restrict pos, double *restrict v, double d, double wall, double c)
{
    for (size_t i = 0; i < n; i++) {
        const double from = pos[i], to = from + d;
        if (d > 0 ? (from <= wall && to > wall) : (from >= wall && to < wall)) {
            pos[i] = wall;
            if (d > 0 ? v[i] > 0 : v[i] < 0)
                v[i] = -c * v[i];
        } else {
            pos[i] = to;
        }
    }
}

/* Local space: every particle moves by what the emitter moved since they
 * were last carried (a difference of directly computed positions, so the
 * carries add up to the emitter's whole way).  The carry runs after the
 * walls, so it respects them itself: a carried particle never ends a step
 * beyond a closed wall. */
static isk_status run_carry(isk_effect *e, fx_group *g, double t0, double h)
{
    const isk_vec2 to = isk__fx_emitter_pos(g, g->def, t0 + h);
    const double dx = to.x - g->carried.x, dy = to.y - g->carried.y;
    g->carried = to;
    if (dx == 0 && dy == 0)
        return ISK_OK;
    isk_particles *p = &g->store;
    const isk_bounds *b = &e->def.bounds;
    const unsigned sides = g->def->motion.bounded ? b->sides : 0u;
    const double c = b->mode == ISK_BOUNCE_REFLECT ? b->restitution : 1.0; /* the thesis's walls flip the sign */
    /* the wall ahead on each axis, if closed; none: infinitely far */
    const unsigned xside = dx > 0 ? ISK_SIDE_RIGHT : ISK_SIDE_LEFT, yside = dy > 0 ? ISK_SIDE_TOP : ISK_SIDE_BOTTOM;
    const double xwall = !(sides & xside) ? (dx > 0 ? INFINITY : -INFINITY)
        : dx > 0                          ? b->xmax - b->margin
                                          : b->xmin + b->margin;
    const double ywall = !(sides & yside) ? (dy > 0 ? INFINITY : -INFINITY)
        : dy > 0                          ? b->ymax - b->margin
                                          : b->ymin + b->margin;
    if (dx != 0)
        carry_axis(p->count, p->x, p->vx, dx, xwall, c);
    if (dy != 0)
        carry_axis(p->count, p->y, p->vy, dy, ywall, c);
    return ISK_OK;
}

static void describe_carry(const isk_effect *e, const fx_group *g, FILE *out)
{
    fprintf(out, "local space: the particles move with the emitter%s",
            g->def->motion.bounded && e->def.bounds.sides ? ", never through a wall" : "");
}

const fx_step_kind isk__fx_step_carry = {"carry", run_carry, describe_carry};

double isk__fx_prewarm_frames(const isk_effect_def *d, const isk_emitter_def *em)
{
    if (!(em->born.prewarm > 0) || em->born.source != ISK_SOURCE_STREAM)
        return 0;
    double n = floor(em->born.prewarm / (d->dt / d->speed_divisor) + 0.5);
    return n < 1 ? 1 : n;
}

void isk__fx_prewarm_offsets(const isk_effect_def *d, double *frames)
{
    for (int i = 0; i < d->nemitters; i++)
        frames[i] = isk__fx_prewarm_frames(d, &d->emitters[i]);
    /* a longest path in the graph of events visits each emitter once, so
     * nemitters rounds of "a target takes its largest source" settle it
     * (a cycle only carries the same largest value round) */
    for (int round = 0; round < d->nemitters; round++) {
        int changed = 0;
        for (int i = 0; i < d->nemitters; i++) {
            const isk_emitter_def *em = &d->emitters[i];
            const int to[2] = {em->events.on_death, em->events.on_hit};
            for (int k = 0; k < 2; k++)
                if (to[k] >= 0 && to[k] < d->nemitters && d->emitters[to[k]].born.source == ISK_SOURCE_SUB &&
                    frames[to[k]] < frames[i]) {
                    frames[to[k]] = frames[i];
                    changed = 1;
                }
        }
        if (!changed)
            break;
    }
}

/* launch_outward: (vx, vy) turned by the direction of (dx, dy), the birth
 * place seen from the shape's centre: a launch along +x then points
 * straight outward.  The turn is by the unit vector itself (no angle, no
 * trigonometry); exactly on the centre there is no direction and no turn. */
static void turn_outward(double dx, double dy, double *vx, double *vy)
{
    const double r = hypot(dx, dy);
    if (!(r > 0.0 && r < INFINITY))
        return;
    const double c = dx / r, s = dy / r, x = *vx, y = *vy;
    *vx = c * x - s * y;
    *vy = s * x + c * y;
}

/* Where and how fast new particles start: built once per spawn call. */
fx_launcher isk__fx_launcher_of(const isk_emitter_def *em)
{
    fx_launcher l = {shape_of(em), velgen_of(em), 0, NAN, 0.0};
    return l;
}

/* One new particle: position, velocity and mass drawn here, lifetime and
 * oscillation by isk__fx_adopt, then its first moments: back-dated births run the
 * group's own pipeline on it for its age; the thesis's jitter applies a
 * random whole number of milliseconds of the external force. */
isk_status isk__fx_birth(isk_effect *e, fx_group *g, const fx_launcher *l, double age, double tb, const double *dv)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    if (p->count >= em->born.capacity) {
        g->dropped++;
        return ISK_OK;
    }
    double x, y, vx, vy, cx = l->shape.cx, cy = l->shape.cy;
    if (l->moving) {
        isk_shape s = l->shape;
        /* birth = frame: born, and so placed, at the end of the step */
        const double at = !isnan(l->place) ? l->place : em->born.birth == ISK_BIRTH_FRAME ? l->t1 : tb;
        const isk_vec2 c = isk__fx_emitter_pos(g, em, at);
        s.cx = cx = c.x;
        s.cy = cy = c.y;
        isk_shape_sample(&s, &g->rng, &x, &y);
    } else {
        isk_shape_sample(&l->shape, &g->rng, &x, &y);
    }
    isk_velgen_sample(&l->launch, &g->rng, &vx, &vy);
    if (em->launch.kind == ISK_VELGEN_DISC) {
        vx += em->launch.velocity.x;
        vy += em->launch.velocity.y;
    }
    if (em->launch.outward)
        turn_outward(x - cx, y - cy, &vx, &vy);
    if (dv) { /* a sub-emitter's inherited velocity (only there: a stream's bits are untouched) */
        vx += dv[0];
        vy += dv[1];
    }
    isk_rng *mass = &g->streams[FX_STREAM_MASS];
    double m = em->launch.mass + (em->launch.mass_range > 0 ? em->launch.mass_range * isk_rng_uniform(mass) : 0.0);
    size_t i;
    isk_status st = isk_particles_add(p, x, y, vx, vy, m, &i);
    if (st != ISK_OK)
        return st;
    isk__fx_adopt(e, g, i);
    switch (em->born.birth) {
    case ISK_BIRTH_BACKDATE:
        if (age > 0) {
            /* the field acts from the birth: its time, the emitter there */
            const double kt = g->field.t, kx = g->field.cx, ky = g->field.cy;
            if (g->has_field)
                isk__fx_field_clock(g, tb);
            isk__pipeline_run(&g->pipeline, p, i, i + 1, age, &e->scratch, NULL);
            g->field.t = kt;
            g->field.cx = kx;
            g->field.cy = ky;
        }
        break;
    case ISK_BIRTH_THESIS_JITTER: {
        /* (rand() % msec) / 1000 s of the external force and a position step. */
        double h = age; /* here: the frame length */
        int msec = (int)(h * 1000.0 + 0.5);
        if (msec > 0) {
            double sec = (double)isk_rng_below(&g->rng, (uint32_t)msec) / 1000.0;
            p->vx[i] += g->const_ax * sec;
            p->vy[i] += g->const_ay * sec;
            p->x[i] += p->vx[i] * sec;
            p->y[i] += p->vy[i] * sec;
        }
        break;
    }
    default:
        break;
    }
    return ISK_OK;
}

/* Births lost to a full pool are counted, not looped over: n more of them. */
static void drop(fx_group *g, double n)
{
    double room = (double)(UINT64_MAX - g->dropped);
    g->dropped = n >= room ? UINT64_MAX : g->dropped + (uint64_t)n;
}

/* Places left in the pool. */
static size_t room_left(const fx_group *g)
{
    return g->store.count < g->def->born.capacity ? g->def->born.capacity - g->store.count : 0;
}

/* Bursts due up to t1_tol: how many are due is computed, not counted one
 * by one, so an interval below the clock's resolution (1e-300) cannot stall
 * the schedule and a tiny one (1e-8: 10^6 bursts a frame) costs at most one
 * turn per particle the pool can still take; the rest are dropped and
 * counted.  Bursts older than the longest life are never born (as single
 * births). */
static isk_status run_bursts(isk_effect *e, fx_group *g, const fx_launcher *l, double t1, double t1_tol, double h)
{
    const isk_emitter_def *em = g->def;
    const double every = isk__fx_burst_every(em), nb = g->next_burst;
    double due = every > 0 ? floor((t1_tol - nb) / every) + 1.0 : 1.0;
    if (!(due >= 1.0))
        due = 1.0; /* rounding at the edge: the one that made the test true */
    double next = every > 0 ? nb + due * every : INFINITY;
    if (!(next > t1_tol))
        next = nextafter(t1_tol, INFINITY); /* the schedule is finer than the clock: never back in time */
    g->next_burst = next;
    if (em->born.count == 0)
        return ISK_OK;
    const double life_max = em->life.seconds + em->life.range;
    double first = 0.0; /* the first burst young enough to live */
    if (isfinite(life_max) && every > 0 && t1 - life_max > nb)
        first = floor((t1 - life_max - nb) / every);
    int doa = 0;
    for (double j = first; j < due; j++) { /* ends: each turn fills the pool or is one of <= 3 dead ones */
        if (room_left(g) == 0) {
            drop(g, (due - j) * (double)em->born.count);
            break;
        }
        const double tb = nb + j * every;
        double age = t1 - tb;
        if (age < 0)
            age = 0;
        if (isfinite(em->life.seconds) && age >= life_max) {
            if (++doa > 2)
                break; /* j no longer moves (beyond 2^53): nothing younger is representable */
            continue; /* dead on arrival: the whole burst */
        }
        for (size_t k = 0; k < em->born.count; k++) {
            isk_status s = isk__fx_birth(e, g, l, em->born.birth == ISK_BIRTH_THESIS_JITTER ? h : age, tb, NULL);
            if (s != ISK_OK)
                return s;
        }
    }
    return ISK_OK;
}

/* ---- streams with a duration ------------------------------------------------------
 *
 * Cycle c covers [S + c*D, S + (c+1)*D) (S: start, D: duration); its
 * births are at S + c*D + k/rate for k = 1..n, n = floor(rate*D) (exactly
 * rate*D when that is a whole number, up to a billionth), and its bursts
 * at S + c*D + j*burst_every for the m values of j with j*burst_every < D
 * (one with burst_every = 0).  Without loop there is cycle 0 only.  A
 * birth or burst is numbered from S on, and its time computed from its
 * number directly, so no sum drifts over many cycles. */

static double whole(double x) { return floor(x + 1e-9 * (x > 1.0 ? x : 1.0)); }

static double births_per_cycle(const isk_emitter_def *em)
{
    return em->born.rate > 0 ? whole(em->born.rate * em->born.duration) : 0.0;
}

static double bursts_per_cycle(const isk_emitter_def *em)
{
    if (em->born.count == 0)
        return 0;
    if (!(em->born.burst_every > 0))
        return 1;
    const double x = em->born.duration / isk__fx_burst_every(em);
    const double m = ceil(x - 1e-9 * (x > 1.0 ? x : 1.0));
    return m < 1 ? 1 : m;
}

/* The time of event number i (0, 1, ...) of n per cycle, the k-th (from 0)
 * of its cycle at offset(k). */
static double event_time(const fx_group *g, double i, double n, double k_scale, double k_first)
{
    const double c = floor(i / n), k = i - c * n;
    return g->cycle_start + c * g->def->born.duration + (k + k_first) * k_scale;
}

/* How many of the events with n per cycle are due by time t: within a
 * cycle those up to offset (t - cycle's start), as computed by `within`. */
static double events_due(const fx_group *g, double t, double n, double k_scale, double k_first)
{
    const isk_emitter_def *em = g->def;
    if (!(t >= g->cycle_start) || n <= 0)
        return 0;
    const double D = em->born.duration, c = floor((t - g->cycle_start) / D);
    if (!em->born.loop && c >= 1)
        return n;
    double in = floor((t - g->cycle_start - c * D) / k_scale) + 1.0 - k_first;
    in = in < 0 ? 0 : in > n ? n : in;
    return c * n + in;
}

/* One kind of event (bursts: `count` births each; births: one each) due in
 * the step ending at t1.  Every turn is an event born, the pool's end (the
 * rest counted as dropped in one addition), or one of <= 3 dead ones. */
static isk_status run_events(isk_effect *e, fx_group *g, const fx_launcher *l, double t1, double h, double *done,
                             double n, double k_scale, double k_first, size_t each)
{
    const isk_emitter_def *em = g->def;
    const double t1_tol = t1 + 1e-9 * (t1 > 1.0 ? t1 : 1.0);
    const double life_max = em->life.seconds + em->life.range;
    if (n <= 0 || each == 0)
        return ISK_OK;
    if (isfinite(life_max)) {
        /* those dead already are never created: skip all but the last one */
        double oldest = events_due(g, t1 - life_max, n, k_scale, k_first) - 1.0;
        if (oldest > *done)
            *done = oldest;
    }
    int doa = 0;
    for (;;) {
        if (!em->born.loop && *done >= n)
            break; /* the one cycle is over */
        const double tb = event_time(g, *done, n, k_scale, k_first);
        if (tb > t1_tol)
            break;
        if (room_left(g) == 0) {
            double left = events_due(g, t1_tol, n, k_scale, k_first) - *done;
            if (left < 1)
                left = 1;
            *done += left;
            drop(g, left * (double)each);
            break;
        }
        *done += 1;
        double age = t1 - tb;
        if (age < 0)
            age = 0;
        if (isfinite(em->life.seconds) && age >= life_max) {
            if (++doa > 2)
                break;
            continue;
        }
        double a = em->born.birth == ISK_BIRTH_BACKDATE ? age : (em->born.birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0);
        for (size_t k = 0; k < each; k++) {
            isk_status s = isk__fx_birth(e, g, l, a, tb, NULL);
            if (s != ISK_OK)
                return s;
        }
    }
    return ISK_OK;
}

void isk__fx_stream_rate_changed(isk_effect *e, fx_group *g)
{
    const isk_emitter_def *em = g->def;
    if (em->born.duration > 0 && em->born.rate > 0)
        g->cycle_births = events_due(g, isk__fx_group_time(e, g), births_per_cycle(em), 1.0 / em->born.rate, 1.0);
}

static isk_status run_cycles(isk_effect *e, fx_group *g, const fx_launcher *l, double t0, double h)
{
    const isk_emitter_def *em = g->def;
    const double t1 = t0 + h;
    const double every = em->born.burst_every > 0 ? isk__fx_burst_every(em) : em->born.duration;
    isk_status s = run_events(e, g, l, t1, h, &g->cycle_bursts, bursts_per_cycle(em), every, 0.0, em->born.count);
    if (s != ISK_OK || !(em->born.rate > 0))
        return s;
    if (em->born.rate_mode == ISK_RATE_THESIS) {
        /* the thesis's rounding per frame, in the steps that start within a cycle */
        if (!(t0 >= g->cycle_start) || (!em->born.loop && t0 >= g->cycle_start + em->born.duration))
            return ISK_OK;
        double want = floor(h * em->born.rate + 0.5);
        double take = fmin(want, (double)room_left(g));
        for (size_t j = 0; j < (size_t)take; j++)
            if ((s = isk__fx_birth(e, g, l, em->born.birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0, t1, NULL)) != ISK_OK)
                return s;
        drop(g, want - take);
        return ISK_OK;
    }
    return run_events(e, g, l, t1, h, &g->cycle_births, births_per_cycle(em), 1.0 / em->born.rate, 1.0, 1);
}

/* Where and how fast the births of a step ending at t1 start: on the
 * emitter's path, placed at t1 in local space. */
static fx_launcher launcher_at(const fx_group *g, const isk_emitter_def *em, double t1)
{
    fx_launcher l = isk__fx_launcher_of(em);
    l.moving = moving(g, em);
    l.t1 = t1;
    if (em->born.space == ISK_SPACE_LOCAL)
        l.place = t1;
    if (l.moving) {
        const isk_vec2 c = isk__fx_emitter_pos(g, em, t1);
        l.shape.cx = c.x;
        l.shape.cy = c.y;
    }
    return l;
}

/* The births due in (t0, t0 + h], each created at t0 + h and advanced by
 * its age.  Every loop here ends after at most (places left in the pool +
 * 1) turns, whatever the rate, interval and step: births beyond the pool's
 * room are counted as dropped in one addition. */
static isk_status run_spawn(isk_effect *e, fx_group *g, double t0, double h)
{
    const isk_emitter_def *em = g->def;
    const double t1 = t0 + h;
    /* A birth due within a nanosecond of the step's end belongs to this step:
     * 30 steps of 1/30 s and 144 of 1/144 s must agree on "t = 1 s". */
    const double t1_tol = t1 + 1e-9 * (t1 > 1.0 ? t1 : 1.0);
    fx_launcher l = launcher_at(g, em, t1);
    isk_status s;
    if (em->born.duration > 0)
        return run_cycles(e, g, &l, t0, h);

    /* Bursts first: they are scheduled events. */
    if (g->next_burst <= t1_tol && (s = run_bursts(e, g, &l, t1, t1_tol, h)) != ISK_OK)
        return s;
    if (!(em->born.rate > 0))
        return ISK_OK;
    if (em->born.rate_mode == ISK_RATE_THESIS) {
        /* The fire thesis: (unsigned)(dt*rate + 0.5) per frame, no carry;
         * at 60 frames/s a rate of 20/s gives 0.833 -> nothing, ever. */
        double want = floor(h * em->born.rate + 0.5); /* <= 10^10: clamped before any integer cast */
        double take = fmin(want, (double)room_left(g));
        for (size_t j = 0; j < (size_t)take; j++)
            if ((s = isk__fx_birth(e, g, &l, em->born.birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0, t1, NULL)) != ISK_OK)
                return s;
        drop(g, want - take);
        return ISK_OK;
    }
    /* Accumulator: the k-th particle is due at start + k/rate. */
    const double life_max = em->life.seconds + em->life.range;
    if (isfinite(life_max)) {
        /* Skip those that would be dead already (never created): all but
         * the last life_max*rate + 1 of a long step. */
        double oldest = floor((t1 - life_max - g->origin) * em->born.rate);
        if (oldest > (double)g->emitted + 1.0)
            g->emitted = oldest - 1.0 >= 18446744073709549568.0 ? UINT64_MAX : (uint64_t)(oldest - 1.0);
    }
    int doa = 0;
    for (;;) { /* ends: each turn is a birth, the pool's end, or one of <= 3 dead ones */
        double tb = g->origin + (double)(g->emitted + 1) / em->born.rate;
        if (tb > t1_tol)
            break;
        if (room_left(g) == 0) {
            /* The rest of this step's births find no room: counted, skipped. */
            double n = floor((t1_tol - g->origin) * em->born.rate) - (double)g->emitted;
            if (n < 1)
                n = 1; /* at least the one found due (a rounded-off last one comes next step) */
            g->emitted += n >= 18446744073709549568.0 ? 0 : (uint64_t)n;
            drop(g, n);
            break;
        }
        g->emitted++;
        double age = t1 - tb;
        if (age < 0)
            age = 0;
        if (isfinite(em->life.seconds) && age >= life_max) {
            if (++doa > 2)
                break; /* the clock no longer resolves single births here */
            continue; /* would be dead already: never created */
        }
        double a = em->born.birth == ISK_BIRTH_BACKDATE ? age : (em->born.birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0);
        if ((s = isk__fx_birth(e, g, &l, a, tb, NULL)) != ISK_OK)
            return s;
    }
    return ISK_OK;
}

static void describe_spawn(const isk_effect *e, const fx_group *g, FILE *out)
{
    (void)e;
    const isk_emitter_def *em = g->def;
    /* In the scene file's words: key = value. */
    fprintf(out, "%g/s, rate_mode %s, birth %s", em->born.rate, isk_rate_mode_names[em->born.rate_mode],
            isk_birth_mode_names[em->born.birth]);
    if (em->born.duration > 0)
        fprintf(out, ", for %g s%s", em->born.duration, em->born.loop ? " in a loop" : "");
    if (em->born.emitter_velocity.x != 0 || em->born.emitter_velocity.y != 0)
        fprintf(out, ", along the emitter's path at (%g, %g)/s", em->born.emitter_velocity.x,
                em->born.emitter_velocity.y);
    if (g->frame_offset)
        fprintf(out, ", prewarmed %ld frames", g->frame_offset);
}

const fx_step_kind isk__fx_step_spawn = {"spawn", run_spawn, describe_spawn};

/* ---- births by hand, stopping and pausing (effect_control.c) ---------------------- */

isk_status isk__fx_stream_emit(isk_effect *e, fx_group *g, size_t n)
{
    const double now = isk__fx_group_time(e, g);
    const fx_launcher l = launcher_at(g, g->def, now);
    const size_t room = room_left(g), born = n < room ? n : room;
    drop(g, (double)(n - born)); /* the rest find no room: counted in one addition */
    for (size_t k = 0; k < born; k++) {
        isk_status s = isk__fx_birth(e, g, &l, 0.0, now, NULL);
        if (s != ISK_OK)
            return s;
    }
    return ISK_OK;
}

void isk__fx_stream_resume(isk_effect *e, fx_group *g)
{
    const isk_emitter_def *em = g->def;
    const double now = isk__fx_group_time(e, g);
    /* the next accumulator birth one interval from now, as at a start */
    g->origin = now;
    g->emitted = 0;
    if (em->born.duration > 0) {
        const double every = em->born.burst_every > 0 ? isk__fx_burst_every(em) : em->born.duration;
        g->cycle_bursts = events_due(g, now, bursts_per_cycle(em), every, 0.0);
        g->cycle_births = em->born.rate > 0 ? events_due(g, now, births_per_cycle(em), 1.0 / em->born.rate, 1.0) : 0.0;
    } else if (g->next_burst <= now) {
        const double every = isk__fx_burst_every(em);
        if (every > 0) {
            double next = g->next_burst + (floor((now - g->next_burst) / every) + 1.0) * every;
            g->next_burst = next > now ? next : nextafter(now, INFINITY);
        } else {
            g->next_burst = INFINITY; /* its one burst was due meanwhile */
        }
    }
}
