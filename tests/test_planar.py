"""Planar bodies and joints (lagrange.model.planar, lagrange.model.joints): each mechanism against an independent
truth — published equations and a published reference solution, closed-form kinematics, a second formulation,
a closed-form frequency — and the refusals."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import (
    DeclarationError,
    Particle,
    PlanarBody,
    RigidBody,
    System,
    coordinates,
    on_line,
    parameters,
    pin,
    revolute,
    rot_z,
    slider,
    spherical,
    spring_potential,
    t,
)
from lagrange.examples import SQUEEZER_DATA, SQUEEZER_INITIAL, SQUEEZER_REFERENCE, andrews_squeezer
from lagrange.model.coordinates import to_symbols


def _numeric(exprs, system, values, state):
    """Float array of ``exprs`` (in the coordinate functions) at ``state = (q, q̇)`` and parameter ``values``."""
    coords = system.coordinates
    e = sp.Matrix(to_symbols(sp.Matrix(exprs), coords))
    from lagrange.model.coordinates import position_symbol, velocity_symbol

    sub = {position_symbol(q): v for q, v in zip(coords, state[0])}
    sub.update({velocity_symbol(q): v for q, v in zip(coords, state[1])})
    sub.update({s: values[s.name] for s in e.free_symbols if s.name in values})
    return np.array(e.xreplace(sub).evalf(30), dtype=float)


# --- the seven-body mechanism: published equations and reference solution ---------------------------------
def _hairer(q, v, p):
    """M, f and G = ∂g/∂q of Andrews' squeezer as published (Hairer & Wanner II §VII.7; the test set's andrews.f),
    written out by hand, in the test set's form M q̈ = f − Gᵀλ."""
    be, th, ga, ph, de, om, ep = q
    bep, thp, _, php, dep, omp, epp = v
    P = p
    sin, cos = np.sin, np.cos
    M = np.zeros((7, 7))
    M[0, 0] = P["m1"] * P["ra"] ** 2 + P["m2"] * (P["rr"] ** 2 - 2 * P["da"] * P["rr"] * cos(th) + P["da"] ** 2) \
        + P["i1"] + P["i2"]
    M[1, 0] = M[0, 1] = P["m2"] * (P["da"] ** 2 - P["da"] * P["rr"] * cos(th)) + P["i2"]
    M[1, 1] = P["m2"] * P["da"] ** 2 + P["i2"]
    M[2, 2] = P["m3"] * (P["sa"] ** 2 + P["sb"] ** 2) + P["i3"]
    ee = P["e"] - P["ea"]
    M[3, 3] = P["m4"] * ee**2 + P["i4"]
    M[4, 3] = M[3, 4] = P["m4"] * (ee**2 + P["zt"] * ee * sin(ph)) + P["i4"]
    M[4, 4] = P["m4"] * (P["zt"] ** 2 + 2 * P["zt"] * ee * sin(ph) + ee**2) + P["m5"] * (P["ta"] ** 2 + P["tb"] ** 2) \
        + P["i4"] + P["i5"]
    zz = P["zf"] - P["fa"]
    M[5, 5] = P["m6"] * zz**2 + P["i6"]
    M[6, 5] = M[5, 6] = P["m6"] * (zz**2 - P["u"] * zz * sin(om)) + P["i6"]
    M[6, 6] = P["m6"] * (zz**2 - 2 * P["u"] * zz * sin(om) + P["u"] ** 2) + P["m7"] * (P["ua"] ** 2 + P["ub"] ** 2) \
        + P["i6"] + P["i7"]
    xd = P["sd"] * cos(ga) + P["sc"] * sin(ga) + P["xb"]
    yd = P["sd"] * sin(ga) - P["sc"] * cos(ga) + P["yb"]
    L = np.hypot(xd - P["xc"], yd - P["yc"])
    force = -P["c0"] * (L - P["l0"]) / L
    fx, fy = force * (xd - P["xc"]), force * (yd - P["yc"])
    f = np.array([
        P["mom"] - P["m2"] * P["da"] * P["rr"] * thp * (thp + 2 * bep) * sin(th),
        P["m2"] * P["da"] * P["rr"] * bep**2 * sin(th),
        fx * (P["sc"] * cos(ga) - P["sd"] * sin(ga)) + fy * (P["sd"] * cos(ga) + P["sc"] * sin(ga)),
        P["m4"] * P["zt"] * ee * dep**2 * cos(ph),
        -P["m4"] * P["zt"] * ee * php * (php + 2 * dep) * cos(ph),
        -P["m6"] * P["u"] * zz * epp**2 * cos(om),
        P["m6"] * P["u"] * zz * omp * (omp + 2 * epp) * cos(om),
    ])
    d, rr, ss, e, zt, zf, u = P["d"], P["rr"], P["ss"], P["e"], P["zt"], P["zf"], P["u"]
    G = np.zeros((6, 7))
    for r in (0, 2, 4):
        G[r, 0], G[r, 1] = -rr * sin(be) + d * sin(be + th), d * sin(be + th)
        G[r + 1, 0], G[r + 1, 1] = rr * cos(be) - d * cos(be + th), -d * cos(be + th)
    G[0, 2], G[1, 2] = -ss * cos(ga), -ss * sin(ga)
    G[2, 3], G[2, 4] = -e * cos(ph + de), -e * cos(ph + de) + zt * sin(de)
    G[3, 3], G[3, 4] = -e * sin(ph + de), -e * sin(ph + de) - zt * cos(de)
    G[4, 5], G[4, 6] = zf * sin(om + ep), zf * sin(om + ep) - u * cos(ep)
    G[5, 5], G[5, 6] = -zf * cos(om + ep), -zf * cos(om + ep) - u * sin(ep)
    return M, f, G


