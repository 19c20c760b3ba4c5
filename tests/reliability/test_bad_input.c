/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_bad_input.c — the bad-input matrix (docs/reliability.md): every public function of
 * every header, each argument in turn replaced by the hostile values its type allows, the
 * others valid.
 *
 *   pointer           NULL
 *   double            NaN, +Inf, -Inf, -2.385, 0, the least subnormal 4.9e-324, 1e308
 *   size (= object's) 0, SIZE_MAX, SIZE_MAX/2 + 1 (m*m overflows), one more than the object's
 *   record length n   0, 1 (SIZE_MAX and SIZE_MAX/8 + 1 are lies about ag[n] a caller
 *                     can tell; the library reads n samples to check them: not tried)
 *   int (enum, count) -1, 0, INT_MAX, INT_MIN
 *   array element     element 0 set to NaN, Inf, -2.385, 0, 4.9e-324, 1e308
 *   square matrix     indefinite, singular (rank 1), non-symmetric, scaled by 4.9e-324,
 *                     scaled by 1e300
 *
 * Each row of the table below is one function: a wrapper that makes the call on a fresh
 * fixture with the row's valid defaults, and per argument a string giving, class by class,
 * the status its docstring promises: 'o' FRICREG_OK, '0' ENULL, 'i' EINVAL, 'n' ENONFINITE,
 * 's' ESIZE, 'y' ENOTSYM, 'p' ENOTPSD, 'f' a documented failure (the docstring names more
 * than one cause, e.g. -Inf for an argument that must be finite and >= 0), '*' any documented
 * status (the docstring does not decide), 'x' not tried (a length the caller's array must
 * have: a lie no library can detect). Every case must also return a status of the function's
 * documented set, leave every output untouched on failure (sentinels) and, for a call on an
 * object, record the failure there with a message; none may crash (the test runs under ASan,
 * UBSan and valgrind). The count of cases and every disagreement are printed; any
 * disagreement fails the test.
 *
 * The classes sit far from most documented bounds (1e308 against 1e250, INT_MAX against 1000),
 * so test edges_of_documented_ranges tries every bound a docstring states at its last accepted
 * value and at the first refused one (the next double or integer; twice a tolerance), with the
 * same checks. */
#include <check.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "fricreg_aft.h"
#include "fricreg_disk_ctx.h"
#include "fricreg_stribeck.h"
#include "fricreg_exact.h"
#include "fricreg_hb.h"
#include "fricreg_iwan.h"
#include "fricreg_jenkins.h"
#include "fricreg_sim.h"
#include "fricreg_structure.h"

/* ---- Value classes --------------------------------------------------------------------- */

enum kind { K_PTR, K_DBL, K_SIZE, K_COUNT, K_INT, K_ARR, K_MAT, K_NKINDS };

static const double dbl_class[] = {NAN, INFINITY, -INFINITY, -2.385, 0.0, 4.9e-324, 1e308};
static const double arr_class[] = {NAN, INFINITY, -2.385, 0.0, 4.9e-324, 1e308};
static const int int_class[] = {-1, 0, INT_MAX, INT_MIN};
static const size_t count_class[] = {0, 1, SIZE_MAX, SIZE_MAX / 8 + 1};
static const char *const mat_class_name[] = {"indefinite", "singular", "non-symmetric",
                                             "scaled 4.9e-324", "scaled 1e300"};
static const int nclasses[K_NKINDS] = {1, 7, 4, 4, 4, 6, 5};

/* The perturbation of one case: which argument slot of which kind, and which class. */
struct perturb {
    enum kind kind;
    int slot, cls;
};

/* ---- Fixture: one valid object of each kind, and sentinel-filled outputs ---------------- */

#define SENTINEL_BYTE 0x5a
#define NOUT 8
#define OUTLEN 64

/* A fixture's matrices are 2 x 2; each kind of square-matrix perturbation replaces one. */
static const double W2B[4] = {1.0, -1.0, -1.0, 2.0}; /* the two blocks' Delassus matrix */
static const double M2[4] = {1.3, 0.2, 0.2, 0.7};
static const double K2[4] = {2.4, -1.1, -1.1, 1.1};

struct fixture {
    fricreg_ctx *ctx;
    fricreg_disk_ctx *dctx; /* one 2-D contact: its blocks and dense W are 2 x 2 too */
    fricreg_exact *ex;
    fricreg_sim *sim;
    fricreg_structure *st;
    fricreg_jenkins *jk;      /* one 2-D Jenkins element after a committed slip */
    fricreg_iwan *iw;         /* one 2-D Iwan element of 3 sliders after a committed slip */
    fricreg_aft *aft;         /* an AFT workspace of H = 2 harmonics and N = 16 samples */
    fricreg_hb *hb;           /* an HB driver of 2 dofs, 1 element, H = 2 */
    double out[NOUT][OUTLEN]; /* outputs, all sentinel before the call */
    void *handle_out;         /* a create's out, sentinel before the call */
    double arr[8][OUTLEN];    /* input arrays of the call (perturbed copies) */
    size_t n_switches, n_cycles;
};

/* Objects some bounds need beside the fixture's (test edges_of_documented_ranges): a chain,
 * an extrapolated run, a stuck exact solution (x0 = 0.5, a = 0, mun = 1: at rest forever, so
 * 10^6 cycles cost nothing). */
static fricreg_sim *chain_, *extrap_;
static fricreg_exact *stuck_;

static void fixture_make(struct fixture *fx)
{
    memset(fx, 0, sizeof *fx);
    const double mun2[2] = {0.5, 0.25}, zdot[2] = {0.0004, -0.0002}, a[2] = {0.213, -0.347};
    double f[2];
    ck_assert_int_eq(fricreg_ctx_create(2, &fx->ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(fx->ctx, 2, W2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(fx->ctx, 2, mun2), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(fx->ctx, 2, zdot, a, f, NULL), FRICREG_OK);

    const double dz[2] = {0.004, -0.002}, da[2] = {0.213, -0.347}, mund[1] = {0.5};
    double df[2];
    ck_assert_int_eq(fricreg_disk_ctx_create(1, &fx->dctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(fx->dctx, FRICREG_DISK_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(fx->dctx, 1, W2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(fx->dctx, 1, mund), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_eval(fx->dctx, 1, dz, da, df), FRICREG_OK);

    ck_assert_int_eq(fricreg_exact_create(0.3, 0.8, 0.4, 2.75, 0.1, &fx->ex), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_run(fx->ex, 20.0), FRICREG_OK);
    fx->n_switches = fricreg_exact_nswitches(fx->ex);
    fx->n_cycles = fricreg_exact_ncycles(fx->ex);
    ck_assert_uint_gt(fx->n_switches, 0);
    ck_assert_uint_gt(fx->n_cycles, 0);

    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &fx->sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(fx->sim, 1), FRICREG_OK);

    const double J[2] = {0.8, 0.0}, mun1[1] = {0.3};
    ck_assert_int_eq(fricreg_structure_create(2, 1, &fx->st), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(fx->st, 2, M2), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(fx->st, 2, K2), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(fx->st, 1, 2, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(fx->st, 1, mun1), FRICREG_OK);

    const double kt1[1] = {2.385}, mun1j[1] = {0.5}, u1[2] = {0.6, -0.3};
    ck_assert_int_eq(fricreg_jenkins_create(2, 1, &fx->jk), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_params(fx->jk, 1, kt1, mun1j), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_trial(fx->jk, 1, u1, df, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_commit(fx->jk), FRICREG_OK);

    const double k3[3] = {2.385, 1.25, 0.5}, phi3[3] = {0.5, 0.25, 1.0};
    ck_assert_int_eq(fricreg_iwan_create(2, 1, 3, &fx->iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_params(fx->iw, 1, 3, k3, phi3), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_trial(fx->iw, 1, u1, df, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_commit(fx->iw), FRICREG_OK);

    ck_assert_int_eq(fricreg_aft_create(2, 16, &fx->aft), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_create(2, 1, 2, &fx->hb), FRICREG_OK);

    memset(fx->out, SENTINEL_BYTE, sizeof fx->out);
    memset(&fx->handle_out, SENTINEL_BYTE, sizeof fx->handle_out);
}

static void fixture_free(struct fixture *fx)
{
    fricreg_ctx_free(fx->ctx);
    fricreg_disk_ctx_free(fx->dctx);
    fricreg_exact_free(fx->ex);
    fricreg_sim_free(fx->sim);
    fricreg_structure_free(fx->st);
    fricreg_jenkins_free(fx->jk);
    fricreg_iwan_free(fx->iw);
    fricreg_aft_free(fx->aft);
    fricreg_hb_free(fx->hb);
}

static int untouched(const void *p, size_t bytes)
{
    const unsigned char *c = p;
    for (size_t k = 0; k < bytes; k++)
        if (c[k] != SENTINEL_BYTE)
            return 0;
    return 1;
}

/* ---- Argument accessors: the default, or the case's hostile value ----------------------- */

static const struct perturb *P_; /* the case being run (one at a time) */
static struct fixture *FX_;

static int is(enum kind kind, int slot)
{
    return P_->kind == kind && P_->slot == slot;
}

static double D(int slot, double value)
{
    return is(K_DBL, slot) ? dbl_class[P_->cls] : value;
}

static int N(int slot, int value)
{
    return is(K_INT, slot) ? int_class[P_->cls] : value;
}

/* A size that must equal the object's (here `value`). */
static size_t Z(int slot, size_t value)
{
    if (!is(K_SIZE, slot))
        return value;
    const size_t sizes[4] = {0, SIZE_MAX, SIZE_MAX / 2 + 1, value + 1};
    return sizes[P_->cls];
}

static size_t C(int slot, size_t value)
{
    return is(K_COUNT, slot) ? count_class[P_->cls] : value;
}

/* An output buffer, or NULL. */
static void *O(int slot)
{
    return is(K_PTR, slot) ? NULL : FX_->out[slot];
}

/* An input array: a copy of base[n] in the fixture, element 0 or the whole matrix perturbed,
 * or NULL. */
static const double *A(int slot, const double *base, size_t n)
{
    if (is(K_PTR, slot))
        return NULL;
    double *a = FX_->arr[slot];
    memcpy(a, base, n * sizeof *a);
    for (size_t k = n; k < OUTLEN; k++)
        a[k] = 0.0; /* a size one too large reads zeros, inside the buffer */
    if (is(K_ARR, slot))
        a[0] = arr_class[P_->cls];
    if (is(K_MAT, slot) && n == 4) {
        static const double mats[3][4] = {{1.0, 2.0, 2.0, 1.0},   /* eigenvalues 3, -1 */
                                          {1.0, 0.5, 0.5, 0.25},  /* rank 1 */
                                          {1.0, -0.5, 0.5, 2.0}}; /* W01 != W10 */
        if (P_->cls < 3)
            memcpy(a, mats[P_->cls], sizeof mats[0]);
        else
            for (int k = 0; k < 4; k++)
                a[k] *= P_->cls == 3 ? 4.9e-324 : 1e300;
    }
    return a;
}

/* ---- The wrappers: one call each, defaults valid for the fixture ------------------------ */

#define OUTD(slot) ((double *)O(slot))
static const double TWO[2] = {0.0123, -0.0231}, MUN2[2] = {0.5, 0.25};

static int w_law_eval(void)
{
    return fricreg_law_eval(N(0, FRICREG_LAW_QUINN), D(0, 0.0004), D(1, 0.3), D(2, 1.0), D(3, 1e-3),
                            OUTD(0));
}
static int w_law_eval_batch(void)
{
    return fricreg_law_eval_batch(N(0, FRICREG_LAW_QUINN), D(0, 1e-3), Z(0, 2), A(1, TWO, 2),
                                  A(2, TWO, 2), A(3, MUN2, 2), OUTD(4));
}
static int w_ctx_create(void)
{
    fricreg_ctx **out = is(K_PTR, 0) ? NULL : (fricreg_ctx **)&FX_->handle_out;
    int status = fricreg_ctx_create(Z(0, 2), out);
    if (status == FRICREG_OK)
        fricreg_ctx_free(*out);
    return status;
}
static fricreg_ctx *CTX(void)
{
    return is(K_PTR, 9) ? NULL : FX_->ctx;
}
static int w_ctx_set_law(void)
{
    return fricreg_ctx_set_law(CTX(), N(0, FRICREG_LAW_QUINN), D(0, 0.02));
}
static int w_ctx_set_bounds(void)
{
    return fricreg_ctx_set_bounds(CTX(), Z(0, 2), A(1, MUN2, 2));
}
static int w_ctx_set_diagonal(void)
{
    const double w[2] = {1.0, 2.0};
    return fricreg_ctx_set_coupling_diagonal(CTX(), Z(0, 2), A(1, w, 2));
}
static int w_ctx_set_dense(void)
{
    return fricreg_ctx_set_coupling_dense(CTX(), Z(0, 2), A(1, W2B, 4));
}
static int w_ctx_set_partition(void)
{
    return fricreg_ctx_set_partition(CTX(), N(0, FRICREG_PARTITION_PAPER));
}
static int w_ctx_stick_stiffness(void)
{
    return fricreg_ctx_stick_stiffness(CTX(), OUTD(1));
}
static int w_ctx_eval(void)
{
    const double zdot[2] = {0.0004, -0.0002}, a[2] = {0.213, -0.347};
    return fricreg_ctx_eval(CTX(), Z(0, 2), A(1, zdot, 2), A(2, a, 2), OUTD(3), OUTD(4));
}
static int w_ctx_tangent(void)
{
    return fricreg_ctx_tangent(CTX(), Z(0, 2), OUTD(1), OUTD(2));
}
static int w_ctx_tangent_no_output(void)
{
    return fricreg_ctx_tangent(CTX(), 2, NULL, NULL);
}
static int w_ctx_get_stat(void)
{
    return fricreg_ctx_get_stat(CTX(), N(0, FRICREG_STAT_EVALS), (int64_t *)O(1));
}

/* fricreg_disk_ctx.h: one 2-D contact */
static int w_dctx_create(void)
{
    fricreg_disk_ctx **out = is(K_PTR, 0) ? NULL : (fricreg_disk_ctx **)&FX_->handle_out;
    int status = fricreg_disk_ctx_create(Z(0, 1), out);
    if (status == FRICREG_OK)
        fricreg_disk_ctx_free(*out);
    return status;
}
static fricreg_disk_ctx *DCTX(void)
{
    return is(K_PTR, 9) ? NULL : FX_->dctx;
}
static int w_dctx_set_law(void)
{
    return fricreg_disk_ctx_set_law(DCTX(), N(0, FRICREG_DISK_QUINN), D(0, 0.02));
}
static int w_dctx_set_bounds(void)
{
    const double mun[1] = {0.5};
    return fricreg_disk_ctx_set_bounds(DCTX(), Z(0, 1), A(1, mun, 1));
}
static int w_dctx_set_blocks(void)
{
    return fricreg_disk_ctx_set_coupling_blocks(DCTX(), Z(0, 1), A(1, W2B, 4));
}
static int w_dctx_set_dense(void)
{
    return fricreg_disk_ctx_set_coupling_dense(DCTX(), Z(0, 1), A(1, W2B, 4));
}
/* The one contact's W2B by compressed rows (or columns: it is symmetric), whole, zero-based;
 * the values perturbed as a dense W's (they are its entries in row-major order). */
static const int64_t W2B_PTR[3] = {0, 2, 4}, W2B_IND[4] = {0, 1, 0, 1};
static const int64_t *I64(int slot, const int64_t *base)
{
    return is(K_PTR, slot) ? NULL : base;
}
static int w_dctx_set_csr(void)
{
    return fricreg_disk_ctx_set_coupling_csr(DCTX(), Z(0, 1), N(0, FRICREG_SPARSE_ZERO_BASED),
                                             I64(1, W2B_PTR), I64(2, W2B_IND), A(3, W2B, 4));
}
static int w_dctx_set_csc(void)
{
    return fricreg_disk_ctx_set_coupling_csc(DCTX(), Z(0, 1), N(0, FRICREG_SPARSE_ZERO_BASED),
                                             I64(1, W2B_PTR), I64(2, W2B_IND), A(3, W2B, 4));
}
static int w_dctx_eval(void)
{
    const double zdot[2] = {0.004, -0.002}, a[2] = {0.213, -0.347};
    return fricreg_disk_ctx_eval(DCTX(), Z(0, 1), A(1, zdot, 2), A(2, a, 2), OUTD(3));
}
static int w_dctx_tangent(void)
{
    return fricreg_disk_ctx_tangent(DCTX(), Z(0, 1), OUTD(1), OUTD(2));
}
static int w_dctx_tangent_no_output(void)
{
    return fricreg_disk_ctx_tangent(DCTX(), 1, NULL, NULL);
}

static int w_ctx_set_stribeck(void)
{
    const double fs[2] = {0.5, 0.25}, fk[2] = {0.3, 0.2}, vs[2] = {0.01, 0.02},
                 delta[2] = {1.0, 2.0};
    return fricreg_ctx_set_stribeck(CTX(), Z(0, 2), A(1, fs, 2), A(2, fk, 2), A(3, vs, 2),
                                    A(4, delta, 2));
}

static int w_dctx_set_stribeck(void)
{
    const double fs[1] = {0.5}, fk[1] = {0.3}, vs[1] = {0.01}, delta[1] = {1.0};
    return fricreg_disk_ctx_set_stribeck(DCTX(), Z(0, 1), A(1, fs, 1), A(2, fk, 1), A(3, vs, 1),
                                         A(4, delta, 1));
}

/* exact */
static int w_exact_solve(void)
{
    fricreg_exact **out = is(K_PTR, 0) ? NULL : (fricreg_exact **)&FX_->handle_out;
    int status = fricreg_exact_solve(D(0, 0.3), D(1, 0.8), D(2, 0.4), D(3, 2.75), D(4, 0.1),
                                     D(5, 20.0), out);
    if (status == FRICREG_OK)
        fricreg_exact_free(*out);
    return status;
}
static int w_exact_create(void)
{
    fricreg_exact **out = is(K_PTR, 0) ? NULL : (fricreg_exact **)&FX_->handle_out;
    int status = fricreg_exact_create(D(0, 0.3), D(1, 0.8), D(2, 0.4), D(3, 2.75), D(4, 0.1), out);
    if (status == FRICREG_OK)
        fricreg_exact_free(*out);
    return status;
}
static fricreg_exact *EX(void)
{
    return is(K_PTR, 9) ? NULL : FX_->ex;
}
static int w_exact_run(void)
{
    return fricreg_exact_run(EX(), D(0, 12.5));
}
static int w_exact_run_cycles(void)
{
    return fricreg_exact_run_cycles(EX(), N(0, 3));
}
static int w_exact_get_value(void)
{
    return fricreg_exact_get_value(EX(), N(0, FRICREG_EXACT_VALUE_TIME), OUTD(1));
}
static int w_exact_get_stat(void)
{
    return fricreg_exact_get_stat(EX(), N(0, FRICREG_EXACT_STAT_ROOTS), (int64_t *)O(1));
}
static int w_exact_state(void)
{
    return fricreg_exact_state(EX(), D(0, 5.0), OUTD(1), OUTD(2));
}
static int w_exact_switches(void)
{
    return fricreg_exact_switches(EX(), Z(0, FX_->n_switches), OUTD(1), (int *)O(2));
}
static int w_exact_dissipation(void)
{
    return fricreg_exact_dissipation(EX(), Z(0, FX_->n_cycles), OUTD(1));
}
static int w_exact_stick_fraction(void)
{
    return fricreg_exact_stick_fraction(EX(), D(0, 0.0), D(1, 10.0), OUTD(1));
}

/* sim */
static int w_sim_create(void)
{
    fricreg_sim **out = is(K_PTR, 0) ? NULL : (fricreg_sim **)&FX_->handle_out;
    int status = fricreg_sim_create(N(0, FRICREG_SYSTEM_TWOBLOCK), out);
    if (status == FRICREG_OK)
        fricreg_sim_free(*out);
    return status;
}
static fricreg_sim *SIM(void)
{
    return is(K_PTR, 9) ? NULL : FX_->sim;
}
static int w_sim_set_param_a(void)
{
    return fricreg_sim_set_param(SIM(), N(0, FRICREG_PARAM_A), D(0, 0.3));
}
static int w_sim_set_param_omega(void)
{
    return fricreg_sim_set_param(SIM(), FRICREG_PARAM_OMEGA, D(0, 0.8));
}
static int w_sim_set_param_mun(void)
{
    return fricreg_sim_set_param(SIM(), FRICREG_PARAM_MUN, D(0, 0.4));
}
static int w_sim_get_param(void)
{
    return fricreg_sim_get_param(SIM(), N(0, FRICREG_PARAM_OMEGA), OUTD(1));
}
static int w_sim_set_law(void)
{
    return fricreg_sim_set_law(SIM(), N(0, FRICREG_LAW_QUINN), D(0, 0.02));
}
static int w_sim_set_partition(void)
{
    return fricreg_sim_set_partition(SIM(), N(0, FRICREG_PARTITION_PAPER));
}
static int w_sim_set_integrator(void)
{
    return fricreg_sim_set_integrator(SIM(), N(0, FRICREG_INT_RKF45), D(0, 0.01), D(1, 1e-6),
                                      D(2, 1e-9));
}
static const double ATOL3[3] = {1e-6, 2.385e-9, 1e-6}; /* the oscillator's (x, v, D) */
static int w_sim_set_abs_tolerances(void)
{
    return fricreg_sim_set_abs_tolerances(SIM(), Z(0, 3), A(1, ATOL3, 3));
}
static int w_sim_get_abs_tolerances(void)
{
    return fricreg_sim_get_abs_tolerances(SIM(), Z(0, 3), OUTD(1));
}
/* A warning to read: the oscillator's fixture adaptive with one atol = rtol = 1e-3, a velocity
 * level 2e-3 above 0.01 eps (FRICREG_WARN_TOL_LOOSE, the only one). */
static int w_sim_get_warning(void)
{
    fricreg_sim_set_integrator(FX_->sim, FRICREG_INT_RKF45, 0.01, 1e-3, 1e-3);
    fricreg_sim_warning_count(FX_->sim);
    return fricreg_sim_get_warning(SIM(), C(0, 0), (int *)O(1), (char *)O(2), 64);
}
static int w_sim_set_max_steps(void)
{
    return fricreg_sim_set_max_steps(SIM(), N(0, 1000));
}
static int w_sim_set_kink_location(void)
{
    return fricreg_sim_set_kink_location(SIM(), N(0, 0));
}
static int w_sim_set_error_estimate(void)
{
    return fricreg_sim_set_error_estimate(SIM(), N(0, 0));
}
static int w_sim_get_dissipation_error(void)
{
    return fricreg_sim_get_dissipation_error(SIM(), Z(0, 1), OUTD(1));
}
static int w_sim_set_observer(void)
{
    return fricreg_sim_set_observer(SIM(), NULL, NULL);
}
static int w_sim_set_warning_handler(void)
{
    return fricreg_sim_set_warning_handler(SIM(), NULL, NULL);
}
static int w_sim_run(void)
{
    return fricreg_sim_run(SIM(), D(0, 1.0));
}
static int w_sim_run_cycles(void)
{
    return fricreg_sim_run_cycles(SIM(), N(0, 1));
}
static int w_sim_get_value(void)
{
    return fricreg_sim_get_value(SIM(), N(0, FRICREG_VALUE_TIME), OUTD(1));
}
static int w_sim_get_stat(void)
{
    return fricreg_sim_get_stat(SIM(), N(0, FRICREG_SIM_STAT_STEPS), (int64_t *)O(1));
}
static int w_sim_get_state(void)
{
    return fricreg_sim_get_state(SIM(), Z(0, 1), OUTD(1), OUTD(2));
}
static int w_sim_get_dissipation(void)
{
    return fricreg_sim_get_dissipation(SIM(), Z(0, 1), OUTD(1));
}
static int w_sim_get_stick_fraction(void)
{
    return fricreg_sim_get_stick_fraction(SIM(), Z(0, 1), OUTD(1));
}

/* structure */
static int w_st_create(void)
{
    fricreg_structure **out = is(K_PTR, 0) ? NULL : (fricreg_structure **)&FX_->handle_out;
    int status = fricreg_structure_create(Z(0, 2), Z(1, 1), out);
    if (status == FRICREG_OK)
        fricreg_structure_free(*out);
    return status;
}
static fricreg_structure *ST(void)
{
    return is(K_PTR, 9) ? NULL : FX_->st;
}
static int w_st_set_mass(void)
{
    return fricreg_structure_set_mass(ST(), Z(0, 2), A(1, M2, 4));
}
static int w_st_set_stiffness(void)
{
    return fricreg_structure_set_stiffness(ST(), Z(0, 2), A(1, K2, 4));
}
static int w_st_set_damping(void)
{
    const double C2[4] = {0.05, -0.01, -0.01, 0.03};
    return fricreg_structure_set_damping(ST(), Z(0, 2), A(1, C2, 4));
}
static int w_st_set_rayleigh(void)
{
    return fricreg_structure_set_rayleigh(ST(), D(0, 0.01), D(1, 0.002));
}
static int w_st_set_contacts(void)
{
    const double J[2] = {0.8, 0.0};
    return fricreg_structure_set_contacts(ST(), Z(0, 1), Z(1, 2), A(1, J, 2));
}
static int w_st_set_bounds(void)
{
    const double mun[1] = {0.3};
    return fricreg_structure_set_bounds(ST(), Z(0, 1), A(1, mun, 1));
}
static int w_st_set_law(void)
{
    return fricreg_structure_set_law(ST(), N(0, FRICREG_LAW_QUINN), D(0, 1e-3));
}
static int w_st_set_influence(void)
{
    const double r[2] = {1.0, 1.0};
    return fricreg_structure_set_influence(ST(), Z(0, 2), A(1, r, 2));
}
static int w_st_set_ground_accel(void)
{
    const double ag[3] = {0.1, -0.2, 0.15};
    return fricreg_structure_set_ground_accel(ST(), D(0, 0.0), D(1, 0.01), C(0, 3), A(1, ag, 3));
}
static int w_st_set_load(void)
{
    const double p[2] = {1.0, -0.5}, g[3] = {0.0, 1.0, 0.5};
    return fricreg_structure_set_load(ST(), Z(0, 2), A(1, p, 2), D(0, 0.0), D(1, 0.01), C(0, 3),
                                      A(2, g, 3));
}
static int w_st_set_initial(void)
{
    const double u0[2] = {0.01, -0.02}, v0[2] = {0.0, 0.1};
    return fricreg_structure_set_initial(ST(), Z(0, 2), A(1, u0, 2), A(2, v0, 2));
}
static int w_st_set_newmark(void)
{
    return fricreg_structure_set_newmark(ST(), D(0, 0.25), D(1, 0.5));
}
static int w_st_set_hht(void)
{
    return fricreg_structure_set_hht(ST(), D(0, -0.1));
}
static int w_st_set_central_difference(void)
{
    return fricreg_structure_set_central_difference(ST());
}
static int w_st_set_max_steps(void)
{
    return fricreg_structure_set_max_steps(ST(), N(0, 1000));
}
static int w_st_set_newton(void)
{
    return fricreg_structure_set_newton(ST(), D(0, 1e-10), N(0, 50));
}
static int w_st_step(void)
{
    return fricreg_structure_step(ST(), D(0, 0.01));
}
static int w_st_run(void)
{
    return fricreg_structure_run(ST(), D(0, 0.01), D(1, 0.05));
}
static int w_st_run_ode(void)
{
    return fricreg_structure_run_ode(ST(), N(0, FRICREG_INT_RKF45), D(0, 0.001), D(1, 1e-6),
                                     D(2, 1e-9), D(3, 0.05));
}
/* the fixture's run_ode state: 2 ndof + 2 + m = 7 components */
static const double ST_ATOL7[7] = {1e-6, 1e-6, 1e-9, 1e-9, 1e-6, 1e-6, 1e-6};
static int w_st_set_ode_abs_tolerances(void)
{
    return fricreg_structure_set_ode_abs_tolerances(ST(), Z(0, 7), A(1, ST_ATOL7, 7));
}
static int w_st_get_ode_abs_tolerances(void)
{
    return fricreg_structure_get_ode_abs_tolerances(ST(), Z(0, 7), OUTD(1));
}
static int w_st_get_state(void)
{
    return fricreg_structure_get_state(ST(), Z(0, 2), OUTD(1), OUTD(2), OUTD(3));
}
static int w_st_get_state_no_output(void)
{
    return fricreg_structure_get_state(ST(), 2, NULL, NULL, NULL);
}
static const double ST_JE[2] = {1.0, 0.0}, ST_KT[1] = {2.0}, ST_MUN[1] = {0.1};
static const int64_t ST_JE_PTR[2] = {0, 1}, ST_JE_IND[1] = {0};
static int w_st_set_jenkins(void)
{
    return fricreg_structure_set_jenkins(ST(), C(0, 1), Z(0, 2), A(1, ST_JE, 2), A(2, ST_KT, 1),
                                         A(3, ST_MUN, 1));
}
static int w_st_set_jenkins_csr(void)
{
    return fricreg_structure_set_jenkins_csr(ST(), C(0, 1), Z(0, 2), N(0, 0), I64(1, ST_JE_PTR),
                                             I64(2, ST_JE_IND), A(3, ST_JE, 1), A(4, ST_KT, 1),
                                             A(5, ST_MUN, 1));
}
static const double ST_JE2[4] = {1.0, 0.0, 0.0, 1.0}, ST_JE2_VAL[2] = {1.0, 1.0};
static const int64_t ST_JE2_PTR[3] = {0, 1, 2}, ST_JE2_IND[2] = {0, 1};
static int w_st_set_jenkins_2d(void)
{
    return fricreg_structure_set_jenkins_2d(ST(), C(0, 1), Z(0, 2), A(1, ST_JE2, 4), A(2, ST_KT, 1),
                                            A(3, ST_MUN, 1));
}
static int w_st_set_jenkins_2d_csr(void)
{
    return fricreg_structure_set_jenkins_2d_csr(ST(), C(0, 1), Z(0, 2), N(0, 0), I64(1, ST_JE2_PTR),
                                                I64(2, ST_JE2_IND), A(3, ST_JE2_VAL, 2),
                                                A(4, ST_KT, 1), A(5, ST_MUN, 1));
}
static const double ST_IW_K[3] = {2.0, 1.0, 0.5}, ST_IW_PHI[3] = {0.1, 0.2, 0.3};
static int w_st_set_iwan(void)
{
    return fricreg_structure_set_iwan(ST(), C(0, 1), Z(0, 2), A(1, ST_JE, 2), C(1, 3),
                                      A(2, ST_IW_K, 3), A(3, ST_IW_PHI, 3));
}
static int w_st_set_iwan_csr(void)
{
    return fricreg_structure_set_iwan_csr(ST(), C(0, 1), Z(0, 2), N(0, 0), I64(1, ST_JE_PTR),
                                          I64(2, ST_JE_IND), A(3, ST_JE, 1), C(1, 3),
                                          A(4, ST_IW_K, 3), A(5, ST_IW_PHI, 3));
}
static int w_st_get_iwan_state(void)
{
    return fricreg_structure_get_iwan_state(ST(), Z(0, 0), Z(1, 3), OUTD(1), OUTD(2), OUTD(3));
}
static int w_st_get_iwan_state_no_output(void)
{
    return fricreg_structure_get_iwan_state(ST(), 0, 3, NULL, NULL, NULL);
}
static const double ST_JN[2] = {0.0, 1.0}, ST_N0[1] = {0.5}, ST_KN[1] = {3.0};
static int w_st_set_jenkins_normal(void)
{
    return fricreg_structure_set_jenkins_normal(ST(), C(0, 1), Z(0, 2), A(1, ST_JE, 2),
                                                A(2, ST_JN, 2), A(3, ST_KT, 1), A(4, ST_MUN, 1),
                                                A(5, ST_N0, 1), A(6, ST_KN, 1));
}
static const double ST_IW_MU[3] = {0.1, 0.2, 0.05};
static int w_st_set_iwan_normal(void)
{
    return fricreg_structure_set_iwan_normal(ST(), C(0, 1), Z(0, 2), A(1, ST_JE, 2), A(2, ST_JN, 2),
                                             C(1, 3), A(3, ST_IW_K, 3), A(4, ST_IW_MU, 3),
                                             A(5, ST_N0, 1), A(6, ST_KN, 1));
}
static int w_st_set_jenkins_2d_normal(void)
{
    return fricreg_structure_set_jenkins_2d_normal(ST(), C(0, 1), Z(0, 2), A(1, ST_JE2, 4),
                                                   A(2, ST_JN, 2), A(3, ST_KT, 1), A(4, ST_MUN, 1),
                                                   A(5, ST_N0, 1), A(6, ST_KN, 1));
}
static int w_st_get_normal_forces(void)
{
    return fricreg_structure_get_normal_forces(ST(), Z(0, 0), OUTD(1));
}
static int w_st_get_jenkins_state(void)
{
    return fricreg_structure_get_jenkins_state(ST(), Z(0, 0), OUTD(1), OUTD(2), OUTD(3));
}
static int w_st_get_jenkins_2d_state(void)
{
    return fricreg_structure_get_jenkins_2d_state(ST(), Z(0, 0), OUTD(1), OUTD(2), OUTD(3));
}
static int w_st_get_jenkins_2d_state_no_output(void)
{
    return fricreg_structure_get_jenkins_2d_state(ST(), 0, NULL, NULL, NULL);
}
static int w_st_get_jenkins_state_no_output(void)
{
    return fricreg_structure_get_jenkins_state(ST(), 0, NULL, NULL, NULL);
}
static int w_st_get_forces(void)
{
    return fricreg_structure_get_forces(ST(), Z(0, 1), OUTD(1));
}
static int w_st_get_dissipation(void)
{
    return fricreg_structure_get_dissipation(ST(), Z(0, 1), OUTD(1));
}
static int w_st_set_warning_handler(void)
{
    return fricreg_structure_set_warning_handler(ST(), NULL, NULL);
}
static int w_st_set_error_estimate(void)
{
    return fricreg_structure_set_error_estimate(ST(), N(0, 1));
}
static int w_st_get_peak_displacement(void)
{
    return fricreg_structure_get_peak_displacement(ST(), Z(0, 2), OUTD(1));
}
/* The error getters after one step with the estimate on (before it: FRICREG_EINVAL). */
static void st_estimated(void)
{
    ck_assert_int_eq(fricreg_structure_set_error_estimate(FX_->st, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_step(FX_->st, 0.01), FRICREG_OK);
}
static int w_st_get_peak_displacement_error(void)
{
    st_estimated();
    return fricreg_structure_get_peak_displacement_error(ST(), Z(0, 2), OUTD(1));
}
static int w_st_get_dissipation_error(void)
{
    st_estimated();
    return fricreg_structure_get_dissipation_error(ST(), Z(0, 1), OUTD(1));
}
static int w_st_get_jenkins_dissipation_error(void)
{
    st_estimated();
    return fricreg_structure_get_jenkins_dissipation_error(ST(), Z(0, 0), OUTD(1));
}
static int w_st_get_value(void)
{
    return fricreg_structure_get_value(ST(), N(0, FRICREG_SVALUE_TIME), OUTD(1));
}
static int w_st_get_stat(void)
{
    return fricreg_structure_get_stat(ST(), N(0, FRICREG_SSTAT_STEPS), (int64_t *)O(1));
}
/* A warning to read: a ground record typed in g (peak 0.2457 < 0.05 g, FRICREG_WARN_GROUND_PEAK,
 * the only one: no step taken, and no DOF moving with the ground, r = 0, for eps to be judged
 * against its velocity). */
static int w_st_get_warning(void)
{
    const double ag[2] = {0.2457, 0.2457}, r[2] = {0.0, 0.0};
    fricreg_structure_set_influence(FX_->st, 2, r);
    fricreg_structure_set_ground_accel(FX_->st, 0.0, 0.01, 2, ag);
    fricreg_structure_warning_count(FX_->st);
    return fricreg_structure_get_warning(ST(), C(0, 0), (int *)O(1), (char *)O(2), 64);
}

/* the functions the first matrix missed */
static int w_ctx_set_keep_tangent(void)
{
    return fricreg_ctx_set_keep_tangent(CTX(), N(0, 0));
}
/* A sparse W: the two contacts' W2B (above) in CSR (or CSC: the same arrays), whole,
 * zero-based, its pattern full so that the square-matrix classes replace its values. */
static int w_ctx_set_csr(void)
{
    return fricreg_ctx_set_coupling_csr(CTX(), Z(0, 2), N(0, 0), I64(1, W2B_PTR), I64(2, W2B_IND),
                                        A(3, W2B, 4));
}
static int w_ctx_set_csc(void)
{
    return fricreg_ctx_set_coupling_csc(CTX(), Z(0, 2), N(0, 0), I64(1, W2B_PTR), I64(2, W2B_IND),
                                        A(3, W2B, 4));
}
static int w_ctx_tangent_apply(void)
{
    const double dz[2] = {0.0123, -0.0231}, da[2] = {0.5, -0.25};
    return fricreg_ctx_tangent_apply(CTX(), Z(0, 2), A(1, dz, 2), A(2, da, 2), OUTD(3));
}
/* One step's forces on the fixture's two blocks: W2B, a W_eff = W2B / (1 + 100 W2B)-like SPD
 * matrix, velocities near the band (eps = 1e-3), a guess inside the bounds. */
static int w_ctx_solve_step(void)
{
    const double z0[2] = {0.0004, -0.0002}, zp[2] = {0.0011, -0.0007}, ap[2] = {0.213, -0.347};
    const double weff[4] = {0.0081, -0.0023, -0.0023, 0.0097}, f0[2] = {0.1, -0.05};
    return fricreg_ctx_solve_step(CTX(), Z(0, 2), A(1, z0, 2), A(2, zp, 2), A(3, ap, 2),
                                  A(4, W2B, 4), A(5, weff, 4), D(0, 0.005), D(1, 1e-10), N(0, 50),
                                  N(1, 0), (double *)A(6, f0, 2), (int *)O(0));
}
/* The same step with W and W_eff by compressed rows (or columns: the same arrays), whole,
 * zero-based, their patterns full so that the square-matrix classes replace their values;
 * the index arrays are pointer slots 10 to 13. */
static int w_ctx_solve_step_sparse(int by_columns)
{
    const double z0[2] = {0.0004, -0.0002}, zp[2] = {0.0011, -0.0007}, ap[2] = {0.213, -0.347};
    const double weff[4] = {0.0081, -0.0023, -0.0023, 0.0097}, f0[2] = {0.1, -0.05};
    return (by_columns ? fricreg_ctx_solve_step_csc : fricreg_ctx_solve_step_csr)(
        CTX(), Z(0, 2), A(1, z0, 2), A(2, zp, 2), A(3, ap, 2), N(0, 0), I64(10, W2B_PTR),
        I64(11, W2B_IND), A(4, W2B, 4), I64(12, W2B_PTR), I64(13, W2B_IND), A(5, weff, 4),
        D(0, 0.005), D(1, 1e-10), N(1, 50), N(2, 0), (double *)A(6, f0, 2), (int *)O(0));
}
static int w_ctx_solve_step_csr(void)
{
    return w_ctx_solve_step_sparse(0);
}
static int w_ctx_solve_step_csc(void)
{
    return w_ctx_solve_step_sparse(1);
}
/* The fixture's two blocks (a dense W, so f is read) at a state near stick. */
static int w_ctx_switching(void)
{
    const double zdot[2] = {0.0004, -0.0002}, a[2] = {0.213, -0.347}, f[2] = {-0.21, 0.125};
    return fricreg_ctx_switching(CTX(), Z(0, 2), A(1, zdot, 2), A(2, a, 2), A(3, f, 2), OUTD(4),
                                 C(0, 2 * FRICREG_SWITCH_PER_CONTACT));
}
static const double V2[2] = {0.004, -0.002}, FEQ2[2] = {0.213, -0.347};
static int w_disk_eval(void)
{
    return fricreg_disk_eval(N(0, FRICREG_DISK_QUINN), A(1, V2, 2), A(2, FEQ2, 2), D(0, 0.5),
                             D(1, 0.02), OUTD(3));
}
static int w_disk_eval_batch(void)
{
    const double v[4] = {0.004, -0.002, 0.0, 0.5}, feq[4] = {0.213, -0.347, 0.1, 0.0};
    return fricreg_disk_eval_batch(N(0, FRICREG_DISK_QUINN), D(0, 0.02), Z(0, 2), A(1, v, 4),
                                   A(2, feq, 4), A(3, MUN2, 2), OUTD(4));
}
static int w_stribeck_eval(void)
{
    return fricreg_stribeck_eval(D(0, 0.0004), D(1, 0.3), D(2, 0.5), D(3, 0.3), D(4, 0.01),
                                 D(5, 1.0), D(6, 0.02), OUTD(0));
}
static const double FS2[2] = {0.5, 0.25}, FK2[2] = {0.3, 0.2}, VS2[2] = {0.01, 0.02},
                    DELTA2[2] = {1.0, 2.0};
static int w_stribeck_eval_batch(void)
{
    return fricreg_stribeck_eval_batch(D(0, 0.02), Z(0, 2), A(1, TWO, 2), A(2, TWO, 2),
                                       A(3, FS2, 2), A(4, FK2, 2), A(5, VS2, 2), A(6, DELTA2, 2),
                                       OUTD(7));
}
static int w_stribeck_disk_eval(void)
{
    return fricreg_stribeck_disk_eval(A(1, V2, 2), A(2, FEQ2, 2), D(0, 0.5), D(1, 0.3), D(2, 0.01),
                                      D(3, 1.0), D(4, 0.02), OUTD(3));
}
static int w_stribeck_disk_eval_batch(void)
{
    return fricreg_stribeck_disk_eval_batch(D(0, 0.02), Z(0, 1), A(1, V2, 2), A(2, FEQ2, 2),
                                            A(3, FS2, 1), A(4, FK2, 1), A(5, VS2, 1),
                                            A(6, DELTA2, 1), OUTD(7));
}
static int w_sim_run_extrapolated(void)
{
    return fricreg_sim_run_extrapolated(SIM(), D(0, 1.0), N(0, 2), N(1, 0));
}
static int w_sim_run_extrapolated_window(void)
{
    return fricreg_sim_run_extrapolated_window(SIM(), D(0, 1.0), N(0, 2), N(1, 0), N(2, 0));
}
static int w_sim_get_extrapolation(void)
{
    return fricreg_sim_get_extrapolation(SIM(), N(0, FRICREG_EXTRAP_LEVELS), OUTD(1));
}
static int w_sim_get_extrapolated_dissipation(void)
{
    return fricreg_sim_get_extrapolated_dissipation(SIM(), Z(0, 1), OUTD(1), OUTD(2));
}

/* fricreg_jenkins.h: one 2-D element */
static int w_jk_create(void)
{
    fricreg_jenkins **out = is(K_PTR, 0) ? NULL : (fricreg_jenkins **)&FX_->handle_out;
    int status = fricreg_jenkins_create(N(0, 2), Z(0, 1), out);
    if (status == FRICREG_OK)
        fricreg_jenkins_free(*out);
    return status;
}
static fricreg_jenkins *JK(void)
{
    return is(K_PTR, 9) ? NULL : FX_->jk;
}
static int w_jk_set_params(void)
{
    const double kt[1] = {2.385}, mun[1] = {0.5};
    return fricreg_jenkins_set_params(JK(), Z(0, 1), A(1, kt, 1), A(2, mun, 1));
}
static int w_jk_trial(void)
{
    const double u[2] = {0.7, 0.1};
    return fricreg_jenkins_trial(JK(), Z(0, 1), A(1, u, 2), OUTD(2), OUTD(3));
}
static int w_jk_commit(void)
{
    return fricreg_jenkins_commit(JK());
}
static int w_jk_reset(void)
{
    return fricreg_jenkins_reset(JK());
}
static int w_jk_get_slider(void)
{
    return fricreg_jenkins_get_slider(JK(), Z(0, 1), OUTD(1));
}

static int w_jk_set_normal(void)
{
    const double mu[1] = {0.5}, n0[1] = {1.5}, kn[1] = {2.0};
    return fricreg_jenkins_set_normal(JK(), Z(0, 1), A(1, mu, 1), A(2, n0, 1), A(3, kn, 1));
}
static int w_jk_trial_normal(void)
{
    const double u[2] = {0.7, 0.1}, g[1] = {0.125};
    return fricreg_jenkins_trial_normal(JK(), Z(0, 1), A(1, u, 2), A(2, g, 1), OUTD(3), OUTD(4),
                                        OUTD(5), OUTD(6));
}

/* fricreg_iwan.h: one 2-D element of 3 sliders */
static int w_iw_create(void)
{
    fricreg_iwan **out = is(K_PTR, 0) ? NULL : (fricreg_iwan **)&FX_->handle_out;
    int status = fricreg_iwan_create(N(0, 2), Z(0, 1), Z(1, 3), out);
    if (status == FRICREG_OK)
        fricreg_iwan_free(*out);
    return status;
}
static fricreg_iwan *IW(void)
{
    return is(K_PTR, 9) ? NULL : FX_->iw;
}
static int w_iw_set_params(void)
{
    const double k[3] = {2.385, 1.0, 0.5}, phi[3] = {0.5, 0.75, 0.125};
    return fricreg_iwan_set_params(IW(), Z(0, 1), Z(1, 3), A(1, k, 3), A(2, phi, 3));
}
static int w_iw_get_params(void)
{
    return fricreg_iwan_get_params(IW(), Z(0, 1), Z(1, 3), OUTD(1), OUTD(2));
}
static int w_iw_set_segalman(void)
{
    const double fs[1] = {2.385}, kt[1] = {10.0}, chi[1] = {-0.5}, beta[1] = {0.35};
    return fricreg_iwan_set_segalman(IW(), Z(0, 1), A(1, fs, 1), A(2, kt, 1), A(3, chi, 1),
                                     A(4, beta, 1), D(0, 1e-4));
}
static int w_iw_set_normal(void)
{
    const double n0[1] = {1.5}, kn[1] = {2.0};
    return fricreg_iwan_set_normal(IW(), Z(0, 1), A(1, n0, 1), A(2, kn, 1));
}
static int w_iw_trial(void)
{
    const double u[2] = {0.7, 0.1};
    return fricreg_iwan_trial(IW(), Z(0, 1), A(1, u, 2), OUTD(2), OUTD(3));
}
static int w_iw_trial_normal(void)
{
    const double u[2] = {0.7, 0.1}, g[1] = {0.125};
    return fricreg_iwan_trial_normal(IW(), Z(0, 1), A(1, u, 2), A(2, g, 1), OUTD(3), OUTD(4),
                                     OUTD(5), OUTD(6));
}
static int w_iw_commit(void)
{
    return fricreg_iwan_commit(IW());
}
static int w_iw_reset(void)
{
    return fricreg_iwan_reset(IW());
}
static int w_iw_get_slider(void)
{
    return fricreg_iwan_get_slider(IW(), Z(0, 1), Z(1, 3), OUTD(1));
}

/* fricreg_hb.h: 2 dofs, one element with lift-off */
static int w_hb_set_normal_elements(void)
{
    const double Jt[2] = {1.0, 0.5}, Jn[2] = {0.25, -1.0}, kt[1] = {1.7}, mu[1] = {0.5},
                 n0[1] = {0.6}, kn[1] = {3.0};
    fricreg_hb *hb = is(K_PTR, 9) ? NULL : FX_->hb;
    return fricreg_hb_set_normal_elements(hb, Z(0, 1), Z(1, 2), A(1, Jt, 2), A(2, Jn, 2),
                                          A(3, kt, 1), A(4, mu, 1), A(5, n0, 1), A(6, kn, 1));
}

static int w_hb_set_iwan_normal(void)
{
    const double Jt[2] = {1.0, 0.5}, Jn[2] = {0.25, -1.0}, k[2] = {1.2, 0.5}, mu[2] = {0.3, 0.2},
                 n0[1] = {0.6}, kn[1] = {3.0};
    fricreg_hb *hb = is(K_PTR, 9) ? NULL : FX_->hb;
    return fricreg_hb_set_iwan_normal(hb, Z(0, 1), Z(1, 2), A(1, Jt, 2), A(2, Jn, 2), C(0, 2),
                                      A(3, k, 2), A(4, mu, 2), A(5, n0, 1), A(6, kn, 1));
}

/* ---- The table ---------------------------------------------------------------------------- */

/* The object a call records its failures in (a const getter records none). */
/* fricreg_aft.h: H = 2 harmonics (n = 5 coefficients), N = 16 samples */
static const double AFT_U[5] = {0.25, 1.5, -0.5, 0.125, 0.375};
static const double AFT_K[3] = {2.385, 1.0, 0.5}, AFT_PHI[3] = {0.5, 0.75, 0.125};
static int w_aft_create(void)
{
    fricreg_aft **out = is(K_PTR, 0) ? NULL : (fricreg_aft **)&FX_->handle_out;
    int status = fricreg_aft_create(N(0, 2), C(0, 16), out);
    if (status == FRICREG_OK)
        fricreg_aft_free(*out);
    return status;
}
static fricreg_aft *AFT(void)
{
    return is(K_PTR, 9) ? NULL : FX_->aft;
}
static int w_aft_jenkins_exact(void)
{
    return fricreg_aft_jenkins_exact(AFT(), D(0, 2.385), D(1, 0.5), Z(0, 5), A(1, AFT_U, 5),
                                     OUTD(2), OUTD(3));
}
static int w_aft_jenkins_sampled(void)
{
    return fricreg_aft_jenkins_sampled(AFT(), D(0, 2.385), D(1, 0.5), Z(0, 5), A(1, AFT_U, 5),
                                       OUTD(2), OUTD(3));
}
static const double AFT_G[5] = {0.1, 0.2, 0.0, 0.05, 0.0}; /* a normal displacement, H = 2 */
static int w_aft_jenkins_normal_sampled(void)
{
    return fricreg_aft_jenkins_normal_sampled(AFT(), D(0, 2.385), D(1, 0.5), D(2, 1.0), D(3, 1.0),
                                              Z(0, 5), A(1, AFT_U, 5), A(2, AFT_G, 5), OUTD(3),
                                              OUTD(4), OUTD(5));
}
static int w_aft_jenkins_normal_exact(void)
{
    return fricreg_aft_jenkins_normal_exact(AFT(), D(0, 2.385), D(1, 0.5), D(2, 1.0), D(3, 1.0),
                                            Z(0, 5), A(1, AFT_U, 5), A(2, AFT_G, 5), OUTD(3),
                                            OUTD(4), OUTD(5));
}
static int w_aft_iwan_exact(void)
{
    return fricreg_aft_iwan_exact(AFT(), C(0, 3), A(1, AFT_K, 3), A(2, AFT_PHI, 3), Z(0, 5),
                                  A(3, AFT_U, 5), OUTD(4), OUTD(5));
}
static int w_aft_iwan_sampled(void)
{
    return fricreg_aft_iwan_sampled(AFT(), C(0, 3), A(1, AFT_K, 3), A(2, AFT_PHI, 3), Z(0, 5),
                                    A(3, AFT_U, 5), OUTD(4), OUTD(5));
}

enum owner {
    NONE,
    CTX_REC,
    EX_REC,
    SIM_REC,
    ST_REC,
    DCTX_REC,
    CHAIN_REC,
    EXSTUCK_REC,
    JK_REC,
    IW_REC,
    AFT_REC,
    HB_REC
};

#define MAXARGS 13
struct arg {
    enum kind kind;
    int slot;
    const char *expect; /* one status letter per class of the kind */
};
struct row {
    const char *name;
    int (*call)(void);
    const char *documented; /* status letters of the docstring's Returns */
    enum owner owner;
    struct arg args[MAXARGS];
};

/* The handle of an object call is pointer slot 9. */
#define HANDLE        \
    {                 \
        K_PTR, 9, "0" \
    }
#define DBL(slot, e)   \
    {                  \
        K_DBL, slot, e \
    }
#define INT(slot, e)   \
    {                  \
        K_INT, slot, e \
    }
#define SIZE(slot, e)   \
    {                   \
        K_SIZE, slot, e \
    }
#define COUNT(slot, e)   \
    {                    \
        K_COUNT, slot, e \
    }
#define PTR(slot, e)   \
    {                  \
        K_PTR, slot, e \
    }
#define ARR(slot, e)   \
    {                  \
        K_ARR, slot, e \
    }
#define MAT(slot, e)   \
    {                  \
        K_MAT, slot, e \
    }

/* Status letters: o OK, 0 ENULL, i EINVAL, n ENONFINITE, s ESIZE, m ENOMEM, y ENOTSYM,
 * p ENOTPSD, g ESINGULAR, e ESTEP, d EDIVERGED, t EINTEGRATOR. */
static const struct row rows[] = {
    /* fricreg.h */
    {"fricreg_law_eval",
     w_law_eval,
     "0in",
     NONE,
     {INT(0, "iiii"), DBL(0, "nnnoooo"), DBL(1, "nnnoooo"), DBL(2, "nnfiooo"), DBL(3, "nnfiiio"),
      PTR(0, "0")}},
    {"fricreg_law_eval_batch",
     w_law_eval_batch,
     "0in",
     NONE,
     {INT(0, "iiii"), DBL(0, "nnfiiio"), SIZE(0, "oxxx"), PTR(1, "0"), ARR(1, "nnoooo"),
      PTR(2, "0"), ARR(2, "nnoooo"), PTR(3, "0")}},
    {"fricreg_law_eval_batch (mun, f)",
     w_law_eval_batch,
     "0in",
     NONE,
     {ARR(3, "nniooo"), PTR(4, "0")}},
    {"fricreg_ctx_create", w_ctx_create, "0im", NONE, {SIZE(0, "iiio"), PTR(0, "0")}},
    {"fricreg_ctx_set_law",
     w_ctx_set_law,
     "0in",
     CTX_REC,
     {HANDLE, INT(0, "iiii"), DBL(0, "nnfiiio")}},
    {"fricreg_ctx_set_bounds",
     w_ctx_set_bounds,
     "0sin",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nniooo")}},
    {"fricreg_ctx_set_coupling_diagonal",
     w_ctx_set_diagonal,
     "0sin",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nniioo")}},
    {"fricreg_ctx_set_coupling_dense",
     w_ctx_set_dense,
     "0snypm",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnpppo"), MAT(1, "poypo")}},
    {"fricreg_ctx_set_coupling_csr",
     w_ctx_set_csr,
     "0sinypm",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), INT(0, "ioii"), PTR(1, "0"), PTR(2, "0"), PTR(3, "0"),
      ARR(3, "nnpppo"), MAT(3, "poypo")}},
    {"fricreg_ctx_set_coupling_csc",
     w_ctx_set_csc,
     "0sinypm",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), INT(0, "ioii"), PTR(1, "0"), PTR(2, "0"), PTR(3, "0"),
      ARR(3, "nnpppo"), MAT(3, "poypo")}},
    {"fricreg_ctx_set_partition", w_ctx_set_partition, "0i", CTX_REC, {HANDLE, INT(0, "iiii")}},
    {"fricreg_ctx_stick_stiffness", w_ctx_stick_stiffness, "0m", CTX_REC, {HANDLE, PTR(1, "0")}},
    {"fricreg_ctx_eval",
     w_ctx_eval,
     "0sng",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnooon"),
      PTR(3, "0"), PTR(4, "o")}},
    {"fricreg_ctx_tangent",
     w_ctx_tangent,
     "0sig",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "o"), PTR(2, "o")}},
    {"fricreg_ctx_tangent (both outputs NULL)",
     w_ctx_tangent_no_output,
     "0sig",
     CTX_REC,
     {PTR(8, "0")}},
    {"fricreg_ctx_tangent_apply",
     w_ctx_tangent_apply,
     "0snig",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "o"), ARR(1, "nnoooo"), PTR(2, "o"), ARR(2, "nnoooo"),
      PTR(3, "0")}},
    {"fricreg_ctx_solve_step (arrays)",
     w_ctx_solve_step,
     "0snimypge",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnoooo"),
      PTR(3, "0"), ARR(3, "nnooof"), PTR(6, "0"), ARR(6, "nnooof"), PTR(0, "0")}},
    {"fricreg_ctx_solve_step (matrices and scalars)",
     w_ctx_solve_step,
     "0snimypge",
     CTX_REC,
     {PTR(4, "0"), MAT(4, "iiypi"), ARR(4, "nnpppi"), PTR(5, "0"), MAT(5, "ooypo"),
      ARR(5, "nnpppo"), DBL(0, "nnniioo"), DBL(1, "nnniioo"), INT(0, "iioi"), INT(1, "ioii")}},
    {"fricreg_ctx_solve_step_csr (arrays)",
     w_ctx_solve_step_csr,
     "0snimypge",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnoooo"),
      PTR(3, "0"), ARR(3, "nnooof"), PTR(6, "0"), ARR(6, "nnooof"), PTR(0, "0")}},
    {"fricreg_ctx_solve_step_csr (matrices)",
     w_ctx_solve_step_csr,
     "0snimypge",
     CTX_REC,
     {INT(0, "ioii"), PTR(10, "0"), PTR(11, "0"), PTR(4, "0"), MAT(4, "iiypi"), ARR(4, "nnpppi"),
      PTR(12, "0"), PTR(13, "0"), PTR(5, "0"), MAT(5, "ooypo"), ARR(5, "nnpppo")}},
    {"fricreg_ctx_solve_step_csr (scalars)",
     w_ctx_solve_step_csr,
     "0snimypge",
     CTX_REC,
     {DBL(0, "nnniioo"), DBL(1, "nnniioo"), INT(1, "iioi"), INT(2, "ioii")}},
    {"fricreg_ctx_solve_step_csc (arrays)",
     w_ctx_solve_step_csc,
     "0snimypge",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnoooo"),
      PTR(3, "0"), ARR(3, "nnooof"), PTR(6, "0"), ARR(6, "nnooof"), PTR(0, "0")}},
    {"fricreg_ctx_solve_step_csc (matrices)",
     w_ctx_solve_step_csc,
     "0snimypge",
     CTX_REC,
     {INT(0, "ioii"), PTR(10, "0"), PTR(11, "0"), PTR(4, "0"), MAT(4, "iiypi"), ARR(4, "nnpppi"),
      PTR(12, "0"), PTR(13, "0"), PTR(5, "0"), MAT(5, "ooypo"), ARR(5, "nnpppo")}},
    {"fricreg_ctx_solve_step_csc (scalars)",
     w_ctx_solve_step_csc,
     "0snimypge",
     CTX_REC,
     {DBL(0, "nnniioo"), DBL(1, "nnniioo"), INT(1, "iioi"), INT(2, "ioii")}},
    {"fricreg_ctx_switching",
     w_ctx_switching,
     "0sn",
     CTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnoooo"),
      PTR(3, "0"), ARR(3, "nnoooo")}},
    {"fricreg_ctx_switching (g, ng)",
     w_ctx_switching,
     "0sn",
     CTX_REC,
     {PTR(4, "0"), COUNT(0, "ssoo")}},
    {"fricreg_ctx_get_stat", w_ctx_get_stat, "0i", NONE, {HANDLE, INT(0, "ioii"), PTR(1, "0")}},
    {"fricreg_ctx_set_keep_tangent",
     w_ctx_set_keep_tangent,
     "0i",
     CTX_REC,
     {HANDLE, INT(0, "ioii")}},
    /* fricreg_disk.h */
    {"fricreg_disk_eval",
     w_disk_eval,
     "0in",
     NONE,
     {INT(0, "iiii"), PTR(1, "0"), ARR(1, "nnoooi"), PTR(2, "0"), ARR(2, "nnoooi"),
      DBL(0, "nnfiooi"), DBL(1, "nnfiii*"), PTR(3, "0")}},
    {"fricreg_disk_eval_batch",
     w_disk_eval_batch,
     "0in",
     NONE,
     {INT(0, "iiii"), DBL(0, "nnfiii*"), SIZE(0, "oxxx"), PTR(1, "0"), ARR(1, "nnoooi"),
      PTR(2, "0"), ARR(2, "nnoooi")}},
    {"fricreg_disk_eval_batch (mun, f)",
     w_disk_eval_batch,
     "0in",
     NONE,
     {PTR(3, "0"), ARR(3, "nniooi"), PTR(4, "0")}},
    /* fricreg_stribeck.h: the laws */
    {"fricreg_stribeck_eval",
     w_stribeck_eval,
     "0ni",
     NONE,
     {DBL(0, "nnnoooo"), DBL(1, "nnnoooo"), DBL(2, "nnfiiio"), DBL(3, "nffiooi"), DBL(4, "nnfiioo"),
      DBL(5, "nnfiioo"), DBL(6, "nnfiiio"), PTR(0, "0")}},
    {"fricreg_stribeck_eval_batch",
     w_stribeck_eval_batch,
     "0ni",
     NONE,
     {DBL(0, "nnfiiio"), SIZE(0, "oxxx"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"),
      ARR(2, "nnoooo")}},
    {"fricreg_stribeck_eval_batch (fs, fk)",
     w_stribeck_eval_batch,
     "0ni",
     NONE,
     {PTR(3, "0"), ARR(3, "nniiio"), PTR(4, "0"), ARR(4, "nfiooi")}},
    {"fricreg_stribeck_eval_batch (vs, delta, f)",
     w_stribeck_eval_batch,
     "0ni",
     NONE,
     {PTR(5, "0"), ARR(5, "nniioo"), PTR(6, "0"), ARR(6, "nniioo"), PTR(7, "0")}},
    {"fricreg_stribeck_disk_eval",
     w_stribeck_disk_eval,
     "0ni",
     NONE,
     {PTR(1, "0"), ARR(1, "nnoooi"), PTR(2, "0"), ARR(2, "nnoooi"), DBL(0, "nnfiiii"),
      DBL(1, "nffiooi"), PTR(3, "0")}},
    {"fricreg_stribeck_disk_eval (vs, delta, eps)",
     w_stribeck_disk_eval,
     "0ni",
     NONE,
     {DBL(2, "nnfiioo"), DBL(3, "nnfiioo"), DBL(4, "nnfiii*")}},
    {"fricreg_stribeck_disk_eval_batch",
     w_stribeck_disk_eval_batch,
     "0ni",
     NONE,
     {DBL(0, "nnfiii*"), SIZE(0, "oxxx"), PTR(1, "0"), ARR(1, "nnoooi"), PTR(2, "0"),
      ARR(2, "nnoooi")}},
    {"fricreg_stribeck_disk_eval_batch (fs, fk)",
     w_stribeck_disk_eval_batch,
     "0ni",
     NONE,
     {PTR(3, "0"), ARR(3, "nniiii"), PTR(4, "0"), ARR(4, "nfiooi")}},
    {"fricreg_stribeck_disk_eval_batch (vs, delta, f)",
     w_stribeck_disk_eval_batch,
     "0ni",
     NONE,
     {PTR(5, "0"), ARR(5, "nniioo"), PTR(6, "0"), ARR(6, "nniioo"), PTR(7, "0")}},
    /* fricreg_disk_ctx.h */
    {"fricreg_disk_ctx_create", w_dctx_create, "0im", NONE, {SIZE(0, "iiio"), PTR(0, "0")}},
    {"fricreg_disk_ctx_set_law",
     w_dctx_set_law,
     "0in",
     DCTX_REC,
     {HANDLE, INT(0, "iiii"), DBL(0, "nnniiii")}},
    {"fricreg_disk_ctx_set_bounds",
     w_dctx_set_bounds,
     "0sni",
     DCTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nniooi")}},
    {"fricreg_disk_ctx_set_coupling_blocks",
     w_dctx_set_blocks,
     "0sinypm",
     DCTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnpppi"), MAT(1, "ppypi")}},
    {"fricreg_disk_ctx_set_coupling_dense",
     w_dctx_set_dense,
     "0sinypm",
     DCTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnpppi"), MAT(1, "ppypi")}},
    {"fricreg_disk_ctx_set_coupling_csr",
     w_dctx_set_csr,
     "0sinypm",
     DCTX_REC,
     {HANDLE, SIZE(0, "ssss"), INT(0, "ioii"), PTR(1, "0"), PTR(2, "0"), PTR(3, "0"),
      ARR(3, "nnpppi"), MAT(3, "ppypi")}},
    {"fricreg_disk_ctx_set_coupling_csc",
     w_dctx_set_csc,
     "0sinypm",
     DCTX_REC,
     {HANDLE, SIZE(0, "ssss"), INT(0, "ioii"), PTR(1, "0"), PTR(2, "0"), PTR(3, "0"),
      ARR(3, "nnpppi"), MAT(3, "ppypi")}},
    {"fricreg_disk_ctx_eval",
     w_dctx_eval,
     "0snig",
     DCTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooi"), PTR(2, "0"), ARR(2, "nnoooi"),
      PTR(3, "0")}},
    {"fricreg_disk_ctx_tangent",
     w_dctx_tangent,
     "0sign",
     DCTX_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "o"), PTR(2, "o")}},
    {"fricreg_disk_ctx_tangent (both outputs NULL)",
     w_dctx_tangent_no_output,
     "0sign",
     DCTX_REC,
     {PTR(8, "0")}},
    /* fricreg_stribeck.h: the 1-D context's Stribeck friction (m = 0 switches it off) */
    {"fricreg_ctx_set_stribeck",
     w_ctx_set_stribeck,
     "0snim",
     CTX_REC,
     {HANDLE, SIZE(0, "osss"), PTR(1, "0"), ARR(1, "nniiio"), PTR(2, "0"), ARR(2, "nniooi")}},
    {"fricreg_ctx_set_stribeck (vs, delta)",
     w_ctx_set_stribeck,
     "0snim",
     CTX_REC,
     {PTR(3, "0"), ARR(3, "nniioo"), PTR(4, "0"), ARR(4, "nniioo")}},
    /* fricreg_stribeck.h: the 2-D context's Stribeck friction (m = 0 switches it off) */
    {"fricreg_disk_ctx_set_stribeck",
     w_dctx_set_stribeck,
     "0snim",
     DCTX_REC,
     {HANDLE, SIZE(0, "osss"), PTR(1, "0"), ARR(1, "nniiii"), PTR(2, "0"), ARR(2, "nniooi")}},
    {"fricreg_disk_ctx_set_stribeck (vs, delta)",
     w_dctx_set_stribeck,
     "0snim",
     DCTX_REC,
     {PTR(3, "0"), ARR(3, "nniioo"), PTR(4, "0"), ARR(4, "nniioo")}},
    /* fricreg_jenkins.h: one 2-D element */
    {"fricreg_jenkins_create",
     w_jk_create,
     "0im",
     NONE,
     {INT(0, "iiii"), SIZE(0, "iiio"), PTR(0, "0")}},
    {"fricreg_jenkins_set_params",
     w_jk_set_params,
     "0sni",
     JK_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nniioo"), PTR(2, "0"), ARR(2, "nniooo")}},
    {"fricreg_jenkins_trial",
     w_jk_trial,
     "0sn",
     JK_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), PTR(3, "o")}},
    {"fricreg_jenkins_commit", w_jk_commit, "0", JK_REC, {HANDLE}},
    {"fricreg_jenkins_reset", w_jk_reset, "0", JK_REC, {HANDLE}},
    {"fricreg_jenkins_get_slider",
     w_jk_get_slider,
     "0s",
     JK_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_jenkins_set_normal",
     w_jk_set_normal,
     "0sni",
     JK_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnioon"), PTR(2, "0"), ARR(2, "nnoooo"),
      PTR(3, "0"), ARR(3, "nniooo")}},
    {"fricreg_jenkins_trial_normal",
     w_jk_trial_normal,
     "0sn",
     JK_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnoooo"),
      PTR(3, "0"), PTR(4, "o"), PTR(5, "o"), PTR(6, "o")}},
    /* fricreg_iwan.h: one 2-D element of 3 sliders */
    {"fricreg_iwan_create",
     w_iw_create,
     "0im",
     NONE,
     {INT(0, "iiii"), SIZE(0, "iiio"), SIZE(1, "iiio"), PTR(0, "0")}},
    {"fricreg_iwan_set_params",
     w_iw_set_params,
     "0sni",
     IW_REC,
     {HANDLE, SIZE(0, "ssss"), SIZE(1, "ssss"), PTR(1, "0"), ARR(1, "nniioo"), PTR(2, "0"),
      ARR(2, "nniooo")}},
    {"fricreg_iwan_get_params",
     w_iw_get_params,
     "0s",
     IW_REC,
     {HANDLE, SIZE(0, "ssss"), SIZE(1, "ssss"), PTR(1, "0"), PTR(2, "0")}},
    {"fricreg_iwan_set_segalman",
     w_iw_set_segalman,
     "0sni",
     IW_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnii**"), PTR(2, "0"), ARR(2, "nniii*"),
      PTR(3, "0"), ARR(3, "nniooi"), PTR(4, "0"), ARR(4, "nnioo*"), DBL(0, "nnniioi")}},
    {"fricreg_iwan_set_normal",
     w_iw_set_normal,
     "0sni",
     IW_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nniino"), PTR(2, "0"), ARR(2, "nniooo")}},
    {"fricreg_iwan_trial",
     w_iw_trial,
     "0sn",
     IW_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), PTR(3, "o")}},
    {"fricreg_iwan_trial_normal",
     w_iw_trial_normal,
     "0sn",
     IW_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnoooo"),
      PTR(3, "0"), PTR(4, "o"), PTR(5, "o"), PTR(6, "o")}},
    {"fricreg_iwan_commit", w_iw_commit, "0", IW_REC, {HANDLE}},
    {"fricreg_iwan_reset", w_iw_reset, "0", IW_REC, {HANDLE}},
    {"fricreg_iwan_get_slider",
     w_iw_get_slider,
     "0s",
     IW_REC,
     {HANDLE, SIZE(0, "ssss"), SIZE(1, "ssss"), PTR(1, "0")}},
    /* fricreg_aft.h: H = 2, N = 16 (N = 0 allowed: the exact path only) */
    {"fricreg_aft_create",
     w_aft_create,
     "0im",
     NONE,
     {INT(0, "iiii"), COUNT(0, "oiii"), PTR(0, "0")}},
    {"fricreg_aft_jenkins_exact",
     w_aft_jenkins_exact,
     "0nist",
     AFT_REC,
     {HANDLE, DBL(0, "nnniion"), DBL(1, "nnniooo"), SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnooon"),
      PTR(2, "0"), PTR(3, "o")}},
    {"fricreg_aft_jenkins_sampled",
     w_aft_jenkins_sampled,
     "0nis",
     AFT_REC,
     {HANDLE, DBL(0, "nnniion"), DBL(1, "nnniooo"), SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnooon"),
      PTR(2, "0"), PTR(3, "o")}},
    {"fricreg_aft_jenkins_normal_sampled",
     w_aft_jenkins_normal_sampled,
     "0nis",
     AFT_REC,
     /* kt = 4.9e-324 against mu N of 1: the slider's excursion overflows */
     {HANDLE, DBL(0, "nnniinn"), DBL(1, "nnnioon"), DBL(2, "nnnooon"), DBL(3, "nnnioon"),
      SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnooon"), PTR(2, "0"), ARR(2, "nnooon"), PTR(3, "0"),
      PTR(4, "0"), PTR(5, "o")}},
    {"fricreg_aft_jenkins_normal_exact",
     w_aft_jenkins_normal_exact,
     "0nist",
     AFT_REC,
     {HANDLE, DBL(0, "nnniion"), DBL(1, "nnnioon"), DBL(2, "nnnooon"), DBL(3, "nnnioon"),
      SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnooon"), PTR(2, "0"), ARR(2, "nnooon"), PTR(3, "0"),
      PTR(4, "0"), PTR(5, "o")}},
    {"fricreg_aft_iwan_exact",
     w_aft_iwan_exact,
     "0nist",
     AFT_REC,
     {HANDLE, COUNT(0, "ioxx"), PTR(1, "0"), ARR(1, "nniion"), PTR(2, "0"), ARR(2, "nniooo"),
      SIZE(0, "ssss"), PTR(3, "0"), ARR(3, "nnooon"), PTR(4, "0"), PTR(5, "o")}},
    {"fricreg_aft_iwan_sampled",
     w_aft_iwan_sampled,
     "0nis",
     AFT_REC,
     {HANDLE, COUNT(0, "ioxx"), PTR(1, "0"), ARR(1, "nniion"), PTR(2, "0"), ARR(2, "nniooo"),
      SIZE(0, "ssss"), PTR(3, "0"), ARR(3, "nnooon"), PTR(4, "0"), PTR(5, "o")}},
    /* fricreg_hb.h (Jt's and Jn's elements: test_hb_liftoff, for the 13 arguments here) */
    {"fricreg_hb_set_normal_elements",
     w_hb_set_normal_elements,
     "0snim",
     HB_REC,
     {HANDLE, SIZE(0, "ssss"), SIZE(1, "ssss"), PTR(1, "0"), PTR(2, "0"), PTR(3, "0"),
      ARR(3, "nniioo"), PTR(4, "0"), ARR(4, "nniooo"), PTR(5, "0"), ARR(5, "nnoooo"), PTR(6, "0"),
      ARR(6, "nniooo")}},
    {"fricreg_hb_set_iwan_normal",
     w_hb_set_iwan_normal,
     "0snim",
     HB_REC,
     {HANDLE, SIZE(0, "ssss"), SIZE(1, "ssss"), PTR(1, "0"), PTR(2, "0"), COUNT(0, "ioii"),
      PTR(3, "0"), PTR(4, "0"), PTR(5, "0"), PTR(6, "0")}},
    {"fricreg_hb_set_iwan_normal (array entries)",
     w_hb_set_iwan_normal,
     "0snim",
     HB_REC,
     {ARR(1, "nnoooo"), ARR(2, "nnoooo"), ARR(3, "nniioo"), ARR(4, "nniooo"), ARR(5, "nnoooo"),
      ARR(6, "nniooo")}},
    /* fricreg_exact.h */
    {"fricreg_exact_solve",
     w_exact_solve,
     "0nimt",
     NONE,
     {DBL(0, "nnnooo*"), DBL(1, "nnfii*i"), DBL(2, "nnfiooo"), DBL(3, "nnnooo*"), DBL(4, "nnnooo*"),
      DBL(5, "nnniioi"), PTR(0, "0")}},
    {"fricreg_exact_create",
     w_exact_create,
     "0nim",
     NONE,
     {DBL(0, "nnnoooo"), DBL(1, "nnfiioo"), DBL(2, "nnfiooo"), DBL(3, "nnnoooo"), DBL(4, "nnnoooo"),
      PTR(0, "0")}},
    {"fricreg_exact_run", w_exact_run, "0nimt", EX_REC, {HANDLE, DBL(0, "nnniioi")}},
    {"fricreg_exact_run_cycles", w_exact_run_cycles, "0nimt", EX_REC, {HANDLE, INT(0, "iiii")}},
    {"fricreg_exact_get_value",
     w_exact_get_value,
     "0i",
     NONE,
     {HANDLE, INT(0, "ioii"), PTR(1, "0")}},
    {"fricreg_exact_get_stat", w_exact_get_stat, "0i", NONE, {HANDLE, INT(0, "ioii"), PTR(1, "0")}},
    {"fricreg_exact_state",
     w_exact_state,
     "0i",
     NONE,
     {HANDLE, DBL(0, "iiiiooi"), PTR(1, "0"), PTR(2, "0")}},
    {"fricreg_exact_switches",
     w_exact_switches,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), PTR(2, "o")}},
    {"fricreg_exact_dissipation",
     w_exact_dissipation,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_exact_stick_fraction",
     w_exact_stick_fraction,
     "0i",
     NONE,
     {HANDLE, DBL(0, "iiiiooi"), DBL(1, "iiiiioi"), PTR(1, "0")}},
    /* fricreg_sim.h */
    {"fricreg_sim_create", w_sim_create, "0im", NONE, {INT(0, "iiii"), PTR(0, "0")}},
    {"fricreg_sim_set_param (a)",
     w_sim_set_param_a,
     "0in",
     SIM_REC,
     {HANDLE, INT(0, "iiii"), DBL(0, "nnnoooo")}},
    {"fricreg_sim_set_param (omega)", w_sim_set_param_omega, "0in", SIM_REC, {DBL(0, "nnfii**")}},
    {"fricreg_sim_set_param (mun)", w_sim_set_param_mun, "0in", SIM_REC, {DBL(0, "nnfiooo")}},
    {"fricreg_sim_get_param", w_sim_get_param, "0i", NONE, {HANDLE, INT(0, "iiii"), PTR(1, "0")}},
    {"fricreg_sim_set_law",
     w_sim_set_law,
     "0in",
     SIM_REC,
     {HANDLE, INT(0, "iiii"), DBL(0, "nnfiooo")}},
    {"fricreg_sim_set_partition", w_sim_set_partition, "0i", SIM_REC, {HANDLE, INT(0, "iiii")}},
    {"fricreg_sim_set_integrator",
     w_sim_set_integrator,
     "0in",
     SIM_REC,
     {HANDLE, INT(0, "iiii"), DBL(0, "nnfiioo"), DBL(1, "nnfiooo"), DBL(2, "nnfiooo")}},
    {"fricreg_sim_set_observer", w_sim_set_observer, "0i", SIM_REC, {HANDLE}},
    {"fricreg_sim_set_warning_handler", w_sim_set_warning_handler, "0i", SIM_REC, {HANDLE}},
    {"fricreg_sim_set_abs_tolerances",
     w_sim_set_abs_tolerances,
     "0sinm",
     SIM_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nniioo")}},
    {"fricreg_sim_get_abs_tolerances",
     w_sim_get_abs_tolerances,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_sim_set_max_steps", w_sim_set_max_steps, "0i", SIM_REC, {HANDLE, INT(0, "iooi")}},
    {"fricreg_sim_get_warning",
     w_sim_get_warning,
     "0i",
     NONE,
     {HANDLE, COUNT(0, "oiii"), PTR(1, "0"), PTR(2, "o")}},
    {"fricreg_sim_set_kink_location",
     w_sim_set_kink_location,
     "0i",
     SIM_REC,
     {HANDLE, INT(0, "ioii")}},
    {"fricreg_sim_set_error_estimate",
     w_sim_set_error_estimate,
     "0i",
     SIM_REC,
     {HANDLE, INT(0, "ioii")}},
    {"fricreg_sim_get_dissipation_error (none held)",
     w_sim_get_dissipation_error,
     "0is",
     NONE,
     {PTR(8, "i"), HANDLE, SIZE(0, "ffff"), PTR(1, "0")}},
    {"fricreg_sim_run", w_sim_run, "0inedtgm", SIM_REC, {HANDLE, DBL(0, "nnfiioi")}},
    {"fricreg_sim_run_cycles", w_sim_run_cycles, "0inedtgm", SIM_REC, {HANDLE, INT(0, "iiii")}},
    {"fricreg_sim_run_extrapolated",
     w_sim_run_extrapolated,
     "0inedtgm",
     SIM_REC,
     {HANDLE, DBL(0, "nnfii*i"), INT(0, "iiii"), INT(1, "ioii")}},
    {"fricreg_sim_run_extrapolated_window",
     w_sim_run_extrapolated_window,
     "0inedtgm",
     SIM_REC,
     {HANDLE, INT(2, "iooi")}},
    {"fricreg_sim_get_extrapolation (none held)",
     w_sim_get_extrapolation,
     "0i",
     NONE,
     {PTR(8, "i"), HANDLE, INT(0, "iiii"), PTR(1, "0")}},
    {"fricreg_sim_get_extrapolated_dissipation (none held)",
     w_sim_get_extrapolated_dissipation,
     "0is",
     NONE,
     {PTR(8, "i"), HANDLE, SIZE(0, "ffff"), PTR(1, "0"), PTR(2, "0")}},
    {"fricreg_sim_get_value", w_sim_get_value, "0i", NONE, {HANDLE, INT(0, "ioii"), PTR(1, "0")}},
    {"fricreg_sim_get_stat", w_sim_get_stat, "0i", NONE, {HANDLE, INT(0, "ioii"), PTR(1, "0")}},
    {"fricreg_sim_get_state",
     w_sim_get_state,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), PTR(2, "0")}},
    {"fricreg_sim_get_dissipation",
     w_sim_get_dissipation,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_sim_get_stick_fraction",
     w_sim_get_stick_fraction,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    /* fricreg_structure.h */
    {"fricreg_structure_create",
     w_st_create,
     "0im",
     NONE,
     {SIZE(0, "iiio"), SIZE(1, "iiio"), PTR(0, "0")}},
    {"fricreg_structure_set_mass",
     w_st_set_mass,
     "0snyp",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnpp**"), MAT(1, "ppy**")}},
    {"fricreg_structure_set_stiffness",
     w_st_set_stiffness,
     "0sny",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), MAT(1, "ooyoo")}},
    {"fricreg_structure_set_damping",
     w_st_set_damping,
     "0sny",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), MAT(1, "ooyoo")}},
    {"fricreg_structure_set_rayleigh",
     w_st_set_rayleigh,
     "0ni",
     ST_REC,
     {HANDLE, DBL(0, "nnfiooo"), DBL(1, "nnfiooo")}},
    {"fricreg_structure_set_contacts",
     w_st_set_contacts,
     "0sni",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), SIZE(1, "ssss"), PTR(1, "0"), ARR(1, "nnoioo")}},
    {"fricreg_structure_set_bounds",
     w_st_set_bounds,
     "0sin",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nniooo")}},
    {"fricreg_structure_set_law",
     w_st_set_law,
     "0in",
     ST_REC,
     {HANDLE, INT(0, "iiii"), DBL(0, "nnfii*o")}},
    {"fricreg_structure_set_influence",
     w_st_set_influence,
     "0sn",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo")}},
    {"fricreg_structure_set_ground_accel",
     w_st_set_ground_accel,
     "0inm",
     ST_REC,
     {HANDLE, DBL(0, "nnnoooo"), DBL(1, "nnfiioo"), COUNT(0, "oixx"), PTR(1, "0"),
      ARR(1, "nnoooo")}},
    {"fricreg_structure_set_load",
     w_st_set_load,
     "0sinm",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), DBL(0, "nnnoooo"), DBL(1, "nnfiioo"),
      COUNT(0, "oixx"), ARR(2, "nnoooo")}},
    {"fricreg_structure_set_load (g NULL)", w_st_set_load, "0sinm", ST_REC, {PTR(2, "0")}},
    {"fricreg_structure_set_initial",
     w_st_set_initial,
     "0sn",
     ST_REC,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoooo"), PTR(2, "0"), ARR(2, "nnoooo")}},
    {"fricreg_structure_set_newmark",
     w_st_set_newmark,
     "0ni",
     ST_REC,
     {HANDLE, DBL(0, "nnfiioi"), DBL(1, "nnfiiii")}},
    {"fricreg_structure_set_hht", w_st_set_hht, "0ni", ST_REC, {HANDLE, DBL(0, "nnfioii")}},
    {"fricreg_structure_set_central_difference",
     w_st_set_central_difference,
     "0",
     ST_REC,
     {HANDLE}},
    {"fricreg_structure_set_max_steps", w_st_set_max_steps, "0i", ST_REC, {HANDLE, INT(0, "iooi")}},
    {"fricreg_structure_set_warning_handler", w_st_set_warning_handler, "0i", ST_REC, {HANDLE}},
    {"fricreg_structure_set_newton",
     w_st_set_newton,
     "0ni",
     ST_REC,
     {HANDLE, DBL(0, "nnfiioi"), INT(0, "iiii")}},
    {"fricreg_structure_step", w_st_step, "0inypged", ST_REC, {HANDLE, DBL(0, "nnniioi")}},
    {"fricreg_structure_run",
     w_st_run,
     "0inypged",
     ST_REC,
     {HANDLE, DBL(0, "nnniiio"), DBL(1, "nnfii*i")}},
    {"fricreg_structure_run_ode",
     w_st_run_ode,
     "0inegdtm",
     ST_REC,
     {HANDLE, INT(0, "iiii"), DBL(0, "nnfii**"), DBL(1, "nnfio**"), DBL(2, "nnfio**"),
      DBL(3, "nnfii**")}},
    {"fricreg_structure_set_ode_abs_tolerances",
     w_st_set_ode_abs_tolerances,
     "0sinm",
     ST_REC,
     {HANDLE, SIZE(0, "osss"), PTR(1, "0"), ARR(1, "nniioo")}},
    {"fricreg_structure_get_ode_abs_tolerances",
     w_st_get_ode_abs_tolerances,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_structure_get_state",
     w_st_get_state,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "o"), PTR(2, "o"), PTR(3, "o")}},
    {"fricreg_structure_get_state (all outputs NULL)",
     w_st_get_state_no_output,
     "0s",
     NONE,
     {PTR(8, "0")}},
    {"fricreg_structure_set_jenkins",
     w_st_set_jenkins,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoioo"), PTR(2, "0"),
      ARR(2, "nniioo"), PTR(3, "0"), ARR(3, "nniooo")}},
    {"fricreg_structure_set_jenkins_csr",
     w_st_set_jenkins_csr,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), INT(0, "ioii"), PTR(1, "0"), PTR(2, "0"),
      PTR(3, "0"), ARR(3, "nnoioo"), PTR(4, "0"), ARR(4, "nniioo"), PTR(5, "0"), ARR(5, "nniooo")}},
    {"fricreg_structure_set_jenkins_2d",
     w_st_set_jenkins_2d,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoioo"), PTR(2, "0"),
      ARR(2, "nniioo"), PTR(3, "0"), ARR(3, "nniooo")}},
    {"fricreg_structure_set_jenkins_2d_csr",
     w_st_set_jenkins_2d_csr,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), INT(0, "ioii"), PTR(1, "0"), PTR(2, "0"),
      PTR(3, "0"), ARR(3, "nnoioo"), PTR(4, "0"), ARR(4, "nniioo"), PTR(5, "0"), ARR(5, "nniooo")}},
    {"fricreg_structure_set_iwan",
     w_st_set_iwan,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), PTR(1, "0"), ARR(1, "nnoioo"), COUNT(1, "ioii"),
      PTR(2, "0"), ARR(2, "nniioo"), PTR(3, "0"), ARR(3, "nniooo")}},
    {"fricreg_structure_set_iwan_csr",
     w_st_set_iwan_csr,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), INT(0, "ioii"), PTR(1, "0"), PTR(2, "0"),
      PTR(3, "0"), ARR(3, "nnoioo"), COUNT(1, "ioii"), PTR(4, "0"), ARR(4, "nniioo"), PTR(5, "0"),
      ARR(5, "nniooo")}},
    {"fricreg_structure_get_iwan_state",
     w_st_get_iwan_state,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "osss"), SIZE(1, "oooo"), PTR(1, "o"), PTR(2, "o"), PTR(3, "o")}},
    {"fricreg_structure_get_iwan_state (all outputs NULL)",
     w_st_get_iwan_state_no_output,
     "0s",
     NONE,
     {PTR(8, "0")}},
    {"fricreg_structure_set_jenkins_normal",
     w_st_set_jenkins_normal,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), PTR(1, "0"), PTR(2, "0"), PTR(3, "0"), PTR(4, "0"),
      PTR(5, "0"), PTR(6, "0")}},
    {"fricreg_structure_set_jenkins_normal (array entries)",
     w_st_set_jenkins_normal,
     "0snim",
     ST_REC,
     {ARR(1, "nnoioo"), ARR(2, "nnoooo"), ARR(3, "nniioo"), ARR(4, "nniooo"), ARR(5, "nnoooo"),
      ARR(6, "nniioo")}},
    {"fricreg_structure_set_iwan_normal",
     w_st_set_iwan_normal,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), PTR(1, "0"), PTR(2, "0"), COUNT(1, "ioii"),
      PTR(3, "0"), PTR(4, "0"), PTR(5, "0"), PTR(6, "0")}},
    {"fricreg_structure_set_iwan_normal (array entries)",
     w_st_set_iwan_normal,
     "0snim",
     ST_REC,
     {ARR(1, "nnoioo"), ARR(2, "nnoooo"), ARR(3, "nniioo"), ARR(4, "nniooo"), ARR(5, "nnoooo"),
      ARR(6, "nniioo")}},
    {"fricreg_structure_set_jenkins_2d_normal",
     w_st_set_jenkins_2d_normal,
     "0snim",
     ST_REC,
     {HANDLE, COUNT(0, "ooii"), SIZE(0, "ssss"), PTR(1, "0"), PTR(2, "0"), PTR(3, "0"), PTR(4, "0"),
      PTR(5, "0"), PTR(6, "0")}},
    {"fricreg_structure_set_jenkins_2d_normal (array entries)",
     w_st_set_jenkins_2d_normal,
     "0snim",
     ST_REC,
     {ARR(1, "nnoioo"), ARR(2, "nnoooo"), ARR(3, "nniioo"), ARR(4, "nniooo"), ARR(5, "nnoooo"),
      ARR(6, "nniioo")}},
    {"fricreg_structure_get_normal_forces",
     w_st_get_normal_forces,
     "0si",
     NONE,
     {HANDLE, SIZE(0, "osss"), PTR(1, "0")}},
    {"fricreg_structure_get_jenkins_state",
     w_st_get_jenkins_state,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "osss"), PTR(1, "o"), PTR(2, "o"), PTR(3, "o")}},
    {"fricreg_structure_get_jenkins_2d_state",
     w_st_get_jenkins_2d_state,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "osss"), PTR(1, "o"), PTR(2, "o"), PTR(3, "o")}},
    {"fricreg_structure_get_jenkins_2d_state (all outputs NULL)",
     w_st_get_jenkins_2d_state_no_output,
     "0s",
     NONE,
     {PTR(8, "0")}},
    {"fricreg_structure_get_jenkins_state (all outputs NULL)",
     w_st_get_jenkins_state_no_output,
     "0s",
     NONE,
     {PTR(8, "0")}},
    {"fricreg_structure_get_forces",
     w_st_get_forces,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_structure_get_dissipation",
     w_st_get_dissipation,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_structure_set_error_estimate",
     w_st_set_error_estimate,
     "0i",
     ST_REC,
     {HANDLE, INT(0, "ioii")}},
    {"fricreg_structure_get_peak_displacement",
     w_st_get_peak_displacement,
     "0s",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_structure_get_peak_displacement_error",
     w_st_get_peak_displacement_error,
     "0is",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_structure_get_dissipation_error",
     w_st_get_dissipation_error,
     "0is",
     NONE,
     {HANDLE, SIZE(0, "ssss"), PTR(1, "0")}},
    {"fricreg_structure_get_jenkins_dissipation_error",
     w_st_get_jenkins_dissipation_error,
     "0is",
     NONE,
     {HANDLE, SIZE(0, "osss"), PTR(1, "0")}},
    {"fricreg_structure_get_value",
     w_st_get_value,
     "0i",
     NONE,
     {HANDLE, INT(0, "ioii"), PTR(1, "0")}},
    {"fricreg_structure_get_stat",
     w_st_get_stat,
     "0i",
     NONE,
     {HANDLE, INT(0, "ioii"), PTR(1, "0")}},
    {"fricreg_structure_get_warning",
     w_st_get_warning,
     "0i",
     NONE,
     {HANDLE, COUNT(0, "oiii"), PTR(1, "0"), PTR(2, "o")}},
};

