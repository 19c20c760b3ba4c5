/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_alloc_failure.c — every allocation made on the way through the library, failed in turn.
 *
 * The program is linked with fricreg's objects and GSL's static archives under
 * -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free, so every allocation of fricreg
 * and of the GSL code it calls passes through the wrappers below (the C library's own do not).
 * For each scenario (create, set_coupling_dense, the step guard's stiffness, a simulation of
 * each system with one stepper of each family, the exact solver, a structure with each
 * scheme), the scenario is run once
 * with no failure to count its allocations n, then again for every k = 1..n with the k-th
 * allocation failing. Each case
 * must return FRICREG_OK or FRICREG_ENOMEM (with ENOMEM recorded in the object's error state
 * where there is an object), call GSL's error handler never (GSL's default one aborts) except
 * from gsl_odeiv2_step_alloc, and leave no block allocated once its objects are freed.
 * fricreg never touches GSL's handler: a failed malloc inside GSL's own stepper
 * allocation reports to it, and a program that wants FRICREG_ENOMEM there instead of GSL's
 * abort calls gsl_set_error_handler_off() once at start (docs/reliability.md). This program
 * does just that in main(); the scenarios then count the handler's calls with a handler of
 * their own, the stepper allocation's apart. fricreg_ctx_eval must not allocate at
 * all (fricreg.h). Run under valgrind or ASan, the same loops also check what the counting
 * cannot: no invalid access on any failure path. */
#include <check.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "fricreg.h"
#include "fricreg_disk_ctx.h"
#include "fricreg_exact.h"
#include "fricreg_sim.h"
#include "fricreg_stribeck.h"
#include "fricreg_structure.h"

/* ---- The allocator hook ------------------------------------------------------------------ */

void *__real_malloc(size_t size);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t size);
void __real_free(void *p);

static int armed;        /* count and fail only between hook_arm and hook_disarm */
static long n_allocs;    /* allocation requests while armed */
static long fail_at;     /* the request that fails (1-based); 0: none */
static long n_failed;    /* requests failed on purpose */
static long n_unchecked; /* requests made inside GSL's unchecked steppers (below), not failed */
static long live;        /* blocks allocated through the hook and not freed */

/* Check (linked statically on Debian) allocates too, in its assertions: the scenarios run
 * between hook_arm and hook_disarm make none, and record what they find in `violation`. */
static void hook_arm(long k)
{
    n_allocs = n_failed = n_unchecked = 0;
    fail_at = k;
    armed = 1;
}

static void hook_disarm(void)
{
    armed = 0;
}

/* GSL steppers that do not survive a failed malloc (GSL 2.7): bsimp_alloc checks none of its
 * 16 allocations and dereferences the first; the implicit and multistep steppers factor their
 * Newton matrix with gsl_linalg_LU_decomp, which allocates its pivots at every call, unchecked,
 * and crashes in LU_decomp_L3 on a NULL; msbdf_alloc also leaks on one of its paths. No caller
 * can repair that from outside (the states are private to GSL), so allocations inside these
 * steppers' alloc and apply are made but never failed, and are counted apart. */
static const char *const gsl_unchecked[] = {"bsimp",  "rk1imp", "rk2imp",
                                            "rk4imp", "msbdf",  "msadams"};
static int in_unchecked; /* inside such a stepper */

static int unchecked(const gsl_odeiv2_step_type *T)
{
    for (size_t k = 0; k < sizeof gsl_unchecked / sizeof gsl_unchecked[0]; k++)
        if (strcmp(T->name, gsl_unchecked[k]) == 0)
            return 1;
    return 0;
}

gsl_odeiv2_step *__real_gsl_odeiv2_step_alloc(const gsl_odeiv2_step_type *T, size_t dim);
int __real_gsl_odeiv2_step_apply(gsl_odeiv2_step *s, double t, double h, double y[], double yerr[],
                                 const double dydt_in[], double dydt_out[],
                                 const gsl_odeiv2_system *sys);

static int in_step_alloc; /* inside gsl_odeiv2_step_alloc, the one GSL allocator left */

gsl_odeiv2_step *__wrap_gsl_odeiv2_step_alloc(const gsl_odeiv2_step_type *T, size_t dim)
{
    int skip = unchecked(T);
    in_unchecked += skip;
    in_step_alloc++;
    gsl_odeiv2_step *s = __real_gsl_odeiv2_step_alloc(T, dim);
    in_step_alloc--;
    in_unchecked -= skip;
    return s;
}

