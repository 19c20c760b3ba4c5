/* SPDX-License-Identifier: GPL-3.0-or-later */
/* joint_step.c — a Newmark / HHT-alpha step of a structure with both friction contacts of
 * bound > 0 and elements (jenkins.c): one Newton over the stacked forces z = (f, fe).
 *
 * With w = 1 + alpha, c = w gamma dt, ce = w beta dt^2 and the step's equation
 * K_eff x = b + w J^T f - w J_e^T fe, the reference point is the contacts' f = 0 and the
 * elements' start forces fe0 (newmark.c's predict forms z0, a0 there and q0 = J_e (u_pred +
 * beta dt^2 K_eff^-1 b_ref)). Everything the two laws read is affine in z:
 *   zdot   = z0 + c (W_eff f - C (fe - fe0)),
 *   a_free = a0 - (W - W_eff) f - C (fe - fe0),
 *   q      = q0 + ce (C^T f - E (fe - fe0)),
 * W = J M^-1 J^T, W_eff = J K_eff^-1 J^T, E = J_e K_eff^-1 J_e^T and the cross block
 * C = J K_eff^-1 J_e^T (m x nc), which is what couples them. Newton solves
 *   G_c = f - F(zdot, a_free) = 0,   G_e = fe - F_e(q) = 0
 * on the dense (m + nc) matrix of the exact tangents: the contacts' rows from the context's
 * rows (fr_ctx_tangent_rows; newton_matrix.h derives them for the contacts alone, and the
 * cross block enters the same way: explicit rows df_i - c s_i [W_eff df - C dfe]_i = -G_i,
 * implicit rows (1 + c k_i)[W_eff df - C dfe]_i = -[W G]_i, the latter divided by
 * W_eff,ii so that they are of order one), or from the dense tangent (fricreg_ctx_tangent)
 * where the context has no rows; the elements' rows those of jenkins.c's condensed Newton with
 * the cross term, dfe - T (ce C^T df - ce E dfe) = -G_e. The direction by GSL's QR with column
 * pivoting; the merit the sum of squares of the contacts' R = w J^T G_c on the degrees of
 * freedom (newmark.c's) and of G_e (jenkins.c's); the line search from the contacts' first
 * stop (fr_newton_first_stop) or the full step, halved until the merit decreases by
 * Armijo's 1e-4. The step converges when both largest entries are within the tolerance.
 *
 * Dense: O((m + nc)^2) memory (allocated at the first such step after a model change) and
 * O((m + nc)^3) per iteration, for the few contacts and elements of a jointed structure; a
 * structure with elements and every bound 0, or without elements, never comes here. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "base/line_search.h"
#include "ctx/ctx_driver.h"
#include "base/newton_loop.h"
#include "structure_internal.h"

/* The contacts' velocities and free accelerations (s->zdot, s->afree), their law's forces
 * (s->f1) and G_c at z, then the elements' coordinates and G_e (jenkins.c, which also leaves
 * the tangents and the trial sliders); the merit's square root into *phi and the largest
 * entry of either residual into *rinf. FRICREG_OK or the context's status. */
static int evaluate(fricreg_structure *s, const double z[], double gc[], double ge[], double *phi,
                    double *rinf)
{
    struct fr_elements *e = &s->el;
    struct fr_joint *j = &e->joint;
    size_t m = s->m, nc = e->nc;
    double w = 1.0 + s->alpha, c = w * s->gamma * s->step_dt,
           ce = w * s->beta * s->step_dt * s->step_dt;
    const double *f = z, *fe = z + m;
    double *dfe = j->dfe;
    for (size_t k = 0; k < nc; k++)
        dfe[k] = fe[k] - j->fe0[k];
    fr_cfactor_compliance(&s->step, f, j->wf);
    fr_cfactor_compliance(&s->mass, f, j->mf);
    for (size_t i = 0; i < m; i++) {
        double cross = 0.0;
        for (size_t k = 0; k < nc; k++)
            cross += j->C[i * nc + k] * dfe[k];
        s->zdot->data[i] = s->z0->data[i] + c * (j->wf[i] - cross);
        s->afree->data[i] = s->af0->data[i] + (j->wf[i] - j->mf[i]) - cross;
    }
    int status = fr_structure_contact_forces(s, s->f1);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++)
        gc[i] = f[i] - s->f1->data[i];
    gsl_vector_view G = gsl_vector_view_array(gc, m);
    double phi_c, rinf_c, rinf_e;
    fr_structure_spread_norms(s, w, &G.vector, &phi_c, &rinf_c);
    for (size_t k = 0; k < nc; k++) {
        double q = 0.0;
        for (size_t i = 0; i < m; i++)
            q += j->C[i * nc + k] * f[i];
        for (size_t l = 0; l < nc; l++)
            q -= e->E[k * nc + l] * dfe[l];
        e->y[k] = e->q0[k] + ce * q;
    }
    double phi_e = fr_elements_residual(e, fe, ge, &rinf_e);
    *phi = fr_merit_pair(phi_c, phi_e);
    *rinf = isnan(rinf_e) || rinf_c <= rinf_e ? rinf_e : rinf_c; /* NaN propagates */
    return FRICREG_OK;
}

