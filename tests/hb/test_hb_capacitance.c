/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_capacitance.c — Check suite for Newton's matrix of harmonic balance solved by its
 * capacitance (src/hb/capacitance.c, newton_matrix.c), white box: on a coupled chain holding
 * every kind of element (two Jenkins, a 3-D contact, a Jenkins element with lift-off, a
 * 3-slider Iwan element; G_h dense across them), at the solutions of levels from all stuck
 * to gross slip and lift-off, Newton's matrix I + Ĝ Ĵ at each, plain and bordered, is solved
 * by the capacitance and by the dense LU of the whole: the solutions agree to 1e-10 of their
 * scale and the determinants' signs (the continuation's fold test) are equal. At the lowest
 * level every element sticks, and the centred stick's Jacobian (fricreg_aft.h: f_h = kt q_h for
 * h >= 1, the closed normal spring on every harmonic) leaves only the tangential mean rows
 * outside the diagonal. Where the stuck part A0 is singular (an undamped oscillator held by a
 * stuck Jenkins element at its stuck natural frequency), the solve falls back to the dense LU
 * and says what it says. Large dense matrices solved by refinement on an earlier one's factor
 * (newton_matrix.c) give their own LU's solutions and the branch of their own LUs. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"
#include "hb/capacitance.h"
#include "hb/dynamic.h"
#include "hb/hb_internal.h"
#include "hb/newton_matrix.h"
#include "hb/residual.h"

#define H 3
#define N 8 /* dofs: a chain to ground */
#define ME 5
/* the tangential mean rows: 2 Jenkins, the contact's x and y, the lift-off's, the Iwan's */
#define MEAN_ROWS 6

static const double OMEGA = 1.1;
static const double LEVELS[] = {0.02, 0.3, 1.0, 3.0, 12.0};
#define NLEVELS (sizeof LEVELS / sizeof LEVELS[0])

/* Element i's rows of J [rows N] on the dofs given, 1 each. */
static void rows_on(double *J, const int *dofs, int rows)
{
    memset(J, 0, (size_t)rows * N * sizeof(double));
    for (int r = 0; r < rows; r++)
        J[r * N + dofs[r]] = 1.0;
}

/* The chain forced at level times its load. */
static fricreg_hb *chain(double level)
{
    double M[N * N] = {0}, K[N * N] = {0}, C[N * N], pc[N] = {0}, ps[N] = {0}, J[3 * N];
    for (int i = 0; i < N; i++) {
        M[i * N + i] = 1.0 + 0.1 * i;
        K[i * N + i] += 2.0;
        if (i + 1 < N) {
            K[i * N + i] += 1.0;
            K[(i + 1) * N + i + 1] += 1.0;
            K[i * N + i + 1] = K[(i + 1) * N + i] = -1.0;
        }
    }
    for (int i = 0; i < N * N; i++)
        C[i] = 0.01 * M[i] + 0.01 * K[i];
    pc[N - 1] = level;
    ps[3] = 0.5 * level;
    pc[4] = 0.3 * level; /* moves the contact's normal dof: lift-off at the higher levels */
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(N, ME, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, N, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, N, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, N, pc, ps), FRICREG_OK);
    static const double jenkins_p[2][2] = {{1.0, 0.2}, {0.8, 0.4}};
    static const double contact_p[5] = {1.5, 0.4, 2.0, 0.5, 0.0};
    static const double normal_p[5] = {1.2, 0.3, 3.0, 0.6, 0.0};
    static const double iwan_p[6] = {1.0, 0.6, 0.4, 0.1, 0.2, 0.35};
    const fricreg_element_type *iwan3 = fricreg_element_sliders(fricreg_element_lookup("iwan"), 3);
    for (int e = 0; e < 2; e++) {
        rows_on(J, (int[]){e}, 1);
        ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 1, N, J,
                                                 jenkins_p[e]),
                         FRICREG_OK);
    }
    rows_on(J, (int[]){2, 3, 4}, 3);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, N, J,
                                             contact_p),
                     FRICREG_OK);
    rows_on(J, (int[]){5, 6}, 2);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins_normal"), 1, N, J,
                                             normal_p),
                     FRICREG_OK);
    rows_on(J, (int[]){7}, 1);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, iwan3, 1, N, J, iwan_p), FRICREG_OK);
    return hb;
}

