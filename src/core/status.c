/* SPDX-License-Identifier: MIT */
/* Status strings and the detailed error helper. */
#include "iskra/status.h"

#include <stdarg.h>
#include <stdio.h>

const char *isk_status_str(isk_status s)
{
    switch (s) {
    case ISK_OK: return "success";
    case ISK_ERR_NULL: return "a required pointer argument was NULL";
    case ISK_ERR_SIZE: return "size or count is zero, negative or too large";
    case ISK_ERR_RANGE: return "value out of range";
    case ISK_ERR_NAN: return "NaN or infinity where a finite number is required";
    case ISK_ERR_NOMEM: return "out of memory";
    case ISK_ERR_IO: return "input/output error";
    case ISK_ERR_FORMAT: return "malformed input";
    case ISK_ERR_UNSUPPORTED: return "not supported";
    case ISK_ERR_DISPLAY: return "window system error";
    case ISK_ERR_FULL: return "container is full";
    case ISK_ERR_MISMATCH: return "differs from the reference image";
    case ISK_STATUS_COUNT: break;
    }
    return "unknown status";
}

isk_status isk_error_set(isk_error *err, isk_status status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        err->status = status;
        err->message[0] = 0;
        if (!fmt)
            return status;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return status;
}
