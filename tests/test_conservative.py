"""Force classification, work along a path and potentials (Wells §5.6–5.8, Probs. 5.1, 5.2, Ex. 5.4)."""

import pytest
import sympy as sp

import lagrange as lg
from lagrange import AnalysisError, coordinates, is_conservative, potential_of, work_along
from lagrange.analysis.conservative import generalized_forces, nonconservative_pairs
from lagrange.simplification import is_zero

x, y, z, k, A, B, m, g, w, tt = sp.symbols("x y z k A B m g omega t_")
t = lg.t


def _same_potential(V, F, coords):
    """−∂V/∂q reproduces every component (the independent check of a potential)."""
    return all(is_zero(-sp.diff(V, q) - f) for q, f in zip(coords, F))


# ---------------------------------------------------------------- Prob 5.1 (book prints no answers; catalog DERIVED)

@pytest.mark.parametrize("F, coords, V", [
    ([0, -m * g], [x, y], m * g * y),                                   # (a)
    ([-k * x, -k * y], [x, y], k * (x**2 + y**2) / 2),                  # (b)
    ([A * y * z, A * x * z, A * x * y], [x, y, z], -A * x * y * z),     # (e)
])
def test_prob_5_1_conservative_fields_and_their_potentials(F, coords, V):
    assert is_conservative(F, coords)
    found = potential_of(F, coords, reference={q: 0 for q in coords})
    assert is_zero(found - V)
    assert _same_potential(found, F, coords)


@pytest.mark.parametrize("F, pair, curl", [
    ([-k * y, k * x], (x, y), -2 * k),             # (c): curl 2k
    ([A * x * y, B * x * y], (x, y), A * x - B * y),  # (d)
])
def test_prob_5_1_nonconservative_fields_are_named(F, pair, curl):
    assert not is_conservative(F, [x, y])
    (qi, qj, c), = nonconservative_pairs(F, [x, y])
    assert (qi, qj) == pair and is_zero(c - curl)
    with pytest.raises(AnalysisError, match=r"not conservative: ∂Q\[x\]/∂y − ∂Q\[y\]/∂x") as err:
        potential_of(F, [x, y])
    assert isinstance(err.value, ValueError)


@pytest.mark.slow
def test_prob_5_1f_spherical_components():
    """As physical components along the spherical unit vectors: V = −B r³ sinθ cosφ reproduces F_r and F_θ;
    the printed F_φ (no sinθ) fails the test, the corrected one passes. As generalized forces it fails."""
    r, th, ph = sp.symbols("r theta phi", positive=True)
    pos = sp.Matrix([r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th)])
    e_r = pos / r
    e_th = pos.diff(th) / r
    e_ph = pos.diff(ph) / (r * sp.sin(th))
    Fr, Fth = 3 * B * r**2 * sp.sin(th) * sp.cos(ph), B * r**2 * sp.cos(th) * sp.cos(ph)
    printed = -B * r**2 * sp.sin(th) * sp.sin(ph)
    corrected = -B * r**2 * sp.sin(ph)
    cart = lambda Fph: list(Fr * e_r + Fth * e_th + Fph * e_ph)  # noqa: E731
    assert not is_conservative(cart(printed), [r, th, ph], position=pos)
    assert is_conservative(cart(corrected), [r, th, ph], position=pos)
    V = potential_of(cart(corrected), [r, th, ph], position=pos, reference={r: 0, th: 0, ph: 0})
    assert is_zero(V + B * r**3 * sp.sin(th) * sp.cos(ph))
    assert not is_conservative([Fr, Fth, printed], [r, th, ph])


@pytest.mark.slow
def test_prob_5_1g_arbitrary_functions_of_their_own_coordinate():
    r, th, ph = sp.symbols("r theta phi")
    f1, f2, f3 = sp.Function("f1"), sp.Function("f2"), sp.Function("f3")
    F = [f1(r), f2(th), f3(ph)]
    assert is_conservative(F, [r, th, ph])
    V = potential_of(F, [r, th, ph])
    assert sp.simplify(V.diff(r) + f1(r)) == 0 and sp.simplify(V.diff(ph) + f3(ph)) == 0


def test_prob_5_1h_time_dependent_field_at_fixed_t():
    F = [-k * x * sp.sin(w * t), k * t * y]
    assert is_conservative(F, [x, y])
    V = potential_of(F, [x, y], reference={x: 0, y: 0})
    assert is_zero(V - (k * x**2 * sp.sin(w * t) / 2 - k * t * y**2 / 2))


# ------------------------------------------------------------------------------------------ Prob 5.2: work

def test_prob_5_2_work_around_a_rectangle():
    x1, x2, y1, y2 = sp.symbols("x1 x2 y1 y2")
    rect = [(x1, y1), (x2, y1), (x2, y2), (x1, y2), (x1, y1)]  # counter-clockwise
    W = work_along([-k * y, k * x], [x, y], rect)
    assert is_zero(W - 2 * k * (x2 - x1) * (y2 - y1))
    assert work_along([3 * B * x**2 * y**2, 2 * B * x**3 * y], [x, y], rect) == 0


