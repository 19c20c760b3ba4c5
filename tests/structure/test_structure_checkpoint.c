/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_checkpoint.c — Check suite for fricreg_structure_save / _restore.
 *
 * Where the numbers come from: an uninterrupted run to T2 is the reference. The same set-up run
 * to T1, saved, freed, and restored into a new structure set up the same way, then run to T2,
 * must agree with it bit for bit (memcmp) in everything a getter shows: u, v, a, the forces,
 * each contact's dissipation, the energies, the counters, the peaks, the elements' state, the
 * error estimates and the warnings. T1 = 0.5 is a step time of dt = 0.01 (the rounded 50 dt is
 * 0.5, and so are 100 dt/2 and 200 dt/4 of the companions), so the uninterrupted run passes
 * through it. The scene sticks and slips: a load of amplitude 1.1 against bounds 0.35 and 0.5
 * (the contacts' dissipation grows in both halves, checked), with a Jenkins element that slips
 * (its dissipation too). A restore into another model fails with FRICREG_EINVAL and leaves the
 * structure as it was; so does a truncated or corrupted blob. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "fricreg_structure.h"
#include "membrane.h"

#define N 3
#define MC 2

static const double DT = 0.01, T1 = 0.5, T2 = 1.0;

enum scheme { NEWMARK, HHT, CENTRAL, RK4_FIXED, RKF45_ADAPTIVE };

struct setup {
    enum scheme scheme;
    int coupled;        /* a consistent mass: W couples the contacts (the context's dense factor) */
    int jenkins;        /* a Jenkins element on dof 2 */
    int estimate;       /* enum fricreg_error_estimate */
    double k22;         /* K(2, 2): another model where it differs */
    int companions;     /* enum fricreg_estimate_companions (0, finer, where not given) */
    int doubt_after_t1; /* auto's answer tolerance (1 until T1) at 1e-9 from T1: confirmed later */
};

static fricreg_structure *make(const struct setup *c)
{
    double M[N * N] = {1.0, 0.0, 0.0, 0.0, 0.8, 0.0, 0.0, 0.0, 1.3};
    if (c->coupled) {
        M[1] = M[3] = 0.1;
        M[5] = M[7] = 0.07;
    }
    double K[N * N] = {40.0, -15.0, 0.0, -15.0, 35.0, -20.0, 0.0, -20.0, c->k22};
    double J[MC * N] = {1.0, 0.0, 0.0, 0.0, 1.0, -0.5};
    double mun[MC] = {0.35, 0.5};
    double p[N] = {1.1, -0.4, 0.7};
    double g[101];
    for (size_t k = 0; k < 101; k++)
        g[k] = sin(7.3 * 0.01 * (double)k) + 0.3 * sin(19.1 * 0.01 * (double)k);
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(N, MC, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, N, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, 0.05, 0.002), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, MC, N, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, MC, mun), FRICREG_OK);
    /* the explicit schemes' step guard: dt times the stick zone's stiffness 2 W_ii mun_i/eps */
    int explicit_scheme = c->scheme == CENTRAL || c->scheme == RK4_FIXED;
    double eps = explicit_scheme ? 0.05 : 2e-3;
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, N, p, 0.0, 0.01, 101, g), FRICREG_OK);
    if (c->jenkins) {
        double Je[N] = {0.0, 0.0, 1.0}, kt = 25.0, slip = 0.3;
        ck_assert_int_eq(fricreg_structure_set_jenkins(s, 1, N, Je, &kt, &slip), FRICREG_OK);
    }
    if (c->scheme == HHT)
        ck_assert_int_eq(fricreg_structure_set_hht(s, -0.1), FRICREG_OK);
    if (c->scheme == CENTRAL)
        ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_estimate(s, c->estimate), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_companions(s, c->companions), FRICREG_OK);
    if (c->companions == FRICREG_COMPANIONS_AUTO) /* the screen quiet until T1 */
        ck_assert_int_eq(fricreg_structure_set_answer_rtol(s, 1.0), FRICREG_OK);
    return s;
}

/* From the structure's time to t_end: one run (the structure's schemes), or run_ode from
 * sample to sample k dt as fricreg-sim does (GSL's). */
