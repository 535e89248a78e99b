/* iskra.h — umbrella header: includes every public module of libiskra.
 *
 * iskra is a C11 2D particle toolkit with its own software rasterizer.
 * Modules (each header documents itself at the top):
 *   iskra/status.h   error codes           iskra/rng.h     seeded generator
 *   iskra/canvas.h   RGBA8 buffers         iskra/blend.h   blend modes
 *   iskra/draw.h     primitives            iskra/text.h    bitmap font
 *   iskra/view.h     world <-> screen      iskra/png.h     PNG files
 * The SDL2 window lives in a separate library: #include "iskra/sdl.h" and
 * link libiskra-sdl (pkg-config iskra-sdl).
 */
#ifndef ISKRA_H
#define ISKRA_H

#include "iskra/status.h"
#include "iskra/rng.h"
#include "iskra/canvas.h"
#include "iskra/blend.h"
#include "iskra/draw.h"
#include "iskra/text.h"
#include "iskra/view.h"
#include "iskra/png.h"

#endif