int __wrap_gsl_odeiv2_step_apply(gsl_odeiv2_step *s, double t, double h, double y[], double yerr[],
                                 const double dydt_in[], double dydt_out[],
                                 const gsl_odeiv2_system *sys)
{
    int skip = unchecked(s->type);
    in_unchecked += skip;
    int status = __real_gsl_odeiv2_step_apply(s, t, h, y, yerr, dydt_in, dydt_out, sys);
    in_unchecked -= skip;
    return status;
}

static int hook_fails(void)
{
    if (armed && in_unchecked)
        n_unchecked++;
    if (!armed || in_unchecked || ++n_allocs != fail_at)
        return 0;
    n_failed++;
    return 1;
}

void *__wrap_malloc(size_t size)
{
    void *p = hook_fails() ? NULL : __real_malloc(size);
    live += armed && p != NULL;
    return p;
}

void *__wrap_calloc(size_t n, size_t size)
{
    void *p = hook_fails() ? NULL : __real_calloc(n, size);
    live += armed && p != NULL;
    return p;
}

void *__wrap_realloc(void *old, size_t size)
{
    if (hook_fails())
        return NULL; /* old stays allocated, as with a real failure */
    void *p = __real_realloc(old, size);
    if (armed)
        live += (old == NULL && p != NULL) - (old != NULL && size == 0 && p == NULL);
    return p;
}

void __wrap_free(void *p)
{
    live -= armed && p != NULL;
    __real_free(p);
}

static char violation[256]; /* the first broken promise of a scenario, or "" */

#define NOTE(...)                                               \
    do {                                                        \
        if (violation[0] == '\0')                               \
            snprintf(violation, sizeof violation, __VA_ARGS__); \
    } while (0)

/* GSL's handler, replaced for the whole program: any call means the library let GSL report an
 * error through the handler, which by default aborts the caller's program; calls from
 * gsl_odeiv2_step_alloc are the documented exception, counted apart. */
static long gsl_handler_calls, gsl_step_alloc_reports;
static char gsl_handler_reason[256];

static void count_gsl_error(const char *reason, const char *file, int line, int gsl_errno)
{
    if (in_step_alloc) {
        gsl_step_alloc_reports++;
        return;
    }
    gsl_handler_calls++;
    snprintf(gsl_handler_reason, sizeof gsl_handler_reason, "%s:%d: %s (GSL error %d)", file, line,
             reason, gsl_errno);
}

/* ---- Scenarios: each runs its calls, frees what it made, returns the first failure ---------- */

#define M_DENSE 5

/* A symmetric positive definite 5 x 5 W with unequal entries: tridiagonal, diagonally
 * dominant (Gershgorin: every eigenvalue >= 2.385 - 2 * 0.731 > 0). */
static void dense_w(double W[M_DENSE * M_DENSE])
{
    for (size_t i = 0; i < M_DENSE; i++)
        for (size_t j = 0; j < M_DENSE; j++)
            W[i * M_DENSE + j] = i == j                       ? 2.385 + 0.25 * (double)i
                                 : (i + 1 == j || j + 1 == i) ? -0.731
                                                              : 0.0;
}

static int ctx_create_free(void)
{
    fricreg_ctx *ctx = NULL;
    int status = fricreg_ctx_create(M_DENSE, &ctx);
    if ((status == FRICREG_OK) != (ctx != NULL))
        NOTE("ctx_create: status %d with handle %p", status, (void *)ctx);
    fricreg_ctx_free(ctx);
    return status;
}

static int ctx_dense(void)
{
    double W[M_DENSE * M_DENSE];
    dense_w(W);
    fricreg_ctx *ctx = NULL;
    int status = fricreg_ctx_create(M_DENSE, &ctx);
    if (status == FRICREG_OK) {
        status = fricreg_ctx_set_coupling_dense(ctx, M_DENSE, W);
        if (status != FRICREG_OK && fricreg_ctx_errcode(ctx) != status)
            NOTE("set_coupling_dense: status %d, errcode %d", status, fricreg_ctx_errcode(ctx));
    }
    fricreg_ctx_free(ctx);
    return status;
}

