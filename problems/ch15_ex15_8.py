"""Wells, Example 15.8 — the EMFs E1, E2 that hold constant charges Q01, Q03 on the network of Fig. 15-3,
with (Q1, Q3) as coordinates (the inverse problem of Sec. 15.6 in its static form).

Branch charges with the junction law Q1 = Q2 + Q3 as a constraint; the superfluous Q2 = Q1 - Q3 is eliminated
(Wells' choice of coordinates here). With Q constant every current and its derivative vanish, so Lagrange's
equations reduce to dV/dQ = 0, which fixes E1 and E2 (E3 given).
"""

import sympy as sp

from lagrange import Holonomic, System, coordinates, eliminate, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

Q1, Q2, Q3 = coordinates("Q1 Q2 Q3")
M11, M22, M33, M12, M13, M23 = parameters("M_11 M_22 M_33 M_12 M_13 M_23")
C1, C2, C3, E1, E2, E3, R1, R2, R3 = parameters("C_1 C_2 C_3 E_1 E_2 E_3 R_1 R_2 R_3")
Q01, Q03 = parameters("Q_01 Q_03")
half = sp.Rational(1, 2)
d1, d2, d3 = Q1.diff(t), Q2.diff(t), Q3.diff(t)

branches = System(
    [Q1, Q2, Q3],
    T=half * (M11 * d1**2 + M22 * d2**2 + M33 * d3**2 + 2 * M12 * d1 * d2 + 2 * M13 * d1 * d3 + 2 * M23 * d2 * d3),
    V=half * (Q1**2 / C1 + Q2**2 / C2 + Q3**2 / C3) - E1 * Q1 + E2 * Q2 + E3 * Q3,
    P=-half * (R1 * d1**2 + R2 * d2**2 + R3 * d3**2),
    constraints=[Holonomic(Q1 - Q2 - Q3, name="junction")],
    name="Fig. 15-3 in branch charges",
)
system = eliminate(branches, {Q2: Q1 - Q3})


def _holding_emfs(s):
    """Solve Lagrange's equations at Q1 = Q01, Q3 = Q03 (currents and their rates zero) for E1, E2."""
    rest = {}
    for q in s.coordinates:
        rest.update({q.diff(t, 2): 0, q.diff(t): 0})
    eqs = [e.subs(rest).subs({Q1: Q01, Q3: Q03}) for e in s.equations()]
    sol = sp.solve(eqs, [E1, E2], dict=True)[0]
    return [sol[E1], sol[E2]]


PROBLEM = Problem(
    id="ex15.8",
    title="EMFs E1, E2 that hold constant charges Q01, Q03 in the Fig. 15-3 network",
    chapter=15,
    source="Wells, Example 15.8",
    system=system,
    answers=[
        PotentialEnergy(half * (Q1**2 / C1 + (Q1 - Q3) ** 2 / C2 + Q3**2 / C3) - E1 * Q1 + E2 * (Q1 - Q3) + E3 * Q3),
        Quantity("[E1, E2]", _holding_emfs,
                 [E3 + Q01 / C1 + Q03 / C3, E3 + (Q03 - Q01) / C2 + Q03 / C3], description="holding EMFs E1, E2"),
    ],
    simulation=Simulation(
        # E1, E2 set to the holding values for Q01 = 0.5, Q03 = 0.3 (E3 = 0.2): the charges stay put
        params={M11: 1.0, M22: 1.2, M33: 0.8, M12: 0.2, M13: 0.1, M23: 0.15, C1: 1.0, C2: 0.5, C3: 2.0,
                E1: 0.2 + 0.5 + 0.15, E2: 0.2 + (0.3 - 0.5) / 0.5 + 0.15, E3: 0.2, R1: 0.1, R2: 0.2, R3: 0.05},
        initial={Q1: 0.5, Q3: 0.3, d1: 0.0, d3: 0.0},
        t_end=5,
    ),
)
