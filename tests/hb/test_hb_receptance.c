/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_receptance.c — Check suite for the receptances solved through the modes of (K, M)
 * (src/hb/modal.c, fricreg_hb_set_receptance), white box where it compares G_h: on a chain of
 * 210 dofs with a consistent (tridiagonal) mass, Rayleigh damping, a Jenkins element, a 3-D
 * contact and a Jenkins element with lift-off, the modes' Y_h, G_h, J D_h^-1 P_h, its Ω
 * derivative and (R)'s Ω derivative agree with LAPACK's LU of each D_h to 1e-10 of their
 * scale, and (R)'s Ω derivative is the central difference's to 1e-6 either way; a solve and a
 * continuation to 1e-8; the automatic choice is the modes' bit for bit at 210 dofs and the
 * LU's below 200; the LU serves, bit for bit, where the modes cannot (a damping matrix, a mass
 * matrix of reciprocal condition number below 1e-6), and a zero damping matrix takes the
 * modes; a new mass matrix gives new modes; a
 * frequency on an undamped mode is FRICREG_ESINGULAR, nothing written. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"
#include "hb/dynamic.h"
#include "hb/hb_internal.h"
#include "hb/residual.h"

#define H 3
#define N 210
#define SMALL 8 /* a chain below the automatic choice's 200 dofs */
static const double OMEGA = 1.1;

/* The chain's matrices of n dofs: springs k_i = (1 + 0.2 sin i) (n/10)² to the next dof and
 * the ground at dof 0, the consistent mass of unit bars (2/3 and 1/6 a bar) and 0.5 at each
 * node, or with the last node's mass scaled by tiny. */
static void chain_matrices(size_t n, double tiny, double *M, double *K)
{
    memset(M, 0, n * n * sizeof(double));
    memset(K, 0, n * n * sizeof(double));
    double s = (double)(n * n) / 100.0;
    for (size_t i = 0; i < n; i++) {
        double k = (1.0 + 0.2 * sin((double)i)) * s;
        M[i * n + i] += 0.5 + 2.0 / 3.0;
        K[i * n + i] += k;
        if (i > 0) {
            M[i * n + i - 1] = M[(i - 1) * n + i] = 1.0 / 6.0;
            K[(i - 1) * n + i - 1] += k;
            K[i * n + i - 1] = K[(i - 1) * n + i] = -k;
        }
    }
    M[n * n - 1] *= tiny;
    M[n * n - 2] = M[(n - 2) * n + n - 1] = 0.0;
}

/* The chain with its three elements, forced at its last dof, receptances by method. */
static fricreg_hb *chain(size_t n, double tiny, int method)
{
    double *M = malloc(2 * n * n * sizeof(double)), *K = M + n * n;
    double *J = calloc(6 * n, sizeof(double)), *pc = calloc(2 * n, sizeof(double)), *ps = pc + n;
    const double pj[2] = {3.0, 0.4}, pn[5] = {3.0, 0.3, 20.0, 1.0, 0.0},
                 p3[5] = {3.0, 0.3, 20.0, 1.0, 0.0};
    size_t dj = n / 10, dn = n / 3, d3 = n - 4; /* the elements' dofs */
    J[dj] = 1.0;
    J[n + dn] = J[2 * n + dn + 1] = 1.0;
    J[3 * n + d3] = J[4 * n + d3 + 1] = J[5 * n + d3 + 2] = 1.0;
    pc[n - 1] = 2.0, ps[n - 2] = 1.0;
    chain_matrices(n, tiny, M, K);
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, 3, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.01, 0.001), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, n, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 1, n, J, pj),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins_normal"), 1, n,
                                             J + n, pn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, n,
                                             J + 3 * n, p3),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_receptance(hb, method), FRICREG_OK);
    free(M), free(J), free(pc);
    return hb;
}

/* The chain of n dofs on the sparse path: its M and K from compressed sparse columns (every
 * non-zero of chain_matrices'), set after the dense ones. */
