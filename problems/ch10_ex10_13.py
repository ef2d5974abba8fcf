"""Wells, Example 10.13 — the two-mass, two-spring system of Example 10.3 (vertical) with viscous drag and
harmonic forces, written in normal coordinates g1, g2 (viscous coupling)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Simulation

g1, g2 = coordinates("g1 g2")
b1, b2, A1, A2, al1, al2, d1, d2, g = parameters("b1 b2 A1 A2 alpha1 alpha2 delta1 delta2 g")

# Example 10.3's numbers are not in the catalog; its mode columns (3, 5) and (−6.25, 5) fix m2/m1 = 3/4 and
# k1/k2 = 6/5 — the Sec. 1.9 (Fig. 1-4) values m1 = 400 g, m2 = 300 g, k1 = 6e4, k2 = 5e4 dyn/cm are used.
m1, m2, k1, k2 = sp.Integer(400), sp.Integer(300), sp.Integer(60000), sp.Integer(50000)
c1 = 1 / sp.sqrt(m1 * 3**2 + m2 * 5**2)                      # (10.21) with d = (3, 5)
c2 = 1 / sp.sqrt(m1 * sp.Rational(25, 4) ** 2 + m2 * 5**2)   # (10.21) with d = (−6.25, 5)
w1sq, w2sq = sp.Rational(200, 3), sp.Integer(375)            # roots of |a ω² − c| for these numbers

y1 = 3 * c1 * g1 - sp.Rational(25, 4) * c2 * g2
y2 = 5 * c1 * g1 + 5 * c2 * g2
s1, s2 = (m1 + m2) * g / k1, m2 * g / k2  # static stretches: gravity and preload drop out (Example 10.3)
f1 = A1 * sp.sin(al1 * t + d1)
f2 = A2 * sp.sin(al2 * t + d2)
system = System(
    [g1, g2],
    bodies=[Particle(m1, (y1,), name="m1"), Particle(m2, (y2,), name="m2")],
    V=sp.Rational(1, 2) * k1 * (y1 + s1) ** 2 + sp.Rational(1, 2) * k2 * (y2 - y1 + s2) ** 2 - m1 * g * y1 - m2 * g * y2,
    P=-sp.Rational(1, 2) * (b1 * y1.diff(t) ** 2 + b2 * y2.diff(t) ** 2),
    forces=f1 * delta(y1) + f2 * delta(y2),
    name="two masses on springs in normal coordinates, drag and harmonic forces",
)
g1d, g2d = g1.diff(t), g2.diff(t)
VC = c1 * c2 * (25 * b2 - sp.Rational(75, 4) * b1)  # viscous coupling coefficient

PROBLEM = Problem(
    id="ex10.13",
    title="Example 10.3 with drag and harmonic forces in normal coordinates: viscous coupling",
    chapter=10,
    source="Wells, Example 10.13 (eqs. 10.36-10.39)",
    system=system,
    answers=[
        # δW = c1(3f1 + 5f2) δg1 + c2(5f2 − 6.25 f1) δg2
        GeneralizedForces({g1: c1 * (3 * f1 + 5 * f2), g2: c2 * (5 * f2 - sp.Rational(25, 4) * f1)}, which="applied"),
        EquationsOfMotion(
            [
                sp.Eq(g1.diff(t, 2) + w1sq * g1 + c1**2 * (9 * b1 + 25 * b2) * g1d + VC * g2d, c1 * (3 * f1 + 5 * f2)),
                sp.Eq(g2.diff(t, 2) + w2sq * g2 + c2**2 * (sp.Rational(25, 4) ** 2 * b1 + 25 * b2) * g2d + VC * g1d,
                      c2 * (5 * f2 - sp.Rational(25, 4) * f1)),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={b1: 50.0, b2: 30.0, A1: 1e4, A2: 5e3, al1: 12.0, al2: 9.0, d1: 0.0, d2: 0.3,
                                  g: 980.0},
                          initial={g1: 0.0, g2: 0.0, g1d: 0.0, g2d: 0.0}, t_end=3.0),
    units="CGS",
    correction="OCR drops c2 in y1 = 3c1 g1 − 6.25 c2 g2 (restored). The book writes the g2 equation only as "
               "'analogous'; its form here is the catalog's derivation. The mass and spring values of Example 10.3 "
               "are not in the catalog: the printed mode columns force m2/m1 = 3/4, k1/k2 = 6/5, and the Sec. 1.9 "
               "numbers (400 g, 300 g, 6e4, 5e4) with these ratios are used; c_s, ω_s² follow from (10.21), (10.10). "
               "Sign: the book's (10.39) prints −Σ p ġ; with its own P < 0 and F = ∂P/∂ġ it is +, as Ex. 10.13 (6) has.",
)
