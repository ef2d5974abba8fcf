"""Wells, Example 14.4 — track forces on a coach (mass M) moving at uniform speed through O1.

Earth frame of Fig. 14-2 under true gravity (EarthFrame). The force the track must exert is
f = d/dt dT/dqdot - dT/dq - F_gravity evaluated with the coach at O1 and constant velocity (accelerations zero).
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x1 y1 z1")
M, gp, w, R, Phi = parameters("M g_prime omega_e R Phi")
s, c = sp.sin(Phi), sp.cos(Phi)

E = EarthFrame(Phi, w, R)
coach = Particle(M, E.point((x, y, z)), name="coach")
system = System([x, y, z], bodies=[coach], forces=[Force(coach, E.gravity_force(M, gp))],
                name="coach in the earth frame")

ACC0 = {q.diff(t, 2): 0 for q in (x, y, z)}
AT_O1 = {x: 0, y: 0, z: 0}  # substituted after the velocities


def _track_force(sys_, moving):
    """Track force at O1 for uniform motion along ``moving`` (the other velocities zero)."""
    still = {q.diff(t): 0 for q in (x, y, z) if q is not moving}
    v = sp.Dummy("v")  # keep the speed while the positions are set to zero
    return [sp.simplify((e.lhs - e.rhs).subs(ACC0).subs(still).subs(moving.diff(t), v).subs(AT_O1)
                        .subs(v, moving.diff(t))) for e in sys_.equations()]


PROBLEM = Problem(
    id="ex14.4",
    title="Track forces on a coach moving north or east at uniform speed through O1",
    chapter=14,
    source="Wells, Example 14.4",
    system=system,
    answers=[
        Quantity("track force, coach moving north (f_x1, f_y1, f_z1)", lambda sys_: _track_force(sys_, y),
                 [-2 * M * w * y.diff(t) * s, 0, M * gp]),
        Quantity("track force, coach moving east (f_x1, f_y1, f_z1)", lambda sys_: _track_force(sys_, x),
                 [0, 2 * M * w * x.diff(t) * s, M * gp - 2 * M * w * x.diff(t) * c]),
    ],
    simulation=Simulation(
        params={M: 9.07e7, gp: 980.629, w: 7.29211e-5, R: 6.389135e8, Phi: 0.7853981634},
        initial={x: 0.0, y: 0.0, z: 0.0, x.diff(t): 0.0, y.diff(t): 2682.24, z.diff(t): 0.0},
        t_end=2,
    ),
    units="cgs; simulation: 100 tons, 60 mi/h north, free flight (no track)",
    correction="Northward case: the book prints f_z1 = -M g'; (14.15) gives +M g' (the text itself says the track "
    "'supports the weight M g''), so +M g' is used. The ω_e^2 terms vanish exactly at O1 here.",
)
