/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_alloc_failure.c — every allocation made on the way through the library, failed in turn,
 * and what each failure leaves behind.
 *
 * The program is linked with fricreg's objects and GSL's static archives under
 * -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free, so every allocation of fricreg
 * and of the GSL code it calls passes through the wrappers below (the C library's own do not),
 * and CHOLMOD's through SuiteSparse's allocator pointers, pointed at them in main().
 *
 * Each scenario is a script: an object created, then a list of calls on it (setters, an
 * evaluation, a run), then what can be seen of it (its getters, evaluations at fixed inputs,
 * and a further run that shows the object still works), compared bit for bit. The script is
 * played once with no failure to count its allocations n and to get the reference view, once
 * more per call with that call left out, then again for every k = 1..n with the k-th
 * allocation failing. Each case must:
 *   - when a call returns FRICREG_ENOMEM (recorded in the object, with a message), leave the
 *     object exactly as before it: every later status and the whole view equal those of the
 *     script played without that call ("nothing modified on failure"; a failed run leaves
 *     what its header says, e.g. level 0 of a failed extrapolation);
 *   - when every call returns FRICREG_OK although an allocation failed (a fallback), have done
 *     the calls' work: the view equals the reference;
 *   - never call GSL's error handler (GSL's default one aborts) except from
 *     gsl_odeiv2_step_alloc, and leave no block allocated once its objects are freed; a create
 *     that fails leaves the caller's handle as it was.
 * Leaving out a call must change the view (checked once per script), so that a call that
 * drops its work and returns FRICREG_OK cannot pass; calls that a later one replaces (the
 * first of two records, the first of two couplings) are marked and exempt. A replaced call
 * is there so that the replacing one has an old value to keep when it fails.
 *
 * fricreg never touches GSL's handler: a failed malloc inside GSL's own stepper allocation
 * reports to it, and a program that wants FRICREG_ENOMEM there instead of GSL's abort calls
 * gsl_set_error_handler_off() once at start (docs/reliability.md). This program does just that
 * in main(); the scenarios then count the handler's calls with a handler of their own, the
 * stepper allocation's apart. fricreg_ctx_eval, fricreg_disk_ctx_eval and _tangent, a
 * structure's steps after the first, the AFT's evaluations, the Iwan elements' calls after
 * create and a dense harmonic-balance driver's solve must not allocate at all. The
 * harmonic-balance driver's solve, displacement and continue have a loop of their own
 * (test_hb_solve_continue): every allocation inside them fails in turn, on a driver set up
 * beforehand. Run under valgrind or ASan, the
 * same loops also check what the counting cannot: no invalid access on any failure path.
 * FRICREG_ALLOC_FAILURE_STRIDE=s in the environment fails only every s-th request (the first
 * and the last always): the release tier's valgrind run, whose every case the ASan run has
 * already failed in turn, looks for uninitialised reads on a quarter of them. */
#include <check.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <SuiteSparse_config.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_odeiv2.h>

#include "fricreg.h"
#include "fricreg_aft.h"
#include "fricreg_hb.h"
#include "fricreg_disk_ctx.h"
#include "fricreg_iwan.h"
#include "fricreg_fit.h"
#include "fricreg_jenkins.h"
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
static int paused;       /* while armed: neither count nor fail (a script's view), but track */
static long n_allocs;    /* allocation requests while armed */
static long fail_at;     /* the request that fails (1-based); 0: none */
static long n_failed;    /* requests failed on purpose */
static long n_unchecked; /* requests made inside GSL's unchecked steppers (below), not failed */
static long live;        /* blocks allocated through the hook and not freed */

/* The next request to fail after k of n: every stride-th, and the last one. */
static long next_failure(long k, long n)
{
    static long stride;
    if (stride == 0) {
        const char *s = getenv("FRICREG_ALLOC_FAILURE_STRIDE");
        stride = s ? strtol(s, NULL, 10) : 1;
        if (stride < 1)
            stride = 1;
    }
    return k < n && k + stride > n ? n : k + stride;
}

/* Check (linked statically on Debian) allocates too, in its assertions: the scenarios run
 * between hook_arm and hook_disarm make none, and record what they find in `violation`. */
static void hook_arm(long k)
{
    n_allocs = n_failed = n_unchecked = 0;
    fail_at = k;
    paused = 0;
    armed = 1;
}