static fricreg_hb *sparse_chain(size_t n)
{
    fricreg_hb *hb = chain(n, 1.0, FRICREG_HB_RECEPTANCE_LU);
    double *M = malloc(4 * n * n * sizeof(double)), *K = M + n * n, *v = K + n * n;
    int64_t *ptr = malloc((n + 1 + n * n) * sizeof(int64_t)), *ind = ptr + n + 1;
    chain_matrices(n, 1.0, M, K);
    for (int which = 0; which < 2; which++) {
        const double *A = which == 0 ? M : K;
        int64_t nz = 0;
        for (size_t j = 0; j < n; j++) {
            ptr[j] = nz;
            for (size_t i = 0; i < n; i++)
                if (A[i * n + j] != 0.0)
                    ind[nz] = (int64_t)i, v[nz++] = A[i * n + j];
        }
        ptr[n] = nz;
        int status = which == 0 ? fricreg_hb_set_mass_csc(hb, n, 0, ptr, ind, v)
                                : fricreg_hb_set_stiffness_csc(hb, n, 0, ptr, ind, v);
        ck_assert_int_eq(status, FRICREG_OK);
    }
    free(M), free(ptr);
    ck_assert_int_ne(hb->sparse, 0);
    return hb;
}

/* max |a − b| over count doubles, and *scale their largest |b|. */
static double distance(const double *a, const double *b, size_t count, double *scale)
{
    double d = 0.0;
    *scale = 0.0;
    for (size_t k = 0; k < count; k++) {
        d = fmax(d, fabs(a[k] - b[k]));
        *scale = fmax(*scale, fabs(b[k]));
    }
    return d;
}

/* Each harmonic's block of an array of (H + 1) blocks of count doubles, against the LU's. */
static void blocks_agree(const char *what, const double *modes, const double *lu, size_t count)
{
    for (int h = 0; h <= H; h++) {
        double scale, d = distance(modes + h * count, lu + h * count, count, &scale);
        ck_assert_msg(d <= 1e-10 * scale, "%s_%d: %g of %g", what, h, d, scale);
    }
}

/* A point q[nq] of the chain's coefficients where the elements slip and the contact lifts
 * off at part of the period (amplitudes up to 0.3). */
static void some_point(size_t nq, double *q)
{
    for (size_t j = 0; j < nq; j++)
        q[j] = 0.3 * sin(1.0 + 0.7 * (double)j) / (double)(1 + j % (2 * H + 1));
}

/* dR/dΩ (fr_hb_domega) at q, at OMEGA factored with its derivatives, into out[nq]. */
static void domega_at(fricreg_hb *hb, const double *q, double *out)
{
    double *R = calloc(hb->nq, sizeof(double));
    ck_assert_int_eq(fr_hb_factor(hb, "test", OMEGA, 1), FRICREG_OK);
    ck_assert_int_eq(fr_hb_residual(hb, "test", q, R, 0), FRICREG_OK);
    fr_hb_domega(hb, out);
    free(R);
}

/* The modes' Y_h, G_h, ql_h, dql_h/dΩ against the LU's at Ω (every harmonic), and dR/dΩ at a
 * point where the elements slip and lift off. */
START_TEST(agrees_with_lu)
{
    fricreg_hb *lu = chain(N, 1.0, FRICREG_HB_RECEPTANCE_LU);
    fricreg_hb *modes = chain(N, 1.0, FRICREG_HB_RECEPTANCE_MODES);
    ck_assert_int_eq(fr_hb_factor(lu, "test", OMEGA, 1), FRICREG_OK);
    ck_assert_int_eq(fr_hb_factor(modes, "test", OMEGA, 1), FRICREG_OK);
    ck_assert_ptr_nonnull(modes->modes);
    ck_assert_ptr_null(lu->modes);
    size_t m = lu->m, nq = lu->nq;
    blocks_agree("Y", modes->Y, lu->Y, 2 * N * (m + 1));
    blocks_agree("G", modes->G, lu->G, 2 * m * m);
    blocks_agree("ql", modes->ql, lu->ql, 2 * m);
    blocks_agree("dql", modes->dql, lu->dql, 2 * m);
    double *q = calloc(3 * nq, sizeof(double)), *a = q + nq, *b = a + nq, scale;
    some_point(nq, q);
    domega_at(lu, q, a);
    domega_at(modes, q, b);
    double d = distance(b, a, nq, &scale);
    ck_assert_msg(scale > 0.0 && d <= 1e-10 * scale, "dR/dOmega: %g of %g", d, scale);
    free(q);
    fricreg_hb_free(lu);
    fricreg_hb_free(modes);
}
END_TEST

