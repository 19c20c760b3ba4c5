/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_fit_hb.c — the identification of a harmonic-balance model's nonlinear mode
 * (fricreg_fit_set_model_hb, fricreg_fit.h).
 *
 * The model: a 3-dof chain (unit masses, unit springs ground-1-2-3, dof 2 free), Jenkins
 * elements between dof 0 and the ground and between dofs 0 and 1 (kt = 1, mu N = 0.1, H = 3),
 * Rayleigh's a0 = 0.03 with the modal damping (xi_k = a0), mode 0: its backbone runs from
 * f = 0.0947 Hz stuck down to 0.0709 Hz, zeta from 0.025 up to 0.125 near a = 1.2 and back
 * (measured on fricreg_hb_nma's grid). The parameters: the two elements' shared kt, their
 * shared mu N, a0. The levels' amplitudes avoid round numbers: the march can stall on a point
 * where an element's stick-slip switch falls exactly on a sample (seen at a = 1.2).
 * Where the numbers come from:
 *   - the sensitivities: central differences of fricreg_fit_eval itself (step 1e-5 relative,
 *     Newton's tolerance 1e-12 on the backbone), agreeing to 1e-6 of each derivative's largest
 *     magnitude over the levels, or of f/p and zeta/p where that is larger (a0 moves no
 *     frequency, and its difference is the solves' noise over the step: 5e-9 measured), with modal amplitudes and with dof 2's displacement and
 *     acceleration (the modal amplitudes then solved for by Newton's method);
 *   - the fit: levels made by fricreg_fit_eval at the parameters above, recovered to 1e-6 from
 *     starts 2 to 2.5x off, one start (modal displacements; dof 2's accelerations); from
 *     kt 3x and mu N 0.4x (the slip amplitude 7.5x off) one start ends in a local minimum,
 *     8 starts recover (measured, 5 s: not run here);
 *   - the cache: residuals at one theta and the Jacobian at another (white box,
 *     fit/residuals.h) equal a fresh evaluation's bit for bit; residuals then Jacobian at one
 *     theta cost one evaluation;
 *   - the failures: each status of the new setters provoked, nothing changed on failure, the
 *     driver refusing a call from its monitor. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fit/residuals.h"
#include "fricreg_element.h"
#include "fricreg_fit.h"
#include "fricreg_hb.h"

#define NPAR 3
#define NL 6
#define H 3
#define NDOF 3
#define SENTINEL (-777.125)

enum { ELEMENT = FRICREG_HB_NMA_PARAM_ELEMENT, DAMPING = FRICREG_HB_NMA_PARAM_DAMPING };

static const double truth[NPAR] = {1.0, 0.1, 0.03};
static const int KIND[NPAR] = {ELEMENT, ELEMENT, DAMPING};
static const size_t FIRST[NPAR] = {0, 0, 0}, COUNT[NPAR] = {2, 2, 0}, INDEX[NPAR] = {0, 1, 1};
static const double MODAL_A[NL] = {0.31, 0.52, 0.83, 1.27, 2.09, 3.41};

/* The chain at p = (kt, mun, a0). */
static fricreg_hb *chain(const double p[])
{
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, K[9] = {2, -1, 0, -1, 2, -1, 0, -1, 1};
    const double J[6] = {1, 0, 0, -1, 1, 0}, e[4] = {p[0], p[1], p[0], p[1]};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(NDOF, 2, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, NDOF, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, NDOF, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, p[2], 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 2, NDOF, J, e),
                     FRICREG_OK);
    return hb;
}

/* A fit of the chain's mode 0 (the driver's Newton tolerance tol), its levels' amplitudes at
 * dof 2 where dof. */
static fricreg_fit *hb_fit(fricreg_hb *hb, int dof, double tol)
{
    fricreg_fit *fit = NULL;
    ck_assert_int_eq(fricreg_fit_create(&fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, tol, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_model_hb(fit, hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, NPAR, KIND,
                                              FIRST, COUNT, INDEX),
                     FRICREG_OK);
    if (dof)
        ck_assert_int_eq(fricreg_fit_set_sensor_dof(fit, NDOF, H, 2), FRICREG_OK);
    return fit;
}

/* The levels of kind at the modal amplitudes MODAL_A (through dof 2's where dof): A[NL]. */
static void levels_at_modal(fricreg_fit *fit, fricreg_hb *hb, int dof, int kind, double A[])
{
    for (int i = 0; i < NL; i++) {
        A[i] = MODAL_A[i];
        if (dof || kind != FRICREG_FIT_DISPLACEMENT) { /* one backbone, read at dof 2 */
            double a, w, z, x[NDOF * (2 * H + 1)];
            ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, 1, &MODAL_A[i]),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &w, &z, NDOF, 2 * H + 1, x),
                             FRICREG_OK);
            const double *x2 = x + 2 * (2 * H + 1);
            A[i] = (dof ? hypot(x2[1], x2[2]) : a) * pow(w, kind);
        }
    }
    (void)fit;
}

/* ---- (1) The sensitivities against central differences ---------------------------------- */

/* A difference's evaluation whose march jumped to another branch (a level's frequency 10 %
 * or more off the base's, where the step moves it by 1e-5): the march's known fragility,
 * measured apart (docs/identification.md), not the derivative's; the difference is taken again
 * at a tenth of the step. */
static int off_branch(const double f[], const double fp[], const double fm[])
{
    for (int i = 0; i < NL; i++)
        if (fabs(fp[i] - f[i]) > 0.1 * f[i] || fabs(fm[i] - f[i]) > 0.1 * f[i])
            return 1;
    return 0;
}

static void check_derivatives(int dof, int kind)
{
    fricreg_hb *hb = chain(truth);
    fricreg_fit *fit = hb_fit(hb, dof, 1e-12);
    double A[NL], f[NL], z[NL], a[NL], df[NL * NPAR], dz[NL * NPAR];
    levels_at_modal(fit, hb, dof, kind, A);
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, kind, NL, A, f, z, a, df, dz), FRICREG_OK);
    for (int i = 0; i < NL; i++) /* the levels' modal amplitudes found again */
        ck_assert_double_le(fabs(a[i] - MODAL_A[i]), 1e-8 * MODAL_A[i]);
    for (int j = 0; j < NPAR; j++) {
        double p[NPAR], fp[NL], zp[NL], fm[NL], zm[NL], h = 1e-5 * truth[j];
        for (int tries = 0; tries < 3; tries++, h *= 0.1) {
            memcpy(p, truth, sizeof p);
            p[j] = truth[j] + h;
            ck_assert_msg(fricreg_fit_eval(fit, p, kind, NL, A, fp, zp, NULL, NULL, NULL) == 0,
                          "%s", fricreg_fit_errmsg(fit));
            p[j] = truth[j] - h;
            ck_assert_msg(fricreg_fit_eval(fit, p, kind, NL, A, fm, zm, NULL, NULL, NULL) == 0,
                          "%s", fricreg_fit_errmsg(fit));
            if (!off_branch(f, fp, fm))
                break; /* else a march left the backbone (docs/identification.md, "Limits") */
        }
        double fbig = 0.0, zbig = 0.0; /* where a column vanishes (a0 moves no frequency), f/p */
        for (int i = 0; i < NL; i++) {
            fbig = fmax(fbig, f[i] / truth[j]);
            zbig = fmax(zbig, z[i] / truth[j]);
        }
        for (int i = 0; i < NL; i++) {
            fbig = fmax(fbig, fabs(df[i * NPAR + j]));
            zbig = fmax(zbig, fabs(dz[i * NPAR + j]));
        }
        for (int i = 0; i < NL; i++) {
            double dfd = (fp[i] - fm[i]) / (2 * h), dzd = (zp[i] - zm[i]) / (2 * h);
            ck_assert_msg(fabs(df[i * NPAR + j] - dfd) <= 1e-6 * fbig + 1e-12,
                          "level %d param %d: %g vs %g (f %.12g %.12g %.12g)", i, j,
                          df[i * NPAR + j], dfd, fm[i], f[i], fp[i]);
            ck_assert_double_le(fabs(dz[i * NPAR + j] - dzd), 1e-6 * zbig + 1e-12);
        }
    }
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}

