"""Wells, Problem 10.7 — frame A on a torsion wire (κ1, turning θ1 about the vertical) carrying a disk D whose
axis is tilted at angle α from the horizontal plane, the disk turning θ2 against a torsion spring κ2 (Fig. 10-9)."""

import sympy as sp

from lagrange import RigidBody, System, coordinates, linearize, parameters, rot_x, rot_z, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

th1, th2 = coordinates("theta1 theta2")
I1, M, s, Ix, Iz, alpha, k1, k2 = parameters("I1 M s I_x I_z alpha kappa1 kappa2")

# Disk: symmetric axis = body z, centre at distance s from the vertical axis of the frame, axis tilted so that
# its vertical component is sin α; the frame's own moment about the wire axis is I1.
disk = RigidBody(M, (Ix, Ix, Iz), origin=(s * sp.cos(th1), s * sp.sin(th1), 0),
                 orientation=rot_z(th1) * rot_x(sp.pi / 2 - alpha) * rot_z(th2), name="disk D")
system = System(
    [th1, th2],
    T=sp.Rational(1, 2) * I1 * th1.diff(t) ** 2,
    bodies=[disk],
    V=sp.Rational(1, 2) * (k1 * th1**2 + k2 * th2**2),
    name="frame on a torsion wire with a tilted disk",
)
th1d, th2d = th1.diff(t), th2.diff(t)
A11 = I1 + M * s**2 + Ix * sp.cos(alpha) ** 2 + Iz * sp.sin(alpha) ** 2
DEN = I1 + M * s**2 + Ix * sp.cos(alpha) ** 2
ROOT = sp.sqrt((A11 * k2 + Iz * k1) ** 2 - 4 * k1 * k2 * DEN * Iz)


def _omega2(sy):
    """Roots ω² of the library's |a ω² − c| (a quadratic in ω²), larger first."""
    x = sp.Symbol("x")
    lin = linearize(sy)
    A, B, C = sp.Poly(sp.expand((lin.a * x - lin.c).det()), x).all_coeffs()
    disc = sp.sqrt(B**2 - 4 * A * C)
    return [(-B + disc) / (2 * A), (-B - disc) / (2 * A)]  # A = det a > 0


PROBLEM = Problem(
    id="p10.7",
    title="Frame on torsion wires with a tilted disk: T, V and ω² of the two modes",
    chapter=10,
    source="Wells, Problem 10.7 (Fig. 10-9)",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (A11 * th1d**2 + Iz * th2d**2 + 2 * Iz * sp.sin(alpha) * th1d * th2d)),
        PotentialEnergy(sp.Rational(1, 2) * (k1 * th1**2 + k2 * th2**2)),
        Quantity("ω²", _omega2,
                 [(A11 * k2 + Iz * k1 + ROOT) / (2 * DEN * Iz), (A11 * k2 + Iz * k1 - ROOT) / (2 * DEN * Iz)],
                 description="ω² = [a11 κ2 + I_z κ1 ± √(...)]/[2(I1 + M s² + I_x cos²α) I_z]"),
    ],
    simulation=Simulation(params={I1: 2.0, M: 1.0, s: 0.5, Ix: 0.3, Iz: 0.5, alpha: 0.6, k1: 3.0, k2: 1.0},
                          initial={th1: 0.2, th2: 0.0, th1d: 0.0, th2d: 0.0}, t_end=10.0),
    ranges={"alpha": (0.1, 1.4)},
    correction="Fig. 10-9 is not in the text: the disk geometry (axis at α to the horizontal, centre at s from the "
               "wire axis) is reconstructed so that the rigid-body T reproduces the book's T exactly.",
)
