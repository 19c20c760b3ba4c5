/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure.c — Check suite for fricreg_structure (fricreg_structure.h): a linear
 * structure with friction, Newmark / HHT-alpha with Newton on the exact tangent.
 *
 * Expected numbers, each derived where it is used:
 *  - average-acceleration Newmark is the trapezoidal rule on (u, v): on an undamped mode of
 *    frequency w it is the Cayley transform of [[0, 1], [-w^2, 0]], whose eigenvalues are
 *    exp(+-i wb dt) with tan(wb dt/2) = w dt/2 and whose eigenvectors are those of the matrix:
 *    from (u0, 0), u_n = u0 cos(wb t_n) exactly, and v.M v/2 + u.K u/2 is conserved;
 *  - a multi-DOF structure splits into its M-orthonormal modes (GSL's generalized symmetric
 *    eigensolver), each following the rule above; with Rayleigh damping each mode's 2x2
 *    trapezoidal map;
 *  - the paper's oscillator (Eq. (5)) as a structure M = K = J = 1, against fricreg_exact;
 *  - a static load held by coupled contacts: J^T f = -p, no motion at all;
 *  - the paper's oscillator and chain through run_ode against fricreg_sim's drivers;
 *  - the ten-storey building (examples/building/) against a fine reference of its own;
 *  - the sparse setters (fricreg_structure_gsl.h) against the dense ones, bit for bit. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_spmatrix.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"
#include "fricreg_structure.h"
#include "fricreg_structure_gsl.h"
#include "quiet_check.h"

#define PI 3.14159265358979323846

/* ---------------------------------------------------------------- helpers */

static fricreg_structure *make(size_t n, size_t m)
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(n, m, &s), FRICREG_OK);
    return s;
}

static void ok(fricreg_structure *s, int status)
{
    QUIET_ASSERT(status == FRICREG_OK, "status %d: %s", status, fricreg_structure_errmsg(s));
}

static double value(const fricreg_structure *s, int which)
{
    double x = NAN;
    ck_assert_int_eq(fricreg_structure_get_value(s, which, &x), FRICREG_OK);
    return x;
}

static int64_t stat(const fricreg_structure *s, int which)
{
    int64_t x = -1;
    ck_assert_int_eq(fricreg_structure_get_stat(s, which, &x), FRICREG_OK);
    return x;
}

/* The two storeys of the coupled-contact tests: M = diag(1.7, 0.9),
 * K = [[30.2, -12.1], [-12.1, 12.1]], contacts J = [[1, 0], [-1, 1]] (storey 1 on the ground,
 * storey 2 on storey 1), bounds mun and the law with its eps. */
static fricreg_structure *make_two_storeys(const double mun[2], int law, double eps)
{
    const double M[4] = {1.7, 0.0, 0.0, 0.9}, K[4] = {30.2, -12.1, -12.1, 12.1};
    const double J[4] = {1.0, 0.0, -1.0, 1.0};
    fricreg_structure *s = make(2, 2);
    ok(s, fricreg_structure_set_mass(s, 2, M));
    ok(s, fricreg_structure_set_stiffness(s, 2, K));
    ok(s, fricreg_structure_set_contacts(s, 2, 2, J));
    ok(s, fricreg_structure_set_bounds(s, 2, mun));
    ok(s, fricreg_structure_set_law(s, law, eps));
    return s;
}

/* A structure with no friction: one contact on DOF 0 with mun = 0 (f = 0 exactly). */
static void frictionless(fricreg_structure *s, size_t n)
{
    double *J = calloc(n, sizeof *J), zero = 0.0;
    J[0] = 1.0;
    ok(s, fricreg_structure_set_contacts(s, 1, n, J));
    ok(s, fricreg_structure_set_bounds(s, 1, &zero));
    free(J);
}

/* tan(wb dt/2) = w dt/2 */
static double trapezoidal_frequency(double w, double dt)
{
    return 2.0 * atan(w * dt / 2.0) / dt;
}

/* ---------------------------------------------------------------- linear structures */

/* SDOF m = 2.385 kg, k = m w^2 with w = 1.7 rad/s, u0 = 0.0371 m, dt = 0.137 s (w dt = 0.23):
 * u_n = u0 cos(wb t_n) to rounding, energy m w^2 u0^2/2 constant. */
/* set_stiffness of a fresh n-dof, 1-contact structure; its status. */
static int make_sized_and_set(size_t n, const double K[])
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(n, 1, &s), FRICREG_OK);
    int status = fricreg_structure_set_stiffness(s, n, K);
    fricreg_structure_free(s);
    return status;
}

START_TEST(newmark_sdof_period_and_energy)
{
    const double mass = 2.385, w = 1.7, u0 = 0.0371, dt = 0.137, k = mass * w * w;
    fricreg_structure *s = make(1, 1);
    ok(s, fricreg_structure_set_mass(s, 1, &mass));
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    frictionless(s, 1);
    double v0 = 0.0;
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    double wb = trapezoidal_frequency(w, dt), e0 = 0.5 * k * u0 * u0;
    for (int n = 1; n <= 400; n++) {
        ok(s, fricreg_structure_step(s, dt));
        double u, v;
        ok(s, fricreg_structure_get_state(s, 1, &u, &v, NULL));
        ck_assert_double_eq_tol(u, u0 * cos(wb * n * dt), 1e-12 * u0);
        ck_assert_double_eq_tol(v, -u0 * w * sin(wb * n * dt), 1e-12 * u0 * w);
    }
    double e = value(s, FRICREG_SVALUE_KINETIC) + value(s, FRICREG_SVALUE_STRAIN);
    ck_assert_double_eq_tol(e, e0, 1e-12 * e0);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_INITIAL), e0, 1e-15 * e0);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), 0.0, 1e-12 * e0);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_TIME), 400 * dt, 1e-12);
    /* Linear: the exact tangent solves each step in one Newton iteration. */
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_STEPS), 400);
    ck_assert_int_le(stat(s, FRICREG_SSTAT_NEWTON_MAX), 1);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
    fricreg_structure_free(s);
}
END_TEST

/* A caller who runs to each sample time t_k = k dt in turn (as fricreg-sim structure does):
 * late in a run t_k - t_(k-1) rounds up to dt + 1 ulp of t, more than 1e-12 dt when t/dt is
 * beyond about 10^4. run() once split such a step into dt and a zero-length sliver and failed
 * ("dt is lost against t") at t = 4.0002 with dt = 2e-4; each call must be one step. */
START_TEST(run_to_each_sample_time_is_one_step)
{
    const double mass = 2.385, k = 417.3, u0 = 0.0371, v0 = 0.0, dt = 2e-4;
    fricreg_structure *s = make(1, 1);
    ok(s, fricreg_structure_set_mass(s, 1, &mass));
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    frictionless(s, 1);
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    for (int n = 1; n <= 25000; n++)
        ok(s, fricreg_structure_run(s, dt, n * dt));
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_STEPS), 25000);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_TIME), 25000 * dt, 1e-12);
    fricreg_structure_free(s);
}
END_TEST

/* 2 DOF, M = diag(1.3, 0.7) kg, K = [[k1 + k2, -k2], [-k2, k2]], k1 = 40.5, k2 = 23.1 N/m,
 * u0 = (0.012, -0.027) m at rest; dt = 0.0731 s. Undamped (_i = 0): each M-orthonormal mode
 * phi_k carries q_k0 = phi_k.M u0 as q_k0 cos(wb_k t). Rayleigh (_i = 1, a0 = 0.31 1/s,
 * a1 = 0.0127 s): each mode's (q, q') follows the trapezoidal map of
 * [[0, 1], [-w^2, -2 zeta w]], 2 zeta w = a0 + a1 w^2, and the balance still closes. */
START_TEST(newmark_two_dof_modal)
{
    const double m1 = 1.3, m2 = 0.7, k1 = 40.5, k2 = 23.1, dt = 0.0731, a0 = 0.31, a1 = 0.0127;
    const double M[4] = {m1, 0.0, 0.0, m2}, K[4] = {k1 + k2, -k2, -k2, k2};
    const double u0[2] = {0.012, -0.027}, v0[2] = {0.0, 0.0};
    int damped = _i;
    fricreg_structure *s = make(2, 1);
    ok(s, fricreg_structure_set_mass(s, 2, M));
    ok(s, fricreg_structure_set_stiffness(s, 2, K));
    if (damped)
        ok(s, fricreg_structure_set_rayleigh(s, a0, a1));
    frictionless(s, 2);
    ok(s, fricreg_structure_set_initial(s, 2, u0, v0));

    /* Modes by GSL: K phi = w^2 M phi, phi^T M phi = 1. */
    gsl_matrix *Km = gsl_matrix_alloc(2, 2), *Mm = gsl_matrix_alloc(2, 2);
    gsl_matrix *phi = gsl_matrix_alloc(2, 2);
    gsl_vector *w2 = gsl_vector_alloc(2);
    memcpy(Km->data, K, sizeof K);
    memcpy(Mm->data, M, sizeof M);
    gsl_eigen_gensymmv_workspace *ws = gsl_eigen_gensymmv_alloc(2);
    ck_assert_int_eq(gsl_eigen_gensymmv(Km, Mm, w2, phi, ws), 0);
    gsl_eigen_gensymmv_free(ws);
    for (int k = 0; k < 2; k++) { /* GSL normalizes to unit length: make phi^T M phi = 1 */
        double pk0 = gsl_matrix_get(phi, 0, k), pk1 = gsl_matrix_get(phi, 1, k);
        double norm = sqrt(m1 * pk0 * pk0 + m2 * pk1 * pk1);
        gsl_matrix_set(phi, 0, k, pk0 / norm);
        gsl_matrix_set(phi, 1, k, pk1 / norm);
    }
    double q[2][2];    /* per mode: (q, q') */
    double P[2][2][2]; /* per mode: the trapezoidal map */
    for (int k = 0; k < 2; k++) {
        double pk0 = gsl_matrix_get(phi, 0, k), pk1 = gsl_matrix_get(phi, 1, k);
        q[k][0] = pk0 * m1 * u0[0] + pk1 * m2 * u0[1];
        q[k][1] = 0.0;
        double ww = gsl_vector_get(w2, k), c = damped ? a0 + a1 * ww : 0.0, h = dt / 2.0;
        /* (I - h A)^-1 (I + h A), A = [[0, 1], [-ww, -c]] */
        double d = 1.0 + h * c + h * h * ww;
        double inv[2][2] = {{(1.0 + h * c) / d, h / d}, {-h * ww / d, 1.0 / d}};
        double B[2][2] = {{1.0, h}, {-h * ww, 1.0 - h * c}};
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                P[k][i][j] = inv[i][0] * B[0][j] + inv[i][1] * B[1][j];
    }
    for (int n = 1; n <= 300; n++) {
        ok(s, fricreg_structure_step(s, dt));
        double expected[2] = {0.0, 0.0};
        for (int k = 0; k < 2; k++) {
            double y0 = P[k][0][0] * q[k][0] + P[k][0][1] * q[k][1];
            double y1 = P[k][1][0] * q[k][0] + P[k][1][1] * q[k][1];
            q[k][0] = y0;
            q[k][1] = y1;
            for (int i = 0; i < 2; i++)
                expected[i] += gsl_matrix_get(phi, i, k) * y0;
        }
        if (!damped) /* the same, in closed form */
            for (int i = 0; i < 2; i++) {
                double closed = 0.0;
                for (int k = 0; k < 2; k++) {
                    double pk0 = gsl_matrix_get(phi, 0, k), pk1 = gsl_matrix_get(phi, 1, k);
                    double wb = trapezoidal_frequency(sqrt(gsl_vector_get(w2, k)), dt);
                    closed += gsl_matrix_get(phi, i, k) * (pk0 * m1 * u0[0] + pk1 * m2 * u0[1]) *
                              cos(wb * n * dt);
                }
                ck_assert_double_eq_tol(expected[i], closed, 1e-12 * 0.027);
            }
        double u[2];
        ok(s, fricreg_structure_get_state(s, 2, u, NULL, NULL));
        ck_assert_double_eq_tol(u[0], expected[0], 1e-11 * 0.027);
        ck_assert_double_eq_tol(u[1], expected[1], 1e-11 * 0.027);
    }
    double e0 = value(s, FRICREG_SVALUE_INITIAL);
    ck_assert_double_eq_tol(
        e0, 0.5 * (K[0] * u0[0] * u0[0] + 2 * K[1] * u0[0] * u0[1] + K[3] * u0[1] * u0[1]), 1e-15);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), 0.0, 1e-12 * e0);
    if (damped) /* 300 steps = 21.9 s of a mode-1 damping ratio 0.027: most of e0 is gone */
        ck_assert_double_gt(value(s, FRICREG_SVALUE_VISCOUS), 0.5 * e0);
    else
        ck_assert_double_eq(value(s, FRICREG_SVALUE_VISCOUS), 0.0);
    gsl_matrix_free(Km);
    gsl_matrix_free(Mm);
    gsl_matrix_free(phi);
    gsl_vector_free(w2);
    fricreg_structure_free(s);
}
END_TEST

