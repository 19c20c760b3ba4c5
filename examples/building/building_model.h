/* SPDX-License-Identifier: GPL-3.0-or-later */
/* building_model.h — the ten-storey shear building, in one place for the program
 * that writes its files (make_building.c) and the one that builds it in code (building.c):
 * storey mass 1e5 kg, storey stiffness 1e8 N/m, 5 % Rayleigh damping in modes 1 and 2, a
 * friction damper on every storey drift slipping at 5 % of the weight above, and the ground
 * acceleration 0.3 g sin(pi t/10) sin(2 pi t) for 10 s, sampled every 1 ms.
 * Matrices are dense and row-major, floor 1 first (floor 0 is the ground). */
#ifndef BUILDING_MODEL_H
#define BUILDING_MODEL_H

#include <math.h>

enum { BUILDING_STOREYS = 10, BUILDING_RECORD_STEPS = 10000 };

static const double building_mass = 1e5, building_stiffness = 1e8, building_g = 9.81,
                    building_zeta = 0.05, building_record_dt = 1e-3;
static const double building_pi = 3.14159265358979323846;

/* Storey i's spring joins floors i - 1 and i: K is tridiagonal, the top floor has one spring. */
static double building_K(int i, int j)
{
    if (i == j)
        return i < BUILDING_STOREYS - 1 ? 2.0 * building_stiffness : building_stiffness;
    return i == j + 1 || j == i + 1 ? -building_stiffness : 0.0;
}

/* Damper i slides with the drift of storey i, u_i - u_(i-1): zdot_i = J_i u'. */
static double building_J(int i, int k)
{
    return k == i ? 1.0 : k == i - 1 ? -1.0 : 0.0;
}

/* Slip load of damper i (N): 5 % of the weight of the floors i, ..., top. */
static double building_mun(int i)
{
    return 0.05 * building_g * building_mass * (BUILDING_STOREYS - i);
}

/* Ground acceleration sample k = 0, ..., BUILDING_RECORD_STEPS (m/s^2), at t = k dt_rec. */
static double building_ground(int k)
{
    double t = building_record_dt * k;
    return 0.3 * building_g * sin(building_pi * t / 10.0) * sin(2.0 * building_pi * t);
}

/* Rayleigh coefficients of damping zeta in modes 1 and 2, whose circular frequencies are
 * w_j = 2 sqrt(k/m) sin((2j - 1) pi/(2(2N + 1))) (fixed base, free top):
 * a0 = 2 zeta w1 w2/(w1 + w2) (1/s), a1 = 2 zeta/(w1 + w2) (s). */
static void building_rayleigh(double *a0, double *a1)
{
    double n = BUILDING_STOREYS, w0 = 2.0 * sqrt(building_stiffness / building_mass);
    double w1 = w0 * sin(building_pi / (2.0 * (2.0 * n + 1.0)));
    double w2 = w0 * sin(3.0 * building_pi / (2.0 * (2.0 * n + 1.0)));
    *a0 = 2.0 * building_zeta * w1 * w2 / (w1 + w2);
    *a1 = 2.0 * building_zeta / (w1 + w2);
}

#endif /* BUILDING_MODEL_H */
