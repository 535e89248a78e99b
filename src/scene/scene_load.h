/* SPDX-License-Identifier: MIT */
/* src/scene/scene_load.h — what the scene loader's files share (internal).
 *
 * The loader is the part of the scene module that reads files: scene text
 * (ini_read.c, scene_parse.c, scene_load.c), the PNGs the emitters name
 * (scene_textures.c) and the files built into the library with the
 * built-in scenes (scene_builtin.c).  It resolves every path while loading,
 * so the runtime (effect*.c) never opens a file. */
#ifndef ISKRA_SCENE_LOAD_H
#define ISKRA_SCENE_LOAD_H

#include <stddef.h>

#include "iskra/effect.h"

/* scene_builtin.c: a file the built-in scenes use (scenes/textures/NAME.png,
 * embedded with them), by the path they name it with; NULL if none. */
const unsigned char *isk__fx_builtin_file(const char *path, size_t *size);

/* scene_textures.c, the parser's part: the emitter's texture path made
 * relative to the scene file's directory (scene_name: the file's path),
 * its PNG read into the definition (once per path) and the grid checked
 * against the image.  Messages name the path; *key is the key at fault
 * (texture, or texture_grid when it does not divide the image). */
isk_status isk__fx_scene_texture(isk_effect_def *d, isk_emitter_def *em, const char *scene_name, const char **key,
                            char *why, size_t n);

#endif