/* A 2-D context (fricreg_disk_ctx.h) with a dense W of order 2m: W = I + 0.1 (coupling). */
static void disk_dense_w(double W[])
{
    for (size_t i = 0; i < 2 * M_DENSE; i++)
        for (size_t j = 0; j < 2 * M_DENSE; j++)
            W[i * 2 * M_DENSE + j] = i == j ? 1.0 + 0.125 * (double)i
                                            : 0.1 / (1.0 + (double)(i > j ? i - j : j - i));
}

static int disk_ctx_dense(void)
{
    double W[4 * M_DENSE * M_DENSE];
    disk_dense_w(W);
    fricreg_disk_ctx *ctx = NULL;
    int status = fricreg_disk_ctx_create(M_DENSE, &ctx);
    if ((status == FRICREG_OK) != (ctx != NULL))
        NOTE("disk_ctx_create: status %d with handle %p", status, (void *)ctx);
    if (status == FRICREG_OK) {
        status = fricreg_disk_ctx_set_coupling_dense(ctx, M_DENSE, W);
        if (status != FRICREG_OK && fricreg_disk_ctx_errcode(ctx) != status)
            NOTE("disk set_coupling_dense: status %d, errcode %d", status,
                 fricreg_disk_ctx_errcode(ctx));
    }
    fricreg_disk_ctx_free(ctx);
    return status;
}

/* Stribeck friction in a 2-D context (fricreg_disk_ctx_set_stribeck allocates at its first
 * call); a failure must leave the context as it was, recorded. */
static const double strib_fs[M_DENSE] = {0.5, 1.25, 0.75, 2.0, 0.875};
static const double strib_fk[M_DENSE] = {0.25, 1.0, 0.75, 0.5, 0.5};
static const double strib_vs[M_DENSE] = {0.01, 0.02, 0.005, 0.04, 0.01};
static const double strib_delta[M_DENSE] = {1.0, 2.0, 0.5, 1.0, 1.5};

static int disk_ctx_stribeck(void)
{
    fricreg_disk_ctx *ctx = NULL;
    int status = fricreg_disk_ctx_create(M_DENSE, &ctx);
    if (status == FRICREG_OK) {
        status = fricreg_disk_ctx_set_stribeck(ctx, M_DENSE, strib_fs, strib_fk, strib_vs,
                                               strib_delta);
        if (status != FRICREG_OK && fricreg_disk_ctx_errcode(ctx) != status)
            NOTE("disk set_stribeck: status %d, errcode %d", status, fricreg_disk_ctx_errcode(ctx));
    }
    fricreg_disk_ctx_free(ctx);
    return status;
}

/* Stribeck friction in a 1-D context with a dense W (fricreg_ctx_set_stribeck allocates at
 * its first call), then one evaluation, which must allocate nothing more. */
static int ctx_stribeck(void)
{
    double W[M_DENSE * M_DENSE], f[M_DENSE];
    const double zdot[M_DENSE] = {0.0, 1e-3, -0.5, 0.0, 2e-4}, a_free[M_DENSE] = {0.1, -0.2};
    dense_w(W);
    fricreg_ctx *ctx = NULL;
    int status = fricreg_ctx_create(M_DENSE, &ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_coupling_dense(ctx, M_DENSE, W);
    if (status == FRICREG_OK) {
        status = fricreg_ctx_set_stribeck(ctx, M_DENSE, strib_fs, strib_fk, strib_vs, strib_delta);
        if (status != FRICREG_OK && fricreg_ctx_errcode(ctx) != status)
            NOTE("set_stribeck: status %d, errcode %d", status, fricreg_ctx_errcode(ctx));
    }
    if (status == FRICREG_OK)
        status = fricreg_ctx_eval(ctx, M_DENSE, zdot, a_free, f, NULL);
    fricreg_ctx_free(ctx);
    return status;
}

/* The step guard's eigenvalue problem: the paper's partition with a dense W (stiffness.c). */
static int ctx_stick_stiffness(void)
{
    double W[M_DENSE * M_DENSE], lambda = -2.385;
    dense_w(W);
    fricreg_ctx *ctx = NULL;
    int status = fricreg_ctx_create(M_DENSE, &ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_coupling_dense(ctx, M_DENSE, W);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER);
    if (status == FRICREG_OK) {
        status = fricreg_ctx_stick_stiffness(ctx, &lambda);
        if (status != FRICREG_OK && lambda != -2.385)
            NOTE("stick_stiffness: status %d but lambda written", status);
        if (status == FRICREG_OK && !(lambda > 0.0))
            NOTE("stick_stiffness: lambda = %g", lambda);
    }
    if (ctx != NULL && status != FRICREG_OK && fricreg_ctx_errcode(ctx) != status)
        NOTE("status %d, errcode %d", status, fricreg_ctx_errcode(ctx));
    fricreg_ctx_free(ctx);
    return status;
}

struct sim_case {
    int system, integrator;
    double dt, rtol, t_end;
};

static const struct sim_case *current_sim;

static int sim_run(void)
{
    const struct sim_case *c = current_sim;
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(c->system, &sim);
    if ((status == FRICREG_OK) != (sim != NULL))
        NOTE("sim_create: status %d with handle %p", status, (void *)sim);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, c->integrator, c->dt, c->rtol, c->rtol);
    if (status == FRICREG_OK && c->integrator == FRICREG_INT_CENTRAL) /* eps = 2 dt: ESTEP */
        status = fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 4.0 * c->dt);
    if (status == FRICREG_OK) {
        status = fricreg_sim_run(sim, c->t_end);
        if (status != FRICREG_OK && fricreg_sim_errcode(sim) != status)
            NOTE("sim_run: status %d, errcode %d", status, fricreg_sim_errcode(sim));
    }
    fricreg_sim_free(sim);
    return status;
}