static void hook_disarm(void)
{
    armed = 0;
    paused = 0;
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

gsl_multifit_nlinear_workspace *
__real_gsl_multifit_nlinear_alloc(const gsl_multifit_nlinear_type *T,
                                  const gsl_multifit_nlinear_parameters *params, size_t n,
                                  size_t p);

/* A fit's least-squares workspace (fricreg_fit_run): GSL's own allocator, which reports a
 * failed malloc through the handler, as gsl_odeiv2_step_alloc does, and (GSL 2.7) leaks what it
 * had allocated before: trust_alloc and qr_alloc free nothing on a NULL. Its allocations are
 * made but never failed, as the unchecked steppers' (docs/reliability.md); fricreg_fit_run's
 * check of its NULL is read, not run, here. */
gsl_multifit_nlinear_workspace *
__wrap_gsl_multifit_nlinear_alloc(const gsl_multifit_nlinear_type *T,
                                  const gsl_multifit_nlinear_parameters *params, size_t n, size_t p)
{
    in_unchecked++;
    gsl_multifit_nlinear_workspace *w = __real_gsl_multifit_nlinear_alloc(T, params, n, p);
    in_unchecked--;
    return w;
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
    if (armed && !paused && in_unchecked)
        n_unchecked++;
    if (!armed || paused || in_unchecked || ++n_allocs != fail_at)
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

/* ---- Scripts: calls on one object, and what can be seen of it ------------------------------ */

#define MAX_CALLS 16
#define MAX_SEEN 1024

/* What one play of a script shows: each call's status (-1: left out) and, afterwards, what can
 * be seen of the object (getters, evaluations, a further run) as doubles, compared bit for
 * bit; the script's own outputs (an evaluation's forces) are appended on success. */
struct view {
    int status[MAX_CALLS];
    size_t n;
    double seen[MAX_SEEN];
};

static void see(struct view *v, double x)
{
    if (v->n < MAX_SEEN)
        v->seen[v->n++] = x;
    else
        NOTE("the view overflows its %d entries", MAX_SEEN);
}

static void see_all(struct view *v, const double x[], size_t n)
{
    for (size_t k = 0; k < n; k++)
        see(v, x[k]);
}

struct script {
    const char *name;
    int ncalls;
    const char *const *call_names;
    unsigned replaced;    /* bit i: a later call replaces call i's work */
    unsigned has_partial; /* bit i: a failed call i may also leave `partial` (documented) */
    int (*open)(void **obj);
    int (*call)(void *obj, int i, struct view *v);
    int (*partial)(void *obj, int i, struct view *v);
    void (*observe)(void *obj, struct view *v);
    int (*errcode)(const void *obj);
    void (*close)(void *obj);
};

/* One play with the k-th allocation failing (none for k = 0), call `skip` left out and call
 * `alt` replaced by the script's partial (-1: none). Returns the create's status; in *failed
 * the first call that returned FRICREG_ENOMEM (-1: none). Allocations are counted up to the
 * view, which is neither counted nor failed. */
static int play(const struct script *sc, long k, int skip, int alt, struct view *v, int *failed)
{
    void *obj = NULL;
    memset(v, 0, sizeof *v);
    *failed = -1;
    hook_arm(k);
    int status = sc->open(&obj);
    if (status == FRICREG_OK) {
        for (int i = 0; i < sc->ncalls; i++) {
            if (i == skip) {
                v->status[i] = -1;
                continue;
            }
            int s = i == alt ? sc->partial(obj, i, v) : sc->call(obj, i, v);
            v->status[i] = s;
            if (s != FRICREG_OK && sc->errcode(obj) != s)
                NOTE("%s: status %d, but %d recorded", sc->call_names[i], s, sc->errcode(obj));
            if (s == FRICREG_ENOMEM && *failed < 0)
                *failed = i;
        }
        paused = 1;
        sc->observe(obj, v);
        sc->close(obj);
    }
    hook_disarm();
    return status;
}

/* Where two plays differ: the first call (other than `except`) whose status differs, or the
 * first entry of the views; "" if they agree bit for bit. */
static const char *difference(const struct view *a, const struct view *b, int ncalls, int except,
                              const struct script *sc)
{
    static char where[200];
    where[0] = '\0';
    for (int i = 0; i < ncalls; i++)
        if (i != except && a->status[i] != b->status[i]) {
            snprintf(where, sizeof where, "%s returned %d instead of %d", sc->call_names[i],
                     a->status[i], b->status[i]);
            return where;
        }
    if (a->n != b->n) {
        snprintf(where, sizeof where, "the view has %zu entries instead of %zu", a->n, b->n);
        return where;
    }
    for (size_t k = 0; k < a->n; k++)
        if (memcmp(&a->seen[k], &b->seen[k], sizeof(double)) != 0) {
            snprintf(where, sizeof where, "view entry %zu is %.17g instead of %.17g", k, a->seen[k],
                     b->seen[k]);
            return where;
        }
    return where;
}

struct tally {
    long cases, enomem, ok;
    long unreached, bad_status, unrecorded, aborts, leaks, changed, undone; /* each stays 0 */
    char first[512]; /* the first of those, described */
};

/* Counts a broken promise in *count and keeps the first description. */
#define BROKEN(t, count, ...)                                  \
    do {                                                       \
        (t).count++;                                           \
        if ((t).first[0] == '\0')                              \
            snprintf((t).first, sizeof(t).first, __VA_ARGS__); \
    } while (0)

static struct view ref_full, ref_skip[MAX_CALLS], ref_partial[MAX_CALLS], got;

/* Plays the script with no failure, once per call with that call left out (or replaced by its
 * partial), then with the k-th allocation failing for every k; every case runs, and the test
 * fails at the end with the counts and the first broken promise. */
static struct tally fail_each_allocation(const struct script *sc)
{
    struct tally t = {0};
    const char *name = sc->name;
    gsl_set_error_handler(count_gsl_error);
    gsl_step_alloc_reports = 0;
    ck_assert_int_le(sc->ncalls, MAX_CALLS);
    int failed = -1;
    long live_before = live;
    violation[0] = '\0';
    gsl_handler_calls = 0;
    int status = play(sc, 0, -1, -1, &ref_full, &failed);
    long n = n_allocs;
    ck_assert_msg(status == FRICREG_OK && violation[0] == '\0' && live == live_before,
                  "%s: status %d with no failure injected %s", name, status, violation);
    for (int i = 0; i < sc->ncalls; i++)
        ck_assert_msg(ref_full.status[i] == FRICREG_OK, "%s: %s returned %d with no failure", name,
                      sc->call_names[i], ref_full.status[i]);
    ck_assert_msg(n > 0, "%s: allocates nothing, so the loop tests nothing", name);
    for (int i = 0; i < sc->ncalls; i++) {
        play(sc, 0, i, -1, &ref_skip[i], &failed);
        ck_assert_msg(violation[0] == '\0', "%s without %s: %s", name, sc->call_names[i],
                      violation);
        ck_assert_msg((sc->replaced >> i & 1) ||
                          difference(&ref_skip[i], &ref_full, sc->ncalls, i, sc)[0] != '\0',
                      "%s: leaving out %s changes nothing that can be seen, so a failure that "
                      "dropped its work would pass",
                      name, sc->call_names[i]);
        if (sc->has_partial >> i & 1)
            play(sc, 0, -1, i, &ref_partial[i], &failed);
    }
    ck_assert_int_eq(gsl_handler_calls, 0);
    for (long k = 1; k <= n; k = next_failure(k, n)) {
        live_before = live;
        violation[0] = '\0';
        gsl_handler_calls = 0;
        status = play(sc, k, -1, -1, &got, &failed);
        t.cases++;
        t.enomem += status == FRICREG_ENOMEM || failed >= 0;
        t.ok += status == FRICREG_OK && failed < 0;
        if (n_failed != 1)
            BROKEN(t, unreached, "allocation %ld of %ld not reached (%ld made)", k, n, n_allocs);
        if (status != FRICREG_OK && status != FRICREG_ENOMEM)
            BROKEN(t, bad_status, "allocation %ld of %ld failed: create returned %d (%s)", k, n,
                   status, fricreg_strerror(status));
        else if (status == FRICREG_OK && failed < 0) {
            const char *d = difference(&got, &ref_full, sc->ncalls, -1, sc);
            if (d[0] != '\0')
                BROKEN(t, undone,
                       "allocation %ld of %ld failed, every call returned OK or its own status, "
                       "but %s: a call did not do its work",
                       k, n, d);
        } else if (status == FRICREG_OK) {
            const char *d = difference(&got, &ref_skip[failed], sc->ncalls, failed, sc);
            if (d[0] != '\0' && (sc->has_partial >> failed & 1))
                d = difference(&got, &ref_partial[failed], sc->ncalls, failed, sc);
            if (d[0] != '\0')
                BROKEN(t, changed,
                       "allocation %ld of %ld failed in %s (ENOMEM), but the object is not as "
                       "before it: %s",
                       k, n, sc->call_names[failed], d);
        }
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
           "%ld OK; %ld changed by a failure, %ld OK but undone, %ld aborts, %ld leaks, %ld "
           "other status, %ld unrecorded, %ld unreached; %ld reports from "
           "gsl_odeiv2_step_alloc\n",
           name, n, n_unchecked, t.cases, t.enomem, t.ok, t.changed, t.undone, t.aborts, t.leaks,
           t.bad_status, t.unrecorded, t.unreached, gsl_step_alloc_reports);
    fflush(stdout); /* Check's child exits without flushing on a failed assertion */
    ck_assert_msg(t.unreached + t.bad_status + t.unrecorded + t.aborts + t.leaks + t.changed +
                          t.undone ==
                      0,
                  "%s: %s", name, t.first);
    return t;
}

/* ---- 1-D contexts ---------------------------------------------------------------------------- */

#define M_DENSE 5

/* A symmetric positive definite 5 x 5 W with unequal entries: tridiagonal, diagonally
 * dominant (Gershgorin: every eigenvalue >= 2.385 - 2 * 0.731 > 0); `off` the off-diagonal. */
static void dense_w(double W[M_DENSE * M_DENSE], double off)
{
    for (size_t i = 0; i < M_DENSE; i++)
        for (size_t j = 0; j < M_DENSE; j++)
            W[i * M_DENSE + j] = i == j                       ? 2.385 + 0.25 * (double)i
                                 : (i + 1 == j || j + 1 == i) ? off
                                                              : 0.0;
}

static const double MUN5[M_DENSE] = {0.4125, 1.25, 0.3175, 2.0625, 0.8125};
/* Inputs of the evaluations: contacts at rest, in the band and sliding. */
static const double ZDOT5[3][M_DENSE] = {{1e-5, -0.375, 2.5e-4, 0.0, 1.875},
                                         {0.0, 0.0, 0.0, 0.0, 0.0},
                                         {-3e-3, 1e-2, 0.0, 7e-3, -2e-4}};
static const double AFREE5[3][M_DENSE] = {{0.9375, -3.25, 0.0625, 1.625, -0.4375},
                                          {0.5, -0.25, 3.0, -1.5, 0.125},
                                          {-0.75, 0.3, 0.2, 2.5, -1.0}};

/* Stribeck friction (fricreg_ctx_set_stribeck, fricreg_disk_ctx_set_stribeck). */
static const double strib_fs[M_DENSE] = {0.5, 1.25, 0.75, 2.0, 0.875};
static const double strib_fk[M_DENSE] = {0.25, 1.0, 0.75, 0.5, 0.5};
static const double strib_vs[M_DENSE] = {0.01, 0.02, 0.005, 0.04, 0.01};
static const double strib_delta[M_DENSE] = {1.0, 2.0, 0.5, 1.0, 1.5};

static char sentinel_byte; /* a create's handle before the call: must stay if it fails */
#define SENTINEL ((void *)&sentinel_byte)

static int ctx_open(void **obj)
{
    fricreg_ctx *ctx = SENTINEL;
    int status = fricreg_ctx_create(M_DENSE, &ctx);
    if (status != FRICREG_OK && ctx != SENTINEL)
        NOTE("ctx_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? ctx : NULL;
    return status;
}

static int ctx_errcode(const void *obj)
{
    return fricreg_ctx_errcode(obj);
}

static void ctx_close(void *obj)
{
    fricreg_ctx_free(obj);
}

/* The context's tangent (its status, and the matrices on success). */
static void see_ctx_tangent(fricreg_ctx *ctx, struct view *v)
{
    double Fz[M_DENSE * M_DENSE], Fa[M_DENSE * M_DENSE];
    int status = fricreg_ctx_tangent(ctx, M_DENSE, Fz, Fa);
    see(v, status);
    if (status == FRICREG_OK) {
        see_all(v, Fz, M_DENSE * M_DENSE);
        see_all(v, Fa, M_DENSE * M_DENSE);
    }
}

/* An evaluation at input set p, its forces appended on success. */
static int ctx_eval(fricreg_ctx *ctx, int p, struct view *v)
{
    double f[M_DENSE], f_eq[M_DENSE];
    int status = fricreg_ctx_eval(ctx, M_DENSE, ZDOT5[p], AFREE5[p], f, f_eq);
    if (status == FRICREG_OK) {
        see_all(v, f, M_DENSE);
        see_all(v, f_eq, M_DENSE);
    }
    return status;
}

/* What can be seen of a context: the tangent of its last evaluation, evaluations at the three
 * input sets under both partitions (each with its tangent), the stick stiffness, the counters. */
static void ctx_observe(void *obj, struct view *v)
{
    fricreg_ctx *ctx = obj;
    see_ctx_tangent(ctx, v);
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        see(v, fricreg_ctx_set_partition(ctx, partition));
        for (int p = 0; p < 3; p++) {
            see(v, ctx_eval(ctx, p, v));
            see_ctx_tangent(ctx, v);
        }
    }
    double lambda = -1.0;
    see(v, fricreg_ctx_stick_stiffness(ctx, &lambda));
    see(v, lambda);
    for (int which = FRICREG_STAT_EVALS; which <= FRICREG_STAT_FACTOR_UPDATES; which++) {
        int64_t count = -1;
        see(v, fricreg_ctx_get_stat(ctx, which, &count));
        see(v, (double)count);
    }
    /* Stribeck friction off: the bounds of set_bounds show (kept while it was on) */
    see(v, fricreg_ctx_set_stribeck(ctx, 0, NULL, NULL, NULL, NULL));
    see(v, ctx_eval(ctx, 2, v));
}

/* A context set up and evaluated, then given a second W: a failed set_coupling_dense keeps the
 * first W, its factor and the tangent of the evaluation. */
static const char *const ctx_coupling_calls[] = {"set_coupling_dense(W1)", "set_bounds", "set_law",
                                                 "eval", "set_coupling_dense(W2)"};

static int ctx_coupling_call(void *obj, int i, struct view *v)
{
    double W[M_DENSE * M_DENSE];
    dense_w(W, i == 0 ? -0.731 : 0.615);
    switch (i) {
    case 0:
    case 4: return fricreg_ctx_set_coupling_dense(obj, M_DENSE, W);
    case 1: return fricreg_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_ctx_set_law(obj, FRICREG_LAW_QUINN, 0.02);
    default: return ctx_eval(obj, 0, v);
    }
}

static const struct script ctx_coupling = {
    "ctx set_coupling_dense", 5,    ctx_coupling_calls, 0,           0,        ctx_open,
    ctx_coupling_call,        NULL, ctx_observe,        ctx_errcode, ctx_close};

/* fricreg_ctx_solve_step (fricreg_structure.h) on a coupled context: its solver (CHOLMOD's
 * copies of W and W_eff, the analysis, the Newton matrix, the vectors) is built at the first
 * call, before any evaluation, and kept in the context while W's and W_eff's patterns hold:
 * the second call (new values, same patterns) reuses it and allocates nothing, the third
 * (another pattern of W_eff) builds a new one, the fourth reuses that. A failed call writes
 * neither f nor info, leaves the context's last evaluation as it was and keeps no solver, so
 * that the next call builds one: its answer must be the warm solver's, bit for bit (the view
 * of the script without the failed call). */
static const char *const ctx_solve_step_calls[] = {"set_coupling_dense",
                                                   "set_bounds",
                                                   "set_law",
                                                   "solve_step",
                                                   "solve_step (reused)",
                                                   "solve_step (new pattern)",
                                                   "solve_step (reused again)"};

static int ctx_solve_step_call(void *obj, int i, struct view *v)
{
    double W[M_DENSE * M_DENSE], Weff[M_DENSE * M_DENSE], f[M_DENSE];
    dense_w(W, -0.731);
    switch (i) {
    case 0: return fricreg_ctx_set_coupling_dense(obj, M_DENSE, W);
    case 1: return fricreg_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_ctx_set_law(obj, FRICREG_LAW_QUINN, 0.02);
    default: {
        /* calls 3, 4: W_eff tridiagonal as W, other values; 5, 6: diagonal */
        double scale = i == 3 ? 0.05 : i == 4 ? 0.0625 : 0.04 + 0.01 * (i - 5);
        for (size_t k = 0; k < M_DENSE * M_DENSE; k++)
            Weff[k] = i >= 5 && k % (M_DENSE + 1) != 0 ? 0.0 : scale * W[k];
        for (size_t k = 0; k < M_DENSE; k++)
            f[k] = 0.5 * MUN5[k];
        int info[2] = {-7, -7};
        long before = n_allocs;
        int status = fricreg_ctx_solve_step(obj, M_DENSE, ZDOT5[0], ZDOT5[2], AFREE5[i % 3], W,
                                            Weff, 0.01, 1e-12, 50, 0, f, info);
        if ((i == 4 || i == 6) && v->status[i - 1] == FRICREG_OK && n_allocs != before)
            NOTE("solve_step on a kept solver made %ld allocations", n_allocs - before);
        if (status != FRICREG_OK && (info[0] != -7 || info[1] != -7 || f[0] != 0.5 * MUN5[0]))
            NOTE("solve_step: status %d but f or info written", status);
        if (status == FRICREG_OK) {
            see_all(v, f, M_DENSE);
            see(v, info[0]);
            see(v, info[1]);
        }
        return status;
    }
    }
}

static const struct script ctx_solve_step = {
    "ctx solve_step",    7,    ctx_solve_step_calls, 0,           0,        ctx_open,
    ctx_solve_step_call, NULL, ctx_observe,          ctx_errcode, ctx_close};

/* The step guard's eigenvalue problem: the paper's partition with a dense W (stiffness.c). A
 * failed call writes no lambda and changes nothing. */
static const char *const ctx_stiffness_calls[] = {"set_coupling_dense", "set_bounds",
                                                  "set_partition", "stick_stiffness"};

static int ctx_stiffness_call(void *obj, int i, struct view *v)
{
    double W[M_DENSE * M_DENSE], lambda = -2.385;
    dense_w(W, -0.731);
    switch (i) {
    case 0: return fricreg_ctx_set_coupling_dense(obj, M_DENSE, W);
    case 1: return fricreg_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_ctx_set_partition(obj, FRICREG_PARTITION_PAPER);
    default: {
        int status = fricreg_ctx_stick_stiffness(obj, &lambda);
        if (status != FRICREG_OK && lambda != -2.385)
            NOTE("stick_stiffness: status %d but lambda written", status);
        if (status == FRICREG_OK)
            see(v, lambda);
        return status;
    }
    }
}

static const struct script ctx_stiffness = {
    "ctx stick_stiffness", 4,    ctx_stiffness_calls, 0,           0,        ctx_open,
    ctx_stiffness_call,    NULL, ctx_observe,         ctx_errcode, ctx_close};

/* Stribeck friction (set_stribeck allocates at its first call) over another law: a failed call
 * keeps that law, its eps and the bounds (fricreg_stribeck.h). */
static const char *const ctx_stribeck_calls[] = {"set_coupling_dense", "set_bounds", "set_law",
                                                 "set_stribeck", "eval"};

static int ctx_stribeck_call(void *obj, int i, struct view *v)
{
    double W[M_DENSE * M_DENSE];
    dense_w(W, -0.731);
    switch (i) {
    case 0: return fricreg_ctx_set_coupling_dense(obj, M_DENSE, W);
    case 1: return fricreg_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_ctx_set_law(obj, FRICREG_LAW_TANH, 0.05);
    case 3:
        return fricreg_ctx_set_stribeck(obj, M_DENSE, strib_fs, strib_fk, strib_vs, strib_delta);
    default: return ctx_eval(obj, 2, v);
    }
}

static const struct script ctx_stribeck = {
    "ctx set_stribeck", 5,    ctx_stribeck_calls, 0,           0,        ctx_open,
    ctx_stribeck_call,  NULL, ctx_observe,        ctx_errcode, ctx_close};

/* A sparse W: dense_w's tridiagonal W as CSR (whole, zero-based) or one-based CSC of its
 * upper triangle. A failed set_coupling_csc keeps the first W, its factor and the tangent of
 * the evaluation. The view's evaluations, tangents and tangent products run on it. */
static size_t sparse_w(double off, int csc, int64_t ptr[M_DENSE + 1], int64_t ind[], double val[])
{
    double W[M_DENSE * M_DENSE];
    dense_w(W, off);
    size_t n = 0;
    for (size_t i = 0; i < M_DENSE; i++) {
        ptr[i] = (int64_t)n + csc;
        for (size_t j = csc ? 0 : 0; j < M_DENSE; j++)
            if (W[i * M_DENSE + j] != 0.0 && (!csc || j <= i)) {
                ind[n] = (int64_t)j + csc;
                val[n++] = W[i * M_DENSE + j];
            }
    }
    ptr[M_DENSE] = (int64_t)n + csc;
    return n;
}

static void see_ctx_tangent_apply(fricreg_ctx *ctx, struct view *v)
{
    double df[M_DENSE];
    int status = fricreg_ctx_tangent_apply(ctx, M_DENSE, ZDOT5[2], AFREE5[1], df);
    see(v, status);
    if (status == FRICREG_OK)
        see_all(v, df, M_DENSE);
}

static void ctx_sparse_observe(void *obj, struct view *v)
{
    see_ctx_tangent_apply(obj, v);
    ctx_observe(obj, v);
    see_ctx_tangent_apply(obj, v);
}

static const char *const ctx_sparse_calls[] = {"set_coupling_csr(W1)", "set_bounds", "set_law",
                                               "eval", "set_coupling_csc(W2)"};

static int ctx_sparse_call(void *obj, int i, struct view *v)
{
    int64_t ptr[M_DENSE + 1], ind[M_DENSE * M_DENSE];
    double val[M_DENSE * M_DENSE];
    switch (i) {
    case 0:
        sparse_w(-0.731, 0, ptr, ind, val);
        return fricreg_ctx_set_coupling_csr(obj, M_DENSE, 0, ptr, ind, val);
    case 4:
        sparse_w(0.615, 1, ptr, ind, val);
        /* row i's entries j <= i read as columns: the upper triangle */
        return fricreg_ctx_set_coupling_csc(obj, M_DENSE,
                                            FRICREG_SPARSE_ONE_BASED | FRICREG_SPARSE_UPPER, ptr,
                                            ind, val);
    case 1: return fricreg_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_ctx_set_law(obj, FRICREG_LAW_QUINN, 0.02);
    default: return ctx_eval(obj, 0, v);
    }
}

static const struct script ctx_sparse = {"ctx set_coupling_csr/csc",
                                         5,
                                         ctx_sparse_calls,
                                         0,
                                         0,
                                         ctx_open,
                                         ctx_sparse_call,
                                         NULL,
                                         ctx_sparse_observe,
                                         ctx_errcode,
                                         ctx_close};

/* create alone: a failure leaves no handle; the view is the defaults' (W = I, law (4)). */
static const struct script ctx_create = {"ctx create", 0,    NULL, 0,           0,
                                         ctx_open,     NULL, NULL, ctx_observe, ctx_errcode,
                                         ctx_close};

/* ---- 2-D contexts ---------------------------------------------------------------------------- */

/* A dense W of order 2m: W = I + 0.1 (coupling); `scale` changes its coupling. */
static void disk_dense_w(double W[], double scale)
{
    for (size_t i = 0; i < 2 * M_DENSE; i++)
        for (size_t j = 0; j < 2 * M_DENSE; j++)
            W[i * 2 * M_DENSE + j] = i == j ? 1.0 + 0.125 * (double)i
                                            : scale / (1.0 + (double)(i > j ? i - j : j - i));
}

/* Anisotropic blocks, contact i's at [4i..4i+3]. */
static void disk_blocks(double w[4 * M_DENSE])
{
    for (size_t i = 0; i < M_DENSE; i++) {
        w[4 * i] = 1.5 + 0.25 * (double)i;
        w[4 * i + 1] = w[4 * i + 2] = 0.3 - 0.1 * (double)i;
        w[4 * i + 3] = 0.875 + 0.125 * (double)i;
    }
}

static const double DZDOT[3][2 * M_DENSE] = {{1e-5, 2e-3, -0.375, 0.0, 0.0, 0.0, 0.0, 1e-3, 1.875,
                                              0.5},
                                             {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
                                             {-3e-3, 1e-2, 0.0, 7e-3, -2e-4, 0.0, 5e-3, -5e-3, 0.0,
                                              0.0}};
static const double DAFREE[3][2 * M_DENSE] = {
    {0.9375, -3.25, 0.0625, 1.625, -0.4375, 0.25, 2.0, -1.0, 0.5, 0.125},
    {0.5, -0.25, 3.0, -1.5, 0.125, 0.75, -0.625, 0.375, 1.25, -2.0},
    {-0.75, 0.3, 0.2, 2.5, -1.0, 0.6, 0.0, -0.4, 0.9, 0.1}};

static int disk_open(void **obj)
{
    fricreg_disk_ctx *ctx = SENTINEL;
    int status = fricreg_disk_ctx_create(M_DENSE, &ctx);
    if (status != FRICREG_OK && ctx != SENTINEL)
        NOTE("disk_ctx_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? ctx : NULL;
    return status;
}

static int disk_errcode(const void *obj)
{
    return fricreg_disk_ctx_errcode(obj);
}

static void disk_close(void *obj)
{
    fricreg_disk_ctx_free(obj);
}

static void see_disk_tangent(fricreg_disk_ctx *ctx, struct view *v)
{
    static double Fz[4 * M_DENSE * M_DENSE], Fa[4 * M_DENSE * M_DENSE];
    int status = fricreg_disk_ctx_tangent(ctx, M_DENSE, Fz, Fa);
    see(v, status);
    if (status == FRICREG_OK) { /* the diagonal blocks: the view's room is limited */
        for (size_t i = 0; i < 2 * M_DENSE; i++) {
            see(v, Fz[i * 2 * M_DENSE + i]);
            see(v, Fa[i * 2 * M_DENSE + (i ^ 1)]);
        }
        double sum = 0.0; /* and every entry, through a sum that is the same bit for bit */
        for (size_t k = 0; k < 4 * M_DENSE * M_DENSE; k++)
            sum += Fz[k] * (double)(k + 1) + Fa[k] / (double)(k + 1);
        see(v, sum);
    }
}

static int disk_eval(fricreg_disk_ctx *ctx, int p, struct view *v)
{
    double f[2 * M_DENSE];
    int status = fricreg_disk_ctx_eval(ctx, M_DENSE, DZDOT[p], DAFREE[p], f);
    if (status == FRICREG_OK)
        see_all(v, f, 2 * M_DENSE);
    return status;
}

/* The tangent of the last evaluation, then evaluations at the three input sets with theirs. */
static void disk_observe(void *obj, struct view *v)
{
    see_disk_tangent(obj, v);
    for (int p = 0; p < 3; p++) {
        see(v, disk_eval(obj, p, v));
        see_disk_tangent(obj, v);
    }
    /* Stribeck friction off: the bounds of set_bounds show (kept while it was on) */
    see(v, fricreg_disk_ctx_set_stribeck(obj, 0, NULL, NULL, NULL, NULL));
    see(v, disk_eval(obj, 2, v));
}

/* A dense W, evaluated, then blocks (a failure keeps the dense W and the tangent), or blocks
 * then a dense W (a failure keeps the blocks). */
static const char *const disk_dense_calls[] = {"set_coupling_dense", "set_bounds", "set_law",
                                               "eval", "set_coupling_blocks"};
static const char *const disk_blocks_calls[] = {"set_coupling_blocks", "set_bounds", "set_law",
                                                "eval", "set_coupling_dense"};

static int disk_coupling_call(void *obj, int i, struct view *v, int dense_first)
{
    double W[4 * M_DENSE * M_DENSE], w[4 * M_DENSE];
    disk_dense_w(W, 0.1);
    disk_blocks(w);
    switch (i) {
    case 0:
    case 4:
        return (i == 0) == dense_first ? fricreg_disk_ctx_set_coupling_dense(obj, M_DENSE, W)
                                       : fricreg_disk_ctx_set_coupling_blocks(obj, M_DENSE, w);
    case 1: return fricreg_disk_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_disk_ctx_set_law(obj, FRICREG_DISK_QUINN, 0.02);
    default: return disk_eval(obj, 0, v);
    }
}

static int disk_dense_call(void *obj, int i, struct view *v)
{
    return disk_coupling_call(obj, i, v, 1);
}

static int disk_blocks_call(void *obj, int i, struct view *v)
{
    return disk_coupling_call(obj, i, v, 0);
}

static const struct script disk_dense = {"disk_ctx set_coupling_dense, then blocks",
                                         5,
                                         disk_dense_calls,
                                         0,
                                         0,
                                         disk_open,
                                         disk_dense_call,
                                         NULL,
                                         disk_observe,
                                         disk_errcode,
                                         disk_close};
static const struct script disk_blocks_script = {"disk_ctx set_coupling_blocks, then dense",
                                                 5,
                                                 disk_blocks_calls,
                                                 0,
                                                 0,
                                                 disk_open,
                                                 disk_blocks_call,
                                                 NULL,
                                                 disk_observe,
                                                 disk_errcode,
                                                 disk_close};

/* Stribeck friction (allocates at its first call) over the force-balance law: a failed call
 * keeps that law and the bounds (fricreg_stribeck.h). */
static const char *const disk_stribeck_calls[] = {"set_coupling_dense", "set_bounds", "set_law",
                                                  "set_stribeck", "eval"};

static int disk_stribeck_call(void *obj, int i, struct view *v)
{
    double W[4 * M_DENSE * M_DENSE];
    disk_dense_w(W, 0.1);
    switch (i) {
    case 0: return fricreg_disk_ctx_set_coupling_dense(obj, M_DENSE, W);
    case 1: return fricreg_disk_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_disk_ctx_set_law(obj, FRICREG_DISK_FORCE_BALANCE, 0.05);
    case 3:
        return fricreg_disk_ctx_set_stribeck(obj, M_DENSE, strib_fs, strib_fk, strib_vs,
                                             strib_delta);
    default: return disk_eval(obj, 2, v);
    }
}

static const struct script disk_stribeck = {"disk_ctx set_stribeck",
                                            5,
                                            disk_stribeck_calls,
                                            0,
                                            0,
                                            disk_open,
                                            disk_stribeck_call,
                                            NULL,
                                            disk_observe,
                                            disk_errcode,
                                            disk_close};

static const struct script disk_create = {
    "disk_ctx create", 0,         NULL, 0, 0, disk_open, NULL, NULL, disk_observe,
    disk_errcode,      disk_close};

/* A sparse W (fricreg_disk_ctx_set_coupling_csr, _csc): disk_dense_w's W by compressed rows,
 * its upper triangle, one-based (duplicates: its diagonal given as two halves). A failure
 * keeps the W before it: a sparse W then dense, or dense then sparse. */
enum { SPARSE_N = 2 * M_DENSE, SPARSE_NNZ = SPARSE_N * (SPARSE_N + 1) / 2 + SPARSE_N };
static int64_t sparse_ptr[SPARSE_N + 1], sparse_ind[SPARSE_NNZ];
static double sparse_val[SPARSE_NNZ];

static void disk_sparse_w(void)
{
    double W[4 * M_DENSE * M_DENSE];
    disk_dense_w(W, 0.1);
    int64_t e = 0;
    for (size_t r = 0; r < SPARSE_N; r++) {
        sparse_ptr[r] = e + 1;
        for (size_t c = r; c < SPARSE_N; c++) {
            int halves = c == r ? 2 : 1;
            for (int h = 0; h < halves; h++) {
                sparse_ind[e] = (int64_t)c + 1;
                sparse_val[e++] = W[r * SPARSE_N + c] / halves;
            }
        }
    }
    sparse_ptr[SPARSE_N] = e + 1;
}

static const char *const disk_sparse_calls[] = {"set_coupling_csr", "set_bounds", "set_law", "eval",
                                                "set_coupling_dense"};
static const char *const disk_dense_sparse_calls[] = {"set_coupling_dense", "set_bounds", "set_law",
                                                      "eval", "set_coupling_csc"};

static int disk_sparse_coupling_call(void *obj, int i, struct view *v, int sparse_first)
{
    double W[4 * M_DENSE * M_DENSE];
    disk_dense_w(W, -0.05);
    disk_sparse_w();
    const int flags = FRICREG_SPARSE_ONE_BASED | FRICREG_SPARSE_UPPER;
    switch (i) {
    case 0:
    case 4:
        if ((i == 0) != sparse_first)
            return fricreg_disk_ctx_set_coupling_dense(obj, M_DENSE, W);
        return i == 0 ? fricreg_disk_ctx_set_coupling_csr(obj, M_DENSE, flags, sparse_ptr,
                                                          sparse_ind, sparse_val)
                      : fricreg_disk_ctx_set_coupling_csc(obj, M_DENSE,
                                                          FRICREG_SPARSE_ONE_BASED |
                                                              FRICREG_SPARSE_LOWER,
                                                          sparse_ptr, sparse_ind, sparse_val);
    case 1: return fricreg_disk_ctx_set_bounds(obj, M_DENSE, MUN5);
    case 2: return fricreg_disk_ctx_set_law(obj, FRICREG_DISK_QUINN, 0.02);
    default: return disk_eval(obj, 0, v);
    }
}

static int disk_sparse_call(void *obj, int i, struct view *v)
{
    return disk_sparse_coupling_call(obj, i, v, 1);
}

static int disk_dense_sparse_call(void *obj, int i, struct view *v)
{
    return disk_sparse_coupling_call(obj, i, v, 0);
}

static const struct script disk_sparse = {"disk_ctx set_coupling_csr, then dense",
                                          5,
                                          disk_sparse_calls,
                                          0,
                                          0,
                                          disk_open,
                                          disk_sparse_call,
                                          NULL,
                                          disk_observe,
                                          disk_errcode,
                                          disk_close};
static const struct script disk_dense_sparse = {"disk_ctx set_coupling_dense, then csc",
                                                5,
                                                disk_dense_sparse_calls,
                                                0,
                                                0,
                                                disk_open,
                                                disk_dense_sparse_call,
                                                NULL,
                                                disk_observe,
                                                disk_errcode,
                                                disk_close};

/* ---- Simulations ----------------------------------------------------------------------------- */

static int current_system, current_integrator;

static int sim_open(void **obj)
{
    fricreg_sim *sim = SENTINEL;
    int status = fricreg_sim_create(current_system, &sim);
    if (status != FRICREG_OK && sim != SENTINEL)
        NOTE("sim_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? sim : NULL;
    return status;
}

static int sim_errcode(const void *obj)
{
    return fricreg_sim_errcode(obj);
}

static void sim_close(void *obj)
{
    fricreg_sim_free(obj);
}

static void see_sim(fricreg_sim *sim, struct view *v)
{
    double x[64], xd[64], value = -1.0;
    size_t n = fricreg_sim_ndof(sim), m = fricreg_sim_ncontacts(sim);
    for (size_t k = 0; k < 64; k++) /* what a failed getter leaves: these */
        x[k] = xd[k] = -1.0;
    for (int which = FRICREG_VALUE_TIME; which <= FRICREG_VALUE_DISSIPATION; which++) {
        see(v, fricreg_sim_get_value(sim, which, &value));
        see(v, value);
    }
    for (int which = FRICREG_SIM_STAT_STEPS; which <= FRICREG_SIM_STAT_REJECTED_STEPS; which++) {
        int64_t count = -1;
        see(v, fricreg_sim_get_stat(sim, which, &count));
        see(v, (double)count);
    }
    if (n > 64 || m > 64) { /* no ck_assert inside a play: Check allocates */
        NOTE("the view's arrays are too short for %zu bodies", n);
        return;
    }
    see(v, fricreg_sim_get_state(sim, n, x, xd));
    see_all(v, x, n);
    see_all(v, xd, n);
    see(v, fricreg_sim_get_stick_fraction(sim, m, x));
    see_all(v, x, m);
    size_t cycles = fricreg_sim_get_value(sim, FRICREG_VALUE_CYCLES, &value) == FRICREG_OK
                        ? (size_t)value
                        : 0;
    double D[8], err[8];
    if (cycles <= 8) {
        for (size_t k = 0; k < 8; k++) /* what a failed getter leaves: these */
            D[k] = err[k] = -1.0;
        see(v, fricreg_sim_get_dissipation(sim, cycles, D));
        see_all(v, D, cycles);
        see(v, fricreg_sim_get_extrapolated_dissipation(sim, cycles, D, err));
        see_all(v, D, cycles);
        see_all(v, err, cycles);
    }
    for (int which = FRICREG_EXTRAP_LEVELS; which <= FRICREG_EXTRAP_RHS_EVALS; which++) {
        value = -1.0;
        see(v, fricreg_sim_get_extrapolation(sim, which, &value));
        see(v, value);
    }
}

#define SIM_T_END 0.05

/* The results, then a further run (which starts again at t = 0) and its results. */
static void sim_observe(void *obj, struct view *v)
{
    see_sim(obj, v);
    see(v, fricreg_sim_run(obj, SIM_T_END));
    see_sim(obj, v);
}

/* One stepper of each family: fricreg's classical RK4 (fixed steps), GSL's embedded explicit
 * rkf45 (adaptive), implicit Gaussian rk4imp, Bulirsch-Stoer bsimp, multistep msbdf, and
 * fricreg's central differences, explicit and with implicit friction (fixed steps). */
static const int integrators[] = {FRICREG_INT_RK4,         FRICREG_INT_RKF45, FRICREG_INT_RK4IMP,
                                  FRICREG_INT_BSIMP,       FRICREG_INT_MSBDF, FRICREG_INT_CENTRAL,
                                  FRICREG_INT_CENTRAL_IMEX};
#define N_INTEGRATORS (sizeof integrators / sizeof integrators[0])
static const int systems[] = {FRICREG_SYSTEM_OSCILLATOR, FRICREG_SYSTEM_CHAIN,
                              FRICREG_SYSTEM_TWOBLOCK};

static int fixed_step(int integrator)
{
    return integrator == FRICREG_INT_RK4 || integrator == FRICREG_INT_RK4IMP ||
           integrator == FRICREG_INT_CENTRAL || integrator == FRICREG_INT_CENTRAL_IMEX;
}

static const char *const sim_calls[] = {"set_integrator", "set_law", "set_param", "run"};

/* Fixed steps for rk4, rk4imp and central differences (with the step guard's eigenvalue
 * problem for rk4 on the coupled two-block W), adaptive ones for the rest; eps = 0.02, four
 * steps (the paper's rule, 2 dt, is refused for central differences); a parameter of the
 * system changed (the two blocks' mu1, the chain's n = 8, the oscillator's a); a few steps are
 * enough, every allocation happens before the first. */
static int sim_call(void *obj, int i, struct view *v)
{
    (void)v;
    double rtol = fixed_step(current_integrator) ? 0.0 : 1e-6;
    switch (i) {
    case 0: return fricreg_sim_set_integrator(obj, current_integrator, 0.005, rtol, rtol);
    case 1: return fricreg_sim_set_law(obj, FRICREG_LAW_QUINN, 0.02);
    case 2:
        return current_system == FRICREG_SYSTEM_TWOBLOCK
                   ? fricreg_sim_set_param(obj, FRICREG_PARAM_MU1, 0.6)
               : current_system == FRICREG_SYSTEM_CHAIN
                   ? fricreg_sim_set_param(obj, FRICREG_PARAM_N, 8.0)
                   : fricreg_sim_set_param(obj, FRICREG_PARAM_A, 0.5);
    default: return fricreg_sim_run(obj, SIM_T_END);
    }
}

static const struct script sim_script = {"sim",       4,           sim_calls, 0,
                                         0,           sim_open,    sim_call,  NULL,
                                         sim_observe, sim_errcode, sim_close};

/* fricreg_sim_run_extrapolated: level 0, two internal copies and the table (extrapolate.c). A
 * failure leaves no extrapolation, and level 0's run if level 0 succeeded (its partial). */
static const char *const extrap_calls[] = {"set_integrator", "set_param", "run_extrapolated"};
#define EXTRAP_T_END 12.566370614359172 /* two periods of omega = 1 */

static int extrap_call(void *obj, int i, struct view *v)
{
    (void)v;
    switch (i) {
    case 0: return fricreg_sim_set_integrator(obj, FRICREG_INT_RK4, 0.05, 0.0, 0.0);
    case 1: return fricreg_sim_set_param(obj, FRICREG_PARAM_A, 0.5);
    default: return fricreg_sim_run_extrapolated(obj, EXTRAP_T_END, 3, 0);
    }
}

static int extrap_partial(void *obj, int i, struct view *v)
{
    (void)v, (void)i;
    return fricreg_sim_run(obj, EXTRAP_T_END);
}

static void extrap_observe(void *obj, struct view *v)
{
    see_sim(obj, v);
    see(v, fricreg_sim_run_extrapolated(obj, EXTRAP_T_END, 2, 0));
    see_sim(obj, v);
}

static const struct script extrap_script = {"sim run_extrapolated",
                                            3,
                                            extrap_calls,
                                            0,
                                            1u << 2,
                                            sim_open,
                                            extrap_call,
                                            extrap_partial,
                                            extrap_observe,
                                            sim_errcode,
                                            sim_close};

/* ---- The exact solver ------------------------------------------------------------------------ */

static int exact_errcode(const void *obj)
{
    return fricreg_exact_errcode(obj);
}

static void exact_close(void *obj)
{
    fricreg_exact_free(obj);
}

/* The solution held: its getters, switches, cycles and states. */
static void see_exact(const fricreg_exact *ex, struct view *v)
{
    double value = -1.0, times[512], D[64], x = -1.0, xd = -1.0;
    int sticks[512];
    for (size_t k = 0; k < 512; k++) /* what a failed getter leaves: these */
        times[k] = sticks[k] = -1;
    for (size_t k = 0; k < 64; k++)
        D[k] = -1.0;
    for (int which = FRICREG_EXACT_VALUE_TIME; which <= FRICREG_EXACT_VALUE_PERIOD; which++) {
        see(v, fricreg_exact_get_value(ex, which, &value));
        see(v, value);
    }
    for (int which = FRICREG_EXACT_STAT_SCAN_POINTS; which <= FRICREG_EXACT_STAT_ROOT_ITERS;
         which++) {
        int64_t count = -1;
        see(v, fricreg_exact_get_stat(ex, which, &count));
        see(v, (double)count);
    }
    size_t n = fricreg_exact_nswitches(ex), cycles = fricreg_exact_ncycles(ex);
    see(v, (double)n);
    see(v, (double)cycles);
    if (n > 512 || cycles > 64) {
        NOTE("the view's arrays are too short for %zu switches", n);
        return;
    }
    see(v, fricreg_exact_switches(ex, n, times, sticks));
    double sum = 0.0; /* every switch, through a sum: the view's room is limited */
    for (size_t k = 0; k < n; k++)
        sum += times[k] * (double)(k + 1) + sticks[k];
    see(v, sum);
    see(v, fricreg_exact_dissipation(ex, cycles, D));
    see_all(v, D, cycles);
    for (double t = 0.0; t < 300.0; t += 23.85) {
        see(v, fricreg_exact_state(ex, t, &x, &xd));
        see(v, x);
        see(v, xd);
    }
}

static void exact_observe(void *obj, struct view *v)
{
    see_exact(obj, v);
    see(v, fricreg_exact_run(obj, 60.0));
    see_exact(obj, v);
}

/* test_exact's long no-stick case: 64 switches by t = 200, so about 80 phases by t = 250, and
 * the phase list outgrows its first 64 entries (a realloc that keeps the earlier ones). A run
 * to t = 100 first: a failed run keeps the solution held before it (fricreg_exact.h). */
static int exact_open(void **obj)
{
    fricreg_exact *ex = SENTINEL;
    int status = fricreg_exact_create(0.3, 1.0, 0.1, 1.2, 0.0, &ex);
    if (status != FRICREG_OK && ex != SENTINEL)
        NOTE("exact_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? ex : NULL;
    return status;
}

static const char *const exact_calls[] = {"run(100)", "run(250)"};

static int exact_call(void *obj, int i, struct view *v)
{
    (void)v;
    int status = fricreg_exact_run(obj, i == 0 ? 100.0 : 250.0);
    if (i == 1 && status == FRICREG_OK && fricreg_exact_nswitches(obj) <= 64)
        NOTE("exact_run: %zu switches, the list never grew", fricreg_exact_nswitches(obj));
    return status;
}

static const struct script exact_script = {
    "exact create+run", 2,    exact_calls,   1u << 0,       0,          exact_open,
    exact_call,         NULL, exact_observe, exact_errcode, exact_close};

/* fricreg_exact_solve: create and run in one; a failure leaves no handle. */
static int exact_solve_open(void **obj)
{
    fricreg_exact *ex = SENTINEL;
    int status = fricreg_exact_solve(2.385, 1.3125, 0.4125, -0.5, 0.125, 60.0, &ex);
    if (status != FRICREG_OK && ex != SENTINEL)
        NOTE("exact_solve failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? ex : NULL;
    return status;
}

static const struct script exact_solve_script = {
    "exact solve", 0,          NULL, 0, 0, exact_solve_open, NULL, NULL, exact_observe,
    exact_errcode, exact_close};

/* ---- Structures ------------------------------------------------------------------------------ */

/* A 3-storey shear frame (storey masses 2, 2, 1; storey stiffnesses 200) with friction dampers
 * across storeys 1 and 2 (J couples them: W dense), Rayleigh damping, ground motion and a load,
 * each given twice (the second replaces the first: a failed set keeps the first); stepped by
 * one scheme of each family (Newmark, HHT-alpha on the sparse near-stick block,
 * FRICREG_CONTACT_SOLVER_SPARSE, central difference) and by a GSL stepper
 * (fricreg_structure_run_ode). */
static const double FRAME_M[9] = {2, 0, 0, 0, 2, 0, 0, 0, 1};
static const double FRAME_K[9] = {400, -200, 0, -200, 400, -200, 0, -200, 200};
static const double FRAME_J[6] = {1, 0, 0, -1, 1, 0}, FRAME_MUN[2] = {5, 3};
static const double FRAME_R[3] = {1, 0.5, 1}; /* not the default r = 1, so that it is seen */
static const double GROUND_A[4] = {0.5, -1.0, 0.75, 0.0}, GROUND_B[5] = {0.25, 1.0, -0.5, 0.3, 0};
static const double LOAD_P1[3] = {0, 0, 1}, LOAD_G1[3] = {0, 40, 0};
static const double LOAD_P2[3] = {0, 1, 0.5}, LOAD_G2[3] = {0, 30, 10};
enum { SCHEME_NEWMARK, SCHEME_HHT, SCHEME_CENTRAL, SCHEME_ODE, N_SCHEMES };
static int current_scheme;
#define ST_DT 0.002 /* 250 steps a run: the allocations are in the set-up, not the steps */
#define ST_T_END 0.5

static int structure_open(void **obj)
{
    fricreg_structure *s = SENTINEL;
    int status = fricreg_structure_create(3, 2, &s);
    if (status != FRICREG_OK && s != SENTINEL)
        NOTE("structure_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? s : NULL;
    return status;
}

static int structure_errcode(const void *obj)
{
    return fricreg_structure_errcode(obj);
}

static void structure_close(void *obj)
{
    fricreg_structure_free(obj);
}

static int structure_advance(fricreg_structure *s, double t_end)
{
    return current_scheme == SCHEME_ODE
               ? fricreg_structure_run_ode(s, FRICREG_INT_RKF45, ST_DT, 1e-6, FRICREG_ATOL_FROM_EPS,
                                           t_end)
               : fricreg_structure_run(s, ST_DT, t_end);
}

static void see_structure(const fricreg_structure *s, struct view *v)
{
    double u[3] = {-1, -1, -1}, ud[3] = {-1, -1, -1}, a[3] = {-1, -1, -1}, f[2] = {-1, -1},
           D[2] = {-1, -1}, value = -1.0;
    see(v, fricreg_structure_get_state(s, 3, u, ud, a));
    see_all(v, u, 3), see_all(v, ud, 3), see_all(v, a, 3);
    see(v, fricreg_structure_get_forces(s, 2, f));
    see_all(v, f, 2);
    see(v, fricreg_structure_get_dissipation(s, 2, D));
    see_all(v, D, 2);
    for (int which = FRICREG_SVALUE_TIME; which <= FRICREG_SVALUE_INITIAL; which++) {
        see(v, fricreg_structure_get_value(s, which, &value));
        see(v, value);
    }
    for (int which = FRICREG_SSTAT_STEPS; which <= FRICREG_SSTAT_LINE_SEARCH_CUTS; which++) {
        int64_t count = -1;
        see(v, fricreg_structure_get_stat(s, which, &count));
        see(v, (double)count);
    }
}

/* The state reached, then 0.1 more of the run (the object still works) and that state. */
static void structure_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, structure_advance(obj, t + 0.1));
    see_structure(obj, v);
}

static const char *const structure_calls[] = {
    "set_mass",   "set_stiffness", "set_rayleigh",        "set_contacts",
    "set_bounds", "set_influence", "set_ground_accel(A)", "set_load(1)",
    "set_law",    "the scheme",    "set_ground_accel(B)", "set_load(2)",
    "run"};

static int structure_call(void *obj, int i, struct view *v)
{
    (void)v;
    static const double u0[3] = {0.01, -0.02, 0.005}, v0[3] = {0.0, 0.1, -0.05};
    switch (i) {
    case 0: return fricreg_structure_set_mass(obj, 3, FRAME_M);
    case 1: return fricreg_structure_set_stiffness(obj, 3, FRAME_K);
    case 2: return fricreg_structure_set_rayleigh(obj, 0.1, 0.001);
    case 3: return fricreg_structure_set_contacts(obj, 2, 3, FRAME_J);
    case 4: return fricreg_structure_set_bounds(obj, 2, FRAME_MUN);
    case 5: return fricreg_structure_set_influence(obj, 3, FRAME_R);
    case 6: return fricreg_structure_set_ground_accel(obj, 0.0, 0.25, 4, GROUND_A);
    case 7: return fricreg_structure_set_load(obj, 3, LOAD_P1, 0.0, 0.5, 3, LOAD_G1);
    case 8: /* a band wide enough for central differences at dt = ST_DT */
        return fricreg_structure_set_law(obj, FRICREG_LAW_QUINN, 0.5);
    case 9:
        switch (current_scheme) {
        case SCHEME_NEWMARK: return fricreg_structure_set_newmark(obj, 0.3025, 0.6);
        case SCHEME_HHT: /* and the near-stick block through K_eff + J^T T J */
            return fricreg_structure_set_hht(obj, -0.1) == FRICREG_OK
                       ? fricreg_structure_set_contact_solver(obj, FRICREG_CONTACT_SOLVER_SPARSE)
                       : fricreg_structure_errcode(obj);
        case SCHEME_CENTRAL: return fricreg_structure_set_central_difference(obj);
        default: return fricreg_structure_set_initial(obj, 3, u0, v0);
        }
    case 10: return fricreg_structure_set_ground_accel(obj, 0.0, 0.2, 5, GROUND_B);
    case 11: return fricreg_structure_set_load(obj, 3, LOAD_P2, 0.0, 0.4, 3, LOAD_G2);
    default: return structure_advance(obj, ST_T_END);
    }
}

static const struct script structure_script = {"structure",
                                               13,
                                               structure_calls,
                                               1u << 6 | 1u << 7,
                                               0,
                                               structure_open,
                                               structure_call,
                                               NULL,
                                               structure_observe,
                                               structure_errcode,
                                               structure_close};

/* The frame with the error estimate on (fricreg_structure_set_error_estimate): its companion
 * is made at the first run and receives the record set between the two runs. A failed
 * allocation for the companion is a failed estimate (+infinity, a warning), not a failed call:
 * the structure's own results must then be those of the reference, and nothing may leak. The
 * view holds the estimate getters' statuses (OK with the estimate, EINVAL without), not their
 * values, which such a failure makes infinite. */
static void see_structure_estimate(const fricreg_structure *s, struct view *v)
{
    double peak[3] = {-1, -1, -1}, err[3] = {-1, -1, -1};
    see_structure(s, v);
    see(v, fricreg_structure_get_peak_displacement(s, 3, peak));
    see_all(v, peak, 3);
    see(v, fricreg_structure_get_peak_displacement_error(s, 3, err));
    see(v, fricreg_structure_get_dissipation_error(s, 2, err));
    double tol[10] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
    see(v, fricreg_structure_get_ode_abs_tolerances(s, 10, tol));
    see_all(v, tol, 10);
}

static void structure_estimate_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_estimate(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, structure_advance(obj, t + 0.1));
    see_structure_estimate(obj, v);
}

static const char *const structure_estimate_calls[] = {"set_mass",
                                                       "set_stiffness",
                                                       "set_contacts",
                                                       "set_bounds",
                                                       "set_influence",
                                                       "set_ground_accel(A)",
                                                       "set_law",
                                                       "set_error_estimate",
                                                       "set_ode_abs_tolerances(1)",
                                                       "the scheme",
                                                       "run (half)",
                                                       "set_ode_abs_tolerances(2)",
                                                       "set_ground_accel(B)",
                                                       "run"};

/* run_ode's tolerances per component (2 ndof + 2 + m = 10), set before the companion is made
 * (it copies them) and again after (passed on to it); the first run's atol is replaced. */
static const double FRAME_ATOL1[10] = {1e-6, 1e-6, 1e-6, 1e-8, 1e-8, 1e-8, 1e-6, 1e-6, 1e-6, 1e-6};
static const double FRAME_ATOL2[10] = {1e-7, 1e-7, 1e-7, 1e-9, 1e-9, 1e-9, 1e-7, 1e-7, 1e-7, 1e-7};

static int structure_estimate_call(void *obj, int i, struct view *v)
{
    (void)v;
    static const double u0[3] = {0.01, -0.02, 0.005}, v0[3] = {0.0, 0.1, -0.05};
    switch (i) {
    case 0: return fricreg_structure_set_mass(obj, 3, FRAME_M);
    case 1: return fricreg_structure_set_stiffness(obj, 3, FRAME_K);
    case 2: return fricreg_structure_set_contacts(obj, 2, 3, FRAME_J);
    case 3: return fricreg_structure_set_bounds(obj, 2, FRAME_MUN);
    case 4: return fricreg_structure_set_influence(obj, 3, FRAME_R);
    case 5: return fricreg_structure_set_ground_accel(obj, 0.0, 0.25, 4, GROUND_A);
    case 6: return fricreg_structure_set_law(obj, FRICREG_LAW_QUINN, 0.5);
    case 7: return fricreg_structure_set_error_estimate(obj, 1);
    case 8: return fricreg_structure_set_ode_abs_tolerances(obj, 10, FRAME_ATOL1);
    case 9:
        switch (current_scheme) {
        case SCHEME_NEWMARK: return fricreg_structure_set_newmark(obj, 0.3025, 0.6);
        case SCHEME_HHT: return fricreg_structure_set_hht(obj, -0.1);
        case SCHEME_CENTRAL: return fricreg_structure_set_central_difference(obj);
        default: return fricreg_structure_set_initial(obj, 3, u0, v0);
        }
    case 10: return structure_advance(obj, 0.5 * ST_T_END);
    case 11: return fricreg_structure_set_ode_abs_tolerances(obj, 10, FRAME_ATOL2);
    case 12: return fricreg_structure_set_ground_accel(obj, 0.0, 0.2, 5, GROUND_B);
    default: return structure_advance(obj, ST_T_END);
    }
}

static const struct script structure_estimate_script = {"structure with the error estimate",
                                                        14,
                                                        structure_estimate_calls,
                                                        1u << 8, /* by call 11 */
                                                        0,
                                                        structure_open,
                                                        structure_estimate_call,
                                                        NULL,
                                                        structure_estimate_observe,
                                                        structure_errcode,
                                                        structure_close};

/* The frame with the error estimate, saved half-way (fricreg_structure_save: no allocation),
 * set back to its start, restored and run on: the restore makes the two companions anew
 * (their structures and copies of the model) and must leave the structure as it was where an
 * allocation fails (FRICREG_ENOMEM: the reference without the restore). The blob lives in a
 * static buffer, so that the script itself allocates nothing. */
static unsigned char checkpoint_blob[1 << 16];
static size_t checkpoint_len;

/* A play starts without a checkpoint (a left-out save: the restore refuses the empty blob). */
static int structure_checkpoint_open(void **obj)
{
    checkpoint_len = 0;
    return structure_open(obj);
}

static const char *const structure_checkpoint_calls[] = {"set_mass",
                                                         "set_stiffness",
                                                         "set_contacts",
                                                         "set_bounds",
                                                         "set_influence",
                                                         "set_ground_accel(A)",
                                                         "set_law",
                                                         "set_error_estimate",
                                                         "set_ode_abs_tolerances(1)",
                                                         "the scheme",
                                                         "run (half)",
                                                         "save",
                                                         "set_initial",
                                                         "restore",
                                                         "run"};

/* The runs around the checkpoint are a fifth of the estimate script's: a restore's ~2000
 * allocations, each failure followed by the rest of the script, took 20 s of the quick tier
 * (a run allocates at its first step; the steps after it only repeat). */
#define CHECKPOINT_T_END (0.2 * ST_T_END)

static int structure_checkpoint_call(void *obj, int i, struct view *v)
{
    static const double u0[3] = {0.02, 0.01, -0.005}, v0[3] = {0.1, 0.0, 0.05};
    switch (i) {
    case 10: return structure_advance(obj, 0.5 * CHECKPOINT_T_END);
    case 11:
        checkpoint_len = sizeof checkpoint_blob;
        return fricreg_structure_save(obj, checkpoint_blob, &checkpoint_len);
    case 12: return fricreg_structure_set_initial(obj, 3, u0, v0);
    case 13: return fricreg_structure_restore(obj, checkpoint_blob, checkpoint_len);
    case 14: return structure_advance(obj, CHECKPOINT_T_END);
    default: return structure_estimate_call(obj, i, v);
    }
}

/* The restore replaces the work of the half run and of set_initial: the run it continues is
 * the same whether the first half was run before the save or after the restore (the point of
 * a checkpoint), so leaving either out shows nothing. */
static const struct script structure_checkpoint_script = {"structure checkpoint",
                                                          15,
                                                          structure_checkpoint_calls,
                                                          1u << 10 | 1u << 12,
                                                          0,
                                                          structure_checkpoint_open,
                                                          structure_checkpoint_call,
                                                          NULL,
                                                          structure_estimate_observe,
                                                          structure_errcode,
                                                          structure_close};

/* The frame with Jenkins elements for dampers (the contacts' bounds 0): set_jenkins (dense)
 * replaced by set_jenkins_csr (the second pair of elements), stepped by Newmark, HHT-alpha and
 * central difference (run_ode refuses elements). */
static const double FRAME_ZERO[2] = {0, 0}, FRAME_KT[2] = {150, 90}, FRAME_MUN_E[2] = {4, 2.5};
static const int64_t FRAME_JE_PTR[3] = {0, 1, 3}, FRAME_JE_IND[3] = {0, 0, 1};
static const double FRAME_JE_VAL[3] = {1, -1, 1};

static void see_structure_jenkins(const fricreg_structure *s, struct view *v)
{
    double f[2] = {-1, -1}, w[2] = {-1, -1}, D[2] = {-1, -1}, value = -1.0;
    see_structure(s, v);
    see(v, fricreg_structure_get_jenkins_state(s, 2, f, w, D));
    see_all(v, f, 2), see_all(v, w, 2), see_all(v, D, 2);
    see(v, fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &value));
    see(v, value);
}

static void structure_jenkins_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_jenkins(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, fricreg_structure_run(obj, ST_DT, t + 0.1));
    see_structure_jenkins(obj, v);
}

static const char *const structure_jenkins_calls[] = {"set_mass",     "set_stiffness",
                                                      "set_contacts", "set_bounds (0)",
                                                      "set_load(1)",  "set_jenkins",
                                                      "the scheme",   "set_jenkins_csr",
                                                      "run"};

static int structure_jenkins_call(void *obj, int i, struct view *v)
{
    (void)v;
    switch (i) {
    case 0: return fricreg_structure_set_mass(obj, 3, FRAME_M);
    case 1: return fricreg_structure_set_stiffness(obj, 3, FRAME_K);
    case 2: return fricreg_structure_set_contacts(obj, 2, 3, FRAME_J);
    case 3: return fricreg_structure_set_bounds(obj, 2, FRAME_ZERO);
    case 4: return fricreg_structure_set_load(obj, 3, LOAD_P1, 0.0, 0.5, 3, LOAD_G1);
    case 5: return fricreg_structure_set_jenkins(obj, 2, 3, FRAME_J, FRAME_MUN, FRAME_MUN);
    case 6:
        switch (current_scheme) {
        case SCHEME_NEWMARK: return fricreg_structure_set_newmark(obj, 0.3025, 0.6);
        case SCHEME_HHT: return fricreg_structure_set_hht(obj, -0.1);
        default: return fricreg_structure_set_central_difference(obj);
        }
    case 7:
        return fricreg_structure_set_jenkins_csr(obj, 2, 3, 0, FRAME_JE_PTR, FRAME_JE_IND,
                                                 FRAME_JE_VAL, FRAME_KT, FRAME_MUN_E);
    default: return fricreg_structure_run(obj, ST_DT, ST_T_END);
    }
}

static const struct script structure_jenkins_script = {"structure with Jenkins elements",
                                                       9,
                                                       structure_jenkins_calls,
                                                       1u << 5,
                                                       0,
                                                       structure_open,
                                                       structure_jenkins_call,
                                                       NULL,
                                                       structure_jenkins_observe,
                                                       structure_errcode,
                                                       structure_close};

/* The same frame with its contacts' bounds > 0 beside the elements: the joint step
 * (joint_step.c) allocates its dense storage at the first step. Newmark and HHT-alpha only:
 * the central difference, explicit, has no joint step (and its step guard refuses these
 * bounds at the default eps). */
static const char *const structure_joint_calls[] = {"set_mass",     "set_stiffness",
                                                    "set_contacts", "set_bounds (> 0)",
                                                    "set_load(1)",  "set_jenkins",
                                                    "the scheme",   "set_jenkins_csr",
                                                    "run"};

static int structure_joint_call(void *obj, int i, struct view *v)
{
    if (i == 3)
        return fricreg_structure_set_bounds(obj, 2, FRAME_MUN);
    return structure_jenkins_call(obj, i, v);
}

static const struct script structure_joint_script = {"structure with Jenkins elements beside "
                                                     "contacts",
                                                     9,
                                                     structure_joint_calls,
                                                     1u << 5,
                                                     0,
                                                     structure_open,
                                                     structure_joint_call,
                                                     NULL,
                                                     structure_jenkins_observe,
                                                     structure_errcode,
                                                     structure_close};

/* The same frame with Iwan elements of three sliders: set_iwan (dense) replaced by
 * set_iwan_csr. */
static const double FRAME_IW_K[6] = {60, 50, 40, 30, 30, 30},
                    FRAME_IW_PHI[6] = {1, 1.5, 2.5, 0.5, 1, 1},
                    FRAME_IW_K2[6] = {75, 50, 25, 40, 30, 20},
                    FRAME_IW_PHI2[6] = {0.5, 1, 2.5, 0.5, 1, 1};

static void see_structure_iwan(const fricreg_structure *s, struct view *v)
{
    double f[2] = {-1, -1}, w[6] = {-1, -1, -1, -1, -1, -1}, D[2] = {-1, -1}, value = -1.0;
    see_structure(s, v);
    see(v, fricreg_structure_get_iwan_state(s, 2, 3, f, w, D));
    see_all(v, f, 2), see_all(v, w, 6), see_all(v, D, 2);
    see(v, fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &value));
    see(v, value);
}

static void structure_iwan_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_iwan(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, fricreg_structure_run(obj, ST_DT, t + 0.1));
    see_structure_iwan(obj, v);
}

static const char *const structure_iwan_calls[] = {"set_mass",     "set_stiffness",
                                                   "set_contacts", "set_bounds (0)",
                                                   "set_load(1)",  "set_iwan",
                                                   "the scheme",   "set_iwan_csr",
                                                   "run"};

static int structure_iwan_call(void *obj, int i, struct view *v)
{
    switch (i) {
    case 5: return fricreg_structure_set_iwan(obj, 2, 3, FRAME_J, 3, FRAME_IW_K, FRAME_IW_PHI);
    case 7:
        return fricreg_structure_set_iwan_csr(obj, 2, 3, 0, FRAME_JE_PTR, FRAME_JE_IND,
                                              FRAME_JE_VAL, 3, FRAME_IW_K2, FRAME_IW_PHI2);
    default: return structure_jenkins_call(obj, i, v);
    }
}

static const struct script structure_iwan_script = {"structure with Iwan elements",
                                                    9,
                                                    structure_iwan_calls,
                                                    1u << 5,
                                                    0,
                                                    structure_open,
                                                    structure_iwan_call,
                                                    NULL,
                                                    structure_iwan_observe,
                                                    structure_errcode,
                                                    structure_close};

/* The same frame with elements of two types added one after the other
 * (fricreg_structure_add_elements): a Jenkins element on J's first row, then an Iwan element
 * of three sliders on its second; a failed add keeps the first. */
static const double FRAME_MIX_JENKINS[2] = {5, 5}, FRAME_MIX_IWAN[6] = {60, 50, 40, 1, 1.5, 2.5};

static void see_structure_mix(const fricreg_structure *s, struct view *v)
{
    double f[2] = {-1, -1}, w[4] = {-1, -1, -1, -1}, D[2] = {-1, -1}, value = -1.0;
    size_t me = fricreg_structure_element_count(s);
    see_structure(s, v);
    see(v, (double)me);
    see(v, fricreg_structure_get_elements(s, me, f, w, D));
    see_all(v, f, 2), see_all(v, w, 4), see_all(v, D, 2);
    see(v, fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &value));
    see(v, value);
}

