"""Wells, Problem 15.5 — Ex. 15.4 with coil 1 replaced by a permanent magnet giving a uniform field; Phi is the
flux through coil 2 (N2 turns) at theta = 90 deg.

The magnet's flux linkage enters L as the term N2 Phi Q2' sin(theta), linear in the current (like A Q1' Q2' sin
theta of Ex. 15.4 with A Q1' frozen): it is given to the engine as part of T (L = T - V).
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation

Q2, th = coordinates("Q2 theta")
M22, I, N2, Phi, k, E0, w, R2 = parameters("M_22 I N_2 Phi k E_0 omega R_2")
half = sp.Rational(1, 2)
d2, thd = Q2.diff(t), th.diff(t)

system = System(
    [Q2, th],
    T=half * M22 * d2**2 + half * I * thd**2 + N2 * Phi * d2 * sp.sin(th),
    V=-Q2 * E0 * sp.sin(w * t) + half * k * th**2,
    P=-half * R2 * d2**2,
    name="moving coil in a permanent magnet's uniform field",
)

PROBLEM = Problem(
    id="p15.5",
    title="Coil on a torsion shaft in a permanent magnet's uniform field (Ex. 15.4 with coil 1 replaced)",
    chapter=15,
    source="Wells, Problem 15.5",
    system=system,
    answers=[
        EquationsOfMotion(
            [
                sp.Eq(M22 * Q2.diff(t, 2) + N2 * Phi * thd * sp.cos(th) - E0 * sp.sin(w * t), -R2 * d2),
                sp.Eq(I * th.diff(t, 2) - N2 * Phi * d2 * sp.cos(th) + k * th, 0),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={M22: 1.0, I: 1.0, N2: 1.0, Phi: 0.5, k: 2.0, E0: 0.5, w: 3.0, R2: 0.5},
        initial={Q2: 0.0, th: 0.2, d2: 0.0, thd: 0.0},
        t_end=20,
    ),
    correction="Wells states only the equations; L (with the magnet term N2 Phi Q2' sin theta) is the one implied "
               "by Ex. 15.4 (catalog).",
)
