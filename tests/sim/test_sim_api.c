/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_sim_api.c — the contract of fricreg_sim.h: every error path, the step checks, the
 * observer, integrator names, and every GSL stepper on the paper's oscillator case.
 *
 * Error checks use a fresh simulation each, so errcode and errmsg can only come from the
 * failing call itself (a new simulation has errcode FRICREG_OK and errmsg ""). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_sim.h"

#define PI 3.14159265358979323846

static fricreg_sim *make(int system)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(system, &sim), FRICREG_OK);
    ck_assert_ptr_nonnull(sim);
    ck_assert_int_eq(fricreg_sim_errcode(sim), FRICREG_OK);
    ck_assert_str_eq(fricreg_sim_errmsg(sim), "");
    return sim;
}

/* The call returned `code`, and the simulation recorded it with a message. */
static void expect_failure(const fricreg_sim *sim, int status, int code)
{
    ck_assert_int_eq(status, code);
    ck_assert_int_eq(fricreg_sim_errcode(sim), code);
    ck_assert_str_ne(fricreg_sim_errmsg(sim), "");
}

static double value(const fricreg_sim *sim, int which)
{
    double out = NAN;
    ck_assert_int_eq(fricreg_sim_get_value(sim, which, &out), FRICREG_OK);
    return out;
}

/* ---- create and NULL handles --------------------------------------------------------------- */

/* Header: FRICREG_EINVAL for an unknown system (valid: 1, 2, 3), FRICREG_ENULL for out NULL;
 * out is written only on success. */
START_TEST(test_create_rejects_unknown_system_and_null_out)
{
    static const int bad[] = {0, 4, -1, 1000};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        fricreg_sim *sim = NULL;
        ck_assert_int_eq(fricreg_sim_create(bad[k], &sim), FRICREG_EINVAL);
        ck_assert_ptr_null(sim);
    }
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, NULL), FRICREG_ENULL);
}
END_TEST

/* Every function taking a simulation answers FRICREG_ENULL (or its documented neutral value)
 * for a NULL one, and free(NULL) does nothing. */
START_TEST(test_null_simulation_is_rejected_everywhere)
{
    double x = 0.0, v = 0.0, d = 0.0;
    ck_assert_int_eq(fricreg_sim_set_param(NULL, FRICREG_PARAM_A, 1.0), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_set_law(NULL, FRICREG_LAW_QUINN, 0.0), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_set_integrator(NULL, FRICREG_INT_RK4, 0.01, 0.0, 0.0),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_set_observer(NULL, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_set_max_steps(NULL, 10), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_run(NULL, 1.0), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_run_cycles(NULL, 1), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_value(NULL, FRICREG_VALUE_TIME, &d), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_param(NULL, FRICREG_PARAM_A, &d), FRICREG_ENULL);
    int64_t count = 0;
    ck_assert_int_eq(fricreg_sim_get_stat(NULL, FRICREG_SIM_STAT_STEPS, &count), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_state(NULL, 1, &x, &v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_dissipation(NULL, 1, &d), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(NULL, 1, &d), FRICREG_ENULL);
    ck_assert_uint_eq(fricreg_sim_ndof(NULL), 0);
    ck_assert_uint_eq(fricreg_sim_ncontacts(NULL), 0);
    ck_assert_int_eq(fricreg_sim_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_sim_errmsg(NULL), "NULL simulation");
    fricreg_sim_free(NULL);
}
END_TEST

/* ---- set_param ----------------------------------------------------------------------------- */

struct bad_param {
    int system, param;
    double value;
    int code;
};

/* Header, enum fricreg_param: which system reads which parameter and its valid range. */
static const struct bad_param bad_params[] = {
    {FRICREG_SYSTEM_OSCILLATOR, 99, 1.0, FRICREG_EINVAL},                /* unknown parameter */
    {FRICREG_SYSTEM_OSCILLATOR, 0, 1.0, FRICREG_EINVAL},                 /* unknown parameter */
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_K, 2.385, FRICREG_EINVAL},      /* twoblock's */
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_MUN, 1.5, FRICREG_EINVAL},      /* oscillator's */
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_N, 8.0, FRICREG_EINVAL},   /* chain's */
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_X0, 0.3, FRICREG_EINVAL},    /* oscillator's */
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_OMEGA, 0.7, FRICREG_EINVAL}, /* belt_omega there */
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_OMEGA, 0.0, FRICREG_EINVAL},
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_OMEGA, -0.5, FRICREG_EINVAL},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_BELT_OMEGA, 0.0, FRICREG_EINVAL},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_K, -2.0, FRICREG_EINVAL},
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_MUN, -0.1, FRICREG_EINVAL},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_MU1, -0.1, FRICREG_EINVAL},
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_N, 1.0, FRICREG_EINVAL},       /* n >= 2 */
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_N, 2.5, FRICREG_EINVAL},       /* an integer */
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_N, 1e7 + 1.0, FRICREG_EINVAL}, /* n <= 10^7 */
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_A, NAN, FRICREG_ENONFINITE},
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_X0, INFINITY, FRICREG_ENONFINITE},
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_N, NAN, FRICREG_ENONFINITE},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_BELT_AMP, -INFINITY, FRICREG_ENONFINITE},
};

START_TEST(test_set_param_rejects_bad_parameter)
{
    const struct bad_param *b = &bad_params[_i];
    fricreg_sim *sim = make(b->system);
    expect_failure(sim, fricreg_sim_set_param(sim, b->param, b->value), b->code);
    fricreg_sim_free(sim);
}
END_TEST

/* The message names the parameter by its symbol, the value and the rule it breaks, or the
 * system that does not read it (the CLI shows the part after "= "). */
