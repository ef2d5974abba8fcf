"""Wells, Example 12.2 — string tensions tau_1, tau_2 of the double pendulum, string lengths r_1, r_2 freed
as superfluous coordinates."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Quantity, Simulation

th, ph, r1, r2 = coordinates("theta phi r_1 r_2")
m1, m2, l1, l2, g = parameters("m_1 m_2 l_1 l_2 g")

# theta, phi: absolute angles of the strings from the downward vertical; Y up.
p1 = (r1 * sp.sin(th), -r1 * sp.cos(th))
p2 = (p1[0] + r2 * sp.sin(ph), p1[1] - r2 * sp.cos(ph))
system = System(
    [th, ph, r1, r2],
    bodies=[Particle(m1, p1, name="m1"), Particle(m2, p2, name="m2")],
    V=m1 * g * p1[1] + m2 * g * p2[1],
    constraints=[Holonomic(r1 - l1, name="string1"), Holonomic(r2 - l2, name="string2")],
    name="double pendulum with free string lengths",
)

PARAMS = {m1: 1.0, m2: 0.7, l1: 1.0, l2: 0.8, g: 9.81}
INIT = {th: 0.6, ph: -0.3, r1: 1.0, r2: 0.8, th.diff(t): 0.5, ph.diff(t): 1.2, r1.diff(t): 0.0, r2.diff(t): 0.0}

# Book: m2 r2 phidd sin(phi - theta) + m2 r2 phid^2 cos(phi - theta) + (m1 + m2) r1 thd^2
#        = tau_1 - (m1 + m2) g cos(theta)
tau1 = (m2 * r2 * ph.diff(t, 2) * sp.sin(ph - th) + m2 * r2 * ph.diff(t) ** 2 * sp.cos(ph - th)
        + (m1 + m2) * r1 * th.diff(t) ** 2 + (m1 + m2) * g * sp.cos(th))
tau2 = m2 * (r2 * ph.diff(t) ** 2 + g * sp.cos(ph) + r1 * th.diff(t) ** 2 * sp.cos(ph - th)
             - r1 * th.diff(t, 2) * sp.sin(ph - th))

PROBLEM = Problem(
    id="ex12.2",
    title="Double pendulum: string tensions tau_1, tau_2 with the string lengths as superfluous coordinates",
    chapter=12,
    source="Wells, Example 12.2",
    system=system,
    answers=[
        # Book's T (only r_1 freed): the engine's T with r_2 held at its constrained value (r_2-dot = 0)
        Quantity(
            "T with r_2 fixed",
            lambda s: s.T.subs(r2.diff(t), 0),
            sp.Rational(1, 2) * m1 * (r1.diff(t) ** 2 + r1**2 * th.diff(t) ** 2)
            + sp.Rational(1, 2) * m2 * (r1.diff(t) ** 2 + r1**2 * th.diff(t) ** 2 + r2**2 * ph.diff(t) ** 2
                                        + 2 * r1 * r2 * th.diff(t) * ph.diff(t) * sp.cos(ph - th)
                                        - 2 * r2 * r1.diff(t) * ph.diff(t) * sp.sin(ph - th)),
            description="kinetic energy with r_1 free (book)",
        ),
        # The strings pull the bobs toward the pivot / toward m1: distorting r_k by +delta r_k the tension does
        # work -tau_k delta r_k, so the engine's multiplier (generalized force on r_k) is lambda_k = -tau_k.
        ConstraintForce("string1", -tau1, PARAMS, INIT, 2.0, description="tau_1 (lambda_1 = -tau_1)"),
        ConstraintForce("string2", -tau2, PARAMS, INIT, 2.0, description="tau_2 (lambda_2 = -tau_2)"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=10),
    correction=("OCR prints phid in place of phidd in the first term of the tau_1 equation (m2 r2 phidd sin(phi - "
                "theta)); corrected (dimensions: every term is a force). tau_2 is not printed in the book's "
                "worked text; the form used is derived in the catalog for part (b). The book's T frees r_1 only; "
                "it is compared with the engine's T at r_2-dot = 0."),
)
