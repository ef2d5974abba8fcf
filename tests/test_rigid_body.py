"""Rigid bodies: Wells' T (8.10), Euler angles, torques, Euler's equations, frames and the rotating earth."""

import warnings

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from lagrange import (
    EulerAngles,
    Force,
    Particle,
    Quaternion,
    RigidBody,
    RotationSequence,
    SingularMassMatrixError,
    System,
    Torque,
    coordinates,
    parameters,
    rot_x,
    rot_y,
    rot_z,
    t,
)
from lagrange.corpus.compare import agree
from lagrange.derive.euler import projected_residuals, support_loads
from lagrange.model.coordinates import to_symbols
from lagrange.model.frames import EarthFrame, Frame
from lagrange.model.inertia import point_masses
from lagrange.simplification import is_zero


def heavy_top(orientation_coords=None):
    psi, th, ph = coordinates("psi theta phi")
    M, g, l, I1, I3 = parameters("M g l I1 I3")
    top = RigidBody(M, (I1, I1, I3), orientation=EulerAngles(psi, th, ph), com=(0, 0, l))
    s = System([psi, th, ph], bodies=[top], V=M * g * top.centre_of_mass[2], name="heavy symmetric top")
    return s, (psi, th, ph), (M, g, l, I1, I3)


def test_rigid_body_energy_equals_particle_model():
    """A rigid set of particles as one RigidBody (inertia from the points) has the T of the particles."""
    x, y, z, a, b, c = coordinates("x y z a b c")
    m1, m2, m3 = parameters("m1 m2 m3")
    pts = [(m1, (1, 0, 0)), (m2, (0, 2, 1)), (m3, (-1, 1, 2))]
    R = rot_z(a) * rot_x(b) * rot_z(c)
    origin = (x, y, z)
    body = RigidBody(m1 + m2 + m3, point_masses(pts), origin=origin, orientation=R,
                     com=tuple(sum((mi * sp.Matrix(ri) for mi, ri in pts), sp.zeros(3, 1)) / (m1 + m2 + m3)))
    particles = [Particle(mi, body.point(ri)) for mi, ri in pts]
    T_particles = sum(p.kinetic_energy() for p in particles)
    coords = [x, y, z, a, b, c]
    syms = [to_symbols(q, coords) for q in coords] + [to_symbols(q.diff(t), coords) for q in coords]
    agree(to_symbols(body.kinetic_energy(), coords), to_symbols(T_particles, coords), syms + [m1, m2, m3])


def test_euler_angle_angular_velocity_matches_rotation_matrix():
    psi, th, ph = coordinates("psi theta phi")
    e = EulerAngles(psi, th, ph)
    R = e.matrix
    W = R.T * R.diff(t)
    direct = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
    for i in range(3):
        assert is_zero(direct[i] - e.body_angular_velocity()[i])


def test_torque_generalized_forces_wells_8_12():
    s, (psi, th, ph), _ = heavy_top()
    body = s.bodies[0]
    tx, ty, tz = parameters("tau_x tau_y tau_z", real=True)
    s2 = System(s.coordinates, bodies=[body], forces=[Torque(body, (tx, ty, tz))])
    F = s2.forces
    assert is_zero(F[th] - (tx * sp.cos(ph) - ty * sp.sin(ph)))
    assert is_zero(F[psi] - (tx * sp.sin(th) * sp.sin(ph) + ty * sp.sin(th) * sp.cos(ph) + tz * sp.cos(th)))
    assert is_zero(F[ph] - tz)


def test_top_momenta_wells_8_13_and_euler_projection():
    s, (psi, th, ph), (M, g, l, I1, I3) = heavy_top()
    ign = s.ignorable_coordinates()
    P_phi = I3 * (psi.diff(t) * sp.cos(th) + ph.diff(t))
    assert is_zero(ign[ph] - P_phi)
    assert is_zero(ign[psi] - (I1 * psi.diff(t) * sp.sin(th) ** 2 + P_phi * sp.cos(th)))
    # Euler's equations projected on ∂ω/∂q̇ reproduce Lagrange's equations (gravity torque about the tip)
    body = s.bodies[0]
    weight = sp.Matrix([0, 0, -M * g])
    torque = body.com.cross(body.R.T * weight)
    res = projected_residuals(body, s.coordinates, torque)
    for q, r, eq in zip(s.coordinates, res, s.equations()):
        lag = eq.lhs - eq.rhs
        coords = list(s.coordinates)
        syms = [to_symbols(c, coords) for c in coords] + [to_symbols(c.diff(t), coords) for c in coords] \
            + [to_symbols(c.diff(t, 2), coords) for c in coords]
        agree(to_symbols(r, coords), to_symbols(lag, coords), syms + [M, g, l, I1, I3], what=f"θ={q}")


