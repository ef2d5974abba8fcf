"""Mass points under Gauss' principle: the reference's worked cases E8–E15, E22, E25 and designs T-B, T-G,
T-H (Sonneveld 2015; numbers from /shared/reference/sonneveld.md, independently verified there)."""

import itertools

import numpy as np
import pytest
import sympy as sp
from scipy.linalg import null_space
from scipy.optimize import minimize

from lagrange import t
from lagrange.errors import DeclarationError, InconsistentConstraintError
from lagrange.gauss.balance import angular_momentum, kinetic_energy, momentum, point_balance
from lagrange.gauss.points import (
    SURFACE_SYMBOLS,
    Dragging,
    Link,
    PointConstraint,
    PointSystem,
    Surface,
    point_symbols,
    simulate_points,
)


def test_e9_fixed_dragger_centripetal():
    s = PointSystem([2.0], [Dragging(0, (0, 0, 0), 0.5, "cord")])
    r = s.accelerations(0.0, [[0.0, 0.5, 0.0]], [[3.0, 0.0, 0.0]])
    assert np.allclose(r.a, [[0, -18.0, 0]], atol=1e-12)  # v²/L towards the pivot
    assert r.tension("cord") == pytest.approx(36.0, rel=1e-12)  # m v²/L


def test_e9_moving_dragger_acceleration_along_the_cord():
    path = (sp.sin(2 * t), sp.cos(3 * t), t**2)
    s = PointSystem([1.5], [Dragging(0, path, 1.0, "cord")])
    tt = 0.4
    xd = np.array([float(sp.sympify(c).subs(t, tt)) for c in path])
    ad = np.array([float(sp.diff(c, t, 2).subs(t, tt)) for c in path])
    vd = np.array([float(sp.diff(c, t).subs(t, tt)) for c in path])
    x = xd - np.array([0.6, 0.0, 0.8])
    r_vec = xd - x
    v = vd - np.cross([0.3, -0.2, 0.5], r_vec)  # ṙ ⟂ r: the cord length is kept
    a = s.accelerations(tt, [x], [v]).a[0]
    rd = vd - v
    expected = (r_vec @ ad + rd @ rd) / (r_vec @ r_vec) * r_vec  # reference E9, eq. (21)
    assert np.allclose(a, expected, rtol=1e-12, atol=1e-12)


def test_e10_duplicated_dragger_and_jamming():
    x, v = [[0.0, 0.0, 0.0]], [[0.0, 1.5, 0.0]]
    one = PointSystem([1.0], [Dragging(0, (1, 0, 0), 1.0, "d1")]).accelerations(0, x, v)
    two = PointSystem([1.0], [Dragging(0, (1, 0, 0), 1.0, "d1"), Dragging(0, (1, 0, 0), 1.0, "d1 again")])
    r2 = two.accelerations(0, x, v)
    assert np.allclose(r2.a, one.a, atol=1e-13) and r2.redundant == 1
    assert r2.constraint_forces.sum(axis=0) == pytest.approx(one.constraint_forces.sum(axis=0), abs=1e-12)
    jam = PointSystem([1.0], [Dragging(0, (1, 0, 0), 1.0, "near"), Dragging(0, (2, 0, 0), 2.0, "far")])
    with pytest.raises(InconsistentConstraintError) as exc:
        jam.accelerations(0, x, v)
    assert set(exc.value.constraints) == {"near", "far"} and "near, far" in str(exc.value)
    rest = jam.accelerations(0, x, [[0.0, 0.0, 0.0]])  # v = 0: consistent, ẍ = 0, λ1 + 2λ2 = 0 free
    assert np.allclose(rest.a, 0, atol=1e-14) and rest.redundant == 1


def test_e11_spinning_barbell():
    m0, m1, L, w = 2.0, 3.0, 1.5, 4.0
    xc0, xc1 = m1 * L / (m0 + m1), m0 * L / (m0 + m1)  # distances from the centre of mass
    s = PointSystem([m0, m1], [Link(0, 1, L, "bar")])
    r = s.accelerations(0, [[-xc0, 0, 0], [xc1, 0, 0]], [[0, -w * xc0, 0], [0, w * xc1, 0]])
    assert np.allclose(r.a[0], [14.4, 0, 0], atol=1e-12)
    assert r.tension("bar") == pytest.approx(28.8, rel=1e-12)
    assert np.allclose(m0 * r.a[0] + m1 * r.a[1], 0, atol=1e-12)