static void structure_mix_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_mix(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, fricreg_structure_run(obj, ST_DT, t + 0.1));
    see_structure_mix(obj, v);
}

static const char *const structure_mix_calls[] = {"set_mass",     "set_stiffness",
                                                  "set_contacts", "set_bounds (0)",
                                                  "set_load(1)",  "add Jenkins",
                                                  "the scheme",   "add an Iwan element",
                                                  "run"};

static int structure_mix_call(void *obj, int i, struct view *v)
{
    switch (i) {
    case 5:
        return fricreg_structure_add_elements(obj, fricreg_element_lookup("jenkins"), 1, 3, FRAME_J,
                                              FRAME_MIX_JENKINS);
    case 7:
        return fricreg_structure_add_elements(
            obj, fricreg_element_sliders(fricreg_element_lookup("iwan"), 3), 1, 3, FRAME_J + 3,
            FRAME_MIX_IWAN);
    default: return structure_jenkins_call(obj, i, v);
    }
}

static const struct script structure_mix_script = {"structure with a mix of element types",
                                                   9,
                                                   structure_mix_calls,
                                                   0,
                                                   0,
                                                   structure_open,
                                                   structure_mix_call,
                                                   NULL,
                                                   structure_mix_observe,
                                                   structure_errcode,
                                                   structure_close};

