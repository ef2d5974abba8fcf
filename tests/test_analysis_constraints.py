"""Analysis on the constraint manifold: linearization, modes, roots and equilibria of constrained systems.

Every result is compared with an independent truth: the same system in other (unconstrained) coordinates, a
closed form, or the textbook linearization; refusals are checked to name what is unsupported.
"""

import numpy as np
import pytest
import sympy as sp

from lagrange import (
    AnalysisError,
    Holonomic,
    LagrangeError,
    Nonholonomic,
    Particle,
    Rough,
    System,
    characteristic_roots,
    coordinates,
    eliminate,
    equilibria,
    hamiltonian,
    linearize,
    normal_modes,
    parameters,
    routhian,
    t,
)
from lagrange.examples import n_link_pendulum
from lagrange.simplification import is_zero

PEND = {"m": 1.3, "g": 9.81, "l": 2.0}


def cartesian_pendulum():
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    return s, x, y, (m, g, l)


def assert_same_roots(r1, r2, tol):
    """Equal multisets of roots (each root of r1 matched to the nearest unused root of r2)."""
    left = list(r2)
    for r in r1:
        k = int(np.argmin([abs(r - x) for x in left]))
        assert abs(r - left[k]) <= tol * max(1.0, abs(r)), (r1, r2)
        left.pop(k)


# ------------------------------------------------------------------------------------- Cartesian pendulum


def test_cartesian_pendulum_frequency_symbolic_and_numeric():
    """Regression: the frequencies were [0, 0]; on the manifold there is one, sqrt(g/l)."""
    s, x, y, (m, g, l) = cartesian_pendulum()
    lin = linearize(s, {x: 0, y: -l})
    assert lin.coordinates == (x,) and lin.speeds == (x.diff(t),)
    assert lin.a.shape == (1, 1) and is_zero(lin.c[0, 0] / lin.a[0, 0] - g / l)
    assert lin.b[0, 0] == 0
    modes = normal_modes(lin, PEND)
    assert modes.omega == pytest.approx([np.sqrt(9.81 / 2.0)], rel=1e-13)
    assert modes.full_shapes[1, 0] == pytest.approx(0.0, abs=1e-14)  # y does not move to first order
    numeric = normal_modes(s, PEND, about={x: 0, y: -2.0})
    assert numeric.omega == pytest.approx([np.sqrt(9.81 / 2.0)], rel=1e-13)
    assert "independent coordinates (x)" in repr(lin)


def test_cartesian_pendulum_equilibria_and_tension():
    """Regression: equilibria returned []. Both are found, with λ: the tension −λ (README: for a string
    φ = r − l the tension is −λ) is m g at the bottom; the top is unstable with roots ±sqrt(g/l)."""
    s, x, y, (m, g, l) = cartesian_pendulum()
    sols = equilibria(s)
    assert {(e[x], e[y]) for e in sols} == {(0, -l), (0, l)}
    bottom = next(e for e in sols if e[y] == -l)
    top = next(e for e in sols if e[y] == l)
    assert is_zero(-bottom.multipliers["string"] - m * g)
    assert is_zero(-top.multipliers["string"] + m * g)  # at the top the rod pushes: negative tension
    num = equilibria(s, PEND, {x: 0.3, y: -1.7})
    assert num[x] == pytest.approx(0, abs=1e-10) and num[y] == pytest.approx(-2.0)
    assert -num.multipliers["string"] == pytest.approx(1.3 * 9.81)
    roots = characteristic_roots(s, PEND, about={"x": 0, "y": 2.0})
    assert roots == pytest.approx([-np.sqrt(9.81 / 2), np.sqrt(9.81 / 2)], rel=1e-12)
    with pytest.raises(LagrangeError, match="unstable"):
        normal_modes(s, PEND, about={"y": 2.0})