START_TEST(test_set_param_message_names_parameter_and_rule)
{
    static const struct {
        int system, param;
        double value;
        const char *msg;
    } cases[] = {
        {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_OMEGA, -0.5, "set_param: omega = -0.5 must be > 0"},
        {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_N, 2.5,
         "set_param: n = 2.5 must be an integer from 2 to 10^7"},
        {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_MU2, -0.25, "set_param: mu2 = -0.25 must be >= 0"},
        {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_K, 2.385,
         "set_param: k = 2.385 is not a parameter of the chain"},
        {FRICREG_SYSTEM_OSCILLATOR, 99, 2.385,
         "set_param: parameter 99 = 2.385 is not a known parameter"},
        {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_X0, INFINITY,
         "set_param: x0 = inf is not finite"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        fricreg_sim *sim = make(cases[k].system);
        ck_assert_int_ne(fricreg_sim_set_param(sim, cases[k].param, cases[k].value), FRICREG_OK);
        ck_assert_str_eq(fricreg_sim_errmsg(sim), cases[k].msg);
        fricreg_sim_free(sim);
    }
}
END_TEST

/* A rejected value changes nothing: the chain keeps n = 32 and period 2 pi/0.5. */
START_TEST(test_failed_set_param_keeps_parameters)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_CHAIN);
    expect_failure(sim, fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, -0.5), FRICREG_EINVAL);
    expect_failure(sim, fricreg_sim_set_param(sim, FRICREG_PARAM_N, 2.5), FRICREG_EINVAL);
    ck_assert_uint_eq(fricreg_sim_ndof(sim), 32);
    ck_assert_double_eq_tol(value(sim, FRICREG_VALUE_PERIOD), 4.0 * PI, 1e-14);
    double n = 0.0, omega = 0.0;
    ck_assert_int_eq(fricreg_sim_get_param(sim, FRICREG_PARAM_N, &n), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_param(sim, FRICREG_PARAM_OMEGA, &omega), FRICREG_OK);
    ck_assert_double_eq(n, 32.0);
    ck_assert_double_eq(omega, 0.5);
    fricreg_sim_free(sim);
}
END_TEST

/* ---- set_law and set_integrator ------------------------------------------------------------ */

/* Header: FRICREG_EINVAL for an unknown law (valid 1 … 6) or eps < 0; FRICREG_ENONFINITE. A
 * rejected call keeps eps at the paper's rule, 2 dt = 0.02. */
START_TEST(test_set_law_rejects_bad_law_and_eps)
{
    static const struct {
        int law;
        double eps;
        int code;
    } bad[] = {
        {0, 0.0, FRICREG_EINVAL},
        {7, 0.0, FRICREG_EINVAL},
        {FRICREG_LAW_QUINN, -0.01, FRICREG_EINVAL},
        {FRICREG_LAW_QUINN, NAN, FRICREG_ENONFINITE},
        {FRICREG_LAW_TANH, INFINITY, FRICREG_ENONFINITE},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
        expect_failure(sim, fricreg_sim_set_law(sim, bad[k].law, bad[k].eps), bad[k].code);
        ck_assert_double_eq_tol(value(sim, FRICREG_VALUE_EPS), 0.02, 1e-16);
        fricreg_sim_free(sim);
    }
}
END_TEST

/* Header: FRICREG_EINVAL for an unknown integrator (valid 1 … 12), dt <= 0, rtol < 0 or
 * atol < 0; FRICREG_ENONFINITE. A rejected call keeps dt = 0.01. */
START_TEST(test_set_integrator_rejects_bad_settings)
{
    static const struct {
        int integ;
        double dt, rtol, atol;
        int code;
    } bad[] = {
        {0, 0.01, 0.0, 0.0, FRICREG_EINVAL},
        {15, 0.01, 0.0, 0.0, FRICREG_EINVAL},
        {FRICREG_INT_CENTRAL_IMEX, 0.01, 0.0, 1e-8, FRICREG_EINVAL}, /* fixed steps only */
        {FRICREG_INT_CENTRAL, 0.01, 1e-6, 0.0, FRICREG_EINVAL},      /* fixed steps only */
        {FRICREG_INT_RK4, 0.0, 0.0, 0.0, FRICREG_EINVAL},
        {FRICREG_INT_RK4, -0.01, 0.0, 0.0, FRICREG_EINVAL},
        {FRICREG_INT_RKF45, 0.01, -1e-6, 1e-8, FRICREG_EINVAL},
        {FRICREG_INT_RKF45, 0.01, 1e-6, -1e-8, FRICREG_EINVAL},
        {FRICREG_INT_RK4, INFINITY, 0.0, 0.0, FRICREG_ENONFINITE},
        {FRICREG_INT_RK4, NAN, 0.0, 0.0, FRICREG_ENONFINITE},
        {FRICREG_INT_RKF45, 0.01, INFINITY, 1e-8, FRICREG_ENONFINITE},
        {FRICREG_INT_RKF45, 0.01, 1e-6, NAN, FRICREG_ENONFINITE},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
        int status = fricreg_sim_set_integrator(sim, bad[k].integ, bad[k].dt, bad[k].rtol,
                                                bad[k].atol);
        expect_failure(sim, status, bad[k].code);
        ck_assert_double_eq_tol(value(sim, FRICREG_VALUE_DT), 0.01, 1e-17);
        fricreg_sim_free(sim);
    }
}
END_TEST

/* ---- run ----------------------------------------------------------------------------------- */

/* Header: FRICREG_EINVAL if t_end <= 0 or more than 2^31 steps; FRICREG_ENONFINITE for a
 * NaN or infinite t_end; run_cycles needs cycles >= 1. (dt = 1e-9 to t = 10 is 5e9 GSL steps
 * of 2 dt.) */
