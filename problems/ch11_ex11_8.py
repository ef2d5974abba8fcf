"""Wells, Example 11.8 — bead on a circular hoop forced to rotate at constant ω about a vertical diameter."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Quantity, Simulation

theta = coordinates("theta")
m, r, g, w = parameters("m r g omega")
th0 = sp.Symbol("theta0", real=True)

# θ measured from the horizontal; the hoop's plane turns at ω about the vertical Z.
system = System(
    [theta],
    bodies=[Particle(m, (r * sp.cos(theta) * sp.cos(w * t), r * sp.cos(theta) * sp.sin(w * t), r * sp.sin(theta)))],
    V=m * g * r * sp.sin(theta),
    name="bead on a rotating hoop",
)


def _steady_sin(s):
    """Relative equilibrium (steady motion) from the equation at rest; the root with cosθ0 ≠ 0."""
    f = s.derived.forcing[0].subs(s.derived.qd[0], 0)
    roots = sp.solve(sp.expand_trig(f).subs(sp.cos(s.derived.q[0]), sp.Symbol("C")).subs(
        sp.sin(s.derived.q[0]), sp.Symbol("S")) / sp.Symbol("C"), sp.Symbol("S"))
    return roots[0]


def _omega2(s):
    lin = linearize(s, about={theta: th0})
    return (lin.c[0, 0] / lin.a[0, 0]).subs(sp.sin(th0), -g / (r * w**2)).subs(
        sp.cos(th0) ** 2, 1 - g**2 / (r**2 * w**4))


PROBLEM = Problem(
    id="ex11.8",
    title="Bead on a hoop rotating at constant ω: steady position sinθ0 = −g/(rω²), oscillation about it",
    chapter=11,
    source="Wells, Example 11.8",
    system=system,
    answers=[
        KineticEnergy(m * (r**2 * theta.diff(t) ** 2 + r**2 * sp.cos(theta) ** 2 * w**2) / 2),
        EquationsOfMotion([sp.Eq(theta.diff(t, 2) + w**2 * sp.sin(theta) * sp.cos(theta) + g / r * sp.cos(theta), 0)],
                          per_equation=True),
        Quantity("steady sinθ0", _steady_sin, -g / (r * w**2)),
        Quantity("ω² of α about the steady position", _omega2, w**2 - g**2 / (r**2 * w**2)),
    ],
    simulation=Simulation(params={m: 1, r: 0.5, g: 9.81, w: 8.0},
                          initial={theta: -0.2, theta.diff(t): 0.1}, t_end=3),
    correction="The book prints the linearized coefficient as ω² − g²/r²; expanding about sinθ0 = −g/(rω²) gives "
               "ω² − g²/(r²ω²) (catalog; dimensionally consistent, and it agrees with the book's stability "
               "condition ω² > g/r).",
)
