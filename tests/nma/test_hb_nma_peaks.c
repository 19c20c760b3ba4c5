/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_peaks.c — Check suite: the backbones of fricreg_hb_nma pass through the forced
 * responses' resonance peaks (fricreg_hb_nma, fricreg_hb_nma_point, fricreg_hb_solve;
 * fricreg_hb.h).
 *
 * The structure: two masses in a chain, m = (1, 0.35), springs ground–1 of 1 and 1–2 of 2.385,
 * two Jenkins elements, ground–1 (J row (1, 0), kt = 0.2, mu N = 0.25) and 1–2 (J row (−1, 1),
 * kt = 0.35, mu N = 0.3), H = 7. Stuck, its modes are at 0.928 and 3.300 rad/s (ratio 3.56: no
 * internal resonance within reach); slipping, mode 1 at a = 3 is at 0.8897 (ζ from friction
 * 0.028), mode 2 at a = 2.4 at 3.1157 (ζ 0.014). Linear damping C = c M, c = 2 ζ_lin ω_k
 * (the stuck mode's ratio ζ_lin), ζ_lin = 0.04, 0.01, 0.0025, 0.000625.
 *
 * What "passes through" means. The forced response under F = f M φ_k cos Ωt (φ_k the stuck
 * mode, mass-normalized) and the EPMC's mode (Krack 2015: fricreg_hb.h, Nonlinear modes)
 *
 *     M x'' + C x' + K x + J^T f(J x) = f M φ_k cos Ωt,
 *     M x'' + C x' + K x + J^T f(J x) = ξ M x',
 *
 * differ only in the drive. Were the mode's motion x = a φ_k cos ωt alone, its drive
 * ξ M x' = −ξ ω a M φ_k sin ωt would be the forcing at Ω = ω, f = ξ ω a = 2 ζ ω² a, with the
 * modal coordinate φ_k^T M X_1 lagging the force by 90°: the phase resonance is a point of the
 * backbone. What the forcing lacks, the drive of the mode's higher harmonics and of its other
 * modes' content, is ξ times their small size: it moves the phase resonance off the backbone
 * by 1e-5 here, less as ξ falls, down to what friction's own ξ leaves. The damping option is
 * FRICREG_HB_NMA_DAMPING_MATRIX: the forced model's own C, so that the drive is the only
 * difference (with C = c M, _MODAL's ξ_k M is the same matrix; with a non-proportional C it
 * would drop the coupling the forced response has).
 *
 * The amplitude's maximum is another point. In the single-mode reduced model (Krack 2015:
 * modal amplitude a, the backbone's ω(a) and ζ(a)), a (ω² − Ω² + i 2 ζ_v ω Ω + i 2 ζ_f ω²) = f,
 * with ζ_v = c/(2ω) the viscous part and ζ_f = ζ − ζ_v friction's (rate-independent: its force
 * at a given a does not depend on Ω), the maximum of a over Ω at fixed a solves
 * r (1 − r²) = 2 ζ_v (ζ_v r + ζ_f), r = Ω/ω, i.e. Ω/ω − 1 = −ζ_v ζ (1 + O(ζ²)): friction alone
 * would put the maximum on the backbone, the viscous part pulls it below, and that vanishes
 * with c — the backbone passes through the peaks as the damping decreases.
 *
 * The peaks are located on point solves (fricreg_hb_solve, warm-started): the phase resonance
 * as the root of the modal coordinate's in-phase part (GSL's Brent root, to 1e-12 of Ω), the
 * maximum of |φ_k^T M X_1| by GSL's Brent minimizer (to 1e-7 of Ω: the maximum is flat). The
 * backbone is then solved at exactly each one's amplitude (a march whose last point it is).
 *
 * Measured (offsets Ω/ω_backbone(a) − 1; a_pr/a_target − 1 from the level f = 2 ζ ω² a_target):
 *
 *     mode ζ_lin     phase res.  amplitude max  −ζ_v ζ     a_pr/a_t − 1
 *     1    0.04      −1.16e-5    −2.93e-3       −2.91e-3   −3.4e-4
 *     1    0.01      −6.48e-6    −4.09e-4       −4.01e-4   −3.4e-4
 *     1    0.0025    −5.18e-6    −8.60e-5       −7.99e-5   −3.4e-4
 *     1    0.000625  −4.85e-6    −2.44e-5       −1.87e-5   −3.4e-4
 *     2    0.04      −1.15e-6    −2.36e-3       −2.36e-3   −7.0e-5
 *     2    0.01      −4.82e-7    −2.52e-4       −2.54e-4   −9.5e-5
 *     2    0.0025    −3.21e-7    −4.11e-5       −4.26e-5   −1.2e-4
 *     2    0.000625  −2.81e-7    −7.95e-6       −9.33e-6   −1.4e-4
 *
 * Asserted: the phase resonance within 5e-5, shrinking with the damping; a_pr within 1e-3 of
 * a_target (the backbone's ζ, not only its ω); the maximum's offset, less the phase
 * resonance's, on −ζ_v ζ to 5e-6 + 1 % of it (measured 1.1e-5 at most, at ζ_lin = 0.04, the
 * O(ζ²) terms), shrinking by at least 2 per level; at the smallest damping both within 1e-3
 * (the acceptance). */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

