# SPDX-License-Identifier: GPL-3.0-or-later
"""The alternating frequency-time method (AFT) of friction elements on Fourier coefficients
(``fricreg_aft.h``): from the coefficients of a periodic relative displacement, the
coefficients of the element force over its stabilized (periodic) hysteresis and their
Jacobian, for a harmonic-balance solver; exactly (switch points as roots of trigonometric
polynomials, pieces integrated in closed form) or sampled (the return mapping at N points and
an FFT). AFT after M. Krack and J. Gross, *Harmonic Balance for Nonlinear Vibration Problems*,
Springer 2019, Sec. 3.3; fricreg's ``docs/aft.md``.

**Coefficient order** (fricreg's, every array of this module unless a function says
otherwise). A periodic quantity over one period, theta = Omega t in [0, 2 pi),

    u(theta) = u0 + sum_{h=1..H} (a_h cos(h theta) + b_h sin(h theta)),

is the float64 array ``u = [u0, a_1, b_1, a_2, b_2, ..., a_H, b_H]`` of ``n = 2H + 1``
numbers; u0 is the mean (not half of it), a_h = (1/pi) int u cos(h theta), b_h = (1/pi) int
u sin(h theta). Forces come back in the same order. A Jacobian is row-major,
``jac[i, j]`` = d f[i] / d u[j]. An element with more than one component (the normal types)
stacks them as rows: coefficients of shape ``(dim, n)``, Jacobian of shape
``(dim n, dim n)`` with ``jac[a n + i, c n + j]`` = d f_a[i] / d u_c[j].

**Other orders.** tmdsimpy and pyHarm use the same basis and scaling per degree of freedom
(``[a0, a1, b1, a2, b2, ...]``, cosine then sine, a0 the mean), but lay out several degrees
of freedom harmonic-major (all dofs' a0, then all dofs' a1, all b1, ...), and tmdsimpy keeps
only the harmonics listed in ``h``: ``aft_layouts.py`` converts, and makes an element a
tmdsimpy force.
"""

import numpy as np

from ._record import record
from ._fricreg import ffi, lib
from ._arrays import as_doubles, as_integer, as_scalar, pointer
from .element import Element
from .errors import raise_status, refused
from ._settings import fixed

__all__ = ["AFT", "AFTResult", "AFTNormalResult", "AFT_ELEMENT_TYPES"]

AFTResult = record("AFTResult", "f jac", """\
The result of :meth:`AFT.jenkins`, :meth:`AFT.iwan` and :meth:`AFT.element`.

f : ndarray of float64, shape (n,), or (dim, n) for :meth:`AFT.element` on a normal type
    The force's coefficients in fricreg's order (a normal type's rows: the tangential
    forces, then the normal force N).
jac : ndarray of float64, shape (dim n, dim n) (row-major, d f[i] / d u[j]), or None
""")

AFTNormalResult = record("AFTNormalResult", "f nf jac", """\
The result of :meth:`AFT.jenkins_normal` and
:meth:`AFT.jenkins_2d_normal`.

f : ndarray of float64, shape (n,) (1-D) or (2, n) (rows fx, fy)
    The tangential force's coefficients.
nf : ndarray of float64, shape (n,)
    The normal force's coefficients, N(theta) = max(0, N0 + kn g(theta)).
jac : ndarray of float64, shape (2n, 2n) or (3n, 3n), or None
    Row-major, rows (f, nf) or (fx, fy, nf), columns (u, g) or (ux, uy, g); d nf / d u = 0.
""")

#: The element types of :class:`fricreg.Element` that :meth:`AFT.element` takes, with the C
#: functions it calls (contact_3d: the sampled path only).
AFT_ELEMENT_TYPES = {
    "jenkins": ("fricreg_aft_jenkins_exact", "fricreg_aft_jenkins_sampled"),
    "iwan": ("fricreg_aft_iwan_exact", "fricreg_aft_iwan_sampled"),
    "jenkins_normal": ("fricreg_aft_jenkins_normal_exact", "fricreg_aft_jenkins_normal_sampled"),
    "contact_3d": (None, "fricreg_aft_jenkins_2d_normal_sampled"),
}


