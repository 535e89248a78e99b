/* SPDX-License-Identifier: MIT */
/* The budgets: no accepted definition may ask for unbounded memory or work.
 * Memory (isk_effect_def.max_memory) counts the textures and the canvas
 * besides the pools; one file named two ways is decoded once; the work of
 * a frame and of a prewarm (isk_effect_def.max_work, `--max-work`) is
 * estimated at create and refused above the budget, naming what needs it. */
#include <criterion/criterion.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/anim.h"
#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "iskra/texture.h"
#include "play_session.h"
#include "tool_cli.h"

#define DIR "out/test_budgets"

/* A definition of 64 emitters drawing one 256 x 256 image, each cut into
 * another grid: 64 textures of the one image. */
static void many_grids(isk_effect_def *d)
{
    isk_effect_def_init(d);
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 256, 256), ISK_OK);
    isk_canvas_fill(&img, isk_rgba(255, 255, 255, 255));
    cr_assert_eq(isk_effect_def_add_texture(d, "spark.png", &img, NULL), ISK_OK);
    isk_canvas_free(&img);
    for (int i = 0; i < 64; i++) {
        char name[16];
        snprintf(name, sizeof name, "e%d", i);
        isk_emitter_def *e = isk_effect_def_add_emitter(d, name);
        e->born.source = ISK_SOURCE_PARTICLE;
        e->born.capacity = 1;
        snprintf(e->look.texture, sizeof e->look.texture, "spark.png");
        e->look.texture_grid.x = 1 << (i % 8);
        e->look.texture_grid.y = 1 << (i / 8);
    }
}

Test(budgets, textures_and_canvas_count_against_max_memory)
{
    isk_effect_def d;
    many_grids(&d);
    /* the sum of its parts: tables, pools, the image twice, 64 textures, the canvas */
    size_t textures = 0;
    for (int i = 0; i < 64; i++)
        textures += isk_texture_bytes(256, 256, 1 << (i % 8), 1 << (i / 8));
    cr_assert_gt(textures, (size_t)64 * 256 * 256 * 4, "each grid a texture of its own: %zu", textures);
    const size_t image = 2u * 256 * 256 * 4, canvas = 4u * 600 * 600;
    size_t pools = 0;
    for (int i = 0; i < 64; i++) {
        isk_effect_def one;
        isk_effect_def_init(&one);
        isk_emitter_def *e = isk_effect_def_add_emitter(&one, "p");
        e->born.source = ISK_SOURCE_PARTICLE;
        e->born.capacity = 1;
        pools += isk_effect_def_memory(&one) - (sizeof(isk_effect_def) + ((size_t)1 << 20)) - canvas;
        isk_effect_def_free(&one);
    }
    const size_t need = isk_effect_def_memory(&d);
    cr_assert_eq(need, sizeof(isk_effect_def) + ((size_t)1 << 20) + pools + image + textures + canvas, "%zu", need);
    /* a budget below it is refused at create, naming the largest parts */
    isk_effect *fx = NULL;
    isk_error err = {0};
    d.max_memory = need - 1;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    cr_assert_null(fx);
    cr_assert_not_null(strstr(err.message, "the texture spark.png cut "), "%s", err.message);
    cr_assert_not_null(strstr(err.message, "--max-memory"), "%s", err.message);
    d.max_memory = need;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    /* the canvas is counted: a bigger one needs its bytes more */
    d.width = 1200;
    cr_assert_eq(isk_effect_def_memory(&d), need + 4u * 600 * 600);
    /* a program's own needs (its encoders) too */
    d.host_memory = 12345;
    cr_assert_eq(isk_effect_def_memory(&d), need + 4u * 600 * 600 + 12345);
    isk_effect_def_free(&d);
}

Test(budgets, texture_bytes_are_the_made_textures)
{
    const int grids[][4] = {{64, 64, 1, 1}, {256, 128, 4, 2}, {4096, 4096, 256, 256}, {30, 7, 3, 7}};
    for (size_t i = 0; i < sizeof grids / sizeof grids[0]; i++) {
        isk_canvas img;
        cr_assert_eq(isk_canvas_init(&img, grids[i][0], grids[i][1]), ISK_OK);
        isk_texture t;
        cr_assert_eq(isk_texture_from_canvas(&t, &img, grids[i][2], grids[i][3]), ISK_OK);
        /* the texels, their slack, and the struct */
        cr_assert_gt(isk_texture_bytes(grids[i][0], grids[i][1], grids[i][2], grids[i][3]), t.bytes);
        cr_assert_leq(isk_texture_bytes(grids[i][0], grids[i][1], grids[i][2], grids[i][3]),
                      t.bytes + sizeof t + 64);
        isk_texture_free(&t);
        isk_canvas_free(&img);
    }
    cr_assert_eq(isk_texture_bytes(30, 7, 4, 7), 0u); /* 4 does not divide 30 */
    cr_assert_eq(isk_texture_bytes(0, 7, 1, 1), 0u);
    cr_assert_eq(isk_texture_bytes(4097, 7, 1, 1), 0u);
}

