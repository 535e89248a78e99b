/* SPDX-License-Identifier: MIT */
/* iskra/scene.h — scene files: INI text that becomes an isk_effect_def.
 *
 * A scene file describes a whole effect (canvas, view, time step, forces,
 * walls, deflectors, emitters, static drawings, the click action) in a
 * hand-writable INI format; docs/scene-format.md documents every section and
 * key with its units, default and valid range.  Parsing fills an
 * isk_effect_def (iskra/effect.h); isk_effect_create() then validates and
 * compiles it.
 *
 * Example:
 *
 *     isk_effect_def d;
 *     isk_error err;
 *     if (isk_scene_load(&d, "fig12_gravity", &err) != ISK_OK) {   // a file or a built-in scene
 *         fprintf(stderr, "%s\n", err.message);  // "scenes/x.ini:12: [emitter smoke] rate: ..."
 *         return 2;
 *     }
 *     isk_effect *fx;
 *     isk_status s = isk_effect_create(&fx, &d, &err);
 *     isk_effect_def_free(&d);
 *     if (s != ISK_OK) { fprintf(stderr, "%s\n", err.message); return 2; }
 *     isk_effect_describe(fx, stdout);          // its emitters' stage lists
 *     isk_effect_destroy(fx);
 *
 * Errors are "NAME:LINE: message" (NAME is the path, the built-in scene's
 * name or the name passed to isk_scene_load_string), naming the section and
 * key and what was expected, with a did-you-mean for misspelt sections, keys,
 * enum values and references.  Unknown sections and keys, duplicate keys and
 * sections, and references to undefined forces/deflectors/emitters are
 * errors.  Input is bounded: ISK_INI_MAX_BYTES of text, lines of at most
 * 65535 characters, and counts capped by the ISK_EFFECT_MAX_* limits of effect.h.
 *
 * On success *out holds the definition (free with isk_effect_def_free).  On
 * failure *out is an initialised, empty definition (freeing it is harmless)
 * and err->status is ISK_ERR_FORMAT (bad scene), ISK_ERR_IO (cannot read the
 * file), ISK_ERR_SIZE (file too large) or ISK_ERR_NOMEM.
 *
 * Built-in scenes are the shipped scenes/ *.ini files, embedded into the
 * library at build time; they are looked up by name (file name without
 * ".ini", e.g. "fig12_gravity").
 *
 * Loading resolves every path: an emitter's `texture` is relative to the
 * scene file, and its PNG is read into the definition
 * (isk_effect_def.textures) while the scene loads, from the file or, for
 * a built-in scene's textures, from the copy built in with it.  A missing
 * or unreadable texture is a load error at its key's line.  Creating and
 * running the effect then open no file.
 */
#ifndef ISKRA_SCENE_H
#define ISKRA_SCENE_H

#include "iskra/effect.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Parses a scene file. */
isk_status isk_scene_load_file(isk_effect_def *out, const char *path, isk_error *err);

/* Parses NUL-terminated scene text; `name` (may be NULL: "<string>") is used
 * in error messages. */
isk_status isk_scene_load_string(isk_effect_def *out, const char *text, const char *name,
                                 isk_error *err);

/* A file path if such a file exists, otherwise a built-in scene's name.
 * Neither: ISK_ERR_IO with "NAME: no such file or built-in scene". */
isk_status isk_scene_load(isk_effect_def *out, const char *name_or_path, isk_error *err);

/* The loading step for a definition filled in C: reads the PNG of every
 * emitter's `texture` that the definition does not hold yet (paths as
 * given, relative to the working directory; a path that is no file but
 * one of the built-in scenes' textures gives that) into
 * isk_effect_def.textures, so isk_effect_create opens no file.  The scene
 * loaders above do this themselves.  Errors name the emitter and the file:
 * ISK_ERR_NULL, ISK_ERR_IO, ISK_ERR_FORMAT, ISK_ERR_SIZE (larger than
 * ISK_TEXTURE_MAX_DIM a side), ISK_ERR_RANGE, ISK_ERR_FULL, ISK_ERR_NOMEM;
 * the textures read before the error stay. */
isk_status isk_scene_load_textures(isk_effect_def *d, isk_error *err);

/* A definition as scene text that parses back to the same definition
 * (every key of every item, written by its row of the key table: what a
 * running effect's isk_effect_definition holds after live changes saves
 * as a scene that reproduces them).  *text is malloc'd (free it).
 * What it writes always loads back to the same definition: ISK_ERR_FORMAT
 * names the key when a value cannot be written (longer than a scene line,
 * text with blanks at an end or a ' ;' comment, a potential moved by a C
 * function), or the item whose name a section header cannot hold (none,
 * or other than 1..31 letters, digits, '_', '-', '.'; isk_effect_create
 * refuses such names too); ISK_ERR_NULL, ISK_ERR_NOMEM. */
isk_status isk_scene_write(const isk_effect_def *def, char **text, isk_error *err);

/* isk_scene_write into a file through iskra/outfile.h: a temporary file
 * in the same directory renamed over `path` (an existing file is replaced
 * whole or not at all, keeping its mode; a symlink stays a link; a device
 * or FIFO is written through, never replaced); ISK_ERR_IO when it cannot
 * be written. */
isk_status isk_scene_save(const isk_effect_def *def, const char *path, isk_error *err);

/* The built-in scenes, sorted by name: count, name (NULL when out of range)
 * and scene text (NULL when out of range or unknown). */
int isk_scene_builtin_count(void);
const char *isk_scene_builtin_name(int i);
const char *isk_scene_builtin_text(const char *name);

#ifdef __cplusplus
}
#endif

#endif