START_TEST(derivatives_modal)
{
    check_derivatives(0, FRICREG_FIT_DISPLACEMENT);
}
END_TEST

START_TEST(derivatives_dof_displacement)
{
    check_derivatives(1, FRICREG_FIT_DISPLACEMENT);
}
END_TEST

START_TEST(derivatives_dof_acceleration)
{
    check_derivatives(1, FRICREG_FIT_ACCELERATION);
}
END_TEST

/* ---- (2) Recovery ------------------------------------------------------------------------ */

static void check_recovery(int dof, int kind, const double factor[NPAR])
{
    fricreg_hb *hb = chain(truth);
    fricreg_fit *fit = hb_fit(hb, dof, 1e-12);
    double A[NL], f[NL], z[NL], p[NPAR], v;
    levels_at_modal(fit, hb, dof, kind, A);
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, kind, NL, A, f, z, NULL, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, kind, A, f, z), FRICREG_OK);
    for (int j = 0; j < NPAR; j++)
        ck_assert_int_eq(fricreg_fit_set_free(fit, j, truth[j] * factor[j], 0.0, INFINITY),
                         FRICREG_OK);
    ck_assert_msg(fricreg_fit_run(fit) == FRICREG_OK, "%s", fricreg_fit_errmsg(fit));
    ck_assert_int_eq(fricreg_fit_get_params(fit, NPAR, p), FRICREG_OK);
    for (int j = 0; j < NPAR; j++)
        ck_assert_double_le(fabs(p[j] - truth[j]), 1e-6 * truth[j]);
    /* the driver left at the fit */
    ck_assert_int_eq(fricreg_hb_get_element_param(hb, 1, 1, &v), FRICREG_OK);
    ck_assert_double_eq(v, p[1]);
    double nmodel, nmarch, nfev, njev;
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_NMODEL, &nmodel), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_NMARCH, &nmarch), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_NFEV, &nfev), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_NJEV, &njev), FRICREG_OK);
    ck_assert_double_lt(nmodel, nfev + njev); /* each Jacobian read from the cache */
    ck_assert_double_ge(nmarch, nmodel);
    /* the fitted curve at the levels is the fit's model */
    double fc[NL], zc[NL], sf[NL], sz[NL];
    ck_assert_int_eq(fricreg_fit_curve(fit, NL, A, fc, zc, sf, sz), FRICREG_OK);
    for (int i = 0; i < NL; i++) {
        ck_assert_double_le(fabs(fc[i] - f[i]), 1e-7 * f[i]);
        ck_assert(isfinite(sf[i]) && isfinite(sz[i]));
    }
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}

