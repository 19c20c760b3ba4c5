/* SPDX-License-Identifier: GPL-3.0-or-later */
/* capacitance.c — Newton's matrix A = I + Ĝ Ĵ of (R) solved through its capacitance on the
 * rows of Ĵ that are not a stiffness on the diagonal, instead of a dense LU of order nq.
 *
 * Ĝ couples every element's coefficients but only within a harmonic (G_h); Ĵ couples the
 * harmonics but only within an element, and many of its rows are k e_iᵀ: a stuck element's
 * harmonics h >= 1 (kt), a closed contact's normal rows (kn), rows of no force (0). With those
 * rows L and the others S, Ĵ = P_L K_L P_Lᵀ + P_S Ĵ_S, and A = A0 + Ĝ P_S Ĵ_S where
 * A0 = I + Ĝ P_L K_L P_Lᵀ is block lower triangular in (L, S), its L block I + G_h,LL K_L one
 * complex matrix a harmonic. Woodbury's identity (Golub & Van Loan, Matrix Computations, 4th
 * ed., Sec. 2.1.4) then solves A through C = I + Ĵ_S W, W = A0⁻¹ Ĝ P_S, of order s = |S|:
 * A⁻¹ = A0⁻¹ − W C⁻¹ Ĵ_S A0⁻¹; a border [A b; cᵀ d] by block elimination into C's last row
 * and column (det C = det A (d − cᵀ A⁻¹ b) / det A0). Where every contact slips but is closed,
 * s = 2 nq / 3 (the LU's work 0.3 of the dense one); where most stick, s is a few rows an
 * element.
 *
 * The real form of fr_hb_apply maps x to y with Y = G_h X, X = x_a − i x_b (harmonic h >= 1,
 * x_0 for h = 0), so Ĝ's column of unknown (r, a) is G_h's column r and that of (r, b) is
 * −i times it; W's, A0⁻¹ of those, are held as complex columns Z (column-major, the harmonic's
 * L rows then its S rows). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/free_all.h"
#include "base/lapack.h"
#include "capacitance.h"
#include "hb_internal.h"
#include "lu.h"

struct fr_hb_capacitance {
    size_t m, H1, nq;    /* the room's shape */
    double *k;           /* [H1 m] the stiffness of row r of harmonic h when in L */
    size_t *rows;        /* [H1 m] harmonic h's L rows (nl[h]) then its S rows, at h m */
    size_t *pos;         /* [H1 m] row r's place in that order */
    size_t *nl, *ns;     /* [H1] each */
    size_t *elem;        /* [m] the element of each row of J */
    double *Mf;          /* [H1 m m] complex: I + G_h,LL K_L, LU-factored, at h m m */
    int *mpiv;           /* [H1 m] its interchanges */
    double *Z;           /* [H1 m m] complex: A0⁻¹ Ĝ's S columns of harmonic h, column-major */
    double *X, *T;       /* [m m] complex scratch each */
    size_t *sj;          /* [nq] the S unknowns' indices in q, ascending */
    size_t *sc;          /* [nq] each one's column of Z (its row's place among the S rows) */
    size_t s, nd;        /* |S|, the order of A (nq + 1: bordered) */
    double *col, *row;   /* [nq + 1] each: the border */
    double *yb, *y, *rc; /* [nq + 1] each: A0⁻¹ col, scratch, C's right-hand side */
    double *work;        /* [2 m] complex scratch */
    int factored;
    /* each harmonic's L rows and stiffnesses when its Mf and Z were made, and G_h's serial
     * then: a harmonic whose split and G_h stay keeps them (a continuation in the level, or
     * Newton at one Ω, between changes of the stick/slip pattern) */
    size_t *kept_rows, *kept_nl;
    double *kept_k;
    unsigned long *kept_serial; /* [H1], 0: none */
};

void fr_hb_capacitance_free(fricreg_hb *hb)
{
    struct fr_hb_capacitance *c = hb->capacitance;
    if (c == NULL)
        return;
    FR_FREE_ALL(c->kept_rows, c->kept_nl, c->kept_k, c->kept_serial);
    FR_FREE_ALL(c->k, c->rows, c->pos, c->nl, c->ns, c->elem, c->Mf, c->mpiv, c->Z, c->X, c->T,
                c->sj, c->sc, c->col, c->row, c->yb, c->y, c->rc, c->work);
    free(c);
    hb->capacitance = NULL;
}

