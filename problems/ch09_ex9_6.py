"""Wells, Example 9.6 — the rolling disk of Ex. 8.11 (ball joint at O, rolling on an incline) by Euler's method.

Euler's equations about the fixed point O along the body axes, (7)-(9) (φ the spin, tied to ψ1 by rolling;
ψ = ψ1 + 180°, so ψ̇1 = ψ̇):
I_x (r1/r3)(ψ̈1 sφ − ψ̇1² (r3/r2) cφ) − (I_z − I_x)(r1³/(r2 r3²)) ψ̇1² cφ = τ_x,
I_x (r1/r3)(ψ̈1 cφ + ψ̇1² (r3/r2) sφ) + (I_z − I_x)(r1³/(r2 r3²)) ψ̇1² sφ = τ_y,
−I_z (r1²/(r2 r3)) ψ̈1 = τ_z;
and (10), (r1/r3)(I_x + I_z r1²/r2²) ψ̈1 = −M g l sε sψ1, the same as Ex. 8.11.

The system is Ex. 8.11's (``ch08_ex8_11``); the left sides of (7)-(9) are compared with the library's Euler
equations J ω̇ + ω × J ω of the disk.
"""

import sympy as sp
from lagrange_problems import ch08_ex8_11 as ex8_11
from lagrange_problems._common import variant

from lagrange import t
from lagrange.corpus import Quantity
from lagrange.derive.euler import euler_equations

psi, disk = ex8_11.psi, ex8_11.disk
Ix, Iz, r1, r2, r3 = ex8_11.Ix, ex8_11.Iz, ex8_11.r1, ex8_11.r2, ex8_11.r3
phi = ex8_11.phi_
d1, d2 = psi.diff(t), psi.diff(t, 2)
sphi, cphi = sp.sin(phi), sp.cos(phi)

B_book = [
    Ix * r1 / r3 * (d2 * sphi - d1**2 * r3 / r2 * cphi) - (Iz - Ix) * r1**3 / (r2 * r3**2) * d1**2 * cphi,
    Ix * r1 / r3 * (d2 * cphi + d1**2 * r3 / r2 * sphi) + (Iz - Ix) * r1**3 / (r2 * r3**2) * d1**2 * sphi,
    -Iz * r1**2 / (r2 * r3) * d2,
]

base = ex8_11.PROBLEM
PROBLEM = variant(
    base,
    id="ex9.6",
    title="Rolling disk of Ex. 8.11 by Euler's method: torques (7)-(9) and the equation of motion (10)",
    chapter=9,
    source="Wells, Example 9.6, eqs. (7)-(10)",
    answers=[Quantity("Euler's equations J ω̇ + ω × J ω about O, body axes (7)-(9)",
                      lambda _s: list(euler_equations(disk)), B_book),
             base.answers[3]],  # (10): the equation of motion of Ex. 8.11
    correction="(10) is compared in Ex. 8.11's angle ψ: with the catalog's ψ = ψ1 + 180° the sine in (10) would "
    "change sign, yet the book prints (10) 'the same as Ex. 8.11', so the two examples measure ψ from opposite ends "
    "of the down-slope line. (7)-(9) hold whatever the reference of ψ (only ψ̇, ψ̈ and the spin φ enter). The c.m. "
    "acceleration (2) is not compared (the catalog's A_x conflicts with (9.7) in sign, OCR), nor the reactions "
    "(5)-(6), which hold the unknown f_b, f'_b.",
)
