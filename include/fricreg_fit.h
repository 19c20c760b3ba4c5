/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_fit.h — a joint's parameters from a test: the fit of a mode's measured natural
 * frequency and damping ratio at several response levels (a stepped-sine test's backbone),
 * with exact sensitivities, covariance, 95 % intervals and identifiability (docs/identification.md).
 *
 * The model (the "modal Iwan" of the literature): one mass-normalized mode, modal coordinate q,
 * a linear modal stiffness K0 in parallel with Segalman's four-parameter Iwan joint (D. J.
 * Segalman, "A four-parameter Iwan model for lap-type joints", J. Appl. Mech. 72 (2005)
 * 752-760; the density of fricreg_iwan.h) and a linear modal damping ratio zeta0. With
 *
 *     c = beta + (chi + 1)/(chi + 2),   phi_max = F_S (1 + beta)/(K_T c),   x = a/phi_max
 *
 * the joint's backbone force and its dissipation per cycle (Masing's rule) at the modal
 * amplitude a are, in closed form,
 *
 *     x < 1:  F = (F_S/c) ((1 + beta) x - x^(chi+2)/(chi + 2))
 *             D = 4 F_S phi_max (chi + 1) x^(chi+3) / (c (chi + 2)(chi + 3))
 *     x >= 1: F = F_S
 *             D = (4 F_S phi_max/c) ((chi + 1)(x/(chi + 2) - 1/(chi + 3)) + beta (x - 1))
 *
 * and the quasi-static modal analysis (QSMA: R. M. Lacayo, M. S. Allen, "Updating structural
 * models containing nonlinear Iwan joints using quasi-static modal analysis", MSSP 118 (2019)
 * 133-157) gives the mode's frequency and damping ratio by
 * the secant stiffness and the energy balance of one cycle:
 *
 *     k_sec = K0 + F/a,   omega = sqrt(k_sec) (rad/s),   f = omega/(2 pi) (Hz)
 *     zeta = zeta0 + D/(2 pi k_sec a^2)
 *
 * A level's measured amplitude A is the response at a sensor of mode shape value s (mass
 * normalized, fricreg_fit_set_sensor) of a kind: displacement A = |s| a, velocity
 * A = |s| omega a, acceleration A = |s| omega^2 a; its modal amplitude a solves that equation
 * (Brent's method on GSL; the right-hand sides grow monotonically in a), and the sensitivities
 * follow a through it by the implicit function theorem. Every derivative is exact (forward
 * differentiation of the closed forms), no finite differences.
 *
 * Units: consistent, mass-normalized modal units: q in m sqrt(kg) when A is in m and s in
 * 1/sqrt(kg) (s = 1: A is the modal amplitude itself); K0, K_T in 1/s^2 (modal stiffness),
 * F_S in modal force (K_T times modal displacement), chi and beta nondimensional; frequencies
 * in Hz; damping ratios nondimensional.
 *
 * The fit: weighted least squares over the levels' frequencies and damping ratios,
 *
 *     r = ((f_i - f_i,meas)/sd_f,i,  (zeta_i - zeta_i,meas)/sd_zeta,i),   i = 1..n
 *
 * with the standard deviations given (fricreg_fit_set_deviations; the covariance is then
 * (J^T J)^-1, the intervals normal), or relative residuals (sd = the measured value; the
 * covariance scaled by the residual variance r^T r/(2n - p) and the intervals Student's t
 * with 2n - p degrees of freedom, as SciPy's curve_fit without absolute_sigma). The free
 * parameters are solved in transformed coordinates theta that keep them inside their bounds:
 * p = lo + exp(theta) with a lower bound only (so a positive parameter is log-scaled),
 * hi - exp(theta) with an upper bound only, lo + (hi - lo)/(1 + exp(-theta)) with both, theta
 * with neither. GSL's trust-region Levenberg-Marquardt (gsl_multifit_nlinear, with the exact
 * Jacobian) runs from each start of a deterministic set (fricreg_fit_set_starts): the least
 * squares has local minima where a level sits on phi_max's kink, so many starts; the best
 * converged one is the fit. Its covariance is the transformed one mapped by dp/dtheta (the
 * delta method); its 95 % intervals are theta's mapped back, so a log-scaled parameter's is
 * asymmetric and never crosses its bound. Identifiability: the singular values of the
 * Jacobian in theta (log-scaled parameters: relative changes) and their right singular
 * vectors, the parameter combinations each determines.
 *
 * The harmonic-balance model (since 1.9, fricreg_fit_set_model_hb): a nonlinear mode of any
 * model the harmonic-balance driver holds (fricreg_hb.h), its backbone by the extended periodic
 * motion concept (fricreg_hb_nma_at: M. Krack, "Nonlinear modal analysis of nonconservative
 * systems: extension of the periodic motion concept", Comput. Struct. 154 (2015) 59-71), and
 * the caller's np parameters of the driver (element values shared by ranges of elements,
 * Rayleigh's coefficients) in place of the modal Iwan's six. A level's modal amplitude a solves
 * |s| omega^kind a = A at the modal sensor, or |X_1,dof| omega^kind = A at a dof
 * (fricreg_fit_set_sensor_dof), by Newton's method on log a over repeated backbones; the exact
 * sensitivities of the backbone's points (fricreg_hb_nma_point_sensitivities) are carried to
 * the measured level by the implicit function theorem (docs/identification.md, "Any HB
 * model"). Each evaluation of the model is one or more backbone marches: the residuals and the
 * Jacobian come from one (cached), and the default is one start.
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is printed,
 * a failed call leaves the caller's arrays and the object's settings untouched, one object per
 * thread. The object keeps the status and a message of its last failed call
 * (fricreg_fit_errcode, fricreg_fit_errmsg, fricreg_fit_errmsg_copy). A fit's results are
 * readable only after a run that returned FRICREG_OK, until a setter changes the problem: a
 * failed run reports nothing as a fit. GSL's multifit workspace reports a failed malloc
 * through GSL's error handler, as gsl_odeiv2_step_alloc does (docs/reliability.md).
 * Since 1.9 (FRICREG_1.9).
 */
#ifndef FRICREG_FIT_H
#define FRICREG_FIT_H

#include "fricreg.h"
#include "fricreg_hb.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup fit Identification: a joint's parameters from measured frequency and damping (fricreg_fit)
 *  An opaque fit of the modal Iwan model to a mode's measured frequency and damping ratio at
 *  several levels: exact sensitivities, GSL's trust-region least squares from several starts,
 *  covariance, intervals, identifiability (docs/identification.md).
 *  \{ */

/** Opaque fit: the levels, their deviations, the sensor, each parameter's start, bounds and
 *  whether it is free, the result of the last successful run, the last error. */
typedef struct fricreg_fit fricreg_fit;

/** The modal Iwan model's parameters: indices into every parameter array of this header
 *  (length FRICREG_FIT_NPARAMS). Values are fixed forever. Since 1.9. */
enum fricreg_fit_param {
    FRICREG_FIT_FS = 0,     /**< F_S, the joint's macroslip force (modal force), > 0 */
    FRICREG_FIT_KT = 1,     /**< K_T, the joint's stiffness before any slip (1/s^2), > 0 */
    FRICREG_FIT_CHI = 2,    /**< chi, the exponent of the slip-force density, > -1 */
    FRICREG_FIT_BETA = 3,   /**< beta, the weight of the density's delta at phi_max, >= 0 */
    FRICREG_FIT_ZETA0 = 4,  /**< zeta0, the linear modal damping ratio, >= 0 */
    FRICREG_FIT_K0 = 5,     /**< K0, the linear modal stiffness beside the joint (1/s^2), >= 0 */
    FRICREG_FIT_NPARAMS = 6 /**< the number of parameters */
};

/** What a level's measured amplitude is (at the sensor of fricreg_fit_set_sensor). Values are
 *  fixed forever. Since 1.9. */
enum fricreg_fit_amplitude {
    FRICREG_FIT_DISPLACEMENT = 0, /**< A = |s| a */
    FRICREG_FIT_VELOCITY = 1,     /**< A = |s| omega a */
    FRICREG_FIT_ACCELERATION = 2  /**< A = |s| omega^2 a */
};

/** The numbers of a fit that fricreg_fit_get_value reads. Values are fixed forever. Since 1.9. */
enum fricreg_fit_value {
    FRICREG_FIT_COST = 0,              /**< r^T r at the fit (chi-square with deviations given) */
    FRICREG_FIT_RESIDUAL_VARIANCE = 1, /**< r^T r/(2n - p); 0 where 2n = p */
    FRICREG_FIT_NFEV = 2,              /**< residual evaluations, over every start */
    FRICREG_FIT_NJEV = 3,              /**< Jacobian evaluations, over every start */
    FRICREG_FIT_ITERATIONS = 4,        /**< iterations of the start that gave the fit */
    FRICREG_FIT_BEST_START = 5,        /**< which start gave the fit (0: the first) */
    FRICREG_FIT_STARTS_CONVERGED = 6,  /**< how many starts converged */
    FRICREG_FIT_NFREE = 7,             /**< the number of free parameters p */
    FRICREG_FIT_CONDITION = 8,         /**< largest over smallest singular value of the Jacobian */
    /** the model's evaluations over every start (residuals and Jacobian at one point are one:
     *  a backbone model's cache): each a backbone at every level */
    FRICREG_FIT_NMODEL = 9,
    /** the HB model's backbone marches (fricreg_hb_nma_at calls; several an evaluation where
     *  the levels' modal amplitudes are solved for); 0 for the modal Iwan model */
    FRICREG_FIT_NMARCH = 10
};

/** Create a fit of the modal Iwan model (fricreg_fit_set_model_hb for another), with no levels.
 *
 *  Defaults: every parameter free, with the bounds of enum fricreg_fit_param (so each is
 *  log-scaled: F_S, K_T, zeta0 and K0 on (0, inf), chi + 1 and beta on (0, inf)) and a start
 *  made from the levels at the run (docs/identification.md, "Starts"); the sensor s = 1; no
 *  deviations (relative residuals); 32 starts.
 *
 *  out  out: the new fit, released with fricreg_fit_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_ENOMEM. Since 1.9. */
FRICREG_API int fricreg_fit_create(fricreg_fit **out);

/** Release the fit. fricreg_fit_free(NULL) does nothing. Since 1.9. */
FRICREG_API void fricreg_fit_free(fricreg_fit *fit);

/** Set the measured levels (replacing any), and forget the deviations.
 *
 *  n             number of levels, >= 1 (a run needs at least as many as free parameters).
 *  kind          what amplitude[] is: a value of enum fricreg_fit_amplitude.
 *  amplitude[n]  the levels' response amplitudes at the sensor, > 0 (finite): m, m/s or
 *                m/s^2 by kind (any consistent unit). Any order.
 *  freq_hz[n]    the measured natural frequencies, Hz, > 0 (finite).
 *  zeta[n]       the measured damping ratios, > 0 (finite), nondimensional.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit or an array is NULL; FRICREG_EINVAL if n is 0 or
 *  above 1e6, kind is unknown or a value is <= 0; FRICREG_ENONFINITE if a value is NaN or
 *  infinite; FRICREG_ENOMEM. Since 1.9. */
FRICREG_API int fricreg_fit_set_levels(fricreg_fit *fit, size_t n, int kind,
                                       const double amplitude[], const double freq_hz[],
                                       const double zeta[]);

/** Set the levels' standard deviations (absolute, in the units of the measurements): the
 *  residuals are weighted by them and the covariance is not rescaled. Both NULL: relative
 *  residuals again, the covariance scaled by the residual variance.
 *
 *  n              must equal the levels' count.
 *  sd_freq_hz[n]  the frequencies' standard deviations, Hz, > 0 (finite).
 *  sd_zeta[n]     the damping ratios' standard deviations, > 0 (finite).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL or only one array is; FRICREG_ESIZE if n
 *  differs from the levels' count; FRICREG_EINVAL if a value is <= 0; FRICREG_ENONFINITE if a
 *  value is NaN or infinite. Since 1.9. */
FRICREG_API int fricreg_fit_set_deviations(fricreg_fit *fit, size_t n, const double sd_freq_hz[],
                                           const double sd_zeta[]);

/** Set the mode shape's value s at the sensor (mass normalized, 1/sqrt(kg) in SI): the
 *  measured amplitude is |s| times the modal one (times omega or omega^2 by kind).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL; FRICREG_ENONFINITE if s is NaN or
 *  infinite; FRICREG_EINVAL if s = 0. Since 1.9. */
FRICREG_API int fricreg_fit_set_sensor(fricreg_fit *fit, double s);

/** Make a parameter free, with a start and bounds.
 *
 *  which  a value of enum fricreg_fit_param; an HB model's: 0 .. np - 1.
 *  start  the first start's value, lower < start < upper (finite); NaN: the model's (the
 *         default): made from the levels at the run (modal Iwan; an HB model's Rayleigh
 *         coefficients), or the driver's value at fricreg_fit_set_model_hb (an element's).
 *  lower  lower bound, -INFINITY for none, not below the parameter's own (0 for F_S, K_T,
 *         beta, zeta0 and K0, -1 for chi; 0 for every HB model parameter).
 *  upper  upper bound, INFINITY for none, > lower. Bounds both finite are searched through
 *         the logistic map of (lower, upper), one alone through the log of the distance to
 *         it; bounds more than 1e300 apart (Fortran's huge(1.0) as "none") as the nearer one
 *         alone (the logistic map of so wide a range has no digits left for the parameter).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL; FRICREG_EINVAL if which is unknown, a bound
 *  lies below the parameter's own or upper <= lower, or start is outside (lower, upper);
 *  FRICREG_ENONFINITE if lower or upper is NaN. Since 1.9. */
FRICREG_API int fricreg_fit_set_free(fricreg_fit *fit, int which, double start, double lower,
                                     double upper);

/** Fix a parameter at a value (beta = 0: the three-parameter model with no delta; K0 = 0: the
 *  joint alone).
 *
 *  which  a value of enum fricreg_fit_param; an HB model's: 0 .. np - 1.
 *  value  finite, in the parameter's range (F_S, K_T > 0; chi > -1; beta, zeta0, K0 >= 0; an
 *         HB model's >= 0, the driver checking the rest at the run, e.g. a stiffness > 0).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL; FRICREG_EINVAL if which is unknown or value
 *  is outside the parameter's range; FRICREG_ENONFINITE if value is NaN or infinite.
 *  Since 1.9. */
FRICREG_API int fricreg_fit_set_fixed(fricreg_fit *fit, int which, double value);

/** Set the number of starts, 1..1000 (default 32; 1 for an HB model, each of whose starts
 *  costs a backbone march or more per iteration: raise it where the levels may hold several
 *  minima): the caller's start where given, then starts about the model's (made from the
 *  levels, or an HB model's driver values), moved in theta along a Halton sequence
 *  (docs/identification.md, "Starts").
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL; FRICREG_EINVAL if nstarts is 0 or above
 *  1000. Since 1.9. */
FRICREG_API int fricreg_fit_set_starts(fricreg_fit *fit, size_t nstarts);

/** Fit the free parameters to the levels.
 *
 *  Each start runs GSL's trust-region Levenberg-Marquardt (gsl_multifit_nlinear) on the exact
 *  Jacobian until its step is below 1e-10 relative, its scaled gradient below 1e-12, or a
 *  Gauss-Newton step would lower r^T r by less than 1e-9 of it (the step left then about 1e-4
 *  of a standard error: docs/identification.md).
 *
 *  Returns FRICREG_OK, the fit then readable by the getters below; else nothing is reported as
 *  a fit, and: FRICREG_ENULL if fit is NULL; FRICREG_EINVAL if no levels are set, there are
 *  fewer levels than free parameters, no parameter is free, a
 *  fixed K0 = 0 leaves a measured acceleration beyond the backbone's reach, or an HB model's
 *  backbone stops before a level or its measured amplitude folds there (the message names
 *  the level), no degree of freedom is left for the residual variance (2n = p without
 *  deviations), or the best fit ends at a bound (the message names the parameter and the
 *  bound: fix it there, or widen the bound); FRICREG_ESINGULAR if the Jacobian at the fit is
 *  rank deficient (smallest over largest singular value below 1e-12: the message names the
 *  combination the levels do not determine); FRICREG_EWORK if no start converged within 500
 *  iterations (an HB model: also where the driver refused every evaluation, e.g. from its
 *  monitor, or with a wrong fricreg_fit_set_sensor_dof size; the message ends with the
 *  model's last reason); FRICREG_ENOMEM. An HB model's driver holds the fitted parameters after
 *  a successful run, and the values it held at the run's start after a failed one (its
 *  elements'; Rayleigh's coefficients, which the driver does not report, stay at the last
 *  evaluation's); its stored backbone is the last one marched, not necessarily the fit's
 *  (fricreg_fit_curve or fricreg_hb_nma_at march it). Since 1.9. */
FRICREG_API int fricreg_fit_run(fricreg_fit *fit);

/** Copy the fitted parameters (the fixed ones as fixed).
 *
 *  np           must be the model's parameter count: FRICREG_FIT_NPARAMS for the modal Iwan
 *               model, fricreg_fit_set_model_hb's np for an HB model (so below).
 *  p[np]        out: the parameters, indexed by enum fricreg_fit_param (an HB model: in the
 *               order of its description).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit or p is NULL; FRICREG_ESIZE if np is not the
 *  model's count; FRICREG_EINVAL if no run has succeeded since the last setter.
 *  Since 1.9. */
FRICREG_API int fricreg_fit_get_params(const fricreg_fit *fit, size_t np, double p[]);

/** Copy the fitted parameters' covariance (row major, symmetric; a fixed parameter's row and
 *  column are 0) and their 95 % intervals.
 *
 *  np              must be the model's parameter count (as fricreg_fit_get_params).
 *  cov[np np]      out, or NULL: cov[i np + j] the covariance of parameters i and j, in their
 *                  units' product (the delta method through dp/dtheta).
 *  lower[np], upper[np]  out, or NULL (both or neither): the 95 % intervals (a fixed
 *                  parameter's is its value twice).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL or only one of lower and upper is;
 *  FRICREG_ESIZE if np is not the model's count; FRICREG_EINVAL if no run has succeeded
 *  since the last setter. Since 1.9. */
FRICREG_API int fricreg_fit_get_covariance(const fricreg_fit *fit, size_t np, double cov[],
                                           double lower[], double upper[]);

/** Copy the identifiability: the singular values of the Jacobian in the transformed free
 *  parameters (theta; log-scaled for a bound on one side) and their right singular vectors,
 *  largest first.
 *
 *  np              must be the model's parameter count (as fricreg_fit_get_params).
 *  sv[np]          out: the p singular values first (p = FRICREG_FIT_NFREE), then zeros.
 *  vectors[np np]  out, or NULL: row k the k-th right singular vector over all parameters
 *                  (0 on fixed ones; rows past p all 0): the combination of the thetas that
 *                  sv[k] determines; a small sv[k] is a poorly determined combination.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit or sv is NULL; FRICREG_ESIZE if np is not the
 *  model's count; FRICREG_EINVAL if no run has succeeded since the last setter.
 *  Since 1.9. */
FRICREG_API int fricreg_fit_get_identifiability(const fricreg_fit *fit, size_t np, double sv[],
                                                double vectors[]);

/** Copy the levels' weighted residuals at the fit, (model - measured)/sd (sd the measured
 *  value without deviations), in the order the levels were set.
 *
 *  n            must equal the levels' count.
 *  r_freq[n]    out: the frequencies' residuals.
 *  r_zeta[n]    out: the damping ratios' residuals.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit, r_freq or r_zeta is NULL; FRICREG_EINVAL if no
 *  run has succeeded since the last setter; FRICREG_ESIZE if n differs from the levels'
 *  count. Since 1.9. */
FRICREG_API int fricreg_fit_get_residuals(const fricreg_fit *fit, size_t n, double r_freq[],
                                          double r_zeta[]);

/** Read one number of the fit: a value of enum fricreg_fit_value (counts as doubles).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit or value is NULL; FRICREG_EINVAL if no run has
 *  succeeded since the last setter or which is unknown. Since 1.9. */
FRICREG_API int fricreg_fit_get_value(const fricreg_fit *fit, int which, double *value);

/** The model's backbone at amplitudes of a kind, with its exact sensitivities: for any
 *  parameters (the fit is not needed, only its model and sensor). An HB model: the driver is
 *  left at p, its backbone through the amplitudes' modal ones (in increasing order).
 *
 *  p[np]             the parameters, in their ranges (as fricreg_fit_set_fixed); np the
 *                    model's count (FRICREG_FIT_NPARAMS, or fricreg_fit_set_model_hb's).
 *  kind              a value of enum fricreg_fit_amplitude.
 *  n                 number of amplitudes, >= 1.
 *  amplitude[n]      > 0, finite, as in fricreg_fit_set_levels.
 *  freq_hz[n]        out: the natural frequencies, Hz.
 *  zeta[n]           out: the damping ratios.
 *  modal[n]          out, or NULL: the modal amplitudes a.
 *  dfreq_dp[n np]    out, or NULL: dfreq_hz[i]/dp[j] at i np + j, the amplitude held (a
 *                    moves with p as its equation says).
 *  dzeta_dp[n np]    out, or NULL: dzeta[i]/dp[j], laid out as dfreq_dp.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit, p, amplitude, freq_hz or zeta is NULL;
 *  FRICREG_EINVAL if kind is unknown, n is 0, a parameter is out of its range or an amplitude
 *  <= 0 or beyond the backbone's reach (an acceleration with K0 = 0; an HB model's backbone
 *  stops before it or its measured amplitude folds); FRICREG_ENONFINITE if an input is NaN or
 *  infinite; FRICREG_ENOMEM; an HB model: the driver's status where it refuses a value or the
 *  call (from its monitor: FRICREG_EINVAL; a wrong sensor size: FRICREG_ESIZE; the message
 *  says which). On failure nothing is written (an HB model's driver may hold p). Since 1.9. */
FRICREG_API int fricreg_fit_eval(fricreg_fit *fit, const double p[], int kind, size_t n,
                                 const double amplitude[], double freq_hz[], double zeta[],
                                 double modal[], double dfreq_dp[], double dzeta_dp[]);

/** The fitted backbone at amplitudes of the levels' kind, with its standard deviations by the
 *  delta method (g^T cov g, g the sensitivities of fricreg_fit_eval): the 95 % band is
 *  value +- 1.96 sd (or Student's t, as the intervals).
 *
 *  n               number of amplitudes, >= 1.
 *  amplitude[n]    > 0, finite.
 *  freq_hz[n], zeta[n]   out: the fitted backbone.
 *  sd_freq_hz[n], sd_zeta[n]  out, or NULL (both or neither): their standard deviations.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit, amplitude, freq_hz or zeta is NULL, or only one
 *  of sd_freq_hz and sd_zeta is; FRICREG_EINVAL if no run has succeeded since the last setter,
 *  n is 0, or an amplitude is <= 0 or beyond the fitted backbone's reach; FRICREG_ENONFINITE if
 *  an amplitude is NaN or infinite; FRICREG_ENOMEM. On failure nothing is written. Since 1.9. */
FRICREG_API int fricreg_fit_curve(fricreg_fit *fit, size_t n, const double amplitude[],
                                  double freq_hz[], double zeta[], double sd_freq_hz[],
                                  double sd_zeta[]);

/** The quantile the 95 % intervals and bands take: 1.96 with deviations given, else Student's
 *  t at 0.975 with 2n - p degrees of freedom. Returns FRICREG_OK; FRICREG_ENULL if fit or q is
 *  NULL; FRICREG_EINVAL if no run has succeeded since the last setter. Since 1.9. */
FRICREG_API int fricreg_fit_get_quantile(const fricreg_fit *fit, double *q);

/** Fit a nonlinear mode of a harmonic-balance driver (fricreg_hb.h) in place of the modal Iwan
 *  model: mode `mode`'s backbone (fricreg_hb_nma_at, EPMC) at the levels, with np parameters of
 *  the driver, each described as fricreg_hb_nma_point_sensitivities describes one. Every
 *  parameter starts free with bounds (0, inf) (log-scaled), at the driver's value (an element
 *  range's; NaN start) or, for Rayleigh's coefficients, which the driver does not report, at
 *  half the smallest level's linear damping 2 omega zeta (split between a0 and a1 omega^2 if
 *  both are parameters); one start (fricreg_fit_set_starts); the levels' amplitudes modal
 *  (times |s| of fricreg_fit_set_sensor; fricreg_fit_set_sensor_dof for a dof's). The fit's
 *  parameter setters and getters then take which in 0 .. np - 1 and np. Each evaluation sets
 *  the driver's values (fricreg_hb_set_element_param; fricreg_hb_set_rayleigh (a0, a1), the one
 *  not among the parameters 0, replacing a damping matrix) and marches its backbone.
 *
 *  hb       the driver, borrowed: kept alive by the caller, not used by it during the fit's
 *           calls, and changed by them (fricreg_fit_run). NULL: back to the modal Iwan model
 *           (as fricreg_fit_set_model_modal_iwan; the other arguments ignored).
 *  mode, damping  as fricreg_hb_nma's (mode checked by the driver at the run).
 *  np       the parameters, 1 .. 16.
 *  kind[np] FRICREG_HB_NMA_PARAM_ELEMENT or FRICREG_HB_NMA_PARAM_DAMPING.
 *  first[np], count[np]  ELEMENT: the elements first .. first + count - 1 (count >= 1), held by
 *           the driver, sharing one value of the parameter; ignored for DAMPING.
 *  index[np]  ELEMENT: the parameter's index in each element's layout (fricreg_element.h; e.g.
 *           jenkins 0 kt, 1 mu N); DAMPING: 1 Rayleigh's a0 (1/s), 2 a1 (s). The modal damping
 *           ratio zeta_k (DAMPING 0) has no setter on the driver: fit a0 with
 *           FRICREG_HB_NMA_DAMPING_MODAL and a1 = 0 instead (then xi_k = a0).
 *
 *  Forgets the parameters' settings and the last fit; keeps the levels, deviations and sensor.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL, or kind, first, count or index is NULL
 *  with hb given; FRICREG_EINVAL if np is 0 or above 16, damping is unknown, a kind is neither
 *  ELEMENT nor DAMPING, an element range is empty or beyond the driver's elements, an index is
 *  beyond an element's parameters, a range's elements differ in the value, a DAMPING index is
 *  0 (zeta_k) or above 2, or two parameters move one value; FRICREG_ENOMEM. Nothing changes on
 *  failure. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_fit_set_model_hb(fricreg_fit *fit, fricreg_hb *hb, size_t mode, int damping,
                                         size_t np, const int kind[], const size_t first[],
                                         const size_t count[], const size_t index[]);

/** Fit a harmonic-balance driver's model by quasi-static modal analysis instead
 *  (fricreg_hb_qsma_sensitivities, fricreg_hb_qsma.h: exact for jenkins and iwan elements, the
 *  marched path's own for contact_3d ones): mode `mode`'s QSMA backbone at the levels, its
 *  exact derivatives in the np parameters, each described as fricreg_fit_set_model_hb
 *  describes one, with the same starts, bounds and settings; the cheap route where QSMA is
 *  valid (one mode, Masing behaviour, light damping: docs/identification.md), its levels'
 *  amplitudes modal (times |s| of fricreg_fit_set_sensor). A velocity or acceleration level's
 *  modal amplitude solves |s| a omega(a)^kind = A by Newton's method on log a. The damping is
 *  QSMA's, zeta_k = phi_k^T C phi_k / (2 omega_k) held along the backbone.
 *
 *  hb       the driver, borrowed as fricreg_fit_set_model_hb's. NULL: back to the modal Iwan
 *           model (the other arguments ignored).
 *  mode, np, kind, first, count, index  as fricreg_fit_set_model_hb's.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL, or kind, first, count or index is NULL
 *  with hb given; FRICREG_EINVAL as fricreg_fit_set_model_hb's; FRICREG_ENOMEM. A run refuses
 *  a model QSMA refuses (an element type it does not take: the driver's message), and a level
 *  beyond macroslip is out of reach (FRICREG_EINVAL, as a backbone that stops before it).
 *  fricreg_fit_set_sensor_dof is refused on this model (its levels are modal). Nothing changes
 *  on failure. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_fit_set_model_qsma(fricreg_fit *fit, fricreg_hb *hb, size_t mode, size_t np,
                                           const int kind[], const size_t first[],
                                           const size_t count[], const size_t index[]);

/** Fit the modal Iwan model again (fricreg_fit_create's): its six parameters with their
 *  defaults, 32 starts; the levels, deviations and sensor value kept, the last fit forgotten.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_fit_set_model_modal_iwan(fricreg_fit *fit);

/** Measure an HB model's levels at a dof of its driver: the amplitude |X_1,dof| of the
 *  displacement's first harmonic (kind displacement), omega |X_1,dof| (velocity) or
 *  omega^2 |X_1,dof| (acceleration). fricreg_fit_set_sensor makes them modal again.
 *
 *  ndof       the driver's degrees of freedom (checked by the driver at the run:
 *             FRICREG_ESIZE there if it is not).
 *  harmonics  the driver's H (fricreg_hb_create's), >= 1 (checked likewise).
 *  dof        the sensor's dof, < ndof.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fit is NULL; FRICREG_EINVAL if the model is the modal
 *  Iwan one or QSMA's (fricreg_fit_set_model_qsma), harmonics < 1 or dof >= ndof. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_fit_set_sensor_dof(fricreg_fit *fit, size_t ndof, int harmonics,
                                           size_t dof);

/** The last error's status. Returns the fricreg_status code of the fit's last failed call,
 *  FRICREG_OK if none (or fit is NULL). Since 1.9. */
FRICREG_API int fricreg_fit_errcode(const fricreg_fit *fit);

/** The last error's message, "" if none; for NULL, "NULL fit". Owned by the fit, valid until
 *  its next call. Since 1.9. */
FRICREG_API const char *fricreg_fit_errmsg(const fricreg_fit *fit);

/** Copy the last error's message into buf[len], truncated and NUL-terminated; returns its
 *  length (as snprintf), or 0 and writes nothing if buf is NULL or len is 0. Since 1.9. */
FRICREG_API size_t fricreg_fit_errmsg_copy(const fricreg_fit *fit, char *buf, size_t len);

/** \} */

#ifdef __cplusplus
}
#endif

#endif