static void *room(size_t count, size_t size)
{
    return count > 0 && count <= SIZE_MAX / size ? malloc(count * size) : NULL;
}

int fr_hb_capacitance_reserve(fricreg_hb *hb)
{
    struct fr_hb_capacitance *c = hb->capacitance;
    size_t m = hb->m, H1 = (size_t)hb->H + 1, nq = hb->nq;
    if (c != NULL && c->m == m && c->H1 == H1)
        return 1;
    fr_hb_capacitance_free(hb);
    if (m > SIZE_MAX / (2 * H1 * m) / sizeof(double))
        return 0;
    c = calloc(1, sizeof *c);
    if (c == NULL)
        return 0;
    hb->capacitance = c;
    *c = (struct fr_hb_capacitance){.m = m, .H1 = H1, .nq = nq};
    size_t hm = H1 * m, hmm = 2 * H1 * m * m;
    c->k = room(hm, sizeof(double));
    c->rows = room(hm, sizeof(size_t));
    c->pos = room(hm, sizeof(size_t));
    c->nl = room(H1, sizeof(size_t));
    c->ns = room(H1, sizeof(size_t));
    c->elem = room(m, sizeof(size_t));
    c->Mf = room(hmm, sizeof(double));
    c->mpiv = room(hm, sizeof(int));
    c->Z = room(hmm, sizeof(double));
    c->X = room(2 * m * m, sizeof(double));
    c->T = room(2 * m * m, sizeof(double));
    c->sj = room(nq, sizeof(size_t));
    c->sc = room(nq, sizeof(size_t));
    c->col = room(nq + 1, sizeof(double));
    c->row = room(nq + 1, sizeof(double));
    c->yb = room(nq + 1, sizeof(double));
    c->y = room(nq + 1, sizeof(double));
    c->rc = room(nq + 1, sizeof(double));
    c->work = room(2 * m, sizeof(double));
    c->kept_rows = room(hm, sizeof(size_t));
    c->kept_nl = room(H1, sizeof(size_t));
    c->kept_k = room(hm, sizeof(double));
    c->kept_serial = calloc(H1, sizeof(unsigned long));
    if (!c->k || !c->rows || !c->pos || !c->nl || !c->ns || !c->elem || !c->Mf || !c->mpiv ||
        !c->Z || !c->X || !c->T || !c->sj || !c->sc || !c->col || !c->row || !c->yb || !c->y ||
        !c->rc || !c->work || !c->kept_rows || !c->kept_nl || !c->kept_k || !c->kept_serial) {
        fr_hb_capacitance_free(hb);
        return 0;
    }
    return 1;
}

/* The rounding below which an entry of a Jacobian block counts as none: its sampled AFT's
 * DFT leaves entries of order u · (the block's largest) where the exact ones are 0. */
#define ROUNDING 1e-12

/* Whether row i of a block [b b] whose largest entry is jmax is k e_iᵀ, its k into *k. */
static int diagonal_row(const double *J, size_t b, size_t i, double jmax, double *k)
{
    for (size_t j = 0; j < b; j++)
        if (j != i && fabs(J[i * b + j]) > ROUNDING * jmax)
            return 0;
    *k = J[i * b + i];
    return 1;
}

/* Row r of harmonic h in L (a stiffness on the diagonal, the same on a and b) or S. */
static int in_l(const fricreg_hb *hb, size_t r, int h, size_t e, double *k)
{
    size_t nc = hb->nc, b = fr_hb_rows_of(hb, e) * nc, i = (r - hb->erow[e]) * nc;
    const double *J = fr_hb_block_of(hb, e);
    double jmax = 0.0, kb;
    for (size_t j = 0; j < b * b; j++)
        jmax = fmax(jmax, fabs(J[j]));
    if (h == 0)
        return diagonal_row(J, b, i, jmax, k);
    size_t ia = i + 2 * (size_t)h - 1;
    return diagonal_row(J, b, ia, jmax, k) && diagonal_row(J, b, ia + 1, jmax, &kb) &&
           fabs(kb - *k) <= ROUNDING * jmax;
}

