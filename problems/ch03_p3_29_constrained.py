"""Wells, Problem 3.29 with superfluous coordinates — bead on a rod at fixed angle θ0 to a vertical shaft
turning with constant angular acceleration c (φ̇ = c t).

Multiplier form (Wells' own remark at the end of Sec. 3.2: keep all three coordinates, the constraint forces
then appear in the equations): spherical (r, θ, φ) of the bead, θ from the upward vertical, gravity −m g δz,
with ``θ − θ0 = 0`` and the moving constraint ``φ − c t²/2 = 0``. Each Jacobian row is a unit row, so the
multipliers are Wells' generalized reactions 𝓕_θ = r N_θ and 𝓕_φ = r sin θ N_φ (moments of the rod's
normal force components along e_θ, e_φ; engine convention: λ A_kr added to the applied forces).
Book: a_θ = −r c² t² sin θ cos θ, a_φ = 2 ṙ c t sin θ + r c sin θ; with gravity's e_θ component +m g sin θ
the reactions are N_θ = m a_θ − m g sin θ, N_φ = m a_φ (catalog, derived from the book's a's).
Eliminating θ and φ gives m a_r = −m g cos θ0 with the book's a_r = r̈ − r c² t² sin² θ.
"""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, delta, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, Problem, Simulation

r, th, ph = coordinates("r theta phi")
m, g, c, th0 = parameters("m g c theta_0")

bead = Particle(m, (r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th)), name="bead")
system = System(
    [r, th, ph],
    bodies=[bead],
    forces=-m * g * delta(r * sp.cos(th)),
    constraints=[Holonomic(th - th0, name="rod angle"), Holonomic(ph - c * t**2 / 2, name="shaft")],
    name="bead on a rod on an accelerating shaft (superfluous theta, phi)",
)
reduced = eliminate(system, {th: th0, ph: c * t**2 / 2})

a_theta = -r * c**2 * t**2 * sp.sin(th0) * sp.cos(th0)
a_phi = 2 * r.diff(t) * c * t * sp.sin(th0) + r * c * sp.sin(th0)
a_r = r.diff(t, 2) - r * c**2 * t**2 * sp.sin(th0) ** 2

PARAMS = {m: 1.0, g: 9.81, c: 0.8, th0: 1.2}
INITIAL = {r: 1.0, th: 1.2, ph: 0.0, r.diff(t): 0.0, th.diff(t): 0.0, ph.diff(t): 0.0}

PROBLEMS = [
    Problem(
        id="p3.29-multipliers",
        title="Bead on a rod of an accelerating shaft in (r, theta, phi), theta and phi constrained: reactions",
        chapter=3,
        source="Wells, Problem 3.29 (and end of Sec. 3.2)",
        system=system,
        answers=[
            ConstraintForce("rod angle", r * (m * a_theta - m * g * sp.sin(th0)), PARAMS, INITIAL, t_end=1.5),
            ConstraintForce("shaft", r * sp.sin(th0) * m * a_phi, PARAMS, INITIAL, t_end=1.5),
        ],
        simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=1.5),
        correction="The book gives a_r, a_θ, a_φ; the reactions N_θ = m a_θ − m g sin θ, N_φ = m a_φ are the "
        "catalog's derivation (θ from the upward vertical, gravity −z).",
    ),
    Problem(
        id="p3.29-multipliers-reduced",
        title="Bead on a rod of an accelerating shaft: theta, phi eliminated gives m a_r = -m g cos(theta_0)",
        chapter=3,
        source="Wells, Problem 3.29",
        system=reduced,
        answers=[EquationsOfMotion([sp.Eq(m * a_r, -m * g * sp.cos(th0))], per_equation=True)],
        simulation=Simulation(params=PARAMS, initial={r: 1.0, r.diff(t): 0.0}, t_end=1.5),
        correction="The equation of motion m a_r = F_r is derived from the book's a_r (the book lists a_r only).",
    ),
]
