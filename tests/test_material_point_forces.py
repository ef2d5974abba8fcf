"""Forces and torques at material points of rigid bodies, against sympy.physics.mechanics.KanesMethod and
Newton–Euler balances.

A force on a rigid body acts at the *material point* that is at the point of application now, and its
generalized force is ``F · ∂v_P/∂q̇`` with the body's velocity field ``v_P = v_O + ω × r_OP`` (Kane &
Levinson 1985, partial velocities). Reading the point as a position expression (``F · ∂r/∂q``) is the same
thing only when the point is fixed in the body; the contact point of a disc (always the lowest point of
the rim) and the rim point of a top that faces a fixed direction are not, and there the position reading
loses the spin part of the virtual work. Each case below builds the same system in sympy's KanesMethod
(``Point.v2pt_theory``, ``RigidBody``, loads) and compares the accelerations at random states to 1e-10;
the geometric reading is shown to disagree where it should.

(a) a disc sliding on a plane with viscous friction at its contact point (holonomic contact built in);
(b) a disc rolling on a plane (non-holonomic) with a braking torque and a force at the contact point, and
    a braked rolling wheel in a vertical plane against a Newton–Euler balance (accelerations and the
    friction force = the multiplier);
(c) a spinning symmetric top with friction at the rim point facing a fixed direction and body/inertial
    torques, with Wells' Euler angles, a rotation matrix and a unit quaternion.
"""

import numpy as np
import pytest
import sympy as sp
from sympy.physics import mechanics as me

import lagrange as lg
from lagrange import DeclarationError, Force, MaterialPoint, Nonholonomic, RigidBody, System, Torque, t
from lagrange.model.coordinates import to_symbols
from lagrange.simplification import is_zero

RTOL = 1e-10
ts = me.dynamicsymbols._t


def _close(a, b, rtol=RTOL):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(float(np.max(np.abs(a))), float(np.max(np.abs(b))), 1e-300)
    assert np.max(np.abs(a - b)) <= rtol * scale, f"\n{a}\n{b}"


def _rel_diff(a, b) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.max(np.abs(a - b)) / max(np.max(np.abs(a)), np.max(np.abs(b))))


def _kane_solver(km, qs, us, params: dict):
    """u̇ (in the order of ``us``) from KanesMethod's mass matrix and forcing at numeric (q, u); the rows of
    those are in KanesMethod's order, independent speeds first."""
    f = sp.lambdify([list(qs), list(us)], [km.mass_matrix.subs(params), km.forcing.subs(params)], "numpy")
    order = [list(km.u).index(u) for u in us]

    def udot(q, u):
        M, F = f(q, u)
        return np.linalg.solve(np.asarray(M, dtype=float), np.asarray(F, dtype=float).ravel())[order]

    return udot


def _kane_frame(qs, us):
    """N, the body frame B (Wells' z-x-z Euler angles, sympy 'Body' ZXZ: N.dcm(B) = R), q̇ → u map."""
    kd_map = {q.diff(ts): u for q, u in zip(qs, us)}
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Body", list(qs[-3:]), "ZXZ")
    B.set_ang_vel(N, B.ang_vel_in(N).subs(kd_map))
    return N, B, kd_map, [q.diff(ts) - u for q, u in zip(qs, us)]


# ---------------------------------------------------------------------------------------------------------
# (a), (b) a disc of radius r on the plane z = 0: centre (x, y, r sin θ), Wells' Euler angles (ψ, θ, φ)
# ---------------------------------------------------------------------------------------------------------

DISC = {"m": 1.3, "g": 9.81, "r": 0.4, "c": 0.7, "b": 0.35, "F0x": 0.8, "F0y": -1.1, "F0z": 2.0}


def _disc_lagrange():
    x, y, psi, th, ph = lg.coordinates("x y psi theta phi")
    m, g, r = lg.parameters("m g r")
    disc = RigidBody(m, (m * r**2 / 4, m * r**2 / 4, m * r**2 / 2), origin=(x, y, r * sp.sin(th)),
                     orientation=lg.EulerAngles(psi, th, ph), name="disc")
    k = disc.R[:, 2]  # the disc's axis
    contact = disc.origin - r * (sp.Matrix([0, 0, 1]) - sp.cos(th) * k) / sp.sin(th)  # the lowest rim point
    return (x, y, psi, th, ph), disc, contact, m * g * r * sp.sin(th)


