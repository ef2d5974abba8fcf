"""Strings are never evaluated: a hostile string given as a value to any entry point that takes values must
not run code. Each string below would create the canary file if it reached ``eval`` (``sympify`` of a string
is ``eval``); the positive control checks that it does. Strings that are plain expressions of numbers go
through the spec parser (lagrange.spec.expressions) and are accepted; anything else is a LagrangeError.

``CANARY_ENTRIES`` counts the entry points tested (docs/guarantees.md cites it).
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.errors import LagrangeError


def _hostile(canary) -> list[str]:
    path = str(canary)
    return [f"__import__('os').system('touch {path}') or 4",
            f"(lambda: __import__('pathlib').Path({path!r}).touch())() or 1",
            f"exec(\"open({path!r}, 'w').close()\") or 2"]


@pytest.fixture
def canary(tmp_path):
    path = tmp_path / "canary"
    yield path
    assert not path.exists(), "a string value was evaluated as code"


def _oscillator():
    x = lg.coordinates("x")
    m, k = lg.parameters("m k")
    return lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)


PARAMS = {"m": 1.0, "k": 4.0}
INITIAL = {"x": 0.1, "x_dot": 0.0}


def _expect_refusal_or_number(call) -> None:
    """The call either refuses the value with a LagrangeError or succeeds (never runs the string)."""
    try:
        call()
    except LagrangeError:
        pass


def test_control_sympify_would_run_the_string(tmp_path):
    """The strings are potent: the evaluation lagrange must avoid runs them (in a child process)."""
    canary = tmp_path / "control"
    code = f"import sympy; sympy.sympify({_hostile(canary)[0]!r})"
    subprocess.run([sys.executable, "-c", code], check=True, timeout=120)
    assert canary.exists()


def _entries():
    def simulate_params(s, v):
        s.simulate(0.1, INITIAL, {**PARAMS, "k": v}, backend="python")

    def simulate_initial(s, v):
        s.simulate(0.1, {**INITIAL, "x": v}, PARAMS, backend="python")

    def compile_params(s, v):
        s.compile({**PARAMS, "k": v}, backend="python")

    def with_params(s, v):
        s.compile(PARAMS, backend="python").with_params({"k": v})

    def symbol_keyed(s, v):
        s.compile({sp.Symbol("m"): 1.0, sp.Symbol("k"): v}, backend="python")

    def sweep_grid(s, v):
        lg.sweep(s, {"k": [v]}, t_end=0.1, initial=INITIAL, params=PARAMS, workers=0, progress=False)

    def sweep_range(s, v):
        lg.sweep(s, {"k": v}, t_end=0.1, initial=INITIAL, params=PARAMS, workers=0, progress=False)

    def sweep_base(s, v):
        lg.sweep(s, {"m": [1.0]}, t_end=0.1, initial={**INITIAL, "x_dot": v}, params=PARAMS, workers=0,
                 progress=False)

    def linearize_about(s, v):
        lg.linearize(s, {"x": v})

    def equilibria_params(s, v):
        lg.equilibria(s, {"m": 1.0, "k": v})

    def modes_params(s, v):
        lg.normal_modes(s, {"m": 1.0, "k": v})

    def declared_energy(s, v):
        lg.System(list(s.coordinates), T=s.T, V=v)

    def declared_force(s, v):
        lg.System(list(s.coordinates), T=s.T, V=0, forces={s.coordinates[0]: v})

    def declared_constraint(s, v):
        lg.System(list(s.coordinates), T=s.T, V=0, constraints=[v])

    def particle_mass(s, v):
        lg.System(list(s.coordinates), bodies=[lg.Particle(v, (s.coordinates[0], 0))], V=0)

    return [simulate_params, simulate_initial, compile_params, with_params, symbol_keyed, sweep_grid, sweep_range,
            sweep_base, linearize_about, equilibria_params, modes_params, declared_energy, declared_force,
            declared_constraint, particle_mass]


ENTRIES = _entries()
#: CLI flags fed the hostile strings
CLI_FLAGS = (("simulate", "--param", "k"), ("simulate", "--initial", "x"), ("modes", "--about", "x"),
             ("modes", "--param", "k"))
CANARY_ENTRIES = len(ENTRIES) + len(CLI_FLAGS)


@pytest.mark.parametrize("entry", ENTRIES, ids=[e.__name__ for e in ENTRIES])
def test_hostile_value_is_not_evaluated(entry, canary):
    s = _oscillator()
    for value in _hostile(canary):
        _expect_refusal_or_number(lambda value=value: entry(s, value))
        assert not canary.exists(), f"{entry.__name__} evaluated {value!r}"


@pytest.mark.parametrize("entry", [simulate for simulate in ENTRIES[:5]], ids=[e.__name__ for e in ENTRIES[:5]])
def test_hostile_value_is_refused_with_a_clear_error(entry, canary):
    """Parameter and initial values: a LagrangeError (and ValueError) naming the value, not a number."""
    s = _oscillator()
    with pytest.raises(LagrangeError, match="__import__|not a number|cannot|not allowed|unknown") as info:
        entry(s, _hostile(canary)[0])
    assert isinstance(info.value, ValueError)


def test_numeric_strings_are_parsed_safely():
    """A string that is an expression of numbers is still accepted, through the spec parser."""
    s = _oscillator()
    model = s.compile({"m": "1", "k": "2*pi"}, backend="python")

    def values(m):
        return {p.name: v for p, v in zip(m.equations.parameters, m.params)}

    assert values(model) == pytest.approx({"m": 1.0, "k": 2 * np.pi})
    assert values(model.with_params({"k": "1/4"})) == pytest.approx({"m": 1.0, "k": 0.25})
    traj = s.simulate(0.5, {"x": "0.1", "x_dot": "0"}, {"m": 1, "k": "4"}, backend="python", rtol=1e-10,
                      atol=1e-12)
    assert traj.y[-1, 0] == pytest.approx(0.1 * np.cos(2 * 0.5), rel=1e-7)


@pytest.mark.parametrize("command, flag, name", CLI_FLAGS)
def test_cli_values_are_not_evaluated(command, flag, name, canary):
    for value in _hostile(canary)[:1]:
        args = [sys.executable, "-m", "lagrange.cli", command, "ex3.2", flag, f"{name}={value}"]
        if command == "simulate":
            args += ["--t-end", "0.1", "-q"]
        r = subprocess.run(args, capture_output=True, text=True, timeout=300)
        assert r.returncode != 0 and "Traceback" not in r.stderr, r.stderr[-2000:]
        assert "not a number" in r.stderr or "unknown" in r.stderr, r.stderr[-2000:]
