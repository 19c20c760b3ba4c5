/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newmark.c — Newmark and HHT-alpha steps of a fricreg_structure, the friction implicit:
 * Newton in the contact space on the exact tangent, with a backtracking line search (the
 * iterations in step_newton.c, shared with fricreg_ctx_solve_step, contact_step.c).
 *
 * Unknown of the step: the acceleration x at its end, with u1 = u_pred + beta dt^2 x and
 * v1 = v_pred + gamma dt x. Residual (Hilber, Hughes & Taylor 1977; alpha = 0 is Newmark),
 * with w = 1 + alpha:
 *   R(x) = M x + w (C v1 + K u1 - p~1 - J^T f1) - alpha (C v + K u - p~ - J^T f),
 * linear in x but for the friction f1. For given forces f, R = 0 is
 *   K_eff x = b + w J^T f,   K_eff = M + w (gamma dt C + beta dt^2 K),
 *   b = w (p~1 - C v_pred - K u_pred) + alpha (C v + K u - p~ - J^T f)  (the start's term),
 * so x(f) = K_eff^-1 (b + w J^T f), and the contacts' velocities and free accelerations at
 * the step's end are affine in f:
 *   zdot(f) = J v_pred + gamma dt J x(f) = z0 + c W_eff f,           c = w gamma dt,
 *   a_free(f) = J M^-1 (p~1 - C v1 - K u1) = (J x(f) - alpha h)/w - W f = a0 - (W - W_eff) f,
 * the second by R = 0, with W = J M^-1 J^T, W_eff = J K_eff^-1 J^T, h = J M^-1 (C v + K u -
 * p~ - J^T f). Newton solves G(f) = f - F(zdot(f), a_free(f)) = 0 in the m forces
 * (newton_matrix.h), F the context's law. At x(f), R = w J^T G(f) exactly, and Newton's steps
 * on f are Newton's steps on x mapped through x(f) (the chain rule through the same affine
 * maps): the stopping rule and the line search read R, as they did when x was the unknown.
 *
 * The step's cost: K_eff factored once per dt (contact_factor.c), one forward solve for b,
 * the Newton iterations in the contact space, where W_eff f costs O(nnz(W_eff)) (its entries
 * below the rounding of the diagonal left out: contact_factor.h), and
 * one backward solve for x. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_blas.h>

#include "base/sparse_ops.h"
#include "ctx/ctx_driver.h"
#include "structure_internal.h"

#define WEFF_DROP 0x1p-53 /* W_eff entries below this times sqrt(W_ii W_jj) / m: rounding */

/* W_eff f and W f into p: the step's products with the forces, O(nnz(W_eff) + nnz(W)). */
static void form_products(fricreg_structure *s, const double f[], struct fr_compliance_pair *p)
{
    fr_cfactor_compliance(&s->step, f, p->weff->data);
    fr_cfactor_compliance(&s->mass, f, p->w->data);
}

static void copy_products(const struct fr_compliance_pair *from, struct fr_compliance_pair *to)
{
    gsl_vector_memcpy(to->weff, from->weff);
    gsl_vector_memcpy(to->w, from->w);
}

/* From f and its products p: zdot(f) and a_free(f) into s->zdot, s->afree; the law's forces
 * into s->f1; G = f - F; then R = w J^T G on the degrees of freedom J touches, its 2-norm
 * into *phi and its largest entry into *rinf. */
static int residual(fricreg_structure *s, const gsl_vector *f, const struct fr_compliance_pair *p,
                    gsl_vector *G, double *phi, double *rinf)
{
    size_t m = s->m;
    const double *weff_f = p->weff->data, *w_f = p->w->data;
    double c = (1.0 + s->alpha) * s->gamma * s->step_dt;
    for (size_t i = 0; i < m; i++) {
        s->zdot->data[i] = s->z0->data[i] + c * weff_f[i];
        /* (W_eff - W) f first: near the range's end a0 and W f can be as large as each other */
        s->afree->data[i] = s->af0->data[i] + (weff_f[i] - w_f[i]);
    }
    int status = fr_structure_contact_forces(s, s->f1);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++)
        G->data[i] = f->data[i] - s->f1->data[i];
    fr_structure_spread_norms(s, 1.0 + s->alpha, G, phi, rinf);
    return FRICREG_OK;
}

