"""Linearization without a point: an equilibrium is found (never q = 0 blindly), and the choice is recorded."""

import logging

import numpy as np
import pytest
import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.analysis.equilibria import equilibria_near
from lagrange.analysis.small_oscillations import characteristic_roots, linearize, normal_modes
from lagrange.errors import AnalysisError, LagrangeError

SPRING = {"m": 1.0, "g": 9.81, "k": 40.0, "r0": 1.0}


def spring_pendulum():
    """A bob on a spring of free length r0 (Wells Ex. 3.4), θ from the downward vertical: no constraints."""
    r, th = coordinates("r theta")
    m, g, k, r0 = parameters("m g k r0")
    s = System([r, th], bodies=[Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
               V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2)
    return s, r, th, (m, g, k, r0)


def test_spring_pendulum_modes_at_the_equilibrium_found(caplog):
    s, r, th, _ = spring_pendulum()
    r_eq = SPRING["r0"] + SPRING["m"] * SPRING["g"] / SPRING["k"]
    with caplog.at_level(logging.INFO, logger="lagrange.analysis"):
        modes = normal_modes(s, SPRING)
    # closed forms: radial √(k/m), pendulum √(g/r_eq) about r_eq = r0 + m g/k
    assert modes.omega == pytest.approx(sorted([np.sqrt(SPRING["g"] / r_eq), np.sqrt(SPRING["k"] / SPRING["m"])]),
                                        rel=1e-12)
    assert "r = 1.24525, theta = 0 (stable" in caplog.text
    lin = linearize(s, params=SPRING)
    assert lin.about[r] == pytest.approx(r_eq, rel=1e-12) and lin.about[th] == 0.0
    assert "stable preferred" in lin.reference and "r = 0.75475, theta = -3.14159 (unstable)" in lin.reference
    assert len(lin.equilibria) == 2 and "about r = 1.24525" in repr(lin)
    roots = characteristic_roots(s, SPRING)
    assert np.max(np.abs(roots.real)) < 1e-9 and sorted(np.abs(roots.imag))[::2] == pytest.approx(modes.omega)


def test_symbolic_linearize_solves_for_the_equilibrium_instead_of_q0():
    s, r, th, (m, g, k, r0) = spring_pendulum()
    lin = linearize(s)  # q = 0 is not an equilibrium (the spring is compressed to zero length there)
    assert sp.simplify(lin.about[r] - (r0 + m * g / k)) == 0 and lin.about[th] == 0
    assert all(sp.simplify(e) == 0 for e in lin.forcing)  # an equilibrium: no constant force left
    assert sp.simplify(lin.c[1, 1] - m * g * (r0 + m * g / k)) == 0 and sp.simplify(lin.c[0, 0] - k) == 0
    assert "sympy solve" in lin.reference


def test_q0_is_kept_when_it_is_an_equilibrium():
    x = coordinates("x")
    m, k = parameters("m k")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)
    lin = linearize(s)
    assert lin.about == {x: 0} and lin.reference.endswith("(stability unknown; q = 0 is an equilibrium)")
    given = linearize(s, {x: 0})
    assert given.reference == "" and given.equilibria == ()


def test_two_equilibria_the_stable_one_is_chosen_and_both_reported():
    th = coordinates("theta")  # from the upward vertical: q = 0 is the unstable equilibrium
    m, g, l = parameters("m g l")
    s = System([th], bodies=[Particle(m, (l * sp.sin(th), l * sp.cos(th)))], V=m * g * l * sp.cos(th))
    P = {"m": 1.0, "g": 9.81, "l": 2.0}
    found = equilibria_near(s, P)
    assert [e[th] for e in found] == pytest.approx([0.0, np.pi]) or [e[th] for e in found] == pytest.approx(
        [0.0, -np.pi])  # one representative per angle, nearest first
    lin = linearize(s, params=P, near={"theta": 0.1})
    assert abs(lin.about[th]) == pytest.approx(np.pi, rel=1e-12)
    assert "(stable" in lin.reference and "theta = 0 (unstable)" in lin.reference
    assert normal_modes(lin).omega == pytest.approx([np.sqrt(9.81 / 2.0)], rel=1e-12)
    sym = linearize(s)  # symbolic: q = 0 is an equilibrium, kept (no numbers to judge stability)
    assert sym.about == {th: 0}


def test_an_equilibrium_away_from_zero_and_an_only_unstable_one():
    x = coordinates("x")
    m, k = parameters("m k")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=-k * x**2 / 2 + k * x**4 / 4 - k * x)
    P = {"m": 1.0, "k": 1.0}
    lin = linearize(s, params=P)  # V' = k(x³ − x − 1): one real root x* ≈ 1.3247, a minimum (V'' > 0)
    assert lin.about[x] == pytest.approx(1.324717957244746, rel=1e-12) and "(stable" in lin.reference
    hill = System([x], T=m * x.diff(t) ** 2 / 2, V=-k * x**2 / 2)
    lin = linearize(hill, params=P)
    assert lin.about == {x: 0.0} and "(unstable" in lin.reference
    with pytest.raises(LagrangeError, match=r"unstable equilibrium at x = 0"):
        normal_modes(lin)


