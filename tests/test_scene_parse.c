/* SPDX-License-Identifier: MIT */
/* Scene files: value syntax, every section and key into the definition,
 * errors as exact FILE:LINE messages with did-you-mean, bounds. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/scene.h"
#include "scene/ini_read.h"
#include "scene/scene_values.h"

/* ---- helpers ---------------------------------------------------------------- */

static isk_effect_def load_ok(const char *text)
{
    isk_effect_def d;
    isk_error err = {0};
    isk_status s = isk_scene_load_string(&d, text, "t.ini", &err);
    cr_assert_eq(s, ISK_OK, "unexpected error: %s", err.message);
    return d;
}

/* The scene must fail with exactly `msg`; the definition is left empty. */
static void load_fails(const char *text, const char *msg)
{
    isk_effect_def d;
    isk_error err = {0};
    isk_status s = isk_scene_load_string(&d, text, "t.ini", &err);
    cr_assert_neq(s, ISK_OK, "accepted a bad scene, expected: %s", msg);
    cr_assert_str_eq(err.message, msg);
    cr_assert_eq(d.nemitters, 0);
    cr_assert_eq(d.nforces, 0);
    cr_assert_null(d.emitters);
    isk_effect_def_free(&d);
}

/* ---- values --------------------------------------------------------------------- */

Test(scene_values, numbers)
{
    double v;
    cr_assert(isk__scv_number("1", &v) && v == 1);
    cr_assert(isk__scv_number("-2.5", &v) && v == -2.5);
    cr_assert(isk__scv_number("+.5", &v) && v == 0.5);
    cr_assert(isk__scv_number("5.", &v) && v == 5);
    cr_assert(isk__scv_number("1e3", &v) && v == 1000);
    cr_assert(isk__scv_number("1.25E-2", &v) && v == 0.0125);
    cr_assert(isk__scv_number("1/60", &v) && v == 1.0 / 60.0);
    cr_assert(isk__scv_number("1 / 4", &v) && v == 0.25);
    const char *bad[] = {"", " ", "nan", "NaN", "inf", "-inf", "infinity", "1e", "0x10", "1.2.3", "1,5",
                         "fast", "1 2", "1/0", "1/", "/2", "1e400", "--1", "1/2/3", "."};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_assert_not(isk__scv_number(bad[i], &v), "accepted \"%s\"", bad[i]);
}

Test(scene_values, integers_and_seed)
{
    uint64_t u;
    cr_assert(isk__scv_u64("0", &u) && u == 0);
    cr_assert(isk__scv_u64("18446744073709551615", &u) && u == UINT64_MAX);
    cr_assert_not(isk__scv_u64("18446744073709551616", &u));
    cr_assert_not(isk__scv_u64("-1", &u));
    cr_assert_not(isk__scv_u64("1.0", &u));
    cr_assert_not(isk__scv_u64("", &u));
}

Test(scene_values, booleans)
{
    int b;
    const char *t[] = {"true", "yes", "on", "1", "TRUE", "Yes"};
    const char *f[] = {"false", "no", "off", "0", "False"};
    for (int i = 0; i < 6; i++)
        cr_assert(isk__scv_bool(t[i], &b) && b == 1, "%s", t[i]);
    for (int i = 0; i < 5; i++)
        cr_assert(isk__scv_bool(f[i], &b) && b == 0, "%s", f[i]);
    cr_assert_not(isk__scv_bool("maybe", &b));
    cr_assert_not(isk__scv_bool("", &b));
}