def _disc_kane(rolling: bool):
    qs = me.dynamicsymbols("x y psi theta phi")
    us = me.dynamicsymbols("u0:5")
    x, y, psi, th, ph = qs
    m, g, r, c, b, F0x, F0y, F0z = sp.symbols("m g r c b F0x F0y F0z", positive=True)
    kd_map = {q.diff(ts): u for q, u in zip(qs, us)}
    kd = [q.diff(ts) - u for q, u in zip(qs, us)]
    N = me.ReferenceFrame("N")
    L = N.orientnew("L", "Body", [psi, th, 0], "ZXZ")  # yaw and lean: the disc's plane is L's x-y plane
    B = L.orientnew("B", "Axis", [ph, L.z])  # spin: N.dcm(B) = R_z(ψ) R_x(θ) R_z(φ)
    B.set_ang_vel(N, B.ang_vel_in(N).subs(kd_map))
    O = me.Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", x * N.x + y * N.y + r * sp.sin(th) * N.z)
    C.set_vel(N, C.pos_from(O).dt(N).subs(kd_map))
    P = C.locatenew("P", -r * L.y)  # the lowest point of the rim
    vP = P.v2pt_theory(C, N, B)  # the disc's material point at the contact
    disc = me.RigidBody("disc", C, B, m, (me.inertia(B, m * r**2 / 4, m * r**2 / 4, m * r**2 / 2), C))
    loads = [(C, -m * g * N.z)]
    if rolling:
        loads += [(P, F0x * N.x + F0y * N.y + F0z * N.z), (B, -b * B.ang_vel_in(N).dot(B.z) * B.z)]
        km = me.KanesMethod(N, qs, us[2:], kd_eqs=kd, u_dependent=us[:2],
                            velocity_constraints=[vP.dot(N.x), vP.dot(N.y)])
    else:
        loads += [(P, -c * vP)]
        km = me.KanesMethod(N, qs, us, kd_eqs=kd)
    km.kanes_equations([disc], loads)
    params = dict(zip((m, g, r, c, b, F0x, F0y, F0z), (DISC[k] for k in ("m", "g", "r", "c", "b", "F0x", "F0y",
                                                                          "F0z"))))
    return _kane_solver(km, qs, us, params)


def _values(names):
    return {s: DISC[s.name] for s in names}


@pytest.fixture(scope="module")
def sliding_disc():
    """(a) Viscous friction −c v_P at the contact point; the disc slides (no rolling constraint)."""
    coords, disc, contact, V = _disc_lagrange()
    c = lg.parameters("c")
    P = disc.point_at(contact)
    F = -c * P.velocity  # the slip velocity of the material point drives the friction
    kw = dict(bodies=[disc], V=V)
    material = System(coords, forces=[Force(P, F)], **kw)
    geometric = System(coords, forces=[Force(contact, F)], **kw)
    by_body = System(coords, forces=[Force(contact, F, body=disc)], **kw)  # the same material point
    assert all(is_zero(by_body.forces[q] - material.forces[q]) for q in coords)
    m, g, r = lg.parameters("m g r")
    models = [s.compile(_values((m, g, r, c))) for s in (material, geometric)]
    return models, _disc_kane(rolling=False)


def test_contact_point_of_disc_is_the_lowest_rim_point():
    """``point_at`` finds the body coordinates −r(sin φ, cos φ, 0) of the contact point (Wells' angles)."""
    (x, y, psi, th, ph), disc, contact, _ = _disc_lagrange()
    r = lg.parameters("r")
    P = disc.point_at(contact)
    assert isinstance(P, MaterialPoint) and P.body is disc
    assert all(sp.simplify(e) == 0 for e in P.r_body - sp.Matrix([-r * sp.sin(ph), -r * sp.cos(ph), 0]))
    assert sp.simplify(contact[2]) == 0
    # the position expression does not move with the spin; the material point does: ∂v_P/∂φ̇ = k × r_OP
    # with k the spin axis and r_OP from the centre to the contact
    assert all(e == 0 for e in contact.diff(ph))
    at = {x: 0.1, y: -0.2, psi: 0.7, th: 1.1, ph: -0.4, r: 0.4}
    k = disc.R[:, 2].subs(at)
    dv = P.partial_velocities([x, y, psi, th, ph])[ph].subs(at)
    expected = k.cross((contact - disc.origin).subs(at))
    assert np.allclose(np.array(dv, dtype=float), np.array(expected, dtype=float), atol=1e-14)
    assert float(expected.norm()) > 0.1
    assert np.allclose(np.array(P.position.subs(at) - contact.subs(at), dtype=float), 0, atol=1e-14)


