/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_contact_solver.c — Check suite for fricreg_structure_set_contact_solver: the near-stick
 * block solved in the structure's space (CHOLMOD's factor of K_eff + J^T T J, Woodbury's
 * identity and refinement: src/structure/contact_sparse.h) against the dense path (the block
 * of W_eff itself, test_masked_factor's reference):
 *   - a small membrane's coupled edge contacts (bench/membrane_contacts.c in small) stepped
 *     both ways, Newton to 1e-13, give the same forces and displacements to 1e-10 relative: all stuck (a weak
 *     shake), mostly slipping (a strong one), mixed on a stiff interface (K = 3e6 N/m: W_eff
 *     dense), mixed on a soft one (K = 1e4 N/m), and with the tanh law (rows with a shift,
 *     no constraint rows);
 *   - the block solves themselves, white box, against the masked factor's LAPACK storage:
 *     blocks with and without shifts, then the same rows with shifts moved (the held factor as
 *     a chord, refined, or refactored), to 1e-10 of the largest |x|; a singular block (twin
 *     contacts, built by hand: the law refuses them) FRICREG_ESINGULAR both ways, x untouched;
 *   - the sparse path's steps after the first allocate nothing through CHOLMOD (its allocators
 *     counted), on a membrane where CHOLMOD would have chosen a supernodal factor;
 *   - the setter's statuses: NULL, values outside the enum (the setting unchanged), the getter's
 *     NULLs, and AUTO read as the dense path. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "fricreg_structure.h"
#include "membrane.h"
#include "base/sparse_factor.h"
#include "structure/contact_factor.h"
#include "structure/contact_sparse.h"
#include "structure/masked_factor.h"
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

/* ---- The block solves themselves ---------------------------------------------------------- */

static double uniform(unsigned long *state)
{
    *state = *state * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*state >> 11) / 9007199254740992.0;
}

/* x by both solvers of one block (rows set, shifts shift) of the structure's W_eff after a
 * step; their statuses, and the largest difference over the largest |x| into *diff. */
static void both_solves(fricreg_structure *s, const unsigned char set[], const double *shift,
                        const double b[], int status[2], double *diff)
{
    double x[2][NCON];
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < NCON; i++)
            x[k][i] = -7.0; /* left alone off the block, and on failure */
    status[0] = fr_masked_factor_solve(&s->newton.block, s->step.D, set, shift, b, x[0], &s->cc);
    status[1] = fr_contact_sparse_solve(&s->sparse, s->step.D, set, shift, b, x[1], &s->cc);
    double big = 0.0, worst = 0.0;
    for (int i = 0; i < NCON; i++) {
        big = fmax(big, fabs(x[0][i]));
        worst = fmax(worst, fabs(x[1][i] - x[0][i]));
        if (!set[i] || status[1] != FRICREG_OK)
            ck_assert_double_eq(x[1][i], -7.0);
    }
    *diff = worst / big;
}

/* Blocks of a stiff membrane's W_eff (dense: the masked factor's LAPACK storage), with and
 * without shifts, then the same rows with shifts moved a little (the held factor as a chord)
 * and much (refactored): the sparse path's x is the dense one's to 1e-10 of the largest. */
START_TEST(block_solves_equal_dense_ones)
{
    struct membrane_case mc = {"blocks", 3e6, 0.35, FRICREG_LAW_QUINN};
    fricreg_structure *s = membrane(&mc);
    ck_assert_int_eq(fricreg_structure_set_contact_solver(s, FRICREG_CONTACT_SOLVER_SPARSE),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_step(s, DT), FRICREG_OK);
    unsigned long state = 55;
    unsigned char set[NCON];
    double b[NCON], shift[NCON], d00 = ((double *)s->step.D->x)[0]; /* W_eff,00 */
    const double scales[] = {1.0, 1.0, 1.5, 100.0, 1e-3};
    for (int trial = 0; trial < 5; trial++) {
        for (int i = 0; i < NCON; i++) {
            if (trial == 0 || trial == 1)
                set[i] = trial == 0 || uniform(&state) < 0.7;
            b[i] = 2.0 * uniform(&state) - 1.0;
            if (trial <= 1)
                shift[i] = uniform(&state) < 0.5 ? 0.0 : d00 * uniform(&state);
            else
                shift[i] *= scales[trial];
        }
        int status[2];
        double diff;
        both_solves(s, set, trial == 0 ? NULL : shift, b, status, &diff);
        printf("block %d: sparse against dense %.2e of the largest |x|\n", trial, diff);
        ck_assert_int_eq(status[0], FRICREG_OK);
        ck_assert_int_eq(status[1], FRICREG_OK);
        ck_assert_double_le(diff, 1e-10);
    }
    fricreg_structure_free(s);
}
END_TEST

