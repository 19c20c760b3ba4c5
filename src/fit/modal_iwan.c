/* SPDX-License-Identifier: GPL-3.0-or-later */
/* modal_iwan.c — the modal Iwan model's backbone by the closed forms of fricreg_fit.h (Segalman
 * 2005's density, Masing's dissipation, the quasi-static modal analysis), differentiated
 * forward (dual.h), and its modal amplitude at a measured level. */
#include <float.h>
#include <math.h>

#include <gsl/gsl_errno.h>

#include "base/fr_math.h"
#include "modal_iwan.h"

#define ROOT_MAX_ITER 200
#define BRACKET_DOUBLINGS 200 /* a 2^200-fold amplitude: beyond it, out of reach */

/* The joint's backbone force F and dissipation per cycle D at the modal amplitude a. */
static void joint(const fr_dual p[], fr_dual a, fr_dual *force, fr_dual *diss)
{
    fr_dual fs = p[FRICREG_FIT_FS], chi = p[FRICREG_FIT_CHI], beta = p[FRICREG_FIT_BETA];
    fr_dual chi1 = fr_dual_add_c(chi, 1.0), chi2 = fr_dual_add_c(chi, 2.0);
    fr_dual chi3 = fr_dual_add_c(chi, 3.0), beta1 = fr_dual_add_c(beta, 1.0);
    fr_dual c = fr_dual_add(beta, fr_dual_div(chi1, chi2));
    fr_dual phi_max = fr_dual_div(fr_dual_mul(fs, beta1), fr_dual_mul(p[FRICREG_FIT_KT], c));
    fr_dual x = fr_dual_div(a, phi_max);
    fr_dual scale = fr_dual_div(fr_dual_scale(4.0, fr_dual_mul(fs, phi_max)), c);
    if (x.v < 1.0) {
        fr_dual slip = fr_dual_div(fr_dual_pow(x, chi2), chi2); /* x^(chi+2)/(chi+2) */
        *force = fr_dual_mul(fr_dual_div(fs, c), fr_dual_sub(fr_dual_mul(beta1, x), slip));
        fr_dual xc3 = fr_dual_pow(x, chi3);
        *diss = fr_dual_div(fr_dual_mul(scale, fr_dual_mul(chi1, xc3)), fr_dual_mul(chi2, chi3));
    } else {
        *force = fs;
        fr_dual partial = fr_dual_mul(chi1, fr_dual_sub(fr_dual_div(x, chi2),
                                                        fr_dual_div(fr_dual_const(1.0), chi3)));
        fr_dual macro = fr_dual_mul(beta, fr_dual_add_c(x, -1.0));
        *diss = fr_dual_mul(scale, fr_dual_add(partial, macro));
    }
}

void fr_modal_iwan_backbone(const double p[], double a, fr_dual *omega, fr_dual *zeta)
{
    fr_dual q[FRICREG_FIT_NPARAMS], amp = fr_dual_var(a, FR_DUAL_A), force, diss;
    for (int j = 0; j < FRICREG_FIT_NPARAMS; j++)
        q[j] = fr_dual_var(p[j], j);
    joint(q, amp, &force, &diss);
    fr_dual k_sec = fr_dual_add(q[FRICREG_FIT_K0], fr_dual_div(force, amp));
    *omega = fr_dual_sqrt(k_sec);
    fr_dual strain = fr_dual_scale(FR_TWO_PI, fr_dual_mul(k_sec, fr_dual_mul(amp, amp)));
    *zeta = fr_dual_add(q[FRICREG_FIT_ZETA0], fr_dual_div(diss, strain));
}

/* |s| omega^kind a at a, differentiated. */
static fr_dual response(const double p[], int kind, double s, double a)
{
    fr_dual omega, zeta, r = fr_dual_var(fabs(s) * a, FR_DUAL_A);
    r.d[FR_DUAL_A] = fabs(s);
    fr_modal_iwan_backbone(p, a, &omega, &zeta);
    for (int k = 0; k < kind; k++)
        r = fr_dual_mul(r, omega);
    return r;
}

struct level_root {
    const double *p;
    int kind;
    double s, target;
};

static double level_residual(double a, void *params)
{
    const struct level_root *q = params;
    return response(q->p, q->kind, q->s, a).v - q->target;
}

/* The modal amplitude of the level, or -1 if out of reach. omega <= sqrt(K0 + K_T), so the
 * linear structure's amplitude is a lower end of the bracket; doubling finds the upper. */
static double modal_amplitude(const double p[], int kind, double s, double A,
                              gsl_root_fsolver *brent)
{
    double omega_lin = sqrt(p[FRICREG_FIT_K0] + p[FRICREG_FIT_KT]);
    double lo = A / (fabs(s) * pow(omega_lin, kind));
    if (kind == FRICREG_FIT_DISPLACEMENT)
        return lo;
    struct level_root q = {p, kind, s, A};
    double f_lo = level_residual(lo, &q);
    if (f_lo >= 0.0)
        return lo;
    double hi = 2.0 * lo;
    int n = 0;
    while (level_residual(hi, &q) <= 0.0) {
        if (++n > BRACKET_DOUBLINGS)
            return -1.0;
        lo = hi;
        hi *= 2.0;
    }
    gsl_function F = {level_residual, &q};
    gsl_root_fsolver_set(brent, &F, lo, hi); /* signs bracket the root: no GSL error */
    double a = lo;
    for (int it = 0; it < ROOT_MAX_ITER; it++) {
        gsl_root_fsolver_iterate(brent);
        a = gsl_root_fsolver_root(brent);
        double l = gsl_root_fsolver_x_lower(brent), u = gsl_root_fsolver_x_upper(brent);
        if (gsl_root_test_interval(l, u, 0.0, 4.0 * DBL_EPSILON) == GSL_SUCCESS)
            break;
    }
    return a;
}

int fr_modal_iwan_level(const double p[], int kind, double s, double A, gsl_root_fsolver *brent,
                        struct fr_level_model *m)
{
    double a = modal_amplitude(p, kind, s, A, brent);
    if (!(a > 0.0))
        return -1;
    fr_dual omega, zeta, h = response(p, kind, s, a);
    if (!(h.d[FR_DUAL_A] > 0.0)) /* a flat response (K0 = 0 in macroslip): a not determined */
        return -1;
    fr_modal_iwan_backbone(p, a, &omega, &zeta);
    m->freq_hz = omega.v / FR_TWO_PI;
    m->zeta = zeta.v;
    m->modal = a;
    for (int j = 0; j < FRICREG_FIT_NPARAMS; j++) {
        double da = -h.d[j] / h.d[FR_DUAL_A]; /* h(a(p), p) = A held */
        m->dfreq[j] = (omega.d[j] + omega.d[FR_DUAL_A] * da) / FR_TWO_PI;
        m->dzeta[j] = zeta.d[j] + zeta.d[FR_DUAL_A] * da;
    }
    return 0;
}