/* The same frame with one 2-D Jenkins element on J's two rows: set_jenkins_2d (dense)
 * replaced by set_jenkins_2d_csr (other parameters); the contacts' bounds 0, or > 0 beside it
 * (the joint step, Newmark and HHT-alpha only). */
static int structure_2d_joint; /* the bounds > 0 */

static void see_structure_jenkins_2d(const fricreg_structure *s, struct view *v)
{
    double f[2] = {-1, -1}, w[2] = {-1, -1}, D[1] = {-1}, value = -1.0;
    see_structure(s, v);
    see(v, fricreg_structure_get_jenkins_2d_state(s, 1, f, w, D));
    see_all(v, f, 2), see_all(v, w, 2), see_all(v, D, 1);
    see(v, fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &value));
    see(v, value);
}

static void structure_jenkins_2d_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_jenkins_2d(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, fricreg_structure_run(obj, ST_DT, t + 0.1));
    see_structure_jenkins_2d(obj, v);
}

static const char *const structure_jenkins_2d_calls[] = {"set_mass",     "set_stiffness",
                                                         "set_contacts", "set_bounds",
                                                         "set_load(1)",  "set_jenkins_2d",
                                                         "the scheme",   "set_jenkins_2d_csr",
                                                         "run"};

static int structure_jenkins_2d_call(void *obj, int i, struct view *v)
{
    switch (i) {
    case 3:
        return fricreg_structure_set_bounds(obj, 2, structure_2d_joint ? FRAME_MUN : FRAME_ZERO);
    case 5: return fricreg_structure_set_jenkins_2d(obj, 1, 3, FRAME_J, FRAME_KT, FRAME_MUN_E);
    case 7:
        return fricreg_structure_set_jenkins_2d_csr(obj, 1, 3, 0, FRAME_JE_PTR, FRAME_JE_IND,
                                                    FRAME_JE_VAL, FRAME_KT + 1, FRAME_MUN_E + 1);
    default: return structure_jenkins_call(obj, i, v);
    }
}

static const struct script structure_jenkins_2d_script = {"structure with 2-D Jenkins elements",
                                                          9,
                                                          structure_jenkins_2d_calls,
                                                          1u << 5,
                                                          0,
                                                          structure_open,
                                                          structure_jenkins_2d_call,
                                                          NULL,
                                                          structure_jenkins_2d_observe,
                                                          structure_errcode,
                                                          structure_close};

/* The same frame with Jenkins elements under a normal load with lift-off
 * (set_jenkins_normal, then again with other parameters). */
static const double FRAME_JN[6] = {0, 1, 0, 0, 0, 1}, FRAME_MU[2] = {0.3, 0.5},
                    FRAME_N0[2] = {3, 1}, FRAME_KN[2] = {400, 300};

static void see_structure_normal(const fricreg_structure *s, struct view *v)
{
    double N[2] = {-1, -1};
    see_structure_jenkins(s, v);
    see(v, fricreg_structure_get_normal_forces(s, 2, N));
    see_all(v, N, 2);
}

static void structure_normal_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_normal(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, fricreg_structure_run(obj, ST_DT, t + 0.1));
    see_structure_normal(obj, v);
}

static const char *const structure_normal_calls[] = {"set_mass",     "set_stiffness",
                                                     "set_contacts", "set_bounds (0)",
                                                     "set_load(1)",  "set_jenkins_normal",
                                                     "the scheme",   "set_jenkins_normal",
                                                     "run"};

static int structure_normal_call(void *obj, int i, struct view *v)
{
    switch (i) {
    case 5:
        return fricreg_structure_set_jenkins_normal(obj, 2, 3, FRAME_J, FRAME_JN, FRAME_KT,
                                                    FRAME_MU, FRAME_N0, FRAME_KN);
    case 7:
        return fricreg_structure_set_jenkins_normal(obj, 2, 3, FRAME_J, FRAME_JN, FRAME_KT,
                                                    FRAME_MUN_E, FRAME_N0, FRAME_KN);
    default: return structure_jenkins_call(obj, i, v);
    }
}

static const struct script structure_normal_script = {"structure with lift-off elements",
                                                      9,
                                                      structure_normal_calls,
                                                      1u << 5,
                                                      0,
                                                      structure_open,
                                                      structure_normal_call,
                                                      NULL,
                                                      structure_normal_observe,
                                                      structure_errcode,
                                                      structure_close};

/* The same frame with Iwan elements of two sliders under that normal law (set_iwan_normal,
 * then again with other friction coefficients). */
static const double FRAME_IWAN_K[4] = {100, 50, 60, 30}, FRAME_IWAN_MU[4] = {0.1, 0.2, 0.3, 0.2},
                    FRAME_IWAN_MU2[4] = {0.2, 0.2, 0.1, 0.4};

static const char *const structure_iwan_normal_calls[] = {"set_mass",     "set_stiffness",
                                                          "set_contacts", "set_bounds (0)",
                                                          "set_load(1)",  "set_iwan_normal",
                                                          "the scheme",   "set_iwan_normal",
                                                          "run"};

static int structure_iwan_normal_call(void *obj, int i, struct view *v)
{
    switch (i) {
    case 5:
    case 7:
        return fricreg_structure_set_iwan_normal(obj, 2, 3, FRAME_J, FRAME_JN, 2, FRAME_IWAN_K,
                                                 i == 5 ? FRAME_IWAN_MU : FRAME_IWAN_MU2, FRAME_N0,
                                                 FRAME_KN);
    default: return structure_jenkins_call(obj, i, v);
    }
}

static void see_structure_iwan_normal(const fricreg_structure *s, struct view *v)
{
    double f[2] = {-1, -1}, w[4] = {-1, -1, -1, -1}, D[2] = {-1, -1}, N[2] = {-1, -1};
    see(v, fricreg_structure_get_iwan_state(s, 2, 2, f, w, D));
    see_all(v, f, 2);
    see_all(v, w, 4);
    see_all(v, D, 2);
    see(v, fricreg_structure_get_normal_forces(s, 2, N));
    see_all(v, N, 2);
}

static void structure_iwan_normal_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_iwan_normal(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, fricreg_structure_run(obj, ST_DT, t + 0.1));
    see_structure_iwan_normal(obj, v);
}

static const struct script structure_iwan_normal_script = {"structure with Iwan lift-off elements",
                                                           9,
                                                           structure_iwan_normal_calls,
                                                           1u << 5,
                                                           0,
                                                           structure_open,
                                                           structure_iwan_normal_call,
                                                           NULL,
                                                           structure_iwan_normal_observe,
                                                           structure_errcode,
                                                           structure_close};

/* The same frame with one 3-D contact element (a 2-D element on J's two rows with the normal
 * row (0, 0, 1)): set_jenkins_2d_normal, then again with other parameters. */
static void see_structure_contact_3d(const fricreg_structure *s, struct view *v)
{
    double N[1] = {-1};
    see_structure_jenkins_2d(s, v);
    see(v, fricreg_structure_get_normal_forces(s, 1, N));
    see_all(v, N, 1);
}

static void structure_contact_3d_observe(void *obj, struct view *v)
{
    double t = 0.0;
    see_structure_contact_3d(obj, v);
    fricreg_structure_get_value(obj, FRICREG_SVALUE_TIME, &t);
    see(v, fricreg_structure_run(obj, ST_DT, t + 0.1));
    see_structure_contact_3d(obj, v);
}

static const char *const structure_contact_3d_calls[] = {"set_mass",     "set_stiffness",
                                                         "set_contacts", "set_bounds (0)",
                                                         "set_load(1)",  "set_jenkins_2d_normal",
                                                         "the scheme",   "set_jenkins_2d_normal",
                                                         "run"};

static int structure_contact_3d_call(void *obj, int i, struct view *v)
{
    switch (i) {
    case 5:
        return fricreg_structure_set_jenkins_2d_normal(obj, 1, 3, FRAME_J, FRAME_JN + 3, FRAME_KT,
                                                       FRAME_MU, FRAME_N0, FRAME_KN);
    case 7:
        return fricreg_structure_set_jenkins_2d_normal(obj, 1, 3, FRAME_J, FRAME_JN + 3,
                                                       FRAME_KT + 1, FRAME_MU + 1, FRAME_N0 + 1,
                                                       FRAME_KN + 1);
    default: return structure_jenkins_call(obj, i, v);
    }
}

static const struct script structure_contact_3d_script = {"structure with 3-D contact elements",
                                                          9,
                                                          structure_contact_3d_calls,
                                                          1u << 5,
                                                          0,
                                                          structure_open,
                                                          structure_contact_3d_call,
                                                          NULL,
                                                          structure_contact_3d_observe,
                                                          structure_errcode,
                                                          structure_close};

/* A model for the tests of steps that make no allocation. */
static int structure_model(fricreg_structure *s)
{
    int status = FRICREG_OK;
    for (int i = 0; i < 9 && status == FRICREG_OK; i++)
        status = structure_call(s, i, NULL);
    return status;
}

/* ---- Jenkins elements ------------------------------------------------------------------------ */

/* create alone (its one block): a failure leaves no handle; the view is three 2-D elements
 * after set_params, two trials (the second committed) and the committed sliders. That trial
 * and commit never allocate is test_jenkins_trial_does_not_allocate's. */
