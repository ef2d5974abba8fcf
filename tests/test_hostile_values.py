"""Hostile and broken values given through the Python API end in a clear LagrangeError (which also subclasses
the matching builtin), never a bare OverflowError, SympifyError or AttributeError from inside numpy, sympy or
scipy. ``HOSTILE_VALUES`` lists them: (id, call, expected error, fragment of the message).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.errors import LagrangeError


def _system():
    x = lg.coordinates("x")
    m = lg.parameters("m")
    return lg.System([x], T=m * x.diff(t) ** 2 / 2, V=x**2 / 2), x


S, X = _system()
I0 = {"x": 0.1, "x_dot": 0.0}
HUGE = 10**5000

HOSTILE_VALUES = [
    ("param_5000_digit_int", lambda: S.simulate(0.1, I0, {"m": HUGE}, backend="python"), "floating-point range"),
    ("initial_5000_digit_int", lambda: S.simulate(0.1, {"x": HUGE, "x_dot": 0}, {"m": 1}, backend="python"),
     "floating-point range"),
    ("t_end_5000_digit_int", lambda: S.simulate(HUGE, I0, {"m": 1}, backend="python"), "finite times"),
    ("param_string_1e99999", lambda: S.simulate(0.1, I0, {"m": "1e" + "9" * 5000}, backend="python"),
     "not a number"),
    ("param_string_5000_digit_rational",
     lambda: S.simulate(0.1, I0, {"m": "1" + "0" * 5000 + "/3"}, backend="python"), "not a number"),
    ("param_list", lambda: S.simulate(0.1, I0, {"m": [1, 2]}, backend="python"), "not a number"),
    ("initial_list", lambda: S.simulate(0.1, {"x": [0.1, 1], "x_dot": 0}, {"m": 1}, backend="python"),
     "not a number"),
    ("t_eval_empty", lambda: S.simulate(0.1, I0, {"m": 1}, backend="python", t_eval=[]), "t_eval is empty"),
    ("t_eval_empty_array", lambda: S.simulate(0.1, I0, {"m": 1}, backend="python", t_eval=np.array([])),
     "t_eval is empty"),
    ("max_step_1e-9", lambda: S.simulate(1.0, I0, {"m": 1}, backend="python", max_step=1e-9), "max_steps"),
    ("normal_modes_list_param", lambda: lg.normal_modes(lg.linearize(S, {X: 0}), {"m": [1, 2]}),
     "not one number"),
    ("equilibria_list_param", lambda: lg.equilibria(S, {"m": [1, 2]}), "not one number"),
    ("linearize_list_about", lambda: lg.linearize(S, {X: [0, 1]}), "not one number"),
    ("sweep_5000_digit_int", lambda: lg.sweep(S, {"m": [HUGE]}, t_end=0.1, initial=I0, params={"m": 1}, workers=0,
                                              progress=False), "floating-point range"),
    ("declared_nan_potential", lambda: lg.System([X], T=S.T, V=sp.nan * X), "not a finite number"),
    ("declared_zoo_kinetic", lambda: lg.System([X], T=S.T + sp.zoo, V=0), "not a finite number"),
]


@pytest.mark.parametrize(("name", "call", "fragment"), HOSTILE_VALUES, ids=[h[0] for h in HOSTILE_VALUES])
def test_hostile_value_is_a_clear_lagrange_error(name, call, fragment):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(LagrangeError) as info:
            call()
    assert isinstance(info.value, (ValueError, TypeError, RuntimeError, PermissionError)), type(info.value)
    assert fragment in str(info.value) and len(str(info.value)) < 2000, str(info.value)[:500]


def test_exact_values_with_many_digits_still_run():
    """The quiet side: a 5,000-digit rational that is a normal number is accepted (m = 1 + 10⁻⁵⁰⁰⁰ ≈ 1), and the
    run is the oscillator's cos t."""
    m = sp.Rational(10**5000 + 1, 10**5000)
    sol = S.simulate(1.0, {"x": 1.0, "x_dot": 0.0}, {"m": m}, backend="python", rtol=1e-10, atol=1e-12)
    assert sol[X][-1] == pytest.approx(np.cos(1.0), rel=1e-7)


