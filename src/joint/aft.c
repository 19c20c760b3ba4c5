/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft.c — the AFT workspace (fricreg_aft.h): create and free, the one input check of the
 * four evaluations, and the copy-out that leaves the caller's arrays untouched on failure.
 * The two paths are aft_exact.c and aft_sampled.c. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "aft_internal.h"
#include "base/free_all.h"

int fricreg_aft_create(int harmonics, size_t samples, fricreg_aft **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (harmonics < 1 || harmonics > FRICREG_AFT_MAX_HARMONICS)
        return FRICREG_EINVAL;
    size_t H = (size_t)harmonics, nc = 2 * H + 1, N = samples;
    if (N != 0 && (N < nc + 1 || N > FRICREG_AFT_MAX_SAMPLES || (N & (N - 1)) != 0))
        return FRICREG_EINVAL;
    fricreg_aft *a = calloc(1, sizeof *a);
    if (a == NULL)
        return FRICREG_ENOMEM;
    a->H = harmonics;
    a->nc = nc;
    a->N = N;
    a->qre = malloc(2 * (H + 1) * nc * sizeof(double));
    a->poly = malloc(nc * sizeof(double));
    a->roots = malloc(8 * H * sizeof(double));
    a->ws.nc = 2 * H;
    a->ws.matrix = malloc(4 * H * H * sizeof(double));
    a->cand = malloc(12 * H * sizeof(double));
    a->rdir = malloc(8 * H * sizeof(int));
    a->cm = malloc((2 * nc + nc * nc + 2 * nc + 6 * nc) * sizeof(double));
    a->fout = malloc((nc + nc * nc) * sizeof(double));
    /* gsl_root_fsolver_alloc's two mallocs, done here: GSL would report a failed one to its
     * error handler (as in exact.c) */
    a->brent = malloc(sizeof *a->brent);
    void *state = malloc(gsl_root_fsolver_brent->size);
    if (a->brent != NULL)
        *a->brent = (gsl_root_fsolver){.type = gsl_root_fsolver_brent, .state = state};
    if (N != 0) {
        a->ctab = malloc((13 * N + nc * N) * sizeof(double));
        a->anchor = malloc(N * sizeof(size_t));
    }
    if (a->brent == NULL)
        free(state);
    if (!a->qre || !a->poly || !a->roots || !a->ws.matrix || !a->cand || !a->rdir || !a->cm ||
        !a->fout || !a->brent || !state || (N != 0 && (!a->ctab || !a->anchor))) {
        fricreg_aft_free(a);
        return FRICREG_ENOMEM;
    }
    a->qim = a->qre + (H + 1) * nc;
    a->cim = a->cand + 2 * H;
    a->rev = a->cand + 4 * H;
    a->sm = a->cm + nc;
    a->gram = a->sm + nc;
    a->phw = a->gram + nc * nc;
    a->dcoef = a->phw + nc;
    a->ncoef = a->dcoef + nc;
    a->nroot = a->cand + 6 * H;
    a->ndir = a->rdir + 2 * H;
    a->jout = a->fout + nc;
    fr_aft_half_angle_table(a, harmonics);
    if (N != 0) {
        a->stab = a->ctab + N;
        a->us = a->stab + N;
        a->fs = a->us + N;
        a->ts = a->fs + N;
        a->ds = a->ts + N;
        a->s2 = a->ds + nc * N;
        for (size_t n = 0; n < N; n++) {
            double th = 6.283185307179586 * (double)n / (double)N;
            a->ctab[n] = cos(th);
            a->stab[n] = sin(th);
        }
    }
    *out = a;
    return FRICREG_OK;
}

void fricreg_aft_free(fricreg_aft *aft)
{
    if (aft == NULL)
        return;
    FR_FREE_ALL(aft->qre, aft->poly, aft->roots, aft->ws.matrix, aft->cand, aft->rdir, aft->cm,
                aft->fout, aft->ctab, aft->anchor);
    if (aft->brent != NULL)
        free(aft->brent->state);
    free(aft->brent);
    free(aft);
}