static int jk_open(void **obj)
{
    fricreg_jenkins *j = SENTINEL;
    int status = fricreg_jenkins_create(2, 3, &j);
    if (status != FRICREG_OK && j != SENTINEL)
        NOTE("jenkins_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? j : NULL;
    return status;
}

static int jk_errcode(const void *obj)
{
    return fricreg_jenkins_errcode(obj);
}

static void jk_close(void *obj)
{
    fricreg_jenkins_free(obj);
}

static void jk_observe(void *obj, struct view *v)
{
    fricreg_jenkins *j = obj;
    const double kt[3] = {2.385, 1.0, 0.5}, mun[3] = {0.7125, 0.25, 3.0};
    const double u[2][6] = {{0.5, -0.25, 1.5, 0.0, 0.125, 0.375}, {-0.75, 0.5, 0.0, 2.0, 1.0, 1.0}};
    double f[6], t[12], w[6];
    see(v, fricreg_jenkins_set_params(j, 3, kt, mun));
    for (int k = 0; k < 2; k++) {
        see(v, fricreg_jenkins_trial(j, 3, u[k], f, t));
        see_all(v, f, 6);
        see_all(v, t, 12);
    }
    see(v, fricreg_jenkins_commit(j));
    see(v, fricreg_jenkins_get_slider(j, 3, w));
    see_all(v, w, 6);
}

static const struct script jk_create = {"jenkins create", 0,    NULL, 0,          0,
                                        jk_open,          NULL, NULL, jk_observe, jk_errcode,
                                        jk_close};

/* ---- Iwan elements --------------------------------------------------------------------------- */

/* create alone (its one block): a failure leaves no handle; the view is two 2-D elements of
 * three sliders after set_params, set_segalman and set_normal, two trials with a normal
 * displacement (the second committed) and the committed sliders. That trial and commit never
 * allocate is test_iwan_trial_does_not_allocate's (every other call's:
 * test_aft_iwan_calls_do_not_allocate). */
static int iw_open(void **obj)
{
    fricreg_iwan *iw = SENTINEL;
    int status = fricreg_iwan_create(2, 2, 3, &iw);
    if (status != FRICREG_OK && iw != SENTINEL)
        NOTE("iwan_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? iw : NULL;
    return status;
}

static int iw_errcode(const void *obj)
{
    return fricreg_iwan_errcode(obj);
}

static void iw_close(void *obj)
{
    fricreg_iwan_free(obj);
}

static void iw_observe(void *obj, struct view *v)
{
    fricreg_iwan *iw = obj;
    const double k[6] = {2.385, 1.0, 0.5, 1.5, 0.25, 3.0}, phi[6] = {0.7125, 0.25, 3.0, 1, 1, 1};
    const double fs[2] = {2.385, 1.0}, kt[2] = {10.0, 4.0}, chi[2] = {-0.5, -0.2},
                 beta[2] = {0.35, 0.0}, n0[2] = {1.5, 2.0}, kn[2] = {3.0, 0.0};
    const double u[2][4] = {{0.5, -0.25, 1.5, 0.0}, {-0.75, 0.5, 0.0, 2.0}}, g[2] = {0.1, -0.2};
    double f[4], t[8], tg[4], nf[2], w[12];
    see(v, fricreg_iwan_set_params(iw, 2, 3, k, phi));
    see(v, fricreg_iwan_set_segalman(iw, 2, fs, kt, chi, beta, 1e-4));
    see(v, fricreg_iwan_set_normal(iw, 2, n0, kn));
    for (int i = 0; i < 2; i++) {
        see(v, fricreg_iwan_trial_normal(iw, 2, u[i], g, f, nf, t, tg));
        see_all(v, f, 4);
        see_all(v, t, 8);
        see_all(v, tg, 4);
        see_all(v, nf, 2);
    }
    see(v, fricreg_iwan_commit(iw));
    see(v, fricreg_iwan_get_slider(iw, 2, 3, w));
    see_all(v, w, 12);
}

static const struct script iw_create = {"iwan create", 0,    NULL, 0,          0,
                                        iw_open,       NULL, NULL, iw_observe, iw_errcode,
                                        iw_close};

/* ---- AFT workspaces ------------------------------------------------------------------------- */

/* create alone (its blocks, GSL's Brent among them): a failure leaves no handle; the view is
 * both paths' coefficients and Jacobians of a Jenkins and an Iwan element. That the
 * evaluations never allocate is test_aft_eval_does_not_allocate's (the lift-off ones too:
 * test_aft_iwan_calls_do_not_allocate). */
static int aft_open(void **obj)
{
    fricreg_aft *a = SENTINEL;
    int status = fricreg_aft_create(2, 16, &a);
    if (status != FRICREG_OK && a != SENTINEL)
        NOTE("aft_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? a : NULL;
    return status;
}

static int aft_errcode(const void *obj)
{
    return fricreg_aft_errcode(obj);
}

static void aft_close(void *obj)
{
    fricreg_aft_free(obj);
}

static void aft_observe(void *obj, struct view *v)
{
    fricreg_aft *a = obj;
    const double u[5] = {0.25, 1.5, -0.5, 0.125, 0.375}, k[2] = {2.385, 1.0},
                 phi[2] = {0.7125, 0.25};
    double f[5], jac[25];
    see(v, fricreg_aft_jenkins_exact(a, 2.385, 0.7125, 5, u, f, jac));
    see_all(v, f, 5);
    see_all(v, jac, 25);
    see(v, fricreg_aft_jenkins_sampled(a, 2.385, 0.7125, 5, u, f, jac));
    see_all(v, f, 5);
    see_all(v, jac, 25);
    see(v, fricreg_aft_iwan_exact(a, 2, k, phi, 5, u, f, jac));
    see_all(v, f, 5);
    see(v, fricreg_aft_iwan_sampled(a, 2, k, phi, 5, u, f, jac));
    see_all(v, f, 5);
}

static const struct script aft_create = {"aft create", 0,    NULL, 0,           0,
                                         aft_open,     NULL, NULL, aft_observe, aft_errcode,
                                         aft_close};

/* ---- Harmonic balance ------------------------------------------------------------------------ */

/* create alone (its blocks, the AFT workspace, the LU pivots): a failure leaves no handle; the
 * view is a 2-dof model with one element solved at one frequency, its displacement, and a
 * short continuation's points (whose one allocation, the first 64 points' room, the view
 * makes: not failed here, but in test_hb_solve_continue, with every allocation of solve and
 * continue). */
static int hb_open(void **obj)
{
    fricreg_hb *hb = SENTINEL;
    int status = fricreg_hb_create(2, 1, 3, &hb);
    if (status != FRICREG_OK && hb != SENTINEL)
        NOTE("hb_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? hb : NULL;
    return status;
}

static int hb_errcode(const void *obj)
{
    return fricreg_hb_errcode(obj);
}

static void hb_close(void *obj)
{
    fricreg_hb_free(obj);
}

static void hb_observe(void *obj, struct view *v)
{
    fricreg_hb *hb = obj;
    const double M[4] = {1.3, 0.0, 0.0, 0.9}, K[4] = {4.2, -1.7, -1.7, 2.385}, J[2] = {0.0, 1.0};
    const double kt[1] = {1.5}, mun[1] = {0.25}, pc[2] = {0.6, 0.0}, ps[2] = {0.0, 0.125};
    double q[7] = {0}, x[14] = {0}, rms[2] = {0}, omega = 0.0; /* left by a failed call */
    see(v, fricreg_hb_set_mass(hb, 2, M));
    see(v, fricreg_hb_set_stiffness(hb, 2, K));
    see(v, fricreg_hb_set_rayleigh(hb, 0.05, 0.01));
    see(v, fricreg_hb_set_elements(hb, 1, 2, J, kt, mun));
    see(v, fricreg_hb_set_excitation(hb, 2, pc, ps));
    see(v, fricreg_hb_solve(hb, 1.1, 7, NULL, q));
    see_all(v, q, 7);
    see(v, fricreg_hb_displacement(hb, 2, 7, x));
    see_all(v, x, 14);
    see(v, fricreg_hb_set_continuation(hb, 0.05, 1e-6, 0.1, 64));
    see(v, fricreg_hb_continue(hb, 1.0, 1.2, 7, NULL));
    see(v, (double)fricreg_hb_points(hb));
    see(v, fricreg_hb_point(hb, fricreg_hb_points(hb) - 1, &omega, 2, rms));
    see(v, omega);
    see_all(v, rms, 2);
}

static const struct script hb_create = {"hb create", 0,    NULL,       0,          0,       hb_open,
                                        NULL,        NULL, hb_observe, hb_errcode, hb_close};

/* The sparse model: the three _csc setters (the first turns the dense model sparse, converting
 * the other two; each builds D_h's pattern), the elements and the excitation; the view solves
 * at one frequency (KLU's analysis and factors, not failed here) and the displacement. */
static const char *const hb_sparse_calls[] = {"set_mass_csc", "set_stiffness_csc(upper, 1-based)",
                                              "set_damping_csc(lower)", "set_elements",
                                              "set_excitation"};

static int hb_sparse_call(void *obj, int i, struct view *v)
{
    (void)v;
    const int64_t Mp[3] = {0, 1, 2}, Mi[2] = {0, 1}, Kp[3] = {1, 2, 4}, Ki[3] = {1, 1, 2};
    const int64_t Cp[3] = {0, 2, 3}, Ci[3] = {0, 1, 1};
    const double Mx[2] = {1.3, 0.9}, Kx[3] = {4.2, -1.7, 2.385}, Cx[3] = {0.2, -0.05, 0.1};
    const double J[2] = {0.0, 1.0}, kt[1] = {1.5}, mun[1] = {0.25}, pc[2] = {0.6, 0.0},
                 ps[2] = {0.0, 0.125};
    switch (i) {
    case 0: return fricreg_hb_set_mass_csc(obj, 2, 0, Mp, Mi, Mx);
    case 1:
        return fricreg_hb_set_stiffness_csc(obj, 2, FRICREG_SPARSE_UPPER | FRICREG_SPARSE_ONE_BASED,
                                            Kp, Ki, Kx);
    case 2: return fricreg_hb_set_damping_csc(obj, 2, FRICREG_SPARSE_LOWER, Cp, Ci, Cx);
    case 3: return fricreg_hb_set_elements(obj, 1, 2, J, kt, mun);
    default: return fricreg_hb_set_excitation(obj, 2, pc, ps);
    }
}

static void hb_sparse_observe(void *obj, struct view *v)
{
    double q[7] = {0}, x[14] = {0}; /* a failed call leaves them: the view must read the same */
    see(v, fricreg_hb_solve(obj, 1.1, 7, NULL, q));
    see_all(v, q, 7);
    see(v, fricreg_hb_displacement(obj, 2, 7, x));
    see_all(v, x, 14);
}

static const struct script hb_sparse = {
    "hb set_*_csc", 5,    hb_sparse_calls,   0,          0,       hb_open,
    hb_sparse_call, NULL, hb_sparse_observe, hb_errcode, hb_close};

/* Iwan elements: set_iwan twice (the second replaces the first's sliders: its one allocation
 * made before the old block is freed); the view solves at one frequency. */
static const char *const hb_iwan_calls[] = {"set_iwan(2 sliders)", "set_iwan(3 sliders)"};

/* create and the dense model (whose setters allocate nothing), no elements yet */
static int hb_iwan_open(void **obj)
{
    const double M[4] = {1.3, 0.0, 0.0, 0.9}, K[4] = {4.2, -1.7, -1.7, 2.385};
    const double pc[2] = {0.6, 0.0}, ps[2] = {0.0, 0.125};
    int status = hb_open(obj);
    if (status == FRICREG_OK && (fricreg_hb_set_mass(*obj, 2, M) != FRICREG_OK ||
                                 fricreg_hb_set_stiffness(*obj, 2, K) != FRICREG_OK ||
                                 fricreg_hb_set_rayleigh(*obj, 0.05, 0.01) != FRICREG_OK ||
                                 fricreg_hb_set_excitation(*obj, 2, pc, ps) != FRICREG_OK))
        NOTE("a dense setter failed");
    return status;
}

static int hb_iwan_call(void *obj, int i, struct view *v)
{
    (void)v;
    const double J[2] = {0.0, 1.0}, k[3] = {1.5, 0.7, 0.4}, phi[3] = {0.25, 0.1, 0.05};
    return fricreg_hb_set_iwan(obj, 1, 2, J, i == 0 ? 2 : 3, k, phi);
}

static void hb_iwan_observe(void *obj, struct view *v)
{
    double q[7] = {0}; /* a failed call leaves it: the view must read the same */
    see(v, fricreg_hb_solve(obj, 1.1, 7, NULL, q));
    see_all(v, q, 7);
}

static const struct script hb_iwan = {
    "hb set_iwan", 2,    hb_iwan_calls,   1,          0,       hb_iwan_open,
    hb_iwan_call,  NULL, hb_iwan_observe, hb_errcode, hb_close};

/* The capacitance solver of Newton's matrix: set_elements (no room at this size by default),
 * then set_newton_solver(capacitance), whose room is allocated at once; the view solves at one
 * frequency, by the capacitance where the room was made and densely where it failed. */
static const char *const hb_newton_solver_calls[] = {"set_elements",
                                                     "set_newton_solver(capacitance)"};

static int hb_newton_solver_call(void *obj, int i, struct view *v)
{
    (void)v;
    const double J[2] = {0.0, 1.0}, kt[1] = {1.5}, mun[1] = {0.25};
    if (i == 0)
        return fricreg_hb_set_elements(obj, 1, 2, J, kt, mun);
    return fricreg_hb_set_newton_solver(obj, FRICREG_HB_NEWTON_CAPACITANCE);
}

static const struct script hb_newton_solver = {
    "hb set_newton_solver", 2,    hb_newton_solver_calls, 0,          0,       hb_iwan_open,
    hb_newton_solver_call,  NULL, hb_iwan_observe,        hb_errcode, hb_close};

/* Elements with lift-off: set_normal_elements twice (the first grows the buffers sized by the
 * rows of J to two rows an element and allocates the parameters, the second only the
 * parameters, the first's freed after); the view solves at one frequency (nq = 2 (2H + 1)). */
static const char *const hb_normal_calls[] = {"set_normal_elements(grows)",
                                              "set_normal_elements(again)"};

static int hb_normal_call(void *obj, int i, struct view *v)
{
    (void)v;
    const double Jt[2] = {0.0, 1.0}, Jn[2] = {-1.0, 0.0}, kt[1] = {1.5}, mu[1] = {0.4},
                 n0[2] = {0.5, 0.3}, kn[1] = {2.0};
    return fricreg_hb_set_normal_elements(obj, 1, 2, Jt, Jn, kt, mu, n0 + i, kn);
}

static void hb_normal_observe(void *obj, struct view *v)
{
    double q[14] = {0}; /* a failed call leaves it: the view must read the same */
    see(v, fricreg_hb_solve(obj, 1.1, 14, NULL, q));
    see_all(v, q, 14);
}

static const struct script hb_normal = {
    "hb set_normal_elements", 2,    hb_normal_calls,   1,          0,       hb_iwan_open,
    hb_normal_call,           NULL, hb_normal_observe, hb_errcode, hb_close};

/* Iwan elements with lift-off: set_iwan_normal twice (the first grows the buffers sized by the
 * rows of J and allocates the normal law and the sliders with one slider's AFT scratch, the
 * second those two only); the view solves at one frequency (nq = 2 (2H + 1)). */
static const char *const hb_iwan_normal_calls[] = {"set_iwan_normal(grows, 2 sliders)",
                                                   "set_iwan_normal(3 sliders)"};

static int hb_iwan_normal_call(void *obj, int i, struct view *v)
{
    (void)v;
    const double Jt[2] = {0.0, 1.0}, Jn[2] = {-1.0, 0.0}, k[3] = {0.9, 0.4, 0.2},
                 mu[3] = {0.2, 0.1, 0.1}, n0[1] = {0.5}, kn[1] = {2.0};
    return fricreg_hb_set_iwan_normal(obj, 1, 2, Jt, Jn, i == 0 ? 2 : 3, k, mu, n0, kn);
}

static const struct script hb_iwan_normal = {
    "hb set_iwan_normal", 2,    hb_iwan_normal_calls, 1,          0,       hb_iwan_open,
    hb_iwan_normal_call,  NULL, hb_normal_observe,    hb_errcode, hb_close};

/* 3-D contact elements: set_jenkins_2d_normal twice (the first grows the buffers sized by the
 * rows of J to three rows an element and allocates the normal law, the two sampled AFT
 * workspaces and their results; the second only the normal law); the view solves at one
 * frequency (nq = 3 (2H + 1)). */
static const char *const hb_contact_3d_calls[] = {"set_jenkins_2d_normal(grows)",
                                                  "set_jenkins_2d_normal(again)"};

static int hb_contact_3d_call(void *obj, int i, struct view *v)
{
    (void)v;
    const double Je[4] = {1.0, 0.0, 0.0, 1.0}, Jn[2] = {0.4, -0.3}, kt[1] = {1.5}, mu[1] = {0.4},
                 n0[2] = {0.5, 0.3}, kn[1] = {2.0};
    return fricreg_hb_set_jenkins_2d_normal(obj, 1, 2, Je, Jn, kt, mu, n0 + i, kn);
}

static void hb_contact_3d_observe(void *obj, struct view *v)
{
    double q[21] = {0}; /* a failed call leaves it: the view must read the same */
    see(v, fricreg_hb_solve(obj, 1.1, 21, NULL, q));
    see_all(v, q, 21);
}

static const struct script hb_contact_3d = {
    "hb set_jenkins_2d_normal", 2,    hb_contact_3d_calls,   1,          0,       hb_iwan_open,
    hb_contact_3d_call,         NULL, hb_contact_3d_observe, hb_errcode, hb_close};

/* A mix by type: add_elements of a Jenkins element (the sliders' array), then of a 3-D contact
 * element beside it (the buffers grown to four rows, the sampled AFT, the sliders again, the
 * held ones copied), then of a spring (marched: its parameters' array and the march's
 * workspace); the view solves the whole model at one frequency (nq = 5 (2H + 1)), or reads the
 * refusal of an incomplete one. */
static const char *const hb_add_calls[] = {"add_elements(jenkins)", "add_elements(contact_3d)",
                                           "add_elements(spring)"};

static int hb_add_open(void **obj)
{
    const double M[4] = {1.3, 0.0, 0.0, 0.9}, K[4] = {4.2, -1.7, -1.7, 2.385};
    const double pc[2] = {0.6, 0.0}, ps[2] = {0.0, 0.125};
    fricreg_hb *hb = SENTINEL;
    int status = fricreg_hb_create(2, 3, 3, &hb);
    *obj = status == FRICREG_OK ? hb : NULL;
    if (status == FRICREG_OK && (fricreg_hb_set_mass(hb, 2, M) != FRICREG_OK ||
                                 fricreg_hb_set_stiffness(hb, 2, K) != FRICREG_OK ||
                                 fricreg_hb_set_rayleigh(hb, 0.05, 0.01) != FRICREG_OK ||
                                 fricreg_hb_set_excitation(hb, 2, pc, ps) != FRICREG_OK))
        NOTE("a dense setter failed");
    return status;
}

static int hb_add_call(void *obj, int i, struct view *v)
{
    (void)v;
    const double J[2] = {0.0, 1.0}, jenkins[2] = {1.5, 0.25};
    const double J3[6] = {1.0, 0.0, 0.0, 1.0, 0.4, -0.3}, contact[5] = {1.5, 0.4, 2.0, 0.5, 0.0};
    const double Js[2] = {1.0, -1.0}, spring[1] = {0.8};
    if (i == 0)
        return fricreg_hb_add_elements(obj, fricreg_element_lookup("jenkins"), 1, 2, J, jenkins);
    if (i == 1)
        return fricreg_hb_add_elements(obj, fricreg_element_lookup("contact_3d"), 1, 2, J3,
                                       contact);
    return fricreg_hb_add_elements(obj, fricreg_element_lookup("spring"), 1, 2, Js, spring);
}

static void hb_add_observe(void *obj, struct view *v)
{
    double q[35] = {0}; /* a failed call leaves it: the view must read the same */
    see(v, (double)fricreg_hb_element_count(obj));
    see(v, fricreg_hb_solve(obj, 1.1, 35, NULL, q));
    see_all(v, q, 35);
}

static const struct script hb_add = {
    "hb add_elements", 3,    hb_add_calls,   0,          0,       hb_add_open,
    hb_add_call,       NULL, hb_add_observe, hb_errcode, hb_close};

/* Hill's method turned on: set_stability's allocations (the companion matrix, the eigenvalues,
 * GSL's workspace on fricreg's memory, M's LU); the view solves with Jenkins elements and reads
 * the solution's stability (FRICREG_EINVAL when set_stability failed: it stayed off). */
static const char *const hb_stability_calls[] = {"set_elements", "set_stability"};

static int hb_stability_call(void *obj, int i, struct view *v)
{
    (void)v;
    const double J[2] = {0.0, 1.0}, kt[1] = {1.5}, mun[1] = {0.25};
    return i == 0 ? fricreg_hb_set_elements(obj, 1, 2, J, kt, mun)
                  : fricreg_hb_set_stability(obj, 1);
}

static void hb_stability_observe(void *obj, struct view *v)
{
    double q[7] = {0}, mu = 0.0;
    int stable = -1;
    see(v, fricreg_hb_solve(obj, 1.1, 7, NULL, q));
    see_all(v, q, 7);
    see(v, fricreg_hb_point_stability(obj, FRICREG_HB_SOLUTION, &stable, &mu));
    see(v, stable);
    see(v, mu);
}

static const struct script hb_stability = {
    "hb set_stability", 2,    hb_stability_calls,   0,          0,       hb_iwan_open,
    hb_stability_call,  NULL, hb_stability_observe, hb_errcode, hb_close};

/* ---- Harmonic balance: every allocation inside solve and continue ----------------------------
 *
 * The scripts above set the driver up under the failing allocator and solve in the view, which is
 * not failed. Here the model is set up first (unarmed) and every allocation made inside
 * fricreg_hb_solve, fricreg_hb_displacement and fricreg_hb_continue fails in turn: dense and
 * sparse models (KLU's analysis and factors), with Jenkins, Iwan and lift-off elements. A
 * dense driver allocates nothing in solve and displacement (its LU factors are on its own
 * arrays, lu.c: GSL 2.7's gsl_linalg_LU_decomp and gsl_linalg_complex_LU_decomp allocated their
 * pivots at every call and crashed on a failed malloc) and only the continuation's room for
 * points in continue; its branch here is long enough (more than 64 points) that the room
 * doubles, so a failed realloc strikes in the middle of the branch. Each case must:
 *   - return FRICREG_OK or FRICREG_ENOMEM from each call, a failure recorded in the driver;
 *   - a call that returned OK: its results equal the run with no failure, bit for bit;
 *   - a failed solve or displacement: the caller's array untouched; a failed continue: the
 *     points reached so far kept, each equal to the run's with no failure (fricreg_hb.h);
 *   - the same driver, run again with no failure, gives the reference run bit for bit;
 *   - never call GSL's error handler, leave no block allocated. */

enum { HB_JENKINS, HB_IWAN, HB_LIFTOFF };

struct hb_case {
    const char *name;
    int sparse, kind, stability;
    double omega, omega0, omega1, ds, ds_max;
    size_t max_points;
};

#define HB_MAX_POINTS 256
#define HB_UNTOUCHED (-2.385e-7) /* what the caller's arrays hold before a call */

struct hb_run {
    int status[3]; /* solve, displacement, continue */
    double q[14], x[14];
    size_t npts, nbif;
    double pts[3 * HB_MAX_POINTS];  /* Omega, rms[2] per point */
    double stab[2 * HB_MAX_POINTS]; /* with stability: stable, mu_max per point */
};

/* The 2-dof model of the scripts above (M, K, Rayleigh or, sparse, the _csc setters with C),
 * H = 3, one element on dof 1 (with lift-off, its normal row on dof 0) and the excitation. */
static fricreg_hb *hb_case_new(const struct hb_case *c)
{
    const double M[4] = {1.3, 0.0, 0.0, 0.9}, K[4] = {4.2, -1.7, -1.7, 2.385};
    const double J[2] = {0.0, 1.0}, Jn[2] = {-1.0, 0.0}, kt[1] = {1.5}, mun[1] = {0.25};
    const double k[3] = {1.5, 0.7, 0.4}, phi[3] = {0.25, 0.1, 0.05}, mu[1] = {0.4}, n0[1] = {0.5},
                 kn[1] = {2.0}, pc[2] = {0.6, 0.0}, ps[2] = {0.0, 0.125};
    fricreg_hb *hb = NULL;
    if (fricreg_hb_create(2, 1, 3, &hb) != FRICREG_OK)
        return NULL;
    int status = FRICREG_OK;
    for (int i = 0; i < 3 && c->sparse && status == FRICREG_OK; i++)
        status = hb_sparse_call(hb, i, NULL);
    if (!c->sparse && status == FRICREG_OK)
        status = fricreg_hb_set_mass(hb, 2, M);
    if (!c->sparse && status == FRICREG_OK)
        status = fricreg_hb_set_stiffness(hb, 2, K);
    if (!c->sparse && status == FRICREG_OK)
        status = fricreg_hb_set_rayleigh(hb, 0.05, 0.01);
    if (status == FRICREG_OK)
        status = c->kind == HB_JENKINS ? fricreg_hb_set_elements(hb, 1, 2, J, kt, mun)
                 : c->kind == HB_IWAN
                     ? fricreg_hb_set_iwan(hb, 1, 2, J, 3, k, phi)
                     : fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, kt, mu, n0, kn);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_excitation(hb, 2, pc, ps);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_continuation(hb, c->ds, 1e-6, c->ds_max, c->max_points);
    if (status == FRICREG_OK && c->stability)
        status = fricreg_hb_set_stability(hb, 1);
    if (status != FRICREG_OK) {
        fricreg_hb_free(hb);
        return NULL;
    }
    return hb;
}

static int hb_untouched(const double *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (x[k] != HB_UNTOUCHED)
            return 0;
    return 1;
}

/* solve at omega (from the stuck guess), the displacement, then the branch omega0 .. omega1
 * and its points; each failed call's status recorded in the driver (else a violation). */
static void hb_play(fricreg_hb *hb, const struct hb_case *c, struct hb_run *r, long *solve_allocs)
{
    size_t nq = c->kind == HB_LIFTOFF ? 14 : 7;
    memset(r, 0, sizeof *r);
    for (size_t k = 0; k < 14; k++)
        r->q[k] = r->x[k] = HB_UNTOUCHED;
    r->status[0] = fricreg_hb_solve(hb, c->omega, nq, NULL, r->q);
    r->status[1] = fricreg_hb_displacement(hb, 2, 7, r->x);
    if (solve_allocs != NULL)
        *solve_allocs = n_allocs;
    r->status[2] = fricreg_hb_continue(hb, c->omega0, c->omega1, nq, NULL);
    for (int i = 0; i < 3; i++)
        if (r->status[i] != FRICREG_OK && fricreg_hb_errcode(hb) != r->status[i] && i == 2)
            NOTE("continue returned %d, but %d recorded", r->status[i], fricreg_hb_errcode(hb));
    int was_paused = paused;
    paused = 1; /* the getters allocate nothing; reading them is not part of the case */
    r->npts = fricreg_hb_points(hb);
    if (r->npts > HB_MAX_POINTS)
        NOTE("%zu points: more than the test keeps", r->npts);
    for (size_t k = 0; k < r->npts && k < HB_MAX_POINTS; k++)
        if (fricreg_hb_point(hb, k, &r->pts[3 * k], 2, &r->pts[3 * k + 1]) != FRICREG_OK)
            NOTE("point %zu of %zu not readable", k, r->npts);
    for (size_t k = 0; c->stability && k < r->npts && k < HB_MAX_POINTS; k++) {
        int stable = -1;
        if (fricreg_hb_point_stability(hb, k, &stable, &r->stab[2 * k + 1]) != FRICREG_OK)
            NOTE("point %zu's stability not readable", k);
        r->stab[2 * k] = stable;
    }
    r->nbif = fricreg_hb_bifurcations(hb);
    paused = was_paused;
}

static int same_bits(const double *a, const double *b, size_t n)
{
    return memcmp(a, b, n * sizeof *a) == 0;
}

/* What a failed case's run must show against the reference ref; "" if it does. */
static const char *hb_judge(const struct hb_run *r, const struct hb_run *ref, size_t nq)
{
    for (int i = 0; i < 3; i++)
        if (r->status[i] != FRICREG_OK && r->status[i] != FRICREG_ENOMEM &&
            !(i == 1 && r->status[0] != FRICREG_OK && r->status[1] == FRICREG_EINVAL))
            return "a call returned neither FRICREG_OK nor FRICREG_ENOMEM";
    if (r->status[0] == FRICREG_OK ? !same_bits(r->q, ref->q, nq) : !hb_untouched(r->q, 14))
        return r->status[0] == FRICREG_OK ? "solve: OK with other results"
                                          : "solve failed but wrote q";
    if (r->status[1] == FRICREG_OK ? !same_bits(r->x, ref->x, 14) : !hb_untouched(r->x, 14))
        return r->status[1] == FRICREG_OK ? "displacement: OK with other results"
                                          : "displacement failed but wrote x";
    if (r->status[2] == FRICREG_OK && r->npts != ref->npts)
        return "continue: OK with another number of points";
    if (r->npts > ref->npts || !same_bits(r->pts, ref->pts, 3 * r->npts) ||
        !same_bits(r->stab, ref->stab, 2 * r->npts))
        return "continue: the points kept differ from the run's with no failure";
    return "";
}

static const struct hb_case hb_cases[] = {
    /* dense: a branch of more than 64 points (the room for points doubles once) */
    {"hb dense, Jenkins", 0, HB_JENKINS, 0, 1.1, 1.0, 1.2, 0.01, 0.01, HB_MAX_POINTS},
    {"hb dense, Iwan", 0, HB_IWAN, 0, 1.1, 1.0, 1.2, 0.01, 0.01, HB_MAX_POINTS},
    {"hb dense, lift-off", 0, HB_LIFTOFF, 0, 1.1, 1.0, 1.2, 0.01, 0.01, HB_MAX_POINTS},
    /* Hill's method on: solve and continue allocate nothing more (the stored points' room
     * grows with the points' extras) */
    {"hb dense, lift-off, stability", 0, HB_LIFTOFF, 1, 1.1, 1.0, 1.2, 0.01, 0.01, HB_MAX_POINTS},
    /* sparse: the first frequency's fresh factors allocate (KLU), the later ones refactor them
     * in place, so the same branches as dense */
    {"hb sparse, Jenkins", 1, HB_JENKINS, 0, 1.1, 1.0, 1.2, 0.01, 0.01, HB_MAX_POINTS},
    {"hb sparse, Iwan", 1, HB_IWAN, 0, 1.1, 1.0, 1.2, 0.01, 0.01, HB_MAX_POINTS},
    {"hb sparse, lift-off", 1, HB_LIFTOFF, 0, 1.1, 1.0, 1.2, 0.01, 0.01, HB_MAX_POINTS},
};

/* A failed case's tally: cases that ended FRICREG_ENOMEM somewhere, all OK, broken. */
struct hb_tally {
    long enomem, ok, broken;
    char first[512]; /* the first broken case, described */
};

/* What the allocator saw of a failed case once its driver is freed: why (the judge's verdict,
 * "" if it held) or the first broken promise: the failure not reached (exactly one), a
 * violation, a call to GSL's handler, a leak. */
static const char *hb_unkept(const char *why, long failed, long live_before)
{
    if (why[0] != '\0')
        return why;
    if (failed != 1)
        return "the allocation was not reached";
    if (violation[0] != '\0')
        return violation;
    if (gsl_handler_calls != 0)
        return gsl_handler_reason;
    return live != live_before ? "a block leaked" : "";
}

/* Counts failure k of n, whose three calls returned status[3], into *t. */
static void hb_count(struct hb_tally *t, const char *why, const int status[3], long k, long n)
{
    int any = 0;
    for (int i = 0; i < 3; i++)
        any |= status[i] == FRICREG_ENOMEM;
    t->enomem += any;
    t->ok += !any;
    if (why[0] != '\0' && t->broken++ == 0)
        snprintf(t->first, sizeof t->first, "allocation %ld of %ld: %s (statuses %d %d %d)", k, n,
                 why, status[0], status[1], status[2]);
}

START_TEST(test_hb_solve_continue)
{
    const struct hb_case *c = &hb_cases[_i];
    size_t nq = c->kind == HB_LIFTOFF ? 14 : 7;
    static struct hb_run ref, again, got;
    gsl_set_error_handler(count_gsl_error);
    gsl_handler_calls = 0;
    violation[0] = '\0';
    long live_before = live, solve_allocs = 0;
    /* armed from the set-up to the free, so that the hook tracks every block; counted and
     * failed only while not paused: the calls under test */
    hook_arm(0);
    paused = 1;
    fricreg_hb *hb = hb_case_new(c);
    if (hb == NULL) {
        hook_disarm();
        ck_abort_msg("%s: the set-up failed with no failure injected", c->name);
    }
    paused = 0;
    hb_play(hb, c, &ref, &solve_allocs);
    long n = n_allocs;
    paused = 1;
    hb_play(hb, c, &again, NULL); /* the same driver again: the same bits (the test's basis) */
    fricreg_hb_free(hb);
    hook_disarm();
    for (int i = 0; i < 3; i++)
        ck_assert_msg(ref.status[i] == FRICREG_OK, "%s: call %d returned %d with no failure",
                      c->name, i, ref.status[i]);
    ck_assert_msg(violation[0] == '\0', "%s: %s", c->name, violation);
    ck_assert_msg(memcmp(&ref, &again, sizeof ref) == 0, "%s: a second run differs", c->name);
    ck_assert_int_eq(live, live_before);
    if (!c->sparse) {
        ck_assert_msg(solve_allocs == 0, "%s: solve and displacement made %ld allocations", c->name,
                      solve_allocs);
        ck_assert_msg(ref.npts > 64, "%s: %zu points: the room for points does not grow", c->name,
                      ref.npts);
    }
    ck_assert_msg(n > 0, "%s: allocates nothing, so the loop tests nothing", c->name);
    struct hb_tally t = {0};
    for (long k = 1; k <= n; k = next_failure(k, n)) {
        live_before = live;
        violation[0] = '\0';
        gsl_handler_calls = 0;
        hook_arm(k);
        paused = 1;
        hb = hb_case_new(c); /* not failed (paused): it worked above */
        paused = 0;
        hb_play(hb, c, &got, NULL);
        paused = 1;
        long failed = n_failed;
        const char *why = hb_judge(&got, &ref, nq);
        if (why[0] == '\0') {
            hb_play(hb, c, &again, NULL); /* the driver still works, as before the failure */
            if (memcmp(&again, &ref, sizeof ref) != 0)
                why = "run again with no failure, the driver gives other results";
        }
        fricreg_hb_free(hb);
        hook_disarm();
        hb_count(&t, hb_unkept(why, failed, live_before), got.status, k, n);
    }
    printf("%s: %ld allocations in solve, displacement and continue (%ld in solve and "
           "displacement), %zu points: %ld cases, %ld ENOMEM, %ld OK, %ld broken\n",
           c->name, n, solve_allocs, ref.npts, n, t.enomem, t.ok, t.broken);
    fflush(stdout);
    ck_assert_msg(t.broken == 0, "%s: %ld broken, the first %s", c->name, t.broken, t.first);
}
END_TEST

/* ---- Harmonic balance: every allocation inside a backbone and a level continuation -----------
 *
 * As test_hb_solve_continue, for fricreg_hb_nma (its state, the linear mode's eigenproblem, a
 * sparse model's factors), fricreg_hb_nma_point with the harmonics (a sparse model refactors)
 * and fricreg_hb_continue_level, on hb_case_new's models. Each failed case must:
 *   - return FRICREG_OK or FRICREG_ENOMEM from each call, the failure recorded in the driver;
 *   - a failed backbone: the points reached kept (fricreg_hb.h), each equal to the run's with
 *     no failure, bit for bit; a failed point: the caller's x untouched; a failed level branch:
 *     its points reached kept, likewise;
 *   - a call that returned OK: its results equal the run's with no failure, bit for bit;
 *   - the same driver, run again with no failure, gives the reference run bit for bit;
 *   - never call GSL's error handler, leave no block allocated. */

#define NMA_POINTS 6
#define NMA_X_POINT 4         /* the point whose harmonics are read: the element slips there */
#define HB_NOT_CALLED (-1000) /* the point's status when the backbone has no such point */

struct hb_mode_run {
    int status[3]; /* nma, nma_point(NMA_X_POINT, with x), continue_level */
    size_t nnma, npts;
    double nma[3 * NMA_POINTS];    /* amplitude, omega, zeta per point */
    double x[14];                  /* the harmonics of point NMA_X_POINT, 2 dofs, H = 3 */
    double pts[4 * HB_MAX_POINTS]; /* omega, level, rms[2] per point */
};

/* The backbone of mode 0 through the element's first slip (between a = 0.17 and 0.26), to
 * a = 1 (sparse: 0.4, for fewer factors), the harmonics of its fifth point (slipping), then
 * the S-curve at Omega = 1.1 from level 0.5 to 2.5. */
static void hb_mode_play(fricreg_hb *hb, const struct hb_case *c, struct hb_mode_run *r)
{
    size_t nq = c->kind == HB_LIFTOFF ? 14 : 7;
    memset(r, 0, sizeof *r);
    for (size_t k = 0; k < 14; k++)
        r->x[k] = HB_UNTOUCHED;
    r->status[0] = fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, c->sparse ? 0.4 : 1.0,
                                  NMA_POINTS);
    int was_paused = paused;
    paused = 1; /* the getters without x allocate nothing */
    r->nnma = fricreg_hb_nma_points(hb);
    for (size_t k = 0; k < r->nnma && k < NMA_POINTS; k++)
        if (fricreg_hb_nma_point(hb, k, &r->nma[3 * k], &r->nma[3 * k + 1], &r->nma[3 * k + 2], 0,
                                 0, NULL) != FRICREG_OK)
            NOTE("backbone point %zu of %zu not readable", k, r->nnma);
    paused = was_paused;
    double a, w, z;
    r->status[1] = r->nnma > NMA_X_POINT
                       ? fricreg_hb_nma_point(hb, NMA_X_POINT, &a, &w, &z, 2, 7, r->x)
                       : HB_NOT_CALLED;
    r->status[2] = fricreg_hb_continue_level(hb, 1.1, 0.5, 2.5, nq, NULL);
    for (int i = 0; i < 3; i++)
        if (r->status[i] != FRICREG_OK && r->status[i] != HB_NOT_CALLED &&
            fricreg_hb_errcode(hb) != r->status[i] && i != 1)
            NOTE("call %d returned %d, but %d recorded", i, r->status[i], fricreg_hb_errcode(hb));
    paused = 1;
    r->npts = fricreg_hb_points(hb);
    if (r->npts > HB_MAX_POINTS)
        NOTE("%zu points: more than the test keeps", r->npts);
    for (size_t k = 0; k < r->npts && k < HB_MAX_POINTS; k++)
        if (fricreg_hb_point(hb, k, &r->pts[4 * k], 2, &r->pts[4 * k + 2]) != FRICREG_OK ||
            fricreg_hb_point_level(hb, k, &r->pts[4 * k + 1]) != FRICREG_OK)
            NOTE("level point %zu of %zu not readable", k, r->npts);
    paused = was_paused;
}

/* What a failed case's run must show against the reference ref; "" if it does. */
static const char *hb_mode_judge(const struct hb_mode_run *r, const struct hb_mode_run *ref)
{
    for (int i = 0; i < 3; i++)
        if (r->status[i] != FRICREG_OK && r->status[i] != FRICREG_ENOMEM &&
            !(i == 1 && r->status[i] == HB_NOT_CALLED && r->nnma <= NMA_X_POINT))
            return "a call returned neither FRICREG_OK nor FRICREG_ENOMEM";
    if (r->status[0] == FRICREG_OK && r->nnma != ref->nnma)
        return "nma: OK with another number of points";
    if (r->nnma > ref->nnma || !same_bits(r->nma, ref->nma, 3 * r->nnma))
        return "nma: the points kept differ from the run's with no failure";
    if (r->status[1] == FRICREG_OK ? !same_bits(r->x, ref->x, 14) : !hb_untouched(r->x, 14))
        return r->status[1] == FRICREG_OK ? "nma_point: OK with other harmonics"
                                          : "nma_point failed but wrote x";
    if (r->status[2] == FRICREG_OK && r->npts != ref->npts)
        return "continue_level: OK with another number of points";
    if (r->npts > ref->npts || !same_bits(r->pts, ref->pts, 4 * r->npts))
        return "continue_level: the points kept differ from the run's with no failure";
    return "";
}

static const struct hb_case hb_mode_cases[] = {
    {"hb modes, dense, Jenkins", 0, HB_JENKINS, 0, 1.1, 1.0, 1.2, 0.05, 0.05, HB_MAX_POINTS},
    {"hb modes, dense, lift-off", 0, HB_LIFTOFF, 0, 1.1, 1.0, 1.2, 0.05, 0.05, HB_MAX_POINTS},
    {"hb modes, sparse, Iwan", 1, HB_IWAN, 0, 1.1, 1.0, 1.2, 0.5, 1.0, HB_MAX_POINTS},
};

START_TEST(test_hb_nma_level)
{
    const struct hb_case *c = &hb_mode_cases[_i];
    static struct hb_mode_run ref, again, got;
    gsl_set_error_handler(count_gsl_error);
    gsl_handler_calls = 0;
    violation[0] = '\0';
    long live_before = live;
    hook_arm(0);
    paused = 1;
    fricreg_hb *hb = hb_case_new(c);
    if (hb == NULL) {
        hook_disarm();
        ck_abort_msg("%s: the set-up failed with no failure injected", c->name);
    }
    paused = 0;
    hb_mode_play(hb, c, &ref);
    long n = n_allocs;
    paused = 1;
    hb_mode_play(hb, c, &again);
    fricreg_hb_free(hb);
    hook_disarm();
    for (int i = 0; i < 3; i++)
        ck_assert_msg(ref.status[i] == FRICREG_OK, "%s: call %d returned %d with no failure",
                      c->name, i, ref.status[i]);
    ck_assert_msg(ref.nnma == NMA_POINTS && ref.npts > 2, "%s: %zu backbone points, %zu level",
                  c->name, ref.nnma, ref.npts);
    ck_assert_msg(violation[0] == '\0', "%s: %s", c->name, violation);
    ck_assert_msg(memcmp(&ref, &again, sizeof ref) == 0, "%s: a second run differs", c->name);
    ck_assert_int_eq(live, live_before);
    ck_assert_msg(n > 0, "%s: allocates nothing, so the loop tests nothing", c->name);
    struct hb_tally t = {0};
    for (long k = 1; k <= n; k = next_failure(k, n)) {
        live_before = live;
        violation[0] = '\0';
        gsl_handler_calls = 0;
        hook_arm(k);
        paused = 1;
        hb = hb_case_new(c);
        paused = 0;
        hb_mode_play(hb, c, &got);
        paused = 1;
        long failed = n_failed;
        const char *why = hb_mode_judge(&got, &ref);
        if (why[0] == '\0') {
            hb_mode_play(hb, c, &again);
            if (memcmp(&again, &ref, sizeof ref) != 0)
                why = "run again with no failure, the driver gives other results";
        }
        fricreg_hb_free(hb);
        hook_disarm();
        hb_count(&t, hb_unkept(why, failed, live_before), got.status, k, n);
    }
    printf("%s: %ld allocations in nma, nma_point and continue_level, %zu + %zu points: %ld "
           "ENOMEM, %ld OK, %ld broken\n",
           c->name, n, ref.nnma, ref.npts, t.enomem, t.ok, t.broken);
    fflush(stdout);
    ck_assert_msg(t.broken == 0, "%s: %ld broken, the first %s", c->name, t.broken, t.first);
}
END_TEST

/* The AFT's six evaluations, each path, with and without the Jacobian, and the Iwan elements'
 * setters, trials, commit, reset and getters, make no allocation at all (their headers: all
 * memory is allocated at create), so no allocation can fail inside them; the create scripts
 * above fail every allocation of the creates. */
START_TEST(test_aft_iwan_calls_do_not_allocate)
{
    fricreg_aft *a = NULL;
    ck_assert_int_eq(fricreg_aft_create(3, 64, &a), FRICREG_OK);
    const double u[7] = {0.3, 1.2, -0.4, 0.1, 0.9, -0.7, 0.35}, k[2] = {2.385, 1.0},
                 phi[2] = {0.7, 0.25}, g[7] = {0.2, 0.5, 0.1, -0.3, 0.05, 0.0, 0.1};
    double f[7], nf[7], jac[49], jac2[196];
    int st[12], c = 0;
    gsl_set_error_handler(count_gsl_error);
    gsl_handler_calls = 0;
    hook_arm(1);
    for (int j = 0; j < 2; j++) {
        st[c++] = fricreg_aft_jenkins_exact(a, 2.385, 0.7, 7, u, f, j ? jac : NULL);
        st[c++] = fricreg_aft_jenkins_sampled(a, 2.385, 0.7, 7, u, f, j ? jac : NULL);
        st[c++] = fricreg_aft_iwan_exact(a, 2, k, phi, 7, u, f, j ? jac : NULL);
        st[c++] = fricreg_aft_iwan_sampled(a, 2, k, phi, 7, u, f, j ? jac : NULL);
        st[c++] = fricreg_aft_jenkins_normal_exact(a, 2.385, 0.4, 0.3, 2.0, 7, u, g, f, nf,
                                                   j ? jac2 : NULL);
        st[c++] = fricreg_aft_jenkins_normal_sampled(a, 2.385, 0.4, 0.3, 2.0, 7, u, g, f, nf,
                                                     j ? jac2 : NULL);
    }
    hook_disarm();
    for (int i = 0; i < c; i++)
        ck_assert_msg(st[i] == FRICREG_OK, "AFT call %d: %s", i, fricreg_aft_errmsg(a));
    ck_assert_msg(n_allocs == 0, "AFT evaluations made %ld allocations", n_allocs);
    fricreg_aft_free(a);

    for (int dim = 1; dim <= 2; dim++) {
        fricreg_iwan *iw = NULL;
        ck_assert_int_eq(fricreg_iwan_create(dim, 2, 3, &iw), FRICREG_OK);
        const double ki[6] = {2.385, 1.0, 0.5, 1.5, 0.25, 3.0}, pi[6] = {0.7125, 0.25, 3, 1, 1, 1};
        const double fs[2] = {2.385, 1.0}, kt[2] = {10.0, 4.0}, chi[2] = {-0.5, -0.2},
                     beta[2] = {0.35, 0.0}, n0[2] = {1.5, 2.0}, kn[2] = {3.0, 0.0};
        const double ui[4] = {0.5, -0.25, 1.5, 0.0}, gi[2] = {0.1, -0.2};
        double fo[4], t[8], tg[4], nfo[2], w[12], kk[6], pp[6];
        int s[10];
        hook_arm(1);
        s[0] = fricreg_iwan_set_params(iw, 2, 3, ki, pi);
        s[1] = fricreg_iwan_get_params(iw, 2, 3, kk, pp);
        s[2] = fricreg_iwan_trial(iw, 2, ui, fo, t);
        s[3] = fricreg_iwan_commit(iw);
        s[4] = fricreg_iwan_set_segalman(iw, 2, fs, kt, chi, beta, 1e-4);
        s[5] = fricreg_iwan_set_normal(iw, 2, n0, kn);
        s[6] = fricreg_iwan_trial_normal(iw, 2, ui, gi, fo, nfo, t, tg);
        s[7] = fricreg_iwan_commit(iw);
        s[8] = fricreg_iwan_get_slider(iw, 2, 3, w);
        s[9] = fricreg_iwan_reset(iw);
        hook_disarm();
        for (int i = 0; i < 10; i++)
            ck_assert_msg(s[i] == FRICREG_OK, "dim %d, Iwan call %d: %s", dim, i,
                          fricreg_iwan_errmsg(iw));
        ck_assert_msg(n_allocs == 0, "dim %d: Iwan calls made %ld allocations", dim, n_allocs);
        fricreg_iwan_free(iw);
    }
    ck_assert_int_eq(gsl_handler_calls, 0);
}
END_TEST

/* ---- The tests ------------------------------------------------------------------------------- */

START_TEST(test_ctx_create)
{
    struct tally t = fail_each_allocation(&ctx_create);
    ck_assert_int_eq(t.enomem, t.cases); /* nothing to fall back on: each failure is reported */
}
END_TEST

START_TEST(test_ctx_set_coupling_dense)
{
    struct tally t = fail_each_allocation(&ctx_coupling);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_ctx_solve_step)
{
    struct tally t = fail_each_allocation(&ctx_solve_step);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_ctx_stick_stiffness)
{
    struct tally t = fail_each_allocation(&ctx_stiffness);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_ctx_set_stribeck)
{
    struct tally t = fail_each_allocation(&ctx_stribeck);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* fricreg.h: "fricreg_ctx_eval never allocates". With every allocation failing, evaluations
 * under both partitions, in stick and in slip, with a dense W, still succeed. */
START_TEST(test_eval_does_not_allocate)
{
    double W[M_DENSE * M_DENSE], f[M_DENSE], f_eq[M_DENSE];
    dense_w(W, -0.731);
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(M_DENSE, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M_DENSE, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M_DENSE, MUN5), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    for (int partition = 0; partition < 2; partition++) {
        ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition ? FRICREG_PARTITION_PAPER
                                                                  : FRICREG_PARTITION_CONSISTENT),
                         FRICREG_OK);
        int with_feq = FRICREG_ENOMEM, without = FRICREG_ENOMEM, switching = FRICREG_ENOMEM;
        double g[FRICREG_SWITCH_PER_CONTACT * M_DENSE];
        hook_arm(1); /* the first request would fail: none may be made */
        with_feq = fricreg_ctx_eval(ctx, M_DENSE, ZDOT5[0], AFREE5[0], f, f_eq);
        without = fricreg_ctx_eval(ctx, M_DENSE, ZDOT5[0], AFREE5[0], f, NULL);
        /* nor do the switching functions ("No heap allocation") */
        switching = fricreg_ctx_switching(ctx, M_DENSE, ZDOT5[0], AFREE5[0], f, g,
                                          sizeof g / sizeof g[0]);
        hook_disarm();
        ck_assert_int_eq(with_feq, FRICREG_OK);
        ck_assert_int_eq(without, FRICREG_OK);
        ck_assert_int_eq(switching, FRICREG_OK);
        ck_assert_msg(n_allocs == 0, "partition %d: eval made %ld allocations", partition,
                      n_allocs);
    }
    fricreg_ctx_free(ctx);
    /* The hook sees the library's allocations: the same set-up under it makes some. */
    struct view v;
    int failed;
    ck_assert_int_eq(play(&ctx_coupling, 0, -1, -1, &v, &failed), FRICREG_OK);
    ck_assert_msg(n_allocs > 0, "set-up allocated nothing: the hook is not in place");
}
END_TEST

/* CHOLMOD works around a few failed allocations of its own: cholmod_l_add shrinks its result
 * to fit at the end, and a shrink that fails leaves it larger (W given whole: its symmetric
 * part, and its difference from its transpose). Those calls return FRICREG_OK having done
 * their work, which fail_each_allocation checks, so not every case is FRICREG_ENOMEM here. */
START_TEST(test_ctx_set_coupling_sparse)
{
    struct tally t = fail_each_allocation(&ctx_sparse);
    ck_assert_int_ge(t.enomem, t.cases - 4);
}
END_TEST

/* fricreg.h: with a sparse W too, eval, tangent and tangent_apply never allocate, also when
 * the near-stick set changes by a few contacts (CHOLMOD's row updates of the factor) or by many
 * (fresh factorizations), under both partitions. A chain of M_CHAIN contacts; the sets change
 * along a walk of velocities, fixed numbers. */
#define M_CHAIN 64

START_TEST(test_sparse_eval_does_not_allocate)
{
    int64_t ptr[M_CHAIN + 1], ind[3 * M_CHAIN];
    double val[3 * M_CHAIN], mun[M_CHAIN], zdot[M_CHAIN], a_free[M_CHAIN], f[M_CHAIN];
    static double T[M_CHAIN * M_CHAIN];
    size_t n = 0;
    for (size_t i = 0; i < M_CHAIN; i++) {
        ptr[i] = (int64_t)n;
        for (size_t j = i > 0 ? i - 1 : 0; j <= i + 1 && j < M_CHAIN; j++) {
            ind[n] = (int64_t)j;
            val[n++] = i == j ? 2.385 + 0.125 * (double)(i % 5) : -0.731;
        }
        mun[i] = 0.25 + 0.0625 * (double)(i % 7);
        a_free[i] = 0.9375 * sin(0.7 * (double)i);
    }
    ptr[M_CHAIN] = (int64_t)n;
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(M_CHAIN, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_csr(ctx, M_CHAIN, 0, ptr, ind, val), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M_CHAIN, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    for (int partition = 0; partition < 2; partition++) {
        ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition ? FRICREG_PARTITION_PAPER
                                                                  : FRICREG_PARTITION_CONSISTENT),
                         FRICREG_OK);
        int64_t before = 0, updates = 0;
        fricreg_ctx_get_stat(ctx, FRICREG_STAT_FACTOR_UPDATES, &before);
        int status = FRICREG_OK;
        hook_arm(1); /* the first request would fail: none may be made */
        for (int step = 0; step < 60 && status == FRICREG_OK; step++) {
            /* every contact in or near the band; step by step a few, and now and then all,
             * move across it */
            for (size_t i = 0; i < M_CHAIN; i++) {
                double phase = (double)i * 0.37 + (step % 10 == 9 ? 1.3 * step : 0.05 * step);
                zdot[i] = 0.03 * sin(phase) * (i % 3 == 0 ? 1.0 : 0.5);
            }
            status = fricreg_ctx_eval(ctx, M_CHAIN, zdot, a_free, f, NULL);
            if (status == FRICREG_OK && step % 7 == 0)
                status = fricreg_ctx_tangent_apply(ctx, M_CHAIN, zdot, a_free, f);
            if (status == FRICREG_OK && step % 20 == 0)
                status = fricreg_ctx_tangent(ctx, M_CHAIN, T, NULL);
        }
        double lambda = 0.0;
        if (status == FRICREG_OK)
            status = fricreg_ctx_stick_stiffness(ctx, &lambda);
        hook_disarm();
        ck_assert_msg(status == FRICREG_OK, "partition %d: %s", partition, fricreg_ctx_errmsg(ctx));
        ck_assert_msg(n_allocs == 0, "partition %d: %ld allocations", partition, n_allocs);
        fricreg_ctx_get_stat(ctx, FRICREG_STAT_FACTOR_UPDATES, &updates);
        ck_assert_msg(updates > before, "partition %d: no factor update was exercised", partition);
    }
    fricreg_ctx_free(ctx);
}
END_TEST