@pytest.fixture(scope="module")
def squeezer():
    return andrews_squeezer()


def test_squeezer_is_a_short_table():
    import inspect

    source = inspect.getsource(andrews_squeezer)
    body = source[source.index('"""', source.index('"""') + 3) + 3:]
    lines = [ln for ln in body.splitlines() if ln.strip() and not ln.strip().startswith("#")]
    assert len(lines) < 30


def test_squeezer_equations_are_the_published_ones(squeezer):
    """M, f and the constraint Jacobian equal the hand-written published ones at random states (1e-12)."""
    values = {k: float(v) for k, v in SQUEEZER_DATA.items()}
    e = squeezer.derived
    assert e.m == 6 and squeezer.dof.configuration == 1
    model = squeezer.compile(values)
    rng = np.random.default_rng(7)
    for _ in range(3):
        q, v = rng.uniform(-np.pi, np.pi, 7), rng.uniform(-50, 50, 7)
        y = np.concatenate([q, v])
        M_ref, f_ref, G_ref = _hairer(q, v, values)
        M, f = model.mass_and_forcing(0.0, y)
        A = model.constraint_functions.matrix(0.0, q)
        assert np.max(np.abs(M - M_ref)) <= 1e-12 * np.max(np.abs(M_ref))
        assert np.max(np.abs(f - f_ref)) <= 1e-12 * np.max(np.abs(f_ref))
        assert np.max(np.abs(A - G_ref)) <= 1e-12 * np.max(np.abs(G_ref))


def test_squeezer_reaches_the_published_reference(squeezer):
    """From the test set's consistent initial state, the angles and rates at t = 0.03 agree with the published
    reference solution (computed by PSIDE at tolerance 1e-14), and the closures hold."""
    values = {k: float(v) for k, v in SQUEEZER_DATA.items()}
    initial = {q: v for q, v in zip(squeezer.coordinates, SQUEEZER_INITIAL)}
    initial.update({q.diff(t): 0.0 for q in squeezer.coordinates})
    tr = squeezer.simulate((0, 0.03), initial, values, rtol=1e-10, atol=1e-10)
    q_ref, v_ref = np.array(SQUEEZER_REFERENCE[0]), np.array(SQUEEZER_REFERENCE[1])
    y = tr.y[-1]
    assert np.max(np.abs(y[:7] - q_ref)) < 1e-7 * np.max(np.abs(q_ref))
    assert np.max(np.abs(y[7:] - v_ref)) < 1e-7 * np.max(np.abs(v_ref))
    assert tr.max_constraint_violation() < 1e-8


