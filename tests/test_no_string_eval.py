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


class _Disguised:
    """Not a string, yet its text is the payload: older sympy parsed ``str(obj)`` of an object it did not know;
    lagrange refuses such a value with a LagrangeError (ExpressionTypeError, a TypeError) instead of passing
    it on."""

    def __init__(self, text):
        self.text = text

    def __str__(self):
        return self.text

    __repr__ = __str__


def _api_entries():
    """Every public constructor and function that takes an expression, a vector, a matrix or a mapping of
    values, with the payload ``v`` in one such argument: ``(name, call(v))``. A vector gets it as its first
    component, a matrix as its first entry, a mapping as a value."""
    from lagrange.model.rotations import rot_x, rot_y
    from lagrange.printing import format_expression, tidy_trig

    x, y = lg.coordinates("x y")
    m, k = lg.parameters("m k")
    osc = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)
    body = lg.RigidBody(1, (1, 1, 1), orientation=lg.rot_z(x))
    masses = lg.System([x], bodies=[lg.Particle(m, (x,))], V=k * x**2 / 2)

    def vec(v):
        return [v, 0, 0]

    def mat(v):
        return [[v, 0, 0], [0, 1, 0], [0, 0, 1]]

    def sys_with(v, **kw):
        return lg.System([x], **{"T": osc.T, "V": 0, **kw}).equations

    calls = {
        "rot_x": lambda v: rot_x(v), "rot_y": lambda v: rot_y(v), "rot_z": lambda v: lg.rot_z(v),
        "EulerAngles": lambda v: lg.EulerAngles(x, v, y).matrix,
        "Quaternion": lambda v: lg.Quaternion(v, x, y, 0).matrix,
        "RotationSequence": lambda v: lg.RotationSequence(("z", v)).matrix,
        "Ellipsoid": lambda v: lg.Ellipsoid(v, 1),
        "Ellipsoid.radius": lambda v: lg.WELLS_1924.radius(v),
        "EarthFrame": lambda v: lg.EarthFrame(v),
        "apparent_gravity": lambda v: lg.apparent_gravity(v),
        "Frame.rotation": lambda v: lg.Frame(rotation=mat(v)),
        "Frame.origin": lambda v: lg.Frame(origin=vec(v)),
        "Frame.point": lambda v: lg.Frame().point(vec(v)),
        "RigidBody.mass": lambda v: lg.RigidBody(v, (1, 1, 1)),
        "RigidBody.inertia": lambda v: lg.RigidBody(1, (v, 1, 1)),
        "RigidBody.inertia_matrix": lambda v: lg.RigidBody(1, sp.Matrix(mat(1)).subs(1, 1).tolist() and mat(v)),
        "RigidBody.orientation": lambda v: lg.RigidBody(1, (1, 1, 1), orientation=mat(v)),
        "RigidBody.origin": lambda v: lg.RigidBody(1, (1, 1, 1), origin=vec(v)),
        "RigidBody.com": lambda v: lg.RigidBody(1, (1, 1, 1), com=vec(v)),
        "RigidBody.point": lambda v: body.point(vec(v)),
        "Inertia": lambda v: lg.Inertia(v, 1, 1),
        "Inertia.rotated": lambda v: lg.Inertia(1, 1, 1).rotated(mat(v)),
        "Particle.mass": lambda v: lg.Particle(v, (x, 0)),
        "Particle.position": lambda v: lg.Particle(1, (v, 0)),
        "MaterialPoint": lambda v: lg.MaterialPoint(body, vec(v)),
        "Force": lambda v: lg.Force(body.point((1, 0, 0)), vec(v)),
        "Torque": lambda v: lg.Torque(body, vec(v)),
        "Holonomic": lambda v: lg.Holonomic(v),
        "Nonholonomic": lambda v: lg.Nonholonomic(v),
        "Differential": lambda v: lg.Differential({x: v}),
        "Rough": lambda v: lg.Rough(x, v, x.diff(t)),
        "System.T": lambda v: sys_with(v, T=v),
        "System.P": lambda v: sys_with(v, P=v),
        "System.rayleigh": lambda v: sys_with(v, rayleigh=v),
        "delta": lambda v: lg.delta(v),
        "euler_lagrange": lambda v: lg.euler_lagrange(v, [x], t),
        "expand_potential": lambda v: lg.expand_potential(v, {x: 0}),
        "expand_potential.about": lambda v: lg.expand_potential(k * x**2, {x: v}),
        "is_conservative": lambda v: lg.is_conservative([v], [x]),
        "potential_of": lambda v: lg.potential_of([v], [x]),
        "work_along": lambda v: lg.work_along([k * x], [x], [v]),
        "to_symbols": lambda v: lg.to_symbols(v, [x]),
        "to_functions": lambda v: lg.to_functions(v, [x]),
        "latex": lambda v: lg.latex(v),
        "tidy_trig": lambda v: tidy_trig(v),
        "format_expression": lambda v: format_expression(v),
        "check_gauss": lambda v: lg.check_gauss(masses, {"m": v, "k": 1}, samples=1),
        "pretty": lambda v: lg.pretty(v),
        "linearize.about": lambda v: lg.linearize(osc, {x: v}),
        "driving_forces": lambda v: lg.driving_forces(osc, {x: v}),
        "actuator_forces": lambda v: lg.actuator_forces(osc, v, [k]),
        "static_equilibrium": lambda v: lg.static_equilibrium(osc, [x], {"m": 1, "k": v}),
        "eliminate": lambda v: lg.eliminate(lg.System([x, y], T=osc.T, V=0), {y: v}),
        "support_loads.force": lambda v: lg.support_loads(body, vec(v)),
        "support_loads.torque": lambda v: lg.support_loads(body, (0, 0, 0), vec(v)),
        "characteristic_roots": lambda v: lg.characteristic_roots(lg.linearize(osc, {x: 0}), {"m": v, "k": 1}),
    }
    return list(calls.items())


