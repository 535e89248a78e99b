/* SPDX-License-Identifier: MIT */
/* The looks of a particle: its angle and spin, its own size and base
 * colour drawn at birth, and the texture it is drawn as.
 *
 * What an emitter does not use costs nothing and changes nothing: the angle
 * column (and the spin stage, effect_compile.c) exist only with a rotation
 * or a spin, the size column only with size_range, the colour column only
 * with color_pick, the first-frame column only with flipbook_random_start
 * on a flipbook; every random draw here happens only when its range or
 * color_pick asks, each from the attribute's own stream (fx_stream), so
 * turning one on or off never changes another particle's draws.  The drawing is
 * effect_texture.c's.  A texture is made from the pixels the definition
 * holds (isk_effect_def.textures, read by the scene loader): nothing here
 * opens a file. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "effect_internal.h"

#define PI 3.14159265358979323846
#define TWO_PI 6.28318530717958647692
/* The side of the texture a sprite kind is baked into for streaks: drawn
 * smaller through its mip levels, larger by bilinear magnification. */
#define FX_STREAK_TEXELS 64

/* An angle can be seen only on a texture or a streak along the velocity:
 * a round sprite, a disc or a dot looks the same at every angle, so for
 * them rotation and spin keep no column, run no stage and draw nothing at
 * random (their bytes are exactly those without the keys). */
static int angle_seen(const isk_emitter_def *em)
{
    return em->look.texture[0] || em->look.align == ISK_ALIGN_VELOCITY;
}

static int rotates(const isk_emitter_def *em)
{
    return angle_seen(em) && (em->look.rotation != 0 || em->look.rotation_range > 0 || isk__fx_looks_spins(em));
}

double isk__fx_looks_spin_change(const isk_emitter_def *em)
{
    return em->look.spin_end == ISK_SPIN_END_NONE ? 0.0 : em->look.spin_end - em->look.spin;
}

int isk__fx_looks_spins(const isk_emitter_def *em)
{
    return angle_seen(em) && (em->look.spin != 0 || em->look.spin_range > 0 || isk__fx_looks_spin_change(em) != 0);
}

/* The frames of the emitter's flipbook (1: a single image, or none). */
static int flipbook_frames(const isk_emitter_def *em)
{
    return em->look.texture[0] ? (int)em->look.texture_grid.x * (int)em->look.texture_grid.y : 1;
}

/* A random first frame is seen only on a flipbook of several frames. */
static int random_start(const isk_emitter_def *em)
{
    return em->look.flipbook_random_start && flipbook_frames(em) > 1 && em->look.draw != ISK_DRAW_NONE;
}

unsigned isk__fx_looks_columns(const isk_emitter_def *em)
{
    return (rotates(em) ? ISK_PARTICLES_ANGLE : 0u) | (em->look.size_range > 0 ? ISK_PARTICLES_SIZE : 0u) |
           (em->look.color_pick.n > 0 ? ISK_PARTICLES_COLOR : 0u) | (random_start(em) ? ISK_PARTICLES_FRAME : 0u);
}

static double wrap(double a)
{
    if (a >= -PI && a < PI)
        return a;
    a -= TWO_PI * floor((a + PI) / TWO_PI);
    return a >= PI ? a - TWO_PI : a < -PI ? a + TWO_PI : a;
}

void isk__fx_looks_adopt(fx_group *g, size_t from)
{
    const isk_emitter_def *em = g->def;
    isk_particles *p = &g->store;
    isk_rng *rotation = &g->streams[FX_STREAM_ROTATION], *spin = &g->streams[FX_STREAM_SPIN];
    isk_rng *size = &g->streams[FX_STREAM_SIZE], *color = &g->streams[FX_STREAM_COLOR];
    if (p->angle) {
        for (size_t i = from; i < p->count; i++) {
            double a = em->look.rotation +
                (em->look.rotation_range > 0 ? em->look.rotation_range * isk_rng_uniform(rotation) : 0.0);
            p->angle[i] = wrap(a);
        }
        for (size_t i = from; i < p->count; i++)
            p->spin[i] = em->look.spin + (em->look.spin_range > 0 ? em->look.spin_range * isk_rng_uniform(spin) : 0.0);
    }
    if (p->size)
        for (size_t i = from; i < p->count; i++)
            p->size[i] = em->look.size + (em->look.size_range > 0 ? em->look.size_range * isk_rng_uniform(size) : 0.0);
    if (p->color)
        for (size_t i = from; i < p->count; i++)
            p->color[i] = em->look.color_pick.n
                ? isk_color_gradient_eval(em->look.color_pick.stops, em->look.color_pick.n, isk_rng_uniform(color))
                : em->look.color;
    if (p->frame0) { /* frames <= ISK_TEXTURE_MAX_GRID^2 = 65536: a frame number fits 16 bits */
        isk_rng *frame = &g->streams[FX_STREAM_FRAME];
        const int frames = flipbook_frames(em);
        for (size_t i = from; i < p->count; i++)
            p->frame0[i] = random_start(em) ? (uint16_t)isk_rng_below(frame, (uint32_t)frames) : 0;
    }
}

/* A sprite kind drawn through a texture: turned along the velocity (a
 * streak), or at a size of its own per particle. */
static int streaks(const isk_emitter_def *em)
{
    return !em->look.texture[0] && em->look.draw == ISK_DRAW_SPRITE &&
        (em->look.align == ISK_ALIGN_VELOCITY || em->look.size_range > 0);
}

