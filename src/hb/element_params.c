/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_params.c — an element's force coefficients differentiated in one of its parameters
 * (element_params.h), exactly and without another AFT for a one-slider element: every law HB
 * runs by its own AFT is homogeneous in its parameters, and so is the AFT (the centred start,
 * the reversals, the rounding thresholds, Richardson's 2 F(N) − F(N/2)). A slider of stiffness
 * k and slip force phi has
 *
 *     (A) f(u; λk, λphi) = λ f(u; k, phi),      (B) f(λu; k, λphi) = λ f(u; k, phi),
 *
 * so, differentiated at λ = 1 with J = ∂F/∂U the AFT's Jacobian, phi dF/dphi = F − J U and
 * k dF/dk = J U. With a normal law N = max(0, n0 + kn g) and slip bounds mu_s N, F depends on
 * n0 only through g + n0/kn, so dF/dn0 = J[:, g_0]/kn (g_0 the mean of g; with kn = 0 (B) on
 * (U, G, n0) gives n0 dF/dn0 = F − J (U, G)); (B) on the tangential U and the mu_s gives
 * mu dF_t/dmu = F_t − J_tt U and N independent of mu and kt; (A) on every stiffness and n0
 * gives kn dF/dkn = F − J_tt U − n0 dF/dn0. An Iwan element's sliders are independent: slider
 * s's F_s and J_s come from its own exact AFT (one slider of the element's law), the identities
 * applied to them. The marched types of a stiffness and a bound (jenkins_2d, jenkins_3d, dahl:
 * σ and fc scale as k and phi), the spring and the marched Iwan sliders (iwan_2d, iwan_3d,
 * slider s by the march of one slider) likewise, on the march's forces and Jacobian, exact for
 * its samples (with Richardson's extrapolation where it lags: linear, so the identities hold for
 * it). */
#include <string.h>

#include "fricreg_element.h"
#include "hb_internal.h"
#include "element_params.h"
#include "joint/aft_march.h"

/* The name of element e's law, as fricreg_element.h's table has it. */
static const char *law_name(int kind, size_t ns)
{
    if (kind == FR_HB_CONTACT_3D)
        return "contact_3d";
    if (kind == FR_HB_LIFTOFF)
        return ns > 1 ? "iwan_normal" : "jenkins_normal";
    return ns > 1 ? "iwan" : "jenkins";
}

/* A marched type whose parameters' identities are known: *iwan its sliders' family (k[ns],
 * phi[ns]), else parameter 0 a stiffness and 1 (if any) a bound. */
static int marched_known(const fricreg_element_type *type, int *iwan)
{
    static const char *const names[] = {"jenkins_2d", "jenkins_3d", "spring",
                                        "dahl",       "iwan_2d",    "iwan_3d"};
    const char *name = fricreg_element_name(type);
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strcmp(name, names[i]) == 0) {
            *iwan = i >= 4;
            return 1;
        }
    return 0;
}

/* Where parameter j of element e divides: its value (0 where nothing does), or refuses. */
static int marched_check(fricreg_hb *hb, const char *fn, const char *what, size_t e, size_t j)
{
    const fricreg_element_type *type = hb->etype[e];
    const char *name = fricreg_element_name(type);
    int iwan = 0;
    if (!marched_known(type, &iwan))
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: element %zu is of the marched type %s, whose parameters' "
                       "derivatives are not supported",
                       fn, what, e, name);
    size_t np = fricreg_element_nparams(type), ns = iwan ? fricreg_element_nsliders(type) : 1;
    if (j >= np)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: index %zu, element %zu (%s) has %zu parameters (from 0)", fn, what,
                       j, e, name, np);
    if (j >= ns && hb->ep[hb->epo[e] + j] == 0.0)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: element %zu (%s): its bound is 0 (the identity divides by it)", fn,
                       what, e, name);
    return FRICREG_OK;
}