/* Newton's matrix recorded at the Jacobians held, solved for rhs into x, its determinant's
 * sign into *sign; by the capacitance or densely. */
static void solve(fricreg_hb *hb, int by_capacitance, size_t nd, const double *col,
                  const double *row, const double *rhs, double *x, double *sign)
{
    hb->capacitance_min = by_capacitance ? 0 : SIZE_MAX;
    hb->capacitance_share = 2.0;
    fr_hb_newton_matrix_room(hb);
    fr_hb_newton_matrix(hb, nd, col, row);
    ck_assert_int_eq(hb->by_capacitance, by_capacitance);
    memcpy(x, rhs, nd * sizeof(double));
    ck_assert_int_eq(fr_hb_newton_solve(hb, "test", x, x), FRICREG_OK);
    *sign = fr_hb_newton_det_sign(hb);
}

static double distance(const double *a, const double *b, size_t n, double *scale)
{
    double d = 0.0;
    *scale = 0.0;
    for (size_t j = 0; j < n; j++) {
        d = fmax(d, fabs(a[j] - b[j]));
        *scale = fmax(*scale, fabs(b[j]));
    }
    return d;
}

/* The branch from 0.3 to 2.5 continued on hb: its points, the last one's rms into rms[N]. */
static size_t branch_to_end(fricreg_hb *hb, double *rms)
{
    double w;
    ck_assert_msg(fricreg_hb_continue(hb, 0.3, 2.5, hb->nq, NULL) == FRICREG_OK, "%s",
                  fricreg_hb_errmsg(hb));
    size_t points = fricreg_hb_points(hb);
    ck_assert_int_eq(fricreg_hb_point(hb, points - 1, &w, N, rms), FRICREG_OK);
    ck_assert_double_eq(w, 2.5);
    return points;
}

/* Two branches to the same end: their last points agree to 1e-8 of the response, and the
 * points number alike within 10 % (more than 20). */
static void branches_alike(const size_t points[2], double rms[2][N])
{
    double scale;
    ck_assert_double_le(distance(rms[1], rms[0], N, &scale), 1e-8 * scale);
    ck_assert_uint_gt(points[0], 20);
    ck_assert_double_le(fabs((double)points[1] - (double)points[0]), 0.1 * (double)points[0]);
}

START_TEST(against_dense)
{
    double level = LEVELS[_i / 2];
    fricreg_hb *hb = chain(level);
    size_t nq = hb->nq, nd = nq + (size_t)_i % 2;
    double *q = malloc(nq * sizeof(double)), *rhs = malloc((nq + 1) * sizeof(double));
    double *col = malloc(nq * sizeof(double)), *row = malloc((nq + 1) * sizeof(double));
    double *xd = malloc((nq + 1) * sizeof(double)), *xc = malloc((nq + 1) * sizeof(double));
    ck_assert_msg(fricreg_hb_solve(hb, OMEGA, nq, NULL, q) == FRICREG_OK, "%s",
                  fricreg_hb_errmsg(hb));
    ck_assert_int_eq(fr_hb_factor(hb, "test", OMEGA, 1), FRICREG_OK);
    ck_assert_int_eq(fr_hb_residual(hb, "test", q, hb->R, 1), FRICREG_OK);
    for (size_t j = 0; j <= nq; j++) { /* fixed, of order one, no structure */
        rhs[j] = sin(1.0 + 3.7 * (double)j);
        row[j] = cos(0.5 + 1.3 * (double)j);
        if (j < nq)
            col[j] = sin(2.0 + 0.9 * (double)j);
    }
    double sd, sc, scale;
    ck_assert_ptr_null(hb->capacitance); /* nq = 56 < FR_HB_CAPACITANCE_MIN: no room */
    hb->capacitance_min = 0;             /* and without the room the dense LU serves */
    fr_hb_newton_matrix(hb, nd, col, row);
    ck_assert_int_eq(hb->by_capacitance, 0);
    solve(hb, 0, nd, col, row, rhs, xd, &sd);
    solve(hb, 1, nd, col, row, rhs, xc, &sc);
    double d = distance(xc, xd, nd, &scale);
    ck_assert_msg(d <= 1e-10 * scale, "level %g, nd %zu: capacitance against dense %g of %g", level,
                  nd, d, scale);
    ck_assert_double_eq(sc, sd);
    size_t s = fr_hb_capacitance_split(hb, nd, col, row);
    if (level == LEVELS[0])
        ck_assert_uint_le(s, MEAN_ROWS); /* all stuck: the tangential means alone */
    else
        ck_assert_uint_gt(s, MEAN_ROWS);
    free(q);
    free(rhs);
    free(col);
    free(row);
    free(xd);
    free(xc);
    fricreg_hb_free(hb);
}
END_TEST

