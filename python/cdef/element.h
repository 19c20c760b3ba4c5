/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element.h — fricreg_element.h's element types (fricreg_element_eval for the tests,
 * which compare the batch with it), in the syntax of cffi's cdef (no macros, no includes;
 * python/build_ffi.py). */
typedef struct fricreg_element_type fricreg_element_type;
#define FRICREG_ELEMENT_MAX_SLIDERS 1024
const fricreg_element_type *fricreg_element_lookup(const char *name);
size_t fricreg_element_count(void);
const fricreg_element_type *fricreg_element_at(size_t index);
const fricreg_element_type *fricreg_element_sliders(const fricreg_element_type *type, size_t ns);
const char *fricreg_element_name(const fricreg_element_type *type);
int fricreg_element_dim(const fricreg_element_type *type);
size_t fricreg_element_nparams(const fricreg_element_type *type);
size_t fricreg_element_nstate(const fricreg_element_type *type);
size_t fricreg_element_nsliders(const fricreg_element_type *type);
int fricreg_element_init(const fricreg_element_type *type, const double params[], double state[]);
int fricreg_element_eval(const fricreg_element_type *type, const double params[],
                         const double state_in[], const double u[], double f[], double dfdu[],
                         double dfdp[], double state_out[]);
int fricreg_element_eval_batch(const fricreg_element_type *type, size_t npoints,
                               const double params[], size_t params_stride, const double state_in[],
                               const double u[], double f[], double dfdu[], double dfdp[],
                               double state_out[], size_t *bad_point);
int fricreg_element_explain(const fricreg_element_type *type, const double params[],
                            const double state_in[], const double u[], char *msg, size_t len);
int fricreg_element_segalman(size_t ns, double fs, double kt, double chi, double beta,
                             double resolution, double k[], double phi[]);
