"""Force classification, work along a path and potentials (Wells §5.6–5.8, Probs. 5.1, 5.2, Ex. 5.4)."""

import pytest
import sympy as sp

import lagrange as lg
from lagrange import AnalysisError, coordinates, is_conservative, potential_of, work_along
from lagrange.analysis.conservative import generalized_forces, nonconservative_pairs
from lagrange.model.coordinates import to_functions
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


# ------------------------------------------- potentials in the field's natural variables (Prob. 5.8, Ex. 5.6 …)

G, M, l, h, a_, R, s = sp.symbols("G M l h a R s", positive=True)


def _sphere_on_a_pendulum_bob(centre):
    """Wells Prob. 5.8: the attraction −GMm d/|d|³ of a sphere (centre c) on a spherical-pendulum bob."""
    th, ph = coordinates("theta phi")
    bob = sp.Matrix([l * sp.sin(th) * sp.cos(ph), l * sp.sin(th) * sp.sin(ph), -l * sp.cos(th)])
    d = bob - sp.Matrix(centre)
    return [th, ph], list(bob), list(-G * M * m * d / d.norm() ** 3), d.norm()


def _numerically_equal(A, B, coords=()):
    """A − B vanishes (below 1e-20 in 30-digit arithmetic) at four random points: every symbol and coordinate
    function at a random value in [0.2, 1.3]."""
    import random

    import mpmath
    rnd = random.Random(7)
    e = sp.sympify(A - B)
    e = e.xreplace({f: sp.Dummy() for f in e.atoms(sp.core.function.AppliedUndef)})
    symbols = sorted(e.free_symbols, key=sp.default_sort_key)
    f = sp.lambdify(symbols, e, modules="mpmath")
    with mpmath.workdps(30):
        for _ in range(4):
            assert abs(f(*(mpmath.mpf(rnd.randint(20, 130)) / 100 for _ in symbols))) < 1e-20, (A, B)
    return True


@pytest.mark.parametrize("centre", [(0, 0, -h), (a_, 0, -h)], ids=["below the pivot", "off the axis"])
def test_prob_5_8_sphere_attracting_a_spherical_pendulum_bob(centre):
    """V = −GMm/d (Wells Prob. 5.8), in the pendulum's own coordinates (θ, φ): found, and equal to the book's."""
    q, bob, F, d = _sphere_on_a_pendulum_bob(centre)
    assert is_conservative(F, q, position=bob)
    V = potential_of(F, q, position=bob)
    assert _numerically_equal(V, -G * M * m / d, q)
    # the generalized forces of the field are −∂V/∂q (an independent route: the book's V differentiated)
    Q = generalized_forces(F, q, position=bob)
    th, ph = (sp.Symbol(n, real=True) for n in ("theta", "phi"))
    book = (-G * M * m / d).subs({q[0]: th, q[1]: ph})
    assert all(_numerically_equal(sp.diff(book, v), -Qv) for v, Qv in zip((th, ph), Q))


def test_prob_5_8_equations_of_motion_agree_with_the_potential():
    """The field as applied forces and −GMm/d as V give the same equations of motion."""
    q, bob, F, d = _sphere_on_a_pendulum_bob((a_, 0, -h))
    V = potential_of(F, q, position=bob)
    T = m / 2 * sum(c.diff(t) ** 2 for c in bob)
    Q = [to_functions(Qr, q) for Qr in generalized_forces(F, q, position=bob)]
    as_forces = lg.System(q, T=T, forces=dict(zip(q, Q)))
    as_potential = lg.System(q, T=T, V=V)
    for e1, e2 in zip(as_forces.derived.forcing, as_potential.derived.forcing):
        assert _numerically_equal(e1, e2, q)


def test_central_fields_in_cylindrical_coordinates():
    """A point mass at (a, 0, h) and a line charge along z, on a point given in cylindrical (ρ, φ, z):
    V = −k/d and −2kλ ln ρ."""
    rho, ph, zz = coordinates("rho phi z")
    kk, lam = sp.symbols("k lambda", positive=True)
    p = sp.Matrix([rho * sp.cos(ph), rho * sp.sin(ph), zz])
    d = p - sp.Matrix([a_, 0, h])
    F = list(-kk * d / d.norm() ** 3)
    V = potential_of(F, [rho, ph, zz], position=list(p))
    assert _numerically_equal(V, -kk / d.norm(), [rho, ph, zz])
    line = [2 * kk * lam * p[0] / (p[0] ** 2 + p[1] ** 2), 2 * kk * lam * p[1] / (p[0] ** 2 + p[1] ** 2), 0]
    V = potential_of(line, [rho, ph, zz], position=list(p), reference={rho: 1})
    assert _numerically_equal(V, -2 * kk * lam * sp.log(rho), [rho, ph, zz])