/* HHT-alpha, alpha = -0.1 (beta = 0.3025, gamma = 0.6), SDOF w = 2.3 rad/s, u0 = 0.41 m:
 * second order (the error at t = 3 falls about 4x per halving of dt), and its numerical
 * damping shows as a positive balance residual, about all of the energy lost. alpha = 0 is
 * average-acceleration Newmark, bit for bit. */
START_TEST(hht_second_order_and_dissipative)
{
    const double w = 2.3, k = w * w, u0 = 0.41, v0 = 0.0, t_end = 3.0;
    double err[3];
    for (int level = 0; level < 3; level++) {
        double dt = 0.02 / (double)(1 << level);
        fricreg_structure *s = make(1, 1);
        ok(s, fricreg_structure_set_stiffness(s, 1, &k));
        frictionless(s, 1);
        ok(s, fricreg_structure_set_hht(s, -0.1));
        ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
        ok(s, fricreg_structure_run(s, dt, t_end));
        double u;
        ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
        err[level] = fabs(u - u0 * cos(w * t_end));
        double e0 = 0.5 * k * u0 * u0,
               e = value(s, FRICREG_SVALUE_STRAIN) + value(s, FRICREG_SVALUE_KINETIC);
        ck_assert_double_lt(e, e0);
        ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), e0 - e, 1e-12 * e0);
        fricreg_structure_free(s);
    }
    ck_assert_double_eq_tol(err[0] / err[1], 4.0, 0.4);
    ck_assert_double_eq_tol(err[1] / err[2], 4.0, 0.4);

    double u[2];
    for (int hht = 0; hht < 2; hht++) {
        fricreg_structure *s = make(1, 1);
        ok(s, fricreg_structure_set_stiffness(s, 1, &k));
        frictionless(s, 1);
        if (hht)
            ok(s, fricreg_structure_set_hht(s, 0.0));
        ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
        ok(s, fricreg_structure_run(s, 0.0173, t_end));
        ok(s, fricreg_structure_get_state(s, 1, &u[hht], NULL, NULL));
        fricreg_structure_free(s);
    }
    ck_assert_double_eq(u[0], u[1]);
}
END_TEST

/* ---------------------------------------------------------------- the paper's oscillator */

/* Eq. (5) as a structure: M = K = J = 1, mun = 1, law (4) with eps = 2 dt; the load
 * a sin(omega t) sampled at the steps (which read it only there). */
static fricreg_structure *oscillator(double dt, double a, double omega, double x0, double t_end)
{
    fricreg_structure *s = make(1, 1);
    double one = 1.0, v0 = 0.0;
    ok(s, fricreg_structure_set_stiffness(s, 1, &one));
    ok(s, fricreg_structure_set_contacts(s, 1, 1, &one));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 2.0 * dt));
    if (a != 0.0) {
        size_t n = (size_t)(t_end / dt) + 3;
        double *g = malloc(n * sizeof *g);
        for (size_t k = 0; k < n; k++)
            g[k] = sin(omega * (double)k * dt);
        ok(s, fricreg_structure_set_load(s, 1, &a, 0.0, dt, n, g));
        free(g);
    }
    ok(s, fricreg_structure_set_initial(s, 1, &x0, &v0));
    return s;
}

/* Unforced, x0 = 2.75: the exact motion slides to -0.75 at t = pi and sticks for ever,
 * dissipating mun * 3.5 = 3.5. The regularized stick: the velocity enters the band at
 * |v| <= eps and decays at rate 2 mun/eps there, so it moves at most eps^2/2 further; held
 * stick: not one ulp of creep from t = 8 to t = 12. The slide is affine in the unknown
 * acceleration: the exact tangent converges in one iteration, and the stick, once its
 * acceleration is exactly 0, needs none. */
START_TEST(oscillator_unforced_sticks_at_rest_position)
{
    const double dt = 1e-3, eps = 2.0 * dt;
    fricreg_structure *s = oscillator(dt, 0.0, 1.0, 2.75, 12.0);
    ok(s, fricreg_structure_run(s, dt, 8.0));
    double u8, u;
    ok(s, fricreg_structure_get_state(s, 1, &u8, NULL, NULL));
    ok(s, fricreg_structure_run(s, dt, 12.0));
    ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
    ck_assert_double_eq_tol(u, -0.75, 0.5 * eps * eps);
    ck_assert_double_eq(u, u8);
    double D;
    ok(s, fricreg_structure_get_dissipation(s, 1, &D));
    ck_assert_double_eq_tol(D, 3.5, 0.5 * eps * eps); /* mun times the distance slid */
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_FRICTION), D, 1e-15);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), 0.0, 1e-12);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_MAX), 1);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
    /* the stick needs no iteration once a is exactly 0: fewer than one per step on average */
    ck_assert_int_lt(stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS), stat(s, FRICREG_SSTAT_STEPS));
    double f;
    ok(s, fricreg_structure_get_forces(s, 1, &f));
    /* at rest the friction holds the spring, to Newton's tolerance 1e-10 of mun = 1 */
    ck_assert_double_eq_tol(f, u, 1e-10);
    fricreg_structure_free(s);
}
END_TEST

/* Forced, a = 2, omega = 0.5 (sticks about a fifth of each cycle; the spec's Fig. 7a case),
 * from rest at the origin: D of the 5th cycle against the exact solution. Measured relative
 * errors: 1.6e-6 (dt = 4e-3), 2.8e-7 (2e-3), 8.8e-8 (1e-3): about second order, as the
 * paper finds for (4) with RK4. Checked: within 1e-6 at dt = 2e-3, and a >= 8x smaller error
 * at dt = 1e-3 than at 4e-3. Newton: at most 3 iterations in a step, none failed. */
START_TEST(oscillator_forced_dissipation_matches_exact)
{
    const double a = 2.0, omega = 0.5, T = 2.0 * PI / omega;
    const int cycles = 5;
    fricreg_exact *ex = NULL;
    ck_assert_int_eq(fricreg_exact_solve(a, omega, 1.0, 0.0, 0.0, cycles * T, &ex), FRICREG_OK);
    double De[5];
    ck_assert_int_eq(fricreg_exact_dissipation(ex, cycles, De), FRICREG_OK);
    fricreg_exact_free(ex);
    const double dts[3] = {4e-3, 2e-3, 1e-3};
    double rel[3];
    for (int i = 0; i < 3; i++) {
        fricreg_structure *s = oscillator(dts[i], a, omega, 0.0, cycles * T);
        ok(s, fricreg_structure_run(s, dts[i], (cycles - 1) * T));
        double before = value(s, FRICREG_SVALUE_FRICTION);
        ok(s, fricreg_structure_run(s, dts[i], cycles * T));
        rel[i] = (value(s, FRICREG_SVALUE_FRICTION) - before) / De[cycles - 1] - 1.0;
        double input = value(s, FRICREG_SVALUE_INPUT);
        ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), 0.0, 1e-6 * input);
        ck_assert_int_le(stat(s, FRICREG_SSTAT_NEWTON_MAX), 3);
        ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
        fricreg_structure_free(s);
    }
    ck_assert_double_lt(fabs(rel[1]), 1e-6);
    ck_assert_double_gt(fabs(rel[0]) / fabs(rel[2]), 8.0);
}
END_TEST

/* General Newmark (beta = 0.3025, gamma = 0.6: damping of high frequencies) on an undamped
 * SDOF, against the method's recurrence written out for M = 1, K = w^2:
 * (1 + beta h^2) a1 = -w^2 (u + dt v + (1/2 - beta) dt^2 a), h = w dt,
 * u1 = u + dt v + dt^2 ((1/2 - beta) a + beta a1), v1 = v + dt ((1 - gamma) a + gamma a1).
 * set_newmark after set_hht is plain Newmark again (alpha = 0). The balance's residual is
 * the energy the method removes: positive, and all of e0 - e. */
START_TEST(newmark_general_beta_gamma)
{
    const double w = 2.3, k = w * w, beta = 0.3025, gamma = 0.6, dt = 0.0917;
    double u = 0.41, v = -0.27, a = -k * u;
    fricreg_structure *s = make(1, 1);
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    frictionless(s, 1);
    ok(s, fricreg_structure_set_hht(s, -0.2));
    ok(s, fricreg_structure_set_newmark(s, beta, gamma));
    ok(s, fricreg_structure_set_initial(s, 1, &u, &v));
    for (int n = 1; n <= 200; n++) {
        double h = w * dt;
        double a1 = -k * (u + dt * v + (0.5 - beta) * dt * dt * a) / (1.0 + beta * h * h);
        u = u + dt * v + dt * dt * ((0.5 - beta) * a + beta * a1);
        v = v + dt * ((1.0 - gamma) * a + gamma * a1);
        a = a1;
        ok(s, fricreg_structure_step(s, dt));
        double got[3];
        ok(s, fricreg_structure_get_state(s, 1, got, got + 1, got + 2));
        ck_assert_double_eq_tol(got[0], u, 1e-12);
        ck_assert_double_eq_tol(got[1], v, 1e-12);
        ck_assert_double_eq_tol(got[2], a, 1e-11);
    }
    double e0 = value(s, FRICREG_SVALUE_INITIAL);
    double e = value(s, FRICREG_SVALUE_KINETIC) + value(s, FRICREG_SVALUE_STRAIN);
    ck_assert_double_lt(e, 0.9 * e0);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), e0 - e, 1e-12 * e0);
    fricreg_structure_free(s);
}
END_TEST

/* Central difference, SDOF as above: u_{n+1} - 2 u_n + u_{n-1} = -(w dt)^2 u_n with
 * u_1 = u0 (1 - (w dt)^2/2), so u_n = u0 cos(wc t_n), cos(wc dt) = 1 - (w dt)^2/2. Stable
 * for w dt < 2; the drivers' guard keeps (w dt/2)^2 < 0.9 (src/ode/step_guard.c), so
 * dt = 1.001 * 2 sqrt(0.9)/w is refused, the state unchanged, and 0.999 times it runs. */
START_TEST(central_difference_sdof_and_bound)
{
    const double mass = 2.385, w = 1.7, u0 = 0.0371, dt = 0.137, k = mass * w * w, v0 = 0.0;
    fricreg_structure *s = make(1, 1);
    ok(s, fricreg_structure_set_mass(s, 1, &mass));
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    frictionless(s, 1);
    ok(s, fricreg_structure_set_central_difference(s));
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    double wc = acos(1.0 - (w * dt) * (w * dt) / 2.0) / dt;
    for (int n = 1; n <= 400; n++) {
        ok(s, fricreg_structure_step(s, dt));
        double u;
        ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
        ck_assert_double_eq_tol(u, u0 * cos(wc * n * dt), 1e-12 * u0);
    }
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS), 0);
    double before[3], after[3];
    ok(s, fricreg_structure_get_state(s, 1, before, before + 1, before + 2));
    ck_assert_int_eq(fricreg_structure_step(s, 1.001 * 2.0 * sqrt(0.9) / w), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "(dt*omega/2)^2"));
    ok(s, fricreg_structure_get_state(s, 1, after, after + 1, after + 2));
    ck_assert_mem_eq(before, after, sizeof before);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_TIME), 400 * dt, 1e-12);
    ok(s, fricreg_structure_step(s, 0.999 * 2.0 * sqrt(0.9) / w));
    fricreg_structure_free(s);
}
END_TEST

/* Central difference on the paper's oscillator: the stick zone's velocity decays only for
 * dt 2 mun/eps < 1 (W = 1), so the paper's eps = 2 dt sits on the margin and is refused;
 * eps = 4 dt holds the stick within eps^2/2 of -0.75 with no creep, and the 5th forced
 * cycle's D converges at second order (measured -4.5e-6, -1.1e-6, -2.7e-7 at dt = 4e-3,
 * 2e-3, 1e-3: ratio 4). */