def test_no_equilibrium_is_a_clear_refusal():
    x = coordinates("x")
    m, g = parameters("m g")
    falling = System([x], T=m * x.diff(t) ** 2 / 2, V=m * g * x)
    with pytest.raises(AnalysisError, match=r"no static equilibrium found near x = 0.*about=") as info:
        linearize(falling, params={"m": 1, "g": 9.81})
    assert isinstance(info.value, ValueError)
    with pytest.raises(AnalysisError, match=r"q = 0 \(x = 0\) is not an equilibrium.*about="):
        linearize(falling)
    with pytest.raises(AnalysisError, match="no static equilibrium"):
        normal_modes(falling, {"m": 1, "g": 9.81})


def test_free_coordinate_and_singular_messages_name_the_point():
    x, th = coordinates("x theta")
    M, m, l, g = parameters("M m l g")
    T = (M + m) * x.diff(t) ** 2 / 2 + m * l * x.diff(t) * th.diff(t) * sp.cos(th) + m * l**2 * th.diff(t) ** 2 / 2
    cart = System([x, th], T=T, V=m * g * l * sp.cos(th))
    P = {"M": 1.0, "m": 0.2, "l": 0.5, "g": 9.81}
    lin = linearize(cart, params=P, near={"x": 3.0})
    assert lin.about[x] == 3.0 and abs(lin.about[th]) == pytest.approx(np.pi) and "any value of x" in lin.reference
    w = np.sqrt((P["M"] + P["m"]) * P["g"] / (P["M"] * P["l"]))  # the hanging cart-pole
    assert normal_modes(lin).omega == pytest.approx([0.0, w], rel=1e-12, abs=1e-12)
    s, r, _, _ = spring_pendulum()
    with pytest.raises(AnalysisError) as info:
        linearize(s, {r: 0}, params=SPRING)  # r = 0: polar coordinates are singular
    assert "the mass matrix is singular at the reference state r = 0, theta = 0" in str(info.value)
    assert "constraint" not in str(info.value) and "about=" in str(info.value)
    with pytest.raises(TypeError, match="near="):
        linearize(s, {r: 1.2}, params=SPRING, near={"r": 1})


def test_constrained_pendulum_without_a_point():
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    P = {"m": 1.0, "g": 9.81, "l": 2.0}
    lin = linearize(s, params=P)  # q = 0 is off the circle (and singular): the search starts elsewhere too
    assert lin.about == {x: 0.0, y: -2.0} and lin.multipliers["string"] == pytest.approx(-9.81)
    assert normal_modes(lin).omega == pytest.approx([np.sqrt(9.81 / 2.0)], rel=1e-12)
    assert "x = 0, y = 2 (unstable)" in lin.reference


def test_constrained_symbolic_q0_on_the_manifold_but_not_an_equilibrium_is_refused():
    x, y = coordinates("x y")
    m, g = parameters("m g")
    incline = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y, constraints=[Holonomic(y - x, "slope")])
    with pytest.raises(AnalysisError, match=r"q = 0 \(x = 0, y = 0\) is not an equilibrium.*about="):
        linearize(incline)  # on the slope at q = 0, but sliding down
    level = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y ** 2, constraints=[Holonomic(y - x, "slope")])
    assert linearize(level).about == {x: 0, y: 0}  # q = 0 is an equilibrium there: kept


def test_bad_starting_points_are_refused_by_name():
    s, r, _, _ = spring_pendulum()
    for bad in ("__import__('os')", float("nan"), None):
        with pytest.raises(AnalysisError, match=r"starting value of r must be a finite number"):
            linearize(s, params=SPRING, near={"r": bad})
    with pytest.raises(AnalysisError, match=r"z is not a coordinate or constraint name \(valid: r, theta\)"):
        linearize(s, params=SPRING, near={"z": 1.0})


def test_a_time_dependent_drive_is_the_linear_models_forcing_not_part_of_the_statics():
    """A spring-mass driven by A sin ωt (Wells §1.9): without a point, symbolic linearization uses the equilibrium
    of the undriven system, q = 0, and keeps the drive as the forcing; a constant load is part of the statics:
    q = 0 is then no equilibrium, and the static deflection F0/k is found."""
    x = coordinates("x")
    m, k, A, w, F0 = parameters("m k A omega F0")
    driven = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, forces={x: A * sp.sin(w * t)})
    lin = linearize(driven)
    assert lin.about[x] == 0 and "without its time-dependent drive" in lin.reference
    assert sp.simplify(lin.c[0, 0] - k) == 0 and sp.simplify(lin.a[0, 0] - m) == 0
    loaded = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, forces={x: F0 + A * sp.sin(w * t)})
    lin = linearize(loaded)
    assert sp.simplify(lin.about[x] - F0 / k) == 0
