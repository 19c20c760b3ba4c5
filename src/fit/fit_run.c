/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_run.c — fricreg_fit_run: GSL's trust-region Levenberg-Marquardt (gsl_multifit_nlinear,
 * the exact Jacobian of residuals.c) from each start; the best converged solution reported
 * (fit_stats.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "base/free_all.h"
#include "base/gsl_mem.h"
#include "fit_stats.h"
#include "hb_model.h"
#include "params.h"
#include "starts.h"

#define MAX_ITER 500
#define XTOL 1e-10
#define GTOL 1e-12
#define STATIONARY_GTOL 1e-8 /* a start no step improves: a solution if this stationary */
/* Converged also where a Gauss-Newton step would lower r^T r by less than this share of it: the
 * step left is then below sqrt(1e-9 dof), about 1e-4 of a standard error (docs/identification.md),
 * and each further iteration costs an HB model a backbone march. */
#define DECREMENT_TOL 1e-9
#define BAD_RESIDUAL 1e100 /* where the model cannot be evaluated: a step GSL rejects */

struct run {
    struct fr_fit_problem pb;
    gsl_vector *r;         /* scratch for the Jacobian's evaluation */
    int failed;            /* an evaluation since the last init failed */
    gsl_matrix *qr;        /* [rows m] scratch: the Jacobian's Householder QR */
    gsl_vector *tau, *qtf; /* [m], [rows]: its reflectors, Q^T r */
};

static int residual_cb(const gsl_vector *x, void *params, gsl_vector *f)
{
    struct run *run = params;
    if (fr_fit_residuals(&run->pb, gsl_vector_const_ptr(x, 0), f, NULL) != 0) {
        gsl_vector_set_all(f, BAD_RESIDUAL);
        run->failed = 1;
    }
    return GSL_SUCCESS;
}

static int jacobian_cb(const gsl_vector *x, void *params, gsl_matrix *J)
{
    struct run *run = params;
    if (fr_fit_residuals(&run->pb, gsl_vector_const_ptr(x, 0), run->r, J) != 0) {
        gsl_matrix_set_zero(J);
        run->failed = 1;
    }
    return GSL_SUCCESS;
}

/* max_k |g_k| max(|x_k|, 1), the gradient GSL's test scales. */
static double scaled_gradient(const gsl_multifit_nlinear_workspace *w)
{
    double g = 0.0;
    for (size_t k = 0; k < w->x->size; k++)
        g = fmax(g, fabs(gsl_vector_get(w->g, k)) * fmax(fabs(gsl_vector_get(w->x, k)), 1.0));
    return g;
}

/* 1 if the Gauss-Newton step at the iterate would lower r^T r by at most DECREMENT_TOL of it:
 * the decrement |P_J r|^2, r's projection on the Jacobian's range, is the first m entries of
 * Q^T r (a rank-deficient J's Q spans more than its range: the test errs on going on). */
static int decrement_small(const gsl_multifit_nlinear_workspace *w, struct run *run)
{
    const gsl_vector *r = gsl_multifit_nlinear_residual(w);
    gsl_matrix_memcpy(run->qr, gsl_multifit_nlinear_jac(w));
    gsl_vector_memcpy(run->qtf, r);
    if (gsl_linalg_QR_decomp(run->qr, run->tau) != GSL_SUCCESS ||
        gsl_linalg_QR_QTvec(run->qr, run->tau, run->qtf) != GSL_SUCCESS)
        return 0;
    double rr = gsl_blas_dnrm2(r), d = 0.0;
    for (size_t k = 0; k < run->tau->size; k++)
        d += gsl_vector_get(run->qtf, k) * gsl_vector_get(run->qtf, k);
    return d <= DECREMENT_TOL * rr * rr;
}

/* Iterates from the initialized point; 1 if it converged, 0 if not (GSL's driver's loop, but a
 * start no step can improve is a solution where its gradient vanishes, and one whose
 * Gauss-Newton decrement is negligible has converged). */
static int iterate(gsl_multifit_nlinear_workspace *w, struct run *run, size_t *iters)
{
    int status = GSL_CONTINUE, info;
    size_t iter = 0;
    while (status == GSL_CONTINUE && iter < MAX_ITER) {
        status = gsl_multifit_nlinear_iterate(w);
        if (status == GSL_ENOPROG && iter == 0) {
            double phi = 0.5 * gsl_blas_dnrm2(w->f) * gsl_blas_dnrm2(w->f);
            *iters = 0;
            return scaled_gradient(w) <= STATIONARY_GTOL * fmax(phi, 1.0);
        }
        iter++;
        status = gsl_multifit_nlinear_test(XTOL, GTOL, 0.0, &info, w);
        if (status == GSL_CONTINUE && decrement_small(w, run))
            status = GSL_SUCCESS;
    }
    *iters = iter;
    return status == GSL_SUCCESS || status == GSL_ETOLF || status == GSL_ETOLX ||
           status == GSL_ETOLG;
}

/* The checks a run makes before it solves. */
static int check_problem(fricreg_fit *fit, const struct fr_fit_problem *pb)
{
    if (fit->n == 0)
        return fr_fail(fit, FRICREG_EINVAL, "run: no levels are set");
    if (pb->nfree == 0)
        return fr_fail(fit, FRICREG_EINVAL, "run: no parameter is free");
    if (fit->n < pb->nfree)
        return fr_fail(fit, FRICREG_EINVAL,
                       "run: %zu levels for %zu free parameters: at least "
                       "as many levels as free parameters are needed",
                       fit->n, pb->nfree);
    if (!fit->has_sd && 2 * fit->n == pb->nfree)
        return fr_fail(fit, FRICREG_EINVAL,
                       "run: %zu levels leave no degree of freedom for "
                       "the residual variance: give the deviations",
                       fit->n);
    return FRICREG_OK;
}

/* The best converged start's theta into best (its start in best0); returns how many
 * converged, or (size_t)-1 if out of memory. */
static size_t solve_starts(fricreg_fit *fit, struct run *run, double best[], double best0[])
{
    size_t m = run->pb.nfree, rows = 2 * fit->n, converged = 0;
    gsl_multifit_nlinear_fdf fdf = {residual_cb, jacobian_cb, NULL, rows, m, run, 0, 0, 0};
    gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
    gsl_vector *x = fr_gsl_vector_new(m);
    run->r = fr_gsl_vector_new(rows);
    run->qr = fr_gsl_matrix_new(rows, m);
    run->tau = fr_gsl_vector_new(m);
    run->qtf = fr_gsl_vector_new(rows);
    gsl_multifit_nlinear_workspace *w = x && run->r && run->qr && run->tau && run->qtf
                                            ? gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust,
                                                                         &params, rows, m)
                                            : NULL;
    double best_cost = INFINITY;
    struct fr_fit_result *res = &fit->result;
    res->nfev = res->njev = 0;
    for (size_t s = 0; w != NULL && s < fit->nstarts; s++) {
        fr_fit_start(&run->pb, s, gsl_vector_ptr(x, 0));
        run->failed = 0;
        gsl_multifit_nlinear_init(x, &fdf, w);
        size_t iters = 0;
        int ok = !run->failed && iterate(w, run, &iters);
        double cost = gsl_blas_dnrm2(w->f);
        res->nfev += fdf.nevalf;
        res->njev += fdf.nevaldf;
        if (!ok || !(cost < BAD_RESIDUAL))
            continue;
        converged++;
        if (cost < best_cost) {
            best_cost = cost;
            memcpy(best, gsl_vector_const_ptr(w->x, 0), m * sizeof *best);
            memcpy(best0, gsl_vector_const_ptr(x, 0), m * sizeof *best0);
            res->iterations = iters;
            res->best_start = s;
        }
    }
    int nomem = w == NULL;
    if (w != NULL)
        gsl_multifit_nlinear_free(w);
    FR_FREE_ALL(x, run->r, run->qr, run->tau, run->qtf);
    return nomem ? (size_t)-1 : converged;
}

