/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_fit.c — the identification of a modal Iwan joint (fricreg_fit.h).
 *
 * Where the numbers come from:
 *   - the backbone: Segalman's closed forms in the density's own constants R and S
 *     (../shared/notes/identification.md: F(u) = R u^(chi+2)/(chi+2) + u (R (phi_max^(chi+1) -
 *     u^(chi+1))/(chi+1) + S), D(A) = 4 R A^(chi+3)/((chi+2)(chi+3)) below macroslip, and the
 *     sliders' sum of 4 phi (A - phi) above), written here independently of the library's
 *     x = a/phi_max form; the equivalent linearization omega^2 = K0 + F/a, zeta = zeta0 +
 *     D/(2 pi omega^2 a^2);
 *   - the sensitivities: central differences of the backbone itself (step 1e-5 relative),
 *     agreeing to 1e-6 of each derivative's largest magnitude;
 *   - the fit: levels made by known parameters (a joint near 170 Hz: F_S 30, K_T 3e5, chi 0.3,
 *     beta 0.5, zeta0 0.002, K0 8.4e5; 8 levels from 3 % to 150 % of phi_max, accelerations
 *     at a sensor of shape 0.37); noise-free they are recovered to 1e-6 from starts 10x off;
 *     with 1 % noise in zeta and 0.05 % in f (GSL's MT19937, seed 1, 100 draws) the 95 %
 *     intervals hold the truth in 90-99 % of draws (measured: 93-96 % per parameter; seeds 2-4
 *     gave 89-97 %); a run stops once a Gauss-Newton step would take less than 1e-9 of the
 *     cost off: started at its answer again, the fit moves by 1e-5 standard errors;
 *   - relative residuals: the covariance is the one with deviations equal to the measured
 *     values, scaled by r^T r/(2n - p), and the quantile Student's t (2.1788 at 12 degrees of
 *     freedom);
 *   - the failures: each status of the header provoked, the caller's arrays untouched. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "fricreg_fit.h"

#define NP FRICREG_FIT_NPARAMS
#define NL 8
#define SENSOR 0.37
#define TWO_PI 6.283185307179586

static const double truth[NP] = {30.0, 3e5, 0.3, 0.5, 0.002, 8.4e5};

static double phi_max_of(const double p[])
{
    double c = p[FRICREG_FIT_BETA] + (p[FRICREG_FIT_CHI] + 1.0) / (p[FRICREG_FIT_CHI] + 2.0);
    return p[FRICREG_FIT_FS] * (1.0 + p[FRICREG_FIT_BETA]) / (p[FRICREG_FIT_KT] * c);
}

/* omega^2 and zeta at the modal amplitude a, by the notes' R, S form. */
static void reference(const double p[], double a, double *w2, double *zeta)
{
    double chi = p[FRICREG_FIT_CHI], beta = p[FRICREG_FIT_BETA], fs = p[FRICREG_FIT_FS];
    double c = beta + (chi + 1.0) / (chi + 2.0), pm = phi_max_of(p);
    double R = fs * (chi + 1.0) / (pow(pm, chi + 2.0) * c), S = fs / pm * beta / c, F, D;
    if (a < pm) {
        F = R * pow(a, chi + 2.0) / (chi + 2.0) +
            a * (R * (pow(pm, chi + 1.0) - pow(a, chi + 1.0)) / (chi + 1.0) + S);
        D = 4.0 * R * pow(a, chi + 3.0) / ((chi + 2.0) * (chi + 3.0));
    } else {
        F = fs;
        D = 4.0 * R * (a * pow(pm, chi + 2.0) / (chi + 2.0) - pow(pm, chi + 3.0) / (chi + 3.0)) +
            4.0 * S * pm * (a - pm);
    }
    *w2 = p[FRICREG_FIT_K0] + F / a;
    *zeta = p[FRICREG_FIT_ZETA0] + D / (TWO_PI * *w2 * a * a);
}

static fricreg_fit *new_fit(void)
{
    fricreg_fit *fit = NULL;
    ck_assert_int_eq(fricreg_fit_create(&fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_sensor(fit, SENSOR), FRICREG_OK);
    return fit;
}

/* The levels' accelerations (3 % to 150 % of phi_max, geometric) and the truth's f, zeta. */
static void true_levels(fricreg_fit *fit, double A[], double f[], double z[])
{
    double pm = phi_max_of(truth);
    for (int i = 0; i < NL; i++)
        A[i] = SENSOR * pm * 0.03 * pow(50.0, i / 7.0) * pow(TWO_PI * 165.0, 2);
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, FRICREG_FIT_ACCELERATION, NL, A, f, z, NULL, NULL,
                                      NULL),
                     FRICREG_OK);
}