START_TEST(central_difference_oscillator)
{
    const double dt = 1e-3, x0 = 2.75, v0 = 0.0;
    fricreg_structure *s = oscillator(dt, 0.0, 1.0, x0, 12.0);
    ok(s, fricreg_structure_set_central_difference(s));
    ck_assert_int_eq(fricreg_structure_step(s, dt), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "stick-zone"));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 4.0 * dt));
    ok(s, fricreg_structure_set_initial(s, 1, &x0, &v0));
    ok(s, fricreg_structure_run(s, dt, 8.0));
    double u8, u;
    ok(s, fricreg_structure_get_state(s, 1, &u8, NULL, NULL));
    ok(s, fricreg_structure_run(s, dt, 12.0));
    ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
    ck_assert_double_eq_tol(u, -0.75, 0.5 * (4.0 * dt) * (4.0 * dt));
    ck_assert_double_eq(u, u8);
    fricreg_structure_free(s);

    const double a = 2.0, omega = 0.5, T = 2.0 * PI / omega;
    fricreg_exact *ex = NULL;
    ck_assert_int_eq(fricreg_exact_solve(a, omega, 1.0, 0.0, 0.0, 5.0 * T, &ex), FRICREG_OK);
    double De[5], rel[2];
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 5, De), FRICREG_OK);
    fricreg_exact_free(ex);
    for (int i = 0; i < 2; i++) {
        double h = 2e-3 / (double)(1 << i);
        s = oscillator(h, a, omega, 0.0, 5.0 * T);
        ok(s, fricreg_structure_set_central_difference(s));
        ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 4.0 * h));
        ok(s, fricreg_structure_run(s, h, 4.0 * T));
        double before = value(s, FRICREG_SVALUE_FRICTION);
        ok(s, fricreg_structure_run(s, h, 5.0 * T));
        rel[i] = (value(s, FRICREG_SVALUE_FRICTION) - before) / De[4] - 1.0;
        fricreg_structure_free(s);
    }
    ck_assert_double_lt(fabs(rel[0]), 2e-6);
    ck_assert_double_eq_tol(rel[0] / rel[1], 4.0, 0.4);
}
END_TEST

/* ---------------------------------------------------------------- coupled contacts */

/* Two storeys, J = [[1, 0], [-1, 1]] (ground and inter-storey slip): W = J M^-1 J^T is dense.
 * A constant load p = (0.731, -0.412) N within the bounds mun = (0.5, 0.6) N is held at rest:
 * J^T f = -p gives f = (-(p1 + p2), -p2) = (-0.319, 0.412), and nothing moves, ever. */
START_TEST(coupled_contacts_hold_a_static_load)
{
    const double mun[2] = {0.5, 0.6}, p[2] = {0.731, -0.412};
    fricreg_structure *s = make_two_storeys(mun, FRICREG_LAW_QUINN, 0.013);
    ok(s, fricreg_structure_set_load(s, 2, p, 0.0, 0.0, 0, NULL));
    ok(s, fricreg_structure_run(s, 0.01, 1.0));
    double u[2], v[2], f[2];
    ok(s, fricreg_structure_get_state(s, 2, u, v, NULL));
    ok(s, fricreg_structure_get_forces(s, 2, f));
    for (int i = 0; i < 2; i++) {
        ck_assert_double_eq_tol(u[i], 0.0, 1e-15);
        ck_assert_double_eq_tol(v[i], 0.0, 1e-15);
    }
    ck_assert_double_eq_tol(f[0], -0.319, 1e-13);
    ck_assert_double_eq_tol(f[1], 0.412, 1e-13);
    fricreg_structure_free(s);
}
END_TEST

/* The same two storeys shaken at the ground, a_g = 2.1 sin(3.7 t) m/s^2 for 4 s, r = (1, 1),
 * Rayleigh damping: the contacts slip and stick, coupled. Newmark and HHT (alpha = -0.05):
 * no Newton failure, few iterations, and Newmark's balance closes to 1e-9 of the input. */
START_TEST(coupled_contacts_shaken)
{
    const double M[4] = {1.7, 0.0, 0.0, 0.9}, K[4] = {30.2, -12.1, -12.1, 12.1};
    const double J[4] = {1.0, 0.0, -1.0, 1.0}, mun[2] = {1.3, 0.45}, r[2] = {1.0, 1.0};
    const double dt = 0.01, dr = 0.005;
    double ag[801];
    for (int k = 0; k < 801; k++)
        ag[k] = 2.1 * sin(3.7 * k * dr);
    fricreg_structure *s = make(2, 2);
    ok(s, fricreg_structure_set_mass(s, 2, M));
    ok(s, fricreg_structure_set_stiffness(s, 2, K));
    ok(s, fricreg_structure_set_rayleigh(s, 0.05, 0.002));
    ok(s, fricreg_structure_set_contacts(s, 2, 2, J));
    ok(s, fricreg_structure_set_bounds(s, 2, mun));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.01));
    ok(s, fricreg_structure_set_influence(s, 2, r));
    ok(s, fricreg_structure_set_ground_accel(s, 0.0, dr, 801, ag));
    if (_i)
        ok(s, fricreg_structure_set_hht(s, -0.05));
    ok(s, fricreg_structure_run(s, dt, 4.0));
    double D[2], input = value(s, FRICREG_SVALUE_INPUT);
    ok(s, fricreg_structure_get_dissipation(s, 2, D));
    ck_assert_double_gt(D[0], 0.0);
    ck_assert_double_gt(D[1], 0.0);
    ck_assert_double_eq_tol(D[0] + D[1], value(s, FRICREG_SVALUE_FRICTION), 1e-12 * input);
    if (!_i)
        ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), 0.0, 1e-9 * fabs(input));
    else
        ck_assert_double_gt(value(s, FRICREG_SVALUE_RESIDUAL), 0.0);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_STEPS), 400);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
    ck_assert_int_le(stat(s, FRICREG_SSTAT_NEWTON_MAX), 10);
    ck_assert_int_le(stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS), 3 * 400);
    fricreg_structure_free(s);
}
END_TEST

/* The default influence vector is r = 1 at every DOF (the CLI's): a run that never sets it
 * equals, bit for bit, one that sets r = 1; r = 0 set explicitly leaves the storeys at rest. */
static void shaken_default_run(const double *r, double u[2])
{
    const double M[4] = {1.7, 0.0, 0.0, 0.9}, K[4] = {30.2, -12.1, -12.1, 12.1};
    const double J[4] = {1.0, 0.0, -1.0, 1.0}, mun[2] = {1.3, 0.45};
    double ag[201];
    for (int k = 0; k < 201; k++)
        ag[k] = 2.1 * sin(3.7 * k * 0.005);
    fricreg_structure *s = make(2, 2);
    ok(s, fricreg_structure_set_mass(s, 2, M));
    ok(s, fricreg_structure_set_stiffness(s, 2, K));
    ok(s, fricreg_structure_set_contacts(s, 2, 2, J));
    ok(s, fricreg_structure_set_bounds(s, 2, mun));
    if (r != NULL)
        ok(s, fricreg_structure_set_influence(s, 2, r));
    ok(s, fricreg_structure_set_ground_accel(s, 0.0, 0.005, 201, ag));
    ok(s, fricreg_structure_run(s, 0.01, 1.0));
    ok(s, fricreg_structure_get_state(s, 2, u, NULL, NULL));
    fricreg_structure_free(s);
}

START_TEST(default_influence_moves_every_dof_with_the_ground)
{
    const double ones[2] = {1.0, 1.0}, zeros[2] = {0.0, 0.0};
    double u_default[2], u_ones[2], u_zeros[2];
    shaken_default_run(NULL, u_default);
    shaken_default_run(ones, u_ones);
    shaken_default_run(zeros, u_zeros);
    ck_assert_double_ne(u_ones[0], 0.0);
    ck_assert_mem_eq(u_default, u_ones, sizeof u_ones);
    ck_assert_double_eq(u_zeros[0], 0.0);
    ck_assert_double_eq(u_zeros[1], 0.0);
}
END_TEST

/* Every law on the shaken storeys: the continuous ones, (3), (4) and tanh, converge at every
 * step and close Newmark's balance; (1) and (2) jump at v = 0, so a step into a stick has no
 * root: failures are counted, not hidden, and the run goes on (as with Karnopp, which jumps
 * at |v| = eps and may or may not be caught on the jump). */
START_TEST(every_law_on_coupled_contacts)
{
    const int law = _i;
    const double mun[2] = {1.3, 0.45}, r[2] = {1.0, 1.0};
    double ag[801];
    for (int k = 0; k < 801; k++)
        ag[k] = 2.1 * sin(3.7 * k * 0.005);
    fricreg_structure *s = make_two_storeys(mun, law, 0.01);
    ok(s, fricreg_structure_set_influence(s, 2, r));
    ok(s, fricreg_structure_set_ground_accel(s, 0.0, 0.005, 801, ag));
    ok(s, fricreg_structure_run(s, 0.01, 4.0));
    double input = value(s, FRICREG_SVALUE_INPUT);
    if (law == FRICREG_LAW_COULOMB || law == FRICREG_LAW_FORCE_BALANCE) {
        ck_assert_int_gt(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
    } else if (law != FRICREG_LAW_KARNOPP) {
        ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
        ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), 0.0, 1e-9 * input);
    }
    fricreg_structure_free(s);
}
END_TEST

/* A shear chain of 100 storeys (lumped masses 1 + 0.01 i kg, storey stiffness 400 N/m, a
 * damper between each storey and the one below): W = J M^-1 J^T is tridiagonal, coupled, and
 * the structure's context holds it sparse (beyond 64 contacts). Shaken at the ground for 200
 * steps, each step's forces must be the consistent law at its end: the law evaluated by a
 * context of its own on the dense W the test forms, at zdot = J v and a_free = J a - W f
 * (J a = J M^-1 (p - C v - K u) + W f). */
START_TEST(many_coupled_contacts_obey_the_law)
{
    enum { N = 100, STEPS = 200 };
    double *M = calloc(N * N, sizeof *M), *K = calloc(N * N, sizeof *K);
    double *J = calloc(N * N, sizeof *J), *W = calloc(N * N, sizeof *W);
    double mun[N], minv[N], r[N], ag[2 * STEPS + 1];
    for (int i = 0; i < N; i++) {
        M[i * N + i] = 1.0 + 0.01 * i;
        minv[i] = 1.0 / M[i * N + i];
        mun[i] = 0.3 * M[i * N + i] * (1.0 + 0.2 * sin(i));
        r[i] = 1.0;
        K[i * N + i] = i + 1 < N ? 800.0 : 400.0;
        if (i > 0)
            K[i * N + i - 1] = K[(i - 1) * N + i] = -400.0;
        J[i * N + i] = 1.0;
        if (i > 0)
            J[i * N + i - 1] = -1.0;
    }
    for (int i = 0; i < N; i++) /* W = J M^-1 J^T, tridiagonal */
        for (int j = 0; j < N; j++)
            for (int k = 0; k < N; k++)
                W[i * N + j] += J[i * N + k] * minv[k] * J[j * N + k];
    for (int k = 0; k <= 2 * STEPS; k++)
        ag[k] = 2.1 * sin(3.7 * k * 0.005);
    fricreg_structure *s = make(N, N);
    ok(s, fricreg_structure_set_mass(s, N, M));
    ok(s, fricreg_structure_set_stiffness(s, N, K));
    ok(s, fricreg_structure_set_rayleigh(s, 0.05, 0.002));
    ok(s, fricreg_structure_set_contacts(s, N, N, J));
    ok(s, fricreg_structure_set_bounds(s, N, mun));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.01));
    ok(s, fricreg_structure_set_influence(s, N, r));
    ok(s, fricreg_structure_set_ground_accel(s, 0.0, 0.005, 2 * STEPS + 1, ag));
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(N, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, N, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, N, W), FRICREG_OK);
    double u[N], v[N], a[N], f[N], zdot[N], afree[N], law[N], worst = 0.0;
    int sticking = 0, sliding = 0;
    for (int step = 0; step < STEPS; step++) {
        ok(s, fricreg_structure_step(s, 0.01));
        ok(s, fricreg_structure_get_state(s, N, u, v, a));
        ok(s, fricreg_structure_get_forces(s, N, f));
        for (int i = 0; i < N; i++) {
            zdot[i] = v[i] - (i > 0 ? v[i - 1] : 0.0);
            double ja = a[i] - (i > 0 ? a[i - 1] : 0.0), wf = 0.0;
            for (int j = 0; j < N; j++)
                wf += W[i * N + j] * f[j];
            afree[i] = ja - wf;
        }
        ck_assert_int_eq(fricreg_ctx_eval(ctx, N, zdot, afree, law, NULL), FRICREG_OK);
        for (int i = 0; i < N; i++) {
            worst = fmax(worst, fabs(f[i] - law[i]) / mun[i]);
            sticking += fabs(zdot[i]) < 0.01;
            sliding += fabs(zdot[i]) >= 0.01;
        }
    }
    printf("many coupled contacts: max |f - F(zdot, a_free)| / mun = %.2e over %d steps; "
           "%d near-stick and %d sliding contact-steps; %lld Newton iterations\n",
           worst, STEPS, sticking, sliding, (long long)stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS));
    ck_assert_double_le(worst, 1e-7);
    ck_assert_int_gt(sticking, STEPS * N / 10); /* both pieces of the law are exercised */
    ck_assert_int_gt(sliding, STEPS * N / 10);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
    /* Newton on the exact tangent: 231 iterations measured, about one a step */
    ck_assert_int_le(stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS), 2 * STEPS);
    fricreg_ctx_free(ctx);
    fricreg_structure_free(s);
    free(M), free(K), free(J), free(W);
}
END_TEST