/* ---- Running the table -------------------------------------------------------------------- */

static int code_of(char letter)
{
    static const char letters[] = "o0insmypgedt";
    static const int codes[] = {FRICREG_OK,         FRICREG_ENULL,     FRICREG_EINVAL,
                                FRICREG_ENONFINITE, FRICREG_ESIZE,     FRICREG_ENOMEM,
                                FRICREG_ENOTSYM,    FRICREG_ENOTPSD,   FRICREG_ESINGULAR,
                                FRICREG_ESTEP,      FRICREG_EDIVERGED, FRICREG_EINTEGRATOR};
    const char *at = strchr(letters, letter);
    return at != NULL && letter != '\0' ? codes[at - letters] : -1;
}

static int documented(const struct row *r, int status)
{
    if (status == FRICREG_OK)
        return 1;
    for (const char *c = r->documented; *c; c++)
        if (code_of(*c) == status)
            return 1;
    return 0;
}

static int recorded(enum owner owner, const struct fixture *fx)
{
    switch (owner) {
    case CTX_REC: return fricreg_ctx_errcode(fx->ctx);
    case EX_REC: return fricreg_exact_errcode(fx->ex);
    case SIM_REC: return fricreg_sim_errcode(fx->sim);
    case ST_REC: return fricreg_structure_errcode(fx->st);
    case DCTX_REC: return fricreg_disk_ctx_errcode(fx->dctx);
    case CHAIN_REC: return fricreg_sim_errcode(chain_);
    case EXSTUCK_REC: return fricreg_exact_errcode(stuck_);
    case JK_REC: return fricreg_jenkins_errcode(fx->jk);
    case IW_REC: return fricreg_iwan_errcode(fx->iw);
    case AFT_REC: return fricreg_aft_errcode(fx->aft);
    case HB_REC: return fricreg_hb_errcode(fx->hb);
    default: return -1;
    }
}

