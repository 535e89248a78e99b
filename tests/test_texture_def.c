/* SPDX-License-Identifier: MIT */
/* The textures a definition holds (isk_effect_def.textures): the loader
 * reads the PNGs while loading (scene files, isk_scene_load_textures), a
 * program may give pixels instead (isk_effect_def_add_texture), and
 * creating or running the effect opens no file.  Checked: the messages of
 * every refusal, the same bytes from pixels as from the file, the effect's
 * own copy, an effect created after its PNG is gone, the built-in copy of a
 * built-in scene's texture. */
#include <criterion/criterion.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "iskra/effect.h"
#include "iskra/png.h"
#include "iskra/scene.h"
#include "iskra/texture.h"
#include "tool_cli.h"

#define TEX "scenes/textures/arrows.png"

/* A stream of particles drawn as the texture `name` (a 4 x 2 sheet). */
static const char *scene_with(const char *name)
{
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "[scene]\nwidth = 64\nheight = 48\nseed = 5\n[view]\nxmin = -4\nxmax = 4\nymin = -3\nymax = 3\n"
             "[emitter e]\nsource = stream\nrate = 40\nlaunch = disc\nspeed_max = 2\nlife = 2\nsize = 0.8\n"
             "draw = sprite\ncolor = white\nrotation_range = 360\ntexture = %s\ntexture_grid = 4, 2\n",
             name);
    return buf;
}

/* Frame 30 of an effect made from d. */
static void render(const isk_effect_def *d, isk_canvas *c)
{
    isk_effect *fx;
    isk_error err;
    cr_assert_eq(isk_effect_create(&fx, d, &err), ISK_OK, "%s", err.message);
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_canvas_init(c, 64, 48), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, c), ISK_OK);
    isk_effect_destroy(fx);
}

static void load(isk_effect_def *d, const char *text, const char *name)
{
    isk_error err;
    cr_assert_eq(isk_scene_load_string(d, text, name, &err), ISK_OK, "%s", err.message);
}

/* A scene's texture is in its definition, under the resolved path. */
Test(texture_def, a_scene_carries_its_texture)
{
    isk_effect_def d;
    load(&d, scene_with("textures/arrows.png"), "scenes/x.ini");
    cr_assert_eq(d.ntextures, 1);
    cr_assert_str_eq(d.textures[0].name, TEX);
    cr_assert_eq(isk_effect_def_find_texture(&d, TEX), 0);
    cr_assert_eq(isk_effect_def_find_texture(&d, "arrows.png"), -1);
    isk_canvas want;
    cr_assert_eq(isk_png_read(&want, TEX, NULL), ISK_OK);
    cr_assert(isk_canvas_equal(&want, &d.textures[0].pixels));
    isk_canvas_free(&want);
    isk_effect_def_free(&d);
    cr_assert(d.textures == NULL && d.ntextures == 0);
}

/* A definition filled in C names its textures; the loading step reads
 * them, and create says which step was missed. */
Test(texture_def, a_c_definition_loads_its_textures_before_create)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "e");
    cr_assert_not_null(e);
    snprintf(e->look.texture, sizeof e->look.texture, "no/such.png");
    isk_effect *fx;
    isk_error err;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "emitter 'e'") && strstr(err.message, "no/such.png") &&
                  strstr(err.message, "isk_scene_load_textures") && strstr(err.message, "isk_effect_def_add_texture"),
              "%s", err.message);
    cr_assert_eq(isk_scene_load_textures(&d, &err), ISK_ERR_IO);
    cr_assert(strstr(err.message, "emitter 'e'") && strstr(err.message, "no/such.png"), "%s", err.message);
    cr_assert_eq(d.ntextures, 0, "a failed read keeps nothing");

    snprintf(e->look.texture, sizeof e->look.texture, TEX);
    cr_assert_eq(isk_scene_load_textures(&d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_scene_load_textures(&d, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.ntextures, 1, "each path read once");
    e->look.texture_grid = (isk_vec2){3, 1};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "emitter 'e'") && strstr(err.message, "arrows.png") && strstr(err.message, "3 x 1"),
              "%s", err.message);
    e->look.texture_grid = (isk_vec2){4, 2};
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);

    cr_assert_eq(isk_scene_load_textures(NULL, &err), ISK_ERR_NULL);
    memset(e->look.texture, 'x', sizeof e->look.texture);
    cr_assert_eq(isk_scene_load_textures(&d, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "emitter 'e'") && strstr(err.message, "255"), "%s", err.message);
    isk_effect_def_free(&d);
}

