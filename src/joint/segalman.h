/* SPDX-License-Identifier: GPL-3.0-or-later */
/* segalman.h — Segalman's four-parameter Iwan model discretized into sliders (the rule of
 * fricreg_iwan_set_segalman, fricreg_iwan.h), shared by fricreg_iwan and the element types'
 * helper fricreg_element_segalman. */
#ifndef FRICREG_JOINT_SEGALMAN_H
#define FRICREG_JOINT_SEGALMAN_H

#include <stddef.h>

/* Slider s (0-based) of ns: its stiffness *k and slip force *phi. */
void fr_segalman_slider(double fs, double kt, double chi, double beta, double resolution, size_t ns,
                        size_t s, double *k, double *phi);

/* The model's parameters for ns sliders: FRICREG_OK, or the status and a message into msg[len]
 * (fricreg_iwan_set_segalman's ranges). */
int fr_segalman_check_params(double fs, double kt, double chi, double beta, double resolution,
                             size_t ns, char *msg, size_t len);

/* The ns sliders of parameters that passed fr_segalman_check_params: FRICREG_OK if each k is
 * finite and > 0 and each phi finite, else the status and a message into msg[len]. */
int fr_segalman_check_sliders(double fs, double kt, double chi, double beta, double resolution,
                              size_t ns, char *msg, size_t len);

#endif
