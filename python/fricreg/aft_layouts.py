# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg's AFT (aft.py) in the layouts of tmdsimpy and pyHarm, the Python packages of this
field: both use fricreg's basis and scaling per degree of freedom (``[a0, a1, b1, a2, b2,
...]``, cosine then sine, a0 the mean), but lay out several degrees of freedom harmonic-major
(all dofs' a0, then all dofs' a1, all b1, ...), and tmdsimpy keeps only the harmonics listed
in ``h``. :func:`to_tmdsimpy`, :func:`from_tmdsimpy`, :func:`jacobian_to_tmdsimpy`, their
pyHarm twins, and :class:`TmdsimpyForce`, an element with tmdsimpy's
``aft(U, w, h, Nt, tol, calc_grad)``. The permutations only move numbers: the results are
fricreg's bit for bit.
"""
import numpy as np

from .aft import AFT, _aft_type
from ._arrays import as_doubles, as_integer
from .errors import refused

__all__ = ["TmdsimpyForce", "to_tmdsimpy", "from_tmdsimpy", "jacobian_to_tmdsimpy",
           "to_pyharm", "from_pyharm", "jacobian_to_pyharm"]


def _harmonics(h):
    """h as a sorted array of distinct harmonics >= 0 (tmdsimpy's list); ValueError."""
    array = np.asarray(h)
    if array.ndim != 1 or array.size == 0 or array.dtype.kind not in "iu":
        raise refused("h: %r is not a nonempty 1-D list of integer harmonics" % (h,))
    if array[0] < 0 or np.any(np.diff(array) <= 0):
        raise refused("h: %s is not sorted, distinct harmonics >= 0" % array.tolist())
    return array


def _index(h, ndof, n):
    """The positions, in a flattened fricreg array of shape (ndof, n), of the entries of a
    harmonic-major vector over the harmonics h: entry k ndof + d is coefficient k of dof d."""
    columns = [0] if h[0] == 0 else []
    for harmonic in h[h > 0]:
        columns += [2 * harmonic - 1, 2 * harmonic]
    return (np.asarray(columns)[:, None] + n * np.arange(ndof)[None, :]).ravel()


def _ndof(value, name):
    ndof = as_integer(value, name)
    if ndof < 1:
        raise refused("%s: %d; expected >= 1" % (name, ndof))
    return ndof


def to_tmdsimpy(coefficients, h):
    """fricreg coefficients in tmdsimpy's order: harmonic-major over the harmonics h.

    Parameters
    ----------
    coefficients : array_like of float, shape (ndof, n) or (n,)
        fricreg's order per dof, ``[u0, a_1, b_1, ..., a_H, b_H]``, n = 2H + 1 odd; rows are
        degrees of freedom.
    h : array_like of int, shape (nh,)
        tmdsimpy's sorted list of harmonics, 0 first if present, max(h) <= H.

    Returns
    -------
    U : ndarray of float64, shape (ndof Nhc,)
        ``U[k ndof + d]`` = component k of dof d, the components ordered
        ``[a0, a_h1, b_h1, a_h2, b_h2, ...]`` over h (Nhc = 2 len(h), less 1 if 0 is in h).
        Harmonics not in h are dropped.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``coefficients`` not 1-D or 2-D with an odd length; ``h`` not sorted
        distinct integers >= 0, or above H.

    Notes
    -----
    tmdsimpy's ``get_fourier_coeff`` and ``time_series_deriv`` (its harmonic utilities):
    x(t) = X0 + sum_k (a_k cos(h_k w t) + b_k sin(h_k w t)), the same basis and scaling as
    fricreg's; only the layout differs.
    """
    c = as_doubles(coefficients, "coefficients")
    c2 = c.reshape(1, -1) if c.ndim == 1 else c
    if c2.ndim != 2 or c2.shape[1] % 2 == 0:
        raise refused("coefficients: shape %s; expected (ndof, 2H + 1) or (2H + 1,)"
                      % (c.shape,))
    h = _harmonics(h)
    if 2 * h[-1] + 1 > c2.shape[1]:
        raise refused("h: harmonic %d above the coefficients' H = %d"
                      % (h[-1], c2.shape[1] // 2))
    return c2.ravel()[_index(h, c2.shape[0], c2.shape[1])]


def from_tmdsimpy(U, h, ndof=1):
    """tmdsimpy's harmonic coefficients in fricreg's order, harmonics not in h set to 0.

    Parameters
    ----------
    U : array_like of float, shape (ndof Nhc,)
        tmdsimpy's layout (see :func:`to_tmdsimpy`).
    h : array_like of int, shape (nh,)
        Its sorted list of harmonics.
    ndof : int
        The degrees of freedom in U.

    Returns
    -------
    coefficients : ndarray of float64, shape (ndof, 2 max(h) + 1)
        fricreg's order per row.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``U`` not of shape (ndof Nhc,); ``h`` as :func:`to_tmdsimpy`;
        ``ndof`` < 1.

    Notes
    -----
    The inverse of :func:`to_tmdsimpy` where h holds every harmonic 0..H.
    """
    h = _harmonics(h)
    ndof = _ndof(ndof, "ndof")
    index = _index(h, ndof, 2 * int(h[-1]) + 1)
    U = as_doubles(U, "U")
    if U.shape != index.shape:
        raise refused("U: shape %s; expected (%d,) = (ndof Nhc,) for ndof = %d, h = %s"
                      % (U.shape, index.size, ndof, h.tolist()))
    out = np.zeros(ndof * (2 * int(h[-1]) + 1))
    out[index] = U
    return out.reshape(ndof, -1)


def jacobian_to_tmdsimpy(jacobian, h, ndof=1):
    """A Jacobian in fricreg's order (:meth:`AFT.element`'s) in tmdsimpy's.

    Parameters
    ----------
    jacobian : array_like of float, shape (ndof n, ndof n)
        Row-major, ``jacobian[d n + i, e n + j]`` = d f_d[i] / d u_e[j].
    h : array_like of int
        tmdsimpy's sorted list of harmonics, max(h) <= H.
    ndof : int
        The degrees of freedom (n = 2H + 1 follows from the Jacobian's size).

    Returns
    -------
    dFdU : ndarray of float64, shape (ndof Nhc, ndof Nhc)
        ``dFdU[k ndof + d, l ndof + e]`` = d F[k ndof + d] / d U[l ndof + e]: the rows and
        columns of the harmonics in h, in :func:`to_tmdsimpy`'s order.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``jacobian`` not square of a size ndof (2H + 1); ``h`` or ``ndof`` as
        above.

    Notes
    -----
    The derivatives in the kept coefficients with the dropped ones held at 0: the Jacobian
    of ``to_tmdsimpy(f(from_tmdsimpy(U)))``.
    """
    ndof = _ndof(ndof, "ndof")
    jac = as_doubles(jacobian, "jacobian", ndim=2)
    n = jac.shape[0] // ndof
    if jac.shape[0] != jac.shape[1] or jac.shape[0] != n * ndof or n % 2 == 0:
        raise refused("jacobian: shape %s; expected (ndof (2H + 1), ndof (2H + 1)) for"
                      " ndof = %d" % (jac.shape, ndof))
    h = _harmonics(h)
    if 2 * h[-1] + 1 > n:
        raise refused("h: harmonic %d above the Jacobian's H = %d" % (h[-1], n // 2))
    index = _index(h, ndof, n)
    return jac[np.ix_(index, index)]


def to_pyharm(coefficients):
    """fricreg coefficients in pyHarm's order: harmonic-major over 0..H.

    Parameters
    ----------
    coefficients : array_like of float, shape (ndof, 2H + 1) or (2H + 1,)

    Returns
    -------
    x : ndarray of float64, shape (ndof (2H + 1),)
        ``x[k ndof + d]`` = coefficient k of dof d, k over ``[a0, a1, b1, ..., aH, bH]``; for
        one dof the same array as fricreg's.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) As :func:`to_tmdsimpy`.

    Notes
    -----
    pyHarm (``src/pyHarm/DynamicOperator.py``, ``CoordinateSystem.getTM``): per dof
    ``[a0, a1, b1, ...]`` with x_time = x @ D["ft"] (rows 1, cos k theta, sin k theta), the
    same basis and scaling as fricreg's; a node's dofs harmonic-major,
    kron(eye(2nh + 1), direction). :func:`to_tmdsimpy` with h = 0..H.
    """
    c = as_doubles(coefficients, "coefficients")
    return to_tmdsimpy(c, np.arange(c.shape[-1] // 2 + 1))


def _pyharm_h(size, ndof, name):
    """The harmonics 0..H of a pyHarm array of size ndof (2H + 1)."""
    if size % ndof or (size // ndof) % 2 == 0:
        raise refused("%s: %d entries are not ndof (2H + 1) for ndof = %d" % (name, size, ndof))
    return np.arange((size // ndof) // 2 + 1)


def from_pyharm(x, ndof=1):
    """pyHarm's harmonic coefficients (:func:`to_pyharm`'s layout) in fricreg's order.

    Parameters
    ----------
    x : array_like of float, shape (ndof (2H + 1),)
    ndof : int

    Returns
    -------
    coefficients : ndarray of float64, shape (ndof, 2H + 1)

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``x`` not 1-D of a size ndof (2H + 1); ``ndof`` < 1.

    Notes
    -----
    :func:`from_tmdsimpy` with h = 0..H.
    """
    ndof = _ndof(ndof, "ndof")
    x = as_doubles(x, "x", ndim=1)
    return from_tmdsimpy(x, _pyharm_h(x.size, ndof, "x"), ndof)


def jacobian_to_pyharm(jacobian, ndof=1):
    """A Jacobian in fricreg's order in pyHarm's (:func:`to_pyharm`'s rows and columns).

    Parameters
    ----------
    jacobian : array_like of float, shape (ndof n, ndof n)
    ndof : int

    Returns
    -------
    dJdx : ndarray of float64, shape (ndof n, ndof n)

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) As :func:`jacobian_to_tmdsimpy`.

    Notes
    -----
    :func:`jacobian_to_tmdsimpy` with h = 0..H.
    """
    ndof = _ndof(ndof, "ndof")
    jac = as_doubles(jacobian, "jacobian", ndim=2)
    return jacobian_to_tmdsimpy(jac, _pyharm_h(jac.shape[0], ndof, "jacobian"), ndof)


class TmdsimpyForce:
    """A fricreg element as a tmdsimpy nonlinear force: ``aft(U, w, h, Nt, tol, calc_grad)``.

    The local displacements are ``Q @ X`` (tmdsimpy's convention), grouped into elements of
    ``element.dim`` consecutive local dofs that share the element's parameters (a normal type's
    last dof of each group is g); the global force is ``T @ f_local``. Attach it with
    tmdsimpy's ``VibrationSystem.add_nl_force``.

    Parameters
    ----------
    element : fricreg.Element
        Of a type in :data:`AFT_ELEMENT_TYPES`.
    Q : array_like of float, shape (Nnl, N), optional
        Global dofs to local ones, Nnl a multiple of element.dim.
    T : array_like of float, shape (N, Nnl), optional
        Local forces to global ones. Q and T both or neither (neither: U holds the element's
        own dim dofs, Nnl = N = dim, and the results are the element's with no product).
    exact : bool
        The exact path (Nt ignored) or the sampled one at N = Nt samples.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``element`` has no AFT (or exact=True for contact_3d); Q, T of other
        shapes, or one without the other.

    Notes
    -----
    :meth:`AFT.element` per element, the orders mapped by :func:`from_tmdsimpy`,
    :func:`to_tmdsimpy` and :func:`jacobian_to_tmdsimpy`. A workspace per (H, Nt) is kept.
    """

    def __init__(self, element, Q=None, T=None, exact=True):
        _aft_type(element, exact)
        self.element, self.exact = element, bool(exact)
        if (Q is None) != (T is None):
            raise refused("Q, T: give both or neither")
        if Q is None:
            self.Q = self.T = None
            self.nnl = self.ndof = element.dim
        else:
            self.Q = as_doubles(Q, "Q", ndim=2).copy()
            self.nnl, self.ndof = self.Q.shape
            self.T = as_doubles(T, "T", ndim=2).copy()
            if self.T.shape != (self.ndof, self.nnl):
                raise refused("T: shape %s; expected Q's transpose shape %s"
                              % (self.T.shape, (self.ndof, self.nnl)))
            if self.nnl == 0 or self.nnl % element.dim:
                raise refused("Q: %d local dofs are not a multiple of %s's %d"
                              % (self.nnl, element.name, element.dim))
        self._workspaces = {}

    def nl_force_type(self):
        """1: a hysteretic force (tmdsimpy's flag).

        Returns
        -------
        int
        """
        return 1

    def aft(self, U, w, h, Nt=128, tol=1e-7, calc_grad=True):
        """The harmonic force coefficients and their Jacobian, in tmdsimpy's order.

        Parameters
        ----------
        U : array_like of float, shape (N Nhc,)
            Global harmonic displacements, ``U[k N + d]`` = component k of dof d (components
            ``[a0, a_h1, b_h1, ...]`` over h).
        w : float
            The frequency (rad/s); the element is rate-independent, so it is not used.
        h : array_like of int
            Sorted list of harmonics, 0 first if present, max(h) <= 40.
        Nt : int
            Samples per period for exact=False (a power of two >= 2 max(h) + 2); ignored by
            the exact path.
        tol : float
            Not used: both paths give the periodic response itself (no march to converge).
        calc_grad : bool
            Return the gradients too.

        Returns
        -------
        Fnl : ndarray of float64, shape (N Nhc,)
            The force's coefficients, U's layout.
        dFnldU : ndarray of float64, shape (N Nhc, N Nhc)
            d Fnl / d U (only with calc_grad).
        dFnldw : ndarray of float64, shape (N Nhc,)
            Zeros: the AFT is rate-independent (only with calc_grad).
            With calc_grad=False the result is ``(Fnl,)``, as tmdsimpy's.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``U`` or ``h`` do not fit; ``Nt`` not an integer.
        fricreg.InputError, fricreg.Error
            From :class:`AFT` (max(h) or Nt out of range) and :meth:`AFT.element`.
        """
        h = _harmonics(h)
        H = max(1, int(h[-1]))
        samples = 0 if self.exact else as_integer(Nt, "Nt")
        key = (H, samples)
        if key not in self._workspaces:
            self._workspaces[key] = AFT(H, samples)
        aft, n, dim = self._workspaces[key], 2 * H + 1, self.element.dim
        nhc = 2 * h.size - (h[0] == 0)  # tmdsimpy's Nhc
        U = as_doubles(U, "U")
        if U.shape != (nhc * self.ndof,):
            raise refused("U: shape %s; expected (%d,) = (N Nhc,) for N = %d, h = %s"
                          % (U.shape, nhc * self.ndof, self.ndof, h.tolist()))
        local = U.reshape(nhc, self.ndof)
        if self.Q is not None:
            local = local @ self.Q.T
        coefficients = np.zeros(self.nnl * n)
        local_index = _index(h, self.nnl, n)
        coefficients[local_index] = local.ravel()
        coefficients = coefficients.reshape(self.nnl, n)
        force = np.empty((self.nnl, n))
        jac = np.zeros((self.nnl * n, self.nnl * n)) if calc_grad else None
        for e in range(0, self.nnl, dim):
            r = aft.element(self.element, coefficients[e:e + dim], self.exact, calc_grad)
            force[e:e + dim] = r.f
            if calc_grad:
                jac[e * n:(e + dim) * n, e * n:(e + dim) * n] = r.jac
        F = force.ravel()[local_index].reshape(nhc, self.nnl)
        Fnl = (F if self.T is None else F @ self.T.T).ravel()
        if not calc_grad:
            return (Fnl,)
        J = jac[np.ix_(local_index, local_index)]
        if self.Q is not None:  # kron(I, T) J kron(I, Q), one harmonic block at a time
            J = np.einsum("ai,kilj,jb->kalb", self.T, J.reshape(nhc, self.nnl, nhc, self.nnl),
                          self.Q, optimize=True).reshape(nhc * self.ndof, nhc * self.ndof)
        return Fnl, J, np.zeros(Fnl.size)