Test(budgets, one_file_named_two_ways_is_one_image)
{
    cli_fresh(DIR "/same");
    isk_canvas img;
    cr_assert_eq(isk_canvas_init(&img, 8, 8), ISK_OK);
    isk_canvas_fill(&img, isk_rgba(255, 128, 0, 255));
    cr_assert_eq(isk_png_write(&img, DIR "/same/x.png", NULL), ISK_OK);
    isk_canvas_free(&img);
    cli_write_file(DIR "/same/s.ini", "[emitter a]\nsource = particle\ntexture = ./x.png\n"
                                      "[emitter b]\nsource = particle\ntexture = x.png\ntexture_grid = 2, 2\n"
                                      "[emitter c]\nsource = particle\ntexture = ../same/x.png\n");
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_file(&d, DIR "/same/s.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.ntextures, 1, "one file, one decoded image: %d", d.ntextures);
    cr_assert_str_eq(d.emitters[1].look.texture, d.emitters[0].look.texture);
    cr_assert_str_eq(d.emitters[2].look.texture, d.emitters[0].look.texture);
    /* so the effect makes two textures (two grids), not three */
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* One emitter of `count` particles at rest, with trails `width` px wide. */
static void wide_trails(isk_effect_def *d, size_t count, double width)
{
    isk_effect_def_init(d);
    isk_emitter_def *e = isk_effect_def_add_emitter(d, "sparks");
    e->born.source = ISK_SOURCE_EXPLOSION;
    e->born.count = count;
    e->look.trail = 64;
    e->look.trail_width = width;
}

Test(budgets, a_frame_over_max_work_is_refused_at_create)
{
    isk_effect_def d;
    wide_trails(&d, 100, 4096); /* 100 x 64 segments x the whole 600 x 600 canvas: 2.3e9 */
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    cr_assert_null(fx);
    cr_assert_not_null(strstr(err.message, "emitter 'sparks': trails of 4096 px x 64 points x 100 particles = 2.3e+09 "
                                           "units of work a frame"),
                       "%s", err.message);
    cr_assert_not_null(strstr(err.message, "more than the budget of 1e+09 (--max-work, isk_effect_def.max_work)"),
                       "%s", err.message);
    /* a program may allow it */
    d.max_work = 3e9;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
    /* narrow trails of the same particles fit the default */
    wide_trails(&d, 100, 2);
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
    /* huge discs of a stream with immortal particles: its capacity of them */
    isk_effect_def_init(&d);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "blobs");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.rate = 10;
    e->look.draw = ISK_DRAW_DISC;
    e->look.size = 1000;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    cr_assert_not_null(strstr(err.message, "emitter 'blobs': 1e+05 particles x 3.6e+05 pixels (its discs)"), "%s",
                       err.message);
    e->life.seconds = 2; /* then at most 21 of them at once */
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

Test(budgets, a_prewarm_over_max_work_is_refused_at_create)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "stream");
    e->born.source = ISK_SOURCE_STREAM;
    e->born.rate = 1e6;
    e->life.seconds = 2;
    e->born.prewarm = 1666; /* 99,960 frames of up to 100,000 particles (its capacity) */
    e->look.draw = ISK_DRAW_NONE;
    isk_effect *fx = NULL;
    isk_error err = {0};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    cr_assert_null(fx);
    cr_assert_not_null(strstr(err.message, "emitter 'stream': a prewarm of 99960 frames x 1e+05 particles x 1 substeps"),
                       "%s", err.message);
    cr_assert_not_null(strstr(err.message, "units of work to prewarm"), "%s", err.message);
    e->born.prewarm = 1; /* 60 frames: within the default */
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

Test(budgets, max_work_option)
{
    cli_fresh(DIR "/mw");
    cli_write_file(DIR "/mw/wide.ini", "[emitter sparks]\nsource = explosion\ncount = 100\ntrail = 64\n"
                                       "trail_width = 4096\n");
    cr_assert_eq(cli_run(DIR "/mw", "describe " DIR "/mw/wide.ini"), 2);
    char *e = cli_slurp(DIR "/mw/stderr.txt");
    cr_assert_not_null(strstr(e, "wide.ini: emitter 'sparks': trails of 4096 px"), "%s", e);
    free(e);
    cr_assert_eq(cli_run(DIR "/mw", "describe " DIR "/mw/wide.ini --max-work 3e9"), 0);
    cr_assert_eq(cli_run(DIR "/mw", "describe " DIR "/mw/wide.ini --max-work=2.2e9"), 2);
    const char *bad[] = {"x", "0", "-1", "1e400", "nan", ""};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char a[200];
        snprintf(a, sizeof a, "describe fig09_stationary_particle --max-work=%s", bad[i]);
        cr_assert_eq(cli_run(DIR "/mw", a), 2, "%s", a);
        e = cli_slurp(DIR "/mw/stderr.txt");
        cr_assert_not_null(strstr(e, "--max-work"), "%s: %s", a, e);
        free(e);
    }
}

