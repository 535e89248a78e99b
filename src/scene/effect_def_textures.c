/* SPDX-License-Identifier: MIT */
/* The textures a definition holds (isk_effect_def.textures): decoded
 * images under the names the emitters' `texture` key gives, owned by the
 * definition.  Plain data, no file: the scene loader fills them
 * (scene_textures.c), isk_effect_create makes each emitter's texture from
 * them (effect_looks.c). */
#include <stdlib.h>
#include <string.h>

#include "effect_internal.h"

int isk_effect_def_find_texture(const isk_effect_def *d, const char *name)
{
    for (int i = 0; d && d->textures && name && i < d->ntextures; i++)
        if (!strncmp(d->textures[i].name, name, sizeof d->textures[i].name))
            return i;
    return -1;
}

/* A canvas a texture can hold: pixels, a stride of whole rows, sides
 * 1..ISK_TEXTURE_MAX_DIM (the texture module's rule and message). */
static isk_status check_pixels(const char *name, const isk_canvas *c, isk_error *err)
{
    if (!c->pixels || c->width < 1 || c->height < 1 || c->stride < 4u * (size_t)c->width)
        return isk_error_set(err, ISK_ERR_SIZE, "texture %s: a malformed canvas (%d x %d, stride %zu%s)", name,
                             c->width, c->height, c->stride, c->pixels ? "" : ", no pixels");
    return isk_texture_check_size(name, c->width, c->height, 1, 1, err);
}

/* *out: a canvas of its own with img's pixels. */
static isk_status copy_pixels(isk_canvas *out, const isk_canvas *img)
{
    isk_status s = isk_canvas_init(out, img->width, img->height);
    for (int y = 0; s == ISK_OK && y < img->height; y++)
        memcpy(out->pixels + (size_t)y * out->stride, img->pixels + (size_t)y * img->stride, 4u * (size_t)img->width);
    return s;
}

isk_status isk_effect_def_add_texture(isk_effect_def *d, const char *name, const isk_canvas *image, isk_error *err)
{
    if (!d || !name || !image)
        return isk_error_set(err, ISK_ERR_NULL, "texture: NULL %s", !d ? "definition" : !name ? "name" : "image");
    const size_t len = strlen(name);
    if (len == 0 || len >= ISK_TEXTURE_PATH_MAX)
        return isk_error_set(err, ISK_ERR_RANGE, "texture '%.40s%s': a name of 1..%d characters", name,
                             len > 40 ? "..." : "", ISK_TEXTURE_PATH_MAX - 1);
    isk_status s = check_pixels(name, image, err);
    if (s != ISK_OK)
        return s;
    int k = isk_effect_def_find_texture(d, name);
    if (k < 0 && d->ntextures >= ISK_EFFECT_MAX_TEXTURES)
        return isk_error_set(err, ISK_ERR_FULL, "texture %s: the definition already holds its %d textures", name,
                             ISK_EFFECT_MAX_TEXTURES);
    isk_canvas copy;
    if (copy_pixels(&copy, image) != ISK_OK)
        return isk_error_set(err, ISK_ERR_NOMEM, "texture %s: out of memory", name);
    if (k < 0) {
        isk_texture_image *a = realloc(d->textures, sizeof *a * (size_t)(d->ntextures + 1));
        if (!a) {
            isk_canvas_free(&copy);
            return isk_error_set(err, ISK_ERR_NOMEM, "texture %s: out of memory", name);
        }
        d->textures = a;
        k = d->ntextures++;
        memset(&a[k], 0, sizeof a[k]);
        memcpy(a[k].name, name, len + 1);
    }
    isk_canvas_free(&d->textures[k].pixels); /* a replaced texture's */
    d->textures[k].pixels = copy;
    return ISK_OK;
}

isk_status isk__fx_def_textures_check(const isk_effect_def *d, char *why, size_t n)
{
    if (d->ntextures < 0 || d->ntextures > ISK_EFFECT_MAX_TEXTURES) {
        snprintf(why, n, "at most %d textures", ISK_EFFECT_MAX_TEXTURES);
        return ISK_ERR_SIZE;
    }
    if (d->ntextures && !d->textures) {
        snprintf(why, n, "a count is set but its array is NULL");
        return ISK_ERR_NULL;
    }
    for (int i = 0; i < d->ntextures; i++) {
        const isk_texture_image *t = &d->textures[i];
        if (!memchr(t->name, 0, sizeof t->name) || !t->name[0]) {
            snprintf(why, n, "texture %d: a name of 1..%d characters", i, ISK_TEXTURE_PATH_MAX - 1);
            return ISK_ERR_RANGE;
        }
        isk_error e = {0};
        isk_status s = check_pixels(t->name, &t->pixels, &e);
        if (s != ISK_OK) {
            snprintf(why, n, "%s", e.message);
            return s;
        }
    }
    return ISK_OK;
}

isk_status isk__fx_def_textures_copy(isk_effect_def *dst, const isk_effect_def *src)
{
    dst->textures = NULL;
    dst->ntextures = 0;
    if (!src->ntextures)
        return ISK_OK;
    dst->textures = calloc((size_t)src->ntextures, sizeof *dst->textures);
    if (!dst->textures)
        return ISK_ERR_NOMEM;
    for (int i = 0; i < src->ntextures; i++, dst->ntextures++) {
        memcpy(dst->textures[i].name, src->textures[i].name, sizeof dst->textures[i].name);
        if (copy_pixels(&dst->textures[i].pixels, &src->textures[i].pixels) != ISK_OK)
            return ISK_ERR_NOMEM; /* the ones copied are freed with dst */
    }
    return ISK_OK;
}

void isk__fx_def_textures_free(isk_effect_def *d)
{
    for (int i = 0; d->textures && i < d->ntextures; i++)
        isk_canvas_free(&d->textures[i].pixels);
    free(d->textures);
    d->textures = NULL;
    d->ntextures = 0;
}
