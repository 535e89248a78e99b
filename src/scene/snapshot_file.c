/* SPDX-License-Identifier: MIT */
/* A snapshot's file (iskra/snapshot.h): its bytes written through
 * iskra/outfile.h (whole or not at all), and read back whole. */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/outfile.h"
#include "iskra/snapshot.h"

/* Largest snapshot file read: a whole pool of 2^28 particles with every
 * column, and far beyond what the memory budget lets an effect hold. */
#define SNAPSHOT_MAX_BYTES ((uint64_t)(SIZE_MAX / 2) < ((uint64_t)1 << 34) ? SIZE_MAX / 2 : (size_t)((uint64_t)1 << 34))

isk_status isk_snapshot_save(const isk_snapshot *snap, const char *path, isk_error *err)
{
    if (!snap || !path || !*path)
        return isk_error_set(err, ISK_ERR_NULL, "isk_snapshot_save: NULL argument or empty path");
    unsigned char *bytes;
    size_t n;
    isk_status s = isk_snapshot_encode(snap, &bytes, &n, err);
    if (s != ISK_OK)
        return s;
    isk_outfile o;
    if ((s = isk_outfile_open(&o, path, err)) == ISK_OK) {
        if (fwrite(bytes, 1, n, o.f) != n) {
            const int e = errno;
            isk_outfile_abort(&o);
            s = isk_error_set(err, ISK_ERR_IO, "%s: cannot write: %s", path, strerror(e));
        } else {
            s = isk_outfile_commit(&o, err);
        }
    }
    free(bytes);
    return s;
}

isk_status isk_snapshot_load(isk_snapshot **out, const char *path, isk_error *err)
{
    if (!out || !path)
        return isk_error_set(err, ISK_ERR_NULL, "isk_snapshot_load: NULL argument");
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return isk_error_set(err, ISK_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    unsigned char *b = NULL;
    size_t n = 0, cap = 0;
    isk_status s = ISK_OK;
    for (;;) {
        if (n == cap) {
            if (cap >= SNAPSHOT_MAX_BYTES) {
                s = isk_error_set(err, ISK_ERR_FORMAT, "%s: larger than any snapshot", path);
                break;
            }
            size_t grow = cap ? cap * 2 : 65536;
            if (grow > SNAPSHOT_MAX_BYTES)
                grow = SNAPSHOT_MAX_BYTES;
            unsigned char *nb = realloc(b, grow);
            if (!nb) {
                s = isk_error_set(err, ISK_ERR_NOMEM, "%s: out of memory", path);
                break;
            }
            b = nb;
            cap = grow;
        }
        size_t got = fread(b + n, 1, cap - n, f);
        n += got;
        if (got == 0) {
            if (ferror(f))
                s = isk_error_set(err, ISK_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
            break;
        }
    }
    fclose(f);
    if (s == ISK_OK)
        s = isk_snapshot_decode(out, b, n, path, err);
    free(b);
    return s;
}