/* The ground motion fed step by step, {a_g(t), a_g(t + dt)} before each step, gives the run
 * of the whole record sampled at the steps: the record is read at step ends only. */
START_TEST(ground_motion_step_by_step)
{
    const double mun[2] = {1.3, 0.45}, r[2] = {1.0, 1.0};
    const double dt = 0.01;
    double ag[301], u[2][2];
    for (int k = 0; k < 301; k++)
        ag[k] = 2.1 * sin(3.7 * k * dt);
    for (int by_step = 0; by_step < 2; by_step++) {
        fricreg_structure *s = make_two_storeys(mun, FRICREG_LAW_QUINN, 0.01);
        ok(s, fricreg_structure_set_influence(s, 2, r));
        if (!by_step)
            ok(s, fricreg_structure_set_ground_accel(s, 0.0, dt, 301, ag));
        for (int k = 0; k < 300; k++) {
            if (by_step)
                ok(s, fricreg_structure_set_ground_accel(s, k * dt, dt, 2, ag + k));
            ok(s, fricreg_structure_step(s, dt));
        }
        ok(s, fricreg_structure_get_state(s, 2, u[by_step], NULL, NULL));
        ck_assert_double_gt(value(s, FRICREG_SVALUE_FRICTION), 0.0);
        fricreg_structure_free(s);
    }
    ck_assert_double_eq_tol(u[1][0], u[0][0], 1e-12 * fabs(u[0][0]));
    ck_assert_double_eq_tol(u[1][1], u[0][1], 1e-12 * fabs(u[0][1]));
}
END_TEST

/* ---------------------------------------------------------------- GSL steppers (run_ode) */

/* The paper's unforced oscillator through run_ode with fixed-step RK4 (dt = 0.01,
 * eps = 2 dt) is the driver's own computation: fricreg_sim's x(20) (the paper's -0.750090)
 * and D, to the last bit or nearly (1e-15). */
START_TEST(run_ode_reproduces_the_oscillator_driver)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run(sim, 20.0), FRICREG_OK);
    double xs, vs, Ds;
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &xs, &vs), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_DISSIPATION, &Ds), FRICREG_OK);
    fricreg_sim_free(sim);

    fricreg_structure *s = oscillator(0.01, 0.0, 1.0, 2.75, 20.0);
    ok(s, fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.01, 0.0, 0.0, 20.0));
    double x, v;
    ok(s, fricreg_structure_get_state(s, 1, &x, &v, NULL));
    ck_assert_double_eq_tol(x, xs, 1e-15);
    ck_assert_double_eq_tol(x, -0.750090, 5e-7);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_FRICTION), Ds, 1e-15 * Ds);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_STEPS), 2000);
    /* the step guard of the drivers: rk4's 2.78 against dt 2/eps = 100 dt */
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.03, 0.0, 0.0, 30.0),
                     FRICREG_ESTEP);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_TIME), 20.0);
    fricreg_structure_free(s);
}
END_TEST

/* The paper's chain (n = 32, a = 0.25, omega = 0.5, eps = 10 omega dt, RK4 dt = 0.01) as a
 * structure: M = I/n, K = n tridiag(-1, 2, -1) with block 1 free (K_11 = n), friction
 * entering as f_i/n (J = I/n, so zdot = v/n and the law's eps is eps/n: the same force),
 * G(t) = a sin(omega t) on block 1. The load is a record sampled every dt/2 from each cycle's
 * start, where RK4's stages read it: D per cycle equals the driver's to 1e-10. */
START_TEST(run_ode_reproduces_the_chain_driver)
{
    enum { N = 32, CYCLES = 4 };
    const double a = 0.25, omega = 0.5, dt = 0.01, T = 2.0 * PI / omega, n = N;
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, CYCLES), FRICREG_OK);
    double Ds[CYCLES];
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, Ds), FRICREG_OK);
    double eps = 0.0;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_EPS, &eps), FRICREG_OK);
    fricreg_sim_free(sim);

    static double M[N * N], K[N * N], J[N * N];
    double p[N] = {a}, mun[N];
    for (int i = 0; i < N; i++) {
        M[i * N + i] = 1.0 / n;
        J[i * N + i] = 1.0 / n;
        K[i * N + i] = i == 0 ? n : 2.0 * n;
        if (i > 0)
            K[i * N + i - 1] = K[(i - 1) * N + i] = -n;
        mun[i] = 1.0;
    }
    fricreg_structure *s = make(N, N);
    ok(s, fricreg_structure_set_mass(s, N, M));
    ok(s, fricreg_structure_set_stiffness(s, N, K));
    ok(s, fricreg_structure_set_contacts(s, N, N, J));
    ok(s, fricreg_structure_set_bounds(s, N, mun));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps / n));
    size_t samples = (size_t)(T / (0.5 * dt)) + 3;
    double *g = malloc(samples * sizeof *g), before = 0.0;
    for (int c = 1; c <= CYCLES; c++) {
        double t0 = (c - 1) * T;
        for (size_t k = 0; k < samples; k++)
            g[k] = sin(omega * (t0 + 0.5 * dt * (double)k));
        ok(s, fricreg_structure_set_load(s, N, p, t0, 0.5 * dt, samples, g));
        ok(s, fricreg_structure_run_ode(s, FRICREG_INT_RK4, dt, 0.0, 0.0, c * T));
        double D = value(s, FRICREG_SVALUE_FRICTION);
        ck_assert_double_eq_tol(D - before, Ds[c - 1], 1e-10 * Ds[c - 1]);
        before = D;
    }
    free(g);
    ck_assert_double_eq_tol(Ds[CYCLES - 1], 0.0105, 0.0005); /* the paper's Fig. 9 */
    fricreg_structure_free(s);
}
END_TEST

/* Adaptive and implicit GSL steppers on the unforced oscillator: msbdf and rkf45 at
 * rtol = 1e-8 reach the stick within eps^2/2 of -0.75 (eps = 0.02), their balance
 * integrated with them to 1e-6 of the initial energy; then Newmark steps on from there. */
START_TEST(run_ode_adaptive_then_newmark)
{
    const int integrators[2] = {FRICREG_INT_MSBDF, FRICREG_INT_RKF45};
    fricreg_structure *s = oscillator(0.01, 0.0, 1.0, 2.75, 20.0);
    ok(s, fricreg_structure_run_ode(s, integrators[_i], 0.01, 1e-8, 1e-10, 20.0));
    double x, v;
    ok(s, fricreg_structure_get_state(s, 1, &x, &v, NULL));
    ck_assert_double_eq_tol(x, -0.75, 0.5 * 0.02 * 0.02);
    double e0 = value(s, FRICREG_SVALUE_INITIAL);
    ck_assert_double_eq_tol(e0, 0.5 * 2.75 * 2.75, 1e-15);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_RESIDUAL), 0.0, 1e-6 * e0);
    ok(s, fricreg_structure_run(s, 0.01, 25.0));
    double x25;
    ok(s, fricreg_structure_get_state(s, 1, &x25, NULL, NULL));
    /* the stick holds under Newmark too: the velocity left (2e-11 after rkf45), decaying at
     * the zone's rate 2 mun/eps (1/3 per step here), moves x by about |v| eps/2; bounded by
     * twice that, plus Newton's tolerance 1e-10 in a times dt^2 */
    ck_assert_double_eq_tol(x25, x, fabs(v) * 0.02 + 1e-14);
    fricreg_structure_free(s);
}
END_TEST

/* ------------------------------------------------------------------ the ten-storey building */

#define STOREYS 10

/* Ten storeys of 1e5 kg and 1e8 N/m, 5 % Rayleigh damping in modes 1 and 2 (shear-building
 * frequencies w_j = 2 sqrt(k/m) sin((2j - 1) pi/(2(2N + 1)))), a friction damper in every
 * storey slipping at 5 % of the weight above, ground acceleration
 * 0.3 g sin(pi t/10) sin(2 pi t) for 10 s then 5 s free; eps = 0.01 m/s (peak drift velocity
 * about 0.19 m/s). Runs to 15 s with steps of dt; returns the damper energy and the peak roof
 * displacement, and the structure in *out. */
static fricreg_structure *building_model(double eps, double alpha)
{
    const double m = 1e5, k = 1e8, g = 9.81, zeta = 0.05, n = STOREYS;
    double M[STOREYS * STOREYS] = {0}, K[STOREYS * STOREYS] = {0}, J[STOREYS * STOREYS] = {0};
    double mun[STOREYS], r[STOREYS];
    for (int i = 0; i < STOREYS; i++) {
        M[i * STOREYS + i] = m;
        K[i * STOREYS + i] = i < STOREYS - 1 ? 2.0 * k : k;
        if (i > 0) {
            K[i * STOREYS + i - 1] = K[(i - 1) * STOREYS + i] = -k;
            J[i * STOREYS + i - 1] = -1.0; /* storey drift u_i - u_(i-1) */
        }
        J[i * STOREYS + i] = 1.0;
        mun[i] = 0.05 * g * m * (STOREYS - i);
        r[i] = 1.0;
    }
    double w1 = 2.0 * sqrt(k / m) * sin(PI / (2.0 * (2.0 * n + 1.0)));
    double w2 = 2.0 * sqrt(k / m) * sin(3.0 * PI / (2.0 * (2.0 * n + 1.0)));
    const double dr = 1e-3;
    double *ag = malloc(10001 * sizeof *ag);
    for (int i = 0; i <= 10000; i++)
        ag[i] = 0.3 * g * sin(PI * i * dr / 10.0) * sin(2.0 * PI * i * dr);
    fricreg_structure *s = make(STOREYS, STOREYS);
    ok(s, fricreg_structure_set_mass(s, STOREYS, M));
    ok(s, fricreg_structure_set_stiffness(s, STOREYS, K));
    ok(s,
       fricreg_structure_set_rayleigh(s, 2.0 * zeta * w1 * w2 / (w1 + w2), 2.0 * zeta / (w1 + w2)));
    ok(s, fricreg_structure_set_contacts(s, STOREYS, STOREYS, J));
    ok(s, fricreg_structure_set_bounds(s, STOREYS, mun));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps));
    ok(s, fricreg_structure_set_influence(s, STOREYS, r));
    ok(s, fricreg_structure_set_ground_accel(s, 0.0, dr, 10001, ag));
    free(ag);
    if (alpha != 0.0)
        ok(s, fricreg_structure_set_hht(s, alpha));
    return s;
}

static double building(double dt, double alpha, double *peak_roof, fricreg_structure **out)
{
    fricreg_structure *s = building_model(0.01, alpha);
    *peak_roof = 0.0;
    int steps = (int)lround(15.0 / dt);
    for (int i = 0; i < steps; i++) {
        ok(s, fricreg_structure_step(s, dt));
        double u[STOREYS];
        ok(s, fricreg_structure_get_state(s, STOREYS, u, NULL, NULL));
        *peak_roof = fmax(*peak_roof, fabs(u[STOREYS - 1]));
    }
    double D[STOREYS], total = 0.0;
    ok(s, fricreg_structure_get_dissipation(s, STOREYS, D));
    for (int i = 0; i < STOREYS; i++) {
        ck_assert_double_gt(D[i], 0.0); /* every damper slips */
        total += D[i];
    }
    *out = s;
    return total;
}

/* The building's acceptance numbers at dt = 0.01 s and 0.005 s, Newmark and HHT (alpha = -0.1):
 * no Newton failure and at most 5 iterations per step on average; damper energy and peak
 * roof displacement within 0.5 % of a fine reference (Newmark, dt = 5e-4 s); Newmark's
 * energy balance closes to 1e-6 of the input, HHT's residual is its numerical damping (> 0).
 * Measured: 1.10 (Newmark) and 1.09 (HHT) iterations per step at dt = 0.01, max 6. */