/* K_eff, its factor and the Newton matrix's pattern, kept while dt and the scheme hold. A
 * run's steps end at t0 + k dt exactly, so their lengths differ from dt by the rounding of t:
 * a step within STEP_RTOL of the factored dt is taken with that dt (fr_newmark_solve), not
 * factored again; the clock keeps its exact times. */
#define STEP_RTOL 1e-9
/* Up to this many contacts the dense Newton matrix is allocated with K_eff's factor, for the
 * steps that need it (a falling Stribeck branch): beyond, at that use. */
#define DENSE_FALLBACK_MAX 64
static int all_finite(const cholmod_sparse *A)
{
    const SuiteSparse_long *Ap = A->p;
    const double *Ax = A->x;
    for (SuiteSparse_long p = 0; p < Ap[A->ncol]; p++)
        if (!isfinite(Ax[p]))
            return 0;
    return 1;
}

/* The Newton matrix for W_eff = s->step.D and, on the sparse path, the blocks' factor of
 * K_eff + J^T T J (contact_sparse.h); FRICREG_OK or FRICREG_ENOMEM (s->step then freed). */
static int prepare_newton(fricreg_structure *s, const cholmod_sparse *Keff)
{
    fr_contact_sparse_free(&s->sparse, &s->cc);
    int dense = s->m <= DENSE_FALLBACK_MAX || fr_ctx_tangent_may_be_dense(s->ctx);
    int ok = fr_newton_matrix_prepare(&s->newton, s->step.D, dense, &s->cc) == FRICREG_OK;
    if (ok && s->contact_solver == FRICREG_CONTACT_SOLVER_SPARSE)
        ok = fr_contact_sparse_prepare(&s->sparse, Keff, s->Jt, &s->cc) == FRICREG_OK;
    s->newton.sparse = ok && s->contact_solver == FRICREG_CONTACT_SOLVER_SPARSE ? &s->sparse : NULL;
    if (ok)
        return FRICREG_OK;
    fr_cfactor_free(&s->step, &s->cc);
    return fr_fail(s, FRICREG_ENOMEM, "step: no memory for the Newton matrix");
}

static int form_step_factor(fricreg_structure *s, double dt)
{
    if (fabs(dt - s->step_dt) <= STEP_RTOL * s->step_dt)
        return FRICREG_OK;
    s->step_dt = 0.0;
    s->el.E_valid = 0;
    s->el.joint.valid = 0;
    fr_cfactor_free(&s->step, &s->cc);
    double w = 1.0 + s->alpha;
    double gc = w * s->gamma * dt, gk = w * s->beta * dt * dt;
    cholmod_sparse *Keff = fr_structure_combine(s, 1.0, gc, gk);
    if (Keff == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "step: no memory for K_eff");
    if (!all_finite(Keff)) {
        cholmod_l_free_sparse(&Keff, &s->cc);
        return fr_fail(s, FRICREG_EINVAL,
                       "step: dt = %g puts K_eff's entries beyond the double range", dt);
    }
    int status = fr_cfactor_build(&s->step, Keff, s->Jt, WEFF_DROP, &s->cc, &s->err, "step",
                                  "K_eff = M + (1 + alpha)(gamma dt C + beta dt^2 K)");
    if (status == FRICREG_OK)
        status = prepare_newton(s, Keff);
    cholmod_l_free_sparse(&Keff, &s->cc);
    if (status != FRICREG_OK)
        return status;
    s->step_dt = dt;
    return FRICREG_OK;
}

int fr_newmark_factor(fricreg_structure *s, double dt)
{
    if (s->step_dt != dt)
        s->step_dt = 0.0; /* within STEP_RTOL is not enough: the factor of dt itself */
    return form_step_factor(s, dt);
}

/* The largest entry of |J|^T mun, on the degrees of freedom J touches (through s->spread):
 * formed once for J and the bounds (s->bound_scale). */
