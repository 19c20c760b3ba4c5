/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_warning_handler.c — Check suite for the warning handlers (fricreg_structure_set_warning_
 * handler, fricreg_sim_set_warning_handler): a handler receives exactly the list that
 * *_warning_count reads back (the list fricreg-sim prints), once per warning per run, and
 * nothing without one.
 *
 * The structure is the ten-storey building of examples/building with its ground record in g
 * (test_warnings.c's "ground record in g": peak 0.3 < 0.49 m/s^2), which raises ground_peak
 * and, the dampers never slipping, eps_speed after a run of 15 s. The simulation is the
 * oscillator with rkf45 at atol = rtol = 1e-3: its velocity level 2e-3 is above 0.01 eps
 * (test_bad_input.c's tol_loose fixture), the only warning it raises. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_sim.h"
#include "fricreg_structure.h"

#include "../../examples/building/building_model.h"

#define N BUILDING_STOREYS
#define NREC (BUILDING_RECORD_STEPS + 1)
#define MAX_HEARD 16

/* What a handler heard, in order; and what it tried from inside. */
struct heard {
    size_t n;
    int code[MAX_HEARD];
    char msg[MAX_HEARD][256];
    fricreg_structure *s; /* when set, the handler tries these calls on it */
    int nested_set, nested_run;
    size_t nested_count;
};

static void hear(int code, const char *message, void *user_data)
{
    struct heard *h = user_data;
    ck_assert_uint_lt(h->n, MAX_HEARD);
    h->code[h->n] = code;
    snprintf(h->msg[h->n], sizeof h->msg[0], "%s", message);
    h->n++;
    if (h->s != NULL) {
        h->nested_set = fricreg_structure_set_law(h->s, FRICREG_LAW_QUINN, 1.0);
        h->nested_run = fricreg_structure_run(h->s, 0.01, 100.0);
        h->nested_count = fricreg_structure_warning_count(h->s);
    }
}

static void ok(fricreg_structure *s, int status)
{
    ck_assert_msg(status == FRICREG_OK, "status %d: %s", status, fricreg_structure_errmsg(s));
}

/* The building with its record in g: M, K, Rayleigh, J, the bounds and eps 0.01 PGV as
 * test_warnings.c's building() builds them. */
static fricreg_structure *building_in_g(void)
{
    double M[N * N] = {0}, K[N * N], J[N * N], mun[N], r[N], a0, a1, pgv = 0.0, v = 0.0;
    static double ag[NREC];
    for (int i = 0; i < N; i++) {
        M[i * N + i] = building_mass;
        for (int j = 0; j < N; j++) {
            K[i * N + j] = building_K(i, j);
            J[i * N + j] = building_J(i, j);
        }
        mun[i] = building_mun(i);
        r[i] = 1.0;
    }
    for (int k = 0; k < NREC; k++)
        ag[k] = building_ground(k) / 9.81;
    for (int k = 1; k < NREC; k++) {
        v += 0.5 * (ag[k - 1] + ag[k]) * building_record_dt * 9.81;
        pgv = fmax(pgv, fabs(v));
    }
    building_rayleigh(&a0, &a1);
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(N, N, &s), FRICREG_OK);
    ok(s, fricreg_structure_set_mass(s, N, M));
    ok(s, fricreg_structure_set_stiffness(s, N, K));
    ok(s, fricreg_structure_set_rayleigh(s, a0, a1));
    ok(s, fricreg_structure_set_contacts(s, N, N, J));
    ok(s, fricreg_structure_set_bounds(s, N, mun));
    ok(s, fricreg_structure_set_influence(s, N, r));
    ok(s, fricreg_structure_set_ground_accel(s, 0.0, building_record_dt, NREC, ag));
    ok(s, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.01 * pgv));
    return s;
}

/* The handler heard exactly the list warning_count reads back, in its order. */
static void heard_the_list(fricreg_structure *s, const struct heard *h, size_t from)
{
    size_t count = fricreg_structure_warning_count(s);
    ck_assert_uint_eq(h->n - from, count);
    for (size_t k = 0; k < count; k++) {
        int code = FRICREG_WARN_NONE;
        char msg[256];
        ck_assert_int_eq(fricreg_structure_get_warning(s, k, &code, msg, sizeof msg), FRICREG_OK);
        ck_assert_int_eq(h->code[from + k], code);
        ck_assert_str_eq(h->msg[from + k], msg);
    }
}

