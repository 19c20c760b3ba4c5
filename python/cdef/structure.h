/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure.h — fricreg_structure.h's linear structure with friction contacts and joint elements
 * (python/fricreg/structure.py), fricreg_types.h's estimators and kinds, fricreg_sim.h's
 * integrator names and fricreg.h's warning names (the dense setters for the tests, which compare
 * fricreg_structure_set_matrix with them), in the syntax of cffi's cdef (no macros, no
 * includes; python/build_ffi.py). The observer that records the time series and stops a run
 * on Ctrl-C is the binding's own C (callbacks.h). */
enum fricreg_error_estimate {
    FRICREG_ESTIMATE_OFF = 0,
    FRICREG_ESTIMATE_TWO_COMPANIONS = 1,
    FRICREG_ESTIMATE_ONE_COMPANION = 2
};
enum fricreg_estimate_kind {
    FRICREG_EST_KIND_ASYMPTOTIC = 1,
    FRICREG_EST_KIND_BOUND = 2,
    FRICREG_EST_KIND_ASSUMED = 3
};
static const double FRICREG_ATOL_FROM_EPS;
const char *fricreg_warning_name(int code);
const char *fricreg_integrator_name(int integrator);
int fricreg_integrator_from_name(const char *name);

typedef struct fricreg_structure fricreg_structure;
int fricreg_structure_create(size_t ndof, size_t m, fricreg_structure **out);
void fricreg_structure_free(fricreg_structure *s);
int fricreg_structure_set_mass(fricreg_structure *s, size_t ndof, const double M[]);
int fricreg_structure_set_stiffness(fricreg_structure *s, size_t ndof, const double K[]);
int fricreg_structure_set_contacts(fricreg_structure *s, size_t m, size_t ndof, const double J[]);
int fricreg_structure_set_rayleigh(fricreg_structure *s, double a0, double a1);
int fricreg_structure_set_matrix(fricreg_structure *s, int which, size_t nrows, size_t ncols,
                                 int format, const int64_t ptr[], const int64_t ind[],
                                 const double values[]);
int fricreg_structure_set_bounds(fricreg_structure *s, size_t m, const double mun[]);
int fricreg_structure_set_law(fricreg_structure *s, int law, double eps);
int fricreg_structure_set_influence(fricreg_structure *s, size_t ndof, const double r[]);
int fricreg_structure_set_ground_accel(fricreg_structure *s, double t0, double dt_rec, size_t n,
                                       const double ag[]);
int fricreg_structure_set_load(fricreg_structure *s, size_t ndof, const double p[], double t0,
                               double dt_rec, size_t n, const double g[]);
int fricreg_structure_set_initial(fricreg_structure *s, size_t ndof, const double u0[],
                                  const double v0[]);
int fricreg_structure_set_newmark(fricreg_structure *s, double beta, double gamma);
int fricreg_structure_set_hht(fricreg_structure *s, double alpha);
int fricreg_structure_set_central_difference(fricreg_structure *s);
int fricreg_structure_set_newton(fricreg_structure *s, double tol, int max_iter);
enum fricreg_contact_solver {
    FRICREG_CONTACT_SOLVER_AUTO = 0,
    FRICREG_CONTACT_SOLVER_DENSE = 1,
    FRICREG_CONTACT_SOLVER_SPARSE = 2
};
int fricreg_structure_set_contact_solver(fricreg_structure *s, int solver);
int fricreg_structure_get_contact_solver(const fricreg_structure *s, int *solver);
int fricreg_structure_step(fricreg_structure *s, double dt);
int fricreg_structure_run(fricreg_structure *s, double dt, double t_end);
typedef int (*fricreg_structure_observer)(void *user, double t, size_t ndof, const double u[],
                                          const double v[], size_t m, const double f[]);
int fricreg_structure_set_observer(fricreg_structure *s, fricreg_structure_observer fn, void *user);
int fricreg_structure_run_ode(fricreg_structure *s, int integrator, double dt, double rtol,
                              double atol, double t_end);