static const char *message(enum owner owner, const struct fixture *fx)
{
    switch (owner) {
    case CTX_REC: return fricreg_ctx_errmsg(fx->ctx);
    case EX_REC: return fricreg_exact_errmsg(fx->ex);
    case SIM_REC: return fricreg_sim_errmsg(fx->sim);
    case DCTX_REC: return fricreg_disk_ctx_errmsg(fx->dctx);
    case CHAIN_REC: return fricreg_sim_errmsg(chain_);
    case EXSTUCK_REC: return fricreg_exact_errmsg(stuck_);
    case JK_REC: return fricreg_jenkins_errmsg(fx->jk);
    case IW_REC: return fricreg_iwan_errmsg(fx->iw);
    case AFT_REC: return fricreg_aft_errmsg(fx->aft);
    case HB_REC: return fricreg_hb_errmsg(fx->hb);
    default: return fricreg_structure_errmsg(fx->st);
    }
}

static void class_name(const struct perturb *p, char *buf, size_t len)
{
    switch (p->kind) {
    case K_PTR: snprintf(buf, len, "pointer %d NULL", p->slot); break;
    case K_DBL: snprintf(buf, len, "double %d = %g", p->slot, dbl_class[p->cls]); break;
    case K_SIZE:
        snprintf(buf, len, "size %d = %s", p->slot,
                 (const char *[]){"0", "SIZE_MAX", "SIZE_MAX/2+1", "one more"}[p->cls]);
        break;
    case K_COUNT: snprintf(buf, len, "count %d = %zu", p->slot, count_class[p->cls]); break;
    case K_INT: snprintf(buf, len, "int %d = %d", p->slot, int_class[p->cls]); break;
    case K_ARR: snprintf(buf, len, "array %d [0] = %g", p->slot, arr_class[p->cls]); break;
    default: snprintf(buf, len, "matrix %d %s", p->slot, mat_class_name[p->cls]);
    }
}