static void advance(fricreg_structure *s, const struct setup *c, double t_end)
{
    if (c->scheme <= CENTRAL) {
        ck_assert_int_eq(fricreg_structure_run(s, DT, t_end), FRICREG_OK);
        return;
    }
    double t = 0.0;
    fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t);
    int integ = c->scheme == RK4_FIXED ? FRICREG_INT_RK4 : FRICREG_INT_RKF45;
    double rtol = c->scheme == RK4_FIXED ? 0.0 : 1e-6;
    double atol = c->scheme == RK4_FIXED ? 0.0 : FRICREG_ATOL_FROM_EPS;
    for (int k = 1; (double)k * DT <= t_end * (1.0 + 1e-12); k++) {
        double t1 = (double)k * DT;
        if (!(t1 > t))
            continue;
        ck_assert_int_eq(fricreg_structure_run_ode(s, integ, t1 - t, rtol, atol, t1), FRICREG_OK);
        t = t1;
    }
}

/* Everything a getter shows, in one array of doubles (the counters and the warnings' codes
 * as doubles: exact). */
#define OUT_LEN 128

static size_t outputs(fricreg_structure *s, const struct setup *c, double out[OUT_LEN])
{
    size_t k = 0;
    memset(out, 0, OUT_LEN * sizeof *out);
    ck_assert_int_eq(fricreg_structure_get_state(s, N, out, out + N, out + 2 * N), FRICREG_OK);
    k += 3 * N;
    ck_assert_int_eq(fricreg_structure_get_forces(s, MC, out + k), FRICREG_OK);
    k += MC;
    ck_assert_int_eq(fricreg_structure_get_dissipation(s, MC, out + k), FRICREG_OK);
    k += MC;
    for (int v = FRICREG_SVALUE_TIME; v <= FRICREG_SVALUE_SCREEN_DISS_ERR; v++)
        if (v != FRICREG_SVALUE_COMPANION_CPU) /* a clock's reading */
            ck_assert_int_eq(fricreg_structure_get_value(s, v, &out[k++]), FRICREG_OK);
    for (int st = FRICREG_SSTAT_STEPS; st <= FRICREG_SSTAT_LINE_SEARCH_CUTS; st++) {
        int64_t x = 0;
        ck_assert_int_eq(fricreg_structure_get_stat(s, st, &x), FRICREG_OK);
        out[k++] = (double)x;
    }
    ck_assert_int_eq(fricreg_structure_get_peak_displacement(s, N, out + k), FRICREG_OK);
    k += N;
    if (c->jenkins) {
        ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 1, out + k, out + k + 1,
                                                             out + k + 2),
                         FRICREG_OK);
        k += 3;
    }
    if (c->estimate) {
        ck_assert_int_eq(fricreg_structure_get_peak_displacement_error(s, N, out + k), FRICREG_OK);
        k += N;
        ck_assert_int_eq(fricreg_structure_get_dissipation_error(s, MC, out + k), FRICREG_OK);
        k += MC;
    }
    size_t nw = fricreg_structure_warning_count(s);
    out[k++] = (double)nw;
    for (size_t w = 0; w < nw; w++) {
        int code = -1;
        ck_assert_int_eq(fricreg_structure_get_warning(s, w, &code, NULL, 0), FRICREG_OK);
        out[k++] = code;
    }
    ck_assert_uint_le(k, OUT_LEN);
    return k;
}

/* The run to T1 saved (the blob into *len bytes, malloc'd). */
static unsigned char *saved_at_t1(const struct setup *c, size_t *len, double dissipation[MC])
{
    fricreg_structure *s = make(c);
    advance(s, c, T1);
    ck_assert_int_eq(fricreg_structure_get_dissipation(s, MC, dissipation), FRICREG_OK);
    *len = 0;
    ck_assert_int_eq(fricreg_structure_save(s, NULL, len), FRICREG_OK);
    ck_assert_uint_gt(*len, 0);
    unsigned char *blob = malloc(*len);
    ck_assert_ptr_nonnull(blob);
    size_t small = *len - 1;
    ck_assert_int_eq(fricreg_structure_save(s, blob, &small), FRICREG_ESIZE);
    ck_assert_uint_eq(small, *len);
    size_t cap = *len + 16;
    ck_assert_int_eq(fricreg_structure_save(s, blob, &cap), FRICREG_OK);
    ck_assert_uint_eq(cap, *len);
    fricreg_structure_free(s);
    return blob;
}

/* The answer tolerance lowered where the setup asks (it is read where the estimate is, at the
 * end: the screen settles there, not at T1), then on to T2. */
static void second_half(fricreg_structure *s, const struct setup *c)
{
    if (c->doubt_after_t1)
        ck_assert_int_eq(fricreg_structure_set_answer_rtol(s, 1e-9), FRICREG_OK);
    advance(s, c, T2);
}