START_TEST(recovery_modal)
{
    const double factor[NPAR] = {2.0, 0.5, 2.0};
    check_recovery(0, FRICREG_FIT_DISPLACEMENT, factor);
}
END_TEST

START_TEST(recovery_dof_acceleration)
{
    const double factor[NPAR] = {2.5, 2.5, 0.4};
    check_recovery(1, FRICREG_FIT_ACCELERATION, factor);
}
END_TEST

/* ---- (3) The cache ----------------------------------------------------------------------- */

/* Residuals at theta1, then the Jacobian at theta2: equal to a fresh problem's at theta2 (a
 * cache keyed wrongly would hand back theta1's model); residuals then Jacobian at one theta:
 * one evaluation. */
START_TEST(cache_not_stale)
{
    fricreg_hb *hb = chain(truth);
    fricreg_fit *fit = hb_fit(hb, 1, 1e-12);
    double A[NL], f[NL], z[NL];
    levels_at_modal(fit, hb, 1, FRICREG_FIT_DISPLACEMENT, A);
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, 0, NL, A, f, z, NULL, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, 0, A, f, z), FRICREG_OK);
    const double t1[NPAR] = {log(1.3), log(0.09), log(0.02)};
    const double t2[NPAR] = {log(0.8), log(0.12), log(0.04)};
    struct fr_fit_problem warm, fresh;
    ck_assert_int_eq(fr_fit_problem_init(&warm, fit), FRICREG_OK);
    ck_assert_int_eq(fr_fit_problem_init(&fresh, fit), FRICREG_OK);
    gsl_vector *r = gsl_vector_alloc(2 * NL), *r2 = gsl_vector_alloc(2 * NL);
    gsl_matrix *J = gsl_matrix_alloc(2 * NL, NPAR), *J2 = gsl_matrix_alloc(2 * NL, NPAR);
    ck_assert_int_eq(fr_fit_residuals(&warm, t1, r, NULL), 0);
    ck_assert_int_eq(fr_fit_residuals(&warm, t1, r, J), 0);
    ck_assert_uint_eq(warm.nmodel, 1);
    ck_assert_int_eq(fr_fit_residuals(&warm, t2, r, J), 0);
    ck_assert_uint_eq(warm.nmodel, 2);
    ck_assert_int_eq(fr_fit_residuals(&fresh, t2, r2, J2), 0);
    for (size_t i = 0; i < 2 * NL; i++) {
        ck_assert_double_eq_tol(gsl_vector_get(r, i), gsl_vector_get(r2, i), 1e-9);
        for (size_t k = 0; k < NPAR; k++)
            ck_assert_double_eq_tol(gsl_matrix_get(J, i, k), gsl_matrix_get(J2, i, k),
                                    1e-7 * (1.0 + fabs(gsl_matrix_get(J2, i, k))));
    }
    fr_fit_problem_free(&warm);
    fr_fit_problem_free(&fresh);
    gsl_vector_free(r);
    gsl_vector_free(r2);
    gsl_matrix_free(J);
    gsl_matrix_free(J2);
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}
END_TEST

