"""The Whipple bicycle: Meijaard, Papadopoulos, Ruina & Schwab (2007), the benchmark of bicycle dynamics.

J. P. Meijaard, J. M. Papadopoulos, A. Ruina, A. L. Schwab, "Linearized dynamics equations for the balance
and steer of a bicycle: a benchmark and review", Proc. R. Soc. A 463 (2007) 1955–1982,
doi:10.1098/rspa.2007.1857.

Four rigid bodies — rear wheel R, rear frame B (with rider), front frame H (fork and handlebar), front wheel F
— declared with :class:`lagrange.RigidBody` and :class:`lagrange.RotationSequence` orientations, eight
coordinates and five constraints:

* coordinates: rear contact point ``x, y``; yaw ``psi``; roll (lean) ``phi``; rear-frame pitch ``theta``; steer
  ``delta``; wheel rotations ``theta_R`` (relative to the rear frame) and ``theta_F`` (relative to the front
  frame);
* rolling without slip of both wheels, longitudinal and lateral (four :class:`lagrange.Nonholonomic`
  constraints, the contact-point velocity of each wheel along the yaw frame's x and y axes), and the front
  wheel touching the ground (one :class:`lagrange.Holonomic` constraint, which fixes the pitch).

Conventions of the paper: inertial axes x forward, y right, z **down**; roll, pitch and steer right-handed about
the yaw frame's x, the rear frame's y and the steer axis (pointing down); the reference configuration is upright
and straight with the rear contact at the origin, where ``theta = 0``. The steer axis is tilted back by λ and
meets the ground the trail c ahead of the front contact. Inertia tensors are the paper's (about each centre of
mass, along the reference axes; off-diagonal entries are tensor entries, not Wells' positive products). Units SI.

Published values used by the tests and the notebook (``BENCHMARK``, ``PUBLISHED``), each checked against two
public transcriptions of the paper: the parameter set (paper Table 1) and the linear coefficient matrices M,
C1, K0, K2 (paper section 5, eq. (5.4)) as in DynamicistToolKit ``dtk/bicycle.py`` (``benchmark_parameters``,
``benchmark_matrices``, github.com/moorepants/DynamicistToolKit); the eigenvalues for v = 0 … 10 m/s (paper
Table 2) and the weave and capsize speeds (paper section 5) as hand-copied from the paper in D. L. Peterson's
Whipple-model unit tests (2011, gtest ``Whipple.Eigenvalues``), identical to 14 decimals in other public
transcriptions. The parameter values are exact rationals (λ = π/10); g, λ and the two input torques stay
symbols.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from lagrange import (
    Holonomic,
    Nonholonomic,
    RigidBody,
    RotationSequence,
    System,
    coordinates,
    parameters,
    rot_x,
    rot_y,
    rot_z,
    t,
)
from lagrange.corpus import LazySystem, Problem, Quantity, Simulation

R_ = sp.Rational

#: Meijaard et al. (2007) Table 1, exact (g and λ = π/10 are the symbols ``g`` and ``lambda``).
BENCHMARK = {
    "w": R_(102, 100), "c": R_(8, 100), "r_R": R_(3, 10), "m_R": 2, "I_Rxx": R_(603, 10000), "I_Ryy": R_(12, 100),
    "x_B": R_(3, 10), "z_B": R_(-9, 10), "m_B": 85,
    "I_Bxx": R_(92, 10), "I_Byy": 11, "I_Bzz": R_(28, 10), "I_Bxz": R_(24, 10),
    "x_H": R_(9, 10), "z_H": R_(-7, 10), "m_H": 4,
    "I_Hxx": R_(5892, 100000), "I_Hyy": R_(6, 100), "I_Hzz": R_(708, 100000), "I_Hxz": R_(-756, 100000),
    "r_F": R_(35, 100), "m_F": 3, "I_Fxx": R_(1405, 10000), "I_Fyy": R_(28, 100),
}

x, y, psi, phi, theta, delta, theta_R, theta_F = coordinates("x y psi phi theta delta theta_R theta_F")
g, lam = parameters("g lambda")
T_phi, T_delta = parameters("T_phi T_delta", real=True)  # roll torque (ground on rear frame), steer torque
v = parameters("v")  # forward speed of the operating point (not a parameter of the system)

COORDINATES = (x, y, psi, phi, theta, delta, theta_R, theta_F)


#: the 24 parameters of the paper besides g and λ, as symbols (z_B, z_H and the products of inertia are signed)
SYMBOLS = {name: parameters(name) for name in BENCHMARK}
SYMBOLS.update({name: parameters(name, real=True) for name in ("z_B", "z_H", "I_Bxz", "I_Hxz")})


def whipple_bicycle(values=None, *, derivation: str = "auto") -> System:
    """The Whipple bicycle; ``values`` maps parameter names to numbers or expressions substituted into the
    declaration (default: every parameter a symbol, see :data:`SYMBOLS`; bind them with :data:`PARAMS`).

    Generalized forces: ``T_phi`` on the roll coordinate (a torque about the yaw frame's x axis from the ground
    on the rear frame) and ``T_delta`` on the steer coordinate (equal and opposite torques on front and rear
    frame about the steer axis) — the inputs of the paper's linear equations (5.3). ``derivation`` is passed to
    :class:`lagrange.System`.
    """
    p = {**SYMBOLS, **{k: sp.sympify(val) for k, val in (values or {}).items()}}
    V3 = sp.Matrix
    ex, ey, ez = V3([1, 0, 0]), V3([0, 1, 0]), V3([0, 0, 1])
    # yaw-frame components of every point (psi only enters through the yaw rotation of the whole)
    roll = rot_x(phi)
    rear_frame = roll * rot_y(theta)
    steer = roll * rot_y(theta + lam) * rot_z(delta)  # z along the steer axis
    front_frame = steer * rot_y(-lam)  # the reference axes when delta = 0
    hub_R = -p["r_R"] * roll * ez

    def on_rear_frame(point):  # a point given in the reference configuration, carried by the rear frame
        return hub_R + rear_frame * (V3(point) - V3([0, 0, -p["r_R"]]))

    axis_point = V3([p["w"] + p["c"], 0, 0])  # where the steer axis meets the ground in the reference

    def on_front_frame(point):
        return on_rear_frame(axis_point) + front_frame * (V3(point) - axis_point)

    rho = {
        "R": hub_R,
        "B": on_rear_frame([p["x_B"], 0, p["z_B"]]),
        "H": on_front_frame([p["x_H"], 0, p["z_H"]]),
        "F": on_front_frame([p["w"], 0, -p["r_F"]]),
    }
    yaw = rot_z(psi)
    P = V3([x, y, 0])

    def inertial(r):
        return P + yaw * r

    J_B = sp.Matrix([[p["I_Bxx"], 0, p["I_Bxz"]], [0, p["I_Byy"], 0], [p["I_Bxz"], 0, p["I_Bzz"]]])
    J_H = sp.Matrix([[p["I_Hxx"], 0, p["I_Hxz"]], [0, p["I_Hyy"], 0], [p["I_Hxz"], 0, p["I_Hzz"]]])
    base = (("z", psi), ("x", phi))
    fork_chain = (*base, ("y", theta + lam), ("z", delta))
    bodies = [
        RigidBody(p["m_R"], (p["I_Rxx"], p["I_Ryy"], p["I_Rxx"]), origin=inertial(rho["R"]),
                  orientation=RotationSequence(*base, ("y", theta + theta_R)), name="rear wheel"),
        RigidBody(p["m_B"], J_B, origin=inertial(rho["B"]), orientation=RotationSequence(*base, ("y", theta)),
                  name="rear frame"),
        RigidBody(p["m_H"], J_H, origin=inertial(rho["H"]), orientation=RotationSequence(*fork_chain, ("y", -lam)),
                  name="front frame"),
        RigidBody(p["m_F"], (p["I_Fxx"], p["I_Fyy"], p["I_Fxx"]), origin=inertial(rho["F"]),
                  orientation=RotationSequence(*fork_chain, ("y", theta_F - lam)), name="front wheel"),
    ]
    # rolling: the wheel's material point at the contact has zero velocity (yaw-frame components)
    rates = {q: q.diff(t) for q in COORDINATES}
    w_B = rates[psi] * ez + rates[phi] * ex + rates[theta] * roll * ey
    w_F = w_B + rates[delta] * steer * ez + rates[theta_F] * front_frame * ey
    v_P = yaw.T * P.diff(t)

    def velocity(r):  # yaw-frame components of the velocity of the point P + yaw r
        return v_P + (rates[psi] * ez).cross(r) + r.diff(t)

    axle_F = front_frame * ey
    reach = sp.sqrt(1 - axle_F[2] ** 2)
    down_F = (ez - axle_F[2] * axle_F) / reach  # from the front hub to the contact, in the wheel plane
    # rear wheel: the same formula simplifies by hand (tests/problems/test_bicycle.py checks it against
    # velocity(rho["R"]) + w_R × r_R roll e_z) to the contact point moving along the heading at r_R (θ̇ + θ̇_R)
    v_heading = sp.cos(psi) * rates[x] + sp.sin(psi) * rates[y]
    slip_R = [v_heading + p["r_R"] * (rates[theta] + rates[theta_R]), -sp.sin(psi) * rates[x] + sp.cos(psi) * rates[y]]
    slip_F = velocity(rho["F"]) + w_F.cross(p["r_F"] * down_F)
    constraints = [
        Nonholonomic(slip_R[0], "rear wheel rolls (longitudinal)"),
        Nonholonomic(slip_R[1], "rear wheel rolls (lateral)"),
        Nonholonomic(slip_F[0], "front wheel rolls (longitudinal)"),
        Nonholonomic(slip_F[1], "front wheel rolls (lateral)"),
        Holonomic(rho["F"][2] + p["r_F"] * reach, "front wheel touches the ground"),
    ]
    masses = {"R": p["m_R"], "B": p["m_B"], "H": p["m_H"], "F": p["m_F"]}
    V = -g * sum(masses[k] * rho[k][2] for k in masses)  # z points down
    return System(list(COORDINATES), bodies=bodies, V=V, forces={phi: T_phi, delta: T_delta},
                  constraints=constraints, name="Whipple bicycle (Meijaard et al. 2007 benchmark)",
                  derivation=derivation)


def operating_point(speed=v, values=None) -> dict:
    """Upright, straight-ahead running at forward ``speed`` along x (paper section 5): every coordinate 0,
    rear and front wheel rates ``−v/r_R`` and ``−v/r_F`` (the wheels roll forward about their +y axles).
    Radii from ``values`` (names to numbers), else the symbols."""
    p = {**SYMBOLS, **(values or {})}
    point = {q: 0 for q in COORDINATES}
    point.update({q.diff(t): 0 for q in COORDINATES})
    point[x.diff(t)] = speed
    point[theta_R.diff(t)] = -speed / sp.sympify(p["r_R"])
    point[theta_F.diff(t)] = -speed / sp.sympify(p["r_F"])
    return point


PARAMS = {**{SYMBOLS[k]: val for k, val in BENCHMARK.items()}, g: R_(981, 100), lam: sp.pi / 10, T_phi: 0, T_delta: 0}

#: Meijaard et al. (2007): linear equations M q̈ + v C1 q̇ + (g K0 + v² K2) q = f, q = (φ, δ), section 5 eq.
#: (5.4); eigenvalues at v = 0 … 10 m/s (Table 2); weave and capsize speeds (section 5).
PUBLISHED = {
    "M": [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]],
    "C1": [[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]],
    "K0": [[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]],
    "K2": [[0.0, 76.59734589573222], [0.0, 2.65431523794604]],
    "weave_speed": 4.29238253634111,
    "capsize_speed": 6.02426201538837,
    "eigenvalues": {  # Table 2: per speed, the four eigenvalues (complex pairs written out)
        0: [-5.53094371765393, -3.13164324790656, 3.13164324790656, 5.53094371765393],
        1: [3.52696170990070 + 0.80774027519930j, 3.52696170990070 - 0.80774027519930j, -3.13423125066578,
            -7.11008014637442],
        2: [2.68234517512745 + 1.68066296590675j, 2.68234517512745 - 1.68066296590675j, -3.07158645641514,
            -8.67387984831735],
        3: [1.70675605663975 + 2.31582447384325j, 1.70675605663975 - 2.31582447384325j, -2.63366137253667,
            -10.35101467245920],
        4: [0.41325331521125 + 3.07910818603206j, 0.41325331521125 - 3.07910818603206j, -1.42944427361326,
            -12.15861426576450],
        5: [-0.77534188219585 + 4.46486771378823j, -0.77534188219585 - 4.46486771378823j, -0.32286642900409,
            -14.07838969279820],
        6: [-1.52644486584142 + 5.87673060598709j, -1.52644486584142 - 5.87673060598709j, -0.00406690076970,
            -16.08537123098030],
        7: [-2.13875644258362 + 7.19525913329805j, -2.13875644258362 - 7.19525913329805j, 0.10268170574766,
            -18.15788466125262],
        8: [-2.69348683581097 + 8.46037971396931j, -2.69348683581097 - 8.46037971396931j, 0.14327879765713,
            -20.27940894394569],
        9: [-3.21675402252485 + 9.69377351531791j, -3.21675402252485 - 9.69377351531791j, 0.15790184030917,
            -22.43788559040858],
        10: [-3.72016840437287 + 10.90681139476287j, -3.72016840437287 - 10.90681139476287j, 0.16105338653172,
             -24.62459635017404],
    },
}


def lean_steer_matrix(model, speed: float, values=None, step: float = 1e-3) -> np.ndarray:
    """The 4×4 state matrix of (φ, δ, φ̇, δ̇) about upright straight running at ``speed``, from a compiled
    model of :func:`whipple_bicycle` (``system.compile(params)``), on the constraint manifold.

    For a state (φ, δ, φ̇, δ̇) the pitch solves the holonomic constraint (Brent), the dependent rates
    (ẋ, ẏ, ψ̇, θ̇, θ̇_F) solve ``A q̇ + b = 0`` with the rear wheel rate held at ``−v/r_R``, and the compiled
    dynamics give (φ̈, δ̈). The Jacobian is taken by central differences with one Richardson step (error
    O(step⁴), about 1e-12 here). Yaw, position and wheel angles are ignorable and stay 0.
    """
    from scipy.optimize import brentq

    r_R = float((values or BENCHMARK)["r_R"])
    cf = model.constraint_functions
    index = {q: i for i, q in enumerate(model.equations.coordinates)}
    n = len(index)
    free = [index[phi], index[delta], index[theta_R]]
    dependent = [k for k in range(n) if k not in free]

    def accelerations(z):
        q = np.zeros(n)
        q[index[phi]], q[index[delta]] = z[0], z[1]

        def contact(pitch):
            qq = q.copy()
            qq[index[theta]] = pitch
            return cf.phi(0.0, qq)[0]

        q[index[theta]] = brentq(contact, -0.5, 0.5, xtol=1e-15, rtol=1e-15)
        A, b = cf.matrix(0.0, q), cf.bias(0.0, q)
        qd = np.zeros(n)
        qd[free] = [z[2], z[3], -speed / r_R]
        qd[dependent] = np.linalg.solve(A[:, dependent], -b - A[:, free] @ qd[free])
        out = model.dynamics(0.0, np.concatenate([q, qd]), model.params)
        return np.array([out[n + index[phi]], out[n + index[delta]]])

    jac = np.zeros((2, 4))
    for k in range(4):
        def central(h, k=k):
            e = np.zeros(4)
            e[k] = h
            return (accelerations(e) - accelerations(-e)) / (2 * h)

        jac[:, k] = (4 * central(step / 2) - central(step)) / 3
    out = np.zeros((4, 4))
    out[:2, 2:] = np.eye(2)
    out[2:] = jac
    return out


def stability_speeds(system, params=None) -> list:
    """Weave and capsize speeds: where the largest real part of the lean–steer eigenvalues crosses zero
    (Brent's method on [4, 5] and [5.5, 6.5] m/s)."""
    from scipy.optimize import brentq

    model = system.compile(params or PARAMS)  # a System or the problem's LazySystem

    def abscissa(speed):
        return float(np.max(np.linalg.eigvals(lean_steer_matrix(model, speed)).real))

    return [brentq(abscissa, 4.0, 5.0, xtol=1e-13), brentq(abscissa, 5.5, 6.5, xtol=1e-13)]


system = LazySystem(whipple_bicycle, "Whipple bicycle (Meijaard et al. 2007 benchmark)")
INITIAL = {**operating_point(R_(5), BENCHMARK), phi.diff(t): R_(1, 2)}

PROBLEM = Problem(
    id="bicycle",
    title="Whipple bicycle benchmark: four rigid bodies, rolling wheels, self-stable between 4.29 and 6.02 m/s",
    chapter=12,
    source="Meijaard, Papadopoulos, Ruina & Schwab (2007), Proc. R. Soc. A 463:1955-1982, Table 2 and section 5",
    system=system,
    answers=[
        Quantity("weave and capsize speeds (m/s)", stability_speeds,
                 [sp.Float(PUBLISHED["weave_speed"], 15), sp.Float(PUBLISHED["capsize_speed"], 15)], rtol=1e-10,
                 description="weave speed 4.29238253634111 and capsize speed 6.02426201538837 m/s"),
    ],
    units="SI (m, kg, s, rad)",
    simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=5.0, options={"rtol": 1e-9, "atol": 1e-9}),
    tags=("rigid bodies", "non-holonomic", "benchmark", "slow"),
    operating_point=operating_point(v),
    correction="Not from Wells: the standard benchmark of multibody codes for non-holonomic rigid-body systems.",
)
