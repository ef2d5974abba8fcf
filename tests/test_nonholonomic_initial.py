"""Initial states of constrained systems: the speeds left out are computed from the velocity constraints, and a
value the user gave is never changed silently (an :class:`InitialStateChangedWarning` names each change).

Truths used: the closed form of a disc rolling upright at a constant spin (x = rΩ cos ψ t, y = rΩ sin ψ t),
the least-norm projection written out by hand, the stability threshold Ω² > g/(3r) of a rolling disc, and the
residual A q̇ + b of the completed speeds.
"""

from __future__ import annotations

import textwrap
import warnings

import numpy as np
import pytest
import sympy as sp

from lagrange import (
    Holonomic,
    InitialConditionError,
    InitialStateChangedWarning,
    Nonholonomic,
    Particle,
    Stabilization,
    System,
    characteristic_roots,
    coordinates,
    linearize,
    parameters,
    t,
)
from lagrange.cli import main
from lagrange.integrate.constrained import complete_speeds, pivot_columns
from lagrange.simplification import is_zero

P = {"m": 1.0, "g": 9.81, "r": 0.3}
SPIN = 15.0


def moves(message) -> str:
    """The list of changed values in an InitialStateChangedWarning."""
    return str(message).split("changing given values: ")[1].split(". Give")[0]


def rolling_disc():
    """Thin uniform disc rolling on a plane: contact point x, y; heading q1, lean q2 (0 upright), spin q3."""
    x, y, q1, q2, q3 = coordinates("x y q1 q2 q3")
    m, g, r = parameters("m g r")
    xd, yd, q1d, q2d, q3d = (c.diff(t) for c in (x, y, q1, q2, q3))
    s1, c1, s2, c2 = sp.sin(q1), sp.cos(q1), sp.sin(q2), sp.cos(q2)
    vc = (xd + r * (c2 * s1 * q2d + s2 * c1 * q1d), yd + r * (s2 * s1 * q1d - c2 * c1 * q2d), -r * s2 * q2d)
    T = (m / 2 * sum(v**2 for v in vc)
         + sp.Rational(1, 2) * (m * r**2 / 4 * (q2d**2 + (q1d * c2) ** 2) + m * r**2 / 2 * (q1d * s2 + q3d) ** 2))
    return System([x, y, q1, q2, q3], T=T, V=m * g * r * c2,
                  constraints=[Nonholonomic(xd - r * c1 * q3d, name="roll x"),
                               Nonholonomic(yd - r * s1 * q3d, name="roll y")])


@pytest.fixture(scope="module")
def disc():
    return rolling_disc()


def independent(disc, heading=0.4):
    """Upright rolling at SPIN with heading ψ: the coordinates and the independent speeds only."""
    x, y, q1, q2, q3 = disc.coordinates
    return {x: 0.0, y: 0.0, q1: heading, q2: 0.0, q3: 0.0, q1.diff(t): 0.0, q2.diff(t): 0.0, q3.diff(t): SPIN}


def test_dependent_speeds_are_computed_and_the_spin_is_kept(disc):
    x, y, q1, q2, q3 = disc.coordinates
    psi, r = 0.4, P["r"]
    with warnings.catch_warnings():
        warnings.simplefilter("error", InitialStateChangedWarning)
        sol = disc.simulate(1.0, independent(disc, psi), P, rtol=1e-11, atol=1e-12)
    y0 = sol.initial[1]
    assert y0[9] == SPIN  # the given spin, exactly
    assert y0[5] == pytest.approx(r * SPIN * np.cos(psi), rel=1e-14)
    assert y0[6] == pytest.approx(r * SPIN * np.sin(psi), rel=1e-14)
    assert set(sol.initial_adjustments) == {"x_dot", "y_dot"}
    assert sol.initial_adjustments["x_dot"][0] is None  # computed, not given
    assert sol.max_constraint_violation() < 1e-12
    # steady upright rolling (closed form): a straight line at speed rΩ, the spin constant
    assert np.allclose(sol[x], r * SPIN * np.cos(psi) * sol.t, atol=1e-8)
    assert np.allclose(sol[y], r * SPIN * np.sin(psi) * sol.t, atol=1e-8)
    assert np.allclose(sol[q3], SPIN * sol.t, atol=1e-8)
    assert np.max(np.abs(sol[q2])) < 1e-9


def test_consistent_full_state_is_taken_unchanged_without_warning(disc):
    x, y, q1, q2, q3 = disc.coordinates
    psi, r = 0.4, P["r"]
    full = {**independent(disc, psi), x.diff(t): r * SPIN * np.cos(psi), y.diff(t): r * SPIN * np.sin(psi)}
    with warnings.catch_warnings():
        warnings.simplefilter("error", InitialStateChangedWarning)
        sol = disc.simulate(0.2, full, P)
    assert sol.initial_adjustments == {}
    assert list(sol.initial[1]) == [full[k] for k in (x, y, q1, q2, q3)] + [
        full[c.diff(t)] for c in (x, y, q1, q2, q3)]