size_t fr_hb_capacitance_split(fricreg_hb *hb, size_t nd, const double *col, const double *row)
{
    size_t m = hb->m, nc = hb->nc, nq = hb->nq;
    struct fr_hb_capacitance *c = hb->capacitance;
    if (c == NULL || c->m != m || c->H1 != (size_t)hb->H + 1) /* no room: the dense LU */
        return nq + 1;
    for (size_t e = 0; e < hb->count; e++)
        for (size_t r = hb->erow[e]; r < hb->erow[e + 1]; r++)
            c->elem[r] = e;
    for (size_t h = 0; h < c->H1; h++) {
        size_t *rows = c->rows + h * m, nl = 0, ns = 0;
        for (size_t r = 0; r < m; r++) /* L rows from the front, S rows from the back */
            if (in_l(hb, r, (int)h, c->elem[r], c->k + h * m + r))
                rows[nl++] = r;
            else {
                c->k[h * m + r] = 0.0; /* none: the kept split compares it */
                rows[m - 1 - ns++] = r;
            }
        for (size_t a = nl, z = m - 1; a < z; a++, z--) { /* S rows ascending */
            size_t t = rows[a];
            rows[a] = rows[z];
            rows[z] = t;
        }
        for (size_t p = 0; p < m; p++)
            c->pos[h * m + rows[p]] = p;
        c->nl[h] = nl;
        c->ns[h] = ns;
    }
    c->s = 0;
    for (size_t j = 0; j < nq; j++) {
        size_t r = j / nc, h = (j % nc + 1) / 2, p = c->pos[h * m + r];
        if (p >= c->nl[h]) {
            c->sj[c->s] = j;
            c->sc[c->s++] = p - c->nl[h];
        }
    }
    c->nd = nd;
    if (nd > nq) {
        memcpy(c->col, col, nq * sizeof(double));
        memcpy(c->row, row, (nq + 1) * sizeof(double));
    }
    c->factored = 0;
    return c->s;
}

/* y[nq] = A0⁻¹ v[nq] (v == y allowed): each harmonic's L part by its factor, its S part
 * v_S − G_h,SL K_L y_L. */
static void stuck_solve(const fricreg_hb *hb, const double *v, double *y)
{
    const struct fr_hb_capacitance *c = hb->capacitance;
    size_t m = hb->m, nc = hb->nc;
    for (size_t h = 0; h < c->H1; h++) {
        const size_t *rows = c->rows + h * m, nl = c->nl[h], ns = c->ns[h];
        const double *G = hb->G + 2 * h * m * m, *k = c->k + h * m;
        double *w = c->work;
        for (size_t p = 0; p < m; p++) { /* V = v_a − i v_b, in the order L then S */
            size_t r = rows[p];
            w[2 * p] = h == 0 ? v[r * nc] : v[r * nc + 2 * h - 1];
            w[2 * p + 1] = h == 0 ? 0.0 : -v[r * nc + 2 * h];
        }
        if (nl > 0)
            fr_hb_zlu_solve_factored(c->Mf + 2 * h * m * m, nl, c->mpiv + h * m, w);
        for (size_t p = nl; p < nl + ns; p++) {
            const double *g = G + 2 * rows[p] * m;
            for (size_t i = 0; i < nl; i++) {
                double gr = g[2 * rows[i]] * k[rows[i]], gi = g[2 * rows[i] + 1] * k[rows[i]];
                w[2 * p] -= gr * w[2 * i] - gi * w[2 * i + 1];
                w[2 * p + 1] -= gr * w[2 * i + 1] + gi * w[2 * i];
            }
        }
        for (size_t p = 0; p < m; p++) {
            size_t r = rows[p];
            if (h == 0) {
                y[r * nc] = w[2 * p];
                continue;
            }
            y[r * nc + 2 * h - 1] = w[2 * p];
            y[r * nc + 2 * h] = -w[2 * p + 1];
        }
    }
}