/* dR/dΩ is R's derivative in Ω at a fixed q (the forces do not depend on Ω): against the
 * central difference (R(Ω + δ) − R(Ω − δ)) / 2δ, δ = 1e-5 Ω, whose error is δ² |d³R/dΩ³| / 6
 * and the rounding u |R| / δ, for the LU, the modes and the sparse model (measured: 1.5e-5, 1.5e-7, 2.2e-9 of the
 * scale at δ = 1e-4, 1e-5, 1e-6 Ω, second order until the rounding). */
START_TEST(domega_is_the_derivative)
{
    const int METHODS[3] = {FRICREG_HB_RECEPTANCE_LU, FRICREG_HB_RECEPTANCE_MODES, -1};
    for (int t = 0; t < 3; t++) { /* -1: the sparse model (KLU) */
        fricreg_hb *hb = METHODS[t] < 0 ? sparse_chain(N) : chain(N, 1.0, METHODS[t]);
        size_t nq = hb->nq;
        double *q = calloc(4 * nq, sizeof(double)), *d = q + nq, *rp = d + nq, *rm = rp + nq;
        double delta = 1e-5 * OMEGA, scale;
        some_point(nq, q);
        domega_at(hb, q, d);
        ck_assert_int_eq(fr_hb_factor(hb, "test", OMEGA + delta, 0), FRICREG_OK);
        ck_assert_int_eq(fr_hb_residual(hb, "test", q, rp, 0), FRICREG_OK);
        ck_assert_int_eq(fr_hb_factor(hb, "test", OMEGA - delta, 0), FRICREG_OK);
        ck_assert_int_eq(fr_hb_residual(hb, "test", q, rm, 0), FRICREG_OK);
        for (size_t j = 0; j < nq; j++)
            rp[j] = (rp[j] - rm[j]) / (2.0 * delta);
        double dist = distance(d, rp, nq, &scale);
        ck_assert_msg(scale > 0.0 && dist <= 1e-6 * scale, "method %d: %g of %g", METHODS[t], dist,
                      scale);
        free(q);
        fricreg_hb_free(hb);
    }
}
END_TEST

/* A solve without a guess and a continuation through the first resonance (at most 40 points):
 * the modes' solution and last point (its Ω and every dof's rms) are the LU's to 1e-8 of the
 * response, in as many points; the automatic choice at 210 dofs is the modes' bit for bit. */
START_TEST(solve_and_continue)
{
    const int METHODS[3] = {FRICREG_HB_RECEPTANCE_LU, FRICREG_HB_RECEPTANCE_MODES,
                            FRICREG_HB_RECEPTANCE_AUTO};
    size_t nq = 6 * (2 * H + 1), points[3];
    double *q = calloc(3 * nq, sizeof(double)), *rms = calloc(3 * N, sizeof(double)), scale;
    double omega_end[3];
    for (int k = 0; k < 3; k++) {
        fricreg_hb *hb = chain(N, 1.0, METHODS[k]);
        ck_assert_msg(fricreg_hb_solve(hb, 0.5, nq, NULL, q + k * nq) == FRICREG_OK, "%s",
                      fricreg_hb_errmsg(hb));
        ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.02, 1e-6, 0.1, 40), FRICREG_OK);
        int status = fricreg_hb_continue(hb, 0.5, 2.0, nq, q + k * nq);
        ck_assert_msg(status == FRICREG_OK || status == FRICREG_EWORK, "%s", fricreg_hb_errmsg(hb));
        points[k] = fricreg_hb_points(hb);
        ck_assert_int_eq(fricreg_hb_point(hb, points[k] - 1, &omega_end[k], N, rms + k * N),
                         FRICREG_OK);
        fricreg_hb_free(hb);
    }
    double d = distance(q + nq, q, nq, &scale);
    ck_assert_msg(d <= 1e-8 * scale, "solve: modes against LU %g of %g", d, scale);
    ck_assert_uint_eq(points[1], points[0]);
    ck_assert_msg(fabs(omega_end[1] - omega_end[0]) <= 1e-8, "%.17g %.17g", omega_end[1],
                  omega_end[0]);
    d = distance(rms + N, rms, N, &scale);
    ck_assert_msg(d <= 1e-8 * scale, "continuation's rms: modes against LU %g of %g", d, scale);
    ck_assert_mem_eq(q + 2 * nq, q + nq, nq * sizeof(double));
    ck_assert_mem_eq(rms + 2 * N, rms + N, N * sizeof(double));
    free(q);
    free(rms);
}
END_TEST