START_TEST(building_newmark_and_hht)
{
    double ref_peak;
    fricreg_structure *s;
    double ref_energy = building(5e-4, 0.0, &ref_peak, &s);
    fricreg_structure_free(s);
    const double dts[2] = {0.01, 0.005};
    for (int i = 0; i < 2; i++) {
        double peak, energy = building(dts[i], _i ? -0.1 : 0.0, &peak, &s);
        ck_assert_double_eq_tol(energy, ref_energy, 5e-3 * ref_energy);
        ck_assert_double_eq_tol(peak, ref_peak, 5e-3 * ref_peak);
        int64_t steps = stat(s, FRICREG_SSTAT_STEPS);
        ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
        ck_assert_int_le(stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS), 5 * steps);
        double input = value(s, FRICREG_SVALUE_INPUT), residual = value(s, FRICREG_SVALUE_RESIDUAL);
        if (_i)
            ck_assert_double_gt(residual, 0.0);
        else
            ck_assert_double_eq_tol(residual, 0.0, 1e-6 * input);
        fricreg_structure_free(s);
    }
}
END_TEST

/* Newton at small eps (Delta t lambda = 17.66 dt/eps = 1766 at eps = 1e-4 m/s, dt = 0.01 s:
 * law (4)'s band is eps/(gamma dt) = 0.02 m/s^2 wide in the step's acceleration). Once every
 * damper sticks (the free vibration, t > 10.5 s) the stick predictor keeps each contact in
 * its band, where the law is linear, so the exact tangent converges in one iteration every
 * step (the previous acceleration as the guess took 10); over the run, stops at zdot = 0
 * keep slip-to-stick steps short: measured 1.29 iterations a step (before: 9.95; 1.70 with
 * the guess alone) and 1.09 at eps = 0.01 m/s (1.15). */
START_TEST(building_newton_at_small_eps)
{
    const double eps[2] = {1e-2, 1e-4}, mean[2] = {1.2, 1.5};
    for (int i = 0; i < 2; i++) {
        fricreg_structure *s = building_model(eps[i], 0.0);
        ok(s, fricreg_structure_run(s, 0.01, 10.5));
        int64_t before = stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS);
        ok(s, fricreg_structure_run(s, 0.01, 15.0));
        ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS) - before, 450);
        ck_assert_int_eq(stat(s, FRICREG_SSTAT_NEWTON_FAILURES), 0);
        ck_assert_double_le((double)stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS),
                            mean[i] * (double)stat(s, FRICREG_SSTAT_STEPS));
        fricreg_structure_free(s);
    }
}
END_TEST

/* ---------------------------------------------------------------- sparse input */

/* A dense row-major rows x cols matrix as a gsl_spmatrix of the given storage format: only
 * its non-zero entries are stored. */
static gsl_spmatrix *sparse(const double A[], size_t rows, size_t cols, int format)
{
    gsl_spmatrix *coo = gsl_spmatrix_alloc(rows, cols);
    for (size_t i = 0; i < rows; i++)
        for (size_t j = 0; j < cols; j++)
            if (A[i * cols + j] != 0.0)
                gsl_spmatrix_set(coo, i, j, A[i * cols + j]);
    if (format == GSL_SPMATRIX_COO)
        return coo;
    gsl_spmatrix *c = gsl_spmatrix_compress(coo, format);
    gsl_spmatrix_free(coo);
    return c;
}

/* A three-DOF frame with two coupled contacts (J 2 x 3), shaken: set up densely and through
 * each of GSL's storage formats, every state, force and energy after 200 steps is the same
 * double (every setter makes the same CHOLMOD matrices). */
START_TEST(sparse_setters_equal_dense)
{
    static const double M[9] = {2.31, 0.17, 0.0, 0.17, 1.43, -0.08, 0.0, -0.08, 0.87};
    static const double K[9] = {41.3, -17.9, 0.0, -17.9, 29.6, -11.7, 0.0, -11.7, 11.7};
    static const double C[9] = {0.21, -0.05, 0.0, -0.05, 0.13, -0.02, 0.0, -0.02, 0.04};
    static const double J[6] = {1.0, 0.0, 0.0, -1.0, 0.0, 1.0}, mun[2] = {0.437, 0.291};
    static const double r[3] = {1.0, 1.0, 1.0}, ag[4] = {0.0, 3.1, -2.7, 0.4};
    const int formats[3] = {GSL_SPMATRIX_COO, GSL_SPMATRIX_CSC, GSL_SPMATRIX_CSR};
    double ref[8 + 3 * 3 + 2 + 2], got[sizeof ref / sizeof *ref];
    for (int k = -1; k < 3; k++) {
        fricreg_structure *s = make(3, 2);
        if (k < 0) {
            ok(s, fricreg_structure_set_mass(s, 3, M));
            ok(s, fricreg_structure_set_stiffness(s, 3, K));
            ok(s, fricreg_structure_set_damping(s, 3, C));
            ok(s, fricreg_structure_set_contacts(s, 2, 3, J));
        } else {
            gsl_spmatrix *Ms = sparse(M, 3, 3, formats[k]), *Ks = sparse(K, 3, 3, formats[k]);
            gsl_spmatrix *Cs = sparse(C, 3, 3, formats[k]), *Js = sparse(J, 2, 3, formats[k]);
            ok(s, fricreg_structure_set_mass_sparse(s, Ms));
            ok(s, fricreg_structure_set_stiffness_sparse(s, Ks));
            ok(s, fricreg_structure_set_damping_sparse(s, Cs));
            ok(s, fricreg_structure_set_contacts_sparse(s, Js));
            gsl_spmatrix_free(Ms);
            gsl_spmatrix_free(Ks);
            gsl_spmatrix_free(Cs);
            gsl_spmatrix_free(Js);
        }
        ok(s, fricreg_structure_set_bounds(s, 2, mun));
        ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.0213));
        ok(s, fricreg_structure_set_influence(s, 3, r));
        ok(s, fricreg_structure_set_ground_accel(s, 0.0, 0.5, 4, ag));
        ok(s, fricreg_structure_run(s, 0.0137, 200 * 0.0137));
        double *out = k < 0 ? ref : got;
        for (int w = 0; w < 8; w++)
            out[w] = value(s, w);
        ok(s, fricreg_structure_get_state(s, 3, out + 8, out + 11, out + 14));
        ok(s, fricreg_structure_get_forces(s, 2, out + 17));
        ok(s, fricreg_structure_get_dissipation(s, 2, out + 19));
        if (k >= 0)
            for (size_t w = 0; w < sizeof ref / sizeof *ref; w++)
                ck_assert_msg(memcmp(&got[w], &ref[w], sizeof(double)) == 0,
                              "format %d, number %zu: %.17g, dense %.17g", k, w, got[w], ref[w]);
        else
            ck_assert_double_gt(ref[19] * ref[20], 0.0); /* both contacts slid */
        fricreg_structure_free(s);
    }
}
END_TEST

/* How compressed_arrays lays a dense matrix out. */
struct layout {
    int by_columns, flags; /* CSC; enum fricreg_sparse_flags (base and triangle) */
    int split;             /* each entry given as two halves, one after the other (summed) */
};

/* The non-zero entries of a dense row-major rows x cols A as compressed arrays ptr[outer + 1],
 * ind[], val[] (room for 2 rows * cols entries), in the layout asked. */
static void compressed_arrays(const double A[], size_t rows, size_t cols, struct layout l,
                              int64_t ptr[], int64_t ind[], double val[])
{
    int64_t base = (l.flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0, nnz = 0;
    size_t outer = l.by_columns ? cols : rows, inner = l.by_columns ? rows : cols;
    ptr[0] = base;
    for (size_t o = 0; o < outer; o++) {
        for (size_t k = inner; k-- > 0;) { /* descending: unsorted within the row */
            size_t i = l.by_columns ? k : o, j = l.by_columns ? o : k;
            double a = A[i * cols + j];
            if (a == 0.0 || ((l.flags & FRICREG_SPARSE_UPPER) && j < i) ||
                ((l.flags & FRICREG_SPARSE_LOWER) && j > i))
                continue;
            for (int half = 0; half <= l.split; half++) {
                ind[nnz] = (int64_t)k + base;
                val[nnz++] = l.split ? 0.5 * a : a; /* halving is exact: the sum is a */
            }
        }
        ptr[o + 1] = nnz + base;
    }
}

/* The same frame set up through fricreg_structure_set_*_csr and _csc, zero- and one-based,
 * whole and by either triangle, entries unsorted and split into summed duplicates: every state,
 * force and energy after 200 steps is the dense setters' double (both make the same CHOLMOD
 * matrices; a whole symmetric matrix's symmetric part is itself). */
START_TEST(compressed_setters_equal_dense)
{
    static const double M[9] = {2.31, 0.17, 0.0, 0.17, 1.43, -0.08, 0.0, -0.08, 0.87};
    static const double K[9] = {41.3, -17.9, 0.0, -17.9, 29.6, -11.7, 0.0, -11.7, 11.7};
    static const double C[9] = {0.21, -0.05, 0.0, -0.05, 0.13, -0.02, 0.0, -0.02, 0.04};
    static const double J[6] = {1.0, 0.0, 0.0, -1.0, 0.0, 1.0}, mun[2] = {0.437, 0.291};
    static const double r[3] = {1.0, 1.0, 1.0}, ag[4] = {0.0, 3.1, -2.7, 0.4};
    const struct layout layouts[] = {
        {0, 0, 0},
        {1, FRICREG_SPARSE_ONE_BASED, 0},
        {0, FRICREG_SPARSE_UPPER, 1},
        {1, FRICREG_SPARSE_ONE_BASED | FRICREG_SPARSE_LOWER, 0},
        {0, FRICREG_SPARSE_ONE_BASED | FRICREG_SPARSE_LOWER, 1},
        {1, FRICREG_SPARSE_UPPER, 1},
    };
    double ref[8 + 3 * 3 + 2 + 2], got[sizeof ref / sizeof *ref];
    int64_t ptr[4], ind[18];
    double val[18];
    for (int k = -1; k < (int)(sizeof layouts / sizeof *layouts); k++) {
        fricreg_structure *s = make(3, 2);
        if (k < 0) {
            ok(s, fricreg_structure_set_mass(s, 3, M));
            ok(s, fricreg_structure_set_stiffness(s, 3, K));
            ok(s, fricreg_structure_set_damping(s, 3, C));
            ok(s, fricreg_structure_set_contacts(s, 2, 3, J));
        } else {
            struct layout l = layouts[k],
                          lj = {l.by_columns, l.flags & FRICREG_SPARSE_ONE_BASED, l.split};
            int (*set[3])(fricreg_structure *, size_t, int, const int64_t[], const int64_t[],
                          const double[]) = {l.by_columns ? fricreg_structure_set_mass_csc
                                                          : fricreg_structure_set_mass_csr,
                                             l.by_columns ? fricreg_structure_set_stiffness_csc
                                                          : fricreg_structure_set_stiffness_csr,
                                             l.by_columns ? fricreg_structure_set_damping_csc
                                                          : fricreg_structure_set_damping_csr};
            const double *model[3] = {M, K, C};
            for (int w = 0; w < 3; w++) {
                compressed_arrays(model[w], 3, 3, l, ptr, ind, val);
                ok(s, set[w](s, 3, l.flags, ptr, ind, val));
            }
            compressed_arrays(J, 2, 3, lj, ptr, ind, val);
            ok(s, (l.by_columns
                       ? fricreg_structure_set_contacts_csc
                       : fricreg_structure_set_contacts_csr)(s, 2, 3, lj.flags, ptr, ind, val));
        }
        ok(s, fricreg_structure_set_bounds(s, 2, mun));
        ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.0213));
        ok(s, fricreg_structure_set_influence(s, 3, r));
        ok(s, fricreg_structure_set_ground_accel(s, 0.0, 0.5, 4, ag));
        ok(s, fricreg_structure_run(s, 0.0137, 200 * 0.0137));
        double *out = k < 0 ? ref : got;
        for (int w = 0; w < 8; w++)
            out[w] = value(s, w);
        ok(s, fricreg_structure_get_state(s, 3, out + 8, out + 11, out + 14));
        ok(s, fricreg_structure_get_forces(s, 2, out + 17));
        ok(s, fricreg_structure_get_dissipation(s, 2, out + 19));
        if (k >= 0)
            for (size_t w = 0; w < sizeof ref / sizeof *ref; w++)
                ck_assert_msg(memcmp(&got[w], &ref[w], sizeof(double)) == 0,
                              "layout %d, number %zu: %.17g, dense %.17g", k, w, got[w], ref[w]);
        fricreg_structure_free(s);
    }
}
END_TEST

/* A refusal: the code, and a message that starts as given (NULL: none to check). */
static void refused(const fricreg_structure *s, int status, int code, const char *message)
{
    ck_assert_int_eq(status, code);
    const char *got = fricreg_structure_errmsg(s);
    if (message)
        ck_assert_msg(strncmp(got, message, strlen(message)) == 0, "'%s', expected '%s'", got,
                      message);
}