/* ---- what `iskra render` holds beside the effect -------------------------------- */

/* The writers' own memory: GIF's tables grow with the frame's pixels
 * (hash slots, colours, each pixel's colour and index, the sort's copy),
 * Y4M keeps a row, raw frames nothing; a PNG writer keeps rows. */
Test(budgets, writers_say_what_they_hold)
{
    isk_anim_opts gif = {ISK_ANIM_GIF, 1000, 1000, 30}, y4m = {ISK_ANIM_Y4M, 1000, 1000, 30},
                  raw = {ISK_ANIM_RAW, 1000, 1000, 0};
    /* per pixel: an index (1), its colour (4), a colour entry (12), its sorted copy (24 where a
     * 64-bit key is aligned to 8, 20 on i386, where it is aligned to 4), two hash slots (8) */
    cr_assert_geq(isk_anim_memory(&gif), (size_t)1000 * 1000 * (1 + 4 + 12 + 20 + 8));
    cr_assert_lt(isk_anim_memory(&gif), (size_t)1000 * 1000 * (1 + 4 + 12 + 24 + 16) + ((size_t)1 << 20));
    gif.width = 2000;
    cr_assert_gt(isk_anim_memory(&gif), (size_t)2000 * 1000 * 45);
    cr_assert_geq(isk_anim_memory(&y4m), 1000u);
    cr_assert_lt(isk_anim_memory(&y4m), 4096u);
    cr_assert_lt(isk_anim_memory(&raw), 1024u);
    raw.width = 0;
    cr_assert_eq(isk_anim_memory(&raw), 0u);
    cr_assert_eq(isk_anim_memory(NULL), 0u);
    cr_assert_gt(isk_png_write_memory(4000), isk_png_write_memory(1000) + 5 * 3000 * 4 - 1);
    cr_assert_eq(isk_png_write_memory(0), 0u);
}

/* A GIF or a strip too big for --max-memory is refused before anything is
 * written, exit 2, the message naming what needs the memory. */
Test(budgets, render_counts_its_writers_and_strip)
{
    cli_fresh(DIR "/host");
    /* 2000 x 2000 GIF frames: the writer's tables take about 190 MiB */
    cr_assert_eq(cli_run(DIR "/host", "render preset_rain --size 2000x2000 --frames 2 --out " DIR "/host/x.gif "
                                      "--max-memory 100M"), 2);
    char *e = cli_slurp(DIR "/host/stderr.txt");
    /* (188 MiB where size_t has 64 bits, 173 on i386: the tables' entries are smaller there) */
    cr_assert_not_null(strstr(e, "more than the limit of 100 MiB (iskra render's GIF writer (2000 x 2000 frames) "),
                       "%s", e);
    cr_assert_not_null(strstr(e, " MiB, the 2000 x 2000 canvas 15 MiB"), "%s", e);
    cr_assert_not_null(strstr(e, "--max-memory"), "%s", e);
    free(e);
    cr_assert_not(cli_exists(DIR "/host/x.gif"));
    /* six panels of 1000 x 1000: a 6020 x 1000 strip, 23 MiB */
    cr_assert_eq(cli_run(DIR "/host", "render preset_rain --size 2000x2000 --frames 12 --every 2 --strip "
                                      DIR "/host/s.png --max-memory 30M"), 2);
    e = cli_slurp(DIR "/host/stderr.txt");
    cr_assert_not_null(strstr(e, "iskra render's strip (6020 x 1000) 24 MiB"), "%s", e);
    free(e);
    cr_assert_not(cli_exists(DIR "/host/s.png"));
    /* within the limit it is written */
    cr_assert_eq(cli_run(DIR "/host", "render preset_rain --size 2000x2000 --frames 12 --every 2 --strip "
                                      DIR "/host/s.png --max-memory 48M"), 0);
    cr_assert(cli_exists(DIR "/host/s.png"));
    /* a strip wider than a canvas can be: a usage error, not "out of memory" */
    cr_assert_eq(cli_run(DIR "/host", "render preset_rain --size 4000x100 --frames 12 --every 1 --strip "
                                      DIR "/host/w.png"), 2);
    e = cli_slurp(DIR "/host/stderr.txt");
    cr_assert_not_null(strstr(e, "--strip: 12 panels of 2000 pixels would be wider than 16384 pixels"), "%s", e);
    free(e);
    cr_assert_not(cli_exists(DIR "/host/w.png"));
}

