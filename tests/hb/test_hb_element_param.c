/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_element_param.c — Check suite for a held element's parameter set and read in place
 * (fricreg_hb_set_element_param, fricreg_hb_get_element_param, fricreg_hb.h). Where the
 * numbers come from: the driver itself, built again. NLvib's chain (tests/support/hb_chain.h)
 * with two elements of a type (jenkins, iwan of three sliders, jenkins_normal, contact_3d, the
 * marched dahl) solved at Ω = 1.2 after one parameter was set in place must give the forced
 * response of the chain built with that value from the start, bit for bit: every copy the
 * driver keeps of a parameter (an Iwan element's sliders' sums among them) moved with it.
 * Then every status, and nothing changed on failure. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"
#include "hb_chain.h"

#define MAXNP 16 /* parameters of the two elements */
#define OMEGA 1.2

/* A type's elements on the chain: two of them, their rows per element dim, J's rows and the
 * parameters of both (element 1's after element 0's). */
struct elements {
    const char *name;
    size_t ns; /* sliders of an Iwan type, 0 for the others */
    size_t dim, np;
    size_t first_moved; /* the parameters moved: first_moved .. min(np, 4) - 1 (the gap stays 0) */
    double J[18];
    double p[MAXNP];
};

static const struct elements CASES[] = {
    {"jenkins", 0, 1, 2, 0, {1, 0, 0, -1, 1, 0}, {20, 1, 15, 0.8}},
    {"iwan", 3, 1, 6, 0, {1, 0, 0, -1, 1, 0}, {10, 6, 4, 0.3, 0.6, 1.0, 8, 7, 5, 0.2, 0.5, 0.9}},
    {"jenkins_normal",
     0,
     2,
     5,
     0,
     {1, 0, 0, 0, 0, 1, -1, 1, 0, 0, 0, 1},
     {20, 0.4, 30, 2.0, 0, 15, 0.3, 25, 1.5, 0}},
    {"contact_3d",
     0,
     3,
     5,
     0,
     {1, 0, 0, 0, 1, 0, 0, 0, -1, -1, 1, 0, 0, -1, 1, 0, 0, 1},
     {20, 0.4, 30, 2.0, 0, 15, 0.3, 25, 1.5, 0}},
    {"dahl", 0, 1, 2, 1, {1, 0, 0, -1, 1, 0}, {20, 1, 15, 0.8}}, /* marched: slow, one */
};
#define NCASES (sizeof CASES / sizeof CASES[0])

static const fricreg_element_type *type_of(const struct elements *c)
{
    const fricreg_element_type *type = fricreg_element_lookup(c->name);
    return c->ns > 0 ? fricreg_element_sliders(type, c->ns) : type;
}

/* The chain with the case's elements, of parameters p. */
static fricreg_hb *chain_with(const struct elements *c, const double *p)
{
    fricreg_hb *hb = hb_chain(0, 0);
    ck_assert_ptr_nonnull(hb);
    ck_assert_int_eq(fricreg_hb_clear_elements(hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, type_of(c), 2, 3, c->J, p), FRICREG_OK);
    return hb;
}

/* The forced response at Ω from the guess q0, or from the driver's own start (q0 NULL). */
static void respond(fricreg_hb *hb, const struct elements *c, const double *q0, double *q)
{
    size_t nq = 2 * c->dim * (2 * HB_CHAIN_H + 1);
    ck_assert_int_eq(fricreg_hb_solve(hb, OMEGA, nq, q0, q), FRICREG_OK);
}

/* Parameter j of element e (one of the range first..first+count-1) set to 1.25 times its value
 * in place equals the chain built so, both solved from the guess q0 (the unmoved chain's
 * solution: the driver's own start from rest is a continuation in the level, 1 900 Newton
 * iterations for the lift-off elements here, which this test does not check). */
static void check_set(const struct elements *c, size_t first, size_t count, size_t j,
                      const double *q0)
{
    double rebuilt_p[MAXNP], q_set[2 * 3 * 15], q_built[2 * 3 * 15], value = 1.25 * c->p[j];
    memcpy(rebuilt_p, c->p, sizeof rebuilt_p);
    for (size_t e = first; e < first + count; e++)
        rebuilt_p[e * c->np + j] = value;
    fricreg_hb *hb = chain_with(c, c->p), *built = chain_with(c, rebuilt_p);
    if (c->first_moved == 0)
        respond(hb, c, q0, q_set); /* a solution before, which the change forgets */
    ck_assert_int_eq(fricreg_hb_set_element_param(hb, first, count, j, value), FRICREG_OK);
    for (size_t e = 0; e < 2; e++) {
        double got;
        ck_assert_int_eq(fricreg_hb_get_element_param(hb, e, j, &got), FRICREG_OK);
        ck_assert_double_eq(got, rebuilt_p[e * c->np + j]);
    }
    respond(hb, c, q0, q_set);
    respond(built, c, q0, q_built);
    size_t nq = 2 * c->dim * (2 * HB_CHAIN_H + 1);
    if (memcmp(q_set, q_built, nq * sizeof *q_set) != 0)
        ck_abort_msg("%s: parameter %zu of elements %zu..%zu set in place differs from built",
                     c->name, j, first, first + count - 1);
    fricreg_hb_free(hb);
    fricreg_hb_free(built);
}

START_TEST(set_equals_built)
{
    const struct elements *c = &CASES[_i];
    size_t moved = c->np > 4 ? 4 : c->np;
    double q0[2 * 3 * 15];
    fricreg_hb *unmoved = chain_with(c, c->p);
    respond(unmoved, c, NULL, q0);
    fricreg_hb_free(unmoved);
    for (size_t j = c->first_moved; j < moved; j++)
        check_set(c, 1, 1, j, q0);
    if (c->first_moved == 0)
        check_set(c, 0, 2, 0, q0); /* a range shares the value */
}
END_TEST

