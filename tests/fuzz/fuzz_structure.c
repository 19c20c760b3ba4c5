/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_structure.c — fuzz target: a linear structure's whole life (include/fricreg_structure.h,
 * and the sparse setters of include/fricreg_structure_gsl.h). The input is a program of calls on
 * one structure of ndof <= 4 degrees of freedom and m <= 4 contacts: M (diagonal, a chain, B B^T
 * of any rank, any symmetric, non-symmetric, scaled), K and C the same (so often indefinite) or
 * Rayleigh damping, J (dense or sparse, zero rows now and then), bounds, law and eps, the
 * influence vector, ground and load records, the initial state, the scheme (Newmark, HHT,
 * central difference), Newton's rule, then step, run and run_ode with any integrator, fixed or
 * adaptive, and the getters; each call now and then with a wrong size or a NULL. The harness
 * sets J (contact i on DOF i mod ndof) first unless the input's first byte says not to.
 *
 * Every call is held to its docstring: status in the documented set, recorded with a message
 * and kept until the next failure (the getters, on a const structure, return theirs
 * unrecorded); a failed call leaves the state (t, u, v, a, f, the dissipation, every energy
 * and counter) unchanged, bit for bit (run and run_ode: when they took no step; a run_ode that
 * failed after some leaves a and f of the equation of motion at the state it reached, and
 * that state within 1e100); a successful setter changes none of it either (the model takes
 * effect at the next step) but set_initial, which restarts at t = 0 from (u0, v0), a, f, D,
 * the counters and the sums zero. After a successful step, run or run_ode: the time as asked
 * (t + dt; t_end exactly); u, v, a, f finite, the state within the 1e100 of EDIVERGED,
 * |f_i| <= mun_i (to 4 ulps); the energies finite (inputs within 1e50: they are quadratic); the
 * dissipation's sum is FRICTION (to the rounding of the largest seen); and, where the header
 * makes them exact, the step's own equations:
 *  - Newmark (and HHT) update u1 = u + dt v + dt^2 ((1/2 - beta) a + beta a1),
 *    v1 = v + dt ((1 - gamma) a + gamma a1); central difference u1 = u + dt v + dt^2 a/2,
 *    v1 = v + dt (a + a1)/2; to rounding, for one step from a known start (Newmark's dt
 *    within the 1e-9 of the factored dt that the header allows);
 *  - the equation of motion M a1 + C v1 + K u1 = p~(t1) + J^T f1 at the step's end: to
 *    Newton's tolerance times the step's force scale (as fricreg_structure_set_newton defines
 *    it) for Newmark (alpha = 0; HHT weighs it with the start) when Newton converged; to
 *    rounding for central difference (with v* = v + dt a in the damping) and after run_ode
 *    (the equilibrium it ends with);
 *  - the energy balance (below).
 *
 * The energy balance's residual, where the header says it closes: average-acceleration Newmark
 * (beta = 1/4, gamma = 1/2, alpha = 0) makes it vanish to Newton's tolerance. Per step it is
 * du.(R0 + R1)/2 with R the equation's residual at the step's ends, |R| <= tol Fs (Fs the
 * force scale), so over N steps it is at most N n tol 2 F U (F, U the largest forces and
 * displacements seen), plus the rounding of the sums, 64 n eps per step of the energies'
 * scale. Checked only while every step since set_initial was such a Newmark step with a smooth
 * law and converged; excluded, and why:
 *  - HHT (alpha < 0) and Newmark with gamma > 1/2 or beta != 1/4: their numerical damping is
 *    in the residual (the header says so), of no promised size;
 *  - central difference: its du = dt v + dt^2 a/2 is not dt (v + v1)/2, the balance's rule;
 *  - run_ode: the balance is integrated by the stepper, its residual is the scheme's
 *    truncation error, which depends on dt and the law's smoothness;
 *  - laws (1), (2) and Karnopp: they jump, a step may have no root (the header), and Newton's
 *    last iterate's residual is up to the jump 2 mun;
 *  - a step whose Newton failed (FRICREG_SSTAT_NEWTON_FAILURES counts it; it returns OK);
 *  - M or K changed after the first step: v.M v/2 and u.K u/2 change without any work;
 *  - an input beyond 1e50 in magnitude (known: a J entry of 1e100 gives OK with a large
 *    residual; a ground record of 1e308 gives OK with zero motion) — the same inputs are
 *    excluded from the equation-of-motion checks;
 *  - Newton's tol above 1e-8, where the bound above says nothing.
 *
 * Work is bounded by the harness: a run of at most 2000 steps by its own count, 6000 steps per
 * input in all (a Newmark step counted max_iter/50 steps when max_iter > 50); run_ode with fixed steps at most 500 (explicit) or 50 (implicit, whose failed
 * iterations are retried in halves, up to 2^10 pieces); adaptive run_ode only for a
 * continuous law, tolerances of at least 1e-6 (the larger) and 1e-10 (the smaller if not 0),
 * and a span of at most 100 / Lambda, Lambda a bound of the stiffest rate: omega_max + c_max
 * + the stick zone's max_i W_ii 2 mun_i/eps, from ||K||_F, ||C||_F and |J_i|^2 over M's
 * smallest eigenvalue; and the library bounds an adaptive run at 2000 accepted steps
 * (fricreg_structure_set_max_steps: FRICREG_EWORK after exactly that many). Adaptive runs with
 * laws (1), (2) and Karnopp chatter, so the harness makes none. The caps keep each input well
 * under a second.
 *
 * GSL's default error handler stays installed: the library promises never to reach it, and an
 * abort from GSL is a finding. */

#include <float.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_spmatrix.h>

#include "fuzz_input.h"

#include "fricreg_structure.h"
#include "fricreg_structure_gsl.h"

enum { MAX_N = 4, MAX_M = 4, MAX_REC = 8, NVALUES = 8, NSTATS = 5 };
#define STEP_CAP 2000.0       /* steps of one run or step sequence, the harness's count */
#define INPUT_STEP_CAP 6000.0 /* steps of one input, all calls */
#define FIXED_ODE_CAP 500.0   /* fixed GSL steps of one run_ode, explicit steppers */
#define IMPLICIT_ODE_CAP 50.0 /* the same, implicit and multistep steppers */
#define ADAPTIVE_CAP 100.0    /* span times the rate bound of one adaptive run_ode */
#define ENERGY_INPUT_MAX 1e50 /* beyond: no energy or equation-of-motion check (known issues) */
#define ENERGY_NEWTON_TOL 1e-8
#define STATE_LIMIT 1e100

#define CODE(c) (1u << (c))
#define SETTER_CODES (CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_ENONFINITE))
#define STEP_CODES                                                             \
    (CODE(FRICREG_ENULL) | CODE(FRICREG_EINVAL) | CODE(FRICREG_ENONFINITE) |   \
     CODE(FRICREG_ENOTSYM) | CODE(FRICREG_ENOTPSD) | CODE(FRICREG_ESINGULAR) | \
     CODE(FRICREG_ESTEP) | CODE(FRICREG_EDIVERGED))
#define ODE_CODES                                                                                  \
    (CODE(FRICREG_ENULL) | CODE(FRICREG_EINVAL) | CODE(FRICREG_ENONFINITE) | CODE(FRICREG_ESTEP) | \
     CODE(FRICREG_ESINGULAR) | CODE(FRICREG_EDIVERGED) | CODE(FRICREG_EINTEGRATOR) |               \
     CODE(FRICREG_ENOMEM) | CODE(FRICREG_EWORK))

enum { SCHEME_NEWMARK, SCHEME_CENTRAL };

struct record {
    double t0, dt;
    size_t n;
    double x[MAX_REC];
};

/* What the structure holds, as the calls that succeeded set it, and the harness's books. */
struct model {
    size_t n, m;
    double M[MAX_N * MAX_N], K[MAX_N * MAX_N], C[MAX_N * MAX_N];
    int rayleigh;
    double a0, a1;
    double J[MAX_M * MAX_N];
    int contacts_set;
    double mun[MAX_M];
    int law;
    double eps;
    double r[MAX_N], p[MAX_N];
    struct record ground, load;
    int scheme;
    double alpha, beta, gamma;
    double newton_tol;
    int newton_max;
    /* ready: a, f and p~ hold the equation of motion at t (the last call was a successful
     * step, run or run_ode, no setter that resets it since); ptil: p~ at t as the structure
     * holds it (the records read when that step ended) */
    int ready;
    double ptil[MAX_N];
    double work;                /* steps spent by this input */
    double big;                 /* the largest magnitude of an accepted input */
    int started;                /* a step since set_initial: the balance started */
    int balance_void;           /* something the balance does not close on happened since */
    double steps_since_fresh;   /* steps since set_initial (the balance's N) */
    double tol_max;             /* the largest Newton tol of those steps */
    double F_max, U_max, E_max; /* the largest force, displacement and energy seen */
    double h;                   /* the step of the stepping call being observed (0: none) */
};

/* What the getters show. */
struct snapshot {
    double u[MAX_N], v[MAX_N], a[MAX_N], f[MAX_M], D[MAX_M];
    double value[NVALUES];
    int64_t stat[NSTATS];
};

/* The last failure's status, which the structure keeps: a successful call does not clear it. */
static int last_error;