/* Every parameter free, started 10x off (chi + 1 by 10). */
static void free_10x_off(fricreg_fit *fit)
{
    const double factor[NP] = {10.0, 0.1, 10.0, 10.0, 0.1, 10.0};
    for (int j = 0; j < NP; j++) {
        double start = j == FRICREG_FIT_CHI ? factor[j] * (truth[j] + 1.0) - 1.0
                                            : truth[j] * factor[j];
        double lower = j == FRICREG_FIT_CHI ? -1.0 : 0.0;
        ck_assert_int_eq(fricreg_fit_set_free(fit, j, start, lower, INFINITY), FRICREG_OK);
    }
}

START_TEST(test_backbone_closed_forms)
{
    fricreg_fit *fit = new_fit();
    const double p[NP] = {2.385, 41.7, -0.37, 0.81, 0.0031, 17.3};
    double pm = phi_max_of(p), A[9], f[9], z[9], a[9];
    for (int i = 0; i < 9; i++)
        A[i] = SENSOR * pm * 0.01 * pow(400.0, i / 8.0); /* 1 % to 4x phi_max */
    ck_assert_int_eq(fricreg_fit_eval(fit, p, FRICREG_FIT_DISPLACEMENT, 9, A, f, z, a, NULL, NULL),
                     FRICREG_OK);
    for (int i = 0; i < 9; i++) {
        double w2, zeta;
        ck_assert_double_eq_tol(a[i], A[i] / SENSOR, 1e-15 * a[i]);
        reference(p, a[i], &w2, &zeta);
        ck_assert_double_eq_tol(f[i], sqrt(w2) / TWO_PI, 1e-12 * f[i]);
        ck_assert_double_eq_tol(z[i], zeta, 1e-12 * zeta);
    }
    /* A velocity and an acceleration level: the modal amplitude solves |s| omega^k a = A. */
    for (int kind = FRICREG_FIT_VELOCITY; kind <= FRICREG_FIT_ACCELERATION; kind++) {
        double Ak = 0.7 * pm * SENSOR * pow(TWO_PI * 0.5, kind), fk, zk, ak, w2, zeta;
        ck_assert_int_eq(fricreg_fit_eval(fit, p, kind, 1, &Ak, &fk, &zk, &ak, NULL, NULL),
                         FRICREG_OK);
        reference(p, ak, &w2, &zeta);
        ck_assert_double_eq_tol(SENSOR * pow(w2, 0.5 * kind) * ak, Ak, 1e-13 * Ak);
        ck_assert_double_eq_tol(zk, zeta, 1e-12 * zeta);
    }
    fricreg_fit_free(fit);
}
END_TEST

START_TEST(test_sensitivities_central_differences)
{
    fricreg_fit *fit = new_fit();
    double pm = phi_max_of(truth);
    for (int kind = 0; kind <= 2; kind++) {
        double A[NL], f[NL], z[NL], df[NL * NP], dz[NL * NP];
        for (int i = 0; i < NL; i++) /* 2 % to 150 %, none within 1 % of phi_max's kink */
            A[i] = SENSOR * pm * 0.02 * pow(75.0, i / 7.0) * pow(TWO_PI * 165.0, kind);
        ck_assert_int_eq(fricreg_fit_eval(fit, truth, kind, NL, A, f, z, NULL, df, dz), FRICREG_OK);
        for (int j = 0; j < NP; j++) {
            double q[NP], fp[NL], zp[NL], fm[NL], zm[NL], h = 1e-5 * fabs(truth[j]), big_f = 0.0,
                                                          big_z = 0.0;
            memcpy(q, truth, sizeof q);
            q[j] = truth[j] + h;
            ck_assert_int_eq(fricreg_fit_eval(fit, q, kind, NL, A, fp, zp, NULL, NULL, NULL), 0);
            q[j] = truth[j] - h;
            ck_assert_int_eq(fricreg_fit_eval(fit, q, kind, NL, A, fm, zm, NULL, NULL, NULL), 0);
            for (int i = 0; i < NL; i++) {
                big_f = fmax(big_f, fabs(df[i * NP + j]));
                big_z = fmax(big_z, fabs(dz[i * NP + j]));
            }
            for (int i = 0; i < NL; i++) {
                ck_assert_double_eq_tol((fp[i] - fm[i]) / (2.0 * h), df[i * NP + j],
                                        1e-6 * big_f + 1e-300);
                ck_assert_double_eq_tol((zp[i] - zm[i]) / (2.0 * h), dz[i * NP + j],
                                        1e-6 * big_z + 1e-300);
            }
        }
    }
    fricreg_fit_free(fit);
}
END_TEST