/* fricreg_ctx_solve_step with a tangent that has no rows (the paper's partition on a coupled W,
 * a near-stick set): the dense Newton matrix goes dense, above 64 contacts too, and a call
 * after the first allocates nothing (fricreg_structure.h: the dense matrix is reserved "wherever
 * the law's tangent may need it"). Two ways in: a context on the paper's partition from its
 * first call, which slides everywhere (rows serve); and one whose kept solver was built on the
 * consistent partition, then switched to the paper's. In both, the armed call is the first
 * near stick. */
enum { M_STEP = 80 };

static void step_inputs(double W[M_STEP * M_STEP], double Weff[M_STEP * M_STEP], double mun[M_STEP])
{
    for (size_t i = 0; i < M_STEP; i++) {
        mun[i] = 0.5 + 0.01 * (double)i;
        for (size_t j = 0; j < M_STEP; j++) {
            double w = i == j ? 2.0 : (i + 1 == j || j + 1 == i ? -0.5 : 0.0);
            W[i * M_STEP + j] = w;
            Weff[i * M_STEP + j] = 0.25 * w;
        }
    }
}

static int step_at(fricreg_ctx *ctx, const double W[], const double Weff[], double speed,
                   double f[M_STEP])
{
    double z0[M_STEP], ap[M_STEP];
    int info[2];
    for (size_t i = 0; i < M_STEP; i++) {
        z0[i] = (i % 2 ? speed : -speed) * (1.0 + 0.01 * (double)i);
        ap[i] = 0.1 * (double)(i % 5) - 0.2;
    }
    return fricreg_ctx_solve_step(ctx, M_STEP, z0, z0, ap, W, Weff, 0.005, 1e-10, 30, 0, f, info);
}

