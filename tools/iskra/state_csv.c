/* SPDX-License-Identifier: MIT */
/* iskra render's particle state as CSV, and the removal report (see
 * state_csv.h). */
#include "state_csv.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cleanup.h"
#include "outpath.h"
#include "scene_args.h"

int state_args_take(state_opts *o, int argc, char **argv, int *i)
{
    const char *v;
    int r;
    if ((r = arg_value("render", argc, argv, i, "--state-every", &v)) != 0) {
        if (r < 0 || !arg_long("render", "--state-every", v, 1, 100000000, &o->every))
            return -1;
        return 1;
    }
    if ((r = arg_value("render", argc, argv, i, "--state", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!*v) {
            fprintf(stderr, "iskra render: --state: empty file name\n");
            return -1;
        }
        o->path = v;
        return 1;
    }
    return 0;
}

int state_args_check(const state_opts *o, const char *out_dir)
{
    if (o->every && !out_dir) {
        fprintf(stderr, "iskra render: --state-every needs --out-dir (the states go beside the frames)\n");
        return 2;
    }
    return 0;
}

static int rows(FILE *f, const isk_effect *fx)
{
    const isk_effect_def *d = isk_effect_definition(fx);
    if (fprintf(f, "emitter,index,x,y,vx,vy,mass,age,life\n") < 0)
        return 0;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        for (size_t i = 0; i < p->count; i++)
            if (fprintf(f, "%s,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", d->emitters[g].name, i, p->x[i],
                        p->y[i], p->vx[i], p->vy[i], p->m[i], p->age[i], p->life[i]) < 0)
                return 0;
    }
    return 1;
}

int state_csv_write(const isk_effect *fx, const char *path)
{
    isk_outfile o;
    if (outpath_make_parents("render", path) || cleanup_outfile_open(&o, path))
        return 1;
    if (!rows(o.f, fx)) {
        cleanup_outfile_abort(&o);
        fprintf(stderr, "iskra render: %s: write failed: %s\n", path, strerror(errno ? errno : EIO));
        return 1;
    }
    return cleanup_outfile_commit(&o);
}

int state_after_frame(state_opts *o, const isk_effect *fx, const char *out_dir, long f)
{
    if (!o->every || !out_dir || f % o->every != 0)
        return 0;
    char path[4200];
    snprintf(path, sizeof path, "%s/" STATE_PREFIX "%06ld" STATE_SUFFIX, out_dir, f);
    /* written and counted together: a file the message after a signal
     * does not count is never in place */
    sigset_t held;
    cleanup_hold(&held);
    int failed = state_csv_write(fx, path);
    if (!failed) {
        if (o->count++ == 0)
            o->first = f;
        cleanup_note(CLEANUP_STATES, out_dir, o->first, f, o->every, o->count);
    }
    cleanup_release(&held);
    return failed;
}

size_t state_report_removed(const isk_effect *fx)
{
    const isk_effect_def *d = isk_effect_definition(fx);
    size_t all = 0;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        size_t k = isk_effect_removed_nonfinite(fx, g);
        if (k)
            fprintf(stderr, "iskra render: emitter '%s': %zu particle%s removed: %s state went non-finite\n",
                    d->emitters[g].name, k, k == 1 ? "" : "s", k == 1 ? "its" : "their");
        all += k;
    }
    return all;
}

int state_finish(const state_opts *o, const isk_effect *fx)
{
    int rc = o->path ? state_csv_write(fx, o->path) : 0;
    state_report_removed(fx);
    return rc;
}
