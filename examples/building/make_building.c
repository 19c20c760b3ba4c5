/* SPDX-License-Identifier: GPL-3.0-or-later */
/* make_building.c — writes the ten-storey shear building as fricreg-sim structure
 * reads it, into the folder given (default "."):
 *
 *   M.mtx       storey masses 1e5 kg (diagonal, symmetric storage)
 *   K.mtx       storey stiffness 1e8 N/m (tridiagonal, symmetric storage)
 *   J.mtx       one friction damper per storey on its drift u_i - u_(i-1) (general, 10 x 10)
 *   mun.txt     slip loads: 5 % of the weight above each storey, 0.05 g m (10 - i) N
 *   ground.txt  a_g(t) = 0.3 g sin(pi t/10) sin(2 pi t) m/s^2 for 10 s, every 1 ms (the record
 *               ends there: the last 5 s of a 15 s run are free vibration)
 *   rayleigh.txt  a0,a1 of 5 % Rayleigh damping in modes 1 and 2 (1/s, s)
 *
 * The model itself is in building_model.h, shared with building.c, which builds it in code.
 * Every number is written with 17 digits, so the files hold the model's doubles exactly.
 * Exit status 0, or 1 if a file cannot be written. */
#include <stdio.h>

#include "building_model.h"

static FILE *open_in(const char *dir, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (f == NULL)
        perror(path);
    return f;
}

static int write_mass(FILE *f)
{
    fprintf(f,
            "%%%%MatrixMarket matrix coordinate real symmetric\n"
            "%% storey masses (kg)\n%d %d %d\n",
            BUILDING_STOREYS, BUILDING_STOREYS, BUILDING_STOREYS);
    for (int i = 1; i <= BUILDING_STOREYS; i++)
        fprintf(f, "%d %d %.17g\n", i, i, building_mass);
    return 0;
}

/* The lower triangle of K (symmetric storage). */
static int write_stiffness(FILE *f)
{
    fprintf(f,
            "%%%%MatrixMarket matrix coordinate real symmetric\n"
            "%% storey stiffness (N/m)\n%d %d %d\n",
            BUILDING_STOREYS, BUILDING_STOREYS, 2 * BUILDING_STOREYS - 1);
    for (int i = 0; i < BUILDING_STOREYS; i++)
        for (int j = i > 0 ? i - 1 : 0; j <= i; j++)
            fprintf(f, "%d %d %.17g\n", i + 1, j + 1, building_K(i, j));
    return 0;
}

static int write_contacts(FILE *f)
{
    fprintf(f,
            "%%%%MatrixMarket matrix coordinate real general\n"
            "%% damper i slides with the drift of storey i\n%d %d %d\n",
            BUILDING_STOREYS, BUILDING_STOREYS, 2 * BUILDING_STOREYS - 1);
    for (int i = 0; i < BUILDING_STOREYS; i++)
        for (int k = i > 0 ? i - 1 : 0; k <= i; k++)
            fprintf(f, "%d %d %.17g\n", i + 1, k + 1, building_J(i, k));
    return 0;
}

static int write_bounds(FILE *f)
{
    fprintf(f, "# slip load of each storey's damper (N): 5 %% of the weight above\n");
    for (int i = 0; i < BUILDING_STOREYS; i++)
        fprintf(f, "%.17g\n", building_mun(i));
    return 0;
}

static int write_ground(FILE *f)
{
    fprintf(f, "# t (s), a_g (m/s^2): 0.3 g sin(pi t/10) sin(2 pi t)\n");
    for (int k = 0; k <= BUILDING_RECORD_STEPS; k++)
        fprintf(f, "%.3f %.17g\n", building_record_dt * k, building_ground(k));
    return 0;
}

static int write_rayleigh(FILE *f)
{
    double a0, a1;
    building_rayleigh(&a0, &a1);
    fprintf(f, "%.17g,%.17g\n", a0, a1);
    return 0;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    static const char *const names[] = {"M.mtx",   "K.mtx",      "J.mtx",
                                        "mun.txt", "ground.txt", "rayleigh.txt"};
    int (*const writers[])(FILE *) = {write_mass,   write_stiffness, write_contacts,
                                      write_bounds, write_ground,    write_rayleigh};
    for (int k = 0; k < 6; k++) {
        FILE *f = open_in(dir, names[k]);
        if (f == NULL)
            return 1;
        writers[k](f);
        if (fclose(f) != 0) {
            perror(names[k]);
            return 1;
        }
    }
    return 0;
}