static fricreg_ctx *step_context(int partition, const double W[], const double mun[])
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(M_STEP, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M_STEP, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M_STEP, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 1e-3), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
    return ctx;
}

START_TEST(test_solve_step_dense_tangent_does_not_allocate)
{
    static double W[M_STEP * M_STEP], Weff[M_STEP * M_STEP];
    double mun[M_STEP], f[M_STEP];
    step_inputs(W, Weff, mun);
    fricreg_ctx *paper = step_context(FRICREG_PARTITION_PAPER, W, mun);
    fricreg_ctx *switched = step_context(FRICREG_PARTITION_CONSISTENT, W, mun);
    memcpy(f, mun, sizeof f);
    ck_assert_int_eq(step_at(paper, W, Weff, 0.5, f), FRICREG_OK); /* builds the solver */
    ck_assert_int_eq(step_at(switched, W, Weff, 1e-5, f), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(switched, FRICREG_PARTITION_PAPER), FRICREG_OK);
    ck_assert_int_eq(step_at(switched, W, Weff, 0.5, f), FRICREG_OK); /* may rebuild it */
    fricreg_ctx *ctxs[2] = {paper, switched};
    for (int k = 0; k < 2; k++) {
        memcpy(f, mun, sizeof f);
        hook_arm(1); /* the first request would fail: none may be made */
        int status = step_at(ctxs[k], W, Weff, 1e-5, f);
        hook_disarm();
        ck_assert_msg(status == FRICREG_OK && n_allocs == 0,
                      "context %d: status %d after %ld allocations", k, status, n_allocs);
        fricreg_ctx_free(ctxs[k]);
    }
}
END_TEST