START_TEST(test_run_rejects_bad_end_time)
{
    static const struct {
        double t_end;
        int code;
    } bad[] = {
        {0.0, FRICREG_EINVAL},
        {-2.385, FRICREG_EINVAL},
        {NAN, FRICREG_ENONFINITE},
        {INFINITY, FRICREG_ENONFINITE},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
        expect_failure(sim, fricreg_sim_run(sim, bad[k].t_end), bad[k].code);
        fricreg_sim_free(sim);
    }
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 1e-9, 0.0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_COULOMB, 0.0), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run(sim, 10.0), FRICREG_EINVAL);
    /* Adaptive steps have no step count to bound, but 1e300 spans more than 10^9 cycles. */
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.01, 1e-6, 1e-8),
                     FRICREG_OK);
    expect_failure(sim, fricreg_sim_run(sim, 1e300), FRICREG_EINVAL);
    fricreg_sim_free(sim);
}
END_TEST

START_TEST(test_run_cycles_rejects_fewer_than_one)
{
    static const int bad[] = {0, -3};
    for (size_t k = 0; k < 2; k++) {
        fricreg_sim *sim = make(FRICREG_SYSTEM_CHAIN);
        expect_failure(sim, fricreg_sim_run_cycles(sim, bad[k]), FRICREG_EINVAL);
        fricreg_sim_free(sim);
    }
}
END_TEST

/* Sec. 3.1.1: in the stick zone of (4) a contact decays at lambda = W_ii 2 mun/eps; RK4's
 * real-axis bound is 2.78. Oscillator, eps = 0.02, dt = 0.05: dt lambda = 5 > 2.78. The message
 * names the stick zone, dt and lambda = 100. */
START_TEST(test_too_large_step_is_estep_naming_the_stick_zone)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.05, 0.0, 0.0), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run(sim, 20.0), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "stick zone"));
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "stiffness 100 "));
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "dt"));
    fricreg_sim_free(sim);
}
END_TEST

/* A stick-zone stiffness beyond the double range (mun = 1e300, eps = 1e-300: lambda = 2e600)
 * has no step and no eps to name ("reduce dt to 0 or raise eps to inf" before): the message
 * says to lower the bounds or raise eps. */
START_TEST(test_overflowing_stick_zone_names_bounds_and_eps)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_MUN, 1e300), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 1e-300), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.01, 0.0, 0.0), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run(sim, 1.0), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "beyond the double range"));
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "raise eps"));
    ck_assert_ptr_null(strstr(fricreg_sim_errmsg(sim), "inf"));
    fricreg_sim_free(sim);
}
END_TEST

/* The same check with coupled contacts under the consistent law uses W_ii: two blocks,
 * eps = 0.02, dt = 0.03, mu2 = 0.6: contact 0 has lambda = 1 * 2 * 0.5/0.02 = 50
 * (dt lambda = 1.5), contact 1 has lambda = 2 * 2 * 0.6/0.02 = 120 (dt lambda = 3.6 > 2.78). */
START_TEST(test_estep_uses_the_coupling_diagonal)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_TWOBLOCK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_MU2, 0.6), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.03, 0.0, 0.0), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run_cycles(sim, 1), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "stiffness 120 "));
    fricreg_sim_free(sim);
}
END_TEST

/* Under the paper's partition the stick zone of coupled contacts is stiffer than its diagonal
 * (shared/spec/coupled.md): two blocks, mun = (10, 5), eps = 0.02, RK4 dt = 0.0025. Consistent:
 * lambda = max W_ii 2 mun_i/eps = 1000, dt lambda = 2.5 <= 2.78, accepted; paper's:
 * lambda = 1000 (1 + 1/sqrt 2) = 1707.1, dt lambda = 4.27, refused. */
START_TEST(test_estep_paper_partition_sees_the_coupling)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_TWOBLOCK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_MU1, 10.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_MU2, 5.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.0025, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_partition(sim, FRICREG_PARTITION_PAPER), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run(sim, 0.1), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "stiffness 1707.1"));
    ck_assert_int_eq(fricreg_sim_set_partition(sim, FRICREG_PARTITION_CONSISTENT), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run(sim, 0.1), FRICREG_OK);
    expect_failure(sim, fricreg_sim_set_partition(sim, 99), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_set_partition(NULL, FRICREG_PARTITION_PAPER), FRICREG_ENULL);
    fricreg_sim_free(sim);
}
END_TEST

/* A spring mode too fast for the step: chain n = 32 under (3) (its stick-zone stiffness
 * mun/eps = 1/(5 dt) under the paper's rule eps = 10 omega dt: dt*lambda = 0.2). The highest
 * spring mode is below 2n = 64 rad/s. RKF45 with dt = 0.012: 64 * 0.012 = 0.768 exceeds its
 * imaginary-axis bound 0.7; RK4 with dt = 0.06: 3.84 exceeds its 2.82 (2 sqrt 2 = 2.83). Both
 * refused before the run, naming the frequency (RK4 used to run and overflow: FRICREG_EDIVERGED
 * at t = 23.6). RK4 with dt = 0.02 (1.28) is within its bound but beyond dt*omega = 1/sqrt 2,
 * where a friction reversal within one step can put energy in: refused, saying so. */
START_TEST(test_spring_mode_too_fast_is_estep)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_CHAIN);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_VELOCITY_LIMITED, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.06, 0.0, 0.0), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run_cycles(sim, 4), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "frequency 64"));
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "> 2.82, the stability bound of rk4"));
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.02, 0.0, 0.0), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run_cycles(sim, 4), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(
        strstr(fricreg_sim_errmsg(sim), "dt*omega = 1.28 > 0.707107 lets a friction"));
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.012, 0.0, 0.0),
                     FRICREG_OK);
    expect_failure(sim, fricreg_sim_run_cycles(sim, 4), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "> 0.7, the stability bound of rkf45"));
    /* just inside the bound, 0.7/64 = 0.01094: it runs */
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.0109, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    fricreg_sim_free(sim);
}
END_TEST

/* A state on its way to overflow is stopped, not carried on: the chain driven with
 * a = 1e120 moves its blocks by ~a/n^2 = 1e117 within the first steps, beyond the 1e100
 * that no motion of these systems comes near. Header: FRICREG_EDIVERGED, naming the time
 * and the body; the results stop before t_end. */
