"""simulate's option objects, the deprecated flat keywords, the method registry's refusals, and a table of bad
inputs (API and spec ``[simulate]``) that must all end in a LagrangeError naming the option (issue 21, item 5)."""

from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest

from lagrange import (
    FrictionOptions,
    LagrangeError,
    MethodError,
    OptionError,
    Stabilization,
    StepOptions,
    System,
    coordinates,
    parameters,
    t,
)
from lagrange.errors import SpecError
from lagrange.integrate import registry
from lagrange.spec.options import merge_run_options


def _oscillator():
    x = coordinates("x")
    m, k = parameters("m k")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2), x


def _pendulum():
    th = coordinates("theta")
    m, g, ell = parameters("m g l")
    import sympy as sp

    return System([th], T=m * ell**2 * th.diff(t) ** 2 / 2, V=-m * g * ell * sp.cos(th)), th


def _block():
    """A block on a rough floor pushed by a spring (Wells' dry friction: P = -mu m g |v|)."""
    x = coordinates("x")
    m, k, mu, g = parameters("m k mu g")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-mu * m * g * abs(x.diff(t))), x


OSC = {"m": 1.0, "k": 4.0}
X0 = {"x": 1.0, "x_dot": 0.0}

#: (keyword options, the text the message must contain)
BAD_API = [
    ({"n_points": 0}, "n_points"),
    ({"n_points": 1}, "n_points"),
    ({"n_points": 200_000_000}, "n_points"),
    ({"n_points": 10.5}, "n_points"),
    ({"rtol": math.nan}, "rtol"),
    ({"rtol": math.inf}, "rtol"),
    ({"rtol": 0.0}, "rtol"),
    ({"rtol": -1e-6}, "rtol"),
    ({"rtol": 0.0, "atol": 0.0}, "rtol"),
    ({"atol": -1e-9}, "atol"),
    ({"atol": math.nan}, "atol"),
    ({"rtol": "1e-6"}, "rtol"),
    ({"max_step": 1e-12}, "max_step"),
    ({"max_step": 0.0}, "max_step"),
    ({"max_step": math.nan}, "max_step"),
    ({"t_eval": [0.0, 5.0, 20.0]}, "t_eval"),
    ({"t_eval": [2.0, 1.0]}, "t_eval"),
    ({"t_eval": [0.0, math.nan]}, "t_eval"),
    ({"t_eval": [[0.0, 1.0]]}, "t_eval"),
    ({"method": "rk4"}, "rk4"),
    ({"method": 3}, "method"),
    ({"loop": "fast"}, "loop"),
    ({"friction": "smooth"}, "friction"),
    ({"friction": FrictionOptions("regularize"), "method": "gl4", "step": 0.01, "events": [lambda t, y: y[0]]},
     "events"),
    ({"stabilization": "drift"}, "stabilization"),
    ({"method": "gl4"}, "step"),
    ({"method": "gl4", "step": 0.01, "t_eval": [0.0, 1.0]}, "t_eval"),
    ({"method": "gl4", "step": 1e-300}, "step"),
    ({"method": "gl4", "step": -0.1}, "step"),
    ({"method": "gl4", "step": math.inf}, "step"),
    ({"method": "taylor", "events": [lambda t, y: y[0]]}, "events"),
    ({"events": [3]}, "events"),
    ({"backend": "fortran"}, "backend"),
    # step-count and output-size limits (public options, validated), and an empty t_eval
    ({"max_step": 1e-9}, "max_steps"),
    ({"method": "gl4", "step": 1e-7}, "max_steps"),
    ({"max_steps": 0}, "max_steps"),
    ({"max_steps": 10**10}, "max_steps"),
    ({"max_steps": 2.5}, "max_steps"),
    ({"max_steps": 100, "max_step": 0.05}, "max_steps"),
    ({"max_output_bytes": 1000}, "max_output_bytes"),
    ({"max_output_bytes": 0}, "max_output_bytes"),
    ({"max_output_bytes": "1e9"}, "max_output_bytes"),
    ({"t_eval": []}, "t_eval"),
]


def _id(options) -> str:
    """A parameter id that is the same in every process (a function's repr holds its address: xdist workers
    would collect different ids)."""
    return re.sub(r"<function [^ ]* at 0x[0-9a-f]+>", "<function>", str(options))


@pytest.mark.parametrize(("options", "names"), BAD_API, ids=[_id(o) for o, _ in BAD_API])
def test_bad_api_option_is_a_lagrange_error_naming_it(options, names):
    s, _ = _oscillator()
    with pytest.raises(LagrangeError, match=names):
        s.simulate(10, X0, OSC, **options)


