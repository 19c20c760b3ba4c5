/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_deadline.c — --max-seconds by the driver's monitor (hb_deadline.h), on POSIX's monotonic
 * clock: the wall clock's settings do not move it. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "hb_deadline.h"

/* CLOCK_MONOTONIC in seconds (a double keeps microseconds over decades of uptime); without a
 * clock +inf, so that a limit stops the call at once rather than never. */
static double now_seconds(void)
{
    struct timespec now;
    if (clock_gettime(CLOCK_MONOTONIC, &now) != 0)
        return INFINITY;
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

static int monitor(void *user, int64_t iterations, double parameter, double residual)
{
    (void)iterations, (void)parameter, (void)residual;
    struct cli_deadline *d = user;
    d->passed = now_seconds() >= d->end; /* the clock never runs back: 0 s stops at once */
    return d->passed;
}

void cli_deadline_start(struct cli_deadline *d, fricreg_hb *hb)
{
    d->passed = 0;
    if (!d->given)
        return;
    d->end = now_seconds() + d->seconds;
    fricreg_hb_set_monitor(hb, monitor, d);
}

int cli_deadline_report(const struct cli_deadline *d, const char *command, const char *progress)
{
    if (!d->passed)
        return 0;
    fprintf(stderr, "fricreg-sim: %s: --max-seconds %g passed: stopped (%s)\n", command, d->seconds,
            progress);
    return 1;
}