START_TEST(test_unstable_run_is_ediverged)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_CHAIN);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 1e120), FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, 4);
    ck_assert_msg(status == FRICREG_EDIVERGED, "status %d (%s), message \"%s\"", status,
                  fricreg_strerror(status), fricreg_sim_errmsg(sim));
    ck_assert_int_eq(fricreg_sim_errcode(sim), FRICREG_EDIVERGED);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "t = "));
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "of body 0"));
    ck_assert_double_lt(value(sim, FRICREG_VALUE_TIME), 1.0);
    fricreg_sim_free(sim);
}
END_TEST

/* ---- getters ------------------------------------------------------------------------------- */

/* Header: FRICREG_ESIZE for a length that is not ndof / ncontacts / CYCLES, FRICREG_ENULL for a
 * NULL array, FRICREG_EINVAL for an unknown quantity; a failed call leaves the caller's arrays
 * untouched. (The getters take a const simulation, so they cannot record errcode/errmsg.) */
START_TEST(test_getters_reject_size_mismatch_and_null)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_run(sim, 3.0 * 2.0 * PI), FRICREG_OK); /* 3 whole cycles */
    ck_assert_double_eq(value(sim, FRICREG_VALUE_CYCLES), 3.0);
    double x[2] = {2.385, 2.385}, v[2] = {2.385, 2.385}, D[4] = {2.385, 2.385, 2.385, 2.385};

    ck_assert_int_eq(fricreg_sim_get_state(sim, 2, x, v), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_sim_get_state(sim, 0, x, v), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, NULL, v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, x, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 2, D), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 4, D), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 3, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 2, D), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 1, NULL), FRICREG_ENULL);
    for (int k = 0; k < 4; k++)
        ck_assert_double_eq(D[k], 2.385);
    for (int k = 0; k < 2; k++) {
        ck_assert_double_eq(x[k], 2.385);
        ck_assert_double_eq(v[k], 2.385);
    }

    double out = 2.385;
    ck_assert_int_eq(fricreg_sim_get_value(sim, 8, &out), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_get_value(sim, -1, &out), FRICREG_EINVAL);
    ck_assert_double_eq(out, 2.385);
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_TIME, NULL), FRICREG_ENULL);
    fricreg_sim_free(sim);
}
END_TEST

/* Header: set_param "discards any results" (and so do set_law and set_integrator, which change
 * what a run means): after each, no cycle, time or dissipation remains. */
START_TEST(test_setters_discard_results)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    for (int k = 0; k < 3; k++) {
        ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
        ck_assert_double_eq(value(sim, FRICREG_VALUE_CYCLES), 2.0);
        ck_assert_double_gt(value(sim, FRICREG_VALUE_DISSIPATION), 0.0);
        int status = k == 0   ? fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 2.385)
                     : k == 1 ? fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.0)
                              : fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.01, 0.0, 0.0);
        ck_assert_int_eq(status, FRICREG_OK);
        ck_assert_double_eq(value(sim, FRICREG_VALUE_CYCLES), 0.0);
        ck_assert_double_eq(value(sim, FRICREG_VALUE_TIME), 0.0);
        ck_assert_double_eq(value(sim, FRICREG_VALUE_DISSIPATION), 0.0);
        ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 0, NULL), FRICREG_OK);
    }
    fricreg_sim_free(sim);
}
END_TEST

/* ---- observer ------------------------------------------------------------------------------ */

struct stopper {
    double t_stop, t_first, t_last;
    int calls;
};

static int stop_after(void *user, double t, size_t ndof, const double x[], const double v[],
                      size_t m, const double f[], const double f_eq[])
{
    struct stopper *s = user;
    (void)ndof, (void)x, (void)v, (void)m, (void)f, (void)f_eq;
    if (s->calls++ == 0)
        s->t_first = t;
    s->t_last = t;
    return t >= s->t_stop;
}

/* Header: the observer is called once at t = 0 and after every accepted step; a nonzero return
 * stops the run, which then returns FRICREG_OK. RK4 with dt = 0.01 is one GSL step of 0.02 per
 * call, so the run stops within 0.02 past t_stop = 1.2345. */
START_TEST(test_observer_stops_the_run_early)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    struct stopper s = {1.2345, NAN, NAN, 0};
    ck_assert_int_eq(fricreg_sim_set_observer(sim, stop_after, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run(sim, 20.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_errcode(sim), FRICREG_OK);
    ck_assert_double_eq(s.t_first, 0.0);
    ck_assert_double_ge(s.t_last, 1.2345);
    ck_assert_double_lt(s.t_last, 1.2345 + 0.02 + 1e-12);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_TIME), s.t_last);
    ck_assert_int_eq(s.calls, 1 + (int)ceil(1.2345 / 0.02));
    fricreg_sim_free(sim);
}
END_TEST

/* An observer that calls every setter and fricreg_sim_run on its own simulation at its
 * second call: each is refused with FRICREG_EINVAL (1.0 freed the run's state under it), and
 * the run completes with the settings it started with: D per cycle bit for bit that of an
 * undisturbed run, x0 still the paper's 2.75. */
struct meddler {
    fricreg_sim *sim;
    int calls, status[6];
};

static int meddle(void *user, double t, size_t ndof, const double x[], const double v[], size_t m,
                  const double f[], const double f_eq[])
{
    (void)t, (void)ndof, (void)x, (void)v, (void)m, (void)f, (void)f_eq;
    struct meddler *md = user;
    if (md->calls++ == 1) {
        md->status[0] = fricreg_sim_set_param(md->sim, FRICREG_PARAM_X0, 1.0);
        md->status[1] = fricreg_sim_set_law(md->sim, FRICREG_LAW_COULOMB, 0.0);
        md->status[2] = fricreg_sim_set_integrator(md->sim, FRICREG_INT_RK2, 0.05, 0.0, 0.0);
        md->status[3] = fricreg_sim_set_partition(md->sim, FRICREG_PARTITION_PAPER);
        md->status[4] = fricreg_sim_set_observer(md->sim, NULL, NULL);
        md->status[5] = fricreg_sim_run(md->sim, 1.0);
    }
    return 0;
}