/* fricreg_sim_run_extrapolated: level 0, two internal copies and the table (extrapolate.c).
 * A failure must leave no extrapolation behind. */
static int sim_run_extrapolated(void)
{
    fricreg_sim *sim = NULL;
    double T = 0.0, D[2], err[2];
    int status = fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.05, 0.0, 0.0);
    if (status == FRICREG_OK)
        status = fricreg_sim_get_value(sim, FRICREG_VALUE_PERIOD, &T);
    if (status == FRICREG_OK) {
        status = fricreg_sim_run_extrapolated(sim, 2.0 * T, 3, 0);
        if (status != FRICREG_OK && fricreg_sim_errcode(sim) != status)
            NOTE("run_extrapolated: status %d, errcode %d", status, fricreg_sim_errcode(sim));
        if (status != FRICREG_OK &&
            fricreg_sim_get_extrapolated_dissipation(sim, 2, D, err) != FRICREG_EINVAL)
            NOTE("run_extrapolated: status %d, but an extrapolation is held", status);
    }
    fricreg_sim_free(sim);
    return status;
}

/* test_exact's long no-stick case: 64 switches by t = 200, so about 80 phases by t = 250, and
 * the phase list outgrows its first 64 entries (a realloc that keeps the earlier ones). */
static int exact_run(void)
{
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_create(0.3, 1.0, 0.1, 1.2, 0.0, &ex);
    if ((status == FRICREG_OK) != (ex != NULL))
        NOTE("exact_create: status %d with handle %p", status, (void *)ex);
    if (status == FRICREG_OK) {
        status = fricreg_exact_run(ex, 250.0);
        if (status != FRICREG_OK && fricreg_exact_errcode(ex) != status)
            NOTE("exact_run: status %d, errcode %d", status, fricreg_exact_errcode(ex));
        if (status == FRICREG_OK && fricreg_exact_nswitches(ex) <= 64)
            NOTE("exact_run: %zu switches, the list never grew", fricreg_exact_nswitches(ex));
    }
    fricreg_exact_free(ex);
    return status;
}

static int exact_solve(void)
{
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_solve(2.385, 1.3125, 0.4125, -0.5, 0.125, 60.0, &ex);
    fricreg_exact_free(ex);
    return status;
}

/* A structure: a 3-storey shear frame (storey masses 2, 2, 1; storey stiffnesses 200) with
 * friction dampers across storeys 1 and 2 (J couples them: W dense), Rayleigh damping, a roof
 * load ramp; stepped by one scheme of each family (Newmark, HHT-alpha, central difference)
 * and by a GSL stepper (fricreg_structure_run_ode), each alloc made by create, the setters
 * and the run failed in turn. */
