/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_internal.h — the AFT workspace's layout (fricreg_aft.h) and the two paths' kernels:
 * aft.c checks the inputs and copies the results out, aft_exact.c and aft_sampled.c compute
 * them into the workspace's result buffers. Included only inside src/joint/. */
#ifndef FRICREG_JOINT_AFT_INTERNAL_H
#define FRICREG_JOINT_AFT_INTERNAL_H

#include <stddef.h>

#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>

#include "base/error.h"
#include "fricreg_aft.h"

struct fricreg_aft {
    int H;     /* harmonics */
    size_t nc; /* coefficients 2H + 1 */
    size_t N;  /* samples of the sampled path, 0 if none */

    /* exact path */
    double *qre, *qim; /* [(H+1)(2H+1)]: (1 + i t)^(D+h) (1 - i t)^(D-h), coefficient of t^k
                          at [(2D+1) h + k]: the half-angle form of e^{i h phi} (aft_roots.c),
                          for the degree D = table_H <= H of the last root solve */
    int table_H;
    double *poly;                  /* [2H+1] the real polynomial in t handed to GSL */
    double *roots;                 /* [4H] its complex roots, packed (re, im) */
    gsl_poly_complex_workspace ws; /* matrix [(2H)^2], allocated here; nc set per solve */
    gsl_root_fsolver *brent;       /* GSL's Brent for the stick-slip onsets, allocated here */
    double *cand;                  /* [2H] a root solve's angles (the real parts) */
    double *cim;                   /* [2H] their imaginary parts' size, |Im theta| to first order */
    double *rev;                   /* [2H] the reversals kept, sorted in [0, 2pi) */
    int *rdir;                     /* [2H] sign of u' after each reversal */
    double *cm, *sm;               /* [2H+1] a piece's integrals of cos m theta, sin m theta */
    double *gram;                  /* [nc nc] a piece's integrals of phi_i phi_j */
    double *phw;                   /* [nc] the basis at the slider's anchor theta_w */
    double *dcoef; /* [nc] scratch: the coefficients of a trigonometric polynomial */
    double *nroot; /* [3][2H] lift-off path: sign changes of v+, v-, the gap (aft_normal_exact.c) */
    int *ndir;     /* [3][2H] the sign after each of them */
    double *ncoef; /* [6][nc] lift-off path: v+, v-, the gap, a stick margin, copies of u, g */

    /* sampled path */
    double *ctab, *stab; /* [N] cos, sin of 2 pi n/N */
    double *us;          /* [N] u at the samples */
    double *fs;          /* [N] f at the samples; the FFT's array */
    double *ts;          /* [N] one slider's tangent at the samples: kt (stick) or 0 */
    size_t *anchor;      /* [N] one slider's anchor at each sample: the sample where it
                            stopped, or N for the centred stick (aft_sampled.c) */
    double *ds;          /* [nc N] the Jacobian's columns in time, column j at [N j], summed
                            over the sliders, then transformed in place */
    double *s2;          /* [8 N] the 2-D element's samples and record (aft_2d.c) */

    /* results, copied out on success */
    double *fout; /* [nc] */
    double *jout; /* [nc nc] */
    struct fr_error err;
};

/* The basis phi_j(theta) of the coefficient layout: 1, cos theta, sin theta, cos 2 theta, ... */
void fr_aft_basis(int H, double theta, double *phi);

/* The table qre, qim for degree D (1 <= D <= H); sets table_H. Uses cm and sm as scratch. */
void fr_aft_half_angle_table(fricreg_aft *a, int D);

/* Exact AFT of ns sliders (k[s], phi[s]) under u[nc] (checked), summed into aft->fout and,
 * when want_jac, aft->jout (both zeroed here). FRICREG_OK, or FRICREG_EINTEGRATOR with the
 * message recorded if GSL's root solver failed. */
int fr_aft_exact(fricreg_aft *aft, const char *fn, size_t ns, const double *k, const double *phi,
                 const double *u, int want_jac);

/* g(theta) of the trigonometric polynomial co[2H+1], g'(theta) into *dg. */
double fr_aft_trig_eval(int H, const double *co, double theta, double *dg);

/* The sign changes of the trigonometric polynomial co (not constant, entries of order 1) in
 * [0, 2pi), sorted, into roots[], the sign of co after each into dir[], their count into *m
 * (0: co keeps one sign). Grid isolation with GSL's Brent, the companion matrix where the grid
 * cannot certify (aft_roots.c). FRICREG_OK, or FRICREG_EINTEGRATOR (message recorded). Uses
 * cand, cim, poly, roots, qre, qim as scratch. */
