/* SPDX-License-Identifier: MIT */
/* The scene loader's textures: every emitter's `texture` path resolved and
 * its PNG decoded into the definition (isk_effect_def.textures) while
 * loading, so creating or running the effect opens no file.
 *
 * Where a texture comes from: the file at its path when there is one;
 * otherwise, when a built-in scene names it (scenes/textures/NAME.png),
 * the copy built into the library with the scenes, so a built-in scene
 * draws anywhere.  A path in a scene file is relative to the scene file;
 * isk_scene_load_textures takes a C definition's paths as given.
 *
 * One file, one image: paths that name the same file ("./x.png" and
 * "x.png", a link and its target) are decoded once, and every emitter
 * naming that file is given the first path's name, so the effect's cache
 * of textures (keyed by name and grid) shares them too. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "effect_internal.h"
#include "iskra/scene.h"
#include "io/png_own.h"
#include "iskra/texture_png.h"
#include "scene/scene_load.h"

#define MAX_TEXTURE_PIXELS ((long long)ISK_TEXTURE_MAX_DIM * ISK_TEXTURE_MAX_DIM)

/* The texture of d that is the file at `path` under another name, or -1
 * (by the file's identity: device and inode). */
static int same_file(const isk_effect_def *d, const char *path)
{
    struct stat want, have;
    if (stat(path, &want) != 0)
        return -1;
    for (int i = 0; i < d->ntextures; i++)
        if (stat(d->textures[i].name, &have) == 0 && have.st_dev == want.st_dev && have.st_ino == want.st_ino)
            return i;
    return -1;
}

/* The PNG at `path` (or its built-in copy) into d, unless d holds it
 * (under that name, or that file under another name): its index. */
static isk_status read_texture(isk_effect_def *d, const char *path, int *index, isk_error *err)
{
    int k = isk_effect_def_find_texture(d, path);
    if (k < 0)
        k = same_file(d, path);
    if (k < 0) {
        size_t size = 0;
        const unsigned char *built_in = access(path, F_OK) != 0 ? isk__fx_builtin_file(path, &size) : NULL;
        isk_canvas img;
        isk_status s = built_in ? isk__png_read_own(&img, built_in, size, path, MAX_TEXTURE_PIXELS, err)
                                : isk_texture_image_read(&img, path, err);
        if (s == ISK_OK && built_in && (s = isk_texture_check_size(path, img.width, img.height, 1, 1, err)) != ISK_OK)
            isk_canvas_free(&img);
        if (s != ISK_OK)
            return s;
        s = isk_effect_def_add_texture(d, path, &img, err);
        isk_canvas_free(&img);
        if (s != ISK_OK)
            return s;
        k = isk_effect_def_find_texture(d, path);
    }
    *index = k;
    return ISK_OK;
}

/* The emitter's texture: its file read (once), and its name the one the
 * definition holds that file under. */
static isk_status use_texture(isk_effect_def *d, isk_emitter_def *em, isk_canvas **pixels, isk_error *err)
{
    int k;
    isk_status s = read_texture(d, em->look.texture, &k, err);
    if (s != ISK_OK)
        return s;
    memcpy(em->look.texture, d->textures[k].name, sizeof em->look.texture);
    *pixels = &d->textures[k].pixels;
    return ISK_OK;
}

isk_status isk__fx_scene_texture(isk_effect_def *d, isk_emitter_def *em, const char *scene_name, const char **key,
                            char *why, size_t n)
{
    *key = "texture";
    if (!em->look.texture[0] || isk__fx_looks_check(em, why, n))
        return ISK_OK; /* a malformed grid is the shared check's to report */
    const char *slash = scene_name ? strrchr(scene_name, '/') : NULL;
    if (em->look.texture[0] != '/' && slash) {
        char path[ISK_TEXTURE_PATH_MAX];
        int dir = (int)(slash - scene_name);
        int len = snprintf(path, sizeof path, "%.*s/%s", dir, scene_name, em->look.texture);
        if (len < 0 || (size_t)len >= sizeof path) {
            snprintf(why, n, "the path '%.*s/%s' is longer than %d characters", dir, scene_name, em->look.texture,
                     ISK_TEXTURE_PATH_MAX - 1);
            return ISK_ERR_RANGE;
        }
        memcpy(em->look.texture, path, (size_t)len + 1);
    }
    isk_error err = {0};
    isk_canvas *img = NULL;
    isk_status s = use_texture(d, em, &img, &err);
    /* the texture module's rules (the grid itself is well formed here:
     * isk__fx_looks_check said so), so a RANGE is the grid not dividing the
     * image: that key's line */
    if (s == ISK_OK &&
        (s = isk_texture_check_size(em->look.texture, img->width, img->height, (int)em->look.texture_grid.x,
                                    (int)em->look.texture_grid.y, &err)) == ISK_ERR_RANGE)
        *key = "texture_grid";
    if (s != ISK_OK) {
        snprintf(why, n, "cannot use '%s' as a texture: %s", em->look.texture, err.message);
        return s;
    }
    return ISK_OK;
}

isk_status isk_scene_load_textures(isk_effect_def *d, isk_error *err)
{
    if (!d)
        return isk_error_set(err, ISK_ERR_NULL, "textures: NULL definition");
    if (d->nemitters < 0 || d->nemitters > ISK_EFFECT_MAX_EMITTERS || (d->nemitters && !d->emitters))
        return isk_error_set(err, ISK_ERR_SIZE, "textures: a malformed definition (%d emitters)", d->nemitters);
    for (int i = 0; i < d->nemitters; i++) {
        isk_emitter_def *em = &d->emitters[i];
        if (!em->look.texture[0])
            continue;
        if (!memchr(em->look.texture, 0, sizeof em->look.texture))
            return isk_error_set(err, ISK_ERR_RANGE, "emitter '%.*s': texture: a path of at most %d characters",
                                 ISK_NAME_MAX - 1, em->name, ISK_TEXTURE_PATH_MAX - 1);
        isk_error le = {0};
        isk_canvas *img;
        isk_status s = use_texture(d, em, &img, &le);
        if (s != ISK_OK)
            return isk_error_set(err, s, "emitter '%.*s': texture: %s", ISK_NAME_MAX - 1, em->name, le.message);
    }
    return ISK_OK;
}
