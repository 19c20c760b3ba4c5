/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_fit_qsma.c — the identification of a harmonic-balance model by quasi-static modal
 * analysis (fricreg_fit_set_model_qsma, fricreg_fit.h).
 *
 * The models: test_fit_hb.c's 3-dof chain with two Jenkins elements (kt = 1, mu N = 0.1,
 * Rayleigh's a0 = 0.03; parameters the shared kt, the shared mu N, a0), and the inclined plane
 * of test_hb_qsma.c, a 2-dof mass on one contact_3d element (kt = 1.5, mu = 0.4, kn = 2,
 * n0 = 0.5, a0 = 0.02; parameters kt, mu, a0: mu and n0 together are nearly the slip force
 * mu N alone, poorly determined apart). Where the numbers come from:
 *   - the sensitivities: central differences of fricreg_fit_eval itself (step 1e-6 relative:
 *     QSMA's path is exact for the chain and its march's own for the plane, so the differences'
 *     error is their h² term), to 1e-6 of each derivative's largest magnitude over the levels
 *     (or of f/p, zeta/p where larger), with modal displacements and with accelerations (the
 *     modal amplitudes then solved by Newton's method through omega(a));
 *   - the fit: levels made by fricreg_fit_eval at the parameters above, recovered to 1e-6 with
 *     one start (the plane's upper bounds DBL_MAX, as Fortran's huge(1.0): none), the plane's 2x off, the chain's 1.7x off (from 2x, kt 2, mu N 0.05, its one
 *     start ends in a local minimum, kt 0.53, mu N 0.36, cost 1.13: measured; the starts'
 *     spread is for that);
 *   - the failures: a level past macroslip out of reach (named), a sensor dof refused, NULLs,
 *     a type QSMA does not take named at the run. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_fit.h"
#include "fricreg_hb.h"

#define NPAR 3
#define NL 6
#define PI 3.14159265358979323846

enum { ELEMENT = FRICREG_HB_NMA_PARAM_ELEMENT, DAMPING = FRICREG_HB_NMA_PARAM_DAMPING };

/* A model, its parameters' description and values, and its levels' modal amplitudes. */
struct model {
    fricreg_hb *(*make)(const double p[]);
    int kind[NPAR];
    size_t first[NPAR], count[NPAR], index[NPAR];
    double truth[NPAR];
    double modal[NL];
    double off;   /* the recovery's start: truth times off (kt, a0) or over it (the slip's) */
    double upper; /* its bounds' upper one: none, or DBL_MAX (none to the fit, not a logistic
                     map whose O(1) values fall among the subnormals) */
};

static fricreg_hb *chain(const double p[])
{
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, K[9] = {2, -1, 0, -1, 2, -1, 0, -1, 1};
    const double J[6] = {1, 0, 0, -1, 1, 0}, e[4] = {p[0], p[1], p[0], p[1]};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(3, 2, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 3, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, p[2], 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 2, 3, J, e),
                     FRICREG_OK);
    return hb;
}

/* The plane at p = (kt, mu, a0). */
static fricreg_hb *plane(const double p[])
{
    const double M[4] = {1.0, 0.0, 0.0, 1.2}, K[4] = {2.0, -0.3, -0.3, 1.5};
    const double J[6] = {1.0, 0.0, 0.0, 1.0, 0.4, -0.3}, e[5] = {p[0], p[1], 2.0, 0.5, 0.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, p[2], 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, 2, J, e),
                     FRICREG_OK);
    return hb;
}

static const struct model CHAIN = {chain,
                                   {ELEMENT, ELEMENT, DAMPING},
                                   {0, 0, 0},
                                   {2, 2, 0},
                                   {0, 1, 1},
                                   {1.0, 0.1, 0.03},
                                   {0.031, 0.12, 0.31, 0.83, 2.09, 3.41},
                                   1.7,
                                   INFINITY};
static const struct model PLANE = {plane,
                                   {ELEMENT, ELEMENT, DAMPING},
                                   {0, 0, 0},
                                   {1, 1, 0},
                                   {0, 1, 1},
                                   {1.5, 0.4, 0.02},
                                   {0.07, 0.15, 0.31, 0.62, 1.13, 1.9},
                                   2.0,
                                   DBL_MAX};