def test_reference_state_off_the_manifold_is_refused_with_the_residual():
    s, x, y, (m, g, l) = cartesian_pendulum()
    with pytest.raises(AnalysisError, match=r"string: φ = -0\.956"):
        linearize(s, {x: 0.3, y: -1.0}, params=PEND)
    with pytest.raises(AnalysisError, match="string: A q̇ \\+ b"):
        linearize(s, {x: 0, y: -2.0, "y_dot": 0.5}, params=PEND)
    with pytest.raises(AnalysisError, match="string: φ = -l"):
        linearize(s)  # the default q = 0 is not on the circle
    with pytest.raises(AnalysisError, match=r"unknown name\(s\).*z.*valid: x, y, x_dot, y_dot"):
        linearize(s, {"z": 1}, params=PEND)
    with pytest.raises(AnalysisError, match=r"\(y\) cannot be the independent coordinates here"):
        linearize(s, {x: 0, y: -2.0}, params={"m": 1, "g": 1, "l": 2}, independent=[y])
    redundant = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
                       constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "a"), Holonomic(x**2 + y**2 - l**2, "b")])
    with pytest.raises(AnalysisError, match="redundant or singular"):
        linearize(redundant, {x: 0, y: -2.0}, params=PEND)


# --------------------------------------------------------------------------------------- double pendulum


def _double_pendulum_cartesian(tilt=0):
    """Gravity along −(sin tilt, cos tilt)."""
    x1, y1, x2, y2 = coordinates("x1 y1 x2 y2")
    m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
    sa, ca = sp.sin(tilt), sp.cos(tilt)
    return System([x1, y1, x2, y2], bodies=[Particle(m1, (x1, y1)), Particle(m2, (x2, y2))],
                  V=g * (m1 * (sa * x1 + ca * y1) + m2 * (sa * x2 + ca * y2)),
                  constraints=[Holonomic(sp.sqrt(x1**2 + y1**2) - l1, "rod 1"),
                               Holonomic(sp.sqrt((x2 - x1) ** 2 + (y2 - y1) ** 2) - l2, "rod 2")])


DP = {"m1": 1.0, "m2": 0.7, "l1": 1.2, "l2": 0.8, "g": 9.81}


def test_double_pendulum_cartesian_matches_angles():
    cart = _double_pendulum_cartesian()
    x1, y1, x2, y2 = cart.coordinates
    angles = n_link_pendulum(2, symbolic=True)
    ref = normal_modes(linearize(angles), DP).omega
    about = {x1: 0, y1: -DP["l1"], x2: 0, y2: -DP["l1"] - DP["l2"]}
    lin = linearize(cart, about, params=DP)
    assert lin.coordinates == (x1, x2)
    modes = normal_modes(lin)
    assert modes.omega == pytest.approx(ref, rel=1e-12)
    # mode shapes in all coordinates: the bobs move horizontally only, first order
    assert np.max(np.abs(modes.full_shapes[[1, 3], :])) < 1e-14


@pytest.mark.slow
def test_double_pendulum_symbolic_route_matches_numeric_route():
    """Exact derivatives both ways: symbolic a, b, c evaluated = the numeric (complex-step) route, to rounding."""
    cart = _double_pendulum_cartesian()
    x1, y1, x2, y2 = cart.coordinates
    l1, l2 = parameters("l1 l2")
    sym = linearize(cart, {x1: 0, y1: -l1, x2: 0, y2: -l1 - l2})
    num = linearize(cart, {x1: 0, y1: -DP["l1"], x2: 0, y2: -DP["l1"] - DP["l2"]}, params=DP)
    for a, b in zip(num.numeric(), sym.numeric(DP)):
        assert np.allclose(a, b, rtol=1e-13, atol=1e-13)
    assert np.allclose(num.numeric_state()[0], sym.numeric_state(DP)[0], rtol=1e-13, atol=1e-13)


