"""Side-by-side comparison with ``sympy.physics.mechanics.LagrangesMethod`` on two classic constrained systems.

(a) A pendulum in Cartesian coordinates (x, y) with the length constraint x² + y² − l² = 0 (sympy:
    ``hol_coneqs``; lagrange: ``Holonomic``). Accelerations and multipliers are compared at consistent states.
(b) The classic sympy rolling disc, kept in x, y (contact point), yaw q1, lean q2, spin q3, with T written
    directly and the two non-holonomic rolling conditions (sympy: ``nonhol_coneqs``; lagrange:
    ``Nonholonomic``). Accelerations (and multipliers) are compared at random consistent states.

Convention differences
----------------------
* Sign: lagrange writes ``M q̈ = f + Aᵀλ`` (the multiplier term is *added* to the applied forces, so
  ``λ_k A_kr`` is Wells' generalized force of constraint on q_r). The textbook form used in sympy's docs,
  ``[[m_d, Λ], [Λᵀ, 0]] [q̈; λ] = [−f_d; −f_a]`` with ``Λ = Aᵀ``, has the opposite sign. sympy's
  ``LagrangesMethod`` stores ``lam_coeffs = −A`` (−Λᵀ, sympy issue #30215), so its ``mass_matrix`` /
  ``mass_matrix_full`` is ``[m_d, −Λ]``. The λ obtained from ``mass_matrix_full``/``forcing_full`` (or ``rhs()``)
  is therefore −λ_textbook, which is the *same* as lagrange's λ. sympy's own ``eom`` attribute, however, is
  ``term1 − term2 − term4 − lam_coeffs.T·λ``, i.e. ``M q̈ − f + Aᵀλ = 0``: the λ that satisfies ``eom`` is
  −λ_lagrange. Both facts are asserted below for the pendulum (this internal inconsistency is the issue).
* Scaling: both libraries take A from the constraint exactly as written (``∂φ/∂q`` for a holonomic
  ``φ = 0``, ``∂g/∂q̇`` for a velocity constraint ``g = 0``), so λ scales inversely with the written form:
  with ``x² + y² − l² = 0`` the string tension is ``τ = −2 l λ_lagrange`` (λ from sympy's
  ``mass_matrix_full`` is the same number); writing the
  constraint as ``(x² + y²)/2 − l²/2`` would give ``τ = −l λ``. The same written form is used on both sides
  below, so no rescaling is needed apart from the sign.
"""

import numpy as np
import pytest
import sympy as sp
from sympy.physics import mechanics as me

from lagrange import Holonomic, Nonholonomic, Particle, System, coordinates, parameters, t
from lagrange.simplification import is_zero

RTOL = 1e-10


def _close(a, b, rtol=RTOL):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(float(np.max(np.abs(a))), float(np.max(np.abs(b))), 1e-300)
    assert np.max(np.abs(a - b)) <= rtol * scale, f"\n{a}\n{b}"


def _sympy_solution(lm, n, m, values):
    """[q̇, q̈, λ] from sympy's full mass matrix and forcing (first-order form with multipliers)."""
    Mf = np.array(lm.mass_matrix_full.subs(values).evalf(), dtype=float)
    ff = np.array(lm.forcing_full.subs(values).evalf(), dtype=float).ravel()
    assert Mf.shape == (2 * n + m, 2 * n + m)
    return np.linalg.solve(Mf, ff)


# --------------------------------------------------------------------------------------------------------------
# (a) Cartesian pendulum with a length constraint
# --------------------------------------------------------------------------------------------------------------

MP = {"m": 1.3, "g": 9.81, "l": 0.7}


@pytest.fixture(scope="module")
def pendulum():
    # sympy side
    xs, ys = me.dynamicsymbols("x y")
    xsd, ysd = me.dynamicsymbols("x y", 1)
    ms, gs, ls = sp.symbols("m g l", positive=True)
    Ls = ms / 2 * (xsd**2 + ysd**2) - ms * gs * ys
    lm = me.LagrangesMethod(Ls, [xs, ys], hol_coneqs=[xs**2 + ys**2 - ls**2])
    lm.form_lagranges_equations()
    # lagrange side
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    system = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
                    constraints=[Holonomic(x**2 + y**2 - l**2, name="string")])
    model = system.compile({m: MP["m"], g: MP["g"], l: MP["l"]})
    sym = {"x": (xs, xsd), "y": (ys, ysd), "params": {ms: MP["m"], gs: MP["g"], ls: MP["l"]}}
    return lm, model, sym


