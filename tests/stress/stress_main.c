/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress_main.c — fricreg-stress: the numerical stress suite (docs/reliability.md).
 *
 *   fricreg-stress [--full] [--seed S] [long|extreme|exact|conditioning|disk_chain ...]
 *
 * With no group named, runs them all. The short default is ctest's (label stress); --full is
 * bench/stress.sh's: 10^7 steps per system, the chain up to n = 10^6, thousands of random
 * cases. Prints one table per group with its worst figures; exits 1 if any check failed,
 * 2 on a bad argument. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "stress.h"

static const struct stress_mode short_mode = {0, 1000000, 300, 8, 20, 1e4, 8, 2000, 20261121, 1e4};
static const struct stress_mode full_mode = {1,   10000000, 2000,  40,       100,
                                             1e6, 40,       40000, 20261121, 1e6};

struct group {
    const char *name;
    int (*run)(const struct stress_mode *mode);
};

static const struct group groups[] = {
    {"long", stress_long_runs},        {"extreme", stress_extreme},
    {"exact", stress_exact_random},    {"conditioning", stress_conditioning},
    {"disk_chain", stress_disk_chain},
};
#define NGROUPS (sizeof groups / sizeof groups[0])

static int usage(void)
{
    fprintf(stderr, "usage: fricreg-stress [--full] [--seed S] "
                    "[long|extreme|exact|conditioning|disk_chain ...]\n");
    return 2;
}

int main(int argc, char **argv)
{
    /* The reference computations (GSL quadrature, QR) report by status here, and this program
     * is single-threaded: switching GSL's aborting handler off is this program's own choice. */
    gsl_set_error_handler_off();
    struct stress_mode mode = short_mode;
    int selected[NGROUPS] = {0}, any = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--full") == 0) {
            uint64_t seed = mode.seed;
            mode = full_mode;
            mode.seed = seed;
        } else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
            mode.seed = strtoull(argv[++i], NULL, 10);
        } else {
            size_t g = 0;
            while (g < NGROUPS && strcmp(argv[i], groups[g].name) != 0)
                g++;
            if (g == NGROUPS)
                return usage();
            selected[g] = any = 1;
        }
    }
    printf("fricreg-stress: %s mode, seed %llu\n\n", mode.full ? "full" : "short",
           (unsigned long long)mode.seed);
    int failures = 0;
    for (size_t g = 0; g < NGROUPS; g++)
        if (!any || selected[g])
            failures += groups[g].run(&mode);
    printf("%s: %d failed check%s\n", failures ? "FAILED" : "passed", failures,
           failures == 1 ? "" : "s");
    return failures ? 1 : 0;
}