/* One solve at OMEGA from rest; q[nq]. */
static void solve_once(fricreg_hb *hb, double *q)
{
    ck_assert_msg(fricreg_hb_solve(hb, OMEGA, hb->nq, NULL, q) == FRICREG_OK, "%s",
                  fricreg_hb_errmsg(hb));
}

/* Where the modes cannot serve, the LU does, bit for bit: below 200 dofs (the automatic
 * choice), a damping matrix (even one equal to Rayleigh's), a mass of reciprocal condition
 * number about 1e-9 (the last node's mass scaled by 1e-9). */
START_TEST(lu_where_modes_cannot)
{
    size_t sizes[3] = {SMALL, N, N};
    double tiny[3] = {1.0, 1.0, 1e-9};
    for (int c = 0; c < 3; c++) {
        size_t n = sizes[c], nq = 6 * (2 * H + 1);
        fricreg_hb *lu = chain(n, tiny[c], FRICREG_HB_RECEPTANCE_LU);
        fricreg_hb *other = chain(n, tiny[c],
                                  c == 0 ? FRICREG_HB_RECEPTANCE_AUTO
                                         : FRICREG_HB_RECEPTANCE_MODES);
        if (c == 1) { /* C = 0.01 M + 0.001 K as a matrix */
            double *C = malloc(n * n * sizeof(double));
            for (size_t k = 0; k < n * n; k++)
                C[k] = 0.01 * lu->M[k] + 0.001 * lu->K[k];
            ck_assert_int_eq(fricreg_hb_set_damping(lu, n, C), FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_set_damping(other, n, C), FRICREG_OK);
            free(C);
        }
        double *q = malloc(2 * nq * sizeof(double));
        solve_once(lu, q);
        solve_once(other, q + nq);
        ck_assert_msg(memcmp(q, q + nq, nq * sizeof(double)) == 0, "case %d", c);
        ck_assert_ptr_null(other->jmodes);
        free(q);
        fricreg_hb_free(lu);
        fricreg_hb_free(other);
    }
}
END_TEST

/* A zero damping matrix (fricreg_hb_set_damping of zeros, as a driver is created) is damping
 * the modes diagonalize: they serve, and the undamped solve agrees with the LU's to 1e-8. */
START_TEST(undamped_takes_the_modes)
{
    fricreg_hb *lu = chain(N, 1.0, FRICREG_HB_RECEPTANCE_LU);
    fricreg_hb *modes = chain(N, 1.0, FRICREG_HB_RECEPTANCE_MODES);
    double *zero = calloc(N * N, sizeof(double)), *q = malloc(2 * lu->nq * sizeof(double)), scale;
    ck_assert_int_eq(fricreg_hb_set_damping(lu, N, zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(modes, N, zero), FRICREG_OK);
    solve_once(lu, q);
    solve_once(modes, q + lu->nq);
    ck_assert_ptr_nonnull(modes->jmodes);
    double d = distance(q + lu->nq, q, lu->nq, &scale);
    ck_assert_msg(d <= 1e-8 * scale, "undamped: modes against LU %g of %g", d, scale);
    free(zero), free(q);
    fricreg_hb_free(lu);
    fricreg_hb_free(modes);
}
END_TEST

/* A new mass matrix after a solve: the next solve takes the new modes, bit for bit a new
 * driver's with that mass. */
START_TEST(new_mass_new_modes)
{
    fricreg_hb *hb = chain(N, 1.0, FRICREG_HB_RECEPTANCE_MODES);
    fricreg_hb *fresh = chain(N, 2.0, FRICREG_HB_RECEPTANCE_MODES);
    size_t nq = hb->nq;
    double *q = malloc(2 * nq * sizeof(double));
    solve_once(hb, q);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, N, fresh->M), FRICREG_OK);
    solve_once(hb, q);
    solve_once(fresh, q + nq);
    ck_assert_mem_eq(q, q + nq, nq * sizeof(double));
    free(q);
    fricreg_hb_free(hb);
    fricreg_hb_free(fresh);
}
END_TEST

