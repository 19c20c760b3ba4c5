/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit.h — fricreg_fit.h's identification of a modal Iwan joint (python/fricreg/fit.py), in the
 * syntax of cffi's cdef (no macros, no includes; python/build_ffi.py). */
enum fricreg_fit_param {
    FRICREG_FIT_FS = 0,
    FRICREG_FIT_KT = 1,
    FRICREG_FIT_CHI = 2,
    FRICREG_FIT_BETA = 3,
    FRICREG_FIT_ZETA0 = 4,
    FRICREG_FIT_K0 = 5,
    FRICREG_FIT_NPARAMS = 6
};
enum fricreg_fit_amplitude {
    FRICREG_FIT_DISPLACEMENT = 0,
    FRICREG_FIT_VELOCITY = 1,
    FRICREG_FIT_ACCELERATION = 2
};
enum fricreg_fit_value {
    FRICREG_FIT_COST = 0,
    FRICREG_FIT_RESIDUAL_VARIANCE = 1,
    FRICREG_FIT_NFEV = 2,
    FRICREG_FIT_NJEV = 3,
    FRICREG_FIT_ITERATIONS = 4,
    FRICREG_FIT_BEST_START = 5,
    FRICREG_FIT_STARTS_CONVERGED = 6,
    FRICREG_FIT_NFREE = 7,
    FRICREG_FIT_CONDITION = 8
};
typedef struct fricreg_fit fricreg_fit;
int fricreg_fit_create(fricreg_fit **out);
void fricreg_fit_free(fricreg_fit *fit);
int fricreg_fit_set_levels(fricreg_fit *fit, size_t n, int kind, const double amplitude[],
                           const double freq_hz[], const double zeta[]);
int fricreg_fit_set_deviations(fricreg_fit *fit, size_t n, const double sd_freq_hz[],
                               const double sd_zeta[]);
int fricreg_fit_set_sensor(fricreg_fit *fit, double s);
int fricreg_fit_set_free(fricreg_fit *fit, int which, double start, double lower, double upper);
int fricreg_fit_set_fixed(fricreg_fit *fit, int which, double value);
int fricreg_fit_set_starts(fricreg_fit *fit, size_t nstarts);
int fricreg_fit_run(fricreg_fit *fit);
int fricreg_fit_get_params(const fricreg_fit *fit, size_t np, double p[]);
int fricreg_fit_get_covariance(const fricreg_fit *fit, size_t np, double cov[], double lower[],
                               double upper[]);
int fricreg_fit_get_identifiability(const fricreg_fit *fit, size_t np, double sv[],
                                    double vectors[]);
int fricreg_fit_get_residuals(const fricreg_fit *fit, size_t n, double r_freq[], double r_zeta[]);
int fricreg_fit_get_value(const fricreg_fit *fit, int which, double *value);
int fricreg_fit_get_quantile(const fricreg_fit *fit, double *q);
int fricreg_fit_set_model_hb(fricreg_fit *fit, struct fricreg_hb *hb, size_t mode, int damping,
                             size_t np, const int kind[], const size_t first[],
                             const size_t count[], const size_t index[]);
int fricreg_fit_set_model_qsma(fricreg_fit *fit, struct fricreg_hb *hb, size_t mode, size_t np,
                               const int kind[], const size_t first[], const size_t count[],
                               const size_t index[]);
int fricreg_fit_set_model_modal_iwan(fricreg_fit *fit);
int fricreg_fit_set_sensor_dof(fricreg_fit *fit, size_t ndof, int harmonics, size_t dof);
int fricreg_fit_eval(fricreg_fit *fit, const double p[], int kind, size_t n,
                     const double amplitude[], double freq_hz[], double zeta[], double modal[],
                     double dfreq_dp[], double dzeta_dp[]);
int fricreg_fit_curve(fricreg_fit *fit, size_t n, const double amplitude[], double freq_hz[],
                      double zeta[], double sd_freq_hz[], double sd_zeta[]);
int fricreg_fit_errcode(const fricreg_fit *fit);
const char *fricreg_fit_errmsg(const fricreg_fit *fit);
