/* SPDX-License-Identifier: MIT */
/* A campfire: fire + sparks + smoke from stacked emitters (fire thesis
 * figure 5.5, "fire, sparks and smoke", with iskra's extensions).
 *
 * Four stream emitters in one effect, drawn in this order:
 *
 *   smoke   overpaint soft sprites, grey, growing and fading out; weight 2.4
 *           against gravity 1.0 (the fire thesis's buoyancy: weight > gravity,
 *           so it rises), slowed, swaying; drawn first, behind the flames
 *   flame   additive radial-gradient sprites (the thesis's glowing mode),
 *           colour over life yellow -> orange -> red -> transparent, shrinking,
 *           rising by buoyancy with a horizontal flame oscillation
 *   core    the same, smaller, hotter and shorter-lived: the white-yellow heart
 *   sparks  small additive sprites thrown up under gravity 3, bouncing off
 *           the ground and the two logs (deflector segments, restitution 0.35)
 *
 * The ground, the glow under the fire and the two logs are drawings of the
 * effect (filled polygons, discs and a sprite), drawn before the emitters, so
 * scenes/fire_campfire.ini can say exactly the same.  --wind X adds a sideways acceleration X (world units
 * per s^2) to flames, smoke and sparks (the fire thesis's wind).
 *
 * Options: --png PATH, --window (animates), --seed N, --frames N (default
 * 180: three seconds at 60 steps/s, the fire well developed), --wind X,
 * --strip PATH (a PNG strip of the first second: 6 panels at t = 1/6 .. 1 s,
 * half size, side by side).  Same seed and frame: the same bytes.
 */
#include <math.h>

#include "example.h"
#include "iskra/effect.h"

#define W 480
#define H 400
#define PI 3.14159265358979323846

typedef struct campfire {
    isk_effect *fx;
} campfire;

/* A log: a thick segment as a filled quadrilateral with round, darker ends. */
static void add_log(isk_effect_def *d, double x0, double y0, double x1, double y1, double r, isk_color col)
{
    double dx = x1 - x0, dy = y1 - y0, L = hypot(dx, dy);
    double nx = -dy / L * r, ny = dx / L * r;
    char name[ISK_NAME_MAX]; /* drawings are named uniquely: "log0", "log0.end1", ... */
    const int id = d->ndrawings;
    snprintf(name, sizeof name, "log%d", id);
    isk_drawing_def *q = isk_effect_def_add_drawing(d, name, ISK_DRAWING_POLYGON);
    double pts[8] = {x0 + nx, y0 + ny, x1 + nx, y1 + ny, x1 - nx, y1 - ny, x0 - nx, y0 - ny};
    q->points = malloc(sizeof pts);
    if (q->points)
        memcpy(q->points, pts, sizeof pts);
    q->npoints = 4;
    q->color = col;
    for (int k = 0; k < 2; k++) {
        /* An end disc and its darker core.  (Each add may move the array, so
         * a pointer from one add is never used after the next.) */
        const double rr[2] = {r, 0.55 * r};
        const isk_color cc[2] = {isk_rgba(90, 60, 40, 255), isk_rgba(60, 38, 25, 255)};
        for (int j = 0; j < 2; j++) {
            snprintf(name, sizeof name, "log%d.%s%d", id, j ? "core" : "end", k);
            isk_drawing_def *disc = isk_effect_def_add_drawing(d, name, ISK_DRAWING_DISC);
            disc->x = k ? x1 : x0;
            disc->y = k ? y1 : y0;
            disc->r = rr[j];
            disc->color = cc[j];
        }
    }
}