def test_heavy_top_invariants_and_nutation_limits():
    """Energy and both momenta stay constant; cos θ oscillates between the roots of the classical cubic
    f(u) = (α − βu)(1 − u²) − (b − a u)² (a = p_φ/I1, b = p_ψ/I1, α = 2E/I1, β = 2Mgl/I1)."""
    s, (psi, th, ph), (M, g, l, I1, I3) = heavy_top()
    p = {M: 1.0, g: 9.81, l: 0.2, I1: 0.05, I3: 0.02}
    th0, wspin, wprec = 0.6, 60.0, 1.0
    sol = s.simulate(3, {psi: 0, th: th0, ph: 0, psi.diff(t): wprec, th.diff(t): 0, ph.diff(t): wspin}, p,
                     rtol=1e-11, atol=1e-12, n_points=6001)
    assert sol.energy_error() < 1e-9
    I1v, I3v, Mgl = 0.05, 0.02, 1.0 * 9.81 * 0.2
    th_, pd, fd, tdot = sol[th], sol[psi.diff(t)], sol[ph.diff(t)], sol[th.diff(t)]
    p_phi = I3v * (pd * np.cos(th_) + fd)
    p_psi = I1v * pd * np.sin(th_) ** 2 + p_phi * np.cos(th_)
    assert np.ptp(p_phi) < 1e-9 * abs(p_phi[0]) and np.ptp(p_psi) < 1e-9 * abs(p_psi[0])
    E = 0.5 * I1v * (tdot**2 + pd**2 * np.sin(th_) ** 2) + 0.5 * I3v * (pd * np.cos(th_) + fd) ** 2 + Mgl * np.cos(th_)
    a, b = p_phi[0] / I1v, p_psi[0] / I1v
    alpha = 2 * (E[0] - 0.5 * p_phi[0] ** 2 / I3v) / I1v
    beta = 2 * Mgl / I1v
    # f(u) = (alpha - beta u)(1 - u^2) - (b - a u)^2 as a polynomial in u
    f = np.polynomial.Polynomial([alpha, -beta]) * np.polynomial.Polynomial([1, 0, -1]) \
        - np.polynomial.Polynomial([b, -a]) ** 2
    roots = sorted(r.real for r in f.roots() if abs(r.imag) < 1e-9 and -1 <= r.real <= 1)
    u = np.cos(th_)
    assert u.max() == pytest.approx(roots[-1], abs=2e-6)
    assert u.min() == pytest.approx(roots[-2], abs=2e-6)


def test_gimbal_lock_detected_and_quaternion_sleeping_top():
    s, (psi, th, ph), (M, g, l, I1, I3) = heavy_top()
    p = {M: 1.0, g: 9.81, l: 0.1, I1: 0.02, I3: 0.01}
    with pytest.raises(SingularMassMatrixError, match="Gimbal lock.*Quaternion"):
        s.simulate(1, {psi: 0, th: 0, ph: 0, psi.diff(t): 0, th.diff(t): 0, ph.diff(t): 100}, p)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        s.simulate(0.01, {psi: 0, th: 1e-5, ph: 0, psi.diff(t): 0, th.diff(t): 0, ph.diff(t): 100}, p)
    assert any("nearly singular" in str(w.message) for w in caught)
    # the remedy: the same top with a quaternion orientation spins upright ("sleeps") and stays there
    q = coordinates("q0 q1 q2 q3")
    topq = RigidBody(M, (I1, I1, I3), orientation=Quaternion(*q), com=(0, 0, l))
    sq = System(list(q), bodies=[topq], V=M * g * topq.centre_of_mass[2])
    ic = {q[0]: 1, q[1]: 1e-4, q[2]: 0, q[3]: 0, q[0].diff(t): 0, q[1].diff(t): 0, q[2].diff(t): 0, q[3].diff(t): 50}
    sol = sq.simulate(2, ic, p)
    cos_tilt = sol["q0"] ** 2 - sol["q1"] ** 2 - sol["q2"] ** 2 + sol["q3"] ** 2
    assert cos_tilt.min() > 0.9999  # fast spin (ω = 100 > ω_crit ≈ 28 rad/s): stable
    assert sol.energy_error() < 1e-7 and sol.max_constraint_violation() < 1e-10
    slow = sq.simulate(2, {**ic, q[3].diff(t): 5}, p)  # ω = 10 < ω_crit: it falls over
    cos_slow = slow["q0"] ** 2 - slow["q1"] ** 2 - slow["q2"] ** 2 + slow["q3"] ** 2
    assert cos_slow.min() < 0.5


