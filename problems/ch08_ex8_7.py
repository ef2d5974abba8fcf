"""Wells, Example 8.7 — slender rod (mass M, length L) pivoted at O on a horizontal arm of radius R
turning by θ1; the rod swings by θ2 from the vertical in the vertical plane containing the arm.

Axes: Z1 vertical pointing DOWN (so the hanging rod is along +Z1 at θ2 = 0), θ1 about Z1. Body axes (Ex 9.4): Y
along the rod, X = −(arm's horizontal normal), Z = X × Y; then ω_x = −θ̇2, ω_y = θ̇1 cθ2, ω_z = θ̇1 sθ2.
About O: I_x = I_z = ML²/3, I_y = 0; ȳ = L/2. Gravity: V = −M g ȳ cθ2 (Ex 9.4).
"""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.rotations import rot_z

th1, th2 = coordinates("theta1 theta2")
M, L, R, g = parameters("M L R g")
t1d, t2d = th1.diff(t), th2.diff(t)
s2, c2 = sp.sin(th2), sp.cos(th2)

Ix = Iz = M * L**2 / 3
yb = L / 2
arm = rot_z(th1)
R_rod = arm * sp.Matrix([[0, s2, -c2], [-1, 0, 0], [0, c2, s2]])  # columns: body X, Y (rod), Z in arm axes
rod = RigidBody(M, (Ix, 0, Iz), origin=arm * sp.Matrix([R, 0, 0]), orientation=R_rod, com=(0, yb, 0), name="rod")
system = System([th1, th2], bodies=[rod], V=-M * g * rod.centre_of_mass[2], name="rod on a rotating arm")

l_ = sp.symbols("l", positive=True)
T_integral = sp.Rational(1, 2) * sp.integrate(((R + l_ * s2) ** 2 * t1d**2 + l_**2 * t2d**2) * M / L, (l_, 0, L))

PROBLEMS = [
    Problem(
        id="ex8.7",
        title="Slender rod pivoted on a rotating horizontal arm: T by (8.10) and by integration",
        chapter=8,
        source="Wells, Example 8.7",
        system=system,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * M * R**2 * t1d**2 + sp.Rational(1, 2) * Iz * t1d**2 * s2**2
                          + M * yb * R * t1d**2 * s2 + sp.Rational(1, 2) * Ix * t2d**2),
            KineticEnergy(T_integral, description="T = 1/2 int[(R + l s(theta2))^2 theta1'^2 + l^2 theta2'^2] rho dl"),
        ],
        simulation=Simulation(params={M: 1.0, L: 1.0, R: 0.5, g: 9.81},
                              initial={th1: 0.0, th2: 0.3, t1d: 2.0, t2d: 0.0}, t_end=5.0),
        correction="The figure's axes are rebuilt: Z1 down so that V = -M g ybar c(theta2) as in Ex 9.4; the gravity is "
        "added for the simulation (the book gives T only).",
    ),
]