/* FUZZ_TRACE=1 in the environment: print each call's status (to read a finding). */
static void require_status(fricreg_structure *s, int status, unsigned allowed, const char *call)
{
    if (getenv("FUZZ_TRACE") != NULL)
        fprintf(stderr, "%s: %d %s\n", call, status,
                status == FRICREG_OK ? "" : fricreg_structure_errmsg(s));
    FUZZ_REQUIRE(status == FRICREG_OK || (status > 0 && status < 32 && (allowed >> status & 1u)),
                 "%s: status %d (%s) not documented (mask %#x): %s", call, status,
                 fricreg_strerror(status), allowed, fricreg_structure_errmsg(s));
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(fricreg_structure_errcode(s) == status, "%s: errcode %d, returned %d", call,
                     fricreg_structure_errcode(s), status);
        FUZZ_REQUIRE(fricreg_structure_errmsg(s)[0] != '\0', "%s: failure %d with no message", call,
                     status);
        last_error = status;
    }
    FUZZ_REQUIRE(fricreg_structure_errcode(s) == last_error,
                 "%s: status %d, errcode %d, the last failure %d", call, status,
                 fricreg_structure_errcode(s), last_error);
}

static void take(const fricreg_structure *s, const struct model *md, struct snapshot *sn)
{
    memset(sn, 0, sizeof *sn);
    FUZZ_REQUIRE(fricreg_structure_get_state(s, md->n, sn->u, sn->v, sn->a) == FRICREG_OK &&
                     fricreg_structure_get_forces(s, md->m, sn->f) == FRICREG_OK &&
                     fricreg_structure_get_dissipation(s, md->m, sn->D) == FRICREG_OK,
                 "getters failed");
    for (int k = 0; k < NVALUES; k++)
        FUZZ_REQUIRE(fricreg_structure_get_value(s, k, &sn->value[k]) == FRICREG_OK,
                     "get_value(%d)", k);
    for (int k = 0; k < NSTATS; k++)
        FUZZ_REQUIRE(fricreg_structure_get_stat(s, k, &sn->stat[k]) == FRICREG_OK, "get_stat(%d)",
                     k);
}

static double now(const struct snapshot *sn)
{
    return sn->value[FRICREG_SVALUE_TIME];
}

/* The state and its books unchanged, bit for bit; the kinetic and strain energies (and the
 * residual, which holds them) read the current M and K, so a successful set_mass or
 * set_stiffness changes them: with_energies 0 leaves them out. */
static void require_unchanged(const struct snapshot *before, const struct snapshot *after,
                              int with_energies, const char *call)
{
    FUZZ_REQUIRE(memcmp(before->u, after->u, sizeof before->u) == 0 &&
                     memcmp(before->v, after->v, sizeof before->v) == 0 &&
                     memcmp(before->a, after->a, sizeof before->a) == 0,
                 "%s changed the state u, v, a", call);
    FUZZ_REQUIRE(memcmp(before->f, after->f, sizeof before->f) == 0, "%s changed the forces", call);
    FUZZ_REQUIRE(memcmp(before->D, after->D, sizeof before->D) == 0, "%s changed the dissipation",
                 call);
    FUZZ_REQUIRE(memcmp(before->stat, after->stat, sizeof before->stat) == 0,
                 "%s changed the counters", call);
    for (int k = 0; k < NVALUES; k++) {
        int energy = k == FRICREG_SVALUE_KINETIC || k == FRICREG_SVALUE_STRAIN ||
                     k == FRICREG_SVALUE_RESIDUAL;
        if (with_energies || !energy)
            FUZZ_REQUIRE(memcmp(&before->value[k], &after->value[k], sizeof(double)) == 0,
                         "%s changed value %d: %.17g -> %.17g", call, k, before->value[k],
                         after->value[k]);
    }
}

/* ---- Inputs -------------------------------------------------------------------------------- */

/* A size: the structure's, or one off, or an absurd one. */
static size_t fuzz_size(struct fuzz_input *in, size_t n)
{
    switch (fuzz_byte(in) % 16) {
    case 0: return n + 1;
    case 1: return n - 1;
    case 2: return SIZE_MAX;
    case 3: return (size_t)1 << 33;
    default: return n;
    }
}

static double largest(const double x[], size_t len)
{
    double big = 0.0;
    for (size_t k = 0; k < len; k++)
        big = fmax(big, fabs(x[k])); /* NaN ignored: NaN inputs are refused */
    return big;
}

/* An n x n model matrix of one of several kinds, row-major: fuzz_matrix's four (any symmetric,
 * B B^T of any rank, the same scaled, any matrix), a diagonal, or a chain's tridiagonal
 * stiffness (springs k_i between DOFs i-1 and i, k_0 to the ground: positive definite when
 * every k_i > 0). */
static void model_matrix(struct fuzz_input *in, size_t n, double A[])
{
    double scratch[MAX_N * MAX_N];
    uint8_t kind = fuzz_byte(in) % 8;
    memset(A, 0, n * n * sizeof *A);
    if (kind < 4) {
        fuzz_matrix(in, n, A, scratch);
    } else if (kind < 6) {
        for (size_t i = 0; i < n; i++)
            A[i * n + i] = kind == 4 ? fuzz_double(in) : fabs(fuzz_double(in));
    } else {
        for (size_t i = 0; i < n; i++) {
            double k = kind == 6 ? fabs(fuzz_double(in)) : fuzz_double(in);
            A[i * n + i] += k;
            if (i > 0) {
                A[(i - 1) * n + i - 1] += k;
                A[i * n + i - 1] -= k;
                A[(i - 1) * n + i] -= k;
            }
        }
    }
}

/* A dense rows x cols matrix as one of GSL's sparse formats (COO, CSC, CSR); NULL if GSL is out
 * of memory (then nothing is tested). */
static gsl_spmatrix *sparse(const double A[], size_t rows, size_t cols, int format)
{
    gsl_spmatrix *coo = gsl_spmatrix_alloc_nzmax(rows, cols, rows * cols + 1, GSL_SPMATRIX_COO);
    if (coo == NULL)
        return NULL;
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

/* ---- The model's setters -------------------------------------------------------------------- */

static const int formats[3] = {GSL_SPMATRIX_COO, GSL_SPMATRIX_CSC, GSL_SPMATRIX_CSR};

/* Calls one setter, checks its status and the state's; returns the status. */
typedef int (*square_setter)(fricreg_structure *, size_t, const double[]);
typedef int (*sparse_setter)(fricreg_structure *, const gsl_spmatrix *);

static void after_setter(fricreg_structure *s, struct model *md, const struct snapshot *before,
                         int status, unsigned allowed, const char *call)
{
    require_status(s, status, allowed, call);
    struct snapshot after;
    take(s, md, &after);
    require_unchanged(before, &after, status != FRICREG_OK, call);
}

/* set_mass, set_stiffness, set_damping, dense or sparse. which: 0 M, 1 K, 2 C. */
static void op_square(struct fuzz_input *in, fricreg_structure *s, struct model *md, int which)
{
    static const square_setter dense[3] = {fricreg_structure_set_mass,
                                           fricreg_structure_set_stiffness,
                                           fricreg_structure_set_damping};
    static const sparse_setter sparse_set[3] = {fricreg_structure_set_mass_sparse,
                                                fricreg_structure_set_stiffness_sparse,
                                                fricreg_structure_set_damping_sparse};
    static const char *names[3] = {"set_mass", "set_stiffness", "set_damping"};
    size_t n = md->n, ndof = fuzz_size(in, n);
    double A[MAX_N * MAX_N], A0[MAX_N * MAX_N];
    model_matrix(in, n, A);
    memcpy(A0, A, sizeof A);
    uint8_t how = fuzz_byte(in);
    struct snapshot before;
    take(s, md, &before);
    int status;
    unsigned allowed = SETTER_CODES | CODE(FRICREG_ENOTSYM) |
                       (which == 0 ? CODE(FRICREG_ENOTPSD) : 0u);
    if (how % 8 == 7) { /* sparse, in one of GSL's three formats (ndof: its size) */
        size_t rows = ndof == n + 1 ? n + 1 : n;
        double big[(MAX_N + 1) * (MAX_N + 1)] = {0};
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++)
                big[i * rows + j] = A[i * n + j];
        gsl_spmatrix *S = sparse(big, rows, rows, formats[how / 8 % 3]);
        if (S == NULL)
            return;
        status = sparse_set[which](s, fuzz_byte(in) == 1 ? NULL : S);
        ndof = rows;
        gsl_spmatrix_free(S);
    } else {
        status = dense[which](s, ndof, how == 1 ? NULL : A);
        FUZZ_REQUIRE(memcmp(A, A0, sizeof A) == 0, "%s changed the caller's matrix", names[which]);
    }
    after_setter(s, md, &before, status, allowed, names[which]);
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(ndof == n && fuzz_all_finite(A, n * n), "%s took a bad call", names[which]);
    for (size_t i = 0; which == 0 && i < n; i++)
        FUZZ_REQUIRE(A[i * n + i] > 0.0, "set_mass took M_%zu%zu = %g", i, i, A[i * n + i]);
    double *dst = which == 0 ? md->M : which == 1 ? md->K : md->C;
    memcpy(dst, A, n * n * sizeof *A);
    if (which == 2)
        md->rayleigh = 0;
    md->big = fmax(md->big, largest(A, n * n));
    md->ready = 0;
    if (which < 2 && md->started)
        md->balance_void = 1; /* v.M v/2 or u.K u/2 jumps without work */
}

