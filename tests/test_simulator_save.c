/* SPDX-License-Identifier: MIT */
/* The simulator's Save: isk_scene_write / isk_scene_save write a definition
 * as a scene file that parses back to the very same definition (every
 * built-in scene, and effects changed while running), and refuse what a
 * scene line cannot hold. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/scene.h"
#include "scene_open.h"

/* Byte for byte, except where a definition came from (the `line` fields)
 * and where arrays live (pointers): those are compared by content. */
static int same_item(const void *a, const void *b, size_t size, size_t line_offset, const char *what, int i)
{
    char *x = malloc(size), *y = malloc(size);
    cr_assert(x && y);
    memcpy(x, a, size);
    memcpy(y, b, size);
    memset(x + line_offset, 0, sizeof(int));
    memset(y + line_offset, 0, sizeof(int));
    int same = memcmp(x, y, size) == 0;
    if (!same)
        for (size_t k = 0; k < size; k++)
            if (x[k] != y[k]) {
                cr_log_error("%s %d differs from byte %zu", what, i, k);
                break;
            }
    free(x);
    free(y);
    return same;
}

/* The parser fills ramps from arrays on its stack, so the padding after
 * each stop's colour is whatever was there: ramps are compared by their
 * values (copied into zeroed ramps). */
static void canonical_ramps(isk_emitter_def *e)
{
    isk_color_ramp *cr[2] = {&e->look.color_over_life, &e->look.color_pick};
    for (int k = 0; k < 2; k++) {
        isk_color_ramp c;
        memset(&c, 0, sizeof c);
        c.n = cr[k]->n;
        for (int i = 0; i < ISK_GRADIENT_MAX_STOPS; i++) {
            c.stops[i].t = cr[k]->stops[i].t;
            c.stops[i].color = cr[k]->stops[i].color;
        }
        *cr[k] = c;
    }
    isk_scalar_ramp *r[2] = {&e->look.alpha_over_life, &e->look.size_over_life};
    for (int k = 0; k < 2; k++) {
        isk_scalar_ramp s;
        memset(&s, 0, sizeof s);
        s.n = r[k]->n;
        for (int i = 0; i < ISK_GRADIENT_MAX_STOPS; i++) {
            s.stops[i].t = r[k]->stops[i].t;
            s.stops[i].value = r[k]->stops[i].value;
        }
        *r[k] = s;
    }
}

static int same_definition(const isk_effect_def *a, const isk_effect_def *b)
{
    isk_effect_def x = *a, y = *b;
    x.forces = y.forces = NULL;
    x.deflectors = y.deflectors = NULL;
    x.emitters = y.emitters = NULL;
    x.drawings = y.drawings = NULL;
    x.textures = y.textures = NULL;
    if (memcmp(&x, &y, sizeof x) != 0) {
        cr_log_error("the [scene], [view], [bounds] or [click] fields differ");
        return 0;
    }
    /* the textures the loader read: the same names and pixels */
    for (int i = 0; i < a->ntextures; i++)
        if (strcmp(a->textures[i].name, b->textures[i].name) ||
            !isk_canvas_equal(&a->textures[i].pixels, &b->textures[i].pixels)) {
            cr_log_error("texture %d differs", i);
            return 0;
        }
    for (int i = 0; i < a->nforces; i++)
        if (!same_item(&a->forces[i], &b->forces[i], sizeof *a->forces, offsetof(isk_force_def, line), "force", i))
            return 0;
    for (int i = 0; i < a->ndeflectors; i++)
        if (!same_item(&a->deflectors[i], &b->deflectors[i], sizeof *a->deflectors,
                       offsetof(isk_deflector_def, line), "deflector", i))
            return 0;
    for (int i = 0; i < a->nemitters; i++) {
        isk_emitter_def p = a->emitters[i], q = b->emitters[i];
        canonical_ramps(&p);
        canonical_ramps(&q);
        /* Which preset filled it is a record the writer leaves out: the
         * values it set are written, key by key. */
        memset(p.preset, 0, sizeof p.preset);
        memset(q.preset, 0, sizeof q.preset);
        if (!same_item(&p, &q, sizeof p, offsetof(isk_emitter_def, line), "emitter", i))
            return 0;
    }
    for (int i = 0; i < a->ndrawings; i++) {
        isk_drawing_def p = a->drawings[i], q = b->drawings[i];
        if (p.npoints != q.npoints || (p.npoints && memcmp(p.points, q.points, sizeof(double) * 2 * (size_t)p.npoints)))
            return 0;
        p.points = q.points = NULL;
        if (!same_item(&p, &q, sizeof p, offsetof(isk_drawing_def, line), "drawing", i))
            return 0;
    }
    return 1;
}