/* The branch through the chain's first resonances at levels 1, 3 and 12 (slip, lift-off),
 * continued with Newton's matrix by its capacitance and densely: both reach Ω1, the last
 * points (one solution there) agree to 1e-8 of the response, and the step control took as
 * many points within 10 % (where elements switch, its decisions follow the rounding of the
 * correctors: measured 558, 607 and 596 points each way). Level 0.3 stops at Ω = 1.75 (the
 * branch doubles back: the 3-D contact's, left open). */
START_TEST(continuation_alike)
{
    double level = LEVELS[_i + 2];
    fricreg_hb *hb[2] = {chain(level), chain(level)};
    double rms[2][N];
    size_t points[2];
    for (int k = 0; k < 2; k++) {
        ck_assert_int_eq(fricreg_hb_set_newton_solver(hb[k], k ? FRICREG_HB_NEWTON_CAPACITANCE
                                                               : FRICREG_HB_NEWTON_DENSE),
                         FRICREG_OK);
        points[k] = branch_to_end(hb[k], rms[k]);
    }
    branches_alike(points, rms);
    fricreg_hb_free(hb[0]);
    fricreg_hb_free(hb[1]);
}
END_TEST

/* The public choice (fricreg_hb_set_newton_solver) at a slipping level, nq = 56: the automatic
 * one is the dense LU below nq = 512, bit for bit; the capacitance, forced, solves each
 * iteration by it and agrees to 1e-9 of the response; dense again frees its room. Out of the
 * enum: FRICREG_EINVAL, with a message, the choice as before. */
START_TEST(public_choice)
{
    const int SOLVERS[3] = {FRICREG_HB_NEWTON_DENSE, FRICREG_HB_NEWTON_AUTO,
                            FRICREG_HB_NEWTON_CAPACITANCE};
    fricreg_hb *hb = chain(LEVELS[2]);
    size_t nq = hb->nq;
    double *q = calloc(3 * nq, sizeof(double)), scale;
    for (int k = 0; k < 3; k++) {
        ck_assert_int_eq(fricreg_hb_set_newton_solver(hb, SOLVERS[k]), FRICREG_OK);
        ck_assert_msg(fricreg_hb_solve(hb, OMEGA, nq, NULL, q + k * nq) == FRICREG_OK, "%s",
                      fricreg_hb_errmsg(hb));
        ck_assert_int_eq(hb->by_capacitance, SOLVERS[k] == FRICREG_HB_NEWTON_CAPACITANCE);
    }
    ck_assert_mem_eq(q + nq, q, nq * sizeof(double));
    double d = distance(q + 2 * nq, q, nq, &scale);
    ck_assert_msg(d <= 1e-9 * scale, "capacitance against dense %g of %g", d, scale);
    ck_assert_ptr_nonnull(hb->capacitance);
    ck_assert_int_eq(fricreg_hb_set_newton_solver(hb, 3), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "set_newton_solver: solver = 3"));
    ck_assert_int_eq(fricreg_hb_set_newton_solver(hb, -1), FRICREG_EINVAL);
    ck_assert_uint_eq(hb->capacitance_min, 0); /* still the capacitance */
    ck_assert_ptr_nonnull(hb->capacitance);
    ck_assert_int_eq(fricreg_hb_set_newton_solver(hb, FRICREG_HB_NEWTON_DENSE), FRICREG_OK);
    ck_assert_ptr_null(hb->capacitance);
    ck_assert_int_eq(fricreg_hb_set_newton_solver(NULL, FRICREG_HB_NEWTON_DENSE), FRICREG_ENULL);
    free(q);
    fricreg_hb_free(hb);
}
END_TEST