# --- planar pendulum: PlanarBody, RigidBody and Particle + T give the same equations -------------------------
def test_planar_pendulum_matches_rigid_body_and_particle():
    th = coordinates("theta")
    m, l, g, I = parameters("m l g I")
    down = PlanarBody(m, I, angle=th, com=(l, 0))  # the rod's body x axis points along the pendulum
    V = m * g * down.centre_of_mass[1]
    planar = System([th], bodies=[down], V=V)
    rigid = System([th], bodies=[RigidBody(m, (0, 0, I + m * l**2), orientation=rot_z(th), com=(l, 0, 0))], V=V)
    bob = Particle(m, (l * sp.cos(th), l * sp.sin(th)))
    point = System([th], bodies=[bob], T=I * th.diff(t) ** 2 / 2, V=V)
    for other in (rigid, point):
        assert sp.simplify(planar.mass_matrix - other.mass_matrix) == sp.zeros(1, 1)
        assert sp.simplify(planar.forcing - other.forcing) == sp.zeros(1, 1)


def test_position_hinged_to_another_body_is_a_tree_joint():
    """A body hinged at another's point (position=other.point) has the kinematics of the hand-written chain."""
    a, b = coordinates("a b")
    l1, l2 = parameters("l1 l2")
    upper = PlanarBody(1, 1, angle=a, points={"end": (l1, 0)}, name="upper")
    lower = PlanarBody(1, 1, upper.point("end"), b, points={"tip": (l2, 0)}, name="lower")
    expected = sp.Matrix([l1 * sp.cos(a) + l2 * sp.cos(b), l1 * sp.sin(a) + l2 * sp.sin(b)])
    assert sp.simplify(lower.position_of("tip") - expected) == sp.zeros(2, 1)
    # a revolute joint at the hinge is implied by the kinematics: no closure is left
    assert revolute(upper.point("end"), lower.point((0, 0))) == ()


def test_eliminate_keeps_a_planar_body():
    """A rod with its own (x, y, θ) pinned at one end, the pin eliminated: the compound pendulum."""
    x, y, th = coordinates("x y th")
    m, l, g = parameters("m l g")
    rod = PlanarBody(m, m * l**2 / 12, (x, y), th, points={"O": (-l / 2, 0)}, name="rod")
    s = System([x, y, th], bodies=[rod], V=m * g * y, constraints=[pin(rod.point("O"))])
    reduced = lg.eliminate(s, [x, y])
    assert isinstance(reduced.bodies[0], PlanarBody)
    assert sp.simplify(reduced.mass_matrix[0, 0] - m * l**2 / 3) == 0
    assert sp.simplify(reduced.forcing[0] + m * g * l * sp.cos(th) / 2) == 0


# --- four-bar linkage in absolute coordinates -------------------------------------------------------------
def _parallelogram():
    """A parallelogram four-bar hanging under gravity: two uniform cranks (m, length L) pivoted at (0, 0) and
    (b, 0) and a uniform coupler (M, length b); every body has its own (x, y, θ) and the joints close the loop."""
    x1, y1, t1, x2, y2, t2, x3, y3, t3 = coordinates("x1 y1 t1 x2 y2 t2 x3 y3 t3")
    m, M, L, b, g = parameters("m M L b g")
    crank1 = PlanarBody(m, m * L**2 / 12, (x1, y1), t1, points={"O": (-L / 2, 0), "E": (L / 2, 0)}, name="crank1")
    crank2 = PlanarBody(m, m * L**2 / 12, (x2, y2), t2, points={"O": (-L / 2, 0), "E": (L / 2, 0)}, name="crank2")
    coupler = PlanarBody(M, M * b**2 / 12, (x3, y3), t3, points={"A": (-b / 2, 0), "B": (b / 2, 0)},
                         name="coupler")
    joints = [pin(crank1.point("O"), (0, 0)), pin(crank2.point("O"), (b, 0)),
              revolute(crank1.point("E"), coupler.point("A")), revolute(crank2.point("E"), coupler.point("B"))]
    V = g * (m * y1 + m * y2 + M * y3)
    return System([t1, x1, y1, x2, y2, t2, x3, y3, t3], bodies=[crank1, crank2, coupler], V=V, constraints=joints,
                  name="four-bar")


