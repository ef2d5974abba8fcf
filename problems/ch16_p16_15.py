"""Wells, Problem 16.15 — particle in the earth frame (T of 14.14) with a potential V(x, y, z): H, xdot, pdot_x."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x y z")
m, w, R, Phi, k, g = parameters("m omega_e R Phi k g")
s, c = sp.sin(Phi), sp.cos(Phi)
xs, ys, zs = (sp.Symbol(n, real=True) for n in "xyz")
px, py, pz = (sp.Symbol(f"p_{n}", real=True) for n in "xyz")


def V_of(X, Y, Z):
    """A sample V(x, y, z) (the book leaves V general): harmonic trap plus uniform field."""
    return k * (X**2 + Y**2) / 2 + m * g * Z + k * X * Z / 3


E = EarthFrame(Phi, w, R)
system = System([x, y, z], bodies=[Particle(m, E.point((x, y, z)))], V=V_of(x, y, z),
                name="particle in the earth frame with a potential")

_H = {}


def _ham(sys):
    """hamiltonian(sys), computed once per system."""
    if id(sys) not in _H:
        _H[id(sys)] = hamiltonian(sys)
    return _H[id(sys)]


Vb = V_of(xs, ys, zs)
H_book = ((px + m * w * (ys * s - zs * c) - m * w * R * c) ** 2 + (py - m * w * xs * s) ** 2
          + (pz + m * w * xs * c) ** 2) / (2 * m) \
    - m * w**2 * (xs**2 + ys**2 * s**2 + (R + zs) ** 2 * c**2 - 2 * ys * (R + zs) * s * c) / 2 + Vb

PROBLEM = Problem(
    id="p16.15",
    title="Particle relative to the rotating earth: H, xdot and pdot_x",
    chapter=16,
    source="Wells, Problem 16.15 (T of eq. 14.14)",
    system=system,
    answers=[
        Quantity("H", lambda s_: _ham(s_).H, H_book),
        Quantity("xdot", lambda s_: _ham(s_).qdot[0], (px + m * w * (ys * s - zs * c) - m * w * R * c) / m),
        Quantity("pdot_x", lambda s_: _ham(s_).pdot[0], w * (py * s - pz * c) - sp.diff(Vb, xs)),
    ],
    simulation=Simulation(params={m: 1, w: 0.05, R: 10, Phi: 0.7, k: 4, g: 9.81},
                          initial={x: 0.1, y: 0, z: 0, x.diff(t): 0, y.diff(t): 0.2, z.diff(t): 0}, t_end=3),
    ranges={"omega_e": (0.1, 0.5)},
    correction="The book prints the prefactor 1/2 m (should be 1/(2m)), '-m omega_e R' (missing cos Phi), "
    "'+1/2 m omega_e^2 [...]' (must be -, since H = T1 - T3 + V) and a spurious '-2 m omega_e^2 x' in pdot_x; "
    "the corrected forms (catalog, verified) are checked. V(x, y, z) is left general in the book; a sample "
    "polynomial V is used (it enters H additively and pdot_x through -dV/dx).",
)