/* ---- a live change against the budgets --------------------------------------------- */

static const char *const LIVE_SCENE =
    "[scene]\nwidth = 200\nheight = 150\ndt = 1/60\nseed = 9\n"
    "[view]\nxmin = -10\nxmax = 10\nymin = 0\nymax = 15\n"
    "[force gravity]\ng = 9.81\n"
    "[emitter sparks]\nsource = stream\nposition = 0, 1\nlaunch = cone\nangle = 90\nspread = 40\n"
    "speed_min = 5\nspeed_max = 9\nrate = 300\nlife = 2\ncapacity = 4000\nforces = gravity\ndraw = disc\n"
    "size = 0.1\n";

static isk_effect *live_effect(double max_work, size_t max_memory)
{
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, LIVE_SCENE, "live.ini", &err), ISK_OK, "%s", err.message);
    d.max_work = max_work;
    d.max_memory = max_memory;
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    return fx;
}

/* Frames 0..frames of fx into one buffer (the canvas after each step). */
static void run_frames(isk_effect *fx, int frames, uint8_t *out)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 200, 150), ISK_OK);
    for (int f = 0; f < frames; f++) {
        cr_assert_eq(isk_effect_step_render(fx, &c), ISK_OK);
        memcpy(out + (size_t)f * 200 * 150 * 4, c.pixels, (size_t)200 * 150 * 4);
    }
    isk_canvas_free(&c);
}

/* A change that would take the effect over its work budget (the estimate
 * of create: here the discs' pixels, or the particles a longer life keeps)
 * or its memory budget (a bigger pool) is refused with create's message
 * and changes nothing: the frames after it are those of a twin never
 * asked; a change within the budgets is taken. */
Test(budgets, a_live_change_over_a_budget_changes_nothing)
{
    enum { FRAMES = 40 };
    const size_t bytes = (size_t)FRAMES * 200 * 150 * 4;
    uint8_t *want = malloc(bytes), *got = malloc(bytes);
    cr_assert(want && got);
    isk_effect *twin = live_effect(1e5, (size_t)64 << 20);
    run_frames(twin, 10, want);
    isk_effect *fx = live_effect(1e5, (size_t)64 << 20);
    run_frames(fx, 10, got);
    static const char *const refused[][3] = {
        {"emitter sparks", "size", "2"},           /* 601 discs of 22 x 22 px: 3e5 pixels */
        {"emitter sparks", "life", "60"},          /* 4000 particles alive */
        {"emitter sparks", "rate", "3000"},        /* 4000 too */
        {"emitter sparks", "trail", "64"},         /* 64 segments each */
        {"scene", "substeps", "50"},
        {"view", "xmax", "-9.9"},                  /* zoomed in: each disc 25 times wider */
        {"emitter sparks", "capacity", "3000000"}, /* its pool: 64 MiB and more */
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        char before[64], after[64];
        isk_error err = {0};
        cr_assert_eq(isk_effect_get(fx, refused[i][0], refused[i][1], before, sizeof before, &err), ISK_OK);
        cr_assert_eq(isk_effect_set(fx, refused[i][0], refused[i][1], refused[i][2], &err), ISK_ERR_SIZE,
                     "[%s] %s = %s: taken", refused[i][0], refused[i][1], refused[i][2]);
        const char *budget = strcmp(refused[i][1], "capacity") ? "--max-work" : "--max-memory";
        cr_assert_not_null(strstr(err.message, budget), "[%s] %s: %s", refused[i][0], refused[i][1], err.message);
        cr_assert_not_null(strstr(err.message, refused[i][1]), "%s", err.message);
        cr_assert_eq(isk_effect_get(fx, refused[i][0], refused[i][1], after, sizeof after, &err), ISK_OK);
        cr_assert_str_eq(after, before);
    }
    run_frames(twin, FRAMES, want);
    run_frames(fx, FRAMES, got);
    cr_assert(!memcmp(want, got, bytes), "a refused change changed the frames after it");
    /* within the budget: taken, and the frames change */
    isk_error err = {0};
    cr_assert_eq(isk_effect_set(fx, "emitter sparks", "size", "0.3", &err), ISK_OK, "%s", err.message);
    run_frames(fx, 2, got);
    run_frames(twin, 2, want);
    cr_assert(memcmp(want, got, (size_t)2 * 200 * 150 * 4));
    isk_effect_destroy(fx);
    isk_effect_destroy(twin);
    free(want);
    free(got);
}