/* One case; returns 1 if it disagrees with the docstring (printed). */
static int run_case(const struct row *r, const struct perturb *p, char expect)
{
    struct fixture fx;
    fixture_make(&fx);
    P_ = p;
    FX_ = &fx;
    int status = r->call();
    char what[96], why[160] = "";
    class_name(p, what, sizeof what);
    int want = code_of(expect);
    if (!documented(r, status))
        snprintf(why, sizeof why, "status %d (%s) is not in its docstring", status,
                 fricreg_strerror(status));
    else if (expect == 'f' && status == FRICREG_OK)
        snprintf(why, sizeof why, "accepted, docstring refuses it");
    else if (want >= 0 && status != want)
        snprintf(why, sizeof why, "status %d (%s), docstring says %d (%s)", status,
                 fricreg_strerror(status), want, fricreg_strerror(want));
    else if (status != FRICREG_OK &&
             !(untouched(fx.out, sizeof fx.out) && untouched(&fx.handle_out, sizeof(void *))))
        snprintf(why, sizeof why, "failed (%d) but wrote an output", status);
    else if (status != FRICREG_OK && r->owner != NONE && !is(K_PTR, 9) &&
             (recorded(r->owner, &fx) != status || message(r->owner, &fx)[0] == '\0'))
        snprintf(why, sizeof why, "failed (%d) but recorded %d, message '%s'", status,
                 recorded(r->owner, &fx), message(r->owner, &fx));
    fixture_free(&fx);
    if (expect == '*' && getenv("BAD_INPUT_VERBOSE") != NULL) /* what the docstring left open */
        printf("open: %s, %s: %s\n", r->name, what, fricreg_strerror(status));
    if (why[0] != '\0')
        printf("DISAGREES: %s, %s: %s\n", r->name, what, why);
    return why[0] != '\0';
}

