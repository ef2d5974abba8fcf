"""Wells, Example 5.5 — masses in line on transverse springs, unstretched at equilibrium: quartic V for small y."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

y1, y2, y3 = coordinates("y1 y2 y3")
m1, m2, m3, k1, k2, k3, k4, s1, s2, s3, s4 = parameters("m1 m2 m3 k1 k2 k3 k4 s1 s2 s3 s4")

# Spring i joins points s_i apart along the line; its transverse ends are displaced by Δy: length sqrt(s² + Δy²).
ys = [0, y1, y2, y3, 0]
ks, ss = [k1, k2, k3, k4], [s1, s2, s3, s4]
V_exact = sum(kk * (sp.sqrt(s**2 + (ys[i + 1] - ys[i]) ** 2) - s) ** 2 / 2 for i, (kk, s) in enumerate(zip(ks, ss, strict=True)))
system = System([y1, y2, y3], bodies=[Particle(m1, (0, y1)), Particle(m2, (0, y2)), Particle(m3, (0, y3))],
                V=V_exact, name="masses on transverse springs")

V_book = (k1 * y1**4 / (8 * s1**2) + k2 * (y1 - y2) ** 4 / (8 * s2**2) + k3 * (y2 - y3) ** 4 / (8 * s3**2)
          + k4 * y3**4 / (8 * s4**2))


def _quartic(s):
    """Leading (fourth-order) Taylor term of the system's exact V in the displacements."""
    eps = sp.Symbol("eps")
    out = 0
    for term in sp.Add.make_args(s.V):  # term by term keeps the series fast
        scaled = term.subs({q: eps * q for q in s.coordinates}, simultaneous=True)
        d = scaled
        for n in range(5):  # Taylor coefficients up to eps^4 (orders 0-3 vanish)
            out += d.subs(eps, 0) / sp.factorial(n)
            d = d.diff(eps)
    return out


PROBLEM = Problem(
    id="ex5.5",
    title="Transverse springs unstretched at equilibrium: V = sum k_i (y_i - y_{i-1})^4 / (8 s_i^2)",
    chapter=5,
    source="Wells, Example 5.5",
    system=system,
    answers=[
        Quantity("quartic approximation of V", _quartic, V_book),
        Quantity("F_y1 from the approximate V", lambda s: -sp.diff(_quartic(s), y1),
                 -(k1 / (2 * s1**2)) * y1**3 - (k2 / (2 * s2**2)) * (y1 - y2) ** 3),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, m3: 1, k1: 10, k2: 10, k3: 10, k4: 10, s1: 1, s2: 1, s3: 1, s4: 1},
                          initial={y1: 0.1, y2: 0, y3: -0.05, y1.diff(t): 0, y2.diff(t): 0, y3.diff(t): 0}, t_end=10),
    correction="OCR: the intermediate step prints '- 2 s1 sqrt(1 + y1^2/s1^2)'; it should read 2 s1^2 sqrt(...) "
    "(dimensions). The final V and F_y1 are as printed.",
)