#include "fricreg_hb.h"

#define NDOF 2
#define NEL 2
#define H 7
#define NC (2 * H + 1)
#define NQ (NEL * NC)

static const double mass[NDOF * NDOF] = {1.0, 0.0, 0.0, 0.35};
static const double stiffness[NDOF * NDOF] = {3.385, -2.385, -2.385, 2.385};
static const double rows[NEL * NDOF] = {1.0, 0.0, -1.0, 1.0};
static const double kt[NEL] = {0.2, 0.35};
static const double mun[NEL] = {0.25, 0.3};

/* The driver at mass-proportional damping C = c M. */
static fricreg_hb *model(double c)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(NDOF, NEL, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, NDOF, mass), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, NDOF, stiffness), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, c, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, NEL, NDOF, rows, kt, mun), FRICREG_OK);
    return hb;
}

/* The stuck structure's modes, K_0 φ = ω² M φ, K_0 = K + J^T diag(kt) J, mass-normalized
 * (GSL's generalized symmetric eigensolver). */
static void stuck_modes(double omega[NDOF], double phi[NDOF][NDOF])
{
    gsl_matrix *k0 = gsl_matrix_alloc(NDOF, NDOF), *m = gsl_matrix_alloc(NDOF, NDOF);
    gsl_matrix *v = gsl_matrix_alloc(NDOF, NDOF);
    gsl_vector *w = gsl_vector_alloc(NDOF);
    gsl_eigen_gensymmv_workspace *ws = gsl_eigen_gensymmv_alloc(NDOF);
    for (int i = 0; i < NDOF; i++)
        for (int j = 0; j < NDOF; j++) {
            double s = stiffness[NDOF * i + j];
            for (int e = 0; e < NEL; e++)
                s += rows[NDOF * e + i] * kt[e] * rows[NDOF * e + j];
            gsl_matrix_set(k0, i, j, s);
            gsl_matrix_set(m, i, j, mass[NDOF * i + j]);
        }
    ck_assert_int_eq(gsl_eigen_gensymmv(k0, m, w, v, ws), GSL_SUCCESS);
    ck_assert_int_eq(gsl_eigen_gensymmv_sort(w, v, GSL_EIGEN_SORT_VAL_ASC), GSL_SUCCESS);
    for (int k = 0; k < NDOF; k++) {
        omega[k] = sqrt(gsl_vector_get(w, k));
        double norm = 0.0; /* GSL normalizes to |v| = 1: mass-normalize */
        for (int i = 0; i < NDOF; i++)
            for (int j = 0; j < NDOF; j++)
                norm += gsl_matrix_get(v, i, k) * mass[NDOF * i + j] * gsl_matrix_get(v, j, k);
        for (int i = 0; i < NDOF; i++)
            phi[k][i] = gsl_matrix_get(v, i, k) / sqrt(norm);
    }
    gsl_eigen_gensymmv_free(ws);
    gsl_vector_free(w);
    gsl_matrix_free(v);
    gsl_matrix_free(m);
    gsl_matrix_free(k0);
}

/* The backbone of mode k at exactly amplitude a: a march from a/64 (below the first slip)
 * whose last point is a. */