static double bound_scale(fricreg_structure *s)
{
    if (s->bound_scale >= 0.0)
        return s->bound_scale;
    const SuiteSparse_long *Jp = s->Jt->p, *Ji = s->Jt->i;
    const double *Jx = s->Jt->x;
    double *r = s->spread->data, big = 0.0;
    for (size_t i = 0; i < s->m; i++)
        for (SuiteSparse_long p = Jp[i]; p < Jp[i + 1]; p++)
            r[Ji[p]] += fabs(Jx[p]) * s->mun[i];
    for (size_t i = 0; i < s->m; i++)
        for (SuiteSparse_long p = Jp[i]; p < Jp[i + 1]; p++) {
            big = fmax(big, r[Ji[p]]);
            r[Ji[p]] = 0.0;
        }
    s->bound_scale = big;
    return big;
}

/* The largest entry of |M a| and of |p~1|: one pass where M is lumped (its upper triangle
 * holds n entries, which M's positive definiteness puts on the diagonal). */
static double inertia_scale(fricreg_structure *s)
{
    const double *a = s->a->data, *p1 = s->ptil1->data;
    if ((size_t)((const SuiteSparse_long *)s->M->p)[s->n] == s->n) {
        const double *Mx = s->M->x;
        double big = 0.0;
        for (size_t k = 0; k < s->n; k++)
            big = fr_max_abs(fr_max_abs(big, Mx[k] * a[k]), p1[k]);
        return big;
    }
    fr_sym_mult(s->M, 1.0, a, 0.0, s->work->data);
    return fmax(fr_norm_inf(s->work), fr_norm_inf(s->ptil1));
}

/* The step's force scale: the largest entry of |M a| and |C v + K u - p~ - J^T f| at its
 * start (hist: HHT only; for Newmark it is -M a to Newton's tolerance), |p~1| at its end, and
 * |J|^T mun. */
static double force_scale(fricreg_structure *s)
{
    double scale = inertia_scale(s);
    if (s->alpha != 0.0)
        scale = fmax(scale, fr_norm_inf(s->hist));
    scale = fmax(scale, bound_scale(s));
    return scale > 0.0 ? scale : 1e-300;
}

/* The engine's callbacks (step_newton.h): W x and the residual above. */
static void w_product_cb(void *user, const double x[], double w_x[])
{
    fricreg_structure *s = user;
    fr_cfactor_compliance(&s->mass, x, w_x);
}

static int residual_cb(void *user, const gsl_vector *f, const struct fr_compliance_pair *p,
                       gsl_vector *G, double *phi, double *rinf)
{
    return residual(user, f, p, G, phi, rinf);
}

/* Newton iterations from fk (its residual evaluated: G, phi = ||R||_2, *rinf = ||R||_inf)
 * until the residual is within tol, the step's iterations (*iters, counted on) run out, or
 * the line search stalls (step_newton.c), slipping contacts stopped at zdot = 0 with
 * stop_slips (the first trial, fr_newton_first_stop: a Newton step from a slip piece is the
 * root of that piece's linearization; when the contact must stop, that root lies beyond the
 * band, which is only eps/(gamma dt) wide in the acceleration, so the full step jumps across
 * it to the other slip piece, and halving finds the band only after many cuts; stopped at
 * zdot_i = 0, the contact is where the law holds it, and the next iteration works on the
 * band's own linearization; once a step, so that a contact that must reverse is stopped only
 * once). FRICREG_ENOMEM if the Newton matrix could not be allocated. On a linear piece of
 * the law one iteration is exact. */
