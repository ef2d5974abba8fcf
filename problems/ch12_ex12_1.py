"""Wells, Example 12.1 — bead on a smooth helical wire r = a, z = b phi (Z vertical) with gravity and an
applied force F = (F_x, F_y, F_z): reactions of the wire by superfluous cylindrical coordinates."""

import sympy as sp

from lagrange import Force, Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, Problem, Simulation

r, phi, z = coordinates("r phi z")
m, g, a, b, Fx, Fy, Fz = parameters("m g a b F_x F_y F_z")

pos = (r * sp.cos(phi), r * sp.sin(phi), z)
F_r = Fx * sp.cos(phi) + Fy * sp.sin(phi)
F_phi = -Fx * sp.sin(phi) + Fy * sp.cos(phi)


def helix(constraints, coords, name):
    return System(coords, bodies=[Particle(m, pos, name="bead")], V=m * g * z,
                  forces=[Force(at=pos, vector=(Fx, Fy, Fz))], constraints=constraints, name=name)


# (b)/(c): r and z both superfluous. The wire is r = a (constraint "radius") and z = b phi ("helix").
full = helix([Holonomic(r - a, name="radius"), Holonomic(z - b * phi, name="helix")], [r, phi, z],
             "bead on a helix (r, phi, z)")
# (d): z eliminated (z = b phi), r kept superfluous.
one = eliminate(full, {z: b * phi})
# both eliminated: the ordinary one-coordinate system
reduced = eliminate(one, {r: a})

PARAMS = {m: 1.0, g: 9.81, a: 0.6, b: 0.25, Fx: 0.8, Fy: -0.5, Fz: 2.0}
INIT = {r: 0.6, phi: 0.3, z: 0.075, r.diff(t): 0.0, phi.diff(t): 2.0, z.diff(t): 0.5}
INIT_D = {r: 0.6, phi: 0.3, r.diff(t): 0.0, phi.diff(t): 2.0}
NOTE = ("Engine sign: (A^T lambda)_q, the multiplier term added to the applied forces, is Wells' generalized "
        "force of constraint on q. With r, phi, z free the generalized forces of the reaction are f_r, r f_phi, "
        "f_z (book's cylindrical components (c)). The book writes r for the wire radius; here it is the "
        "parameter a (r = a on the wire).")

PROBLEMS = [
    Problem(
        id="ex12.1",
        title="Bead on a smooth helix r = a, z = b phi with gravity and applied F: f_r, f_phi, f_z (two superfluous)",
        chapter=12,
        source="Wells, Example 12.1 (b)-(c) (Fig. 12-2)",
        system=full,
        answers=[
            # (c): f_r = m rdd - m r phid^2 - F_r           (= (A^T lambda)_r = lambda_radius)
            ConstraintForce("radius", m * r.diff(t, 2) - m * r * phi.diff(t) ** 2 - F_r, PARAMS, INIT, 2.0,
                            coordinate=r, description="f_r = m rdd - m r phid^2 - F_r"),
            # (c): r f_phi = m r^2 phidd + 2 m r rd phid - r F_phi   (generalized force on phi; only "helix" acts)
            ConstraintForce("helix", m * r**2 * phi.diff(t, 2) + 2 * m * r * r.diff(t) * phi.diff(t) - r * F_phi,
                            PARAMS, INIT, 2.0, coordinate=phi, description="r f_phi"),
            # (c): f_z = m zdd - F_z + m g                   (= (A^T lambda)_z = lambda_helix)
            ConstraintForce("helix", m * z.diff(t, 2) - Fz + m * g, PARAMS, INIT, 2.0, coordinate=z,
                            description="f_z = m zdd - F_z + m g"),
            # (b), r constant: f_x cos(phi) + f_y sin(phi) = -m r phid^2 - F_x cos(phi) - F_y sin(phi)
            ConstraintForce("radius", -m * r * phi.diff(t) ** 2 - Fx * sp.cos(phi) - Fy * sp.sin(phi),
                            PARAMS, INIT, 2.0, coordinate=r, description="(b) f_x cos(phi) + f_y sin(phi)"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT, t_end=5),
        correction=NOTE,
    ),
    Problem(
        id="ex12.1-d",
        title="Bead on a smooth helix with z eliminated, r superfluous: -m r phid^2 = F_r + f_r",
        chapter=12,
        source="Wells, Example 12.1 (d)",
        system=one,
        answers=[
            ConstraintForce("radius", -m * r * phi.diff(t) ** 2 - F_r, PARAMS, INIT_D, 2.0, coordinate=r,
                            description="f_r = -m r phid^2 - F_r"),
            # (d) second equation: the reaction's share (F_z + f_z - m g) b + (F_phi + f_phi) r has
            # f_z b + f_phi r = 0 (the smooth wire does no work along itself), so phi gets no constraint force
            ConstraintForce("radius", sp.S.Zero, PARAMS, INIT_D, 2.0, coordinate=phi,
                            description="f_z b + r f_phi = 0 (no constraint force on phi)"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT_D, t_end=5),
        correction=NOTE,
    ),
    Problem(
        id="ex12.1-reduced",
        title="Bead on a smooth helix: m(a^2 + b^2) phidd = (F_z - m g) b + F_phi a",
        chapter=12,
        source="Wells, Example 12.1 (d)",
        system=reduced,
        answers=[
            EquationsOfMotion([sp.Eq(m * (a**2 + b**2) * phi.diff(t, 2), (Fz - m * g) * b + F_phi * a)],
                              per_equation=True),
        ],
        simulation=Simulation(params=PARAMS, initial={phi: 0.3, phi.diff(t): 2.0}, t_end=5),
        correction=("Book (d): m(r^2 + b^2) phidd = (F_z + f_z - m g) b + (F_phi + f_phi) r; with the smooth wire "
                    "f_z b + f_phi r = 0 (no work along the wire, checked in ex12.1-d), leaving this equation; "
                    "r = a is the wire radius."),
    ),
]
