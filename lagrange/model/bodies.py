r"""Bodies that carry kinetic energy, and applied forces.

A body is anything with ``kinetic_energy()`` returning T in the coordinate functions and ``t``,
``name``, ``position_vectors()`` (the points drawn by animations) and ``subs(mapping)``. Particles live
here; :class:`~lagrange.model.rigid_body.RigidBody` follows the same protocol.

Positions are Wells' *transformation equations* :math:`x_i = x_i(q_1..q_n, t)`: explicit ``t`` covers
moving frames, moving constraints and prescribed motions. T is always reckoned from velocities
relative to an inertial frame (Wells 2.37):

.. math:: T = \tfrac12 \sum_i m_i (\dot x_i^2 + \dot y_i^2 + \dot z_i^2),
   \qquad \dot x_i = \sum_k \frac{\partial x_i}{\partial q_k}\dot q_k + \frac{\partial x_i}{\partial t}.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import sympy as sp

from ..errors import DeclarationError
from .coordinates import normalize_time, time_derivative

__all__ = ["Body", "Particle", "Force", "as_vector"]


def as_vector(components, what: str) -> sp.Matrix:
    """A 3-component column vector from 1, 2 or 3 expressions (missing ones are 0)."""
    if isinstance(components, sp.MatrixBase):
        comps = list(components)
    elif isinstance(components, Sequence) and not isinstance(components, str):
        comps = list(components)
    else:
        comps = [components]
    if not 1 <= len(comps) <= 3:
        raise DeclarationError(f"{what} needs 1 to 3 components (x, y, z), got {len(comps)}")
    comps = [sp.sympify(c) for c in comps] + [sp.S.Zero] * (3 - len(comps))
    return sp.Matrix(comps)


@runtime_checkable
class Body(Protocol):
    name: str

    def kinetic_energy(self) -> sp.Expr: ...

    def position_vectors(self) -> tuple[sp.Matrix, ...]: ...

    def subs(self, mapping) -> Body: ...


@dataclass(frozen=True, eq=False)
class Particle:
    """A point mass at ``position`` (1 to 3 Cartesian components, inertial frame).

    Parameters
    ----------
    mass : sympy expression
    position : sequence of 1–3 expressions in the coordinates and ``t``
    name : optional label used in messages and plots

    >>> from lagrange import coordinates, parameters, Particle, t
    >>> import sympy as sp
    >>> theta = coordinates("theta"); m, l = parameters("m l")
    >>> bob = Particle(m, (l*sp.sin(theta), -l*sp.cos(theta)))
    >>> sp.simplify(bob.kinetic_energy())
    l**2*m*Derivative(theta(t), t)**2/2
    """

    mass: sp.Expr
    position: sp.Matrix
    name: str = ""

    def __init__(self, mass, position, name: str = ""):
        mass, position = normalize_time(sp.sympify(mass)), normalize_time(position)  # dynamicsymbols accepted
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "position", as_vector(position, f"position of particle {name!r}"))
        object.__setattr__(self, "name", name)

    @property
    def velocity(self) -> sp.Matrix:
        """Inertial velocity, d(position)/dt including explicit time dependence."""
        return time_derivative(self.position)

    def kinetic_energy(self) -> sp.Expr:
        """½ m v·v with the inertial velocity."""
        v = self.velocity
        return sp.Rational(1, 2) * self.mass * (v.T * v)[0, 0]

    def position_vectors(self) -> tuple[sp.Matrix, ...]:
        """The points to draw: the particle's position."""
        return (self.position,)

    def subs(self, mapping) -> Particle:
        """The particle with ``mapping`` substituted in its mass and position (then ``doit``)."""
        return Particle(sp.sympify(self.mass).subs(mapping).doit(), self.position.subs(mapping).doit(), self.name)

    def __repr__(self) -> str:
        label = f" {self.name!r}" if self.name else ""
        return f"Particle{label}(mass={self.mass}, position={tuple(self.position)})"


@dataclass(frozen=True, eq=False)
class Force:
    """A force ``vector`` (1–3 Cartesian components) applied at a particle or a point.

    ``at`` is a :class:`Particle` or a position (1–3 expressions in the coordinates and t). The vector
    may depend on t, the coordinates and the velocities (Lorentz force, drag). Its generalized force is
    Wells (4.10), ``F_q = F · ∂r/∂q`` with t frozen.
    """

    at: sp.Matrix
    vector: sp.Matrix
    name: str = ""

    def __init__(self, at, vector, name: str = ""):
        point = at.position if isinstance(at, Particle) else as_vector(normalize_time(at), "point of application")
        object.__setattr__(self, "at", point)
        object.__setattr__(self, "vector", as_vector(normalize_time(vector), f"force {name!r}"))
        object.__setattr__(self, "name", name)
