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
"""

from __future__ import annotations

import sympy as sp

from ..conventions import t
from ..safe_sympify import sympify as _sympify
from ..simplification import trigsimp
from .bodies import as_vector
from .coordinates import time_derivative
from .rotations import rot_z

__all__ = ["Frame", "EarthFrame", "OMEGA_EARTH"]

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
        self.rotation = sp.Matrix(rotation) if rotation is not None else sp.eye(3)
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
        """The frame's angular velocity along the inertial axes, from ``Ṙ Rᵀ = [ω]×``."""
        _, R = self.to_inertial()
        W = time_derivative(R) * R.T
        return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]]).applyfunc(lambda e: trigsimp(sp.expand(e)))


class EarthFrame(Frame):
    """Wells' earth-surface frame (Fig. 14-2): X₁ east, Y₁ north, Z₁ up at latitude ``latitude`` on the
    earth of radius ``radius`` turning at ``omega`` about the inertial Z axis (through the centre)."""

    def __init__(self, latitude, omega=OMEGA_EARTH, radius=None, name: str = "earth"):
        Phi = _sympify(latitude)
        w = _sympify(omega)
        R = sp.Symbol("R", positive=True) if radius is None else _sympify(radius)
        spin = rot_z(w * t)
        east = sp.Matrix([0, 1, 0])
        north = sp.Matrix([-sp.sin(Phi), 0, sp.cos(Phi)])
        up = sp.Matrix([sp.cos(Phi), 0, sp.sin(Phi)])
        axes = sp.Matrix.hstack(east, north, up)
        super().__init__(origin=spin * (R * up), rotation=spin * axes, name=name)
        self.latitude, self.omega, self.radius = Phi, w, R

    def true_gravity(self, g_apparent) -> sp.Matrix:
        """True gravity per unit mass along (east, north, up) from the plumb-line value ``g′``
        (Wells 14.11–14.13): ``(0, ω² R sinΦ cosΦ, −(g′ + ω² R cos²Φ))``."""
        w, R, Phi = self.omega, self.radius, self.latitude
        return sp.Matrix([0, w**2 * R * sp.sin(Phi) * sp.cos(Phi), -(g_apparent + w**2 * R * sp.cos(Phi) ** 2)])

    def gravity_force(self, mass, g_apparent) -> sp.Matrix:
        """The true gravity force on ``mass`` in inertial components (for :class:`~lagrange.Force`)."""
        return self.direction(mass * self.true_gravity(g_apparent))
