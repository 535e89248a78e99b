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

#include "effect_internal.h"
#include "iskra/shape.h"

#define FX_MAX_RATE 1e7 /* particles per second */

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

isk_status fx_stream_validate(const isk_emitter_def *em, char *why, size_t n)
{
    if ((unsigned)em->shape >= ISK_SHAPE_COUNT || (unsigned)em->launch >= ISK_VELGEN_COUNT) {
        snprintf(why, n, "unknown spawn shape or velocity kind");
        return ISK_ERR_RANGE;
    }
    isk_shape s = shape_of(em);
    if (isk_shape_check(&s) != ISK_OK) {
        snprintf(why, n, "spawn shape parameters invalid (radii >= 0, inner <= outer, all finite)");
        return ISK_ERR_RANGE;
    }
    isk_velgen v = velgen_of(em);
    if (isk_velgen_check(&v) != ISK_OK) {
        snprintf(why, n, "velocity parameters invalid (speeds finite, 0 <= min <= max, spread 0..360 degrees)");
        return ISK_ERR_RANGE;
    }
    if (!isfinite(em->rate) || em->rate < 0 || em->rate > FX_MAX_RATE) {
        snprintf(why, n, "rate must be 0..%g particles per second", FX_MAX_RATE);
        return ISK_ERR_RANGE;
    }
    if ((unsigned)em->rate_mode > ISK_RATE_THESIS || (unsigned)em->birth > ISK_BIRTH_FRAME) {
        snprintf(why, n, "unknown rate or birth mode");
        return ISK_ERR_RANGE;
    }
    if (em->count > em->capacity) {
        snprintf(why, n, "burst count %zu exceeds capacity %zu", em->count, em->capacity);
        return ISK_ERR_RANGE;
    }
    if (!isfinite(em->burst_every) || em->burst_every < 0) {
        snprintf(why, n, "burst interval must be >= 0 seconds");
        return ISK_ERR_RANGE;
    }
    if (em->rate == 0 && em->count == 0) {
        snprintf(why, n, "a stream needs rate > 0 or a burst count > 0");
        return ISK_ERR_RANGE;
    }
    return ISK_OK;
}

void fx_stream_reset(fx_group *g, double time)
{
    g->dropped = 0;
    g->next_burst = g->def->count > 0 ? g->def->start + time : INFINITY;
    g->origin = g->def->start + time;
    g->emitted = 0;
}

/* Where and how fast new particles start: built once per spawn call. */
typedef struct launcher {
    isk_shape shape;
    isk_velgen launch;
} launcher;

/* One new particle: position, velocity and mass drawn here, lifetime and
 * oscillation by fx_adopt, then its first moments: back-dated births run the
 * group's own pipeline on it for its age; the thesis's jitter applies a
 * random whole number of milliseconds of the external force. */
static isk_status birth(isk_effect *e, fx_group *g, const launcher *l, double age)
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

/* The births due in (t0, t0 + h], each created at t0 + h and advanced by
 * its age. */
static isk_status run_spawn(isk_effect *e, fx_group *g, double t0, double h)
{
    const isk_emitter_def *em = g->def;
    const double t1 = t0 + h;
    /* A birth due within a nanosecond of the step's end belongs to this step:
     * 30 steps of 1/30 s and 144 of 1/144 s must agree on "t = 1 s". */
    const double t1_tol = t1 + 1e-9 * (t1 > 1.0 ? t1 : 1.0);
    const launcher l = {shape_of(em), velgen_of(em)};
    isk_status s;

    /* Bursts first: they are scheduled events. */
    while (g->next_burst <= t1_tol) {
        double age = t1 - g->next_burst;
        if (age < 0) age = 0;
        for (size_t k = 0; k < em->count; k++) {
            if (isfinite(em->life) && age >= em->life + em->life_range)
                break; /* dead on arrival: the whole burst */
            if ((s = birth(e, g, &l, em->birth == ISK_BIRTH_THESIS_JITTER ? h : age)) != ISK_OK)
                return s;
        }
        g->next_burst = em->burst_every > 0 ? g->next_burst + em->burst_every : INFINITY;
    }
    if (!(em->rate > 0))
        return ISK_OK;
    if (em->rate_mode == ISK_RATE_THESIS) {
        /* The fire thesis: (unsigned)(dt*rate + 0.5) per frame, no carry;
         * at 60 frames/s a rate of 20/s gives 0.833 -> nothing, ever. */
        unsigned k = (unsigned)(h * em->rate + 0.5);
        for (unsigned j = 0; j < k; j++)
            if ((s = birth(e, g, &l, em->birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0)) != ISK_OK)
                return s;
        return ISK_OK;
    }
    /* Accumulator: the k-th particle is due at start + k/rate. */
    for (;;) {
        double tb = g->origin + (double)(g->emitted + 1) / em->rate;
        if (tb > t1_tol)
            break;
        g->emitted++;
        double age = t1 - tb;
        if (age < 0)
            age = 0;
        if (isfinite(em->life) && age >= em->life + em->life_range)
            continue; /* would be dead already: never created */
        double a = em->birth == ISK_BIRTH_BACKDATE ? age : (em->birth == ISK_BIRTH_THESIS_JITTER ? h : 0.0);
        if ((s = birth(e, g, &l, a)) != ISK_OK)
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
