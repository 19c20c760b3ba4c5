/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_deadline.h — `fricreg-sim hb` and `nma`'s --max-seconds: a wall-clock limit on the
 * harmonic-balance call, enforced by the driver's monitor (fricreg_hb_set_monitor), which stops
 * the call at its next Newton step once the limit has passed. */
#ifndef FRICREG_CLI_HB_DEADLINE_H
#define FRICREG_CLI_HB_DEADLINE_H

#include "cli.h"
#include "fricreg_hb.h"

struct cli_deadline {
    double seconds; /* --max-seconds, >= 0 */
    int given;
    double end; /* CLOCK_MONOTONIC's time it passes, in seconds */
    int passed; /* the monitor stopped the call */
};

/* --max-seconds's row over d (a struct cli_deadline *). */
#define CLI_DEADLINE_OPTION(d)                                                                  \
    {                                                                                           \
        "--max-seconds", CLI_NONNEGATIVE,                                                       \
            .slot = &(d)->seconds, .given = &(d)->given, .meta = "S",                           \
            .help = "stop after S seconds of wall-clock time, at the next Newton step, with a " \
                    "message and exit status 1 (nothing on stdout); 0 stops at the first step", \
            .dflt = "none"                                                                      \
    }

/* Starts the clock now and installs the monitor on hb, when --max-seconds was given. */
void cli_deadline_start(struct cli_deadline *d, fricreg_hb *hb);

/* After a failed call: whether the limit stopped it, then one line on stderr saying so
 * ("fricreg-sim: COMMAND: --max-seconds S passed: ..."), with what names the progress. */
int cli_deadline_report(const struct cli_deadline *d, const char *command, const char *progress);

#endif
