/* SPDX-License-Identifier: GPL-3.0-or-later */
/* make_building.c — writes the ten-storey shear building of issue 10 as fricreg-sim structure
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
 * The shear building's circular frequencies are w_j = 2 sqrt(k/m) sin((2j - 1) pi/(2(2N + 1)))
 * (fixed base, free top); Rayleigh damping zeta in modes 1 and 2 takes a0 = 2 zeta w1 w2/(w1 +
 * w2), a1 = 2 zeta/(w1 + w2). Exit status 0, or 1 if a file cannot be written. */
#include <math.h>
#include <stdio.h>

#define STOREYS 10

static const double mass = 1e5, stiffness = 1e8, g = 9.81, zeta = 0.05;
static const double pi = 3.14159265358979323846;

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
            STOREYS, STOREYS, STOREYS);
    for (int i = 1; i <= STOREYS; i++)
        fprintf(f, "%d %d %.17g\n", i, i, mass);
    return 0;
}

/* Storey i's spring joins floors i - 1 and i (floor 0 the ground): the top floor has one. */
static int write_stiffness(FILE *f)
{
    fprintf(f,
            "%%%%MatrixMarket matrix coordinate real symmetric\n"
            "%% storey stiffness (N/m)\n%d %d %d\n",
            STOREYS, STOREYS, 2 * STOREYS - 1);
    for (int i = 1; i <= STOREYS; i++) {
        fprintf(f, "%d %d %.17g\n", i, i, i < STOREYS ? 2.0 * stiffness : stiffness);
        if (i > 1)
            fprintf(f, "%d %d %.17g\n", i, i - 1, -stiffness);
    }
    return 0;
}

static int write_contacts(FILE *f)
{
    fprintf(f,
            "%%%%MatrixMarket matrix coordinate real general\n"
            "%% damper i slides with the drift of storey i\n%d %d %d\n",
            STOREYS, STOREYS, 2 * STOREYS - 1);
    for (int i = 1; i <= STOREYS; i++) {
        fprintf(f, "%d %d 1\n", i, i);
        if (i > 1)
            fprintf(f, "%d %d -1\n", i, i - 1);
    }
    return 0;
}

static int write_bounds(FILE *f)
{
    fprintf(f, "# slip load of each storey's damper (N): 5 %% of the weight above\n");
    for (int i = 0; i < STOREYS; i++)
        fprintf(f, "%.17g\n", 0.05 * g * mass * (STOREYS - i));
    return 0;
}

static int write_ground(FILE *f)
{
    fprintf(f, "# t (s), a_g (m/s^2): 0.3 g sin(pi t/10) sin(2 pi t)\n");
    for (int k = 0; k <= 10000; k++) {
        double t = 1e-3 * k;
        fprintf(f, "%.3f %.17g\n", t, 0.3 * g * sin(pi * t / 10.0) * sin(2.0 * pi * t));
    }
    return 0;
}

static int write_rayleigh(FILE *f)
{
    double n = STOREYS, w0 = 2.0 * sqrt(stiffness / mass);
    double w1 = w0 * sin(pi / (2.0 * (2.0 * n + 1.0)));
    double w2 = w0 * sin(3.0 * pi / (2.0 * (2.0 * n + 1.0)));
    fprintf(f, "%.17g,%.17g\n", 2.0 * zeta * w1 * w2 / (w1 + w2), 2.0 * zeta / (w1 + w2));
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