static void op_rayleigh(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    double a0 = fuzz_double(in), a1 = fuzz_double(in);
    struct snapshot before;
    take(s, md, &before);
    int status = fricreg_structure_set_rayleigh(s, a0, a1);
    after_setter(s, md, &before, status, CODE(FRICREG_ENONFINITE) | CODE(FRICREG_EINVAL),
                 "set_rayleigh");
    FUZZ_REQUIRE((status == FRICREG_OK) == (isfinite(a0) && isfinite(a1) && a0 >= 0.0 && a1 >= 0.0),
                 "set_rayleigh(%g, %g): status %d", a0, a1, status);
    if (status != FRICREG_OK)
        return;
    md->rayleigh = 1, md->a0 = a0, md->a1 = a1;
    md->big = fmax(md->big, fmax(a0, a1));
    md->ready = 0;
}

static void op_contacts(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    size_t n = md->n, m = md->m, mm = fuzz_size(in, m), nn = fuzz_size(in, n);
    double J[MAX_M * MAX_N], J0[MAX_M * MAX_N];
    uint8_t kind = fuzz_byte(in);
    for (size_t i = 0; i < m; i++)
        for (size_t k = 0; k < n; k++) {
            if (kind % 4 == 0) /* often one entry per row: contact i on one DOF, or a storey */
                J[i * n + k] = k == i % n ? 1.0 : (k + 1 == i % n && kind & 4 ? -1.0 : 0.0);
            else
                J[i * n + k] = fuzz_byte(in) < 96 ? 0.0 : fuzz_double(in);
        }
    if (kind % 4 == 0 && kind >= 128) /* and a fuzzed scale on one row */
        for (size_t k = 0, i = fuzz_byte(in) % m; k < n; k++)
            J[i * n + k] *= fuzz_double(in);
    memcpy(J0, J, sizeof J);
    uint8_t how = fuzz_byte(in);
    struct snapshot before;
    take(s, md, &before);
    int status;
    if (how % 8 == 7) {
        size_t rows = mm == m + 1 ? m + 1 : m, cols = nn == n + 1 ? n + 1 : n;
        double big[(MAX_M + 1) * (MAX_N + 1)] = {0};
        for (size_t i = 0; i < m; i++)
            for (size_t k = 0; k < n; k++)
                big[i * cols + k] = J[i * n + k];
        gsl_spmatrix *S = sparse(big, rows, cols, formats[how / 8 % 3]);
        if (S == NULL)
            return;
        status = fricreg_structure_set_contacts_sparse(s, S);
        mm = rows, nn = cols;
        gsl_spmatrix_free(S);
    } else {
        status = fricreg_structure_set_contacts(s, mm, nn, how == 1 ? NULL : J);
        FUZZ_REQUIRE(memcmp(J, J0, sizeof J) == 0, "set_contacts changed the caller's J");
    }
    after_setter(s, md, &before, status, SETTER_CODES | CODE(FRICREG_EINVAL), "set_contacts");
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(mm == m && nn == n && fuzz_all_finite(J, m * n), "set_contacts took a bad call");
    for (size_t i = 0; i < m; i++)
        FUZZ_REQUIRE(largest(J + i * n, n) > 0.0, "set_contacts took a zero row %zu", i);
    memcpy(md->J, J, m * n * sizeof *J);
    md->contacts_set = 1;
    md->big = fmax(md->big, largest(J, m * n));
    md->ready = 0;
}

static void op_bounds(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double mun[MAX_M];
    for (size_t i = 0; i < MAX_M; i++)
        mun[i] = fabs(fuzz_double(in)) * (fuzz_byte(in) == 9 ? -1.0 : 1.0);
    struct snapshot before;
    take(s, md, &before);
    int null = fuzz_byte(in) == 1;
    int status = fricreg_structure_set_bounds(s, m, null ? NULL : mun);
    after_setter(s, md, &before, status, SETTER_CODES | CODE(FRICREG_EINVAL), "set_bounds");
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(m == md->m && !null, "set_bounds took a bad call");
    for (size_t i = 0; i < m; i++)
        FUZZ_REQUIRE(isfinite(mun[i]) && mun[i] >= 0.0, "set_bounds took mun %g", mun[i]);
    memcpy(md->mun, mun, m * sizeof *mun);
    md->big = fmax(md->big, largest(mun, m));
    md->ready = 0;
}

static void op_law(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    int law = fuzz_int(in, 0, 8);
    double eps = fuzz_double(in);
    struct snapshot before;
    take(s, md, &before);
    int status = fricreg_structure_set_law(s, law, eps);
    after_setter(s, md, &before, status, CODE(FRICREG_EINVAL) | CODE(FRICREG_ENONFINITE),
                 "set_law");
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(fricreg_law_name(law) != NULL && isfinite(eps) && eps > 0.0,
                 "set_law took law %d eps %g", law, eps);
    md->law = law, md->eps = eps;
    md->ready = 0;
}

static void op_influence(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    size_t ndof = fuzz_size(in, md->n);
    double r[MAX_N];
    for (size_t k = 0; k < MAX_N; k++)
        r[k] = fuzz_byte(in) < 128 ? 1.0 : fuzz_double(in);
    struct snapshot before;
    take(s, md, &before);
    int null = fuzz_byte(in) == 1;
    int status = fricreg_structure_set_influence(s, ndof, null ? NULL : r);
    after_setter(s, md, &before, status, SETTER_CODES, "set_influence");
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(ndof == md->n && !null && fuzz_all_finite(r, md->n), "set_influence took it");
    memcpy(md->r, r, md->n * sizeof *r);
    md->big = fmax(md->big, largest(r, md->n));
    md->ready = 0;
}

/* A record's parameters: n in 0..8 samples (n = 1 refused), t0 and dt_rec. */
static void fuzz_record(struct fuzz_input *in, struct record *rec)
{
    rec->n = fuzz_byte(in) % (MAX_REC + 1);
    uint8_t when = fuzz_byte(in);
    rec->t0 = when < 128 ? 0.0 : fuzz_double(in);
    rec->dt = when % 2 ? fuzz_double(in) : 0.01 * (1 + when % 50);
    for (size_t k = 0; k < MAX_REC; k++)
        rec->x[k] = fuzz_double(in);
}

static int record_valid(const struct record *rec)
{
    return rec->n == 0 || (rec->n >= 2 && isfinite(rec->t0) && isfinite(rec->dt) && rec->dt > 0.0 &&
                           fuzz_all_finite(rec->x, rec->n));
}

static void op_ground(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    struct record rec;
    fuzz_record(in, &rec);
    struct snapshot before;
    take(s, md, &before);
    int null = rec.n > 0 && fuzz_byte(in) == 1;
    int status = fricreg_structure_set_ground_accel(s, rec.t0, rec.dt, rec.n, null ? NULL : rec.x);
    after_setter(s, md, &before, status,
                 CODE(FRICREG_ENULL) | CODE(FRICREG_EINVAL) | CODE(FRICREG_ENONFINITE) |
                     CODE(FRICREG_ENOMEM),
                 "set_ground_accel");
    FUZZ_REQUIRE(status == FRICREG_ENOMEM ||
                     (status == FRICREG_OK) == (record_valid(&rec) && !null),
                 "set_ground_accel(n %zu, t0 %g, dt %g): status %d", rec.n, rec.t0, rec.dt, status);
    if (status != FRICREG_OK)
        return;
    md->ground = rec;
    md->big = fmax(md->big, largest(rec.x, rec.n));
}

static void op_load(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    size_t ndof = fuzz_size(in, md->n);
    double p[MAX_N];
    for (size_t k = 0; k < MAX_N; k++)
        p[k] = fuzz_double(in);
    struct record rec;
    fuzz_record(in, &rec);
    struct snapshot before;
    take(s, md, &before);
    uint8_t null = fuzz_byte(in);
    int status = fricreg_structure_set_load(s, ndof, null == 1 ? NULL : p, rec.t0, rec.dt, rec.n,
                                            null == 2 && rec.n > 0 ? NULL : rec.x);
    after_setter(s, md, &before, status, SETTER_CODES | CODE(FRICREG_EINVAL) | CODE(FRICREG_ENOMEM),
                 "set_load");
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(ndof == md->n && null != 1 && !(null == 2 && rec.n > 0) &&
                     fuzz_all_finite(p, md->n) && record_valid(&rec),
                 "set_load took a bad call");
    memcpy(md->p, p, md->n * sizeof *p);
    md->load = rec;
    md->big = fmax(md->big, fmax(largest(p, md->n), largest(rec.x, rec.n)));
}

static void restart_books(struct model *md)
{
    md->ready = 0;
    md->started = 0;
    md->balance_void = 0;
    md->steps_since_fresh = 0.0;
    md->tol_max = 0.0;
    md->F_max = md->U_max = md->E_max = 0.0;
}