START_TEST(test_observer_cannot_change_its_own_run)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR), *plain = make(FRICREG_SYSTEM_OSCILLATOR);
    struct meddler md = {sim, 0, {0}};
    ck_assert_int_eq(fricreg_sim_set_observer(sim, meddle, &md), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    for (int k = 0; k < 6; k++)
        ck_assert_int_eq(md.status[k], FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "during a run"));
    ck_assert_int_eq(fricreg_sim_run_cycles(plain, 2), FRICREG_OK);
    double D[2], D_plain[2], x0 = NAN;
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 2, D), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(plain, 2, D_plain), FRICREG_OK);
    ck_assert_double_eq(D[0], D_plain[0]);
    ck_assert_double_eq(D[1], D_plain[1]);
    ck_assert_int_eq(fricreg_sim_get_param(sim, FRICREG_PARAM_X0, &x0), FRICREG_OK);
    ck_assert_double_eq(x0, 2.75);
    /* after the run the setters work again */
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 1.0), FRICREG_OK);
    fricreg_sim_free(plain);
    fricreg_sim_free(sim);
}
END_TEST

/* A run refused before its first step leaves no stale results: after a good run, an ESTEP run
 * (dt = 0.05 with eps = 0.02, test above) reports the initial state x0 = 2.75, v0 = 0, time 0,
 * no cycles and zero stick fractions (1.0 returned uninitialized memory here). */
START_TEST(test_refused_run_leaves_the_initial_state)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 2.385), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.05, 0.0, 0.0), FRICREG_OK);
    expect_failure(sim, fricreg_sim_run(sim, 20.0), FRICREG_ESTEP);
    double x = NAN, v = NAN, frac = NAN;
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x, &v), FRICREG_OK);
    ck_assert_double_eq(x, 2.385);
    ck_assert_double_eq(v, 0.0);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_TIME), 0.0);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_CYCLES), 0.0);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 0, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 1, &frac), FRICREG_OK);
    ck_assert_double_eq(frac, 0.0);
    fricreg_sim_free(sim);
}
END_TEST

/* Stopping at the first call (t = 0) is also a successful, empty run. */
START_TEST(test_observer_stopping_at_start_is_ok)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_TWOBLOCK);
    struct stopper s = {0.0, NAN, NAN, 0};
    ck_assert_int_eq(fricreg_sim_set_observer(sim, stop_after, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    ck_assert_int_eq(s.calls, 1);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_TIME), 0.0);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_CYCLES), 0.0);
    fricreg_sim_free(sim);
}
END_TEST

/* ---- integrator names ---------------------------------------------------------------------- */

START_TEST(test_integrator_names_round_trip)
{
    static const char *gsl_names[] = {"rk2",    "rk4",    "rkf45", "rkck",    "rk8pd", "rk1imp",
                                      "rk2imp", "rk4imp", "bsimp", "msadams", "msbdf"};
    for (int id = 1; id <= 11; id++) {
        const char *name = fricreg_integrator_name(id);
        ck_assert_ptr_nonnull(name);
        ck_assert_str_eq(name, gsl_names[id - 1]);
        ck_assert_int_eq(fricreg_integrator_from_name(name), id);
    }
    ck_assert_ptr_null(fricreg_integrator_name(0));
    ck_assert_str_eq(fricreg_integrator_name(FRICREG_INT_RK4_GSL), "rk4-gsl");
    ck_assert_str_eq(fricreg_integrator_name(FRICREG_INT_CENTRAL), "central");
    ck_assert_str_eq(fricreg_integrator_name(FRICREG_INT_CENTRAL_IMEX), "central-imex");
    ck_assert_ptr_null(fricreg_integrator_name(15));
    ck_assert_int_eq(fricreg_integrator_from_name("rk5"), 0);
    ck_assert_int_eq(fricreg_integrator_from_name("RK4"), 0);
    ck_assert_int_eq(fricreg_integrator_from_name(""), 0);
    ck_assert_int_eq(fricreg_integrator_from_name(NULL), 0);
}
END_TEST

/* ---- every stepper on the paper's oscillator case ------------------------------------------ */

/* x_final of the unforced oscillator from (2.75, 0) under (4) with eps = 0.02, to t = 20. */
static double oscillator_final_x(int integ, double dt, double rtol, double atol)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, integ, dt, rtol, atol), FRICREG_OK);
    int status = fricreg_sim_run(sim, 20.0);
    ck_assert_msg(status == FRICREG_OK, "%s: status %d (%s)", fricreg_integrator_name(integ),
                  status, fricreg_sim_errmsg(sim));
    double x, v;
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x, &v), FRICREG_OK);
    fricreg_sim_free(sim);
    return x;
}

/* Paper Sec. 3.1.1 and spec ("adaptive and stiff integrators exhibit the same behavior"): every
 * GSL stepper, adaptive with rtol = 1e-8, atol = 1e-10, holds the stick at -0.75 (the O(eps^2)
 * regularization error is 9e-5 at eps = 0.02, well inside 1e-3). */
START_TEST(test_adaptive_stepper_holds_the_stick)
{
    const int integ = FRICREG_INT_RK2 + _i; /* all 11 */
    double x = oscillator_final_x(integ, 0.01, 1e-8, 1e-10);
    ck_assert_msg(fabs(x + 0.75) < 1e-3, "%s: x_final = %.9g", fricreg_integrator_name(integ), x);
}
END_TEST