/* Pixels given in C draw exactly as the file they came from. */
Test(texture_def, pixels_given_in_c_draw_as_the_file_does)
{
    isk_effect_def a, b;
    load(&a, scene_with(TEX), "t.ini");
    cr_assert_eq(isk_scene_load_string(&b, scene_with("mine"), "t.ini", NULL), ISK_ERR_FORMAT, "no file 'mine'");
    isk_effect_def_init(&b);
    load(&b, scene_with(TEX), "t.ini");
    snprintf(b.emitters[0].look.texture, sizeof b.emitters[0].look.texture, "mine");
    isk_canvas img;
    isk_error err;
    cr_assert_eq(isk_png_read(&img, TEX, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(isk_effect_def_add_texture(&b, "mine", &img, &err), ISK_OK, "%s", err.message);
    isk_canvas_free(&img);
    isk_canvas ca, cb;
    render(&a, &ca);
    render(&b, &cb);
    cr_assert(isk_canvas_equal(&ca, &cb));
    isk_canvas blank;
    cr_assert_eq(isk_canvas_init(&blank, 64, 48), ISK_OK);
    isk_canvas_fill(&blank, ISK_BLACK);
    cr_assert(!isk_canvas_equal(&ca, &blank), "the texture was drawn");
    isk_canvas_free(&blank);
    isk_canvas_free(&ca);
    isk_canvas_free(&cb);
    isk_effect_def_free(&a);
    isk_effect_def_free(&b);
}

Test(texture_def, add_texture_checks_its_arguments)
{
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_canvas img, other;
    cr_assert_eq(isk_canvas_init(&img, 8, 4), ISK_OK);
    cr_assert_eq(isk_canvas_init(&other, 2, 2), ISK_OK);
    isk_canvas_fill(&img, ISK_WHITE);
    isk_canvas_fill(&other, ISK_BLACK);
    isk_error err;
    cr_assert_eq(isk_effect_def_add_texture(NULL, "t", &img, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_def_add_texture(&d, NULL, &img, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_def_add_texture(&d, "t", NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_effect_def_add_texture(&d, "", &img, &err), ISK_ERR_RANGE);
    char long_name[ISK_TEXTURE_PATH_MAX + 1];
    memset(long_name, 'n', sizeof long_name - 1);
    long_name[sizeof long_name - 1] = 0;
    cr_assert_eq(isk_effect_def_add_texture(&d, long_name, &img, &err), ISK_ERR_RANGE);
    cr_assert(strstr(err.message, "255"), "%s", err.message);
    isk_canvas bad = img;
    bad.pixels = NULL;
    cr_assert_eq(isk_effect_def_add_texture(&d, "t", &bad, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, "texture t"), "%s", err.message);
    bad = img;
    bad.stride = 4;
    cr_assert_eq(isk_effect_def_add_texture(&d, "t", &bad, &err), ISK_ERR_SIZE);
    isk_canvas wide;
    cr_assert_eq(isk_canvas_init(&wide, ISK_TEXTURE_MAX_DIM + 1, 1), ISK_OK);
    cr_assert_eq(isk_effect_def_add_texture(&d, "wide", &wide, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, "wide") && strstr(err.message, "4096"), "%s", err.message);
    isk_canvas_free(&wide);
    cr_assert_eq(d.ntextures, 0, "nothing kept from a refusal");

    /* a copy, replaced by name; the same name again keeps one entry */
    cr_assert_eq(isk_effect_def_add_texture(&d, "t", &img, &err), ISK_OK, "%s", err.message);
    isk_canvas_fill(&img, ISK_BLACK);
    cr_assert_eq(isk_canvas_at(&d.textures[0].pixels, 3, 3)[0], 255, "the definition holds a copy");
    cr_assert_eq(isk_effect_def_add_texture(&d, "t", &other, &err), ISK_OK, "%s", err.message);
    cr_assert_eq(d.ntextures, 1);
    cr_assert(isk_canvas_equal(&d.textures[0].pixels, &other));
    for (int i = 1; i < ISK_EFFECT_MAX_TEXTURES; i++) {
        char name[16];
        snprintf(name, sizeof name, "t%d", i);
        cr_assert_eq(isk_effect_def_add_texture(&d, name, &other, &err), ISK_OK, "%s", err.message);
    }
    cr_assert_eq(isk_effect_def_add_texture(&d, "one more", &other, &err), ISK_ERR_FULL);
    cr_assert(strstr(err.message, "one more"), "%s", err.message);
    cr_assert_eq(isk_effect_def_add_texture(&d, "t5", &img, &err), ISK_OK, "a held name is replaced when full");
    cr_assert_eq(d.ntextures, ISK_EFFECT_MAX_TEXTURES);
    isk_canvas_free(&img);
    isk_canvas_free(&other);
    isk_effect_def_free(&d);
}

/* isk_effect_create validates a hand-filled texture table like every
 * other array of the definition. */
Test(texture_def, create_refuses_a_malformed_table)
{
    isk_effect_def d;
    load(&d, scene_with(TEX), "t.ini");
    isk_texture_image *held = d.textures;
    isk_effect *fx;
    isk_error err;
    d.textures = NULL;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_NULL);
    cr_assert(strstr(err.message, "NULL"), "%s", err.message);
    d.textures = held;
    d.ntextures = ISK_EFFECT_MAX_TEXTURES + 1;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, "64 textures"), "%s", err.message);
    d.ntextures = 1;
    uint8_t *px = held[0].pixels.pixels;
    held[0].pixels.pixels = NULL;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_ERR_SIZE);
    cr_assert(strstr(err.message, TEX), "%s", err.message);
    held[0].pixels.pixels = px;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
}

/* Loading resolves every path: with the scene's PNG deleted after loading,
 * the effect is created and draws the same bytes; it keeps its own copy
 * of the pixels, and its definition shows them. */
Test(texture_def, creating_opens_no_file)
{
    cli_fresh("out/test_texture_def/gone");
    isk_canvas img;
    cr_assert_eq(isk_png_read(&img, TEX, NULL), ISK_OK);
    cr_assert_eq(isk_png_write(&img, "out/test_texture_def/gone/sheet.png", NULL), ISK_OK);
    isk_effect_def d;
    load(&d, scene_with("sheet.png"), "out/test_texture_def/gone/s.ini");
    isk_canvas before, after;
    render(&d, &before);
    cr_assert_eq(remove("out/test_texture_def/gone/sheet.png"), 0);
    isk_effect *fx;
    isk_error err;
    cr_assert_eq(isk_effect_create(&fx, &d, &err), ISK_OK, "%s", err.message);
    isk_effect_def_free(&d); /* the effect's own copy */
    const isk_effect_def *held = isk_effect_definition(fx);
    cr_assert_eq(held->ntextures, 1);
    cr_assert(isk_canvas_equal(&held->textures[0].pixels, &img));
    for (int i = 0; i < 30; i++)
        cr_assert_eq(isk_effect_step(fx), ISK_OK);
    cr_assert_eq(isk_canvas_init(&after, 64, 48), ISK_OK);
    cr_assert_eq(isk_effect_render(fx, &after), ISK_OK);
    cr_assert(isk_canvas_equal(&before, &after));
    isk_effect_destroy(fx);
    isk_canvas_free(&before);
    isk_canvas_free(&after);
    isk_canvas_free(&img);
}

/* A PNG whose header reads but whose pixels do not is a load error now,
 * at the key's line, naming the file. */
Test(texture_def, a_corrupt_png_is_refused_at_its_line)
{
    cli_fresh("out/test_texture_def/corrupt");
    FILE *f = fopen(TEX, "rb");
    cr_assert_not_null(f);
    static unsigned char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    f = fopen("out/test_texture_def/corrupt/cut.png", "wb");
    cr_assert_not_null(f);
    cr_assert_eq(fwrite(buf, 1, n / 2, f), n / 2);
    fclose(f);
    isk_effect_def d;
    isk_error err;
    cr_assert_eq(isk_scene_load_string(&d, scene_with("cut.png"), "out/test_texture_def/corrupt/s.ini", &err),
                 ISK_ERR_FORMAT);
    cr_assert(strstr(err.message, "out/test_texture_def/corrupt/s.ini:20: ") == err.message, "%s", err.message);
    cr_assert(strstr(err.message, "texture") && strstr(err.message, "cut.png"), "%s", err.message);
    cr_assert_eq(d.ntextures, 0);
    isk_effect_def_free(&d);
}

/* Away from the repository, a built-in scene's texture path gives the copy
 * built into the library: through the loading step of a C definition,
 * and through a built-in scene. */
Test(texture_def, a_built_in_texture_is_found_anywhere)
{
    isk_canvas want;
    cr_assert_eq(isk_png_read(&want, TEX, NULL), ISK_OK);
    cr_assert_eq(chdir("/"), 0);
    cr_assert_neq(access(TEX, F_OK), 0);
    isk_effect_def d;
    isk_effect_def_init(&d);
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "e");
    cr_assert_not_null(e);
    snprintf(e->look.texture, sizeof e->look.texture, TEX);
    isk_error err;
    cr_assert_eq(isk_scene_load_textures(&d, &err), ISK_OK, "%s", err.message);
    cr_assert(isk_canvas_equal(&d.textures[0].pixels, &want));
    isk_effect_def_free(&d);
    cr_assert_eq(isk_scene_load(&d, "looks_pinwheel", &err), ISK_OK, "%s", err.message);
    const int k = isk_effect_def_find_texture(&d, TEX);
    cr_assert_geq(k, 0);
    cr_assert(isk_canvas_equal(&d.textures[k].pixels, &want));
    isk_effect_def_free(&d);
    isk_canvas_free(&want);
}