/* An undamped unit oscillator (k = 1) held by a stuck Jenkins element (kt = 3) at its stuck
 * frequency Ω = 2: the stuck part of Newton's matrix is singular, the capacitance gives way
 * to the dense LU, which finds the whole singular (every element stuck: A = A0). */
START_TEST(stuck_singular)
{
    fricreg_hb *hb = NULL;
    double one = 1.0, zero = 0.0, p[2] = {3.0, 100.0};
    ck_assert_int_eq(fricreg_hb_create(1, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &one, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 1, 1, &one, p),
                     FRICREG_OK);
    size_t nq = 2 * H + 1;
    double q[2 * H + 1] = {0.0}, x[2 * H + 1] = {1.0};
    ck_assert_int_eq(fr_hb_factor(hb, "test", 2.0, 0), FRICREG_OK);
    ck_assert_int_eq(fr_hb_residual(hb, "test", q, hb->R, 1), FRICREG_OK);
    hb->capacitance_min = 0;
    hb->capacitance_share = 2.0;
    fr_hb_newton_matrix_room(hb);
    fr_hb_newton_matrix(hb, nq, NULL, NULL);
    ck_assert_int_eq(hb->by_capacitance, 1);
    ck_assert_int_eq(fr_hb_newton_solve(hb, "test", x, x), FRICREG_ESINGULAR);
    ck_assert_int_eq(hb->by_capacitance, 0); /* fell back */
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "Newton's matrix is singular"));
    fricreg_hb_free(hb);
}
END_TEST

/* Two dofs, the second of negative stiffness (K = diag(1, −1)), held by a closed Jenkins
 * element with lift-off (tangential row on the first, normal row on the second, kn = 3) at
 * rest, q = 0: every row of Ĵ is diagonal, and the mean normal row of I + Ĝ Ĵ is
 * 1 + (−1) 3 = −2, the harmonics' blocks of positive determinant (|det|² of complex ones), so
 * det A < 0: the capacitance's sign comes from the stuck part's mean block. */
START_TEST(negative_mean_block)
{
    fricreg_hb *hb = NULL;
    double M[4] = {1, 0, 0, 1}, K[4] = {1, 0, 0, -1}, J[4] = {1, 0, 0, 1}, pc[2] = {1, 0},
           ps[2] = {0, 0}, p[5] = {2.0, 0.5, 3.0, 1.0, 0.0};
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins_normal"), 1, 2, J,
                                             p),
                     FRICREG_OK);
    size_t nq = hb->nq;
    double q[2 * (2 * H + 1)] = {0.0}, rhs[2 * (2 * H + 1)] = {1.0}, xd[2 * (2 * H + 1)],
                          xc[2 * (2 * H + 1)], sd, sc, scale;
    ck_assert_int_eq(fr_hb_factor(hb, "test", 0.7, 0), FRICREG_OK);
    ck_assert_int_eq(fr_hb_residual(hb, "test", q, hb->R, 1), FRICREG_OK);
    hb->capacitance_min = 0;
    fr_hb_newton_matrix_room(hb);
    ck_assert_uint_eq(fr_hb_capacitance_split(hb, nq, NULL, NULL), 0);
    solve(hb, 0, nq, NULL, NULL, rhs, xd, &sd);
    solve(hb, 1, nq, NULL, NULL, rhs, xc, &sc);
    ck_assert_double_le(distance(xc, xd, nq, &scale), 1e-12 * scale);
    ck_assert_double_eq(sd, -1.0);
    ck_assert_double_eq(sc, -1.0);
    fricreg_hb_free(hb);
}
END_TEST

/* Dense Newton's matrices solved by refinement on an earlier factor (held_min 0: at every
 * order) against each by its own LU (FRICREG_HB_NEWTON_DENSE), at level 12 (slip and
 * lift-off): both reach Ω1, the last points agree to 1e-8 of the response, the points number
 * alike within 10 % (measured: 596 each), and the branches are not the same bits. */