isk_status isk__fx_looks_streak(fx_group *g)
{
    const isk_emitter_def *em = g->def;
    /* align, size_range, draw or sprite may have made a streak of a sprite
     * kind, or unmade it (the texture itself is fixed at create) */
    if (!em->look.texture[0]) {
        isk__fx_looks_free(g);
        if (streaks(em)) {
            isk_status s = isk_texture_from_sprite(&g->streak, em->look.sprite, FX_STREAK_TEXELS);
            if (s != ISK_OK)
                return s;
            g->texture = &g->streak;
        }
    }
    return ISK_OK;
}

isk_status isk__fx_looks_columns_live(fx_group *g)
{
    const isk_emitter_def *em = g->def;
    const unsigned want = isk__fx_looks_columns(em);
    if (!(want & ~g->store.flags))
        return ISK_OK;
    /* the particles already there get the emitter's own size and colour */
    g->store.default_size = em->look.size;
    g->store.default_color = em->look.color;
    return isk_particles_add_columns(&g->store, want);
}

isk_status isk__fx_looks_prepare(isk_effect *e, fx_group *g, isk_error *err)
{
    const isk_emitter_def *em = g->def;
    g->texture = NULL;
    if (em->look.draw == ISK_DRAW_NONE)
        return ISK_OK;
    if (em->look.texture[0]) {
        char where[32] = "";
        if (em->line > 0)
            snprintf(where, sizeof where, " (line %d)", em->line);
        const int k = isk_effect_def_find_texture(&e->def, em->look.texture);
        if (k < 0)
            return isk_error_set(err, ISK_ERR_RANGE,
                                 "emitter '%s'%s: texture %s: not among the definition's textures (read the PNGs "
                                 "it names with isk_scene_load_textures, or give pixels with "
                                 "isk_effect_def_add_texture)",
                                 em->name, where, em->look.texture);
        isk_status s = e->textures ? ISK_OK : isk_texture_cache_create(&e->textures, ISK_EFFECT_MAX_EMITTERS);
        if (s != ISK_OK)
            return isk_error_set(err, s, "emitter '%s': texture: %s", em->name, isk_status_str(s));
        isk_error le = {0};
        s = isk_texture_cache_get_canvas(e->textures, em->look.texture, &e->def.textures[k].pixels,
                                         (int)em->look.texture_grid.x, (int)em->look.texture_grid.y, &g->texture, &le);
        if (s != ISK_OK)
            return isk_error_set(err, s, "emitter '%s'%s: texture: %s%s%s", em->name, where, le.message,
                                 s == ISK_ERR_NOMEM ? ": " : "", s == ISK_ERR_NOMEM ? isk_status_str(s) : "");
        return ISK_OK;
    }
    if (!streaks(em))
        return ISK_OK;
    isk_status s = isk_texture_from_sprite(&g->streak, em->look.sprite, FX_STREAK_TEXELS);
    if (s != ISK_OK)
        return isk_error_set(err, s, "emitter '%s': cannot bake its streak: %s", em->name, isk_status_str(s));
    g->texture = &g->streak;
    return ISK_OK;
}

void isk__fx_looks_free(fx_group *g)
{
    isk_texture_free(&g->streak);
    g->texture = NULL;
}

static int whole_in(double v, double lo, double hi)
{
    return v >= lo && v <= hi && v == floor(v);
}

const char *isk__fx_looks_check(const isk_emitter_def *em, char *why, size_t n)
{
    if (!whole_in(em->look.texture_grid.x, 1, ISK_TEXTURE_MAX_GRID) ||
        !whole_in(em->look.texture_grid.y, 1, ISK_TEXTURE_MAX_GRID)) {
        snprintf(why, n, "expected whole numbers of columns and rows, 1..%d, got %.15g, %.15g", ISK_TEXTURE_MAX_GRID,
                 em->look.texture_grid.x, em->look.texture_grid.y);
        return "texture_grid";
    }
    if (!memchr(em->look.texture, 0, sizeof em->look.texture)) {
        snprintf(why, n, "a path of at most %d characters", ISK_TEXTURE_PATH_MAX - 1);
        return "texture";
    }
    return NULL;
}

void isk__fx_looks_describe(const fx_group *g, FILE *out)
{
    const isk_emitter_def *em = g->def;
    if (!g->texture && !rotates(em) && !em->look.size_range && !em->look.color_pick.n)
        return;
    fprintf(out, "  %-9s ", "looks");
    const char *sep = "";
    if (g->texture == &g->streak) {
        fprintf(out, "streak (%s sprite, %g x size long)", isk_sprite_kind_names[em->look.sprite],
                ISK_STREAK_STRETCH);
        sep = ",";
    } else if (g->texture) {
        fprintf(out, "texture %s (%d frame%s%s)", em->look.texture, g->texture->frames,
                g->texture->frames == 1 ? "" : "s",
                g->texture->frames > 1 ? (em->look.texture_fps > 0 ? ", at a rate" : ", over the life") : "");
        sep = ",";
    }
    if (em->look.align == ISK_ALIGN_VELOCITY && g->texture) {
        fprintf(out, "%s along the velocity", sep);
        sep = ",";
    }
    if (rotates(em)) {
        fprintf(out, "%s angle %g + U*%g deg", sep, em->look.rotation * (180 / PI),
                em->look.rotation_range * (180 / PI));
        sep = ",";
    }
    if (em->look.size_range > 0) {
        fprintf(out, "%s size %g + U*%g", sep, em->look.size, em->look.size_range);
        sep = ",";
    }
    if (em->look.color_pick.n)
        fprintf(out, "%s colour picked from %d stops", sep, em->look.color_pick.n);
    fputc('\n', out);
}