def test_e11_spider_closed_form_equals_kkt():
    rng = np.random.default_rng(5)
    N, m0 = 4, 1.7
    mk = rng.uniform(0.5, 2.0, N)
    R = rng.normal(size=(3, N))
    Rd = rng.normal(size=(3, N))
    Rd -= R * np.sum(R * Rd, axis=0) / np.sum(R * R, axis=0)  # keep every leg length: ṙ_k ⟂ r_k
    x0, v0 = rng.normal(size=3), rng.normal(size=3)
    D = np.diag(m0 / mk * np.sum(R * R, axis=0))  # eq. (42)
    mu = np.linalg.solve(D + R.T @ R, m0 * np.sum(Rd * Rd, axis=0))  # eq. (46)
    links = [Link(0, k + 1, float(np.linalg.norm(R[:, k]))) for k in range(N)]
    s = PointSystem([m0, *mk], links)
    r = s.accelerations(0, np.vstack([x0, (x0[:, None] + R).T]), np.vstack([v0, (v0[:, None] + Rd).T]))
    assert np.allclose(r.a[0], R @ mu / m0, atol=1e-12)  # eq. (44)
    assert np.allclose(r.a[1:], (-mu * R / mk).T, atol=1e-12)  # eq. (45)


def _truss(seed=0):
    rng = np.random.default_rng(seed)
    x = rng.normal(size=(5, 3))
    links = [Link(i, j, float(np.linalg.norm(x[j] - x[i])), f"{i}-{j}") for i, j in
             [(0, 1), (1, 2), (2, 3), (3, 4), (0, 2), (1, 3)]]
    v = rng.normal(size=(5, 3))
    s = PointSystem(rng.uniform(0.5, 2, 5), links)
    x, v = s.project(0.0, x, v)
    return s, x, v, rng


def test_e13_free_construction_balance_and_newton_third_law():
    s, x, v, _ = _truss()
    r = s.accelerations(0.0, x, v)
    m = np.array(s.masses)
    assert np.allclose(m @ r.a, 0, atol=1e-12)  # ṗ = 0
    assert np.allclose((m[:, None] * np.cross(x, r.a)).sum(axis=0), 0, atol=1e-12)  # ḃ = 0
    assert abs(np.sum(m[:, None] * v * r.a)) < 1e-12  # Ẇ = 0
    for k, link in enumerate(s.constraints):  # each link pulls its ends with equal and opposite forces
        f = r.constraint_forces[k]
        assert np.allclose(f[link.i], -f[link.j]) and np.allclose(np.cross(f[link.i], x[link.j] - x[link.i]), 0)


def test_t_b_gauss_optimality_and_slsqp():
    s, x, v, rng = _truss(1)
    s = PointSystem(s.masses, s.constraints, gravity=(0, 0, -9.81),
                    forces=lambda t_, x_, v_: -0.3 * v_)
    r = s.accelerations(0.0, x, v)
    F = r.applied.ravel()
    M = s.mass_vector

    def Z(a):
        return 0.5 * np.sum(M * (a - F / M) ** 2)

    A, b, _, _ = s.constraint_rows(0.0, x, v)
    N = null_space(A)
    for _ in range(5):  # Z(ẍ + δ) − Z(ẍ) = ½ δᵀMδ for δ in N(A): the gradient M ẍ − F is ⟂ N(A)
        delta = N @ rng.normal(size=N.shape[1])
        assert Z(r.a.ravel() + delta) - Z(r.a.ravel()) == pytest.approx(0.5 * delta @ (M * delta), rel=1e-9)
    res = minimize(Z, np.zeros(15), method="SLSQP", options={"ftol": 1e-15, "maxiter": 1000},
                   constraints=[{"type": "eq", "fun": lambda a: A @ a - b, "jac": lambda a: A}])
    assert np.allclose(res.x, r.a.ravel(), atol=1e-6)


def test_t_g_implied_links_change_nothing():
    rng = np.random.default_rng(2)
    x = rng.normal(size=(4, 3))
    tet = [Link(i, j, float(np.linalg.norm(x[j] - x[i]))) for i, j in itertools.combinations(range(4), 2)]
    v = rng.normal(size=(4, 3))
    s = PointSystem([1.0, 2.0, 1.5, 0.7], tet, gravity=(0, 0, -1.0))
    x, v = s.project(0.0, x, v)
    base = s.accelerations(0.0, x, v)
    # a fifth point linked to all four: its 4 links fix it, 1 of them is implied → redundant
    x5 = x.mean(axis=0) + [0.1, 0.2, 0.3]
    xs = np.vstack([x, x5])
    extra = [Link(i, 4, float(np.linalg.norm(x5 - x[i]))) for i in range(4)]
    s5 = PointSystem([*s.masses, 1.0], tet + extra + [tet[0]], gravity=(0, 0, -1.0))
    xs, vs = s5.project(0.0, xs, np.vstack([v, np.zeros(3)]))
    r5 = s5.accelerations(0.0, xs, vs)
    assert r5.redundant == 2  # the repeated link and one implied link
    # the same 5-point body without redundancy (9 = 3·5 − 6 links) gives the same accelerations
    s9 = PointSystem(s5.masses, tet + extra[:3], gravity=(0, 0, -1.0))
    assert np.allclose(s9.accelerations(0.0, xs, vs).a, r5.a, atol=1e-12)
    assert base.redundant == 0


