"""Wells, Problem 13.17 — particle m under a central force f_r(r) in a plane (Fig. 13-12): P_θ = m r² θ̇ is
constant, and the force law that produces a given orbit."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, Problem, Quantity, Simulation

r, theta = coordinates("r theta")
m, P, A, eps, C, a = parameters("m P_theta A epsilon C a")
F = sp.Symbol("f_r", real=True)
system = System([r, theta], bodies=[Particle(m, (r * sp.cos(theta), r * sp.sin(theta)))], forces={r: F},
                name="particle under a central force")
th = sp.Symbol("th", real=True)


def _force_for_orbit(rho):
    """f_r on the orbit r = rho(th): θ̇ from the conserved momentum P_θ, ṙ and r̈ by the chain rule, then the
    engine's r equation solved for f_r."""

    def compute(s):
        p = s.ignorable_coordinates()[theta]
        w = sp.solve(sp.Eq(p, P), theta.diff(t))[0].subs(r, rho)  # θ̇ on the orbit
        rd = sp.diff(rho, th) * w
        rdd = sp.diff(rd, th) * w
        eq = s.equations()[0]
        e = (eq.lhs - eq.rhs).subs({r.diff(t, 2): rdd}).subs({r.diff(t): rd, theta.diff(t): w}).subs(
            {r: rho, theta: th})
        return sp.solve(e, F)[0]

    return compute


orbits = {
    "b": A / (1 - eps * sp.cos(th)),
    "c": sp.sqrt(C / (sp.sin(th) * sp.cos(th))),
    "d": a * (1 + sp.cos(th)),
    "e": 2 * a * sp.cos(th),
}
PROBLEM = Problem(
    id="p13.17",
    title="Central force: P_θ = m r²θ̇ constant; f_r for a conic, xy = C, a cardioid and a circle through O",
    chapter=13,
    source="Wells, Problem 13.17 (Fig. 13-12)",
    system=system,
    answers=[
        ConservedMomenta({theta: m * r**2 * theta.diff(t)}),
        Quantity("(b) r = A/(1 − ε cosθ): f_r = −P²/(mAr²)", _force_for_orbit(orbits["b"]),
                 (-P**2 / (m * A * r**2)).subs(r, orbits["b"])),
        Quantity("(c) xy = C: f_r = P² r/(4mC²)", _force_for_orbit(orbits["c"]),
                 (P**2 * r / (4 * m * C**2)).subs(r, orbits["c"])),
        Quantity("(d) r = a(1 + cosθ): f_r = −3P² a/(m r⁴)", _force_for_orbit(orbits["d"]),
                 (-3 * P**2 * a / (m * r**4)).subs(r, orbits["d"])),
        Quantity("(e) r = 2a cosθ: f_r = −8a²P²/(m r⁵)", _force_for_orbit(orbits["e"]),
                 (-8 * a**2 * P**2 / (m * r**5)).subs(r, orbits["e"])),
    ],
    simulation=Simulation(params={m: 1, F: 0}, initial={r: 1.0, theta: 0, r.diff(t): 0.2, theta.diff(t): 1.0},
                          t_end=3),
    correction="(e) The text prints f_r = −3a²P_θ²/(m r⁵); the circle r = 2a cosθ needs −8a²P_θ²/(m r⁵) "
               "(u'' + u = 8a²u³ from u = 1/(2a cosθ); likely OCR of 8 as 3, catalog verified). The book's answer "
               "(a), the orbit equation u'' + u = −m f_r/(P_θ² u²), is what the computation uses implicitly. "
               "Each book f_r is compared on its orbit (r replaced by the orbit r(θ)). The simulation has f_r = 0.",
    ranges={"epsilon": (0.1, 0.9), "th": (0.15, 0.85)},
)
