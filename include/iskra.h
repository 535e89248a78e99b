/* SPDX-License-Identifier: MIT */
/* iskra.h — umbrella header: includes every public module of libiskra.
 *
 * iskra is a C11 2D particle toolkit with its own software rasterizer.
 * Modules (each header documents itself at the top):
 *   iskra/version.h  ISKRA_VERSION_*       iskra/color.h   RGBA colours
 *   iskra/status.h   error codes           iskra/rng.h     seeded generator
 *   iskra/canvas.h   RGBA8 buffers         iskra/blend.h   blend modes
 *   iskra/draw.h     primitives            iskra/text.h    bitmap font
 *   iskra/view.h     world <-> screen      iskra/png.h     PNG files
 *   iskra/vec2.h     2D vector (Vektor2D)  iskra/particles.h  SoA particle store
 *   iskra/forces.h   gravity, drag, Coulomb potentials
 *   iskra/integrate.h  integrators         iskra/bounds.h  walls / bounce
 *   iskra/explode.h  emitters              iskra/system.h  stepped system
 *   iskra/teach.h    the thesis's classes, one particle at a time
 *   iskra/sinlut.h   sine lookup table     iskra/gradient.h  baked colour/scalar ramps
 *   iskra/sprite.h   baked round sprites   iskra/deflector.h  bouncing segments
 *   iskra/contacts.h walls and segments in one pass, in path order
 *   iskra/texture.h  image sprites: scaled, rotated, tinted, sprite-sheet frames
 *   iskra/texture_png.h  textures from PNG files and bytes
 *   iskra/shape.h    spawn shapes, velocity generators
 *   iskra/timestep.h fixed-step accumulator  iskra/effect.h  whole effects (stage lists)
 *   iskra/tasks.h    an effect's work on your own job system
 *   iskra/probes.h   gates, regions, histograms, totals: an effect's measuring tools
 *   iskra/scene.h    INI scene files      iskra/presets.h  fire, smoke, sparks, ...
 *   iskra/keys.h     every scene key: type, range, default, meaning (one table)
 *   iskra/chart.h    line charts (work-precision diagrams, log/linear axes)
 *   iskra/problems.h closed-form reference problems (integrator accuracy)
 *   iskra/outfile.h  safe output files     iskra/refimg.h  reference-image checks
 *   iskra/anim.h     animated GIF, YUV4MPEG2, raw RGBA frames
 *   iskra/ui.h       immediate-mode widgets drawn by the rasterizer (iskra/ui_sdl.h feeds
 *                    them the window's events)
 * The SDL2 window lives in a separate library: #include "iskra/sdl.h" and
 * link libiskra-sdl (pkg-config iskra-sdl).  Every header can be used from
 * C++ (extern "C"; tests/cxx_link.cpp checks).
 *
 * Example: frame 120 of a built-in scene, written to a PNG:
 *
 *     isk_effect_def d;
 *     isk_error err = {0};
 *     if (isk_scene_load(&d, "fire_campfire", &err) != ISK_OK) {   // a file or a built-in scene
 *         fprintf(stderr, "%s\n", err.message);
 *         return 1;
 *     }
 *     isk_effect *fx = NULL;
 *     isk_canvas c = {0};
 *     int ok = isk_effect_create(&fx, &d, &err) == ISK_OK
 *           && isk_canvas_init(&c, d.width, d.height) == ISK_OK
 *           && isk_effect_run(fx, &c, 120) == ISK_OK
 *           && isk_png_write(&c, "campfire.png", &err) == ISK_OK;
 *     if (!ok) fprintf(stderr, "campfire: %s\n", err.message[0] ? err.message : "out of memory");
 *     isk_canvas_free(&c);
 *     isk_effect_destroy(fx);
 *     isk_effect_def_free(&d);
 *     return !ok;
 */
#ifndef ISKRA_H
#define ISKRA_H

#include "iskra/version.h"
#include "iskra/color.h"
#include "iskra/status.h"
#include "iskra/rng.h"
#include "iskra/canvas.h"
#include "iskra/blend.h"
#include "iskra/draw.h"
#include "iskra/text.h"
#include "iskra/texture.h"
#include "iskra/view.h"
#include "iskra/png.h"
#include "iskra/texture_png.h"
#include "iskra/vec2.h"
#include "iskra/particles.h"
#include "iskra/forces.h"
#include "iskra/integrate.h"
#include "iskra/limits.h"
#include "iskra/impact.h"
#include "iskra/bounds.h"
#include "iskra/explode.h"
#include "iskra/system.h"
#include "iskra/teach.h"
#include "iskra/sinlut.h"
#include "iskra/gradient.h"
#include "iskra/sprite.h"
#include "iskra/deflector.h"
#include "iskra/contacts.h"
#include "iskra/shape.h"
#include "iskra/timestep.h"
#include "iskra/tasks.h"
#include "iskra/effect.h"
#include "iskra/probes.h"
#include "iskra/scene.h"
#include "iskra/snapshot.h"
#include "iskra/timeline.h"
#include "iskra/keys.h"
#include "iskra/presets.h"
#include "iskra/chart.h"
#include "iskra/problems.h"
#include "iskra/stability.h"
#include "iskra/outfile.h"
#include "iskra/refimg.h"
#include "iskra/anim.h"
#include "iskra/ui.h"

#endif