def test_structural_and_expanded_derivations_agree():
    """The structural derivation takes a PlanarBody as the RigidBody it is: same M and f as the expanded T."""
    vals = {"m": 0.7, "M": 1.3, "L": 0.9, "b": 1.1, "g": 9.81}
    base = _parallelogram()
    assert base.derivation == "structural"  # 9 coordinates: auto picks it
    kw = {"bodies": base.bodies, "V": base.V, "constraints": [c.position for c in base.constraints]}
    expanded = System(list(base.coordinates), derivation="expanded", **kw)
    y = np.random.default_rng(3).uniform(-1, 1, 18)
    M1, f1 = base.compile(vals).mass_and_forcing(0.0, y)
    M2, f2 = expanded.compile(vals).mass_and_forcing(0.0, y)
    assert np.allclose(M1, M2, rtol=1e-13, atol=1e-13) and np.allclose(f1, f2, rtol=1e-13, atol=1e-13)


def test_four_bar_frequency_and_closure():
    s = _parallelogram()
    assert len(s.constraints) == 8 and s.dof.configuration == 1
    vals = {"m": 0.7, "M": 1.3, "L": 0.9, "b": 1.1, "g": 9.81}
    L, b = vals["L"], vals["b"]
    hanging = {"t1": -np.pi / 2, "x1": 0.0, "y1": -L / 2, "x2": b, "y2": -L / 2, "t2": -np.pi / 2,
               "x3": b / 2, "y3": -L, "t3": 0.0}
    modes = lg.normal_modes(s, params=vals, about=hanging)
    # independent: the coupler translates on a circle; T = ½(2 m L²/3 + M L²) φ̇², V = −(m + M) g L cos φ
    omega = np.sqrt(vals["g"] * (vals["m"] + vals["M"]) / ((2 * vals["m"] / 3 + vals["M"]) * L))
    assert modes.omega[-1] == pytest.approx(omega, rel=1e-10)
    # a swing of 0.4 rad from rest: the closures hold and the energy is kept
    phi0 = 0.4
    c, sn = np.cos(phi0 - np.pi / 2), np.sin(phi0 - np.pi / 2)
    start = {"t1": phi0 - np.pi / 2, "x1": L / 2 * c, "y1": L / 2 * sn, "x2": b + L / 2 * c, "y2": L / 2 * sn,
             "t2": phi0 - np.pi / 2, "x3": b / 2 + L * c, "y3": L * sn, "t3": 0.0}
    start.update({k + "_dot": 0.0 for k in list(start)})
    tr = s.simulate((0, 2.0), start, vals, rtol=1e-10, atol=1e-10)
    assert tr.max_constraint_violation() < 1e-8
    E = tr.energy
    assert np.ptp(E) < 1e-7 * np.max(np.abs(E))


# --- slider-crank against its closed-form kinematics ------------------------------------------------------
def test_slider_crank_kinematics():
    """Every body has its own (x, y, θ) but the crank (hinged at the origin); the piston slides on the ground's
    x axis (slider: on the line and not turning)."""
    phi, x2, y2, t2, x3, y3, t3 = coordinates("phi x2 y2 t2 x3 y3 t3")
    r, l, m, I = parameters("r l m I")
    crank = PlanarBody(m, I, angle=phi, points={"P": (r, 0)}, name="crank")  # hinged at the fixed origin
    rod = PlanarBody(m, m * l**2 / 12, (x2, y2), t2, points={"A": (-l / 2, 0), "B": (l / 2, 0)}, name="rod")
    piston = PlanarBody(m, I, (x3, y3), t3, name="piston")
    guide = slider((0, 0), piston.point((0, 0)), axis=(1, 0))
    assert [c.expr for c in guide] == [y3, t3]
    # given y = 0 and angle 0 in the kinematics instead, the slider has nothing left to say
    assert slider((0, 0), PlanarBody(m, I, (x3, 0), 0).point((0, 0))) == ()
    s = System([phi, x2, y2, t2, x3, y3, t3], bodies=[crank, rod, piston],
               constraints=[revolute(crank.point("P"), rod.point("A")), revolute(rod.point("B"), piston.point((0, 0))),
                            guide])
    assert s.dof.configuration == 1
    vals = {"r": 0.3, "l": 1.0, "m": 1.0, "I": 0.2}
    R, Lr, w = vals["r"], vals["l"], 5.0
    start = {"phi": 0.0, "x2": R + Lr / 2, "y2": 0.0, "t2": 0.0, "x3": R + Lr, "y3": 0.0, "t3": 0.0,
             "phi_dot": w, "x2_dot": 0.0, "y2_dot": R * w / 2, "t2_dot": -R * w / Lr, "x3_dot": 0.0,
             "y3_dot": 0.0, "t3_dot": 0.0}
    tr = s.simulate((0, 3.0), start, vals, rtol=1e-10, atol=1e-10)
    ph, piston_x = tr["phi"], tr["x3"]
    closed = R * np.cos(ph) + np.sqrt(Lr**2 - (R * np.sin(ph)) ** 2)
    assert np.max(np.abs(piston_x - closed)) < 1e-7
    assert np.ptp(ph) > 2 * np.pi  # it went round