Test(scene_values, colours)
{
    isk_color c;
    cr_assert(isk__scv_color("#ff8000", &c) && c.r == 255 && c.g == 128 && c.b == 0 && c.a == 255);
    cr_assert(isk__scv_color("#FF800040", &c) && c.a == 0x40);
    cr_assert(isk__scv_color("green", &c) && c.r == 0 && c.g == 128 && c.b == 0 && c.a == 255);
    cr_assert(isk__scv_color("Yellow", &c) && c.r == 255 && c.g == 255 && c.b == 0);
    cr_assert(isk__scv_color("orange", &c) && c.r == 255 && c.g == 165 && c.b == 0);
    cr_assert(isk__scv_color("transparent", &c) && c.a == 0);
    const char *bad[] = {"#fff", "#ff80", "#gg0000", "#ff00001", "yelow", "", "#"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        cr_assert_not(isk__scv_color(bad[i], &c), "accepted \"%s\"", bad[i]);
    /* every listed name parses */
    for (int i = 0; i < isk__scv_color_count; i++)
        cr_assert(isk__scv_color(isk__scv_color_name_at(i), &c), "%s", isk__scv_color_name_at(i));
}

Test(scene_values, lists)
{
    char buf[64], *items[8];
    int n;
    cr_assert(isk__scv_split(" a , b,c ", buf, sizeof buf, ',', items, 8, &n) && n == 3);
    cr_assert_str_eq(items[0], "a");
    cr_assert_str_eq(items[2], "c");
    cr_assert(isk__scv_split("  ", buf, sizeof buf, ',', items, 8, &n) && n == 0);
    cr_assert_not(isk__scv_split("a,,b", buf, sizeof buf, ',', items, 8, &n));
    cr_assert_not(isk__scv_split("a,", buf, sizeof buf, ',', items, 8, &n));
    cr_assert_not(isk__scv_split("1,2,3", buf, sizeof buf, ',', items, 2, &n));
}

/* ---- round trip: every section and key ----------------------------------------- */

Test(scene_parse, scene_and_view_keys)
{
    isk_effect_def d = load_ok("[scene]\n"
                               "width = 800\nheight = 400\nbackground = #102030\nclear = no\n"
                               "dt = 1/50\nsubsteps = 4\nintegrator = rk4\nseed = 12345678901234\n"
                               "speed_divisor = 2\ncentre = thesis\nframes = 77\n"
                               "[view]\nxmin = -5\nxmax = 15\nymin = 0\nymax = 10\n");
    cr_assert_eq(d.width, 800);
    cr_assert_eq(d.height, 400);
    cr_assert_eq(d.background.r, 0x10);
    cr_assert_eq(d.background.b, 0x30);
    cr_assert_eq(d.clear, 0);
    cr_assert_eq(d.dt, 1.0 / 50.0);
    cr_assert_eq(d.substeps, 4);
    cr_assert_eq(d.integrator, ISK_INTEGRATE_RK4);
    cr_assert_eq(d.seed, 12345678901234ull);
    cr_assert_eq(d.speed_divisor, 2);
    cr_assert_eq(d.centre, ISK_FIDELITY_THESIS);
    cr_assert_eq(d.show.frames, 77);
    cr_assert_eq(d.view_kind, ISK_VIEWDEF_WINDOW);
    cr_assert_eq(d.xmin, -5);
    cr_assert_eq(d.xmax, 15);
    cr_assert_eq(d.ymin, 0);
    cr_assert_eq(d.ymax, 10);
    isk_effect_def_free(&d);

    d = load_ok("[view]\nzoom = 8\npan = 1.5, -2\n");
    cr_assert_eq(d.view_kind, ISK_VIEWDEF_CAMERA);
    cr_assert_eq(d.zoom, 8);
    cr_assert_eq(d.tx, 1.5);
    cr_assert_eq(d.ty, -2);
    isk_effect_def_free(&d);
}

Test(scene_parse, defaults_without_sections)
{
    isk_effect_def d = load_ok("; nothing but a comment\n");
    isk_effect_def ref;
    isk_effect_def_init(&ref);
    cr_assert_eq(d.width, ref.width);
    cr_assert_eq(d.dt, ref.dt);
    cr_assert_eq(d.bounds.sides, 0u);
    cr_assert_eq(d.click.enabled, 0);
    isk_effect_def_free(&d);
}

Test(scene_parse, forces_all_kinds_and_potential_attributes)
{
    isk_effect_def d = load_ok("[force gravity]\ng = 9.81\n"
                               "[force air]\nkind = drag\nb = 0.47\n"
                               "[force breeze]\nkind = wind\nacceleration = 1.5, 0\n"
                               "[force A]\nkind = potential\nk = 800\ncharge = -1\nposition = 5, 5\n"
                               "exponent = 2\nlaw = text\nmin_distance = 0.5\nmax_distance = off\n"
                               "x_multiplier = 0.3\nenabled = false\nvelocity = 0, 20\ndraw = no\n");
    cr_assert_eq(d.nforces, 4);
    cr_assert_eq(d.forces[0].kind, ISK_FORCE_GRAVITY);
    cr_assert_eq(d.forces[0].g, 9.81);
    cr_assert_eq(d.forces[1].kind, ISK_FORCE_DRAG);
    cr_assert_eq(d.forces[1].b, 0.47);
    cr_assert_eq(d.forces[2].kind, ISK_FORCE_WIND);
    cr_assert_eq(d.forces[2].accel.x, 1.5);
    const isk_force_def *f = &d.forces[3];
    cr_assert_str_eq(f->name, "A");
    cr_assert_eq(f->kind, ISK_FORCE_POTENTIAL);
    cr_assert_eq(f->pot.k, 800);
    cr_assert_eq(f->pot.charge, -1);
    cr_assert_eq(f->pot.r.x, 5);
    cr_assert_eq(f->pot.P, 4, "law = text: P = p + 2");
    cr_assert_eq(f->pot.min_dist, 0.5);
    cr_assert_eq(f->pot.max_dist, ISK_DIST_OFF);
    cr_assert_eq(f->pot.x_mult, 0.3);
    cr_assert_eq(f->pot.enabled, 0);
    cr_assert_eq(f->pot.vel.y, 20);
    cr_assert_eq(f->draw, 0);
    cr_assert_eq(f->line, 9);
    isk_effect_def_free(&d);
}

Test(scene_parse, deflectors_bounds_click_drawings)
{
    isk_effect_def d = load_ok("[deflector floor]\nsegment = -1, 0, 1, 0\nrestitution = 0.5\nprobability = 0.25\n"
                               "reaction = stick\nrestitution_mode = normal\n"
                               "[bounds]\nmode = reflect\nsides = bottom, left\nmargin = 0.2\nrestitution = 0.7\n"
                               "window = 0, 10, 0, 5\n"
                               "[emitter e]\n"
                               "[click]\nexplosion = ring\ncount = 50\nemitter = e\nat_start = 1, 2\n"
                               "[drawing label]\nkind = text\nunits = pixels\nposition = 10, 20\ntext = hello, world\n"
                               "scale = 2\ncolor = red\nblend = add\n"
                               "[drawing path]\npoints = 0,0, 1,1, 2,0\nclosed = yes\n"
                               "[drawing disc]\nposition = 1, 1\nradius = 0.5\n");
    cr_assert_eq(d.ndeflectors, 1);
    cr_assert_str_eq(d.deflectors[0].name, "floor");
    cr_assert_eq(d.deflectors[0].seg.x0, -1);
    cr_assert_eq(d.deflectors[0].seg.x1, 1);
    cr_assert_eq(d.deflectors[0].seg.restitution, 0.5);
    cr_assert_eq(d.deflectors[0].seg.probability, 0.25);
    cr_assert_eq(d.deflectors[0].seg.reaction, ISK_DEFLECT_STICK);
    cr_assert_eq(d.deflectors[0].seg.mode, ISK_RESTITUTION_NORMAL);
    cr_assert_eq(d.bounds.mode, ISK_BOUNCE_REFLECT);
    cr_assert_eq(d.bounds.sides, (unsigned)(ISK_SIDE_BOTTOM | ISK_SIDE_LEFT));
    cr_assert_eq(d.bounds.margin, 0.2);
    cr_assert_eq(d.bounds.restitution, 0.7);
    cr_assert_eq(d.bounds.xmax, 10);
    cr_assert_eq(d.bounds.ymax, 5);
    cr_assert_eq(d.click.enabled, 1);
    cr_assert_eq(d.click.explosion, ISK_EXPLOSION_RING);
    cr_assert_eq(d.click.count, 50);
    cr_assert_eq(d.click.emitter, 0);
    cr_assert_eq(d.click.at_start, 1);
    cr_assert_eq(d.click.y, 2);
    cr_assert_eq(d.ndrawings, 3);
    cr_assert_eq(d.drawings[0].kind, ISK_DRAWING_TEXT);
    cr_assert_eq(d.drawings[0].pixels, 1);
    cr_assert_str_eq(d.drawings[0].text, "hello, world");
    cr_assert_eq(d.drawings[0].scale, 2);
    cr_assert_eq(d.drawings[0].blend, ISK_BLEND_ADD);
    cr_assert_eq(d.drawings[1].kind, ISK_DRAWING_POLYLINE, "kind from the keys: points");
    cr_assert_eq(d.drawings[1].npoints, 3);
    cr_assert_eq(d.drawings[1].points[4], 2);
    cr_assert_eq(d.drawings[1].closed, 1);
    cr_assert_eq(d.drawings[2].kind, ISK_DRAWING_DISC, "kind taken from the name 'disc'");
    cr_assert_eq(d.drawings[2].r, 0.5);
    isk_effect_def_free(&d);
}

Test(scene_parse, bounds_defaults_follow_the_view_and_mode)
{
    isk_effect_def d = load_ok("[view]\nxmin = 0\nxmax = 10\nymin = 0\nymax = 10\n[bounds]\nmode = thesis\n");
    cr_assert_eq(d.bounds.sides, (unsigned)ISK_SIDE_ALL);
    cr_assert_eq(d.bounds.margin, 0.1);
    cr_assert_eq(d.bounds.xmin, 0);
    cr_assert_eq(d.bounds.xmax, 10);
    isk_effect_def_free(&d);
    d = load_ok("[bounds]\nsides = none\n");
    cr_assert_eq(d.bounds.sides, 0u);
    cr_assert_eq(d.bounds.margin, 0.0);
    isk_effect_def_free(&d);
}

Test(scene_parse, emitter_every_key)
{
    isk_effect_def d = load_ok("[force g]\nkind = gravity\ng = 1\n[force w]\nkind = wind\nacceleration = 1, 0\n"
                               "[deflector a]\nsegment = 0,0,1,0\n[deflector b]\nsegment = 0,1,1,1\n"
                               "[emitter smoke]\n"
                               "source = stream\nposition = 1, 2\nvelocity = 0, 1\nmass = 2\nmass_range = 0.5\n"
                               "count = 30\nstart = 0.5\nshape = ring\nshape_a = 0.5\nshape_b = 1\n"
                               "shape_angle = 90\nshape_faithful = yes\nlaunch = cone\nangle = 45\nspread = 30\n"
                               "speed_min = 1\nspeed_max = 2\nrate = 100\nrate_mode = thesis\nbirth = thesis-jitter\n"
                               "burst_every = 2\nlife = 3\nlife_range = 0.5\ncapacity = 5000\nforces = w, g\n"
                               "deflectors = all\nbounded = false\ndraw_before_bounce = true\n"
                               "gravity_multiplier = -0.5\nweight = 2\nslowing = 0.1\nosc_omega = 1, 2\n"
                               "osc_amplitude = 0.1, 0.2\nosc_decay = 0.3\nosc_faithful = on\nosc_table = libm\n"
                               "integrator = verlet\nsubsteps = 3\ndraw = sprite\nsprite = smooth\nsize = 0.4\n"
                               "color = #ff800080\nblend = add\n"
                               "color_over_life = 0:white, 0.5:#ff8000, 1:#00000000\n"
                               "alpha_over_life = 0:1, 1:0\nsize_over_life = 0:1, 0.25:2, 1:0.5\norder = -3\n"
                               "[emitter boom]\nsource = explosion\nexplosion = multi-coulomb\ncount = 20000\n"
                               "limit = 20000\nkick = new\nposition = 0, -3\n"
                               "[emitter layer]\nsource = layer\nrect = 0, 10, 0, 2\ncount = 100\n");
    cr_assert_eq(d.nemitters, 3);
    const isk_emitter_def *e = &d.emitters[0];
    const double deg = 3.14159265358979323846 / 180.0;
    cr_assert_str_eq(e->name, "smoke");
    cr_assert_eq(e->line, 11);
    cr_assert_eq(e->born.source, ISK_SOURCE_STREAM);
    cr_assert_eq(e->born.position.y, 2);
    cr_assert_eq(e->launch.velocity.y, 1);
    cr_assert_eq(e->launch.mass, 2);
    cr_assert_eq(e->launch.mass_range, 0.5);
    cr_assert_eq(e->born.count, 30);
    cr_assert_eq(e->born.start, 0.5);
    cr_assert_eq(e->born.shape, ISK_SHAPE_RING);
    cr_assert_eq(e->born.shape_a, 0.5);
    cr_assert_eq(e->born.shape_b, 1);
    cr_assert_eq(e->born.shape_angle, 90 * deg);
    cr_assert_eq(e->born.shape_faithful, 1);
    cr_assert_eq(e->launch.kind, ISK_VELGEN_CONE);
    cr_assert_eq(e->launch.angle, 45 * deg);
    cr_assert_eq(e->launch.spread, 30 * deg);
    cr_assert_eq(e->launch.speed_min, 1);
    cr_assert_eq(e->launch.speed_max, 2);
    cr_assert_eq(e->born.rate, 100);
    cr_assert_eq(e->born.rate_mode, ISK_RATE_THESIS);
    cr_assert_eq(e->born.birth, ISK_BIRTH_THESIS_JITTER);
    cr_assert_eq(e->born.burst_every, 2);
    cr_assert_eq(e->life.seconds, 3);
    cr_assert_eq(e->life.range, 0.5);
    cr_assert_eq(e->born.capacity, 5000);
    cr_assert_eq(e->motion.nforces, 2);
    cr_assert_eq(e->motion.forces[0], 1, "listed order: w first");
    cr_assert_eq(e->motion.forces[1], 0);
    cr_assert_eq(e->motion.ndeflectors, 2);
    cr_assert_eq(e->motion.bounded, 0);
    cr_assert_eq(e->motion.draw_before_bounce, 1);
    cr_assert_eq(e->motion.gravity_multiplier, -0.5);
    cr_assert_eq(e->motion.weight, 2);
    cr_assert_eq(e->motion.slowing, 0.1);
    cr_assert_eq(e->motion.osc_omega_min, 1);
    cr_assert_eq(e->motion.osc_omega_max, 2);
    cr_assert_eq(e->motion.osc_amplitude_min, 0.1);
    cr_assert_eq(e->motion.osc_amplitude_max, 0.2);
    cr_assert_eq(e->motion.osc_decay, 0.3);
    cr_assert_eq(e->motion.osc_faithful, 1);
    cr_assert_eq(e->motion.osc_table, ISK_SINLUT_LIBM);
    cr_assert_eq(e->motion.integrator, ISK_INTEGRATE_VERLET);
    cr_assert_eq(e->motion.substeps, 3);
    cr_assert_eq(e->look.draw, ISK_DRAW_SPRITE);
    cr_assert_eq(e->look.sprite, ISK_SPRITE_SMOOTH);
    cr_assert_eq(e->look.size, 0.4);
    cr_assert_eq(e->look.color.a, 0x80);
    cr_assert_eq(e->look.blend, ISK_BLEND_ADD);
    cr_assert_eq(e->look.color_over_life.n, 3);
    cr_assert_eq(e->look.color_over_life.stops[1].t, 0.5);
    cr_assert_eq(e->look.color_over_life.stops[1].color.g, 0x80);
    cr_assert_eq(e->look.color_over_life.stops[2].color.a, 0);
    cr_assert_eq(e->look.alpha_over_life.n, 2);
    cr_assert_eq(e->look.alpha_over_life.stops[1].value, 0);
    cr_assert_eq(e->look.size_over_life.n, 3);
    cr_assert_eq(e->look.size_over_life.stops[1].value, 2);
    cr_assert_eq(e->look.order, -3);
    e = &d.emitters[1];
    cr_assert_eq(e->born.source, ISK_SOURCE_EXPLOSION);
    cr_assert_eq(e->born.explosion, ISK_EXPLOSION_MULTI_COULOMB);
    cr_assert_eq(e->born.count, 20000);
    cr_assert_eq(e->born.limit, 20000);
    cr_assert_eq(e->born.kick, ISK_KICK_NEW);
    cr_assert_eq(e->motion.bounded, 1, "default: the walls apply");
    e = &d.emitters[2];
    cr_assert_eq(e->born.source, ISK_SOURCE_LAYER);
    cr_assert_eq(e->born.rect[1], 10);
    cr_assert_eq(e->born.count, 100);
    isk_effect_def_free(&d);
}

Test(scene_parse, layout_freedom)
{
    /* indented keys, ':' separators, inline comments, CRLF, forward references,
     * life = forever, a BOM */
    isk_effect_def d = load_ok("\xEF\xBB\xBF[emitter e]\r\n"
                               "    forces = later   ; defined below\r\n"
                               "\tlife: forever\r\n"
                               "  color = #ff0000 ; red\r\n"
                               "[force later]\r\nkind=drag\r\nb=1\r\n");
    cr_assert_eq(d.emitters[0].motion.nforces, 1);
    cr_assert_eq(d.emitters[0].motion.forces[0], 0);
    cr_assert(isinf(d.emitters[0].life.seconds));
    cr_assert_eq(d.emitters[0].look.color.r, 255);
    cr_assert_eq(d.forces[0].b, 1);
    isk_effect_def_free(&d);
}

/* ---- errors ------------------------------------------------------------------------ */

Test(scene_errors, numbers_and_ranges)
{
    load_fails("[emitter smoke]\nsource = stream\nrate = fast\n",
               "t.ini:3: [emitter smoke] rate: expected a number between 0 and 1e7, got \"fast\"");
    load_fails("[scene]\ndt = nan\n", "t.ini:2: [scene] dt: expected a number > 0 and <= 1000, got \"nan\"");
    load_fails("[scene]\ndt = inf\n", "t.ini:2: [scene] dt: expected a number > 0 and <= 1000, got \"inf\"");
    load_fails("[scene]\ndt = 0\n", "t.ini:2: [scene] dt: expected a number > 0 and <= 1000, got \"0\"");
    load_fails("[scene]\nwidth = 2.5\n", "t.ini:2: [scene] width: expected a whole number between 1 and 16384, got \"2.5\"");
    load_fails("[scene]\nwidth = 100000\n",
               "t.ini:2: [scene] width: expected a whole number between 1 and 16384, got \"100000\"");
    load_fails("[force drag]\nb = -1\n", "t.ini:2: [force drag] b: expected a number between 0 and 1e12, got \"-1\"");
    load_fails("[emitter p]\nposition = 1\n", "t.ini:2: [emitter p] position: expected 2 numbers \"x, y\", got \"1\"");
    load_fails("[emitter p]\nposition = 1, x\n",
               "t.ini:2: [emitter p] position: expected 2 numbers \"x, y\": item 2 is not a number between -1e150 and 1e150: \"x\"");
    load_fails("[emitter p]\nsource = explosion\ncount = 0\n",
               "t.ini:3: [emitter p] count: must be 1..10000 (raise limit for more)");
    load_fails("[emitter p]\nsource = stream\ncount = 268435457\n",
               "t.ini:3: [emitter p] count: expected a whole number between 0 and 268435456, got \"268435457\"");
    load_fails("[scene]\nseed = -1\n",
               "t.ini:2: [scene] seed: expected a whole number between 0 and 18446744073709551615, got \"-1\"");
    load_fails("[emitter p]\nosc_omega = 2, 1\n", "t.ini:2: [emitter p] osc_omega: min (2) is greater than max (1)");
    load_fails("[emitter p]\nalpha_over_life = 0:1, 0:0\n",
               "t.ini:2: [emitter p] alpha_over_life: stop 2: positions must increase (0 after 0)");
    load_fails("[emitter p]\nalpha_over_life = 0:2\n",
               "t.ini:2: [emitter p] alpha_over_life: stop 1: expected a number between 0 and 1, got \"2\"");
    load_fails("[emitter p]\nlife = 0\n", "t.ini:2: [emitter p] life: expected a number of seconds > 0 or forever, got \"0\"");
    load_fails("[deflector d]\nsegment = 1, 1, 1, 1\n",
               "t.ini:2: [deflector d] segment: the two end points are the same (a segment needs a length)");
}

Test(scene_errors, enums_colours_booleans_with_did_you_mean)
{
    load_fails("[emitter sparks]\nsource = explosion\nexplosion = gaus\n",
               "t.ini:3: [emitter sparks] explosion: expected ring, uniform, gauss, coulomb or multi-coulomb, got "
               "\"gaus\"; did you mean \"gauss\"?");
    load_fails("[scene]\nbackground = yelow\n",
               "t.ini:2: [scene] background: expected a colour (#rrggbb, #rrggbbaa or a name such as yellow), got "
               "\"yelow\"; did you mean \"yellow\"?");
    load_fails("[scene]\nclear = maybe\n",
               "t.ini:2: [scene] clear: expected true or false (also yes/no, on/off, 1/0), got \"maybe\"");
    load_fails("[bounds]\nsides = bottm\n",
               "t.ini:2: [bounds] sides: expected top, right, bottom or left (or all, none), got \"bottm\"; did you "
               "mean \"bottom\"?");
}

Test(scene_errors, unknown_sections_and_keys)
{
    load_fails("[scene]\nwidth = 400\n\n[emiter sparks]\n",
               "t.ini:4: unknown section [emiter sparks]; did you mean [emitter sparks]?");
    load_fails("[physics]\n", "t.ini:1: unknown section [physics]; sections are [scene], [view], [force NAME], "
                              "[deflector NAME], [bounds], [emitter NAME], [drawing NAME], [click] and [probe NAME]");
    load_fails("[scene]\ndt = 1/60\n\n[emitter smoke]\nsource = stream\nrat = 20\n",
               "t.ini:6: [emitter smoke] unknown key 'rat'; did you mean 'rate'?");
    load_fails("[scene]\nxmin = 0\n", "t.ini:2: [scene] unknown key 'xmin' (it belongs in a [view] section)");
    load_fails("[scene]\nfoo = 1\n",
               "t.ini:2: [scene] unknown key 'foo' (see docs/scene-format.md for the keys of [scene])");
    load_fails("width = 3\n",
               "t.ini:1: 'width = 3' is outside any section (start the file with a section such as [scene])");
    load_fails("[emitter]\n", "t.ini:1: section [emitter] needs a name: [emitter NAME]");
    load_fails("[scene main]\n", "t.ini:1: section [scene] takes no name (got [scene main])");
    load_fails("[emitter a b]\n", "t.ini:1: bad name 'a b' in [emitter a b]: use letters, digits, '_', '-' or '.' "
                                  "(at most 31 characters)");
    load_fails("[force all]\n", "t.ini:1: 'all' is reserved and cannot name a [force]");
}

Test(scene_errors, syntax)
{
    load_fails("[scene]\nwidth 600\n",
               "t.ini:2: cannot parse this line: expected [section], key = value, or a ; comment");
    load_fails("[scene\n", "t.ini:1: section header without ']'");
    load_fails("[scene] x\n", "t.ini:1: unexpected text after ']' (a comment starts with ';')");
    load_fails("[scene]\n= 5\n", "t.ini:2: missing key name before '='");
    /* errors come in file order: the bad key on line 2 before the syntax error on line 3 */
    load_fails("[scene]\nwidht = 5\n???\n", "t.ini:2: [scene] unknown key 'widht'; did you mean 'width'?");
    /* a bad header above a syntax error is reported first */
    load_fails("[scen]\n???\n", "t.ini:1: unknown section [scen]; did you mean [scene]?");
}

Test(scene_errors, duplicates)
{
    load_fails("[scene]\nwidth = 600\nheight = 400\nwidth = 800\n", "t.ini:4: [scene] width: given twice (first at line 2)");
    load_fails("[emitter a]\n[emitter b]\n[emitter a]\n", "t.ini:3: duplicate section [emitter a] (first defined at line 1)");
    load_fails("[scene]\n[view]\n[scene]\n", "t.ini:3: duplicate section [scene] (first defined at line 1)");
    load_fails("[emitter e]\nforces = g, g\n[force g]\n", "t.ini:2: [emitter e] forces: 'g' is listed twice");
}

Test(scene_errors, references)
{
    load_fails("[force gravity]\ng = 9.81\n\n[emitter sparks]\nsource = explosion\nexplosion = gauss\nforces = gravty, drag\n",
               "t.ini:7: [emitter sparks] forces: no force named 'gravty'; did you mean 'gravity'?");
    load_fails("[emitter e]\ndeflectors = floor\n",
               "t.ini:2: [emitter e] deflectors: no deflector named 'floor' (the scene defines no [deflector NAME] section)");
    load_fails("[emitter layer]\n[click]\nemitter = layr\n", "t.ini:3: [click] emitter: no emitter named 'layr'; did you mean 'layer'?");
}

Test(scene_errors, kinds_and_required_keys)
{
    load_fails("[force air]\nkind = drag\ng = 9.81\n", "t.ini:3: [force air] g: only for kind = gravity (this force has kind = drag)");
    load_fails("[force air]\nb = 1\n", "t.ini:1: [force air] needs kind = gravity, drag, wind, potential or turbulence");
    load_fails("[force P]\nkind = potential\nposition = 1, 1\n", "t.ini:1: [force P] needs k (the potential's strength)");
    load_fails("[emitter e]\nsource = stream\nrect = 0, 1, 0, 1\n",
               "t.ini:3: [emitter e] rect: only for source = layer (this emitter has source = stream)");
    load_fails("[emitter e]\nrate = 5\n",
               "t.ini:2: [emitter e] rate: only for source = stream (this emitter has source = particle)");
    load_fails("[emitter e]\nsource = layer\ncount = 5\n", "t.ini:1: [emitter e] needs rect (xmin, xmax, ymin, ymax of the layer)");
    load_fails("[bounds]\nmode = thesis\nrestitution = 0.5\n",
               "t.ini:3: [bounds] restitution: only for mode = reflect (this [bounds] has mode = thesis)");
    load_fails("[view]\nxmin = 0\nzoom = 3\n",
               "t.ini:3: [view] mixes a world window (xmin, xmax, ymin, ymax) with a camera (zoom, pan): use one");
    load_fails("[view]\nxmin = 5\nxmax = 1\n", "t.ini:3: [view] xmin (5) must be less than xmax (1)");
    load_fails("[drawing d]\nkind = text\nposition = 1, 1\n", "t.ini:1: [drawing d] needs text (what to write)");
    load_fails("[force P]\nkind = potential\nk = 1\nposition = 0, 0\nlaw = text\n",
               "t.ini:5: [force P] law: needs an exponent to apply to");
}

/* ---- bounds on input size ------------------------------------------------------------ */

Test(scene_bounds, line_too_long)
{
    static char text[70000];
    memset(text, 'a', sizeof text);
    memcpy(text, "[scene]\nx=", 10);
    text[8 + 65536] = 0; /* line 2: 65536 characters */
    load_fails(text, "t.ini:2: line too long (at most 65535 characters)");
    text[8 + 65535] = 0; /* one fewer is read, and x is no key of [scene] */
    isk_effect_def d;
    isk_error err = {0};
    cr_assert_neq(isk_scene_load_string(&d, text, "t.ini", &err), ISK_OK);
    cr_assert(!strncmp(err.message, "t.ini:2: ", 9) && strstr(err.message, "'x'") && !strstr(err.message, "too long"),
              "%.200s", err.message);
    isk_effect_def_free(&d);
}

Test(scene_bounds, too_many_emitters)
{
    size_t cap = 80 * 32;
    char *text = malloc(cap), *p = text;
    for (int i = 0; i < ISK_EFFECT_MAX_EMITTERS + 1; i++)
        p += sprintf(p, "[emitter e%d]\n", i);
    char msg[80];
    snprintf(msg, sizeof msg, "t.ini:%d: too many emitters (at most %d)", ISK_EFFECT_MAX_EMITTERS + 1,
             ISK_EFFECT_MAX_EMITTERS);
    load_fails(text, msg);
    free(text);
}

Test(scene_bounds, too_many_stops_and_points)
{
    load_fails("[emitter e]\nsize_over_life = 0:1,0.05:1,0.1:1,0.15:1,0.2:1,0.25:1,0.3:1,0.35:1,0.4:1,0.45:1,0.5:1,"
               "0.55:1,0.6:1,0.65:1,0.7:1,0.75:1,0.8:1\n",
               "t.ini:2: [emitter e] size_over_life: at most 16 stops, got 17");
    load_fails("[drawing d]\npoints = 1, 2, 3\n",
               "t.ini:2: [drawing d] points: expected 2 to 64 points \"x0, y0, x1, y1, ...\" (an even count of "
               "numbers), got \"1, 2, 3\"");
}

Test(scene_bounds, file_errors)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_file(&d, "tests/data/no/such.ini", &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "tests/data/no/such.ini: "));
    FILE *f = fopen("out/nul_scene.ini", "wb");
    if (!f) {
        (void)system("mkdir -p out");
        f = fopen("out/nul_scene.ini", "wb");
    }
    cr_assert_not_null(f);
    fwrite("[scene]\nwidth = 5\0\n", 1, 19, f);
    fclose(f);
    cr_assert_eq(isk_scene_load_file(&d, "out/nul_scene.ini", &err), ISK_ERR_FORMAT);
    cr_assert_str_eq(err.message, "out/nul_scene.ini:2: contains a NUL byte (not a text file?)");
    isk_effect_def_free(&d);
}

