"""Wells, Example 5.3 — springs and pulleys (Fig. 5-6): V in spring lengths, eliminated by the constraints."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, Problem, Simulation

y1, y2 = coordinates("y1 y2")
th1, th2 = coordinates("theta1 theta2")
m1, m2, g, k1, k2, l1, l2, I1, I2, R1, R2, C1, C2, C3 = parameters("m1 m2 g k1 k2 l1 l2 I1 I2 R1 R2 C1 C2 C3")

# T as the book writes it (pulley inertias through y1d, y2d); V in the spring lengths s1, s2, then the
# constraints s1 + y2 = C1 and (y2 - s2) + (y2 - y1) = C2 remove the superfluous s1, s2.
T_y = ((I2 / R2**2 + m1) * y1.diff(t) ** 2 / 2 + (I1 / R1**2 + I2 / R2**2 + m2) * y2.diff(t) ** 2 / 2
       - (I2 / R2**2) * y1.diff(t) * y2.diff(t))
s1, s2 = sp.symbols("s1 s2")
V_lengths = m1 * g * y1 + m2 * g * y2 + k1 * (s1 - l1) ** 2 / 2 + k2 * (s2 - l2) ** 2 / 2
V_y = V_lengths.subs({s1: C1 - y2, s2: 2 * y2 - y1 - C2})
sys_y = System([y1, y2], T=T_y, V=V_y, name="springs and pulleys (y1, y2)")

# The same system in the pulley angles: y2 = C3 - R1 θ1, y1 = C3 - R1 θ1 - R2 θ2 (map inferred in the catalog).
to_angles = {y1: C3 - R1 * th1 - R2 * th2, y2: C3 - R1 * th1}
sys_th = System([th1, th2], T=T_y.subs(to_angles).doit(), V=V_y.subs(to_angles), name="springs and pulleys (angles)")

L_book = (((m1 + m2) * R1**2 + I1) * th1.diff(t) ** 2 / 2 + (m1 * R2**2 + I2) * th2.diff(t) ** 2 / 2
          + m1 * R1 * R2 * th1.diff(t) * th2.diff(t)
          - m1 * g * (C3 - R1 * th1 - R2 * th2) - m2 * g * (C3 - R1 * th1)
          - k1 * ((C1 - C3 + R1 * th1) - l1) ** 2 / 2 - k2 * ((C3 - C2 - R1 * th1 + R2 * th2) - l2) ** 2 / 2)
T_part = sum(term for term in sp.Add.make_args(sp.expand(L_book)) if term.has(th1.diff(t)) or term.has(th2.diff(t)))
V_part = T_part - L_book

params = {m1: 1, m2: 1.5, g: 9.81, k1: 30, k2: 20, l1: 1, l2: 1, I1: 0.2, I2: 0.1, R1: 0.3, R2: 0.2,
          C1: 5, C2: 1, C3: 4}

PROBLEMS = [
    Problem(
        id="ex5.3",
        title="Springs and pulleys in (y1, y2): V from spring lengths and constraints",
        chapter=5,
        source="Wells, Example 5.3, Fig. 5-6",
        system=sys_y,
        answers=[
            PotentialEnergy(m1 * g * y1 + m2 * g * y2 + k1 * (C1 - y2 - l1) ** 2 / 2
                            + k2 * (2 * y2 - y1 - C2 - l2) ** 2 / 2),
            EquationsOfMotion(
                [
                    sp.Eq((m1 + I2 / R2**2) * y1.diff(t, 2) - (I2 / R2**2) * y2.diff(t, 2) + m1 * g
                          - k2 * (2 * y2 - y1 - C2 - l2), 0),
                    sp.Eq((m2 + I1 / R1**2 + I2 / R2**2) * y2.diff(t, 2) - (I2 / R2**2) * y1.diff(t, 2) + m2 * g
                          - k1 * (C1 - y2 - l1) + 2 * k2 * (2 * y2 - y1 - C2 - l2), 0),
                ],
                per_equation=True,
            ),
        ],
        simulation=Simulation(params={p: v for p, v in params.items() if p != C3}, initial={y1: 1.0, y2: 2.0, y1.diff(t): 0, y2.diff(t): 0}, t_end=5),
        correction="The book gives T and V only; the equations of motion are DERIVED in the catalog from the book's L.",
    ),
    Problem(
        id="ex5.3-angles",
        title="Springs and pulleys in the pulley angles (theta1, theta2): the book's L",
        chapter=5,
        source="Wells, Example 5.3 (extension in theta1, theta2)",
        system=sys_th,
        answers=[KineticEnergy(T_part), PotentialEnergy(V_part)],
        simulation=Simulation(params=params, initial={th1: 0.5, th2: 0.3, th1.diff(t): 0, th2.diff(t): 0}, t_end=5),
        correction="The map y2 = C3 - R1 theta1, y1 = C3 - R1 theta1 - R2 theta2 is inferred (catalog); with it the "
        "book's L in angles and its L in (y1, y2) agree.",
    ),
]