static void backbone_at(fricreg_hb *hb, size_t k, double a, double *omega, double *zeta)
{
    const size_t np = 16;
    ck_assert_int_eq(fricreg_hb_nma(hb, k, FRICREG_HB_NMA_DAMPING_MATRIX, a / 64.0, a, np),
                     FRICREG_OK);
    double a_last;
    ck_assert_int_eq(fricreg_hb_nma_point(hb, np - 1, &a_last, omega, zeta, 0, 0, NULL),
                     FRICREG_OK);
    ck_assert_double_eq_tol(a_last, a, 1e-12 * a);
}

/* A forced response at Ω under F = f M φ_k cos Ωt, and its first harmonic's modal coordinate
 * φ_k^T M X_1 = cos_part − i sin_part. */
struct forced {
    fricreg_hb *hb;
    const double *phi;
    double q[NQ];
    int warm;
};

static void modal_coordinate(struct forced *s, double omega, double *cos_part, double *sin_part)
{
    ck_assert_int_eq(fricreg_hb_solve(s->hb, omega, NQ, s->warm ? s->q : NULL, s->q), FRICREG_OK);
    s->warm = 1;
    double x[NDOF * NC];
    ck_assert_int_eq(fricreg_hb_displacement(s->hb, NDOF, NC, x), FRICREG_OK);
    double c = 0.0, d = 0.0;
    for (int i = 0; i < NDOF; i++)
        for (int j = 0; j < NDOF; j++) {
            c += s->phi[i] * mass[NDOF * i + j] * x[NC * j + 1];
            d += s->phi[i] * mass[NDOF * i + j] * x[NC * j + 2];
        }
    *cos_part = c;
    *sin_part = d;
}

static double in_phase(double omega, void *p)
{
    double c, d;
    modal_coordinate(p, omega, &c, &d);
    return c;
}

static double minus_amplitude(double omega, void *p)
{
    double c, d;
    modal_coordinate(p, omega, &c, &d);
    return -hypot(c, d);
}

/* Phase resonance: the root of the in-phase part in [lo, hi] by Brent's method. */
static double phase_resonance(struct forced *s, double lo, double hi)
{
    gsl_function fn = {in_phase, s};
    gsl_root_fsolver *r = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    ck_assert_int_eq(gsl_root_fsolver_set(r, &fn, lo, hi), GSL_SUCCESS);
    int status = GSL_CONTINUE;
    for (int it = 0; it < 100 && status == GSL_CONTINUE; it++) {
        ck_assert_int_eq(gsl_root_fsolver_iterate(r), GSL_SUCCESS);
        status = gsl_root_test_interval(gsl_root_fsolver_x_lower(r), gsl_root_fsolver_x_upper(r),
                                        0.0, 1e-12);
    }
    ck_assert_int_eq(status, GSL_SUCCESS);
    double root = gsl_root_fsolver_root(r);
    gsl_root_fsolver_free(r);
    return root;
}

/* The amplitude's maximum in [lo, hi] around guess by Brent's minimization. */
static double amplitude_peak(struct forced *s, double guess, double lo, double hi)
{
    gsl_function fn = {minus_amplitude, s};
    gsl_min_fminimizer *r = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    ck_assert_int_eq(gsl_min_fminimizer_set(r, &fn, guess, lo, hi), GSL_SUCCESS);
    int status = GSL_CONTINUE;
    for (int it = 0; it < 100 && status == GSL_CONTINUE; it++) {
        ck_assert_int_eq(gsl_min_fminimizer_iterate(r), GSL_SUCCESS);
        status = gsl_min_test_interval(gsl_min_fminimizer_x_lower(r), gsl_min_fminimizer_x_upper(r),
                                       0.0, 1e-7);
    }
    ck_assert_int_eq(status, GSL_SUCCESS);
    double peak = gsl_min_fminimizer_x_minimum(r);
    gsl_min_fminimizer_free(r);
    return peak;
}

/* One mode's peaks at one linear damping: the phase resonance and the amplitude's maximum, each
 * with the backbone at its amplitude. */
struct peaks {
    double omega_pr, a_pr, omega_bb_pr; /* phase resonance, its amplitude, the backbone there */
    double omega_pk, a_pk, omega_bb_pk, zeta_bb_pk; /* the amplitude's maximum, likewise */
    double zeta_visc;                               /* c/(2 ω) of the backbone at a_pk */
};

