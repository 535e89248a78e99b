/* SPDX-License-Identifier: MIT */
/* The draw of a group whose particles are textures: the emitter's image,
 * one frame of its sprite sheet, or a sprite kind baked into a texture and
 * drawn as a streak (effect_looks.c prepares g->texture).
 *
 * Each particle is drawn by iskra/texture.h's rule at its screen point:
 *   size     the particle's size (its own with size_range, else the
 *            emitter's) times size_over_life, times the view's scale: the
 *            frame's width in pixels; the height keeps the frame's aspect.
 *            A streak is ISK_STREAK_STRETCH times longer than wide.
 *   angle    its angle (rotation, spin: counter-clockwise in the world,
 *            so on a screen whose y grows down it is negated), plus with
 *            align = velocity atan2 of the screen velocity (vx sx, vy sy).
 *            A streak without align is round: its angle is not used.
 *   frame    flipbooks: floor(t * frames) at normalised age t (clamped
 *            to the last frame), or with texture_fps floor(age * fps)
 *            modulo frames; with flipbook_random_start plus the
 *            particle's first frame, modulo frames.
 *   tint     the particle's colour (ramps, color_pick); white leaves the
 *            image as it is.
 *   origin   texture_origin (ox, oy), fractions of the frame from its
 *            top-left corner: that point of the image sits on the screen
 *            point and the image turns about it.  The image's centre is
 *            then the point minus R(angle) ((ox - 1/2) w, (oy - 1/2) h);
 *            at the default (1/2, 1/2) nothing is computed.
 * The band form (isk__draw_texture_rows) blends only the band's rows of a
 * sprite placed on the whole canvas, so the bands give the bytes of the
 * whole call. */
#include <math.h>

#include "effect_internal.h"
#include "effect_style.h"
#include "raster/texture_rows.h"

/* The frame of particle i (0 for a single image). */
static int frame_of(const isk_emitter_def *em, const isk_particles *p, size_t i, int frames)
{
    if (frames <= 1)
        return 0;
    double k;
    if (em->look.texture_fps > 0) {
        k = fmod(floor(p->age[i] * em->look.texture_fps), (double)frames);
        if (!(k >= 0)) /* a NaN age, or a negative one: the first frame */
            k = 0;
    } else {
        double t = isfinite(p->life[i]) && p->life[i] > 0 ? p->age[i] / p->life[i] : 0.0;
        k = floor(t * frames);
        k = k >= frames ? frames - 1 : k > 0 ? k : 0; /* also maps NaN to 0 */
    }
    if (p->frame0) /* flipbook_random_start: on from its own first frame */
        return (int)(((unsigned)k + p->frame0[i]) % (unsigned)frames);
    return (int)k;
}

isk_status isk__fx_draw_textures(isk_effect *e, isk_canvas *c, fx_group *g, const fx_band *b)
{
    const isk_particles *p = &g->store;
    const isk_emitter_def *em = g->def;
    const isk_texture *t = g->texture;
    const isk_view *v = &e->view;
    const int vary = fx_varies(g);
    const int streak = t == &g->streak;
    const int align = em->look.align == ISK_ALIGN_VELOCITY;
    const int turn = p->angle && (!streak || align);
    /* the world's counter-clockwise is the screen's clockwise when one axis flips */
    const double turn_sign = (v->sx < 0) != (v->sy < 0) ? -1.0 : 1.0;
    const double scale = fabs(v->sx);
    const double aspect = (double)t->frame_h / (double)t->frame_w;
    const double stretch = streak ? ISK_STREAK_STRETCH : 1.0;
    const double ox = em->look.texture_origin.x - 0.5, oy = em->look.texture_origin.y - 0.5;
    const int offset = ox != 0.0 || oy != 0.0;
    const size_t n = b->list ? b->nlist : b->end; /* a list: another order than the store's */
    for (size_t k = b->list ? 0 : b->first; k < n; k++) {
        const size_t i = b->list ? b->list[k] : k;
        double X, Y, mult;
        isk_view_to_screen(v, p->x[i], p->y[i], &X, &Y);
        isk_color col = fx_style(g, p, i, vary, &mult);
        const double w = (p->size ? p->size[i] : em->look.size) * mult * scale;
        double angle = turn ? turn_sign * p->angle[i] : 0.0;
        if (align)
            angle += atan2(p->vy[i] * v->sy, p->vx[i] * v->sx);
        if (offset) {
            const double dx = ox * w * stretch, dy = oy * w * aspect;
            const double c = angle != 0.0 ? cos(angle) : 1.0, s = angle != 0.0 ? sin(angle) : 0.0;
            X -= c * dx - s * dy;
            Y -= s * dx + c * dy;
        }
        isk__draw_texture_rows(c, t, frame_of(em, p, i, t->frames), X, Y, w * stretch, w * aspect, angle, col,
                               em->look.blend, b->r0, b->r1, 0);
    }
    return ISK_OK;
}