static int iterate(fricreg_structure *s, double tol, int stop_slips, double *phi, double *rinf,
                   int *iters)
{
    struct fr_step_newton e = {
        .m = s->m,
        .coef = (1.0 + s->alpha) * s->gamma * s->step_dt,
        .eps = fr_ctx_eps(s->ctx),
        .mun = s->mun,
        .max_iter = s->newton_max,
        .ctx = s->ctx,
        .nm = &s->newton,
        .W = s->mass.D,
        .Weff = s->step.D,
        .cc = &s->cc,
        .fk = s->fk,
        .ft = s->ft,
        .df = s->df,
        .G = s->G,
        .Gt = s->Gt,
        .at_k = &s->at_fk,
        .at_t = &s->at_ft,
        .at_df = &s->at_df,
        .zdot = s->zdot,
        .stopped = s->stopped,
        .cuts = &s->stats[FRICREG_SSTAT_LINE_SEARCH_CUTS],
        .user = s,
        .w_product = w_product_cb,
        .residual = residual_cb,
    };
    if (fr_step_newton_iterate(&e, tol, stop_slips, 1, phi, rinf, iters) == FRICREG_ENOMEM)
        return fr_fail(s, FRICREG_ENOMEM, "step: no memory for the Newton %s (%zu contacts)",
                       s->newton.sparse != NULL ? "block's sparse factor" : "matrix", s->m);
    return FRICREG_OK;
}

/* fk = guess (whose products are p), its residual, phi and rinf. */
static int start_at(fricreg_structure *s, double dt, const gsl_vector *guess,
                    const struct fr_compliance_pair *p, double *phi, double *rinf)
{
    gsl_vector_memcpy(s->fk, guess);
    copy_products(p, &s->at_fk);
    int status = residual(s, s->fk, &s->at_fk, s->G, phi, rinf);
    if (status != FRICREG_OK)
        return fr_fail(s, status, "step: friction at t = %g: %s", s->t + dt,
                       fricreg_ctx_errmsg(s->ctx));
    return FRICREG_OK;
}

/* Law (4) with a diagonal W: the stick guess solves the band's own law (band_guess). */
static int law_exact(const fricreg_structure *s)
{
    return s->w_diagonal && fr_ctx_law(s->ctx) == FRICREG_LAW_QUINN;
}

/* Newton's first guess where the start's forces are not within the tolerance: those forces,
 * but for the contacts whose force at t is below their bound (law (4): in its band, for (3)
 * and tanh every contact), S, which take new forces, the others R keeping theirs.
 * Why: at small eps the band (law (4): |zdot - xi| < eps/2) is only eps/(c W_eff) wide in the
 * forces. A sticking contact's velocity wanders inside it, and the start's forces, held over
 * the step while the structure moves, put it outside: Newton then brings the sticking contacts
 * back one at a time (a stop each, fr_newton_first_stop), about an iteration per contact. On the
 * ten-storey building (examples/building/) at eps = 1e-4 m/s and dt = 0.01 s that was 12
 * iterations a step through its 5 s of free vibration, all ten dampers sticking.
 * The forces on S:
 *   - law (4) with a diagonal W (law_exact = 1, band_guess): those of the band's own affine
 *     piece, where the law is W_ii f_i + a_free,i + k_i zdot_i = 0 with k_i = 2 mun_i W_ii/eps
 *     (the free near-stick row of fr_ctx_tangent_rows; W f cancels against a_free's -W f):
 *       (1 + c k_i) [W_eff f]_i = -a0_i - k_i z0_i,   i in S.
 *     Where S and R are what the law makes of the result, this is the step's solution to
 *     rounding (newton: no Newton iteration after it);
 *   - otherwise (hold_guess), the forces that keep S's velocities over the step,
 *     zdot_S(f) = zdot_S(t).
 * W_eff,SS is positive definite unless contacts of S depend on each other (equal rows of J):
 * then no guess. The guess goes into s->ft and its products into s->at_ft; each returns 0 if
 * there is none. s->stopped holds the marks of S (mark_below_bound: their number). */
static size_t mark_below_bound(fricreg_structure *s)
{
    size_t k = 0;
    for (size_t i = 0; i < s->m; i++) {
        s->stopped[i] = fabs(s->f->data[i]) < s->mun[i];
        k += s->stopped[i];
    }
    return k;
}

/* law_exact's guess, solved for the forces themselves: W_eff,SS f_S = rhs_S - W_eff,SR f_R
 * (fr_newton_stick_rhs's b with W_eff f_R for W_eff f). With every contact in S (all
 * sticking) that is one solve and one product, the guess's. */