def test_t_h_galilean_invariance():
    u = np.array([0.7, -1.1, 0.4])
    path = sp.Matrix([sp.cos(t), sp.sin(2 * t), 0])
    s = PointSystem([1.0, 2.0], [Dragging(0, path, 1.2, "cord"), Link(0, 1, 0.8, "bar")], gravity=(0, 0, -9.81))
    sb = PointSystem([1.0, 2.0], [Dragging(0, path + sp.Matrix(u) * t, 1.2, "cord"), Link(0, 1, 0.8, "bar")],
                     gravity=(0, 0, -9.81))
    tt = 0.3
    x0 = np.array([[float(path[0].subs(t, tt)) - 1.2, float(path[1].subs(t, tt)), 0], [0, 0, 0]])
    x0[1] = x0[0] + [0, 0.8, 0]
    x, v = s.project(tt, x0, np.array([[0.1, 0.3, 0.2], [0.4, -0.2, 0.1]]))
    a = s.accelerations(tt, x, v).a
    ab = sb.accelerations(tt, x + u * tt, v + u).a
    assert np.allclose(a, ab, atol=1e-12)
    m, M = np.array([1.0, 2.0]), 3.0
    W, p = kinetic_energy(m, v), momentum(m, v)
    assert kinetic_energy(m, v + u) == pytest.approx(W + p @ u + 0.5 * M * u @ u)  # eq. (15) with −u
    assert np.allclose(momentum(m, v + u), p + M * u)  # eq. (14)


def test_e22_double_pendulum_accelerations_and_tensions():
    m1, m2, l1, l2, g = 1.3, 0.7, 1.1, 0.8, 9.81
    th1, th2, w1, w2 = 0.7, -0.4, 1.2, -0.5
    x1 = np.array([l1 * np.sin(th1), -l1 * np.cos(th1), 0])
    x2 = x1 + [l2 * np.sin(th2), -l2 * np.cos(th2), 0]
    v1 = np.array([l1 * np.cos(th1) * w1, l1 * np.sin(th1) * w1, 0])
    v2 = v1 + [l2 * np.cos(th2) * w2, l2 * np.sin(th2) * w2, 0]
    s = PointSystem([m1, m2], [Dragging(0, (0, 0, 0), l1, "rod1"), Link(0, 1, l2, "rod2")], gravity=(0, -g, 0))
    r = s.accelerations(0, [x1, x2], [v1, v2])
    assert np.allclose(r.a[:, :2].ravel(), [-6.96515996, -3.79565784, 1.17885302, -7.02175041], atol=5e-9)
    assert r.tension("rod1") == pytest.approx(12.7744, abs=1e-4)
    assert r.tension("rod2") == pytest.approx(2.1191, abs=1e-4)


def test_e25_pendulum_on_a_moving_support():
    tt, th, thd = 0.3, 0.4, -0.8
    xs, vs = 0.1 * np.cos(5 * tt), -0.5 * np.sin(5 * tt)
    x = np.array([xs + np.sin(th), -np.cos(th), 0])
    v = np.array([vs + np.cos(th) * thd, np.sin(th) * thd, 0])
    s = PointSystem([1.0], [Dragging(0, (sp.Rational(1, 10) * sp.cos(5 * t), 0, 0), 1.0, "rod")],
                    gravity=(0, -9.81, 0))
    r = s.accelerations(tt, [x], [v])
    assert np.allclose(r.a[0, :2], [-3.79467701, -0.83474485], atol=5e-9)
    assert r.tension("rod") == pytest.approx(9.74447426, abs=5e-9)
    assert v @ (r.applied[0] + r.constraint_forces[0, 0]) == pytest.approx(4.94874080, abs=5e-9)  # Ṫ
    # Lagrange's closed form θ̈ = −(g sinθ + ẍ_s cosθ)/l maps to the same Cartesian acceleration
    xs_dd = -2.5 * np.cos(5 * tt)
    thdd = -(9.81 * np.sin(th) + xs_dd * np.cos(th))
    assert thdd == pytest.approx(-3.65731074, abs=5e-9)
    assert r.a[0, 0] == pytest.approx(xs_dd + np.cos(th) * thdd - np.sin(th) * thd**2, abs=1e-12)


