/* SPDX-License-Identifier: MIT */
/* bench_walls — the walls against the memory-bandwidth limit, and the
 * bounce at the time of impact (iskra/impact.h) against the end-of-step
 * rule it replaced, measured in one run.
 *
 * The limit of a row: the bytes its stage set must move to and from memory
 * in a particle-step over the best STREAM kernel (copy, scale, add, triad)
 * measured in the same process, once in every round among the stage sets
 * (the best of the rounds), on arrays whose total footprint is that of
 * the store's columns the stage set touches, so both sit in the same level
 * of the memory.  Each column counts once a step: the runner keeps a block
 * of 128 particles in L1 from one stage to the next, so a column two stages
 * touch is read once and written once (when some stage changes it).
 *   the motion rows (motion, walls, remember, resting, drag, Coulomb): the
 *     motion stage reads x, y, vx, vy, m and writes x, y, vx, vy: 72 B; the
 *     remember, walls and forces stages work on the block in L1 (the walls
 *     read m for the drag's flight, the remember stage copies into the
 *     scratch).  Footprint 40 B a particle.
 *   fire: the drift with the thesis's slowing reads and writes x, y, vx, vy
 *     (no mass): 64 B; the sway reads osc_amp, osc_phase, osc_omega,
 *     osc_offset and writes osc_amp, osc_phase, osc_offset (it changes x
 *     and vx too, which the drift has read and writes anyway): 56 B; 120 B
 *     in all, as two stages or in one pass.  Footprint 64 B a particle.
 * The goal for every stage set: within 1.5x of its limit.
 *
 * Variants, each a pipeline of the library's block runner over the same
 * store (semi-implicit Euler, gravity 9.81 + linear drag 0.47, dt = 1/600,
 * particles uniform in a 10 x 10 box with speeds up to 5 per axis: the
 * bench_integrators setup; reflect walls on all four sides, c = 0.8):
 *   motion         forces + integrator, no walls
 *   walls, end     + the walls with the end-of-step rule (the old stage)
 *   walls, impact  forces + integrator + the walls at the time of impact,
 *                  the flight known from the end state (what scenes and
 *                  isk_system run with constant forces and drag)
 *   + remember     the same with the start state remembered and fitted
 *                  (what runs when potentials act; without them, as here,
 *                  the motion stage copies the block's start first)
 *   resting        the impact walls with every particle resting on the
 *                  floor (c = 0.5) and sliding along it: every particle
 *                  hits every step, the worst case of the scalar path
 *   y at rest      the same with the blocks' states (sim/stage.h's
 *                  isk_rest, what the effects run with): every block's y
 *                  axis rests and the runner steps x alone
 *   standing still the same without the sliding: every block comes to rest
 *                  and the runner skips its stages
 * (the last two rows' bytes stay those of the stage set they stand for)
 *   drag alone     the motion with the drag as its only force
 *   + Coulomb      the motion with one potential at the box's centre
 *                  (P = 2, sound centre rule, no distance switches): the
 *                  fused pass, forces and integrator in one loop
 *                  (src/sim/motion_fused.h)
 *   thesis, P = 1  the same potential with the thesis's centre rule and
 *                  P = 1 (the fused pass's other rule and exponent)
 *   Coulomb+walls  the Coulomb motion with the impact walls, from the start
 *                  state the fused pass keeps as it reads it (what a scene
 *                  with potentials and sound walls runs)
 *   fire           what a fire scene compiles to: the drift with the
 *                  thesis's slowing, then the sway (ISK_PARTICLES_OSC,
 *                  lerp on a 4096-entry table, the thesis's vx coupling),
 *                  one drift+sway stage doing both in one pass
 * at 10^6 and 10^7 particles.  Rounds interleave the variants; each figure
 * is the fastest of ROUNDS_MAX (the least disturbed) with the median beside
 * it.  The machine is shared: read the ratios, not the nanoseconds.
 *
 * `bench_walls --quick` runs 10^6 particles and 16384 (a store in the
 * caches: what the stages' arithmetic costs with the memory out of the
 * picture, steady on a busy machine), 5 rounds: a figure in seconds for
 * iterating on a kernel (quote the full run). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "iskra/sinlut.h"
#include "iskra/system.h"
#include "sim/rest.h"
#include "sim/stage.h"

enum { ROUNDS_MAX = 7 };
static const double DT = 1.0 / 600, G = 9.81, DRAG = 0.47;

/* ---- the bandwidth limit ---------------------------------------------------- */