static const double FRAME_M[9] = {2, 0, 0, 0, 2, 0, 0, 0, 1};
static const double FRAME_K[9] = {400, -200, 0, -200, 400, -200, 0, -200, 200};
static const double FRAME_J[6] = {1, 0, 0, -1, 1, 0}, FRAME_MUN[2] = {5, 3};
static const double FRAME_P[3] = {0, 0, 1}, FRAME_G[3] = {0, 40, 0};
enum { SCHEME_NEWMARK, SCHEME_HHT, SCHEME_CENTRAL, SCHEME_ODE, N_SCHEMES };
static int current_scheme;

static int structure_model(fricreg_structure *s)
{
    int status = fricreg_structure_set_mass(s, 3, FRAME_M);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_stiffness(s, 3, FRAME_K);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_rayleigh(s, 0.1, 0.001);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_contacts(s, 2, 3, FRAME_J);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_bounds(s, 2, FRAME_MUN);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_load(s, 3, FRAME_P, 0.0, 0.5, 3, FRAME_G);
    if (status == FRICREG_OK) /* a band wide enough for central differences at dt = 0.001 */
        status = fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.5);
    return status;
}

static int structure_run(void)
{
    fricreg_structure *s = NULL;
    int status = fricreg_structure_create(3, 2, &s);
    if ((status == FRICREG_OK) != (s != NULL))
        NOTE("structure_create: status %d with handle %p", status, (void *)s);
    if (status == FRICREG_OK)
        status = structure_model(s);
    if (status == FRICREG_OK && current_scheme == SCHEME_HHT)
        status = fricreg_structure_set_hht(s, -0.1);
    if (status == FRICREG_OK && current_scheme == SCHEME_CENTRAL)
        status = fricreg_structure_set_central_difference(s);
    if (status == FRICREG_OK)
        status = current_scheme == SCHEME_ODE
                     ? fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 0.001, 1e-6, 1e-8, 1.0)
                     : fricreg_structure_run(s, 0.001, 1.0);
    if (s != NULL && status != FRICREG_OK && fricreg_structure_errcode(s) != status)
        NOTE("structure: status %d, errcode %d", status, fricreg_structure_errcode(s));
    fricreg_structure_free(s);
    return status;
}

/* ---- The loop ---------------------------------------------------------------------------- */

struct tally {
    long cases, enomem, ok;
    long unreached, bad_status, unrecorded, aborts, leaks; /* each must stay 0 */
    char first[512];                                       /* the first of those, described */
};
/* One run of scenario with the k-th allocation failing (none for k = 0): its status, and in
 * *made the allocations it asked for, *failed those refused. */
static int run_case(int (*scenario)(void), long k, long *made, long *failed)
{
    violation[0] = '\0';
    gsl_handler_calls = 0;
    hook_arm(k);
    int status = scenario();
    hook_disarm();
    *made = n_allocs;
    *failed = n_failed;
    return status;
}

/* Counts a broken promise in *count and keeps the first description. */
#define BROKEN(t, count, ...)                                  \
    do {                                                       \
        (t).count++;                                           \
        if ((t).first[0] == '\0')                              \
            snprintf((t).first, sizeof(t).first, __VA_ARGS__); \
    } while (0)

/* Runs scenario with no failure, then with the k-th allocation failing for every k; every
 * case runs, and the test fails at the end with the counts and the first broken promise. */
