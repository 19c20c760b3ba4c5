/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mtx_read.c — time and memory of `fricreg-sim structure`'s Matrix Market reader
 * (src/cli/matrix_market.c) on one file: wall and CPU seconds of cli_read_mtx, the process's
 * peak resident memory before and after (getrusage), and what was read. One file per process,
 * so that each peak is that file's (bench/cli_structure.sh).
 *
 *   usage: fricreg-bench-mtx-read FILE
 * Prints one line: file rows cols entries wall_s cpu_s peak_before_MiB peak_MiB. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <sys/resource.h>
#include <time.h>

#include "bench.h"
#include "matrix_market.h"

static double peak_mib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0;
}

static double wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: fricreg-bench-mtx-read FILE\n");
        return 1;
    }
    struct cli_sparse A = {0};
    double before = peak_mib(), wall = wall_seconds(), cpu = bench_cpu_seconds();
    if (cli_read_mtx("--mass", argv[1], 0, 0, &A) != 0)
        return 1; /* the reader said why */
    wall = wall_seconds() - wall;
    cpu = bench_cpu_seconds() - cpu;
    printf("%s %zu %zu %lld %.3f %.3f %.1f %.1f\n", argv[1], A.rows, A.cols,
           (long long)A.colptr[A.cols], wall, cpu, before, peak_mib());
    cli_sparse_free(&A);
    return 0;
}