/* The best converged start's solution reported; or the status of the first thing that failed. */
static int solve(fricreg_fit *fit, struct run *run)
{
    double best[FR_FIT_MAXP], best0[FR_FIT_MAXP];
    size_t converged = solve_starts(fit, run, best, best0);
    if (converged == (size_t)-1)
        return fr_fail(fit, FRICREG_ENOMEM, "run: out of memory for the least-squares workspace");
    if (converged == 0 && run->pb.unreachable)
        return fr_fail(fit, FRICREG_EINVAL,
                       "run: level %zu (amplitude %g) is beyond the "
                       "backbone's reach (%s): no start converged",
                       run->pb.bad_level, fit->amp[run->pb.bad_level], fit->reason);
    if (converged == 0 && fit->hb != NULL)
        return fr_fail(fit, FRICREG_EWORK,
                       "run: none of %zu starts converged within %d iterations (the model's "
                       "last failure: %s)",
                       fit->nstarts, MAX_ITER, fit->reason);
    if (converged == 0)
        return fr_fail(fit, FRICREG_EWORK,
                       "run: none of %zu starts converged within %d "
                       "iterations",
                       fit->nstarts, MAX_ITER);
    struct fr_fit_result kept = fit->result;
    int st = fr_fit_finish(&run->pb, best, best0);
    if (st != FRICREG_OK)
        return st;
    fit->result.nfev = kept.nfev;
    fit->result.njev = kept.njev;
    fit->result.iterations = kept.iterations;
    fit->result.best_start = kept.best_start;
    fit->result.converged = converged;
    fit->result.nmodel = run->pb.nmodel;
    fit->result.marches = fit->marches;
    return FRICREG_OK;
}

int fricreg_fit_run(fricreg_fit *fit)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    fit->have_fit = 0;
    fit->marches = 0;
    struct run run;
    int st = fr_fit_problem_init(&run.pb, fit);
    if (st != FRICREG_OK)
        return st;
    double saved[FR_FIT_MAXP];
    if (fit->hb != NULL)
        fr_fit_hb_save(fit, saved);
    st = check_problem(fit, &run.pb);
    if (st == FRICREG_OK)
        st = solve(fit, &run);
    fr_fit_problem_free(&run.pb);
    if (fit->hb != NULL && st == FRICREG_OK) /* the driver at the fit */
        st = fr_fit_hb_apply(fit, fit->result.p) == FRICREG_OK
                 ? FRICREG_OK
                 : fr_fail(fit, FRICREG_EINVAL, "run: the driver refuses the fit: %s", fit->reason);
    if (fit->hb != NULL && st != FRICREG_OK)
        fr_fit_hb_restore(fit, saved);
    fit->have_fit = st == FRICREG_OK;
    return st;
}