START_TEST(test_noise_free_recovery)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], sf[NL], sz[NL], p[NP], lo[NP], hi[NP], v;
    true_levels(fit, A, f, z);
    for (int i = 0; i < NL; i++) {
        sf[i] = 5e-4 * f[i];
        sz[i] = 0.01 * z[i];
    }
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, sf, sz), FRICREG_OK);
    free_10x_off(fit);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_covariance(fit, NP, NULL, lo, hi), FRICREG_OK);
    for (int j = 0; j < NP; j++) {
        ck_assert_double_eq_tol(p[j], truth[j], 1e-6 * fabs(truth[j]));
        ck_assert(lo[j] < truth[j] && truth[j] < hi[j]);
    }
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_COST, &v), FRICREG_OK);
    ck_assert(v < 1e-12);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_NFREE, &v), FRICREG_OK);
    ck_assert_double_eq(v, NP);
    ck_assert_int_eq(fricreg_fit_get_quantile(fit, &v), FRICREG_OK);
    ck_assert_double_eq_tol(v, 1.959963984540054, 1e-12);
    /* From the levels' own start too (no start given). */
    for (int j = 0; j < NP; j++)
        ck_assert_int_eq(fricreg_fit_set_free(fit, j, NAN, j == 2 ? -1.0 : 0.0, INFINITY), 0);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_OK);
    for (int j = 0; j < NP; j++)
        ck_assert_double_eq_tol(p[j], truth[j], 1e-6 * fabs(truth[j]));
    fricreg_fit_free(fit);
}
END_TEST

START_TEST(test_coverage_of_intervals)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], sf[NL], sz[NL], fm[NL], zm[NL], lo[NP], hi[NP];
    int inside[NP] = {0}, fits = 0;
    true_levels(fit, A, f, z);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    ck_assert_ptr_nonnull(rng);
    gsl_rng_set(rng, 1);
    for (int draw = 0; draw < 100; draw++) {
        for (int i = 0; i < NL; i++) {
            sf[i] = 5e-4 * f[i];
            sz[i] = 0.01 * z[i];
            fm[i] = f[i] + gsl_ran_gaussian(rng, sf[i]);
            zm[i] = z[i] + gsl_ran_gaussian(rng, sz[i]);
        }
        ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, fm, zm), 0);
        ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, sf, sz), FRICREG_OK);
        free_10x_off(fit);
        if (fricreg_fit_run(fit) != FRICREG_OK)
            continue;
        fits++;
        ck_assert_int_eq(fricreg_fit_get_covariance(fit, NP, NULL, lo, hi), FRICREG_OK);
        for (int j = 0; j < NP; j++)
            inside[j] += lo[j] <= truth[j] && truth[j] <= hi[j];
    }
    gsl_rng_free(rng);
    ck_assert_int_eq(fits, 100);
    for (int j = 0; j < NP; j++)
        ck_assert_msg(inside[j] >= 90 && inside[j] <= 99, "parameter %d: %d of 100", j, inside[j]);
    fricreg_fit_free(fit);
}
END_TEST

/* A run stops where a Gauss-Newton step would lower the cost by less than 1e-9 of it: one noisy
 * draw from the truth 2x off, one start. Started again at its answer, the fit moves less than
 * 1e-4 of a standard error, and it took ITERATIONS_WITH_RULE iterations, where GSL's step test
 * alone (the rule left out) took three more, its answer 1e-5 standard errors away. */