def test_slider_and_on_line_equations():
    x, y, th, a = coordinates("x y th a")
    guide = PlanarBody(1, 1, angle=a, name="guide")
    block = PlanarBody(1, 1, (x, y), th, name="block")
    line, angle = slider(guide.point((0, 0)), block.point((0, 0)), axis=(1, 0), angle=0)
    # block on the guide's rotating x axis, and turning with it
    assert sp.simplify(line.expr - (sp.cos(a) * y - sp.sin(a) * x)) == 0
    assert sp.simplify(angle.expr - (th - a)) == 0
    (slot,) = on_line(block.point((0, 0)), through=(0, 1), direction=(3, 4))
    assert sp.simplify(slot.expr - (sp.Rational(3, 5) * (y - 1) - sp.Rational(4, 5) * x)) == 0


# --- springs, torques, inputs -----------------------------------------------------------------------------
def test_spring_between_two_bodies_points():
    a, b = coordinates("a b")
    k, l0, h = parameters("k l0 h")
    left = PlanarBody(1, 1, (0, 0), a, points={"tip": (1, 0)}, name="left")
    right = PlanarBody(1, 1, (h, 0), b, points={"tip": (1, 0)}, name="right")
    V = spring_potential(left.point("tip"), right.point("tip"), k, l0)
    dx, dy = sp.cos(a) - h - sp.cos(b), sp.sin(a) - sp.sin(b)
    assert sp.simplify(V - k * (sp.sqrt(dx**2 + dy**2) - l0) ** 2 / 2) == 0
    # the damper's generalized force is −c ℓ̇ ∂ℓ/∂q
    c = parameters("c")
    P = lg.damper_power(left.point("tip"), right.point("tip"), c)
    ell = sp.sqrt(dx**2 + dy**2)
    s = System([a, b], bodies=[left, right], P=P)
    s_ref = System([a, b], bodies=[left, right], forces={q: -c * ell.diff(t) * ell.diff(q) for q in (a, b)})
    vals = {"c": 0.7, "h": 2.5}
    state = (np.array([0.3, -0.4]), np.array([1.1, 0.6]))
    F = _numeric(list(s.generalized_forces().values()), s, vals, state)
    F_ref = _numeric(list(s_ref.generalized_forces().values()), s_ref, vals, state)
    assert np.allclose(F, F_ref, rtol=1e-12, atol=0)


def test_torque_input_spins_a_disc():
    th = coordinates("theta")
    u = lg.inputs("u")
    I = parameters("I")
    disc = PlanarBody(2, I, (0, 0), th, name="disc")
    s = System([th], bodies=[disc], forces=[disc.torque(u)])
    assert sp.simplify(s.forcing[0] - u) == 0
    tr = s.simulate((0, 2.0), {"theta": 0.0, "theta_dot": 0.0}, {"I": 0.5}, inputs={"u": lambda time: 3 * time},
                    rtol=1e-10, atol=1e-12)
    # θ = u t³ / (6 I) with u = 3t: θ = t³ / (2 I)
    assert tr["theta"][-1] == pytest.approx(2.0**3 / (2 * 0.5), rel=1e-8)


def test_force_at_a_named_point():
    th = coordinates("theta")
    F0 = parameters("F0")
    bar = PlanarBody(1, 1, (0, 0), th, points={"end": (2, 0)}, name="bar")
    s = System([th], bodies=[bar], forces=[lg.Force(bar.point("end"), (0, F0))])
    assert sp.simplify(s.generalized_forces()[th] - 2 * F0 * sp.cos(th)) == 0