static int band_guess(fricreg_structure *s, size_t k)
{
    size_t m = s->m;
    const unsigned char *set = s->stopped;
    const double *f = s->f->data;
    double *guess = s->ft->data, *b = s->mwork2->data, *weff_r = s->mwork->data;
    for (size_t i = 0; i < m; i++)
        guess[i] = set[i] ? 0.0 : f[i];
    if (k < m) /* W_eff f_R: what the kept forces do to S */
        fr_cfactor_compliance(&s->step, guess, weff_r);
    else
        memset(weff_r, 0, m * sizeof *weff_r);
    double c = (1.0 + s->alpha) * s->gamma * s->step_dt;
    fr_newton_stick_rhs(m, 1, c, fr_ctx_eps(s->ctx), s->mun, fr_ctx_coupling_diagonal(s->ctx),
                        s->z0->data, s->af0->data, weff_r, NULL, NULL, b);
    double *weff_g = s->at_ft.weff->data;
    if (fr_newton_stick_solve(&s->newton, s->step.D, set, b, guess, weff_g, &s->cc) != FRICREG_OK)
        return 0;                  /* guess_S is then not read */
    for (size_t i = 0; i < m; i++) /* W_eff [guess_S; 0] + W_eff [0; f_R] */
        weff_g[i] += weff_r[i];
    fr_cfactor_compliance(&s->mass, guess, s->at_ft.w->data);
    return 1;
}

/* The other laws' guess (and law (4)'s with a coupled W), as a change df_S of the start's
 * forces f, whose products are s->at_start: W_eff,SS df_S = (zdot_S(t) - zdot_S(f))/c, so
 * that the guess's products are f's and df's, one product. Reads the start's residual
 * (s->zdot). */
static int hold_guess(fricreg_structure *s)
{
    size_t m = s->m;
    double *f = s->f->data, *guess = s->ft->data, *df = s->mwork->data, *b = s->mwork2->data;
    double c = (1.0 + s->alpha) * s->gamma * s->step_dt;
    memset(df, 0, m * sizeof *df);
    fr_csc_mult_t(s->Jt, s->v->data, b); /* zdot(t) */
    fr_newton_stick_rhs(m, 0, c, fr_ctx_eps(s->ctx), s->mun, NULL, NULL, NULL, NULL, b,
                        s->zdot->data, b);
    if (fr_newton_stick_solve(&s->newton, s->step.D, s->stopped, b, df, s->at_ft.weff->data,
                              &s->cc) != FRICREG_OK)
        return 0;
    for (size_t i = 0; i < m; i++)
        guess[i] = f[i] + df[i];
    fr_cfactor_compliance(&s->mass, df, s->at_ft.w->data);
    fr_step_combine(&s->at_start, 1.0, &s->at_ft, &s->at_ft);
    return 1;
}

/* Newton from the forces at the step's start or, where they are not within tol, the stick
 * guess if its residual is smaller: returns a status, and *converged and *iters. With law (4)
 * and a diagonal W the guess comes first, before the start's residual: where it is within
 * tol it is the step's solution (one iteration counted, no more made), and the start's
 * products and residual are not formed.
 * On return the context's last evaluation and s->f1 are at fk. Slipping contacts are
 * stopped at zdot = 0 (fr_newton_first_stop). Where a stop ends on a kink of the law (zdot = 0 is the
 * band's edge when |f_eq| >= mun) the line search can stall there: Newton then starts again
 * from the start's forces, without stops, with the iterations left. */