static void split_equals_uninterrupted(const struct setup *c)
{
    double full[OUT_LEN], split[OUT_LEN], d1[MC];
    fricreg_structure *s = make(c);
    if (c->companions == FRICREG_COMPANIONS_AUTO)
        advance(s, c, T1); /* the coarser screen's 4 dt do not divide T1: the split's calls */
    second_half(s, c);     /* else in one call: the run's grid continued through T1 */
    size_t n_full = outputs(s, c, full);
    fricreg_structure_free(s);

    size_t len = 0;
    unsigned char *blob = saved_at_t1(c, &len, d1);
    fricreg_structure *r = make(c);
    ck_assert_int_eq(fricreg_structure_restore(r, blob, len), FRICREG_OK);
    double t = 0.0;
    fricreg_structure_get_value(r, FRICREG_SVALUE_TIME, &t);
    ck_assert(t == T1);
    second_half(r, c);
    size_t n_split = outputs(r, c, split);
    fricreg_structure_free(r);
    free(blob);

    ck_assert_uint_eq(n_split, n_full);
    for (size_t k = 0; k < n_full; k++)
        ck_assert_msg(memcmp(&full[k], &split[k], sizeof(double)) == 0,
                      "output %zu: %.17g uninterrupted, %.17g split", k, full[k], split[k]);
    /* stick-slip in both halves: the contacts dissipate before T1 and after it */
    for (size_t i = 0; i < MC; i++) {
        ck_assert_double_gt(d1[i], 1e-5);
        ck_assert_double_gt(full[3 * N + MC + i], d1[i] * (1.0 + 1e-3));
    }
}

START_TEST(test_newmark_contacts_jenkins)
{
    struct setup c = {NEWMARK, 0, 1, FRICREG_ESTIMATE_TWO_COMPANIONS, 30.0};
    split_equals_uninterrupted(&c);
}
END_TEST

START_TEST(test_hht_contacts_jenkins)
{
    struct setup c = {HHT, 0, 1, FRICREG_ESTIMATE_ONE_COMPANION, 30.0};
    split_equals_uninterrupted(&c);
}
END_TEST

START_TEST(test_central_contacts_jenkins)
{
    struct setup c = {CENTRAL, 0, 1, FRICREG_ESTIMATE_TWO_COMPANIONS, 30.0};
    split_equals_uninterrupted(&c);
}
END_TEST

/* The screened estimate (FRICREG_COMPANIONS_AUTO): saved while the screen is quiet, its finer
 * pair parked at the start, and confirmed after the restore where the answer tolerance drops
 * at T1 (the finer pair stepped from the start through the restore), Newmark and adaptive. */
START_TEST(test_screened_estimate)
{
    const struct setup cases[] = {
        {NEWMARK, 0, 1, FRICREG_ESTIMATE_TWO_COMPANIONS, 30.0, FRICREG_COMPANIONS_AUTO, 0},
        {NEWMARK, 0, 1, FRICREG_ESTIMATE_TWO_COMPANIONS, 30.0, FRICREG_COMPANIONS_AUTO, 1},
        {RKF45_ADAPTIVE, 0, 0, FRICREG_ESTIMATE_ONE_COMPANION, 30.0, FRICREG_COMPANIONS_AUTO, 1}};
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        fricreg_structure *s = make(&cases[k]);
        advance(s, &cases[k], T1);
        double used = -7.0;
        ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_COMPANIONS_USED, &used),
                         FRICREG_OK);
        ck_assert_msg(used == FRICREG_COMPANIONS_COARSER, "case %zu: the screen quiet at T1", k);
        second_half(s, &cases[k]);
        ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_COMPANIONS_USED, &used),
                         FRICREG_OK);
        ck_assert_msg(used == (cases[k].doubt_after_t1 ? FRICREG_COMPANIONS_FINER
                                                       : FRICREG_COMPANIONS_COARSER),
                      "case %zu: confirmed after T1 where the tolerance dropped", k);
        fricreg_structure_free(s);
        split_equals_uninterrupted(&cases[k]);
    }
}
END_TEST

/* A consistent mass couples the contacts: the context's warm start and its updated factor. */
START_TEST(test_newmark_coupled)
{
    struct setup c = {NEWMARK, 1, 1, FRICREG_ESTIMATE_OFF, 30.0};
    split_equals_uninterrupted(&c);
}
END_TEST

START_TEST(test_rk4_fixed)
{
    struct setup c = {RK4_FIXED, 0, 0, FRICREG_ESTIMATE_TWO_COMPANIONS, 30.0};
    split_equals_uninterrupted(&c);
}
END_TEST

/* GSL's adaptive driver starts anew at each run_ode call: nothing to carry between calls. */
START_TEST(test_rkf45_adaptive)
{
    struct setup c = {RKF45_ADAPTIVE, 0, 0, FRICREG_ESTIMATE_ONE_COMPANION, 30.0};
    split_equals_uninterrupted(&c);
}
END_TEST

