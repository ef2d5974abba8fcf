"""NumericModel pickling (by source), parameter rebinding and rhs_many against per-row calls."""

import pickle

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.errors import ParameterError, SingularMassMatrixError

r, th = lg.coordinates("r theta")
m, g, k, r0, w = lg.parameters("m g k r0 w")
# a spring pendulum driven by an explicit-time force (rows at different t must differ)
SPRING = lg.System([r, th], bodies=[lg.Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
                   V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2, forces={th: sp.cos(w * t)})
PARAMS = {"m": 1.0, "g": 9.81, "k": 40.0, "r0": 1.0, "w": 2.0}
NAMES = ["g", "k", "m", "r0", "w"]


def _rows(n=7, seed=3):
    rng = np.random.default_rng(seed)
    Y = np.column_stack([1 + 0.5 * rng.random(n), rng.normal(size=n), rng.normal(size=n), rng.normal(size=n)])
    P = np.column_stack([9.81 + rng.random(n), 10 + 50 * rng.random(n), 0.5 + rng.random(n), 1 + rng.random(n),
                         rng.random(n) * 3])
    return rng.random(n) * 5, Y, P


@pytest.mark.parametrize("backend", ["python", "numba", "reference"])
def test_pickle_roundtrip_rebuilds_the_same_function(backend):
    model = SPRING.compile(PARAMS, backend=backend)
    clone = pickle.loads(pickle.dumps(model))
    assert clone.backend == backend and clone.source == model.source
    assert np.array_equal(clone.params, model.params)
    tt, Y, _ = _rows()
    for ti, yi in zip(tt, Y):
        assert np.array_equal(np.asarray(clone.fun(ti, yi)), np.asarray(model.fun(ti, yi)))
    d0, d1 = model.diagnostics(tt, Y), clone.diagnostics(tt, Y)
    assert np.allclose(d0["energy"], d1["energy"], rtol=1e-14, atol=0)


def test_pickled_constrained_model_keeps_multipliers():
    x, y = lg.coordinates("x y")
    length = lg.parameters("l")
    pend = lg.System([x, y], bodies=[lg.Particle(m, (x, y))], V=m * g * y,
                     constraints=[lg.Holonomic(sp.sqrt(x**2 + y**2) - length, "string")])
    model = pend.compile({"m": 1.0, "g": 9.81, "l": 1.0})
    clone = pickle.loads(pickle.dumps(model))
    state = np.array([0.6, -0.8, 0.3, 0.225])
    assert np.array_equal(clone.multipliers(0.0, state), model.multipliers(0.0, state))
    assert clone.rhs_many(0.0, state[None, :]).shape == (1, 4)


@pytest.mark.parametrize("backend", ["python", "numba", "reference"])
def test_rhs_many_equals_per_row_calls(backend):
    model = SPRING.compile(PARAMS, backend=backend)
    tt, Y, P = _rows()
    many = model.rhs_many(tt, Y, P)
    for i in range(len(Y)):
        one = model.with_params(dict(zip(NAMES, P[i]))).fun(tt[i], Y[i])
        assert np.array_equal(many[i], np.asarray(one, dtype=float))
    # default: the bound parameters for every row, one time for all
    same = model.rhs_many(1.5, Y)
    assert np.array_equal(same[2], np.asarray(model.fun(1.5, Y[2]), dtype=float))
    # the forcing depends on t: rows at different times differ
    assert not np.array_equal(model.rhs_many(0.0, Y[:1])[0], model.rhs_many(1.0, Y[:1])[0])


def test_rhs_many_against_the_reference_backend():
    tt, Y, P = _rows(seed=11)
    fast = SPRING.compile(PARAMS, backend="numba").rhs_many(tt, Y, P)
    ref = SPRING.compile(PARAMS, backend="reference").rhs_many(tt, Y, P)
    assert np.allclose(fast, ref, rtol=1e-12, atol=1e-12)


def test_rhs_many_bad_input():
    model = SPRING.compile(PARAMS)
    with pytest.raises(ValueError, match=r"shape \(k, 4\)"):
        model.rhs_many(0.0, np.zeros((3, 3)))
    with pytest.raises(ValueError, match="g, k, m, r0, w"):
        model.rhs_many(0.0, np.ones((3, 4)), np.ones((2, 5)))
    P = np.tile(model.params, (2, 1))
    P[1, NAMES.index("m")] = 0.0  # massless bob: singular mass matrix in row 1 only
    with pytest.raises(SingularMassMatrixError, match="singular"):
        model.rhs_many(0.0, np.ones((2, 4)), P)
    with pytest.raises(ParameterError, match="unknown parameter"):
        model.with_params({"mass": 2.0})