/* write -> parse -> compare, then write again: the same text. */
static void round_trip(const isk_effect_def *d, const char *what)
{
    char *text = NULL, *again = NULL;
    isk_error err;
    cr_assert_eq(isk_scene_write(d, &text, &err), ISK_OK, "%s: %s", what, err.message);
    isk_effect_def back;
    cr_assert_eq(isk_scene_load_string(&back, text, what, &err), ISK_OK, "%s: %s\n%s", what, err.message, text);
    cr_assert(same_definition(d, &back), "%s: the written scene reads back differently:\n%s", what, text);
    cr_assert_eq(isk_scene_write(&back, &again, &err), ISK_OK);
    cr_assert_str_eq(text, again, "%s: writing is not stable", what);
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &back, &err), ISK_OK, "%s: %s", what, err.message);
    isk_effect_destroy(fx);
    isk_effect_def_free(&back);
    free(text);
    free(again);
}

Test(save, every_builtin_scene_round_trips)
{
    int n = isk_scene_builtin_count();
    cr_assert_gt(n, 10);
    for (int i = 0; i < n; i++) {
        const char *name = isk_scene_builtin_name(i);
        isk_effect_def d;
        isk_error err;
        cr_assert_eq(isk_scene_load(&d, name, &err), ISK_OK, "%s", err.message);
        round_trip(&d, name);
        isk_effect_def_free(&d);
    }
}

/* Same definition means same pixels: the saved scene renders as the
 * running one does. */