static int newton(fricreg_structure *s, double dt, int *converged, int *iters)
{
    double phi = 0.0, rinf = 0.0, phi_guess = 0.0;
    double tol = s->newton_tol * force_scale(s);
    int guess = 0, status;
    *iters = 0;
    size_t below = mark_below_bound(s);
    if (law_exact(s) && below > 0 && (guess = band_guess(s, below)) != 0) {
        /* needs no residual at the start */
        if ((status = start_at(s, dt, s->ft, &s->at_ft, &phi, &rinf)) != FRICREG_OK)
            return status;
        if (rinf <= tol) { /* the law's own solution on its piece: a Newton step, converged */
            memset(s->stopped, 0, s->m * sizeof *s->stopped);
            *iters = 1;
            *converged = 1;
            return FRICREG_OK;
        }
        phi_guess = phi;
    }
    form_products(s, s->f->data, &s->at_start);
    if ((status = start_at(s, dt, s->f, &s->at_start, &phi, &rinf)) != FRICREG_OK)
        return status;
    if (rinf > tol) { /* Newton from the guess where its residual is the smaller */
        double phi_start = phi;
        if (guess != 0) { /* band_guess's, evaluated above */
            if (phi_guess < phi_start)
                status = start_at(s, dt, s->ft, &s->at_ft, &phi, &rinf);
        } else if (!law_exact(s) && below > 0 && hold_guess(s)) { /* reads the start's residual */
            status = start_at(s, dt, s->ft, &s->at_ft, &phi, &rinf);
            if (status == FRICREG_OK && !(phi < phi_start))
                status = start_at(s, dt, s->f, &s->at_start, &phi, &rinf);
        }
        if (status != FRICREG_OK)
            return status;
    }
    memset(s->stopped, 0, s->m * sizeof *s->stopped);
    if ((status = iterate(s, tol, 1, &phi, &rinf, iters)) != FRICREG_OK)
        return status;
    if (rinf > tol && isfinite(phi) && *iters < s->newton_max) {
        if ((status = start_at(s, dt, s->f, &s->at_start, &phi, &rinf)) != FRICREG_OK ||
            (status = iterate(s, tol, 0, &phi, &rinf, iters)) != FRICREG_OK)
            return status;
    }
    *converged = rinf <= tol; /* also when the extra iteration stalls at the rounding floor */
    if (!isfinite(phi))
        return fr_fail(s, FRICREG_EDIVERGED, "step: the residual at t = %g is not finite",
                       s->t + dt);
    return FRICREG_OK;
}

/* The joint step (joint_step.c): Newton over the contacts' and the elements' forces, from
 * the stick guess of newton() above where law (4) has one, the elements at their forces at t.
 * The tolerance is the elements': the step's force scale or their largest force at t. */
static int joint_newton(fricreg_structure *s, int *converged, int *iters)
{
    double scale = force_scale(s);
    for (size_t i = 0; i < s->el.nc; i++)
        scale = fmax(scale, fabs(s->el.fe[i]));
    size_t below = mark_below_bound(s);
    int guess = law_exact(s) && below > 0 && band_guess(s, below);
    return fr_joint_newton(s, s->newton_tol * scale, guess ? s->ft->data : NULL, converged, iters);
}

/* The predictors, the start's term hist = C v + K u - p~ - J^T f + J_e^T fe, the Jenkins
 * elements' forces at the step's end (b then holds them: jenkins.c), and b's forward solve
 * (into s->yb) with what the contacts see of it: z0 and a0. joint: the elements are left to
 * joint_step.c: b holds their forces at t, b is kept in s->x, and e->q0 is the elements'
 * coordinates at that b (one backward solve more). */
