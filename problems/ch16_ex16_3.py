"""Wells, Example 16.3 — two-body gravitational problem: c.m. coordinates and relative spherical coordinates."""

import sympy as sp

from lagrange import System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

X, Y, Z, r, th, ph = coordinates("x y z r theta phi")
m1, m2, G = parameters("m_1 m_2 G")
mu = m1 * m2 / (m1 + m2)
Xd, Yd, Zd, rd, thd, phd = (c.diff(t) for c in (X, Y, Z, r, th, ph))
rs, ths = sp.Symbol("r", real=True), sp.Symbol("theta", real=True)
px, py, pz, pr, pth, pph = (sp.Symbol(n, real=True) for n in ("p_x", "p_y", "p_z", "p_r", "p_theta", "p_phi"))

# x, y, z: centre of mass; r, theta, phi: position of m2 relative to m1 (book's L with reduced mass mu).
T = (m1 + m2) * (Xd**2 + Yd**2 + Zd**2) / 2 + mu * (rd**2 + r**2 * thd**2 + r**2 * phd**2 * sp.sin(th) ** 2) / 2
system = System([X, Y, Z, r, th, ph], T=T, V=-G * m1 * m2 / r, name="two-body gravitational problem")

_H = {}


def _ham(sys):
    """hamiltonian(sys), computed once per system (the 6x6 transform takes about a second)."""
    if id(sys) not in _H:
        _H[id(sys)] = hamiltonian(sys)
    return _H[id(sys)]


H_book = ((px**2 + py**2 + pz**2) / (2 * (m1 + m2))
          + (pr**2 + pth**2 / rs**2 + pph**2 / (rs**2 * sp.sin(ths) ** 2)) / (2 * mu) - G * m1 * m2 / rs)

PROBLEM = Problem(
    id="ex16.3",
    title="Two-body gravitational problem: H in c.m. and relative spherical coordinates",
    chapter=16,
    source="Wells, Example 16.3",
    system=system,
    answers=[
        Quantity("H", lambda s: _ham(s).H, H_book),
        # the 12 first-order equations: qdot = dH/dp, pdot = -dH/dq of the book's H
        Quantity("qdot = dH/dp", lambda s: _ham(s).qdot,
                 [sp.diff(H_book, p) for p in (px, py, pz, pr, pth, pph)]),
        Quantity("pdot = -dH/dq", lambda s: _ham(s).pdot,
                 [0, 0, 0, -sp.diff(H_book, rs), -sp.diff(H_book, ths), 0]),
    ],
    simulation=Simulation(params={m1: 1, m2: 0.5, G: 1},
                          initial={X: 0, Y: 0, Z: 0, r: 1, th: 1.2, ph: 0, Xd: 0.1, Yd: 0, Zd: 0, rd: 0,
                                   thd: 0.2, phd: 1.0}, t_end=5),
)