/* A failed restore leaves the structure as it was: its outputs bit for bit. */
static void refused(fricreg_structure *s, const struct setup *c, const void *blob, size_t len,
                    const char *why)
{
    double before[OUT_LEN], after[OUT_LEN];
    size_t n = outputs(s, c, before);
    ck_assert_int_eq(fricreg_structure_restore(s, blob, len), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_errcode(s), FRICREG_EINVAL);
    ck_assert_msg(strstr(fricreg_structure_errmsg(s), why) != NULL, "message: %s",
                  fricreg_structure_errmsg(s));
    ck_assert_uint_eq(outputs(s, c, after), n);
    ck_assert_int_eq(memcmp(before, after, n * sizeof *before), 0);
}

START_TEST(test_mismatched_model)
{
    struct setup c = {NEWMARK, 0, 1, FRICREG_ESTIMATE_OFF, 30.0};
    double d1[MC];
    size_t len = 0;
    unsigned char *blob = saved_at_t1(&c, &len, d1);
    struct setup other = c;
    other.k22 = 31.0;
    fricreg_structure *s = make(&other);
    advance(s, &other, 0.2); /* a state of its own to keep */
    refused(s, &other, blob, len, "model");
    fricreg_structure_free(s);
    other = c;
    other.scheme = HHT;
    s = make(&other);
    refused(s, &other, blob, len, "alpha");
    fricreg_structure_free(s);
    other = c;
    other.jenkins = 0;
    s = make(&other);
    refused(s, &other, blob, len, "elements");
    fricreg_structure_free(s);
    other = c; /* the near-stick block's path: answers that differ by rounding, not bit for bit */
    s = make(&other);
    ck_assert_int_eq(fricreg_structure_set_contact_solver(s, FRICREG_CONTACT_SOLVER_SPARSE),
                     FRICREG_OK);
    refused(s, &other, blob, len, "contact solver");
    fricreg_structure_free(s);
    fricreg_structure *small = NULL;
    ck_assert_int_eq(fricreg_structure_create(N - 1, MC, &small), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_restore(small, blob, len), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(small), "ndof = 3"));
    fricreg_structure_free(small);
    free(blob);
}
END_TEST

START_TEST(test_truncated_corrupted)
{
    struct setup c = {NEWMARK, 0, 1, FRICREG_ESTIMATE_TWO_COMPANIONS, 30.0};
    double d1[MC];
    size_t len = 0;
    unsigned char *blob = saved_at_t1(&c, &len, d1);
    fricreg_structure *s = make(&c);
    advance(s, &c, 0.2);
    /* every length short of the whole: the header's, then the length check */
    for (size_t cut = 0; cut < len; cut += 1 + cut / 7)
        refused(s, &c, blob, cut, cut < 40 ? "" : "truncated");
    /* one byte flipped anywhere: the magic, the header's fields or the hash */
    for (size_t k = 0; k < len; k += 1 + k / 5) {
        blob[k] ^= 0x5a;
        refused(s, &c, blob, len, "");
        blob[k] ^= 0x5a;
    }
    ck_assert_int_eq(fricreg_structure_restore(s, NULL, len), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_restore(NULL, blob, len), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_save(s, blob, NULL), FRICREG_ENULL);
    size_t n = 0;
    ck_assert_int_eq(fricreg_structure_save(NULL, NULL, &n), FRICREG_ENULL);
    /* intact, it restores */
    ck_assert_int_eq(fricreg_structure_restore(s, blob, len), FRICREG_OK);
    fricreg_structure_free(s);
    free(blob);
}
END_TEST

/* A checkpoint of a structure never stepped restores to the same start. */
START_TEST(test_before_first_step)
{
    struct setup c = {NEWMARK, 1, 1, FRICREG_ESTIMATE_TWO_COMPANIONS, 30.0};
    double full[OUT_LEN], split[OUT_LEN];
    fricreg_structure *s = make(&c);
    size_t len = 0;
    ck_assert_int_eq(fricreg_structure_save(s, NULL, &len), FRICREG_OK);
    unsigned char *blob = malloc(len);
    ck_assert_int_eq(fricreg_structure_save(s, blob, &len), FRICREG_OK);
    advance(s, &c, T1);
    size_t n = outputs(s, &c, full);
    fricreg_structure *r = make(&c);
    advance(r, &c, 0.2);
    ck_assert_int_eq(fricreg_structure_restore(r, blob, len), FRICREG_OK);
    advance(r, &c, T1);
    ck_assert_uint_eq(outputs(r, &c, split), n);
    ck_assert_int_eq(memcmp(full, split, n * sizeof *full), 0);
    fricreg_structure_free(s);
    fricreg_structure_free(r);
    free(blob);
}
END_TEST