/* The STREAM arrays of one footprint: two or three arrays whose total size
 * is the footprint's bytes, kept for the whole measurement so that each
 * round measures them again beside the stage sets (a disturbance of the
 * shared machine then lowers one round's figure, not every ratio). */
typedef struct stream {
    double *a, *b, *c;
    size_t n2, n3;
    double best; /* bytes per ns, the best so far */
} stream;

static int stream_init(stream *st, size_t bytes)
{
    st->n2 = bytes / 16;
    st->n3 = bytes / 24;
    st->a = malloc(st->n2 * sizeof *st->a);
    st->b = malloc(st->n2 * sizeof *st->b);
    st->c = malloc(st->n3 * sizeof *st->c);
    st->best = 0;
    if (!st->a || !st->b || !st->c)
        return 1;
    for (size_t i = 0; i < st->n2; i++)
        st->a[i] = 1.0, st->b[i] = 2.0;
    for (size_t i = 0; i < st->n3; i++)
        st->c[i] = 0.5;
    return 0;
}

static void stream_free(stream *st)
{
    free(st->a), free(st->b), free(st->c);
}

/* One round: copy, scale, add and triad twice each, keeping the best (the
 * first pass finds the arrays evicted by the stage sets, as their first
 * step, the warm one, finds the store). */
static void stream_round(stream *st)
{
    const size_t n2 = st->n2, n3 = st->n3;
    for (int pass = 0; pass < 8; pass++) {
        const int k = pass % 4;
        double t0 = bench_now(), moved;
        double *restrict A = st->a, *restrict B = st->b, *restrict C = st->c;
        const double s = 1.0000001;
        switch (k) {
        case 0: for (size_t i = 0; i < n2; i++) A[i] = B[i]; moved = 16.0 * (double)n2; break;
        case 1: for (size_t i = 0; i < n2; i++) A[i] = s * B[i]; moved = 16.0 * (double)n2; break;
        case 2: for (size_t i = 0; i < n3; i++) A[i] = B[i] + C[i]; moved = 24.0 * (double)n3; break;
        default: for (size_t i = 0; i < n3; i++) A[i] = B[i] + s * C[i]; moved = 24.0 * (double)n3; break;
        }
        double t = bench_now() - t0;
        if (t > 0 && moved / (t * 1e9) > st->best)
            st->best = moved / (t * 1e9);
    }
    volatile double sink = st->a[n2 / 2] + st->c[n3 / 3];
    (void)sink;
}

/* ---- the variants ------------------------------------------------------------- */

/* The walls as they were: the end-of-step rule, no start state. */
static void run_end_walls(const isk_stage *st, isk_block *b, double h)
{
    (void)h;
    isk_bounds_apply_arrays(st->u.walls.b, b->n, b->x, b->y, b->vx, b->vy);
}
static void describe_end_walls(const isk_stage *st, FILE *out)
{
    (void)st;
    fprintf(out, "end-of-step rule");
}
static const isk_stage_kind end_walls = {.name = "walls", .run = run_end_walls, .describe = describe_end_walls};

enum { V_MOTION, V_END, V_IMPACT, V_START, V_REST, V_SLIDE, V_STILL, V_DRAG, V_COULOMB, V_COULOMB_T, V_COULOMB_WALLS, V_FIRE, NV };

/* A row: its name, the bytes its stage set moves a particle-step and the
 * bytes a particle of the columns it touches (the top comment says why). */
