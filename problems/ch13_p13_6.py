"""Wells, Problem 13.6 — flat board (mass M, inertia Ī about its c.m.) sliding on the D2 plane of Fig. 2-21:
the c.m. forces are those of a particle of mass M, and the torque is Ī θ̈3 when θ̇1, θ̇2 are constant."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity

th1, th2, r, al, th3 = coordinates("theta1 theta2 r alpha theta3")
M, Ib, s, r0, w1, w2, w3, c3, w4 = parameters("M I_b s r_0 omega_1 omega_2 omega_3 c_3 omega_4")
ang = th1 + th2 + al
# c.m. of the board at polar (r, α) on D2; θ3 = the board's rotation relative to D2
system = System([th1, th2, r, al, th3],
                T=Ib * (th1.diff(t) + th2.diff(t) + th3.diff(t)) ** 2 / 2,
                bodies=[Particle(M, (s * sp.cos(th1) + r * sp.cos(ang), s * sp.sin(th1) + r * sp.sin(ang)))],
                name="board sliding on a disk carried by a turning disk")

d1, d2, rd, ad = th1.diff(t), th2.diff(t), r.diff(t), al.diff(t)
T1 = M / 2 * (rd**2 + r**2 * ad**2 + 2 * s * d1 * sp.sin(th2 + al) * rd
              + (2 * r**2 * (d1 + d2) + 2 * s * d1 * r * sp.cos(th2 + al)) * ad
              + r**2 * (d1 + d2) ** 2 + 2 * s * r * d1 * (d1 + d2) * sp.cos(th2 + al) + s**2 * d1**2)
th3_motion = c3 * sp.sin(w4 * t)


def _forces(sys_):
    """Wells (13.1): the prescribed motion substituted into the derived equations (lhs − rhs = F'_q)."""
    motion = {th1: w1 * t, th2: w2 * t, r: r0 + 0 * t, al: w3 * t, th3: th3_motion}
    sub = {c.diff(t, 2): v.diff(t, 2) for c, v in motion.items()}
    sub.update({c.diff(t): v.diff(t) for c, v in motion.items()})
    eqs = dict(zip(sys_.coordinates, sys_.equations()))
    return [(eqs[c].lhs - eqs[c].rhs).subs(sub).subs(motion) for c in (r, al, th3)]


PROBLEM = Problem(
    id="p13.6",
    title="Board on the D2 plane: c.m. forces as for a particle M, torque Ī θ̈3",
    chapter=13,
    source="Wells, Problem 13.6 (system of Example 13.5, Fig. 2-21)",
    system=system,
    answers=[
        KineticEnergy(T1 + Ib * (d1 + d2 + th3.diff(t)) ** 2 / 2),
        Quantity("f_r, F_α (Problem 13.5 with m → M) and the torque on θ3", _forces, [
            -M * r0 * (w1 + w2 + w3) ** 2 - M * s * w1**2 * sp.cos((w2 + w3) * t),
            M * s * r0 * w1**2 * sp.sin((w2 + w3) * t),
            Ib * th3_motion.diff(t, 2)]),
    ],
    correction="The particle forces are those of Problem 13.5 (book's f_α = m s r ω1² sin(ω2+ω3)t read as the "
               "generalized force F_α = r f_α); θ3 is prescribed as c3 sin(ω4 t) to test the torque Ī θ̈3. No simulation: the disks are massless, so the mass matrix "
               "is singular (θ1, θ2 are driven).",
)
