"""Wells, Problem 2.16 — two particles on a light rigid rod of length l moving in a plane."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

m1, m2, l = parameters("m1 m2 l")
half = sp.Rational(1, 2)

# (a) m1 at polar (r, θ); φ is the rod angle. The constraint (x2−x1)² + (y2−y1)² = l² is built in.
r, theta, phi = coordinates("r theta phi")
P1 = (r * sp.cos(theta), r * sp.sin(theta))
P2 = (P1[0] + l * sp.cos(phi), P1[1] + l * sp.sin(phi))
polar = System([r, theta, phi], bodies=[Particle(m1, P1), Particle(m2, P2)], name="dumbbell, (r, θ, φ)")

# (b) centre of mass (x, y) and rod angle φ (the CM theorem, 2.47).
x, y, psi = coordinates("x y psi")
Mt = m1 + m2
e = (sp.cos(psi), sp.sin(psi))
cm = System(
    [x, y, psi],
    bodies=[Particle(m1, (x - m2 / Mt * l * e[0], y - m2 / Mt * l * e[1])),
            Particle(m2, (x + m1 / Mt * l * e[0], y + m1 / Mt * l * e[1]))],
    name="dumbbell, centre of mass",
)


def _dist2(s):
    a, b = (bd.position_vectors()[0] for bd in s.bodies)
    return sp.trigsimp(sum((a[i] - b[i]) ** 2 for i in range(2)))


def _dof(s):
    # degrees of freedom = rank of the mass matrix at a generic point (exact rationals, 30-digit evaluation)
    pt = {q: sp.Rational(3 + i, 7 + 2 * i) for i, q in enumerate(s.coordinates)}
    pt.update({p: sp.Rational(11 + i, 9) for i, p in enumerate(s.parameters)})
    M = s.mass_matrix.subs(pt).evalf(30)
    return M.rank(iszerofunc=lambda v: abs(v) < 1e-20)


rd, thd, phd = r.diff(t), theta.diff(t), phi.diff(t)
I_rod = m1 * m2 / Mt * l**2
NOTE = ("The key prints '(ẋ²+ẏ²)' for the first bracket and '2lrφ̇ sin' in the last term (OCR/typo); the "
        "corrected form ½(m1+m2)(ṙ²+r²θ̇²) + ½m2[l²φ̇² − 2lṙφ̇ sin(φ−θ) + 2lrθ̇φ̇ cos(φ−θ)] is re-derived in "
        "the catalog (sym ✓).")
PROBLEMS = [
    Problem(
        id="p2.16",
        title="Two particles on a light rod in a plane: 3 DOF, T in (r, θ, φ)",
        chapter=2,
        source="Wells, Problem 2.16 (answer key)",
        system=polar,
        answers=[
            KineticEnergy(half * Mt * (rd**2 + r**2 * thd**2) + half * m2 * (
                l**2 * phd**2 - 2 * l * rd * phd * sp.sin(phi - theta) + 2 * l * r * thd * phd * sp.cos(phi - theta))),
            Quantity("rod length squared", _dist2, l**2),
            Quantity("degrees of freedom (rank of the mass matrix)", _dof, 3),
        ],
        simulation=Simulation(params={m1: 1, m2: 2, l: 1},
                              initial={r: 1.0, theta: 0.2, phi: 1.0, rd: 0.1, thd: 0.3, phd: -0.5}, t_end=2.0),
        correction=NOTE,
    ),
    Problem(
        id="p2.16-cm",
        title="Two particles on a light rod: T = ½(m1+m2)(ẋ²+ẏ²) + ½Iφ̇², I = m1 m2 l²/(m1+m2)",
        chapter=2,
        source="Wells, Problem 2.16 (answer key, CM form)",
        system=cm,
        answers=[KineticEnergy(half * Mt * (x.diff(t) ** 2 + y.diff(t) ** 2) + half * I_rod * psi.diff(t) ** 2)],
        simulation=Simulation(params={m1: 1, m2: 2, l: 1},
                              initial={x: 0, y: 0, psi: 0, x.diff(t): 1, y.diff(t): 0, psi.diff(t): 2}, t_end=2.0),
        correction="The rod angle is called psi here (phi in the book) to keep the two variants' coordinates apart.",
    ),
]
