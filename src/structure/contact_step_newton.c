/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_step_newton.c — the contact-space Newton of fricreg_ctx_solve_step
 * (contact_step_newton.h) on its solver (contact_step_solver.h).
 *
 * The caller's step makes the contacts' velocities and free accelerations affine in the forces
 * (fricreg_structure.h, fricreg_ctx_solve_step):
 *   zdot(f) = zdot_pred + c W_eff f,   a_free(f) = a_pred - (W - W_eff) f,
 * and Newton solves G(f) = f - F(zdot(f), a_free(f)) = 0, F the context's law. The iterations
 * (direction, stop, line search) are step_newton.c's and the stick guess's solve and right-hand
 * side newton_matrix.c's, all shared with newmark.c; the sequence (stick guess, start, restart
 * without stops) is newmark.c's newton(). What differs is how the residual is measured.
 * newmark.c reads the structure's residual R = w J^T G on its degrees of freedom, which this
 * function does not see; the line search here reads its M^-1 norm,
 *   ||R||_{M^-1}^2 = G^T J M^-1 J^T G = G^T W G,
 * which is newmark.c's ||R||_2 up to a constant when M is a multiple of I (the building) and
 * the same kind of measure otherwise. With the plain 2-norm of G instead, the line search
 * stalled at the building's reversals (a stopped damper beside two sliding ones: 1 step of
 * 1500 unconverged at eps = 1e-3, 5 at 1e-4), where ||R|| weighs the dampers' differences.
 * The stopping rule reads max_i |G_i|, in force units. */
#include <math.h>
#include <string.h>

#include "contact_factor.h"
#include "contact_step_newton.h"
#include "ctx/ctx_driver.h"
#include "newton_matrix.h"
#include "step_newton.h"

static void products_of(struct fr_step_solver *s, const double f[], struct fr_compliance_pair *p)
{
    fr_delassus_mult(s->Weff, 1.0, f, 0.0, p->weff->data);
    fr_delassus_mult(s->W, 1.0, f, 0.0, p->w->data);
}

/* G = f - F(zdot(f), a_free(f)) from f and its products, the merit sqrt(G^T W G) into *phi
 * and ||G||_inf into *rinf; the context's status (its eval's). */
static int residual(struct fr_step_solver *s, const gsl_vector *fv,
                    const struct fr_compliance_pair *p, gsl_vector *Gv, double *phi, double *rinf)
{
    size_t m = s->m;
    const double *f = fv->data, *weff_f = p->weff->data, *w_f = p->w->data;
    double *G = Gv->data;
    for (size_t i = 0; i < m; i++) {
        s->zdot[i] = s->z0[i] + s->c * weff_f[i];
        s->afree[i] = s->a0[i] + (weff_f[i] - w_f[i]); /* as newmark.c: the difference first */
    }
    int status = fricreg_ctx_eval(s->ctx, m, s->zdot, s->afree, s->F, NULL);
    if (status != FRICREG_OK)
        return status;
    double big = 0.0, q = 0.0;
    for (size_t i = 0; i < m; i++) {
        G[i] = f[i] - s->F[i];
        big = fmax(big, fabs(G[i]));
    }
    fr_delassus_mult(s->W, 1.0, G, 0.0, s->wg);
    for (size_t i = 0; i < m; i++)
        q += G[i] * s->wg[i];
    *phi = sqrt(fmax(q, 0.0));
    *rinf = big;
    return FRICREG_OK;
}

static void w_product_cb(void *user, const double x[], double w_x[])
{
    struct fr_step_solver *s = user;
    fr_delassus_mult(s->W, 1.0, x, 0.0, w_x);
}

static int residual_cb(void *user, const gsl_vector *f, const struct fr_compliance_pair *p,
                       gsl_vector *G, double *phi, double *rinf)
{
    return residual(user, f, p, G, phi, rinf);
}

/* fk = x (products p) and its residual. */
static int start_at(struct fr_step_solver *s, const gsl_vector *x,
                    const struct fr_compliance_pair *p, double *phi, double *rinf)
{
    gsl_vector_memcpy(&s->v[FR_STEP_V_FK], x);
    gsl_vector_memcpy(s->at_k.weff, p->weff);
    gsl_vector_memcpy(s->at_k.w, p->w);
    return residual(s, &s->v[FR_STEP_V_FK], &s->at_k, &s->v[FR_STEP_V_G], phi, rinf);
}

/* Law (4) with a diagonal W: the stick guess solves the band's own piece (newmark.c). */
static int law_exact(const struct fr_step_solver *s)
{
    if (fr_ctx_law(s->ctx) != FRICREG_LAW_QUINN)
        return 0;
    const SuiteSparse_long *Wp = s->W->p;
    return Wp[s->m] == (SuiteSparse_long)s->m; /* the diagonal alone */
}

/* The stick guess of newmark.c's stick_guess into s->ft, its products into at_guess: 0 if
 * there is none, 1 (2 for law_exact). Reads s->zdot (the start's residual) unless law_exact. */