static fricreg_fit *qsma_fit(const struct model *md, fricreg_hb *hb)
{
    fricreg_fit *fit = NULL;
    ck_assert_int_eq(fricreg_fit_create(&fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_model_qsma(fit, hb, 0, NPAR, md->kind, md->first, md->count,
                                                md->index),
                     FRICREG_OK);
    return fit;
}

/* The levels of kind at md's modal amplitudes: A[NL] (ω from QSMA for a velocity or an
 * acceleration). */
static void levels_at_modal(fricreg_fit *fit, const struct model *md, int kind, double A[])
{
    double f[NL], z[NL];
    ck_assert_int_eq(fricreg_fit_eval(fit, md->truth, FRICREG_FIT_DISPLACEMENT, NL, md->modal, f, z,
                                      NULL, NULL, NULL),
                     FRICREG_OK);
    for (int i = 0; i < NL; i++)
        A[i] = md->modal[i] * pow(2.0 * PI * f[i], kind);
}

static void check_derivatives(const struct model *md, int kind)
{
    fricreg_hb *hb = md->make(md->truth);
    fricreg_fit *fit = qsma_fit(md, hb);
    double A[NL], f[NL], z[NL], a[NL], df[NL * NPAR], dz[NL * NPAR], worst = 0.0;
    levels_at_modal(fit, md, kind, A);
    ck_assert_int_eq(fricreg_fit_eval(fit, md->truth, kind, NL, A, f, z, a, df, dz), FRICREG_OK);
    for (int i = 0; i < NL; i++) /* the levels' modal amplitudes found again */
        ck_assert_double_le(fabs(a[i] - md->modal[i]), 1e-10 * md->modal[i]);
    for (int j = 0; j < NPAR; j++) {
        double p[NPAR], fp[NL], zp[NL], fm[NL], zm[NL], h = 1e-6 * md->truth[j];
        memcpy(p, md->truth, sizeof p);
        p[j] = md->truth[j] + h;
        ck_assert_int_eq(fricreg_fit_eval(fit, p, kind, NL, A, fp, zp, NULL, NULL, NULL), 0);
        p[j] = md->truth[j] - h;
        ck_assert_int_eq(fricreg_fit_eval(fit, p, kind, NL, A, fm, zm, NULL, NULL, NULL), 0);
        double fbig = 0.0, zbig = 0.0;
        for (int i = 0; i < NL; i++) {
            fbig = fmax(fbig, fmax(f[i] / md->truth[j], fabs(df[i * NPAR + j])));
            zbig = fmax(zbig, fmax(z[i] / md->truth[j], fabs(dz[i * NPAR + j])));
        }
        for (int i = 0; i < NL; i++) {
            double ef = fabs(df[i * NPAR + j] - (fp[i] - fm[i]) / (2 * h));
            double ez = fabs(dz[i * NPAR + j] - (zp[i] - zm[i]) / (2 * h));
            ck_assert_double_le(ef, 1e-6 * fbig);
            ck_assert_double_le(ez, 1e-6 * zbig);
            worst = fmax(worst, fmax(ef / fbig, ez / zbig));
        }
    }
    if (getenv("HB_PRINT"))
        printf("QSMA fit's derivatives (kind %d) within %.2e of central differences\n", kind,
               worst);
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}

START_TEST(derivatives_chain)
{
    check_derivatives(&CHAIN, FRICREG_FIT_DISPLACEMENT);
    check_derivatives(&CHAIN, FRICREG_FIT_ACCELERATION);
}
END_TEST

START_TEST(derivatives_contact_3d)
{
    check_derivatives(&PLANE, FRICREG_FIT_DISPLACEMENT);
    check_derivatives(&PLANE, FRICREG_FIT_VELOCITY);
}
END_TEST

static void check_recovery(const struct model *md, int kind)
{
    fricreg_hb *hb = md->make(md->truth);
    fricreg_fit *fit = qsma_fit(md, hb);
    double A[NL], f[NL], z[NL], p[NPAR], nmodel;
    levels_at_modal(fit, md, kind, A);
    ck_assert_int_eq(fricreg_fit_eval(fit, md->truth, kind, NL, A, f, z, NULL, NULL, NULL),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, kind, A, f, z), FRICREG_OK);
    for (int j = 0; j < NPAR; j++)
        ck_assert_int_eq(fricreg_fit_set_free(fit, j,
                                              md->truth[j] * (j % 2 ? 1.0 / md->off : md->off), 0.0,
                                              md->upper),
                         FRICREG_OK);
    ck_assert_msg(fricreg_fit_run(fit) == FRICREG_OK, "%s", fricreg_fit_errmsg(fit));
    ck_assert_int_eq(fricreg_fit_get_params(fit, NPAR, p), FRICREG_OK);
    for (int j = 0; j < NPAR; j++)
        ck_assert_double_le(fabs(p[j] - md->truth[j]), 1e-6 * md->truth[j]);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_NMODEL, &nmodel), FRICREG_OK);
    if (getenv("HB_PRINT"))
        printf("QSMA fit recovered in %g model evaluations\n", nmodel);
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}

