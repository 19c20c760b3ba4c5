/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_files.c — writes the shear chain of structure_scaling.c as `fricreg-sim structure`
 * reads it, for the command line's benchmark at any size (bench/cli_structure.sh):
 *
 *   M.mtx         lumped storey masses, 1 kg (diagonal, symmetric storage)
 *   K.mtx         storey stiffness 10^4 N/m, fixed at the base (tridiagonal, symmetric
 *                 storage: its lower triangle, 2 n - 1 entries)
 *   J.mtx         k friction dampers on storey drifts spread evenly up the chain (general)
 *   mun.txt       their slip loads, 30 % of a rigid chain's storey shear at 3 m/s^2
 *   ground.txt    a_g(t) = 3 sin(2 pi t) m/s^2 for 20 s, every 5 ms
 *   rayleigh.txt  the Rayleigh coefficients 0,0.002 (C = 0.002 s K)
 *
 *   usage: fricreg-bench-structure-files N K DIR
 * Exit status 0, or 1 (a file cannot be written, or a bad argument). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define STOREY_K 1e4
#define GROUND_A 3.0
#define RECORD_DT 0.005
#define RECORD_SAMPLES 4001
#define TWO_PI 6.283185307179586

static size_t n_storeys, n_dampers;

static void write_mass(FILE *f)
{
    fprintf(f, "%%%%MatrixMarket matrix coordinate real symmetric\n%% storey masses (kg)\n");
    fprintf(f, "%zu %zu %zu\n", n_storeys, n_storeys, n_storeys);
    for (size_t i = 1; i <= n_storeys; i++)
        fprintf(f, "%zu %zu 1\n", i, i);
}

/* K_ii = 2 k (k at the top), K_i+1,i = -k: column by column, as a sparse code writes it. */
static void write_stiffness(FILE *f)
{
    fprintf(f, "%%%%MatrixMarket matrix coordinate real symmetric\n%% storey stiffness (N/m)\n");
    fprintf(f, "%zu %zu %zu\n", n_storeys, n_storeys, 2 * n_storeys - 1);
    for (size_t j = 1; j <= n_storeys; j++) {
        fprintf(f, "%zu %zu %.17g\n", j, j, j < n_storeys ? 2.0 * STOREY_K : STOREY_K);
        if (j < n_storeys)
            fprintf(f, "%zu %zu %.17g\n", j + 1, j, -STOREY_K);
    }
}

/* Damper d on the drift of storey p_d = (d + 1/2) n / k (from 0): J row e_p - e_(p-1). */
static size_t damper_storey(size_t d)
{
    return (size_t)(((double)d + 0.5) * (double)n_storeys / (double)n_dampers);
}

static void write_contacts(FILE *f)
{
    size_t entries = 0;
    for (size_t d = 0; d < n_dampers; d++)
        entries += damper_storey(d) > 0 ? 2 : 1;
    fprintf(f, "%%%%MatrixMarket matrix coordinate real general\n%% dampers on storey drifts\n");
    fprintf(f, "%zu %zu %zu\n", n_dampers, n_storeys, entries);
    for (size_t d = 0; d < n_dampers; d++) {
        size_t p = damper_storey(d);
        if (p > 0)
            fprintf(f, "%zu %zu -1\n", d + 1, p);
        fprintf(f, "%zu %zu 1\n", d + 1, p + 1);
    }
}

static void write_bounds(FILE *f)
{
    for (size_t d = 0; d < n_dampers; d++)
        fprintf(f, "%.17g\n", 0.3 * GROUND_A * (double)(n_storeys - damper_storey(d)));
}

static void write_ground(FILE *f)
{
    for (int k = 0; k < RECORD_SAMPLES; k++)
        fprintf(f, "%.3f %.17g\n", k * RECORD_DT, GROUND_A * sin(TWO_PI * k * RECORD_DT));
}

static void write_rayleigh(FILE *f)
{
    fprintf(f, "0,0.002\n");
}

int main(int argc, char **argv)
{
    if (argc != 4 || (n_storeys = strtoul(argv[1], NULL, 10)) < 2 ||
        (n_dampers = strtoul(argv[2], NULL, 10)) < 1 || n_dampers > n_storeys) {
        fprintf(stderr, "usage: fricreg-bench-structure-files N K DIR (2 <= N, 1 <= K <= N)\n");
        return 1;
    }
    static const char *const names[] = {"M.mtx",   "K.mtx",      "J.mtx",
                                        "mun.txt", "ground.txt", "rayleigh.txt"};
    void (*const writers[])(FILE *) = {write_mass,   write_stiffness, write_contacts,
                                       write_bounds, write_ground,    write_rayleigh};
    for (int k = 0; k < 6; k++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", argv[3], names[k]);
        FILE *f = fopen(path, "w");
        if (f == NULL) {
            perror(path);
            return 1;
        }
        writers[k](f);
        if (fclose(f) != 0) {
            perror(path);
            return 1;
        }
    }
    return 0;
}