/* The same with a fixed step dt = 0.005 (dt lambda = 0.5 in the stick zone). */
START_TEST(test_fixed_step_stepper_holds_the_stick)
{
    /* All but rk1imp, implicit Euler, whose first-order error at this step is 7e-3. */
    static const int integ[] = {FRICREG_INT_RK2,    FRICREG_INT_RK4,   FRICREG_INT_RKF45,
                                FRICREG_INT_RKCK,   FRICREG_INT_RK8PD, FRICREG_INT_RK2IMP,
                                FRICREG_INT_RK4IMP, FRICREG_INT_BSIMP, FRICREG_INT_MSADAMS,
                                FRICREG_INT_MSBDF};
    double x = oscillator_final_x(integ[_i], 0.005, 0.0, 0.0);
    ck_assert_msg(fabs(x + 0.75) < 1e-3, "%s: x_final = %.9g", fricreg_integrator_name(integ[_i]),
                  x);
}
END_TEST

/* GSL's bsimp breaks off a step that meets its runaway test, a change beyond 100 dim times
 * |y_i| (here x0 = 1e-300 once the forcing a = 2 breaks the stick near t = 0.52), with yerr =
 * +Inf and GSL_SUCCESS: a fixed step took it as done without moving the state, and the run
 * returned FRICREG_OK frozen at x = 1e-300, v = 0 (the run from x0 = 0 ends at x = 1.2). Found
 * while reducing a fuzz finding of the structure target. Such a step now fails, is retried in
 * halves like any failed implicit step, and the run reports FRICREG_EINTEGRATOR. */
START_TEST(test_bsimp_fixed_step_does_not_freeze)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 2.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 1e-300), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_BSIMP, 0.01, 0.0, 0.0),
                     FRICREG_OK);
    int status = fricreg_sim_run(sim, 3.0);
    double x, v;
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x, &v), FRICREG_OK);
    ck_assert_msg(status == FRICREG_EINTEGRATOR || (status == FRICREG_OK && x > 1.0),
                  "status %d, x = %g, v = %g", status, x, v);
    fricreg_sim_free(sim);
}
END_TEST

/* ---- get_param ----------------------------------------------------------------------------- */

#define NPARAMS 11 /* enum fricreg_param: 1 … 11 */

struct paper_value {
    int system, param;
    double value;
};

/* The header's defaults (enum fricreg_system), the paper's values: every parameter each system
 * reads, and no other. */
static const struct paper_value paper_values[] = {
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_A, 0.0},
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_OMEGA, 1.0},
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_MUN, 1.0},
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_X0, 2.75},
    {FRICREG_SYSTEM_OSCILLATOR, FRICREG_PARAM_V0, 0.0},
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_N, 32.0},
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_A, 0.25},
    {FRICREG_SYSTEM_CHAIN, FRICREG_PARAM_OMEGA, 0.5},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_K, 2.0},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_MU1, 0.5},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_MU2, 0.25},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_BELT_AMP, 1.0},
    {FRICREG_SYSTEM_TWOBLOCK, FRICREG_PARAM_BELT_OMEGA, 0.5},
};

/* The paper's value of `param` in `system`, or NAN if the system does not read it. */
static double paper_default(int system, int param)
{
    for (size_t k = 0; k < sizeof paper_values / sizeof paper_values[0]; k++)
        if (paper_values[k].system == system && paper_values[k].param == param)
            return paper_values[k].value;
    return NAN;
}

/* Header: get_param reads the paper's default of every parameter the system reads, and
 * answers FRICREG_EINVAL, leaving *value alone, for each one it does not (0, 12 and -1 are
 * no parameter at all). A getter records no error. */
START_TEST(test_get_param_reads_the_papers_defaults)
{
    const int system = FRICREG_SYSTEM_OSCILLATOR + _i;
    fricreg_sim *sim = make(system);
    for (int param = -1; param <= NPARAMS + 1; param++) {
        double expected = paper_default(system, param), out = 2.385;
        int status = fricreg_sim_get_param(sim, param, &out);
        if (isnan(expected)) {
            ck_assert_msg(status == FRICREG_EINVAL, "system %d, param %d: %d", system, param,
                          status);
            ck_assert_double_eq(out, 2.385);
        } else {
            ck_assert_int_eq(status, FRICREG_OK);
            ck_assert_double_eq(out, expected);
        }
    }
    ck_assert_int_eq(fricreg_sim_get_param(sim, FRICREG_PARAM_A, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_errcode(sim), FRICREG_OK);
    fricreg_sim_free(sim);
}
END_TEST

/* get_param reads back what set_param stored, for every parameter of every system; a rejected
 * set_param leaves the value read before it. Values: 2.385 + k/8 (exact in binary), 17 for n. */
START_TEST(test_get_param_reads_back_set_values)
{
    for (size_t k = 0; k < sizeof paper_values / sizeof paper_values[0]; k++) {
        const struct paper_value *pv = &paper_values[k];
        fricreg_sim *sim = make(pv->system);
        double set = pv->param == FRICREG_PARAM_N ? 17.0 : 2.385 + (double)k / 8.0, out = NAN;
        ck_assert_int_eq(fricreg_sim_set_param(sim, pv->param, set), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_get_param(sim, pv->param, &out), FRICREG_OK);
        ck_assert_double_eq(out, set);
        ck_assert_int_ne(fricreg_sim_set_param(sim, pv->param, NAN), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_get_param(sim, pv->param, &out), FRICREG_OK);
        ck_assert_double_eq(out, set);
        fricreg_sim_free(sim);
    }
}
END_TEST

/* ---- get_stat ------------------------------------------------------------------------------ */

static int64_t counter(const fricreg_sim *sim, int which)
{
    int64_t out = -1;
    ck_assert_int_eq(fricreg_sim_get_stat(sim, which, &out), FRICREG_OK);
    return out;
}

/* Header: FRICREG_EINVAL for an unknown counter (valid 0 … 4), FRICREG_ENULL for a NULL value;
 * *value untouched on failure, no error recorded. Before any run every counter is 0. */
START_TEST(test_get_stat_rejects_unknown_counter)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_TWOBLOCK);
    static const int bad[] = {-1, FRICREG_SIM_STAT_KINKS + 1, 1000};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        int64_t out = 2385;
        ck_assert_int_eq(fricreg_sim_get_stat(sim, bad[k], &out), FRICREG_EINVAL);
        ck_assert_int_eq(out, 2385);
    }
    ck_assert_int_eq(fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_STEPS, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_errcode(sim), FRICREG_OK);
    for (int which = FRICREG_SIM_STAT_STEPS; which <= FRICREG_SIM_STAT_KINKS; which++)
        ck_assert_int_eq(counter(sim, which), 0);
    fricreg_sim_free(sim);
}
END_TEST

