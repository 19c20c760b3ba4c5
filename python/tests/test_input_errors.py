# SPDX-License-Identifier: GPL-3.0-or-later
"""Every public call refuses bad input with fricreg.InputError (a ValueError too), its message
naming the argument: a wrong shape, a wrong dtype, an unknown name, a non-physical value.
Each call is first made with valid arguments (it must pass), then once per bad argument."""
import numpy as np
import pytest

import fricreg

M = np.eye(2)
K = np.array([[2.0, -1.0], [-1.0, 2.0]])
C = 0.02 * K
J = np.array([[1.0, 0.0]])
U7 = np.zeros(7)  # AFT coefficients at H = 3


def call(function, **valid):
    """A call with valid arguments, and the same call with some of them replaced."""
    def make(**bad):
        return function(**dict(valid, **bad))
    return make


def method(factory, name, **valid):
    """A method's call on a fresh object (a call that changes its object, a run, changes no
    later one) with valid arguments, and the same call with some of them replaced."""
    def make(**bad):
        return getattr(factory(), name)(**dict(valid, **bad))
    return make


def hb(**kw):
    args = dict(M=M, K=K, C=C, elements=[("jenkins", J, [[2.0, 1.0]])], harmonics=3)
    args.update(kw)
    return fricreg.HarmonicBalance(args.pop("M"), args.pop("K"), args.pop("C"), **args)


def solved_hb():
    h = hb(excitation=([0.0, 1.0], None))
    h.backbone(0, 0.1, 1.0, 4)
    return h


def structure(**kw):
    args = dict(M=M, K=K, damping=C, J=J, mun=[0.5])
    args.update(kw)
    return fricreg.Structure(args.pop("M"), args.pop("K"), **args)


PARAMS6 = [1.0, 3000.0, -0.5, 0.1, 0.001, 3000.0]  # F_S, K_T, chi, beta, zeta0, K0
AMPLITUDES = [1e-4, 2e-4, 4e-4, 8e-4, 1.6e-3, 3.2e-3]
_F, _Z = fricreg.backbone(PARAMS6, AMPLITUDES)[:2]
LEVELS = dict(amplitude=AMPLITUDES, freq_hz=list(_F), zeta=list(_Z))