START_TEST(matrix)
{
    int cases = 0, disagreements = 0;
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        const struct row *r = &rows[k];
        /* The defaults first: valid, so that every other case differs from a success in one
         * argument (but in the rows whose call is itself the bad input, marked by slot 8). */
        struct perturb none = {K_PTR, -1, 0};
        disagreements += run_case(r, &none, r->args[0].slot == 8 ? r->args[0].expect[0] : 'o');
        cases++;
        for (int a = 0; a < MAXARGS && r->args[a].expect != NULL; a++) {
            const struct arg *arg = &r->args[a];
            ck_assert_msg((int)strlen(arg->expect) == nclasses[arg->kind],
                          "%s: argument %d has %zu letters for %d classes", r->name, a,
                          strlen(arg->expect), nclasses[arg->kind]);
            for (int cls = 0; cls < nclasses[arg->kind]; cls++) {
                if (arg->expect[cls] == 'x')
                    continue;
                struct perturb p = {arg->kind, arg->slot, cls};
                disagreements += run_case(r, &p, arg->expect[cls]);
                cases++;
            }
        }
    }
    printf("bad-input matrix: %d cases over %zu rows, %d disagreements\n", cases,
           sizeof rows / sizeof rows[0], disagreements);
    ck_assert_int_eq(disagreements, 0);
    ck_assert_int_ge(cases, 400);
}
END_TEST