def test_work_depends_on_the_path_only_for_a_nonconservative_field():
    s = sp.Symbol("s")
    straight, parabola = [s, s], [s, s**2]
    F_nc, F_c = [-k * y, k * x], [-k * x, -k * y]
    assert work_along(F_nc, [x, y], straight, (s, 0, 1)) == 0
    assert is_zero(work_along(F_nc, [x, y], parabola, (s, 0, 1)) - k / 3)
    Wc = [work_along(F_c, [x, y], p, (s, 0, 1)) for p in (straight, parabola)]
    assert is_zero(Wc[0] - Wc[1]) and is_zero(Wc[0] + k)   # = V(0) − V(1, 1) = −k
    # a conservative field's work equals the drop in its potential
    V = potential_of(F_c, [x, y])
    assert is_zero(Wc[0] - (V.subs({x: 0, y: 0}) - V.subs({x: 1, y: 1})))


def test_curl_free_field_with_a_hole_is_only_locally_conservative():
    """(−y, x)/(x² + y²) in polar coordinates is Q_θ = 1: exact locally, work 2π around the origin."""
    r, th = sp.symbols("r theta", positive=True)
    pos = [r * sp.cos(th), r * sp.sin(th)]
    F = [-pos[1] / r**2, pos[0] / r**2]
    Q = generalized_forces(F, [r, th], position=pos)
    assert is_zero(Q[0]) and is_zero(Q[1] - 1)
    assert is_conservative(F, [r, th], position=pos)
    s = sp.Symbol("s")
    assert is_zero(work_along(F, [r, th], [1, s], (s, 0, 2 * sp.pi), position=pos) - 2 * sp.pi)


@pytest.mark.slow
def test_numeric_quadrature_when_no_closed_form(monkeypatch):
    s = sp.Symbol("s")
    W = work_along([sp.exp(-x**2) * sp.cos(x**3), 0], [x, y], [s, 0], (s, 0, 1))
    ref = sp.Integral(sp.exp(-s**2) * sp.cos(s**3), (s, 0, 1)).evalf(20)
    assert abs(W - ref) < 1e-15
    monkeypatch.setattr("lagrange.analysis.conservative._INTEGRATE_SECONDS", 0.2)  # keep the test fast
    with pytest.raises(AnalysisError, match="no closed form"):
        work_along([sp.exp(-k * x**2) * sp.sin(x) / x, 0], [x, y], [s, 0], (s, 0, 1))


# ------------------------------------------------ §5.6 text, Ex. 5.4: in generalized coordinates of a System

def test_ex_5_4_double_pendulum_forces_from_a_system_in_generalized_coordinates():
    """Gravity on the double pendulum as generalized forces of a System (Wells Ex. 5.4): exact, and its
    potential is V = −m1 g r1 cosθ − m2 g (r1 cosθ + r2 cosφ)."""
    th, ph = coordinates("theta phi")
    m1, m2, r1, r2 = sp.symbols("m1 m2 r1 r2", positive=True)
    forces = {th: -(m1 + m2) * g * r1 * sp.sin(th), ph: -m2 * g * r2 * sp.sin(ph)}
    s = lg.System(T=sp.Rational(1, 2) * m1 * r1**2 * th.diff(t)**2, forces=forces, coordinates=[th, ph])
    assert is_conservative(s.forces, s.coordinates)
    V = potential_of(s.forces, s.coordinates, reference={th: sp.pi / 2, ph: sp.pi / 2})
    assert V.has(th) and is_zero((V + m1 * g * r1 * sp.cos(th) + m2 * g * (r1 * sp.cos(th) + r2 * sp.cos(ph)))
                                 .subs({th: sp.Symbol("a"), ph: sp.Symbol("b")}))
    assert not s.derived.is_conservative  # the Jacobi-integral meaning: declared as applied forces


def test_cartesian_field_through_a_rotating_frame():
    """A central spring force −k r on a particle described in a frame turning at ω: Q = F·∂r/∂q at fixed t is
    exact (the potential is ½k(x² + y²)); a Lorentz-like velocity force is refused by name."""
    X, Y = coordinates("X Y")
    frame = lg.Frame(rotation=lg.rot_z(w * t))
    pos = list(frame.point((X, Y)))
    F = [-k * c for c in pos]
    assert is_conservative(F, [X, Y], position=pos)
    V = potential_of(F, [X, Y], position=pos, reference={X: 0, Y: 0})
    assert is_zero(sp.expand(V - k * (X**2 + Y**2) / 2).subs({X: x, Y: y}))
    with pytest.raises(AnalysisError, match="velocities"):
        is_conservative([B * Y.diff(t), -B * X.diff(t)], [X, Y])


def test_bad_input_is_named():
    with pytest.raises(AnalysisError, match="2 force components for 3 coordinates"):
        is_conservative([x, y], [x, y, z])
    with pytest.raises(AnalysisError, match="not among the coordinates"):
        X = coordinates("X")
        is_conservative([X * sp.Function("Z")(t)], [X])
    with pytest.raises(AnalysisError, match="over must be"):
        work_along([x, y], [x, y], [x, y], over=5)
    with pytest.raises(AnalysisError, match="reference configuration must give"):
        potential_of([-k * x, -k * y], [x, y], reference={x: 0})
