/* SPDX-License-Identifier: MIT */
/* The scene the simulator runs: starting it (from the definition's values:
 * speed, click mode, the first potential selected, start paused), after a
 * reset, and its frames (stepping, drawing, the cost per particle-step for
 * the integrator table and the charts). */
#include <limits.h>
#include <string.h>

#include "play.h"
#include "play_shadow.h"
#include "progress.h"

void play_restarted(player *p)
{
    play_charts_reset(p);
    play_rewind_restart(p);
    play_shadow_restart(p);
    p->dragging = 0;
    size_t n;
    isk_effect_potentials(p->fx, &n);
    if (p->selected >= (int)n)
        p->selected = n ? (int)n - 1 : -1;
}

void play_begin_scene(player *p)
{
    const isk_effect_def *d = isk_effect_definition(p->fx);
    p->base_dt = d->dt;
    p->slider = play_slider_of_divisor(d->speed_divisor);
    p->click_mode = d->click.enabled ? (int)d->click.explosion : PLAY_CLICK_NONE;
    p->precision_text[0] = 0;
    p->physics_off = p->count_refused = 0;
    size_t n;
    isk_effect_potentials(p->fx, &n);
    p->selected = n ? 0 : -1; /* the thesis's editor shows potential 1 */
    p->pot_scroll = 0;
    play_inspector_begin(p);
    memset(p->stats, 0, sizeof p->stats);
    isk_timestep_init(&p->ts, p->base_dt, PLAY_MAX_STEPS_PER_FRAME);
    p->pace = 1;
    play_restarted(p);
    p->paused = 0;
    if (d->show.start_paused) {
        /* the thesis's prviFrame: one frame, then hold */
        play_simulate(p, 1);
        p->paused = 1;
    }
}

void play_simulate(player *p, int steps)
{
    if (steps <= 0 || p->failed)
        return;
    const isk_effect_def *d = isk_effect_definition(p->fx);
    const int trails = !d->clear;
    size_t particles = isk_effect_particle_count(p->fx);
    double t0 = progress_now(), shadow_seconds = 0.0;
    for (int i = 0; i < steps; i++) {
        const double t_step = p->shadow ? progress_now() : 0.0;
        isk_status s = trails ? isk_effect_step_render(p->fx, &p->sim) : isk_effect_step(p->fx);
        if (s != ISK_OK) {
            play_say(p, "frame %ld: %s", isk_effect_frame(p->fx), isk_status_str(s));
            p->failed = 1;
            return;
        }
        if (p->shadow)
            shadow_seconds += play_shadow_stepped(p, progress_now() - t_step);
        play_rewind_stepped(p);
    }
    double seconds = progress_now() - t0 - shadow_seconds; /* the scene's own */
    play_shadow_measure(p);
    if (!trails && isk_effect_render(p->fx, &p->sim) != ISK_OK) {
        p->failed = 1;
        return;
    }
    /* Cost per particle and substep of the stepping alone (not drawing). */
    p->update_ms = p->update_ms > 0 ? 0.9 * p->update_ms + 0.1 * seconds * 1000.0 : seconds * 1000.0;
    /* in double: a million particles' substeps pass a 32-bit long's 2^31 */
    const double particle_steps = (double)particles * d->substeps * steps;
    play_charts_sample(p, particle_steps > 0 ? seconds / particle_steps : 0.0,
                       particle_steps < (double)LONG_MAX ? (long)particle_steps : LONG_MAX);
}
