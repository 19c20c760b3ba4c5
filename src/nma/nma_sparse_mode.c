/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_sparse_mode.c — a sparse model's linear mode k for the nonlinear modes (nma_linear.c):
 * K_0 φ = λ M φ, K_0 = K + J^T diag(k_r) J, by subspace iteration with Rayleigh–Ritz (K. J.
 * Bathe, Finite Element Procedures, 2nd ed., 2014, Sec. 11.6, eqs. 11.112–11.117): a block X of
 * p = min(n, max(2(k+1), k+9)) vectors (Bathe's q = min(2p, p + 8) for p wanted modes),
 *
 *     K_0 X̄ = M X,   K_r = X̄^T M X,   M_r = X̄^T M X̄,   K_r Q = M_r Q Λ (Q^T M_r Q = I),
 *     X <- X̄ Q,
 *
 * K_0 factored once by CHOLMOD (L L^T: a K_0 that is not positive definite is refused), the
 * small p x p problem by nma_eigen.c's dense solver. Converged when the first k+1 Ritz values
 * change by at most 1e-12 of themselves (Bathe's criterion, eq. 11.124) and each of their
 * vectors φ_i is an eigenvector to 1e-10: ‖φ_i − λ_i K_0^-1 M φ_i‖_M, the inverse iteration's
 * residual, the sine of φ_i's angle with its image (Bathe's error measure, eq. 11.126, formed
 * without its 1 − cos² cancellation); a Ritz value converges as the square of its vector, and
 * φ itself enters ξ_k and the amplitude of first slip. The mode is then checked by its backward
 * error ‖K_0 φ − λ M φ‖ / ((‖K_0‖_1 + λ ‖M‖_1) ‖φ‖) (F. Tisseur, Backward error and condition of
 * polynomial eigenvalue problems, Linear Algebra Appl. 309, 2000, Thm. 1). The start is M's
 * diagonal (Bathe Sec. 11.6.3) and pseudo-random vectors of a fixed seed, so that no mode is
 * missed for want of a component. M is factored too, only to refuse one that is not positive
 * definite as the dense path does (a pivot not above 1e-14 of its largest diagonal entry). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/sparse_factor.h"
#include "nma_internal.h"

#define RITZ_TOL 1e-12
#define VECTOR_TOL 1e-10
#define BACKWARD_TOL 1e-10
#define MAX_ITERATIONS 300

/* The iteration's arrays, all or nothing: n x p blocks column-major (column c at c n). */
struct subspace {
    size_t n, p;
    double *X, *Y, *Yb;      /* [n p] each: Ritz vectors, M X, M X̄ */
    double *Kr, *Mr, *V, *Q; /* [p p] each, row-major */
    double *work;            /* [5 p] the eigensolver's */
    double *lam, *lam_old;   /* [p] each: Ritz values */
    double *eps;             /* [p] the vectors' inverse-iteration residuals */
};

static void subspace_free(struct subspace *s)
{
    free(s->X);
    free(s->Kr);
}

static int subspace_alloc(struct subspace *s, size_t n, size_t p)
{
    *s = (struct subspace){.n = n, .p = p};
    s->X = malloc(3 * n * p * sizeof *s->X);
    s->Kr = calloc(4 * p * p + 8 * p, sizeof *s->Kr);
    if (s->X == NULL || s->Kr == NULL) {
        subspace_free(s);
        return FRICREG_ENOMEM;
    }
    s->Y = s->X + n * p;
    s->Yb = s->Y + n * p;
    s->Mr = s->Kr + p * p;
    s->V = s->Mr + p * p;
    s->Q = s->V + p * p;
    s->work = s->Q + p * p;
    s->lam = s->work + 5 * p;
    s->lam_old = s->lam + p;
    s->eps = s->lam_old + p;
    return FRICREG_OK;
}

/* y = A x on the model's pattern (both triangles), A's values v. */
static void pattern_apply(const fricreg_hb *hb, const double *v, const double *x, double *y)
{
    memset(y, 0, hb->n * sizeof *y);
    for (size_t j = 0; j < hb->n; j++)
        for (int64_t q = hb->Dp[j]; q < hb->Dp[j + 1]; q++)
            y[hb->Di[q]] += v[q] * x[j];
}

/* y = K_0 x = K x + J^T diag(k_r) J x. */
static void stuck_apply(const fricreg_hb *hb, const double *x, double *y)
{
    size_t n = hb->n;
    pattern_apply(hb, hb->vK, x, y);
    for (size_t r = 0; r < hb->m; r++) {
        double k, limit, jx = 0.0;
        fr_hb_nma_row(hb, r, &k, &limit);
        const double *Jr = hb->J + r * n;
        for (size_t i = 0; i < n && k > 0.0; i++)
            jx += Jr[i] * x[i];
        for (size_t i = 0; i < n && k > 0.0 && jx != 0.0; i++)
            y[i] += k * jx * Jr[i];
    }
}

/* ‖A‖_1 on the pattern (the largest absolute column sum). */
static double pattern_norm1(const fricreg_hb *hb, const double *v)
{
    double norm = 0.0;
    for (size_t j = 0; j < hb->n; j++) {
        double s = 0.0;
        for (int64_t q = hb->Dp[j]; q < hb->Dp[j + 1]; q++)
            s += fabs(v[q]);
        norm = fmax(norm, s);
    }
    return norm;
}

/* K_0's upper triangle (stype 1): K's nonzeros and, per row r of J with k_r > 0, the products
 * of its nonzeros (J's rows are sparse for an element: the dofs it joins). NULL: no memory. */
static cholmod_sparse *stuck_stiffness(fricreg_hb *hb, int64_t *cols)
{
    size_t n = hb->n, count = 0;
    for (size_t j = 0; j < n; j++)
        for (int64_t q = hb->Dp[j]; q < hb->Dp[j + 1]; q++)
            count += (size_t)hb->Di[q] <= j && hb->vK[q] != 0.0;
    for (size_t r = 0; r < hb->m; r++) {
        double k, limit;
        fr_hb_nma_row(hb, r, &k, &limit);
        size_t nz = 0;
        for (size_t i = 0; i < n && k > 0.0; i++)
            nz += hb->J[r * n + i] != 0.0;
        if (nz > 0 && (nz + 1) / 2 > (SIZE_MAX / 4 - count) / nz)
            return NULL; /* a dense row of J on a huge model: beyond any memory */
        count += nz * (nz + 1) / 2;
    }
    cholmod_triplet *T = cholmod_l_allocate_triplet(n, n, count ? count : 1, 1, CHOLMOD_REAL,
                                                    &hb->cc);
    if (T == NULL)
        return NULL;
    SuiteSparse_long *Ti = T->i, *Tj = T->j;
    double *Tx = T->x;
    size_t t = 0;
    for (size_t j = 0; j < n; j++)
        for (int64_t q = hb->Dp[j]; q < hb->Dp[j + 1]; q++)
            if ((size_t)hb->Di[q] <= j && hb->vK[q] != 0.0) {
                Ti[t] = hb->Di[q];
                Tj[t] = (SuiteSparse_long)j;
                Tx[t++] = hb->vK[q];
            }
    for (size_t r = 0; r < hb->m; r++) {
        double k, limit;
        fr_hb_nma_row(hb, r, &k, &limit);
        const double *Jr = hb->J + r * n;
        size_t nz = 0;
        for (size_t i = 0; i < n && k > 0.0; i++)
            if (Jr[i] != 0.0)
                cols[nz++] = (int64_t)i;
        for (size_t a = 0; a < nz; a++)
            for (size_t b = a; b < nz; b++) { /* cols ascending: (a, b) in the upper triangle */
                Ti[t] = cols[a];
                Tj[t] = cols[b];
                Tx[t++] = k * Jr[cols[a]] * Jr[cols[b]];
            }
    }
    T->nnz = t;
    cholmod_sparse *A = cholmod_l_triplet_to_sparse(T, t, &hb->cc); /* duplicates summed */
    cholmod_l_free_triplet(&T, &hb->cc);
    return A;
}

/* A's L L^T factor (the ordering AMD; simplicial if asked), or NULL with *status set:
 * FRICREG_ENOTPSD (not positive definite; *minor its column), FRICREG_ENOMEM, FRICREG_EINVAL. */
static cholmod_factor *factor(fricreg_hb *hb, cholmod_sparse *A, int simplicial, int *status,
                              size_t *minor)
{
    fr_cholmod_ordering(&hb->cc, CHOLMOD_AMD, simplicial);
    cholmod_factor *L = cholmod_l_analyze(A, &hb->cc);
    if (L != NULL)
        cholmod_l_factorize(A, L, &hb->cc);
    *status = fr_cholmod_status(hb->cc.status);
    if (*status == FRICREG_OK && (L == NULL || L->minor < L->n))
        *status = L == NULL ? FRICREG_ENOMEM : FRICREG_ENOTPSD;
    if (*status != FRICREG_OK) {
        *minor = L != NULL ? (size_t)L->minor : 0;
        cholmod_l_free_factor(&L, &hb->cc);
    }
    return L;
}

/* M positive definite as the dense path has it: CHOLMOD's factor of M exists and its smallest
 * pivot (L_jj², simplicial) is above 1e-14 of M's largest diagonal entry. */
static int check_mass(fricreg_hb *hb, const char *fn)
{
    int status;
    size_t minor = 0;
    cholmod_factor *L = factor(hb, hb->Ms, 1, &status, &minor);
    if (status == FRICREG_ENOTPSD)
        return fr_fail(hb, status, "%s: M is not positive definite (no Cholesky factor)", fn);
    if (status != FRICREG_OK)
        return fr_fail(hb, status, "%s: %s of M's sparse factor", fn,
                       status == FRICREG_ENOMEM ? "no memory" : "CHOLMOD's failure");
    double dmax = 0.0, dmin = INFINITY;
    for (size_t j = 0; j < hb->n; j++)
        for (int64_t q = hb->Dp[j]; q < hb->Dp[j + 1]; q++)
            if ((size_t)hb->Di[q] == j)
                dmax = fmax(dmax, hb->vM[q]);
    const SuiteSparse_long *Lp = L->p;
    const double *Lx = L->x;
    for (size_t j = 0; j < hb->n; j++) { /* simplicial: column j's diagonal comes first */
        double d = Lx[Lp[j]];
        dmin = fmin(dmin, L->is_ll ? d * d : d);
    }
    cholmod_l_free_factor(&L, &hb->cc);
    if (!(dmin > 1e-14 * dmax))
        return fr_fail(hb, FRICREG_ENOTPSD,
                       "%s: M is not positive definite (a pivot of its Cholesky factor, %g, not "
                       "above 1e-14 of its largest diagonal entry %g)",
                       fn, dmin, dmax);
    return FRICREG_OK;
}

/* The start: M's diagonal, then pseudo-random entries in [-1, 1) (xorshift64, G. Marsaglia,
 * J. Stat. Softw. 8(14), 2003; a fixed seed: the same start every call). */
static void start(const fricreg_hb *hb, struct subspace *s)
{
    uint64_t state = 0x9E3779B97F4A7C15u;
    for (size_t j = 0; j < s->n; j++)
        for (int64_t q = hb->Dp[j]; q < hb->Dp[j + 1]; q++)
            if ((size_t)hb->Di[q] == j)
                s->X[j] = hb->vM[q];
    for (size_t e = s->n; e < s->n * s->p; e++) {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        s->X[e] = (double)(state >> 11) * 0x1.0p-52 - 1.0;
    }
    for (size_t c = 0; c < s->p; c++)
        pattern_apply(hb, hb->vM, s->X + c * s->n, s->Y + c * s->n);
}

/* out[r][c] = A_r · B_c over n, A and B n x p column-major, out p x p row-major. */
static void gram(const double *A, const double *B, size_t n, size_t p, double *out)
{
    for (size_t r = 0; r < p; r++)
        for (size_t c = 0; c < p; c++) {
            double sum = 0.0;
            for (size_t i = 0; i < n; i++)
                sum += A[r * n + i] * B[c * n + i];
            out[r * p + c] = sum;
        }
    for (size_t r = 0; r < p; r++) /* symmetric in exact arithmetic */
        for (size_t c = 0; c < r; c++)
            out[r * p + c] = out[c * p + r] = 0.5 * (out[r * p + c] + out[c * p + r]);
}

/* B <- B Q (n x p column-major, Q p x p row-major), through the scratch row tmp [p]. */
static void rotate(double *B, const double *Q, size_t n, size_t p, double *tmp)
{
    for (size_t i = 0; i < n; i++) {
        for (size_t c = 0; c < p; c++) {
            double sum = 0.0;
            for (size_t r = 0; r < p; r++)
                sum += B[r * n + i] * Q[r * p + c];
            tmp[c] = sum;
        }
        for (size_t c = 0; c < p; c++)
            B[c * n + i] = tmp[c];
    }
}

/* The inverse-iteration residuals ‖φ_i − λ_i z_i‖_M of the current Ritz vectors φ_i = X_i
 * (M φ_i = Y_i, λ_i = lam) against their images z_i = Xb_i (M z_i = Yb_i), i < want. */
static void residuals(struct subspace *s, const double *Xb, size_t want)
{
    size_t n = s->n;
    for (size_t c = 0; c < want; c++) {
        const double *x = s->X + c * n, *y = s->Y + c * n, *xb = Xb + c * n, *yb = s->Yb + c * n;
        double l = s->lam[c], sum = 0.0;
        for (size_t i = 0; i < n; i++)
            sum += (x[i] - l * xb[i]) * (y[i] - l * yb[i]);
        s->eps[c] = sqrt(fabs(sum));
    }
}

/* The Rayleigh–Ritz step on Kr, Mr: Ritz values into lam, M_r-orthonormal Q. FRICREG_OK,
 * FRICREG_ENONFINITE, FRICREG_EWORK (M_r not positive definite: the block lost its rank). */
static int ritz(struct subspace *s)
{
    size_t p = s->p, bad = 0;
    for (size_t e = 0; e < p * p; e++)
        if (!isfinite(s->Kr[e]) || !isfinite(s->Mr[e]))
            return FRICREG_ENONFINITE;
    if (fr_hb_nma_cholesky(s->Mr, p) != FRICREG_OK)
        return FRICREG_EWORK;
    fr_hb_nma_reduce(s->Mr, s->Kr, p);
    int status = fr_hb_nma_symmv(s->Kr, s->V, s->work, p, &bad);
    if (status != FRICREG_OK)
        return status == FRICREG_ENONFINITE ? status : FRICREG_EWORK;
    double *col = s->work + p; /* the eigensolver's workspace, free again */
    for (size_t c = 0; c < p; c++) {
        s->lam[c] = s->work[c];
        fr_hb_nma_back(s->Mr, s->V, p, c, col);
        for (size_t r = 0; r < p; r++)
            s->Q[r * p + c] = col[r];
    }
    return FRICREG_OK;
}

/* The iteration on K_0's factor L0 until mode `want − 1` and those below converged. FRICREG_OK,
 * FRICREG_ENONFINITE, FRICREG_EWORK, FRICREG_ENOMEM (no message). */
static int iterate(fricreg_hb *hb, cholmod_factor *L0, struct subspace *s, size_t want,
                   int *iterations)
{
    size_t n = s->n, p = s->p;
    cholmod_dense B = {.nrow = n,
                       .ncol = p,
                       .nzmax = n * p,
                       .d = n,
                       .x = s->Y,
                       .xtype = CHOLMOD_REAL,
                       .dtype = CHOLMOD_DOUBLE};
    for (int it = 0; it < MAX_ITERATIONS; it++) {
        cholmod_dense *Xb = cholmod_l_solve(CHOLMOD_A, L0, &B, &hb->cc); /* K_0 X̄ = M X */
        if (Xb == NULL)
            return fr_cholmod_status(hb->cc.status) == FRICREG_ENOMEM ? FRICREG_ENOMEM
                                                                      : FRICREG_EINVAL;
        const double *xb = Xb->x;
        for (size_t c = 0; c < p; c++)
            pattern_apply(hb, hb->vM, xb + c * n, s->Yb + c * n);
        gram(xb, s->Y, n, p, s->Kr);
        gram(xb, s->Yb, n, p, s->Mr);
        if (it > 0)
            residuals(s, xb, want);
        memcpy(s->lam_old, s->lam, p * sizeof *s->lam);
        int status = ritz(s);
        if (status == FRICREG_OK) {
            memcpy(s->X, xb, n * p * sizeof *s->X);
            rotate(s->X, s->Q, n, p, s->work);
            memcpy(s->Y, s->Yb, n * p * sizeof *s->Y);
            rotate(s->Y, s->Q, n, p, s->work);
        }
        cholmod_l_free_dense(&Xb, &hb->cc);
        if (status != FRICREG_OK)
            return status;
        int done = it > 0;
        for (size_t c = 0; c < want && done; c++)
            done = fabs(s->lam[c] - s->lam_old[c]) <= RITZ_TOL * fabs(s->lam[c]) &&
                   s->eps[c] <= VECTOR_TOL;
        if (done) {
            *iterations = it + 1;
            return FRICREG_OK;
        }
    }
    *iterations = MAX_ITERATIONS;
    return FRICREG_EWORK;
}

/* The backward error of (λ, φ) as eigenpair of (K_0, M), scratch r and t [n] each. */
static double backward_error(const fricreg_hb *hb, const double *phi, double lambda, double *r,
                             double *t)
{
    size_t n = hb->n;
    stuck_apply(hb, phi, r);
    pattern_apply(hb, hb->vM, phi, t);
    double k0 = pattern_norm1(hb, hb->vK), res = 0.0, norm = 0.0;
    for (size_t row = 0; row < hb->m; row++) { /* ‖J^T diag(k) J‖_1 <= Σ k ‖J_r‖_∞ ‖J_r‖_1 */
        double k, limit, big = 0.0, sum = 0.0;
        fr_hb_nma_row(hb, row, &k, &limit);
        for (size_t i = 0; i < n; i++) {
            big = fmax(big, fabs(hb->J[row * n + i]));
            sum += fabs(hb->J[row * n + i]);
        }
        k0 += k * big * sum;
    }
    for (size_t i = 0; i < n; i++) {
        double d = r[i] - lambda * t[i];
        res += d * d;
        norm += phi[i] * phi[i];
    }
    return sqrt(res) / ((k0 + fabs(lambda) * pattern_norm1(hb, hb->vM)) * sqrt(norm));
}

/* The mode from the factored K_0: the message of any failure recorded. */
static int solve(fricreg_hb *hb, const char *fn, cholmod_factor *L0, size_t mode, double *phi,
                 double *lambda)
{
    size_t n = hb->n, want = mode + 1;
    size_t p = want + 8 > 2 * want ? want + 8 : 2 * want;
    p = p < n ? p : n;
    struct subspace s;
    if (subspace_alloc(&s, n, p) != FRICREG_OK)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the subspace iteration", fn);
    start(hb, &s);
    int iterations = 0, status = iterate(hb, L0, &s, want, &iterations);
    if (status == FRICREG_OK) {
        memcpy(phi, s.X + mode * n, n * sizeof *phi);
        *lambda = s.lam[mode];
        double eta = backward_error(hb, phi, *lambda, s.Y, s.Yb);
        if (!(eta <= BACKWARD_TOL))
            status = fr_fail(hb, FRICREG_EWORK,
                             "%s: the subspace iteration's mode %zu has a backward error %g "
                             "(above %g)",
                             fn, mode, eta, BACKWARD_TOL);
    } else if (status == FRICREG_EWORK)
        fr_fail(hb, status,
                "%s: the subspace iteration for mode %zu (%zu vectors) did not converge in %d "
                "iterations (Ritz values to %g, vectors to %g)",
                fn, mode, p, iterations, RITZ_TOL, VECTOR_TOL);
    else if (status == FRICREG_ENONFINITE)
        fr_fail(hb, status,
                "%s: the subspace iteration overflows (M and K of scales too far apart)", fn);
    else
        fr_fail(hb, status, "%s: %s in the subspace iteration's solves", fn,
                status == FRICREG_ENOMEM ? "no memory" : "CHOLMOD failed");
    subspace_free(&s);
    return status;
}

int fr_hb_nma_sparse_mode(fricreg_hb *hb, const char *fn, size_t mode, double *phi, double *lambda)
{
    int status = check_mass(hb, fn);
    if (status != FRICREG_OK)
        return status;
    int64_t *cols = malloc(hb->n * sizeof *cols);
    cholmod_sparse *K0 = cols != NULL ? stuck_stiffness(hb, cols) : NULL;
    free(cols);
    if (K0 == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for K + J^T diag(k) J", fn);
    size_t minor = 0;
    cholmod_factor *L0 = factor(hb, K0, 0, &status, &minor);
    cholmod_l_free_sparse(&K0, &hb->cc);
    if (status == FRICREG_ENOTPSD)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: the structure with its elements stuck has a mode of omega^2 <= 0 (K + "
                       "J^T diag(kt) J is not positive definite: CHOLMOD's factor stops at column "
                       "%zu)",
                       fn, minor);
    if (status != FRICREG_OK)
        return fr_fail(hb, status, "%s: %s of K + J^T diag(kt) J's sparse factor", fn,
                       status == FRICREG_ENOMEM ? "no memory" : "CHOLMOD's failure");
    status = solve(hb, fn, L0, mode, phi, lambda);
    cholmod_l_free_factor(&L0, &hb->cc);
    return status;
}