static void same_frames(isk_effect *fx, const isk_effect_def *saved, long frames)
{
    isk_effect *copy;
    isk_error err;
    cr_assert_eq(isk_effect_create(&copy, saved, &err), ISK_OK, "%s", err.message);
    const isk_effect_def *d = isk_effect_definition(fx);
    isk_canvas a, b;
    cr_assert_eq(isk_canvas_init(&a, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_canvas_init(&b, d->width, d->height), ISK_OK);
    cr_assert_eq(isk_effect_reset(fx), ISK_OK);
    cr_assert_eq(isk_effect_run(fx, &a, frames), ISK_OK);
    cr_assert_eq(isk_effect_run(copy, &b, frames), ISK_OK);
    cr_assert(isk_canvas_equal(&a, &b));
    isk_canvas_free(&a);
    isk_canvas_free(&b);
    isk_effect_destroy(copy);
}

Test(save, live_changes_are_saved)
{
    isk_effect *fx = scene_open_builtin("fig26_mushroom_one_potential");
    isk_error err;
    static const char *const sets[][3] = {
        {"force gravity", "g", "10"},     {"force drag", "b", "0.3"},          {"bounds", "sides", "all"},
        {"force A", "k", "650.5"},        {"force A", "position", "4.25, 6"}, {"force A", "enabled", "false"},
        {"click", "explosion", "gauss"},  {"click", "count", "321"},           {"emitter layer", "count", "1200"},
        {"emitter layer", "rect", "1, 9, 0, 1.5"}, {"scene", "speed_divisor", "30"}, {"scene", "substeps", "3"},
        {"scene", "integrator", "rk4"},   {"scene", "start_paused", "true"},
    };
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++)
        cr_assert_eq(isk_effect_set(fx, sets[i][0], sets[i][1], sets[i][2], &err), ISK_OK, "%s", err.message);
    isk_potential p;
    isk_potential_init(&p, 0.0, (isk_vec2){2.5, 7.5}, 1.0);
    cr_assert_eq(isk_effect_add_potential(fx, "P2", &p, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_set(fx, "force P2", "k", "40", &err), ISK_OK, "%s", err.message);
    round_trip(isk_effect_definition(fx), "live");

    char *text;
    cr_assert_eq(isk_scene_write(isk_effect_definition(fx), &text, &err), ISK_OK);
    cr_assert(strstr(text, "\n[force P2]\nkind = potential\nk = 40\n"), "%s", text);
    cr_assert(strstr(text, "\ng = 10\n"));
    cr_assert(strstr(text, "\nstart_paused = true\n"));
    isk_effect_def saved;
    cr_assert_eq(isk_scene_load_string(&saved, text, "saved", &err), ISK_OK, "%s", err.message);
    same_frames(fx, &saved, 40);
    isk_effect_def_free(&saved);
    free(text);
    isk_effect_destroy(fx);
}

Test(save, a_file_is_written_whole_or_not_at_all)
{
    mkdir("out", 0777);
    mkdir("out/test_simulator_save", 0777);
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load(&d, "fig16_regular", &err), ISK_OK);
    const char *path = "out/test_simulator_save/fig16.ini";
    remove(path);
    cr_assert_eq(isk_scene_save(&d, path, &err), ISK_OK, "%s", err.message);
    isk_effect_def back;
    cr_assert_eq(isk_scene_load_file(&back, path, &err), ISK_OK, "%s", err.message);
    cr_assert(same_definition(&d, &back));
    isk_effect_def_free(&back);
    /* a directory that does not exist: an error, and nothing left behind */
    cr_assert_eq(isk_scene_save(&d, "out/test_simulator_save/no/such/dir/x.ini", &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "out/test_simulator_save/no/such/dir/x.ini"), "%s", err.message);
    cr_assert_eq(isk_scene_save(&d, NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_scene_save(NULL, path, &err), ISK_ERR_NULL);
    char *t;
    cr_assert_eq(isk_scene_write(&d, NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_scene_write(NULL, &t, &err), ISK_ERR_NULL);
    cr_assert_null(t);
    isk_effect_def_free(&d);
}

Test(save, what_a_line_cannot_hold_is_refused_and_long_lines_are_held)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_drawing_def *t = isk_effect_def_add_drawing(&d, "label", ISK_DRAWING_TEXT);
    snprintf(t->text, sizeof t->text, "a ; comment");
    char *text;
    isk_error err;
    cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_ERR_FORMAT);
    cr_assert(strstr(err.message, "[drawing label] text"), "%s", err.message);
    snprintf(t->text, sizeof t->text, " padded");
    cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_ERR_FORMAT);
    snprintf(t->text, sizeof t->text, "a;b is fine");
    cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_OK, "%s", err.message);
    free(text);
    isk_effect_def_free(&d);
    /* a polyline of 64 points at full precision fits on a line (lines
     * hold 65535 characters) and loads back exactly */
    isk_effect_def_init(&d);
    isk_drawing_def *l = isk_effect_def_add_drawing(&d, "path", ISK_DRAWING_POLYLINE);
    l->npoints = 64;
    l->points = malloc(sizeof(double) * 128);
    for (int i = 0; i < 128; i++)
        l->points[i] = 1.0 / (i + 3);
    cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_OK, "%s", err.message);
    isk_effect_def back;
    cr_assert_eq(isk_scene_load_string(&back, text, "path.ini", &err), ISK_OK, "%s", err.message);
    cr_assert_eq(back.drawings[0].npoints, 64);
    cr_assert(!memcmp(back.drawings[0].points, l->points, sizeof(double) * 128));
    isk_effect_def_free(&back);
    free(text);
    isk_effect_def_free(&d);
}

/* A save writes what a person would: an enum by its name, never an old
 * spelling (osc_table = true was floor's), and no empty line for a text
 * key that is not given (texture =). */