typedef struct variant {
    const char *name;
    int bytes, footprint;
} variant;
enum { MOTION_BYTES = 72, MOTION_FOOTPRINT = 40, FIRE_BYTES = 64 + 56, FIRE_FOOTPRINT = 64 };
static const variant VARIANT[NV] = {
    {"motion", MOTION_BYTES, MOTION_FOOTPRINT},
    {"walls, end-of-step rule", MOTION_BYTES, MOTION_FOOTPRINT},
    {"walls, at the time of impact", MOTION_BYTES, MOTION_FOOTPRINT},
    {"  the same from a remembered start", MOTION_BYTES, MOTION_FOOTPRINT},
    {"impact, all resting on the floor", MOTION_BYTES, MOTION_FOOTPRINT},
    {"  the same, their y axis at rest", MOTION_BYTES, MOTION_FOOTPRINT},
    {"  standing still: blocks at rest", MOTION_BYTES, MOTION_FOOTPRINT},
    {"drag alone (no walls)", MOTION_BYTES, MOTION_FOOTPRINT},
    {"motion + one Coulomb potential", MOTION_BYTES, MOTION_FOOTPRINT},
    {"  the same, thesis rule, P = 1", MOTION_BYTES, MOTION_FOOTPRINT},
    {"Coulomb + walls (kept start)", MOTION_BYTES, MOTION_FOOTPRINT},
    {"fire: drift+slowing, sway", FIRE_BYTES, FIRE_FOOTPRINT},
};

typedef struct world {
    isk_particles p;
    isk_forces f, drag, coulomb, coulomb_t;
    isk_potential pot, pot_t;
    isk_sinlut sine;
    isk_bounds box, floor;
    isk_pipeline pl[NV];
    isk_rest rest; /* the standing row's blocks at rest */
    isk_scratch *s;
} world;

enum { MOVING, SLIDING, STANDING };

static void fill(world *w, size_t n, int resting)
{
    isk_particles_clear(&w->p);
    isk_rng r;
    isk_rng_seed(&r, 1);
    for (size_t i = 0; i < n; i++) {
        double x = isk_rng_range(&r, 0, 10), y = isk_rng_range(&r, 0, 10);
        double vx = isk_rng_range(&r, -5, 5), vy = isk_rng_range(&r, -5, 5), m = 1 + isk_rng_uniform(&r);
        if (resting)
            y = 0, vx *= resting == SLIDING ? 0.1 : 0.0, vy = 0;
        isk_particles_add(&w->p, x, y, vx, vy, m, NULL);
    }
    for (size_t i = 0; i < n; i++) { /* the fire's sway: 1..3 rad/s, 0.1..0.3 wide */
        w->p.osc_amp[i] = isk_rng_range(&r, 0.1, 0.3);
        w->p.osc_omega[i] = isk_rng_range(&r, 1, 3);
        w->p.osc_phase[i] = isk_rng_range(&r, 0, 6.283185307179586);
        w->p.osc_offset[i] = 0;
    }
}