int fricreg_aft_harmonics(const fricreg_aft *aft)
{
    return aft ? aft->H : 0;
}

size_t fricreg_aft_samples(const fricreg_aft *aft)
{
    return aft ? aft->N : 0;
}

/* Slider s's stiffness and bound as fn's header names them: kt and mun of a Jenkins call (with
 * a normal law the bound is the law's, checked apart), k[s] and phi[s] of an Iwan call. */
static void slider_names(const char *fn, size_t s, char kname[32], char pname[32])
{
    if (strncmp(fn, "jenkins", 7) == 0) {
        strcpy(kname, "kt");
        strcpy(pname, "mun");
        return;
    }
    snprintf(kname, 32, "k[%zu]", s);
    snprintf(pname, 32, "phi[%zu]", s);
}

/* The checks every evaluation shares: the pointers, n, the sliders and u, in that order. */
static int check(fricreg_aft *a, const char *fn, int sampled, size_t ns, const double *k,
                 const double *phi, size_t n, const double *u, const double *f)
{
    if (k == NULL || phi == NULL || u == NULL || f == NULL)
        return fr_fail(a, FRICREG_ENULL, "%s: %s is NULL", fn,
                       u == NULL   ? "u"
                       : f == NULL ? "f"
                       : k == NULL ? "k"
                                   : "phi");
    if (sampled && a->N == 0)
        return fr_fail(a, FRICREG_EINVAL, "%s: the workspace was created with no samples (N = 0)",
                       fn);
    if (n != a->nc)
        return fr_fail(a, FRICREG_ESIZE, "%s: n = %zu, the workspace has 2H + 1 = %zu", fn, n,
                       a->nc);
    if (ns == 0)
        return fr_fail(a, FRICREG_EINVAL, "%s: ns = 0 sliders", fn);
    double ksum = 0.0, usum = 0.0;
    char kname[32], pname[32]; /* the header's names: kt and mun of a Jenkins call, else k[s] */
    for (size_t s = 0; s < ns; s++) {
        slider_names(fn, s, kname, pname);
        if (!isfinite(k[s]) || !isfinite(phi[s]))
            return fr_fail(a, FRICREG_ENONFINITE, "%s: %s = %g, %s = %g", fn, kname, k[s], pname,
                           phi[s]);
        if (!(k[s] > 0.0))
            return fr_fail(a, FRICREG_EINVAL, "%s: %s = %g must be > 0", fn, kname, k[s]);
        if (!(phi[s] >= 0.0))
            return fr_fail(a, FRICREG_EINVAL, "%s: %s = %g must be >= 0", fn, pname, phi[s]);
        ksum += k[s];
    }
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(u[j]))
            return fr_fail(a, FRICREG_ENONFINITE, "%s: u[%zu] = %g", fn, j, u[j]);
        usum += fabs(u[j]);
    }
    /* the pieces' integrals reach 2 pi kt sum |u[j]| before they cancel to |f| <= mun, and
     * u(θ), its range and its derivative's coefficients (h u_h, h <= 40) reach 8 sum |u[j]|
     * (with a subnormal kt, u near DBL_MAX passed the first and its range overflowed) */
    if (!isfinite(8.0 * fmax(1.0, ksum) * usum))
        return fr_fail(a, FRICREG_ENONFINITE,
                       "%s: 8 x max(1, stiffness %g) x the sum of |u[j]| %g overflows", fn, ksum,
                       usum);
    return FRICREG_OK;
}

/* Checks, computes into the workspace, copies out. */
static int evaluate(fricreg_aft *a, const char *fn, int sampled, size_t ns, const double *k,
                    const double *phi, size_t n, const double *u, double *f, double *jac)
{
    if (a == NULL)
        return FRICREG_ENULL;
    int status = check(a, fn, sampled, ns, k, phi, n, u, f);
    if (status != FRICREG_OK)
        return status;
    if (sampled)
        fr_aft_sampled(a, ns, k, phi, u, jac != NULL);
    else if ((status = fr_aft_exact(a, fn, ns, k, phi, u, jac != NULL)) != FRICREG_OK)
        return status;
    memcpy(f, a->fout, n * sizeof *f);
    if (jac != NULL)
        memcpy(jac, a->jout, n * n * sizeof *jac);
    return FRICREG_OK;
}

