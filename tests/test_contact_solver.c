/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_contact_solver.c — Check suite for fricreg_structure_set_contact_solver: the near-stick
 * block solved in the structure's space (CHOLMOD's factor of K_eff + J^T T J, Woodbury's
 * identity and refinement: src/structure/contact_sparse.h) against the dense path (the block
 * of W_eff itself, test_masked_factor's reference):
 *   - a small membrane's coupled edge contacts (bench/membrane_contacts.c in small) stepped
 *     both ways give the same forces and displacements to 1e-10 relative: all stuck (a weak
 *     shake), mostly slipping (a strong one), mixed on a stiff interface (K = 3e6 N/m: W_eff
 *     dense), mixed on a soft one (K = 1e4 N/m), and with the tanh law (rows with a shift,
 *     no constraint rows);
 *   - the setter's statuses: NULL, values outside the enum (the setting unchanged), the getter's
 *     NULLs, and AUTO read as the dense path. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "fricreg_structure.h"
#include "structure/structure_internal.h"

#define SIDE 8
#define NDOF (SIDE * SIDE)
#define NCON (2 * SIDE)
#define STEPS 120
#define DT 0.005

struct membrane_case {
    const char *name;
    double spring_k, shake_g; /* N/m between neighbours; the ground's amplitude in g */
    int law;
};

/* A SIDE x SIDE grid of 1 kg nodes, springs of spring_k between neighbours and 10^3 N/m to the
 * ground, C = 0.002 s K, shaken at shake_g, 4 Hz; contacts on the edge row against the ground
 * (mu N = 20 N) and on the next row against the edge (4 N), coupled through the edge's nodes. */
static fricreg_structure *membrane(const struct membrane_case *mc)
{
    static double K[NDOF * NDOF], M[NDOF * NDOF], J[NCON * NDOF];
    double mun[NCON], r[NDOF], ag[2 * STEPS + 1];
    memset(K, 0, sizeof K);
    memset(M, 0, sizeof M);
    memset(J, 0, sizeof J);
    for (int a = 0; a < NDOF; a++) {
        int row = a / SIDE, col = a % SIDE;
        M[a * NDOF + a] = 1.0;
        K[a * NDOF + a] += 1e3;
        r[a] = 1.0;
        int nb[2] = {col + 1 < SIDE ? a + 1 : -1, row + 1 < SIDE ? a + SIDE : -1};
        for (int k = 0; k < 2; k++)
            if (nb[k] >= 0) {
                K[a * NDOF + a] += mc->spring_k;
                K[nb[k] * NDOF + nb[k]] += mc->spring_k;
                K[a * NDOF + nb[k]] -= mc->spring_k;
                K[nb[k] * NDOF + a] -= mc->spring_k;
            }
    }
    for (int c = 0; c < SIDE; c++) {
        J[c * NDOF + c] = 1.0;
        mun[c] = 20.0;
        J[(SIDE + c) * NDOF + SIDE + c] = 1.0;
        J[(SIDE + c) * NDOF + c] = -1.0;
        mun[SIDE + c] = 4.0;
    }
    for (int k = 0; k <= 2 * STEPS; k++)
        ag[k] = mc->shake_g * 9.81 * sin(6.283185307179586 * 4.0 * k * (DT / 2));
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(NDOF, NCON, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, NDOF, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, NDOF, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, 0.0, 0.002), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, NCON, NDOF, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, NCON, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, mc->law, 1e-3), FRICREG_OK);
    /* Newton to near rounding: the paths' iterates then differ by their solves, not by where
     * within the default tolerance (1e-10 of the force scale) each stopped */
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-13, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_influence(s, NDOF, r), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_ground_accel(s, 0.0, DT / 2, 2 * STEPS + 1, ag),
                     FRICREG_OK);
    return s;
}

/* STEPS steps with the solver given: forces f, displacements u; the contact-steps stuck
 * (|f_i| < 0.999 mu N_i); whether the sparse path's factor was there. */
static void membrane_run(const struct membrane_case *mc, int solver, double (*f)[NCON],
                         double (*u)[NDOF], int *stuck, int *sparse)
{
    fricreg_structure *s = membrane(mc);
    ck_assert_int_eq(fricreg_structure_set_contact_solver(s, solver), FRICREG_OK);
    *stuck = 0;
    for (int step = 0; step < STEPS; step++) {
        int status = fricreg_structure_step(s, DT);
        ck_assert_msg(status == FRICREG_OK, "%s, step %d: %s", mc->name, step,
                      fricreg_structure_errmsg(s));
        ck_assert_int_eq(fricreg_structure_get_forces(s, NCON, f[step]), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_state(s, NDOF, u[step], NULL, NULL), FRICREG_OK);
        for (int i = 0; i < NCON; i++)
            *stuck += fabs(f[step][i]) < 0.999 * (i < SIDE ? 20.0 : 4.0);
    }
    *sparse = s->newton.sparse != NULL && s->sparse.L != NULL;
    fricreg_structure_free(s);
}

