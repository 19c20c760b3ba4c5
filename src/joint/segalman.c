/* SPDX-License-Identifier: GPL-3.0-or-later */
/* segalman.c — Segalman's four-parameter model on sliders (segalman.h), its checks, and the
 * element types' helper fricreg_element_segalman (fricreg_element.h). */
#include <math.h>

#include "element_kind.h"
#include "segalman.h"

/* Grid point j of m (fricreg_iwan.h), in units of phi_max: x_0 = 0, x_j =
 * resolution^((m - j)/(m - 1)), x_m = 1. */
static double grid(double resolution, size_t m, size_t j)
{
    if (j == 0)
        return 0.0;
    return m == 1 ? 1.0 : pow(resolution, (double)(m - j) / (double)(m - 1));
}

/* Slider s (0-based) of Segalman's model for one element, on the moment rule's geometric grid
 * (fricreg_iwan.h). With a = chi + 1, b = chi + 2 and the grid x_j in units of phi_max,
 * slider j - 1 has k = Kc (x_j^a - x_(j-1)^a), phi = Fc (x_j^b - x_(j-1)^b), where
 * Kc = K_T/(1 + beta) = R phi_max^a/a and Fc = R phi_max^b/b = F_S - S phi_max; the delta's
 * slider (the last, if beta > 0) has k = S = beta Kc, phi = S phi_max. Both sums telescope to
 * Kc + S = K_T and Fc + S phi_max = F_S. */
void fr_segalman_slider(double fs, double kt, double chi, double beta, double resolution, size_t ns,
                        size_t s, double *k, double *phi)
{
    double a = chi + 1.0, b = chi + 2.0, r = a / b;
    double kc = kt / (1.0 + beta), fc = fs * r / (beta + r);
    size_t m = beta > 0.0 ? ns - 1 : ns;
    if (s == m) { /* the delta at phi_max */
        double phimax = fs * (1.0 + beta) / (kt * (beta + r));
        *k = beta * kc;
        *phi = *k * phimax;
        return;
    }
    double x1 = grid(resolution, m, s + 1), x0 = grid(resolution, m, s);
    *k = kc * (pow(x1, a) - pow(x0, a));
    *phi = fc * (pow(x1, b) - pow(x0, b));
}

int fr_segalman_check_params(double fs, double kt, double chi, double beta, double resolution,
                             size_t ns, char *msg, size_t len)
{
    if (!isfinite(fs) || !isfinite(kt) || !isfinite(chi) || !isfinite(beta) ||
        !isfinite(resolution))
        return fr_element_say(FRICREG_ENONFINITE, msg, len,
                              "fs = %g, kt = %g, chi = %g, beta = %g, resolution = %g", fs, kt, chi,
                              beta, resolution);
    if (!(fs > 0.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "fs = %g must be > 0", fs);
    if (!(kt > 0.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "kt = %g must be > 0", kt);
    if (!(chi > -1.0 && chi <= 1.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "chi = %g must be in (-1, 1]", chi);
    if (!(beta >= 0.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "beta = %g must be >= 0", beta);
    if (beta > 0.0 && ns < 2)
        return fr_element_say(FRICREG_EINVAL, msg, len, "beta = %g > 0 needs ns >= 2 (ns = %zu)",
                              beta, ns);
    size_t m = beta > 0.0 ? ns - 1 : ns;
    if (m >= 2 && !(resolution > 0.0 && resolution < 1.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "resolution = %g must be in (0, 1)",
                              resolution);
    return FRICREG_OK;
}

int fr_segalman_check_sliders(double fs, double kt, double chi, double beta, double resolution,
                              size_t ns, char *msg, size_t len)
{
    for (size_t s = 0; s < ns; s++) {
        double k, phi;
        fr_segalman_slider(fs, kt, chi, beta, resolution, ns, s, &k, &phi);
        if (!isfinite(k) || !isfinite(phi))
            return fr_element_say(FRICREG_ENONFINITE, msg, len,
                                  "slider %zu: k = %g, phi = %g (extreme parameters)", s, k, phi);
        if (!(k > 0.0) || !(phi >= 0.0))
            return fr_element_say(
                FRICREG_EINVAL, msg, len,
                "slider %zu: k = %g underflows (chi = %g near -1, or resolution = %g too "
                "small)",
                s, k, chi, resolution);
    }
    return FRICREG_OK;
}

int fricreg_element_segalman(size_t ns, double fs, double kt, double chi, double beta,
                             double resolution, double k[], double phi[])
{
    if (k == NULL || phi == NULL)
        return FRICREG_ENULL;
    if (ns == 0 || ns > FRICREG_ELEMENT_MAX_SLIDERS)
        return FRICREG_EINVAL;
    int status = fr_segalman_check_params(fs, kt, chi, beta, resolution, ns, NULL, 0);
    if (status == FRICREG_OK)
        status = fr_segalman_check_sliders(fs, kt, chi, beta, resolution, ns, NULL, 0);
    if (status != FRICREG_OK)
        return status;
    for (size_t s = 0; s < ns; s++)
        fr_segalman_slider(fs, kt, chi, beta, resolution, ns, s, &k[s], &phi[s]);
    return FRICREG_OK;
}