def test_step_and_output_limits_pass_quietly_within_them():
    """The quiet side of the limits: a run inside max_steps and max_output_bytes runs, and gives the
    oscillator's closed form (x = cos 2t)."""
    s, x = _oscillator()
    sol = s.simulate(10, X0, OSC, max_step=0.2, max_steps=100, n_points=11, max_output_bytes=11 * 2 * 8,
                     rtol=1e-10, atol=1e-12)
    assert np.allclose(sol[x], np.cos(2.0 * sol.t), atol=1e-7)
    fixed = s.simulate(10, X0, OSC, method="gl4", step=0.01, max_steps=1000)
    assert abs(fixed[x][-1] - np.cos(20.0)) < 1e-5


@pytest.mark.parametrize(("build", "names"), [
    (lambda: FrictionOptions(epsilon=math.inf), "epsilon"),
    (lambda: FrictionOptions(epsilon=math.nan), "epsilon"),
    (lambda: FrictionOptions(epsilon=0.0), "epsilon"),
    (lambda: FrictionOptions(epsilon=-1e-3), "epsilon"),
    (lambda: FrictionOptions("smooth"), "friction"),
    (lambda: Stabilization("baumgarte", alpha=-1.0), "alpha"),
    (lambda: Stabilization("baumgarte", beta=math.nan), "beta"),
    (lambda: Stabilization(project_initial="yes"), "project_initial"),
    (lambda: Stabilization("drift"), "stabilization"),
    (lambda: StepOptions(0.0), "step"),
    (lambda: StepOptions(math.nan), "step"),
])
def test_option_objects_validate_themselves(build, names):
    with pytest.raises(LagrangeError, match=names):
        build()


def test_bad_friction_epsilon_through_the_deprecated_keyword():
    s, x = _block()
    with pytest.warns(DeprecationWarning), pytest.raises(OptionError, match="epsilon"):
        s.simulate(1, X0, {"m": 1, "k": 1, "mu": 0.1, "g": 9.81}, friction="regularize", friction_epsilon=math.inf)


#: spec [simulate] tables that must be refused, and the key the message names
BAD_SPEC = [
    ({"n_points": 0}, "n_points"),
    ({"n_points": 200_000_000}, "n_points"),
    ({"friction_epsilon": math.inf}, "friction_epsilon"),
    ({"friction_epsilon": math.nan}, "friction_epsilon"),
    ({"friction_epsilon": 0.0}, "friction_epsilon"),
    ({"friction": "smooth"}, "friction"),
    ({"stabilization": "drift"}, "stabilization"),
    ({"baumgarte": [1.0]}, "baumgarte"),
    ({"baumgarte": [1.0, math.inf]}, "stabilization"),
    ({"method": "rk4"}, "method"),
    ({"loop": "fast"}, "loop"),
    ({"rtol": math.nan}, "rtol"),
    ({"rtol": "tight"}, "rtol"),
    ({"atol": -1.0}, "atol"),
    ({"step": 1e-300, "method": "gl4"}, None),  # refused by simulate (the step count), below
    ({"max_step": 1e-12}, None),
    ({"max_steps": 0}, "max_steps"),
    ({"max_steps": 2.5}, "max_steps"),
    ({"max_output_bytes": -1}, "max_output_bytes"),
    ({"max_step": 1e-3, "max_steps": 100}, None),  # refused by simulate (the step count), below
]


@pytest.mark.parametrize(("table", "key"), BAD_SPEC, ids=[_id(o) for o, _ in BAD_SPEC])
def test_bad_spec_simulate_value_is_refused_naming_it(table, key):
    s, _ = _oscillator()
    flags = dict.fromkeys(("method", "step", "rtol", "atol", "backend", "friction"))
    if key is not None:
        with pytest.raises(SpecError, match=key):
            merge_run_options(table, flags, "spec.toml")
        return
    options = merge_run_options(table, flags, "spec.toml")
    with pytest.raises(OptionError, match="step|max_step") as info:
        s.simulate(10, X0, OSC, **options)
    assert "limit" in str(info.value)