API_ENTRIES = _api_entries()
CANARY_ENTRIES = len(ENTRIES) + len(CLI_FLAGS) + len(API_ENTRIES)


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


@pytest.mark.parametrize("name, call", API_ENTRIES, ids=[n for n, _ in API_ENTRIES])
def test_public_api_never_evaluates_a_string(name, call, canary):
    """Each public constructor and function that takes expressions: a code-running string (or an object whose
    text is one) is read by the spec parser or refused with a LagrangeError; it never runs."""
    for value in _hostile(canary):
        try:
            call(value)
        except LagrangeError:
            pass
        assert not canary.exists(), f"{name} evaluated {value!r}"
    if name in ("latex", "pretty"):  # printers typeset any object's text as text; they convert nothing
        assert "import" in call(_Disguised(_hostile(canary)[0])) and not canary.exists()
    else:
        with pytest.raises(LagrangeError):
            call(_Disguised(_hostile(canary)[0]))


def test_public_api_still_takes_strings_of_numbers():
    """The quiet side: a string that is an expression of numbers is read as that number where an expression
    is expected."""
    x = lg.coordinates("x")
    assert lg.rot_z("pi/2") == lg.rot_z(sp.pi / 2)
    assert lg.EulerAngles(x, "1/2", 0).theta == sp.Rational(1, 2)
    assert lg.Frame(rotation=[["1", 0, 0], [0, 1, 0], [0, 0, 1]]).rotation == sp.eye(3)
    assert lg.RigidBody(1, (1, 1, 1), orientation=[["1", 0, 0], [0, 1, 0], [0, 0, 1]]).R == sp.eye(3)
    assert lg.Ellipsoid("2", 1).a == 2
    assert lg.Holonomic("0").expr == 0


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


# --- names of user functions and symbols never become code (lagrange.safe_sympify.lambdify) ---------------------

