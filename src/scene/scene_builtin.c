/* SPDX-License-Identifier: MIT */
/* Built-in scenes: the shipped scenes/ *.ini, embedded at build time by
 * tools/embed_scenes.sh into $(BUILD)/gen/scenes_gen.h, with the textures
 * they use.  Only the tables: isk_scene_load (scene_load.c) looks names
 * up here, the texture loader (scene_textures.c) the files. */
#include <string.h>

#include "iskra/scene.h"
#include "scene/scene_load.h"
#include "scenes_gen.h"

#define NBUILTIN ((int)(sizeof builtin_scenes / sizeof builtin_scenes[0]) - 1)

int isk_scene_builtin_count(void)
{
    return NBUILTIN;
}

const char *isk_scene_builtin_name(int i)
{
    return i >= 0 && i < NBUILTIN ? builtin_scenes[i].name : NULL;
}

const char *isk_scene_builtin_text(const char *name)
{
    for (int i = 0; name && i < NBUILTIN; i++)
        if (!strcmp(builtin_scenes[i].name, name))
            return builtin_scenes[i].text;
    return NULL;
}

const unsigned char *isk__fx_builtin_file(const char *path, size_t *size)
{
    for (int i = 0; path && builtin_files[i].path; i++)
        if (!strcmp(builtin_files[i].path, path)) {
            *size = builtin_files[i].size;
            return builtin_files[i].data;
        }
    return NULL;
}