/* Each refusal of a compressed setter: its code, a message that names the array and the
 * entry, and nothing changed (M stays I: the kinetic energy at v0 = (1, 1) stays 1). */
START_TEST(compressed_setters_refuse)
{
    fricreg_structure *s = make(2, 2);
    const double v0[2] = {1.0, 1.0}, u0[2] = {0.0, 0.0};
    ok(s, fricreg_structure_set_initial(s, 2, u0, v0));
    /* rows {0: columns 0, 1; 1: column 1}: [[2, 0.5], [0, 1]], not symmetric */
    const int64_t p[3] = {0, 2, 3}, i[3] = {0, 1, 1}, p1[3] = {1, 3, 4}, i1[3] = {1, 2, 2};
    const double x[3] = {2.0, 0.5, 1.0}, nan1[3] = {2.0, NAN, 1.0}, indef[3] = {1.0, 2.0, 1.0};
    const int64_t from1[3] = {1, 3, 4}, decreasing[3] = {0, 3, 2}, empty_row[3] = {0, 2, 2};
    const int upper = FRICREG_SPARSE_UPPER, one = FRICREG_SPARSE_ONE_BASED;
    refused(s, fricreg_structure_set_mass_csr(NULL, 2, 0, p, i, x), FRICREG_ENULL, NULL);
    refused(s, fricreg_structure_set_mass_csr(s, 2, 0, NULL, i, x), FRICREG_ENULL,
            "set_mass_csr: rowptr is NULL");
    refused(s, fricreg_structure_set_mass_csc(s, 2, 0, p, NULL, x), FRICREG_ENULL,
            "set_mass_csc: rowind is NULL");
    refused(s, fricreg_structure_set_mass_csr(s, 3, 0, p, i, x), FRICREG_ESIZE,
            "set_mass_csr: the matrix is 3 x 3, the structure needs 2 x 2");
    refused(s, fricreg_structure_set_mass_csr(s, 2, 8, p, i, x), FRICREG_EINVAL,
            "set_mass_csr: unknown flags 0x8");
    refused(s, fricreg_structure_set_mass_csr(s, 2, upper | FRICREG_SPARSE_LOWER, p, i, x),
            FRICREG_EINVAL, "set_mass_csr: FRICREG_SPARSE_UPPER and FRICREG_SPARSE_LOWER");
    refused(s, fricreg_structure_set_contacts_csr(s, 2, 2, upper, p, i, x), FRICREG_EINVAL,
            "set_contacts_csr: a triangle flag for a matrix that need not be symmetric");
    refused(s, fricreg_structure_set_mass_csr(s, 2, 0, from1, i, x), FRICREG_EINVAL,
            "set_mass_csr: rowptr[0] = 1 must be 0");
    refused(s, fricreg_structure_set_mass_csr(s, 2, 0, decreasing, i, x), FRICREG_EINVAL,
            "set_mass_csr: rowptr[2] = 2 is below rowptr[1] = 3");
    refused(s, fricreg_structure_set_mass_csr(s, 2, one, p1, i, x), FRICREG_EINVAL,
            "set_mass_csr: colind[0] = 0 is outside 1..2");
    refused(s, fricreg_structure_set_stiffness_csc(s, 2, upper, p, i, x), FRICREG_EINVAL,
            "set_stiffness_csc: entry (1, 0) lies outside the upper triangle given");
    refused(s, fricreg_structure_set_damping_csr(s, 2, 0, p, i, nan1), FRICREG_ENONFINITE,
            "set_damping_csr: val[1] (entry (0, 1)) is not finite");
    refused(s, fricreg_structure_set_stiffness_csr(s, 2, 0, p, i, x), FRICREG_ENOTSYM,
            "set_stiffness_csr: entries (0, 1) = 0.5 and (1, 0) = 0 differ");
    refused(s, fricreg_structure_set_mass_csr(s, 2, one | upper, p1, i1, indef), FRICREG_ENOTPSD,
            "set_mass_csr: the mass matrix is not positive definite");
    refused(s, fricreg_structure_set_contacts_csr(s, 2, 2, 0, empty_row, i, x), FRICREG_EINVAL,
            "set_contacts_csr: row 1 of J is zero");
    ck_assert_double_eq(value(s, FRICREG_SVALUE_KINETIC), 1.0);
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_EINVAL); /* J never set */
    fricreg_structure_free(s);
}
END_TEST

/* Each refusal of a sparse setter: its code, a message named after it, nothing changed. */
START_TEST(sparse_setters_refuse)
{
    static const double A[4] = {1.7, 0.3, 0.2, 0.9}, Z[4] = {1.0, -1.0, 0.0, 0.0};
    fricreg_structure *s = make(2, 2);
    gsl_spmatrix *wrong = gsl_spmatrix_alloc(3, 2), *asym = sparse(A, 2, 2, GSL_SPMATRIX_CSR);
    gsl_spmatrix *zero_row = sparse(Z, 2, 2, GSL_SPMATRIX_COO);
    ck_assert_int_eq(fricreg_structure_set_mass_sparse(NULL, asym), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_mass_sparse(s, NULL), FRICREG_ENULL);
    ck_assert_str_eq(fricreg_structure_errmsg(s), "set_mass_sparse: the matrix is NULL");
    ck_assert_int_eq(fricreg_structure_set_stiffness_sparse(s, wrong), FRICREG_ESIZE);
    ck_assert_str_eq(fricreg_structure_errmsg(s),
                     "set_stiffness_sparse: the matrix is 3 x 2, the structure needs 2 x 2");
    ck_assert_int_eq(fricreg_structure_set_damping_sparse(s, asym), FRICREG_ENOTSYM);
    ck_assert_ptr_nonnull(
        strstr(fricreg_structure_errmsg(s), "set_damping_sparse: entries (0, 1)"));
    ck_assert_int_eq(fricreg_structure_set_contacts_sparse(s, zero_row), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "set_contacts_sparse: row 1 of J"));
    ck_assert_int_eq(fricreg_structure_errcode(s), FRICREG_EINVAL);
    /* Nothing was set: J never was, so a step is refused. */
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_EINVAL);
    gsl_spmatrix_free(wrong);
    gsl_spmatrix_free(asym);
    gsl_spmatrix_free(zero_row);
    fricreg_structure_free(s);
}
END_TEST

/* ---------------------------------------------------------------- errors */

START_TEST(every_error_code)
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(2, 1, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_create(0, 1, &s), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_create(2, 0, &s), FRICREG_EINVAL);
    ck_assert_ptr_null(s);
    s = make(2, 1);
    const double good[4] = {2.0, 0.5, 0.5, 1.0};
    const double asym[4] = {2.0, 0.5, 0.4, 1.0}, indef[4] = {1.0, 2.0, 2.0, 1.0};
    const double nan2[4] = {2.0, NAN, NAN, 1.0};

    ck_assert_int_eq(fricreg_structure_set_mass(NULL, 2, good), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 3, good), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 2, nan2), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 2, asym), FRICREG_ENOTSYM);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "(0, 1)"));
    ck_assert_int_eq(fricreg_structure_errcode(s), FRICREG_ENOTSYM);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 2, indef), FRICREG_ENOTPSD);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "positive definite"));
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 2, asym), FRICREG_ENOTSYM);
    /* symmetry against the rows' scales: a stiff degree of freedom (1e15) beside a soft
     * block (~1) whose coupling is 30% asymmetric, which 1e-12 max|K| = 1e3 let pass */
    const double stiff_soft[9] = {1e15, 0.0, 0.0, 0.0, 3.0, 1.0, 0.0, 1.3, 2.0};
    ck_assert_int_eq(make_sized_and_set(3, stiff_soft), FRICREG_ENOTSYM);
    /* the same units change D K D of a symmetric K (D = 1e-9, 1, 1e9) passes, and so does a
     * K with a rigid-body mode's zero row, and entries that differ by 0.5e-12 of their rows */
    const double scaled[9] = {1e-18 * 4.0, 1e-9 * 1.0, 0.0,       1e-9 * 1.0, 3.0,
                              1e9 * 1.0,   0.0,        1e9 * 1.0, 1e18 * 2.0};
    ck_assert_int_eq(make_sized_and_set(3, scaled), FRICREG_OK);
    const double zero_row[9] = {0.0, 0.0, 0.0, 0.0, 2.0, -1.0, 0.0, -1.0, 2.0};
    ck_assert_int_eq(make_sized_and_set(3, zero_row), FRICREG_OK);
    const double rounding[9] = {2.0, 1.0, 0.0, 1.0 + 1e-12, 2.0, 0.0, 0.0, 0.0, 2.0};
    ck_assert_int_eq(make_sized_and_set(3, rounding), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, 1, good), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, -0.1, 0.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, INFINITY, 0.0), FRICREG_ENONFINITE);

    const double J0[2] = {0.0, 0.0}, J1[2] = {0.3, 1.0};
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 2, 1, J1), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 2, J0), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "row 0"));
    /* J never set: the step refuses, naming set_contacts */
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "set_contacts"));

    const double neg = -1.0, bad_eps = 0.0;
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &neg), FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_structure_errmsg(s), "set_bounds: mun[0] = -1 is negative");
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 2, good), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_set_law(s, 99, 0.01), FRICREG_EINVAL);
    /* the context's message names the function once (it was "set_law: set_law: ...") */
    ck_assert_str_eq(fricreg_structure_errmsg(s), "set_law: unknown law 99");
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, bad_eps), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_influence(s, 2, nan2 + 1), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_structure_set_ground_accel(s, 0.0, 0.01, 1, good), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_ground_accel(s, 0.0, -0.01, 2, good), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_ground_accel(s, 0.0, 0.01, 2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_ground_accel(s, 0.0, 0.01, 2, nan2 + 1),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_structure_set_load(s, 2, good, 0.0, 0.0, 3, good), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_load(s, 1, good, 0.0, 0.0, 0, NULL), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_set_initial(s, 2, good, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_newmark(s, 0.0, 0.5), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_newmark(s, 0.25, 0.4), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_newmark(s, NAN, 0.5), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_structure_set_hht(s, -0.34), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_hht(s, 0.01), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1.0, 10), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-9, 0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_step(s, 0.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_step(s, NAN), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_structure_step(NULL, 0.01), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_run(s, 0.01, 0.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_run(s, 1e-300, 1.0), FRICREG_EINVAL);

    /* getters: status only, the caller's arrays untouched */
    double u[3] = {7.0, 7.0, 7.0}, x = 7.0;
    int64_t c = 7;
    ck_assert_int_eq(fricreg_structure_get_state(s, 3, u, NULL, NULL), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_get_state(s, 2, NULL, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_forces(s, 2, u), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_get_dissipation(s, 2, u), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_SCREEN_DISS_ERR + 1, &x),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_stat(s, 5, &c), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_stat(NULL, 0, &c), FRICREG_ENULL);
    ck_assert(u[0] == 7.0 && u[1] == 7.0 && u[2] == 7.0 && x == 7.0 && c == 7);

    ck_assert_int_eq(fricreg_structure_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_structure_errmsg(NULL), "NULL structure");
    char buf[8];
    size_t len = fricreg_structure_errmsg_copy(s, buf, sizeof buf);
    ck_assert_uint_eq(len, strlen(fricreg_structure_errmsg(s)));
    ck_assert_uint_eq(strlen(buf), 7);
    fricreg_structure_free(s);
    fricreg_structure_free(NULL);
}
END_TEST

/* A refused set_mass in the middle of a run changes nothing: the run goes on exactly as
 * without the call, also where the next step needs M's factor (the rejected matrix was
 * factored in the factor's storage, which must then be refactored from the kept M). */
START_TEST(refused_setter_mid_run_changes_nothing)
{
    const double mun[2] = {1.3, 0.45}, p[2] = {2.9, -0.8};
    const double indefinite[4] = {1.0, 2.0, 2.0, 1.0};
    double u[2][2];
    for (int refuse = 0; refuse < 2; refuse++) {
        fricreg_structure *s = make_two_storeys(mun, FRICREG_LAW_QUINN, 0.01);
        ok(s, fricreg_structure_set_load(s, 2, p, 0.0, 0.0, 0, NULL));
        ok(s, fricreg_structure_run(s, 0.01, 0.5));
        if (refuse)
            ck_assert_int_eq(fricreg_structure_set_mass(s, 2, indefinite), FRICREG_ENOTPSD);
        /* new bounds: the next step solves M a = ... for its start with M's factor */
        ok(s, fricreg_structure_set_bounds(s, 2, mun));
        ok(s, fricreg_structure_run(s, 0.01, 1.0));
        ok(s, fricreg_structure_get_state(s, 2, u[refuse], NULL, NULL));
        fricreg_structure_free(s);
    }
    ck_assert_double_ne(u[0][0], 0.0);
    ck_assert_mem_eq(u[0], u[1], sizeof u[0]);
}
END_TEST

/* Two contacts on one DOF (equal rows of J): W = [[1, 1], [1, 1]] is singular and both stick
 * at rest: their forces are not unique. */
START_TEST(redundant_contacts_are_singular)
{
    fricreg_structure *s = make(1, 2);
    const double J[2] = {1.0, 1.0}, k = 3.1, u0 = 0.2, v0 = 0.0;
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    ok(s, fricreg_structure_set_contacts(s, 2, 1, J));
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_ESINGULAR);
    double t = -1.0;
    ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t), FRICREG_OK);
    ck_assert_double_eq(t, 0.0);
    fricreg_structure_free(s);
}
END_TEST

