/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_threads.c — separate objects in separate threads (fricreg.h: "separate contexts may be
 * used from separate threads at once"), next to a thread of the program's own that uses GSL
 * with its own error handler.
 *
 * Eight threads each run, ROUNDS times, their own context (dense W: eval, tangent, stick
 * stiffness, and a singular W), a simulation (a different system and stepper
 * family per thread: fricreg's rk4, GSL's rkf45, rk4imp, msbdf) and an exact solution; every
 * result must equal, bit for bit, the same work done before in one thread. Meanwhile a ninth
 * thread provokes GSL_ERRORS errors of its own (Cholesky of an indefinite matrix) and its
 * handler must see every one: a library that switches GSL's process-wide handler off around
 * its calls makes such a thread lose some of its errors (4.3 % of them, measured). The
 * handler must still be the program's at the end. Built with -fsanitize=thread by
 * tests/tsan.sh (ctest tsan), which fails on any ThreadSanitizer report. */
#include <check.h>
#include <pthread.h>
#include <stdatomic.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"

#define NTHREADS 8
#define ROUNDS 3
#define NRESULTS 48
#define GSL_ERRORS 2000

struct results {
    double v[NRESULTS];
    int n;
    int status[8];
    int nstatus;
};

static void put(struct results *r, double x)
{
    if (r->n < NRESULTS)
        r->v[r->n++] = x;
}

/* Context k: a 3 x 3 dense positive definite W that depends on k, evaluated near stick. */
static void context_work(int k, struct results *r)
{
    const double d = 0.1 * k;
    const double W[9] = {2.385 + d,      0.5,          0.1, 0.5, 1.5 + d, 0.3 - 0.02 * k, 0.1,
                         0.3 - 0.02 * k, 1.2 + 0.5 * d};
    const double singular[9] = {1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0 + d};
    const double mun[3] = {1.3, 0.7 + d, 2.385}, zdot[3] = {1e-3 * k, 0.0, -0.25};
    const double a_free[3] = {0.5 + d, -0.25, 3.0};
    double f[3], f_eq[3], Fz[9], Fa[9], lambda = 0.0;
    fricreg_ctx *ctx = NULL;
    r->status[r->nstatus++] = fricreg_ctx_create(3, &ctx);
    fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02);
    fricreg_ctx_set_bounds(ctx, 3, mun);
    fricreg_ctx_set_coupling_dense(ctx, 3, W);
    r->status[r->nstatus++] = fricreg_ctx_eval(ctx, 3, zdot, a_free, f, f_eq);
    fricreg_ctx_tangent(ctx, 3, Fz, Fa);
    fricreg_ctx_stick_stiffness(ctx, &lambda);
    for (int i = 0; i < 3; i++) {
        put(r, f[i]);
        put(r, Fz[4 * i]);
    }
    put(r, lambda);
    fricreg_ctx_set_coupling_dense(ctx, 3, singular);
    const double rest[3] = {0.0, 0.0, 0.0};
    r->status[r->nstatus++] = fricreg_ctx_eval(ctx, 3, rest, a_free, f, f_eq); /* an error path */
    fricreg_ctx_free(ctx);
}

static void sim_work(int k, struct results *r)
{
    static const int integrators[4][2] = {{FRICREG_INT_RK4, 0},
                                          {FRICREG_INT_RKF45, 1},
                                          {FRICREG_INT_RK4IMP, 0},
                                          {FRICREG_INT_MSBDF, 1}};
    const int *integ = integrators[k % 4];
    fricreg_sim *sim = NULL;
    r->status[r->nstatus++] = fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR + k % 3, &sim);
    fricreg_sim_set_integrator(sim, integ[0], 0.01, integ[1] ? 1e-7 : 0.0, integ[1] ? 1e-9 : 0.0);
    if (k % 3 != 2)
        fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, 0.5 + 0.05 * k);
    r->status[r->nstatus++] = fricreg_sim_run_cycles(sim, 2);
    double x[64], v[64], D[2];
    size_t n = fricreg_sim_ndof(sim);
    fricreg_sim_get_state(sim, n, x, v);
    fricreg_sim_get_dissipation(sim, 2, D);
    put(r, x[0]);
    put(r, v[n - 1]);
    put(r, D[0]);
    put(r, D[1]);
    fricreg_sim_free(sim);
}