@pytest.mark.parametrize("seed", range(4))
def test_sliding_disc_contact_friction_matches_kane(sliding_disc, seed):
    (material, geometric), kane = sliding_disc
    rng = np.random.default_rng(seed)
    q = rng.uniform(-1.0, 1.0, 5)
    q[3] = rng.uniform(0.4, 2.7)  # leaning, away from lying flat (θ = 0, π)
    qd = rng.uniform(-2.0, 2.0, 5)
    y = np.concatenate([q, qd])
    ref = kane(q, qd)
    _close(material.fun(0.0, y)[5:], ref)
    # the position-expression reading loses the spin part of the friction's virtual work
    assert _rel_diff(geometric.fun(0.0, y)[5:], ref) > 1e-3


@pytest.fixture(scope="module")
def rolling_disc():
    """(b) Rolling (v_P = 0 at the contact) with a braking torque −b ω_z on the axis and a force F0 at the
    contact point."""
    coords, disc, contact, V = _disc_lagrange()
    b, F0x, F0y, F0z = lg.parameters("b F0x F0y F0z")
    P = disc.point_at(contact)
    vP = P.velocity
    rolling = [Nonholonomic(vP[0], name="roll x"), Nonholonomic(vP[1], name="roll y")]
    brake = Torque(disc, (0, 0, -b * disc.angular_velocity[2]))
    F0 = (F0x, F0y, F0z)
    kw = dict(bodies=[disc], V=V, constraints=rolling)
    material = System(coords, forces=[Force(P, F0), brake], **kw)
    geometric = System(coords, forces=[Force(contact, F0), brake], **kw)
    m, g, r = lg.parameters("m g r")
    vals = _values((m, g, r, b, F0x, F0y, F0z))
    state = [to_symbols(e, coords) for e in [*coords, *(q.diff(t) for q in coords)]]
    v_contact = sp.lambdify([state], to_symbols(vP.subs(vals), coords))
    # F0z does no work at the contact (v_P,z ≡ 0), so it is absent from the material reading's equations
    models = [s.compile({k: v for k, v in vals.items() if k in s.parameters}) for s in (material, geometric)]
    return models, v_contact, _disc_kane(rolling=True)


@pytest.mark.parametrize("seed", range(4))
def test_rolling_disc_with_brake_and_contact_force_matches_kane(rolling_disc, seed):
    (material, geometric), v_contact, kane = rolling_disc
    rng = np.random.default_rng(10 + seed)
    q = rng.uniform(-1.0, 1.0, 5)
    q[3] = rng.uniform(0.5, 2.6)
    qd = rng.uniform(-2.0, 2.0, 5)
    qd[:2] = 0.0
    qd[:2] = -np.asarray(v_contact(np.concatenate([q, qd])), dtype=float).ravel()[:2]  # rolling-consistent
    y = np.concatenate([q, qd])
    assert np.max(np.abs(material.constraint_functions.velocity_residual(0.0, y))) < 1e-13
    ref = kane(q, qd)
    qdd = np.asarray(material.fun(0.0, y)[5:])
    _close(qdd, ref)
    # the multipliers of the rows v_P,x = v_P,y = 0 are the friction force at the contact (A = ∂v_P/∂q̇):
    # Newton for the centre (x, y, r sin θ), horizontally: m (ẍ, ÿ) = λ + (F0x, F0y)
    lam = material.multipliers(0.0, y)
    _close(lam, DISC["m"] * qdd[:2] - np.array([DISC["F0x"], DISC["F0y"]]))
    # the force at the (momentarily fixed) contact point does no work; read at the position it would
    assert _rel_diff(geometric.fun(0.0, y)[5:], ref) > 1e-3


