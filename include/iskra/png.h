/* iskra/png.h — write and read canvases as PNG files (libpng).
 *
 *     isk_error err;
 *     if (isk_png_write(&canvas, "out/frame.png", &err) != ISK_OK)
 *         fprintf(stderr, "%s\n", err.message);
 *
 * Writing goes to a temporary file beside the target which is renamed over
 * it only when complete, so a failure never leaves a half-written PNG and
 * never destroys an existing file.  Output is 8-bit RGBA, non-interlaced.
 * Reading accepts any PNG libpng can decode and converts it to RGBA8.
 * Nothing is printed: libpng's warnings and errors go into `err`.
 */
#ifndef ISKRA_PNG_H
#define ISKRA_PNG_H

#include "iskra/canvas.h"
#include "iskra/status.h"

#ifdef __cplusplus
extern "C" {
#endif

isk_status isk_png_write(const isk_canvas *c, const char *path, isk_error *err);

/* Reads `path` into a newly initialised canvas (free with isk_canvas_free). */
isk_status isk_png_read(isk_canvas *out, const char *path, isk_error *err);

#ifdef __cplusplus
}
#endif

#endif