int fr_hb_element_param_check(fricreg_hb *hb, const char *fn, const char *what, size_t e, size_t j)
{
    int kind = hb->kind[e];
    if (kind == FR_HB_MARCH)
        return marched_check(hb, fn, what, e, j);
    const double *k, *phi;
    size_t ns = fr_hb_sliders(hb, e, &k, &phi), me = hb->me;
    int normal = kind != FR_HB_SLIDERS;
    size_t nparams = normal ? 2 * ns + 3 : 2 * ns;
    const char *law = law_name(kind, ns);
    double n0 = hb->nl[2 * me + e], kn = hb->nl[3 * me + e];
    if (j >= nparams)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: index %zu, element %zu (%s) has %zu parameters (from 0)", fn, what,
                       j, e, law, nparams);
    if (normal && j == 2 * ns + 2)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: element %zu (%s): HB's normal law has no gap (its preload is n0)",
                       fn, what, e, law);
    if (j >= ns && j < 2 * ns && phi[j - ns] == 0.0)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: element %zu (%s): its %s is 0 (the identity divides by it; the "
                       "rigid-plastic limit is not taken)",
                       fn, what, e, law, normal ? "mu" : "slip force");
    if (normal && j == 2 * ns && kn == 0.0)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: element %zu (%s): kn is 0 (the identity divides by it)", fn, what,
                       e, law);
    if (normal && j == 2 * ns + 1 && kn == 0.0 && n0 == 0.0)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: element %zu (%s): kn and n0 are both 0 (the identities divide by "
                       "one of them)",
                       fn, what, e, law);
    return FRICREG_OK;
}

/* Row i of the b-wide J times u over the columns [0, cols). */
static double row_times(const double *J, size_t b, size_t i, size_t cols, const double *u)
{
    double s = 0.0;
    for (size_t c = 0; c < cols; c++)
        s += J[i * b + c] * u[c];
    return s;
}

/* Slider s of element e alone (an Iwan element's): its forces and Jacobian into fs, Js by the
 * element's own exact AFT with that one slider. */
static int one_slider(fricreg_hb *hb, const char *fn, size_t e, size_t s, const double *u,
                      double *fs, double *Js)
{
    const double *k, *phi;
    size_t nc = hb->nc, me = hb->me;
    fr_hb_sliders(hb, e, &k, &phi);
    int status = hb->kind[e] == FR_HB_SLIDERS
                     ? fricreg_aft_iwan_exact(hb->aft, 1, k + s, phi + s, nc, u, fs, Js)
                     : fricreg_aft_jenkins_normal_exact(hb->aft, k[s], phi[s], hb->nl[2 * me + e],
                                                        hb->nl[3 * me + e], nc, u, u + nc, fs,
                                                        fs + nc, Js);
    if (status != FRICREG_OK)
        return fr_fail(hb, status, "%s: the AFT of element %zu's slider %zu failed: %s", fn, e, s,
                       fricreg_aft_errmsg(hb->aft));
    return FRICREG_OK;
}

/* Slider s of marched Iwan element e alone (a one-slider type of its family): forces and
 * Jacobian into fs, Js, with Richardson's extrapolation where the march lags (hb->half the
 * N/2 samples' scratch). */
static int marched_slider(fricreg_hb *hb, const char *fn, size_t e, size_t s, const double *u,
                          double *fs, double *Js)
{
    const fricreg_element_type *type = fricreg_element_sliders(hb->etype[e], 1);
    size_t ns = fricreg_element_nsliders(hb->etype[e]), b = fr_hb_rows_of(hb, e) * hb->nc;
    const double *p = hb->ep + hb->epo[e], ps[2] = {p[s], p[ns + s]};
    double *fh = hb->half, *jh = hb->half + b;
    int status = fr_aft_march(hb->aft, hb->march, type, ps, u, fs, Js);
    if (status == FRICREG_OK && fr_aft_march_lags(type))
        status = fr_aft_march(hb->aft_half, hb->march, type, ps, u, fh, jh);
    if (status != FRICREG_OK)
        return fr_fail(hb, status, "%s: the march of element %zu's slider %zu failed (%s)", fn, e,
                       s, fricreg_strerror(status));
    for (size_t i = 0; fr_aft_march_lags(type) && i < b; i++)
        fs[i] = 2.0 * fs[i] - fh[i];
    for (size_t i = 0; fr_aft_march_lags(type) && i < b * b; i++)
        Js[i] = 2.0 * Js[i] - jh[i];
    return FRICREG_OK;
}

