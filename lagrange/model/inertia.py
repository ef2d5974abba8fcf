r"""Moments and products of inertia: Wells' chapter-7 toolkit, as exact sympy functions.

Convention (Wells 7.1–7.2), stated once for this module and :mod:`lagrange.model.standard_bodies`
--------------------------------------------------------------------------------------------------
Moments and products of inertia about the axes X, Y, Z through a point O are

.. math::

    I_x = \sum m (y^2 + z^2), \qquad I_{xy} = \sum m\,x y, \quad\text{etc.}

The products are **positive sums** (Wells 7.1) and enter the inertia tensor with a **minus sign**:

.. math::

    J = \begin{bmatrix} I_x & -I_{xy} & -I_{xz} \\ -I_{xy} & I_y & -I_{yz} \\
        -I_{xz} & -I_{yz} & I_z \end{bmatrix},
    \qquad
    I_{Oa} = I_x l^2 + I_y m^2 + I_z n^2 - 2 I_{xy} l m - 2 I_{xz} l n - 2 I_{yz} m n \quad (7.2)

for the line through O with direction cosines (l, m, n), i.e. :math:`I_{Oa} = u^T J u`.
:class:`Inertia` stores Wells' positive products; :attr:`Inertia.tensor` is the signed J.

Direction cosines of rotated axes (Wells 7.18–7.20, Table 8.2) are held in a 3x3 matrix ``R`` whose
**rows are the new axes** and whose columns are the old axes: ``R[i, j]`` is :math:`\alpha_{ij}`, the
cosine between new axis i and old axis j. Then :math:`J' = R J R^T`.

Everything is exact: numbers are integers or ``sp.Rational`` and floats are refused (they enter only at
code generation, or in :meth:`Inertia.principal_axes_numeric`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

import numpy as np
import sympy as sp

from ..errors import DeclarationError
from ..records import record
from ..safe_sympify import matrix as _matrix
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero, simplify

__all__ = [
    "Inertia",
    "point_masses",
    "centre_of_mass",
    "equimomental_particles",
    "foci",
    "spherical_points",
    "euler_zxz",
    "plane_rotation",
]

_NAMES = ("I_x", "I_y", "I_z", "I_xy", "I_xz", "I_yz")
_AXES = {"x": 0, "y": 1, "z": 2}


def _exact(value, what: str, problems: list[str]) -> sp.Expr:
    """Sympify ``value``; record a problem if it holds a float (the symbolic layer is exact)."""
    expr = _sympify(value)
    if isinstance(expr, sp.Basic) and expr.atoms(sp.Float):
        problems.append(f"{what} = {value!r} holds a float; use an integer, sp.Rational or a symbol")
    return expr


def _rational(value):
    """``value`` with every Float replaced by the rational of its decimal representation (0.1 → 1/10)."""
    expr = _sympify(value)
    if isinstance(expr, sp.Basic) and expr.atoms(sp.Float):
        expr = expr.xreplace({f: sp.nsimplify(f, rational=True) for f in expr.atoms(sp.Float)})
    return expr


def _check_nonnegative(subject: str, **quantities) -> list[sp.Expr]:
    """Sympify ``quantities`` and raise one DeclarationError listing every float or negative value."""
    problems: list[str] = []
    out = []
    for name, value in quantities.items():
        expr = _exact(value, name, problems)
        if getattr(expr, "is_negative", None):
            problems.append(f"{name} = {expr} is negative; masses and lengths must be >= 0")
        out.append(expr)
    if problems:
        raise DeclarationError(problems, subject=subject)
    return out


def _vector(values, what: str) -> sp.Matrix:
    """A 3-vector from exactly 3 components (exact), else DeclarationError."""
    comps = list(values) if isinstance(values, (Sequence, sp.MatrixBase)) and not isinstance(values, str) else None
    if comps is None or len(comps) != 3:
        raise DeclarationError(f"{what} must have 3 components (x, y, z), got {values!r}", subject=what)
    problems: list[str] = []
    vec = sp.Matrix([_exact(c, f"{what}[{i}]", problems) for i, c in enumerate(comps)])
    if problems:
        raise DeclarationError(problems, subject=what)
    return vec


def _matrix3(R, what: str) -> sp.Matrix:
    M = _matrix(R, where=what)
    if M.shape != (3, 3):
        raise DeclarationError(f"{what} must be 3x3, got shape {M.shape}", subject=what)
    return M


def _trigonometric_roots(J: sp.Matrix) -> list[sp.Expr]:
    """Eigenvalues of a real symmetric 3x3 J by the trigonometric form of the cubic (no imaginary unit)."""
    q = J.trace() / 3
    B0 = J - q * sp.eye(3)
    p = sp.sqrt((B0 * B0).trace() / 6)
    r = B0.det(method="berkowitz") / (2 * p**3)
    phi = sp.acos(r) / 3
    return [q + 2 * p * sp.cos(phi + 2 * sp.pi * k / 3) for k in range(3)]


@record(frozen=True, slots=True)
class Inertia:
    r"""Moments and (positive, Wells 7.1) products of inertia about one point and one set of axes.

    Parameters
    ----------
    I_x, I_y, I_z : sympy expressions
        Moments about X, Y, Z.
    I_xy, I_xz, I_yz : sympy expressions, default 0
        Wells' products :math:`\sum m x y` etc. They enter :attr:`tensor` with a minus sign.

    Floats are accepted and made exact: each becomes the rational of its shortest decimal representation
    (``0.1`` → ``1/10``, by ``nsimplify(..., rational=True)``), so results are exact for the number as
    typed (not for the binary double). Pass ``sp.Rational`` or symbols to state exactness yourself.

    Raises
    ------
    DeclarationError
        If a moment is known to be negative.

    References
    ----------
    Wells, *Lagrangian Dynamics*, Ch. 7, eqs. (7.1)–(7.20).

    Examples
    --------
    >>> import sympy as sp
    >>> J = Inertia(2, 3, 4, I_xy=1)
    >>> J.tensor
    Matrix([
    [ 2, -1, 0],
    [-1,  3, 0],
    [ 0,  0, 4]])
    >>> J.about_line(1, 0, 0), J.about_line(sp.sqrt(2)/2, sp.sqrt(2)/2, 0)
    (2, 3/2)
    """

    I_x: sp.Expr
    I_y: sp.Expr
    I_z: sp.Expr
    I_xy: sp.Expr = sp.S.Zero
    I_xz: sp.Expr = sp.S.Zero
    I_yz: sp.Expr = sp.S.Zero

    def __post_init__(self):
        problems: list[str] = []
        for name in _NAMES:
            value = _exact(_rational(getattr(self, name)), name, problems)
            if name in _NAMES[:3] and getattr(value, "is_negative", None):
                problems.append(f"{name} = {value} is negative; a moment of inertia is >= 0")
            object.__setattr__(self, name, value)
        if problems:
            raise DeclarationError(problems, subject="Inertia")

    # ----- conversions -------------------------------------------------------------------------
    @property
    def tensor(self) -> sp.Matrix:
        """The signed 3x3 inertia tensor J (off-diagonals are minus Wells' products)."""
        return sp.Matrix([[self.I_x, -self.I_xy, -self.I_xz],
                          [-self.I_xy, self.I_y, -self.I_yz],
                          [-self.I_xz, -self.I_yz, self.I_z]])

    @classmethod
    def from_tensor(cls, J) -> Inertia:
        """Inertia from a symmetric signed 3x3 tensor J (inverse of :attr:`tensor`).

        Raises
        ------
        DeclarationError
            If J is not 3x3 or not symmetric.

        >>> Inertia.from_tensor(Inertia(1, 2, 3, 4, 5, 6).tensor) == Inertia(1, 2, 3, 4, 5, 6)
        True
        """
        J = _matrix3(J, "inertia tensor")
        if not all(_is_zero(J[i, j] - J[j, i]) for i, j in ((0, 1), (0, 2), (1, 2))):
            raise DeclarationError("the tensor must be symmetric (J[i, j] == J[j, i])", subject="inertia tensor")
        return cls(J[0, 0], J[1, 1], J[2, 2], -J[0, 1], -J[0, 2], -J[1, 2])

    def simplified(self) -> Inertia:
        """Every component passed through (bounded) ``sp.simplify``."""
        return Inertia(*(simplify(getattr(self, n)) for n in _NAMES))

    # ----- moments about lines, the ellipsoid ----------------------------------------------------
    def about_line(self, l, m, n) -> sp.Expr:
        r"""Moment about the line through the origin with direction cosines (l, m, n) (Wells 7.2).

        .. math:: I_{Oa} = I_x l^2 + I_y m^2 + I_z n^2 - 2I_{xy} lm - 2I_{xz} ln - 2I_{yz} mn

        (l, m, n) must be a unit vector; use :meth:`about_direction` for any direction.
        """
        u = _vector((l, m, n), "direction cosines")
        return sp.expand((u.T * self.tensor * u)[0, 0])

    def about_direction(self, x, y, z) -> sp.Expr:
        r"""Moment about the line from the origin through the point (x, y, z) (Wells Prob. 7.3).

        .. math:: I_{Oa} = \frac{I_x x^2 + I_y y^2 + I_z z^2 - 2I_{xy}xy - 2I_{xz}xz - 2I_{yz}yz}{x^2+y^2+z^2}

        >>> Inertia(1, 2, 3).about_direction(0, 5, 0)
        2
        """
        u = _vector((x, y, z), "direction")
        return sp.cancel((u.T * self.tensor * u)[0, 0] / (u.T * u)[0, 0])

    def ellipsoid(self, x, y, z) -> sp.Expr:
        r"""Left side of the ellipsoid of inertia (Wells 7.5); the ellipsoid is ``ellipsoid(x, y, z) = 1``.

        .. math:: I_x x^2 + I_y y^2 + I_z z^2 - 2I_{xy}xy - 2I_{xz}xz - 2I_{yz}yz
        """
        u = _vector((x, y, z), "point")
        return sp.expand((u.T * self.tensor * u)[0, 0])

    # ----- principal moments and axes ------------------------------------------------------------
    def characteristic_polynomial(self, p: sp.Symbol) -> sp.Expr:
        r"""Wells' cubic (7.11) in ``p`` = :math:`I^p`: :math:`\det(I^p E - J)`; its roots are the principal moments."""
        return sp.expand((p * sp.eye(3) - self.tensor).det())

    def principal(self) -> list[sp.Expr]:
        r"""The three principal moments (with multiplicity), the roots of the cubic (7.11), in a real form.

        The tensor is real and symmetric, so the roots are real; they are returned without the imaginary unit
        that Cardano's formula carries (casus irreducibilis). Diagonal tensors give their diagonal; roots sympy
        finds free of ``I`` (a factorable cubic) are kept; otherwise the trigonometric form of the cubic
        (Smith 1961) is used: with :math:`q = \operatorname{tr}J/3`,
        :math:`p = \sqrt{\operatorname{tr}((J - qE)^2)/6}`, :math:`r = \det((J - qE)/p)/2`,

        .. math:: I_k = q + 2p\cos\Big(\frac{\arccos r + 2\pi k}{3}\Big),\qquad k = 0, 1, 2,

        valid wherever ``p ≠ 0`` (``p = 0`` only for a multiple of the identity). Sorted ascending when all are
        numbers.

        >>> Inertia(2, 2, 5, I_xy=1).principal()
        [1, 3, 5]
        >>> [round(float(v), 10) for v in Inertia(3, 4, 5, I_xy=1, I_yz=1, I_xz=1).principal()]
        [1.7856802566, 4.5391888728, 5.6751308706]
        """
        J = self.tensor
        off = (J[0, 1], J[0, 2], J[1, 2])
        if all(v == 0 for v in off):
            values = [J[0, 0], J[1, 1], J[2, 2]]
        else:
            lam = sp.Dummy("lam")
            _, factors = sp.factor_list(self.characteristic_polynomial(lam), lam)
            if all(sp.degree(f, lam) <= 2 for f, _ in factors):  # linear and quadratic factors: real radicals
                found = [v for f, k in factors for v in sp.roots(sp.Poly(f, lam), multiple=True) * k]
                values = [simplify(v, limit=400) for v in found]
            else:
                values = _trigonometric_roots(J)
        if all(v.is_number for v in values):
            values.sort(key=lambda v: float(v))
        return values

    def principal_axes_numeric(self, values: Mapping | None = None) -> tuple[np.ndarray, np.ndarray]:
        r"""Principal moments and axes at numbers, by ``numpy.linalg.eigh`` of the signed tensor.

        Parameters
        ----------
        values : mapping symbol -> number, optional
            Values for every free symbol of the tensor.

        Returns
        -------
        moments : ndarray, shape (3,)
            Ascending principal moments.
        axes : ndarray, shape (3, 3)
            Row i holds the direction cosines (l, m, n) of the axis of ``moments[i]`` (the rows form
            a right-handed set; the first two rows have a positive first non-zero component), so
            ``axes`` is an ``R`` for :meth:`rotated`: ``rotated(axes)`` is diagonal.

        Raises
        ------
        DeclarationError
            If symbols are left without values.

        >>> m, ax = Inertia(2, 2, 5, I_xy=1).principal_axes_numeric()
        >>> m.round(12).tolist(), ax[0].round(6).tolist()
        ([1.0, 3.0, 5.0], [0.707107, 0.707107, 0.0])
        """
        J = self.tensor.subs(dict(values or {}))
        if J.free_symbols:
            names = ", ".join(sorted(s.name for s in J.free_symbols))
            raise DeclarationError(f"give values for {names}", subject="principal_axes_numeric values")
        moments, vecs = np.linalg.eigh(np.array(J.evalf(30), dtype=float))
        axes = vecs.T.copy()
        for i in range(2):
            k = int(np.argmax(np.abs(axes[i]) > 1e-12))
            if axes[i, k] < 0:
                axes[i] = -axes[i]
        axes[2] = np.cross(axes[0], axes[1])
        return moments, axes

    # ----- changes of axes -----------------------------------------------------------------------
    def rotated(self, R) -> Inertia:
        r"""Inertia about new axes through the same point (Wells 7.18–7.20): :math:`J' = R J R^T`.

        Parameters
        ----------
        R : 3x3 matrix of direction cosines :math:`\alpha_{ij}`, row i = new axis i in the old axes.
            It must be orthogonal (checked to 1e-20 when R has no free symbols, not for symbolic R).
            The inverse change (7.20) is ``rotated(R.T)``.

        >>> import sympy as sp
        >>> th = sp.Symbol("theta")
        >>> J = Inertia(1, 2, 3).rotated(plane_rotation(th))
        >>> sp.simplify(J.I_x - (sp.cos(th)**2 + 2*sp.sin(th)**2))
        0
        """
        R = _matrix3(R, "rotation matrix R")
        if not R.free_symbols and max(abs(v) for v in (R * R.T - sp.eye(3)).evalf(30)) > 1e-20:
            raise DeclarationError("R must be orthogonal (R Rᵀ = E)", subject="rotation matrix R")
        Jr = R * self.tensor * R.T  # symmetric by construction: read the upper triangle
        return Inertia(Jr[0, 0], Jr[1, 1], Jr[2, 2], -Jr[0, 1], -Jr[0, 2], -Jr[1, 2])

    def translated(self, mass, com, to_point=(0, 0, 0)) -> Inertia:
        r"""Parallel-axis theorem: inertia about axes parallel to the present ones through ``to_point``.

        ``self`` is about the present origin O; ``com`` is the centre of mass and ``to_point`` the
        new origin, both in the present axes. With :math:`P(M, r)` the inertia of a particle M at r,

        .. math:: I_{new} = I_O - P(M, \bar r) + P(M, \bar r - r_{new})

        which is (7.12)–(7.13) when O is the c.m. (``com = 0``), (7.12) backwards when
        ``to_point = com``, and (7.17) between any two parallel frames.

        Raises
        ------
        DeclarationError
            If the mass is negative or a point does not have 3 components.

        >>> import sympy as sp
        >>> M, R = sp.symbols("M R", positive=True)
        >>> Inertia(M*R**2/4, M*R**2/4, M*R**2/2).translated(M, (0, 0, 0), (0, R, 0)).I_x
        5*M*R**2/4
        """
        (mass,) = _check_nonnegative("translated", mass=mass)
        c = _vector(com, "com")
        p = _vector(to_point, "to_point")
        return self - _particle(mass, c) + _particle(mass, c - p)

    def from_centre(self, mass, point) -> Inertia:
        """``self`` is about the c.m.; return the inertia about ``point`` (parallel axes, 7.12–7.13)."""
        return self.translated(mass, (0, 0, 0), point)

    def to_centre(self, mass, com) -> Inertia:
        """``self`` is about O with the c.m. at ``com``; return the central inertia (7.12 backwards)."""
        return self.translated(mass, com, com)

    # ----- composite bodies ----------------------------------------------------------------------
    def __add__(self, other: Inertia) -> Inertia:
        """Composite body: both parts must be about the same point and axes."""
        if not isinstance(other, Inertia):
            return NotImplemented
        return Inertia(*(sp.expand(getattr(self, n) + getattr(other, n)) for n in _NAMES))

    def __sub__(self, other: Inertia) -> Inertia:
        """Remove a part (a hole), same point and axes."""
        if not isinstance(other, Inertia):
            return NotImplemented
        return Inertia(*(sp.expand(getattr(self, n) - getattr(other, n)) for n in _NAMES))

    def equals(self, other: Inertia) -> bool:
        """True when every component agrees (``is_zero`` of the difference; 30 digits to 1e-20 for pure numbers)."""
        return all(_is_zero(getattr(self, n) - getattr(other, n)) for n in _NAMES)


def _is_zero(expr: sp.Expr) -> bool:
    expr = sp.expand(expr)
    if expr == 0:
        return True
    if not expr.free_symbols:
        return abs(expr.evalf(30)) < 1e-20
    return is_zero(expr)


def _particle(mass, r: sp.Matrix) -> Inertia:
    x, y, z = r
    return Inertia(mass * (y**2 + z**2), mass * (x**2 + z**2), mass * (x**2 + y**2),
                   mass * x * y, mass * x * z, mass * y * z)


def _particles(masses_and_positions, what: str) -> list[tuple[sp.Expr, sp.Matrix]]:
    problems: list[str] = []
    out = []
    for i, item in enumerate(masses_and_positions):
        try:
            mass, pos = item
        except (TypeError, ValueError):
            problems.append(f"item {i} must be (mass, (x, y, z)), got {item!r}")
            continue
        mass = _exact(mass, f"mass {i}", problems)
        if getattr(mass, "is_negative", None):
            problems.append(f"mass {i} = {mass} is negative")
        pos = list(pos) if isinstance(pos, (Sequence, sp.MatrixBase)) else []
        if len(pos) != 3:
            problems.append(f"position {i} must have 3 components (x, y, z)")
            continue
        out.append((mass, sp.Matrix([_exact(c, f"position {i}", problems) for c in pos])))
    if not out and not problems:
        problems.append("no particles given")
    if problems:
        raise DeclarationError(problems, subject=what)
    return out


def point_masses(masses_and_positions: Iterable) -> Inertia:
    r"""Inertia about the origin of a set of particles (Wells 7.1).

    .. math:: I_x = \sum_i m_i (y_i^2 + z_i^2), \qquad I_{xy} = \sum_i m_i x_i y_i, \ \ldots

    Parameters
    ----------
    masses_and_positions : iterable of ``(mass, (x, y, z))``

    Raises
    ------
    DeclarationError
        Listing every item that is malformed, has a negative mass or holds a float.

    >>> point_masses([(2, (1, 1, 0))])
    Inertia(I_x=2, I_y=2, I_z=4, I_xy=2, I_xz=0, I_yz=0)
    """
    parts = _particles(masses_and_positions, "point_masses")
    total = _particle(*parts[0])
    for mass, r in parts[1:]:
        total = total + _particle(mass, r)
    return total


def centre_of_mass(masses_and_positions: Iterable) -> tuple[sp.Expr, sp.Matrix]:
    """Total mass and c.m. position (3x1 Matrix) of a set of particles.

    >>> centre_of_mass([(1, (0, 0, 0)), (3, (4, 0, 0))])
    (4, Matrix([
    [3],
    [0],
    [0]]))
    """
    parts = _particles(masses_and_positions, "centre_of_mass")
    total = sum((m for m, _ in parts), sp.S.Zero)
    return total, (sum((m * r for m, r in parts), sp.zeros(3, 1)) / total).applyfunc(simplify)


def _require_principal(inertia: Inertia, what: str) -> None:
    if not all(is_zero(getattr(inertia, n)) for n in _NAMES[3:]):
        raise DeclarationError("the inertia must be about principal axes (all products zero); "
                               "rotate it with principal_axes_numeric first", subject=what)


def equimomental_particles(M, inertia: Inertia) -> list[tuple[sp.Expr, tuple]]:
    r"""Six particles M/6 dynamically equivalent to a body (Wells Sec. 7.10, Ex. 7.9).

    The particles sit at ±a, ±b, ±c on the principal axes through the c.m., with

    .. math:: a = \sqrt{\tfrac{3}{2M}(\bar I_y + \bar I_z - \bar I_x)}, \ \text{and cyclically.}

    Parameters
    ----------
    M : total mass
    inertia : central principal inertia (products zero)

    Returns
    -------
    list of ``(M/6, (x, y, z))``, ready for :func:`point_masses`.

    Raises
    ------
    DeclarationError
        If a product of inertia is non-zero or M is negative.

    >>> import sympy as sp
    >>> M, R = sp.symbols("M R", positive=True)
    >>> equimomental_particles(M, Inertia(*[2*M*R**2/5]*3))[0]
    (M/6, (sqrt(15)*R/5, 0, 0))
    """
    (M,) = _check_nonnegative("equimomental_particles", M=M)
    _require_principal(inertia, "equimomental_particles")
    I = (inertia.I_x, inertia.I_y, inertia.I_z)
    out = []
    for k in range(3):
        d = sp.sqrt(sp.Rational(3, 2) / M * (sum(I) - 2 * I[k]))
        for sign in (1, -1):
            pos = [sp.S.Zero] * 3
            pos[k] = sign * d
            out.append((M / 6, tuple(pos)))
    return out


def foci(M, inertia: Inertia, axis: str) -> dict[str, sp.Expr]:
    r"""Distances s from the c.m. along a principal ``axis`` where two principal moments become equal.

    At the point s on principal axis a the moments about the three parallel principal axes are
    :math:`\bar I_a` and :math:`\bar I_b + M s^2` (b ≠ a); they match :math:`\bar I_a` at
    :math:`s = \pm\sqrt{(\bar I_a - \bar I_b)/M}` (Wells Sec. 7.8). Such a point is a focus of
    inertia when s is real; the ellipsoid there is one of revolution.

    Returns
    -------
    dict ``{b: s}`` for the two other axes b, with s >= 0 (the points are at ±s; s is imaginary
    when :math:`\bar I_b > \bar I_a`, i.e. no such point).

    >>> import sympy as sp
    >>> foci(1, Inertia(1, 2, 4), "z")
    {'x': sqrt(3), 'y': sqrt(2)}
    """
    (M,) = _check_nonnegative("foci", M=M)
    _require_principal(inertia, "foci")
    if axis not in _AXES:
        raise DeclarationError(f"axis must be 'x', 'y' or 'z', got {axis!r}", subject="foci")
    I = (inertia.I_x, inertia.I_y, inertia.I_z)
    a = _AXES[axis]
    return {b: sp.sqrt(sp.expand((I[a] - I[k]) / M)) for b, k in _AXES.items() if k != a}


def spherical_points(M, inertia: Inertia, axis: str) -> sp.Expr:
    r"""Distance s of the spherical points (all moments equal) on principal ``axis`` (Wells Sec. 7.8).

    They exist when the two other central moments are equal, :math:`\bar I_b = \bar I_c`, and then
    lie at :math:`s = \pm\sqrt{(\bar I_a - \bar I_b)/M}`, where every line has moment :math:`\bar I_a`.

    Raises
    ------
    DeclarationError
        If the other two moments differ.

    >>> import sympy as sp
    >>> M, a, b = sp.symbols("M a b", positive=True)
    >>> spherical_points(M, Inertia(2*M*b**2/3, M*(a**2 + b**2)/3, M*(a**2 + b**2)/3), "x")
    sqrt(-a**2/3 + b**2/3)
    """
    others = [k for k in "xyz" if k != axis]
    if axis in _AXES and not is_zero(getattr(inertia, "I_" + others[0]) - getattr(inertia, "I_" + others[1])):
        raise DeclarationError(f"no spherical points on {axis}: I_{others[0]} != I_{others[1]}",
                               subject="spherical_points")
    return foci(M, inertia, axis)[others[0]]


def euler_zxz(psi, theta, phi) -> sp.Matrix:
    r"""Direction cosines of body axes for Wells' Euler angles (Table 8.2, Fig. 8-16; Probs. 7.24–7.25).

    ψ is the precession about the fixed Z1 (from X1 to the line of nodes ON), θ the nutation about
    ON (from Z1 to the body z), φ the spin about z (from ON to the body x). Wells' ψ/φ are swapped
    relative to Goldstein's. Row i is body axis x, y, z; column j is fixed X1, Y1, Z1:

    .. math::

        \alpha = \begin{bmatrix}
        c\phi c\psi - s\phi s\psi c\theta & c\phi s\psi + s\phi c\psi c\theta & s\theta s\phi \\
        -s\phi c\psi - c\phi s\psi c\theta & -s\phi s\psi + c\phi c\psi c\theta & s\theta c\phi \\
        s\theta s\psi & -s\theta c\psi & c\theta \end{bmatrix}
        = (R_z(\psi) R_x(\theta) R_z(\phi))^T

    so ``body_inertia.rotated(euler_zxz(...).T)`` is the inertia about the fixed axes.

    >>> import sympy as sp
    >>> euler_zxz(0, 0, sp.pi/2)
    Matrix([
    [ 0, 1, 0],
    [-1, 0, 0],
    [ 0, 0, 1]])
    """
    cps, sps = sp.cos(psi), sp.sin(psi)
    cth, sth = sp.cos(theta), sp.sin(theta)
    cph, sph = sp.cos(phi), sp.sin(phi)
    return sp.Matrix([
        [cph * cps - sph * sps * cth, cph * sps + sph * cps * cth, sth * sph],
        [-sph * cps - cph * sps * cth, -sph * sps + cph * cps * cth, sth * cph],
        [sth * sps, -sth * cps, cth],
    ])


def plane_rotation(theta) -> sp.Matrix:
    r"""Direction cosines of axes turned by ``theta`` about z (new x at angle θ from old x; Prob. 7.21).

    >>> plane_rotation(0) == sp.eye(3)
    True
    """
    c, s = sp.cos(theta), sp.sin(theta)
    return sp.Matrix([[c, s, 0], [-s, c, 0], [0, 0, 1]])
