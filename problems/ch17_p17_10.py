"""Wells, Problem 17.10 — spherical spring pendulum with viscous drag, by Hamilton's principle (17.8)."""

import sympy as sp

from lagrange import Particle, System, coordinates, euler_lagrange, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

r, th, ph = coordinates("r theta phi")
m, g, k, r0, b = parameters("m g k r_0 b")
rd, thd, phd = r.diff(t), th.diff(t), ph.diff(t)
S, C = sp.sin(th), sp.cos(th)

# theta from the downward vertical; the book's P = 1/2 b(v^2) is in the Rayleigh sign (force -dP/dqdot)
system = System(
    [r, th, ph],
    bodies=[Particle(m, (r * S * sp.cos(ph), r * S * sp.sin(ph), -r * C))],
    V=-m * g * r * C + k * (r - r0) ** 2 / 2,
    rayleigh=b * (rd**2 + r**2 * thd**2 + r**2 * S**2 * phd**2) / 2,
    name="spherical spring pendulum with drag",
)

book = [
    m * r.diff(t, 2) - m * r * thd**2 - m * r * S**2 * phd**2 + k * (r - r0) - m * g * C + b * rd,
    m * r**2 * th.diff(t, 2) + 2 * m * r * rd * thd - m * r**2 * S * C * phd**2 + b * r**2 * thd + m * g * r * S,
    m * r**2 * S**2 * ph.diff(t, 2) + 2 * m * r * rd * phd * S**2 + 2 * m * r**2 * thd * phd * S * C
    + b * r**2 * S**2 * phd,
]


def _hamilton_17_8(s):
    """(17.8): dL/dq - d/dt dL/dqdot + F_q = 0, F_q = -dP/dqdot; returned with Wells' sign."""
    Q = s.generalized_forces()
    return [-(e.lhs + Q[q]) for e, q in zip(euler_lagrange(s.T - s.V, s.coordinates, t), s.coordinates)]


PROBLEM = Problem(
    id="p17.10",
    title="Spherical spring pendulum with viscous drag via (17.8)",
    chapter=17,
    source="Wells, Problem 17.10",
    system=system,
    answers=[
        Quantity("equations from (17.8)", _hamilton_17_8, book),
        EquationsOfMotion([sp.Eq(e, 0) for e in book], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 40, r0: 1, b: 0.2},
                          initial={r: 1.2, th: 0.5, ph: 0, rd: 0, thd: 0, phd: 1.5}, t_end=5),
    correction="OCR fixes (catalog, verified): the r equation has -m g cos(theta) (printed 'mgr cos theta', "
    "dimensionally wrong) and the theta equation 2 m r rdot thetadot (printed '2mrr thetaddot'). The book's "
    "P = +1/2 b(...) is used in the Rayleigh sign (force -dP/dqdot), as its own equations (+b rdot) require.",
)