/* Marched element e's parameter j: a stiffness (J U / k) or a bound ((F − J U) / phi) of the
 * element, or of its slider s alone. */
static int marched_dfdp(fricreg_hb *hb, const char *fn, size_t e, size_t j, const double *u,
                        const double *f, double *out, double *work)
{
    int iwan = 0;
    marched_known(hb->etype[e], &iwan);
    size_t b = fr_hb_rows_of(hb, e) * hb->nc,
           ns = iwan ? fricreg_element_nsliders(hb->etype[e]) : 1;
    size_t s = iwan ? j % ns : 0;
    const double *p = hb->ep + hb->epo[e], *fs = f, *Js = fr_hb_block_of(hb, e);
    double value = p[j];
    if (iwan && ns > 1) {
        int status = marched_slider(hb, fn, e, s, u, work, work + b);
        if (status != FRICREG_OK)
            return status;
        fs = work;
        Js = work + b;
    }
    for (size_t i = 0; i < b; i++) {
        double ju = row_times(Js, b, i, b, u);
        out[i] += j < ns ? ju / value : (fs[i] - ju) / value;
    }
    return FRICREG_OK;
}

int fr_hb_element_dfdp(fricreg_hb *hb, const char *fn, size_t e, size_t j, const double *q,
                       double *df, double *work)
{
    size_t nc = hb->nc, me = hb->me, rows = fr_hb_rows_of(hb, e), b = rows * nc;
    size_t at = hb->erow[e] * nc;
    const double *u = q + at, *f = hb->fq + at, *J = fr_hb_block_of(hb, e), *k, *phi;
    size_t ns = fr_hb_sliders(hb, e, &k, &phi);
    size_t nt = hb->kind[e] == FR_HB_SLIDERS ? b : (rows - 1) * nc; /* the tangential rows */
    double *out = df + at;
    if (hb->kind[e] == FR_HB_MARCH)
        return marched_dfdp(hb, fn, e, j, u, f, out, work);
    if (j < 2 * ns) { /* slider s's k or phi (mu): its F_s, J_s (b x b) the element's if alone */
        size_t s = j % ns;
        const double *fs = f, *Js = J;
        if (ns > 1) {
            int status = one_slider(hb, fn, e, s, u, work, work + 2 * nc);
            if (status != FRICREG_OK)
                return status;
            fs = work;
            Js = work + 2 * nc;
        }
        for (size_t i = 0; i < nt; i++) {
            double ju = row_times(Js, b, i, nt, u);
            out[i] += j < ns ? ju / k[s] : (fs[i] - ju) / phi[s];
        }
        return FRICREG_OK;
    }
    double n0 = hb->nl[2 * me + e], kn = hb->nl[3 * me + e], *dn0 = work;
    for (size_t i = 0; i < b; i++) /* dF/dn0: J's column g_0 over kn, or (B) over n0 */
        dn0[i] = kn != 0.0 ? J[i * b + nt] / kn : (f[i] - row_times(J, b, i, b, u)) / n0;
    for (size_t i = 0; i < b; i++) {
        if (j == 2 * ns + 1) {
            out[i] += dn0[i];
            continue;
        }
        double jtt = i < nt ? row_times(J, b, i, nt, u) : 0.0;
        out[i] += (f[i] - jtt - n0 * dn0[i]) / kn;
    }
    return FRICREG_OK;
}