/* ---- (4) The failures -------------------------------------------------------------------- */

static void expect_model_error(fricreg_fit *fit, fricreg_hb *hb, size_t np, const int kind[],
                               const size_t first[], const size_t count[], const size_t index[],
                               int status, const char *words)
{
    ck_assert_int_eq(fricreg_fit_set_model_hb(fit, hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, np, kind,
                                              first, count, index),
                     status);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), words));
}

START_TEST(model_errors)
{
    fricreg_hb *hb = chain(truth);
    fricreg_fit *fit = NULL;
    ck_assert_int_eq(fricreg_fit_create(&fit), FRICREG_OK);
    const int el[1] = {ELEMENT}, damp[1] = {DAMPING}, amp[1] = {FRICREG_HB_NMA_PARAM_AMPLITUDE};
    const size_t z0[2] = {0, 0}, one[1] = {1}, two[1] = {2}, three[1] = {3}, i7[1] = {7};
    ck_assert_int_eq(fricreg_fit_set_model_hb(NULL, hb, 0, 0, 1, el, z0, one, z0), FRICREG_ENULL);
    expect_model_error(fit, hb, 1, NULL, z0, one, z0, FRICREG_ENULL, "NULL");
    expect_model_error(fit, hb, 0, el, z0, one, z0, FRICREG_EINVAL, "np = 0");
    expect_model_error(fit, hb, 17, el, z0, one, z0, FRICREG_EINVAL, "np = 17");
    expect_model_error(fit, hb, 1, amp, z0, one, z0, FRICREG_EINVAL, "not ELEMENT or DAMPING");
    expect_model_error(fit, hb, 1, el, z0, z0, z0, FRICREG_EINVAL, "not within");
    expect_model_error(fit, hb, 1, el, one, two, z0, FRICREG_EINVAL, "not within");
    expect_model_error(fit, hb, 1, el, z0, three, z0, FRICREG_EINVAL, "not within");
    expect_model_error(fit, hb, 1, el, z0, one, i7, FRICREG_EINVAL, "parameter 0");
    expect_model_error(fit, hb, 1, damp, z0, one, z0, FRICREG_EINVAL, "fit Rayleigh's a0");
    expect_model_error(fit, hb, 1, damp, z0, one, three, FRICREG_EINVAL, "DAMPING index 3");
    const int twice[2] = {ELEMENT, ELEMENT};
    const size_t f2[2] = {0, 1}, c2[2] = {2, 1}, i2[2] = {1, 1};
    expect_model_error(fit, hb, 2, twice, f2, c2, i2, FRICREG_EINVAL, "move the same value");
    ck_assert_int_eq(fricreg_fit_set_model_hb(fit, hb, 0, 9, 1, el, z0, one, z0), FRICREG_EINVAL);
    /* a range whose elements differ */
    ck_assert_int_eq(fricreg_hb_set_element_param(hb, 1, 1, 1, 0.2), FRICREG_OK);
    expect_model_error(fit, hb, 1, el, z0, two, one, FRICREG_EINVAL, "differs");
    /* nothing changed: still the modal Iwan model */
    double p[FRICREG_FIT_NPARAMS];
    ck_assert_int_eq(fricreg_fit_set_free(fit, 5, NAN, 0.0, INFINITY), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, FRICREG_FIT_NPARAMS, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_sensor_dof(fit, NDOF, H, 0), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "modal Iwan"));
    /* the HB model: its which and np */
    ck_assert_int_eq(fricreg_fit_set_model_hb(fit, hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, 1, el, z0,
                                              one, z0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_free(fit, 1, NAN, 0.0, INFINITY), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_fixed(fit, 0, -1.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_sensor_dof(fit, NDOF, H, NDOF), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_sensor_dof(fit, NDOF, 0, 0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_sensor_dof(NULL, NDOF, H, 0), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_set_model_modal_iwan(NULL), FRICREG_ENULL);
    /* eval: p of the model's one entry, a wrong sensor size is the driver's */
    double q[1] = {-1.0}, A[1] = {0.5}, f[1] = {SENTINEL}, z[1] = {SENTINEL};
    ck_assert_int_eq(fricreg_fit_eval(fit, q, 0, 1, A, f, z, NULL, NULL, NULL), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "out of its range"));
    q[0] = 1.0;
    ck_assert_int_eq(fricreg_fit_set_sensor_dof(fit, NDOF + 1, H, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_eval(fit, q, 0, 1, A, f, z, NULL, NULL, NULL), FRICREG_ESIZE);
    ck_assert_double_eq(f[0], SENTINEL);
    /* a level beyond the backbone's reach: an acceleration above what a stuck-free... the
     * march's own limit, here a mode the driver does not have */
    ck_assert_int_eq(fricreg_fit_set_model_hb(fit, hb, 7, FRICREG_HB_NMA_DAMPING_MODAL, 1, el, z0,
                                              one, z0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_eval(fit, q, 0, 1, A, f, z, NULL, NULL, NULL), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "cannot be evaluated"));
    /* back to the modal Iwan model */
    ck_assert_int_eq(fricreg_fit_set_model_hb(fit, NULL, 0, 0, 0, NULL, NULL, NULL, NULL),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_free(fit, 5, NAN, 0.0, INFINITY), FRICREG_OK);
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}
END_TEST

/* A level the backbone cannot reach: the run's "beyond the backbone's reach" naming it. */
START_TEST(unreachable_level)
{
    fricreg_hb *hb = chain(truth);
    fricreg_fit *fit = hb_fit(hb, 0, 1e-12);
    const double A[NL] = {0.31, 0.52, 0.83, 1.27, 2.09, 1e9},
                 f[NL] = {0.08, 0.08, 0.08, 0.08, 0.08, 0.08};
    const double z[NL] = {0.05, 0.05, 0.05, 0.05, 0.05, 0.05};
    double f0[NL], z0[NL];
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, 0, NL, A, f0, z0, NULL, NULL, NULL),
                     FRICREG_EINVAL);
    ck_assert_msg(strstr(fricreg_fit_errmsg(fit), "amplitude[5]") != NULL, "%s",
                  fricreg_fit_errmsg(fit));
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, 0, A, f, z), FRICREG_OK);
    /* a start off the driver's value: the failed run's evaluations move it */
    ck_assert_int_eq(fricreg_fit_set_free(fit, 0, 1.3, 0.0, INFINITY), FRICREG_OK);
    double before;
    ck_assert_int_eq(fricreg_hb_get_element_param(hb, 0, 0, &before), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "level 5"));
    double after;
    ck_assert_int_eq(fricreg_hb_get_element_param(hb, 0, 0, &after), FRICREG_OK);
    ck_assert_double_eq(after, before); /* restored */
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}
END_TEST