/* Whether harmonic h's Mf and Z are those of its split and G_h (factor serial); else they
 * will be, once made. */
static int kept(struct fr_hb_capacitance *c, size_t h, unsigned long serial)
{
    size_t m = c->m, *rows = c->rows + h * m, nl = c->nl[h];
    double *k = c->k + h * m;
    int same = serial != 0 && c->kept_serial[h] == serial && c->kept_nl[h] == nl &&
               memcmp(c->kept_rows + h * m, rows, m * sizeof *rows) == 0 &&
               memcmp(c->kept_k + h * m, k, m * sizeof *k) == 0;
    c->kept_serial[h] = serial;
    c->kept_nl[h] = nl;
    memcpy(c->kept_rows + h * m, rows, m * sizeof *rows);
    memcpy(c->kept_k + h * m, k, m * sizeof *k);
    return same;
}

/* Harmonic h's columns Z = A0⁻¹ Ĝ P_S: its L block M = I + G_LL K_L factored, Z_L = M⁻¹ G_LS,
 * Z_S = G_SS − G_SL K_L Z_L (zgemm). 0, or 1 where M is singular. */
static int harmonic_columns(fricreg_hb *hb, size_t h)
{
    struct fr_hb_capacitance *c = hb->capacitance;
    size_t m = hb->m, nl = c->nl[h], ns = c->ns[h];
    if (kept(c, h, hb->factor_serial))
        return 0;
    const size_t *rows = c->rows + h * m, *sr = rows + nl;
    const double *G = hb->G + 2 * h * m * m, *k = c->k + h * m;
    double *M = c->Mf + 2 * h * m * m, *Z = c->Z + 2 * h * m * m, *X = c->X, *T = c->T;
    double amax = 0.0;
    for (size_t i = 0; i < nl; i++)
        for (size_t j = 0; j < nl; j++) {
            const double *g = G + 2 * (rows[i] * m + rows[j]);
            double *a = M + 2 * (i * nl + j);
            a[0] = (i == j) + g[0] * k[rows[j]];
            a[1] = g[1] * k[rows[j]];
            amax = fmax(amax, fabs(a[0]) + fabs(a[1]));
        }
    if (nl > 0)
        fr_hb_zlu_factor(M, nl, c->mpiv + h * m);
    for (size_t i = 0; i < nl; i++) {
        double p = fabs(M[2 * (i * nl + i)]) + fabs(M[2 * (i * nl + i) + 1]);
        if (!(p > 1e-14 * amax)) {
            c->kept_serial[h] = 0; /* nothing kept */
            return 1;
        }
    }
    for (size_t q = 0; q < ns; q++)
        for (size_t i = 0; i < nl; i++) {
            const double *g = G + 2 * (rows[i] * m + sr[q]);
            X[2 * (q * nl + i)] = g[0];
            X[2 * (q * nl + i) + 1] = g[1];
        }
    if (nl > 0 && ns > 0)
        fr_hb_zlu_solve_many(M, nl, c->mpiv + h * m, ns, X);
    for (size_t q = 0; q < ns; q++) {
        memcpy(Z + 2 * q * m, X + 2 * q * nl, 2 * nl * sizeof(double));
        for (size_t j = 0; j < ns; j++) {
            const double *g = G + 2 * (sr[j] * m + sr[q]);
            Z[2 * (q * m + nl + j)] = g[0];
            Z[2 * (q * m + nl + j) + 1] = g[1];
        }
    }
    if (nl == 0 || ns == 0)
        return 0;
    for (size_t i = 0; i < nl; i++) /* T = G_SL K_L, column-major ns x nl */
        for (size_t j = 0; j < ns; j++) {
            const double *g = G + 2 * (sr[j] * m + rows[i]);
            T[2 * (i * ns + j)] = g[0] * k[rows[i]];
            T[2 * (i * ns + j) + 1] = g[1] * k[rows[i]];
        }
    int ins = (int)ns, inl = (int)nl, ldz = (int)m;
    const double minus[2] = {-1.0, 0.0}, one[2] = {1.0, 0.0};
    zgemm_("N", "N", &ins, &ins, &inl, minus, T, &ins, X, &inl, one, Z + 2 * nl, &ldz, 1, 1);
    return 0;
}

