/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A structure's set-up against its steps: a fixed-free chain of n masses (tridiagonal K,
 * lumped M) with one friction contact at its tip, under a tip load that makes it slip. Timed,
 * as the median of REPEATS: (a) create, the model setters, 10 Newmark steps and the warnings'
 * judgement (fricreg_structure_warning_count: the dt check reads omega_1); (b) 10 more steps
 * of the same structure alone. The ratio a/b is what a short run pays for its set-up.
 * Usage: fricreg-bench-structure-setup [n ...] (default 500 2000 8000). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "fricreg_structure.h"

#define STEPS 10
#define REPEATS 7
#define DT 1e-3

static fricreg_structure *chain(int n)
{
    int64_t *kp = malloc((size_t)(n + 1) * sizeof *kp), *ki = malloc(2 * (size_t)n * sizeof *ki);
    int64_t *mp = malloc((size_t)(n + 1) * sizeof *mp), *mi = malloc((size_t)n * sizeof *mi);
    double *kv = malloc(2 * (size_t)n * sizeof *kv), *mv = malloc((size_t)n * sizeof *mv);
    double *p = calloc((size_t)n, sizeof *p);
    fricreg_structure *s = NULL;
    if (kp && ki && mp && mi && kv && mv && p && fricreg_structure_create((size_t)n, 1, &s) == 0) {
        int64_t nnz = 0;
        kp[0] = 0;
        for (int j = 0; j < n; j++) { /* upper triangle */
            mp[j] = mi[j] = j;
            mv[j] = 1.0;
            if (j > 0) {
                ki[nnz] = j - 1;
                kv[nnz++] = -1e4;
            }
            ki[nnz] = j;
            kv[nnz++] = j == n - 1 ? 1e4 : 2e4;
            kp[j + 1] = nnz;
        }
        mp[n] = n;
        int64_t jp[2] = {0, 1}, ji[1] = {n - 1};
        double jv[1] = {1.0}, mun = 1.0;
        p[n - 1] = 2.0;
        if (fricreg_structure_set_mass_csc(s, (size_t)n, FRICREG_SPARSE_UPPER, mp, mi, mv) ||
            fricreg_structure_set_stiffness_csc(s, (size_t)n, FRICREG_SPARSE_UPPER, kp, ki, kv) ||
            fricreg_structure_set_contacts_csr(s, 1, (size_t)n, 0, jp, ji, jv) ||
            fricreg_structure_set_bounds(s, 1, &mun) ||
            fricreg_structure_set_load(s, (size_t)n, p, 0.0, 0.0, 0, NULL)) {
            fricreg_structure_free(s);
            s = NULL;
        }
    }
    free(kp), free(ki), free(mp), free(mi), free(kv), free(mv), free(p);
    return s;
}

static int steps(fricreg_structure *s)
{
    for (int k = 0; k < STEPS; k++)
        if (fricreg_structure_step(s, DT) != FRICREG_OK)
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    int sizes[16] = {500, 2000, 8000}, nsizes = 3;
    if (argc > 1)
        for (nsizes = 0; nsizes < argc - 1 && nsizes < 16; nsizes++)
            sizes[nsizes] = atoi(argv[nsizes + 1]);
    printf("%8s %14s %14s %8s\n", "n", "setup+10 (s)", "10 steps (s)", "ratio");
    for (int i = 0; i < nsizes; i++) {
        double whole[REPEATS], alone[REPEATS];
        for (int r = 0; r < REPEATS; r++) {
            double t0 = bench_cpu_seconds();
            fricreg_structure *s = chain(sizes[i]);
            if (s == NULL || steps(s) != 0) {
                fprintf(stderr, "n = %d: the chain failed\n", sizes[i]);
                return 1;
            }
            if (getenv("NO_WARN") == NULL)
                (void)fricreg_structure_warning_count(s);
            double t1 = bench_cpu_seconds();
            if (steps(s) != 0)
                return 1;
            double t2 = bench_cpu_seconds();
            whole[r] = t1 - t0;
            alone[r] = t2 - t1;
            fricreg_structure_free(s);
        }
        double a = bench_median(whole, REPEATS), b = bench_median(alone, REPEATS);
        printf("%8d %14.4g %14.4g %8.3g\n", sizes[i], a, b, a / b);
    }
    return 0;
}