# ---------------------------------------------------------------------------------------------------------
# (b) braked wheel rolling in the x-z plane: Newton–Euler in closed form
# ---------------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("kind", ["holonomic", "nonholonomic"])
def test_braked_rolling_wheel_newton_euler(kind):
    r"""Wheel (m, I about its axle y, radius r) rolling along x: ẋ = r φ̇ (R = rot_y(φ)). Brake torque −τ_b
    about y, tangential force F_t at the contact point. Newton–Euler: m ẍ = F_t + f, I φ̈ = −τ_b − r (F_t + f),
    so φ̈ = −τ_b/(I + m r²) whatever F_t, and the friction f = m ẍ − F_t is the multiplier of ẋ − r φ̇."""
    x, ph = lg.coordinates("x phi")
    m, I, r, tau_b, F_t = lg.parameters("m I r tau_b F_t")
    wheel = RigidBody(m, (I, I, I), origin=(x, 0, r), orientation=lg.rot_y(ph), name="wheel")
    roll = (lg.Holonomic(x - r * ph, name="roll") if kind == "holonomic"
            else Nonholonomic(x.diff(t) - r * ph.diff(t), name="roll"))
    contact = (x, 0, 0)
    brake = Torque(wheel, (0, -tau_b, 0), frame="inertial")
    vals = {m: 2.0, I: 0.09, r: 0.3, tau_b: 0.5, F_t: 1.7}
    material_system = System([x, ph], bodies=[wheel], forces=[Force(contact, (F_t, 0, 0), body=wheel), brake],
                             constraints=[roll])
    material = material_system.compile(vals)
    geometric = System([x, ph], bodies=[wheel], forces=[Force(contact, (F_t, 0, 0)), brake],
                       constraints=[roll]).compile(vals)
    phdd = -0.5 / (0.09 + 2.0 * 0.3**2)
    for w in (0.0, 1.3, -4.0):
        y = np.array([0.2, 0.2 / 0.3, 0.3 * w, w])
        qdd = np.asarray(material.fun(0.0, y)[2:])
        _close(qdd, [0.3 * phdd, phdd])
        _close(material.multipliers(0.0, y), [2.0 * qdd[0] - 1.7])
        assert _rel_diff(geometric.fun(0.0, y)[2:], qdd) > 0.1
    if kind == "holonomic":  # x eliminated: the contact force's F_φ = F_x r + F_φ = F_t r − r F_t = 0
        reduced = lg.eliminate(material_system, {x: r * ph})
        assert sp.simplify(reduced.generalized_forces()[ph] + tau_b) == 0
        assert F_t not in reduced.parameters
        _close(reduced.compile({k: v for k, v in vals.items() if k != F_t}).fun(0.0, np.array([0.2, 1.3]))[1:], [phdd])


# ---------------------------------------------------------------------------------------------------------
# (c) symmetric top on its apex: friction at the rim point that faces +X, and torques
# ---------------------------------------------------------------------------------------------------------

TOP = {"M": 0.8, "g": 9.81, "l": 0.12, "A": 0.011, "C": 0.006, "a": 0.07, "h": 0.15, "c": 0.4, "F0": 0.3,
       "b": 0.002, "tau0": 0.05}
TOP_STATES = [np.array([0.3, 0.9, -0.4, 1.1, -0.7, 40.0]), np.array([-1.2, 0.4, 2.0, -0.5, 2.2, -25.0]),
              np.array([2.0, 2.1, 0.7, 3.0, 0.4, 15.0])]


def _rim_facing_x(R, a, h):
    """Body coordinates of the rim point (radius a, height h on the axis) nearest the inertial +X direction."""
    d0, d1 = R[0, 0], R[0, 1]  # Rᵀ X̂, projected on the body x-y plane
    n = sp.sqrt(d0**2 + d1**2)
    return (a * d0 / n, a * d1 / n, h)