/* Each potential adds to every particle-step's cost: the one that would
 * take a frame over --max-work is refused with create's message and
 * changes nothing (not the forces, not isk_effect_edits, not the frames
 * after it: those of a twin given only the accepted ones). */
Test(budgets, a_potential_added_over_the_work_budget_changes_nothing)
{
    enum { FRAMES = 20 };
    const size_t bytes = (size_t)FRAMES * 200 * 150 * 4;
    uint8_t *want = malloc(bytes), *got = malloc(bytes);
    cr_assert(want && got);
    isk_effect *fx = live_effect(1e5, (size_t)64 << 20);
    isk_effect *twin = live_effect(1e5, (size_t)64 << 20);
    run_frames(fx, 5, got);
    run_frames(twin, 5, want);
    isk_potential pot;
    isk_potential_init(&pot, 2.0, (isk_vec2){1.0, 5.0}, 1.0);
    isk_error err = {0};
    int taken = 0;
    isk_status s = ISK_OK;
    char name[16];
    for (; taken < ISK_EFFECT_MAX_FORCES; taken++) {
        snprintf(name, sizeof name, "p%d", taken);
        const unsigned long edits = isk_effect_edits(fx);
        if ((s = isk_effect_add_potential(fx, name, &pot, &err)) != ISK_OK) {
            cr_assert_eq(isk_effect_edits(fx), edits, "a refused potential counts as an edit");
            break;
        }
        cr_assert_eq(isk_effect_add_potential(twin, name, &pot, &err), ISK_OK, "%s", err.message);
    }
    cr_assert_eq(s, ISK_ERR_SIZE, "no potential was refused (%d taken)", taken);
    cr_assert_gt(taken, 0);
    cr_assert_not_null(strstr(err.message, "--max-work"), "%s", err.message);
    cr_assert_not_null(strstr(err.message, name), "%s", err.message);
    size_t n = 0;
    isk_effect_potentials(fx, &n);
    cr_assert_eq(n, (size_t)taken);
    cr_assert_lt(isk_effect_def_find_force(isk_effect_definition(fx), name), 0, "%s stayed", name);
    run_frames(fx, FRAMES, got);
    run_frames(twin, FRAMES, want);
    cr_assert(!memcmp(want, got, bytes), "a refused potential changed the frames after it");
    /* one taken out makes room again */
    cr_assert_eq(isk_effect_remove_force(fx, "p0", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_add_potential(fx, name, &pot, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    isk_effect_destroy(twin);
    free(want);
    free(got);
}

/* The simulator's panel goes through isk_effect_set: a size typed into
 * the inspector that would take a frame over --max-work is refused (the
 * saved scene keeps the old one), one within it is taken. */
Test(budgets, the_panel_refuses_a_change_over_the_work_budget)
{
    static const struct {
        const char *typed, *saved;
    } cases[] = {{"100", "0.09"}, {"0.2", "0.2"}};
    for (int i = 0; i < 2; i++) {
        char dir[64], args[600];
        snprintf(dir, sizeof dir, DIR "/panel%d", i);
        snprintf(args, sizeof args,
                 "fire_campfire --max-work 1e7 --screen 1280x720 --frames 12 --save %s/s.ini --script "
                 "'press:emitter-sparks/size wait:2 type:%s key:return wait:2 f2'",
                 dir, cases[i].typed);
        cr_assert_eq(play_session(dir, args), 0, "%s", play_stderr(dir));
        char path[96];
        snprintf(path, sizeof path, "%s/s.ini", dir);
        isk_effect_def d;
        isk_error err = {0};
        cr_assert_eq(isk_scene_load_file(&d, path, &err), ISK_OK, "%s", err.message);
        const int k = isk_effect_def_find_emitter(&d, "sparks");
        cr_assert_geq(k, 0);
        char want[32];
        snprintf(want, sizeof want, "%.15g", d.emitters[k].look.size);
        cr_assert_str_eq(want, cases[i].saved, "typed %s", cases[i].typed);
        isk_effect_def_free(&d);
    }
}
