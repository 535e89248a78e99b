/* SPDX-License-Identifier: MIT */
/* src/scene/preset_list.h — the presets' names, in one list (internal).
 *
 * FX_PRESETS(X) applies X to each preset's name, in the order
 * isk_preset_name counts them (iskra/presets.h).  presets.c makes its table
 * from it (each name with its function fill_NAME), names.c the names, which
 * the key table gives the `preset` key, so `iskra keys`, the docs and the
 * parser's messages list every preset.  A new preset is a new entry here
 * and its fill_ function. */
#ifndef ISKRA_SCENE_PRESET_LIST_H
#define ISKRA_SCENE_PRESET_LIST_H

#define FX_PRESETS(X) X(fire) X(smoke) X(sparks) X(fountain) X(snow) X(explosion) X(galaxy) X(fireworks) X(rain) X(magic)

#define FX_PRESET_PLUS_ONE(name) +1
enum { FX_PRESET_COUNT = 0 FX_PRESETS(FX_PRESET_PLUS_ONE) };

/* "fire", "smoke", ...: the names, indexed as isk_preset_name counts them. */
extern const char *const isk__fx_preset_names[FX_PRESET_COUNT];

#endif