static int stick_guess(struct fr_step_solver *s, const double zstart[])
{
    size_t m = s->m, k = 0;
    for (size_t i = 0; i < m; i++) {
        s->stopped[i] = fabs(s->f0[i]) < s->mun[i];
        k += s->stopped[i];
        s->df[i] = 0.0;
    }
    if (k == 0)
        return 0;
    int exact = law_exact(s);
    fr_newton_stick_rhs(m, exact, s->c, fr_ctx_eps(s->ctx), s->mun,
                        fr_ctx_coupling_diagonal(s->ctx), s->z0, s->a0, s->at_start.weff->data,
                        zstart, s->zdot, s->b);
    if (fr_newton_stick_solve(&s->nm, s->Weff, s->stopped, s->b, s->df, s->at_guess.weff->data,
                              &s->cc) != FRICREG_OK)
        return 0;
    double *guess = s->v[FR_STEP_V_FT].data;
    for (size_t i = 0; i < m; i++) {
        guess[i] = s->f0[i] + s->df[i];
        if (!isfinite(guess[i]))
            return 0; /* beyond the range (a tiny c): no guess, Newton from f0 */
    }
    fr_delassus_mult(s->W, 1.0, s->df, 0.0, s->at_guess.w->data);
    fr_step_combine(&s->at_start, 1.0, &s->at_guess, &s->at_guess);
    return exact ? 2 : 1;
}

/* The shared iterations (step_newton.c) from fk; plain: full steps, no stops, no search. */
static int iterate(struct fr_step_solver *s, double tol, int max_iter, int stops, int search,
                   double *phi, double *rinf, int *iters)
{
    struct fr_step_newton e = {
        .m = s->m,
        .coef = s->c,
        .eps = fr_ctx_eps(s->ctx),
        .mun = s->mun,
        .max_iter = max_iter,
        .ctx = s->ctx,
        .nm = &s->nm,
        .W = s->W,
        .Weff = s->Weff,
        .cc = &s->cc,
        .fk = &s->v[FR_STEP_V_FK],
        .ft = &s->v[FR_STEP_V_FT],
        .df = &s->v[FR_STEP_V_DF],
        .G = &s->v[FR_STEP_V_G],
        .Gt = &s->v[FR_STEP_V_GT],
        .at_k = &s->at_k,
        .at_t = &s->at_t,
        .at_df = &s->at_df,
        .zdot = &s->v[FR_STEP_V_ZDOT],
        .stopped = s->stopped,
        .cuts = NULL,
        .user = s,
        .w_product = w_product_cb,
        .residual = residual_cb,
    };
    return fr_step_newton_iterate(&e, tol, stops, search, phi, rinf, iters);
}

int fr_contact_step_newton(struct fr_step_solver *s, const double zstart[], double tol,
                           int max_iter, int plain, int *converged, int *iters)
{
    double phi = 0.0, rinf = 0.0, phi_guess = 0.0;
    int guess = 0, status;
    *iters = 0;
    products_of(s, s->f0, &s->at_start);
    if (!plain && law_exact(s) && (guess = stick_guess(s, zstart)) != 0) {
        if ((status = start_at(s, &s->v[FR_STEP_V_FT], &s->at_guess, &phi, &rinf)) != FRICREG_OK)
            return status;
        if (rinf <= tol) {
            *iters = 1;
            *converged = 1;
            return FRICREG_OK;
        }
        phi_guess = phi;
    }
    if ((status = start_at(s, &s->v[FR_STEP_V_F0], &s->at_start, &phi, &rinf)) != FRICREG_OK)
        return status;
    if (!plain && rinf > tol) {
        double phi_start = phi;
        if (guess != 0) {
            if (phi_guess < phi_start)
                status = start_at(s, &s->v[FR_STEP_V_FT], &s->at_guess, &phi, &rinf);
        } else if (stick_guess(s, zstart)) {
            status = start_at(s, &s->v[FR_STEP_V_FT], &s->at_guess, &phi, &rinf);
            if (status == FRICREG_OK && !(phi < phi_start))
                status = start_at(s, &s->v[FR_STEP_V_F0], &s->at_start, &phi, &rinf);
        }
        if (status != FRICREG_OK)
            return status;
    }
    memset(s->stopped, 0, s->m);
    if ((status = iterate(s, tol, max_iter, !plain, !plain, &phi, &rinf, iters)) != FRICREG_OK)
        return status;
    if (!plain && rinf > tol && isfinite(phi) && *iters < max_iter) {
        if ((status = start_at(s, &s->v[FR_STEP_V_F0], &s->at_start, &phi, &rinf)) != FRICREG_OK ||
            (status = iterate(s, tol, max_iter, 0, 1, &phi, &rinf, iters)) != FRICREG_OK)
            return status;
    }
    *converged = rinf <= tol;
    return isfinite(phi) ? FRICREG_OK : FRICREG_EDIVERGED;
}
