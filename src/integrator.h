/* integrator.h — internal: our integrator enum mapped onto GSL's gsl_odeiv2 steppers. */
#ifndef FRICREG_INTEGRATOR_H
#define FRICREG_INTEGRATOR_H

#include <gsl/gsl_odeiv2.h>

struct fr_integrator {
    int id;                          /* enum fricreg_integrator */
    const char *name;                /* GSL's name */
    const gsl_odeiv2_step_type *(*type)(void);
    /* Largest stable dt*lambda on the negative real axis for a fixed step of this stepper
     * (0: not checked a priori, the stepper reports its own failure). */
    double real_axis_bound;
    /* GSL steps of this stepper per fricreg step dt (see fr_integrator_gsl_step). */
    int substeps;
};

/* The table row of an integrator id, or NULL if unknown. */
const struct fr_integrator *fr_integrator_find(int id);

#endif
