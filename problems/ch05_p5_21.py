"""Wells, Problem 5.21 — particle on two springs in a vertical plane rotating with a vertical shaft (Fig. 5-22)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

x, y, theta = coordinates("x y theta")
m, g, R, s, k1, k2, l1p, l2p, w = parameters("m g R s k1 k2 l1p l2p omega")

# The plane turns with the shaft through theta; in it, x is horizontal from a point at distance R from the
# axis, y vertical (up). Spring 1 runs to the anchor (0, s), spring 2 to the anchor (0, 0).
pos = ((R + x) * sp.cos(theta), (R + x) * sp.sin(theta), y)
V = (m * g * y + k1 * (sp.sqrt(x**2 + (s - y) ** 2) - l1p) ** 2 / 2
     + k2 * (sp.sqrt(x**2 + y**2) - l2p) ** 2 / 2)
system = System([x, y, theta], bodies=[Particle(m, pos)], V=V, name="particle on springs, rotating plane")


def _steady(sys):
    """x and y equations at relative rest (xd = yd = 0) with thd = omega, thdd = 0."""
    at_rest = {x.diff(t, 2): 0, y.diff(t, 2): 0, theta.diff(t, 2): 0}
    eqs = [e.lhs - e.rhs for e in sys.equations()]
    ex, ey = (eqs[i].subs(at_rest).subs({x.diff(t): 0, y.diff(t): 0, theta.diff(t): w}) for i in (0, 1))
    return [-ex, ey]  # the book writes the x equation as -(d/dt dL/dxd - dL/dx)


L1 = sp.sqrt(x**2 + (s - y) ** 2)
L2 = sp.sqrt(x**2 + y**2)
PROBLEM = Problem(
    id="p5.21",
    title="Particle on springs in a plane rotating with a shaft: L and the steady-motion equations",
    chapter=5,
    source="Wells, Problem 5.21",
    system=system,
    answers=[
        KineticEnergy(m / 2 * ((R + x) ** 2 * theta.diff(t) ** 2 + x.diff(t) ** 2 + y.diff(t) ** 2)),
        PotentialEnergy(m * g * y + k1 * (L1 - l1p) ** 2 / 2 + k2 * (L2 - l2p) ** 2 / 2),
        Quantity("steady motion at thd = omega", _steady, [
            m * (R + x) * w**2 - (k1 + k2) * x + k1 * x * l1p / L1 + k2 * x * l2p / L2,
            m * g + (k1 + k2) * y - k1 * s + k1 * (s - y) * l1p / L1 - k2 * y * l2p / L2,
        ]),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, R: 0.5, s: 2, k1: 30, k2: 30, l1p: 0.8, l2p: 0.8},
                          initial={x: 0.2, y: 1.0, theta: 0, x.diff(t): 0, y.diff(t): 0, theta.diff(t): 2},
                          t_end=5),
    correction="x0, y0 of the book's steady-motion equations are written x, y; l1', l2' are l1p, l2p. "
    "The shaft's rotation is left free (theta a coordinate); steady motion sets thd = omega.",
)
