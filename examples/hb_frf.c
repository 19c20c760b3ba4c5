/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_frf.c — harmonic balance (fricreg_hb.h): the steady state of an oscillator with a Jenkins
 * element, m x'' + c x' + k x + f = F cos Ωt, f a spring kt in series with a slider of bound
 * mun (the element table's "jenkins" type, fricreg_element.h, added by fricreg_hb_add_elements),
 * at one frequency and along a resonance by continuation. Build: cc hb_frf.c
 * $(pkg-config --cflags --libs fricreg) or with CMake (fricreg::fricreg). */
#include <math.h>
#include <stdio.h>

#include "fricreg_hb.h"

#define H 7            /* harmonics */
#define NC (2 * H + 1) /* coefficients per dof or element */

static int check(fricreg_hb *hb, int status)
{
    if (status != FRICREG_OK)
        fprintf(stderr, "fricreg_hb: %s (%s)\n", fricreg_strerror(status), fricreg_hb_errmsg(hb));
    return status != FRICREG_OK;
}

int main(void)
{
    const double m = 1.0, c = 0.1, k = 3.0, J = 1.0, kt = 1.0, mun = 1.0;
    const double params[2] = {kt, mun}; /* the "jenkins" type's parameters: kt, mun */
    const fricreg_element_type *jenkins = fricreg_element_lookup("jenkins");
    double pc = 0.1, ps = 0.0, q[NC], x[NC];
    fricreg_hb *hb = NULL;
    if (fricreg_hb_create(1, 1, H, &hb) != FRICREG_OK)
        return 1;
    if (check(hb, fricreg_hb_set_mass(hb, 1, &m)) ||
        check(hb, fricreg_hb_set_stiffness(hb, 1, &k)) ||
        check(hb, fricreg_hb_set_damping(hb, 1, &c)) ||
        check(hb, fricreg_hb_add_elements(hb, jenkins, 1, 1, &J, params)) ||
        check(hb, fricreg_hb_set_excitation(hb, 1, &pc, &ps)))
        return 1;

    /* A small force: the element sticks, a spring kt, and the response is linear:
     * |X| = F / |k + kt − m Ω² + i c Ω| = 0.1 / |3 + 0.1 i| = 0.033315 at Ω = 1. */
    if (check(hb, fricreg_hb_solve(hb, 1.0, NC, NULL, q)) ||
        check(hb, fricreg_hb_displacement(hb, 1, NC, x)))
        return 1;
    printf("stuck, Omega = 1: amplitude %.6f\n", hypot(x[1], x[2]));

    /* A large force: the element slips each period and damps the resonance, whose peak lies
     * between the slipped (sqrt(k/m) = 1.732) and stuck (sqrt((k + kt)/m) = 2) frequencies. */
    pc = 1.5;
    if (check(hb, fricreg_hb_set_excitation(hb, 1, &pc, &ps)) ||
        check(hb, fricreg_hb_continue(hb, 0.5, 3.0, NC, NULL)))
        return 1;
    double peak = 0.0, w_peak = 0.0;
    size_t n = fricreg_hb_points(hb);
    for (size_t i = 0; i < n; i++) {
        double omega, rms;
        if (check(hb, fricreg_hb_point(hb, i, &omega, 1, &rms)))
            return 1;
        if (i % 8 == 0 || i + 1 == n)
            printf("Omega = %.4f  rms = %.5f\n", omega, rms);
        if (rms > peak)
            peak = rms, w_peak = omega;
    }
    printf("%zu points; peak rms %.4f at Omega = %.4f: between the slipped and stuck "
           "resonances: %s\n",
           n, peak, w_peak, w_peak > sqrt(k / m) && w_peak < sqrt((k + kt) / m) ? "yes" : "no");
    fricreg_hb_free(hb);
    return 0;
}
