"""Wells, Example 16.7 — bead on the parabolic wire z = a r^2 whose shaft turns with θ = θ0 + ωt + ½αt^2."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

r = coordinates("r")
m, g, a, w, al, th0 = parameters("m g a omega alpha theta_0")
rs, pr = sp.Symbol("r", real=True), sp.Symbol("p_r", real=True)
theta = th0 + w * t + al * t**2 / 2  # prescribed rotation of the wire

system = System([r], bodies=[Particle(m, (r * sp.cos(theta), r * sp.sin(theta), a * r**2))],
                V=m * g * a * r**2, name="bead on a rotating parabolic wire")

H_book = pr**2 / (2 * m * (1 + 4 * a**2 * rs**2)) - m * rs**2 * (w + al * t) ** 2 / 2 + m * g * a * rs**2

PROBLEM = Problem(
    id="ex16.7",
    title="Bead on a parabolic wire with angular acceleration: H = T1 - T3 + V, not the energy",
    chapter=16,
    source="Wells, Example 16.7",
    system=system,
    answers=[
        KineticEnergy(m * ((1 + 4 * a**2 * r**2) * r.diff(t) ** 2 + r**2 * (w + al * t) ** 2) / 2),
        PotentialEnergy(m * g * a * r**2),
        Quantity("p_r", lambda s: hamiltonian(s).momenta[0], m * (1 + 4 * a**2 * r**2) * r.diff(t)),
        Quantity("H", lambda s: hamiltonian(s).H, H_book),
        # (16.11) with no non-conservative forces: dH/dt = dH/dt|explicit of the book's H (H is not conserved)
        Quantity("dH/dt (16.11)", lambda s: hamiltonian(s).energy_rate(), sp.diff(H_book, t)),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, a: 0.5, w: 2.0, al: 0.2},
                          initial={r: 0.5, r.diff(t): 0}, t_end=3),
    correction="The book prints V = 'mgrar^2' (OCR); V = m g a r^2 for z = a r^2. H = T1 - T3 + V differs from "
    "the energy T + V by m r^2 (omega + alpha t)^2.",
)