#define ITERATIONS_WITH_RULE 10
START_TEST(test_stops_at_negligible_decrement)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], sf[NL], sz[NL], p[NP], again[NP], cov[NP * NP], iters;
    true_levels(fit, A, f, z);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    ck_assert_ptr_nonnull(rng);
    gsl_rng_set(rng, 1);
    for (int i = 0; i < NL; i++) {
        sf[i] = 5e-4 * f[i];
        sz[i] = 0.01 * z[i];
        f[i] += gsl_ran_gaussian(rng, sf[i]);
        z[i] += gsl_ran_gaussian(rng, sz[i]);
    }
    gsl_rng_free(rng);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, sf, sz), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_starts(fit, 1), FRICREG_OK);
    for (int j = 0; j < NP; j++)
        ck_assert_int_eq(fricreg_fit_set_free(fit, j, truth[j] * (j % 2 ? 0.5 : 2.0),
                                              j == FRICREG_FIT_CHI ? -1.0 : 0.0, INFINITY),
                         FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_covariance(fit, NP, cov, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_ITERATIONS, &iters), FRICREG_OK);
    for (int j = 0; j < NP; j++)
        ck_assert_int_eq(fricreg_fit_set_free(fit, j, p[j], j == FRICREG_FIT_CHI ? -1.0 : 0.0,
                                              INFINITY),
                         FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, again), FRICREG_OK);
    for (int j = 0; j < NP; j++) {
        ck_assert_double_le(fabs(again[j] - p[j]), 1e-4 * sqrt(cov[j * NP + j]));
    }
    ck_assert_double_eq(iters, ITERATIONS_WITH_RULE);
    fricreg_fit_free(fit);
}
END_TEST

START_TEST(test_relative_residuals)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], cov_rel[NP * NP], cov_abs[NP * NP], var, q;
    true_levels(fit, A, f, z);
    for (int i = 0; i < NL; i++) { /* a deterministic disturbance, so r^T r > 0 */
        f[i] *= 1.0 + 4e-4 * sin(2.1 * i);
        z[i] *= 1.0 + 1e-2 * cos(1.3 * i);
    }
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_set_fixed(fit, FRICREG_FIT_BETA, truth[FRICREG_FIT_BETA]), 0);
    ck_assert_int_eq(fricreg_fit_set_fixed(fit, FRICREG_FIT_K0, truth[FRICREG_FIT_K0]), 0);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_covariance(fit, NP, cov_rel, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_RESIDUAL_VARIANCE, &var), 0);
    ck_assert_int_eq(fricreg_fit_get_quantile(fit, &q), FRICREG_OK);
    ck_assert_double_eq_tol(q, 2.178812829667228, 1e-9); /* t(0.975) at 2 8 - 4 = 12 */
    ck_assert_double_eq(cov_rel[FRICREG_FIT_BETA * NP + FRICREG_FIT_BETA], 0.0);
    ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, f, z), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_covariance(fit, NP, cov_abs, NULL, NULL), FRICREG_OK);
    for (int i = 0; i < NP; i++) /* symmetric to the bit, as the header's covariance is */
        for (int j = 0; j < NP; j++)
            ck_assert(cov_abs[i * NP + j] == cov_abs[j * NP + i]);
    for (int k = 0; k < NP * NP; k++)
        ck_assert_double_eq_tol(cov_rel[k], var * cov_abs[k],
                                1e-6 * fabs(var * cov_abs[k]) + 1e-300);
    fricreg_fit_free(fit);
}
END_TEST

