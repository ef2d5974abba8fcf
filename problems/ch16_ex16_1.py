"""Wells, Example 16.1 — projectile: momenta, Hamiltonian and canonical equations."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

x, y, z = coordinates("x y z")
m, g = parameters("m g")
px, py, pz = (sp.Symbol(n, real=True) for n in ("p_x", "p_y", "p_z"))
zs = sp.Symbol("z", real=True)

system = System([x, y, z], bodies=[Particle(m, (x, y, z))], V=m * g * z, name="projectile")

PROBLEM = Problem(
    id="ex16.1",
    title="Projectile: p = m v, H = (px^2 + py^2 + pz^2)/2m + mgz, canonical equations",
    chapter=16,
    source="Wells, Example 16.1",
    system=system,
    answers=[
        Quantity("momenta", lambda s: hamiltonian(s).momenta, [m * x.diff(t), m * y.diff(t), m * z.diff(t)]),
        Quantity("H", lambda s: hamiltonian(s).H, (px**2 + py**2 + pz**2) / (2 * m) + m * g * zs),
        Quantity("qdot = dH/dp", lambda s: hamiltonian(s).qdot, [px / m, py / m, pz / m]),
        Quantity("pdot = -dH/dq", lambda s: hamiltonian(s).pdot, [0, 0, -m * g]),
        EquationsOfMotion([sp.Eq(m * x.diff(t, 2), 0), sp.Eq(m * y.diff(t, 2), 0),
                           sp.Eq(m * z.diff(t, 2), -m * g)], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, g: 9.81}, initial={x: 0, y: 0, z: 0, x.diff(t): 3, y.diff(t): 1,
                                                          z.diff(t): 10}, t_end=2),
)