/* Fixed-step RK4 over 3.5 cycles of the oscillator with omega = 1.2385, dt = 0.01: the period
 * T = 2 pi/1.2385 = 5.07326 is ceil(T/0.02) = ceil(253.66) = 254 GSL rk4 steps of 2 dt per
 * cycle (the last shortened to end on the boundary), and the half cycle after the third is
 * ceil(126.83) = 127: 3 * 254 + 127 = 889 GSL steps, counted as 2 steps of dt each,
 * STEPS = 1778; each costs 8 evaluations (test_chain.c), RHS_EVALS = 7112; CYCLES =
 * floor(3.5) = 3; an explicit stepper never fails a step, REJECTED_STEPS = 0. The double
 * forms of get_value agree, and a setter zeroes every counter. */
START_TEST(test_fixed_rk4_counts_match_the_step_grid)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, 1.2385), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run(sim, 3.5 * 2.0 * PI / 1.2385), FRICREG_OK);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_STEPS), 1778);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_RHS_EVALS), 7112);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_CYCLES), 3);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_REJECTED_STEPS), 0);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_STEPS), 1778.0);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_RHS_EVALS), 7112.0);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_CYCLES), 3.0);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 2.385), FRICREG_OK);
    for (int which = FRICREG_SIM_STAT_STEPS; which <= FRICREG_SIM_STAT_KINKS; which++)
        ck_assert_int_eq(counter(sim, which), 0);
    fricreg_sim_free(sim);
}
END_TEST

static int count_calls(void *user, double t, size_t ndof, const double x[], const double v[],
                       size_t m, const double f[], const double f_eq[])
{
    (void)t, (void)ndof, (void)x, (void)v, (void)m, (void)f, (void)f_eq;
    ++*(int64_t *)user;
    return 0;
}

/* Adaptive rkf45 (GSL 2.7): each attempt at a step, accepted or rejected, evaluates the five
 * stages after k1 and dydt at its end, which the next step reuses as its k1; only the first
 * step evaluates its k1. So RHS_EVALS = 1 + 6 (STEPS + REJECTED_STEPS) exactly, without kink
 * location (its trial steps add their own right-hand sides: counted, more). An initial
 * step dt = 1 against rtol = 1e-9 is rejected at once, so REJECTED_STEPS > 0; the observer,
 * called at t = 0 and after every accepted step, counts STEPS + 1 calls. Forced oscillator,
 * a = 0.6137, eps = 0.02, 2 cycles. */
START_TEST(test_adaptive_counts_rejected_steps)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    int64_t calls = 0;
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 0.6137), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 1.0, 1e-9, 1e-12),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_observer(sim, count_calls, &calls), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_kink_location(sim, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    int64_t steps = counter(sim, FRICREG_SIM_STAT_STEPS);
    int64_t rejected = counter(sim, FRICREG_SIM_STAT_REJECTED_STEPS);
    ck_assert_int_gt(rejected, 0);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_RHS_EVALS), 1 + 6 * (steps + rejected));
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_KINKS), 0);
    ck_assert_int_eq(calls, steps + 1);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_CYCLES), 2);
    calls = 0; /* with location: every accepted step observed once, cut ones included */
    ck_assert_int_eq(fricreg_sim_set_kink_location(sim, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    ck_assert_int_gt(counter(sim, FRICREG_SIM_STAT_KINKS), 0);
    ck_assert_int_eq(calls, counter(sim, FRICREG_SIM_STAT_STEPS) + 1);
    fricreg_sim_free(sim);
}
END_TEST

/* A fixed-step multistep stepper whose corrector fails at the stick retries the step as two
 * halves (REJECTED_STEPS > 0) and keeps the caller's grid: the unforced oscillator to t = 20
 * with dt = 0.005 is 3 cycles of ceil(2 pi/0.005) = 1257 steps and ceil((20 - 6 pi)/0.005) =
 * ceil(230.09) = 231 more, STEPS = 4002 whatever the retries. */
START_TEST(test_fixed_step_retries_count_as_rejected)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSADAMS, 0.005, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run(sim, 20.0), FRICREG_OK);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_STEPS), 4002);
    ck_assert_int_gt(counter(sim, FRICREG_SIM_STAT_REJECTED_STEPS), 0);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_CYCLES), 3);
    fricreg_sim_free(sim);
}
END_TEST

/* The adaptive steps of one forcing cycle are bounded (fricreg_sim_set_max_steps):
 *   - Coulomb's law under rkf45 (rtol 1e-6, atol 1e-8) shrinks its steps without end at the
 *     first stick (it took 12 s a cycle, about 5e7 steps): with the bound at 10^5 the run
 *     stops inside the first cycle with FRICREG_EWORK, naming the law's jump, with exactly
 *     10^5 accepted steps and kink locations (a location counts as a step: 99866 and 134);
 *     by default (a law that jumps: 10^4) the force balance likewise without kink location;
 *     with it, its step lands on zdot = 0 and the stick holds (4 cycles in 167 steps, D on
 *     the first 3.5000007 against the closed form's 3.5, `fricreg-sim exact`);
 *   - law (4) at the same tolerances takes more than 100 steps a cycle (steps and kink
 *     locations, counted with the bound off), so a bound of 100 stops it in cycle 1, and its
 *     own count lets it finish;
 *   - the bound is per cycle: 2 cycles pass the bound that one passes;
 *   - negative bounds are refused, and 0 removes it. */