START_TEST(test_bad_input)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], p[NP], bad[NL];
    true_levels(fit, A, f, z);
    ck_assert_int_eq(fricreg_fit_create(NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_set_levels(NULL, NL, 0, A, f, z), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, 0, NULL, f, z), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, 0, 0, A, f, z), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, 3, A, f, z), FRICREG_EINVAL);
    memcpy(bad, A, sizeof bad);
    bad[3] = -1.0;
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, 0, bad, f, z), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "amplitude[3]"));
    bad[3] = NAN;
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, 0, A, bad, z), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, 0, A, f, bad), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_fit_errcode(fit), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_EINVAL); /* no levels were set */
    ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, f, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, f, z), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_fit_set_sensor(fit, 0.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_sensor(fit, INFINITY), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_fit_set_free(fit, NP, 1.0, 0.0, INFINITY), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_free(fit, FRICREG_FIT_CHI, 0.0, -2.0, 1.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_free(fit, FRICREG_FIT_FS, 5.0, 1.0, 1.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_free(fit, FRICREG_FIT_FS, 5.0, 6.0, 9.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_free(fit, FRICREG_FIT_FS, 5.0, NAN, 9.0), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_fit_set_fixed(fit, FRICREG_FIT_KT, 0.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_fixed(fit, FRICREG_FIT_CHI, -1.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_fixed(fit, FRICREG_FIT_BETA, NAN), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_fit_set_starts(fit, 0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_starts(fit, 1001), FRICREG_EINVAL);
    /* Fewer levels than free parameters; no parameter free. */
    ck_assert_int_eq(fricreg_fit_set_levels(fit, 5, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "5 levels for 6 free"));
    for (int j = 0; j < NP; j++)
        ck_assert_int_eq(fricreg_fit_set_fixed(fit, j, truth[j]), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_EINVAL);
    /* eval: a parameter out of range, an amplitude <= 0; nothing written. */
    double out[NL], keep[NL];
    for (int i = 0; i < NL; i++)
        out[i] = keep[i] = 2.385 + i;
    memcpy(p, truth, sizeof p);
    p[FRICREG_FIT_CHI] = -1.5;
    ck_assert_int_eq(fricreg_fit_eval(fit, p, 0, NL, A, out, out, NULL, NULL, NULL),
                     FRICREG_EINVAL);
    p[FRICREG_FIT_CHI] = NAN;
    ck_assert_int_eq(fricreg_fit_eval(fit, p, 0, NL, A, out, out, NULL, NULL, NULL),
                     FRICREG_ENONFINITE);
    bad[3] = 0.0;
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, 0, NL, bad, out, out, NULL, NULL, NULL),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, 0, 0, A, out, out, NULL, NULL, NULL),
                     FRICREG_EINVAL);
    ck_assert_mem_eq(out, keep, sizeof out);
    fricreg_fit_free(fit);
    fricreg_fit_free(NULL);
}
END_TEST

START_TEST(test_no_fit_is_reported_before_a_run)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], p[NP], keep[NP], sv[NP], v = 2.385, r[NL];
    for (int j = 0; j < NP; j++)
        p[j] = keep[j] = 2.385 * j;
    true_levels(fit, A, f, z);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_get_value(fit, FRICREG_FIT_COST, &v), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP - 1, p), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_get_covariance(fit, NP, NULL, p, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_get_identifiability(fit, NP, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_fit_get_residuals(fit, NL - 1, r, r), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_fit_get_value(fit, 99, &v), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_get_identifiability(fit, NP, sv, NULL), FRICREG_OK);
    ck_assert(sv[0] >= sv[NP - 1] && sv[NP - 1] > 0.0);
    /* Any setter forgets the fit, even one that sets what was there. */
    ck_assert_int_eq(fricreg_fit_set_sensor(fit, SENSOR), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_fit_curve(fit, NL, A, r, r, NULL, NULL), FRICREG_EINVAL);
    ck_assert_mem_eq(p, keep, sizeof p);
    ck_assert_double_eq(v, 2.385);
    fricreg_fit_free(fit);
}
END_TEST