/* ---- Documented bounds: the last value accepted, and the first refused --------------------

The classes above are far from most bounds (1e308 against a bound of 1e250 or 1000), so a
bound moved or loosened passes them. Each edge below is a bound some docstring states, tried
at its last accepted value (must return FRICREG_OK) and at the first value beyond (the
next double, or the next integer; for a tolerance, twice it: rounding blurs the line by a few
ulps), which must return the documented refusal, write no output and record it. An upper
bound that takes hours or gigabytes to reach from inside (2^26 contacts, 2^31 steps, 10^9
cycles) is tried from outside only: inside NAN. */

struct edge {
    const char *name;
    int (*call)(int which, double x);
    int which;
    double inside, outside;
    char refused;
    enum owner owner;
};

static double below(double x)
{
    return nextafter(x, -INFINITY);
}
static double above(double x)
{
    return nextafter(x, INFINITY);
}

static int e_law_eval(int which, double x)
{
    return fricreg_law_eval(which == 2 ? (int)x : FRICREG_LAW_QUINN, 0.0004, 0.3,
                            which == 1 ? x : 1.0, which == 0 ? x : 1e-3, OUTD(0));
}
static int e_law_eval_batch(int which, double x)
{
    const double mun[2] = {which == 2 ? x : 0.5, 0.25};
    return fricreg_law_eval_batch(which == 1 ? (int)x : FRICREG_LAW_QUINN, which == 0 ? x : 1e-3, 2,
                                  TWO, TWO, mun, OUTD(0));
}
static int e_aft_create(int which, double x)
{
    fricreg_aft *a = (fricreg_aft *)FX_->handle_out;
    int H = which == 0 ? (int)x : 3;
    size_t N = which == 0 ? 0 : (size_t)x;
    int status = fricreg_aft_create(H, N, &a);
    if (status == FRICREG_OK)
        fricreg_aft_free(a);
    else
        memcpy(&FX_->handle_out, &a, sizeof a);
    return status;
}
static int e_aft_eval(int which, double x)
{
    const double u[5] = {0.25, 1.5, -0.5, 0.125, 0.375};
    double *f = FX_->out[0], *jac = FX_->out[1];
    if (which == 0)
        return fricreg_aft_jenkins_exact(FX_->aft, x, 0.5, 5, u, f, jac);
    if (which == 1)
        return fricreg_aft_jenkins_exact(FX_->aft, 2.385, x, 5, u, f, jac);
    const double k[2] = {1.0, x}, phi[2] = {0.5, 0.25};
    return fricreg_aft_iwan_sampled(FX_->aft, 2, k, phi, 5, u, f, jac);
}
static int e_ctx_create(int which, double x)
{
    (void)which;
    fricreg_ctx *ctx = (fricreg_ctx *)FX_->handle_out;
    int status = fricreg_ctx_create((size_t)x, &ctx);
    if (status == FRICREG_OK)
        fricreg_ctx_free(ctx);
    else
        memcpy(&FX_->handle_out, &ctx, sizeof ctx);
    return status;
}
static int e_ctx_set_law(int which, double x)
{
    return fricreg_ctx_set_law(FX_->ctx, which == 1 ? (int)x : FRICREG_LAW_QUINN,
                               which == 0 ? x : 0.02);
}
static int e_ctx_set_bounds(int which, double x)
{
    (void)which;
    const double mun[2] = {x, 0.25};
    return fricreg_ctx_set_bounds(FX_->ctx, 2, mun);
}
static int e_ctx_set_dense(int which, double x)
{
    const double W[3][4] = {{x, 0.0, 0.0, 1.0},            /* W_ii >= DBL_MIN */
                            {1.0, 0.5 + x, 0.5, 1.0},      /* symmetric to 1e-12 */
                            {1.0, 1.0 + x, 1.0 + x, 1.0}}; /* eigenvalue -x >= -1e-12 m */
    return fricreg_ctx_set_coupling_dense(FX_->ctx, 2, W[which]);
}
static int e_ctx_set_csr(int which, double x)
{
    const double W[3][4] = {{x, 0.0, 0.0, 1.0},            /* W_ii >= DBL_MIN */
                            {1.0, 0.5 + x, 0.5, 1.0},      /* symmetric to 1e-12 */
                            {1.0, 1.0 + x, 1.0 + x, 1.0}}; /* eigenvalue -x >= -1e-12 r */
    return fricreg_ctx_set_coupling_csr(FX_->ctx, 2, 0, W2B_PTR, W2B_IND, W[which]);
}
static int e_ctx_int(int which, double x)
{
    switch (which) {
    case 0: return fricreg_ctx_set_partition(FX_->ctx, (int)x);
    case 1: return fricreg_ctx_set_keep_tangent(FX_->ctx, (int)x);
    default: return fricreg_ctx_get_stat(FX_->ctx, (int)x, (int64_t *)OUTD(0));
    }
}
static int e_ctx_eval(int which, double x)
{
    (void)which;
    const double zdot[2] = {0.0004, -0.0002}, a[2] = {x, -0.347};
    return fricreg_ctx_eval(FX_->ctx, 2, zdot, a, OUTD(0), OUTD(1));
}
static int e_ctx_set_stribeck(int which, double x)
{
    const double fk[2] = {x, 0.2};
    return fricreg_ctx_set_stribeck(FX_->ctx, 2, which == 0 ? FS2 : FS2, fk, VS2, DELTA2);
}
static int e_disk_eval(int which, double x)
{
    double v[2] = {0.004, -0.002}, feq[2] = {0.213, -0.347}, mun = 0.5, eps = 0.02;
    int law = FRICREG_DISK_QUINN;
    switch (which) {
    case 0: eps = x; break;
    case 1: law = (int)x; break;
    case 2: v[0] = x; break;
    case 3: feq[1] = x; break;
    default: mun = x;
    }
    return fricreg_disk_eval(law, v, feq, mun, eps, OUTD(0));
}
static int e_disk_eval_batch(int which, double x)
{
    double v[2] = {0.004, -0.002}, feq[2] = {0.213, -0.347}, mun[1] = {0.5}, eps = 0.02;
    int law = FRICREG_DISK_QUINN;
    switch (which) {
    case 0: eps = x; break;
    case 1: law = (int)x; break;
    case 2: v[1] = x; break;
    case 3: feq[0] = x; break;
    default: mun[0] = x;
    }
    return fricreg_disk_eval_batch(law, eps, 1, v, feq, mun, OUTD(0));
}
static int e_dctx_create(int which, double x)
{
    (void)which;
    fricreg_disk_ctx *ctx = (fricreg_disk_ctx *)FX_->handle_out;
    int status = fricreg_disk_ctx_create((size_t)x, &ctx);
    if (status == FRICREG_OK)
        fricreg_disk_ctx_free(ctx);
    else
        memcpy(&FX_->handle_out, &ctx, sizeof ctx);
    return status;
}
static int e_dctx_set_law(int which, double x)
{
    return which == 0 ? fricreg_disk_ctx_set_law(FX_->dctx, (int)x, 0.02)
                      : fricreg_disk_ctx_set_law(FX_->dctx, FRICREG_DISK_QUINN, x);
}
static int e_dctx_set_bounds(int which, double x)
{
    (void)which;
    return fricreg_disk_ctx_set_bounds(FX_->dctx, 1, &x);
}
/* which 0-2: blocks, 3-5: dense (one contact: W is its block) */
static int e_dctx_coupling(int which, double x)
{
    const double W[3][4] = {{1.0, 0.0, 0.0, x},        /* smallest eigenvalue > 1e-12 largest */
                            {x, 0.0, 0.0, x},          /* and >= DBL_MIN */
                            {1.0, 0.5 + x, 0.5, 1.0}}; /* symmetric to 1e-12 */
    return which < 3 ? fricreg_disk_ctx_set_coupling_blocks(FX_->dctx, 1, W[which])
                     : fricreg_disk_ctx_set_coupling_dense(FX_->dctx, 1, W[which - 3]);
}
/* which 0-2: e_dctx_coupling's W by compressed rows, 3-5: by columns (the diagonal ones by
 * their upper triangle: a W given whole is read as (W + W^T)/2, which moves a subnormal
 * entry by its last bit); 6: diag(x, x) by rows; 7: the same with each diagonal entry given
 * as two halves (duplicates summed) */
static int e_dctx_sparse(int which, double x)
{
    const double W[3][4] = {{1.0, 0.0, 0.0, x}, {x, 0.0, 0.0, x}, {1.0, 0.5 + x, 0.5, 1.0}};
    const int64_t ptr[3] = {0, 2, 4}, ind[4] = {0, 1, 0, 1};
    const int64_t dptr[3] = {0, 2, 4}, dind[4] = {0, 0, 1, 1}, tptr[3] = {0, 1, 2};
    const double diag[4] = {x, 0.0, 0.0, x}, halves[4] = {0.5 * x, 0.5 * x, 0.5 * x, 0.5 * x};
    const double tri[2] = {W[which % 3][0], W[which % 3][3]};
    const int up = FRICREG_SPARSE_UPPER;
    switch (which) {
    case 0:
    case 1: return fricreg_disk_ctx_set_coupling_csr(FX_->dctx, 1, up, tptr, ind, tri);
    case 2: return fricreg_disk_ctx_set_coupling_csr(FX_->dctx, 1, 0, ptr, ind, W[2]);
    case 3:
    case 4: return fricreg_disk_ctx_set_coupling_csc(FX_->dctx, 1, up, tptr, ind, tri);
    case 5: return fricreg_disk_ctx_set_coupling_csc(FX_->dctx, 1, 0, ptr, ind, W[2]);
    case 6: return fricreg_disk_ctx_set_coupling_csr(FX_->dctx, 1, 0, ptr, ind, diag);
    default: return fricreg_disk_ctx_set_coupling_csr(FX_->dctx, 1, 0, dptr, dind, halves);
    }
}
static int e_dctx_eval(int which, double x)
{
    double zdot[2] = {0.004, -0.002}, a[2] = {0.213, -0.347};
    (which == 0 ? zdot : a)[0] = x;
    return fricreg_disk_ctx_eval(FX_->dctx, 1, zdot, a, OUTD(0));
}
static int e_dctx_set_stribeck(int which, double x)
{
    double fs[1] = {0.5}, fk[1] = {0.3};
    (which == 0 ? fs : fk)[0] = x;
    return fricreg_disk_ctx_set_stribeck(FX_->dctx, 1, fs, fk, VS2, DELTA2);
}
/* fs 0.5, fk 0.3, vs 0.01, delta 1, eps 0.02; which picks the one that is x */
static int e_stribeck_eval(int which, double x)
{
    double a[5] = {0.5, 0.3, 0.01, 1.0, 0.02};
    a[which] = x;
    return fricreg_stribeck_eval(0.0004, 0.3, a[0], a[1], a[2], a[3], a[4], OUTD(0));
}
static int e_stribeck_eval_batch(int which, double x)
{
    double a[5] = {0.5, 0.3, 0.01, 1.0, 0.02};
    a[which] = x;
    return fricreg_stribeck_eval_batch(a[4], 1, TWO, TWO, &a[0], &a[1], &a[2], &a[3], OUTD(0));
}
/* 5, 6: a component of v or f_eq */
static int e_stribeck_disk_eval(int which, double x)
{
    double a[5] = {0.5, 0.3, 0.01, 1.0, 0.02}, v[2] = {0.004, -0.002}, feq[2] = {0.213, -0.347};
    if (which < 5)
        a[which] = x;
    else
        (which == 5 ? v : feq)[1] = x;
    return fricreg_stribeck_disk_eval(v, feq, a[0], a[1], a[2], a[3], a[4], OUTD(0));
}
static int e_stribeck_disk_eval_batch(int which, double x)
{
    double a[5] = {0.5, 0.3, 0.01, 1.0, 0.02}, v[2] = {0.004, -0.002}, feq[2] = {0.213, -0.347};
    if (which < 5)
        a[which] = x;
    else
        (which == 5 ? v : feq)[0] = x;
    return fricreg_stribeck_disk_eval_batch(a[4], 1, v, feq, &a[0], &a[1], &a[2], &a[3], OUTD(0));
}
static int e_exact_create(int which, double x)
{
    (void)which;
    fricreg_exact *ex = (fricreg_exact *)FX_->handle_out;
    int status = fricreg_exact_create(0.3, 0.8, x, 2.75, 0.1, &ex);
    if (status == FRICREG_OK)
        fricreg_exact_free(ex);
    else
        memcpy(&FX_->handle_out, &ex, sizeof ex);
    return status;
}
static int e_exact_solve(int which, double x)
{
    (void)which;
    fricreg_exact *ex = (fricreg_exact *)FX_->handle_out;
    int status = fricreg_exact_solve(0.0, 0.8, 1.0, 0.5, 0.0, x, &ex);
    if (status == FRICREG_OK)
        fricreg_exact_free(ex);
    else
        memcpy(&FX_->handle_out, &ex, sizeof ex);
    return status;
}
static int e_exact_stuck(int which, double x)
{
    return which == 0 ? fricreg_exact_run(stuck_, x) : fricreg_exact_run_cycles(stuck_, (int)x);
}
/* which 0, 1: get_value, get_stat; 2, 3: state at t (the fixture runs to 20), t >= 0; 4: the
 * stick fraction over [0, x]; 5: over [x, 10] */
static int e_exact_get(int which, double x)
{
    switch (which) {
    case 0: return fricreg_exact_get_value(FX_->ex, (int)x, OUTD(0));
    case 1: return fricreg_exact_get_stat(FX_->ex, (int)x, (int64_t *)OUTD(0));
    case 2:
    case 3: return fricreg_exact_state(FX_->ex, x, OUTD(0), OUTD(1));
    case 4: return fricreg_exact_stick_fraction(FX_->ex, 0.0, x, OUTD(0));
    default: return fricreg_exact_stick_fraction(FX_->ex, x, 10.0, OUTD(0));
    }
}
static int e_chain_n(int which, double x)
{
    (void)which;
    return fricreg_sim_set_param(chain_, FRICREG_PARAM_N, x);
}
/* which 0: mun; 1: law's eps (0: the paper's rule); 2: law; 3: partition; 4: integrator;
 * 5: rtol of central differences; 6: rtol of rkf45; 7: kink location; 8: msbdf's atol
 * (FRICREG_ATOL_FROM_EPS = -1 or >= 0); 9: a velocity's entry of set_abs_tolerances;
 * 10: error estimate */
static int e_sim_set(int which, double x)
{
    switch (which) {
    case 0: return fricreg_sim_set_param(FX_->sim, FRICREG_PARAM_MUN, x);
    case 1: return fricreg_sim_set_law(FX_->sim, FRICREG_LAW_QUINN, x);
    case 2: return fricreg_sim_set_law(FX_->sim, (int)x, 0.02);
    case 3: return fricreg_sim_set_partition(FX_->sim, (int)x);
    case 4: return fricreg_sim_set_integrator(FX_->sim, (int)x, 0.01, 0.0, 0.0);
    case 5: return fricreg_sim_set_integrator(FX_->sim, FRICREG_INT_CENTRAL, 0.01, x, 0.0);
    case 7: return fricreg_sim_set_kink_location(FX_->sim, (int)x);
    case 10: return fricreg_sim_set_error_estimate(FX_->sim, (int)x);
    case 8: return fricreg_sim_set_integrator(FX_->sim, FRICREG_INT_MSBDF, 0.01, 1e-6, x);
    case 9: {
        const double atol[3] = {1e-6, x, 1e-6};
        return fricreg_sim_set_abs_tolerances(FX_->sim, 3, atol);
    }
    default: return fricreg_sim_set_integrator(FX_->sim, FRICREG_INT_RKF45, 0.01, x, 0.0);
    }
}
/* which 0: fixed steps (rkf45, dt = 0.01: one GSL step per dt; rk4's GSL steps are 2 dt, and
 * the cap counts GSL steps) to t_end = x; 1: rkf45's whole cycles (adaptive);
 * 2, 3: levels; 4, 5: order; 6: window (t_end = 1) */
static int e_sim_run(int which, double x)
{
    switch (which) {
    case 0:
        if (fricreg_sim_set_integrator(FX_->sim, FRICREG_INT_RKF45, 0.01, 0.0, 0.0) != FRICREG_OK)
            return -1;
        return fricreg_sim_run(FX_->sim, x);
    case 1:
        if (fricreg_sim_set_integrator(FX_->sim, FRICREG_INT_RKF45, 0.01, 1e-6, 1e-9) != FRICREG_OK)
            return -1;
        return fricreg_sim_run_cycles(FX_->sim, (int)x);
    case 2:
    case 3: return fricreg_sim_run_extrapolated(FX_->sim, 1.0, (int)x, 0);
    case 4:
    case 5: return fricreg_sim_run_extrapolated(FX_->sim, 1.0, 2, (int)x);
    default: return fricreg_sim_run_extrapolated_window(FX_->sim, 1.0, 2, 0, (int)x);
    }
}
/* which 0: get_value; 1: get_stat; 2, 3: get_extrapolation of an extrapolated run */
static int e_sim_get(int which, double x)
{
    switch (which) {
    case 0: return fricreg_sim_get_value(FX_->sim, (int)x, OUTD(0));
    case 1: return fricreg_sim_get_stat(FX_->sim, (int)x, (int64_t *)OUTD(0));
    default: return fricreg_sim_get_extrapolation(extrap_, (int)x, OUTD(0));
    }
}
static int e_st_create(int which, double x)
{
    fricreg_structure *s = (fricreg_structure *)FX_->handle_out;
    int status = fricreg_structure_create(which == 0 ? (size_t)x : 1, which == 1 ? (size_t)x : 1,
                                          &s);
    if (status == FRICREG_OK)
        fricreg_structure_free(s);
    else
        memcpy(&FX_->handle_out, &s, sizeof s);
    return status;
}
/* which 0, 1: Rayleigh a0, a1; 2: the law's eps; 3: mun; 4-7: Newmark beta (upper), gamma
 * (lower, upper), HHT alpha (lower, upper: 8); 9, 10: Newton's tol (upper), max_iter */
static int e_st_set(int which, double x)
{
    fricreg_structure *s = FX_->st;
    switch (which) {
    case 0: return fricreg_structure_set_rayleigh(s, x, 0.002);
    case 1: return fricreg_structure_set_rayleigh(s, 0.01, x);
    case 2: return fricreg_structure_set_law(s, FRICREG_LAW_QUINN, x);
    case 3: return fricreg_structure_set_bounds(s, 1, &x);
    case 4: return fricreg_structure_set_newmark(s, x, 0.5);
    case 5:
    case 6: return fricreg_structure_set_newmark(s, 0.25, x);
    case 7:
    case 8: return fricreg_structure_set_hht(s, x);
    case 9: return fricreg_structure_set_newton(s, x, 50);
    default: return fricreg_structure_set_newton(s, 1e-10, (int)x);
    }
}
/* which 0: run with dt = 1e-9 to x (2^31 steps); 1: run_ode's integrator (adaptive); 2:
 * rk4imp on K (x = 0) or on a K that is not semidefinite (x = 1); 3, 4: get_value, get_stat */