def test_central_fields_other_than_inverse_square():
    """A Gaussian well −k d e^{−d²} and a 1/d field (potential ½k ln d²), on the pendulum bob off the axis:
    the natural variable is the argument of the exponential or the logarithm's."""
    q, bob, _, dist = _sphere_on_a_pendulum_bob((a_, 0, -h))
    d = sp.Matrix(bob) - sp.Matrix([a_, 0, -h])
    V = potential_of(list(-k * d * sp.exp(-d.dot(d))), q, position=bob)
    assert _numerically_equal(V, -k * sp.exp(-dist**2) / 2)
    V = potential_of(list(-k * d / d.dot(d)), q, position=bob)
    assert _numerically_equal(V, k * sp.log(dist**2) / 2)


def test_ex_5_6_charge_near_two_fixed_charges_in_polar_coordinates():
    """Wells Ex. 5.6: V = QQ1/(r² + s² + 2rs cosθ)^½ + QQ2/(r² + s² − 2rs cosθ)^½ (Q1 at −s, Q2 at +s)."""
    r, th = coordinates("r theta")
    Q, Q1, Q2 = sp.symbols("Q Q1 Q2")
    p = sp.Matrix([r * sp.cos(th), r * sp.sin(th)])
    d1, d2 = p - sp.Matrix([-s, 0]), p - sp.Matrix([s, 0])
    F = list(Q * Q1 * d1 / d1.norm() ** 3 + Q * Q2 * d2 / d2.norm() ** 3)
    V = potential_of(F, [r, th], position=list(p))
    book = (Q * Q1 / sp.sqrt(r**2 + s**2 + 2 * r * s * sp.cos(th))
            + Q * Q2 / sp.sqrt(r**2 + s**2 - 2 * r * s * sp.cos(th)))
    assert _numerically_equal(V, book, [r, th])


def test_ex_5_1_and_prob_5_6_spring_to_a_point_plus_gravity():
    """A spring (k, l0) from a fixed point C to the point where gravity also acts: the exact V of Wells
    Prob. 5.6 (bar of mass M pivoted at A, spring from its end B to C at distance s_ below A; gravity at the
    middle) and of Ex. 5.1 (bob on a rubber band: V = ½k(r − r0)² − mgr cosθ)."""
    th = coordinates("theta")
    kk, l0, Mb, L, sC = sp.symbols("k l0 M l s_", positive=True)
    B = sp.Matrix([L * sp.sin(th), -L * sp.cos(th)])
    dC = B - sp.Matrix([0, -sC])
    spring = generalized_forces(list(-kk * (dC.norm() - l0) * dC / dC.norm()), [th], position=list(B))
    gravity = generalized_forces([0, -Mb * g], [th], position=[L / 2 * sp.sin(th), -L / 2 * sp.cos(th)])
    V = potential_of([spring[0] + gravity[0]], [th])
    book = -Mb * g * L * sp.cos(th) / 2 + kk * (sp.sqrt(sC**2 + L**2 - 2 * sC * L * sp.cos(th)) - l0) ** 2 / 2
    assert _numerically_equal(sp.diff(V - book, th), 0, [th])
    r, th2 = coordinates("r theta")
    bob = [r * sp.sin(th2), -r * sp.cos(th2)]
    band = [-kk * (sp.sqrt(bob[0]**2 + bob[1]**2) - l0) * c / sp.sqrt(bob[0]**2 + bob[1]**2) for c in bob]
    V = potential_of([band[0], band[1] - m * g], [r, th2], position=bob, reference={r: l0, th2: sp.pi / 2})
    rp = sp.Symbol("r", positive=True)   # the book's form holds for r > 0 (V has |r| for any real r)
    assert is_zero((V - (kk * (r - l0) ** 2 / 2 - m * g * r * sp.cos(th2))).subs(r, rp))