int fr_aft_sign_changes(fricreg_aft *a, const char *fn, const double *co, double *roots, int *dir,
                        int *m);

/* The angles of the global maximum and minimum of u (0 and 0 for a constant u), from its
 * velocity reversals. FRICREG_OK or FRICREG_EINTEGRATOR (message recorded). */
int fr_aft_extremes(fricreg_aft *a, const char *fn, const double *u, double *thmax, double *thmin);

/* The root of co in [lo, hi] where co changes sign: GSL's Brent, then Newton's polish. */
double fr_aft_root_in(fricreg_aft *a, const double *co, double lo, double hi);

/* A piece [al, be]: its Gram matrix G_ij = int phi_i phi_j into a->gram (and int cos, sin
 * into cm, sm). */
void fr_aft_gram(fricreg_aft *a, double al, double be);

/* Weight of coefficient i: 1/(2 pi) for the mean, 1/pi for the harmonics. */
double fr_aft_weight(size_t i);

/* A stick piece [al, be] of f = kt u - kw, the slider w anchored at thw as the force kw = kt w
 * (finite where w is not: w = u - mu P/kt overflows for a subnormal kt; dw/du_j =
 * phi_j(thw)), added to fout and, when want_jac, to jout (nc x nc, row stride nc). */
void fr_aft_add_stick(fricreg_aft *a, double kt, const double *u, double kw, double thw, double al,
                      double be, int want_jac);

/* Exact AFT of one Jenkins element under normal load with lift-off (aft_normal_exact.c), the
 * exact counterpart of fr_aft_sampled_normal, same outputs. FRICREG_OK or FRICREG_EINTEGRATOR
 * (message recorded, outputs untouched). */
int fr_aft_exact_normal(fricreg_aft *aft, const char *fn, double kt, double mu, double n0,
                        double kn, const double *u, const double *g, double *f, double *nf,
                        double *jac);

/* Sampled AFT of the same, into the same buffers. Cannot fail on checked inputs. */
void fr_aft_sampled(fricreg_aft *aft, size_t ns, const double *k, const double *phi,
                    const double *u, int want_jac);

/* Sampled AFT of one Jenkins element under normal load with lift-off (aft_normal.c): from
 * the checked u[nc], g[nc], the coefficients of f into f[nc] and of N into nf[nc] and, with
 * jac not NULL, the Jacobian jac[2nc x 2nc] (fricreg_aft_jenkins_normal_sampled). Cannot
 * fail on checked inputs; the outputs are written last, so they may alias u and g. */
void fr_aft_sampled_normal(fricreg_aft *aft, double kt, double mu, double n0, double kn,
                           const double *u, const double *g, double *f, double *nf, double *jac);

/* Sampled AFT of the 3-D contact element (aft_2d.c): from the checked u[2 nc] (ux, then uy)
 * and g[nc], the coefficients of fx, fy into f[2 nc] and of N into nf[nc] and, with jac not
 * NULL, the Jacobian jac[3nc x 3nc] (fricreg_aft_jenkins_2d_normal_sampled). Cannot fail on
 * checked inputs; the outputs are written after u and g are read. */
void fr_aft_sampled_2d_normal(fricreg_aft *aft, double kt, double mu, double n0, double kn,
                              const double *u, const double *g, double *f, double *nf, double *jac);

/* The samples of the trigonometric polynomial c[nc] into x[N]. */
void fr_aft_sample_values(const fricreg_aft *a, const double *c, double *x);

/* phi_j at sample n of the sampled path, by the tables: cos, sin of h theta_n at index
 * h n mod N. */
double fr_aft_sample_basis(const fricreg_aft *a, size_t j, size_t n);

/* Coefficients of the sampled sequence x[N] (transformed in place, x destroyed) into
 * out[i * stride], i = 0 .. 2H: f0 = X_0/N, fa_h = 2 Re X_h/N, fb_h = -2 Im X_h/N. */
void fr_aft_sample_coefficients(const fricreg_aft *a, double *x, double *out, size_t stride);

/* The exact paths' sticks below the rounding of u. A stick moves the slider's spring by at
 * most 2 mu N / kt before it slips, but u(θ) − w is evaluated to about DBL_EPSILON sum |u_j|:
 * where mu max N <= UNRESOLVED_STICK kt sum |u_j| (a stick of 1e-6 rad at most) its end would
 * be found in rounding noise and its force, up to DBL_EPSILON kt sum |u_j|, would exceed
 * mu N by orders of magnitude (6e-15 against 1e-200 with lift-off, 5e-231 against 5.5e-306
 * without). Such sticks take no time: the slider follows u and f = ±mu N between the
 * reversals, which is the limit. */
#define UNRESOLVED_STICK 1e-12

#endif