def test_double_pendulum_tilted_gravity_any_choice_of_independent_coordinates():
    """Gravity along −(sin a, cos a): the chain hangs tilted, both x and y of each bob vary to first order, and
    every admissible choice of independent coordinates gives the frequencies of the angles version."""
    tilted = _double_pendulum_cartesian(sp.Rational(2, 5))
    x1, y1, x2, y2 = tilted.coordinates
    a = 0.4
    ref = normal_modes(linearize(n_link_pendulum(2, symbolic=True)), DP).omega
    L1, L2 = DP["l1"], DP["l1"] + DP["l2"]
    about = {x1: -L1 * np.sin(a), y1: -L1 * np.cos(a), x2: -L2 * np.sin(a), y2: -L2 * np.cos(a)}
    for choice in (None, [y1, y2], ["x1", "y2"], [x1, x2]):
        modes = normal_modes(tilted, DP, about=about, independent=choice)
        assert modes.omega == pytest.approx(ref, rel=1e-11)
    with pytest.raises(AnalysisError, match="2 independent coordinates are needed"):
        linearize(tilted, about, params=DP, independent=[x1])


# ------------------------------------------------------------------------------------ bead on a rotating hoop


def _hoop():
    rho, z = coordinates("rho z")
    m, g, R, w = parameters("m g R omega")
    T = m / 2 * (rho.diff(t) ** 2 + z.diff(t) ** 2 + w**2 * rho**2)  # in the frame turning with the hoop
    return System([rho, z], T=T, V=m * g * z, constraints=[Holonomic(sp.sqrt(rho**2 + z**2) - R, "hoop")])


HOOP = {"m": 0.5, "g": 9.81, "R": 0.6, "omega": 6.0}


def test_bead_on_rotating_hoop_constrained_vs_eliminated():
    s = _hoop()
    rho, z = s.coordinates
    R, g, w = HOOP["R"], HOOP["g"], HOOP["omega"]
    reduced = eliminate(s, {z: -sp.sqrt(parameters("R") ** 2 - rho**2)})
    th0 = np.arccos(g / (R * w**2))  # the off-axis relative equilibrium (w² > g/R)
    eq = equilibria(s, HOOP, {rho: 0.5, z: -0.3})
    assert eq[rho] == pytest.approx(R * np.sin(th0), rel=1e-10) and eq[z] == pytest.approx(-R * np.cos(th0))
    about = {rho: eq[rho], z: eq[z]}
    constrained = normal_modes(s, HOOP, about=about).omega
    elim = normal_modes(reduced, HOOP, about={rho: eq[rho]}).omega
    closed = w * np.sin(th0)  # ω_small = Ω sin θ0
    assert constrained == pytest.approx([closed], rel=1e-9) and elim == pytest.approx([closed], rel=1e-9)
    other = normal_modes(s, HOOP, about=about, independent=[z]).omega
    assert other == pytest.approx([closed], rel=1e-9)
    # at the bottom the point is unstable when Ω² > g/R: roots ±sqrt(Ω² − g/R)
    roots = characteristic_roots(s, HOOP, about={rho: 0, z: -R})
    assert roots.real == pytest.approx([-np.sqrt(w**2 - g / R), np.sqrt(w**2 - g / R)], rel=1e-12)


# ------------------------------------------------------------------------------------------ rolling disc


def _rolling_disc():
    """Thin uniform disc rolling on a plane: contact point x, y; yaw q1, lean q2 (0 upright), spin q3."""
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
    return _rolling_disc()


def disc_closed_form(spin, g=1.0, r=1.0):
    """Upright rolling at spin Ω: with A = m r²/2 (axial), C = m r²/4, yaw C ψ̈ = −A Ω θ̇ and lean
    (C + m r²) θ̈ = m g r θ − (A + m r²) Ω ψ̇ give λ² = (m g r − (A + m r²) A Ω²/C)/(C + m r²)
    = (4/5)(g/r − 3Ω²), and six zero roots (x, y, yaw, spin angle, spin rate, the yaw integral)."""
    return np.sqrt(complex(0.8 * (g / r - 3 * spin**2)))


