"""Wells, Problem 4.13 — free electric motor sliding on a smooth plane: frame, armature and an arm on the shaft."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import ConservedMomenta, GeneralizedForces, KineticEnergy, Problem, Simulation

x, y, theta1, theta2 = coordinates("x y theta1 theta2")
M1, M2, M3, I1, I2, I3, r, tau = parameters("M1 M2 M3 I1 I2 I3 r tau")

# Frame (M1, I1, angle θ1) and armature (M2, I2, angle θ2) centred at (x, y); the arm (M3, I3 about its CM)
# turns with the armature, its CM at distance r from the shaft. The motor torque is an internal pair.
system = System(
    [x, y, theta1, theta2],
    T=sp.Rational(1, 2) * I1 * theta1.diff(t) ** 2 + sp.Rational(1, 2) * (I2 + I3) * theta2.diff(t) ** 2,
    bodies=[Particle(M1 + M2, (x, y), name="frame + armature"),
            Particle(M3, (x + r * sp.cos(theta2), y + r * sp.sin(theta2)), name="arm CM")],
    forces=tau * delta(theta2) - tau * delta(theta1),
    name="free electric motor",
)

xd, yd = x.diff(t), y.diff(t)
PROBLEM = Problem(
    id="p4.13",
    title="Free motor on a smooth plane: T, internal torque pair, conserved linear momenta",
    chapter=4,
    source="Wells, Problem 4.13",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (M1 + M2 + M3) * (xd**2 + yd**2) + sp.Rational(1, 2) * I1 * theta1.diff(t) ** 2
                      + sp.Rational(1, 2) * (I2 + I3 + M3 * r**2) * theta2.diff(t) ** 2
                      + M3 * r * theta2.diff(t) * (yd * sp.cos(theta2) - xd * sp.sin(theta2))),
        GeneralizedForces({x: 0, y: 0, theta1: -tau, theta2: tau}),
        # Derived: x and y are ignorable (the plane is smooth), so both momenta are conserved.
        ConservedMomenta({x: (M1 + M2 + M3) * xd - M3 * r * theta2.diff(t) * sp.sin(theta2),
                          y: (M1 + M2 + M3) * yd + M3 * r * theta2.diff(t) * sp.cos(theta2)}),
    ],
    simulation=Simulation(params={M1: 5, M2: 2, M3: 0.5, I1: 1, I2: 0.2, I3: 0.05, r: 0.3, tau: 0.5},
                          initial={x: 0, y: 0, theta1: 0, theta2: 0, xd: 0, yd: 0, theta1.diff(t): 0,
                                   theta2.diff(t): 0}, t_end=3),
    correction="The conserved momenta p_x, p_y are not printed; they follow from the book's T with F_x = F_y = 0.",
)
