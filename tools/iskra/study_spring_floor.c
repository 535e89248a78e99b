/* SPDX-License-Identifier: MIT */
/* `iskra bench accuracy --only spring-floor`: the energy a bounce keeps
 * when the force varies along the path.
 *
 * A spring on a restitution-1 floor (iskra/problems.h,
 * isk_problem_spring_floor): 100 s, about 48 bounces, every integrator at
 * dt 1/60 and 1/240, with the floor and without it.  The table gives the
 * relative change of the energy per bounce with the floor, the same over
 * as many bounces without it (the integrator's own drift), and their
 * difference: what the bounces themselves change.  spring_floor.csv. */
#include <math.h>
#include <stdio.h>

#include "iskra/integrate.h"
#include "iskra/problems.h"
#include "study.h"

int study_spring_floor(const study_opts *o)
{
    static const double dts[] = {1.0 / 60, 1.0 / 240};
    static const int per_second[] = {60, 240};
    const double seconds = 100.0; /* --quick too: two integrators' runs cost milliseconds */
    study_buf csv = {0};
    study_printf(&csv, "integrator,dt,bounces,per_bounce,without_floor,bounce_itself\n");
    printf("-- spring on a floor: P = 0, kQ = 4 (omega 2), restitution-1 floor, %g s\n", seconds);
    printf("  relative energy change per bounce: with the floor | without it (the integrator's own) | the bounce's\n");
    printf("  %-11s %6s %8s %12s %12s %12s\n", "integrator", "dt", "bounces", "with floor", "without", "bounce");
    int rc = 0;
    for (int m = 0; m < ISK_INTEGRATOR_COUNT && !rc; m++)
        for (int k = 0; k < 2; k++) {
            isk_spring_floor with, without;
            isk_status st = isk_problem_spring_floor((isk_integrator)m, dts[k], seconds, 1, &with);
            if (st == ISK_OK)
                st = isk_problem_spring_floor((isk_integrator)m, dts[k], seconds, 0, &without);
            if (st != ISK_OK || with.bounces == 0) {
                fprintf(stderr, "iskra bench: spring-floor: %s: %s\n", isk_integrator_name((isk_integrator)m),
                        st != ISK_OK ? isk_status_str(st) : "no bounce");
                rc = 1;
                break;
            }
            const double per = pow(1.0 + with.change, 1.0 / with.bounces) - 1.0;
            const double own = pow(1.0 + without.change, 1.0 / with.bounces) - 1.0;
            printf("  %-11s 1/%-4d %8d %+12.3e %+12.3e %+12.3e\n", isk_integrator_name((isk_integrator)m),
                   per_second[k], with.bounces, per, own, per - own);
            study_printf(&csv, "%s,1/%d,%d,%.6e,%.6e,%.6e\n", isk_integrator_name((isk_integrator)m), per_second[k],
                         with.bounces, per, own, per - own);
        }
    if (!rc)
        rc = study_write_text(o, "spring_floor.csv", &csv);
    study_buf_free(&csv);
    return rc;
}