Test(save, names_not_old_spellings_and_no_empty_keys)
{
    int n = isk_scene_builtin_count();
    for (int i = 0; i < n; i++) {
        isk_effect_def d;
        isk_error err;
        cr_assert_eq(isk_scene_load(&d, isk_scene_builtin_name(i), &err), ISK_OK, "%s", err.message);
        char *text;
        cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_OK, "%s", err.message);
        cr_expect_null(strstr(text, "osc_table = true"), "%s", isk_scene_builtin_name(i));
        cr_expect_null(strstr(text, "osc_table = false"), "%s", isk_scene_builtin_name(i));
        for (const char *line = text; *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : "") {
            size_t len = strcspn(line, "\n");
            cr_expect(!(len >= 2 && line[len - 1] == '=' && line[len - 2] == ' ') &&
                          !(len >= 3 && !strncmp(line + len - 2, "= ", 2)),
                      "%s: an empty value: %.*s", isk_scene_builtin_name(i), (int)len, line);
        }
        free(text);
        isk_effect_def_free(&d);
    }
    /* the old spelling is still read, and written as the name */
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d, "[emitter e]\nsource = stream\nrate = 10\nosc_table = true\n", "old", &err), ISK_OK,
                 "%s", err.message);
    isk_effect *fx;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    char v[32];
    cr_assert_eq(isk_effect_get(fx, "emitter e", "osc_table", v, sizeof v, &err), ISK_OK);
    cr_assert_str_eq(v, "floor");
    cr_assert_eq(isk_effect_get(fx, "emitter e", "integrator", v, sizeof v, &err), ISK_OK);
    cr_assert_str_eq(v, "scene", "a word for a value no name has is still the word");
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* The text of d saved, loaded back and saved again: the same bytes. */
static void saves_and_loads_back(const isk_effect_def *d, const char *what)
{
    char *a, *b;
    isk_error err;
    cr_assert_eq(isk_scene_write(d, &a, &err), ISK_OK, "%s: %s", what, err.message);
    isk_effect_def back;
    cr_assert_eq(isk_scene_load_string(&back, a, "saved.ini", &err), ISK_OK,
                 "%s: isk_effect_set took it, but the saved scene does not load: %s", what, err.message);
    cr_assert_eq(isk_scene_write(&back, &b, &err), ISK_OK, "%s: %s", what, err.message);
    cr_assert_str_eq(a, b, "%s: the saved scene loads to other bytes", what);
    free(a);
    free(b);
    isk_effect_def_free(&back);
}

/* The class: whatever isk_effect_set accepts, the saved file loads (to
 * the same bytes).  Every live numeric key of every item of a few scenes
 * at its range's ends and at 0, every enum at each of its names.  It
 * caught a stream's rate = 0, which set took and the loader refused. */
Test(save, whatever_set_accepts_saves_and_loads_back, .timeout = 120)
{
    const char *scenes[] = {"fire_campfire", "fig19_coulomb", "simulator", "looks_pinwheel"};
    long tried = 0, taken = 0;
    for (size_t sc = 0; sc < sizeof scenes / sizeof scenes[0]; sc++) {
        isk_effect *fx = scene_open_builtin(scenes[sc]);
        for (int s = 0; s < ISK_SECTION_COUNT; s++) {
            for (int i = 0; i < isk_key_items(isk_effect_definition(fx), (isk_section_kind)s); i++) {
                const isk_effect_def *d = isk_effect_definition(fx);
                const int kind = isk_key_item_kind(d, (isk_section_kind)s, i);
                char section[64];
                const char *name = isk_key_item_name(d, (isk_section_kind)s, i);
                snprintf(section, sizeof section, "%s%s%s", isk_section_name((isk_section_kind)s), *name ? " " : "",
                         name);
                for (int r = 0; r < isk_key_count(); r++) {
                    const isk_key *k = isk_key_at(r);
                    if (k->section != (isk_section_kind)s || !isk_key_applies(k, kind) || k->directive ||
                        isk_key_when_set(k, kind) == ISK_KEY_WHEN_CREATED)
                        continue;
                    char values[16][48];
                    int nv = 0;
                    if (k->type == ISK_KEY_NUMBER || k->type == ISK_KEY_WHOLE || k->type == ISK_KEY_LONG ||
                        k->type == ISK_KEY_COUNT) {
                        if (k->lo_bound == ISK_BOUND_INCL)
                            snprintf(values[nv++], 48, "%.17g", k->min);
                        if (k->hi_bound == ISK_BOUND_INCL && k->max < 1e7)
                            snprintf(values[nv++], 48, "%.17g", k->max);
                        snprintf(values[nv++], 48, "0");
                    } else if (k->type == ISK_KEY_ENUM || k->type == ISK_KEY_BOOL) {
                        const char *words[16];
                        int nw = k->type == ISK_KEY_BOOL ? 2 : isk_key_choices(k, words, 16);
                        for (int w = 0; w < nw && nv < 16; w++)
                            snprintf(values[nv++], 48, "%s", k->type == ISK_KEY_BOOL ? (w ? "true" : "false") : words[w]);
                    }
                    char old[4096];
                    isk_error err;
                    cr_assert_eq(isk_effect_get(fx, section, k->name, old, sizeof old, &err), ISK_OK, "%s", err.message);
                    for (int v = 0; v < nv; v++) {
                        tried++;
                        if (isk_effect_set(fx, section, k->name, values[v], &err) != ISK_OK)
                            continue;
                        taken++;
                        char what[1024];
                        snprintf(what, sizeof what, "%s: [%s] %s = %s", scenes[sc], section, k->name, values[v]);
                        saves_and_loads_back(isk_effect_definition(fx), what);
                        cr_assert_eq(isk_effect_set(fx, section, k->name, old, &err), ISK_OK, "%s back: %s", what,
                                     err.message);
                    }
                }
            }
        }
        isk_effect_destroy(fx);
    }
    cr_assert_gt(taken, 100, "%ld of %ld values taken: the sweep tried too little", taken, tried);
}

