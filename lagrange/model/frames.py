r"""Reference frames that translate and rotate in a prescribed way, nested frames, and the rotating earth.

A :class:`Frame` has an origin and a rotation (columns: its axes in the parent frame), both functions
of t. ``frame.point(local)`` gives the inertial position of a point with local coordinates, which is
what a :class:`~lagrange.Particle` or :class:`~lagrange.RigidBody` needs: T is then reckoned relative to
inertial space automatically and the Coriolis, centrifugal and Euler terms come out of Lagrange's
equations (Wells 1.2, 2.14, 8.4).

The rotating earth (Wells ch. 14, Fig. 14-2): X₁ east, Y₁ north, Z₁ up at geographic latitude Φ on a
sphere of radius R turning at ω_e about the polar axis. True gravity ``g`` lies in the Y₁Z₁ plane; the
plumb line gives the apparent ``g′`` along −Z₁ (14.11)–(14.13):
``g sin α = ω_e² R sinΦ cosΦ``, ``g cos α = g′ + ω_e² R cos²Φ``. Generalized forces use the true g
(Wells' rule); the large ``R ω_e²`` terms then cancel symbolically in the derived equations (14.16).

The earth as an ellipsoid of revolution (Wells 14.1–14.10, Table 14.1): :class:`Ellipsoid` gives the
geocentric latitude Φ₁ and radius R₁ of a point at geographic latitude Φ, the geographic radius R (the length of
the normal from the surface to the polar axis, so the point is ``R cos Φ`` from the axis) and the plumb-line
gravity g′ of the international formula (14.9). ``EarthFrame(Φ, ellipsoid=WELLS_1924)`` places its origin on the
ellipsoid with Z₁ along the normal and uses that R.
"""

from __future__ import annotations

import sympy as sp

from ..conventions import t
from ..errors import DeclarationError
from ..records import record
from ..safe_sympify import matrix as _matrix
from ..safe_sympify import sympify as _sympify
from ..simplification import trigsimp
from .bodies import as_vector
from .coordinates import time_derivative
from .rotations import rot_z

__all__ = ["Frame", "EarthFrame", "OMEGA_EARTH", "Ellipsoid", "WELLS_1924", "apparent_gravity",
           "true_gravity_magnitude"]

#: Earth's rotation rate (rad/s), Wells ch. 14.
OMEGA_EARTH = sp.Float("7.29211e-5")


class Frame:
    """A frame with ``origin(t)`` and ``rotation(t)`` relative to ``parent`` (None: inertial).

    >>> from lagrange import coordinates, parameters, t
    >>> from lagrange.model.rotations import rot_z
    >>> w = parameters("omega"); x, y = coordinates("x y")
    >>> Frame(rotation=rot_z(w*t)).point((x, y))[0]
    x(t)*cos(omega*t) - y(t)*sin(omega*t)
    """

    def __init__(self, origin=(0, 0, 0), rotation=None, parent: Frame | None = None, name: str = ""):
        self.origin = as_vector(origin, f"origin of frame {name!r}")
        self.rotation = _matrix(rotation, where=f"rotation of frame {name!r}") if rotation is not None else sp.eye(3)
        if self.rotation.shape != (3, 3):
            raise ValueError("a frame rotation must be a 3x3 matrix (columns: the frame's axes)")
        self.parent = parent
        self.name = name

    def to_inertial(self) -> tuple[sp.Matrix, sp.Matrix]:
        """(origin, rotation) of this frame relative to inertial space, composing parents."""
        if self.parent is None:
            return self.origin, self.rotation
        o, R = self.parent.to_inertial()
        return o + R * self.origin, R * self.rotation

    def point(self, local) -> sp.Matrix:
        """Inertial position of the point with local coordinates ``local`` (1–3 expressions)."""
        o, R = self.to_inertial()
        return o + R * as_vector(local, "local point")

    def direction(self, local) -> sp.Matrix:
        """Inertial components of a vector given along this frame's axes."""
        return self.to_inertial()[1] * as_vector(local, "local vector")

    def angular_velocity(self) -> sp.Matrix:
        """The frame's angular velocity along the inertial axes, composed level by level:
        ``ω = ω_parent + R_parent ω_rel``. ``ω_rel`` of an elementary rotation (:func:`rot_x`, :func:`rot_y`,
        :func:`rot_z` of an angle θ) is ``θ̇`` along its axis, with no simplification; any other rotation
        matrix gets ``Ṙ Rᵀ = [ω_rel]×`` simplified at its own level only (small), never the multiplied-out
        chain."""
        rate = _elementary_rate(self.rotation)
        if rate is None:
            R = self.rotation
            W = time_derivative(R) * R.T
            rate = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]]).applyfunc(lambda e: trigsimp(sp.expand(e)))
        if self.parent is None:
            return rate
        _, R_parent = self.parent.to_inertial()
        return self.parent.angular_velocity() + R_parent * rate