def test_inconsistent_over_specified_state_warns_naming_each_change(disc):
    """ẋ = ẏ = 0 given with the spin 15 (heading 0): the least-norm projection onto roll x, ẋ − rΩ = 0 (row
    a = [1, 0, 0, 0, −r], residual g = −rΩ) moves q̇ by −aᵀg/(a·a): ẋ → rΩ/(1 + r²), Ω → Ω − r²Ω/(1 + r²)."""
    x, y, q1, q2, q3 = disc.coordinates
    r = P["r"]
    bad = {**independent(disc, 0.0), x.diff(t): 0.0, y.diff(t): 0.0}
    xd, spin = r * SPIN / (1 + r**2), SPIN - r**2 * SPIN / (1 + r**2)
    with pytest.warns(InitialStateChangedWarning, match=r"roll x: A q̇ \+ b = -4.5.*x_dot 0 → 4.12844.*"
                                                        r"q3_dot 15 → 13.7614") as rec:
        sol = disc.simulate(0.2, bad, P)
    assert moves(rec[0].message) == "x_dot 0 → 4.128440367, q3_dot 15 → 13.76146789"  # only the changed ones
    assert sol.initial_adjustments["x_dot"] == (0.0, pytest.approx(xd, rel=1e-13))
    assert sol.initial_adjustments["q3_dot"] == (SPIN, pytest.approx(spin, rel=1e-13))
    assert sol.initial_constraint_violation["roll x"] == (0.0, pytest.approx(-r * SPIN))
    assert sol.max_constraint_violation() < 1e-12
    with pytest.raises(InitialConditionError, match="roll x: A q̇ \\+ b = -4.5"):
        disc.simulate(0.2, bad, P, stabilization=Stabilization(project_initial=False))


def test_a_speed_the_constraints_do_not_determine_is_missing(disc):
    q1 = disc.coordinates[2]
    partial = {k: v for k, v in independent(disc).items() if k != q1.diff(t)}
    with pytest.raises(InitialConditionError, match="missing initial value.*q1_dot.*determine only x_dot, y_dot"):
        disc.simulate(0.2, partial, P)
    x = coordinates("x")
    free = System([x], bodies=[Particle(parameters("m"), (x,))])  # unconstrained: every speed is required
    with pytest.raises(InitialConditionError, match="missing initial value.*x_dot"):
        free.simulate(0.2, {x: 0.0}, {"m": 1.0})


def pendulum():
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    return s, x, y


def test_holonomic_speed_computed_and_a_moved_coordinate_warns():
    s, x, y = pendulum()
    PP = {"m": 1.0, "g": 9.81, "l": 1.0}
    with warnings.catch_warnings():
        warnings.simplefilter("error", InitialStateChangedWarning)
        sol = s.simulate(0.1, {x: 0.6, y: -0.8, x.diff(t): 1.0}, PP)  # ẏ from x ẋ + y ẏ = 0
    assert sol.initial[1][3] == pytest.approx(0.75, rel=1e-14)
    assert sol.initial_adjustments == {"y_dot": (None, pytest.approx(0.75, rel=1e-14))}
    # a coordinate off the constraint: moved radially onto the circle (x 1.05 → 1), with a warning
    with pytest.warns(InitialStateChangedWarning, match=r"string: φ = 0.05.*x 1.05 → 1\b") as rec:
        sol = s.simulate(0.1, {x: 1.05, y: 0.0, x.diff(t): 0.0, y.diff(t): 0.2}, PP)
    assert moves(rec[0].message) == "x 1.05 → 1"  # y = 0 and the speeds did not move
    assert sol.initial_adjustments == {"x": (1.05, pytest.approx(1.0, rel=1e-14))}
    # at the centre the constraint's Jacobian (x, y)/sqrt(x² + y²) is not finite: nothing can be computed
    with pytest.raises(InitialConditionError, match="y_dot.*not finite at the initial positions"):
        s.simulate(0.1, {x: 0.0, y: 0.0, x.diff(t): 1.0}, {**PP, "l": 0.0})


@pytest.mark.parametrize("spin", [0.5, 3.0, np.sqrt(9.81 / 0.9) * 0.999, np.sqrt(9.81 / 0.9) * 1.001, 15.0])
def test_characteristic_roots_with_only_the_spin_given(disc, spin):
    """Upright rolling, spin Ω given alone (ẋ = rΩ computed): λ² = (4/5)(g/r − 3Ω²); stable iff Ω² > g/(3r)."""
    q3 = disc.coordinates[4]
    roots = characteristic_roots(disc, P, velocities={q3.diff(t): spin})
    lam = np.sqrt(complex(0.8 * (P["g"] / P["r"] - 3 * spin**2)))
    big = roots[np.argsort(-np.abs(roots))][:2]
    assert np.sort_complex(big) == pytest.approx(np.sort_complex(np.array([-lam, lam])), rel=1e-9)
    assert (np.max(roots.real) < 1e-6) == (spin**2 > P["g"] / (3 * P["r"]))


