/* SPDX-License-Identifier: MIT */
/* iskra render --probes FILE.csv (see probes_csv.h). */
#include "probes_csv.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cleanup.h"
#include "iskra/probes.h"
#include "outpath.h"
#include "scene_args.h"

/* Room for every value of the largest reading (a histogram's bins, its
 * under and over). */
#define MAX_VALUES (ISK_PROBE_MAX_BINS + 8)

int probes_args_take(probes_opts *o, int argc, char **argv, int *i)
{
    const char *v;
    int r = arg_value("render", argc, argv, i, "--probes", &v);
    if (r == 0)
        return 0;
    if (r < 0)
        return -1;
    if (!*v) {
        fprintf(stderr, "iskra render: --probes: empty file name\n");
        return -1;
    }
    o->path = v;
    return 1;
}

static int failed(probes_opts *o)
{
    fprintf(stderr, "iskra render: %s: write failed: %s\n", o->path, strerror(errno ? errno : EIO));
    probes_abort(o);
    return 1;
}

/* One row's cells after its first: every probe's values in order, as
 * PROBE.VALUE names (the header) or as numbers.  0, or <0 when a write
 * failed. */
static int probe_cells(FILE *f, const isk_effect *fx, int names)
{
    for (int i = 0; i < isk_effect_probe_count(fx); i++) {
        isk_probe_reading r;
        isk_probe_value v[MAX_VALUES];
        isk_effect_probe_read(fx, i, &r);
        const int n = isk_probe_values(&r, v, MAX_VALUES);
        for (int k = 0; k < n && k < MAX_VALUES; k++)
            if ((names ? fprintf(f, ",%s.%s", r.name, v[k].name) : fprintf(f, ",%.17g", v[k].value)) < 0)
                return -1;
    }
    return fprintf(f, "\n") < 0 ? -1 : 0;
}

int probes_begin(probes_opts *o, const isk_effect *fx)
{
    if (!o->path)
        return 0;
    if (outpath_make_parents("render", o->path) || cleanup_outfile_open(&o->out, o->path))
        return 1;
    o->open = 1;
    if (fprintf(o->out.f, "frame,time") < 0 || probe_cells(o->out.f, fx, 1) < 0)
        return failed(o);
    return 0;
}

int probes_after_frame(probes_opts *o, const isk_effect *fx, long f)
{
    if (!o->open || f < 1)
        return 0;
    if (fprintf(o->out.f, "%ld,%.17g", f, isk_effect_time(fx)) < 0 || probe_cells(o->out.f, fx, 0) < 0)
        return failed(o);
    return 0;
}

int probes_finish(probes_opts *o)
{
    if (!o->open)
        return 0;
    o->open = 0;
    return cleanup_outfile_commit(&o->out);
}

void probes_abort(probes_opts *o)
{
    if (o->open)
        cleanup_outfile_abort(&o->out);
    o->open = 0;
}