def test_ensemble_step_and_output_limits():
    """integrate_ensemble applies the same limits: max_step=1e-9 over a span of 1 is refused naming max_steps,
    so is output beyond max_output_bytes; within them it runs (x(π) = cos(√k π) x0)."""
    from lagrange.errors import OptionError
    from lagrange.sweep import integrate_ensemble

    x = lg.coordinates("x")
    k = lg.parameters("k")
    osc = lg.System([x], bodies=[lg.Particle(1, (x,))], V=k * x**2 / 2).compile({"k": 1.0}, backend="python")
    with pytest.raises(OptionError, match="max_steps"):
        integrate_ensemble(osc, 1.0, [[1.0, 0.0]], max_step=1e-9)
    with pytest.raises(OptionError, match="max_output_bytes"):
        integrate_ensemble(osc, 1.0, [[1.0, 0.0]] * 4, n_points=1000, max_output_bytes=4 * 1000 * 2 * 8 - 1)
    res = integrate_ensemble(osc, np.pi, [[1.0, 0.0], [2.0, 0.0]], P=[[1.0], [4.0]], t_eval=[np.pi],
                             max_step=0.1, max_steps=100, max_output_bytes=2 * 2 * 8)
    assert np.allclose(res.y[:, -1, 0], [-1.0, 2.0], atol=1e-7)


def test_scipy_run_stops_at_max_steps_with_its_partial_trajectory():
    """A run whose own steps are many (a stiff spring over a long span, no max_step to refuse up front) stops
    at max_steps with an IntegrationError naming it and carrying the trajectory so far, which follows the
    closed form x = cos(ωt); with room it finishes."""
    from lagrange.errors import IntegrationError

    x = lg.coordinates("x")
    k = lg.parameters("k")
    s = lg.System([x], bodies=[lg.Particle(1, (x,))], V=k * x**2 / 2)
    opts = {"backend": "python", "rtol": 1e-10, "atol": 1e-12, "method": "DOP853"}
    with pytest.raises(IntegrationError, match="max_steps=200") as info:
        s.simulate(10.0, {"x": 1.0, "x_dot": 0.0}, {"k": 1e4}, max_steps=200, **opts)
    p = info.value.partial
    assert p is not None and 0 < info.value.t < 10.0 and len(p.t) > 2
    assert np.allclose(p[x], np.cos(100.0 * p.t), atol=1e-6)
    sol = s.simulate(0.5, {"x": 1.0, "x_dot": 0.0}, {"k": 1e4}, max_steps=10_000, **opts)
    assert sol[x][-1] == pytest.approx(np.cos(50.0), abs=1e-7)


@pytest.mark.parametrize("route", ["compiled", "taylor", "heyoka"])
def test_every_adaptive_route_honours_max_steps(route):
    """The compiled DOP853 loop, the Taylor method and heyoka stop at the max_steps given to simulate (an
    IntegrationError with the partial trajectory), not at their own default of 10⁷."""
    from lagrange.errors import IntegrationError

    kw = {"compiled": {"backend": "numba", "loop": "compiled"}, "taylor": {"method": "taylor"},
          "heyoka": {"method": "heyoka"}}[route]
    pytest.importorskip({"compiled": "numba", "taylor": "numpy", "heyoka": "heyoka"}[route])
    x = lg.coordinates("x")
    k = lg.parameters("k")
    s = lg.System([x], bodies=[lg.Particle(1, (x,))], V=k * x**2 / 2)
    with pytest.raises(IntegrationError) as info:
        s.simulate(10.0, {"x": 1.0, "x_dot": 0.0}, {"k": 1e4}, max_steps=50, rtol=1e-10, atol=1e-12, **kw)
    assert info.value.partial is not None and info.value.t < 1.0
