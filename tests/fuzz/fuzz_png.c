/* SPDX-License-Identifier: MIT */
/* libFuzzer target: bytes -> isk_png_read_memory (the bounded PNG reader),
 * and what it accepts written back and read again, which must give the
 * same pixels.  Built and run by `make fuzz FUZZ_TARGET=png` (clang with
 * -fsanitize=fuzzer,address,undefined) and by `make fuzz-smoke`; seeds in
 * tests/fuzz/png_corpus/, crashers kept in tests/fuzz/png_regressions/ and
 * replayed by tests/test_png_fuzz_regressions.c.  The pixel cap keeps each
 * input cheap: a header may declare any size, only the cap is decoded. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "iskra/png.h"

#define MAX_PIXELS (1024 * 1024)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    isk_canvas c, again;
    isk_error err;
    if (isk_png_read_memory(&c, data, size, "fuzz.png", MAX_PIXELS, &err) != ISK_OK) {
        if (c.pixels || !err.message[0])
            abort(); /* a failure must leave no canvas and say why */
        return 0;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (f && isk_png_write_stream(&c, f, "fuzz.png", &err) == ISK_OK && fflush(f) == 0) {
        if (isk_png_read_memory(&again, buf, len, "again.png", MAX_PIXELS, &err) != ISK_OK ||
            !isk_canvas_equal(&c, &again))
            abort(); /* our own output must read back exactly */
        isk_canvas_free(&again);
    }
    if (f)
        fclose(f);
    free(buf);
    isk_canvas_free(&c);
    return 0;
}
