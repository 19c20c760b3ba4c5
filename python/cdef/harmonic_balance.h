/* SPDX-License-Identifier: GPL-3.0-or-later */
/* harmonic_balance.h — fricreg_hb.h's harmonic-balance driver: the model, the solves, the
 * continuation with stability and bifurcations, the nonlinear modes, in the syntax of cffi's
 * cdef (python/build_ffi.py); and the monitor through which Python stops a solve
 * (harmonic_balance.py: Ctrl-C). */
typedef struct fricreg_hb fricreg_hb;
typedef int (*fricreg_hb_monitor)(void *user, int64_t iterations, double parameter,
                                  double residual);
#define FRICREG_HB_MAX_HARMONICS 40
enum fricreg_hb_nma_damping { FRICREG_HB_NMA_DAMPING_MATRIX = 0, FRICREG_HB_NMA_DAMPING_MODAL = 1 };
enum fricreg_hb_stability_method {
    FRICREG_HB_STABILITY_AUTO = 0,
    FRICREG_HB_STABILITY_HILL = 1,
    FRICREG_HB_STABILITY_MONODROMY = 2,
    FRICREG_HB_STABILITY_CONDENSED = 3
};
enum fricreg_hb_newton_solver {
    FRICREG_HB_NEWTON_AUTO = 0,
    FRICREG_HB_NEWTON_DENSE = 1,
    FRICREG_HB_NEWTON_CAPACITANCE = 2
};
enum fricreg_hb_receptance {
    FRICREG_HB_RECEPTANCE_AUTO = 0,
    FRICREG_HB_RECEPTANCE_LU = 1,
    FRICREG_HB_RECEPTANCE_MODES = 2
};
enum fricreg_hb_bifurcation_type {
    FRICREG_HB_TP = 1,
    FRICREG_HB_BP = 2,
    FRICREG_HB_PD = 3,
    FRICREG_HB_NS = 4
};
enum fricreg_hb_nma_special_type { FRICREG_HB_NMA_FOLD = 1, FRICREG_HB_NMA_CROSSING = 2 };

int fricreg_hb_create(size_t ndof, size_t m, int harmonics, fricreg_hb **out);
void fricreg_hb_free(fricreg_hb *hb);
int fricreg_hb_set_matrix(fricreg_hb *hb, int which, size_t nrows, size_t ncols, int format,
                          const int64_t ptr[], const int64_t ind[], const double values[]);
int fricreg_hb_set_rayleigh(fricreg_hb *hb, double a0, double a1);
int fricreg_hb_set_element_param(fricreg_hb *hb, size_t first, size_t count, size_t index,
                                 double value);
int fricreg_hb_get_element_param(fricreg_hb *hb, size_t e, size_t index, double *value);
int fricreg_hb_add_elements(fricreg_hb *hb, const fricreg_element_type *type, size_t me,
                            size_t ndof, const double J[], const double params[]);
int fricreg_hb_set_excitation(fricreg_hb *hb, size_t ndof, const double pc[], const double ps[]);
int fricreg_hb_set_newton(fricreg_hb *hb, double tol, int max_iter);
int fricreg_hb_set_newton_solver(fricreg_hb *hb, int solver);
int fricreg_hb_set_receptance(fricreg_hb *hb, int method);
int fricreg_hb_set_continuation(fricreg_hb *hb, double ds, double ds_min, double ds_max,
                                size_t max_points);
int fricreg_hb_set_monitor(fricreg_hb *hb, fricreg_hb_monitor fn, void *user);
int fricreg_hb_solve(fricreg_hb *hb, double omega, size_t nq, const double q0[], double q[]);
int fricreg_hb_displacement(fricreg_hb *hb, size_t ndof, size_t nc, double x[]);
int fricreg_hb_continue(fricreg_hb *hb, double omega0, double omega1, size_t nq, const double q0[]);
int fricreg_hb_continue_level(fricreg_hb *hb, double omega, double level0, double level1, size_t nq,
                              const double q0[]);
size_t fricreg_hb_points(const fricreg_hb *hb);
int fricreg_hb_point(fricreg_hb *hb, size_t k, double *omega, size_t ndof, double rms[]);
int fricreg_hb_point_level(fricreg_hb *hb, size_t k, double *level);
int fricreg_hb_point_displacement(fricreg_hb *hb, size_t k, size_t ndof, size_t nc, double x[]);
int fricreg_hb_peak(fricreg_hb *hb, size_t dof, double *omega, double *rms);
int fricreg_hb_set_stability(fricreg_hb *hb, int enable);
int fricreg_hb_point_stability(fricreg_hb *hb, size_t k, int *stable, double *mu_max);
int fricreg_hb_point_exponents(fricreg_hb *hb, size_t k, size_t nexp, double exponents[]);
int fricreg_hb_set_stability_method(fricreg_hb *hb, int method);
int fricreg_hb_get_stability_method(fricreg_hb *hb, int *method);
size_t fricreg_hb_bifurcations(const fricreg_hb *hb);
int fricreg_hb_bifurcation(fricreg_hb *hb, size_t i, int *type, double *omega, size_t *point,
                           size_t ndof, double rms[]);
int fricreg_hb_bifurcation_level(fricreg_hb *hb, size_t i, double *level);
int fricreg_hb_nma(fricreg_hb *hb, size_t mode, int damping, double a0, double a1, size_t npoints);
int fricreg_hb_nma_continue(fricreg_hb *hb, size_t mode, int damping, double a0, double a1,
                            size_t npoints);
int fricreg_hb_nma_at(fricreg_hb *hb, size_t mode, int damping, size_t n, const double amplitude[]);
size_t fricreg_hb_nma_points(const fricreg_hb *hb);
int fricreg_hb_nma_point(fricreg_hb *hb, size_t i, double *amplitude, double *omega, double *zeta,
                         size_t ndof, size_t nc, double x[]);
int fricreg_hb_nma_harmonic_energy(fricreg_hb *hb, size_t i, size_t nh, double fraction[]);
int fricreg_hb_nma_modal_participation(fricreg_hb *hb, size_t i, int harmonic, size_t nmodes,
                                       double fraction[]);
enum fricreg_hb_nma_param {
    FRICREG_HB_NMA_PARAM_ELEMENT = 0,
    FRICREG_HB_NMA_PARAM_DAMPING = 1,
    FRICREG_HB_NMA_PARAM_AMPLITUDE = 2
};
int fricreg_hb_nma_point_sensitivities(fricreg_hb *hb, size_t i, size_t np, const int kind[],
                                       const size_t first[], const size_t count[],
                                       const size_t index[], double domega[], double dzeta[],
                                       size_t ndof, double damp[]);
size_t fricreg_hb_nma_special_points(const fricreg_hb *hb);
int fricreg_hb_nma_special_point(fricreg_hb *hb, size_t i, int *type, double *amplitude,
                                 double *omega, double *zeta, int *harmonic, size_t *mode);
const char *fricreg_hb_errmsg(const fricreg_hb *hb);

/* Python's monitor (harmonic_balance.py), installed on every driver: it stops a solve on
 * Ctrl-C. */
extern "Python" int fricreg_py_hb_monitor(void *user, int64_t iterations, double parameter,
                                          double residual);
int fricreg_hb_qsma_at(fricreg_hb *hb, size_t mode, size_t n, const double amplitude[],
                       double omega[], double zeta[]);
int fricreg_hb_qsma_sensitivities(fricreg_hb *hb, size_t mode, size_t n, const double amplitude[],
                                  size_t np, const int kind[], const size_t first[],
                                  const size_t count[], const size_t index[], double domega[],
                                  double dzeta[]);