START_TEST(recovery_chain)
{
    check_recovery(&CHAIN, FRICREG_FIT_DISPLACEMENT);
}
END_TEST

START_TEST(recovery_contact_3d)
{
    check_recovery(&PLANE, FRICREG_FIT_ACCELERATION);
}
END_TEST

START_TEST(failures)
{
    /* macroslip: a unit mass on one Jenkins element alone slips freely at a = 0.2935 */
    const double one = 1.0, zero = 0.0, e[2] = {2.385, 0.7};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 1, 1, &one, e),
                     FRICREG_OK);
    fricreg_fit *fit = NULL;
    const int el = ELEMENT;
    const size_t z0 = 0, c1 = 1, i1 = 1;
    ck_assert_int_eq(fricreg_fit_create(&fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_model_qsma(NULL, hb, 0, 1, &el, &z0, &c1, &i1), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_set_model_qsma(fit, hb, 0, 1, NULL, &z0, &c1, &i1), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_set_model_qsma(fit, hb, 0, 0, &el, &z0, &c1, &i1), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "set_model_qsma"));
    ck_assert_int_eq(fricreg_fit_set_model_qsma(fit, hb, 0, 1, &el, &z0, &c1, &i1), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_sensor_dof(fit, 1, 1, 0), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "modal"));
    const double A[3] = {0.1, 0.2, 0.5}, f[3] = {0.2, 0.2, 0.2}, z[3] = {0.01, 0.01, 0.01};
    double p = 0.7, fo[3], zo[3];
    ck_assert_int_eq(fricreg_fit_eval(fit, &p, 0, 3, A, fo, zo, NULL, NULL, NULL), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "amplitude[2]"));
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "macroslip"));
    ck_assert_int_eq(fricreg_fit_set_levels(fit, 3, 0, A, f, z), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "level 2"));
    /* a type QSMA does not take, named by the driver at the run */
    const double e2[7] = {2.0, 1.0, 0.3, 0.2, 1.5, 1.0, 0.0}, J2[2] = {1.0, 0.5};
    ck_assert_int_eq(fricreg_hb_clear_elements(hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(
                         hb, fricreg_element_sliders(fricreg_element_lookup("iwan_normal"), 2), 1,
                         1, J2, e2),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_model_qsma(fit, hb, 0, 1, &el, &z0, &c1, &i1), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_eval(fit, &p, 0, 3, A, fo, zo, NULL, NULL, NULL), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "iwan_normal"));
    /* NULL: back to the modal Iwan model */
    ck_assert_int_eq(fricreg_fit_set_model_qsma(fit, NULL, 0, 0, NULL, NULL, NULL, NULL),
                     FRICREG_OK);
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_qsma");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, derivatives_chain);
    tcase_add_test(tc, derivatives_contact_3d);
    tcase_add_test(tc, recovery_chain);
    tcase_add_test(tc, recovery_contact_3d);
    tcase_add_test(tc, failures);
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
