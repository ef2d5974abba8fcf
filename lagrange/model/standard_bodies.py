r"""Inertia of the standard homogeneous bodies Wells uses in chapter 7 and after.

Every function returns an :class:`~lagrange.model.inertia.Inertia` about the **centre of mass**, with
the principal axes along x, y, z and z the symmetry axis when there is one — except
:func:`triangle_plate`, which is about the right-angle corner (as Wells gives it, Ex. 7.2). Wells'
sign convention for products is stated once in :mod:`lagrange.model.inertia`. Masses and lengths
must be non-negative and exact (symbols, integers or ``sp.Rational``); a DeclarationError lists
every one that is not.

Move a body elsewhere with :meth:`Inertia.from_centre` (parallel axes) and :meth:`Inertia.rotated`.
"""

from __future__ import annotations

import sympy as sp

from .inertia import Inertia, _check_nonnegative

__all__ = [
    "rod",
    "disk",
    "ring",
    "cylinder",
    "cylindrical_shell",
    "sphere",
    "spherical_shell",
    "hemisphere",
    "cone",
    "block",
    "rectangular_plate",
    "triangle_plate",
    "HEMISPHERE_CENTRE",
    "CONE_CENTRE",
]

_half, _third = sp.Rational(1, 2), sp.Rational(1, 3)

#: Distance of a solid hemisphere's c.m. from the centre of its flat face, per unit radius (3R/8).
HEMISPHERE_CENTRE = sp.Rational(3, 8)
#: Distance of a solid cone's c.m. from its base, per unit height (h/4; 3h/4 from the apex).
CONE_CENTRE = sp.Rational(1, 4)


def _axisymmetric(transverse, axial) -> Inertia:
    return Inertia(transverse, transverse, axial)


def rod(M, L) -> Inertia:
    r"""Thin rod of length L along z: :math:`\bar I_x = \bar I_y = ML^2/12`, :math:`\bar I_z = 0`.

    >>> import sympy as sp; M, L = sp.symbols("M L", positive=True)
    >>> rod(M, L).I_x
    L**2*M/12
    """
    M, L = _check_nonnegative("rod", M=M, L=L)
    return _axisymmetric(M * L**2 / 12, sp.S.Zero)


def disk(M, R) -> Inertia:
    r"""Thin disk of radius R, axis z: :math:`\bar I_z = MR^2/2`, :math:`\bar I_x = \bar I_y = MR^2/4`."""
    M, R = _check_nonnegative("disk", M=M, R=R)
    return _axisymmetric(M * R**2 / 4, M * R**2 / 2)


def ring(M, R) -> Inertia:
    r"""Thin circular hoop of radius R, axis z: :math:`\bar I_z = MR^2`, :math:`\bar I_x = \bar I_y = MR^2/2`."""
    M, R = _check_nonnegative("ring", M=M, R=R)
    return _axisymmetric(M * R**2 / 2, M * R**2)


def cylinder(M, R, L) -> Inertia:
    r"""Solid cylinder, radius R, length L, axis z: :math:`\bar I_z = MR^2/2`, :math:`\bar I_x = M(3R^2+L^2)/12`."""
    M, R, L = _check_nonnegative("cylinder", M=M, R=R, L=L)
    return _axisymmetric(M * (3 * R**2 + L**2) / 12, M * R**2 / 2)


def cylindrical_shell(M, R, L) -> Inertia:
    r"""Thin-walled tube (no end caps), radius R, length L, axis z: :math:`\bar I_z = MR^2`,
    :math:`\bar I_x = M(6R^2 + L^2)/12`."""
    M, R, L = _check_nonnegative("cylindrical_shell", M=M, R=R, L=L)
    return _axisymmetric(M * (6 * R**2 + L**2) / 12, M * R**2)


def sphere(M, R) -> Inertia:
    r"""Solid sphere: :math:`\bar I = \tfrac25 MR^2` about every axis."""
    M, R = _check_nonnegative("sphere", M=M, R=R)
    return _axisymmetric(2 * M * R**2 / 5, 2 * M * R**2 / 5)


def spherical_shell(M, R) -> Inertia:
    r"""Thin spherical shell: :math:`\bar I = \tfrac23 MR^2` about every axis."""
    M, R = _check_nonnegative("spherical_shell", M=M, R=R)
    return _axisymmetric(2 * M * R**2 / 3, 2 * M * R**2 / 3)


def hemisphere(M, R) -> Inertia:
    r"""Solid hemisphere, axis z, dome towards +z; c.m. at 3R/8 above the flat face (Prob. 7.16).

    :math:`\bar I_z = \tfrac25 MR^2`, :math:`\bar I_x = \bar I_y = \tfrac25 MR^2 - M(3R/8)^2 = \tfrac{83}{320} MR^2`.
    """
    M, R = _check_nonnegative("hemisphere", M=M, R=R)
    return _axisymmetric(sp.Rational(83, 320) * M * R**2, 2 * M * R**2 / 5)


def cone(M, r, h) -> Inertia:
    r"""Solid right circular cone, base radius r, height h, axis z from base to apex (Ex. 7.5).

    The c.m. is h/4 above the base (base plane at z = -h/4, apex at z = 3h/4).

    .. math:: \bar I_x = \bar I_y = \tfrac{3}{80} M (4r^2 + h^2), \qquad \bar I_z = \tfrac{3}{10} M r^2
    """
    M, r, h = _check_nonnegative("cone", M=M, r=r, h=h)
    return _axisymmetric(sp.Rational(3, 80) * M * (4 * r**2 + h**2), sp.Rational(3, 10) * M * r**2)


def block(M, a, b, c) -> Inertia:
    r"""Rectangular block 2a x 2b x 2c (edges along x, y, z; Ex. 7.4).

    .. math:: \bar I_x = M(b^2+c^2)/3, \quad \bar I_y = M(a^2+c^2)/3, \quad \bar I_z = M(a^2+b^2)/3

    >>> import sympy as sp; M, a, b, c = sp.symbols("M a b c", positive=True)
    >>> block(M, a, b, c).from_centre(M, (a, b, c)).I_xy
    M*a*b
    """
    M, a, b, c = _check_nonnegative("block", M=M, a=a, b=b, c=c)
    return Inertia(M * (b**2 + c**2) / 3, M * (a**2 + c**2) / 3, M * (a**2 + b**2) / 3)


def rectangular_plate(M, a, b) -> Inertia:
    r"""Thin rectangular lamina 2a x 2b in the xy plane: :math:`\bar I_x = Mb^2/3`, :math:`\bar I_y = Ma^2/3`,
    :math:`\bar I_z = M(a^2+b^2)/3`."""
    M, a, b = _check_nonnegative("rectangular_plate", M=M, a=a, b=b)
    return Inertia(M * b**2 / 3, M * a**2 / 3, M * (a**2 + b**2) / 3)


def triangle_plate(M, a, b) -> Inertia:
    r"""Thin right-triangle lamina, legs a on X and b on Y, **about the right-angle corner** (Ex. 7.2).

    .. math:: I_x = Mb^2/6, \quad I_y = Ma^2/6, \quad I_z = M(a^2+b^2)/6, \quad I_{xy} = Mab/12

    The c.m. is at (a/3, b/3, 0): ``triangle_plate(M, a, b).to_centre(M, (a/3, b/3, 0))`` gives the
    central values (:math:`\bar I_{xy} = -Mab/36`).
    """
    M, a, b = _check_nonnegative("triangle_plate", M=M, a=a, b=b)
    return Inertia(M * b**2 / 6, M * a**2 / 6, M * (a**2 + b**2) / 6, M * a * b / 12)
