"""Wells, Example 3.5 with the rod as a moving constraint — bead on a smooth rod rotating at constant ω.

Multiplier form in inertial (x, y): the rod is ``Holonomic(y cos ωt − x sin ωt)`` (t explicit: a moving
constraint). Its Jacobian row A = (−sin ωt, cos ωt) is the unit vector e⊥ across the rod in the sense of
rotation, so λ is the rod's normal force N on the bead along e⊥ (engine convention: λ·A_kr is added to the
applied forces). Wells' eq. (6) (δt variation, corrected OCR): 2 m r ṙ ω² δt = (F_y cos ωt − F_x sin ωt) r ω δt
+ N r ω δt, i.e. N = 2 m ω ṙ − (F_y cos ωt − F_x sin ωt), with r = x cos ωt + y sin ωt along the rod.

The "-reduced" variant keeps Wells' own superfluous coordinate: (r, s) along and across the rod,
x = r cos ωt − s sin ωt, y = r sin ωt + s cos ωt, constraint s = 0 (λ = N again); eliminating s gives (5).
"""

import sympy as sp

from lagrange import Force, Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, GeneralizedForces, Problem, Simulation

x, y, r, s = coordinates("x y r s")
m, w, Fx, Fy = parameters("m omega F_x F_y")
c, sn = sp.cos(w * t), sp.sin(w * t)

bead = Particle(m, (x, y), name="bead")
system = System(
    [x, y],
    bodies=[bead],
    forces=[Force(bead, (Fx, Fy))],
    constraints=[Holonomic(y * c - x * sn, name="rod")],
    name="bead on a rotating rod (inertial x, y; moving constraint)",
)

bead_rs = Particle(m, (r * c - s * sn, r * sn + s * c), name="bead")
system_rs = System(
    [r, s],
    bodies=[bead_rs],
    forces=[Force(bead_rs, (Fx, Fy))],
    constraints=[Holonomic(s, name="rod")],
    name="bead on a rotating rod (r along, s across the rod)",
)
reduced = eliminate(system_rs, {s: 0})

PARAMS = {m: 1.0, w: 1.0, Fx: 0.3, Fy: -0.2}
INITIAL = {x: 0.5, y: 0.0, x.diff(t): 0.2, y.diff(t): 0.5}  # on the rod at t = 0, ẏ = r ω
rdot_xy = x.diff(t) * c + y.diff(t) * sn  # ṙ in inertial components
transverse_applied = Fy * c - Fx * sn

PROBLEMS = [
    Problem(
        id="ex3.5-multipliers",
        title="Bead on a rotating rod in inertial (x, y), rod as a moving constraint: N = 2 m w r' (+ applied part)",
        chapter=3,
        source="Wells, Example 3.5, eq. (6)",
        system=system,
        answers=[
            GeneralizedForces({x: Fx, y: Fy}, which="applied"),
            # λ = N along e⊥ = (−sin ωt, cos ωt): Wells' (6) solved for N
            ConstraintForce("rod", 2 * m * w * rdot_xy - transverse_applied, PARAMS, INITIAL, t_end=2),
            # generalized reaction on x: −N sin ωt
            ConstraintForce("rod", -(2 * m * w * rdot_xy - transverse_applied) * sn, PARAMS, INITIAL, t_end=2,
                            coordinate=x),
        ],
        simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=2),
        correction="Eq. (6) is printed '(2mrω̇²)'; read 2 m r ṙ ω² (catalog), so N = 2 m ω ṙ − (F_y cos ωt − F_x sin ωt); "
        "the book's N = 2 m ω ṙ is the case without a transverse applied force.",
    ),
    Problem(
        id="ex3.5-multipliers-rs",
        title="Bead on a rotating rod in (r, s) with the constraint s = 0: N = 2 m w r' (+ applied part)",
        chapter=3,
        source="Wells, Example 3.5, eq. (6)",
        system=system_rs,
        answers=[
            GeneralizedForces({r: Fx * c + Fy * sn, s: Fy * c - Fx * sn}, which="applied"),
            # A = (0, 1): λ = 𝓕_s = N, the rod's push across the rod in +s
            ConstraintForce("rod", 2 * m * w * r.diff(t) - transverse_applied, PARAMS,
                            {r: 0.5, s: 0.0, r.diff(t): 0.2, s.diff(t): 0.0}, t_end=2),
        ],
        simulation=Simulation(params=PARAMS, initial={r: 0.5, s: 0.0, r.diff(t): 0.2, s.diff(t): 0.0}, t_end=2),
        correction="Eq. (6) is printed '(2mrω̇²)'; read 2 m r ṙ ω² (catalog).",
    ),
    Problem(
        id="ex3.5-multipliers-reduced",
        title="Bead on a rotating rod: s eliminated from the (r, s) multiplier form gives m(r'' - r w^2) = F_r",
        chapter=3,
        source="Wells, Example 3.5, eq. (5)",
        system=reduced,
        answers=[
            GeneralizedForces({r: Fx * c + Fy * sn}),
            EquationsOfMotion([sp.Eq(m * (r.diff(t, 2) - r * w**2), Fx * c + Fy * sn)], per_equation=True),
        ],
        simulation=Simulation(params=PARAMS, initial={r: 0.5, r.diff(t): 0.2}, t_end=2),
    ),
]