static int e_st_run(int which, double x)
{
    fricreg_structure *s = FX_->st;
    const double K_unstable[4] = {-2.4, 0.0, 0.0, 1.1};
    switch (which) {
    case 0: return fricreg_structure_run(s, 1e-9, x);
    case 1: return fricreg_structure_run_ode(s, (int)x, 0.001, 1e-6, 1e-9, 0.05);
    case 2:
        if (x != 0.0 && fricreg_structure_set_stiffness(s, 2, K_unstable) != FRICREG_OK)
            return -1;
        return fricreg_structure_run_ode(s, FRICREG_INT_RK4IMP, 0.001, 0.0, 0.0, 0.05);
    case 3: return fricreg_structure_get_value(s, (int)x, OUTD(0));
    default: return fricreg_structure_get_stat(s, (int)x, (int64_t *)OUTD(0));
    }
}

#define TINY 4.9e-324
/* The first t_end beyond 10^6 cycles of omega = 0.8, as fricreg_exact_run computes cycles,
 * and the last one within. */
static double exact_cycles_edge(int beyond)
{
    double t = 1e6 * 6.283185307179586 / 0.8;
    while (t * 0.8 / 6.283185307179586 > 1e6)
        t = below(t);
    while (!(above(t) * 0.8 / 6.283185307179586 > 1e6))
        t = above(t);
    return beyond ? above(t) : t;
}

static void edge_objects(void)
{
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &chain_), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_create(0.0, 0.8, 1.0, 0.5, 0.0, &stuck_), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &extrap_), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(extrap_, 1.0, 2, 0), FRICREG_OK);
}

static void edge_objects_free(void)
{
    fricreg_sim_free(chain_), fricreg_sim_free(extrap_);
    fricreg_exact_free(stuck_);
    chain_ = extrap_ = NULL;
    stuck_ = NULL;
}

/* One side of an edge; returns 1 if it disagrees with the docstring (printed). */
static int run_edge(const struct edge *e, double x, char expect)
{
    struct fixture fx;
    fixture_make(&fx);
    edge_objects();
    static const struct perturb none = {K_PTR, -1, 0};
    P_ = &none;
    FX_ = &fx;
    int status = e->call(e->which, x), want = code_of(expect);
    char why[200] = "";
    if (status != want)
        snprintf(why, sizeof why, "status %d (%s), docstring says %d (%s)", status,
                 fricreg_strerror(status), want, fricreg_strerror(want));
    else if (status != FRICREG_OK &&
             !(untouched(fx.out, sizeof fx.out) && untouched(&fx.handle_out, sizeof(void *))))
        snprintf(why, sizeof why, "failed (%d) but wrote an output", status);
    else if (status != FRICREG_OK && e->owner != NONE &&
             (recorded(e->owner, &fx) != status || message(e->owner, &fx)[0] == '\0'))
        snprintf(why, sizeof why, "failed (%d) but recorded %d, message '%s'", status,
                 recorded(e->owner, &fx), message(e->owner, &fx));
    fixture_free(&fx);
    edge_objects_free();
    if (getenv("BAD_INPUT_VERBOSE") != NULL)
        printf("edge %s at %.17g: %s\n", e->name, x, fricreg_strerror(status));
    if (why[0] != '\0')
        printf("DISAGREES: edge %s at %.17g: %s\n", e->name, x, why);
    fflush(stdout);
    return why[0] != '\0';
}

START_TEST(edges_of_documented_ranges)
{
    const struct edge edges[] = {
        /* fricreg.h */
        {"law_eval eps >= DBL_MIN", e_law_eval, 0, DBL_MIN, 0, 'i', NONE},
        {"law_eval mun >= 0", e_law_eval, 1, 0.0, -TINY, 'i', NONE},
        {"law_eval law <= quinn", e_law_eval, 2, FRICREG_LAW_QUINN, FRICREG_LAW_QUINN + 1, 'i',
         NONE},
        {"law_eval law >= coulomb", e_law_eval, 2, FRICREG_LAW_COULOMB, 0, 'i', NONE},
        {"law_eval_batch eps >= DBL_MIN", e_law_eval_batch, 0, DBL_MIN, 0, 'i', NONE},
        {"law_eval_batch law <= quinn", e_law_eval_batch, 1, FRICREG_LAW_QUINN,
         FRICREG_LAW_QUINN + 1, 'i', NONE},
        {"law_eval_batch mun >= 0", e_law_eval_batch, 2, 0.0, -TINY, 'i', NONE},
        {"ctx_create m <= 2^26", e_ctx_create, 0, NAN, 67108865.0, 'i', NONE},
        {"ctx_create m >= 1", e_ctx_create, 0, 1.0, 0.0, 'i', NONE},
        {"ctx_set_law eps >= DBL_MIN", e_ctx_set_law, 0, DBL_MIN, 0, 'i', CTX_REC},
        {"ctx_set_law law <= quinn", e_ctx_set_law, 1, FRICREG_LAW_QUINN, FRICREG_LAW_QUINN + 1,
         'i', CTX_REC},
        {"ctx_set_bounds mun >= 0", e_ctx_set_bounds, 0, 0.0, -TINY, 'i', CTX_REC},
        {"ctx_set_coupling_dense W_ii >= DBL_MIN", e_ctx_set_dense, 0, DBL_MIN, 0, 'p', CTX_REC},
        {"ctx_set_coupling_dense symmetric to 1e-12", e_ctx_set_dense, 1, 0.5e-12, 2e-12, 'y',
         CTX_REC},
        {"ctx_set_coupling_dense eigenvalue >= -1e-12 m", e_ctx_set_dense, 2, 1e-12, 4e-12, 'p',
         CTX_REC},
        {"ctx_set_coupling_csr W_ii >= DBL_MIN", e_ctx_set_csr, 0, DBL_MIN, 0, 'p', CTX_REC},
        {"ctx_set_coupling_csr symmetric to 1e-12", e_ctx_set_csr, 1, 0.5e-12, 2e-12, 'y', CTX_REC},
        {"ctx_set_coupling_csr eigenvalue >= -1e-12 r (r = 2)", e_ctx_set_csr, 2, 1e-12, 4e-12, 'p',
         CTX_REC},
        {"ctx_set_partition <= paper", e_ctx_int, 0, FRICREG_PARTITION_PAPER,
         FRICREG_PARTITION_PAPER + 1, 'i', CTX_REC},
        {"ctx_set_partition >= consistent", e_ctx_int, 0, FRICREG_PARTITION_CONSISTENT, 0, 'i',
         CTX_REC},
        {"ctx_set_keep_tangent <= 1", e_ctx_int, 1, 1, 2, 'i', CTX_REC},
        {"ctx_set_keep_tangent >= 0", e_ctx_int, 1, 0, -1, 'i', CTX_REC},
        {"ctx_get_stat <= factor updates", e_ctx_int, 2, FRICREG_STAT_FACTOR_UPDATES,
         FRICREG_STAT_FACTOR_UPDATES + 1, 'i', NONE},
        {"ctx_eval f_eq within 1e280", e_ctx_eval, 0, 0.5e280, 2e280, 'n', CTX_REC},
        {"ctx_eval f_eq within -1e280", e_ctx_eval, 0, -0.5e280, -2e280, 'n', CTX_REC},
        {"ctx_set_stribeck fk <= fs", e_ctx_set_stribeck, 0, 0.5, above(0.5), 'i', CTX_REC},
        {"ctx_set_stribeck fk >= 0", e_ctx_set_stribeck, 0, 0.0, -TINY, 'i', CTX_REC},
        /* fricreg_disk.h */
        {"disk_eval eps >= DBL_MIN", e_disk_eval, 0, DBL_MIN, below(DBL_MIN), 'i', NONE},
        {"disk_eval law <= quinn-nested", e_disk_eval, 1, FRICREG_DISK_QUINN_NESTED,
         FRICREG_DISK_QUINN_NESTED + 1, 'i', NONE},
        {"disk_eval law >= coulomb", e_disk_eval, 1, FRICREG_DISK_COULOMB, 0, 'i', NONE},
        {"disk_eval v <= 1e250", e_disk_eval, 2, 1e250, above(1e250), 'i', NONE},
        {"disk_eval v >= -1e250", e_disk_eval, 2, -1e250, below(-1e250), 'i', NONE},
        {"disk_eval f_eq <= 1e250", e_disk_eval, 3, 1e250, above(1e250), 'i', NONE},
        {"disk_eval mun <= 1e250", e_disk_eval, 4, 1e250, above(1e250), 'i', NONE},
        {"disk_eval mun >= 0", e_disk_eval, 4, 0.0, -TINY, 'i', NONE},
        {"disk_eval_batch eps >= DBL_MIN", e_disk_eval_batch, 0, DBL_MIN, below(DBL_MIN), 'i',
         NONE},
        {"disk_eval_batch law <= quinn-nested", e_disk_eval_batch, 1, FRICREG_DISK_QUINN_NESTED,
         FRICREG_DISK_QUINN_NESTED + 1, 'i', NONE},
        {"disk_eval_batch v <= 1e250", e_disk_eval_batch, 2, 1e250, above(1e250), 'i', NONE},
        {"disk_eval_batch f_eq >= -1e250", e_disk_eval_batch, 3, -1e250, below(-1e250), 'i', NONE},
        {"disk_eval_batch mun <= 1e250", e_disk_eval_batch, 4, 1e250, above(1e250), 'i', NONE},
        {"disk_eval_batch mun >= 0", e_disk_eval_batch, 4, 0.0, -TINY, 'i', NONE},
        /* fricreg_disk_ctx.h */
        {"disk_ctx_create m <= 2^24", e_dctx_create, 0, NAN, 16777217.0, 'i', NONE},
        {"disk_ctx_set_law quinn, not the lens", e_dctx_set_law, 0, FRICREG_DISK_QUINN,
         FRICREG_DISK_QUINN_LENS, 'i', DCTX_REC},
        {"disk_ctx_set_law force-balance, not coulomb", e_dctx_set_law, 0,
         FRICREG_DISK_FORCE_BALANCE, FRICREG_DISK_COULOMB, 'i', DCTX_REC},
        {"disk_ctx_set_law not the nested law", e_dctx_set_law, 0, FRICREG_DISK_QUINN,
         FRICREG_DISK_QUINN_NESTED, 'i', DCTX_REC},
        {"disk_ctx_set_law eps >= DBL_MIN", e_dctx_set_law, 1, DBL_MIN, below(DBL_MIN), 'i',
         DCTX_REC},
        {"disk_ctx_set_law eps <= 1e250", e_dctx_set_law, 1, 1e250, above(1e250), 'i', DCTX_REC},
        {"disk_ctx_set_bounds mun <= 1e250", e_dctx_set_bounds, 0, 1e250, above(1e250), 'i',
         DCTX_REC},
        {"disk_ctx_set_bounds mun >= 0", e_dctx_set_bounds, 0, 0.0, -TINY, 'i', DCTX_REC},
        {"disk_ctx_set_coupling_blocks eigenvalues within 1e12", e_dctx_coupling, 0, 2e-12, 0.5e-12,
         'p', DCTX_REC},
        {"disk_ctx_set_coupling_blocks eigenvalue >= DBL_MIN", e_dctx_coupling, 1, DBL_MIN,
         below(DBL_MIN), 'p', DCTX_REC},
        {"disk_ctx_set_coupling_blocks symmetric to 1e-12", e_dctx_coupling, 2, 0.5e-12, 2e-12, 'y',
         DCTX_REC},
        {"disk_ctx_set_coupling_dense eigenvalues within 1e12", e_dctx_coupling, 3, 2e-12, 0.5e-12,
         'p', DCTX_REC},
        {"disk_ctx_set_coupling_dense eigenvalue >= DBL_MIN", e_dctx_coupling, 4, DBL_MIN,
         below(DBL_MIN), 'p', DCTX_REC},
        {"disk_ctx_set_coupling_dense symmetric to 1e-12", e_dctx_coupling, 5, 0.5e-12, 2e-12, 'y',
         DCTX_REC},
        {"disk_ctx_set_coupling_csr eigenvalues within 1e12", e_dctx_sparse, 0, 2e-12, 0.5e-12, 'p',
         DCTX_REC},
        {"disk_ctx_set_coupling_csr eigenvalue >= DBL_MIN", e_dctx_sparse, 1, DBL_MIN,
         below(DBL_MIN), 'p', DCTX_REC},
        {"disk_ctx_set_coupling_csr symmetric to 1e-12", e_dctx_sparse, 2, 0.5e-12, 2e-12, 'y',
         DCTX_REC},
        {"disk_ctx_set_coupling_csc eigenvalues within 1e12", e_dctx_sparse, 3, 2e-12, 0.5e-12, 'p',
         DCTX_REC},
        {"disk_ctx_set_coupling_csc eigenvalue >= DBL_MIN", e_dctx_sparse, 4, DBL_MIN,
         below(DBL_MIN), 'p', DCTX_REC},
        {"disk_ctx_set_coupling_csc symmetric to 1e-12", e_dctx_sparse, 5, 0.5e-12, 2e-12, 'y',
         DCTX_REC},
        {"disk_ctx_set_coupling_csr values <= 1e250", e_dctx_sparse, 6, 1e250, above(1e250), 'i',
         DCTX_REC},
        {"disk_ctx_set_coupling_csr duplicates summed <= 1e250", e_dctx_sparse, 7, 1e250,
         above(1e250), 'i', DCTX_REC},
        {"disk_ctx_eval zdot <= 1e250", e_dctx_eval, 0, 1e250, above(1e250), 'i', DCTX_REC},
        {"disk_ctx_eval a_free >= -1e250", e_dctx_eval, 1, -1e250, below(-1e250), 'i', DCTX_REC},
        {"disk_ctx_set_stribeck fs <= 1e250", e_dctx_set_stribeck, 0, 1e250, above(1e250), 'i',
         DCTX_REC},
        {"disk_ctx_set_stribeck fk <= fs", e_dctx_set_stribeck, 1, 0.5, above(0.5), 'i', DCTX_REC},
        {"disk_ctx_set_stribeck fk >= 0", e_dctx_set_stribeck, 1, 0.0, -TINY, 'i', DCTX_REC},
        /* fricreg_stribeck.h */
        {"stribeck_eval fs >= fk", e_stribeck_eval, 0, 0.3, below(0.3), 'i', NONE},
        {"stribeck_eval fk >= 0", e_stribeck_eval, 1, 0.0, -TINY, 'i', NONE},
        {"stribeck_eval vs > 0", e_stribeck_eval, 2, TINY, 0.0, 'i', NONE},
        {"stribeck_eval delta > 0", e_stribeck_eval, 3, TINY, 0.0, 'i', NONE},
        {"stribeck_eval eps >= DBL_MIN", e_stribeck_eval, 4, DBL_MIN, below(DBL_MIN), 'i', NONE},
        {"stribeck_eval_batch fk <= fs", e_stribeck_eval_batch, 1, 0.5, above(0.5), 'i', NONE},
        {"stribeck_eval_batch vs > 0", e_stribeck_eval_batch, 2, TINY, 0.0, 'i', NONE},
        {"stribeck_eval_batch delta > 0", e_stribeck_eval_batch, 3, TINY, 0.0, 'i', NONE},
        {"stribeck_eval_batch eps >= DBL_MIN", e_stribeck_eval_batch, 4, DBL_MIN, below(DBL_MIN),
         'i', NONE},
        {"stribeck_disk_eval fs <= 1e250", e_stribeck_disk_eval, 0, 1e250, above(1e250), 'i', NONE},
        {"stribeck_disk_eval fk <= fs", e_stribeck_disk_eval, 1, 0.5, above(0.5), 'i', NONE},
        {"stribeck_disk_eval eps >= DBL_MIN", e_stribeck_disk_eval, 4, DBL_MIN, below(DBL_MIN), 'i',
         NONE},
        {"stribeck_disk_eval v <= 1e250", e_stribeck_disk_eval, 5, 1e250, above(1e250), 'i', NONE},
        {"stribeck_disk_eval f_eq >= -1e250", e_stribeck_disk_eval, 6, -1e250, below(-1e250), 'i',
         NONE},
        {"stribeck_disk_eval_batch fs <= 1e250", e_stribeck_disk_eval_batch, 0, 1e250, above(1e250),
         'i', NONE},
        {"stribeck_disk_eval_batch fk >= 0", e_stribeck_disk_eval_batch, 1, 0.0, -TINY, 'i', NONE},
        {"stribeck_disk_eval_batch v >= -1e250", e_stribeck_disk_eval_batch, 5, -1e250,
         below(-1e250), 'i', NONE},
        {"stribeck_disk_eval_batch f_eq <= 1e250", e_stribeck_disk_eval_batch, 6, 1e250,
         above(1e250), 'i', NONE},
        /* fricreg_aft.h */
        {"aft_create H >= 1", e_aft_create, 0, 1, 0, 'i', NONE},
        {"aft_create H <= max", e_aft_create, 0, FRICREG_AFT_MAX_HARMONICS,
         FRICREG_AFT_MAX_HARMONICS + 1, 'i', NONE},
        {"aft_create N >= 2H + 2 (H = 3)", e_aft_create, 1, 8, 4, 'i', NONE},
        {"aft_create N a power of two", e_aft_create, 1, 16, 24, 'i', NONE},
        {"aft_create N <= 2^24", e_aft_create, 1, NAN, 2.0 * FRICREG_AFT_MAX_SAMPLES, 'i', NONE},
        {"aft_jenkins_exact kt > 0", e_aft_eval, 0, TINY, 0.0, 'i', AFT_REC},
        {"aft_jenkins_exact mun >= 0", e_aft_eval, 1, 0.0, -TINY, 'i', AFT_REC},
        {"aft_iwan_sampled k > 0", e_aft_eval, 2, TINY, 0.0, 'i', AFT_REC},
        /* fricreg_exact.h */
        {"exact_create mun >= 0", e_exact_create, 0, 0.0, -TINY, 'i', NONE},
        {"exact_solve t_end within 10^6 cycles", e_exact_solve, 0, exact_cycles_edge(0),
         exact_cycles_edge(1), 'i', NONE},
        {"exact_run t_end within 10^6 cycles", e_exact_stuck, 0, exact_cycles_edge(0),
         exact_cycles_edge(1), 'i', EXSTUCK_REC},
        {"exact_run_cycles <= 10^6", e_exact_stuck, 1, 1e6, 1e6 + 1, 'i', EXSTUCK_REC},
        {"exact_run_cycles >= 1", e_exact_stuck, 1, 1, 0, 'i', EXSTUCK_REC},
        {"exact_get_value <= period", e_exact_get, 0, FRICREG_EXACT_VALUE_PERIOD,
         FRICREG_EXACT_VALUE_PERIOD + 1, 'i', NONE},
        {"exact_get_stat <= root iterations", e_exact_get, 1, FRICREG_EXACT_STAT_ROOT_ITERS,
         FRICREG_EXACT_STAT_ROOT_ITERS + 1, 'i', NONE},
        {"exact_state t <= t_end", e_exact_get, 2, 20.0, above(20.0), 'i', NONE},
        {"exact_state t >= 0", e_exact_get, 3, 0.0, -TINY, 'i', NONE},
        {"exact_stick_fraction t1 <= t_end", e_exact_get, 4, 20.0, above(20.0), 'i', NONE},
        {"exact_stick_fraction t0 < t1", e_exact_get, 5, below(10.0), 10.0, 'i', NONE},
        /* fricreg_sim.h */
        {"sim_set_param n >= 2", e_chain_n, 0, 2.0, 1.0, 'i', CHAIN_REC},
        {"sim_set_param n <= 10^7", e_chain_n, 0, 1e7, 1e7 + 1, 'i', CHAIN_REC},
        {"sim_set_param n an integer", e_chain_n, 0, 3.0, 2.5, 'i', CHAIN_REC},
        {"sim_set_param mun >= 0", e_sim_set, 0, 0.0, -TINY, 'i', SIM_REC},
        {"sim_set_law eps >= 0 (0: the paper's rule)", e_sim_set, 1, 0.0, -TINY, 'i', SIM_REC},
        {"sim_set_law law <= quinn", e_sim_set, 2, FRICREG_LAW_QUINN, FRICREG_LAW_QUINN + 1, 'i',
         SIM_REC},
        {"sim_set_partition <= paper", e_sim_set, 3, FRICREG_PARTITION_PAPER,
         FRICREG_PARTITION_PAPER + 1, 'i', SIM_REC},
        {"sim_set_integrator <= central-imex", e_sim_set, 4, FRICREG_INT_CENTRAL_IMEX,
         FRICREG_INT_CENTRAL_IMEX + 1, 'i', SIM_REC},
        {"sim_set_integrator central: fixed steps only", e_sim_set, 5, 0.0, 1e-6, 'i', SIM_REC},
        {"sim_set_integrator rtol >= 0", e_sim_set, 6, 0.0, -TINY, 'i', SIM_REC},
        {"sim_run at most 2^31 fixed steps", e_sim_run, 0, NAN, 0.01 * 2147483648.0 * 1.0000001,
         'i', SIM_REC},
        {"sim_run_cycles at most 10^9 cycles", e_sim_run, 1, NAN, 1000000001.0, 'i', SIM_REC},
        {"sim_run_extrapolated levels >= 2", e_sim_run, 2, 2, 1, 'i', SIM_REC},
        {"sim_run_extrapolated levels <= 8", e_sim_run, 3, 8, 9, 'i', SIM_REC},
        {"sim_run_extrapolated order >= 0", e_sim_run, 4, 0, -1, 'i', SIM_REC},
        {"sim_run_extrapolated order <= 4", e_sim_run, 5, 4, 5, 'i', SIM_REC},
        {"sim_run_extrapolated_window window >= 0", e_sim_run, 6, 0, -1, 'i', SIM_REC},
        {"sim_get_value <= dissipation", e_sim_get, 0, FRICREG_VALUE_DISSIPATION,
         FRICREG_VALUE_DISSIPATION + 1, 'i', NONE},
        {"sim_get_stat <= kinks", e_sim_get, 1, FRICREG_SIM_STAT_KINKS, FRICREG_SIM_STAT_KINKS + 1,
         'i', NONE},
        {"sim_set_kink_location on <= 1", e_sim_set, 7, 1, 2, 'i', SIM_REC},
        {"sim_set_error_estimate on <= 2", e_sim_set, 10, 2, 3, 'i', SIM_REC},
        {"sim_set_error_estimate on >= 0", e_sim_set, 10, 0, -1, 'i', SIM_REC},
        {"sim_set_integrator atol = FRICREG_ATOL_FROM_EPS, not below", e_sim_set, 8,
         FRICREG_ATOL_FROM_EPS, -1.0000000000000002, 'i', SIM_REC},
        {"sim_set_integrator atol = FRICREG_ATOL_FROM_EPS, not above", e_sim_set, 8,
         FRICREG_ATOL_FROM_EPS, -0.99999999999999989, 'i', SIM_REC},
        {"sim_set_abs_tolerances atol > 0", e_sim_set, 9, TINY, 0.0, 'i', SIM_REC},
        {"sim_set_kink_location on >= 0", e_sim_set, 7, 0, -1, 'i', SIM_REC},
        {"sim_get_extrapolation <= rhs evals", e_sim_get, 2, FRICREG_EXTRAP_RHS_EVALS,
         FRICREG_EXTRAP_RHS_EVALS + 1, 'i', NONE},
        {"sim_get_extrapolation >= levels", e_sim_get, 3, FRICREG_EXTRAP_LEVELS, -1, 'i', NONE},
        /* fricreg_structure.h */
        {"structure_create ndof <= 2^40", e_st_create, 0, NAN, 1099511627777.0, 'i', NONE},
        {"structure_create m <= 2^26", e_st_create, 1, NAN, 67108865.0, 'i', NONE},
        {"structure_set_rayleigh a0 >= 0", e_st_set, 0, 0.0, -TINY, 'i', ST_REC},
        {"structure_set_rayleigh a1 >= 0", e_st_set, 1, 0.0, -TINY, 'i', ST_REC},
        {"structure_set_law eps >= DBL_MIN", e_st_set, 2, DBL_MIN, below(DBL_MIN), 'i', ST_REC},
        {"structure_set_bounds mun >= 0", e_st_set, 3, 0.0, -TINY, 'i', ST_REC},
        {"structure_set_newmark beta <= 1/2", e_st_set, 4, 0.5, above(0.5), 'i', ST_REC},
        {"structure_set_newmark beta > 0", e_st_set, 4, TINY, 0.0, 'i', ST_REC},
        {"structure_set_newmark gamma >= 1/2", e_st_set, 5, 0.5, below(0.5), 'i', ST_REC},
        {"structure_set_newmark gamma <= 1", e_st_set, 6, 1.0, above(1.0), 'i', ST_REC},
        {"structure_set_hht alpha >= -1/3", e_st_set, 7, -1.0 / 3.0, below(-1.0 / 3.0), 'i',
         ST_REC},
        {"structure_set_hht alpha <= 0", e_st_set, 8, 0.0, TINY, 'i', ST_REC},
        {"structure_set_newton tol < 1", e_st_set, 9, below(1.0), 1.0, 'i', ST_REC},
        {"structure_set_newton tol > 0", e_st_set, 9, TINY, 0.0, 'i', ST_REC},
        {"structure_set_newton max_iter <= 1000", e_st_set, 10, 1000, 1001, 'i', ST_REC},
        {"structure_set_newton max_iter >= 1", e_st_set, 10, 1, 0, 'i', ST_REC},
        {"structure_run at most 2^31 steps", e_st_run, 0, NAN, 1e-9 * 2147483648.0 * 1.0000001, 'i',
         ST_REC},
        {"structure_run_ode integrator <= rk4-gsl", e_st_run, 1, FRICREG_INT_RK4_GSL,
         FRICREG_INT_CENTRAL, 'i', ST_REC},
        {"structure_run_ode not central-imex", e_st_run, 1, FRICREG_INT_RK4_GSL,
         FRICREG_INT_CENTRAL_IMEX, 'i', ST_REC},
        {"structure_run_ode integrator known", e_st_run, 1, FRICREG_INT_RK4_GSL,
         FRICREG_INT_CENTRAL_IMEX + 1, 'i', ST_REC},
        {"structure_run_ode rk4imp: K semidefinite", e_st_run, 2, 0.0, 1.0, 'i', ST_REC},
        {"structure_get_value <= screen's dissipation error", e_st_run, 3,
         FRICREG_SVALUE_SCREEN_DISS_ERR, FRICREG_SVALUE_SCREEN_DISS_ERR + 1, 'i', NONE},
        {"structure_get_stat <= line-search cuts", e_st_run, 4, FRICREG_SSTAT_LINE_SEARCH_CUTS,
         FRICREG_SSTAT_LINE_SEARCH_CUTS + 1, 'i', NONE},
    };
    int cases = 0, disagreements = 0;
    for (size_t k = 0; k < sizeof edges / sizeof edges[0]; k++) {
        const struct edge e = edges[k];
        if (!isnan(e.inside)) {
            disagreements += run_edge(&e, e.inside, 'o');
            cases++;
        }
        disagreements += run_edge(&e, e.outside, e.refused);
        cases++;
    }
    printf("documented edges: %d cases over %zu bounds, %d disagreements\n", cases,
           sizeof edges / sizeof edges[0], disagreements);
    ck_assert_int_eq(disagreements, 0);
}
END_TEST