/* The contacts' rows of the Newton matrix from the context's dense tangent: row i of
 * I - c F_z W_eff + F_a (W - W_eff) over f, (c F_z + F_a) C over fe. */
static int dense_rows(fricreg_structure *s, double c)
{
    struct fr_joint *j = &s->el.joint;
    size_t m = j->m, nc = j->nc, dim = j->dim;
    int status = fricreg_ctx_tangent(s->ctx, m, j->Fz, j->Fa);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++) {
        double *row = j->T + i * dim;
        const double *fz = j->Fz + i * m, *fa = j->Fa + i * m;
        memset(row, 0, dim * sizeof *row);
        row[i] = 1.0;
        for (size_t k = 0; k < m; k++) {
            if (fz[k] == 0.0 && fa[k] == 0.0)
                continue;
            for (size_t l = 0; l < m; l++)
                row[l] += -c * fz[k] * j->Weff[k * m + l] +
                          fa[k] * (j->W[k * m + l] - j->Weff[k * m + l]);
            for (size_t l = 0; l < nc; l++)
                row[m + l] += (c * fz[k] + fa[k]) * j->C[k * nc + l];
        }
        j->rhs[i] = -j->gc[i];
        j->fz[i] = fz[i];
    }
    return FRICREG_OK;
}

/* The contacts' rows from the context's rows (fr_ctx_tangent_rows): 0 where it has none or an
 * implicit row's 1 + c k_i is not > 0 (then dense_rows). */
static int context_rows(fricreg_structure *s, double c)
{
    struct fr_joint *j = &s->el.joint;
    size_t m = j->m, nc = j->nc, dim = j->dim;
    if (fr_ctx_tangent_rows(s->ctx, j->implicit, j->coef) != FRICREG_OK)
        return 0;
    int any_implicit = 0;
    for (size_t i = 0; i < m; i++) {
        if (j->implicit[i] && !(1.0 + c * j->coef[i] > 0.0))
            return 0;
        any_implicit |= j->implicit[i];
    }
    if (any_implicit)
        fr_delassus_mult(s->mass.D, 1.0, j->gc, 0.0, j->wg); /* [W G] */
    for (size_t i = 0; i < m; i++) {
        double *row = j->T + i * dim, k = j->coef[i];
        const double *weff = j->Weff + i * m, *cross = j->C + i * nc;
        if (j->implicit[i]) { /* [W_eff df - C dfe]_i = -[W G]_i / (1 + c k_i), over W_eff,ii */
            double d = weff[i];
            for (size_t l = 0; l < m; l++)
                row[l] = weff[l] / d;
            for (size_t l = 0; l < nc; l++)
                row[m + l] = -cross[l] / d;
            j->rhs[i] = -j->wg[i] / ((1.0 + c * k) * d);
            j->fz[i] = -k;
        } else { /* df_i - c s_i [W_eff df - C dfe]_i = -G_i */
            for (size_t l = 0; l < m; l++)
                row[l] = -c * k * weff[l];
            row[i] += 1.0;
            for (size_t l = 0; l < nc; l++)
                row[m + l] = c * k * cross[l];
            j->rhs[i] = -j->gc[i];
            j->fz[i] = k;
        }
    }
    return 1;
}

/* d = -T^-1 (G_c, G_e) at the last evaluation. FRICREG_OK; FRICREG_ESINGULAR; the context's
 * tangent's status. */