def _evil_function(canary):
    return sp.Function(f"__import__('os').system('touch {canary}') or (lambda *a: 0)")


def test_control_lambdify_prints_a_function_name_as_code(tmp_path):
    """The payload is potent: sympy's own lambdify prints an undefined function's name into the code it runs
    (in a child process)."""
    canary = tmp_path / "control"
    code = (f"import sympy as sp\nt = sp.Symbol('t')\nf = sp.Function({_evil_function(canary).__name__!r})\n"
            "sp.lambdify(t, f(t), 'math')(0.0)")
    subprocess.run([sys.executable, "-c", code], check=False, timeout=120, capture_output=True)
    assert canary.exists()


@pytest.mark.parametrize("which", ["hostile", "plain"])
def test_input_value_with_an_undefined_function_is_refused(which, canary):
    """An input's value holding an undefined function (a hostile name, or just ``f``) is refused with a
    LagrangeError naming the function; nothing runs."""
    x = lg.coordinates("x")
    m, k = lg.parameters("m k")
    u = lg.inputs("u")
    s = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, forces={x: u})
    f = _evil_function(canary) if which == "hostile" else sp.Function("f")
    with pytest.raises(LagrangeError, match="undefined function") as info:
        s.simulate(0.1, INITIAL, PARAMS, inputs={"u": f(t)}, backend="python")
    assert isinstance(info.value, TypeError) and f.__name__ in str(info.value)


def test_input_value_expression_still_runs():
    """The quiet side: an input given as an expression of t runs, and matches the same input as a callable."""
    x = lg.coordinates("x")
    m, k = lg.parameters("m k")
    u = lg.inputs("u")
    s = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, forces={x: u})
    opts = {"backend": "python", "rtol": 1e-10, "atol": 1e-12}
    a = s.simulate(1.0, INITIAL, PARAMS, inputs={"u": sp.sin(3 * t)}, **opts)
    b = s.simulate(1.0, INITIAL, PARAMS, inputs={"u": lambda tt: np.sin(3 * tt)}, **opts)
    assert np.allclose(a.y[-1], b.y[-1], rtol=1e-8, atol=1e-10)


def test_hostile_symbol_names_are_renamed_in_generated_code(canary):
    """A parameter whose name is code is only a name: the generated code refers to it by position, and the
    run gives the oscillator's closed form."""
    x = lg.coordinates("x")
    name = f"__import__('os').system('touch {canary}')"
    m, k = sp.Symbol("m", positive=True), sp.Symbol(name, positive=True)
    s = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)
    traj = s.simulate(0.5, INITIAL, {"m": 1.0, name: 4.0}, backend="python", rtol=1e-10, atol=1e-12)
    assert traj.y[-1, 0] == pytest.approx(0.1 * np.cos(2 * 0.5), rel=1e-7)


def test_safe_lambdify_refuses_loose_and_undefined_names(canary):
    """The helper every numeric evaluation of a user expression goes through: arguments with any name work
    (they are replaced by dummies); a symbol that is not an argument, or an undefined function, is refused
    before code is generated."""
    from lagrange.errors import ExpressionTypeError
    from lagrange.safe_sympify import lambdify

    evil = sp.Symbol(f"__import__('os').system('touch {canary}')")
    y = sp.Symbol("y")
    assert lambdify([evil], evil**2 + 1, "math")(3.0) == 10.0
    shadow = sp.Symbol("sin")  # an argument named like a function of the namespace means only the argument
    assert lambdify([shadow, y], sp.sin(y) * shadow, "math")(2.0, 0.5) == pytest.approx(2.0 * np.sin(0.5))
    with pytest.raises(ExpressionTypeError, match="no value"):
        lambdify([y], y + evil, "math")
    with pytest.raises(ExpressionTypeError, match="undefined function"):
        lambdify([y], _evil_function(canary)(y), "math")