static int build(world *w, size_t n)
{
    memset(w, 0, sizeof *w);
    if (isk_particles_init(&w->p, n, ISK_PARTICLES_OSC) != ISK_OK || isk_sinlut_init(&w->sine, 4096) != ISK_OK)
        return 1;
    w->s = aligned_alloc(64, (sizeof(isk_scratch) + 63) / 64 * 64);
    if (!w->s)
        return 1;
    w->f.gravity = G;
    w->f.drag = DRAG;
    w->drag.drag = DRAG;
    /* a potential at the box's centre pulling with the thesis's law (P = 2),
     * sound centre rule, no distance switches: it acts on every particle */
    isk_potential_init(&w->pot, 1.0, isk_vec2_make(5, 5), -2.0);
    w->coulomb = w->f;
    w->coulomb.pot = &w->pot;
    w->coulomb.npot = 1;
    w->coulomb.centre = ISK_FIDELITY_SOUND;
    w->pot_t = w->pot;
    w->pot_t.P = 1.0;
    w->coulomb_t = w->coulomb;
    w->coulomb_t.pot = &w->pot_t;
    w->coulomb_t.centre = ISK_FIDELITY_THESIS;
    isk_bounds_reflect(&w->box, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 0.8);
    isk_bounds_reflect(&w->floor, 0, 10, 0, 10, ISK_SIDE_ALL, 0, 0.5);
    for (int v = 0; v < NV; v++) {
        isk_pipeline *pl = &w->pl[v];
        isk__pipeline_init(pl);
        if (v == V_FIRE) { /* what a fire scene compiles to (scene/effect_compile.c) */
            isk_stage *d = isk__pipeline_add(pl, &isk__stage_drift_sway);
            d->u.drift_sway.ay = 0.5; /* buoyancy */
            d->u.drift_sway.slowing = 0.5;
            d->u.drift_sway.order = ISK_DRIFT_THESIS;
            d->u.drift_sway.osc.decay = 0.2;
            d->u.drift_sway.osc.table = &w->sine;
            d->u.drift_sway.osc.mode = ISK_SINLUT_LERP;
            d->u.drift_sway.osc.faithful = 1;
            continue;
        }
        const int kept_start = v == V_START || v == V_COULOMB_WALLS; /* as effect_compile.c asks */
        isk_stage *m = isk__pipeline_add(pl, &isk__stage_motion);
        isk__stage_motion_init(m, ISK_INTEGRATE_SEMI_EULER,
                               v == V_DRAG                              ? &w->drag
                               : v == V_COULOMB || v == V_COULOMB_WALLS ? &w->coulomb
                               : v == V_COULOMB_T                       ? &w->coulomb_t
                                                                        : &w->f);
        m->u.motion.remember = kept_start;
        if (v == V_MOTION || v == V_DRAG || v == V_COULOMB || v == V_COULOMB_T)
            continue;
        isk_stage *st = isk__pipeline_add(pl, v == V_END ? &end_walls : &isk__stage_walls);
        st->u.walls.b = v == V_REST || v == V_SLIDE || v == V_STILL ? &w->floor : &w->box;
        st->u.walls.drag = DRAG;
        st->u.walls.start = kept_start;
        st->u.walls.ay = -G; /* the constant acceleration, and semi-implicit Euler's offset */
        st->u.walls.offset = isk_integrator_velocity_offset(ISK_INTEGRATE_SEMI_EULER);
    }
    fill(w, n, 0);
    return 0;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The first row with row v's footprint (v itself, or one before it): the
 * one whose STREAM arrays measure that footprint's limit. */
static int first_of_footprint(int v)
{
    int u = 0;
    while (VARIANT[u].footprint != VARIANT[v].footprint)
        u++;
    return u;
}

static void print_limits(size_t n, const stream st[NV])
{
    printf("  bandwidth limit: the best STREAM kernel on the columns a stage set touches (each round)\n   ");
    for (int v = 0; v < NV; v++)
        if (first_of_footprint(v) == v)
            printf("  %d B a particle (%.1f MB): %.2f GB/s", VARIANT[v].footprint,
                   (double)VARIANT[v].footprint * (double)n / 1e6, st[v].best);
    printf("\n");
}

/* The STREAM arrays of the footprints (st[v] for the first row of each,
 * see first_of_footprint; the others stay empty, so freeing them is a
 * no-op).  Returns 1 when memory runs out. */
static int streams_init(stream st[NV], size_t n)
{
    int bad = 0;
    memset(st, 0, NV * sizeof *st);
    for (int v = 0; v < NV; v++)
        if (first_of_footprint(v) == v)
            bad |= stream_init(&st[v], (size_t)VARIANT[v].footprint * n);
    return bad;
}

static void streams_free(stream st[NV])
{
    for (int v = 0; v < NV; v++)
        stream_free(&st[v]);
}

static int measure(size_t n, int steps, int rounds)
{
    world w;
    if (build(&w, n)) {
        fprintf(stderr, "bench_walls: out of memory at %zu particles\n", n);
        return 1;
    }
    stream st[NV];
    if (streams_init(st, n)) {
        fprintf(stderr, "bench_walls: out of memory for the STREAM arrays at %zu particles\n", n);
        streams_free(st);
        free(w.s);
        isk__rest_free(&w.rest);
        isk_particles_free(&w.p);
        return 1;
    }
    double t[NV][ROUNDS_MAX];
    size_t still = 0, sliding = 0; /* the standing row's blocks at rest, the sliding row's y at rest */
    for (int r = 0; r < rounds; r++) {
        const int slot = r % (NV + 1); /* the STREAM round's place among the rows, a different one every round */
        for (int k = 0; k <= NV; k++) {
            if (k == slot) {
                for (int v = 0; v < NV; v++)
                    if (first_of_footprint(v) == v)
                        stream_round(&st[v]);
                continue;
            }
            const int v = (k - (k > slot) + r) % NV; /* the rows in a different order every round */
            fill(&w, n, v == V_REST || v == V_SLIDE ? SLIDING : v == V_STILL ? STANDING : MOVING);
            isk_rest *rest = v == V_STILL || v == V_SLIDE ? &w.rest : NULL;
            isk__rest_forget(&w.rest, 0);
            const isk_run_context ctx = {NULL, rest};
            for (int s = 0; s < (rest ? 12 : 1); s++) /* warm; standing: every block comes to rest */
                isk__pipeline_run(&w.pl[v], &w.p, 0, w.p.count, DT, w.s, &ctx);
            double t0 = bench_now();
            for (int s = 0; s < steps; s++)
                isk__pipeline_run(&w.pl[v], &w.p, 0, w.p.count, DT, w.s, &ctx);
            t[v][r] = (bench_now() - t0) / ((double)steps * (double)n) * 1e9;
            if (v == V_STILL)
                still = isk__rest_blocks(rest, w.p.count, ISK_REST_X | ISK_REST_Y);
            if (v == V_SLIDE)
                sliding = isk__rest_blocks(rest, w.p.count, ISK_REST_Y);
        }
    }
    printf("%zu particles, %d steps per timing, fastest (median) of %d rounds\n", n, steps, rounds);
    print_limits(n, st);
    double limit[NV]; /* bytes per ns */
    for (int v = 0; v < NV; v++)
        limit[v] = st[first_of_footprint(v)].best;
    printf("  %-34s %5s %10s %21s %7s\n", "stage set", "bytes", "limit", "time (median)", "ratio");
    double best[NV];
    for (int v = 0; v < NV; v++) {
        qsort(t[v], (size_t)rounds, sizeof t[v][0], cmp);
        best[v] = t[v][0];
        const double floor_ns = VARIANT[v].bytes / limit[v]; /* the least a particle-step can cost */
        printf("  %-34s %3d B %7.3f ns %7.3f ns (%7.3f) %6.2fx\n", VARIANT[v].name, VARIANT[v].bytes, floor_ns,
               t[v][0], t[v][rounds / 2], t[v][0] / floor_ns);
    }
    printf("  impact / end-of-step rule: %.3f   impact / motion alone: %.3f   (goal: every stage set <= 1.5x "
           "its limit)\n",
           best[V_IMPACT] / best[V_END], best[V_IMPACT] / best[V_MOTION]);
    printf("  blocks at rest: standing %zu, sliding with y at rest %zu, of %zu\n\n", still, sliding,
           (w.p.count + ISK_SIM_BLOCK - 1) / ISK_SIM_BLOCK);
    streams_free(st);
    free(w.s);
    isk__rest_free(&w.rest);
    isk_particles_free(&w.p);
    return 0;
}

int main(int argc, char **argv)
{
    const int quick = bench_quick_arg(argc, argv,
                                      "usage: bench_walls [--quick]\n"
                                      "  each stage set's time a particle-step against the memory-bandwidth limit;\n"
                                      "  --quick: 10^6 and 16384 particles, fewer rounds\n");
    const int rounds = quick ? 5 : ROUNDS_MAX;
    printf("bench_walls: gravity %.2f + drag %.2f + reflect walls, semi-implicit Euler, dt 1/600\n\n", G, DRAG);
    if (measure(1000000, 10, rounds))
        return 1;
    return quick ? measure(16384, 600, rounds) : measure(10000000, 2, rounds);
}