int fricreg_structure_get_state(const fricreg_structure *s, size_t ndof, double u[], double v[],
                                double a[]);
int fricreg_structure_get_forces(const fricreg_structure *s, size_t m, double f[]);
int fricreg_structure_get_dissipation(const fricreg_structure *s, size_t m, double D[]);
enum fricreg_structure_value {
    FRICREG_SVALUE_TIME = 0,
    FRICREG_SVALUE_INPUT = 1,
    FRICREG_SVALUE_KINETIC = 2,
    FRICREG_SVALUE_STRAIN = 3,
    FRICREG_SVALUE_VISCOUS = 4,
    FRICREG_SVALUE_FRICTION = 5,
    FRICREG_SVALUE_RESIDUAL = 6,
    FRICREG_SVALUE_INITIAL = 7,
    FRICREG_SVALUE_GROUND_PGV = 8,
    FRICREG_SVALUE_JENKINS = 9,
    FRICREG_SVALUE_COMPANION_CPU = 10,
    FRICREG_SVALUE_COMPANIONS_USED = 11,
    FRICREG_SVALUE_SCREEN_PEAK_ERR = 12,
    FRICREG_SVALUE_SCREEN_DISS_ERR = 13
};
int fricreg_structure_add_elements(fricreg_structure *s, const fricreg_element_type *type,
                                   size_t me, size_t ndof, const double J[], const double params[]);
size_t fricreg_structure_element_count(const fricreg_structure *s);
int fricreg_structure_get_elements(const fricreg_structure *s, size_t me, double f[],
                                   double state[], double D[]);
int fricreg_structure_get_value(const fricreg_structure *s, int which, double *value);
int fricreg_structure_set_error_estimate(fricreg_structure *s, int on);
enum fricreg_estimate_companions {
    FRICREG_COMPANIONS_FINER = 0,
    FRICREG_COMPANIONS_COARSER = 1,
    FRICREG_COMPANIONS_AUTO = 2
};
int fricreg_structure_set_error_companions(fricreg_structure *s, int which);
int fricreg_structure_get_peak_displacement(const fricreg_structure *s, size_t ndof, double peak[]);
int fricreg_structure_get_peak_displacement_error(const fricreg_structure *s, size_t ndof,
                                                  double err[]);
int fricreg_structure_get_dissipation_error(const fricreg_structure *s, size_t m, double err[]);
int fricreg_structure_get_jenkins_dissipation_error(const fricreg_structure *s, size_t me,
                                                    double err[]);
enum fricreg_estimated_quantity {
    FRICREG_EST_PEAK_DISPLACEMENT = 1,
    FRICREG_EST_DISSIPATION = 2,
    FRICREG_EST_ELEMENT_DISSIPATION = 3
};
int fricreg_structure_get_error_kind(const fricreg_structure *s, int quantity, size_t n,
                                     int kind[]);
int fricreg_structure_set_answer_rtol(fricreg_structure *s, double rtol);
enum fricreg_structure_stat {
    FRICREG_SSTAT_STEPS = 0,
    FRICREG_SSTAT_NEWTON_ITERATIONS = 1,
    FRICREG_SSTAT_NEWTON_MAX = 2,
    FRICREG_SSTAT_NEWTON_FAILURES = 3,
    FRICREG_SSTAT_LINE_SEARCH_CUTS = 4
};
int fricreg_structure_get_stat(const fricreg_structure *s, int which, int64_t *value);
const char *fricreg_structure_errmsg(const fricreg_structure *s);
size_t fricreg_structure_warning_count(fricreg_structure *s);
int fricreg_structure_get_warning(const fricreg_structure *s, size_t k, int *code, char *buf,
                                  size_t len);
const char *fricreg_structure_warning_message(const fricreg_structure *s, size_t k);
int fricreg_structure_save(fricreg_structure *s, void *buf, size_t *size);
int fricreg_structure_restore(fricreg_structure *s, const void *buf, size_t size);
