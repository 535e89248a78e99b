/* SPDX-License-Identifier: MIT */
/* src/scene/snapshot_internal.h — a snapshot's parts, shared by the copy
 * in memory (effect_snapshot.c) and the exact file (snapshot_bytes.c).
 *
 * What a run depends on besides its definition is listed once, as rows:
 * a field of isk_effect, fx_group, isk_potential or isk_probe_reading and
 * its type.  The copy in memory packs each row's bytes; the file writes
 * each as 8 little-endian bytes; both walk the same tables:
 *
 *     unsigned char *packed = malloc(isk__snap_rows_size(isk__snap_group_rows, isk__snap_ngroup_rows));
 *     isk__snap_rows_out(isk__snap_group_rows, isk__snap_ngroup_rows, group, packed);  // copy out
 *     isk__snap_rows_in(isk__snap_group_rows, isk__snap_ngroup_rows, packed, group);   // put back
 */
#ifndef ISKRA_SCENE_SNAPSHOT_INTERNAL_H
#define ISKRA_SCENE_SNAPSHOT_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "effect_internal.h"
#include "iskra/snapshot.h"

/* ROW_F64N: a double that may be NaN (a potential energy without a law) */
typedef enum { ROW_F64, ROW_U64, ROW_SIZE, ROW_INT, ROW_LONG, ROW_U32, ROW_F64N } row_type;
extern const size_t isk__snap_row_bytes[]; /* a row's bytes in memory, by row_type */

typedef struct state_row {
    const char *name;
    size_t offset;
    row_type type;
} state_row;

/* the tables (effect_snapshot.c) and their lengths */
extern const state_row isk__snap_group_rows[], isk__snap_effect_rows[], isk__snap_potential_rows[],
    isk__snap_reading_rows[];
extern const int isk__snap_ngroup_rows, isk__snap_neffect_rows, isk__snap_npot_rows, isk__snap_nreading_rows;

typedef struct snap_group {
    unsigned char *state; /* group_rows, packed */
    isk_particles store;
    fx_event *events;
    size_t nevents;
} snap_group;

/* A probe: its reading (the name pointer is the effect's), a gate's window. */
typedef struct snap_probe {
    isk_probe_reading r;
    int ring_n, ring_head, ring_used;
    uint64_t *ring; /* 2 * ring_n: forward then backward crossings per frame */
    double *ring_t; /* ring_n: each frame's length */
} snap_probe;

struct isk_snapshot {
    isk_effect_def def;
    int nprobes;
    snap_probe *probes;
    unsigned char *effect_state; /* effect_rows, packed */
    size_t npots;
    isk_potential *pots;
    int *pot_force;
    int ngroups;
    snap_group *groups;
};

/* The bytes the rows take in memory, packed; the rows of `from` into
 * packed bytes and back. */
size_t isk__snap_rows_size(const state_row *rows, int n);
void isk__snap_rows_out(const state_row *rows, int n, const void *from, unsigned char *to);
void isk__snap_rows_in(const state_row *rows, int n, const unsigned char *from, void *to);
/* An empty snapshot for ngroups groups and npots potentials (NULL: no
 * memory); room for n probes with rings of ring_n[i] frames, all zero
 * (ISK_ERR_NOMEM). */
isk_snapshot *isk__snap_new(int ngroups, size_t npots);
isk_status isk__snap_probes_new(isk_snapshot *s, int n, const int *ring_n);

#endif