static void exact_work(int k, struct results *r)
{
    fricreg_exact *ex = NULL;
    r->status[r->nstatus++] = fricreg_exact_create(2.0 + 0.1 * k, 0.5 + 0.1 * k, 1.0, 0.0, 0.0,
                                                   &ex);
    r->status[r->nstatus++] = fricreg_exact_run_cycles(ex, 5);
    double D[5], x, v;
    fricreg_exact_dissipation(ex, 5, D);
    fricreg_exact_state(ex, 2.385, &x, &v);
    for (int c = 0; c < 5; c++)
        put(r, D[c]);
    put(r, x);
    put(r, (double)fricreg_exact_nswitches(ex));
    fricreg_exact_free(ex);
}

static void work(int k, struct results *r)
{
    memset(r, 0, sizeof *r);
    context_work(k, r);
    sim_work(k, r);
    exact_work(k, r);
}

static struct results reference[NTHREADS];

struct worker {
    int k;
    int mismatches;
};

static void *worker_main(void *arg)
{
    struct worker *w = arg;
    for (int round = 0; round < ROUNDS; round++) {
        struct results r;
        work(w->k, &r);
        w->mismatches += memcmp(&r, &reference[w->k], sizeof r) != 0;
    }
    return NULL;
}

/* The program's own GSL use: its errors go to its handler, every one. */
static atomic_int users_errors;

static void users_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason, (void)file, (void)line, (void)gsl_errno;
    atomic_fetch_add(&users_errors, 1);
}

static void *gsl_user_main(void *arg)
{
    int *edom = arg;
    for (int i = 0; i < GSL_ERRORS; i++) {
        double a[4] = {1.0, 2.0, 2.0, 1.0}; /* indefinite: Cholesky reports GSL_EDOM */
        gsl_matrix_view A = gsl_matrix_view_array(a, 2, 2);
        *edom += gsl_linalg_cholesky_decomp1(&A.matrix) == GSL_EDOM;
    }
    return NULL;
}

START_TEST(threads_match_one_thread)
{
    gsl_set_error_handler(users_handler);
    for (int k = 0; k < NTHREADS; k++) {
        work(k, &reference[k]);
        ck_assert_int_eq(reference[k].n, 18);
        for (int s = 0; s < reference[k].nstatus; s++)
            if (s != 2) /* the singular W's status: compared with the threads' below */
                ck_assert_msg(reference[k].status[s] == FRICREG_OK, "thread %d, call %d: %s", k, s,
                              fricreg_strerror(reference[k].status[s]));
    }
    ck_assert_int_eq(atomic_load(&users_errors), 0); /* fricreg reported nothing to it */

    pthread_t threads[NTHREADS], gsl_user;
    struct worker workers[NTHREADS];
    int edom = 0;
    ck_assert_int_eq(pthread_create(&gsl_user, NULL, gsl_user_main, &edom), 0);
    for (int k = 0; k < NTHREADS; k++) {
        workers[k] = (struct worker){.k = k};
        ck_assert_int_eq(pthread_create(&threads[k], NULL, worker_main, &workers[k]), 0);
    }
    for (int k = 0; k < NTHREADS; k++)
        ck_assert_int_eq(pthread_join(threads[k], NULL), 0);
    ck_assert_int_eq(pthread_join(gsl_user, NULL), 0);

    for (int k = 0; k < NTHREADS; k++)
        ck_assert_msg(workers[k].mismatches == 0,
                      "thread %d: %d of %d rounds differ from one "
                      "thread's",
                      k, workers[k].mismatches, ROUNDS);
    ck_assert_int_eq(edom, GSL_ERRORS);
    ck_assert_int_eq(atomic_load(&users_errors), GSL_ERRORS); /* none lost, none added */
    ck_assert_ptr_eq(gsl_set_error_handler(users_handler), users_handler);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("threads");
    TCase *tc = tcase_create("threads");
    tcase_set_timeout(tc, 600.0); /* under ThreadSanitizer, on a shared machine */
    tcase_add_test(tc, threads_match_one_thread);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