static isk_status build(isk_effect **out, uint64_t seed, double wind)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.width = W;
    d.height = H;
    d.xmin = -3.0;
    d.xmax = 3.0;
    d.ymin = -0.5;
    d.ymax = 4.5;
    d.dt = 1.0 / 60.0;
    d.seed = seed;
    d.background = isk_rgba(10, 10, 22, 255);

    /* The scenery, drawn every frame before the particles. */
    isk_drawing_def *soil = isk_effect_def_add_drawing(&d, "ground", ISK_DRAWING_POLYGON);
    const double gpts[8] = {-3.0, -0.5, 3.0, -0.5, 3.0, 0.0, -3.0, 0.0};
    soil->points = malloc(sizeof gpts);
    if (soil->points)
        memcpy(soil->points, gpts, sizeof gpts);
    soil->npoints = 4;
    soil->color = isk_rgba(24, 18, 14, 255);
    isk_drawing_def *glow = isk_effect_def_add_drawing(&d, "glow", ISK_DRAWING_SPRITE);
    glow->sprite = ISK_SPRITE_SMOOTH;
    glow->size = 3.2; /* 256 px */
    glow->x = 0.0;
    glow->y = 0.25;
    glow->color = isk_rgba(255, 110, 30, 90);
    glow->blend = ISK_BLEND_ADD;
    add_log(&d, -1.1, 0.12, 0.9, 0.42, 0.12, isk_rgba(70, 45, 30, 255));
    add_log(&d, 1.1, 0.12, -0.9, 0.42, 0.12, isk_rgba(82, 54, 36, 255));

    int grav = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    d.forces[grav].g = 1.0;
    int wf = isk_effect_def_add_force(&d, "wind", ISK_FORCE_WIND);
    d.forces[wf].accel = isk_vec2_make(wind, 0);
    int ground = isk_effect_def_add_deflector(&d, "ground", isk_deflector_segment(-3.2, 0.0, 3.2, 0.0));
    int log1 = isk_effect_def_add_deflector(&d, "log1", isk_deflector_segment(-1.1, 0.12, 0.9, 0.42));
    int log2 = isk_effect_def_add_deflector(&d, "log2", isk_deflector_segment(1.1, 0.12, -0.9, 0.42));
    for (int k = 0; k < d.ndeflectors; k++)
        d.deflectors[k].seg.restitution = 0.35;

    /* Smoke: rises because its weight (2.4) beats gravity (1.0). */
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "smoke");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.position = isk_vec2_make(0.0, 1.7);
    e->born.shape = ISK_SHAPE_ELLIPSE;
    e->born.shape_a = 0.3;
    e->born.shape_b = 0.15;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = PI / 2;
    e->launch.spread = 0.6;
    e->launch.speed_min = 0.2;
    e->launch.speed_max = 0.5;
    e->motion.weight = 2.4;
    e->motion.slowing = 0.6;
    e->born.rate = 18;
    e->life.seconds = 3.0;
    e->life.range = 1.5;
    e->born.capacity = 200;
    e->motion.osc_omega_min = -1.6; /* both signs: half sway left first */
    e->motion.osc_omega_max = 1.6;
    e->motion.osc_amplitude_min = 0.1;
    e->motion.osc_amplitude_max = 0.3;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_SMOOTH;
    e->look.size = 0.9;
    e->look.color = isk_rgba(120, 112, 108, 255);
    e->look.color_over_life.n = 2;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(150, 120, 100, 255)};
    e->look.color_over_life.stops[1] = (isk_color_stop){1.0, isk_rgba(70, 70, 75, 255)};
    e->look.alpha_over_life.n = 3;
    e->look.alpha_over_life.stops[0] = (isk_scalar_stop){0.0, 0.0};
    e->look.alpha_over_life.stops[1] = (isk_scalar_stop){0.2, 0.32};
    e->look.alpha_over_life.stops[2] = (isk_scalar_stop){1.0, 0.0};
    e->look.size_over_life.n = 2;
    e->look.size_over_life.stops[0] = (isk_scalar_stop){0.0, 0.6};
    e->look.size_over_life.stops[1] = (isk_scalar_stop){1.0, 2.4};
    e->look.blend = ISK_BLEND_OVER;
    e->look.order = 0;
    isk_emitter_use_force(e, grav);
    isk_emitter_use_force(e, wf);

    /* Flame: additive gradient sprites with a colour ramp. */
    e = isk_effect_def_add_emitter(&d, "flame");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.position = isk_vec2_make(0.0, 0.3);
    e->born.shape = ISK_SHAPE_ELLIPSE;
    e->born.shape_a = 0.42;
    e->born.shape_b = 0.08;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = PI / 2;
    e->launch.spread = 0.35;
    e->launch.speed_min = 1.2;
    e->launch.speed_max = 2.2;
    e->motion.weight = 3.5;   /* hot gas: buoyancy, no gravity */
    e->motion.slowing = 0.9;
    e->born.rate = 420;
    e->life.seconds = 0.4;
    e->life.range = 0.8;
    e->born.capacity = 600;
    e->motion.osc_omega_min = -9.0;
    e->motion.osc_omega_max = 9.0;
    e->motion.osc_amplitude_min = 0.08;
    e->motion.osc_amplitude_max = 0.22;
    e->motion.osc_decay = 0.3;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_LINEAR;
    e->look.size = 0.5;
    e->look.color_over_life.n = 4;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 220, 110, 60)};
    e->look.color_over_life.stops[1] = (isk_color_stop){0.3, isk_rgba(255, 140, 30, 60)};
    e->look.color_over_life.stops[2] = (isk_color_stop){0.65, isk_rgba(220, 50, 10, 45)};
    e->look.color_over_life.stops[3] = (isk_color_stop){1.0, isk_rgba(90, 0, 0, 0)};
    e->look.size_over_life.n = 2;
    e->look.size_over_life.stops[0] = (isk_scalar_stop){0.0, 1.0};
    e->look.size_over_life.stops[1] = (isk_scalar_stop){1.0, 0.3};
    e->look.blend = ISK_BLEND_ADD;
    e->look.order = 1;
    isk_emitter_use_force(e, wf);

    /* Core: the hot heart of the flame. */
    e = isk_effect_def_add_emitter(&d, "core");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.position = isk_vec2_make(0.0, 0.3);
    e->born.shape = ISK_SHAPE_ELLIPSE;
    e->born.shape_a = 0.35;
    e->born.shape_b = 0.08;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = PI / 2;
    e->launch.spread = 0.25;
    e->launch.speed_min = 0.8;
    e->launch.speed_max = 1.3;
    e->motion.weight = 2.0;
    e->motion.slowing = 0.8;
    e->born.rate = 70;
    e->life.seconds = 0.3;
    e->life.range = 0.35;
    e->born.capacity = 300;
    e->motion.osc_omega_min = -14.0;
    e->motion.osc_omega_max = 14.0;
    e->motion.osc_amplitude_min = 0.02;
    e->motion.osc_amplitude_max = 0.06;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_LINEAR;
    e->look.size = 0.32;
    e->look.color_over_life.n = 3;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 250, 210, 70)};
    e->look.color_over_life.stops[1] = (isk_color_stop){0.5, isk_rgba(255, 200, 80, 60)};
    e->look.color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(255, 110, 20, 0)};
    e->look.size_over_life.n = 2;
    e->look.size_over_life.stops[0] = (isk_scalar_stop){0.0, 1.0};
    e->look.size_over_life.stops[1] = (isk_scalar_stop){1.0, 0.5};
    e->look.blend = ISK_BLEND_ADD;
    e->look.order = 2;
    isk_emitter_use_force(e, wf);

    /* Sparks: thrown up, pulled down by gravity 3, bouncing off the logs and
     * the ground. */
    e = isk_effect_def_add_emitter(&d, "sparks");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.position = isk_vec2_make(0.0, 0.55);
    e->born.shape = ISK_SHAPE_DISC;
    e->born.shape_a = 0.3;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = PI / 2;
    e->launch.spread = 1.1;
    e->launch.speed_min = 1.8;
    e->launch.speed_max = 3.6;
    e->motion.gravity_multiplier = 3.0;
    e->motion.slowing = 0.25;
    e->born.rate = 22;
    e->life.seconds = 1.0;
    e->life.range = 1.6;
    e->born.capacity = 200;
    e->motion.osc_omega_min = -9.0;
    e->motion.osc_omega_max = 9.0;
    e->motion.osc_amplitude_min = 0.02;
    e->motion.osc_amplitude_max = 0.08;
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_LINEAR;
    e->look.size = 0.09;
    e->look.color_over_life.n = 3;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(255, 245, 200, 255)};
    e->look.color_over_life.stops[1] = (isk_color_stop){0.5, isk_rgba(255, 170, 50, 255)};
    e->look.color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(220, 50, 0, 0)};
    e->look.blend = ISK_BLEND_ADD;
    e->look.order = 3;
    isk_emitter_use_force(e, grav);
    isk_emitter_use_force(e, wf);
    isk_emitter_use_deflector(e, ground);
    isk_emitter_use_deflector(e, log1);
    isk_emitter_use_deflector(e, log2);

    isk_error err;
    isk_status s = isk_effect_create(out, &d, &err);
    if (s != ISK_OK)
        fprintf(stderr, "fire_campfire: %s\n", err.message);
    isk_effect_def_free(&d);
    return s;
}

