/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_params.h — internal: the elements' force coefficients differentiated in one parameter
 * of an element, exactly, from the forces and Jacobian of the last residual (element_params.c). */
#ifndef FRICREG_HB_ELEMENT_PARAMS_H
#define FRICREG_HB_ELEMENT_PARAMS_H

#include "hb_internal.h"

/* Parameter j of element e in fricreg_element.h's layout of its type (jenkins, jenkins_2d,
 * jenkins_3d kt, mun; iwan, iwan_2d, iwan_3d k[ns], phi[ns]; spring k; dahl sigma, fc;
 * jenkins_normal and contact_3d kt, mu, kn, n0, gap; iwan_normal k[ns], mu[ns], kn, n0, gap),
 * checked for fr_hb_element_dfdp: FRICREG_OK, or FRICREG_EINVAL (message recorded, with fn and
 * the caller's name of the parameter, what) for j out of the layout, a gap (HB's normal law
 * has none), a marched type not named here, or a parameter whose identity divides by a value
 * that is 0 (a slip force, mu, fc, or kn; n0 with kn = 0 too). */
int fr_hb_element_param_check(fricreg_hb *hb, const char *fn, const char *what, size_t e, size_t j);

/* d(F)/d(p_j) of element e added into df at its rows (df[nq], (R)'s layout), at the unknowns q
 * of the last fr_hb_residual with jac (its fq and jq), by the laws' two scalings: with F, its
 * Jacobian J and U the element's coefficients, dF/dk = J U / k, dF/dphi = (F − J U) / phi for a
 * slider (an Iwan element's slider s from its own exact AFT or march, F_s and J_s; a marched
 * type's stiffness and bound as a slider's); with a normal law
 * dF/dn0 = J[:, g_0] / kn (else (F − J (U, G)) / n0), dF_t/dkt = J_tt U / kt, dF_t/dmu =
 * (F_t − J_tt U) / mu, dF/dkn = (F − J_tt U − n0 dF/dn0) / kn. work: 3 nc + 9 nc² doubles.
 * FRICREG_OK, or an Iwan slider's AFT or march status (message recorded, with fn). Needs
 * fr_hb_element_param_check's FRICREG_OK. */
int fr_hb_element_dfdp(fricreg_hb *hb, const char *fn, size_t e, size_t j, const double *q,
                       double *df, double *work);

#endif
