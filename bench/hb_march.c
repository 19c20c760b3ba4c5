/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_march.c — the cost of harmonic balance on a law it knows only by its eval (the march of
 * src/joint/aft_march.c) against the exact AFT of the same element, in one process: NLvib's
 * chain (tests/support/hb_chain.h, H = 7) with jenkins elements (exact) or jenkins_2d elements
 * (marched), continued from 0.5 to 2 rad/s with the defaults, with and without stability:
 * points, median CPU seconds, the ratio, and each dof's located peak.
 * Usage: fricreg-bench-hb-march [repeats]. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "fricreg_hb.h"
#include "hb_chain.h"

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    if (repeats < 1 || repeats > 64)
        repeats = 3;
    for (int stability = 0; stability <= 1; stability++) {
        double seconds[2], peaks[2][3][2], t[64];
        for (int marched = 0; marched <= 1; marched++) {
            fricreg_hb *hb = hb_chain(marched, stability);
            if (hb == NULL)
                return 1;
            size_t nq = hb_chain_nq(marched);
            int status = 0;
            for (int r = 0; r < repeats; r++) {
                double t0 = bench_cpu_seconds();
                status = fricreg_hb_continue(hb, 0.5, 2.0, nq, NULL);
                t[r] = bench_cpu_seconds() - t0;
            }
            seconds[marched] = bench_median(t, (size_t)repeats);
            for (size_t dof = 0; dof < 3; dof++)
                if (status != FRICREG_OK || fricreg_hb_peak(hb, dof, &peaks[marched][dof][0],
                                                            &peaks[marched][dof][1]) != FRICREG_OK)
                    peaks[marched][dof][0] = peaks[marched][dof][1] = NAN;
            printf("%s, stability %s: status %d, %zu points, %.3g s\n",
                   marched ? "jenkins_2d (marched)" : "jenkins (exact)", stability ? "on" : "off",
                   status, fricreg_hb_points(hb), seconds[marched]);
            fricreg_hb_free(hb);
        }
        printf("  marched / exact: %.0f\n", seconds[1] / seconds[0]);
        for (int dof = 0; dof < 3; dof++)
            printf("  dof %d's peak: Omega %.7g against %.7g, RMS %.8g against %.8g (%.2g)\n",
                   dof + 1, peaks[1][dof][0], peaks[0][dof][0], peaks[1][dof][1], peaks[0][dof][1],
                   fabs(peaks[1][dof][1] - peaks[0][dof][1]) / peaks[0][dof][1]);
    }
    return 0;
}
