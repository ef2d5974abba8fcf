"""Wells, Example 14.12 and eq. (14.21) — satellite or long-range projectile in earth-centred spherical coordinates.

r (from the earth's centre), geocentric latitude Phi1 and longitude phi measured in the earth (which turns at
omega_e): inertial position r (cPhi1 cos(phi + omega_e t), cPhi1 sin(phi + omega_e t), sPhi1). Applied forces
left general (F_r, F_Phi1, F_phi constants).
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Simulation

r, lat, phi = coordinates("r Phi1 phi")
m, w, Fr, Fl, Fp = parameters("m omega_e F_r F_Phi1 F_phi")
rd, latd, phid = r.diff(t), lat.diff(t), phi.diff(t)
lon = phi + w * t
pos = (r * sp.cos(lat) * sp.cos(lon), r * sp.cos(lat) * sp.sin(lon), r * sp.sin(lat))
system = System([r, lat, phi], bodies=[Particle(m, pos, name="satellite")], forces={r: Fr, lat: Fl, phi: Fp},
                name="particle in earth-centred spherical coordinates")

PROBLEM = Problem(
    id="ex14.12",
    title="Satellite in earth-centred spherical coordinates: T (14.21) and the three equations of motion",
    chapter=14,
    source="Wells, Example 14.12, eq. (14.21)",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (rd**2 + r**2 * latd**2 + r**2 * (phid + w) ** 2 * sp.cos(lat) ** 2)),
        EquationsOfMotion(
            [
                sp.Eq(m * r.diff(t, 2) - m * r * latd**2 - m * r * (phid + w) ** 2 * sp.cos(lat) ** 2, Fr),
                sp.Eq(m * r**2 * lat.diff(t, 2) + 2 * m * r * rd * latd
                      + m * r**2 * (phid + w) ** 2 * sp.sin(lat) * sp.cos(lat), Fl),
                sp.Eq(sp.diff(m * r**2 * (phid + w) * sp.cos(lat) ** 2, t), Fp),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m: 1.0, w: 7.29211e-5, Fr: -0.5, Fl: 0.0, Fp: 0.0},
        initial={r: 1.0, lat: 0.3, phi: 0.0, rd: 0.0, latd: 0.2, phid: 0.5},
        t_end=5,
    ),
    ranges={"Phi1": (0.1, 1.2)},
)