@pytest.mark.parametrize("theta, omega", [(0.3, 0.0), (-1.1, 2.0), (2.5, -0.7), (0.0, 3.1)])
def test_pendulum_accelerations_and_multipliers(pendulum, theta, omega):
    lm, model, sym = pendulum
    lv = MP["l"]
    xv, yv = lv * np.sin(theta), -lv * np.cos(theta)  # on the circle
    xdv, ydv = lv * np.cos(theta) * omega, lv * np.sin(theta) * omega  # tangent velocity
    state = np.array([xv, yv, xdv, ydv])

    out = np.asarray(model.dynamics(0.0, state, model._pcall), dtype=float)
    qdd_l, lam_l = out[2:4], out[4:]
    np.testing.assert_allclose(model.multipliers(0.0, state), lam_l, rtol=0, atol=0)
    np.testing.assert_allclose(model.fun(0.0, state), out[:4], rtol=0, atol=0)

    (xs, xsd), (ys, ysd) = sym["x"], sym["y"]
    values = {**sym["params"], xs: xv, ys: yv, xsd: xdv, ysd: ydv}
    sol = _sympy_solution(lm, 2, 1, values)
    qdd_s, lam_s = sol[2:4], sol[4:]

    _close(qdd_l, qdd_s)
    _close(lam_l, lam_s)  # mass_matrix_full carries −Λ (issue #30215): same sign as lagrange's λ

    # sympy's eom attribute uses the other sign: it vanishes with λ = −λ_lagrange, not with +λ_lagrange
    lam_sym = lm.lam_vec[0]
    xdd, ydd = xs.diff(me.dynamicsymbols._t, 2), ys.diff(me.dynamicsymbols._t, 2)
    acc = {xdd: qdd_l[0], ydd: qdd_l[1]}
    eom_minus = np.array(lm.eom.subs(acc).subs({lam_sym: -lam_l[0]}).subs(values).evalf(), dtype=float).ravel()
    eom_plus = np.array(lm.eom.subs(acc).subs({lam_sym: lam_l[0]}).subs(values).evalf(), dtype=float).ravel()
    force_scale = MP["m"] * max(np.max(np.abs(qdd_l)), MP["g"])
    assert np.max(np.abs(eom_minus)) <= RTOL * force_scale
    assert np.max(np.abs(eom_plus)) > 1e-3 * force_scale

    # physical reading: tension τ = m v²/l + m g cos θ, and with φ = x² + y² − l², τ = −2 l λ_lagrange
    tau = MP["m"] * (lv * omega) ** 2 / lv + MP["m"] * MP["g"] * np.cos(theta)
    _close(-2 * lv * lam_l[0], tau)


# --------------------------------------------------------------------------------------------------------------
# (b) rolling disc on a plane: x, y (contact point), yaw q1, lean q2, spin q3
# --------------------------------------------------------------------------------------------------------------

DP = {"m": 2.0, "g": 9.81, "r": 0.4}


def _disc_sympy():
    x, y, q1, q2, q3 = me.dynamicsymbols("x y q1 q2 q3")
    ms, gs, rs = sp.symbols("m g r", positive=True)
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [q1, N.z])  # yaw
    L = Y.orientnew("L", "Axis", [q2, Y.x])  # lean
    R = L.orientnew("R", "Axis", [q3, L.y])  # spin
    O = me.Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", x * N.x + y * N.y)  # contact point on the plane
    Dmc = C.locatenew("Dmc", rs * L.z)  # disc centre
    Dmc.set_vel(N, Dmc.pos_from(O).dt(N))
    I = me.inertia(L, ms * rs**2 / 4, ms * rs**2 / 2, ms * rs**2 / 4)
    disc = me.RigidBody("disc", Dmc, R, ms, (I, Dmc))
    disc.potential_energy = ms * gs * rs * sp.cos(q2)
    Lag = me.Lagrangian(N, disc)
    # velocity of the disc's material point at the contact: v_centre + ω × (−r L.z)
    P = Dmc.locatenew("P", -rs * L.z)
    vP = P.v2pt_theory(Dmc, N, R)
    nonhol = [vP.dot(N.x), vP.dot(N.y)]
    lm = me.LagrangesMethod(Lag, [x, y, q1, q2, q3], nonhol_coneqs=nonhol, frame=N)
    lm.form_lagranges_equations()
    coords = [x, y, q1, q2, q3]
    speeds = [c.diff(me.dynamicsymbols._t) for c in coords]
    return lm, coords, speeds, {ms: DP["m"], gs: DP["g"], rs: DP["r"]}