def _elementary_rate(R: sp.Matrix) -> sp.Matrix | None:
    """``θ̇ e_axis`` when ``R`` is exactly ``rot_x(θ)``, ``rot_y(θ)`` or ``rot_z(θ)`` (entry by entry), else None."""
    from .rotations import _AXIS, _ELEMENTARY

    for axis, k in (("x", 0), ("y", 1), ("z", 2)):
        other = (k + 1) % 3  # the entry R[other, other] of an elementary rotation is cos θ
        c = R[other, other]
        if not isinstance(c, sp.cos):
            continue
        angle = c.args[0]
        if R == _ELEMENTARY[axis](angle):
            return sp.Matrix(_AXIS[axis]) * angle.diff(t)
    if R == sp.eye(3):
        return sp.zeros(3, 1)
    return None


@record(frozen=True, slots=True)
class Ellipsoid:
    r"""An oblate ellipsoid of revolution (semi-axes ``a`` equatorial ≥ ``b`` polar, metres), Wells ch. 14.

    Geographic latitude Φ is the angle of the surface normal with the equator; geocentric latitude Φ₁ that of
    the radius from the centre. With :math:`\epsilon^2 = (a^2 - b^2)/a^2`:

    .. math::

        R_1 = b\,(1 - \epsilon^2\cos^2\Phi_1)^{-1/2}\ (14.1), \qquad
        R = a\,(1 - \epsilon^2\sin^2\Phi)^{-1/2}\ (14.4), \qquad
        \tan\Phi = (a^2/b^2)\tan\Phi_1\ (14.6).

    R (the geographic radius) is the length of the normal from the surface to the polar axis: the point is
    ``R cos Φ`` from the axis, which is what the centrifugal terms need (14.11). Angles in radians; exact
    sympy results (evaluate with ``float`` or ``.evalf()``); a symbolic latitude gives expressions.

    >>> from sympy import pi
    >>> round(float(WELLS_1924.geocentric_radius(pi/2)))    # b, Table 14.1
    6356912
    """

    a: sp.Expr
    b: sp.Expr
    name: str = ""

    def __post_init__(self):
        # exact symbols: floats enter only at code generation
        a, b = (sp.nsimplify(_sympify(v, where=f"Ellipsoid.{k}")) for k, v in (("a", self.a), ("b", self.b)))
        if a.is_positive is False or b.is_positive is False or (a - b).is_negative:
            raise DeclarationError(f"an ellipsoid needs a ≥ b > 0 (equatorial and polar semi-axes), got a={a}, b={b}")
        object.__setattr__(self, "a", a)
        object.__setattr__(self, "b", b)

    @property
    def eccentricity_squared(self) -> sp.Expr:
        """``ε² = (a² − b²)/a²`` (Wells: 0.00672267 for the 1924 ellipsoid)."""
        return (self.a**2 - self.b**2) / self.a**2

    @property
    def flattening(self) -> sp.Expr:
        """``f = (a − b)/a`` (1/297 for the 1924 ellipsoid)."""
        return (self.a - self.b) / self.a

    def geocentric_latitude(self, latitude) -> sp.Expr:
        """Φ₁ from the geographic latitude Φ: ``tan Φ₁ = (b²/a²) tan Φ`` (14.6), for −π/2 ≤ Φ ≤ π/2."""
        Phi = _sympify(latitude)
        return sp.atan2(self.b**2 * sp.sin(Phi), self.a**2 * sp.cos(Phi))

    def geographic_latitude(self, geocentric_latitude) -> sp.Expr:
        """Φ from the geocentric latitude Φ₁ (the inverse of (14.6))."""
        Phi1 = _sympify(geocentric_latitude)
        return sp.atan2(self.a**2 * sp.sin(Phi1), self.b**2 * sp.cos(Phi1))

    def radius(self, latitude) -> sp.Expr:
        """The geographic radius ``R = a (1 − ε² sin²Φ)^(−1/2)`` at geographic latitude Φ (14.4)."""
        return self.a / sp.sqrt(1 - self.eccentricity_squared * sp.sin(_sympify(latitude)) ** 2)

    def geocentric_radius(self, latitude) -> sp.Expr:
        """The distance R₁ from the centre to the surface point at geographic latitude Φ (14.1 with Φ₁ of 14.6)."""
        Phi1 = self.geocentric_latitude(latitude)
        return self.b / sp.sqrt(1 - self.eccentricity_squared * sp.cos(Phi1) ** 2)

    def surface_point(self, latitude) -> sp.Matrix:
        """``(R cos Φ, 0, (b²/a²) R sin Φ)``: the surface point in the meridian plane (x from the axis, z north)."""
        Phi = _sympify(latitude)
        R = self.radius(Phi)
        return sp.Matrix([R * sp.cos(Phi), 0, self.b**2 / self.a**2 * R * sp.sin(Phi)])