def _omega_function(body, coords):
    syms_q = [to_symbols(c, coords) for c in coords]
    syms_v = [to_symbols(c.diff(t), coords) for c in coords]
    return sp.lambdify([syms_q + syms_v], to_symbols(body.angular_velocity, coords), "numpy")


@pytest.mark.parametrize("axis, stable", [(0, True), (1, False), (2, True)])
def test_torque_free_intermediate_axis_and_euler_equations(axis, stable):
    """Torque-free body with I = (1, 2, 3): spin about the largest and smallest axes is stable, about the
    intermediate one it is not. ω(t) from Lagrange (quaternions) agrees with Euler's equations integrated
    directly (a second formulation)."""
    q = coordinates("q0 q1 q2 q3")
    J = np.array([1.0, 2.0, 3.0])
    body = RigidBody(1, tuple(int(v) for v in J), orientation=Quaternion(*q))
    s = System(list(q), bodies=[body])
    w0 = np.full(3, 1e-3)
    w0[axis] = 2.0
    ic = {**{qi: v for qi, v in zip(q, (1, 0, 0, 0))}, **{qi.diff(t): v for qi, v in zip(q, (0, *(w0 / 2)))}}
    sol = s.simulate(12, ic, {}, rtol=1e-11, atol=1e-12, n_points=121)
    omega = np.array([np.ravel(_omega_function(body, list(q))(yi)) for yi in sol.y])

    def euler(_, w):
        return [(J[1] - J[2]) * w[1] * w[2] / J[0], (J[2] - J[0]) * w[2] * w[0] / J[1],
                (J[0] - J[1]) * w[0] * w[1] / J[2]]

    ref = solve_ivp(euler, (0, 12), w0, t_eval=sol.t, rtol=1e-12, atol=1e-13, method="DOP853").y.T
    assert np.max(np.abs(omega - ref)) < 1e-6
    drift = np.max(np.abs(omega[:, axis] - w0[axis]))
    assert (drift < 1e-2) if stable else (drift > 1.0)


def test_support_loads_of_an_unbalanced_rotor():
    """A body turning at constant ω about a fixed vertical axis with its c.m. at distance r: the bearing
    must supply the centripetal force M ω² r toward the axis."""
    M, r, w = parameters("M r omega")
    body = RigidBody(M, (1, 1, 1), orientation=rot_z(w * t), com=(r, 0, 0))
    F, _ = support_loads(body, frame="inertial")
    centripetal = sp.Matrix([-M * w**2 * r * sp.cos(w * t), -M * w**2 * r * sp.sin(w * t), 0])
    assert all(is_zero(e) for e in (F - centripetal))


def test_earth_frame_wells_14_16_cancels_R_omega_squared(agrees_with_wells_14_16):
    x, y, z = coordinates("x1 y1 z1")
    m, gp, w, R, Phi = parameters("m gp omega_e R Phi")
    E = EarthFrame(Phi, w, R)
    p = Particle(m, E.point((x, y, z)))
    s = System([x, y, z], bodies=[p], forces=[Force(p, E.gravity_force(m, gp))])
    assert all(R not in f.free_symbols for f in s.derived.forcing)
    agrees_with_wells_14_16(s, (x, y, z), m, w, Phi, gp)


def test_foucault_pendulum_precession_rate():
    """The swing plane turns at −ω_e sinΦ (clockwise in the north) to 1e-3 over many swings."""
    x, y = coordinates("x y")
    m, gp, L = parameters("m gp L")
    Phi, omega = 0.8, 2e-3  # ω exaggerated (still ≪ √(g/L) = 0.99) so that the test runs in seconds
    E = EarthFrame(sp.Float(Phi), sp.Float(omega), sp.Integer(6_371_000))
    bob = Particle(m, E.point((x, y, L - sp.sqrt(L**2 - x**2 - y**2))))
    s = System([x, y], bodies=[bob], forces=[Force(bob, E.gravity_force(m, gp))])
    p = {m: 1.0, gp: 9.81, L: 10.0}
    T_end = 1200.0
    sol = s.simulate(T_end, {x: 0.05, y: 0, x.diff(t): 0, y.diff(t): 0}, p, rtol=1e-10, atol=1e-12,
                     n_points=24001)
    r = np.hypot(sol[x], sol[y])
    peaks = np.where((r[1:-1] > r[:-2]) & (r[1:-1] >= r[2:]))[0] + 1
    ang = np.unwrap(2 * np.arctan2(sol[y][peaks], sol[x][peaks])) / 2  # the swing direction, modulo π
    rate = np.polyfit(sol.t[peaks], ang, 1)[0]
    assert rate == pytest.approx(-omega * np.sin(Phi), rel=1e-3)