# (call's name, the call, [(argument, bad value), ...])
CASES = [
    ("law_eval", call(fricreg.law_eval, law="quinn", v=[0.1, 0.2, 0.3], f_eq=[0.2], mun=[1.0],
                      eps=1e-3),
     [("law", "nolaw"), ("mun", [1.0, 2.0]), ("v", ["a"]), ("eps", "small"),
      ("eps", -1.0), ("mun", [np.nan])]),
    ("segalman", call(fricreg.segalman, ns=8, fs=1.0, kt=1.0, chi=-0.5, beta=0.1,
                      resolution=0.01),
     [("ns", 0), ("ns", 2.5), ("ns", "8"), ("fs", -1.0), ("chi", 2.0), ("resolution", np.nan)]),
    ("Element", call(fricreg.Element, name="jenkins", params=[20.0, 1.0]),
     [("name", "nosuch"), ("name", 3), ("params", [20.0]), ("params", ["a", "b"]),
      ("params", [-1.0, 1.0])]),
    ("Element.eval", call(fricreg.Element("jenkins", [20.0, 1.0]).eval, u=[0.1], state=[0.0]),
     [("u", [[0.1, 0.2]]), ("u", ["x"]), ("state", [0.0, 0.0]), ("u", [np.inf])]),
    ("Element.init", call(fricreg.Element("jenkins", [20.0, 1.0]).init, npoints=3),
     [("npoints", -1), ("npoints", 2.5), ("npoints", "3")]),
    ("AFT", call(fricreg.AFT, harmonics=3, samples=0),
     [("harmonics", 0), ("harmonics", 2.5), ("harmonics", "3"), ("samples", -4)]),
    ("AFT.jenkins", call(fricreg.AFT(3).jenkins, kt=20.0, mun=1.0, u=U7),
     [("kt", -1.0), ("kt", "k"), ("u", np.zeros(6)), ("u", U7.astype(complex)),
      ("mun", np.nan)]),
    ("AFT.iwan", call(fricreg.AFT(3).iwan, k=[1.0, 2.0], phi=[0.1, 0.2], u=U7),
     [("phi", [0.1]), ("k", [-1.0, 2.0]), ("u", np.zeros(5))]),
    ("AFT.element", call(fricreg.AFT(3).element, element=fricreg.Element("jenkins", [2.0, 1.0]),
                         coefficients=U7),
     [("element", "jenkins"), ("coefficients", np.zeros(6))]),
    ("Context", call(fricreg.Context, m=2, W=K, mun=[1.0, 1.0]),
     [("m", 0), ("m", 2.5), ("W", np.eye(3)), ("mun", [1.0, -1.0]), ("law", "nolaw"),
      ("partition", "nosuch"), ("eps", -1.0)]),
    ("Context.eval", call(fricreg.Context(2, W=K, mun=[1.0, 1.0]).eval, zdot=[0.1, 0.0],
                          a_free=[0.0, 0.0]),
     [("zdot", [0.1]), ("zdot", ["a", "b"]), ("a_free", [np.nan, 0.0])]),
    ("HarmonicBalance", hb,
     [("M", np.eye(3)), ("M", -M), ("K", np.array([[2.0, -1.0], [-0.5, 2.0]])),
      ("C", [["a", "b"], ["c", "d"]]), ("elements", []), ("elements", [("nosuch", J, [[1.0]])]),
      ("elements", [("jenkins", np.ones((1, 3)), [[2.0, 1.0]])]), ("harmonics", 0),
      ("harmonics", 7.5), ("harmonics", "3"), ("rayleigh", (0.1, 0.01))]),
    ("HarmonicBalance.solve", method(lambda: hb(excitation=([0.0, 1.0], None)), "solve",
                                     omega=1.0),
     [("omega", -1.0), ("omega", "1"), ("guess", np.zeros(3))]),
    ("HarmonicBalance.backbone", call(hb().backbone, mode=0, a0=0.1, a1=1.0, npoints=4),
     [("mode", 5), ("a0", -0.1), ("npoints", 1), ("damping", "nosuch"), ("mode", 0.5)]),
    ("HarmonicBalance.backbone_at", call(hb().backbone_at, mode=0, amplitudes=[0.1, 0.2]),
     [("amplitudes", [0.2, 0.1]), ("amplitudes", [[0.1]]), ("damping", "x")]),
    ("HarmonicBalance.backbone_sensitivities",
     call(solved_hb().backbone_sensitivities, point=1, params=[("element", 0, 1, 0)]),
     [("point", 99), ("params", [("stiffness", 0)]), ("params", [("element", 0, 1)])]),
    ("HarmonicBalance.set_continuation", call(hb().set_continuation, ds=0.02),
     [("ds", -1.0), ("max_points", 1), ("ds_min", "x")]),
    ("HarmonicBalance.set_newton", call(hb().set_newton, tol=1e-10, max_iter=50),
     [("tol", 2.0), ("max_iter", 0), ("max_iter", 2.5)]),
    ("HarmonicBalance.set_stability", call(hb().set_stability, enable=True, method="auto"),
     [("method", "nosuch")]),
    ("HarmonicBalance.set_excitation", call(hb().set_excitation, pc=[0.0, 1.0]),
     [("pc", [1.0]), ("pc", [np.nan, 1.0])]),
    ("HarmonicBalance.set_element_param",
     call(hb().set_element_param, first=0, count=1, index=0, value=3.0),
     [("index", 5), ("value", -1.0), ("first", 1), ("count", 0.5)]),
    ("Structure", structure,
     [("M", np.eye(3)), ("M", -M), ("mun", [-1.0]), ("J", np.ones((1, 3))), ("law", "nosuch"),
      ("contact_solver", "nosuch"), ("error_estimate", "nosuch"),
      ("error_companions", "nosuch"), ("u0", [0.0])]),
    ("Structure.run", method(structure, "run", dt=1e-3, t_end=1e-2),
     [("integrator", "nosuch"), ("dt", -1.0), ("t_end", "x"), ("output_dofs", [5])]),
    ("Structure.restore", method(structure, "restore", data=structure().save()),
     [("data", b"not a checkpoint"), ("data", 12), ("integrator", "nosuch")]),
    ("backbone", call(fricreg.backbone, params=PARAMS6, amplitude=[0.1, 0.2]),
     [("params", PARAMS6[:5]), ("amplitude", [-0.1]), ("kind", "nosuch"), ("sensor", "s")]),
    ("fit_backbone", call(fricreg.fit_backbone, kind="displacement", **LEVELS),
     [("amplitude", [0.1]), ("zeta", LEVELS["zeta"][:5]), ("kind", "nosuch"),
      ("x0", {"nosuch": 1.0}), ("starts", 0), ("fixed", {"FS": -1.0})]),
    ("to_tmdsimpy", call(fricreg.to_tmdsimpy, coefficients=U7, h=[0, 1, 2, 3]),
     [("h", [1, 0]), ("h", [0, 5]), ("coefficients", np.zeros(6))]),
    ("from_tmdsimpy", call(fricreg.from_tmdsimpy, U=np.zeros(7), h=[0, 1, 2, 3]),
     [("U", np.zeros(5)), ("ndof", 0)]),
    ("TmdsimpyForce", call(fricreg.TmdsimpyForce,
                           element=fricreg.Element("jenkins", [2.0, 1.0])),
     [("element", "jenkins"), ("Q", np.eye(2))]),
    ("HarmonicBalance.frequency_response",
     method(lambda: hb(excitation=([0.0, 1.0], None)), "frequency_response", omega0=0.5,
            omega1=0.6),
     [("omega0", -1.0), ("omega1", "x"), ("guess", np.zeros(2))]),
    ("HarmonicBalance.level_response",
     method(lambda: hb(excitation=([0.0, 1.0], None)), "level_response", omega=1.0, level0=0.1,
            level1=0.2),
     [("omega", np.nan), ("level0", -1.0), ("level1", [1.0, 2.0])]),
    ("HarmonicBalance.peak", method(lambda: _swept(), "peak", dof=1),
     [("dof", 7), ("dof", 1.0)]),
    ("HarmonicBalance.modal_participation",
     method(solved_hb, "modal_participation", point=1, harmonic=1),
     [("point", 99), ("harmonic", 9), ("harmonic", "1")]),
    ("HarmonicBalance.element_param", method(hb, "element_param", element=0, index=0),
     [("element", 3), ("index", 9), ("element", 0.0)]),
    ("FitResult.curve", method(lambda: fricreg.fit_backbone(kind="displacement", **LEVELS),
                               "curve", amplitude=[1e-4, 2e-4]),
     [("amplitude", [[1e-4]]), ("amplitude", [-1e-4]), ("amplitude", ["a"])]),
    ("to_pyharm", call(fricreg.to_pyharm, coefficients=U7), [("coefficients", np.zeros(6))]),
    ("from_pyharm", call(fricreg.from_pyharm, x=np.zeros(7)),
     [("x", np.zeros(6)), ("ndof", 0), ("ndof", "1")]),
    ("jacobian_to_tmdsimpy", call(fricreg.jacobian_to_tmdsimpy, jacobian=np.zeros((7, 7)),
                                  h=[0, 1, 2, 3]),
     [("jacobian", np.zeros((6, 6))), ("h", [3, 1])]),
    ("jacobian_to_pyharm", call(fricreg.jacobian_to_pyharm, jacobian=np.zeros((7, 7))),
     [("jacobian", np.zeros((7, 6))), ("ndof", -1)]),
    ("TmdsimpyForce.aft", method(lambda: fricreg.TmdsimpyForce(
        fricreg.Element("jenkins", [2.0, 1.0])), "aft", U=np.zeros(7), w=1.0, h=[0, 1, 2, 3]),
     [("U", np.zeros(5)), ("h", [2, 1])]),
    ("Context.set_law", method(lambda: fricreg.Context(2, W=K, mun=[1.0, 1.0]), "set_law",
                               law="karnopp"),
     [("law", "nosuch"), ("eps", -1.0)]),
    ("Context.set_bounds", method(lambda: fricreg.Context(2), "set_bounds", mun=[0.5, 1.0]),
     [("mun", [0.5]), ("mun", [0.5, -1.0]), ("mun", "0.5"), ("mun", [np.nan, 1.0])]),
    ("Context.set_coupling", method(lambda: fricreg.Context(2), "set_coupling", W=K),
     [("W", np.eye(3)), ("W", [[1.0, 2.0], [2.0, 1.0]]), ("W", [0.0, 1.0]), ("W", [["a"]])]),
    ("Context.set_partition", method(lambda: fricreg.Context(2), "set_partition",
                                     partition="paper"),
     [("partition", "nosuch"), ("partition", 1)]),
    ("Context.set_keep_tangent", method(lambda: fricreg.Context(2), "set_keep_tangent",
                                        keep=False),
     [("keep", "no"), ("keep", 2), ("keep", None)]),
    ("Structure.set_law", method(structure, "set_law", law="tanh", eps=2e-3),
     [("law", "nosuch"), ("eps", 0.0), ("eps", "small"), ("eps", np.inf)]),
    ("Structure.set_bounds", method(structure, "set_bounds", mun=[0.3]),
     [("mun", [0.3, 0.4]), ("mun", [-0.3]), ("mun", ["a"]), ("mun", np.nan)]),
]


def _swept():
    h = hb(excitation=([0.0, 1.0], None))
    h.frequency_response(0.5, 0.6)
    return h


def refusal(make, argument, value):
    """What is wrong with the call's answer to one bad argument, or None."""
    try:
        make(**{argument: value})
    except fricreg.InputError as error:
        if not isinstance(error, ValueError):
            return "an InputError that is no ValueError"
        if argument not in str(error):
            return "the message %r does not name %s" % (str(error), argument)
        return None
    except Exception as error:  # noqa: BLE001: what escapes is the finding
        return "%s: %s" % (type(error).__name__, error)
    return "accepted"


@pytest.mark.parametrize("name, make, bad", CASES, ids=[c[0] for c in CASES])
def test_every_public_call_refuses_bad_input_as_input_error(name, make, bad):
    make()  # valid: must pass
    wrong = ["%s(%s=%r): %s" % (name, argument, value, refusal(make, argument, value))
             for argument, value in bad if refusal(make, argument, value) is not None]
    assert not wrong, "\n".join(wrong)
