"""Series expansion of a potential (Wells §5.10, Ex. 5.5, 5.6, 5.8, Probs. 5.5, 5.6, 5.9)."""

import pytest
import sympy as sp

import lagrange as lg
from lagrange import AnalysisError, coordinates, expand_potential, normal_modes
from lagrange.simplification import is_zero

k, s, l0 = sp.symbols("k s l0", positive=True)


def test_prob_5_5_quartic_term_of_a_transverse_spring():
    """V = ½k(√(s² + x²) − l0)² ≈ k(s − l0)x²/(2s) + k l0 x⁴/(8s³) (Prob. 5.5, constant dropped)."""
    x = sp.Symbol("x")
    ser = expand_potential(k / 2 * (sp.sqrt(s**2 + x**2) - l0) ** 2, {x: 0}, order=4)
    assert is_zero(ser.expr - ser.terms[0] - (k * (s - l0) * x**2 / (2 * s) + k * l0 * x**4 / (8 * s**3)))
    assert ser.terms[1] == 0 and ser.terms[3] == 0 and ser.gradient == (0,)
    assert is_zero(ser.stiffness[0, 0] - k * (s - l0) / s)
    # unstretched at equilibrium (s = l0, Ex. 5.5): no quadratic term, the quartic k x⁴/(8 s²) governs
    unstretched = expand_potential(k / 2 * (sp.sqrt(s**2 + x**2) - s) ** 2, {x: 0}, order=4)
    assert unstretched.quadratic_form == 0 and is_zero(unstretched.terms[4] - k * x**4 / (8 * s**2))


def test_ex_5_8_string_to_a_spring_junction():
    """V ≈ k (s0²/l0²) y² with the linear term vanishing (Ex. 5.8)."""
    y, s0, s1 = sp.symbols("y s0 s1", positive=True)
    L0 = sp.sqrt(s1**2 + s0**2)
    V = k * y**2 + 2 * k * s0 * y - 2 * k * L0 * sp.sqrt(s1**2 + (s0 + y) ** 2)
    ser = expand_potential(V, {y: 0}, order=2)
    assert ser.terms[1] == 0
    assert is_zero(ser.quadratic_form - k * s0**2 / L0**2 * y**2)


def test_prob_5_6_bar_and_spring_stiffness_matches_normal_modes():
    """K = d²V/dθ² at θ = 0 = ½Mgl + k s l (1 − l0/|s − l|) (catalog DERIVED), and the period from
    normal_modes of the same System agrees."""
    th = coordinates("theta")
    M, g, l = sp.symbols("M g l", positive=True)
    V = -M * g * l * sp.cos(th) / 2 + k / 2 * (sp.sqrt(s**2 + l**2 - 2 * s * l * sp.cos(th)) - l0) ** 2
    ser = expand_potential(V, {th: 0}, order=2)
    K = ser.stiffness[0, 0]
    vals = {M: 2, g: sp.Rational(981, 100), l: 1, k: 30, s: 3, l0: sp.Rational(3, 2)}
    expected = M * g * l / 2 + k * s * l * (1 - l0 / (s - l))
    assert abs(float((K - expected).subs(vals))) < 1e-12
    sysm = lg.System(T=sp.Rational(1, 2) * (M * l**2 / 3) * th.diff(lg.t) ** 2, V=V, coordinates=[th])
    omega = normal_modes(sysm, {str(p): v for p, v in vals.items()}, about={th: 0}).omega[0]
    assert abs(float(omega) ** 2 - float((K / (M * l**2 / 3)).subs(vals))) < 1e-9


@pytest.mark.slow
def test_ex_5_6_and_prob_5_9_multipoles_about_infinity():
    r, th, Q, Q1 = sp.symbols("r theta Q Q1", positive=True)
    d_plus = sp.sqrt(r**2 + s**2 + 2 * r * s * sp.cos(th))
    d_minus = sp.sqrt(r**2 + s**2 - 2 * r * s * sp.cos(th))
    dipole = expand_potential(Q * Q1 / d_plus - Q * Q1 / d_minus, {r: sp.oo}, order=2)   # Q2 = −Q1
    assert is_zero(dipole.expr + 2 * Q * Q1 * s * sp.cos(th) / r**2)
    same = expand_potential(Q * Q1 / d_plus + Q * Q1 / d_minus, {r: sp.oo}, order=1)     # Q2 = Q1
    assert is_zero(same.expr - 2 * Q * Q1 / r)
    quad = expand_potential(Q * Q1 / d_plus - 2 * Q * Q1 / r + Q * Q1 / d_minus, {r: sp.oo}, order=3)
    assert is_zero(quad.expr - (2 * Q * Q1 * s**2 * sp.cos(th) ** 2 / r**3 - Q * Q1 * s**2 * sp.sin(th) ** 2 / r**3))


def test_on_axis_disk_gravity_far_field():
    """Prob. 5.22 (catalog: no transcribed answer): the on-axis potential of a uniform disk,
    −(2GMm/a²)(√(z² + a²) − z) = −GMm/z · (1 − a²/(4z²) + a⁴/(8z⁴) − …) (binomial series)."""
    z, a, G, M, m = sp.symbols("z a G M m", positive=True)
    ser = expand_potential(-2 * G * M * m / a**2 * (sp.sqrt(z**2 + a**2) - z), {z: sp.oo}, order=5)
    assert is_zero(ser.expr + G * M * m / z * (1 - a**2 / (4 * z**2) + a**4 / (8 * z**4)))


@pytest.mark.slow
def test_two_coordinates_hessian_is_the_spring_formula_5_13():
    """A stretched spring from the origin to an anchor at (X, Y): the Hessian at the junction is
    k[(l'/l) n nᵀ + (1 − l'/l) I] (Wells 5.13)."""
    x, y = coordinates("x y")
    X, Y = sp.symbols("X Y", positive=True)
    lp = sp.Symbol("lp", positive=True)
    V = k / 2 * (sp.sqrt((X - x) ** 2 + (Y - y) ** 2) - lp) ** 2
    ser = expand_potential(V, {x: 0, y: 0}, order=2)
    L = sp.sqrt(X**2 + Y**2)
    n = sp.Matrix([X, Y]) / L
    expected = k * (lp / L * n * n.T + (1 - lp / L) * sp.eye(2))
    assert all(is_zero(ser.stiffness[i, j] - expected[i, j]) for i in range(2) for j in range(2))
    assert ser.expr.has(x) and ser.expr.has(y)  # the coordinate functions come back as given


def test_bad_input_is_named():
    x = sp.Symbol("x")
    with pytest.raises(AnalysisError, match="singular at x = 0"):
        expand_potential(1 / x, {x: 0})
    with pytest.raises(AnalysisError, match="non-negative integer"):
        expand_potential(x**2, {x: 0}, order=-1)
    with pytest.raises(AnalysisError, match="mapping"):
        expand_potential(x**2, [x])
    q1, q2 = coordinates("q1 q2")
    with pytest.raises(AnalysisError, match="q2"):
        expand_potential(q1**2 + q2**2, {q1: 0})
    with pytest.raises(AnalysisError, match="velocities"):
        expand_potential(q1.diff(lg.t) ** 2, {q1: 0})
    with pytest.raises(AnalysisError, match="one coordinate only"):
        expand_potential(1 / q1 + q2, {q1: sp.oo, q2: 0})