static void draw(campfire *cf, isk_canvas *c)
{
    isk_effect_render(cf->fx, c);
}

static void frame(void *state, isk_canvas *c)
{
    campfire *cf = state;
    isk_effect_step(cf->fx);
    draw(cf, c);
}

/* 2x2 box filter, rounded: (a+b+c+d+2)/4 per channel. */
static void half_size(const isk_canvas *src, isk_canvas *dst)
{
    for (int y = 0; y < dst->height; y++)
        for (int x = 0; x < dst->width; x++) {
            uint8_t *o = isk_canvas_at(dst, x, y);
            for (int k = 0; k < 4; k++) {
                unsigned s = isk_canvas_at(src, 2 * x, 2 * y)[k] + isk_canvas_at(src, 2 * x + 1, 2 * y)[k] +
                             isk_canvas_at(src, 2 * x, 2 * y + 1)[k] + isk_canvas_at(src, 2 * x + 1, 2 * y + 1)[k];
                o[k] = (uint8_t)((s + 2) / 4);
            }
        }
}

#define STRIP_PANELS 6
#define STRIP_GAP 4

static int strip(campfire *cf, const char *path, isk_canvas *c)
{
    isk_canvas out, panel;
    const int pw = W / 2, ph = H / 2;
    if (isk_canvas_init(&out, STRIP_PANELS * pw + (STRIP_PANELS - 1) * STRIP_GAP, ph) != ISK_OK)
        return 1;
    isk_canvas_fill(&out, isk_rgba(60, 60, 60, 255));
    long f = 0;
    for (int k = 1; k <= STRIP_PANELS; k++) {
        long target = 60L * k / STRIP_PANELS; /* frames 10, 20, ..., 60 */
        while (f < target) {
            isk_effect_step(cf->fx);
            f++;
        }
        draw(cf, c);
        isk_canvas_view(&panel, &out, (k - 1) * (pw + STRIP_GAP), 0, pw, ph);
        half_size(c, &panel);
        char label[32];
        snprintf(label, sizeof label, "t=%.2fs", (double)f / 60.0);
        isk_draw_text(&panel, 4, 4, label, 1, isk_rgba(200, 200, 200, 255), ISK_BLEND_OVER);
    }
    isk_error err;
    int rc = 0;
    if (isk_png_write(&out, path, &err) != ISK_OK) {
        fprintf(stderr, "fire_campfire: %s\n", err.message);
        rc = 1;
    }
    isk_canvas_free(&out);
    return rc;
}

