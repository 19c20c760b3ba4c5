/* SPDX-License-Identifier: GPL-3.0-or-later */
/* building.c — the ten-storey building (docs/structural.md) from C, through fricreg_structure.h:
 * Newmark average acceleration, dt = 0.01 s, eps = 0.01 m/s, 15 s (10 s of ground motion, 5 s
 * free), law (4). Prints the peak roof displacement, each damper's energy and their total,
 * Newton's iterations per step (mean, max) and failures, and the energy balance.
 *
 * The model is built in code (building_model.h, the definitions make_building writes to the
 * Matrix Market files that `fricreg-sim structure` reads): a program that owns its model needs
 * no file format, and the example shows the library's calls alone. The files hold the same
 * doubles (17 digits), and the calls below are the CLI's, in its order, with its steps, so the
 * numbers equal the CLI's summary bit for bit (test example_building_c).
 *
 *   usage: building_c [DT [EPS]]        (defaults 0.01 s and 0.01 m/s)
 * Output: one "name value" line per number, 17 digits; exit status 0, or 1 on a failure. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "building_model.h"
#include "fricreg_structure.h"

enum { N = BUILDING_STOREYS };

static int fail(const fricreg_structure *s, const char *what)
{
    fprintf(stderr, "building: %s: %s\n", what, fricreg_structure_errmsg(s));
    return 1;
}

/* M, K and C = a0 M + a1 K (5 % in modes 1 and 2), the dampers on the storey drifts, their
 * slip loads, and the ground acceleration moving every floor (r = 1). */
static int set_up(fricreg_structure *s, double eps)
{
    static double M[N * N], K[N * N], J[N * N], mun[N], r[N], ag[BUILDING_RECORD_STEPS + 1];
    for (int i = 0; i < N; i++) {
        for (int j = 0; j < N; j++) {
            M[i * N + j] = i == j ? building_mass : 0.0;
            K[i * N + j] = building_K(i, j);
            J[i * N + j] = building_J(i, j);
        }
        mun[i] = building_mun(i);
        r[i] = 1.0;
    }
    for (int k = 0; k <= BUILDING_RECORD_STEPS; k++)
        ag[k] = building_ground(k);
    double a0, a1;
    building_rayleigh(&a0, &a1);
    if (fricreg_structure_set_mass(s, N, M) != FRICREG_OK)
        return fail(s, "mass");
    if (fricreg_structure_set_stiffness(s, N, K) != FRICREG_OK)
        return fail(s, "stiffness");
    if (fricreg_structure_set_rayleigh(s, a0, a1) != FRICREG_OK)
        return fail(s, "rayleigh");
    if (fricreg_structure_set_contacts(s, N, N, J) != FRICREG_OK)
        return fail(s, "contacts");
    if (fricreg_structure_set_bounds(s, N, mun) != FRICREG_OK)
        return fail(s, "bounds");
    if (fricreg_structure_set_influence(s, N, r) != FRICREG_OK)
        return fail(s, "influence");
    if (fricreg_structure_set_ground_accel(s, 0.0, building_record_dt, BUILDING_RECORD_STEPS + 1,
                                           ag) != FRICREG_OK)
        return fail(s, "ground");
    if (fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps) != FRICREG_OK)
        return fail(s, "law");
    return 0; /* Newmark average acceleration is the default scheme */
}

static double value(const fricreg_structure *s, int which)
{
    double v = 0.0;
    fricreg_structure_get_value(s, which, &v);
    return v;
}

/* Steps to t_end. Step k ends at k dt exactly: each is taken as one step of t_k - t, since
 * k dt - (k - 1) dt may exceed dt by a rounding, which would make fricreg_structure_run add a
 * tiny step. */
static int run(fricreg_structure *s, double dt, double t_end)
{
    int64_t nsteps = (int64_t)ceil(t_end / dt * (1.0 - 1e-12));
    for (int64_t k = 1; k <= nsteps; k++) {
        double t1 = k == nsteps ? t_end : (double)k * dt;
        if (fricreg_structure_run(s, t1 - value(s, FRICREG_SVALUE_TIME), t1) != FRICREG_OK)
            return fail(s, "run");
    }
    return 0;
}

/* The peak roof displacement is the structure's own max |u| over the run, turning points
 * between the step ends included (a maximum of the step ends alone falls short). */
static void report(const fricreg_structure *s)
{
    double D[N], peak[N];
    fricreg_structure_get_peak_displacement(s, N, peak);
    int64_t steps = 0, iterations = 0, max = 0, failures = 0;
    fricreg_structure_get_dissipation(s, N, D);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_STEPS, &steps);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &iterations);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_MAX, &max);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_FAILURES, &failures);
    printf("peak_roof_displacement_m %.17g\n", peak[N - 1]);
    for (int i = 0; i < N; i++)
        printf("damper_energy_J %d %.17g\n", i + 1, D[i]);
    printf("damper_energy_total_J %.17g\n", value(s, FRICREG_SVALUE_FRICTION));
    printf("newton_iterations_mean %.17g\n", (double)iterations / (double)steps);
    printf("newton_iterations_max %lld\n", (long long)max);
    printf("newton_failures %lld\n", (long long)failures);
    printf("energy_input_J %.17g\n", value(s, FRICREG_SVALUE_INPUT));
    printf("energy_residual_J %.17g\n", value(s, FRICREG_SVALUE_RESIDUAL));
    printf("energy_residual_over_input %.17g\n",
           value(s, FRICREG_SVALUE_RESIDUAL) / value(s, FRICREG_SVALUE_INPUT));
}

int main(int argc, char **argv)
{
    double dt = argc > 1 ? atof(argv[1]) : 0.01, eps = argc > 2 ? atof(argv[2]) : 0.01;
    if (!(dt > 0.0) || !(eps > 0.0)) {
        fprintf(stderr, "usage: building_c [DT [EPS]] (both > 0)\n");
        return 1;
    }
    fricreg_structure *s = NULL;
    if (fricreg_structure_create(N, N, &s) != FRICREG_OK) {
        fprintf(stderr, "building: out of memory\n");
        return 1;
    }
    int status = set_up(s, eps);
    if (status == 0)
        status = run(s, dt, 15.0);
    if (status == 0)
        report(s);
    fricreg_structure_free(s);
    return status;
}
