/* SPDX-License-Identifier: MIT */
/* src/io/png_own.h — reading PNG bytes that are iskra's own: the built-in
 * scenes' textures, compiled into the library (internal).
 *
 *     isk_canvas img;
 *     if (isk__png_read_own(&img, bytes, size, "textures/spark.png", max_pixels, &err) != ISK_OK) ...
 *
 * The same as isk_png_read_memory, except on targets whose libpng has no
 * setjmp (the browser's wasm32): libpng cannot return from an error
 * there, so isk_png_read_memory refuses every file, and only these bytes,
 * which every native test run reads, are decoded. */
#ifndef ISKRA_IO_PNG_OWN_H
#define ISKRA_IO_PNG_OWN_H

#include <stddef.h>

#include "iskra/canvas.h"
#include "iskra/status.h"

isk_status isk__png_read_own(isk_canvas *out, const void *data, size_t size, const char *name, long long max_pixels,
                             isk_error *err);

#endif