/* Undamped, M = I and K = diag((k + 1)²): at Ω = 3 the fundamental's D_1 has the mode
 * λ = 9 = Ω² (d = 0 to rounding): FRICREG_ESINGULAR naming it, q untouched; at Ω = 3.3 the
 * modes solve (no multiple of 3.3 squared is a λ). */
START_TEST(singular_on_a_mode)
{
    fricreg_hb *hb = NULL;
    double *M = calloc(2 * N * N, sizeof(double)), *K = M + N * N, *J = calloc(N, sizeof(double));
    double pc[N] = {0}, ps[N] = {0}, p[2] = {1.0, 0.1};
    for (size_t k = 0; k < N; k++) {
        M[k * N + k] = 1.0;
        K[k * N + k] = (double)((k + 1) * (k + 1));
    }
    pc[0] = J[1] = 1.0;
    ck_assert_int_eq(fricreg_hb_create(N, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, N, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, N, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 1, N, J, p),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_receptance(hb, FRICREG_HB_RECEPTANCE_MODES), FRICREG_OK);
    double q[2 * H + 1], marker = 42.0;
    for (int c = 0; c < 2 * H + 1; c++)
        q[c] = marker;
    ck_assert_int_eq(fricreg_hb_solve(hb, 3.0, 2 * H + 1, NULL, q), FRICREG_ESINGULAR);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "is singular at Omega = 3 (mode 2"));
    for (int c = 0; c < 2 * H + 1; c++)
        ck_assert_double_eq(q[c], marker);
    ck_assert_msg(fricreg_hb_solve(hb, 3.3, 2 * H + 1, NULL, q) == FRICREG_OK, "%s",
                  fricreg_hb_errmsg(hb));
    ck_assert_ptr_nonnull(hb->modes);
    free(M), free(J);
    fricreg_hb_free(hb);
}
END_TEST

/* Out of the enum: FRICREG_EINVAL with a message, the choice kept (the next solve is the modes'
 * bit for bit); NULL: FRICREG_ENULL. */
START_TEST(choice_refused)
{
    fricreg_hb *hb = chain(N, 1.0, FRICREG_HB_RECEPTANCE_MODES);
    size_t nq = hb->nq;
    double *q = malloc(2 * nq * sizeof(double));
    solve_once(hb, q);
    ck_assert_int_eq(fricreg_hb_set_receptance(hb, 3), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "set_receptance: method = 3"));
    ck_assert_int_eq(fricreg_hb_set_receptance(hb, -1), FRICREG_EINVAL);
    ck_assert_uint_eq(hb->modal_min, 0);
    solve_once(hb, q + nq);
    ck_assert_mem_eq(q, q + nq, nq * sizeof(double));
    ck_assert_int_eq(fricreg_hb_set_receptance(NULL, FRICREG_HB_RECEPTANCE_LU), FRICREG_ENULL);
    free(q);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_receptance");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, agrees_with_lu);
    tcase_add_test(tc, domega_is_the_derivative);
    tcase_add_test(tc, new_mass_new_modes);
    tcase_add_test(tc, singular_on_a_mode);
    tcase_add_test(tc, choice_refused);
    suite_add_tcase(s, tc);
    TCase *solves = tcase_create("solves");
    tcase_add_test(solves, solve_and_continue);
    tcase_add_test(solves, lu_where_modes_cannot);
    tcase_add_test(solves, undamped_takes_the_modes);
    suite_add_tcase(s, solves);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
