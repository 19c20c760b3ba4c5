# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg.Context against the C library's context called directly (fricreg_ctx_*) bit for bit,
the closed forms of tests/ctx/test_context.c and tests/structure/test_contact_step.c (the README's
two blocks, the diagonal coupling, the paper's partition, the step of one contact into a stop),
dense against sparse W, and every error path."""
import ast
import os
import subprocess
import sys

import numpy as np
import pytest

import fricreg
from fricreg._fricreg import ffi, lib

W2B = np.array([[1.0, -1.0], [-1.0, 2.0]])  # the paper's two blocks (README, quickstart.c)
MUN2B = np.array([0.5, 0.25])
EPS2B = 0.02


def dbl(array):
    """A double[] view of a float64 array for a direct C call."""
    return ffi.from_buffer("double[]", np.ascontiguousarray(array, dtype=np.float64))


def i64(array):
    """An int64_t[] view of an index array for a direct C call."""
    return ffi.from_buffer("int64_t[]", np.ascontiguousarray(array, dtype=np.int64))


def c_context(m, law, eps, mun, W, partition=1):
    """A context made by the C calls alone: W of shape (m,) diagonal, (m, m) dense, or a
    scipy CSR/CSC matrix."""
    out = ffi.new("fricreg_ctx **")
    assert lib.fricreg_ctx_create(m, out) == 0
    ctx = ffi.gc(out[0], lib.fricreg_ctx_free)
    assert lib.fricreg_ctx_set_law(ctx, lib.fricreg_law_from_name(law.encode()), eps) == 0
    assert lib.fricreg_ctx_set_partition(ctx, partition) == 0
    if hasattr(W, "tocsr"):
        setter = lib.fricreg_ctx_set_coupling_csc if W.format == "csc" \
            else lib.fricreg_ctx_set_coupling_csr
        status = setter(ctx, m, 0, i64(W.indptr), i64(W.indices), dbl(W.data))
    elif np.ndim(W) == 1:
        status = lib.fricreg_ctx_set_coupling_diagonal(ctx, m, dbl(W))
    else:
        status = lib.fricreg_ctx_set_coupling_dense(ctx, m, dbl(W))
    assert status == 0, ffi.string(lib.fricreg_ctx_errmsg(ctx))
    assert lib.fricreg_ctx_set_bounds(ctx, m, dbl(mun)) == 0
    return ctx


def c_eval(ctx, m, zdot, a_free):
    """fricreg_ctx_eval: (f, f_eq)."""
    f, f_eq = np.empty(m), np.empty(m)
    assert lib.fricreg_ctx_eval(ctx, m, dbl(zdot), dbl(a_free), dbl(f), dbl(f_eq)) == 0
    return f, f_eq


def banded_spd(m, rng, band=1):
    """A symmetric, diagonally dominant (so positive definite) banded matrix, exact zeros
    outside the band."""
    A = np.zeros((m, m))
    for k in range(1, band + 1):
        off = rng.uniform(-0.4, 0.4, m - k)
        A += np.diag(off, k) + np.diag(off, -k)
    return A + np.diag(rng.uniform(1.0, 2.0, m) + np.abs(A).sum(axis=1))


def test_readme_two_blocks_at_rest():
    # W f_eq = -a_free: f_eq = W^-1 (0.1, -0.05) = [[2, 1], [1, 1]] (0.1, -0.05) = (0.15, 0.05)
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B)
    zdot, a_free = np.zeros(2), np.array([-0.1, 0.05])
    f, f_eq = ctx.eval(zdot, a_free)
    np.testing.assert_allclose(f, [0.15, 0.05], rtol=1e-14)
    np.testing.assert_allclose(f_eq, [0.15, 0.05], rtol=1e-14)
    cf, cf_eq = c_eval(c_context(2, "quinn", EPS2B, MUN2B, W2B), 2, zdot, a_free)
    assert f.tobytes() == cf.tobytes() and f_eq.tobytes() == cf_eq.tobytes()
    assert (ctx.m, ctx.law, ctx.eps, ctx.partition) == (2, "quinn", EPS2B, "consistent")


def test_defaults_and_diagonal_closed_forms():
    # tests/ctx/test_context.c defaults_quinn_unit_bounds_identity: law (4), eps 1e-3, mun 1, W = I
    f, f_eq = fricreg.Context(3).eval([0.00013, -0.0002, 0.0031], [0.37, -0.81, 2.2])
    np.testing.assert_allclose(f, [-0.63, 1.0, -1.0], rtol=1e-12)
    np.testing.assert_allclose(f_eq[:2], [-0.37, 0.81], rtol=1e-14)
    assert np.isnan(f_eq[2])  # slip: f_eq not computed
    # diagonal_coupling_divides: W = diag(2.385, 0.731, 1.913), eps = 0.0731
    ctx = fricreg.Context(W=[2.385, 0.731, 1.913], mun=[0.9, 0.35, 1.2], eps=0.0731)
    f, f_eq = ctx.eval([0.0104, -0.0402, -0.0873], [-0.617, 0.5117, 4.4])
    np.testing.assert_allclose(f, [0.0026126583440162668, 0.034952120383036939, 1.2],
                               rtol=1e-12)
    np.testing.assert_allclose(f_eq[:2], [0.25870020964360585, -0.7], rtol=1e-14)


def test_partitions_two_blocks_closed_forms():
    # test_context.c: paper (-0.264, 0.2115) from the joint f_eq = (-0.079, 0.134);
    # consistent (-0.294, 0.104) from the QP, f_eq given the other's actual force
    zdot, a = [0.0037, -0.0031], [0.213, -0.347]
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B, partition="paper")
    f, f_eq = ctx.eval(zdot, a)
    np.testing.assert_allclose(f, [-0.264, 0.2115], atol=1e-14)
    np.testing.assert_allclose(f_eq, [-0.079, 0.134], atol=1e-14)
    ctx.set_partition("consistent")
    f, f_eq = ctx.eval(zdot, a)
    np.testing.assert_allclose(f, [-0.294, 0.104], atol=1e-14)
    np.testing.assert_allclose(f_eq, [-0.109, 0.0265], atol=1e-14)
    # each f_i is law (4) at (zdot_i, f_eq,i): the consistent fixed point
    np.testing.assert_allclose(f, fricreg.law_eval("quinn", zdot, f_eq, MUN2B, EPS2B), atol=1e-15)


@pytest.mark.parametrize("law", fricreg.LAWS)
@pytest.mark.parametrize("partition", fricreg.PARTITIONS)
@pytest.mark.parametrize("kind", ["diagonal", "dense"])
def test_each_law_equals_the_c_call(law, partition, kind):
    rng = np.random.default_rng(7)
    m, eps = 6, 0.05
    W = banded_spd(m, rng, band=2)
    W = np.diag(W).copy() if kind == "diagonal" else W
    mun = rng.uniform(0.3, 1.2, m)
    ctx = fricreg.Context(W=W, mun=mun, law=law, eps=eps, partition=partition)
    cctx = c_context(m, law, eps, mun, W, fricreg.PARTITIONS.index(partition) + 1)
    for _ in range(5):
        zdot = rng.uniform(-2 * eps, 2 * eps, m)
        zdot[rng.integers(m)] = 0.0  # force balance's near-stick set
        a_free = rng.uniform(-1.5, 1.5, m)
        f, f_eq = ctx.eval(zdot, a_free)
        cf, cf_eq = c_eval(cctx, m, zdot, a_free)
        assert f.tobytes() == cf.tobytes() and f_eq.tobytes() == cf_eq.tobytes()
        assert np.all(np.abs(f) <= mun)
        jz, ja = ctx.tangent()
        cz, ca = np.empty((m, m)), np.empty((m, m))
        assert lib.fricreg_ctx_tangent(cctx, m, dbl(cz), dbl(ca)) == 0
        assert jz.tobytes() == cz.tobytes() and ja.tobytes() == ca.tobytes()
        g = ctx.switching(zdot, a_free, f)
        cg = np.empty(7 * m)
        assert lib.fricreg_ctx_switching(cctx, m, dbl(zdot), dbl(a_free), dbl(f), dbl(cg),
                                         7 * m) == 0
        assert g.shape == (m, 7) and g.tobytes() == cg.tobytes()


def test_quinn_at_rest_is_the_force_balance():
    # Law (4) at zdot = 0 equals (2): diagonal W contact by contact, f = mun sat(f_eq/mun) with
    # f_eq = -a_free/w; coupled W (consistent), Coulomb's stick problem: the same QP with c = 0
    rng = np.random.default_rng(5)
    m = 7
    w, mun, zdot = rng.uniform(0.5, 2.0, m), rng.uniform(0.3, 1.0, m), np.zeros(m)
    a_free = rng.uniform(-2.0, 2.0, m)
    f, f_eq = fricreg.Context(W=w, mun=mun, eps=0.0731).eval(zdot, a_free)
    assert f.tobytes() == fricreg.law_eval("force-balance", zdot, f_eq, mun, 0.0731).tobytes()
    np.testing.assert_allclose(f, np.clip(-a_free / w, -mun, mun), rtol=1e-15)
    W = banded_spd(m, rng)
    quinn, _ = fricreg.Context(W=W, mun=mun, eps=0.0731).eval(zdot, a_free)
    balance, _ = fricreg.Context(W=W, mun=mun, law="force-balance").eval(zdot, a_free)
    np.testing.assert_allclose(quinn, balance, atol=1e-14)
    small = 1e-3 * a_free  # nothing saturates: one solve, W f = -a_free
    quinn, _ = fricreg.Context(W=W, mun=mun).eval(zdot, small)
    np.testing.assert_allclose(W @ quinn, -small, atol=1e-16)


def test_tangent_closed_form_and_apply():
    # both contacts at rest and free: f = -W^-1 (a_free + diag(W) 2 zdot mun/eps), so
    # df/da_free = -W^-1 = -[[2, 1], [1, 1]], df/dzdot = -W^-1 diag(2 W_ii mun_i/eps) (50, 50)
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B)
    ctx.eval([0.0, 0.0], [-0.1, 0.05])
    df_dzdot, df_dafree = ctx.tangent()
    np.testing.assert_allclose(df_dafree, [[-2.0, -1.0], [-1.0, -1.0]], rtol=1e-14)
    np.testing.assert_allclose(df_dzdot, [[-100.0, -50.0], [-50.0, -50.0]], rtol=1e-14)
    d1, d2 = np.array([0.3, -0.7]), np.array([1.1, 0.4])
    np.testing.assert_allclose(ctx.tangent_apply(d1, d2), df_dzdot @ d1 + df_dafree @ d2,
                               rtol=1e-14)
    np.testing.assert_allclose(ctx.tangent_apply(dafree=d2), df_dafree @ d2, rtol=1e-14)
    np.testing.assert_allclose(ctx.tangent_apply(d1), df_dzdot @ d1, rtol=1e-14)
    assert ctx.stick_stiffness() == 50.0  # max_i W_ii 2 mun_i/eps = max(50, 50)


def test_stats_and_keep_tangent():
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B)
    ctx.eval([0.0037, -0.0031], [0.213, -0.347])
    ctx.eval([0.0037, -0.0031], [0.213, -0.347])  # the factor is reused
    stats = ctx.stats(reset=True)
    assert (stats["evals"], stats["factorizations"], stats["qp_iterations"]) == (2, 1, 2)
    assert ctx.stats()["evals"] == 0
    ctx.set_keep_tangent(False)
    ctx.eval([0.0, 0.0], [0.1, 0.1])
    with pytest.raises(fricreg.InputError,
                       match=r"Context.tangent: .*inputs are not kept \(set_keep_tangent 0\)"):
        ctx.tangent()
    assert not ctx.keep_tangent


@pytest.mark.parametrize("kind", ["csr", "csc", "coo", "lil"])
def test_sparse_W_gives_the_dense_forces(kind):
    sparse = pytest.importorskip("scipy.sparse")
    rng = np.random.default_rng(23)
    m, eps = 9, 0.02
    W = banded_spd(m, rng, band=2)
    mun = rng.uniform(0.3, 1.0, m)
    dense = fricreg.Context(W=W, mun=mun, eps=eps)
    given = getattr(sparse, kind + "_matrix")(W)
    ctx = fricreg.Context(W=given, mun=mun, eps=eps)
    assert ctx.W.format == ("csc" if kind == "csc" else "csr")
    np.testing.assert_array_equal(ctx.W.toarray(), W)
    csr = sparse.csr_matrix(W)
    cctx = c_context(m, "quinn", eps, mun, csr)
    for _ in range(20):  # a walk whose near-stick set changes
        zdot, a_free = rng.uniform(-1.5 * eps, 1.5 * eps, m), rng.uniform(-1.0, 1.0, m)
        f, f_eq = ctx.eval(zdot, a_free)
        cf, cf_eq = c_eval(cctx, m, zdot, a_free)  # CSC of a symmetric W: CSR's arrays
        assert f.tobytes() == cf.tobytes() and f_eq.tobytes() == cf_eq.tobytes()
        fd, fd_eq = dense.eval(zdot, a_free)  # the dense path's forces, to rounding
        np.testing.assert_allclose(f, fd, atol=1e-12)
        np.testing.assert_allclose(f_eq, fd_eq, atol=1e-12)
        np.testing.assert_allclose(ctx.tangent_apply(zdot, a_free),
                                   dense.tangent_apply(zdot, a_free), rtol=1e-10, atol=1e-10)


def test_step_of_one_contact_into_a_stop():
    # tests/structure/test_contact_step.c plain_newton_cycles: W = 2, W_eff = 1, c = 0.005, eps =
    # 1e-3, zdot_pred = 0, a_pred = 0.3, guess f = -1. Inside the band, with zdot = c W_eff f and
    # f_eq = -(a_pred - (W - W_eff) f)/W = (f - 0.3)/2: f = -(2/eps)(zdot - (eps/2) f_eq)
    # = -10 f + 0.5 (f - 0.3), so f = -0.15/10.5 = -1/70. Plain Newton 2-cycles between +-1.
    ctx = fricreg.Context(W=[2.0], eps=1e-3)
    guess = np.array([-1.0])
    step = ctx.solve_step([0.001], [0.0], [0.3], [[1.0]], 0.005, 1e-12, f=guess)
    assert step.converged and step.iterations <= 3
    np.testing.assert_allclose(step.f, [-1.0 / 70.0], rtol=1e-12)
    assert guess[0] == -1.0  # the guess is not modified
    plain = ctx.solve_step([0.001], [0.0], [0.3], [[1.0]], 0.005, 1e-12, f=guess, plain=True)
    assert not plain.converged and plain.iterations == 50 and abs(plain.f[0]) == 1.0


def random_step(rng, m, eps):
    """One random step's inputs (test_contact_step.c random_steps): W and W_eff banded SPD,
    W_eff << W, velocities around the band."""
    W, Weff = banded_spd(m, rng), 0.05 * banded_spd(m, rng)
    z0 = eps * rng.uniform(-3.0, 3.0, m)
    return W, Weff, z0, z0 + eps * rng.uniform(-2.0, 2.0, m), rng.uniform(-1.5, 1.5, m)


def c_solve_step(ctx, m, z0, zp, ap, W, Weff, c, tol, f):
    """fricreg_ctx_solve_step (the dense entry): (f, iterations, converged)."""
    f, info = f.copy(), ffi.new("int[2]")
    assert lib.fricreg_ctx_solve_step(ctx, m, dbl(z0), dbl(zp), dbl(ap), dbl(W), dbl(Weff),
                                      c, tol, 50, 0, dbl(f), info) == 0
    return f, info[0], info[1]


@pytest.mark.parametrize("law", ["quinn", "tanh"])
def test_solve_step_equals_the_c_call_and_solves_the_step(law):
    rng = np.random.default_rng(2385)
    m, eps, c, tol = 6, 1e-3, 0.005, 1e-10
    for _ in range(10):
        W, Weff, z0, zp, ap = random_step(rng, m, eps)
        mun = rng.uniform(0.5, 1.5, m)
        guess = mun * rng.uniform(-1.0, 1.0, m)
        ctx = fricreg.Context(W=W, mun=mun, law=law, eps=eps)
        inputs = [a.copy() for a in (W, Weff, z0, zp, ap, guess)]
        step = ctx.solve_step(z0, zp, ap, Weff, c, tol, f=guess)
        for before, after in zip(inputs, (W, Weff, z0, zp, ap, guess)):
            assert before.tobytes() == after.tobytes()
        cf, iterations, converged = c_solve_step(
            c_context(m, law, eps, mun, W), m, z0, zp, ap, W, Weff, c, tol, guess)
        assert step.f.tobytes() == cf.tobytes()
        assert (step.iterations, step.converged) == (iterations, True)
        # the forces are the law at the step's end: f = F(zp + c Weff f, ap - (W - Weff) f)
        F, _ = ctx.eval(zp + c * Weff @ step.f, ap - (W - Weff) @ step.f)
        assert np.max(np.abs(step.f - F)) <= 2 * tol


@pytest.mark.parametrize("kind", ["csr", "csc", "coo"])
def test_solve_step_sparse_equals_dense(kind):
    sparse = pytest.importorskip("scipy.sparse")
    rng = np.random.default_rng(31)
    m, eps, c, tol = 8, 1e-3, 0.005, 1e-10
    for coupled in (True, False):
        W, Weff, z0, zp, ap = random_step(rng, m, eps)
        W = W if coupled else np.diag(W).copy()
        mun = rng.uniform(0.5, 1.5, m)
        dense = fricreg.Context(W=W, mun=mun, eps=eps).solve_step(z0, zp, ap, Weff, c, tol)
        # the context's W dense or sparse, W_eff sparse: the dense call's forces, bit for bit
        for W_ctx in (W, sparse.csr_matrix(W) if coupled else W):
            ctx = fricreg.Context(W=W_ctx, mun=mun, eps=eps)
            step = ctx.solve_step(z0, zp, ap, getattr(sparse, kind + "_matrix")(Weff), c, tol)
            assert step.f.tobytes() == dense.f.tobytes()
            assert (step.iterations, step.converged) == (dense.iterations, dense.converged)


def test_no_scipy_without_sparse_input():
    tree = ast.parse(open(fricreg.context.__file__, encoding="utf-8").read())
    top = [node for node in tree.body if isinstance(node, (ast.Import, ast.ImportFrom))]
    assert not any("scipy" in ast.dump(node) for node in top)
    # dense and diagonal paths run with scipy made unimportable
    code = ("import sys, numpy as np, fricreg\n"
            "sys.modules['scipy'] = sys.modules['scipy.sparse'] = None\n"
            "ctx = fricreg.Context(W=[[1.0, -1.0], [-1.0, 2.0]], mun=[0.5, 0.25])\n"
            "ctx.eval([0, 0], [0.1, 0.2])\n"
            "ctx.solve_step([0, 0], [0, 0], [0.1, 0.2], 0.1 * np.eye(2), 0.005, 1e-10)\n"
            "fricreg.Context(W=[2.0, 3.0]).solve_step([0, 0], [0, 0], [1, 1], np.eye(2), 1, 1)\n"
            "print('ok')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=dict(os.environ), check=False)
    assert out.stdout.strip() == "ok", out.stderr


def test_failed_setters_keep_the_settings():
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B, law="karnopp")
    before = ctx.eval([0.0037, -0.0031], [0.213, -0.347])
    bad_W, bad_mun = np.array([[1.0, -1.0], [-0.5, 2.0]]), np.array([0.5, -0.25])
    # each method refuses with an InputError naming its argument, and changes nothing
    for call, argument in ((lambda: ctx.set_coupling(bad_W), "W"),
                           (lambda: ctx.set_coupling(np.eye(3)), "W"),
                           (lambda: ctx.set_bounds(bad_mun), "mun"),
                           (lambda: ctx.set_bounds("0.5"), "mun"),
                           (lambda: ctx.set_law("karnopp", 0.0), "eps"),
                           (lambda: ctx.set_law("coulomb", [0.1, 0.2]), "eps"),
                           (lambda: ctx.set_law("dahl", 0.1), "law"),
                           (lambda: ctx.set_partition("joint"), "partition"),
                           (lambda: ctx.set_keep_tangent("no"), "keep"),
                           (lambda: ctx.set_keep_tangent(2), "keep")):
        with pytest.raises(fricreg.InputError, match=r"(^|: )%s: " % argument):
            call()
    assert (ctx.law, ctx.eps, ctx.partition, ctx.keep_tangent) == ("karnopp", EPS2B,
                                                                   "consistent", True)
    assert ctx.W.tobytes() == W2B.tobytes() and ctx.mun.tobytes() == MUN2B.tobytes()
    assert bad_W[1, 0] == -0.5 and bad_mun[1] == -0.25  # inputs never modified
    after = ctx.eval([0.0037, -0.0031], [0.213, -0.347])
    assert before[0].tobytes() == after[0].tobytes()
    ctx.set_bounds(0.5)  # a scalar for every contact
    assert ctx.mun.tolist() == [0.5, 0.5]
    mun = np.array([0.3, 0.4])
    ctx.set_bounds(mun)
    mun[0] = 7.0  # the context keeps its own copy
    assert ctx.mun.tolist() == [0.3, 0.4]
    ctx.W[0, 0] = 9.0  # a copy
    assert ctx.W[0, 0] == 1.0


def test_set_methods_set_what_the_properties_read():
    ctx = fricreg.Context(2)
    ctx.set_law("tanh", 0.0273)
    ctx.set_law(3)  # a code; eps kept
    ctx.set_bounds([0.61, 0.29])
    ctx.set_coupling(W2B)
    ctx.set_partition("paper")
    ctx.set_keep_tangent(False)
    assert (ctx.law, ctx.eps, ctx.partition, ctx.keep_tangent) == (fricreg.LAWS[2], 0.0273,
                                                                   "paper", False)
    assert ctx.mun.tolist() == [0.61, 0.29] and ctx.W.tobytes() == W2B.tobytes()
    ctx.set_keep_tangent(np.bool_(True))
    assert ctx.keep_tangent is True
    # the context's forces are the C library's with the same settings
    zdot, a_free = [0.0037, -0.0031], [0.213, -0.347]
    cf, cf_eq = c_eval(c_context(2, fricreg.LAWS[2], 0.0273, [0.61, 0.29], W2B,
                                 lib.FRICREG_PARTITION_PAPER), 2,
                       zdot, a_free)
    assert ctx.eval(zdot, a_free)[0].tobytes() == cf.tobytes()
    with pytest.raises(AttributeError):
        ctx.m = 3  # fixed at construction
    assert ctx.m == 2


@pytest.mark.parametrize("name, value, method", [
    ("law", "coulomb", "set_law"), ("eps", 0.0273, "set_law"),
    ("mun", [0.61, 0.29], "set_bounds"), ("W", [[2.0, 0.5], [0.5, 1.0]], "set_coupling"),
    ("partition", "paper", "set_partition"), ("keep_tangent", False, "set_keep_tangent")])
def test_assigning_a_setting_warns_and_still_sets_it(name, value, method):
    ctx = fricreg.Context(2)
    with pytest.warns(DeprecationWarning, match=r"Context: setting %s by assignment is "
                      r"deprecated and will end in 2.0 .*: call %s\(" % (name, method)) as record:
        setattr(ctx, name, value)
    assert record[0].filename == __file__  # the warning points at the assignment
    read = getattr(ctx, name)
    assert (read.tolist() if isinstance(read, np.ndarray) else read) == value
    if name == "keep_tangent":
        return  # as in 1.8, any value is taken for its truth
    with pytest.warns(DeprecationWarning), pytest.raises(fricreg.InputError):
        setattr(ctx, name, "bad")  # refused by the method, which keeps the setting
    read = getattr(ctx, name)
    assert (read.tolist() if isinstance(read, np.ndarray) else read) == value


def test_errors_name_the_argument():
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B)
    with pytest.raises(fricreg.InputError,
                       match=r"set_coupling: W: .*W\[0\]\[1\] = -1 but") as info:
        fricreg.Context(W=[[1.0, -1.0], [-0.5, 2.0]])
    assert info.value.status == lib.FRICREG_ENOTSYM
    with pytest.raises(fricreg.InputError, match="set_coupling: W: .*not semidefinite") as info:
        ctx.set_coupling([[1.0, -2.0], [-2.0, 2.0]])
    assert info.value.status == lib.FRICREG_ENOTPSD
    with pytest.raises(fricreg.InputError, match="set_coupling: W: .*not finite"):
        ctx.set_coupling([[1.0, np.nan], [np.nan, 2.0]])
    with pytest.raises(fricreg.InputError, match=r"set_coupling: W: .*w\[1\] = -1 must be > 0"):
        ctx.set_coupling([1.0, -1.0])
    with pytest.raises(ValueError, match=r"W: shape \(3, 3\); expected \(2,\) \(diagonal\)"):
        ctx.set_coupling(np.eye(3))
    with pytest.raises(fricreg.InputError, match=r"set_bounds: mun: .*mun\[1\] = -1 is negative"):
        ctx.set_bounds([1.0, -1.0])
    with pytest.raises(ValueError, match=r"mun: shape \(3,\); expected \(2,\)"):
        ctx.set_bounds([1.0, 1.0, 1.0])
    with pytest.raises(fricreg.InputError, match="Context.set_law: .*eps = 0 must be >= DBL_MIN"):
        ctx.set_law(ctx.law, 0.0)
    with pytest.raises(fricreg.InputError, match="Context.set_law: .*eps is not finite"):
        ctx.set_law(ctx.law, np.inf)
    with pytest.raises(ValueError, match="law: 'dahl' is not a law"):
        fricreg.Context(2, law="dahl")
    with pytest.raises(ValueError, match="partition: 'joint' is not a partition"):
        fricreg.Context(2, partition="joint")
    with pytest.raises(fricreg.InputError, match="Context: m = 0"):
        fricreg.Context(0)
    with pytest.raises(ValueError, match="m: not given"):
        fricreg.Context()
    with pytest.raises(fricreg.InputError, match=r"Context.eval: .*zdot\[1\] is not finite") \
            as info:
        ctx.eval([0.0, np.nan], [0.0, 0.0])
    assert info.value.status == lib.FRICREG_ENONFINITE
    with pytest.raises(fricreg.InputError, match=r"Context.eval: .*a_free\[0\] is not finite"):
        ctx.eval([0.0, 0.0], [np.inf, 0.0])
    with pytest.raises(ValueError, match=r"a_free: shape \(3,\); expected \(2,\)"):
        ctx.eval([0.0, 0.0], [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="zdot: dtype <U1 is not real numbers"):
        ctx.eval(["a", "b"], [0.0, 0.0])
    with pytest.raises(fricreg.InputError, match="Context.tangent: .*no successful evaluation"):
        ctx.tangent()
    with pytest.raises(ValueError, match=r"dafree: shape \(1,\)"):
        ctx.tangent_apply(dafree=[1.0])
    with pytest.raises(ValueError, match=r"f: shape \(1,\)"):
        ctx.switching([0.0, 0.0], [0.0, 0.0], [0.0])
    redundant = fricreg.Context(W=[[1.0, 1.0], [1.0, 1.0]])  # PSD, accepted; W_SS singular
    with pytest.raises(fricreg.Error, match="Context.eval: .*singular") as info:
        redundant.eval([0.0, 0.0], [0.1, 0.1])
    assert info.value.status == lib.FRICREG_ESINGULAR and not isinstance(info.value, ValueError)


def test_solve_step_errors():
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B)
    z, Weff = np.zeros(2), 0.1 * np.eye(2)
    with pytest.raises(fricreg.InputError, match="Context.solve_step: ") as info:
        ctx.solve_step(z, z, z, Weff, 0.0, 1e-10)
    assert info.value.status == lib.FRICREG_EINVAL
    with pytest.raises(fricreg.InputError, match="Context.solve_step: ") as info:
        ctx.solve_step(z, z, z, Weff, 0.005, -1.0)
    assert info.value.status == lib.FRICREG_EINVAL
    with pytest.raises(fricreg.InputError, match="Context.solve_step: ") as info:
        ctx.solve_step(z, z, z, [[0.1, 0.0], [0.05, 0.1]], 0.005, 1e-10)
    assert info.value.status == lib.FRICREG_ENOTSYM
    with pytest.raises(fricreg.InputError, match="Context.solve_step: ") as info:
        ctx.solve_step(z, [0.0, np.nan], z, Weff, 0.005, 1e-10)
    assert info.value.status == lib.FRICREG_ENONFINITE
    with pytest.raises(ValueError, match=r"W_eff: shape \(3, 3\); expected \(2, 2\)"):
        ctx.solve_step(z, z, z, np.eye(3), 0.005, 1e-10)
    with pytest.raises(ValueError, match=r"a_pred: shape \(3,\); expected \(2,\)"):
        ctx.solve_step(z, z, np.zeros(3), Weff, 0.005, 1e-10)
    with pytest.raises(ValueError, match=r"c: shape \(2,\); expected a number"):
        ctx.solve_step(z, z, z, Weff, [0.1, 0.1], 1e-10)


def test_sparse_errors():
    sparse = pytest.importorskip("scipy.sparse")
    ctx = fricreg.Context(W=W2B, mun=MUN2B, eps=EPS2B)
    with pytest.raises(fricreg.InputError, match=r"set_coupling: W: .*W\(0, 1\) = 0.5 but") as info:
        ctx.set_coupling(sparse.csr_matrix([[1.0, 0.5], [0.0, 2.0]]))
    assert info.value.status == lib.FRICREG_ENOTSYM
    with pytest.raises(fricreg.InputError, match=r"set_coupling: W: .*W\(0, 1\) = 0.5 but"):
        ctx.set_coupling(sparse.csc_matrix([[1.0, 0.5], [0.0, 2.0]]))  # CSC read as CSC
    with pytest.raises(ValueError, match=r"W: shape \(3, 3\); expected \(2, 2\)"):
        ctx.set_coupling(sparse.identity(3, format="csr"))
    with pytest.raises(fricreg.InputError, match="Context.solve_step: ") as info:
        ctx.solve_step([0, 0], [0, 0], [0, 0], sparse.csc_matrix([[0.1, 0.0], [0.05, 0.1]]),
                       0.005, 1e-10)
    assert info.value.status == lib.FRICREG_ENOTSYM
    assert ctx.W.tobytes() == W2B.tobytes()