def _disc_lagrange():
    x, y, q1, q2, q3 = coordinates("x y q1 q2 q3")
    m, g, r = parameters("m g r")
    xd, yd, q1d, q2d, q3d = (c.diff(t) for c in (x, y, q1, q2, q3))
    s1, c1, s2, c2 = sp.sin(q1), sp.cos(q1), sp.sin(q2), sp.cos(q2)
    # centre = (x + r s2 s1, y − r s2 c1, r c2); body rates in the lean frame L: (q2', q1' s2 + q3', q1' c2)
    vc = (xd + r * (c2 * s1 * q2d + s2 * c1 * q1d), yd + r * (s2 * s1 * q1d - c2 * c1 * q2d), -r * s2 * q2d)
    T = (m / 2 * sum(v**2 for v in vc)
         + sp.Rational(1, 2) * (m * r**2 / 4 * (q2d**2 + (q1d * c2) ** 2) + m * r**2 / 2 * (q1d * s2 + q3d) ** 2))
    system = System(
        [x, y, q1, q2, q3],
        T=T,
        V=m * g * r * c2,
        constraints=[Nonholonomic(xd - r * c1 * q3d, name="roll x"), Nonholonomic(yd - r * s1 * q3d, name="roll y")],
    )
    return system.compile({m: DP["m"], g: DP["g"], r: DP["r"]})


@pytest.fixture(scope="module")
def disc():
    return _disc_sympy(), _disc_lagrange()


def test_disc_constraints_are_the_classic_rolling_conditions(disc):
    (lm, coords, speeds, params), _ = disc
    x, y, q1, q2, q3 = coords
    rs = [s for s in params if s.name == "r"][0]
    expected = [speeds[0] - rs * sp.cos(q1) * speeds[4], speeds[1] - rs * sp.sin(q1) * speeds[4]]
    got = lm.coneqs
    assert len(got) == 2
    for a, b in zip(got, expected):
        assert is_zero(a - b)


@pytest.mark.parametrize("seed", range(6))
def test_disc_accelerations_at_random_consistent_states(disc, seed):
    (lm, coords, speeds, params), model = disc
    rng = np.random.default_rng(seed)
    q = rng.uniform(-1.0, 1.0, 5)
    q[3] = rng.uniform(-1.2, 1.2)  # lean away from lying flat
    u1, u2, u3 = rng.uniform(-2.0, 2.0, 3)
    rv = DP["r"]
    qd = np.array([rv * np.cos(q[2]) * u3, rv * np.sin(q[2]) * u3, u1, u2, u3])  # rolling-consistent
    state = np.concatenate([q, qd])

    out = np.asarray(model.dynamics(0.0, state, model._pcall), dtype=float)
    qdd_l, lam_l = out[5:10], out[10:]
    res = model.constraint_functions.velocity_residual(0.0, state)
    assert np.max(np.abs(res)) < 1e-14

    values = {**params, **dict(zip(coords, q)), **dict(zip(speeds, qd))}
    sol = _sympy_solution(lm, 5, 2, values)
    qdd_s, lam_s = sol[5:10], sol[10:]

    _close(qdd_l, qdd_s)
    _close(lam_l, lam_s)  # same written constraints; mass_matrix_full's λ has lagrange's sign
    # the accelerations satisfy the differentiated constraints: d/dt(ẋ − r cos q1 q̇3) = 0, etc.
    c1, s1 = np.cos(q[2]), np.sin(q[2])
    acc_x = qdd_l[0] - rv * (c1 * qdd_l[4] - s1 * qd[2] * qd[4])
    acc_y = qdd_l[1] - rv * (s1 * qdd_l[4] + c1 * qd[2] * qd[4])
    assert max(abs(acc_x), abs(acc_y)) <= RTOL * max(1.0, float(np.max(np.abs(qdd_l))))