/* W's entry at unknown j = (r, c) of q (c in harmonic h) and S column l (of harmonic h). */
static double w_entry(const struct fr_hb_capacitance *c, size_t r, size_t h, int b_row, size_t l,
                      size_t nc)
{
    size_t j = c->sj[l], m = c->m;
    const double *z = c->Z + 2 * (h * m * m + c->sc[l] * m + c->pos[h * m + r]);
    int b_col = h > 0 && (j % nc) == 2 * h; /* column (r2, b): −i times column (r2, a) */
    if (!b_col)
        return b_row ? -z[1] : z[0];
    return b_row ? z[0] : z[1];
}

/* Σ_j Ĵ[i, j] x_j over element e's columns, i its block's row bi. */
static double block_row_dot(const fricreg_hb *hb, size_t e, size_t bi, const double *x)
{
    size_t b = fr_hb_rows_of(hb, e) * hb->nc, at = hb->erow[e] * hb->nc;
    const double *J = fr_hb_block_of(hb, e) + bi * b;
    double s = 0.0;
    for (size_t j = 0; j < b; j++)
        s += J[j] * x[at + j];
    return s;
}

/* C = I + Ĵ_S W into A (row-major, order s + border), bordered by Ĵ_S A0⁻¹ col, −c_qᵀ W and
 * d − c_qᵀ A0⁻¹ col. */
static void capacitance_matrix(fricreg_hb *hb)
{
    struct fr_hb_capacitance *c = hb->capacitance;
    size_t s = c->s, nc = hb->nc, nq = hb->nq, border = c->nd > nq, ld = s + border;
    double *C = hb->A;
    for (size_t a = 0; a < s; a++) {
        size_t i = c->sj[a], r = i / nc, e = c->elem[r], e0 = hb->erow[e];
        size_t rows = fr_hb_rows_of(hb, e), b = rows * nc, bi = (r - e0) * nc + i % nc;
        const double *J = fr_hb_block_of(hb, e) + bi * b;
        for (size_t l = 0; l < s; l++) {
            size_t h = (c->sj[l] % nc + 1) / 2, ca = h == 0 ? 0 : 2 * h - 1;
            double sum = a == l ? 1.0 : 0.0;
            for (size_t t = 0; t < rows; t++) {
                sum += J[t * nc + ca] * w_entry(c, e0 + t, h, 0, l, nc);
                if (h > 0)
                    sum += J[t * nc + ca + 1] * w_entry(c, e0 + t, h, 1, l, nc);
            }
            C[a * ld + l] = sum;
        }
        if (border)
            C[a * ld + s] = block_row_dot(hb, e, bi, c->yb);
    }
    if (!border)
        return;
    for (size_t l = 0; l < s; l++) {
        size_t h = (c->sj[l] % nc + 1) / 2, ca = h == 0 ? 0 : 2 * h - 1;
        double sum = 0.0;
        for (size_t r = 0; r < hb->m; r++) {
            sum += c->row[r * nc + ca] * w_entry(c, r, h, 0, l, nc);
            if (h > 0)
                sum += c->row[r * nc + ca + 1] * w_entry(c, r, h, 1, l, nc);
        }
        C[s * ld + l] = -sum;
    }
    double d = c->row[nq];
    for (size_t j = 0; j < nq; j++)
        d -= c->row[j] * c->yb[j];
    C[s * ld + s] = d;
}