START_TEST(test_fit_failures)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], sf[NL], sz[NL], p[NP];
    true_levels(fit, A, f, z);
    for (int i = 0; i < NL; i++) {
        sf[i] = 5e-4 * f[i];
        sz[i] = 0.01 * z[i];
    }
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, sf, sz), FRICREG_OK);
    /* One start 10x off does not converge within 500 iterations (the valley where beta runs
     * to 0: the second centre, the levels' start, is what rescues it with more starts). */
    free_10x_off(fit);
    ck_assert_int_eq(fricreg_fit_set_starts(fit, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_EWORK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_EINVAL);
    /* Levels of a joint without the delta (beta = 0) fitted with beta free: at its bound. */
    double p0[NP];
    memcpy(p0, truth, sizeof p0);
    p0[FRICREG_FIT_BETA] = 0.0;
    ck_assert_int_eq(fricreg_fit_eval(fit, p0, FRICREG_FIT_ACCELERATION, NL, A, f, z, NULL, NULL,
                                      NULL),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_set_starts(fit, 8), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "beta ended at its lower bound"));
    ck_assert_int_eq(fricreg_fit_set_fixed(fit, FRICREG_FIT_BETA, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_OK);
    ck_assert_double_eq_tol(p[FRICREG_FIT_CHI], truth[FRICREG_FIT_CHI], 1e-6);
    /* Eight levels at one amplitude give two numbers (f, zeta) for three free parameters:
     * rank deficient. */
    double same[NL];
    for (int i = 0; i < NL; i++)
        same[i] = A[4];
    ck_assert_int_eq(fricreg_fit_eval(fit, truth, FRICREG_FIT_ACCELERATION, NL, same, f, z, NULL,
                                      NULL, NULL),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, same, f, z), 0);
    for (int j = 0; j < NP; j++)
        if (j == FRICREG_FIT_CHI || j == FRICREG_FIT_BETA || j == FRICREG_FIT_ZETA0)
            ck_assert_int_eq(fricreg_fit_set_fixed(fit, j, truth[j]), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_ESINGULAR);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "do not determine"));
    /* K0 = 0 with accelerations beyond |s| F_S: out of the backbone's reach. */
    double far = 2.0 * SENSOR * truth[FRICREG_FIT_FS], ff, zf;
    memcpy(p0, truth, sizeof p0);
    p0[FRICREG_FIT_K0] = 0.0;
    ck_assert_int_eq(fricreg_fit_eval(fit, p0, FRICREG_FIT_ACCELERATION, 1, &far, &ff, &zf, NULL,
                                      NULL, NULL),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_fit_errmsg(fit), "reach"));
    fricreg_fit_free(fit);
}
END_TEST

START_TEST(test_curve_band)
{
    fricreg_fit *fit = new_fit();
    double A[NL], f[NL], z[NL], sf[NL], sz[NL], cf[NL], cz[NL], bf[NL], bz[NL], cov[NP * NP];
    double df[NL * NP], dz[NL * NP], p[NP];
    true_levels(fit, A, f, z);
    for (int i = 0; i < NL; i++) {
        sf[i] = 5e-4 * f[i];
        sz[i] = 0.01 * z[i];
        f[i] *= 1.0 + 4e-4 * sin(2.1 * i);
    }
    ck_assert_int_eq(fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z), 0);
    ck_assert_int_eq(fricreg_fit_set_deviations(fit, NL, sf, sz), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_run(fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_curve(fit, NL, A, cf, cz, bf, bz), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_params(fit, NP, p), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_get_covariance(fit, NP, cov, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_eval(fit, p, FRICREG_FIT_ACCELERATION, NL, A, sf, sz, NULL, df,
                                      dz),
                     FRICREG_OK);
    double r_f[NL], r_z[NL];
    ck_assert_int_eq(fricreg_fit_get_residuals(fit, NL, r_f, r_z), FRICREG_OK);
    for (int i = 0; i < NL; i++) {
        double vf = 0.0;
        for (int a = 0; a < NP; a++)
            for (int b = 0; b < NP; b++)
                vf += df[i * NP + a] * cov[a * NP + b] * df[i * NP + b];
        ck_assert_double_eq(cf[i], sf[i]);
        ck_assert_double_eq(cz[i], sz[i]);
        ck_assert_double_eq_tol(bf[i], sqrt(vf), 1e-12 * sqrt(vf));
        ck_assert_double_eq_tol(r_f[i],
                                (cf[i] - f[i]) / (5e-4 * f[i] / (1.0 + 4e-4 * sin(2.1 * i))), 1e-9);
    }
    fricreg_fit_free(fit);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("fit");
    TCase *tc = tcase_create("fit");
    tcase_add_test(tc, test_backbone_closed_forms);
    tcase_add_test(tc, test_sensitivities_central_differences);
    tcase_add_test(tc, test_noise_free_recovery);
    tcase_add_test(tc, test_stops_at_negligible_decrement);
    tcase_add_test(tc, test_coverage_of_intervals);
    tcase_add_test(tc, test_relative_residuals);
    tcase_add_test(tc, test_bad_input);
    tcase_add_test(tc, test_no_fit_is_reported_before_a_run);
    tcase_add_test(tc, test_fit_failures);
    tcase_add_test(tc, test_curve_band);
    suite_add_tcase(suite, tc);
    SRunner *sr = srunner_create(suite);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