def test_ex_5_10_driven_spring_end_time_dependent_central_field():
    """Wells Ex. 5.10: spring end driven at x = A sin ωt; at fixed t, V = ½k([(x − A sin ωt)² + y²]^½ − l0)²,
    also found in polar coordinates."""
    kk, l0, Aa = sp.symbols("k l0 A", positive=True)
    X, Y = coordinates("X Y")
    dx, L = X - Aa * sp.sin(w * t), sp.sqrt((X - Aa * sp.sin(w * t)) ** 2 + Y**2)
    F = [-kk * (L - l0) * dx / L, -kk * (L - l0) * Y / L]
    V = potential_of(F, [X, Y])
    assert _numerically_equal(sp.diff(V - kk * (L - l0) ** 2 / 2, X), 0, [X, Y])
    assert _numerically_equal(sp.diff(V - kk * (L - l0) ** 2 / 2, Y), 0, [X, Y])
    r, th = coordinates("r theta")
    p = [r * sp.cos(th), r * sp.sin(th)]
    Fp = [f.subs({X: p[0], Y: p[1]}) for f in F]
    Vp = potential_of(Fp, [r, th], position=p)
    book = (kk * (L - l0) ** 2 / 2).subs({X: p[0], Y: p[1]})
    assert _numerically_equal(sp.diff(Vp - book, r), 0, [r, th])
    assert _numerically_equal(sp.diff(Vp - book, th), 0, [r, th])


def test_sec_5_6_and_ex_5_9_potential_of_a_generalized_force():
    """Wells §5.6: F_θ = −mgr sinθ has V = −mgr cosθ; Ex. 5.9 (string pulled through a hole, r = r0 − vt):
    F_θ = −mg(r0 − vt) sinθ has V = −mg(r0 − vt) cosθ at fixed t."""
    th = coordinates("theta")
    r0, v, rr = sp.symbols("r0 v r", positive=True)
    assert is_zero(potential_of([-m * g * rr * sp.sin(th)], [th], reference={th: sp.pi / 2})
                   + m * g * rr * sp.cos(th))
    V = potential_of([-m * g * (r0 - v * t) * sp.sin(th)], [th], reference={th: sp.pi / 2})
    assert is_zero(V + m * g * (r0 - v * t) * sp.cos(th))


def test_nonconservative_fields_stay_refused_as_such():
    """A swirl k ẑ × r added to an inverse-square field, in cylindrical and in spherical-pendulum coordinates:
    not conservative, and said so (not 'no closed form')."""
    rho, ph, zz = coordinates("rho phi z")
    p = sp.Matrix([rho * sp.cos(ph), rho * sp.sin(ph), zz])
    swirl = sp.Matrix([-k * p[1], k * p[0], 0])
    d = p - sp.Matrix([a_, 0, h])
    F = list(-G * M * m * d / d.norm() ** 3 + swirl)
    assert not is_conservative(F, [rho, ph, zz], position=list(p))
    with pytest.raises(AnalysisError, match="not conservative.*no potential exists"):
        potential_of(F, [rho, ph, zz], position=list(p))
    q, bob, Fs, _ = _sphere_on_a_pendulum_bob((a_, 0, -h))
    swirl = [-k * bob[1], k * bob[0], 0]
    with pytest.raises(AnalysisError, match=r"not conservative: ∂Q\[theta\]/∂phi"):
        potential_of([f + c for f, c in zip(Fs, swirl)], q, position=bob)


def test_conservative_field_without_a_closed_form_is_not_said_to_have_no_potential(monkeypatch):
    """Q = (sin x / ln x, 0) passes the exactness test; its potential has no elementary form: the message says
    so and what to try, never that no potential exists."""
    monkeypatch.setattr("lagrange.analysis.conservative._INTEGRATE_SECONDS", 0.25)  # keep the test fast
    F = [sp.sin(x) / sp.log(x) + sp.exp(-y**2) * 0, 0]
    assert is_conservative(F, [x, y])
    with pytest.raises(AnalysisError) as err:
        potential_of(F, [x, y])
    msg = str(err.value)
    assert "no closed form found" in msg and "a potential exists locally" in msg and "work_along" in msg
    assert "no potential exists" not in msg and "cannot be written" not in msg