def _top_system(orientation, coords, geometric=False):
    """Friction −c v_P + F0 Ŷ at the rim point facing +X, a bearing torque −b ω_z about the axis (body frame)
    and a constant torque τ0 about the inertial X axis. ``geometric``: the rim force read at the position
    expression of the point instead (the old reading)."""
    M, g, l, A, C, a, h, c, F0, b, tau0 = lg.parameters("M g l A C a h c F0 b tau0")
    top = RigidBody(M, (A, A, C), orientation=orientation, com=(0, 0, l), name="top")
    rim = top.point(_rim_facing_x(top.R, a, h))
    friction = -c * rim.velocity + sp.Matrix([0, F0, 0])
    forces = [Force(rim.position if geometric else rim, friction),
              Torque(top, (0, 0, -b * top.angular_velocity[2])),
              Torque(top, (tau0, 0, 0), frame="inertial")]
    return System(coords, bodies=[top], V=M * g * top.centre_of_mass[2], forces=forces)


def _top_values(system):
    return {s: TOP[s.name] for s in system.parameters}


@pytest.fixture(scope="module")
def top_kane():
    qs = me.dynamicsymbols("psi theta phi")
    us = me.dynamicsymbols("u0:3")
    M, g, l, A, C, a, h, c, F0, b, tau0 = sp.symbols("M g l A C a h c F0 b tau0", positive=True)
    N, B, _, kd = _kane_frame(qs, us)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", l * B.z)
    G.v2pt_theory(O, N, B)
    d0, d1 = N.x.dot(B.x), N.x.dot(B.y)
    n = sp.sqrt(d0**2 + d1**2)
    P = O.locatenew("P", a * d0 / n * B.x + a * d1 / n * B.y + h * B.z)
    vP = P.v2pt_theory(O, N, B)
    body = me.RigidBody("top", G, B, M, (me.inertia(B, A, A, C), O))
    loads = [(G, -M * g * N.z), (P, -c * vP + F0 * N.y),
             (B, -b * B.ang_vel_in(N).dot(B.z) * B.z + tau0 * N.x)]
    km = me.KanesMethod(N, qs, us, kd_eqs=kd)
    km.kanes_equations([body], loads)
    params = dict(zip((M, g, l, A, C, a, h, c, F0, b, tau0), (TOP[k] for k in ("M", "g", "l", "A", "C", "a", "h",
                                                                               "c", "F0", "b", "tau0"))))
    return _kane_solver(km, qs, us, params)


def _euler_rates():
    """(ω_body, ω̇_body) of Wells' Euler angles as numeric functions of (q, q̇) and (q, q̇, q̈)."""
    psi, th, ph = lg.coordinates("psi theta phi")
    coords = (psi, th, ph)
    w = lg.EulerAngles(psi, th, ph).body_angular_velocity()
    dw = w.diff(t)
    state = [to_symbols(e, coords) for e in [*coords, *(q.diff(t) for q in coords)]]
    acc = [to_symbols(q.diff(t, 2), coords) for q in coords]
    return (sp.lambdify([state], to_symbols(w, coords)), sp.lambdify([state, acc], to_symbols(dw, coords)))


@pytest.mark.parametrize("geometric", [False, pytest.param(True, marks=pytest.mark.slow)])
def test_top_with_rim_friction_and_torques_euler_angles_matches_kane(top_kane, geometric):
    psi, th, ph = lg.coordinates("psi theta phi")
    system = _top_system(lg.EulerAngles(psi, th, ph), [psi, th, ph], geometric)
    model = system.compile(_top_values(system))
    for y in TOP_STATES:
        qdd, ref = model.fun(0.0, y)[3:], top_kane(y[:3], y[3:])
        if geometric:
            assert _rel_diff(qdd, ref) > 1e-2
        else:
            _close(qdd, ref)


def test_top_rotation_matrix_orientation_matches_kane(top_kane):
    """The generic path (ω = vee(RᵀṘ)) for a plain rotation matrix gives the same q̈."""
    psi, th, ph = lg.coordinates("psi theta phi")
    system = _top_system(lg.rot_z(psi) * lg.rot_x(th) * lg.rot_z(ph), [psi, th, ph])
    model = system.compile(_top_values(system))
    for y in TOP_STATES[:2]:
        _close(model.fun(0.0, y)[3:], top_kane(y[:3], y[3:]))


def _quat(axis: int, angle: float) -> np.ndarray:
    q = np.zeros(4)
    q[0], q[1 + axis] = np.cos(angle / 2), np.sin(angle / 2)
    return q