/* Twin contacts (equal rows of J), which the structure's law refuses before any block is
 * solved, built here by hand: K_eff a path of 8 unknowns (diagonal 3, off-diagonal -1), four
 * contacts e_0 - e_2, e_3, e_5, and e_0 - e_2 again. A block holding both twins without shifts
 * is singular: the sparse path says so as the dense one does (FRICREG_ESINGULAR, x untouched);
 * with a shift on one twin it is regular again, and solved alike. */
#define TN 8
#define TM 4
START_TEST(singular_block_is_esingular)
{
    cholmod_common c;
    ck_assert_int_eq(fr_cholmod_start(&c), FRICREG_OK);
    cholmod_sparse *K = cholmod_l_allocate_sparse(TN, TN, 2 * TN, 1, 1, 1, CHOLMOD_REAL, &c);
    SuiteSparse_long *Kp = K->p, *Ki = K->i, q = 0;
    double *Kx = K->x;
    for (SuiteSparse_long j = 0; j < TN; j++) {
        Kp[j] = q;
        if (j > 0)
            Ki[q] = j - 1, Kx[q++] = -1.0;
        Ki[q] = j, Kx[q++] = 3.0;
    }
    Kp[TN] = q;
    cholmod_sparse *Jt = cholmod_l_allocate_sparse(TN, TM, 2 * TM, 1, 1, 0, CHOLMOD_REAL, &c);
    const SuiteSparse_long jp[TM + 1] = {0, 2, 3, 4, 6}, ji[6] = {0, 2, 3, 5, 0, 2};
    const double jx[6] = {1.0, -1.0, 1.0, 1.0, 1.0, -1.0};
    memcpy(Jt->p, jp, sizeof jp);
    memcpy(Jt->i, ji, sizeof ji);
    memcpy(Jt->x, jx, sizeof jx);
    struct fr_cfactor cf = {0};
    struct fr_error err = {0};
    ck_assert_int_eq(fr_cfactor_build(&cf, K, Jt, 0.0, &c, &err, "test", "K"), FRICREG_OK);
    struct fr_masked_factor mf = {0};
    struct fr_contact_sparse sp = {0};
    ck_assert_int_eq(fr_masked_factor_prepare(&mf, cf.D, FR_BLOCK_DENSE, &c), FRICREG_OK);
    ck_assert_int_eq(fr_contact_sparse_prepare(&sp, K, Jt, &c), FRICREG_OK);
    unsigned char set[TM] = {1, 1, 1, 1};
    double b[TM] = {1.0, 0.5, -0.25, 2.0}, shift[TM] = {0.0, 0.0, 0.0, 0.0}, x[2][TM];
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < TM; i++)
            x[0][i] = x[1][i] = -7.0;
        int sd = fr_masked_factor_solve(&mf, cf.D, set, shift, b, x[0], &c);
        int ss = fr_contact_sparse_solve(&sp, cf.D, set, shift, b, x[1], &c);
        ck_assert_int_eq(sd, pass == 0 ? FRICREG_ESINGULAR : FRICREG_OK);
        ck_assert_int_eq(ss, sd);
        double big = 0.0;
        for (int i = 0; i < TM; i++)
            big = fmax(big, fabs(x[0][i]));
        for (int i = 0; i < TM; i++)
            ck_assert_double_eq_tol(x[1][i], x[0][i], 1e-10 * big); /* -7 both on failure */
        shift[TM - 1] = ((double *)cf.D->x)[0];                     /* W_eff,00: the twin regular */
    }
    fr_contact_sparse_free(&sp, &c);
    fr_masked_factor_free(&mf, &c);
    fr_cfactor_free(&cf, &c);
    cholmod_l_free_sparse(&K, &c);
    cholmod_l_free_sparse(&Jt, &c);
    fr_cholmod_finish(&c);
}
END_TEST