static void op_initial(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    size_t ndof = fuzz_size(in, md->n), n = md->n;
    double u0[MAX_N], v0[MAX_N];
    for (size_t k = 0; k < MAX_N; k++) {
        u0[k] = fuzz_byte(in) < 64 ? 0.0 : fuzz_double(in);
        v0[k] = fuzz_byte(in) < 64 ? 0.0 : fuzz_double(in);
    }
    struct snapshot before, after;
    take(s, md, &before);
    uint8_t null = fuzz_byte(in);
    int status = fricreg_structure_set_initial(s, ndof, null == 1 ? NULL : u0,
                                               null == 2 ? NULL : v0);
    require_status(s, status, SETTER_CODES, "set_initial");
    take(s, md, &after);
    if (status != FRICREG_OK) {
        require_unchanged(&before, &after, 1, "set_initial");
        return;
    }
    FUZZ_REQUIRE(ndof == n && null != 1 && null != 2 && fuzz_all_finite(u0, n) &&
                     fuzz_all_finite(v0, n),
                 "set_initial took a bad call");
    FUZZ_REQUIRE(memcmp(after.u, u0, n * sizeof *u0) == 0 &&
                     memcmp(after.v, v0, n * sizeof *v0) == 0,
                 "set_initial: the state is not (u0, v0)");
    for (size_t k = 0; k < n; k++)
        FUZZ_REQUIRE(after.a[k] == 0.0, "set_initial: a[%zu] = %g", k, after.a[k]);
    for (size_t i = 0; i < md->m; i++)
        FUZZ_REQUIRE(after.f[i] == 0.0 && after.D[i] == 0.0, "set_initial: f or D not 0");
    for (int k = 0; k < NSTATS; k++)
        FUZZ_REQUIRE(after.stat[k] == 0, "set_initial: counter %d = %lld", k,
                     (long long)after.stat[k]);
    static const int zero[] = {FRICREG_SVALUE_TIME, FRICREG_SVALUE_INPUT, FRICREG_SVALUE_VISCOUS,
                               FRICREG_SVALUE_FRICTION};
    for (size_t k = 0; k < sizeof zero / sizeof *zero; k++)
        FUZZ_REQUIRE(after.value[zero[k]] == 0.0, "set_initial: value %d = %g", zero[k],
                     after.value[zero[k]]);
    md->big = fmax(md->big, fmax(largest(u0, n), largest(v0, n)));
    restart_books(md);
}

static void op_scheme(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    uint8_t which = fuzz_byte(in) % 4;
    struct snapshot before;
    take(s, md, &before);
    int status;
    if (which == 0) { /* Newmark: average acceleration, or any beta, gamma */
        uint8_t sel = fuzz_byte(in);
        double beta = sel < 128 ? 0.25 : fuzz_double(in), gamma = sel < 128 ? 0.5 : fuzz_double(in);
        status = fricreg_structure_set_newmark(s, beta, gamma);
        after_setter(s, md, &before, status, CODE(FRICREG_ENONFINITE) | CODE(FRICREG_EINVAL),
                     "set_newmark");
        int valid = isfinite(beta) && isfinite(gamma) && beta > 0.0 && beta <= 0.5 &&
                    gamma >= 0.5 && gamma <= 1.0;
        FUZZ_REQUIRE((status == FRICREG_OK) == valid, "set_newmark(%g, %g): %d", beta, gamma,
                     status);
        if (status == FRICREG_OK)
            md->scheme = SCHEME_NEWMARK, md->alpha = 0.0, md->beta = beta, md->gamma = gamma;
    } else if (which == 1) {
        uint8_t sel = fuzz_byte(in);
        double alpha = sel < 128 ? -(double)(sel % 34) / 100.0 : fuzz_double(in);
        status = fricreg_structure_set_hht(s, alpha);
        after_setter(s, md, &before, status, CODE(FRICREG_ENONFINITE) | CODE(FRICREG_EINVAL),
                     "set_hht");
        FUZZ_REQUIRE((status == FRICREG_OK) == (alpha >= -1.0 / 3.0 && alpha <= 0.0),
                     "set_hht(%g): %d", alpha, status);
        if (status == FRICREG_OK) {
            md->scheme = SCHEME_NEWMARK, md->alpha = alpha;
            md->beta = (1.0 - alpha) * (1.0 - alpha) / 4.0, md->gamma = 0.5 - alpha;
        }
    } else if (which == 2) {
        status = fricreg_structure_set_central_difference(s);
        after_setter(s, md, &before, status, 0u, "set_central_difference");
        FUZZ_REQUIRE(status == FRICREG_OK, "set_central_difference: %d", status);
        md->scheme = SCHEME_CENTRAL;
    } else {
        uint8_t sel = fuzz_byte(in);
        double tol = sel < 128 ? pow(10.0, -(double)(sel % 15)) : fuzz_double(in);
        int max_iter = fuzz_byte(in) < 200 ? 1 + fuzz_byte(in) % 60 : fuzz_int(in, 0, 1200);
        status = fricreg_structure_set_newton(s, tol, max_iter);
        after_setter(s, md, &before, status, CODE(FRICREG_ENONFINITE) | CODE(FRICREG_EINVAL),
                     "set_newton");
        int valid = tol > 0.0 && tol < 1.0 && max_iter >= 1 && max_iter <= 1000;
        FUZZ_REQUIRE((status == FRICREG_OK) == valid, "set_newton(%g, %d): %d", tol, max_iter,
                     status);
        if (status == FRICREG_OK)
            md->newton_tol = tol, md->newton_max = max_iter;
    }
}

/* ---- The model's numbers, as the harness computes them -------------------------------------- */

/* The record at t, as fricreg_structure_set_ground_accel defines it (linear, zero outside, a
 * time within 1e-9 dt_rec of an end on it), by the library's own formula. */
static double record_at(const struct record *rec, double t)
{
    if (rec->n == 0)
        return 0.0;
    double pos = (t - rec->t0) / rec->dt, last = (double)(rec->n - 1);
    if (!(pos >= -1e-9) || pos > last + 1e-9)
        return 0.0;
    pos = fmin(fmax(pos, 0.0), last);
    size_t k = (size_t)pos;
    if (k >= rec->n - 1)
        return rec->x[rec->n - 1];
    double w = pos - (double)k;
    return (1.0 - w) * rec->x[k] + w * rec->x[k + 1];
}

/* p~(t) = p g(t) - M r a_g(t), and the magnitudes of its terms into mag[n]. */
static void effective_load(const struct model *md, double t, double ptil[], double mag[])
{
    size_t n = md->n;
    double g = md->load.n == 0 ? 1.0 : record_at(&md->load, t), ag = record_at(&md->ground, t);
    for (size_t i = 0; i < n; i++) {
        double mr = 0.0, mr_mag = 0.0;
        for (size_t k = 0; k < n; k++) {
            mr += md->M[i * n + k] * md->r[k];
            mr_mag += fabs(md->M[i * n + k] * md->r[k]);
        }
        ptil[i] = g * md->p[i] - ag * mr;
        mag[i] = fabs(g * md->p[i]) + fabs(ag) * mr_mag;
    }
}

/* The damping in force: C, or a0 M + a1 K. */
static double damping(const struct model *md, size_t i, size_t j)
{
    size_t n = md->n;
    return md->rayleigh ? md->a0 * md->M[i * n + j] + md->a1 * md->K[i * n + j] : md->C[i * n + j];
}

/* The equation of motion's residual R = M a + C vel + K u - p~ - J^T f, row by row, and the
 * magnitudes of its terms (M's with sqrt(M_ii M_jj), the bound of a Cholesky solve's backward
 * error |L||L^T|). */
static void eom_residual(const struct model *md, const double u[], const double vel[],
                         const double a[], const double f[], const double ptil[],
                         const double pmag[], double R[], double mag[])
{
    size_t n = md->n;
    for (size_t i = 0; i < n; i++) {
        double r = -ptil[i], g = pmag[i];
        for (size_t j = 0; j < n; j++) {
            double Mij = md->M[i * n + j], Cij = damping(md, i, j), Kij = md->K[i * n + j];
            r += Mij * a[j] + Cij * vel[j] + Kij * u[j];
            g += fmax(fabs(Mij), sqrt(md->M[i * n + i] * md->M[j * n + j])) * fabs(a[j]) +
                 fabs(Cij * vel[j]) + fabs(Kij * u[j]);
        }
        for (size_t c = 0; c < md->m; c++) {
            r -= md->J[c * n + i] * f[c];
            g += fabs(md->J[c * n + i] * f[c]);
        }
        R[i] = r;
        mag[i] = g;
    }
}

/* Newton's force scale of a step from (u, v, a, f) at t, p~ held ptil0, to p~1 (newmark.c,
 * fricreg_structure_set_newton): the largest entry of |M a|, |C v + K u - p~ - J^T f| at the
 * start, |p~1|, and |J|^T mun. */
static double force_scale(const struct model *md, const struct snapshot *s0, const double ptil1[])
{
    size_t n = md->n;
    double scale = 0.0;
    for (size_t i = 0; i < n; i++) {
        double ma = 0.0, e = -md->ptil[i], jm = 0.0;
        for (size_t j = 0; j < n; j++) {
            ma += md->M[i * n + j] * s0->a[j];
            e += damping(md, i, j) * s0->v[j] + md->K[i * n + j] * s0->u[j];
        }
        for (size_t c = 0; c < md->m; c++) {
            e -= md->J[c * n + i] * s0->f[c];
            jm += fabs(md->J[c * n + i]) * md->mun[c];
        }
        scale = fmax(scale, fmax(fmax(fabs(ma), fabs(e)), fmax(fabs(ptil1[i]), jm)));
    }
    return scale;
}

/* The rounding of the state's update (u1 within 8 eps umag, v1 within 8 eps vmag of the
 * scheme's formulas) seen by K u1 and C v1, added to the load's magnitudes pmag: with a long
 * step the predictor u + dt v + dt^2 a/4 is far larger than u1, which is what is left of it
 * after cancellation, and its rounding alone can exceed Newton's tolerance. */