def test_nested_frames_compose():
    a, b = parameters("a b")
    x = coordinates("x")
    inner = Frame(origin=(a, 0, 0), rotation=rot_z(b * t), parent=Frame(rotation=rot_z(a * t)))
    P = inner.point((x, 0, 0))
    expected = rot_z(a * t) * (sp.Matrix([a, 0, 0]) + rot_z(b * t) * sp.Matrix([x, 0, 0]))
    assert all(is_zero(e) for e in (P - expected))
    w = inner.angular_velocity()
    assert is_zero(w[2] - (a + b))


def test_rotation_sequence_matches_its_matrix_and_the_general_angular_velocity():
    """RotationSequence's closed-form ω (body and inertial) equals vee(RᵀṘ) of the multiplied-out matrix, and a
    rigid body's T is the same with either orientation (numbers at random states)."""
    from lagrange.model.rotations import body_angular_velocity, space_angular_velocity

    a, b, c = coordinates("a b c")
    lam, m = parameters("lam m")
    seq = RotationSequence(("z", a), ("x", b), ("y", c + lam), ("z", a - c), ("y", -lam))
    R = rot_z(a) * rot_x(b) * rot_y(c + lam) * rot_z(a - c) * rot_y(-lam)
    assert (seq.matrix - R).applyfunc(sp.expand) == sp.zeros(3, 3)
    J = sp.Matrix([[3, 0, 1], [0, 2, 0], [1, 0, 4]])
    pairs = [
        (seq.body_angular_velocity(), body_angular_velocity(R)),
        (seq.space_angular_velocity(), space_angular_velocity(R)),
        (RigidBody(m, J, origin=(a, b, 0), orientation=seq).kinetic_energy(),
         RigidBody(m, J, origin=(a, b, 0), orientation=R).kinetic_energy()),
    ]
    coords = [a, b, c]
    rng = np.random.default_rng(7)
    for _ in range(3):
        values = dict(zip(["a", "b", "c", "a_dot", "b_dot", "c_dot", "lam", "m"], rng.uniform(-2, 2, 8)))
        values["m"] = abs(values["m"])
        def number(expr, values=values):
            e = sp.Matrix([to_symbols(expr, coords)])
            return np.array(e.evalf(subs={s: values[s.name] for s in e.free_symbols}), dtype=float)

        for mine, general in pairs:
            assert np.allclose(number(mine), number(general), rtol=1e-12, atol=1e-12)
    with pytest.raises(ValueError, match="'x', 'y' or 'z'"):
        RotationSequence(("w", a))
    with pytest.raises(ValueError, match="at least one"):
        RotationSequence()
    with pytest.raises(ValueError, match="pairs"):
        RotationSequence(a)
    # substitution keeps the sequence (used by lagrange.eliminate)
    body = RigidBody(m, J, orientation=seq).subs({c: 0})
    assert isinstance(body.orientation, RotationSequence) and not body.orientation.matrix.has(c)


@pytest.mark.parametrize("com", [(0, 0, "l"), ("l", 0, 0), (0, "l", 0), ("l", "k", "l - k")])
def test_lazy_rotation_matrix_and_centre_of_mass_by_columns(com):
    """A body with Euler angles builds R only when asked; its centre of mass, taken from the columns it needs,
    is the very expression R r̄ gives (the same tree, not only equal values); the Euler matrix is the product
    R_z(ψ) R_x(θ) R_z(φ); a matrix orientation of the wrong shape is still refused at declaration; and a
    System declared from it has the symbols of R among its declared symbols without building R."""
    psi, th, ph, x = coordinates("psi theta phi x")
    M, l, k, I1, I3 = parameters("M l k I1 I3")
    r = [sp.sympify(c, locals={"l": l, "k": k}) for c in com]
    e = EulerAngles(psi, th, ph)
    assert (e.matrix - rot_z(psi) * rot_x(th) * rot_z(ph)).applyfunc(sp.expand) == sp.zeros(3, 3)
    assert [e.column(j) for j in range(3)] == [list(e.matrix[:, j]) for j in range(3)]
    lazy = RigidBody(M, (I1, I1, I3), origin=(x, 0, 0), orientation=e, com=r)
    com_lazy = lazy.centre_of_mass
    assert "R" not in vars(lazy)
    eager = RigidBody(M, (I1, I1, I3), origin=(x, 0, 0), orientation=e, com=r)
    assert eager.R == e.matrix and "R" in vars(eager)
    assert eager.centre_of_mass == com_lazy  # through R: structurally the same expressions
    s = System([psi, th, ph, x], bodies=[lazy], V=M * com_lazy[2])
    assert "R" not in vars(lazy)
    assert {M, l, I1, I3} <= s.declared_symbols
    with pytest.raises(ValueError, match="3x3"):
        RigidBody(M, (I1, I1, I3), orientation=sp.Matrix([[1, 0], [0, 1]]))