START_TEST(refined_alike)
{
    fricreg_hb *hb[2] = {chain(LEVELS[4]), chain(LEVELS[4])};
    double rms[2][N];
    size_t points[2];
    for (int k = 0; k < 2; k++) {
        ck_assert_int_eq(fricreg_hb_set_newton_solver(hb[k], FRICREG_HB_NEWTON_DENSE), FRICREG_OK);
        ck_assert_uint_eq(hb[k]->held_min, SIZE_MAX);
        hb[k]->held_min = k ? 0 : SIZE_MAX;
        points[k] = branch_to_end(hb[k], rms[k]);
    }
    branches_alike(points, rms);
    /* the refinement served: the branch moved by rounding at least */
    ck_assert(points[1] != points[0] || memcmp(rms[1], rms[0], sizeof rms[0]) != 0);
    fricreg_hb_free(hb[0]);
    fricreg_hb_free(hb[1]);
}
END_TEST

/* Jacobians of the solution at level 1, and Newton's matrix recorded there, bordered by col
 * and row, its Ω factored off by dw. */
static void matrix_at(fricreg_hb *hb, const double *q, double dw, const double *col,
                      const double *row)
{
    ck_assert_int_eq(fr_hb_factor(hb, "test", OMEGA + dw, 1), FRICREG_OK);
    ck_assert_int_eq(fr_hb_residual(hb, "test", q, hb->R, 1), FRICREG_OK);
    fr_hb_newton_matrix(hb, hb->nq + 1, col, row);
}

/* The factor held (fr_hb_newton_held) and the refinement on it: after a dense solve, the next
 * matrix of its order, recorded at Ω 1e-3 away, is solved by refinement on it where its order
 * is at least held_min: to 1e-11 of the solution by its own LU, nothing formed (A still the
 * held factor), the determinant's sign its own LU's. A matrix too far from the factor (Ω 0.5
 * away) is solved by its own LU, bit for bit as without the factor. No factor is held of
 * another order, after the capacitance solved the last matrix, or once the elements are
 * cleared; AUTO's held_min is FR_HB_REFINE_MIN, DENSE's none. */
START_TEST(held_factor)
{
    fricreg_hb *hb = chain(LEVELS[2]);
    size_t nq = hb->nq, nd = nq + 1, bytes = nd * nd * sizeof(double);
    double *q = malloc(nq * sizeof(double)), *x = malloc(nd * sizeof(double));
    double *y = malloc(nd * sizeof(double)), *rhs = malloc(nd * sizeof(double));
    double *col = malloc(nd * sizeof(double)), *row = malloc(nd * sizeof(double));
    double *held = malloc(bytes), sign, scale;
    ck_assert_uint_eq(hb->held_min, FR_HB_REFINE_MIN);
    ck_assert_msg(fricreg_hb_solve(hb, OMEGA, nq, NULL, q) == FRICREG_OK, "%s",
                  fricreg_hb_errmsg(hb));
    for (size_t j = 0; j < nd; j++) {
        col[j] = sin(2.0 + 0.9 * (double)j);
        row[j] = cos(0.5 + 1.3 * (double)j);
        rhs[j] = sin(1.0 + 3.7 * (double)j);
    }
    hb->capacitance_min = SIZE_MAX;
    matrix_at(hb, q, 1e-3, col, row); /* its own LU: x, the sign */
    ck_assert_int_eq(fr_hb_newton_held(hb), 0);
    ck_assert_int_eq(fr_hb_newton_solve(hb, "test", memcpy(x, rhs, nd * sizeof(double)), x),
                     FRICREG_OK);
    sign = fr_hb_newton_det_sign(hb);
    matrix_at(hb, q, 0.0, col, row); /* the factor to hold */
    ck_assert_int_eq(fr_hb_newton_solve(hb, "test", memcpy(y, rhs, nd * sizeof(double)), y),
                     FRICREG_OK);
    memcpy(held, hb->A, bytes);
    matrix_at(hb, q, 1e-3, col, row);
    ck_assert_int_eq(fr_hb_newton_held(hb), 0); /* below held_min */
    hb->held_min = nd;
    ck_assert_int_eq(fr_hb_newton_held(hb), 1);
    ck_assert_int_eq(fr_hb_newton_solve(hb, "test", memcpy(y, rhs, nd * sizeof(double)), y),
                     FRICREG_OK);
    double d = distance(y, x, nd, &scale);
    ck_assert_msg(d <= 1e-11 * scale, "refined against its own LU: %g of %g", d, scale);
    ck_assert(memcmp(y, x, nd * sizeof(double)) != 0); /* not its own LU */
    ck_assert_mem_eq(hb->A, held, bytes);
    ck_assert_double_eq(fr_hb_newton_det_sign(hb), sign);
    matrix_at(hb, q, 0.5, col, row); /* far: its own LU */
    ck_assert_int_eq(fr_hb_newton_held(hb), 1);
    ck_assert_int_eq(fr_hb_newton_solve(hb, "test", memcpy(y, rhs, nd * sizeof(double)), y),
                     FRICREG_OK);
    hb->held_nd = 0;
    matrix_at(hb, q, 0.5, col, row);
    ck_assert_int_eq(fr_hb_newton_solve(hb, "test", memcpy(x, rhs, nd * sizeof(double)), x),
                     FRICREG_OK);
    ck_assert_mem_eq(y, x, nd * sizeof(double));
    fr_hb_newton_matrix(hb, nq, NULL, NULL);
    ck_assert_int_eq(fr_hb_newton_held(hb), 0); /* another order */
    solve(hb, 1, nd, col, row, rhs, x, &sign);
    hb->capacitance_min = SIZE_MAX;
    fr_hb_newton_matrix(hb, nd, col, row);
    ck_assert_int_eq(fr_hb_newton_held(hb), 0); /* the capacitance solved the last */
    solve(hb, 0, nd, col, row, rhs, x, &sign);
    fr_hb_newton_matrix(hb, nd, col, row);
    ck_assert_int_eq(fr_hb_newton_held(hb), 1);
    ck_assert_int_eq(fricreg_hb_clear_elements(hb), FRICREG_OK);
    ck_assert_uint_eq(hb->held_nd, 0); /* the rows moved: the factor forgotten */
    ck_assert_int_eq(fricreg_hb_set_newton_solver(hb, FRICREG_HB_NEWTON_DENSE), FRICREG_OK);
    ck_assert_uint_eq(hb->held_min, SIZE_MAX);
    free(q);
    free(x);
    free(y);
    free(rhs);
    free(col);
    free(row);
    free(held);
    fricreg_hb_free(hb);
}
END_TEST