static void add_update_rounding(const struct model *md, const double umag[], const double vmag[],
                                double pmag[])
{
    size_t n = md->n;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            pmag[i] += fabs(md->K[i * n + j]) * umag[j] + fabs(damping(md, i, j)) * vmag[j];
}

/* The equation of motion at the state sn, time t, damping seen at vel: its largest residual
 * within tol_abs + 16 n eps (the largest row's terms' magnitude). Normwise, as a solve's
 * backward error is: the structure forms a from pieces (M^-1 r0 + M^-1 J^T f), each rounded
 * on its own scale, and where they cancel the error of a is that of the pieces, seen by every
 * row of M, also by a row whose own terms are small. */
static void check_eom(const struct model *md, const struct snapshot *sn, const double vel[],
                      const double ptil[], const double pmag[], double tol_abs, const char *call)
{
    double R[MAX_N], mag[MAX_N];
    eom_residual(md, sn->u, vel, sn->a, sn->f, ptil, pmag, R, mag);
    double scale = 0.0;
    for (size_t i = 0; i < md->n; i++)
        scale = fmax(scale, mag[i]);
    for (size_t i = 0; i < md->n; i++) {
        double tol = tol_abs + 16.0 * (double)md->n * DBL_EPSILON * scale + 1e-300;
        FUZZ_REQUIRE(fabs(R[i]) <= tol,
                     "%s: equation of motion's residual %.3g in row %zu, tolerance %.3g "
                     "(terms %.3g)",
                     call, R[i], i, tol, mag[i]);
    }
}

/* Whether W = J M^-1 J^T is out of the range a step takes (an entry beyond the doubles, a W_ii
 * below DBL_MIN), or near it (1e-300, 1e300: the harness's rounding differs from the
 * library's), by Cholesky (M was accepted: positive definite). */
/* K_eff = M + (1 + alpha)(gamma dt C + beta dt^2 K) with an entry near or beyond the double
 * range (the step refuses such a dt, EINVAL): judged with a margin of 2, the structure's sums
 * being rounded otherwise. */
static int keff_out_of_range(const struct model *md, double dt)
{
    if (md->scheme != SCHEME_NEWMARK)
        return 0;
    double w = 1.0 + md->alpha, gc = w * md->gamma * dt, gk = w * md->beta * dt * dt;
    for (size_t k = 0; k < md->n * md->n; k++) {
        double c = md->rayleigh ? md->a0 * md->M[k] + md->a1 * md->K[k] : md->C[k];
        double e = fabs(md->M[k]) + fabs(gc) * fabs(c) + fabs(gk) * fabs(md->K[k]);
        if (!(e <= DBL_MAX / 2.0))
            return 1;
    }
    return 0;
}

static int coupling_out_of_range(const struct model *md)
{
    size_t n = md->n, m = md->m;
    double L[MAX_N * MAX_N] = {0}, G[MAX_M * MAX_N];
    for (size_t j = 0; j < n; j++) {
        double d = md->M[j * n + j];
        for (size_t k = 0; k < j; k++)
            d -= L[j * n + k] * L[j * n + k];
        if (!(d > 0.0))
            return 1;
        L[j * n + j] = sqrt(d);
        for (size_t i = j + 1; i < n; i++) {
            double x = md->M[i * n + j];
            for (size_t k = 0; k < j; k++)
                x -= L[i * n + k] * L[j * n + k];
            L[i * n + j] = x / L[j * n + j];
        }
    }
    for (size_t c = 0; c < m; c++) /* G = J L^-T: W = G G^T */
        for (size_t j = 0; j < n; j++) {
            double x = md->J[c * n + j];
            for (size_t k = 0; k < j; k++)
                x -= G[c * n + k] * L[j * n + k];
            G[c * n + j] = x / L[j * n + j];
        }
    for (size_t a = 0; a < m; a++)
        for (size_t b = 0; b < m; b++) {
            double w = 0.0;
            for (size_t k = 0; k < n; k++)
                w += G[a * n + k] * G[b * n + k];
            if (!(fabs(w) <= 1e300) || (a == b && !(w >= 1e-300)))
                return 1;
        }
    return 0;
}

/* ---- Stepping ------------------------------------------------------------------------------- */

static int smooth(int law)
{
    return law == FRICREG_LAW_VELOCITY_LIMITED || law == FRICREG_LAW_TANH ||
           law == FRICREG_LAW_QUINN;
}

/* The balance's scales at the state sn (before and after each stepping call): the largest
 * force, the sum over a row of |M a|, |C v|, |K u|, |p~| and |J|^T mun (which bound the
 * equilibrium's M a too, and so Newton's force scale); the largest displacement, with the
 * terms of a step's update |u| + h |v| + h^2 |a| (a step of 1e16 from u = DBL_MIN, v = -1:
 * u1 is their sum, rounded to 2.4, and du is no longer dt (v + v1)/2 — fuzz finding, the
 * harness's); the largest energy. */
static void observe(struct model *md, const struct snapshot *sn)
{
    size_t n = md->n, m = md->m;
    double ptil[MAX_N], pmag[MAX_N];
    effective_load(md, now(sn), ptil, pmag);
    for (size_t i = 0; i < n; i++) {
        double F = pmag[i] + fabs(md->ptil[i]);
        for (size_t j = 0; j < n; j++)
            F += fabs(md->K[i * n + j] * sn->u[j]) + fabs(md->M[i * n + j] * sn->a[j]) +
                 fabs(damping(md, i, j) * sn->v[j]);
        for (size_t c = 0; c < m; c++)
            F += fabs(md->J[c * n + i]) * md->mun[c];
        md->F_max = fmax(md->F_max, F);
        md->U_max = fmax(md->U_max,
                         fabs(sn->u[i]) + md->h * fabs(sn->v[i]) + md->h * md->h * fabs(sn->a[i]));
    }
    static const int energies[] = {FRICREG_SVALUE_INPUT,    FRICREG_SVALUE_KINETIC,
                                   FRICREG_SVALUE_STRAIN,   FRICREG_SVALUE_VISCOUS,
                                   FRICREG_SVALUE_FRICTION, FRICREG_SVALUE_INITIAL};
    for (size_t k = 0; k < sizeof energies / sizeof *energies; k++)
        md->E_max = fmax(md->E_max, fabs(sn->value[energies[k]]));
    for (size_t i = 0; i < m; i++)
        md->E_max = fmax(md->E_max, fabs(sn->D[i]));
}

/* The checks of every successful step, run or run_ode: the time, finite state within the
 * divergence limit, the bounds, the dissipation's sum; and the books of the balance. */
static void check_ok_state(struct model *md, const struct snapshot *sn, double t_expected,
                           int a_limited, const char *call)
{
    size_t n = md->n, m = md->m;
    FUZZ_REQUIRE(now(sn) == t_expected, "%s: time %.17g, expected %.17g", call, now(sn),
                 t_expected);
    for (size_t k = 0; k < n; k++) {
        FUZZ_REQUIRE(fabs(sn->u[k]) <= STATE_LIMIT && fabs(sn->v[k]) <= STATE_LIMIT,
                     "%s: OK with u[%zu] = %g, v = %g", call, k, sn->u[k], sn->v[k]);
        FUZZ_REQUIRE(isfinite(sn->a[k]) && (!a_limited || fabs(sn->a[k]) <= STATE_LIMIT),
                     "%s: OK with a[%zu] = %g", call, k, sn->a[k]);
    }
    double dsum = 0.0, dmag = 0.0;
    for (size_t i = 0; i < m; i++) {
        FUZZ_REQUIRE(isfinite(sn->f[i]) && fabs(sn->f[i]) <= md->mun[i] * (1.0 + 4 * DBL_EPSILON),
                     "%s: f[%zu] = %.17g, mun %.17g (law %d, eps %g)", call, i, sn->f[i],
                     md->mun[i], md->law, md->eps);
        FUZZ_REQUIRE(isfinite(sn->D[i]) || md->big > ENERGY_INPUT_MAX, "%s: D[%zu] = %g", call, i,
                     sn->D[i]);
        dsum += sn->D[i];
        dmag += fabs(sn->D[i]);
    }
    /* the energies are quadratic: finite while the inputs are within 1e50 (the state within
     * 1e100), else they may overflow */
    for (int k = 0; k < NVALUES; k++)
        FUZZ_REQUIRE(isfinite(sn->value[k]) ||
                         (k != FRICREG_SVALUE_TIME && md->big > ENERGY_INPUT_MAX),
                     "%s: value %d = %g", call, k, sn->value[k]);
    observe(md, sn);
    /* the sums differ by their roundings, of the largest dissipation seen (E_max) */
    double fric = sn->value[FRICREG_SVALUE_FRICTION];
    double scale = fmax(md->E_max, dmag + fabs(fric));
    FUZZ_REQUIRE(!(fabs(fric - dsum) >
                   64.0 * (double)m * DBL_EPSILON * fmax(1.0, md->steps_since_fresh + 1.0) * scale +
                       1e-300),
                 "%s: FRICTION %.17g, sum of D %.17g", call, fric, dsum);
}

