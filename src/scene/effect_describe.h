/* SPDX-License-Identifier: MIT */
/* src/scene/effect_describe.h — the parts of isk_effect_describe that are
 * the scene's settings rather than its pipeline (internal).
 *
 * isk__fx_describe_settings prints, after the pipeline and the drawings, every
 * key of [scene], of [bounds] (when it has walls), of each
 * [deflector NAME] and of [click] (when clicks or a click at the start are
 * on) as "key = value", formatted by the key table, so describe shows what
 * the pipeline does not (the seed, the click, start_paused, ...) and a new
 * key shows up without an edit here. */
#ifndef ISKRA_SCENE_EFFECT_DESCRIBE_H
#define ISKRA_SCENE_EFFECT_DESCRIBE_H

#include <stdio.h>

#include "iskra/effect.h"

void isk__fx_describe_settings(const isk_effect_def *d, FILE *out);

#endif
