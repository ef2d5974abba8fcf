"""Wells, Example 3.5 — bead on a smooth rod rotating at constant ω in a plane (moving constraint, explicit t)."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Quantity, Simulation

r = coordinates("r")
m, w, Fx, Fy = parameters("m omega F_x F_y")

# x = r cos ωt, y = r sin ωt; a constant applied force (F_x, F_y) acts on the bead.
bead = Particle(m, (r * sp.cos(w * t), r * sp.sin(w * t)), name="bead")
system = System([r], bodies=[bead], forces=[Force(bead, (Fx, Fy))], name="bead on a rotating rod")


def transverse_force(s):
    """Wells' δt variation (3.23): m a·∂r/∂t = (total force)·∂r/∂t, with ∂r/∂t = rω e_perp.

    The total transverse force (the rod's normal force N when no applied force acts across the rod)."""
    pos = s.bodies[0].position
    rs = sp.Dummy("r")
    dr_dt = pos.subs(r, rs).diff(t).subs(rs, r)  # partial in t, r held fixed
    acc = pos.diff(t, 2)
    lhs = m * (acc.T * dr_dt)[0, 0]
    return sp.simplify(lhs / (r * w))


PROBLEM = Problem(
    id="ex3.5",
    title="Bead on a rod rotating at constant omega: m(r'' - r w^2) = F_r, constraint force N = 2 m w r'",
    chapter=3,
    source="Wells, Example 3.5",
    system=system,
    answers=[
        GeneralizedForces({r: Fx * sp.cos(w * t) + Fy * sp.sin(w * t)}),
        EquationsOfMotion(
            [sp.Eq(m * (r.diff(t, 2) - r * w**2), Fx * sp.cos(w * t) + Fy * sp.sin(w * t))], per_equation=True
        ),
        Quantity("transverse force N = (F_y cos wt - F_x sin wt)_total from the δt variation", transverse_force, 2 * m * w * r.diff(t)),
    ],
    simulation=Simulation(params={m: 1, w: 1, Fx: 0.1, Fy: 0.0}, initial={r: 0.5, r.diff(t): 0}, t_end=2),
    correction="Eq. (6) is printed '(2mrω̇²)'; the δt variation gives 2 m r ṙ ω² δt = (F_y cos ωt − F_x sin ωt) r ω δt "
               "+ N r ω δt, i.e. N = 2 m ω ṙ (catalog).",
)