/* The balance, where it closes (the comment at the top). */
static void check_balance(const struct model *md, const struct snapshot *sn, const char *call)
{
    if (md->balance_void || !md->started || md->big > ENERGY_INPUT_MAX ||
        md->tol_max > ENERGY_NEWTON_TOL)
        return;
    double N = md->steps_since_fresh, n = (double)md->n;
    double scale = fmax(md->E_max, 2.0 * md->F_max * md->U_max);
    double tol = N * n * (md->tol_max + 64.0 * n * DBL_EPSILON) * scale + 1e-300;
    double residual = sn->value[FRICREG_SVALUE_RESIDUAL];
    if (getenv("FUZZ_TRACE") != NULL)
        fprintf(stderr, "%s: energy residual %.3g, tolerance %.3g\n", call, residual, tol);
    FUZZ_REQUIRE(fabs(residual) <= tol,
                 "%s: energy residual %.6g, tolerance %.3g (scale %.3g, %g steps, tol %g)", call,
                 residual, tol, scale, N, md->tol_max);
}

/* The books of a successful stepping call of `steps` steps: which may the balance count. */
static void count_steps(struct model *md, double steps, int newton_failed, int ode)
{
    int exact = !ode && md->scheme == SCHEME_NEWMARK && md->alpha == 0.0 && md->beta == 0.25 &&
                md->gamma == 0.5 && smooth(md->law) && !newton_failed;
    if (!exact)
        md->balance_void = 1;
    md->started = 1;
    md->steps_since_fresh += steps;
    md->tol_max = fmax(md->tol_max, md->newton_tol);
}

/* The cost of one step in the harness's unit: a Newmark step may take max_iter iterations of up
 * to 31 residuals each; the caps are set for the default 50. */
static double step_cost(const struct model *md)
{
    return md->scheme == SCHEME_NEWMARK ? fmax(1.0, md->newton_max / 50.0) : 1.0;
}

static int64_t stat_delta(const struct snapshot *a, const struct snapshot *b, int k)
{
    return b->stat[k] - a->stat[k];
}

/* Failed stepping call: its status was documented and recorded; the state, if it moved, is
 * that of a successful step (finite, within the limit; set_initial may start beyond it). */
static void check_failed_run(const struct model *md, const struct snapshot *before,
                             const struct snapshot *after, const char *call)
{
    int moved = now(after) != now(before) || stat_delta(before, after, FRICREG_SSTAT_STEPS) != 0;
    for (size_t k = 0; moved && k < md->n; k++)
        FUZZ_REQUIRE(fabs(after->u[k]) <= STATE_LIMIT && fabs(after->v[k]) <= STATE_LIMIT,
                     "%s failed and left u[%zu] = %g, v = %g", call, k, after->u[k], after->v[k]);
    FUZZ_REQUIRE(now(after) >= now(before), "%s went back in time", call);
}

static void op_step(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    uint8_t sel = fuzz_byte(in);
    double dt = sel < 160 ? pow(10.0, -(double)(sel % 6)) * (1.0 + (sel % 7) / 7.0)
                          : fuzz_double(in);
    if (md->work + step_cost(md) > INPUT_STEP_CAP)
        return;
    struct snapshot before, after;
    take(s, md, &before);
    md->h = isfinite(dt) && dt > 0.0 ? dt : 0.0;
    observe(md, &before);
    int ready = md->ready;
    int status = fricreg_structure_step(s, dt);
    require_status(s, status, STEP_CODES, "step");
    take(s, md, &after);
    md->work += step_cost(md);
    if (status != FRICREG_OK) {
        require_unchanged(&before, &after, 1, "step");
        FUZZ_REQUIRE(status != FRICREG_ENONFINITE || !isfinite(dt),
                     "step(%g): ENONFINITE with a finite dt: %s", dt, fricreg_structure_errmsg(s));
        FUZZ_REQUIRE(status != FRICREG_EINVAL || !(dt > 0.0) ||
                         !(now(&before) + dt > now(&before)) || !md->contacts_set ||
                         coupling_out_of_range(md) || keff_out_of_range(md, dt),
                     "step(%g): EINVAL: %s", dt, fricreg_structure_errmsg(s));
        return;
    }
    FUZZ_REQUIRE(isfinite(dt) && dt > 0.0 && md->contacts_set, "step(%g) took a bad call", dt);
    check_ok_state(md, &after, now(&before) + dt, 1, "step");
    FUZZ_REQUIRE(stat_delta(&before, &after, FRICREG_SSTAT_STEPS) == 1, "step: STEPS + %lld",
                 (long long)stat_delta(&before, &after, FRICREG_SSTAT_STEPS));
    int64_t iters = stat_delta(&before, &after, FRICREG_SSTAT_NEWTON_ITERATIONS);
    int failed = stat_delta(&before, &after, FRICREG_SSTAT_NEWTON_FAILURES) > 0;
    FUZZ_REQUIRE(iters >= 0 && iters <= md->newton_max &&
                     after.stat[FRICREG_SSTAT_NEWTON_MAX] <= 1000 &&
                     (md->scheme != SCHEME_CENTRAL || (iters == 0 && !failed)),
                 "step: %lld Newton iterations (max_iter %d, scheme %d)", (long long)iters,
                 md->newton_max, md->scheme);
    double ptil1[MAX_N], pmag1[MAX_N], t1 = now(&after);
    effective_load(md, t1, ptil1, pmag1);
    if (ready && md->big <= ENERGY_INPUT_MAX) {
        /* the scheme's update formulas from the known start (u, v, a), with the step the
         * times make: (t + dt) - t, not dt */
        size_t n = md->n;
        dt = t1 - now(&before);
        int central = md->scheme == SCHEME_CENTRAL;
        double beta = central ? 0.0 : md->beta, gamma = central ? 0.5 : md->gamma;
        double vstar[MAX_N], umag[MAX_N], vmag[MAX_N];
        for (size_t k = 0; k < n; k++) {
            double u = before.u[k], v = before.v[k], a = before.a[k], a1 = after.a[k];
            double u1 = u + dt * v + dt * dt * ((0.5 - beta) * a + beta * a1);
            double v1 = v + dt * ((1.0 - gamma) * a + gamma * a1);
            umag[k] = fabs(u) + fabs(dt * v) + dt * dt * (fabs(a) + fabs(a1));
            vmag[k] = fabs(v) + dt * (fabs(a) + fabs(a1));
            /* the step is taken with the factored dt where that is within 1e-9 of this one
             * (the header): u1 and v1 move by dh times their derivatives in dt */
            double dh = central ? 0.0 : 1e-9 * dt;
            double utol = 8.0 * DBL_EPSILON * umag[k] + dh * (fabs(v) + dt * (fabs(a) + fabs(a1)));
            double vtol = 8.0 * DBL_EPSILON * vmag[k] + dh * (fabs(a) + fabs(a1));
            FUZZ_REQUIRE(fabs(after.u[k] - u1) <= utol + 1e-300 &&
                             fabs(after.v[k] - v1) <= vtol + 1e-300,
                         "step: u1[%zu] = %.17g, v1 = %.17g; the scheme's %.17g, %.17g", k,
                         after.u[k], after.v[k], u1, v1);
            vstar[k] = v + dt * a;
        }
        add_update_rounding(md, umag, vmag, pmag1);
        if (central)
            check_eom(md, &after, vstar, ptil1, pmag1, 0.0, "step (central difference)");
        else if (md->alpha == 0.0 && !failed)
            check_eom(md, &after, after.v, ptil1, pmag1,
                      md->newton_tol * force_scale(md, &before, ptil1) * (1.0 + 1e-6),
                      "step (Newmark)");
    }
    memcpy(md->ptil, ptil1, sizeof ptil1);
    md->ready = 1;
    count_steps(md, 1.0, failed, 0);
    check_balance(md, &after, "step");
}

/* dt and t_end of a run from the input: t_end = t + k dt mostly, anything now and then. */
static void fuzz_span(struct fuzz_input *in, double t, double *dt, double *t_end)
{
    uint8_t sel = fuzz_byte(in);
    *dt = sel < 160 ? pow(10.0, -(double)(sel % 6)) * (1.0 + (sel % 7) / 7.0) : fuzz_double(in);
    uint8_t how = fuzz_byte(in);
    if (how < 160)
        *t_end = t + *dt * (1.0 + (double)fuzz_byte(in) * (how % 2 ? 0.37 : 4.0));
    else if (how < 224)
        *t_end = t + fuzz_double(in);
    else
        *t_end = fuzz_double(in);
}

/* Refused before any work by the header's rules. */
static int refused_run(double t, double dt, double t_end)
{
    return !isfinite(dt) || !isfinite(t_end) || !(dt > 0.0) || !(t_end > t);
}