def test_the_potential_is_verified_before_it_is_returned():
    """The check that guards every returned V: a right V passes quietly, a wrong one (off by a term in y, or by
    a factor) is refused."""
    from lagrange.analysis.conservative import _forces, _verify
    Q = (-k * x, -k * y)
    _verify(k * (x**2 + y**2) / 2, Q, [x, y], [x, y])
    _verify(k * (x**2 + y**2) / 2 + 7, Q, [x, y], [x, y])
    with pytest.raises(AnalysisError, match="does not reproduce Q\\[y\\]"):
        _verify(k * x**2 / 2 + k * y**2, Q, [x, y], [x, y])
    q, bob, F, d = _sphere_on_a_pendulum_bob((a_, 0, -h))
    th, ph = (sp.Symbol(n, real=True) for n in ("theta", "phi"))
    Qs = _forces(F, q, [th, ph], bob)
    book = (-G * M * m / d).subs({q[0]: th, q[1]: ph})
    _verify(book, Qs, q, [th, ph])
    with pytest.raises(AnalysisError, match="does not reproduce"):
        _verify(2 * book, Qs, q, [th, ph])


# ------------------------------------------------------- work of velocity-dependent forces along a path (Ch. 6)

X, Y = coordinates("X Y")
mu, N = sp.symbols("mu N", positive=True)
_speed = sp.sqrt(X.diff(t) ** 2 + Y.diff(t) ** 2)
DRY = [-mu * N * X.diff(t) / _speed, -mu * N * Y.diff(t) / _speed]   # Coulomb friction −μN v/|v| (Wells Ex. 6.1)


@pytest.mark.parametrize("path, over, length", [
    ([A * s, B * s], (s, 0, 1), sp.sqrt(A**2 + B**2)),                  # straight line
    ([A * s, B * s], (s, 1, 0), sp.sqrt(A**2 + B**2)),                  # the same line, run backwards
    ([R * sp.cos(s), R * sp.sin(s)], (s, 0, 2 * sp.pi), 2 * sp.pi * R),  # a full circle
    ([R * sp.cos(s), R * sp.sin(s)], (s, sp.pi, 0), sp.pi * R),         # half a circle, clockwise
    ([s**3, 0], (s, -1, 1), 2),                                         # tangent zero at s = 0 (no reversal)
    ([s**2, s**2], (s, -1, 1), 2 * sp.sqrt(2)),                         # out and back: a reversal at s = 0
])
def test_dry_friction_work_is_minus_mu_n_times_the_length(path, over, length):
    A_, B_ = sp.symbols("A B", positive=True)
    path = [sp.sympify(c).subs({A: A_, B: B_}) for c in path]
    W = work_along(DRY, [X, Y], path, over=over)
    assert is_zero(W + mu * N * sp.sympify(length).subs({A: A_, B: B_}))


def test_dry_friction_work_on_a_polygon_and_in_polar_coordinates():
    """Around a triangle: −μN × perimeter. In polar coordinates (generalized forces of Wells Prob. 6.9's
    friction term, f ṙ/v and f r²θ̇/v): along the arc r = R from θ = 0 to π, −f πR."""
    A_, B_, f = sp.symbols("A B f", positive=True)
    W = work_along(DRY, [X, Y], [(0, 0), (A_, 0), (A_, B_), (0, 0)])
    assert is_zero(W + mu * N * (A_ + B_ + sp.sqrt(A_**2 + B_**2)))
    r, th = coordinates("r theta")
    v = sp.sqrt(r.diff(t) ** 2 + r**2 * th.diff(t) ** 2)
    W = work_along([-f * r.diff(t) / v, -f * r**2 * th.diff(t) / v], [r, th], [R, s], over=(s, 0, sp.pi))
    assert is_zero(W + f * sp.pi * R)
    # a position-dependent normal force (Wells Prob. 6.12: N varies along the path): −μ ∫ N(x) dx
    Fx = [-mu * (N + k * X) * X.diff(t) / _speed, -mu * (N + k * X) * Y.diff(t) / _speed]
    assert is_zero(work_along(Fx, [X, Y], [s, 0], over=(s, 0, 2)) + mu * (2 * N + 2 * k))