/* A solve starts from no factor held: from a guess 1e-3 off the solution, with refinement at
 * every order, it gives the same bits after a solve that left its factor as on a new driver. */
START_TEST(fresh_factors_each_call)
{
    fricreg_hb *hb[2] = {chain(LEVELS[2]), chain(LEVELS[2])};
    size_t nq = hb[0]->nq;
    double *q = malloc(3 * nq * sizeof(double));
    for (int k = 0; k < 2; k++) {
        ck_assert_int_eq(fricreg_hb_set_newton_solver(hb[k], FRICREG_HB_NEWTON_DENSE), FRICREG_OK);
        hb[k]->held_min = 0;
    }
    ck_assert_int_eq(fricreg_hb_solve(hb[0], OMEGA, nq, NULL, q), FRICREG_OK);
    ck_assert_uint_gt(hb[0]->held_nd, 0);
    for (size_t j = 0; j < nq; j++)
        q[j] *= 1.001;
    ck_assert_int_eq(fricreg_hb_solve(hb[0], OMEGA, nq, q, q + nq), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb[1], OMEGA, nq, q, q + 2 * nq), FRICREG_OK);
    ck_assert_mem_eq(q + nq, q + 2 * nq, nq * sizeof(double));
    free(q);
    fricreg_hb_free(hb[0]);
    fricreg_hb_free(hb[1]);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_capacitance");
    TCase *tc = tcase_create("core");
    tcase_add_loop_test(tc, against_dense, 0, 2 * NLEVELS);
    tcase_add_loop_test(tc, continuation_alike, 2, 3); /* level 12: slip and lift-off */
    tcase_add_test(tc, public_choice);
    tcase_add_test(tc, stuck_singular);
    tcase_add_test(tc, negative_mean_block);
    tcase_add_test(tc, refined_alike);
    tcase_add_test(tc, fresh_factors_each_call);
    tcase_add_test(tc, held_factor);
    suite_add_tcase(s, tc);
    /* levels 1 and 3 (5 s native, 160 s under valgrind): the same paths as level 12's */
    TCase *levels = tcase_create("levels");
    tcase_add_loop_test(levels, continuation_alike, 0, 2);
    suite_add_tcase(s, levels);
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
