/* SPDX-License-Identifier: MIT */
/* Driving an emitter from code: particles now (isk_effect_emit), stopping
 * and starting its births (isk_effect_set_active), pausing it
 * (isk_effect_set_paused) and moving it (isk_effect_move).
 *
 * Stopping and pausing are the keys `active` and `paused`, so a scene file,
 * the simulator's panel, isk_effect_get and a saved scene all see them;
 * these calls are their typed setters.  Moving is the key `position`
 * without its text: a mouse that drags an emitter calls it every event, so
 * it neither parses nor recompiles, and gives the bytes isk_effect_set
 * gives (births spread along the way, no gap). */
#include <math.h>

#include "effect_internal.h"
#include "iskra/limits.h"

isk_status isk_effect_emit(isk_effect *e, const char *section, size_t n, isk_error *err)
{
    fx_group *g;
    isk_status s = isk__fx_emitter_of(e, "isk_effect_emit", section, &g, err);
    if (s != ISK_OK)
        return s;
    const isk_emitter_def *em = g->def;
    switch (em->born.source) {
    case ISK_SOURCE_STREAM:
        e->edits++;
        s = isk__fx_stream_emit(e, g, n);
        break;
    case ISK_SOURCE_EXPLOSION: {
        const size_t limit = em->born.limit ? em->born.limit : ISK_EXPLODE_THESIS_LIMIT;
        if (n > limit)
            return isk_error_set(err, ISK_ERR_RANGE, "isk_effect_emit: [emitter %s]: %zu particles, over its limit %zu",
                                 em->name, n, limit);
        e->edits++;
        s = isk__fx_fire_explosion(e, g, em->born.explosion, em->born.position.x, em->born.position.y, n, em->born.kick);
        if (s == ISK_ERR_FULL)
            return isk_error_set(err, s, "isk_effect_emit: [emitter %s]: its multi-coulomb explosion is still "
                                         "releasing particles",
                                 em->name);
        break;
    }
    default:
        return isk_error_set(err, ISK_ERR_RANGE, "isk_effect_emit: [emitter %s] is a %s source: only stream and "
                                                 "explosion emitters emit",
                             em->name, isk_source_names[em->born.source]);
    }
    return s == ISK_OK ? ISK_OK : isk_error_set(err, s, "isk_effect_emit: [emitter %s]: %s", em->name, isk_status_str(s));
}

isk_status isk_effect_set_active(isk_effect *e, const char *section, int active, isk_error *err)
{
    return isk_effect_set(e, section, "active", active ? "true" : "false", err);
}

isk_status isk_effect_set_paused(isk_effect *e, const char *section, int paused, isk_error *err)
{
    return isk_effect_set(e, section, "paused", paused ? "true" : "false", err);
}

isk_status isk_effect_move(isk_effect *e, const char *section, double x, double y, isk_error *err)
{
    fx_group *g;
    isk_status s = isk__fx_emitter_of(e, "isk_effect_move", section, &g, err);
    if (s != ISK_OK)
        return s;
    isk_emitter_def *em = &e->def.emitters[g->index];
    if (!isfinite(x) || !isfinite(y))
        return isk_error_set(err, ISK_ERR_NAN, "isk_effect_move: [emitter %s]: a position that is not a number",
                             em->name);
    if (fabs(x) > ISK_COORD_MAX || fabs(y) > ISK_COORD_MAX)
        return isk_error_set(err, ISK_ERR_RANGE, "isk_effect_move: [emitter %s]: (%g, %g) is beyond +-%g", em->name,
                             x, y, ISK_COORD_MAX);
    const isk_source_kind src = em->born.source;
    if (src != ISK_SOURCE_STREAM && src != ISK_SOURCE_EXPLOSION && src != ISK_SOURCE_PARTICLE)
        return isk_error_set(err, ISK_ERR_RANGE, "isk_effect_move: [emitter %s] is a %s source: it has no position",
                             em->name, isk_source_names[src]);
    /* the rest of isk_effect_set's work for this key: a stream's path goes
     * on from where it is (an explosion's next centre and a particle's
     * place at reset need nothing more) */
    const isk_emitter_def old = *em;
    e->edits++;
    em->born.position = (isk_vec2){x, y};
    if (src == ISK_SOURCE_STREAM)
        isk__fx_path_changed(e, g, &old, "position");
    return ISK_OK;
}