/* ---- built-in scenes ------------------------------------------------------------------ */

Test(scene_builtin, every_builtin_parses_and_creates)
{
    cr_assert_gt(isk_scene_builtin_count(), 0);
    for (int i = 0; i < isk_scene_builtin_count(); i++) {
        const char *name = isk_scene_builtin_name(i);
        cr_assert_not_null(isk_scene_builtin_text(name));
        if (i > 0)
            cr_assert_lt(strcmp(isk_scene_builtin_name(i - 1), name), 0, "sorted");
        isk_effect_def d;
        isk_error err;
        cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s: %s", name, err.message);
        isk_effect *fx;
        cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s: %s", name, err.message);
        isk_effect_destroy(fx);
        isk_effect_def_free(&d);
    }
    cr_assert_null(isk_scene_builtin_name(-1));
    cr_assert_null(isk_scene_builtin_name(isk_scene_builtin_count()));
    cr_assert_null(isk_scene_builtin_text("no_such_scene"));
}

Test(scene_builtin, lookup_file_first_then_name)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load(&d, "scenes/fig12_gravity.ini", &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    cr_assert_eq(isk_scene_load(&d, "fig12_gravity", &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d);
    cr_assert_eq(isk_scene_load(&d, "fig12_gravty", &err), ISK_ERR_IO);
    cr_assert_str_eq(err.message, "fig12_gravty: no such file or built-in scene; did you mean fig12_gravity?");
    cr_assert_eq(isk_scene_load(&d, "nothing/here.ini", &err), ISK_ERR_IO);
    isk_effect_def_free(&d);
}

/* ---- long lines: a 64-point polyline, a chain of every deflector ----------------------- */

/* Appends to a growing text (aborts the test when it cannot). */
static void add(char **text, size_t *len, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char piece[256];
    int n = vsnprintf(piece, sizeof piece, fmt, ap);
    va_end(ap);
    cr_assert(n > 0 && n < (int)sizeof piece);
    *text = realloc(*text, *len + (size_t)n + 1);
    cr_assert_not_null(*text);
    memcpy(*text + *len, piece, (size_t)n + 1);
    *len += (size_t)n;
}

/* Lines of several thousand characters at full precision (%.17g) load,
 * save and load again to the same definition and the same text. */
Test(scene_bounds, long_lines_round_trip)
{
    char *text = NULL;
    size_t len = 0;
    add(&text, &len, "[scene]\nwidth = 64\nheight = 64\n[view]\nxmin = -1\nxmax = 1\nymin = -1\nymax = 1\n");
    enum { DEFLECTORS = ISK_EFFECT_MAX_DEFLECTORS, POINTS = 64 };
    double want[2 * POINTS];
    for (int i = 0; i < DEFLECTORS; i++)
        add(&text, &len, "[deflector a_long_deflector_name_%04d]\nsegment = %.17g, %.17g, %.17g, %.17g\n", i,
            -0.1234567890123456789 * i, 1.0 / 3.0 + i, 2.0 / 7.0 - i, 1e-17 * i);
    add(&text, &len, "[emitter e]\nsource = particle\ndeflectors = ");
    for (int i = 0; i < DEFLECTORS; i++)
        add(&text, &len, "%sa_long_deflector_name_%04d", i ? ", " : "", i);
    add(&text, &len, "\n[drawing path]\nkind = polyline\npoints = ");
    for (int i = 0; i < 2 * POINTS; i++) {
        want[i] = (i % 2 ? -1.0 : 1.0) * (0.1 + i / 3.0) * 1.0000000000000002;
        add(&text, &len, "%s%.17g", i ? ", " : "", want[i]);
    }
    add(&text, &len, "\n");
    const char *chain = strstr(text, "deflectors = "), *pts = strstr(text, "points = ");
    cr_assert_gt(strcspn(chain, "\n"), 7000);
    cr_assert_gt(strcspn(pts, "\n"), 2500);

    isk_effect_def d, again;
    isk_error err = {0};
    cr_assert_eq(isk_scene_load_string(&d, text, "long.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.emitters[0].motion.ndeflectors, DEFLECTORS);
    cr_assert_eq(d.emitters[0].motion.deflectors[DEFLECTORS - 1], DEFLECTORS - 1);
    cr_assert_eq(d.drawings[0].npoints, POINTS);
    cr_assert(!memcmp(d.drawings[0].points, want, sizeof want), "the points are not read exactly");
    char *saved, *saved_again;
    cr_assert_eq(isk_scene_write(&d, &saved, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_scene_load_string(&again, saved, "saved.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(again.drawings[0].npoints, POINTS);
    cr_assert(!memcmp(again.drawings[0].points, want, sizeof want), "the points change on saving");
    cr_assert_eq(again.emitters[0].motion.ndeflectors, DEFLECTORS);
    for (int i = 0; i < DEFLECTORS; i++)
        cr_assert(!memcmp(&again.deflectors[i].seg, &d.deflectors[i].seg, sizeof d.deflectors[i].seg),
                  "deflector %d changes on saving", i);
    cr_assert_eq(isk_scene_write(&again, &saved_again, &err), ISK_OK, "%s", err.message);
    cr_assert_str_eq(saved, saved_again);
    free(saved);
    free(saved_again);
    isk_effect_def_free(&d);
    isk_effect_def_free(&again);
    free(text);
}