@pytest.mark.parametrize("spin", [0.0, 0.3, 1 / np.sqrt(3), 0.9, 2.0])
def test_rolling_disc_roots_match_the_closed_form(disc, spin):
    """Regression: at the critical spin 1/sqrt(3) every root is 0; it was reported unstable (±1.633)."""
    x, y, q1, q2, q3 = disc.coordinates
    P = {"m": 1.7, "g": 1.0, "r": 1.0}
    roots = characteristic_roots(disc, P, about={q3.diff(t): spin, x.diff(t): spin})
    assert roots.shape == (8,)  # 5 coordinates + 3 independent speeds
    lam = disc_closed_form(spin)
    big = roots[np.argsort(-np.abs(roots))][:2]
    small = roots[np.argsort(-np.abs(roots))][2:]
    if abs(lam) > 1e-6:
        assert np.sort_complex(big) == pytest.approx(np.sort_complex(np.array([-lam, lam])), rel=1e-10, abs=1e-10)
    assert np.max(np.abs(small)) < 1e-6  # zeros (a defective zero root is only accurate to ~sqrt(eps))
    stable = np.max(roots.real) < 1e-6
    assert stable == (spin**2 >= 1 / 3 - 1e-12)  # Ω² > g/(3r), the critical spin included (roots 0, not ±1.633)


def test_rolling_disc_speed_choice_symbolic_and_input_state(disc):
    x, y, q1, q2, q3 = disc.coordinates
    P = {"m": 1.0, "g": 1.0, "r": 1.0}
    about = {q3.diff(t): 1.0, x.diff(t): 1.0}
    auto = linearize(disc, about, params=P)
    assert auto.a is None and len(auto.states) == 8  # no second-order form
    chosen = linearize(disc, about, params=P, speeds=[q1, q2, q3])
    assert chosen.speeds == (q1.diff(t), q2.diff(t), q3.diff(t))
    assert_same_roots(characteristic_roots(auto), characteristic_roots(chosen), 1e-12)
    with pytest.raises(AnalysisError, match="normal_modes|second-order"):
        normal_modes(auto)
    with pytest.raises(AnalysisError, match="roll x: A q̇ \\+ b = -1"):  # spinning without rolling forward
        linearize(disc, {q3.diff(t): 1.0, x.diff(t): 0.0}, params=P)  # (x_dot given: not computed)


@pytest.mark.slow
def test_rolling_disc_symbolic_characteristic_polynomial(disc):
    x, y, q1, q2, q3 = disc.coordinates
    W, lam = sp.symbols("Omega lambda")
    r, g = parameters("r g")
    sym = linearize(disc, {q3.diff(t): W, x.diff(t): r * W})
    expected = lam**6 * (lam**2 - sp.Rational(4, 5) * (g / r - 3 * W**2))
    assert is_zero(sym.characteristic_polynomial(lam) - expected)


def test_mixed_holonomic_and_nonholonomic_disc_matches_the_plain_disc(disc):
    """The disc with a superfluous height h of the centre, held by the holonomic h = r cos(lean) (V = m g h):
    the same roots as the plain disc (the bicycle's mix of one holonomic and several rolling constraints)."""
    x, y, q1, q2, q3 = disc.coordinates
    h = coordinates("h")
    m, g, r = parameters("m g r")
    mixed = System([x, y, q1, q2, q3, h], T=disc.T, V=m * g * h,
                   constraints=[Nonholonomic(c.velocity, c.name) for c in disc.constraints]
                   + [Holonomic(h - r * sp.cos(q2), "height")])
    P = {"m": 1.0, "g": 1.0, "r": 1.0}
    for spin in (0.2, 1.0):
        about = {q3.diff(t): spin, x.diff(t): spin}
        lin = linearize(mixed, {**about, h: 1.0}, params=P)
        assert h not in lin.coordinates and len(lin.states) == 8  # 6 − 1 coordinates, 6 − 3 speeds
        assert_same_roots(characteristic_roots(lin), characteristic_roots(disc, P, about=about), 1e-9)


# -------------------------------------------------------------------------------------------- inputs: B