def test_ex_6_1_friction_work_equals_the_energy_lost_on_the_incline():
    """Wells Ex. 6.1: the particle slides up the rough incline and stops; the energy lost, from the simulated
    motion, equals the friction work along the straight path it ran (independent: integrator vs. work_along)."""
    import numpy as np

    from lagrange.corpus import get_problem
    prob = get_problem("ex6.1")
    sysm = prob.system
    xq, yq = sysm.coordinates
    mm, gg, mmu, al = sp.symbols("m g mu alpha", positive=True)
    par = {"m": 1.0, "g": 9.81, "mu": 0.3, "alpha": 0.4}
    v0, T_stop = 3.0, 3.0 / (9.81 * (np.sin(0.4) + 0.3 * np.cos(0.4)))
    sol = sysm.simulate(0.999 * T_stop, {xq: 0, yq: 0, xq.diff(t): 0, yq.diff(t): v0},
                        {sp.Symbol(n): v for n, v in par.items()}, rtol=1e-11, atol=1e-12)
    yf, vf = sol.y[-1, 1], sol.y[-1, 3]
    lost = 0.5 * v0**2 - 0.5 * vf**2 - 9.81 * np.sin(0.4) * yf
    friction = [-mm * gg * mmu * sp.cos(al) * c.diff(t) / sp.sqrt(xq.diff(t)**2 + yq.diff(t)**2) for c in (xq, yq)]
    W = work_along(friction, [xq, yq], [0, s], over=(s, 0, sp.Float(yf)))
    Wn = float(W.subs({mm: 1, gg: 9.81, mmu: 0.3, al: 0.4}))
    assert abs(-Wn - lost) < 1e-8 * lost


def test_ex_6_2_dumbbell_friction_work_translating_and_turning():
    """Wells Ex. 6.2 (dry friction on both masses of a dumbbell, q = (x, y, θ), F = ∂P/∂q̇): translating by L
    at fixed θ, W = −(f1 + f2)L; turning in place by Φ about (x, y), W = −(f1 l1 + f2 l2)Φ."""
    from lagrange.corpus import get_problem
    sysm = get_problem("ex6.2").system
    xq, yq, thq = sysm.coordinates
    Q = [sp.diff(sysm.P, q.diff(t)) for q in (xq, yq, thq)]
    m1, m2, l1, l2, mmu, gg = sp.symbols("m1 m2 l1 l2 mu g", positive=True)
    f1, f2 = mmu * m1 * gg, mmu * m2 * gg
    L, Phi, th0 = sp.symbols("L Phi theta0", positive=True)
    W = work_along(Q, [xq, yq, thq], [L * s, 0, th0], over=(s, 0, 1))
    assert _numerically_equal(W, -(f1 + f2) * L, [])
    W = work_along(Q, [xq, yq, thq], [0, 0, s], over=(s, 0, Phi))
    assert is_zero(W + (f1 * l1 + f2 * l2) * Phi)


def test_rate_dependent_forces_need_the_rate():
    """Viscous drag −c v does work −c ∫ v·dq, which depends on how fast the path is run: refused without
    rate=; with a constant rate ṡ = 2 along a straight line of length L, W = −c·2·L² (independent: v = 2L)."""
    c = sp.Symbol("c", positive=True)
    A_, B_ = sp.symbols("A B", positive=True)
    viscous = [-c * X.diff(t), -c * Y.diff(t)]
    with pytest.raises(AnalysisError, match="depends on how fast the path is run.*rate="):
        work_along(viscous, [X, Y], [A_ * s, B_ * s], over=(s, 0, 1))
    W = work_along(viscous, [X, Y], [A_ * s, B_ * s], over=(s, 0, 1), rate=2)
    assert is_zero(W + 2 * c * (A_**2 + B_**2))
    # dry friction ignores the rate: the same work at any rate
    assert is_zero(work_along(DRY, [X, Y], [A_ * s, B_ * s], over=(s, 0, 1), rate=5 * (1 + s**2))
                   + mu * N * sp.sqrt(A_**2 + B_**2))