int fricreg_aft_jenkins_exact(fricreg_aft *aft, double kt, double mun, size_t n, const double u[],
                              double f[], double jac[])
{
    return evaluate(aft, "jenkins_exact", 0, 1, &kt, &mun, n, u, f, jac);
}

int fricreg_aft_jenkins_sampled(fricreg_aft *aft, double kt, double mun, size_t n, const double u[],
                                double f[], double jac[])
{
    return evaluate(aft, "jenkins_sampled", 1, 1, &kt, &mun, n, u, f, jac);
}

int fricreg_aft_iwan_exact(fricreg_aft *aft, size_t ns, const double k[], const double phi[],
                           size_t n, const double u[], double f[], double jac[])
{
    return evaluate(aft, "iwan_exact", 0, ns, k, phi, n, u, f, jac);
}

int fricreg_aft_iwan_sampled(fricreg_aft *aft, size_t ns, const double k[], const double phi[],
                             size_t n, const double u[], double f[], double jac[])
{
    return evaluate(aft, "iwan_sampled", 1, ns, k, phi, n, u, f, jac);
}

/* The scale of the normal force and of its Jacobian, |n0| + kn (1 + sum |g[j]|): the force
 * reaches |n0| + kn sum |g[j]|, dN/dg reaches kn. */
static double normal_scale(const fricreg_aft *a, double n0, double kn, const double *g)
{
    double gsum = 0.0;
    for (size_t j = 0; j < a->nc; j++)
        gsum += fabs(g[j]);
    return fabs(n0) + kn * (1.0 + gsum);
}

/* The normal law's checks beyond check()'s: g, mu, n0, kn, and the overflow of the bound. */
static int check_normal(fricreg_aft *a, const char *fn, double mu, double n0, double kn,
                        const double *g, const double *nf)
{
    if (g == NULL || nf == NULL)
        return fr_fail(a, FRICREG_ENULL, "%s: %s is NULL", fn, g == NULL ? "g" : "nf");
    if (!isfinite(mu) || !isfinite(n0) || !isfinite(kn))
        return fr_fail(a, FRICREG_ENONFINITE, "%s: mu = %g, n0 = %g, kn = %g", fn, mu, n0, kn);
    if (!(mu >= 0.0))
        return fr_fail(a, FRICREG_EINVAL, "%s: mu = %g must be >= 0", fn, mu);
    if (!(kn >= 0.0))
        return fr_fail(a, FRICREG_EINVAL, "%s: kn = %g must be >= 0", fn, kn);
    for (size_t j = 0; j < a->nc; j++)
        if (!isfinite(g[j]))
            return fr_fail(a, FRICREG_ENONFINITE, "%s: g[%zu] = %g", fn, j, g[j]);
    /* the Fourier integrals of the normal force reach 8 times its scale, and the Jacobian's
     * df/dg and dN/dg (1 + mu) kn */
    if (!isfinite(8.0 * (1.0 + mu) * normal_scale(a, n0, kn, g)))
        return fr_fail(a, FRICREG_ENONFINITE,
                       "%s: the normal force |n0| + kn x the sum of |g[j]|, or kn, overflows", fn);
    return FRICREG_OK;
}

/* The sampled marches hold the slider's place w = u - mu N/kt (slider.h), beyond the double
 * range for a spring far weaker than its bound (kt = 5e-324 against mu N = 2 gave f not
 * finite); the exact path carries the slider as the force kt w and takes such a kt. */