def test_particle_on_a_surface_closed_form():
    X, Y, Z = SURFACE_SYMBOLS
    phi = X**2 / 4 + Y**2 + Z**2 / 9 - 1  # an ellipsoid
    s = PointSystem([1.7], [Surface(0, phi, "shell")], gravity=(0, 0, -9.81))
    x = np.array([1.2, 0.5, 0.0])
    x[2] = 3 * np.sqrt(1 - x[0] ** 2 / 4 - x[1] ** 2)
    grad = np.array([x[0] / 2, 2 * x[1], 2 * x[2] / 9])
    v = np.cross(grad, [0.3, -0.7, 0.2])
    hess = np.diag([0.5, 2.0, 2 / 9])
    F = 1.7 * np.array([0, 0, -9.81])
    lam = -(1.7 * v @ hess @ v + grad @ F) / (grad @ grad)
    r = s.accelerations(0.0, [x], [v])
    assert r.multipliers[0] == pytest.approx(lam, rel=1e-12)
    assert np.allclose(1.7 * r.a[0], F + lam * grad, atol=1e-12)


def test_general_point_constraint_and_symbolic_forces():
    X, V = point_symbols(2)
    # the two points stay at equal height: z0 − z1 = 0; a spring between them (symbolic force)
    k = 3.0
    dx = X[1] - X[0]
    s = PointSystem([1.0, 2.0], [PointConstraint(X[0, 2] - X[1, 2], 2, "level")],
                    forces={0: list(k * dx), 1: list(-k * dx)}, gravity=(0, 0, -1.0))
    x = np.array([[0, 0, 1.0], [1, 2, 1.0]])
    v = np.array([[0.1, 0, 0.5], [0, 0.3, 0.5]])
    r = s.accelerations(0, x, v)
    assert r.a[0, 2] == pytest.approx(r.a[1, 2]) and r.a[0, 2] == pytest.approx(-1.0)
    assert np.allclose(r.a[0, :2], k * np.array([1, 2])) and np.allclose(r.a[1, :2], -k * np.array([1, 2]) / 2)


def test_declaration_errors_are_collected():
    with pytest.raises(DeclarationError) as exc:
        PointSystem([1.0, -2.0], [Link(0, 5, 1.0), Dragging(3, (0, 0, 0), 1.0)])
    assert len(exc.value.problems) == 3
    with pytest.raises(DeclarationError, match="lagrange.t"):
        Dragging(0, (sp.Symbol("w") * t, 0, 0), 1.0)


def test_e15_balance_laws_and_drift_along_a_run():
    path = sp.Matrix([sp.Rational(1, 5) * sp.sin(3 * t), 0, 0])
    s = PointSystem([1.0, 0.5], [Dragging(0, path, 1.0, "cord"), Link(0, 1, 0.7, "bar")], gravity=(0, -9.81, 0),
                    forces=lambda t_, x_, v_: -0.1 * v_)
    x0 = np.array([[0.6, -0.8, 0.0], [0.6, -1.5, 0.1]])
    v0 = np.array([[0.5, 0.2, 0.0], [0.3, 0.0, 0.4]])
    traj = simulate_points(s, np.linspace(0, 1, 401), x0, v0)
    assert np.max(traj.violation) < 1e-8  # drift between projections
    rep = point_balance(s, traj)
    assert rep.ok(1e-7), str(rep)  # Simpson's rule error ~ h^4 (1.5e-6 at h = 0.01, 6e-9 at h = 0.0025)
    # a wrong force bookkeeping is caught: leaving out the cord's force breaks the energy and momentum laws
    F_wrong = np.array([s.accelerations(ti, xi, vi).applied for ti, xi, vi in zip(traj.t, traj.x, traj.v)])
    from lagrange.gauss.balance import balance_residuals

    bad = balance_residuals(traj.t, s.masses, traj.x, traj.v, F_wrong)
    assert bad.energy > 1e-3 and bad.momentum > 1e-3


def test_e8_clipping_the_bar():
    m0, m1 = 2.0, 3.0  # E11's barbell (L = 1.5, ω = 4) at the moment its bar is clipped
    x = np.array([[-0.9, 0, 0], [0.6, 0, 0]])
    v = np.array([[0, -3.6, 0], [0, 2.4, 0]])
    free = PointSystem([m0, m1])  # the bar is clipped: no constraint left
    traj = simulate_points(free, np.linspace(0, 1, 11), x, v)
    assert np.allclose(traj.x[-1], x + v, atol=1e-12) and np.allclose(traj.v[-1], v)
    assert kinetic_energy([m0, m1], v) == pytest.approx(21.6)
    assert np.allclose(momentum([m0, m1], traj.v[-1]), 0) and np.allclose(angular_momentum([m0, m1], traj.x,
                                                                                             traj.v).std(axis=0), 0)
