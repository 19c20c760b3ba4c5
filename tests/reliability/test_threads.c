/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_threads.c — separate objects in separate threads (fricreg.h: "separate contexts may be
 * used from separate threads at once"), next to a thread of the program's own that uses GSL
 * with its own error handler.
 *
 * Eight threads each run, ROUNDS times, one object of every kind, their own: a 1-D context
 * (dense W: eval, tangent, stick stiffness, and a singular W), a 1-D context with a sparse W
 * (CHOLMOD's factor, its row updates, the tangent's product, a redundant pair), one with Stribeck
 * friction (both partitions), a 2-D context with Stribeck friction (dense W, then anisotropic
 * blocks: eval and tangent), a structure (Newmark or HHT-alpha, its near-stick block by LAPACK
 * or in the structure's space by CHOLMOD, then run_ode with rkf45 or rk4, then elements of two types added and run), a simulation (a different system and stepper family per thread: fricreg's rk4, GSL's
 * rkf45, rk4imp, msbdf), an exact solution, a harmonic-balance driver (dense or sparse, with
 * Hill's stability, a monitor, a continuation, the truncation error and a backbone), an Iwan
 * element, an AFT object and an element type on the thread's own arrays; every result and status must equal, bit for
 * bit, the same work done before in one thread, and every status the one expected. Meanwhile a ninth
 * thread provokes GSL_ERRORS errors of its own (Cholesky of an indefinite matrix) and its
 * handler must see every one: a library that switches GSL's process-wide handler off around
 * its calls makes such a thread lose some of its errors (4.3 % of them, measured). The
 * handler must still be the program's at the end. Built with -fsanitize=thread by
 * tests/tsan.sh (ctest tsan), which fails on any ThreadSanitizer report. */
#include <check.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

#include "fricreg_disk_ctx.h"
#include "fricreg_aft.h"
#include "fricreg_element.h"
#include "fricreg_exact.h"
#include "fricreg_hb.h"
#include "fricreg_iwan.h"
#include "fricreg_sim.h"
#include "fricreg_stribeck.h"
#include "fricreg_structure.h"

#define NTHREADS 8
#define ROUNDS 3
#define NRESULTS 400
#define NSTATUS 160
#define GSL_ERRORS 2000

struct results {
    double v[NRESULTS];
    int n;
    int status[NSTATUS];
    int nstatus;
    int unexpected; /* statuses other than the one expected */
};

static void put(struct results *r, double x)
{
    if (r->n < NRESULTS)
        r->v[r->n++] = x;
}

static void put_all(struct results *r, const double x[], int n)
{
    for (int k = 0; k < n; k++)
        put(r, x[k]);
}

/* Records a call's status, and whether it is the one expected. */
static void expect(struct results *r, int status, int want)
{
    if (r->nstatus < NSTATUS)
        r->status[r->nstatus++] = status;
    r->unexpected += status != want;
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
    expect(r, fricreg_ctx_create(3, &ctx), FRICREG_OK);
    expect(r, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    expect(r, fricreg_ctx_set_bounds(ctx, 3, mun), FRICREG_OK);
    expect(r, fricreg_ctx_set_coupling_dense(ctx, 3, W), FRICREG_OK);
    expect(r, fricreg_ctx_eval(ctx, 3, zdot, a_free, f, f_eq), FRICREG_OK);
    expect(r, fricreg_ctx_tangent(ctx, 3, Fz, Fa), FRICREG_OK);
    expect(r, fricreg_ctx_stick_stiffness(ctx, &lambda), FRICREG_OK);
    for (int i = 0; i < 3; i++) {
        put(r, f[i]);
        put(r, Fz[4 * i]);
    }
    put(r, lambda);
    expect(r, fricreg_ctx_set_coupling_dense(ctx, 3, singular), FRICREG_OK);
    const double rest[3] = {0.0, 0.0, 0.0};
    /* an error path for most k: contacts 0 and 1 are redundant, both at rest (FRICREG_OK where
     * the QP's active set holds one of them at its bound): compared with the threads' only */
    int singular_status = fricreg_ctx_eval(ctx, 3, rest, a_free, f, f_eq);
    expect(r, singular_status, singular_status);
    fricreg_ctx_free(ctx);
}

/* A sparse W in a 1-D context k (a chain of 12 contacts, one-based CSC of its upper triangle
 * for even k, zero-based CSR whole for odd k): evaluations under both partitions along a walk
 * that moves contacts in and out of the band (the factor's row updates and refactorizations),
 * the tangent's product, the stick stiffness, and a redundant pair (FRICREG_ESINGULAR). */
static void sparse_ctx_work(int k, struct results *r)
{
    enum { M = 12 };
    int64_t ptr[M + 1], ind[3 * M];
    double val[3 * M], mun[M], zdot[M], a_free[M], f[M], df[M], lambda = 0.0;
    int csc = k % 2 == 0, n = 0;
    for (int i = 0; i < M; i++) {
        ptr[i] = n + csc;
        for (int j = i > 0 ? i - 1 : 0; j <= i + 1 && j < M; j++)
            if (!csc || j <= i) {
                ind[n] = j + csc;
                val[n++] = i == j ? 2.385 + 0.1 * ((i + k) % 4) : -0.6 - 0.01 * k;
            }
        mun[i] = 0.5 + 0.125 * ((i * 7 + k) % 5);
        a_free[i] = 1.5 * ((i * 3 + k) % 7 - 3) / 3.0;
    }
    ptr[M] = n + csc;
    fricreg_ctx *ctx = NULL;
    expect(r, fricreg_ctx_create(M, &ctx), FRICREG_OK);
    expect(r, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    expect(r, fricreg_ctx_set_bounds(ctx, M, mun), FRICREG_OK);
    expect(r,
           csc ? fricreg_ctx_set_coupling_csc(ctx, M,
                                              FRICREG_SPARSE_ONE_BASED | FRICREG_SPARSE_UPPER, ptr,
                                              ind, val)
               : fricreg_ctx_set_coupling_csr(ctx, M, 0, ptr, ind, val),
           FRICREG_OK);
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        expect(r, fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
        for (int step = 0; step < 6; step++) {
            for (int i = 0; i < M; i++)
                zdot[i] = 0.03 * ((i * 5 + step * 3 + k) % 9 - 4) / 4.0;
            expect(r, fricreg_ctx_eval(ctx, M, zdot, a_free, f, NULL), FRICREG_OK);
        }
        put_all(r, f, M);
    }
    expect(r, fricreg_ctx_tangent_apply(ctx, M, zdot, a_free, df), FRICREG_OK);
    put_all(r, df, M);
    expect(r, fricreg_ctx_stick_stiffness(ctx, &lambda), FRICREG_OK);
    put(r, lambda);
    const int64_t pair_ptr[3] = {0, 2, 4}, pair_ind[4] = {0, 1, 0, 1};
    const double pair[4] = {1.0 + 0.1 * k, 1.0 + 0.1 * k, 1.0 + 0.1 * k, 1.0 + 0.1 * k};
    fricreg_ctx *two = NULL;
    const double rest[2] = {0.0, 0.0}, load[2] = {0.1, 0.1};
    expect(r, fricreg_ctx_create(2, &two), FRICREG_OK);
    expect(r, fricreg_ctx_set_coupling_csr(two, 2, 0, pair_ptr, pair_ind, pair), FRICREG_OK);
    expect(r, fricreg_ctx_eval(two, 2, rest, load, f, NULL), FRICREG_ESINGULAR);
    fricreg_ctx_free(two);
    fricreg_ctx_free(ctx);
}

/* Stribeck friction in a 1-D context k: dense W, contacts at rest, in the band and sliding,
 * under both partitions; the forces, the tangent and the stick stiffness. */
static void stribeck_ctx_work(int k, struct results *r)
{
    const double d = 0.05 * k;
    const double W[9] = {1.8 + d, -0.4,           0.2,    -0.4, 2.2, 0.1 + 0.01 * k,
                         0.2,     0.1 + 0.01 * k, 1.1 + d};
    const double fs[3] = {1.2 + d, 0.9, 2.0}, fk[3] = {0.8, 0.6 + 0.5 * d, 1.5};
    const double vs[3] = {0.01, 0.02 + 0.001 * k, 0.005}, delta[3] = {1.0, 2.0, 0.5 + d};
    const double zdot[3] = {0.0, 4e-3 + 1e-4 * k, -0.3}, a_free[3] = {0.7 - d, -1.25, 0.4};
    double f[3], Fz[9], Fa[9], lambda = 0.0;
    fricreg_ctx *ctx = NULL;
    expect(r, fricreg_ctx_create(3, &ctx), FRICREG_OK);
    expect(r, fricreg_ctx_set_coupling_dense(ctx, 3, W), FRICREG_OK);
    expect(r, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    expect(r, fricreg_ctx_set_stribeck(ctx, 3, fs, fk, vs, delta), FRICREG_OK);
    expect(r, fricreg_ctx_eval(ctx, 3, zdot, a_free, f, NULL), FRICREG_OK);
    put_all(r, f, 3);
    expect(r, fricreg_ctx_tangent(ctx, 3, Fz, Fa), FRICREG_OK);
    put_all(r, Fz, 9);
    put_all(r, Fa, 9);
    expect(r, fricreg_ctx_stick_stiffness(ctx, &lambda), FRICREG_OK);
    put(r, lambda);
    expect(r, fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
    expect(r, fricreg_ctx_eval(ctx, 3, zdot, a_free, f, NULL), FRICREG_OK);
    put_all(r, f, 3);
    fricreg_ctx_free(ctx);
}

/* A 2-D context k of 3 contacts with Stribeck friction: a dense W (diagonally dominant, so
 * positive definite), then anisotropic blocks; contacts at rest, in the band and sliding,
 * eval and tangent each. */
static void disk_work(int k, struct results *r)
{
    enum { M = 3, N = 2 * M };
    double W[N * N], w[4 * M], f[N], Fz[N * N], Fa[N * N];
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            W[i * N + j] = i == j ? 1.5 + 0.1 * i + 0.05 * k : 0.2 / (1.0 + abs(i - j));
    for (int i = 0; i < M; i++) {
        w[4 * i] = 1.25 + 0.1 * i + 0.02 * k;
        w[4 * i + 1] = w[4 * i + 2] = 0.3 - 0.05 * i;
        w[4 * i + 3] = 0.8 + 0.125 * i;
    }
    const double fs[M] = {1.2 + 0.05 * k, 0.9, 2.0}, fk[M] = {0.8, 0.6, 1.5 - 0.02 * k};
    const double vs[M] = {0.01, 0.02, 0.005 + 0.001 * k}, delta[M] = {1.0, 2.0, 0.5};
    const double zdot[N] = {0.0, 0.0, 3e-3, -1e-3 * (k + 1), 0.25, -0.5};
    const double a_free[N] = {0.6 - 0.03 * k, -0.35, 1.25, 0.4, -0.2, 0.9};
    fricreg_disk_ctx *ctx = NULL;
    expect(r, fricreg_disk_ctx_create(M, &ctx), FRICREG_OK);
    expect(r, fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.02), FRICREG_OK);
    expect(r, fricreg_disk_ctx_set_stribeck(ctx, M, fs, fk, vs, delta), FRICREG_OK);
    for (int coupling = 0; coupling < 2; coupling++) {
        expect(r,
               coupling == 0 ? fricreg_disk_ctx_set_coupling_dense(ctx, M, W)
                             : fricreg_disk_ctx_set_coupling_blocks(ctx, M, w),
               FRICREG_OK);
        expect(r, fricreg_disk_ctx_eval(ctx, M, zdot, a_free, f), FRICREG_OK);
        put_all(r, f, N);
        expect(r, fricreg_disk_ctx_tangent(ctx, M, Fz, Fa), FRICREG_OK);
        put_all(r, Fz, N * N);
        put_all(r, Fa, N * N);
    }
    fricreg_disk_ctx_free(ctx);
}

/* A structure k: two masses on springs, a friction contact on the first, a load record;
 * Newmark (even k) or HHT-alpha (odd k) to t = 1, then GSL's rkf45 (adaptive; or rk4 in fixed
 * steps) to t = 2. */
static void structure_work(int k, struct results *r)
{
    const double M[4] = {2.0, 0.0, 0.0, 1.0}, K[4] = {30.0, -10.0, -10.0, 10.0 + k};
    const double J[2] = {1.0, 0.0}, mun[1] = {0.3 + 0.01 * k}, p[2] = {0.0, 1.0};
    const double load[3] = {0.0, 2.385 + 0.1 * k, 0.0};
    double u[2], v[2], D[1], residual = 0.0;
    fricreg_structure *s = NULL;
    expect(r, fricreg_structure_create(2, 1, &s), FRICREG_OK);
    expect(r, fricreg_structure_set_mass(s, 2, M), FRICREG_OK);
    expect(r, fricreg_structure_set_stiffness(s, 2, K), FRICREG_OK);
    expect(r, fricreg_structure_set_rayleigh(s, 0.05, 0.002), FRICREG_OK);
    expect(r, fricreg_structure_set_contacts(s, 1, 2, J), FRICREG_OK);
    expect(r, fricreg_structure_set_bounds(s, 1, mun), FRICREG_OK);
    expect(r, fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.01), FRICREG_OK);
    expect(r, fricreg_structure_set_load(s, 2, p, 0.0, 0.5, 3, load), FRICREG_OK);
    if (k % 2)
        expect(r, fricreg_structure_set_hht(s, -0.05 * (k % 4)), FRICREG_OK);
    if (k % 4 >= 2) /* the near-stick block in the structure's space (contact_sparse.c) */
        expect(r, fricreg_structure_set_contact_solver(s, FRICREG_CONTACT_SOLVER_SPARSE),
               FRICREG_OK);
    expect(r, fricreg_structure_run(s, 0.01, 1.0), FRICREG_OK);
    expect(r, fricreg_structure_get_state(s, 2, u, v, NULL), FRICREG_OK);
    expect(r, fricreg_structure_get_dissipation(s, 1, D), FRICREG_OK);
    expect(r, fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual), FRICREG_OK);
    put_all(r, u, 2), put_all(r, v, 2), put(r, D[0]), put(r, residual);
    int adaptive = k % 4 < 2;
    expect(r,
           fricreg_structure_run_ode(s, adaptive ? FRICREG_INT_RKF45 : FRICREG_INT_RK4, 0.005,
                                     adaptive ? 1e-7 : 0.0, adaptive ? 1e-9 : 0.0, 2.0),
           FRICREG_OK);
    expect(r, fricreg_structure_get_state(s, 2, u, v, NULL), FRICREG_OK);
    expect(r, fricreg_structure_get_dissipation(s, 1, D), FRICREG_OK);
    put_all(r, u, 2), put_all(r, v, 2), put(r, D[0]);
    /* then elements of two types (each stepped by its kernel) to t = 3 */
    const double Jj[2] = {0.0, 1.0}, Pj[2] = {20.0, 0.2 + 0.01 * k}, Ji[2] = {1.0, -1.0};
    const double Pi[6] = {10.0, 8.0, 6.0, 0.05, 0.1, 0.2};
    double fe[2], we[4], De[2];
    expect(r, fricreg_structure_add_elements(s, fricreg_element_lookup("jenkins"), 1, 2, Jj, Pj),
           FRICREG_OK);
    expect(r,
           fricreg_structure_add_elements(
               s, fricreg_element_sliders(fricreg_element_lookup("iwan"), 3), 1, 2, Ji, Pi),
           FRICREG_OK);
    expect(r, fricreg_structure_run(s, 0.01, 3.0), FRICREG_OK);
    expect(r, fricreg_structure_get_elements(s, 2, fe, we, De), FRICREG_OK);
    put_all(r, fe, 2), put_all(r, we, 4), put_all(r, De, 2);
    fricreg_structure_free(s);
}

static void sim_work(int k, struct results *r)
{
    static const int integrators[4][2] = {{FRICREG_INT_RK4, 0},
                                          {FRICREG_INT_RKF45, 1},
                                          {FRICREG_INT_RK4IMP, 0},
                                          {FRICREG_INT_MSBDF, 1}};
    const int *integ = integrators[k % 4];
    fricreg_sim *sim = NULL;
    expect(r, fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR + k % 3, &sim), FRICREG_OK);
    expect(r,
           fricreg_sim_set_integrator(sim, integ[0], 0.01, integ[1] ? 1e-7 : 0.0,
                                      integ[1] ? 1e-9 : 0.0),
           FRICREG_OK);
    if (k % 3 != 2)
        expect(r, fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, 0.5 + 0.05 * k), FRICREG_OK);
    expect(r, fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
    double x[64], v[64], D[2];
    size_t n = fricreg_sim_ndof(sim);
    expect(r, fricreg_sim_get_state(sim, n, x, v), FRICREG_OK);
    expect(r, fricreg_sim_get_dissipation(sim, 2, D), FRICREG_OK);
    put(r, x[0]);
    put(r, v[n - 1]);
    put(r, D[0]);
    put(r, D[1]);
    fricreg_sim_free(sim);
}

static void exact_work(int k, struct results *r)
{
    fricreg_exact *ex = NULL;
    expect(r, fricreg_exact_create(2.0 + 0.1 * k, 0.5 + 0.1 * k, 1.0, 0.0, 0.0, &ex), FRICREG_OK);
    expect(r, fricreg_exact_run_cycles(ex, 5), FRICREG_OK);
    double D[5], x, v;
    expect(r, fricreg_exact_dissipation(ex, 5, D), FRICREG_OK);
    expect(r, fricreg_exact_state(ex, 2.385, &x, &v), FRICREG_OK);
    for (int c = 0; c < 5; c++)
        put(r, D[c]);
    put(r, x);
    put(r, (double)fricreg_exact_nswitches(ex));
    fricreg_exact_free(ex);
}

/* The monitor of hb_work: counts its calls (each thread its own counter). */
static int count_steps(void *user, int64_t iterations, double parameter, double residual)
{
    (void)iterations, (void)parameter, (void)residual;
    ++*(int *)user;
    return 0;
}

/* A harmonic-balance driver k: three masses in a chain with two Jenkins elements, H = 3,
 * dense (even k) or sparse (odd k: K by its upper triangle, KLU's factors kept within each
 * call), Hill's stability on for k % 4 < 2, a counting monitor: a point solve without a
 * guess, its displacement and truncation error, a continuation over the first resonance, and
 * three points of mode 1's backbone. */
static void hb_work(int k, struct results *r)
{
    enum { N = 3, ME = 2, H = 3, NC = 2 * H + 1 };
    const double M[9] = {1.1, 0, 0, 0, 0.9, 0, 0, 0, 1.25};
    const double K[9] = {5.3, -2.1, 0, -2.1, 3.7, -1.6, 0, -1.6, 1.6};
    const int64_t Kp[4] = {0, 1, 3, 5}, Ki[5] = {0, 0, 1, 1, 2};
    const double Kx[5] = {5.3, -2.1, 3.7, -1.6, 1.6};
    const double J[6] = {0, 0, 1, -1, 1, 0}, kt[2] = {2.5, 1.4}, mun[2] = {0.3 + 0.01 * k, 0.12};
    const double pc[3] = {0.8, 0, 0}, ps[3] = {0.25, 0, 0};
    double q[ME * NC], x[N * NC], rms[N], err[N], omega = 0.0;
    int steps = 0;
    fricreg_hb *hb = NULL;
    expect(r, fricreg_hb_create(N, ME, H, &hb), FRICREG_OK);
    expect(r, fricreg_hb_set_mass(hb, N, M), FRICREG_OK);
    if (k % 2)
        expect(r, fricreg_hb_set_stiffness_csc(hb, N, FRICREG_SPARSE_UPPER, Kp, Ki, Kx),
               FRICREG_OK);
    else
        expect(r, fricreg_hb_set_stiffness(hb, N, K), FRICREG_OK);
    expect(r, fricreg_hb_set_rayleigh(hb, 0.03, 0.01), FRICREG_OK);
    expect(r, fricreg_hb_set_elements(hb, ME, N, J, kt, mun), FRICREG_OK);
    expect(r, fricreg_hb_set_excitation(hb, N, pc, ps), FRICREG_OK);
    expect(r, fricreg_hb_set_stability(hb, k % 4 < 2), FRICREG_OK);
    expect(r, fricreg_hb_set_monitor(hb, count_steps, &steps), FRICREG_OK);
    expect(r, fricreg_hb_solve(hb, 1.2 + 0.02 * k, ME * NC, NULL, q), FRICREG_OK);
    expect(r, fricreg_hb_displacement(hb, N, NC, x), FRICREG_OK);
    expect(r, fricreg_hb_truncation_error(hb, FRICREG_HB_SOLUTION, N, err, NULL), FRICREG_OK);
    put_all(r, q, 4), put_all(r, x, 3), put_all(r, err, N);
    expect(r, fricreg_hb_continue(hb, 1.0, 1.5, ME * NC, NULL), FRICREG_OK);
    size_t npts = fricreg_hb_points(hb);
    expect(r, fricreg_hb_point(hb, npts - 1, &omega, N, rms), FRICREG_OK);
    put(r, (double)npts), put(r, omega), put_all(r, rms, N);
    expect(r, fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, 0.1, 1.0, 3), FRICREG_OK);
    double a, w, zeta;
    expect(r, fricreg_hb_nma_point(hb, 2, &a, &w, &zeta, 0, 0, NULL), FRICREG_OK);
    put(r, w), put(r, zeta), put(r, (double)steps);
    fricreg_hb_free(hb);
}

/* The joints' own objects k: a 2-D Iwan element of 4 sliders stepped round a circle (trial,
 * commit), an AFT object's exact Jenkins, Iwan and lift-off forces with their Jacobians, and
 * the contact_3d element type stepped on the thread's own state. */
static void joint_work(int k, struct results *r)
{
    const double ks[4] = {1.0, 2.0, 3.0, 4.0 + k}, phi[4] = {0.1, 0.2, 0.3, 0.4};
    fricreg_iwan *iw = NULL;
    expect(r, fricreg_iwan_create(2, 1, 4, &iw), FRICREG_OK);
    expect(r, fricreg_iwan_set_params(iw, 1, 4, ks, phi), FRICREG_OK);
    for (int step = 0; step < 40; step++) {
        double u[2] = {0.3 * cos(0.2 * step), 0.3 * sin(0.2 * step)}, f[2], dfdu[4];
        expect(r, fricreg_iwan_trial(iw, 1, u, f, dfdu), FRICREG_OK);
        expect(r, fricreg_iwan_commit(iw), FRICREG_OK);
        if (step % 10 == 9)
            put_all(r, f, 2);
    }
    fricreg_iwan_free(iw);
    enum { H = 5, NC = 2 * H + 1 };
    fricreg_aft *aft = NULL;
    double u[NC] = {0.01 * k, 0.4, -0.1, 0.05}, g[NC] = {0.2, 0.3}, f[NC], nf[NC];
    double jac[4 * NC * NC];
    expect(r, fricreg_aft_create(H, 64, &aft), FRICREG_OK);
    expect(r, fricreg_aft_jenkins_exact(aft, 2.0, 0.3, NC, u, f, jac), FRICREG_OK);
    put_all(r, f, 3), put(r, jac[0]);
    expect(r, fricreg_aft_iwan_exact(aft, 4, ks, phi, NC, u, f, jac), FRICREG_OK);
    put_all(r, f, 3), put(r, jac[0]);
    expect(r, fricreg_aft_jenkins_normal_exact(aft, 2.0, 0.3, 0.5, 1.0, NC, u, g, f, nf, jac),
           FRICREG_OK);
    put_all(r, f, 3), put_all(r, nf, 3), put(r, jac[0]);
    fricreg_aft_free(aft);
    /* an element type on the thread's own arrays (fricreg_element.h: pure, any thread):
     * contact_3d round a circle, lifting off and closing again */
    const fricreg_element_type *ct = fricreg_element_lookup("contact_3d");
    double pc[5] = {10.0, 0.5, 4.0, 1.0 + 0.1 * k, 0.0}, w[2] = {0.0, 0.0}, fc[3], tc[9];
    int failed = 0;
    for (int step = 0; step < 40; step++) {
        double uc[3] = {0.3 * cos(0.2 * step), 0.3 * sin(0.2 * step), 0.3 * sin(0.1 * step)};
        failed += fricreg_element_eval(ct, pc, w, uc, fc, tc, NULL, w) != FRICREG_OK;
    }
    expect(r, failed, 0);
    put_all(r, fc, 3);
}

static void work(int k, struct results *r)
{
    memset(r, 0, sizeof *r);
    context_work(k, r);
    sparse_ctx_work(k, r);
    stribeck_ctx_work(k, r);
    disk_work(k, r);
    structure_work(k, r);
    sim_work(k, r);
    exact_work(k, r);
    hb_work(k, r);
    joint_work(k, r);
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
        /* results per thread: context 3 f + 3 Fz_ii + lambda = 7; sparse context 2 x 12 f +
         * 12 df + lambda = 37; Stribeck context 3 f + 2 x 9 tangent + lambda + 3 f = 25; 2-D
         * context 2 x (6 f + 2 x 36 tangent) = 156; structure 2 x (2 u + 2 v + D) + the
         * residual + its elements' 2 f + 4 w + 2 D = 19; simulation 4; exact 7; harmonic balance 4 q + 3 x + 3 errors +
         * points + Omega + 3 rms + omega + zeta + monitor's calls = 18; Iwan 4 x 2 f, AFT
         * 3 x (3 f + jac) + 3 nf and contact_3d's 3 f = 26 */
        ck_assert_int_eq(reference[k].n, 7 + 37 + 25 + 156 + 19 + 4 + 7 + 18 + 26);
        ck_assert_msg(reference[k].unexpected == 0, "thread %d: %d unexpected statuses", k,
                      reference[k].unexpected);
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
    /* 10 s: the release tier's (threads_release, and tsan) */
    tcase_set_tags(tc, "release");
    tcase_add_test(tc, threads_match_one_thread);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
