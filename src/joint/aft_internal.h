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
                          at [(2D+1) h + k]: the half-angle form of e^{i h phi} (aft_exact.c),
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

    /* sampled path */
    double *ctab, *stab; /* [N] cos, sin of 2 pi n/N */
    double *us;          /* [N] u at the samples */
    double *fs;          /* [N] f at the samples; the FFT's array */
    double *ts;          /* [N] one slider's tangent at the samples: kt (stick) or 0 */
    size_t *anchor;      /* [N] one slider's anchor at each sample: the sample where it
                            stopped, or N for the centred stick (aft_sampled.c) */
    double *ds;          /* [nc N] the Jacobian's columns in time, column j at [N j], summed
                            over the sliders, then transformed in place */

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

/* Sampled AFT of the same, into the same buffers. Cannot fail on checked inputs. */
void fr_aft_sampled(fricreg_aft *aft, size_t ns, const double *k, const double *phi,
                    const double *u, int want_jac);

/* Sampled AFT of one Jenkins element under normal load with lift-off (aft_normal.c): from
 * the checked u[nc], g[nc], the coefficients of f into f[nc] and of N into nf[nc] and, with
 * jac not NULL, the Jacobian jac[2nc x 2nc] (fricreg_aft_jenkins_normal_sampled). Cannot
 * fail on checked inputs; the outputs are written last, so they may alias u and g. */
void fr_aft_sampled_normal(fricreg_aft *aft, double kt, double mu, double n0, double kn,
                           const double *u, const double *g, double *f, double *nf, double *jac);

/* phi_j at sample n of the sampled path, by the tables: cos, sin of h theta_n at index
 * h n mod N. */
double fr_aft_sample_basis(const fricreg_aft *a, size_t j, size_t n);

/* Coefficients of the sampled sequence x[N] (transformed in place, x destroyed) into
 * out[i * stride], i = 0 .. 2H: f0 = X_0/N, fa_h = 2 Re X_h/N, fb_h = -2 Im X_h/N. */
void fr_aft_sample_coefficients(const fricreg_aft *a, double *x, double *out, size_t stride);

#endif
