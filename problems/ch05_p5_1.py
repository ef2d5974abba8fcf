"""Wells, Problem 5.1 — which force fields are conservative, and their potential V (Q = -grad V, (5.4)-(5.8)).

The book prints no answers; the expected values are the closed forms (the catalog's derived answers) (a potential V whose -grad V is the field,
V = 0 at the origin) and, for the non-conservative fields, the failing exactness test (5.6). The library's
:func:`lagrange.is_conservative` and :func:`lagrange.potential_of` must agree. Part (f) is ambiguous in the
catalog (as physical components F_phi is off by a factor sin(theta); as generalized forces (5.8) fails) and
part (g) has arbitrary functions; both are left out.
"""

import sympy as sp

from lagrange import is_conservative, potential_of, t
from lagrange.corpus import Problem, Quantity

x, y, z = sp.symbols("x y z", real=True)
m, g, k, A, B, w = sp.symbols("m g k A B omega", positive=True)
XY, XYZ = [x, y], [x, y, z]
ORIGIN2, ORIGIN3 = {x: 0, y: 0}, {x: 0, y: 0, z: 0}

# label: (field, coordinates, V with V(0) = 0 or None when the field is not conservative)
FIELDS = {
    "(a) (0, -mg)": ([0, -m * g], XY, m * g * y),
    "(b) (-kx, -ky)": ([-k * x, -k * y], XY, k * (x**2 + y**2) / 2),
    "(c) (-ky, kx)": ([-k * y, k * x], XY, None),  # dQy/dx - dQx/dy = 2k
    "(d) (Axy, Bxy)": ([A * x * y, B * x * y], XY, None),  # dQx/dy = Ax, dQy/dx = By
    "(e) (Ayz, Axz, Axy)": ([A * y * z, A * x * z, A * x * y], XYZ, -A * x * y * z),
    # time-dependent: exact at fixed t (Wells 5.11), V(x, y, t)
    "(h) (-kx sin wt, kty)": ([-k * x * sp.sin(w * t), k * t * y], XY,
                              k * x**2 * sp.sin(w * t) / 2 - k * t * y**2 / 2),
}

answers = []
for label, (F, q, V) in FIELDS.items():
    answers.append(Quantity(f"{label}: conservative (1) or not (0)", lambda _, F=F, q=q: int(is_conservative(F, q)),
                            int(V is not None)))
    if V is not None:
        ref = ORIGIN2 if len(q) == 2 else ORIGIN3
        answers.append(Quantity(f"{label}: V (zero at the origin)",
                                lambda _, F=F, q=q, ref=ref: potential_of(F, q, reference=ref), V))

PROBLEM = Problem(
    id="p5.1",
    title="Which forces are conservative, and their V: (0, -mg), (-kx, -ky), (-ky, kx), (Axy, Bxy), (Ayz, Axz, Axy), "
    "(-kx sin wt, kty)",
    chapter=5,
    source="Wells, Problem 5.1 (a)-(e), (h)",
    system=None,
    answers=answers,
)