static int check_excursion(fricreg_aft *a, const char *fn, double kt, double mu, double n0,
                           double kn, const double *g)
{
    double bound = mu * normal_scale(a, n0, kn, g);
    if (!isfinite(8.0 * bound / kt))
        return fr_fail(a, FRICREG_ENONFINITE,
                       "%s: the slider's excursion mu (|n0| + kn (1 + sum |g[j]|))/kt = %g/%g "
                       "overflows",
                       fn, bound, kt);
    return FRICREG_OK;
}

/* The checks of the 1-D Jenkins element with a normal law: its displacements u[n] and forces
 * f[n] as check's for one slider of stiffness kt (the normal law checked apart), then the
 * normal law's; sampled: the excursion too. */
static int check_jenkins_normal(fricreg_aft *aft, const char *fn, int sampled, double kt, double mu,
                                double n0, double kn, size_t n, const double u[], const double g[],
                                double f[], double nf[])
{
    double unit = 1.0; /* check() reads a slider bound: the normal law is checked apart */
    int status = check(aft, fn, sampled, 1, &kt, &unit, n, u, f);
    if (status == FRICREG_OK)
        status = check_normal(aft, fn, mu, n0, kn, g, nf);
    if (status == FRICREG_OK && sampled)
        status = check_excursion(aft, fn, kt, mu, n0, kn, g);
    return status;
}

int fricreg_aft_jenkins_normal_sampled(fricreg_aft *aft, double kt, double mu, double n0, double kn,
                                       size_t n, const double u[], const double g[], double f[],
                                       double nf[], double jac[])
{
    static const char fn[] = "jenkins_normal_sampled";
    if (aft == NULL)
        return FRICREG_ENULL;
    int status = check_jenkins_normal(aft, fn, 1, kt, mu, n0, kn, n, u, g, f, nf);
    if (status != FRICREG_OK)
        return status;
    fr_aft_sampled_normal(aft, kt, mu, n0, kn, u, g, f, nf, jac);
    return FRICREG_OK;
}

int fricreg_aft_jenkins_2d_normal_sampled(fricreg_aft *aft, double kt, double mu, double n0,
                                          double kn, size_t n, const double u[], const double g[],
                                          double f[], double nf[], double jac[])
{
    static const char fn[] = "jenkins_2d_normal_sampled";
    if (aft == NULL)
        return FRICREG_ENULL;
    double unit = 1.0; /* check() reads a slider bound: the normal law is checked apart */
    int status = check(aft, fn, 1, 1, &kt, &unit, n, u, f);
    for (size_t j = n; status == FRICREG_OK && j < 2 * n; j++) /* uy, named by its place in u */
        if (!isfinite(u[j]))
            status = fr_fail(aft, FRICREG_ENONFINITE, "%s: u[%zu] = %g", fn, j, u[j]);
    if (status == FRICREG_OK) /* uy's scale, as ux's */
        status = check(aft, fn, 1, 1, &kt, &unit, n, u + n, f);
    if (status == FRICREG_OK)
        status = check_normal(aft, fn, mu, n0, kn, g, nf);
    if (status != FRICREG_OK)
        return status;
    if ((status = check_excursion(aft, fn, kt, mu, n0, kn, g)) != FRICREG_OK)
        return status;
    fr_aft_sampled_2d_normal(aft, kt, mu, n0, kn, u, g, f, nf, jac);
    return FRICREG_OK;
}

int fricreg_aft_jenkins_normal_exact(fricreg_aft *aft, double kt, double mu, double n0, double kn,
                                     size_t n, const double u[], const double g[], double f[],
                                     double nf[], double jac[])
{
    static const char fn[] = "jenkins_normal_exact";
    if (aft == NULL)
        return FRICREG_ENULL;
    int status = check_jenkins_normal(aft, fn, 0, kt, mu, n0, kn, n, u, g, f, nf);
    if (status != FRICREG_OK)
        return status;
    return fr_aft_exact_normal(aft, fn, kt, mu, n0, kn, u, g, f, nf, jac);
}

FR_ERROR_GETTERS(fricreg_aft, "NULL AFT workspace")