/* A negative stiffness K = -1e6 N/m (unstable: u grows as exp(1000 t)), no friction, dt =
 * 1e-3 s: the trapezoidal factor (1 + 0.5)/(1 - 0.5) = 3 per step passes 1e100 within 300
 * steps; the run stops there, on the last finite state. */
START_TEST(divergence_is_reported)
{
    fricreg_structure *s = make(1, 1);
    const double k = -1e6, u0 = 1.0, v0 = 0.0;
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    frictionless(s, 1);
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    ck_assert_int_eq(fricreg_structure_run(s, 1e-3, 0.3), FRICREG_EDIVERGED);
    ck_assert_int_eq(fricreg_structure_errcode(s), FRICREG_EDIVERGED);
    double u;
    ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
    ck_assert(isfinite(u) && fabs(u) <= 1e100 && fabs(u) > 1e90);
    fricreg_structure_free(s);
}
END_TEST

/* GSL's implicit steppers that solve I - h c J by GSL's LU (rk1imp, rk2imp, rk4imp, bsimp,
 * msbdf) refuse an unstable structure, whose J has an eigenvalue with a positive real part and
 * so an h where that matrix is singular, which gsl_linalg_LU_solve reports to GSL's handler
 * (the default aborted: fuzz finding, rk4imp with K indefinite). Newmark and the explicit
 * steppers still run it, as does a negative damping with msadams (no LU). */
START_TEST(lu_steppers_refuse_an_unstable_structure)
{
    const int lu[] = {FRICREG_INT_RK1IMP, FRICREG_INT_RK2IMP, FRICREG_INT_RK4IMP, FRICREG_INT_BSIMP,
                      FRICREG_INT_MSBDF};
    const double K[4] = {2.0, 0.0, 0.0, -0.5}, C[4] = {0.1, 0.0, 0.0, -0.2};
    const double u0[2] = {0.01, 0.02}, v0[2] = {0.0, 0.0};
    for (int model = 0; model < 2; model++)
        for (size_t k = 0; k < sizeof lu / sizeof lu[0]; k++) {
            fricreg_structure *s = make(2, 1);
            if (model == 0) { /* indefinite K */
                ok(s, fricreg_structure_set_stiffness(s, 2, K));
            } else { /* negative damping */
                const double Kpos[4] = {2.0, 0.0, 0.0, 0.5};
                ok(s, fricreg_structure_set_stiffness(s, 2, Kpos));
                ok(s, fricreg_structure_set_damping(s, 2, C));
            }
            frictionless(s, 2);
            ok(s, fricreg_structure_set_initial(s, 2, u0, v0));
            ck_assert_int_eq(fricreg_structure_run_ode(s, lu[k], 0.01, 1e-6, 1e-9, 1.0),
                             FRICREG_EINVAL);
            ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "positive semidefinite"));
            ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.01, 0.0, 0.0, 0.1),
                             FRICREG_OK);
            ok(s, fricreg_structure_run(s, 0.01, 0.2));
            fricreg_structure_free(s);
        }
}
END_TEST

/* ---------------------------------------------------------------- long runs: observer, bound */

struct watch {
    fricreg_structure *s;
    int calls, stop_at;
    double last_t, max_force_excess;
    int meddled; /* the status of a setter called from the observer */
};

static int watcher(void *user, double t, size_t ndof, const double u[], const double v[], size_t m,
                   const double f[])
{
    struct watch *w = user;
    (void)u, (void)v;
    ck_assert_uint_eq(ndof, 2);
    ck_assert_uint_eq(m, 2);
    ck_assert_double_gt(t, w->last_t);
    w->last_t = t;
    for (size_t i = 0; i < m; i++) /* the bounds of make_two_storeys' callers: 0.4, 0.3 */
        w->max_force_excess = fmax(w->max_force_excess, fabs(f[i]) - (i == 0 ? 0.4 : 0.3));
    const double mun[2] = {5.0, 5.0};
    w->meddled = fricreg_structure_set_bounds(w->s, 2, mun);
    return ++w->calls == w->stop_at;
}

/* The observer sees every step of run (Newmark) and every GSL step of run_ode, at increasing
 * times, with forces within their bounds; a setter called from it is refused (EINVAL) and
 * changes nothing; asking to stop ends the call with FRICREG_OK at its time: run stops after
 * 7 of 100 steps at t = 7 dt. */
START_TEST(observer_sees_every_step_and_stops_the_run)
{
    const double mun[2] = {0.4, 0.3}, u0[2] = {0.05, 0.08}, v0[2] = {0.0, 0.0};
    fricreg_structure *s = make_two_storeys(mun, FRICREG_LAW_QUINN, 1e-3);
    ok(s, fricreg_structure_set_initial(s, 2, u0, v0));
    struct watch w = {.s = s, .stop_at = -1};
    ok(s, fricreg_structure_set_observer(s, watcher, &w));
    ok(s, fricreg_structure_run(s, 0.01, 1.0));
    ck_assert_int_eq(w.calls, 100);
    ck_assert_int_eq(w.calls, stat(s, FRICREG_SSTAT_STEPS));
    ck_assert_int_eq(w.meddled, FRICREG_EINVAL);
    ck_assert_double_le(w.max_force_excess, 1e-12);
    double f[2];
    ok(s, fricreg_structure_get_forces(s, 2, f));
    ck_assert_double_le(fabs(f[0]), 0.4 + 1e-12); /* the bounds were not changed */

    int64_t before = stat(s, FRICREG_SSTAT_STEPS);
    w = (struct watch){.s = s, .stop_at = 25, .last_t = 1.0};
    ok(s, fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.001, 0.0, 0.0, 2.0));
    ck_assert_int_eq(w.calls, 25);
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_STEPS) - before, 2 * 25); /* rk4: 2 a GSL step */
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_TIME), 1.0 + 25 * 0.002, 1e-12);

    w = (struct watch){.s = s, .stop_at = 7, .last_t = 0.0};
    ok(s, fricreg_structure_set_initial(s, 2, u0, v0));
    ok(s, fricreg_structure_run(s, 0.01, 1.0));
    ck_assert_int_eq(w.calls, 7);
    ck_assert_double_eq_tol(value(s, FRICREG_SVALUE_TIME), 0.07, 1e-15);
    ok(s, fricreg_structure_set_observer(s, NULL, NULL));
    ck_assert_int_eq(fricreg_structure_set_observer(NULL, NULL, NULL), FRICREG_ENULL);
    fricreg_structure_free(s);
}
END_TEST

/* Everything a getter shows: t, u, v, a, f, D, the energies and the counters. */
struct shown {
    double u[2], v[2], a[2], f[2], D[2], value[8];
    int64_t stat[5];
};

static void show(const fricreg_structure *s, size_t n, size_t m, struct shown *w)
{
    memset(w, 0, sizeof *w);
    ok((fricreg_structure *)s, fricreg_structure_get_state(s, n, w->u, w->v, w->a));
    ok((fricreg_structure *)s, fricreg_structure_get_forces(s, m, w->f));
    ok((fricreg_structure *)s, fricreg_structure_get_dissipation(s, m, w->D));
    for (int k = 0; k < 8; k++)
        w->value[k] = value(s, k);
    for (int k = 0; k < 5; k++)
        w->stat[k] = stat(s, k);
}

/* A refused or failed step shows nothing of what it did (fuzz findings, fuzz_structure):
 *  - a first step after set_initial computes the acceleration and the forces at t = 0 before
 *    it is refused: SDOF m = 1, k = 2.385, p = 1.7, u0 = 0.1, mun = 0.3, law (4) eps = 1e-3,
 *    central difference at dt = 1 (dt lambda = 600 > 0.9: FRICREG_ESTEP). The equilibrium is
 *    f = -0.3, a = 1.7 - 0.2385 - 0.3 = 1.1615; a and f showed it (and INITIAL the energy at
 *    t = 0), where the header promises the state of before: a = f = 0;
 *  - a Newmark step that diverges (M = 1, a load p = 1e130, dt = 1: u1 = p/4 beyond 1e100);
 *  - a Newmark step refused because K_eff = M + gamma dt C + beta dt^2 K is not positive
 *    definite (k = -1e130, dt = 1: 1 - 2.5e129). */
START_TEST(failed_step_changes_nothing)
{
    const double k = 2.385, p = 1.7, mun = 0.3, u0 = 0.1, v0 = 0.0;
    fricreg_structure *s = make(1, 1);
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    frictionless(s, 1);
    ok(s, fricreg_structure_set_bounds(s, 1, &mun));
    ok(s, fricreg_structure_set_load(s, 1, &p, 0.0, 0.0, 0, NULL));
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    ok(s, fricreg_structure_set_central_difference(s));
    struct shown before, after;
    show(s, 1, 1, &before);
    ck_assert_int_eq(fricreg_structure_step(s, 1.0), FRICREG_ESTEP);
    show(s, 1, 1, &after);
    ck_assert_mem_eq(&before, &after, sizeof before);
    ck_assert_double_eq(after.a[0], 0.0);
    /* the step that passes computes the same equilibrium */
    ok(s, fricreg_structure_step(s, 1e-4));
    ck_assert_double_eq(value(s, FRICREG_SVALUE_INITIAL), 0.5 * k * u0 * u0);
    fricreg_structure_free(s);

    const double huge = 1e130, unstable = -1e130, one = 1.0;
    s = make(1, 1);
    ok(s, fricreg_structure_set_load(s, 1, &huge, 0.0, 0.0, 0, NULL));
    ok(s, fricreg_structure_set_contacts(s, 1, 1, &one));
    ok(s, fricreg_structure_set_initial(s, 1, &one, &v0));
    show(s, 1, 1, &before);
    ck_assert_int_eq(fricreg_structure_run(s, 1.0, 21.0), FRICREG_EDIVERGED);
    show(s, 1, 1, &after);
    ck_assert_mem_eq(&before, &after, sizeof before);
    const double zero = 0.0;
    ok(s, fricreg_structure_set_load(s, 1, &zero, 0.0, 0.0, 0, NULL));
    ok(s, fricreg_structure_set_stiffness(s, 1, &unstable));
    show(s, 1, 1, &before);
    ck_assert_int_eq(fricreg_structure_step(s, 1.0), FRICREG_ENOTPSD);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "K_eff"));
    show(s, 1, 1, &after);
    ck_assert_mem_eq(&before, &after, sizeof before);
    fricreg_structure_free(s);
}
END_TEST

/* run_ode's adaptive steps are bounded per call (fricreg_structure_set_max_steps, 10^6 by
 * default): Coulomb's law under rkf45 shrinks its steps without end at the first stick, and
 * with the bound at 2000 the call returns FRICREG_EWORK, naming the law's jump, after exactly
 * 2000 accepted steps, its state finite; law (4) at the same tolerances finishes 0.5 s in fewer
 * than 2000; negative bounds are refused. */
START_TEST(run_ode_adaptive_steps_are_bounded)
{
    const double mun[2] = {0.4, 0.3}, u0[2] = {0.05, 0.08}, v0[2] = {0.0, 0.0};
    fricreg_structure *s = make_two_storeys(mun, FRICREG_LAW_COULOMB, 1e-3);
    ok(s, fricreg_structure_set_initial(s, 2, u0, v0));
    ck_assert_int_eq(fricreg_structure_set_max_steps(s, -1), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_max_steps(NULL, 1), FRICREG_ENULL);
    ok(s, fricreg_structure_set_max_steps(s, 2000));
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 1e-3, 1e-6, 1e-8, 2.0),
                     FRICREG_EWORK);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "jump at zdot = 0"));
    ck_assert_int_eq(stat(s, FRICREG_SSTAT_STEPS), 2000);
    double u[2], v[2];
    ok(s, fricreg_structure_get_state(s, 2, u, v, NULL));
    ck_assert(isfinite(u[0]) && isfinite(u[1]) && isfinite(v[0]) && isfinite(v[1]));
    ck_assert_double_lt(value(s, FRICREG_SVALUE_TIME), 2.0);

    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 1e-2));
    ok(s, fricreg_structure_set_initial(s, 2, u0, v0));
    ok(s, fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 1e-3, 1e-6, 1e-8, 0.5));
    ck_assert_int_lt(stat(s, FRICREG_SSTAT_STEPS), 2000);
    fricreg_structure_free(s);
}
END_TEST

