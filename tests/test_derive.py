import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.simplification import is_zero


def _spring_pendulum():
    r, th = coordinates("r theta")
    m, g, k, r0, b = parameters("m g k r0 b")
    s = System(
        [r, th],
        bodies=[Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
        V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2,
        P=-b * r.diff(t) ** 2 / 2,
    )
    return s, r, th, (m, g, k, r0, b)


def test_book_form_of_spring_pendulum():
    s, r, th, (m, g, k, r0, b) = _spring_pendulum()
    e_r, e_th = s.equations()
    assert is_zero(e_r.lhs - (m * r.diff(t, 2) - m * r * th.diff(t) ** 2 + k * (r - r0) - m * g * sp.cos(th)))
    assert is_zero(e_r.rhs + b * r.diff(t))  # Wells: F = +dP/dqdot with P = -b rdot^2/2
    expected = m * r**2 * th.diff(t, 2) + 2 * m * r * r.diff(t) * th.diff(t) + m * g * r * sp.sin(th)
    assert is_zero(e_th.lhs - expected)
    assert e_th.rhs == 0


def test_rayleigh_equals_minus_power_function():
    s, r, th, (m, g, k, r0, b) = _spring_pendulum()
    s2 = System(s.coordinates, bodies=s.bodies, V=s.V, rayleigh=b * r.diff(t) ** 2 / 2)
    assert all(is_zero(a - c) for a, c in zip(s.forcing, s2.forcing))


def test_mass_matrix_symmetric_and_forcing():
    s, r, th, (m, *_rest) = _spring_pendulum()
    M = s.mass_matrix
    assert M == M.T
    assert all(is_zero(e) for e in (M - sp.diag(m, m * r**2)))


def test_energy_split_wells_2_55_translating_frame():
    """Wells (2.45)/(2.55): A contains the 1/2; B and C appear for a frame with constant acceleration."""
    x = coordinates("x")
    m, v, a = parameters("m v a")
    s = System([x], bodies=[Particle(m, (x + v * t + a * t**2 / 2,))])
    A, B, C = s.energy_split()
    assert is_zero(A[0, 0] - m / 2)
    assert is_zero(B[0] - m * (v + a * t))
    assert is_zero(C - m * (v + a * t) ** 2 / 2)
    (eq,) = s.equations()
    assert is_zero(eq.lhs - (m * x.diff(t, 2) + m * a))


def test_jacobi_integral_and_ignorable_coordinates():
    """Wells Ex. 3.3: particle on a table tied through a hole to a spring: p_theta = m r^2 thetadot."""
    r, th = coordinates("r theta")
    m, k = parameters("m k")
    s = System([r, th], bodies=[Particle(m, (r * sp.cos(th), r * sp.sin(th)))], V=k * r**2 / 2)
    ign = s.ignorable_coordinates()
    assert list(ign) == [th]
    assert is_zero(ign[th] - m * r**2 * th.diff(t))
    h = s.jacobi_integral()
    assert is_zero(h - (s.T + s.V))
    assert s.derived.is_conservative


def test_rotating_frame_gives_coriolis_and_centrifugal():
    """Wells Ex. 1.2: axes rotating at constant omega."""
    x, y = coordinates("x y")
    m, w = parameters("m omega")
    Fx, Fy = parameters("F_x F_y", real=True)
    c, s_ = sp.cos(w * t), sp.sin(w * t)
    s = System([x, y], bodies=[Particle(m, (x * c - y * s_, x * s_ + y * c))], forces={x: Fx, y: Fy})
    ex, ey = s.equations()
    assert is_zero(ex.lhs - ex.rhs - (m * x.diff(t, 2) - m * x * w**2 - 2 * m * w * y.diff(t) - Fx))
    assert is_zero(ey.lhs - ey.rhs - (m * y.diff(t, 2) - m * y * w**2 + 2 * m * w * x.diff(t) - Fy))
    # h differs from T + V in a moving frame (Jacobi integral of the rotating frame)
    assert not is_zero(s.jacobi_integral() - (s.T + s.V))


def test_printing_uses_dots():
    s, *_ = _spring_pendulum()
    text = str(s)
    assert "\u03b8\u0308" in text and "r\u0307" in text  # θ with two dots, r with one
    assert r"\ddot{\theta}" in s._repr_latex_()


def test_nlink_derivation_is_compact():
    from lagrange.examples import n_link_pendulum

    s = n_link_pendulum(5)
    ops = sp.count_ops(list(s.derived.mass_matrix)) + sp.count_ops(list(s.derived.forcing))
    assert ops < 3000


def _both_paths(system, monkeypatch):
    """The equations derived with symengine (when installed) and with sympy alone."""
    from lagrange.derive import lagrange as derive_module

    fast = derive_module.lagrange_equations(system)
    with monkeypatch.context() as m:
        m.setattr(derive_module, "_symengine_derivatives", lambda *args: None)
        slow = derive_module.lagrange_equations(system)
    return fast, slow


def test_symengine_and_sympy_derivatives_are_the_same_expressions(monkeypatch):
    """Every corpus system whose T symengine takes (a sample of every 7th, all chapters): M, f and the
    Jacobi integral agree symbolically (their difference simplifies to zero)."""
    import pytest

    pytest.importorskip("symengine")
    from lagrange.corpus import all_problems
    from lagrange.derive import lagrange as derive_module
    from lagrange.derive.lagrange import _symengine_derivatives

    monkeypatch.setattr(derive_module, "SYMENGINE_MIN_NODES", 0)  # textbook T's are below it
    from lagrange.model.coordinates import position_symbol, to_symbols, velocity_symbol

    checked = 0
    for problem in all_problems()[::7]:
        s = problem.system
        if s is None or s.constraints:
            continue
        coords = s.coordinates
        T = to_symbols(s.T, coords)
        q, qd = [position_symbol(c) for c in coords], [velocity_symbol(c) for c in coords]
        if _symengine_derivatives(T, q, qd) is None:
            continue
        fast, slow = _both_paths(s, monkeypatch)
        for a, b in [*zip(fast.mass_matrix, slow.mass_matrix), *zip(fast.forcing, slow.forcing),
                     (fast.jacobi, slow.jacobi)]:
            # (limit: the sample, every 7th problem, includes p11.12, whose difference has 1,127 operations —
            # above is_zero's default ceiling of 300, below which it would try expand)
            assert is_zero(a - b, limit=2000), (problem.id, a, b)
        checked += 1
    assert checked >= 20


def test_symengine_is_skipped_for_what_it_cannot_carry_back(monkeypatch):
    """Small T's, floats, functions it does not convert back unchanged and same-named symbols of different
    assumptions take the sympy path; a symbol's assumptions survive the symengine round trip."""
    import pytest

    pytest.importorskip("symengine")
    from lagrange.derive import lagrange as derive_module
    from lagrange.derive.lagrange import _symengine_derivatives

    q, qd = sp.Symbol("q", real=True), sp.Symbol("q_dot", real=True)
    assert _symengine_derivatives(sp.cos(q) * qd**2, [q], [qd]) is None  # small: sympy is cheaper
    monkeypatch.setattr(derive_module, "SYMENGINE_MIN_NODES", 0)
    m = sp.Symbol("m", positive=True)
    assert _symengine_derivatives(sp.Float("0.1", 30) * qd**2, [q], [qd]) is None
    assert _symengine_derivatives(sp.Abs(q) * qd**2, [q], [qd]) is None
    assert _symengine_derivatives((m + sp.Symbol("m")) * qd**2, [q], [qd]) is None
    dT, hessian, conv = _symengine_derivatives(m * sp.cos(q) * qd**2 / 2, [q], [qd])
    assert hessian[0, 0] == m * sp.cos(q) and hessian[0, 0].free_symbols == {m, q}
    assert sp.simplify(conv[0] - (-m * sp.sin(q) * qd**2 + m * sp.sin(q) * qd**2 / 2)) == 0