static void locate_peaks(size_t k, double c, double a_target, const double phi[NDOF][NDOF],
                         struct peaks *p)
{
    fricreg_hb *hb = model(c);
    double omega_t, zeta_t;
    backbone_at(hb, k, a_target, &omega_t, &zeta_t);
    /* the single-mode balance at phase resonance: f = ξ ω a = 2 ζ ω² a */
    double f = 2.0 * zeta_t * omega_t * omega_t * a_target;
    double pc[NDOF], ps[NDOF] = {0.0, 0.0};
    for (int i = 0; i < NDOF; i++) {
        pc[i] = 0.0;
        for (int j = 0; j < NDOF; j++)
            pc[i] += f * mass[NDOF * i + j] * phi[k][j];
    }
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, NDOF, pc, ps), FRICREG_OK);
    struct forced s = {.hb = hb, .phi = phi[k]};
    /* four half-power half-widths each side: the in-phase part keeps its sign beyond */
    double lo = omega_t * (1.0 - 4.0 * zeta_t), hi = omega_t * (1.0 + 4.0 * zeta_t), cp, sp;
    p->omega_pr = phase_resonance(&s, lo, hi);
    modal_coordinate(&s, p->omega_pr, &cp, &sp);
    p->a_pr = hypot(cp, sp);
    p->omega_pk = amplitude_peak(&s, p->omega_pr, lo, hi);
    modal_coordinate(&s, p->omega_pk, &cp, &sp);
    p->a_pk = hypot(cp, sp);
    double zeta;
    backbone_at(hb, k, p->a_pr, &p->omega_bb_pr, &zeta);
    backbone_at(hb, k, p->a_pk, &p->omega_bb_pk, &p->zeta_bb_pk);
    p->zeta_visc = c / (2.0 * p->omega_bb_pk);
    fricreg_hb_free(hb);
}

/* Both modes at the four dampings: the table of the header comment. */
START_TEST(peaks_on_backbone)
{
    double omega_lin[NDOF], phi[NDOF][NDOF];
    stuck_modes(omega_lin, phi);
    ck_assert_double_gt(omega_lin[1], 3.0 * omega_lin[0]); /* well separated: no 1:1, 2:1 */
    const double a_target[NDOF] = {3.0, 2.4};
    const double zeta_lin[] = {0.04, 0.01, 0.0025, 0.000625};
    const size_t nlevels = sizeof zeta_lin / sizeof zeta_lin[0];
    for (size_t k = 0; k < NDOF; k++) {
        double prev_pr = INFINITY, prev_pk = INFINITY, off_pr = 0.0, off_pk = 0.0;
        for (size_t level = 0; level < nlevels; level++) {
            struct peaks p;
            locate_peaks(k, 2.0 * zeta_lin[level] * omega_lin[k], a_target[k], phi, &p);
            /* the forced responses slip: the backbone at a_pk is below the stuck mode's ω */
            ck_assert_double_lt(p.omega_bb_pk, 0.97 * omega_lin[k]);
            off_pr = p.omega_pr / p.omega_bb_pr - 1.0;
            off_pk = p.omega_pk / p.omega_bb_pk - 1.0;
            /* phase resonance: on the backbone to the drive's mismatch, shrinking with ξ */
            ck_assert_double_lt(fabs(off_pr), 5e-5);
            ck_assert_double_lt(fabs(off_pr), prev_pr);
            /* the backbone's ζ: the single-mode level reaches a_target */
            ck_assert_double_eq_tol(p.a_pr, a_target[k], 1e-3 * a_target[k]);
            /* the amplitude's maximum: below by ζ_v ζ (the reduced model), shrinking */
            double rom = -p.zeta_visc * p.zeta_bb_pk;
            ck_assert_double_eq_tol(off_pk - off_pr, rom, 5e-6 + 0.01 * fabs(rom));
            ck_assert_double_lt(fabs(off_pk), 0.5 * prev_pk);
            prev_pr = fabs(off_pr);
            prev_pk = fabs(off_pk);
        }
        /* the acceptance: at the smallest damping both peaks on the backbone to 1e-3 */
        ck_assert_double_lt(fabs(off_pr), 1e-3);
        ck_assert_double_lt(fabs(off_pk), 1e-3);
    }
}
END_TEST

int main(void)
{
    gsl_set_error_handler_off(); /* the root and minimizer report through their status */
    Suite *s = suite_create("hb_nma_peaks");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, peaks_on_backbone);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