/* run_ode's failures (fuzz findings, fuzz_structure):
 *  - one that fails after accepted steps leaves the state of the last one, but the
 *    acceleration and forces were those of the run's start: an unstable spring k = -9.7 under
 *    a load p = 0.23 from u0 = 0.1 (-k u0 + p = 1.2 beyond mun = 0.41: it slides, law (4) with
 *    eps = 0.05), RK4 at dt = 0.05 diverges (EDIVERGED, u beyond 1e90 near t = 74); at the
 *    state reached, a = p - k u + f (M = 1, J = 1) must hold, with f = -mun sgn(v);
 *  - one that fails at its first step (two equal rows of J sticking at rest, k = 3.1:
 *    ESINGULAR) started the energy balance: INITIAL showed the energy at t = 0, where nothing
 *    may change. */
START_TEST(run_ode_failure_state)
{
    const double k = -9.7, p = 0.23, mun = 0.41, u0 = 0.1, v0 = 0.0, one = 1.0;
    fricreg_structure *s = make(1, 1);
    ok(s, fricreg_structure_set_stiffness(s, 1, &k));
    ok(s, fricreg_structure_set_contacts(s, 1, 1, &one));
    ok(s, fricreg_structure_set_bounds(s, 1, &mun));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.05));
    ok(s, fricreg_structure_set_load(s, 1, &p, 0.0, 0.0, 0, NULL));
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.05, 0.0, 0.0, 200.0),
                     FRICREG_EDIVERGED);
    double u, v, a, f;
    ok(s, fricreg_structure_get_state(s, 1, &u, &v, &a));
    ok(s, fricreg_structure_get_forces(s, 1, &f));
    ck_assert(value(s, FRICREG_SVALUE_TIME) > 1.0 && fabs(u) > 1e90 && fabs(u) <= 1e100);
    ck_assert(fabs(f) <= mun && f != 0.0);
    ck_assert_double_eq_tol(a, p - k * u + f, 1e-15 * fabs(k * u));
    fricreg_structure_free(s);

    const double J[2] = {1.0, 1.0}, kpos = 3.1;
    s = make(1, 2);
    ok(s, fricreg_structure_set_stiffness(s, 1, &kpos));
    ok(s, fricreg_structure_set_contacts(s, 2, 1, J));
    ok(s, fricreg_structure_set_initial(s, 1, &u0, &v0));
    struct shown before, after;
    show(s, 1, 2, &before);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 1e-4, 0.0, 0.0, 0.01),
                     FRICREG_ESINGULAR);
    show(s, 1, 2, &after);
    ck_assert_mem_eq(&before, &after, sizeof before);
    fricreg_structure_free(s);
}
END_TEST

/* J and M of scales too far apart (fuzz finding, fuzz_structure): W = J M^-1 J^T overflowed
 * (M = 1e-310 beside J = 1) and the step returned FRICREG_ENONFINITE, documented for a dt that
 * is not finite; W_ii underflowed to 0 (M = 1 beside J = 1e-200): FRICREG_EINVAL naming the
 * context's argument w[0]. Both are now FRICREG_EINVAL naming the contact and W_ii. */
START_TEST(coupling_out_of_range)
{
    const double tiny = 1e-310, one = 1.0, small = 1e-200;
    fricreg_structure *s = make(1, 1);
    ok(s, fricreg_structure_set_mass(s, 1, &tiny));
    ok(s, fricreg_structure_set_contacts(s, 1, 1, &one));
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "contact 0's W_ii = inf"));
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.01, 0.0, 0.0, 1.0),
                     FRICREG_EINVAL);
    ok(s, fricreg_structure_set_mass(s, 1, &one));
    ok(s, fricreg_structure_set_contacts(s, 1, 1, &small));
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "below DBL_MIN"));
    ok(s, fricreg_structure_set_contacts(s, 1, 1, &one));
    ok(s, fricreg_structure_step(s, 0.01));
    fricreg_structure_free(s);
}
END_TEST

/* A load p = DBL_MAX held at rest by a bound mun = DBL_MAX (fuzz finding, fuzz_structure): the
 * trapezoid's (f + f1)/2 and (p~ + p~1)/2 overflowed, and 0 * Inf made the dissipation and the
 * input NaN with FRICREG_OK. Both are 0: nothing moved. */
START_TEST(extreme_forces_at_rest)
{
    const double big = DBL_MAX;
    fricreg_structure *s = make(1, 1);
    frictionless(s, 1);
    ok(s, fricreg_structure_set_bounds(s, 1, &big));
    ok(s, fricreg_structure_set_load(s, 1, &big, 0.0, 0.0, 0, NULL));
    ok(s, fricreg_structure_step(s, 0.01));
    double u, f, D;
    ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
    ok(s, fricreg_structure_get_forces(s, 1, &f));
    ok(s, fricreg_structure_get_dissipation(s, 1, &D));
    ck_assert_double_eq(u, 0.0);
    ck_assert_double_eq(f, -DBL_MAX);
    ck_assert_double_eq(D, 0.0);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_INPUT), 0.0);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_FRICTION), 0.0);
    fricreg_structure_free(s);
}
END_TEST

/* GSL's symmetric eigensolver has no iteration cap: the step guard's L^-1 K L^-T (M = I) of
 * K = [[3490, 3490, 0], [3490, 3490, -DBL_MAX], [0, -DBL_MAX, 0]] never returned (fuzz finding,
 * fuzz_structure: run_ode with fixed RK4). The structure's eigen-solves now scale the matrix
 * by a power of two first and refuse Inf and NaN (fr_eigen_symm, base/eigen.c, as the
 * contexts' did): omega_max is +Inf and the step is refused (FRICREG_ESTEP), GSL's LU
 * steppers too (stability unknown: FRICREG_EINVAL), and Newmark refuses the step (K_eff = M +
 * beta dt^2 K is not positive definite: FRICREG_ENOTPSD). set_mass's
 * check goes the same way: M_01 = 1e300 beside M_00 = M_11 = 1e-300 (D^-1/2 M D^-1/2 infinite)
 * is FRICREG_ENOTPSD. */
START_TEST(eigen_solves_of_extreme_models)
{
    const double K[9] = {3490.0, 3490.0, 0.0, 3490.0, 3490.0, -DBL_MAX, 0.0, -DBL_MAX, 0.0};
    const double J[3] = {1.0, 0.0, 0.0}, u0[3] = {0.0, 0.0, 0.0}, v0[3] = {0.0, 0.0, 0.0};
    fricreg_structure *s = make(3, 1);
    ok(s, fricreg_structure_set_stiffness(s, 3, K));
    ok(s, fricreg_structure_set_contacts(s, 1, 3, J));
    ok(s, fricreg_structure_set_initial(s, 3, u0, v0));
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.01, 0.0, 0.0, 1.0),
                     FRICREG_ESTEP);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4IMP, 0.01, 0.0, 0.0, 1.0),
                     FRICREG_EINVAL); /* stability not known: GSL's LU steppers refused */
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_ENOTPSD); /* K_eff indefinite */
    const double M[9] = {1e-300, 1e300, 0.0, 1e300, 1e-300, 0.0, 0.0, 0.0, 1.0};
    ck_assert_int_eq(fricreg_structure_set_mass(s, 3, M), FRICREG_ENOTPSD);
    fricreg_structure_free(s);
}
END_TEST

/* run_ode with a fixed bsimp step on two coupled DOFs (K = [[1, 0.5], [0.5, 1]]) from
 * u0 = (1, 1e-300): every step met bsimp's runaway test (the second DOF's change beside its
 * 1e-300), which GSL reports only by yerr = +Inf, and the run returned FRICREG_OK with u frozen
 * at u0 after 100 steps (from u0 = (1, 0) it ends at (0.5497, -0.2105)). Found while reducing a
 * fuzz finding (an adaptive bsimp run that never ended). The run now fails, nothing moved. */
START_TEST(bsimp_fixed_step_does_not_freeze)
{
    const double K[4] = {1.0, 0.5, 0.5, 1.0}, u0[2] = {1.0, 1e-300}, v0[2] = {0.0, 0.0};
    fricreg_structure *s = make(2, 1);
    ok(s, fricreg_structure_set_stiffness(s, 2, K));
    frictionless(s, 2);
    ok(s, fricreg_structure_set_initial(s, 2, u0, v0));
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_BSIMP, 0.01, 0.0, 0.0, 1.0),
                     FRICREG_EINTEGRATOR);
    double u[2];
    ok(s, fricreg_structure_get_state(s, 2, u, NULL, NULL));
    ck_assert_double_eq(value(s, FRICREG_SVALUE_TIME), 0.0);
    ck_assert_mem_eq(u, u0, sizeof u);
    fricreg_structure_free(s);
}
END_TEST

static Suite *structure_suite(void)
{
    Suite *suite = suite_create("structure");
    TCase *linear = tcase_create("linear");
    tcase_add_test(linear, newmark_sdof_period_and_energy);
    tcase_add_test(linear, run_to_each_sample_time_is_one_step);
    tcase_add_loop_test(linear, newmark_two_dof_modal, 0, 2);
    tcase_add_test(linear, hht_second_order_and_dissipative);
    tcase_add_test(linear, newmark_general_beta_gamma);
    tcase_add_test(linear, central_difference_sdof_and_bound);
    suite_add_tcase(suite, linear);
    TCase *friction = tcase_create("friction");
    tcase_add_test(friction, oscillator_unforced_sticks_at_rest_position);
    tcase_add_test(friction, oscillator_forced_dissipation_matches_exact);
    tcase_add_test(friction, coupled_contacts_hold_a_static_load);
    tcase_add_loop_test(friction, coupled_contacts_shaken, 0, 2);
    tcase_add_test(friction, many_coupled_contacts_obey_the_law);
    tcase_add_loop_test(friction, every_law_on_coupled_contacts, FRICREG_LAW_COULOMB,
                        FRICREG_LAW_QUINN + 1);
    tcase_add_test(friction, ground_motion_step_by_step);
    tcase_add_test(friction, default_influence_moves_every_dof_with_the_ground);
    tcase_add_test(friction, building_newton_at_small_eps);
    tcase_add_test(friction, sparse_setters_equal_dense);
    tcase_add_test(friction, compressed_setters_equal_dense);
    tcase_add_test(friction, central_difference_oscillator);
    suite_add_tcase(suite, friction);
    TCase *ode = tcase_create("run_ode");
    tcase_add_test(ode, run_ode_reproduces_the_oscillator_driver);
    tcase_add_test(ode, run_ode_reproduces_the_chain_driver);
    tcase_add_loop_test(ode, run_ode_adaptive_then_newmark, 0, 2);
    suite_add_tcase(suite, ode);
    TCase *bld = tcase_create("building");
    tcase_add_loop_test(bld, building_newmark_and_hht, 0, 2);
    suite_add_tcase(suite, bld);
    TCase *errors = tcase_create("errors");
    tcase_add_test(errors, every_error_code);
    tcase_add_test(errors, sparse_setters_refuse);
    tcase_add_test(errors, compressed_setters_refuse);
    tcase_add_test(errors, redundant_contacts_are_singular);
    tcase_add_test(errors, refused_setter_mid_run_changes_nothing);
    tcase_add_test(errors, divergence_is_reported);
    tcase_add_test(errors, lu_steppers_refuse_an_unstable_structure);
    tcase_add_test(errors, observer_sees_every_step_and_stops_the_run);
    tcase_add_test(errors, run_ode_adaptive_steps_are_bounded);
    tcase_add_test(errors, failed_step_changes_nothing);
    tcase_add_test(errors, run_ode_failure_state);
    tcase_add_test(errors, coupling_out_of_range);
    tcase_add_test(errors, extreme_forces_at_rest);
    tcase_add_test(errors, eigen_solves_of_extreme_models);
    tcase_add_test(errors, bsimp_fixed_step_does_not_freeze);
    suite_add_tcase(suite, errors);
    return suite;
}

int main(void)
{
    SRunner *runner = srunner_create(structure_suite());
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
