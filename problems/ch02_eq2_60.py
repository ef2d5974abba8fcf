"""Wells, eq. (2.60) — acceleration components in spherical coordinates from (3.24)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

r, theta, phi = coordinates("r theta phi")
m = parameters("m")

system = System(
    [r, theta, phi],
    bodies=[Particle(m, (r * sp.sin(theta) * sp.cos(phi), r * sp.sin(theta) * sp.sin(phi), r * sp.cos(theta)))],
    name="particle, spherical coordinates",
)


def _components(s):
    # a_q = (1/h_q)[d/dt ∂T'/∂q̇ − ∂T'/∂q], T' = T/m; with no forces the left side of Lagrange's
    # equation is exactly the bracket times m.
    pos = s.bodies[0].position_vectors()[0]
    out = []
    for q, eq in zip(s.coordinates, s.equations(), strict=True):
        h = sp.sqrt(sum(sp.diff(c, q) ** 2 for c in pos))
        out.append((eq.lhs - eq.rhs) / (m * h))
    return out


rd, thd, phd = r.diff(t), theta.diff(t), phi.diff(t)
PROBLEM = Problem(
    id="eq2.60",
    title="Spherical acceleration components a_r, a_θ, a_φ",
    chapter=2,
    source="Wells, Sec. 2.11, eq. (2.60) (method of (3.24))",
    system=system,
    answers=[
        Quantity(
            "(a_r, a_theta, a_phi)",
            _components,
            [
                r.diff(t, 2) - r * thd**2 - r * phd**2 * sp.sin(theta) ** 2,
                r * theta.diff(t, 2) + 2 * rd * thd - r * phd**2 * sp.sin(theta) * sp.cos(theta),
                r * phi.diff(t, 2) * sp.sin(theta) + 2 * rd * phd * sp.sin(theta)
                + 2 * r * phd * thd * sp.cos(theta),
            ],
        ),
    ],
    simulation=Simulation(params={m: 1}, initial={r: 1.0, theta: 1.0, phi: 0.0, r.diff(t): 0.1,
                                                  theta.diff(t): 0.2, phi.diff(t): 0.5}, t_end=2.0),
)