START_TEST(test_disk_ctx_set_coupling)
{
    struct tally t = fail_each_allocation(_i == 0 ? &disk_dense : &disk_blocks_script);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* ---- Identification ---------------------------------------------------------------------- */

/* A fit of the modal Iwan model (fricreg_fit.h): levels, deviations, beta fixed, a run of 4
 * starts; the view is the fit's parameters, covariance and residuals (or the getters' statuses
 * where there is none) and a further eval. The levels: tests/fit/test_fit.c's joint at 6
 * amplitudes, made by fricreg_fit_eval outside the armed hook. */
#define FIT_NL 6
static double fit_amp[FIT_NL], fit_freq[FIT_NL], fit_zeta[FIT_NL], fit_sd_f[FIT_NL],
    fit_sd_z[FIT_NL];

static int fit_open(void **obj)
{
    fricreg_fit *fit = SENTINEL;
    int status = fricreg_fit_create(&fit);
    if (status != FRICREG_OK && fit != SENTINEL)
        NOTE("fit_create failed (%d) but wrote its handle", status);
    *obj = status == FRICREG_OK ? fit : NULL;
    return status;
}

static const char *const fit_call_names[] = {"fit_set_levels", "fit_set_deviations",
                                             "fit_set_fixed", "fit_run"};

static int fit_call(void *obj, int i, struct view *v)
{
    (void)v;
    fricreg_fit *fit = obj;
    switch (i) {
    case 0:
        return fricreg_fit_set_levels(fit, FIT_NL, FRICREG_FIT_DISPLACEMENT, fit_amp, fit_freq,
                                      fit_zeta);
    case 1: return fricreg_fit_set_deviations(fit, FIT_NL, fit_sd_f, fit_sd_z);
    case 2: return fricreg_fit_set_fixed(fit, FRICREG_FIT_BETA, 0.5);
    default: fricreg_fit_set_starts(fit, 4); return fricreg_fit_run(fit);
    }
}

static void fit_observe(void *obj, struct view *v)
{
    fricreg_fit *fit = obj;
    double p[FRICREG_FIT_NPARAMS], cov[FRICREG_FIT_NPARAMS * FRICREG_FIT_NPARAMS], r[2 * FIT_NL];
    double f[2], z[2], a[2] = {1e-5, 2e-4};
    const double q[FRICREG_FIT_NPARAMS] = {30.0, 3e5, 0.3, 0.5, 0.002, 8.4e5};
    int st = fricreg_fit_get_params(fit, FRICREG_FIT_NPARAMS, p);
    see(v, st);
    if (st == FRICREG_OK) {
        see_all(v, p, FRICREG_FIT_NPARAMS);
        see(v, fricreg_fit_get_covariance(fit, FRICREG_FIT_NPARAMS, cov, NULL, NULL));
        see_all(v, cov, FRICREG_FIT_NPARAMS * FRICREG_FIT_NPARAMS);
        see(v, fricreg_fit_get_residuals(fit, FIT_NL, r, r + FIT_NL));
        see_all(v, r, 2 * FIT_NL);
    }
    see(v, fricreg_fit_eval(fit, q, FRICREG_FIT_DISPLACEMENT, 2, a, f, z, NULL, NULL, NULL));
    see_all(v, f, 2);
    see_all(v, z, 2);
}

static int fit_errcode(const void *obj)
{
    return fricreg_fit_errcode(obj);
}

static void fit_close(void *obj)
{
    fricreg_fit_free(obj);
}

static const struct script fit_script = {"fit",       4,           fit_call_names, 0,
                                         0,           fit_open,    fit_call,       NULL,
                                         fit_observe, fit_errcode, fit_close};

START_TEST(test_fit_run)
{
    fricreg_fit *fit = NULL;
    const double q[FRICREG_FIT_NPARAMS] = {30.0, 3e5, 0.3, 0.5, 0.002, 8.4e5};
    for (int i = 0; i < FIT_NL; i++)
        fit_amp[i] = 5e-6 * pow(50.0, i / (FIT_NL - 1.0));
    ck_assert_int_eq(fricreg_fit_create(&fit), FRICREG_OK);
    ck_assert_int_eq(fricreg_fit_eval(fit, q, FRICREG_FIT_DISPLACEMENT, FIT_NL, fit_amp, fit_freq,
                                      fit_zeta, NULL, NULL, NULL),
                     FRICREG_OK);
    fricreg_fit_free(fit);
    for (int i = 0; i < FIT_NL; i++) {
        fit_sd_f[i] = 5e-4 * fit_freq[i];
        fit_sd_z[i] = 0.01 * fit_zeta[i];
        fit_freq[i] *= 1.0 + 2e-4 * sin(1.7 * i); /* a residual, so the covariance is seen */
    }
    struct tally t = fail_each_allocation(&fit_script);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_jenkins_create)
{
    struct tally t = fail_each_allocation(&jk_create);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* trial and commit of a set-up object request no memory. */
START_TEST(test_jenkins_trial_does_not_allocate)
{
    fricreg_jenkins *j = NULL;
    ck_assert_int_eq(fricreg_jenkins_create(2, 2, &j), FRICREG_OK);
    const double u[4] = {0.5, -2.25, 0.125, 0.0};
    double f[4], t[8];
    hook_arm(1);
    int status = fricreg_jenkins_trial(j, 2, u, f, t);
    int commit = fricreg_jenkins_commit(j);
    hook_disarm();
    ck_assert_int_eq(status, FRICREG_OK);
    ck_assert_int_eq(commit, FRICREG_OK);
    ck_assert_msg(n_allocs == 0, "jenkins trial and commit made %ld allocations", n_allocs);
    fricreg_jenkins_free(j);
}
END_TEST

START_TEST(test_aft_create)
{
    struct tally t = fail_each_allocation(&aft_create);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* both paths' evaluations, with Jacobians, of a set-up workspace request no memory. */
START_TEST(test_hb_create)
{
    struct tally t = fail_each_allocation(&hb_create);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* every allocation of the _csc setters fails cleanly: ENOMEM and the model as before the call,
 * or (4 of 196: cholmod_l_add's final shrink of a matrix given whole, as in
 * test_ctx_set_coupling_sparse) OK with the same model, which fail_each_allocation checks */
START_TEST(test_hb_sparse)
{
    struct tally t = fail_each_allocation(&hb_sparse);
    ck_assert_int_ge(t.enomem, t.cases - 4);
}
END_TEST

/* set_iwan's one allocation fails cleanly: ENOMEM and the sliders as before */
START_TEST(test_hb_iwan)
{
    struct tally t = fail_each_allocation(&hb_iwan);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* set_newton_solver's room fails cleanly: ENOMEM and the dense solver as before */
START_TEST(test_hb_newton_solver)
{
    struct tally t = fail_each_allocation(&hb_newton_solver);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* set_stability's allocations fail cleanly: ENOMEM and stability still off */
START_TEST(test_hb_stability)
{
    struct tally t = fail_each_allocation(&hb_stability);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* set_normal_elements' allocations fail cleanly: ENOMEM and the elements as before */
START_TEST(test_hb_normal)
{
    struct tally t = fail_each_allocation(&hb_normal);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* set_iwan_normal's allocations fail cleanly: ENOMEM and the elements as before */
START_TEST(test_hb_iwan_normal)
{
    struct tally t = fail_each_allocation(&hb_iwan_normal);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* set_jenkins_2d_normal's allocations fail cleanly: ENOMEM and the elements as before */
START_TEST(test_hb_contact_3d)
{
    struct tally t = fail_each_allocation(&hb_contact_3d);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* add_elements's allocations fail cleanly: ENOMEM and the elements as before */
START_TEST(test_hb_add_elements)
{
    struct tally t = fail_each_allocation(&hb_add);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_aft_eval_does_not_allocate)
{
    fricreg_aft *a = NULL;
    ck_assert_int_eq(fricreg_aft_create(3, 64, &a), FRICREG_OK);
    const double u[7] = {0.3, 1.2, -0.4, 0.1, 0.9, -0.7, 0.35}, k[2] = {2.385, 1.0},
                 phi[2] = {0.7, 0.25};
    double f[7], jac[49];
    int st[5];
    hook_arm(1);
    st[0] = fricreg_aft_jenkins_exact(a, 2.385, 0.7, 7, u, f, jac);
    st[1] = fricreg_aft_jenkins_sampled(a, 2.385, 0.7, 7, u, f, jac);
    st[2] = fricreg_aft_iwan_exact(a, 2, k, phi, 7, u, f, jac);
    st[3] = fricreg_aft_iwan_sampled(a, 2, k, phi, 7, u, f, jac);
    double u2[14] = {0.3, 1.2, -0.4, 0.1, 0.9, -0.7, 0.35, 0.0, 0.2, 0.8}, g[7] = {0.1, 0.3};
    double f2[14], nf[7], jac3[441];
    st[4] = fricreg_aft_jenkins_2d_normal_sampled(a, 2.385, 0.3, 1.0, 2.0, 7, u2, g, f2, nf, jac3);
    hook_disarm();
    for (int i = 0; i < 5; i++)
        ck_assert_int_eq(st[i], FRICREG_OK);
    ck_assert_msg(n_allocs == 0, "AFT evaluations made %ld allocations", n_allocs);
    fricreg_aft_free(a);
}
END_TEST

START_TEST(test_iwan_create)
{
    struct tally t = fail_each_allocation(&iw_create);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* trial, trial_normal and commit of a set-up object request no memory. */
START_TEST(test_iwan_trial_does_not_allocate)
{
    fricreg_iwan *iw = NULL;
    ck_assert_int_eq(fricreg_iwan_create(2, 2, 4, &iw), FRICREG_OK);
    const double u[4] = {0.5, -2.25, 0.125, 0.0}, g[2] = {0.25, -3.0};
    double f[4], t[8], tg[4], nf[2];
    hook_arm(1);
    int status = fricreg_iwan_trial(iw, 2, u, f, t);
    int normal = fricreg_iwan_trial_normal(iw, 2, u, g, f, nf, t, tg);
    int commit = fricreg_iwan_commit(iw);
    hook_disarm();
    ck_assert_int_eq(status, FRICREG_OK);
    ck_assert_int_eq(normal, FRICREG_OK);
    ck_assert_int_eq(commit, FRICREG_OK);
    ck_assert_msg(n_allocs == 0, "iwan trials and commit made %ld allocations", n_allocs);
    fricreg_iwan_free(iw);
}
END_TEST

START_TEST(test_disk_ctx_create)
{
    struct tally t = fail_each_allocation(&disk_create);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* A disk context of M_DENSE contacts on the dense W of disk_dense_w. */
static fricreg_disk_ctx *disk_dense_ctx(void)
{
    double W[4 * M_DENSE * M_DENSE];
    disk_dense_w(W, 0.1);
    fricreg_disk_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_disk_ctx_create(M_DENSE, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, M_DENSE, W), FRICREG_OK);
    return ctx;
}

/* eval and tangent of a set-up disk context of M_DENSE contacts (at rest, in the band and
 * sliding) succeed with the first allocation armed to fail, and request none. */
static void expect_disk_eval_allocates_nothing(fricreg_disk_ctx *ctx, const char *what)
{
    double f[2 * M_DENSE], T[4 * M_DENSE * M_DENSE];
    hook_arm(1); /* the first request would fail: none may be made */
    int status = fricreg_disk_ctx_eval(ctx, M_DENSE, DZDOT[0], DAFREE[0], f);
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
    fricreg_disk_ctx *ctx = disk_dense_ctx();
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, M_DENSE, MUN5), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.02), FRICREG_OK);
    expect_disk_eval_allocates_nothing(ctx, "disk");
    fricreg_disk_ctx_free(ctx);
}
END_TEST

START_TEST(test_disk_ctx_set_coupling_sparse)
{
    struct tally t = fail_each_allocation(_i == 0 ? &disk_sparse : &disk_dense_sparse);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

/* A chain's W1 (x) I2, W1 = tridiag(-1, 2, -1) of order M_DENSE, by compressed rows: so
 * strongly coupled (cond 14) that block Gauss-Seidel does not converge in its first 8 sweeps
 * and Newton's method runs. */
static int64_t chain_ptr[2 * M_DENSE + 1], chain_ind[6 * M_DENSE];
static double chain_val[6 * M_DENSE];

static void disk_chain_w(void)
{
    int64_t e = 0;
    for (size_t r = 0; r < 2 * M_DENSE; r++) {
        chain_ptr[r] = e;
        for (int d = -1; d <= 1; d++) {
            size_t c = r + 2 * (size_t)(d + 1);
            if (c < 2 || c - 2 >= 2 * M_DENSE)
                continue;
            chain_ind[e] = (int64_t)(c - 2);
            chain_val[e++] = d == 0 ? 2.0 : -1.0;
        }
    }
    chain_ptr[2 * M_DENSE] = e;
}

/* With a sparse W, eval (block Gauss-Seidel, or Newton's method on CHOLMOD's factor, set up by
 * the setter) and the tangent (4m solves with that factor) allocate nothing either. */
START_TEST(test_disk_sparse_eval_does_not_allocate)
{
    fricreg_disk_ctx *ctx = NULL;
    disk_sparse_w();
    disk_chain_w();
    ck_assert_int_eq(fricreg_disk_ctx_create(M_DENSE, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, M_DENSE, MUN5), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_csr(ctx, M_DENSE,
                                                       FRICREG_SPARSE_ONE_BASED |
                                                           FRICREG_SPARSE_UPPER,
                                                       sparse_ptr, sparse_ind, sparse_val),
                     FRICREG_OK);
    expect_disk_eval_allocates_nothing(ctx, "disk sparse");
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_csr(ctx, M_DENSE, FRICREG_SPARSE_ZERO_BASED,
                                                       chain_ptr, chain_ind, chain_val),
                     FRICREG_OK);
    expect_disk_eval_allocates_nothing(ctx, "disk chain (cold)");
    expect_disk_eval_allocates_nothing(ctx, "disk chain (warm)");
    fricreg_disk_ctx_free(ctx);
}
END_TEST

START_TEST(test_disk_ctx_set_stribeck)
{
    struct tally t = fail_each_allocation(&disk_stribeck);
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

START_TEST(test_sim_run)
{
    current_system = systems[_i / (int)N_INTEGRATORS];
    current_integrator = integrators[_i % (int)N_INTEGRATORS];
    if (current_system == FRICREG_SYSTEM_TWOBLOCK && current_integrator == FRICREG_INT_CENTRAL_IMEX)
        return; /* refused (FRICREG_EINVAL) before the run allocates: test_central_imex.c */
    char name[64];
    snprintf(name, sizeof name, "sim %d %s", current_system,
             fricreg_integrator_name(current_integrator));
    struct script sc = sim_script;
    sc.name = name;
    fail_each_allocation(&sc);
}
END_TEST

START_TEST(test_sim_run_extrapolated)
{
    current_system = FRICREG_SYSTEM_OSCILLATOR;
    struct tally t = fail_each_allocation(&extrap_script);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_exact_run)
{
    struct tally t = fail_each_allocation(&exact_script);
    ck_assert_int_eq(t.enomem, t.cases);
}
END_TEST

START_TEST(test_exact_solve)
{
    fail_each_allocation(&exact_solve_script);
}
END_TEST

START_TEST(test_structure_run)
{
    static const char *const names[N_SCHEMES] = {"structure newmark", "structure hht",
                                                 "structure central difference",
                                                 "structure run_ode rkf45"};
    current_scheme = _i;
    struct script sc = structure_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    /* Every failure is FRICREG_ENOMEM but CHOLMOD's own fallbacks: it shrinks arrays it sized
     * generously (cholmod_l_add, cholmod_l_sort) and keeps the larger block when that realloc
     * fails. Those calls return OK with the same result, which fail_each_allocation checks. */
    ck_assert_int_ge(t.enomem, t.cases - 30);
}
END_TEST

START_TEST(test_structure_estimate_run)
{
    static const char *const names[N_SCHEMES] = {"structure newmark, error estimate",
                                                 "structure hht, error estimate",
                                                 "structure central difference, error estimate",
                                                 "structure run_ode rkf45, error estimate"};
    current_scheme = _i;
    struct script sc = structure_estimate_script;
    sc.name = names[_i];
    fail_each_allocation(&sc); /* a companion's failure is OK with the structure's own results */
}
END_TEST

START_TEST(test_structure_checkpoint_run)
{
    static const char *const names[N_SCHEMES] = {"structure newmark, checkpoint",
                                                 "structure hht, checkpoint",
                                                 "structure central difference, checkpoint",
                                                 "structure run_ode rkf45, checkpoint"};
    current_scheme = _i;
    struct script sc = structure_checkpoint_script;
    sc.name = names[_i];
    fail_each_allocation(&sc); /* the restore's companions: ENOMEM, the structure unchanged */
}
END_TEST

START_TEST(test_structure_jenkins_run)
{
    static const char *const names[3] = {"structure newmark, Jenkins elements",
                                         "structure hht, Jenkins elements",
                                         "structure central difference, Jenkins elements"};
    current_scheme = _i;
    struct script sc = structure_jenkins_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
}
END_TEST

START_TEST(test_structure_joint_run)
{
    static const char *const names[2] = {"structure newmark, Jenkins elements beside contacts",
                                         "structure hht, Jenkins elements beside contacts"};
    current_scheme = _i;
    struct script sc = structure_joint_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
}
END_TEST

START_TEST(test_structure_iwan_run)
{
    static const char *const names[3] = {"structure newmark, Iwan elements",
                                         "structure hht, Iwan elements",
                                         "structure central difference, Iwan elements"};
    current_scheme = _i;
    struct script sc = structure_iwan_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
}
END_TEST

START_TEST(test_structure_mix_run)
{
    static const char *const names[3] = {"structure newmark, a mix of element types",
                                         "structure hht, a mix of element types",
                                         "structure central difference, a mix of element types"};
    current_scheme = _i;
    struct script sc = structure_mix_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
}
END_TEST

START_TEST(test_structure_jenkins_2d_run)
{
    static const char *const names[5] = {"structure newmark, 2-D Jenkins elements",
                                         "structure hht, 2-D Jenkins elements",
                                         "structure central difference, 2-D Jenkins elements",
                                         "structure newmark, 2-D Jenkins elements beside contacts",
                                         "structure hht, 2-D Jenkins elements beside contacts"};
    current_scheme = _i % 3;
    structure_2d_joint = _i >= 3;
    struct script sc = structure_jenkins_2d_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    structure_2d_joint = 0;
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
}
END_TEST

START_TEST(test_structure_normal_run)
{
    static const char *const names[3] = {"structure newmark, lift-off elements",
                                         "structure hht, lift-off elements",
                                         "structure central difference, lift-off elements"};
    current_scheme = _i;
    struct script sc = structure_normal_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
}
END_TEST

/* Newmark only: the other schemes' allocations are set_jenkins_normal's (the same setter body
 * and step, test_structure_normal_run) */
START_TEST(test_structure_iwan_normal_run)
{
    current_scheme = SCHEME_NEWMARK;
    struct tally t = fail_each_allocation(&structure_iwan_normal_script);
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
}
END_TEST

START_TEST(test_structure_contact_3d_run)
{
    static const char *const names[3] = {"structure newmark, 3-D contact elements",
                                         "structure hht, 3-D contact elements",
                                         "structure central difference, 3-D contact elements"};
    current_scheme = _i;
    struct script sc = structure_contact_3d_script;
    sc.name = names[_i];
    struct tally t = fail_each_allocation(&sc);
    ck_assert_int_ge(t.enomem, t.cases - 30); /* CHOLMOD's own fallbacks, as above */
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
        ck_assert(scheme == SCHEME_CENTRAL || iterations > 0); /* Newton ran (a step whose start
                                                                * is its solution needs none) */
        fricreg_structure_free(s);
    }
}
END_TEST

/* A structure set up by call's eight setters (one of the element scenarios) under scheme,
 * stepped once so that its first step's storage (E, the joint step's) exists; then a run of
 * 499 steps that must make no allocation. */
static fricreg_structure *run_without_allocation(int (*call)(void *, int, struct view *),
                                                 int scheme)
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(3, 2, &s), FRICREG_OK);
    current_scheme = scheme;
    for (int i = 0; i < 8; i++)
        ck_assert_int_eq(call(s, i, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_step(s, 0.001), FRICREG_OK);
    hook_arm(1);
    int status = fricreg_structure_run(s, 0.001, 0.5);
    hook_disarm();
    ck_assert_int_eq(status, FRICREG_OK);
    ck_assert_msg(n_allocs == 0, "scheme %d: 499 steps made %ld allocations", scheme, n_allocs);
    return s;
}

/* The same with Jenkins elements: their Newton (GSL's pivoted QR on arrays of the setter) and
 * their explicit evaluation make no allocation either. */
START_TEST(test_structure_jenkins_steps_do_not_allocate)
{
    for (int scheme = SCHEME_NEWMARK; scheme <= SCHEME_CENTRAL; scheme++) {
        fricreg_structure *s = run_without_allocation(structure_jenkins_call, scheme);
        double D[2];
        ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 2, NULL, NULL, D), FRICREG_OK);
        ck_assert(D[0] > 0.0 || D[1] > 0.0); /* an element slipped: both pieces were solved */
        fricreg_structure_free(s);
    }
}
END_TEST

/* And beside contacts of bound > 0 (Newmark, HHT-alpha): once the first step has allocated
 * the joint step's storage, the joint Newton makes no allocation. */
START_TEST(test_structure_joint_steps_do_not_allocate)
{
    for (int scheme = SCHEME_NEWMARK; scheme <= SCHEME_HHT; scheme++)
        fricreg_structure_free(run_without_allocation(structure_joint_call, scheme));
}
END_TEST

/* And with lift-off elements: the coupled Newton makes no allocation. */
START_TEST(test_structure_normal_steps_do_not_allocate)
{
    for (int scheme = SCHEME_NEWMARK; scheme <= SCHEME_CENTRAL; scheme++)
        fricreg_structure_free(run_without_allocation(structure_normal_call, scheme));
}
END_TEST

/* And with Iwan elements: the sliders' sums make no allocation. */
START_TEST(test_structure_iwan_steps_do_not_allocate)
{
    for (int scheme = SCHEME_NEWMARK; scheme <= SCHEME_CENTRAL; scheme++) {
        fricreg_structure *s = run_without_allocation(structure_iwan_call, scheme);
        double D[2];
        ck_assert_int_eq(fricreg_structure_get_iwan_state(s, 2, 3, NULL, NULL, D), FRICREG_OK);
        ck_assert(D[0] > 0.0 || D[1] > 0.0); /* a slider slipped */
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
    tcase_add_test(core, test_ctx_solve_step);
    tcase_add_test(core, test_eval_does_not_allocate);
    tcase_add_test(core, test_ctx_set_coupling_sparse);
    tcase_add_test(core, test_sparse_eval_does_not_allocate);
    tcase_add_test(core, test_solve_step_dense_tangent_does_not_allocate);
    tcase_add_test(core, test_structure_steps_do_not_allocate);
    tcase_add_test(core, test_structure_jenkins_steps_do_not_allocate);
    tcase_add_test(core, test_structure_iwan_steps_do_not_allocate);
    tcase_add_test(core, test_structure_normal_steps_do_not_allocate);
    tcase_add_test(core, test_structure_joint_steps_do_not_allocate);
    tcase_add_test(core, test_disk_ctx_create);
    tcase_add_test(core, test_jenkins_create);
    tcase_add_test(core, test_jenkins_trial_does_not_allocate);
    tcase_add_test(core, test_iwan_create);
    tcase_add_test(core, test_iwan_trial_does_not_allocate);
    tcase_add_test(core, test_aft_create);
    tcase_add_test(core, test_aft_eval_does_not_allocate);
    tcase_add_test(core, test_aft_iwan_calls_do_not_allocate);
    tcase_add_loop_test(core, test_disk_ctx_set_coupling, 0, 2);
    tcase_add_test(core, test_disk_eval_does_not_allocate);
    tcase_add_test(core, test_ctx_set_stribeck);
    tcase_add_test(core, test_disk_ctx_set_stribeck);
    tcase_add_test(core, test_disk_stribeck_eval_does_not_allocate);
    tcase_add_loop_test(core, test_disk_ctx_set_coupling_sparse, 0, 2);
    tcase_add_test(core, test_disk_sparse_eval_does_not_allocate);
    suite_add_tcase(s, core);
    TCase *drivers = tcase_create("drivers");
    tcase_add_loop_test(drivers, test_sim_run, 0, (int)(3 * N_INTEGRATORS));
    tcase_add_test(drivers, test_sim_run_extrapolated);
    tcase_add_test(drivers, test_exact_run);
    tcase_add_test(drivers, test_exact_solve);
    tcase_add_test(drivers, test_hb_create);
    tcase_add_test(drivers, test_fit_run);
    tcase_add_test(drivers, test_hb_sparse);
    tcase_add_test(drivers, test_hb_iwan);
    tcase_add_test(drivers, test_hb_newton_solver);
    tcase_add_test(drivers, test_hb_normal);
    tcase_add_test(drivers, test_hb_iwan_normal);
    tcase_add_test(drivers, test_hb_contact_3d);
    tcase_add_test(drivers, test_hb_add_elements);
    tcase_add_test(drivers, test_hb_stability);
    tcase_add_loop_test(drivers, test_structure_run, 0, N_SCHEMES);
    tcase_add_loop_test(drivers, test_structure_estimate_run, 0, N_SCHEMES);
    tcase_add_loop_test(drivers, test_structure_jenkins_run, 0, 3);
    tcase_add_loop_test(drivers, test_structure_joint_run, 0, 2); /* implicit: the joint step */
    tcase_add_loop_test(drivers, test_structure_iwan_run, 0, 3);
    tcase_add_loop_test(drivers, test_structure_mix_run, 0, 3);
    tcase_add_loop_test(drivers, test_structure_jenkins_2d_run, 0, 5);
    tcase_add_loop_test(drivers, test_structure_normal_run, 0, 3);
    tcase_add_loop_test(drivers, test_structure_contact_3d_run, 0, 3);
    tcase_add_test(drivers, test_structure_iwan_normal_run);
    suite_add_tcase(s, drivers);
    TCase *checkpoint = tcase_create("structure_checkpoint"); /* restore: ~2000 each */
    tcase_add_loop_test(checkpoint, test_structure_checkpoint_run, 0, N_SCHEMES);
    suite_add_tcase(s, checkpoint);
    TCase *hb = tcase_create("harmonic_balance"); /* alone: CK_RUN_CASE=harmonic_balance */
    tcase_add_loop_test(hb, test_hb_solve_continue, 0, (int)(sizeof hb_cases / sizeof hb_cases[0]));
    suite_add_tcase(s, hb);
    TCase *modes = tcase_create("harmonic_balance_modes"); /* backbones, level branches */
    tcase_add_loop_test(modes, test_hb_nma_level, 0,
                        (int)(sizeof hb_mode_cases / sizeof hb_mode_cases[0]));
    suite_add_tcase(s, modes);
    return s;
}

int main(void)
{
    gsl_set_error_handler_off(); /* the documented remedy: docs/reliability.md */
    /* CHOLMOD allocates through SuiteSparse's function pointers, set in the shared library to
     * the C library's own, which --wrap cannot reach: they are pointed at the wrappers (the
     * names below are wrapped in this program), as an application that counts its memory
     * would do. */
    SuiteSparse_config.malloc_func = malloc;
    SuiteSparse_config.calloc_func = calloc;
    SuiteSparse_config.realloc_func = realloc;
    SuiteSparse_config.free_func = free;
    SRunner *runner = srunner_create(alloc_suite());
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