/* The functions that return no status: their NULL and out-of-range arguments. */
START_TEST(non_status_functions)
{
    char buf[8];
    ck_assert_int_eq(fricreg_version_number(), FRICREG_VERSION_NUMBER);
    ck_assert_ptr_nonnull(fricreg_version());
    ck_assert_str_eq(fricreg_strerror(-1), "unknown fricreg status code");
    ck_assert_str_eq(fricreg_strerror(INT_MAX), "unknown fricreg status code");
    ck_assert_str_eq(fricreg_strerror(INT_MIN), "unknown fricreg status code");
    for (int bad = 0; bad < 4; bad++) {
        ck_assert_ptr_null(fricreg_law_name(int_class[bad]));
        ck_assert_ptr_null(fricreg_integrator_name(int_class[bad]));
    }
    for (int bad = 0; bad < 4; bad++)
        ck_assert_ptr_null(fricreg_disk_law_name(int_class[bad]));
    ck_assert_ptr_null(fricreg_law_name(FRICREG_LAW_QUINN + 1)); /* one past the last */
    ck_assert_ptr_null(fricreg_disk_law_name(FRICREG_DISK_QUINN_NESTED + 1));
    ck_assert_ptr_null(fricreg_integrator_name(FRICREG_INT_CENTRAL_IMEX + 1));
    ck_assert_ptr_nonnull(fricreg_law_name(FRICREG_LAW_QUINN));
    ck_assert_ptr_nonnull(fricreg_disk_law_name(FRICREG_DISK_QUINN_NESTED));
    ck_assert_ptr_nonnull(fricreg_integrator_name(FRICREG_INT_CENTRAL_IMEX));
    ck_assert_int_eq(fricreg_disk_law_from_name(NULL), 0);
    ck_assert_int_eq(fricreg_disk_law_from_name(""), 0);
    ck_assert_int_eq(fricreg_disk_law_from_name("QUINN"), 0);
    ck_assert_int_eq(fricreg_law_from_name(NULL), 0);
    ck_assert_int_eq(fricreg_law_from_name(""), 0);
    ck_assert_int_eq(fricreg_law_from_name("QUINN"), 0);
    ck_assert_int_eq(fricreg_integrator_from_name(NULL), 0);
    ck_assert_int_eq(fricreg_integrator_from_name("rk4 "), 0);

    ck_assert_uint_eq(fricreg_ctx_size(NULL), 0);
    ck_assert_uint_eq(fricreg_ctx_switching_count(NULL), 0);
    ck_assert_int_eq(fricreg_ctx_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_ctx_errmsg(NULL), "NULL context");
    fricreg_ctx_free(NULL);
    fricreg_ctx_reset_stats(NULL);
    ck_assert_uint_eq(fricreg_disk_ctx_size(NULL), 0);
    ck_assert_int_eq(fricreg_disk_ctx_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_disk_ctx_errmsg(NULL), "NULL context");
    fricreg_disk_ctx_free(NULL);
    ck_assert_int_eq(fricreg_exact_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_exact_errmsg(NULL), "NULL exact solution");
    ck_assert_uint_eq(fricreg_exact_nswitches(NULL), 0);
    ck_assert_uint_eq(fricreg_exact_ncycles(NULL), 0);
    fricreg_exact_free(NULL);
    ck_assert_int_eq(fricreg_sim_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_sim_errmsg(NULL), "NULL simulation");
    ck_assert_uint_eq(fricreg_sim_ndof(NULL), 0);
    ck_assert_uint_eq(fricreg_sim_ncontacts(NULL), 0);
    fricreg_sim_free(NULL);
    ck_assert_int_eq(fricreg_structure_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_structure_errmsg(NULL), "NULL structure");
    fricreg_structure_free(NULL);
    ck_assert_uint_eq(fricreg_structure_warning_count(NULL), 0);
    ck_assert_str_eq(fricreg_structure_warning_message(NULL, 0), "");
    ck_assert_uint_eq(fricreg_sim_warning_count(NULL), 0);
    ck_assert_str_eq(fricreg_sim_warning_message(NULL, 0), "");
    ck_assert_str_eq(fricreg_warning_name(-1), "unknown");
    ck_assert_str_eq(fricreg_warning_name(FRICREG_WARN_NOT_ASYMPTOTIC + 1), "unknown");
    ck_assert_str_eq(fricreg_warning_name(FRICREG_WARN_EPS_LARGE), "eps_large");

    /* errmsg_copy: buf NULL or len 0 gives 0 and writes nothing; a short buffer is truncated
     * and NUL-terminated; the full length is returned ("NULL context" is 12 characters). */
    size_t (*const copy[5])(const void *, char *, size_t) = {
        (size_t(*)(const void *, char *, size_t))fricreg_ctx_errmsg_copy,
        (size_t(*)(const void *, char *, size_t))fricreg_exact_errmsg_copy,
        (size_t(*)(const void *, char *, size_t))fricreg_sim_errmsg_copy,
        (size_t(*)(const void *, char *, size_t))fricreg_structure_errmsg_copy,
        (size_t(*)(const void *, char *, size_t))fricreg_disk_ctx_errmsg_copy};
    const size_t full[5] = {strlen("NULL context"), strlen("NULL exact solution"),
                            strlen("NULL simulation"), strlen("NULL structure"),
                            strlen("NULL context")};
    for (int k = 0; k < 5; k++) {
        memset(buf, SENTINEL_BYTE, sizeof buf);
        ck_assert_uint_eq(copy[k](NULL, NULL, sizeof buf), 0);
        ck_assert_uint_eq(copy[k](NULL, buf, 0), 0);
        ck_assert(untouched(buf, sizeof buf));
        ck_assert_uint_eq(copy[k](NULL, buf, 5), full[k]);
        ck_assert_uint_eq(strlen(buf), 4);
        ck_assert(untouched(buf + 5, sizeof buf - 5));
    }
}
END_TEST

/* W = [[2.385, -1e-12], [-1e-12, 1e-270]] is indefinite (det < 0) but its smallest eigenvalue
 * relative to max|W| is -4e-25, within any tolerance on that scale; on the Jacobi-scaled
 * matrix its off-diagonal is 1e-12/sqrt(2.385e-270) = 6.5e122 > 1. Once accepted (a finding
 * of fuzz_ctx), and eval then returned forces that are not the law. */
START_TEST(indefinite_w_with_tiny_diagonal)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    const double W[4] = {2.385, -1e-12, -1e-12, 1e-270};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_ENOTPSD);
    const double W_psd[4] = {2.385, -1e-136, -1e-136, 1e-270}; /* det = 2.385e-270 - 1e-272 */
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W_psd), FRICREG_OK);
    fricreg_ctx_free(ctx);
}
END_TEST

/* a_free = -7.3e289 against W ~ 6e-255: f_eq,0 ~ 1.2e544 overflows; the QP's solve produced a
 * NaN that was clamped to a bound and returned as success (fuzz_ctx). Refused now. */
START_TEST(dense_feq_overflow_is_refused)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    const double W[4] = {6.1e-255, 6.1e-255, 6.1e-255, 1.22e-254};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_OK);
    const double zdot[2] = {0.0, 0.0}, a[2] = {-7.3e289, 0.0};
    double f[2] = {-777.0, -777.0};
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, NULL), FRICREG_ENONFINITE);
    ck_assert_double_eq(f[0], -777.0);
    ck_assert_double_eq(f[1], -777.0);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "contact 0"));
    /* within range, the same W is solved: f_eq,0 = 7.3e-255/6.1e-255 saturates at +1 */
    const double a_ok[2] = {-7.3e-255, 0.0};
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a_ok, f, NULL), FRICREG_OK);
    ck_assert_double_eq(f[0], 1.0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* The stick stiffness with slopes mun/eps that overflow: mun = 1e10, eps = 1e-300 gives
 * s = 1e310 = Inf, and D^1/2 W D^1/2 with W_01 = 0 had Inf and NaN (Inf * 0) entries, on which
 * GSL's eigensolver never returned (fuzz_ctx; the call hung). Now the matrix is scaled first:
 * lambda = 2 (W_11 s_1, the largest) * 1e10 / 1e-300 rounds to +Inf, an honest "too stiff",
 * and with a finite slope the scaling is exact: W = [[1, -1], [-1, 2]], mun = (0.5, 0.25),
 * eps = 0.02, law (3): D = diag(25, 12.5), eigenvalues 25 +- sqrt(312.5) = 25 +- 17.67767. */
START_TEST(stick_stiffness_with_overflowing_slopes)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    const double W[4] = {1.0, 0.0, 0.0, 2.0}, mun[2] = {1e10, 1e10};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_VELOCITY_LIMITED, 1e-300), FRICREG_OK);
    double lambda = 0.0;
    ck_assert_int_eq(fricreg_ctx_stick_stiffness(ctx, &lambda), FRICREG_OK);
    ck_assert(isinf(lambda) && lambda > 0.0);

    const double W2[4] = {1.0, -1.0, -1.0, 2.0}, mun2[2] = {0.5, 0.25};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W2), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, mun2), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_VELOCITY_LIMITED, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_stick_stiffness(ctx, &lambda), FRICREG_OK);
    ck_assert_double_eq_tol(lambda, 25.0 + sqrt(312.5), 1e-12);
    fricreg_ctx_free(ctx);
}
END_TEST

/* The tangent with the smallest W set_coupling_dense takes: W = w [[1, 1], [1, 1]] (PSD,
 * rank 1), the paper's partition, contact 0 at rest with f_eq,0 = -(a_0 + W_01 f_1)/W_00
 * far beyond mun, saturated at f_0 = -1, contact 1 sliding (f_1 = +1). d f_0/d a_free is 0
 * there (saturated). With w = 3.46e-323 (subnormal) W_00^-1 was beyond DBL_MAX and Inf * 0
 * gave NaN (fuzz_ctx); such a W is refused now (ENOTPSD), and at w = DBL_MIN the inverse,
 * 4.5e307, is finite: no NaN. */
START_TEST(tangent_with_tiny_w)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    const double sub = 3.4584595208887258e-323, W_sub[4] = {sub, sub, sub, sub};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W_sub), FRICREG_ENOTPSD);
    const double w = DBL_MIN, W[4] = {w, w, w, w};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
    const double zdot[2] = {0.0, -6705.9326171875}, a[2] = {1e-290, -6.7e-4};
    double f[2], dz[4], da[4];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, NULL), FRICREG_OK);
    ck_assert_double_eq(f[0], -1.0);
    ck_assert_double_eq(f[1], 1.0);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_OK);
    for (int k = 0; k < 4; k++) {
        ck_assert_msg(!isnan(dz[k]) && !isnan(da[k]), "entry %d: %g %g", k, dz[k], da[k]);
        ck_assert_double_eq(da[k], 0.0); /* saturated and sliding: a_free moves nothing */
    }
    fricreg_ctx_free(ctx);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("bad_input");
    TCase *tc = tcase_create("bad_input");
    tcase_add_test(tc, matrix);
    tcase_add_test(tc, edges_of_documented_ranges);
    tcase_add_test(tc, non_status_functions);
    tcase_add_test(tc, indefinite_w_with_tiny_diagonal);
    tcase_add_test(tc, dense_feq_overflow_is_refused);
    tcase_add_test(tc, stick_stiffness_with_overflowing_slopes);
    tcase_add_test(tc, tangent_with_tiny_w);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