def _qmul(p, q):
    p0, pv, q0, qv = p[0], p[1:], q[0], q[1:]
    return np.concatenate([[p0 * q0 - pv @ qv], p0 * qv + q0 * pv + np.cross(pv, qv)])


def test_top_quaternion_orientation_matches_kane(top_kane):
    """Unit quaternion (4 coordinates, norm constraint and its multiplier): the body angular acceleration
    ω̇ = 2 E q̈ agrees with Kane's Euler-angle solution at the same physical state."""
    qc = lg.coordinates("q0 q1 q2 q3")
    quat = lg.Quaternion(*qc)
    system = _top_system(quat, list(qc))
    model = system.compile(_top_values(system))
    omega, omega_dot = _euler_rates()
    R_num = sp.lambdify([list(qc)], quat.matrix)
    euler_R = sp.lambdify([sp.symbols("a b c")], lg.EulerAngles(*sp.symbols("a b c")).matrix)
    for y in TOP_STATES:
        q = _qmul(_qmul(_quat(2, y[0]), _quat(0, y[1])), _quat(2, y[2]))  # z-x-z
        assert np.allclose(R_num(q), euler_R(y[:3]), atol=1e-14)
        E = np.array([[-q[1], q[0], q[3], -q[2]], [-q[2], -q[3], q[0], q[1]], [-q[3], q[2], -q[1], q[0]]])
        w = np.asarray(omega(y), dtype=float).ravel()
        qd = E.T @ w / 2
        qdd = np.asarray(model.fun(0.0, np.concatenate([q, qd]))[4:])
        _close(2 * E @ qdd, np.asarray(omega_dot(y, top_kane(y[:3], y[3:])), dtype=float).ravel())


# ---------------------------------------------------------------------------------------------------------
# API: what a material point is, combinations, refusals
# ---------------------------------------------------------------------------------------------------------


def test_point_fixed_in_body_gives_wells_4_10():
    """For constant body coordinates the material point and its position expression give the same F_q."""
    x, y, th = lg.coordinates("x y theta")
    M, Iz, a, b, FX, FY = lg.parameters("M I_z a b F_X F_Y")
    lamina = RigidBody(M, (0, 0, Iz), origin=(x, y, 0), orientation=lg.rot_z(th))
    P = lamina.point((a, b, 0))
    mat = System([x, y, th], bodies=[lamina], forces=[Force(P, (FX, FY))]).generalized_forces()
    geo = System([x, y, th], bodies=[lamina], forces=[Force(P.position, (FX, FY))]).generalized_forces()
    c, s = sp.cos(th), sp.sin(th)
    expected = {x: FX, y: FY, th: FY * (a * c - b * s) - FX * (a * s + b * c)}
    for q in (x, y, th):
        assert sp.simplify(mat[q] - expected[q]) == 0
        assert sp.simplify(geo[q] - expected[q]) == 0


def test_material_point_is_accepted_as_a_position():
    th, s = lg.coordinates("theta s")
    m = lg.parameters("m")
    rod = RigidBody(m, (0, m, m), orientation=lg.rot_z(th), name="rod")
    slider = lg.Particle(m, rod.point((s, 0, 0)))  # a bead sliding along the rod: its own position
    assert slider.position == sp.Matrix([s * sp.cos(th), s * sp.sin(th), 0])
    assert rod.centre_of_mass == sp.zeros(3, 1)


def test_force_on_the_rod_and_on_the_bead_differ():
    """At the same place, a force on the rod's material point does no work on s; on the bead it does."""
    th, s = lg.coordinates("theta s")
    m, F = lg.parameters("m F")
    rod = RigidBody(m, (0, m, m), orientation=lg.rot_z(th), name="rod")
    bead = lg.Particle(m, rod.point((s, 0, 0)), name="bead")
    on_rod = System([th, s], bodies=[rod, bead], forces=[Force(rod.point((s, 0, 0)), (0, F))])
    on_bead = System([th, s], bodies=[rod, bead], forces=[Force(bead, (0, F))])
    assert on_rod.generalized_forces()[s] == 0
    assert sp.simplify(on_bead.generalized_forces()[s] - F * sp.sin(th)) == 0
    assert sp.simplify(on_rod.generalized_forces()[th] - F * s * sp.cos(th)) == 0


