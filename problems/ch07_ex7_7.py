"""Wells, Sec. 7.8 / Example 7.7 — foci and spherical points of inertia of a block."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import foci, spherical_points
from lagrange.model.standard_bodies import block

M, a, b, c = parameters("M a b c")
box = block(M, a, b, c)
Ibar_y, Ibar_z = M * (a**2 + c**2) / 3, M * (a**2 + b**2) / 3  # Ex. 7.4
cube_like = block(M, a, b, b)  # b = c > a
s_sph = spherical_points(M, cube_like, "x")
at_sph = cube_like.from_centre(M, (s_sph, 0, 0))

PROBLEMS = [
    Problem(
        id="ex7.7-foci",
        title="Block with a > b > c: foci of inertia on the Z̄ axis",
        chapter=7,
        source="Wells, Sec. 7.8 and Example 7.7",
        system=None,
        answers=[Quantity("focus distance s on Z̄", lambda _: foci(M, box, "z")["y"], sp.sqrt((Ibar_z - Ibar_y) / M))],
        ranges={"a": (3.0, 4.0), "b": (2.0, 2.9), "c": (1.0, 1.9)},
    ),
    Problem(
        id="ex7.7-spherical",
        title="Block with b = c > a: spherical points on the X̄ axis",
        chapter=7,
        source="Wells, Sec. 7.8 and Example 7.7",
        system=None,
        answers=[
            Quantity("spherical-point distance s on X̄", lambda _: s_sph, sp.sqrt((b**2 - a**2) / 3)),
            Quantity("moments there (all equal)", lambda _: [at_sph.I_x, at_sph.I_y, at_sph.I_z],
                     [2 * M * b**2 / 3] * 3),
        ],
        ranges={"a": (1.0, 1.9), "b": (2.0, 3.0)},
    ),
]