static void op_run(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    double dt, t_end;
    struct snapshot before, after;
    take(s, md, &before);
    double t = now(&before);
    fuzz_span(in, t, &dt, &t_end);
    md->h = isfinite(dt) && dt > 0.0 ? dt : 0.0;
    observe(md, &before);
    int refused = refused_run(t, dt, t_end);
    double steps = refused ? 0.0 : ceil((t_end - t) / dt), cost = steps * step_cost(md);
    if (!refused && (cost > STEP_CAP || md->work + cost > INPUT_STEP_CAP))
        return; /* affordable runs only */
    int status = fricreg_structure_run(s, dt, t_end);
    require_status(s, status, STEP_CODES, "run");
    take(s, md, &after);
    md->work += cost;
    if (refused) {
        FUZZ_REQUIRE(status != FRICREG_OK, "run(%g, %g) from %g: OK", dt, t_end, t);
        require_unchanged(&before, &after, 1, "run (refused)");
        return;
    }
    double taken = (double)stat_delta(&before, &after, FRICREG_SSTAT_STEPS);
    if (status != FRICREG_OK) {
        check_failed_run(md, &before, &after, "run");
        if (taken == 0.0) /* no step taken: the state is the one it started from */
            require_unchanged(&before, &after, 1, "run (failed at its first step)");
        if (taken > 0.0) { /* the state moved: the last successful step's */
            md->ready = 1;
            double ptil1[MAX_N], pmag1[MAX_N];
            effective_load(md, now(&after), ptil1, pmag1);
            memcpy(md->ptil, ptil1, sizeof ptil1);
            count_steps(md, taken, stat_delta(&before, &after, FRICREG_SSTAT_NEWTON_FAILURES) > 0,
                        0);
        }
        return;
    }
    FUZZ_REQUIRE(md->contacts_set, "run: OK without J");
    check_ok_state(md, &after, t_end, 1, "run");
    FUZZ_REQUIRE(taken >= 1.0 && taken <= steps + 1.0, "run: %g steps, expected about %g", taken,
                 steps);
    int failed = stat_delta(&before, &after, FRICREG_SSTAT_NEWTON_FAILURES) > 0;
    double pmag1[MAX_N];
    effective_load(md, t_end, md->ptil, pmag1);
    md->ready = 1;
    count_steps(md, taken, failed, 0);
    check_balance(md, &after, "run");
}

/* A bound of the stiffest rate of the model: omega_max + c_max + the stick zone's
 * max_i W_ii 2 mun_i/eps, each from Frobenius norms over M's smallest eigenvalue. */
static double rate_bound(const struct model *md)
{
    size_t n = md->n;
    gsl_matrix *A = gsl_matrix_alloc(n, n);
    gsl_vector *eval = gsl_vector_alloc(n);
    gsl_eigen_symm_workspace *work = gsl_eigen_symm_alloc(n);
    FUZZ_REQUIRE(A && eval && work, "harness: out of memory");
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            gsl_matrix_set(A, i, j, md->M[i * n + j]);
    gsl_eigen_symm(A, eval, work);
    double lambda = gsl_vector_min(eval);
    gsl_eigen_symm_free(work);
    gsl_vector_free(eval);
    gsl_matrix_free(A);
    if (!(lambda > 0.0))
        return INFINITY;
    double k2 = 0.0, c2 = 0.0, stick = 0.0;
    for (size_t i = 0; i < n * n; i++) {
        k2 += md->K[i] * md->K[i];
        double c = damping(md, i / n, i % n);
        c2 += c * c;
    }
    for (size_t c = 0; c < md->m; c++) {
        double j2 = 0.0;
        for (size_t k = 0; k < n; k++)
            j2 += md->J[c * n + k] * md->J[c * n + k];
        stick = fmax(stick, j2 / lambda * 2.0 * md->mun[c] / md->eps);
    }
    return sqrt(sqrt(k2) / lambda) + sqrt(c2) / lambda + stick;
}

static void op_run_ode(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    int integ = fuzz_int(in, 0, 15);
    uint8_t tols = fuzz_byte(in);
    double rtol = 0.0, atol = 0.0;
    if (tols >= 128) { /* adaptive */
        rtol = tols & 1 ? fuzz_double(in) : pow(10.0, -(double)(tols / 2 % 12));
        atol = tols & 2 ? fuzz_double(in) : pow(10.0, -(double)(tols / 4 % 12));
    }
    struct snapshot before, after;
    take(s, md, &before);
    md->h = 0.0; /* run_ode: no balance check */
    observe(md, &before);
    double t = now(&before), dt, t_end;
    fuzz_span(in, t, &dt, &t_end);
    const char *name = fricreg_integrator_name(integ);
    int known = name != NULL && integ != FRICREG_INT_CENTRAL && integ != FRICREG_INT_CENTRAL_IMEX;
    int adaptive = rtol > 0.0 || atol > 0.0;
    /* the steppers that iterate to atol + rtol |y| need atol > 0 (fricreg_sim_set_integrator) */
    int iterating = integ == FRICREG_INT_RK1IMP || integ == FRICREG_INT_RK2IMP ||
                    integ == FRICREG_INT_RK4IMP || integ == FRICREG_INT_MSADAMS ||
                    integ == FRICREG_INT_MSBDF;
    int refused = refused_run(t, dt, t_end) || !known || !isfinite(rtol) || !isfinite(atol) ||
                  rtol < 0.0 || atol < 0.0 || (iterating && rtol > 0.0 && atol == 0.0);
    int explicit_rk = integ >= FRICREG_INT_RK2 && integ <= FRICREG_INT_RK8PD;
    explicit_rk = explicit_rk || integ == FRICREG_INT_RK4_GSL;
    double steps = refused ? 0.0 : ceil((t_end - t) / dt);
    if (!refused) {
        if (!adaptive && steps > (explicit_rk ? FIXED_ODE_CAP : IMPLICIT_ODE_CAP))
            return;
        if (adaptive) {
            double lo = fmin(rtol > 0.0 ? rtol : INFINITY, atol > 0.0 ? atol : INFINITY);
            if (!smooth(md->law) || fmax(rtol, atol) < 1e-6 || lo < 1e-10 || !md->contacts_set ||
                !((t_end - t) * rate_bound(md) <= ADAPTIVE_CAP))
                return;
            steps = STEP_CAP; /* its work: the bound set below */
        }
        if (md->work + steps > INPUT_STEP_CAP)
            return;
    }
    /* an adaptive run's work is bounded by the library (set_max_steps), not guessed: bsimp,
     * whose runaway test is relative to |y_i|, takes steps of 1e-3 beside a component of
     * 1e-322 where the rate bound allows 10^3 times more */
    FUZZ_REQUIRE(fricreg_structure_set_max_steps(s, (int64_t)STEP_CAP) == FRICREG_OK,
                 "set_max_steps(%g)", STEP_CAP);
    int status = fricreg_structure_run_ode(s, integ, dt, rtol, atol, t_end);
    require_status(s, status, ODE_CODES, "run_ode");
    take(s, md, &after);
    md->work += steps;
    if (refused) {
        FUZZ_REQUIRE(status != FRICREG_OK, "run_ode(%d, %g, %g, %g, %g) from %g: OK", integ, dt,
                     rtol, atol, t_end, t);
        require_unchanged(&before, &after, 1, "run_ode (refused)");
        return;
    }
    double taken = (double)stat_delta(&before, &after, FRICREG_SSTAT_STEPS);
    FUZZ_REQUIRE(stat_delta(&before, &after, FRICREG_SSTAT_NEWTON_ITERATIONS) == 0,
                 "run_ode counted Newton iterations");
    FUZZ_REQUIRE(status != FRICREG_EWORK || (adaptive && taken == STEP_CAP),
                 "run_ode: EWORK after %g steps (adaptive %d, bound %g)", taken, adaptive,
                 STEP_CAP);
    if (status != FRICREG_OK) {
        check_failed_run(md, &before, &after, "run_ode");
        if (taken == 0.0) /* no step accepted: the state is the one it started from */
            require_unchanged(&before, &after, 1, "run_ode (failed at its first step)");
        if (taken > 0.0 || now(&after) != now(&before)) {
            /* the last accepted step's state, a and f from its equation of motion (unless
             * that fails too: then those of the start) */
            double ptil1[MAX_N], pmag1[MAX_N];
            effective_load(md, now(&after), ptil1, pmag1);
            if (md->big <= ENERGY_INPUT_MAX && status != FRICREG_ESINGULAR &&
                status != FRICREG_EDIVERGED)
                check_eom(md, &after, after.v, ptil1, pmag1, 0.0, "run_ode (failed)");
            md->ready = 0; /* the next step takes its acceleration from the equation */
            count_steps(md, taken, 0, 1);
        }
        return;
    }
    FUZZ_REQUIRE(md->contacts_set, "run_ode: OK without J");
    check_ok_state(md, &after, t_end, 0, "run_ode");
    double ptil1[MAX_N], pmag1[MAX_N];
    effective_load(md, t_end, ptil1, pmag1);
    if (md->big <= ENERGY_INPUT_MAX) /* ends on the equilibrium at t_end: exact */
        check_eom(md, &after, after.v, ptil1, pmag1, 0.0, "run_ode");
    memcpy(md->ptil, ptil1, sizeof ptil1);
    md->ready = 1;
    count_steps(md, taken, 0, 1);
}

/* ---- Getters and messages ------------------------------------------------------------------- */