static struct tally fail_each_allocation(const char *name, int (*scenario)(void))
{
    struct tally t = {0};
    gsl_set_error_handler(count_gsl_error);
    gsl_step_alloc_reports = 0;
    long n = 0, made = 0, failed = 0, live_before = live;
    int status = run_case(scenario, 0, &n, &failed);
    ck_assert_msg(status == FRICREG_OK && violation[0] == '\0' && live == live_before,
                  "%s: status %d with no failure injected %s", name, status, violation);
    ck_assert_msg(n > 0, "%s: allocates nothing, so the loop tests nothing", name);
    for (long k = 1; k <= n; k++) {
        live_before = live;
        status = run_case(scenario, k, &made, &failed);
        t.cases++;
        t.enomem += status == FRICREG_ENOMEM;
        t.ok += status == FRICREG_OK;
        if (failed != 1)
            BROKEN(t, unreached, "allocation %ld of %ld not reached (%ld made)", k, n, made);
        if (status != FRICREG_OK && status != FRICREG_ENOMEM)
            BROKEN(t, bad_status, "allocation %ld of %ld failed: status %d (%s)", k, n, status,
                   fricreg_strerror(status));
        if (violation[0] != '\0')
            BROKEN(t, unrecorded, "allocation %ld of %ld failed: %s", k, n, violation);
        if (gsl_handler_calls != 0)
            BROKEN(t, aborts,
                   "allocation %ld of %ld failed: GSL's error handler was called "
                   "(%s); GSL's default handler aborts",
                   k, n, gsl_handler_reason);
        if (live != live_before)
            BROKEN(t, leaks, "allocation %ld of %ld failed: %ld block(s) leaked", k, n,
                   live - live_before);
    }
    printf("%s: %ld allocations (+%ld in GSL's unchecked steppers), %ld cases: %ld ENOMEM, "
           "%ld OK; %ld aborts, %ld leaks, %ld other status, %ld unrecorded, %ld unreached; "
           "%ld reports from gsl_odeiv2_step_alloc\n",
           name, n, n_unchecked, t.cases, t.enomem, t.ok, t.aborts, t.leaks, t.bad_status,
           t.unrecorded, t.unreached, gsl_step_alloc_reports);
    fflush(stdout); /* Check's child exits without flushing on a failed assertion */
    ck_assert_msg(t.unreached + t.bad_status + t.unrecorded + t.aborts + t.leaks == 0, "%s: %s",
                  name, t.first);
    return t;
}

START_TEST(test_ctx_create)
{
    struct tally t = fail_each_allocation("ctx_create", ctx_create_free);
    ck_assert_int_eq(t.enomem, t.cases); /* nothing to fall back on: each failure is reported */
}
END_TEST

START_TEST(test_ctx_set_coupling_dense)
{
    struct tally t = fail_each_allocation("ctx_set_coupling_dense", ctx_dense);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_ctx_stick_stiffness)
{
    struct tally t = fail_each_allocation("ctx_stick_stiffness", ctx_stick_stiffness);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* fricreg.h: "fricreg_ctx_eval never allocates". With every allocation failing, evaluations
 * under both partitions, in stick and in slip, with a dense W, still succeed. */
START_TEST(test_eval_does_not_allocate)
{
    double W[M_DENSE * M_DENSE], f[M_DENSE], f_eq[M_DENSE];
    dense_w(W);
    const double mun[M_DENSE] = {0.4125, 1.25, 0.3175, 2.0625, 0.8125};
    const double zdot[M_DENSE] = {1e-5, -0.375, 2.5e-4, 0.0, 1.875};
    const double a_free[M_DENSE] = {0.9375, -3.25, 0.0625, 1.625, -0.4375};
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(M_DENSE, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M_DENSE, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M_DENSE, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    for (int partition = 0; partition < 2; partition++) {
        ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition ? FRICREG_PARTITION_PAPER
                                                                  : FRICREG_PARTITION_CONSISTENT),
                         FRICREG_OK);
        int with_feq = FRICREG_ENOMEM, without = FRICREG_ENOMEM;
        hook_arm(1); /* the first request would fail: none may be made */
        with_feq = fricreg_ctx_eval(ctx, M_DENSE, zdot, a_free, f, f_eq);
        without = fricreg_ctx_eval(ctx, M_DENSE, zdot, a_free, f, NULL);
        hook_disarm();
        ck_assert_int_eq(with_feq, FRICREG_OK);
        ck_assert_int_eq(without, FRICREG_OK);
        ck_assert_msg(n_allocs == 0, "partition %d: eval made %ld allocations", partition,
                      n_allocs);
    }
    fricreg_ctx_free(ctx);
    /* The hook sees the library's allocations: the same set-up under it makes some. */
    long made = 0, failed = 0;
    ck_assert_int_eq(run_case(ctx_dense, 0, &made, &failed), FRICREG_OK);
    ck_assert_msg(made > 0, "set-up allocated nothing: the hook is not in place");
}
END_TEST

START_TEST(test_disk_ctx_set_coupling_dense)
{
    struct tally t = fail_each_allocation("disk_ctx_set_coupling_dense", disk_ctx_dense);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* A disk context of M_DENSE contacts on the dense W of disk_dense_w. */
static fricreg_disk_ctx *disk_dense_ctx(void)
{
    double W[4 * M_DENSE * M_DENSE];
    disk_dense_w(W);
    fricreg_disk_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_disk_ctx_create(M_DENSE, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, M_DENSE, W), FRICREG_OK);
    return ctx;
}