#: The international (Hayford 1924) ellipsoid Wells uses: a = 6 378 388 m, f = 1/297 exactly, so
#: b = a(1 − f) = 6 356 911.9 m (Wells prints 6 356 912) and ε² = 2f − f² = 0.00672267.
WELLS_1924 = Ellipsoid(6_378_388, 6_378_388 * (1 - sp.Rational(1, 297)), name="international 1924")

_GPRIME = (sp.Rational("9.78049"), sp.Rational("0.0052884"), sp.Rational("0.0000059"))  # m/s², (14.9)
_HEIGHT = (sp.Rational("0.30855"), sp.Rational("0.00022"), sp.Rational("0.000072"))  # gal/km, (14.10)


def apparent_gravity(latitude, height=0) -> sp.Expr:
    r"""Plumb-line gravity g′ (m/s²) at geographic latitude Φ and height h (metres), Wells (14.9)–(14.10):

    .. math:: g' = 9.78049\,(1 + 0.0052884\sin^2\Phi - 0.0000059\sin^2 2\Phi),\qquad
              g'_h = g' - (0.30855 + 0.00022\cos 2\Phi - 0.000072\,h_{\mathrm{km}})\,h_{\mathrm{km}}\ \mathrm{gal}.

    The international gravity formula, which belongs to the 1924 ellipsoid (:data:`WELLS_1924`).

    >>> from sympy import pi
    >>> round(float(apparent_gravity(pi/4)) * 100, 3)   # gal, Table 14.1
    980.629
    """
    Phi, h = _sympify(latitude), _sympify(height)
    g0, c2, c22 = _GPRIME
    g = g0 * (1 + c2 * sp.sin(Phi) ** 2 - c22 * sp.sin(2 * Phi) ** 2)
    if h == 0:
        return g
    a0, a2, ah = _HEIGHT
    hk = h / 1000
    return g - (a0 + a2 * sp.cos(2 * Phi) - ah * hk) * hk / 100


