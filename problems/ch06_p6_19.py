"""Wells, Problem 6.19 — a dumbbell of two equal spheres (each at distance l from the centre of mass, direction
θ, φ in spherical angles) moving in a viscous fluid that resists each sphere with a v: the power function."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem, Simulation

x, y, z, theta, phi = coordinates("x y z theta phi")
m, l, a = parameters("m l a")

u = sp.Matrix([sp.sin(theta) * sp.cos(phi), sp.sin(theta) * sp.sin(phi), sp.cos(theta)])
c = sp.Matrix([x, y, z])
spheres = [Particle(m, tuple(c + l * u), name="sphere 1"), Particle(m, tuple(c - l * u), name="sphere 2")]
# Wells' P for viscous drag a on each sphere: P = −½ a Σ v_i², from each sphere's velocity
P = sum(-a * sum(sp.diff(comp, t) ** 2 for comp in s.position) / 2 for s in spheres)
system = System([x, y, z, theta, phi], bodies=spheres, P=P, name="dumbbell in a viscous fluid")

xd, yd, zd, thd, phd = (q.diff(t) for q in (x, y, z, theta, phi))
P_corrected = -a * (xd**2 + yd**2 + zd**2) - a * l**2 * (thd**2 + sp.sin(theta) ** 2 * phd**2)

PROBLEM = Problem(
    id="p6.19",
    title="Dumbbell of two spheres in a viscous fluid: P = −a v² − a l²(θ̇² + sin²θ φ̇²)",
    chapter=6,
    source="Wells, Problem 6.19",
    system=system,
    answers=[PowerFunction(P_corrected)],
    simulation=Simulation(params={m: 1, l: 0.5, a: 0.3},
                          initial={x: 0, y: 0, z: 0, theta: 1.0, phi: 0, xd: 1, yd: 0, zd: 0.5, thd: 0.5, phd: 1.0},
                          t_end=3.0),
    correction="The book prints P = −½a(ẋ² + ẏ² + ż²) − a(l²θ̇² + l²φ̇² sin²θ). With drag a on each sphere the "
    "translational part is −a(ẋ² + ẏ² + ż²) (two spheres, ½a v² each); the book's ½a would need a to be the "
    "total of both spheres, and then the rotational term would be ½a l²(…). The consistent form (catalog) is "
    "checked.",
)