static int direction(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    struct fr_joint *j = &e->joint;
    size_t m = j->m, nc = j->nc, dim = j->dim;
    double w = 1.0 + s->alpha, c = w * s->gamma * s->step_dt,
           ce = w * s->beta * s->step_dt * s->step_dt;
    int status = FRICREG_OK;
    if (!context_rows(s, c) && (status = dense_rows(s, c)) != FRICREG_OK)
        return status;
    for (size_t k = 0; k < nc; k++) { /* dfe - T_e ce (C^T df - E dfe) = -G_e */
        double *row = j->T + (m + k) * dim, t[3] = {0.0, 0.0, 0.0};
        size_t p[3] = {k, k, k}; /* the tangent's row: its diagonal, then up to two others */
        int n = fr_elements_tangent_row(e, k, p, t);
        for (int r = n; r < 3; r++)
            p[r] = k, t[r] = 0.0;
        for (size_t i = 0; i < m; i++)
            row[i] = -ce *
                     (t[0] * j->C[i * nc + k] + (t[1] != 0.0 ? t[1] * j->C[i * nc + p[1]] : 0.0) +
                      (t[2] != 0.0 ? t[2] * j->C[i * nc + p[2]] : 0.0));
        for (size_t l = 0; l < nc; l++)
            row[m + l] = ce * (t[0] * e->E[k * nc + l] +
                               (t[1] != 0.0 ? t[1] * e->E[p[1] * nc + l] : 0.0) +
                               (t[2] != 0.0 ? t[2] * e->E[p[2] * nc + l] : 0.0));
        row[m + k] += 1.0;
        j->rhs[m + k] = -j->ge[k];
    }
    gsl_matrix_view T = gsl_matrix_view_array(j->T, dim, dim);
    gsl_vector_view tau = gsl_vector_view_array(j->tau, dim),
                    norm = gsl_vector_view_array(j->norm, dim),
                    rhs = gsl_vector_view_array(j->rhs, dim), d = gsl_vector_view_array(j->d, dim);
    gsl_permutation perm = {dim, j->perm};
    int signum;
    if (gsl_linalg_QRPT_decomp(&T.matrix, &tau.vector, &perm, &signum, &norm.vector) != GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    for (size_t i = 0; i < dim; i++)
        if (!(fabs(j->T[i * dim + i]) > 0.0))
            return FRICREG_ESINGULAR; /* the solve would call GSL's error handler */
    if (gsl_linalg_QRPT_solve(&T.matrix, &tau.vector, &perm, &rhs.vector, &d.vector) != GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    return FRICREG_OK;
}

/* A trial z + lambda d into zt and its residuals; accepted by Armijo on the merit, they become
 * z's (every evaluation's by-products are then at z). */
struct joint_trial {
    fricreg_structure *s;
    const struct fr_line_search *ls;
    double *phi, *rinf;
};

static int joint_trial(void *user, double lambda, int *accept)
{
    struct joint_trial *t = user;
    struct fr_joint *j = &t->s->el.joint;
    size_t dim = j->dim;
    for (size_t i = 0; i < dim; i++)
        j->zt[i] = j->z[i] + lambda * j->d[i];
    double phi_t, rinf_t;
    *accept = evaluate(t->s, j->zt, j->gct, j->get, &phi_t, &rinf_t) == FRICREG_OK &&
              fr_armijo_decrease(t->ls, *t->phi, phi_t, lambda);
    if (*accept) {
        memcpy(j->z, j->zt, dim * sizeof *j->z);
        memcpy(j->gc, j->gct, j->m * sizeof *j->gc);
        memcpy(j->ge, j->get, j->nc * sizeof *j->ge);
        *t->phi = phi_t;
        *t->rinf = rinf_t;
    }
    return FRICREG_OK;
}

/* Backtracking along d from z (stops: from the contacts' first stop); on success z, its
 * residuals and every evaluation's by-products are at the accepted point. 0 if no cut
 * decreased the merit. */
static int line_search(fricreg_structure *s, int stops, double *phi, double *rinf)
{
    struct fr_joint *j = &s->el.joint;
    size_t m = j->m, nc = j->nc;
    double lambda = 1.0, c = (1.0 + s->alpha) * s->gamma * s->step_dt;
    if (stops) { /* the velocities' change over the full step, over c */
        fr_cfactor_compliance(&s->step, j->d, j->dzc);
        for (size_t i = 0; i < m; i++)
            for (size_t k = 0; k < nc; k++)
                j->dzc[i] -= j->C[i * nc + k] * j->d[m + k];
        lambda = fr_newton_first_stop(m, s->zdot->data, j->dzc, c, fr_ctx_eps(s->ctx), s->mun,
                                      j->fz, s->stopped);
    }
    struct fr_line_search ls = {FR_ARMIJO, FR_STEP_HALVINGS,
                                &s->stats[FRICREG_SSTAT_LINE_SEARCH_CUTS]};
    struct joint_trial t = {s, &ls, phi, rinf};
    int accepted;
    fr_line_search(&ls, lambda, joint_trial, &t, &accepted); /* the trials cannot fail */
    return accepted;
}

/* The loop's view of the joint Newton (newton_loop.h). */
struct joint_loop {
    fricreg_structure *s;
    int stops;
};

static int joint_direction(void *user)
{
    fricreg_structure *s = ((struct joint_loop *)user)->s;
    if (s->el.overflow != 0) /* no direction from an infinite tangent */
        return FRICREG_ENONFINITE;
    return direction(s);
}

static int joint_search(void *user, double *phi, double *rinf, int *accepted)
{
    struct joint_loop *l = user;
    *accepted = line_search(l->s, l->stops, phi, rinf);
    return FRICREG_OK;
}

static void joint_restore(void *user, double *phi, double *rinf)
{
    struct fr_joint *j = &((struct joint_loop *)user)->s->el.joint;
    evaluate(((struct joint_loop *)user)->s, j->z, j->gc, j->ge, phi, rinf);
}

/* Newton from z (evaluated) until rinf <= tol, the iterations run out, an element overflowed,
 * the tangent is singular or the line search stalls (back to z): newton_loop.h's. */
static void iterate(fricreg_structure *s, double tol, int stops, double *phi, double *rinf,
                    int *iters)
{
    struct joint_loop l = {s, stops};
    struct fr_newton_loop nl = {tol,          s->newton_max, 0,    &l,  joint_direction,
                                joint_search, joint_restore, NULL, NULL};
    fr_newton_loop_run(&nl, phi, rinf, iters); /* its end is the step's: judged by solve */
}

/* z = (f, fe0) evaluated. */
static int start_at(fricreg_structure *s, const double f[], double *phi, double *rinf)
{
    struct fr_joint *j = &s->el.joint;
    memcpy(j->z, f, j->m * sizeof *j->z);
    memcpy(j->z + j->m, j->fe0, j->nc * sizeof *j->z);
    int status = evaluate(s, j->z, j->gc, j->ge, phi, rinf);
    if (status != FRICREG_OK)
        return fr_fail(s, status, "step: friction at t = %g: %s", s->t + s->step_dt,
                       fricreg_ctx_errmsg(s->ctx));
    return FRICREG_OK;
}

/* fr_joint_newton's iterations: z ends at the step's forces. */
static int solve(fricreg_structure *s, double tol, const double guess[], int *converged, int *iters)
{
    double phi = 0.0, rinf = 0.0, phi_guess = INFINITY;
    int status;
    if (guess != NULL) { /* the contacts' band guess with the elements at their start forces */
        if ((status = start_at(s, guess, &phi, &rinf)) != FRICREG_OK)
            return status;
        if (rinf <= tol) { /* the solution on the guess's pieces: a Newton step, converged */
            *iters = 1;
            *converged = 1;
            return FRICREG_OK;
        }
        phi_guess = phi;
    }
    if ((status = start_at(s, s->f->data, &phi, &rinf)) != FRICREG_OK)
        return status;
    if (rinf > tol && phi_guess < phi && (status = start_at(s, guess, &phi, &rinf)) != FRICREG_OK)
        return status;
    iterate(s, tol, 1, &phi, &rinf, iters);
    if (rinf > tol && isfinite(phi) && *iters < s->newton_max) { /* again, without stops */
        if ((status = start_at(s, s->f->data, &phi, &rinf)) != FRICREG_OK)
            return status;
        iterate(s, tol, 0, &phi, &rinf, iters);
    }
    if (s->el.overflow != 0 && !(rinf <= tol)) /* at the last iterate: its force or tangent */
        return fr_elements_overflow(s, s->t + s->step_dt);
    if (!isfinite(phi))
        return fr_fail(s, FRICREG_EDIVERGED, "step: the residual at t = %g is not finite",
                       s->t + s->step_dt);
    *converged = rinf <= tol;
    return FRICREG_OK;
}

int fr_joint_newton(fricreg_structure *s, double tol, const double guess[], int *converged,
                    int *iters)
{
    struct fr_elements *e = &s->el;
    struct fr_joint *j = &e->joint;
    *iters = 0;
    *converged = 0;
    memcpy(j->fe0, e->fe, j->nc * sizeof *j->fe0);
    memset(s->stopped, 0, j->m * sizeof *s->stopped); /* the guess's marks */
    int status = solve(s, tol, guess, converged, iters);
    memset(s->stopped, 0, j->m * sizeof *s->stopped);
    memcpy(s->fk->data, j->z, j->m * sizeof *j->z);
    memcpy(e->fe1, j->z + j->m, j->nc * sizeof *e->fe1);
    fr_elements_bound(e, e->fe1);
    return status;
}
