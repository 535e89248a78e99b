/* SPDX-License-Identifier: MIT */
/* Names as scene files spell them: one table per enum of iskra/effect.h,
 * indexed by value, and the presets' names (preset_list.h).  The key
 * table (keys.c), the parser, describe, the messages and `iskra keys` all
 * read these.  Data only, so every file may use them and none of them
 * reaches back. */
#include <string.h>

#include "iskra/effect.h"
#include "key_value.h"
#include "preset_list.h"

const char *const isk_force_kind_names[ISK_FORCE_KIND_COUNT] = {"gravity", "drag", "wind", "potential",
                                                                           "turbulence"};
const char *const isk_space_names[ISK_SPACE_COUNT] = {"world", "local"};
const char *const isk_source_names[ISK_SOURCE_KIND_COUNT] = {"particle", "explosion", "layer", "stream", "sub"};
const char *const isk_rate_mode_names[ISK_RATE_MODE_COUNT] = {"accumulate", "thesis"};
const char *const isk_birth_mode_names[ISK_BIRTH_MODE_COUNT] = {"backdate", "thesis-jitter", "frame"};
const char *const isk_draw_mode_names[ISK_DRAW_COUNT] = {"dot", "pixel", "disc", "sprite", "none", "dot-browser"};
const char *const isk_drawing_kind_names[ISK_DRAWING_KIND_COUNT] = {"polyline", "disc", "text", "polygon", "sprite"};
const char *const isk_units_names[2] = {"world", "pixels"};
const char *const isk_view_kind_names[ISK_VIEWDEF_COUNT] = {"window", "camera"};
const char *const isk_align_names[ISK_ALIGN_COUNT] = {"none", "velocity"};
const char *const isk_probe_kind_names[ISK_PROBE_KIND_COUNT] = {"gate", "region", "histogram", "totals"};
const char *const isk_probe_of_names[ISK_PROBE_OF_COUNT] = {"speed", "angle", "age"};
const char *const isk_draw_order_names[ISK_DRAW_ORDER_COUNT] = {"newest", "oldest", "random"};

#define PRESET_NAME(name) #name,
const char *const isk__fx_preset_names[FX_PRESET_COUNT] = {FX_PRESETS(PRESET_NAME)};

/* The one rule for the name of a force, deflector, emitter or drawing:
 * scene files hold it in a section header and in references, so it is
 * 1..ISK_NAME_MAX-1 letters, digits, '_', '-' or '.', terminated within
 * its field (`cap` bytes).  Anything else ("x]\nrate = 1e7") could not be
 * written, or would be written as other lines. */
int isk__fx_name_ok(const char *s, size_t cap)
{
    if (!s || cap == 0 || !s[0])
        return 0;
    for (size_t i = 0; i < cap; i++) {
        const char c = s[i];
        if (c == 0)
            return 1;
        if (i + 1 >= ISK_NAME_MAX ||
            !((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
              c == '.'))
            return 0;
    }
    return 0; /* not terminated within its field */
}

/* Words that mean something else where a name is expected. */
int isk__fx_name_reserved(const char *s)
{
    return !strcmp(s, "all") || !strcmp(s, "none");
}