def test_cart_pole_input_matrix_textbook_and_constrained():
    """Cart (M) with a point-mass pole (m, l) upright, horizontal force F on the cart. Textbook:
    ẍ = −(m g/M) θ + F/M, θ̈ = (M + m) g θ/(M l) − F/(M l)."""
    x, th = coordinates("x theta")
    M, m, l, g, F = parameters("M m l g F")
    pole = System([x, th], bodies=[Particle(M, (x, 0)), Particle(m, (x + l * sp.sin(th), l * sp.cos(th)))],
                  V=m * g * l * sp.cos(th), forces={x: F})
    lin = linearize(pole, {x: 0, th: 0}, inputs=[F])
    A_book = sp.Matrix([[0, 0, 1, 0], [0, 0, 0, 1], [0, -m * g / M, 0, 0], [0, (M + m) * g / (M * l), 0, 0]])
    B_book = sp.Matrix([0, 0, 1 / M, -1 / (M * l)])
    assert all(is_zero(e) for e in lin.A - A_book) and all(is_zero(e) for e in lin.B - B_book)
    P = {"M": 2.0, "m": 0.4, "l": 0.7, "g": 9.81}
    An, Bn = linearize(pole, {x: 0, th: 0}, params=P, inputs=[F]).numeric_state()
    subs = {M: 2.0, m: 0.4, l: 0.7, g: 9.81}
    assert np.allclose(An, np.array(A_book.subs(subs), dtype=float), rtol=1e-14)
    assert np.allclose(Bn, np.array(B_book.subs(subs), dtype=float), rtol=1e-14)
    # the same cart-pole with the bob in Cartesian coordinates and a rod constraint: states (x, xb, ẋ, ẋb)
    # relate to (x, θ, ẋ, θ̇) by δxb = δx + l δθ, so A_c = T A T⁻¹ and B_c = T B
    xc, xb, yb = coordinates("xc xb yb")
    cart = System([xc, xb, yb], bodies=[Particle(M, (xc, 0)), Particle(m, (xb, yb))], V=m * g * yb,
                  forces={xc: F}, constraints=[Holonomic(sp.sqrt((xb - xc) ** 2 + yb**2) - l, "rod")])
    c = linearize(cart, {xc: 0, xb: 0, yb: 0.7}, params=P, inputs=[F])
    assert c.coordinates == (xc, xb)
    T2 = np.array([[1.0, 0.0], [1.0, 0.7]])
    T = np.block([[T2, np.zeros((2, 2))], [np.zeros((2, 2)), T2]])
    Ac, Bc = c.numeric_state()
    assert np.allclose(Ac, T @ An @ np.linalg.inv(T), rtol=1e-12, atol=1e-12)
    assert np.allclose(Bc, T @ Bn, rtol=1e-12, atol=1e-12)


# ------------------------------------------------------------------------------------------------ refusals


def test_moving_constraint_rough_constraint_and_friction_kink_are_refused():
    x, y = coordinates("x y")
    m, w, g, mu = parameters("m omega g mu")
    rod = System([x, y], bodies=[Particle(m, (x, y))],
                 constraints=[Holonomic(y * sp.cos(w * t) - x * sp.sin(w * t), "rod")])  # Wells Ex. 3.5
    with pytest.raises(AnalysisError, match="moving.*rod"):
        linearize(rod, params={"m": 1, "omega": 2})
    with pytest.raises(AnalysisError, match="moving.*rod"):
        equilibria(rod)
    wire = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
                  constraints=[Rough(y, mu, x.diff(t), "rough floor")])
    with pytest.raises(AnalysisError, match="rough"):
        linearize(wire, params={"m": 1, "g": 9.81, "mu": 0.2})
    block = System([x], bodies=[Particle(m, (x,))], V=m * g * x**2 / 2, forces={x: -mu * m * g * sp.sign(x.diff(t))})
    with pytest.raises(AnalysisError, match="sign"):
        linearize(block, params={"m": 1, "g": 9.81, "mu": 0.2})
    moving = linearize(block, {x.diff(t): 1.0, x: -0.2}, params={"m": 1, "g": 9.81, "mu": 0.2})
    assert moving.numeric()[2][0, 0] == pytest.approx(9.81, rel=1e-14)  # sliding: friction locally constant


def test_routhian_and_hamiltonian_refuse_constrained_systems():
    s, *_ = cartesian_pendulum()
    for fn in (routhian, hamiltonian):
        with pytest.raises(AnalysisError, match="string") as exc:
            fn(s)
        assert isinstance(exc.value, ValueError)