/* eval and tangent of a set-up disk context of M_DENSE contacts (at rest, in the band and
 * sliding) succeed with the first allocation armed to fail, and request none. */
static void expect_disk_eval_allocates_nothing(fricreg_disk_ctx *ctx, const char *what)
{
    const double zdot[2 * M_DENSE] = {1e-5, 2e-3, -0.375, 0.0, 0.0, 0.0, 0.0, 1e-3, 1.875, 0.5};
    const double a_free[2 * M_DENSE] = {0.9375, -3.25, 0.0625, 1.625, -0.4375,
                                        0.25,   2.0,   -1.0,   0.5,   0.125};
    double f[2 * M_DENSE], T[4 * M_DENSE * M_DENSE];
    hook_arm(1); /* the first request would fail: none may be made */
    int status = fricreg_disk_ctx_eval(ctx, M_DENSE, zdot, a_free, f);
    int tangent = fricreg_disk_ctx_tangent(ctx, M_DENSE, T, T);
    hook_disarm();
    ck_assert_int_eq(status, FRICREG_OK);
    ck_assert_int_eq(tangent, FRICREG_OK);
    ck_assert_msg(n_allocs == 0, "%s eval and tangent made %ld allocations", what, n_allocs);
}

/* fricreg_disk_ctx.h: eval never allocates; neither does the tangent (Brent's solver and the
 * KKT storage are the context's). Contacts at rest, in the band and sliding, dense W. */
START_TEST(test_disk_eval_does_not_allocate)
{
    const double mun[M_DENSE] = {0.4125, 1.25, 0.3175, 2.0625, 0.8125};
    fricreg_disk_ctx *ctx = disk_dense_ctx();
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, M_DENSE, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.02), FRICREG_OK);
    expect_disk_eval_allocates_nothing(ctx, "disk");
    fricreg_disk_ctx_free(ctx);
}
END_TEST