def _aft_type(element, exact):
    """The C type name of a fricreg.Element that has an AFT; ValueError otherwise."""
    if not isinstance(element, Element):
        raise refused("element: %r is not a fricreg.Element" % (element,))
    name = ffi.string(lib.fricreg_element_name(element._type)).decode()
    if name not in AFT_ELEMENT_TYPES:
        raise refused("element: %s has no AFT in fricreg_aft.h (the types that have: %s)"
                      % (name, ", ".join(AFT_ELEMENT_TYPES)))
    if exact and AFT_ELEMENT_TYPES[name][0] is None:
        raise refused("exact: %s has only the sampled AFT (%s); pass exact=False"
                      % (name, AFT_ELEMENT_TYPES[name][1]))
    return name


class AFT:
    """An AFT workspace for harmonics 0..H and, for the sampled path, N samples a period
    (``fricreg_aft_create``; freed with ``fricreg_aft_free`` when the object goes).

    Every buffer an evaluation needs is allocated here; the element parameters are arguments
    of each call, so one object serves every element of a model. One object per thread.

    Parameters
    ----------
    harmonics : int
        H, 1 <= H <= 40 (``FRICREG_AFT_MAX_HARMONICS``): coefficient arrays have n = 2H + 1
        entries.
    samples : int
        N: 0 (the exact path only; a sampled call then raises), or a power of two with
        2H + 2 <= N <= 2**24.

    Attributes
    ----------
    harmonics, samples, n : int
        H, N and 2H + 1 (read-only).

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``harmonics`` or ``samples`` is not an integer, or ``samples`` is
        negative. Refused by the library: H or N out of the ranges above.
    fricreg.OutOfMemoryError
        The workspace could not be allocated.

    Notes
    -----
    The methods call ``fricreg_aft_jenkins_exact`` / ``_sampled``, ``fricreg_aft_iwan_exact``
    / ``_sampled``, ``fricreg_aft_jenkins_normal_exact`` / ``_sampled`` and
    ``fricreg_aft_jenkins_2d_normal_sampled``; their numbers are the C functions' bit for
    bit. The stabilized hysteresis: where the element slips, the unique periodic response;
    where it sticks throughout, the centred slider w = (max u + min u)/2 (``fricreg_aft.h``).
    The element is rate-independent: nothing depends on the frequency.
    """

    # every attribute: assigning a misspelt setting raises instead of adding one
    __slots__ = ("_aft", "_harmonics", "_samples", "_n", "__weakref__")

    def __init__(self, harmonics, samples=0):
        H = as_integer(harmonics, "harmonics")
        N = as_integer(samples, "samples")
        if N < 0:
            raise refused("samples: %d is negative" % N)
        out = ffi.new("fricreg_aft **")
        fits = 1 <= H <= lib.FRICREG_AFT_MAX_HARMONICS and N <= lib.FRICREG_AFT_MAX_SAMPLES
        status = lib.fricreg_aft_create(H, N, out) if fits else lib.FRICREG_EINVAL
        if status != lib.FRICREG_OK:
            detail = "" if status == lib.FRICREG_ENOMEM else (
                "harmonics = %d, samples = %d: H must be 1..%d, and N 0 or a power of two with"
                " 2H + 2 <= N <= %d" % (H, N, lib.FRICREG_AFT_MAX_HARMONICS,
                                        lib.FRICREG_AFT_MAX_SAMPLES))
            raise_status(status, "AFT", detail)
        self._aft = ffi.gc(out[0], lib.fricreg_aft_free)
        self._harmonics = lib.fricreg_aft_harmonics(self._aft)
        self._samples = lib.fricreg_aft_samples(self._aft)
        self._n = 2 * self._harmonics + 1

    harmonics = fixed("harmonics", "int: H, fixed at construction.")
    samples = fixed("samples", "int: N, the samples a period (0: the exact path only), fixed "
                    "at construction.")
    n = fixed("n", "int: 2H + 1, the length of a coefficient array.")

    def __repr__(self):
        return "AFT(harmonics=%d, samples=%d)" % (self.harmonics, self.samples)

    def _check(self, status, where):
        """Raise with the workspace's own message if the call failed."""
        if status != lib.FRICREG_OK:
            raise_status(status, where, ffi.string(lib.fricreg_aft_errmsg(self._aft)).decode())

    def _coefficients(self, value, name, rows=None):
        """value as coefficients of shape (n,), or (rows, n); ValueError naming it."""
        array = as_doubles(value, name)
        shape = (self.n,) if rows is None else (rows, self.n)
        if array.shape != shape:
            raise refused("%s: shape %s; expected %s (n = 2H + 1 = %d)"
                          % (name, array.shape, shape, self.n))
        return array

    def _jac(self, size, jacobian):
        """A fresh Jacobian and its C pointer, or None and NULL."""
        if not jacobian:
            return None, ffi.NULL
        jac = np.empty((size, size))
        return jac, pointer(jac)

    def jenkins(self, kt, mun, u, exact=True, jacobian=True):
        """The AFT of one 1-D Jenkins element: the force's coefficients and their Jacobian.

        Parameters
        ----------
        kt : float
            Tangential stiffness > 0 (force per unit displacement).
        mun : float
            Slip bound mu N >= 0 (force units); 0 gives f = 0 and jac = 0.
        u : array_like of float, shape (n,)
            The relative displacement's coefficients ``[u0, a_1, b_1, ..., a_H, b_H]``.
        exact : bool
            The exact path (default) or the sampled one (needs ``samples`` > 0; error
            O(N**-2)).
        jacobian : bool
            Compute the Jacobian.

        Returns
        -------
        AFTResult
            ``f`` of shape (n,): the spring force kt (u - w) (u = A cos(theta) gives
            fa_1 > 0, fb_1 < 0); ``jac`` of shape (n, n), ``jac[i, j]`` = d f[i]/d u[j], or
            None.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``u`` is not of shape (n,) or not real numbers; a scalar is not a
            real number. Refused by the library: kt <= 0, mun < 0, a NaN or infinite input, or a
            sampled call on a workspace with samples = 0; the message is
            ``fricreg_aft_errmsg``'s.
        fricreg.Error
            ``FRICREG_EINTEGRATOR``: GSL's polynomial root solver did not converge.

        Notes
        -----
        ``fricreg_aft_jenkins_exact`` or ``fricreg_aft_jenkins_sampled``. For u = A cos(theta)
        with kt A > mun and r = mun/kt: fa_1 = (kt A/pi)(t - sin t cos t) with
        cos t = 1 - 2r/A, fb_1 = -(4 mun/pi)(1 - r/A) (Caughey 1960), and the energy
        dissipated per period, pi sum_h h (b_h fa_h - a_h fb_h), is 4 mun (A - r).
        """
        u = self._coefficients(u, "u")
        f = np.empty(self.n)
        jac, jac_c = self._jac(self.n, jacobian)
        call = lib.fricreg_aft_jenkins_exact if exact else lib.fricreg_aft_jenkins_sampled
        status = call(self._aft, as_scalar(kt, "kt"), as_scalar(mun, "mun"), self.n, pointer(u),
                      pointer(f), jac_c)
        self._check(status, "AFT.jenkins")
        return AFTResult(f, jac)

    def iwan(self, k, phi, u, exact=True, jacobian=True):
        """The AFT of one 1-D Iwan element: the sum of its sliders' Jenkins AFTs.

        Parameters
        ----------
        k : array_like of float, shape (ns,)
            The sliders' stiffnesses > 0 (force per unit displacement), ns >= 1.
        phi : array_like of float, shape (ns,)
            Their slip forces >= 0 (force units).
        u : array_like of float, shape (n,)
            The relative displacement's coefficients.
        exact, jacobian : bool
            As :meth:`jenkins`.

        Returns
        -------
        AFTResult
            ``f`` of shape (n,), ``jac`` of shape (n, n) or None.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``k`` or ``phi`` is not 1-D or their shapes differ; ``u`` is not
            of shape (n,). Refused by the library: no slider, some k <= 0 or phi < 0, a NaN or
            infinite input, or a sampled call with samples = 0 (``fricreg_aft_errmsg``'s
            message).
        fricreg.Error
            ``FRICREG_EINTEGRATOR`` as :meth:`jenkins`.

        Notes
        -----
        ``fricreg_aft_iwan_exact`` (the velocity reversals found once for every slider) or
        ``fricreg_aft_iwan_sampled`` (one FFT for the sum).
        """
        k = as_doubles(k, "k", ndim=1)
        phi = as_doubles(phi, "phi", ndim=1)
        if phi.shape != k.shape:
            raise refused("phi: shape %s; expected k's %s" % (phi.shape, k.shape))
        u = self._coefficients(u, "u")
        f = np.empty(self.n)
        jac, jac_c = self._jac(self.n, jacobian)
        call = lib.fricreg_aft_iwan_exact if exact else lib.fricreg_aft_iwan_sampled
        status = call(self._aft, k.size, pointer(k), pointer(phi), self.n, pointer(u),
                      pointer(f), jac_c)
        self._check(status, "AFT.iwan")
        return AFTResult(f, jac)

    def jenkins_normal(self, kt, mu, n0, kn, u, g, exact=True, jacobian=True):
        """The AFT of one 1-D Jenkins element under a normal load with lift-off: slip bound
        mu N, N = max(0, N0 + kn g).

        Parameters
        ----------
        kt : float
            Tangential stiffness > 0 (force per unit displacement).
        mu : float
            Friction coefficient >= 0.
        n0 : float
            Preload N0 (force units): the normal force at g = 0 (negative: open at g = 0).
        kn : float
            Normal stiffness >= 0 (force per unit displacement).
        u : array_like of float, shape (n,)
            The tangential displacement's coefficients.
        g : array_like of float, shape (n,)
            The normal displacement's coefficients (positive pressing).
        exact, jacobian : bool
            As :meth:`jenkins`.

        Returns
        -------
        AFTNormalResult
            ``f``, ``nf`` of shape (n,); ``jac`` of shape (2n, 2n), rows (f, nf), columns
            (u, g), or None.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``u`` or ``g`` is not of shape (n,); a scalar is not a real
            number. Refused by the library: kt <= 0, mu < 0, kn < 0, a NaN or infinite input or
            an overflowing scale, or a sampled call with samples = 0 (``fricreg_aft_errmsg``).
        fricreg.Error
            ``FRICREG_EINTEGRATOR`` (the exact path's root solver).

        Notes
        -----
        ``fricreg_aft_jenkins_normal_exact`` or ``fricreg_aft_jenkins_normal_sampled``. With
        kn = 0 and N0 >= 0 it is :meth:`jenkins` at mun = mu N0 (the sampled path to the bit).
        """
        u = self._coefficients(u, "u")
        g = self._coefficients(g, "g")
        f, nf = np.empty(self.n), np.empty(self.n)
        jac, jac_c = self._jac(2 * self.n, jacobian)
        call = (lib.fricreg_aft_jenkins_normal_exact if exact
                else lib.fricreg_aft_jenkins_normal_sampled)
        status = call(self._aft, as_scalar(kt, "kt"), as_scalar(mu, "mu"), as_scalar(n0, "n0"),
                      as_scalar(kn, "kn"), self.n, pointer(u), pointer(g), pointer(f),
                      pointer(nf), jac_c)
        self._check(status, "AFT.jenkins_normal")
        return AFTNormalResult(f, nf, jac)

    def jenkins_2d_normal(self, kt, mu, n0, kn, u, g, jacobian=True):
        """The sampled AFT of one 3-D contact element: a 2-D Jenkins element (an isotropic
        Coulomb disk |f| <= mu N) under N = max(0, N0 + kn g) with lift-off.

        Parameters
        ----------
        kt, mu, n0, kn : float
            As :meth:`jenkins_normal`.
        u : array_like of float, shape (2, n)
            The tangential displacements' coefficients, rows ux, uy.
        g : array_like of float, shape (n,)
            The normal displacement's coefficients (positive pressing).
        jacobian : bool
            Compute the Jacobian.

        Returns
        -------
        AFTNormalResult
            ``f`` of shape (2, n) (rows fx, fy), ``nf`` of shape (n,), ``jac`` of shape
            (3n, 3n), rows (fx, fy, nf), columns (ux, uy, g), or None.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``u`` is not of shape (2, n) or ``g`` of shape (n,). Refused by
            the library: the workspace has samples = 0, kt <= 0, mu < 0, kn < 0, or a NaN or
            infinite input (``fricreg_aft_errmsg``).

        Notes
        -----
        ``fricreg_aft_jenkins_2d_normal_sampled`` (there is no exact path). Its error is first
        order in 1/N where the slip turns (the sampled return mapping drags the slider along
        chords); ``fricreg_hb`` extrapolates 2 F(N) - F(N/2). With uy = 0 and kn = 0, fx and
        N equal :meth:`jenkins_normal`'s sampled ones.
        """
        u = self._coefficients(u, "u", rows=2)
        g = self._coefficients(g, "g")
        f, nf = np.empty((2, self.n)), np.empty(self.n)
        jac, jac_c = self._jac(3 * self.n, jacobian)
        status = lib.fricreg_aft_jenkins_2d_normal_sampled(
            self._aft, as_scalar(kt, "kt"), as_scalar(mu, "mu"), as_scalar(n0, "n0"),
            as_scalar(kn, "kn"), self.n, pointer(u), pointer(g), pointer(f), pointer(nf), jac_c)
        self._check(status, "AFT.jenkins_2d_normal")
        return AFTNormalResult(f, nf, jac)

    def element(self, element, coefficients, exact=True, jacobian=True):
        """The AFT of a :class:`fricreg.Element`, dispatched on its type with its parameters.

        Parameters
        ----------
        element : fricreg.Element
            Of a type in :data:`AFT_ELEMENT_TYPES`: ``jenkins`` ([kt, mun]), ``iwan``
            ([k_1..k_ns, phi_1..phi_ns]), ``jenkins_normal`` ([kt, mu, kn, n0, gap]: N0 =
            n0 - kn gap), ``contact_3d`` (as jenkins_normal; sampled only).
        coefficients : array_like of float, shape (dim, n), or (n,) for dim = 1
            The displacement's coefficients, one row per component of the element's u:
            jenkins_normal (u, g), contact_3d (ux, uy, g).
        exact, jacobian : bool
            As :meth:`jenkins`; contact_3d needs exact=False.

        Returns
        -------
        AFTResult
            ``f`` of the shape of ``coefficients``, one row per component of the element's
            force (the normal force N last); ``jac`` of shape (dim n, dim n),
            ``jac[a n + i, c n + j]`` = d f_a[i] / d u_c[j], or None.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``element`` is no Element or of a type without an AFT; exact=True
            for contact_3d; ``coefficients`` of another shape.
        fricreg.InputError, fricreg.Error
            As the method called.

        Notes
        -----
        Calls :meth:`jenkins`, :meth:`iwan`, :meth:`jenkins_normal` or
        :meth:`jenkins_2d_normal` (so the C functions of :data:`AFT_ELEMENT_TYPES`). The
        elements' normal law is N = max(0, n0 + kn (g - gap)) (``fricreg_element.h``), the
        AFT's N = max(0, N0 + kn g): N0 = n0 - kn gap, n0 itself when gap = 0.
        """
        name = _aft_type(element, exact)
        dim, p = element.dim, element.params
        c = as_doubles(coefficients, "coefficients")
        if not (c.shape == (dim, self.n) or (dim == 1 and c.shape == (self.n,))):
            raise refused("coefficients: shape %s; %s expects (%d, %d)%s"
                          % (c.shape, name, dim, self.n,
                             " or (%d,)" % self.n if dim == 1 else ""))
        if name == "jenkins":
            r = self.jenkins(p[0], p[1], c.reshape(self.n), exact, jacobian)
        elif name == "iwan":
            ns = element.nsliders
            r = self.iwan(p[:ns], p[ns:], c.reshape(self.n), exact, jacobian)
        else:
            kt, mu, kn, n0, gap = p
            n0 = n0 - kn * gap if gap != 0.0 else n0
            if name == "jenkins_normal":
                r = self.jenkins_normal(kt, mu, n0, kn, c[0], c[1], exact, jacobian)
            else:
                r = self.jenkins_2d_normal(kt, mu, n0, kn, c[:2], c[2], jacobian)
            return AFTResult(np.vstack([r.f, r.nf]), r.jac)
        return AFTResult(r.f.reshape(c.shape), r.jac)