/* The driver busy: a call from its monitor is refused, and the fit says so. */
struct busy {
    fricreg_fit *fit;
    int status, calls;
};

static int monitor(void *user, int64_t iterations, double parameter, double residual)
{
    (void)iterations;
    (void)parameter;
    (void)residual;
    struct busy *b = user;
    if (b->calls++ == 0) {
        double A[1] = {0.5}, f[1], z[1];
        b->status = fricreg_fit_eval(b->fit, truth, 0, 1, A, f, z, NULL, NULL, NULL);
    }
    return 0;
}

START_TEST(driver_busy)
{
    fricreg_hb *hb = chain(truth);
    fricreg_fit *fit = hb_fit(hb, 0, 1e-12);
    struct busy b = {fit, FRICREG_OK, 0};
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, monitor, &b), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, 0.3, 1.0, 3), FRICREG_OK);
    ck_assert_int_gt(b.calls, 0);
    ck_assert_int_eq(b.status, FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "monitor"));
    fricreg_fit_free(fit);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_hb");
    TCase *d = tcase_create("derivatives");
    tcase_add_test(d, derivatives_modal);
    tcase_add_test(d, derivatives_dof_displacement);
    tcase_add_test(d, derivatives_dof_acceleration);
    suite_add_tcase(s, d);
    TCase *r = tcase_create("recovery");
    tcase_add_test(r, recovery_modal);
    tcase_add_test(r, recovery_dof_acceleration);
    tcase_add_test(r, cache_not_stale);
    suite_add_tcase(s, r);
    TCase *e = tcase_create("errors");
    tcase_add_test(e, model_errors);
    tcase_add_test(e, unreachable_level);
    tcase_add_test(e, driver_busy);
    suite_add_tcase(s, e);
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