/* The response moves with the value: a test that cannot pass by a setter that does nothing. */
START_TEST(set_moves_response)
{
    const struct elements *c = &CASES[0];
    double q0[2 * 15], q1[2 * 15];
    fricreg_hb *hb = chain_with(c, c->p);
    respond(hb, c, NULL, q0);
    ck_assert_int_eq(fricreg_hb_set_element_param(hb, 0, 2, 1, 0.5), FRICREG_OK);
    respond(hb, c, NULL, q1);
    ck_assert(memcmp(q0, q1, sizeof q0) != 0);
    fricreg_hb_free(hb);
}
END_TEST

/* Every read of both elements' parameters, the gap 0. */
START_TEST(get_reads_layout)
{
    const struct elements *c = &CASES[_i];
    fricreg_hb *hb = chain_with(c, c->p);
    for (size_t e = 0; e < 2; e++)
        for (size_t j = 0; j < c->np; j++) {
            double got = -1.0;
            ck_assert_int_eq(fricreg_hb_get_element_param(hb, e, j, &got), FRICREG_OK);
            ck_assert_double_eq(got, c->p[e * c->np + j]);
        }
    fricreg_hb_free(hb);
}
END_TEST

/* A refused set: its status, and every parameter as it was. */
static void refused(fricreg_hb *hb, const struct elements *c, size_t first, size_t count, size_t j,
                    double value, int status)
{
    ck_assert_int_eq(fricreg_hb_set_element_param(hb, first, count, j, value), status);
    ck_assert_int_eq(fricreg_hb_errcode(hb), status);
    ck_assert_str_ne(fricreg_hb_errmsg(hb), "");
    for (size_t e = 0; e < 2; e++)
        for (size_t k = 0; k < c->np; k++) {
            double got;
            ck_assert_int_eq(fricreg_hb_get_element_param(hb, e, k, &got), FRICREG_OK);
            ck_assert_double_eq(got, c->p[e * c->np + k]);
        }
}

START_TEST(every_status)
{
    const struct elements *jk = &CASES[0], *cn = &CASES[3], *dahl = &CASES[4];
    fricreg_hb *hb = chain_with(jk, jk->p);
    double v = 7.0;
    ck_assert_int_eq(fricreg_hb_set_element_param(NULL, 0, 1, 0, 1.0), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_get_element_param(NULL, 0, 0, &v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_get_element_param(hb, 0, 0, NULL), FRICREG_ENULL);
    refused(hb, jk, 0, 0, 0, 1.0, FRICREG_EINVAL); /* empty range */
    refused(hb, jk, 1, 2, 0, 1.0, FRICREG_EINVAL); /* beyond the elements */
    refused(hb, jk, 2, 1, 0, 1.0, FRICREG_EINVAL);
    refused(hb, jk, 0, 2, 2, 1.0, FRICREG_EINVAL);  /* beyond the parameters */
    refused(hb, jk, 0, 2, 0, 0.0, FRICREG_EINVAL);  /* a stiffness > 0 */
    refused(hb, jk, 0, 2, 1, -0.1, FRICREG_EINVAL); /* a slip force >= 0 */
    refused(hb, jk, 0, 2, 1, NAN, FRICREG_ENONFINITE);
    refused(hb, jk, 0, 2, 0, INFINITY, FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_get_element_param(hb, 2, 0, &v), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_get_element_param(hb, 0, 2, &v), FRICREG_EINVAL);
    ck_assert_double_eq(v, 7.0);
    fricreg_hb_free(hb);

    hb = chain_with(cn, cn->p);
    refused(hb, cn, 0, 1, 2, -1.0, FRICREG_EINVAL); /* kn >= 0 */
    refused(hb, cn, 0, 1, 4, 0.1, FRICREG_EINVAL);  /* HB's normal law has no gap */
    ck_assert_int_eq(fricreg_hb_set_element_param(hb, 0, 1, 4, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_element_param(hb, 0, 1, 3, -0.5), FRICREG_OK); /* n0 any */
    fricreg_hb_free(hb);

    hb = chain_with(dahl, dahl->p);
    refused(hb, dahl, 0, 2, 1, -1.0, FRICREG_EINVAL); /* by the type's own explain */
    fricreg_hb_free(hb);
}
END_TEST

/* The monitor's calls are refused: the driver is busy. */
struct attempt {
    fricreg_hb *hb;
    int status;
};

static int set_from_monitor(void *user, int64_t iterations, double parameter, double residual)
{
    (void)iterations, (void)parameter, (void)residual;
    struct attempt *at = user;
    at->status = fricreg_hb_set_element_param(at->hb, 0, 1, 0, 30.0);
    return 0;
}

START_TEST(refused_from_monitor)
{
    const struct elements *c = &CASES[0];
    fricreg_hb *hb = chain_with(c, c->p);
    double q[2 * 15];
    struct attempt at = {hb, FRICREG_OK};
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, set_from_monitor, &at), FRICREG_OK);
    respond(hb, c, NULL, q);
    ck_assert_int_eq(at.status, FRICREG_EINVAL);
    double kt;
    ck_assert_int_eq(fricreg_hb_get_element_param(hb, 0, 0, &kt), FRICREG_OK);
    ck_assert_double_eq(kt, 20.0);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_element_param");
    TCase *tc = tcase_create("core");
    tcase_add_loop_test(tc, set_equals_built, 0, NCASES);
    tcase_add_loop_test(tc, get_reads_layout, 0, NCASES);
    tcase_add_test(tc, set_moves_response);
    tcase_add_test(tc, every_status);
    tcase_add_test(tc, refused_from_monitor);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
