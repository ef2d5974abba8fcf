"""Wells, Problem 13.13 — board rolling without slipping on a rough fixed cylinder of radius R (Fig. 13-9):
T, V and the equilibrium at θ = θ0."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

theta = coordinates("theta")
M, I, R, g, th0 = parameters("M I R g theta_0")
# contact point R(cosθ, sinθ); the c.m. lies on the board (tangent line) at arc length R(θ − θ0) from it
xc = R * sp.cos(theta) + R * (theta - th0) * sp.sin(theta)
yc = R * sp.sin(theta) - R * (theta - th0) * sp.cos(theta)
system = System([theta], T=I * theta.diff(t) ** 2 / 2, bodies=[Particle(M, (xc, yc))], V=M * g * yc,
                name="board rolling on a cylinder")
TH = sp.Symbol("theta", real=True)


def _static(s):
    """Static generalized force at θ (velocities zero): −∂V/∂θ."""
    return s.derived.forcing[0].subs({v: 0 for v in s.derived.qd})


PROBLEM = Problem(
    id="p13.13",
    title="Board rolling on a rough cylinder: ∂V/∂θ = MgR(θ − θ0) sinθ, equilibrium at θ = θ0",
    chapter=13,
    source="Wells, Problem 13.13 (Fig. 13-9)",
    system=system,
    answers=[
        KineticEnergy(M * R**2 * (theta - th0) ** 2 * theta.diff(t) ** 2 / 2 + I * theta.diff(t) ** 2 / 2),
        PotentialEnergy(M * g * R * (sp.sin(theta) - (theta - th0) * sp.cos(theta))),
        Quantity("−∂V/∂θ", _static, -M * g * R * (TH - th0) * sp.sin(TH)),
        Quantity("equilibrium at θ = θ0", lambda s: _static(s).subs(TH, th0), 0),
    ],
    simulation=Simulation(params={M: 1, I: 0.1, R: 0.5, g: 9.81, th0: 1.5},
                          initial={theta: 1.7, theta.diff(t): 0}, t_end=3),
    correction="The geometry (c.m. on the board at arc length R(θ − θ0) from the contact point) is reconstructed "
               "from the book's T and V.",
)