# --- spatial joints ---------------------------------------------------------------------------------------
def test_spatial_pin_and_spherical():
    x, y, th = coordinates("x y th")
    m, l, g = parameters("m l g")
    rod = RigidBody(m, (0, m * l**2 / 12, m * l**2 / 12), origin=(x, y, 0), orientation=rot_z(th), name="rod")
    hinge = pin(rod.point((-l / 2, 0, 0)), (0, 0, 0))
    assert [c.name for c in hinge] == ["pin rod(-l/2, 0, 0) (x)", "pin rod(-l/2, 0, 0) (y)"]  # z is 0 = 0
    s = System([th, x, y], bodies=[rod], V=m * g * y, constraints=[hinge])
    modes = lg.normal_modes(s, params={"m": 1.0, "l": 1.2, "g": 9.81},
                            about={"th": -np.pi / 2, "x": 0.0, "y": -0.6})
    assert modes.omega[-1] == pytest.approx(np.sqrt(9.81 * 0.6 / (1.2**2 / 3)), rel=1e-10)
    other = RigidBody(m, (1, 1, 1), origin=(x, 0, 1), name="other")
    ball = spherical(rod.point((l / 2, 0, 0)), other.point((0, 0, 0)))
    assert [c.name.rsplit(" ", 1)[1] for c in ball] == ["(x)", "(y)", "(z)"]
    expected = [l / 2 * sp.cos(th), y + l / 2 * sp.sin(th), -1]  # rod tip minus the other body's origin
    assert all(sp.simplify(c.expr - e) == 0 for c, e in zip(ball, expected))


# --- Gauss' check -----------------------------------------------------------------------------------------
def test_gauss_check_agrees_on_the_four_bar():
    s = _parallelogram()
    check = lg.check_gauss(s, {"m": 0.7, "M": 1.3, "L": 0.9, "b": 1.1, "g": 9.81}, samples=3, diagnostics=False)
    assert check.applicable and check.agrees


# --- refusals ---------------------------------------------------------------------------------------------
def test_refusals_name_the_problem():
    a, b = coordinates("a b")
    body = PlanarBody(1, 1, angle=a, points={"P": (1, 0)}, name="crank")
    other = PlanarBody(1, 1, (2, 0), b, name="rod")
    with pytest.raises(DeclarationError, match="no point named 'Q'.*its points: P"):
        body.point("Q")
    with pytest.raises(DeclarationError, match="both points are on body 'crank'"):
        revolute(body.point("P"), body.point((0, 0)))
    with pytest.raises(DeclarationError, match="leaves the plane"):
        PlanarBody(1, 1, (0, 0, a))
    with pytest.raises(DeclarationError, match="leaves the plane"):
        PlanarBody(1, 1, points={"P": (1, 0, 1)})
    with pytest.raises(DeclarationError, match="leaves the plane"):
        body.point((1, 0, 2))
    with pytest.raises(DeclarationError, match="one moment about the centre of mass"):
        PlanarBody(1, (1, 1, 1))
    with pytest.raises(DeclarationError, match="spatial rigid body"):
        revolute(body.point("P"), RigidBody(1, (1, 1, 1), name="box").point((0, 0, 0)))
    with pytest.raises(DeclarationError, match="not a body's point"):
        revolute(body.point("P"), (1, 2))
    with pytest.raises(DeclarationError, match="zero vector"):
        on_line(other.point((0, 0)), direction=(0, 0))
    with pytest.raises(DeclarationError, match="angle .* must be one expression"):
        PlanarBody(1, 1, angle=(a, b))
    with pytest.raises(DeclarationError, match="is not finite"):
        body.point((float("nan"), 0))
    with pytest.raises(DeclarationError, match="inertia of planar body = None is not an expression"):
        PlanarBody(1, None)
    with pytest.raises(DeclarationError, match="stiffness = nan is not finite"):
        spring_potential(body.point("P"), (0, 0), float("nan"))
    # a joint whose points can never meet is a constraint without coordinates: System refuses it
    fixed1, fixed2 = PlanarBody(1, 1, (0, 0), name="f1"), PlanarBody(1, 1, (1, 0), name="f2")
    with pytest.raises(DeclarationError, match="involves no coordinate"):
        System([a], bodies=[body, fixed1, fixed2], constraints=[revolute(fixed1.point((0, 0)), fixed2.point((0, 0)))])
    for exc in (DeclarationError,):
        assert issubclass(exc, ValueError) and issubclass(exc, lg.LagrangeError)