def true_gravity_magnitude(latitude, omega=OMEGA_EARTH, ellipsoid: Ellipsoid = WELLS_1924, g_apparent=None):
    r"""True gravity g and the plumb line's deflection α from it (radians), Wells (14.11)–(14.13):

    .. math:: g^2 = g'^2 + \omega_e^2 R\cos^2\Phi\,(2g' + \omega_e^2 R), \qquad
              \tan\alpha = \tfrac12\omega_e^2 R\sin 2\Phi / (g' + \omega_e^2 R\cos^2\Phi)

    with R the geographic radius and g′ from :func:`apparent_gravity` unless given. Returns ``(g, α)``.
    """
    Phi = _sympify(latitude)
    w = _sympify(omega)
    R = ellipsoid.radius(Phi)
    gp = apparent_gravity(Phi) if g_apparent is None else _sympify(g_apparent)
    g = sp.sqrt(gp**2 + w**2 * R * sp.cos(Phi) ** 2 * (2 * gp + w**2 * R))
    alpha = sp.atan2(w**2 * R * sp.sin(Phi) * sp.cos(Phi), gp + w**2 * R * sp.cos(Phi) ** 2)
    return g, alpha


class EarthFrame(Frame):
    """Wells' earth-surface frame (Fig. 14-2): X₁ east, Y₁ north, Z₁ up at latitude ``latitude`` on the
    earth of radius ``radius`` turning at ``omega`` about the inertial Z axis (through the centre).

    With ``ellipsoid=`` (e.g. :data:`WELLS_1924`) the earth is that ellipsoid: ``latitude`` is the geographic
    latitude Φ, Z₁ is the normal to the ellipsoid, the origin is the surface point, and ``radius`` is the
    geographic radius R of (14.4) (the origin is ``R cos Φ`` from the axis, which is all the rotation sees);
    :meth:`true_gravity` then defaults g′ to the international formula (14.9). Giving both ``radius`` and
    ``ellipsoid`` is refused."""

    def __init__(self, latitude, omega=OMEGA_EARTH, radius=None, name: str = "earth",
                 ellipsoid: Ellipsoid | None = None):
        Phi = _sympify(latitude)
        w = _sympify(omega)
        if ellipsoid is not None and radius is not None:
            raise DeclarationError("EarthFrame: give either radius= (a spherical earth) or ellipsoid=, not both")
        if ellipsoid is not None and not isinstance(ellipsoid, Ellipsoid):
            raise DeclarationError(f"EarthFrame: ellipsoid must be an Ellipsoid, got {ellipsoid!r}")
        spin = rot_z(w * t)
        east = sp.Matrix([0, 1, 0])
        north = sp.Matrix([-sp.sin(Phi), 0, sp.cos(Phi)])
        up = sp.Matrix([sp.cos(Phi), 0, sp.sin(Phi)])
        axes = sp.Matrix.hstack(east, north, up)
        if ellipsoid is None:
            R = sp.Symbol("R", positive=True) if radius is None else _sympify(radius)
            origin = R * up
        else:
            R = ellipsoid.radius(Phi)
            origin = ellipsoid.surface_point(Phi)
        super().__init__(origin=spin * origin, rotation=spin * axes, name=name)
        self.latitude, self.omega, self.radius, self.ellipsoid = Phi, w, R, ellipsoid

    def true_gravity(self, g_apparent=None) -> sp.Matrix:
        """True gravity per unit mass along (east, north, up) from the plumb-line value ``g′``
        (Wells 14.11–14.13): ``(0, ω² R sinΦ cosΦ, −(g′ + ω² R cos²Φ))``. ``g′`` defaults to
        :func:`apparent_gravity` (14.9) on an ellipsoidal earth and is required on a spherical one."""
        w, R, Phi = self.omega, self.radius, self.latitude
        if g_apparent is None:
            if self.ellipsoid is None:
                raise DeclarationError("EarthFrame.true_gravity: give g_apparent (the plumb-line g′) for a "
                                       "spherical earth; only an ellipsoidal earth has a default (14.9)")
            g_apparent = apparent_gravity(Phi)
        return sp.Matrix([0, w**2 * R * sp.sin(Phi) * sp.cos(Phi), -(g_apparent + w**2 * R * sp.cos(Phi) ** 2)])

    def gravity_force(self, mass, g_apparent=None) -> sp.Matrix:
        """The true gravity force on ``mass`` in inertial components (for :class:`~lagrange.Force`)."""
        return self.direction(mass * self.true_gravity(g_apparent))