static void op_getters(struct fuzz_input *in, fricreg_structure *s, struct model *md)
{
    int errcode = fricreg_structure_errcode(s);
    char msg[512];
    snprintf(msg, sizeof msg, "%s", fricreg_structure_errmsg(s));
    size_t n = fuzz_size(in, md->n), m = fuzz_size(in, md->m);
    double x[MAX_N + 1], y[MAX_N + 1], z[MAX_N + 1];
    fuzz_fill(x, sizeof x), fuzz_fill(y, sizeof y), fuzz_fill(z, sizeof z);
    uint8_t which = fuzz_byte(in);
    int status = fricreg_structure_get_state(s, n, which & 1 ? x : NULL, which & 2 ? y : NULL,
                                             which & 4 ? z : NULL);
    int valid = n == md->n && (which & 7) != 0;
    FUZZ_REQUIRE((status == FRICREG_OK) == valid &&
                     (valid || status == ((which & 7) == 0 ? FRICREG_ENULL : FRICREG_ESIZE)),
                 "get_state(%zu, %#x): %d", n, which, status);
    if (status != FRICREG_OK)
        FUZZ_REQUIRE(fuzz_untouched(x, sizeof x) && fuzz_untouched(y, sizeof y) &&
                         fuzz_untouched(z, sizeof z),
                     "get_state wrote on failure");
    else
        FUZZ_REQUIRE(fuzz_untouched(x + n, sizeof *x) && fuzz_untouched(y + n, sizeof *y) &&
                         fuzz_untouched(z + n, sizeof *z),
                     "get_state wrote past ndof");
    fuzz_fill(x, sizeof x), fuzz_fill(y, sizeof y);
    int s1 = fricreg_structure_get_forces(s, m, which & 8 ? NULL : x);
    int s2 = fricreg_structure_get_dissipation(s, m, which & 16 ? NULL : y);
    FUZZ_REQUIRE(s1 == (which & 8    ? FRICREG_ENULL
                        : m == md->m ? FRICREG_OK
                                     : FRICREG_ESIZE) &&
                     s2 == (which & 16   ? FRICREG_ENULL
                            : m == md->m ? FRICREG_OK
                                         : FRICREG_ESIZE),
                 "get_forces/get_dissipation(%zu): %d %d", m, s1, s2);
    FUZZ_REQUIRE((s1 == FRICREG_OK || fuzz_untouched(x, sizeof x)) &&
                     (s2 == FRICREG_OK || fuzz_untouched(y, sizeof y)),
                 "get_forces/get_dissipation wrote on failure");
    int k = fuzz_int(in, -1, NVALUES + 2);
    double value;
    fuzz_fill(&value, sizeof value);
    status = fricreg_structure_get_value(s, k, which & 32 ? NULL : &value);
    FUZZ_REQUIRE(status == (which & 32              ? FRICREG_ENULL
                            : k >= 0 && k < NVALUES ? FRICREG_OK
                                                    : FRICREG_EINVAL),
                 "get_value(%d): %d", k, status);
    FUZZ_REQUIRE(status == FRICREG_OK || fuzz_untouched(&value, sizeof value),
                 "get_value wrote on failure");
    int64_t stat;
    fuzz_fill(&stat, sizeof stat);
    status = fricreg_structure_get_stat(s, k, which & 64 ? NULL : &stat);
    FUZZ_REQUIRE(status == (which & 64             ? FRICREG_ENULL
                            : k >= 0 && k < NSTATS ? FRICREG_OK
                                                   : FRICREG_EINVAL),
                 "get_stat(%d): %d", k, status);
    FUZZ_REQUIRE(status == FRICREG_OK || fuzz_untouched(&stat, sizeof stat),
                 "get_stat wrote on failure");
    /* the getters record nothing */
    FUZZ_REQUIRE(fricreg_structure_errcode(s) == errcode &&
                     strcmp(fricreg_structure_errmsg(s), msg) == 0,
                 "a getter changed the last error");
    char buf[8];
    size_t len = fuzz_byte(in) % (sizeof buf + 1);
    fuzz_fill(buf, sizeof buf);
    size_t full = fricreg_structure_errmsg_copy(s, buf, len);
    FUZZ_REQUIRE(full == (len > 0 ? strlen(fricreg_structure_errmsg(s)) : 0),
                 "errmsg_copy length %zu", full);
    if (len > 0)
        FUZZ_REQUIRE(memchr(buf, '\0', len) != NULL, "errmsg_copy: no NUL in %zu", len);
    if (len < sizeof buf)
        FUZZ_REQUIRE(fuzz_untouched(buf + len, sizeof buf - len), "errmsg_copy wrote past len");
}

/* create with a bad size or a NULL out, and every call on a NULL structure: refused. */
static void check_refusals(uint8_t sel)
{
    /* zero, SIZE_MAX, and one beyond the caps: 2^40 degrees of freedom, 2^26 contacts */
    static const size_t sizes[4] = {0, SIZE_MAX, ((size_t)1 << 40) + 1, ((size_t)1 << 26) + 1};
    fricreg_structure *s;
    fuzz_fill(&s, sizeof s);
    int contacts = (sel & 4) != 0;
    size_t bad = sizes[sel % 4 == 3 && !contacts ? 2 : sel % 4]; /* 2^26 + 1 dof is valid */
    int status = fricreg_structure_create(contacts ? 1 : bad, contacts ? bad : 1, &s);
    FUZZ_REQUIRE(status == FRICREG_EINVAL && fuzz_untouched(&s, sizeof s), "create: status %d",
                 status);
    FUZZ_REQUIRE(fricreg_structure_create(1, 1, NULL) == FRICREG_ENULL, "create(1, 1, NULL)");
    double x[1] = {1.0}, value;
    int64_t stat;
    int statuses[] = {
        fricreg_structure_set_mass(NULL, 1, x),
        fricreg_structure_set_stiffness(NULL, 1, x),
        fricreg_structure_set_damping(NULL, 1, x),
        fricreg_structure_set_rayleigh(NULL, 0.0, 0.0),
        fricreg_structure_set_contacts(NULL, 1, 1, x),
        fricreg_structure_set_bounds(NULL, 1, x),
        fricreg_structure_set_law(NULL, FRICREG_LAW_QUINN, 0.1),
        fricreg_structure_set_influence(NULL, 1, x),
        fricreg_structure_set_ground_accel(NULL, 0.0, 0.0, 0, NULL),
        fricreg_structure_set_load(NULL, 1, x, 0.0, 0.0, 0, NULL),
        fricreg_structure_set_initial(NULL, 1, x, x),
        fricreg_structure_set_newmark(NULL, 0.25, 0.5),
        fricreg_structure_set_hht(NULL, 0.0),
        fricreg_structure_set_central_difference(NULL),
        fricreg_structure_set_newton(NULL, 1e-10, 50),
        fricreg_structure_step(NULL, 0.1),
        fricreg_structure_run(NULL, 0.1, 1.0),
        fricreg_structure_run_ode(NULL, FRICREG_INT_RK4, 0.1, 0.0, 0.0, 1.0),
        fricreg_structure_get_state(NULL, 1, x, x, x),
        fricreg_structure_get_forces(NULL, 1, x),
        fricreg_structure_get_dissipation(NULL, 1, x),
        fricreg_structure_get_value(NULL, 0, &value),
        fricreg_structure_get_stat(NULL, 0, &stat),
        fricreg_structure_set_mass_sparse(NULL, NULL),
        fricreg_structure_set_stiffness_sparse(NULL, NULL),
        fricreg_structure_set_damping_sparse(NULL, NULL),
        fricreg_structure_set_contacts_sparse(NULL, NULL),
    };
    for (size_t k = 0; k < sizeof statuses / sizeof *statuses; k++)
        FUZZ_REQUIRE(statuses[k] == FRICREG_ENULL, "call %zu on NULL: %d", k, statuses[k]);
    FUZZ_REQUIRE(fricreg_structure_errcode(NULL) == FRICREG_OK &&
                     strcmp(fricreg_structure_errmsg(NULL), "NULL structure") == 0,
                 "errcode/errmsg of NULL");
    fricreg_structure_free(NULL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    last_error = FRICREG_OK;
    uint8_t first = fuzz_byte(&in);
    if (first >= 248) {
        check_refusals(first);
        return 0;
    }
    size_t n = 1 + first % MAX_N, m = 1 + first / MAX_N % MAX_M;
    fricreg_structure *s = NULL;
    if (fricreg_structure_create(n, m, &s) != FRICREG_OK)
        return 0; /* out of memory: nothing to fuzz */
    /* the defaults of fricreg_structure_create */
    struct model md = {.n = n,
                       .m = m,
                       .law = FRICREG_LAW_QUINN,
                       .eps = 1e-3,
                       .beta = 0.25,
                       .gamma = 0.5,
                       .newton_tol = 1e-10,
                       .newton_max = 50};
    for (size_t i = 0; i < n; i++)
        md.M[i * n + i] = 1.0;
    for (size_t i = 0; i < m; i++)
        md.mun[i] = 1.0;
    if (first / (MAX_N * MAX_M) % 4 != 3) { /* contact i on DOF i mod n, unless told not to */
        double J[MAX_M * MAX_N] = {0};
        for (size_t i = 0; i < m; i++)
            J[i * n + i % n] = 1.0;
        FUZZ_REQUIRE(fricreg_structure_set_contacts(s, m, n, J) == FRICREG_OK,
                     "set_contacts of the default J");
        memcpy(md.J, J, sizeof J);
        md.contacts_set = 1;
    }
    while (!fuzz_done(&in)) {
        switch (fuzz_byte(&in) % 16) {
        case 0: op_square(&in, s, &md, 0); break;
        case 1: op_square(&in, s, &md, 1); break;
        case 2: op_square(&in, s, &md, 2); break;
        case 3: op_rayleigh(&in, s, &md); break;
        case 4: op_contacts(&in, s, &md); break;
        case 5: op_bounds(&in, s, &md); break;
        case 6: op_law(&in, s, &md); break;
        case 7: op_influence(&in, s, &md); break;
        case 8: op_ground(&in, s, &md); break;
        case 9: op_load(&in, s, &md); break;
        case 10: op_initial(&in, s, &md); break;
        case 11: op_scheme(&in, s, &md); break;
        case 12: op_step(&in, s, &md); break;
        case 13: op_run(&in, s, &md); break;
        case 14: op_run_ode(&in, s, &md); break;
        default: op_getters(&in, s, &md);
        }
    }
    fricreg_structure_free(s);
    return 0;
}