int fr_hb_capacitance_factor(fricreg_hb *hb, const char *fn)
{
    struct fr_hb_capacitance *c = hb->capacitance;
    if (c->factored)
        return FRICREG_OK;
    for (size_t h = 0; h < c->H1; h++)
        if (harmonic_columns(hb, h))
            return FR_HB_STUCK_SINGULAR;
    if (c->nd > hb->nq)
        stuck_solve(hb, c->col, c->yb);
    capacitance_matrix(hb);
    size_t ld = c->s + (c->nd > hb->nq);
    double amax = 0.0;
    for (size_t k = 0; k < ld * ld; k++)
        amax = fmax(amax, fabs(hb->A[k]));
    if (ld > 0) /* none: every row diagonal, A = A0 */
        fr_hb_lu_factor(hb->A, ld, hb->piv2);
    for (size_t k = 0; k < ld; k++) {
        double piv = fabs(hb->A[k * ld + k]);
        if (!(piv > 1e-14 * amax) || !isfinite(piv))
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: Newton's matrix is singular (pivot %zu of its capacitance's LU "
                           "factor: %g, largest entry %g)",
                           fn, k, piv, amax);
    }
    c->factored = 1;
    return FRICREG_OK;
}

void fr_hb_capacitance_solve(fricreg_hb *hb, const double *rhs, double *sol)
{
    struct fr_hb_capacitance *c = hb->capacitance;
    size_t s = c->s, nc = hb->nc, nq = hb->nq, m = hb->m, border = c->nd > nq;
    double *y = c->y, *z = c->rc;
    stuck_solve(hb, rhs, y);
    for (size_t a = 0; a < s; a++) {
        size_t i = c->sj[a], r = i / nc, e = c->elem[r];
        z[a] = block_row_dot(hb, e, (r - hb->erow[e]) * nc + i % nc, y);
    }
    if (border) {
        z[s] = rhs[nq];
        for (size_t j = 0; j < nq; j++)
            z[s] -= c->row[j] * y[j];
    }
    if (s + border > 0)
        fr_hb_lu_solve_factored(hb->A, s + border, hb->piv2, z);
    double p = border ? z[s] : 0.0;
    for (size_t j = 0; j < nq; j++)
        sol[j] = y[j] - (border ? p * c->yb[j] : 0.0);
    for (size_t h = 0; h < c->H1; h++) { /* − W z, harmonic by harmonic: Z (z_a − i z_b) */
        size_t nl = c->nl[h], ns = c->ns[h], span = nl + ns;
        double *u = c->work;
        memset(u, 0, 2 * span * sizeof(double));
        for (size_t l = 0; l < s; l++) {
            size_t j = c->sj[l];
            if ((j % nc + 1) / 2 != h)
                continue;
            int b_col = h > 0 && j % nc == 2 * h;
            double wr = b_col ? 0.0 : z[l], wi = b_col ? -z[l] : 0.0;
            const double *col = c->Z + 2 * (h * m * m + c->sc[l] * m);
            for (size_t p2 = 0; p2 < span; p2++) {
                u[2 * p2] += col[2 * p2] * wr - col[2 * p2 + 1] * wi;
                u[2 * p2 + 1] += col[2 * p2] * wi + col[2 * p2 + 1] * wr;
            }
        }
        for (size_t p2 = 0; p2 < span; p2++) {
            size_t r = c->rows[h * m + p2];
            if (h == 0) {
                sol[r * nc] -= u[2 * p2];
                continue;
            }
            sol[r * nc + 2 * h - 1] -= u[2 * p2];
            sol[r * nc + 2 * h] += u[2 * p2 + 1];
        }
    }
    if (border)
        sol[nq] = p;
}

void fr_hb_capacitance_border(const fricreg_hb *hb, const double **col, const double **row)
{
    *col = hb->capacitance->col;
    *row = hb->capacitance->row;
}

double fr_hb_capacitance_det_sign(const fricreg_hb *hb)
{
    const struct fr_hb_capacitance *c = hb->capacitance;
    size_t nl = c->nl[0], ld = c->s + (c->nd > hb->nq);
    double sign = 1.0;
    for (size_t k = 0; k < nl; k++) /* harmonic 0's block: real, in complex arithmetic */
        sign *= (c->Mf[2 * (k * nl + k)] < 0.0 ? -1.0 : 1.0) *
                (c->mpiv[k] != (int)k + 1 ? -1.0 : 1.0);
    for (size_t k = 0; k < ld; k++)
        sign *= (hb->A[k * ld + k] < 0.0 ? -1.0 : 1.0) * (hb->piv2[k] != (int)k + 1 ? -1.0 : 1.0);
    return sign;
}
