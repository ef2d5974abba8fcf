"""Ready-made systems used by benchmarks, tests and notebooks."""

from __future__ import annotations

import sympy as sp

from .model.bodies import Particle
from .model.coordinates import coordinates, parameters
from .model.system import System

__all__ = ["n_link_pendulum"]


def n_link_pendulum(n: int, *, symbolic: bool = False, **system_kwargs) -> System:
    """Planar pendulum of ``n`` point masses on massless rods, absolute angles from the downward vertical.

    With ``symbolic=False`` (default) masses and lengths are 1 and ``g`` is a parameter, as in
    ``reference/numerics.md``; with ``symbolic=True`` masses ``m_i`` and lengths ``l_i`` are parameters.
    ``system_kwargs`` are passed to :class:`~lagrange.System` as they are (e.g. ``derivation="expanded"``;
    keywords it does not take raise its ``TypeError``); ``name`` defaults to ``"<n>-link pendulum"``.
    """
    if n < 1:
        raise ValueError("n must be at least 1")
    qs = coordinates([f"q{i + 1}" for i in range(n)])
    qs = qs if isinstance(qs, tuple) else (qs,)
    g = parameters("g")
    X, Y = sp.S.Zero, sp.S.Zero
    bodies = []
    V = sp.S.Zero
    for i, q in enumerate(qs):
        if symbolic:
            m, length = parameters(f"m{i + 1} l{i + 1}")
        else:
            m, length = sp.S.One, sp.S.One
        X += length * sp.sin(q)
        Y -= length * sp.cos(q)
        bodies.append(Particle(m, (X, Y), name=f"bob{i + 1}"))
        V += m * g * Y
    system_kwargs.setdefault("name", f"{n}-link pendulum")
    return System(list(qs), bodies=bodies, V=V, **system_kwargs)