/* ---- The near-stick block's factor ---------------------------------------------------------
 * A 16 x 16 membrane with contacts on four rows, 64 in all, the most that couple through W in
 * a checkpoint (tests/support/membrane.h: bench/membrane_contacts.c in small). Newmark's
 * near-stick block keeps its factor from one step to the next, and that factor's last bits
 * depend on the blocks before it: the dense path keeps leading rows and deletes others, the
 * sparse path refines other shifts' solves on it (a chord). Restored without it (before
 * checkpoints carried it), the runs below left the uninterrupted ones by rounding: 816 and 749
 * of the 832 outputs differed (restored into a fresh structure, 256 and 203 of the 256
 * displacements, by up to 3.6e-16 and 6.9e-18 m). */
#define MSIDE 16
#define MROWS 4
#define MN (MSIDE * MSIDE)
#define MM (MROWS * MSIDE)

static fricreg_structure *membrane(double spring_k, int solver)
{
    fricreg_structure *s = test_membrane(MSIDE, MROWS, spring_k, solver);
    ck_assert_ptr_nonnull(s);
    return s;
}

static void membrane_steps(fricreg_structure *s, int steps)
{
    for (int k = 0; k < steps; k++)
        ck_assert_int_eq(fricreg_structure_step(s, TEST_MEMBRANE_DT), FRICREG_OK);
}

/* u, v, a and the forces after `saved` steps and `more` further ones, uninterrupted and
 * restored (into a structure that stepped on its own first, its block factor its own): bit
 * for bit. */
static void membrane_split_equals_uninterrupted(double spring_k, int solver, int saved, int more)
{
    static double full[3 * MN + MM], split[3 * MN + MM];
    fricreg_structure *s = membrane(spring_k, solver);
    membrane_steps(s, saved);
    size_t len = 0;
    ck_assert_int_eq(fricreg_structure_save(s, NULL, &len), FRICREG_OK);
    unsigned char *blob = malloc(len);
    ck_assert_ptr_nonnull(blob);
    ck_assert_int_eq(fricreg_structure_save(s, blob, &len), FRICREG_OK);
    fricreg_structure *r = membrane(spring_k, solver);
    membrane_steps(r, 10);
    ck_assert_int_eq(fricreg_structure_restore(r, blob, len), FRICREG_OK);
    fricreg_structure *runs[2] = {s, r};
    double *outs[2] = {full, split};
    for (int k = 0; k < 2; k++) {
        membrane_steps(runs[k], more);
        double *o = outs[k];
        ck_assert_int_eq(fricreg_structure_get_state(runs[k], MN, o, o + MN, o + 2 * MN),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_forces(runs[k], MM, o + 3 * MN), FRICREG_OK);
    }
    size_t differ = 0;
    for (size_t k = 0; k < 3 * MN + MM; k++)
        differ += memcmp(&full[k], &split[k], sizeof(double)) != 0;
    ck_assert_msg(differ == 0, "%zu of %d outputs differ", differ, 3 * MN + MM);
    fricreg_structure_free(s);
    fricreg_structure_free(r);
    free(blob);
}

START_TEST(test_dense_block_factor_carried)
{
    membrane_split_equals_uninterrupted(3e6, FRICREG_CONTACT_SOLVER_DENSE, 60, 60);
}
END_TEST

START_TEST(test_sparse_block_factor_carried)
{
    membrane_split_equals_uninterrupted(1e4, FRICREG_CONTACT_SOLVER_SPARSE, 47, 40);
}
END_TEST

static Suite *checkpoint_suite(void)
{
    Suite *s = suite_create("structure_checkpoint");
    TCase *tc = tcase_create("checkpoint");
    tcase_add_test(tc, test_newmark_contacts_jenkins);
    tcase_add_test(tc, test_screened_estimate);
    tcase_add_test(tc, test_hht_contacts_jenkins);
    tcase_add_test(tc, test_central_contacts_jenkins);
    tcase_add_test(tc, test_newmark_coupled);
    tcase_add_test(tc, test_rk4_fixed);
    tcase_add_test(tc, test_rkf45_adaptive);
    tcase_add_test(tc, test_mismatched_model);
    tcase_add_test(tc, test_truncated_corrupted);
    tcase_add_test(tc, test_before_first_step);
    tcase_add_test(tc, test_dense_block_factor_carried);
    tcase_add_test(tc, test_sparse_block_factor_carried);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(checkpoint_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