/* A stream stopped live (rate 0, no bursts) saves as such and loads. */
Test(save, a_stream_stopped_live_loads_back)
{
    isk_effect *fx = scene_open_builtin("fire_campfire");
    const isk_effect_def *d = isk_effect_definition(fx);
    int stream = -1;
    for (int i = 0; i < d->nemitters && stream < 0; i++)
        if (d->emitters[i].born.source == ISK_SOURCE_STREAM && d->emitters[i].born.count == 0)
            stream = i;
    cr_assert_geq(stream, 0, "fire_campfire has a stream without bursts");
    char section[64];
    snprintf(section, sizeof section, "emitter %s", d->emitters[stream].name);
    isk_error err;
    cr_assert_eq(isk_effect_set(fx, section, "rate", "0", &err), ISK_OK, "%s", err.message);
    saves_and_loads_back(isk_effect_definition(fx), "rate = 0");
    isk_effect_destroy(fx);
}

/* Names come from C unchecked: one holding "]" and a line break wrote
 * lines of its own into the saved file.  Creating the effect refuses it,
 * and so does writing a definition that was never created. */
Test(save, names_from_c_are_checked_where_they_enter)
{
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load(&d, "fig19_coulomb", &err), ISK_OK, "%s", err.message);
    cr_assert_gt(d.nemitters, 0);
    char good[ISK_NAME_MAX];
    memcpy(good, d.emitters[0].name, sizeof good);
    const char *bad[] = {"x]\nrate = 1e7\n[emitter y", "a b", "all", "none", "", "x;y"};
    for (size_t b = 0; b < sizeof bad / sizeof bad[0]; b++) {
        snprintf(d.emitters[0].name, sizeof d.emitters[0].name, "%s", bad[b]);
        char *text = NULL;
        cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_ERR_FORMAT, "'%s' was written", bad[b]);
        cr_assert_null(text);
        cr_assert_not_null(strstr(err.message, "emitter 0"), "%s", err.message);
        isk_effect *fx = NULL;
        if (*bad[b]) {
            cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE, "'%s' was taken as a name", bad[b]);
            cr_assert_not_null(strstr(err.message, "a name is 1..31 letters"), "%s", err.message);
        }
    }
    /* a name that fills its field with no terminator */
    memset(d.emitters[0].name, 'a', sizeof d.emitters[0].name);
    isk_effect *fx = NULL;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    char *text = NULL;
    cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_ERR_FORMAT);
    memcpy(d.emitters[0].name, good, sizeof good);
    cr_assert_eq(isk_scene_write(&d, &text, &err), ISK_OK, "%s", err.message);
    free(text);
    isk_effect_def_free(&d);
}