START_TEST(test_adaptive_steps_are_bounded_per_cycle)
{
    fricreg_sim *sim = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_COULOMB, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.01, 1e-6, 1e-8),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_max_steps(sim, -1), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_set_max_steps(sim, 100000), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 4), FRICREG_EWORK);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "jump at zdot = 0"));
    double period = value(sim, FRICREG_VALUE_PERIOD), t = value(sim, FRICREG_VALUE_TIME);
    ck_assert_double_lt(t, period);
    ck_assert_int_gt(counter(sim, FRICREG_SIM_STAT_KINKS), 0);
    ck_assert_int_eq(counter(sim, FRICREG_SIM_STAT_STEPS) + counter(sim, FRICREG_SIM_STAT_KINKS),
                     100000);
    /* by default a law that jumps gets 10^4 adaptive steps a cycle */
    fricreg_sim *fresh = make(FRICREG_SYSTEM_OSCILLATOR);
    ck_assert_int_eq(fricreg_sim_set_law(fresh, FRICREG_LAW_FORCE_BALANCE, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(fresh, FRICREG_INT_RKF45, 0.01, 1e-6, 1e-8),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_kink_location(fresh, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(fresh, 4), FRICREG_EWORK);
    ck_assert_int_eq(counter(fresh, FRICREG_SIM_STAT_STEPS), 10000);
    ck_assert_int_eq(fricreg_sim_set_kink_location(fresh, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(fresh, 4), FRICREG_OK);
    ck_assert_int_lt(counter(fresh, FRICREG_SIM_STAT_STEPS), 1000);
    double D[4];
    ck_assert_int_eq(fricreg_sim_get_dissipation(fresh, 4, D), FRICREG_OK);
    ck_assert_double_eq_tol(D[0], 3.5, 1e-5);
    fricreg_sim_free(fresh);

    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_max_steps(sim, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    int64_t cycle = counter(sim, FRICREG_SIM_STAT_STEPS) + counter(sim, FRICREG_SIM_STAT_KINKS);
    ck_assert_int_gt(cycle, 100);
    ck_assert_int_eq(fricreg_sim_set_max_steps(sim, 100), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_EWORK);
    ck_assert_ptr_null(strstr(fricreg_sim_errmsg(sim), "jump"));
    ck_assert_int_eq(fricreg_sim_set_max_steps(sim, cycle), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    fricreg_sim_free(sim);
}
END_TEST

static Suite *sim_api_suite(void)
{
    Suite *s = suite_create("sim_api");
    TCase *errors = tcase_create("errors");
    tcase_add_test(errors, test_create_rejects_unknown_system_and_null_out);
    tcase_add_test(errors, test_null_simulation_is_rejected_everywhere);
    tcase_add_loop_test(errors, test_set_param_rejects_bad_parameter, 0,
                        (int)(sizeof bad_params / sizeof bad_params[0]));
    tcase_add_test(errors, test_set_param_message_names_parameter_and_rule);
    tcase_add_test(errors, test_failed_set_param_keeps_parameters);
    tcase_add_test(errors, test_set_law_rejects_bad_law_and_eps);
    tcase_add_test(errors, test_set_integrator_rejects_bad_settings);
    tcase_add_test(errors, test_run_rejects_bad_end_time);
    tcase_add_test(errors, test_run_cycles_rejects_fewer_than_one);
    tcase_add_test(errors, test_getters_reject_size_mismatch_and_null);
    tcase_add_test(errors, test_setters_discard_results);
    suite_add_tcase(s, errors);

    TCase *run = tcase_create("run_checks");
    tcase_add_test(run, test_too_large_step_is_estep_naming_the_stick_zone);
    tcase_add_test(run, test_overflowing_stick_zone_names_bounds_and_eps);
    tcase_add_test(run, test_estep_uses_the_coupling_diagonal);
    tcase_add_test(run, test_estep_paper_partition_sees_the_coupling);
    tcase_add_test(run, test_refused_run_leaves_the_initial_state);
    tcase_add_test(run, test_spring_mode_too_fast_is_estep);
    tcase_add_test(run, test_unstable_run_is_ediverged);
    tcase_add_test(run, test_observer_stops_the_run_early);
    tcase_add_test(run, test_observer_cannot_change_its_own_run);
    tcase_add_test(run, test_observer_stopping_at_start_is_ok);
    tcase_add_test(run, test_adaptive_steps_are_bounded_per_cycle);
    suite_add_tcase(s, run);

    TCase *params = tcase_create("get_param");
    tcase_add_loop_test(params, test_get_param_reads_the_papers_defaults, 0, 3);
    tcase_add_test(params, test_get_param_reads_back_set_values);
    suite_add_tcase(s, params);

    TCase *stats = tcase_create("get_stat");
    tcase_add_test(stats, test_get_stat_rejects_unknown_counter);
    tcase_add_test(stats, test_fixed_rk4_counts_match_the_step_grid);
    tcase_add_test(stats, test_adaptive_counts_rejected_steps);
    tcase_add_test(stats, test_fixed_step_retries_count_as_rejected);
    suite_add_tcase(s, stats);

    TCase *steppers = tcase_create("steppers");
    tcase_add_test(steppers, test_integrator_names_round_trip);
    tcase_add_loop_test(steppers, test_adaptive_stepper_holds_the_stick, 0, 11);
    tcase_add_loop_test(steppers, test_fixed_step_stepper_holds_the_stick, 0, 10);
    tcase_add_test(steppers, test_bsimp_fixed_step_does_not_freeze);
    suite_add_tcase(s, steppers);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(sim_api_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