static int predict(fricreg_structure *s, double dt, int joint, int *converged, int *iters)
{
    size_t n = s->n, m = s->m;
    double b2 = s->beta * dt * dt, g = s->gamma * dt, w = 1.0 + s->alpha;
    double *up = s->up->data, *vp = s->vp->data, *hist = s->hist->data, *yb = s->yb->data;
    const double *u = s->u->data, *v = s->v->data, *a = s->a->data;
    for (size_t k = 0; k < n; k++) {
        up[k] = u[k] + dt * v[k] + (0.5 * dt * dt - b2) * a[k];
        vp[k] = v[k] + (dt - g) * a[k];
    }
    if (s->alpha != 0.0) { /* Newmark: hist = -M a to Newton's tolerance, and unused */
        fr_structure_net_force(s, s->ptil, s->u, s->v, s->hist); /* p~ - C v - K u */
        fr_csc_mult_add(s->Jt, 1.0, s->f->data, hist);
        for (size_t k = 0; k < n; k++)
            hist[k] = -hist[k];
        if (s->el.me > 0) /* the elements' forces on the structure, -J_e^T fe, at t */
            fr_csc_mult_add(s->el.Jt, 1.0, s->el.fe, hist);
    }
    fr_structure_net_force(s, s->ptil1, s->up, s->vp, s->yb); /* p~1 - C vp - K up */
    if (s->alpha != 0.0)
        for (size_t k = 0; k < n; k++)
            yb[k] = w * yb[k] + s->alpha * hist[k];
    if (joint) {
        fr_csc_mult_add(s->el.Jt, -w, s->el.fe, yb);
        gsl_vector_memcpy(s->x, s->yb);
    } else if (s->el.me > 0) {
        int status = fr_elements_newmark(s, dt, force_scale(s), s->yb, converged, iters);
        if (status != FRICREG_OK)
            return status;
    }
    fr_cfactor_forward(&s->step, yb, yb, &s->cc);
    if (joint) { /* q0 = J_e (u_pred + beta dt^2 K_eff^-1 b) */
        double *x0 = s->dx->data;
        fr_cfactor_backward(&s->step, yb, x0, &s->cc);
        for (size_t k = 0; k < n; k++)
            x0[k] = up[k] + b2 * x0[k];
        fr_csc_mult_t(s->el.Jt, x0, s->el.q0);
    }
    double *z0 = s->z0->data, *a0 = s->af0->data;
    fr_cfactor_project(&s->step, yb, a0, &s->cc); /* J x0 */
    fr_csc_mult_t(s->Jt, vp, z0);
    for (size_t i = 0; i < m; i++)
        z0[i] += g * a0[i];
    if (s->alpha != 0.0) { /* h = J M^-1 hist, through M's factor */
        fr_cfactor_forward(&s->mass, hist, s->work->data, &s->cc);
        fr_cfactor_project(&s->mass, s->work->data, s->mwork->data, &s->cc);
        for (size_t i = 0; i < m; i++)
            a0[i] -= s->alpha * s->mwork->data[i];
    }
    for (size_t i = 0; i < m; i++)
        a0[i] /= w;
    return FRICREG_OK;
}

int fr_newmark_solve(fricreg_structure *s, double dt, int *converged, int *iters)
{
    int status = form_step_factor(s, dt);
    if (status != FRICREG_OK)
        return status;
    dt = s->step_dt;
    int joint = fr_elements_joint(s);
    if ((status = fr_elements_compliance(s, joint)) != FRICREG_OK)
        return status;
    int el_converged = 1, el_iters = 0;
    if ((status = predict(s, dt, joint, &el_converged, &el_iters)) != FRICREG_OK ||
        (status = joint ? joint_newton(s, converged, iters) : newton(s, dt, converged, iters)) !=
            FRICREG_OK)
        return status;
    *converged = *converged && el_converged;
    *iters += el_iters;
    if (joint) { /* b with the elements' forces at the step's end, forward again */
        double *dfe = s->el.joint.dfe;
        for (size_t i = 0; i < s->el.nc; i++)
            dfe[i] = s->el.fe1[i] - s->el.fe[i];
        fr_csc_mult_add(s->el.Jt, -(1.0 + s->alpha), dfe, s->x->data);
        fr_cfactor_forward(&s->step, s->x->data, s->yb->data, &s->cc);
    }
    /* x = K_eff^-1 (b + w J^T f): the forward half is yb, the backward half completes it. */
    fr_cfactor_lift(&s->step, 1.0 + s->alpha, s->fk->data, s->yb->data, &s->cc);
    fr_cfactor_backward(&s->step, s->yb->data, s->x->data, &s->cc);
    double b2 = s->beta * dt * dt, g = s->gamma * dt, big = 0.0;
    for (size_t k = 0; k < s->n; k++) {
        double x = s->x->data[k], u1 = s->up->data[k] + b2 * x, v1 = s->vp->data[k] + g * x;
        s->u1->data[k] = u1;
        s->v1->data[k] = v1;
        big = fr_max_abs(fr_max_abs(fr_max_abs(big, u1), v1), x);
    }
    s->end_max = big;
    return FRICREG_OK;
}