def test_prescribed_motion_with_material_point_force():
    """A prescribed coordinate is substituted in the body and the point (t explicit), and has no virtual
    displacement: the same F_q as the system written with the motion substituted by hand."""
    x, th = lg.coordinates("x theta")
    m, Iz, a, c, w = lg.parameters("m I_z a c omega")
    drive = sp.sin(w * t)

    def build(origin_x, coords, prescribed):
        disc = RigidBody(m, (Iz, Iz, Iz), origin=(origin_x, 0, 0), orientation=lg.rot_z(th), name="disc")
        P = disc.point_at((origin_x, -a, 0))  # the point of the disc on a fixed line y = −a
        return System(coords, bodies=[disc], forces=[Force(P, -c * P.velocity)], prescribed=prescribed)

    auto = build(x, [th], {x: drive}).generalized_forces()[th]
    by_hand = build(drive, [th], None).generalized_forces()[th]
    assert sp.simplify(auto - by_hand) == 0
    # friction −c v_P at the material point below the centre: v_P = (ẋ + a θ̇, 0, 0)
    assert sp.simplify(by_hand + c * a * (drive.diff(t) + a * th.diff(t))) == 0


def test_coulomb_friction_at_material_point_compiles_and_opposes_slip():
    """Sign terms (Coulomb friction) in the force vector at a material point."""
    x, th = lg.coordinates("x theta")
    m, I, r, mu, g = lg.parameters("m I r mu g")
    wheel = RigidBody(m, (I, I, I), origin=(x, 0, r), orientation=lg.rot_y(th), name="wheel")
    P = wheel.point_at((x, 0, 0))
    slip = P.velocity[0]
    s = System([x, th], bodies=[wheel], forces=[Force(P, (-mu * m * g * sp.sign(slip), 0, 0))])
    model = s.compile({m: 2.0, I: 0.09, r: 0.3, mu: 0.4, g: 9.81})
    # sliding forward without spin: friction brakes x and spins the wheel up (θ̈ > 0 makes ẋ − rθ̇ smaller)
    acc = model.fun(0.0, np.array([0.0, 0.0, 1.0, 0.0]))[2:]
    _close(acc, [-0.4 * 9.81, 0.4 * 2.0 * 9.81 * 0.3 / 0.09])


def test_gauss_check_and_power_balance_with_material_point_force():
    """The Gauss route takes the same generalized forces: it agrees with Lagrange's equations, and along a run
    the power balance d(T + V)/dt = q̇·Q holds with the friction and drive at the contact and a brake torque."""
    x, ph = lg.coordinates("x phi")
    m, I, r, tau_b, F_t, c = lg.parameters("m I r tau_b F_t c")
    wheel = RigidBody(m, (I, I, I), origin=(x, 0, r), orientation=lg.rot_y(ph), name="wheel")
    P = wheel.point_at((x, 0, 0))
    system = System([x, ph], bodies=[wheel], name="wheel skidding on the ground",
                    forces=[Force(P, (F_t - c * P.velocity[0], 0, 0)), Torque(wheel, (0, -tau_b, 0), frame="inertial")])
    check = lg.check_gauss(system, {m: 2.0, I: 0.09, r: 0.3, tau_b: 0.5, F_t: 1.7, c: 0.3})
    assert check.agrees and check.ok, str(check)
    assert check.diagnostics.power_residual is not None and check.diagnostics.power_residual < 1e-8


def test_errors():
    th = lg.coordinates("theta")
    m = lg.parameters("m")
    body = RigidBody(m, (m, m, m), orientation=lg.rot_z(th), name="B")
    other = RigidBody(m, (m, m, m), name="C")
    with pytest.raises(DeclarationError, match="contain velocities"):
        body.point((th.diff(t), 0, 0))
    with pytest.raises(DeclarationError, match="material point of rigid body 'B' but body= is 'C'"):
        Force(body.point((1, 0, 0)), (1, 0, 0), body=other)
    with pytest.raises(DeclarationError, match="not a RigidBody"):
        Force((1, 0, 0), (1, 0, 0), body=lg.Particle(m, (th, 0)))
    with pytest.raises(DeclarationError, match="particle"):
        Force(lg.Particle(m, (th, 0), name="p"), (1, 0, 0), body=body)
    assert issubclass(DeclarationError, ValueError)