def test_spec_values_become_option_objects_without_warnings():
    flags = dict.fromkeys(("method", "step", "rtol", "atol", "backend", "friction"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        opts = merge_run_options({"friction": "regularize", "friction_epsilon": 1e-4, "stabilization": "baumgarte",
                                  "baumgarte": [5.0, 6.0], "project_initial": False}, flags, "s.toml")
    assert opts["friction"] == FrictionOptions("regularize", 1e-4)
    assert opts["stabilization"] == Stabilization("baumgarte", 5.0, 6.0, project_initial=False)


def test_model_params_are_mapped_by_name_not_position():
    """k = 100 asked with a model compiled at k = 4 must give the k = 100 answer (ω = 10, not 2)."""
    s, x = _oscillator()
    model = s.compile({"m": 1.0, "k": 4.0})
    sol = s.simulate(1.0, X0, {"m": 1.0, "k": 100.0}, model=model, rtol=1e-10, atol=1e-12)
    assert np.allclose(sol[x], np.cos(10.0 * sol.t), atol=1e-7)
    # the keys' order does not matter either
    sol2 = s.simulate(1.0, X0, {"k": 100.0, "m": 1.0}, model=model, rtol=1e-10, atol=1e-12)
    assert np.allclose(sol2[x], sol[x], atol=0, rtol=0)


def test_model_of_another_system_is_refused():
    s, _ = _oscillator()
    p, _ = _pendulum()
    model = p.compile({"m": 1.0, "g": 9.81, "l": 1.0})
    with pytest.raises(OptionError, match="model=.*different system"):
        s.simulate(1.0, X0, OSC, model=model)
    with pytest.raises(OptionError, match="model="):
        s.simulate(1.0, X0, OSC, model="compiled")


def test_deprecated_flat_keywords_still_work_and_warn():
    s, x = _block()
    p = {"m": 1.0, "k": 4.0, "mu": 0.1, "g": 9.81}
    new = s.simulate(2, X0, p, method="LSODA", friction=FrictionOptions("regularize", epsilon=1e-3))
    with pytest.warns(DeprecationWarning, match="friction_epsilon"):
        old = s.simulate(2, X0, p, method="LSODA", friction="regularize", friction_epsilon=1e-3)
    assert np.array_equal(new.y, old.y)
    # and the ε really reaches the equations: a different ε gives a different motion
    other = s.simulate(2, X0, p, method="LSODA", friction=FrictionOptions("regularize", epsilon=1e-1))
    assert not np.allclose(other.y, new.y, atol=1e-6)


def test_deprecated_baumgarte_keywords_match_the_stabilization_object():
    """A particle held on a circle by a holonomic constraint (a pendulum in Cartesian coordinates)."""
    from lagrange import Holonomic

    x, y = coordinates("x y")
    m, g, r = parameters("m g r")
    s = System([x, y], T=m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=m * g * y,
               constraints=[Holonomic(x**2 + y**2 - r**2, "rod")])
    p = {"m": 1.0, "g": 9.81, "r": 1.0}
    y0 = {"x": 1.0, "y": 0.0, "x_dot": 0.0, "y_dot": 0.0}
    new = s.simulate(1, y0, p, method="LSODA", stabilization=Stabilization("baumgarte", alpha=3.0, beta=4.0))
    with pytest.warns(DeprecationWarning, match="baumgarte"):
        old = s.simulate(1, y0, p, method="LSODA", stabilization="baumgarte", baumgarte=(3.0, 4.0))
    assert np.array_equal(new.y, old.y)
    assert "baumgarte" in new.method
    assert np.max(np.abs(new[x] ** 2 + new[y] ** 2 - 1.0)) < 1e-3


def test_step_options_equal_a_plain_step():
    s, x = _oscillator()
    a = s.simulate(1, X0, OSC, method="gl4", step=0.01)
    b = s.simulate(1, X0, OSC, method="gl4", step=StepOptions(0.01))
    assert np.array_equal(a.y, b.y)
    assert np.allclose(a[x], np.cos(2 * a.t), atol=1e-8)


def test_registry_refusal_names_the_combination_and_the_methods_that_support_it():
    s, _ = _block()
    p = {"m": 1.0, "k": 4.0, "mu": 0.1, "g": 9.81}
    with pytest.raises(MethodError) as info:
        s.simulate(1, X0, p, method="taylor")
    msg = str(info.value)
    assert "taylor" in msg and "sign()" in msg and "DOP853" in msg and "gl4" not in msg
    with pytest.raises(MethodError, match="non-conservative") as info:
        s.simulate(1, X0, p, method="gl4", step=0.01, friction="regularize")
    assert "DOP853" in str(info.value)


def test_registry_table_and_names():
    assert registry.find(" dop853 ").name == "DOP853"
    assert registry.find("Implicit_Midpoint").name == "midpoint"
    assert registry.find("rk4") is None
    with pytest.raises(MethodError, match="unknown method 'rk4'"):
        registry.get("rk4")
    assert set(registry.supporting("events")) == {"DOP853", "RK45", "RK23", "LSODA", "Radau", "BDF", "heyoka"}
    text = registry.table()
    for m in registry.METHODS:
        assert m.name in text
    # every run function resolves
    for m in registry.METHODS:
        assert callable(m.runner())


def test_cli_lists_the_methods(capsys):
    from lagrange.cli import main

    assert main(["methods"]) == 0
    out = capsys.readouterr().out
    assert "DOP853" in out and "gl6" in out and "holon." in out
    assert main(["simulate", "--list-methods"]) == 0
    assert capsys.readouterr().out == out