/* ---- No allocation in a step -------------------------------------------------------------- */
#ifdef FRICREG_TEST_COUNT_CHOLMOD
#include <SuiteSparse_config.h>

static long cholmod_allocations;
static void *(*real_malloc)(size_t);
static void *(*real_calloc)(size_t, size_t);
static void *(*real_realloc)(void *, size_t);
static void *counted_malloc(size_t n)
{
    cholmod_allocations++;
    return real_malloc(n);
}
static void *counted_calloc(size_t n, size_t size)
{
    cholmod_allocations++;
    return real_calloc(n, size);
}
static void *counted_realloc(void *p, size_t n)
{
    cholmod_allocations++;
    return real_realloc(p, n);
}

/* Whether CHOLMOD left to itself would factor A supernodally (its flops per entry of L at
 * least Common->supernodal_switch), in A's own order. */
static int cholmod_would_go_supernodal(cholmod_sparse *A)
{
    cholmod_common c;
    ck_assert_int_eq(fr_cholmod_start(&c), FRICREG_OK);
    fr_cholmod_ordering(&c, CHOLMOD_NATURAL, 0);
    cholmod_factor *L = cholmod_l_analyze(A, &c);
    ck_assert_ptr_nonnull(L);
    int super = L->is_super;
    cholmod_l_free_factor(&L, &c);
    fr_cholmod_finish(&c);
    return super;
}

/* The sparse path's steps after the first take no memory through CHOLMOD (SuiteSparse_config's
 * allocators counted), on a membrane where CHOLMOD would choose a supernodal factor of
 * K_eff + J^T T J (96 x 96 nodes, two rows of contacts: tests/support/membrane.h), whose every
 * numeric factorization allocates its update matrix: the path's factor is simplicial, A stays
 * in the one triangle CHOLMOD factors in place, the workspaces are kept. */
START_TEST(steps_allocate_nothing)
{
    fricreg_structure *s = test_membrane(96, 2, 3e6, FRICREG_CONTACT_SOLVER_SPARSE);
    ck_assert_ptr_nonnull(s);
    ck_assert_int_eq(fricreg_structure_step(s, TEST_MEMBRANE_DT), FRICREG_OK);
    ck_assert(!s->sparse.L->is_super);
    ck_assert_msg(cholmod_would_go_supernodal(s->sparse.A), "the membrane is too small here");
    real_malloc = SuiteSparse_config.malloc_func;
    real_calloc = SuiteSparse_config.calloc_func;
    real_realloc = SuiteSparse_config.realloc_func;
    SuiteSparse_config.malloc_func = counted_malloc;
    SuiteSparse_config.calloc_func = counted_calloc;
    SuiteSparse_config.realloc_func = counted_realloc;
    cholmod_allocations = 0;
    int64_t before = 0, after = 0;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &before);
    for (int step = 1; step < STEPS; step++)
        ck_assert_int_eq(fricreg_structure_step(s, TEST_MEMBRANE_DT), FRICREG_OK);
    SuiteSparse_config.malloc_func = real_malloc;
    SuiteSparse_config.calloc_func = real_calloc;
    SuiteSparse_config.realloc_func = real_realloc;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &after);
    ck_assert_int_gt(after - before, STEPS / 2); /* the blocks were solved */
    ck_assert_int_eq(cholmod_allocations, 0);
    fricreg_structure_free(s);
}
END_TEST
#endif

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
    tcase_add_test(tc, block_solves_equal_dense_ones);
    tcase_add_test(tc, singular_block_is_esingular);
#ifdef FRICREG_TEST_COUNT_CHOLMOD
    tcase_add_test(tc, steps_allocate_nothing);
#endif
    tcase_add_test(tc, setter_statuses);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