START_TEST(test_ctx_set_stribeck)
{
    struct tally t = fail_each_allocation("ctx_set_stribeck", ctx_stribeck);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_disk_ctx_set_stribeck)
{
    struct tally t = fail_each_allocation("disk_ctx_set_stribeck", disk_ctx_stribeck);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* With Stribeck friction too, eval and tangent allocate nothing (contacts at rest, in the band
 * and sliding, dense W). */
START_TEST(test_disk_stribeck_eval_does_not_allocate)
{
    fricreg_disk_ctx *ctx = disk_dense_ctx();
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(ctx, M_DENSE, strib_fs, strib_fk, strib_vs,
                                                   strib_delta),
                     FRICREG_OK);
    expect_disk_eval_allocates_nothing(ctx, "disk Stribeck");
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* One stepper of each family: fricreg's classical RK4 (fixed steps), GSL's embedded explicit
 * rkf45 (adaptive), implicit Gaussian rk4imp, Bulirsch-Stoer bsimp, multistep msbdf, and
 * fricreg's central differences, explicit and with implicit friction (fixed steps). */
static const int integrators[] = {FRICREG_INT_RK4,         FRICREG_INT_RKF45, FRICREG_INT_RK4IMP,
                                  FRICREG_INT_BSIMP,       FRICREG_INT_MSBDF, FRICREG_INT_CENTRAL,
                                  FRICREG_INT_CENTRAL_IMEX};
#define N_INTEGRATORS (sizeof integrators / sizeof integrators[0])
static const int systems[] = {FRICREG_SYSTEM_OSCILLATOR, FRICREG_SYSTEM_CHAIN,
                              FRICREG_SYSTEM_TWOBLOCK};

START_TEST(test_sim_run)
{
    int system = systems[_i / (int)N_INTEGRATORS],
        integrator = integrators[_i % (int)N_INTEGRATORS];
    if (system == FRICREG_SYSTEM_TWOBLOCK && integrator == FRICREG_INT_CENTRAL_IMEX)
        return; /* refused (FRICREG_EINVAL) before the run allocates: test_central_imex.c */
    /* Fixed steps for rk4 and rk4imp (with the step guard's eigenvalue problem for rk4 on the
     * coupled two-block W), adaptive ones for the rest; a few steps are enough, every
     * allocation happens before the first. */
    int fixed = integrator == FRICREG_INT_RK4 || integrator == FRICREG_INT_RK4IMP ||
                integrator == FRICREG_INT_CENTRAL || integrator == FRICREG_INT_CENTRAL_IMEX;
    struct sim_case c = {system, integrator, 0.005, fixed ? 0.0 : 1e-6, 0.05};
    char name[64];
    snprintf(name, sizeof name, "sim %d %s", system, fricreg_integrator_name(integrator));
    current_sim = &c;
    fail_each_allocation(name, sim_run);
}
END_TEST

START_TEST(test_sim_run_extrapolated)
{
    struct tally t = fail_each_allocation("sim_run_extrapolated", sim_run_extrapolated);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_exact_run)
{
    struct tally t = fail_each_allocation("exact_create+run", exact_run);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_exact_solve)
{
    fail_each_allocation("exact_solve", exact_solve);
}
END_TEST

START_TEST(test_structure_run)
{
    static const char *const names[N_SCHEMES] = {"structure newmark", "structure hht",
                                                 "structure central difference",
                                                 "structure run_ode rkf45"};
    current_scheme = _i;
    fail_each_allocation(names[_i], structure_run);
}
END_TEST

/* fricreg_structure.h: steps never allocate once the first step after the model's setters
 * has handed W to the contacts, for every scheme (GSL 2.7's gsl_linalg_LU_decomp allocated in
 * each Newton iteration until 1.3). */
START_TEST(test_structure_steps_do_not_allocate)
{
    for (int scheme = SCHEME_NEWMARK; scheme <= SCHEME_CENTRAL; scheme++) {
        fricreg_structure *s = NULL;
        ck_assert_int_eq(fricreg_structure_create(3, 2, &s), FRICREG_OK);
        ck_assert_int_eq(structure_model(s), FRICREG_OK);
        if (scheme == SCHEME_HHT)
            ck_assert_int_eq(fricreg_structure_set_hht(s, -0.1), FRICREG_OK);
        if (scheme == SCHEME_CENTRAL)
            ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_step(s, 0.001), FRICREG_OK); /* forms W */
        hook_arm(1); /* the first request would fail: none may be made */
        int status = fricreg_structure_run(s, 0.001, 0.5);
        hook_disarm();
        ck_assert_int_eq(status, FRICREG_OK);
        ck_assert_msg(n_allocs == 0, "scheme %d: 499 steps made %ld allocations", scheme, n_allocs);
        int64_t iterations = 0;
        ck_assert_int_eq(fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS,
                                                    &iterations),
                         FRICREG_OK);
        ck_assert(scheme == SCHEME_CENTRAL || iterations >= 499); /* Newton ran in each step */
        fricreg_structure_free(s);
    }
}
END_TEST

static Suite *alloc_suite(void)
{
    Suite *s = suite_create("alloc_failure");
    TCase *core = tcase_create("core");
    tcase_add_test(core, test_ctx_create);
    tcase_add_test(core, test_ctx_set_coupling_dense);
    tcase_add_test(core, test_ctx_stick_stiffness);
    tcase_add_test(core, test_eval_does_not_allocate);
    tcase_add_test(core, test_structure_steps_do_not_allocate);
    tcase_add_test(core, test_disk_ctx_set_coupling_dense);
    tcase_add_test(core, test_disk_eval_does_not_allocate);
    tcase_add_test(core, test_ctx_set_stribeck);
    tcase_add_test(core, test_disk_ctx_set_stribeck);
    tcase_add_test(core, test_disk_stribeck_eval_does_not_allocate);
    suite_add_tcase(s, core);
    TCase *drivers = tcase_create("drivers");
    tcase_add_loop_test(drivers, test_sim_run, 0, (int)(3 * N_INTEGRATORS));
    tcase_add_test(drivers, test_sim_run_extrapolated);
    tcase_add_test(drivers, test_exact_run);
    tcase_add_test(drivers, test_exact_solve);
    tcase_add_loop_test(drivers, test_structure_run, 0, N_SCHEMES);
    suite_add_tcase(s, drivers);
    return s;
}

int main(void)
{
    gsl_set_error_handler_off(); /* the documented remedy: docs/reliability.md */
    SRunner *runner = srunner_create(alloc_suite());
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
