"""Injected numerical faults: every integration path stops with the time, the state and the likely cause,
and returns what it computed up to there (``error.partial``).

Faults are chosen with a closed form, so the fault time and the partial trajectory are checked against
independent truth:

* blow-up: ``ẍ = x²`` (``V = −x³/3``) from ``x = 1`` on the zero-energy orbit, ``x = (1 − ct/2)⁻²`` with
  ``c = √(2/3)``, infinite at ``t* = √6``;
* a math domain error: a force ``√(1 − t)``, undefined after ``t = 1``; ``ẋ = ⅔(1 − (1 − t)^{3/2})``;
* a mass matrix that becomes singular: ``T = ẋ²/2 + (1 − t)ẏ²/2`` (y's inertia vanishes at t = 1 while
  ``ẏ = 0``, x oscillates as ``cos t``);
* a coordinate singularity: ``T = x²ẋ²/2`` (M = x²) from x = 1, ẋ = −1: ``x² = 1 − 2t`` reaches the
  singular point x = 0 at t = ½;
* Newton failures of the implicit geometric methods with a huge step.

``N_FAULTS`` (the number of parametrized fault cases) is cited in the README's guarantees section.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import IntegrationError, SingularMassMatrixError, t
from lagrange.errors import LagrangeError

C = math.sqrt(2.0 / 3.0)
T_BLOWUP = math.sqrt(6.0)
SCIPY_METHODS = ["DOP853", "RK45", "RK23", "LSODA", "Radau", "BDF"]


def _blowup_system():
    x = lg.coordinates("x")
    return lg.System([x], T=x.diff(t) ** 2 / 2, V=-x**3 / 3), x


def _blowup_exact(tt):
    return (1.0 - C * np.asarray(tt) / 2.0) ** -2


def _domain_system():
    x = lg.coordinates("x")
    return lg.System([x], T=x.diff(t) ** 2 / 2, forces={x: sp.sqrt(1 - t)}), x


def _domain_exact_velocity(tt):
    return 2.0 / 3.0 * (1.0 - (1.0 - np.asarray(tt)) ** 1.5)


def _check_partial(exc: LagrangeError, coords_named: tuple[str, ...]):
    """The common contract: t and state set, partial finite and ending at the fault."""
    assert exc.t is not None and math.isfinite(exc.t)
    assert exc.state is not None and {lg.model.coordinates.coordinate_name(c) for c in exc.state} >= set(
        coords_named)
    msg = str(exc)
    assert "t=" in msg and all(f"{nm}=" in msg for nm in coords_named) and "partial" in msg
    p = exc.partial
    assert p is not None and len(p.t) >= 2 and not p.success
    assert np.all(np.isfinite(p.t)) and np.all(np.isfinite(p.y))
    assert np.all(np.diff(p.t) > 0)
    return p


@pytest.mark.parametrize("method", SCIPY_METHODS)
def test_finite_time_blowup(method):
    s, x = _blowup_system()
    with pytest.raises(IntegrationError) as info:
        s.simulate(5.0, {x: 1.0, x.diff(t): C}, {}, method=method)
    exc = info.value
    p = _check_partial(exc, ("x",))
    assert p.t[-1] == pytest.approx(T_BLOWUP, abs=5e-3) and exc.t == pytest.approx(T_BLOWUP, abs=5e-3)
    assert "blow-up" in str(exc)
    early = p.t < 2.0
    assert early.sum() > 100
    assert np.allclose(p[x][early], _blowup_exact(p.t[early]), rtol=1e-5)


@pytest.mark.filterwarnings("ignore:invalid value encountered in sqrt:RuntimeWarning")  # numpy's NaN is the fault
@pytest.mark.parametrize(("method", "backend"), [(m, "python") for m in SCIPY_METHODS] + [("DOP853", "reference")])
def test_math_domain_error_mid_run(method, backend):
    s, x = _domain_system()
    with pytest.raises(IntegrationError) as info:
        s.simulate(3.0, {x: 0.0, x.diff(t): 0.0}, {}, method=method, backend=backend)
    exc = info.value
    p = _check_partial(exc, ("x",))
    msg = str(exc)
    assert ("domain" in msg) or ("non-finite" in msg)  # python: math domain error; reference (numpy): NaN
    assert 0.99 < p.t[-1] <= 1.0 and p.t[-1] <= exc.t < 1.01
    assert np.allclose(p[x.diff(t)], _domain_exact_velocity(p.t), atol=1e-5)


def _near_fault(p, exc, t_fault: float, max_step: float) -> None:
    """The partial trajectory ends at the last accepted step, at most one step before the fault; the
    reported time is where the fault was met (a stage of the failing step)."""
    assert t_fault - max_step <= p.t[-1] <= t_fault and p.t[-1] <= exc.t <= t_fault + max_step


@pytest.mark.parametrize("loop", ["scipy", pytest.param("compiled", marks=pytest.mark.slow)])
def test_nan_from_numba_backend(loop):
    """Compiled code computes sqrt(−ε) as NaN instead of raising: reported as a non-finite value, by scipy's
    loop and by the compiled loop."""
    pytest.importorskip("numba")
    s, x = _domain_system()
    with pytest.raises(IntegrationError) as info:
        s.simulate(3.0, {x: 0.0, x.diff(t): 0.0}, {}, backend="numba", loop=loop)
    p = _check_partial(info.value, ("x",))
    assert 0.99 < p.t[-1] <= 1.0
    assert np.allclose(p[x.diff(t)], _domain_exact_velocity(p.t), atol=1e-5)


def test_mass_matrix_becomes_singular_mid_run():
    x, y = lg.coordinates("x y")
    s = lg.System([x, y], T=x.diff(t) ** 2 / 2 + (1 - t) * y.diff(t) ** 2 / 2, V=x**2 / 2)
    with pytest.raises(SingularMassMatrixError) as info:
        s.simulate(2.0, {x: 1.0, y: 0.5, x.diff(t): 0.0, y.diff(t): 0.0}, {}, max_step=0.02)
    exc = info.value
    p = _check_partial(exc, ("x", "y"))
    assert "coordinates involved: y" in str(exc)
    _near_fault(p, exc, 1.0, 0.02)
    assert np.allclose(p[x], np.cos(p.t), atol=1e-8) and np.allclose(p[y], 0.5)


def test_coordinate_singularity():
    """M = x² vanishes at x = 0, reached at t = ½ (with ẋ → −∞): the run stops there, naming x."""
    x = lg.coordinates("x")
    s = lg.System([x], T=x**2 * x.diff(t) ** 2 / 2)
    with pytest.raises(IntegrationError) as info:
        s.simulate(1.0, {x: 1.0, x.diff(t): -1.0}, {})
    exc = info.value
    p = _check_partial(exc, ("x",))
    assert exc.t == pytest.approx(0.5, abs=1e-6) and p.t[-1] == pytest.approx(0.5, abs=1e-6)
    assert "singularity" in str(exc)
    early = p.t < 0.45
    assert np.allclose(p[x][early], np.sqrt(1.0 - 2.0 * p.t[early]), rtol=1e-7)


def test_fault_on_the_projection_path():
    """A constrained run (step-by-step driver with projection) keeps its partial trajectory too."""
    x, y = lg.coordinates("x y")
    m, g, length = lg.parameters("m g l")
    s = lg.System([x, y], bodies=[lg.Particle(m, (x, y))], V=m * g * y, forces={x: sp.sqrt(1 - t)},
                  constraints=[lg.Holonomic(sp.sqrt(x**2 + y**2) - length, "string")])
    with pytest.raises(IntegrationError) as info:
        s.simulate(2.0, {x: 0.6, y: -0.8, x.diff(t): 0, y.diff(t): 0}, {m: 1, g: 9.81, length: 1}, max_step=0.02)
    p = _check_partial(info.value, ("x", "y"))
    _near_fault(p, info.value, 1.0, 0.02)
    assert np.max(np.abs(np.hypot(p[x], p[y]) - 1.0)) < 1e-9  # partial data still on the constraint


def test_fault_on_the_friction_segment_path():
    """Dry friction (event-segmented integration) with a force undefined after t = 1."""
    x = lg.coordinates("x")
    m, mu, g = lg.parameters("m mu g")
    s = lg.System([x], T=m * x.diff(t) ** 2 / 2, P=-mu * m * g * sp.Abs(x.diff(t)),
                  forces={x: 3 * sp.sqrt(1 - t)})
    with pytest.raises(IntegrationError) as info:
        s.simulate(2.0, {x: 0.0, x.diff(t): 1.0}, {m: 1, mu: 0.1, g: 9.81})
    p = _check_partial(info.value, ("x",))
    assert 0.95 < p.t[-1] <= 1.0 and p.t[-1] <= info.value.t
    # sliding forward all along: ẍ = 3√(1 − t) − μg
    exact = 1.0 + 2.0 * (1.0 - (1.0 - p.t) ** 1.5) - 0.981 * p.t
    assert np.allclose(p[x.diff(t)], exact, atol=1e-6)


@pytest.mark.parametrize("loop", ["scipy", "compiled"])
@pytest.mark.parametrize(("method", "h", "fail_t"), [("midpoint", 5.0, 10.0), ("gl4", 5.0, 5.0), ("dg", 2.0, 4.0)])
def test_newton_failure_with_a_huge_step(method, h, fail_t, loop):
    """A pendulum swinging near the top with a step of several periods: Newton fails; the error names the
    step, its time, the residual, and the partial trajectory equals the same run stopped before it."""
    x = lg.coordinates("x")
    s = lg.System([x], T=x.diff(t) ** 2 / 2, V=-sp.cos(x))
    ic = {x: 3.0, x.diff(t): 0.0}
    with pytest.raises(IntegrationError) as info:
        s.simulate(40.0, ic, {}, method=method, step=h, loop=loop)
    exc = info.value
    p = _check_partial(exc, ("x",))
    msg = str(exc)
    assert "Newton" in msg and "residual" in msg and f"step {round(fail_t / h) + 1} of" in msg
    assert exc.t == fail_t and p.t[-1] == fail_t
    ref = s.simulate(fail_t, ic, {}, method=method, step=h, loop=loop)
    assert np.allclose(p.y[-1], ref.y[-1], rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("loop", ["scipy", "compiled"])
@pytest.mark.parametrize("method", ["midpoint", "gl4", "gl6", "dg"])
def test_blowup_in_a_geometric_method(method, loop):
    s, x = _blowup_system()
    with pytest.raises(IntegrationError) as info:
        s.simulate(5.0, {x: 1.0, x.diff(t): C}, {}, method=method, step=0.01, loop=loop)
    exc = info.value
    p = _check_partial(exc, ("x",))
    assert 2.3 < exc.t < T_BLOWUP and p.t[-1] == exc.t
    early = p.t < 1.5
    rtol = 1e-6 if method in ("gl4", "gl6") else 1e-3  # orders 4, 6 and 2 at h = 0.01
    assert np.allclose(p[x][early], _blowup_exact(p.t[early]), rtol=rtol)


@pytest.mark.parametrize("loop", ["scipy", "compiled"])
@pytest.mark.parametrize("method", ["midpoint", "gl4"])
def test_inertia_vanishes_in_a_geometric_method(method, loop):
    """T = (1 − t) ẏ²/2, V = y²/2: the mass matrix vanishes at t = 1, where y diverges logarithmically —
    y = c J₀(2√s) + d Y₀(2√s) with s = 1 − t (Bessel's equation after s y'' + y' + y = 0). Both step loops stop
    at the step from t = 1 and name the singular mass matrix; the partial trajectory follows the closed form
    and ends at the last state whose velocity exists."""
    from scipy.special import j0, j1, y0, y1

    y = lg.coordinates("y")
    s = lg.System([y], T=(1 - t) * y.diff(t) ** 2 / 2, V=y**2 / 2)
    with pytest.raises(IntegrationError) as info:
        s.simulate(2.0, {y: 1.0, y.diff(t): 0.0}, {}, method=method, step=0.01, loop=loop)
    exc = info.value
    p = _check_partial(exc, ("y",))
    assert exc.t == pytest.approx(1.0, abs=1e-12) and "mass matrix is singular" in str(exc)
    assert p.t[-1] == pytest.approx(0.99, abs=1e-12)
    c, d = np.linalg.solve([[j0(2.0), y0(2.0)], [j1(2.0), y1(2.0)]], [1.0, 0.0])  # y(0) = 1, ẏ(0) = 0
    early = p.t <= 0.8
    root = 2 * np.sqrt(1 - p.t[early])
    exact = c * j0(root) + d * y0(root)
    assert np.allclose(p[y][early], exact, rtol=1e-6 if method == "gl4" else 1e-3, atol=1e-9)


def _n_cases(fn) -> int:
    return math.prod(len(m.args[1]) for m in getattr(fn, "pytestmark", []) if m.name == "parametrize")


FAULT_TESTS = [test_finite_time_blowup, test_math_domain_error_mid_run, test_nan_from_numba_backend,
               test_mass_matrix_becomes_singular_mid_run, test_coordinate_singularity,
               test_fault_on_the_projection_path, test_fault_on_the_friction_segment_path,
               test_newton_failure_with_a_huge_step, test_blowup_in_a_geometric_method,
               test_inertia_vanishes_in_a_geometric_method]
#: faults injected by this module (one per parametrized case)
N_FAULTS = sum(_n_cases(f) for f in FAULT_TESTS)


def test_fault_count():
    assert N_FAULTS == 6 + 7 + 2 + 1 + 1 + 1 + 1 + 3 * 2 + 4 * 2 + 2 * 2