def test_velocity_dependent_forces_that_cannot_be_taken_are_refused():
    with pytest.raises(AnalysisError, match="no tangent"):             # a repeated polygon point: no direction
        work_along(DRY, [X, Y], [(0, 0), (0, 0), (1, 0)])
    with pytest.raises(AnalysisError, match="no tangent"):             # a path that stays put
        work_along(DRY, [X, Y], [sp.sin(s) ** 2 + sp.cos(s) ** 2, 2], over=(s, 0, 1))
    with pytest.raises(AnalysisError, match="does not depend on its parameter"):
        work_along(DRY, [X, Y], [1, 2], over=(s, 0, 1))
    with pytest.raises(AnalysisError, match="increasing or decreasing"):  # the direction of travel is unknown
        work_along(DRY, [X, Y], [s, 0], over=(s, 0, sp.Symbol("q")))
    with pytest.raises(AnalysisError, match="also depends on t"):       # a moving surface (Wells Prob. 6.10)
        work_along([-mu * N * (X.diff(t) - sp.cos(t)) / _speed, 0], [X, Y], [s, 0], over=(s, 0, 1))
    with pytest.raises(AnalysisError, match="only first time derivatives"):
        work_along([X.diff(t, 2), 0], [X, Y], [s, 0], over=(s, 0, 1))
    with pytest.raises(AnalysisError, match="coordinate function"):     # plain symbols have no velocity
        work_along([X.diff(t), 0], [X, y], [s, 0], over=(s, 0, 1))
    with pytest.raises(AnalysisError, match="velocities"):              # still no potential for such a force
        potential_of(DRY, [X, Y])


def test_non_finite_components_and_a_bad_rate_are_named():
    for bad in (sp.nan, sp.zoo, sp.oo * x):
        with pytest.raises(AnalysisError, match="not finite"):
            potential_of([bad, 0], [x, y])
    with pytest.raises(AnalysisError, match="rate = .* must be one finite expression"):
        work_along([-X.diff(t), 0], [X, Y], [s, s], over=(s, 0, 1), rate=[1, 2])
    for wrong in (-1, 0, -(1 + s**2)):   # running the path backwards, or not at all
        with pytest.raises(AnalysisError, match="does not run the path from s0 to s1"):
            work_along([-X.diff(t), 0], [X, Y], [s, s], over=(s, 0, 1), rate=wrong)
    assert is_zero(work_along([-X.diff(t), 0], [X, Y], [s, s], over=(s, 1, 0), rate=-3) + 3)  # −c v·dx, v = 3


def test_an_undecided_exactness_test_is_settled_by_a_verified_potential(monkeypatch):
    """When the curl can be neither proven zero nor shown nonzero, a potential whose gradient is proven to be
    the field decides 'conservative'; without one the answer is an error saying both, never a guess."""
    from lagrange.analysis import conservative
    monkeypatch.setattr(conservative, "_curl_pairs", lambda Q, c, s: ([], AnalysisError("cannot decide (forced)")))
    q, bob, F, d = _sphere_on_a_pendulum_bob((a_, 0, -h))
    assert is_conservative(F, q, position=bob)
    assert _numerically_equal(potential_of(F, q, position=bob), -G * M * m / d)
    monkeypatch.setattr(conservative, "_INTEGRATE_SECONDS", 0.25)  # keep the test fast
    with pytest.raises(AnalysisError, match=r"cannot decide \(forced\), and no potential"):
        is_conservative([sp.sin(x) / sp.log(x), 0], [x, y])
    with pytest.raises(AnalysisError, match="could not be decided either") as err:
        potential_of([sp.sin(x) / sp.log(x), 0], [x, y])
    assert "passes the exactness test" not in str(err.value)


def test_cartesian_dry_friction_on_a_point_given_in_polar_coordinates():
    """−μN v/|v| with v = d/dt (r cosθ, r sinθ), through position=: along the spiral r = 1 + s, θ = s
    (0 ≤ s ≤ 1) the work is −μN × the arc length ∫₁² √(1 + u²) du = −μN(2√5 − √2 + asinh 2 − asinh 1)/2."""
    r, th = coordinates("r theta")
    pos = [r * sp.cos(th), r * sp.sin(th)]
    v = [c.diff(t) for c in pos]
    speed = sp.sqrt(v[0] ** 2 + v[1] ** 2)
    W = work_along([-mu * N * c / speed for c in v], [r, th], [1 + s, s], over=(s, 0, 1), position=pos)
    length = (2 * sp.sqrt(5) - sp.sqrt(2) + sp.asinh(2) - sp.asinh(1)) / 2
    assert _numerically_equal(W, -mu * N * length)