def test_linearize_reports_the_computed_speeds_numeric_and_symbolic(disc):
    x, y, q1, q2, q3 = disc.coordinates
    lin = linearize(disc, {q1: 0.4}, velocities={q3.diff(t): SPIN}, params=P)
    assert lin.velocities[x.diff(t)] == pytest.approx(P["r"] * SPIN * np.cos(0.4), rel=1e-14)
    assert lin.velocities[y.diff(t)] == pytest.approx(P["r"] * SPIN * np.sin(0.4), rel=1e-14)
    W, lam = sp.symbols("Omega lambda")
    r, g = parameters("r g")
    sym = linearize(disc, {q3.diff(t): W})
    assert is_zero(sym.velocities[x.diff(t)] - r * W)
    assert is_zero(sym.characteristic_polynomial(lam) - lam**6 * (lam**2 - sp.Rational(4, 5) * (g / r - 3 * W**2)))


def test_pivot_rule_and_completion_against_the_residual():
    rng = np.random.default_rng(5)
    J = np.array([[1.0, 2.0, 0.0, 0.0], [2.0, 4.0, 0.0, 0.0]])  # rank 1: one column, the last usable one
    assert pivot_columns(J) == [1]
    for _ in range(20):
        A, b, qd = rng.normal(size=(2, 5)), rng.normal(size=2), rng.normal(size=5)
        given = [True, False, True, False, False]
        done, dep, undetermined = complete_speeds(A, b, qd, given)
        assert len(dep) == 2 and len(undetermined) == 1 and not set(dep) & {0, 2}
        assert np.max(np.abs(A @ done + b)) < 1e-12  # the constraints hold
        assert done[0] == qd[0] and done[2] == qd[2] and done[undetermined[0]] == qd[undetermined[0]]


DISC_SPEC = '''
import sympy as sp
from lagrange import Nonholonomic, System, coordinates, parameters, t
x, y, q1, q2, q3 = coordinates("x y q1 q2 q3")
m, g, r = parameters("m g r")
xd, yd, q1d, q2d, q3d = (c.diff(t) for c in (x, y, q1, q2, q3))
s1, c1, s2, c2 = sp.sin(q1), sp.cos(q1), sp.sin(q2), sp.cos(q2)
vc = (xd + r * (c2 * s1 * q2d + s2 * c1 * q1d), yd + r * (s2 * s1 * q1d - c2 * c1 * q2d), -r * s2 * q2d)
T = (m / 2 * sum(v**2 for v in vc)
     + sp.Rational(1, 2) * (m * r**2 / 4 * (q2d**2 + (q1d * c2) ** 2) + m * r**2 / 2 * (q1d * s2 + q3d) ** 2))
system = System([x, y, q1, q2, q3], T=T, V=m * g * r * c2,
                constraints=[Nonholonomic(xd - r * c1 * q3d, name="roll x"),
                             Nonholonomic(yd - r * s1 * q3d, name="roll y")])
params = {"m": 1.0, "g": 9.81, "r": 0.3}
initial = {"x": 0, "y": 0, "q1": 0, "q2": 0, "q3": 0, "q1_dot": 0, "q2_dot": 0, "q3_dot": 10}
t_end = 0.5
'''


def test_cli_initial_gives_only_the_independent_speeds(tmp_path, capsys):
    path = tmp_path / "disc.py"
    path.write_text(textwrap.dedent(DISC_SPEC))
    status = main(["simulate", str(path), "-q", "--initial", f"q3_dot={SPIN}", "--no-progress"])
    out = capsys.readouterr().out
    assert status == 0
    line = next(ln for ln in out.splitlines() if ln.startswith("state at t="))
    end = {k: float(v) for k, v in (kv.split("=") for kv in line.split(": ", 1)[1].split(", "))}
    assert end["q3_dot"] == pytest.approx(SPIN, rel=1e-9) and end["x_dot"] == pytest.approx(0.3 * SPIN, rel=1e-9)
    assert end["x"] == pytest.approx(0.3 * SPIN * 0.5, rel=1e-8)
    with pytest.warns(InitialStateChangedWarning, match="q3_dot 15 → 13.76"):
        status = main(["simulate", str(path), "-q", "--initial", f"q3_dot={SPIN}", "--initial", "x_dot=0",
                       "--no-progress"])
    assert status == 0


def test_sweep_over_the_spin_with_only_the_independent_speeds(disc):
    from lagrange import sweep

    q3 = disc.coordinates[4]
    ini = {k: v for k, v in independent(disc, 0.0).items() if k != q3.diff(t)}
    table = sweep(disc, {"q3_dot": [5.0, 10.0]}, t_end=0.2, initial={**ini, q3.diff(t): 1.0}, params=P, workers=0)
    assert list(table["status"]) == ["ok", "ok"]
    assert list(table["final_x_dot"]) == pytest.approx([P["r"] * 5.0, P["r"] * 10.0], rel=1e-9)
    assert list(table["final_x"]) == pytest.approx([P["r"] * 5.0 * 0.2, P["r"] * 10.0 * 0.2], rel=1e-8)
