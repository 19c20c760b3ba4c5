/* SPDX-License-Identifier: GPL-3.0-or-later */
/* membrane.c — the tests' friction interface on a membrane (membrane.h). */
#include "membrane.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define MAX_NODES 16384
#define SAMPLES 400

/* K's upper triangle in CSC: column j holds its neighbours above and left, then itself. */
static size_t stiffness(size_t side, double spring_k, int64_t kp[], int64_t ki[], double kx[])
{
    size_t q = 0;
    for (size_t j = 0; j < side * side; j++) {
        size_t r = j / side, c = j % side;
        double neighbours = (r > 0) + (r + 1 < side) + (c > 0) + (c + 1 < side);
        kp[j] = (int64_t)q;
        if (r > 0) {
            ki[q] = (int64_t)(j - side);
            kx[q++] = -spring_k;
        }
        if (c > 0) {
            ki[q] = (int64_t)(j - 1);
            kx[q++] = -spring_k;
        }
        ki[q] = (int64_t)j;
        kx[q++] = neighbours * spring_k + 1e3;
    }
    kp[side * side] = (int64_t)q;
    return q;
}

/* J's rows in CSR: contact j on node j, less the node before it in its column past the edge. */
static void contacts(size_t side, size_t m, int64_t jp[], int64_t ji[], double jx[], double mun[])
{
    size_t q = 0;
    for (size_t j = 0; j < m; j++) {
        jp[j] = (int64_t)q;
        if (j >= side) {
            ji[q] = (int64_t)(j - side);
            jx[q++] = -1.0;
        }
        ji[q] = (int64_t)j;
        jx[q++] = 1.0;
        mun[j] = j < side ? 20.0 : 4.0;
    }
    jp[m] = (int64_t)q;
}

fricreg_structure *test_membrane(size_t side, size_t rows, double spring_k, int solver)
{
    static int64_t kp[MAX_NODES + 1], ki[3 * MAX_NODES], mp[MAX_NODES + 1], jp[MAX_NODES + 1],
        ji[2 * MAX_NODES];
    static double kx[3 * MAX_NODES], mx[MAX_NODES], jx[2 * MAX_NODES], mun[MAX_NODES],
        ones[MAX_NODES], ag[SAMPLES];
    size_t n = side * side, m = rows * side;
    if (side < 2 || rows < 1 || rows > side || n > MAX_NODES)
        return NULL;
    stiffness(side, spring_k, kp, ki, kx);
    contacts(side, m, jp, ji, jx, mun);
    for (size_t j = 0; j <= n; j++)
        mp[j] = (int64_t)j;
    for (size_t j = 0; j < n; j++)
        mx[j] = ones[j] = 1.0;
    for (size_t k = 0; k < SAMPLES; k++)
        ag[k] = 0.35 * 9.81 * sin(6.283185307179586 * 4.0 * (double)k * TEST_MEMBRANE_DT);
    fricreg_structure *s = NULL;
    if (fricreg_structure_create(n, m, &s) != FRICREG_OK)
        return NULL;
    int ok = fricreg_structure_set_mass_csc(s, n, 0, mp, mp, mx) == FRICREG_OK &&
             fricreg_structure_set_stiffness_csc(s, n, FRICREG_SPARSE_UPPER, kp, ki, kx) ==
                 FRICREG_OK &&
             fricreg_structure_set_rayleigh(s, 0.0, 0.002) == FRICREG_OK &&
             fricreg_structure_set_contacts_csr(s, m, n, 0, jp, ji, jx) == FRICREG_OK &&
             fricreg_structure_set_bounds(s, m, mun) == FRICREG_OK &&
             fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 1e-3) == FRICREG_OK &&
             fricreg_structure_set_influence(s, n, ones) == FRICREG_OK &&
             fricreg_structure_set_ground_accel(s, 0.0, TEST_MEMBRANE_DT, SAMPLES, ag) ==
                 FRICREG_OK &&
             fricreg_structure_set_contact_solver(s, solver) == FRICREG_OK;
    if (!ok) {
        fricreg_structure_free(s);
        return NULL;
    }
    return s;
}