/* Both paths on one case: the largest differences, forces over mu N and displacements over
 * the run's largest, both within 1e-10; the stuck contact-steps within [stuck_lo, stuck_hi]
 * of STEPS NCON, so that the case is the one it claims. */
static void paths_agree(const struct membrane_case *mc, double stuck_lo, double stuck_hi)
{
    static double f[2][STEPS][NCON], u[2][STEPS][NDOF];
    int stuck[2], sparse[2];
    membrane_run(mc, FRICREG_CONTACT_SOLVER_DENSE, f[0], u[0], &stuck[0], &sparse[0]);
    membrane_run(mc, FRICREG_CONTACT_SOLVER_SPARSE, f[1], u[1], &stuck[1], &sparse[1]);
    ck_assert(!sparse[0] && sparse[1]);
    double umax = 0.0, worst_f = 0.0, worst_u = 0.0;
    for (int step = 0; step < STEPS; step++)
        for (int a = 0; a < NDOF; a++)
            umax = fmax(umax, fabs(u[0][step][a]));
    for (int step = 0; step < STEPS; step++) {
        for (int i = 0; i < NCON; i++)
            worst_f = fmax(worst_f, fabs(f[1][step][i] - f[0][step][i]) / (i < SIDE ? 20.0 : 4.0));
        for (int a = 0; a < NDOF; a++)
            worst_u = fmax(worst_u, fabs(u[1][step][a] - u[0][step][a]) / umax);
    }
    double fraction = (double)stuck[0] / (STEPS * NCON);
    printf("%s: stuck fraction %.3f; sparse against dense: max |df| / mu N = %.2e, "
           "max |du| / max |u| = %.2e\n",
           mc->name, fraction, worst_f, worst_u);
    ck_assert_double_ge(fraction, stuck_lo);
    ck_assert_double_le(fraction, stuck_hi);
    ck_assert_double_le(worst_f, 1e-10);
    ck_assert_double_le(worst_u, 1e-10);
}

START_TEST(all_stuck)
{
    struct membrane_case mc = {"stuck, K = 3e6", 3e6, 0.01, FRICREG_LAW_QUINN};
    paths_agree(&mc, 1.0, 1.0);
}
END_TEST

START_TEST(mostly_slipping)
{
    struct membrane_case mc = {"slipping, K = 1e4", 1e4, 5.0, FRICREG_LAW_QUINN};
    paths_agree(&mc, 0.0, 0.3);
}
END_TEST

START_TEST(mixed_stiff)
{
    struct membrane_case mc = {"mixed, K = 3e6", 3e6, 0.35, FRICREG_LAW_QUINN};
    paths_agree(&mc, 0.1, 0.9);
}
END_TEST

START_TEST(mixed_soft)
{
    struct membrane_case mc = {"mixed, K = 1e4", 1e4, 0.35, FRICREG_LAW_QUINN};
    paths_agree(&mc, 0.1, 0.9);
}
END_TEST

START_TEST(mixed_tanh)
{
    struct membrane_case mc = {"mixed, tanh, K = 3e6", 3e6, 0.35, FRICREG_LAW_TANH};
    paths_agree(&mc, 0.1, 0.9);
}
END_TEST

START_TEST(setter_statuses)
{
    struct membrane_case mc = {"statuses", 3e6, 0.35, FRICREG_LAW_QUINN};
    fricreg_structure *s = membrane(&mc);
    int solver = -1;
    ck_assert_int_eq(fricreg_structure_set_contact_solver(NULL, FRICREG_CONTACT_SOLVER_SPARSE),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_contact_solver(NULL, &solver), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_contact_solver(s, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_contact_solver(s, &solver), FRICREG_OK);
    ck_assert_int_eq(solver, FRICREG_CONTACT_SOLVER_DENSE); /* the default, AUTO, for now */
    ck_assert_int_eq(fricreg_structure_set_contact_solver(s, FRICREG_CONTACT_SOLVER_SPARSE),
                     FRICREG_OK);
    const int bad[] = {-1, 3, 1000};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        ck_assert_int_eq(fricreg_structure_set_contact_solver(s, bad[k]), FRICREG_EINVAL);
        ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "set_contact_solver"));
        ck_assert_int_eq(fricreg_structure_get_contact_solver(s, &solver), FRICREG_OK);
        ck_assert_int_eq(solver, FRICREG_CONTACT_SOLVER_SPARSE); /* unchanged */
    }
    ck_assert_int_eq(fricreg_structure_set_contact_solver(s, FRICREG_CONTACT_SOLVER_AUTO),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_contact_solver(s, &solver), FRICREG_OK);
    ck_assert_int_eq(solver, FRICREG_CONTACT_SOLVER_DENSE);
    fricreg_structure_free(s);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("contact_solver");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, all_stuck);
    tcase_add_test(tc, mostly_slipping);
    tcase_add_test(tc, mixed_stiff);
    tcase_add_test(tc, mixed_soft);
    tcase_add_test(tc, mixed_tanh);
    tcase_add_test(tc, setter_statuses);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