START_TEST(structure_run_delivers_each_warning_once)
{
    struct heard h = {0};
    fricreg_structure *s = building_in_g();
    ok(s, fricreg_structure_set_warning_handler(s, hear, &h));
    ok(s, fricreg_structure_run(s, 0.01, 15.0));
    ck_assert_uint_eq(h.n, 2);
    ck_assert_int_eq(h.code[0], FRICREG_WARN_GROUND_PEAK);
    ck_assert_int_eq(h.code[1], FRICREG_WARN_EPS_SPEED);
    heard_the_list(s, &h, 0); /* the judgement again: nothing new to deliver */
    ck_assert_uint_eq(h.n, 2);
    ok(s, fricreg_structure_run(s, 0.01, 20.0)); /* the same run, on: no news */
    ck_assert_uint_eq(h.n, 2);
    double u0[N] = {0}, v0[N] = {0};
    ok(s, fricreg_structure_set_initial(s, N, u0, v0)); /* a new run: its warnings are news */
    ok(s, fricreg_structure_run(s, 0.01, 15.0));
    ck_assert_uint_eq(h.n, 4);
    heard_the_list(s, &h, 2);
    fricreg_structure_free(s);
}
END_TEST

/* Without a handler (the default, or removed) nothing is called: the list is only read back. */
START_TEST(structure_no_handler_no_call)
{
    struct heard h = {0};
    fricreg_structure *s = building_in_g();
    ok(s, fricreg_structure_run(s, 0.01, 15.0));
    ok(s, fricreg_structure_set_warning_handler(s, hear, &h));
    ok(s, fricreg_structure_set_warning_handler(s, NULL, NULL));
    double u0[N] = {0}, v0[N] = {0};
    ok(s, fricreg_structure_set_initial(s, N, u0, v0));
    ok(s, fricreg_structure_run(s, 0.01, 15.0));
    ck_assert_uint_eq(h.n, 0);
    ck_assert_uint_eq(fricreg_structure_warning_count(s), 2);
    ck_assert_uint_eq(h.n, 0);
    ck_assert_int_eq(fricreg_structure_set_warning_handler(NULL, hear, &h), FRICREG_ENULL);
    fricreg_structure_free(s);
}
END_TEST

/* step judges nothing; the loop's own warning_count delivers. */
START_TEST(structure_step_loop_judges_at_warning_count)
{
    struct heard h = {0};
    fricreg_structure *s = building_in_g();
    ok(s, fricreg_structure_set_warning_handler(s, hear, &h));
    for (int k = 0; k < 1500; k++)
        ok(s, fricreg_structure_step(s, 0.01));
    ck_assert_uint_eq(h.n, 0);
    ck_assert_uint_eq(fricreg_structure_warning_count(s), 2);
    ck_assert_uint_eq(h.n, 2);
    heard_the_list(s, &h, 0);
    fricreg_structure_free(s);
}
END_TEST

/* From the handler: a setter and a run are refused and change nothing, warning_count judges
 * nothing (the list as it is), and the run that called the handler succeeds. */
START_TEST(structure_handler_may_only_read)
{
    struct heard h = {0};
    fricreg_structure *s = building_in_g();
    h.s = s;
    ok(s, fricreg_structure_set_warning_handler(s, hear, &h));
    ok(s, fricreg_structure_run(s, 0.01, 15.0));
    ck_assert_uint_eq(h.n, 2);
    ck_assert_int_eq(h.nested_set, FRICREG_EINVAL);
    ck_assert_int_eq(h.nested_run, FRICREG_EINVAL);
    ck_assert_uint_eq(h.nested_count, 2);
    double t = 0.0;
    ok(s, fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t));
    ck_assert_double_eq(t, 15.0);
    fricreg_structure_free(s);
}
END_TEST

static fricreg_sim *loose_oscillator(void)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.01, 1e-3, 1e-3),
                     FRICREG_OK);
    return sim;
}

/* A simulation's run starts from its initial state: each run's warnings are news; the
 * extrapolation's levels and the error estimate's companion run on simulations of their own
 * and do not call it, so an extrapolated run delivers tol_loose once. */
START_TEST(sim_runs_deliver_each_warning_once)
{
    struct heard h = {0};
    fricreg_sim *sim = loose_oscillator();
    ck_assert_int_eq(fricreg_sim_set_warning_handler(sim, hear, &h), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    ck_assert_uint_eq(h.n, 1);
    ck_assert_int_eq(h.code[0], FRICREG_WARN_TOL_LOOSE);
    ck_assert_str_eq(h.msg[0], fricreg_sim_warning_message(sim, 0));
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 1);
    ck_assert_uint_eq(h.n, 1);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    ck_assert_uint_eq(h.n, 2);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, 4.0 * acos(-1.0), 2, 0), FRICREG_OK);
    ck_assert_uint_eq(h.n, 3);
    ck_assert_int_eq(fricreg_sim_set_warning_handler(sim, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    ck_assert_uint_eq(h.n, 3);
    ck_assert_int_eq(fricreg_sim_set_warning_handler(NULL, hear, &h), FRICREG_ENULL);
    fricreg_sim_free(sim);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("warning_handler");
    TCase *tc = tcase_create("handlers");
    tcase_add_test(tc, structure_run_delivers_each_warning_once);
    tcase_add_test(tc, structure_no_handler_no_call);
    tcase_add_test(tc, structure_step_loop_judges_at_warning_count);
    tcase_add_test(tc, structure_handler_may_only_read);
    tcase_add_test(tc, sim_runs_deliver_each_warning_once);
    suite_add_tcase(suite, tc);
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
