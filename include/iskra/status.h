/* SPDX-License-Identifier: MIT */
/* iskra/status.h — error codes shared by every module.
 *
 * Every iskra function that can fail returns an isk_status; ISK_OK is 0, so
 * `if (isk_canvas_init(&c, 600, 600) != ISK_OK)` works.  Nothing in the
 * library prints or aborts; isk_status_str() gives a one-line English
 * explanation.  Functions doing I/O also take an optional isk_error* that
 * receives a detailed message (file name, libpng's text).
 *
 * Example:
 *
 *     isk_canvas c;
 *     isk_status s = isk_canvas_init(&c, 0, 600);             // a zero width
 *     printf("%s\n", isk_status_str(s));                      // what ISK_ERR_SIZE means
 *     isk_error err;
 *     if (isk_png_read(&c, "missing.png", &err) != ISK_OK)    // I/O: a message too
 *         printf("%s: %s\n", isk_status_str(err.status), err.message);
 *     else
 *         isk_canvas_free(&c);
 */
#ifndef ISKRA_STATUS_H
#define ISKRA_STATUS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum isk_status {
    ISK_OK = 0,
    ISK_ERR_NULL,        /* a required pointer argument was NULL */
    ISK_ERR_SIZE,        /* a size or count is zero, negative or too large */
    ISK_ERR_RANGE,       /* a number lies outside its valid range */
    ISK_ERR_NAN,         /* NaN or infinity where a finite number is required */
    ISK_ERR_NOMEM,       /* memory allocation failed */
    ISK_ERR_IO,          /* a file could not be opened, written or renamed */
    ISK_ERR_FORMAT,      /* input is not in the expected format */
    ISK_ERR_UNSUPPORTED, /* valid request this build cannot honour */
    ISK_ERR_DISPLAY,     /* the window system (SDL) failed */
    ISK_ERR_FULL,        /* a fixed-capacity container is full */
    ISK_ERR_MISMATCH,    /* an image differs from its reference (iskra/refimg.h) */
    ISK_STATUS_COUNT
} isk_status;

/* Short English explanation of a status; never NULL. */
const char *isk_status_str(isk_status s);

/* Detailed error report filled in by functions that take one (may be NULL). */
typedef struct isk_error {
    isk_status status;
    char message[512];
} isk_error;

/* Sets err->status and a printf-style message (no-op when err is NULL);
 * returns status so callers can write `return isk_error_set(err, ...)`. */
isk_status isk_error_set(isk_error *err, isk_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#ifdef __cplusplus
}
#endif

#endif