#define ABOUT "a campfire: additive flames, bouncing sparks, rising smoke"

/* The options this example adds to the shared ones (example.h). */
static void own_usage(FILE *f)
{
    fprintf(f, "  --wind X     sideways wind acceleration X in [-100, 100] (world units/s^2)\n"
               "               on flames, smoke and sparks (default 0)\n"
               "  --strip PATH write a PNG strip of the first second: 6 half-size panels at\n"
               "               t = 1/6 .. 1 s (alone, it replaces the default output)\n");
}

int main(int argc, char **argv)
{
    /* Our own options first; the rest go to the shared parser. */
    double wind = 0.0;
    const char *strip_path = NULL;
    int other_output = 0;
    char *rest[64];
    int nrest = 0;
    for (int i = 0; i < argc && nrest < 64; i++) {
        if (i > 0 && (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))) {
            example_usage(stdout, "fire_campfire", ABOUT, EX_SEED | EX_FRAMES);
            own_usage(stdout);
            return 0;
        }
        if (i > 0 && (!strcmp(argv[i], "--wind") || !strcmp(argv[i], "--strip")) && i + 1 >= argc) {
            fprintf(stderr, "fire_campfire: %s needs a value\n", argv[i]);
            example_usage(stderr, "fire_campfire", ABOUT, EX_SEED | EX_FRAMES);
            own_usage(stderr);
            return 2;
        }
        if (i > 0 && !strcmp(argv[i], "--wind")) {
            char *end;
            wind = strtod(argv[i + 1], &end);
            if (*end || !isfinite(wind) || fabs(wind) > 100) {
                fprintf(stderr, "fire_campfire: --wind expects a number in [-100, 100], got '%s'\n", argv[i + 1]);
                return 2;
            }
            i++;
        } else if (i > 0 && !strcmp(argv[i], "--strip")) {
            strip_path = argv[++i];
        } else {
            if (i > 0 && (!strcmp(argv[i], "--png") || !strcmp(argv[i], "--window")))
                other_output = 1;
            rest[nrest++] = argv[i];
        }
    }
    example_opts o = {.seed = 1, .frames = 180};
    if (strip_path && !other_output) {
        /* Only the strip: parse for --seed (and errors), without the default output. */
        rest[nrest++] = "--png";
        rest[nrest++] = "/dev/null";
    }
    example_parse(nrest, rest, &o, EX_SEED | EX_FRAMES, "fire_campfire", ABOUT);

    campfire cf;
    isk_canvas c;
    if (build(&cf.fx, o.seed, wind) != ISK_OK)
        return 1;
    if (isk_canvas_init(&c, W, H) != ISK_OK)
        return 1;
    int rc = 0;
    if (strip_path) {
        rc = strip(&cf, strip_path, &c);
        isk_effect_reset(cf.fx);
    }
    if (!rc && !(strip_path && !other_output)) {
        draw(&cf, &c);
        rc = example_animate(&c, &o, &cf, frame);
    }
    isk_canvas_free(&c);
    isk_effect_destroy(cf.fx);
    return rc;
}
