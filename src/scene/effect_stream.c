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
 * draws, iskra/shape.h), velocity (the generator's), mass (one uniform, only
 * with a mass range), life (one, only with a life range), oscillation
 * (omega then amplitude, then the phase with osc_random_phase; only with
 * oscillation), jitter (one, only in the thesis jitter mode). */
#include <math.h>
#include <stdint.h>

#include "effect_internal.h"
#include "iskra/shape.h"

static isk_shape shape_of(const isk_emitter_def *em)
{
    isk_shape s = {0};
    s.kind = em->shape;
    s.cx = em->pos.x;
    s.cy = em->pos.y;
    s.a = em->shape_a;
    s.b = em->shape_b;
    s.angle = em->shape_angle;
    s.ellipse_mode = em->shape_faithful ? ISK_ELLIPSE_THESIS : ISK_ELLIPSE_UNIFORM;
    return s;
}

static isk_velgen velgen_of(const isk_emitter_def *em)
{
    switch (em->launch) {
    case ISK_VELGEN_DISC: return isk_velgen_disc(em->speed_max);
    case ISK_VELGEN_DIRECTION: return isk_velgen_direction(em->angle, em->speed_min, em->speed_max);
    case ISK_VELGEN_CONE: return isk_velgen_cone(em->angle, em->spread, em->speed_min, em->speed_max);
    default: return isk_velgen_constant(em->vel.x, em->vel.y);
    }
}

void fx_stream_reset(fx_group *g, double time)
{
    g->dropped = 0;
    g->next_burst = g->def->count > 0 ? g->def->start + time : INFINITY;
    g->origin = g->def->start + time;
    g->emitted = 0;
}

/* Where and how fast new particles start: built once per spawn call. */
fx_launcher fx_launcher_of(const isk_emitter_def *em)
{
    fx_launcher l = {shape_of(em), velgen_of(em)};
    return l;
}

/* One new particle: position, velocity and mass drawn here, lifetime and
 * oscillation by fx_adopt, then its first moments: back-dated births run the
 * group's own pipeline on it for its age; the thesis's jitter applies a
 * random whole number of milliseconds of the external force. */
isk_status fx_birth(isk_effect *e, fx_group *g, const fx_launcher *l, double age, const double *dv)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    if (p->count >= em->capacity) {
        g->dropped++;
        return ISK_OK;
    }
    double x, y, vx, vy;
    isk_shape_sample(&l->shape, &g->rng, &x, &y);
    isk_velgen_sample(&l->launch, &g->rng, &vx, &vy);
    if (em->launch == ISK_VELGEN_DISC) {
        vx += em->vel.x;
        vy += em->vel.y;
    }
    if (dv) { /* a sub-emitter's inherited velocity (only there: a stream's bits are untouched) */
        vx += dv[0];
        vy += dv[1];
    }
    double m = em->mass + (em->mass_range > 0 ? em->mass_range * isk_rng_uniform(&g->rng) : 0.0);
    size_t i;
    isk_status st = isk_particles_add(p, x, y, vx, vy, m, &i);
    if (st != ISK_OK)
        return st;
    fx_adopt(e, g, i);
    switch (em->birth) {
    case ISK_BIRTH_BACKDATE:
        if (age > 0)
            isk_pipeline_run(&g->pipeline, p, i, i + 1, age, &e->scratch);
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
    double room = (double)(SIZE_MAX - g->dropped);
    g->dropped = n >= room ? SIZE_MAX : g->dropped + (size_t)n;
}

