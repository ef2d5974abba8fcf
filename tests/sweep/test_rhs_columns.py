"""The vectorized ``rhs_many`` kernel (states as columns, lagrange.codegen.batch_source) against the
per-member ``rhs`` (bit for bit: the same printed arithmetic) and the reference backend, in combination with
explicit time, per-member parameters, friction sign terms, nested function calls, non-integer powers,
constraints, singular members and non-finite states."""

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.codegen.batch_source import columns_source
from lagrange.codegen.cse import fuse
from lagrange.errors import SingularMassMatrixError

r, th = lg.coordinates("r theta")
m, g, k, r0, w, mu = lg.parameters("m g k r0 w mu")
SPRING = lg.System([r, th], bodies=[lg.Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
                   V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2, forces={th: sp.cos(w * t)})
PARAMS = {"m": 1.0, "g": 9.81, "k": 40.0, "r0": 1.0, "w": 2.0}
x = lg.coordinates("x")
xd = sp.Symbol("x_dot")
# Coulomb-like friction (a sign of the velocity), a nested call, a non-integer power, abs, explicit time
ODD = lg.System([x], bodies=[lg.Particle(m * (2 + sp.cos(x) ** 2), (x,))],
                V=k * sp.sqrt(1 + x**2) ** 3 + sp.exp(sp.sin(x) / 3),
                forces={x: -mu * sp.sign(sp.Derivative(x, t)) * (1 + sp.Abs(x)) + (1 + sp.sin(w * t) ** 2) ** 1.5})
ODD_PARAMS = {"m": 1.3, "k": 2.0, "mu": 0.4, "w": 1.7}


def _members(n2, kmem, seed):
    rng = np.random.default_rng(seed)
    Y = rng.normal(size=(kmem, n2))
    return rng.random(kmem) * 3, Y


def test_columns_equal_rows_and_per_member_calls_bit_for_bit():
    model = SPRING.compile(PARAMS, backend="numba")
    tt, Y = _members(4, 9, 5)
    Y[:, 0] = 1 + np.abs(Y[:, 0])
    P = np.tile(model.params, (9, 1)) * (1 + 0.1 * np.random.default_rng(1).random((9, len(model.params))))
    cols = model.rhs_many(tt, Y.T, P.T, columns=True)
    assert cols.shape == (4, 9) and cols.flags.c_contiguous
    assert np.array_equal(cols, model.rhs_many(tt, Y, P).T)
    names = [s.name for s in model.equations.numeric_parameters]
    for i in range(9):
        one = model.with_params(dict(zip(names, P[i]))).fun(tt[i], Y[i])
        assert np.array_equal(cols[:, i], np.asarray(one, dtype=float))
    ref = SPRING.compile(PARAMS, backend="reference").rhs_many(tt, Y, P)
    assert np.allclose(cols.T, ref, rtol=1e-12, atol=1e-12)


def test_friction_sign_nested_calls_and_powers():
    model = ODD.compile(ODD_PARAMS, backend="numba")
    tt, Y = _members(2, 40, 7)
    Y[:3, 1] = 0.0  # sign(0) = 0: no friction
    many = model.rhs_many(tt, Y)
    for i in range(len(Y)):
        assert np.array_equal(many[i], np.asarray(model.fun(tt[i], Y[i]), dtype=float))
    ref = ODD.compile(ODD_PARAMS, backend="reference").rhs_many(tt, Y)
    assert np.allclose(many, ref, rtol=1e-12, atol=1e-12)
    # the generated kernel really hoisted the calls out of the vector loop
    src, n_calls = columns_source(fuse(model.equations)[0], n_params=len(model.params))
    second = src.split("for c in range(k):")[2]
    # only vectorizable operations remain (sqrt and abs are LLVM intrinsics)
    assert n_calls >= 5 and "math.sqrt" in second and "**1.5" not in second
    assert "math." not in second.replace("math.sqrt", "")


def test_singular_member_is_named_and_nonfinite_states_pass_through():
    model = SPRING.compile(PARAMS, backend="numba")
    P = np.tile(model.params, (3, 1))
    P[1, [s.name for s in model.equations.numeric_parameters].index("m")] = 0.0
    with pytest.raises(SingularMassMatrixError, match="singular"):
        model.rhs_many(0.0, np.ones((4, 3)), P.T, columns=True)
    Y = np.ones((3, 4))
    Y[2, 3] = np.nan  # a NaN velocity: NaN derivatives for that member only, as the per-member rhs gives
    out = model.rhs_many(0.0, Y)
    assert np.isnan(out[2]).any() and np.isfinite(out[:2]).all()
    assert np.array_equal(out[0], np.asarray(model.fun(0.0, Y[0]), dtype=float))


def test_constrained_model_in_columns_layout():
    X, Yc = lg.coordinates("X Y")
    length = lg.parameters("l")
    pend = lg.System([X, Yc], bodies=[lg.Particle(m, (X, Yc))], V=m * g * Yc,
                     constraints=[lg.Holonomic(sp.sqrt(X**2 + Yc**2) - length, "string")])
    model = pend.compile({"m": 1.0, "g": 9.81, "l": 1.0})
    states = np.array([[0.6, -0.8, 0.3, 0.225], [0.0, -1.0, 1.0, 0.0]])
    cols = model.rhs_many(0.0, states.T, columns=True)
    assert np.array_equal(cols, model.rhs_many(0.0, states).T)


def test_columns_shape_errors():
    model = SPRING.compile(PARAMS)
    with pytest.raises(ValueError, match=r"shape \(4, k\)"):
        model.rhs_many(0.0, np.zeros((3, 4)), columns=True)
    with pytest.raises(ValueError, match=r"P must have shape \(5, 2\)"):
        model.rhs_many(0.0, np.zeros((4, 2)), np.ones((2, 5)), columns=True)
