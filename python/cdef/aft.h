/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft.h — fricreg_aft.h's alternating frequency-time method (the workspace, the exact and
 * sampled AFT of the Jenkins, Iwan, Jenkins-with-lift-off and 3-D contact elements), in the
 * syntax of cffi's cdef (no macros, no includes; python/build_ffi.py). */
typedef struct fricreg_aft fricreg_aft;
#define FRICREG_AFT_MAX_HARMONICS 40
#define FRICREG_AFT_MAX_SAMPLES 16777216
int fricreg_aft_create(int harmonics, size_t samples, fricreg_aft **out);
void fricreg_aft_free(fricreg_aft *aft);
int fricreg_aft_harmonics(const fricreg_aft *aft);
size_t fricreg_aft_samples(const fricreg_aft *aft);
int fricreg_aft_jenkins_exact(fricreg_aft *aft, double kt, double mun, size_t n, const double u[],
                              double f[], double jac[]);
int fricreg_aft_jenkins_sampled(fricreg_aft *aft, double kt, double mun, size_t n, const double u[],
                                double f[], double jac[]);
int fricreg_aft_iwan_exact(fricreg_aft *aft, size_t ns, const double k[], const double phi[],
                           size_t n, const double u[], double f[], double jac[]);
int fricreg_aft_iwan_sampled(fricreg_aft *aft, size_t ns, const double k[], const double phi[],
                             size_t n, const double u[], double f[], double jac[]);
int fricreg_aft_jenkins_normal_sampled(fricreg_aft *aft, double kt, double mu, double n0, double kn,
                                       size_t n, const double u[], const double g[], double f[],
                                       double nf[], double jac[]);
int fricreg_aft_jenkins_normal_exact(fricreg_aft *aft, double kt, double mu, double n0, double kn,
                                     size_t n, const double u[], const double g[], double f[],
                                     double nf[], double jac[]);
int fricreg_aft_jenkins_2d_normal_sampled(fricreg_aft *aft, double kt, double mu, double n0,
                                          double kn, size_t n, const double u[], const double g[],
                                          double f[], double nf[], double jac[]);
int fricreg_aft_errcode(const fricreg_aft *aft);
const char *fricreg_aft_errmsg(const fricreg_aft *aft);
size_t fricreg_aft_errmsg_copy(const fricreg_aft *aft, char *buf, size_t len);