/* Places left in the pool. */
static size_t room_left(const fx_group *g)
{
    return g->store.count < g->def->capacity ? g->def->capacity - g->store.count : 0;
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
    const double every = em->burst_every, nb = g->next_burst;
    double due = every > 0 ? floor((t1_tol - nb) / every) + 1.0 : 1.0;
    if (!(due >= 1.0))
        due = 1.0; /* rounding at the edge: the one that made the test true */
    double next = every > 0 ? nb + due * every : INFINITY;
    if (!(next > t1_tol))
        next = nextafter(t1_tol, INFINITY); /* the schedule is finer than the clock: never back in time */
    g->next_burst = next;
    if (em->count == 0)
        return ISK_OK;
    const double life_max = em->life + em->life_range;
    double first = 0.0; /* the first burst young enough to live */
    if (isfinite(life_max) && every > 0 && t1 - life_max > nb)
        first = floor((t1 - life_max - nb) / every);
    int doa = 0;
    for (double j = first; j < due; j++) { /* ends: each turn fills the pool or is one of <= 3 dead ones */
        if (room_left(g) == 0) {
            drop(g, (due - j) * (double)em->count);
            break;
        }
        double age = t1 - (nb + j * every);
        if (age < 0)
            age = 0;
        if (isfinite(em->life) && age >= life_max) {
            if (++doa > 2)
                break; /* j no longer moves (beyond 2^53): nothing younger is representable */
            continue; /* dead on arrival: the whole burst */
        }
        for (size_t k = 0; k < em->count; k++) {
            isk_status s = fx_birth(e, g, l, em->birth == ISK_BIRTH_THESIS_JITTER ? h : age, NULL);
            if (s != ISK_OK)
                return s;
        }
    }
    return ISK_OK;
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
    const fx_launcher l = fx_launcher_of(em);
    isk_status s;

    /* Bursts first: they are scheduled events. */
    if (g->next_burst <= t1_tol && (s = run_bursts(e, g, &l, t1, t1_tol, h)) != ISK_OK)
        return s;
    if (!(em->rate > 0))
        return ISK_OK;
    if (em->rate_mode == ISK_RATE_THESIS) {
        /* The fire thesis: (unsigned)(dt*rate + 0.5) per frame, no carry;
         * at 60 frames/s a rate of 20/s gives 0.833 -> nothing, ever. */
        double want = floor(h * em->rate + 0.5); /* <= 10^10: clamped before any integer cast */
        double take = fmin(want, (double)room_left(g));
        for (size_t j = 0; j < (size_t)take; j++)
            if ((s = fx_birth(e, g, &l, em->birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0, NULL)) != ISK_OK)
                return s;
        drop(g, want - take);
        return ISK_OK;
    }
    /* Accumulator: the k-th particle is due at start + k/rate. */
    const double life_max = em->life + em->life_range;
    if (isfinite(life_max)) {
        /* Skip those that would be dead already (never created): all but
         * the last life_max*rate + 1 of a long step. */
        double oldest = floor((t1 - life_max - g->origin) * em->rate);
        if (oldest > (double)g->emitted + 1.0)
            g->emitted = oldest - 1.0 >= 18446744073709549568.0 ? UINT64_MAX : (uint64_t)(oldest - 1.0);
    }
    int doa = 0;
    for (;;) { /* ends: each turn is a birth, the pool's end, or one of <= 3 dead ones */
        double tb = g->origin + (double)(g->emitted + 1) / em->rate;
        if (tb > t1_tol)
            break;
        if (room_left(g) == 0) {
            /* The rest of this step's births find no room: counted, skipped. */
            double n = floor((t1_tol - g->origin) * em->rate) - (double)g->emitted;
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
        if (isfinite(em->life) && age >= life_max) {
            if (++doa > 2)
                break; /* the clock no longer resolves single births here */
            continue; /* would be dead already: never created */
        }
        double a = em->birth == ISK_BIRTH_BACKDATE ? age : (em->birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0);
        if ((s = fx_birth(e, g, &l, a, NULL)) != ISK_OK)
            return s;
    }
    return ISK_OK;
}

static void describe_spawn(const isk_effect *e, const fx_group *g, FILE *out)
{
    (void)e;
    const isk_emitter_def *em = g->def;
    /* In the scene file's words: key = value. */
    fprintf(out, "%g/s, rate_mode %s, birth %s", em->rate, isk_rate_mode_names[em->rate_mode],
            isk_birth_mode_names[em->birth]);
}

const fx_step_kind fx_step_spawn = {"spawn", run_spawn, describe_spawn};
