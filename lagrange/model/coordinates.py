"""Generalized coordinates, parameters, virtual displacements and the symbol maps behind them.

Coordinates are undefined sympy functions of the time symbol :data:`lagrange.t`, so ``q.diff(t)`` is the
velocity and printing shows dots. Derivations work on plain symbols (``q``, ``q_dot``, ``q_ddot``);
:func:`to_symbols` and :func:`to_functions` translate between the two forms.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import lru_cache

import sympy as sp
from sympy.core.function import AppliedUndef

from ..conventions import VELOCITY_SUFFIX, t

__all__ = [
    "coordinates",
    "parameters",
    "delta",
    "is_coordinate",
    "coordinate_name",
    "state_text",
    "position_symbol",
    "velocity_symbol",
    "acceleration_symbol",
    "virtual_displacement",
    "to_symbols",
    "to_functions",
    "applied_functions",
    "time_derivative",
]

_DELTA_PREFIX = "delta_"


def _names(spec: str | Sequence[str]) -> list[str]:
    if isinstance(spec, str):
        names = spec.replace(",", " ").split()
    else:
        names = [str(n) for n in spec]
    if not names:
        raise ValueError("no names given: pass e.g. 'r theta'")
    for n in names:
        if not n.isidentifier():
            raise ValueError(f"{n!r} is not a valid name: use letters, digits and underscores")
    return names


def coordinates(spec: str | Sequence[str]):
    """Generalized coordinates as sympy functions of :data:`lagrange.t`.

    Like :func:`sympy.symbols`, one name gives one object and several names give a tuple.

    Examples
    --------
    >>> from lagrange import coordinates, t
    >>> r, theta = coordinates("r theta")
    >>> theta.diff(t)
    Derivative(theta(t), t)
    """
    funcs = tuple(sp.Function(n, real=True)(t) for n in _names(spec))
    return funcs[0] if len(funcs) == 1 else funcs


def parameters(spec: str | Sequence[str], **assumptions):
    """Parameters as real symbols, positive unless other assumptions are given.

    >>> from lagrange import parameters
    >>> m, g = parameters("m g")
    >>> m.is_positive
    True
    """
    if not assumptions:
        assumptions = {"positive": True}
    assumptions.setdefault("real", True)
    syms = tuple(sp.Symbol(n, **assumptions) for n in _names(spec))
    return syms[0] if len(syms) == 1 else syms


def is_coordinate(obj) -> bool:
    """True for an undefined function applied to :data:`t` alone, e.g. ``theta(t)``."""
    return isinstance(obj, AppliedUndef) and obj.args == (t,)


def coordinate_name(q) -> str:
    return q.func.__name__


def state_text(coords: Sequence, y) -> str:
    """``"x=1, theta=0.5, x_dot=0, theta_dot=-2"`` for the state ``y = [q, q̇]`` of ``coords`` (6 digits), as
    error messages name where a run stopped."""
    names = [coordinate_name(c) for c in coords]
    n = len(names)
    return ", ".join([f"{names[i]}={y[i]:.6g}" for i in range(n)]
                     + [f"{names[i]}{VELOCITY_SUFFIX}={y[n + i]:.6g}" for i in range(n)])


def position_symbol(q) -> sp.Symbol:
    return sp.Symbol(coordinate_name(q), real=True)


def velocity_symbol(q) -> sp.Symbol:
    return sp.Symbol(coordinate_name(q) + VELOCITY_SUFFIX, real=True)


def acceleration_symbol(q) -> sp.Symbol:
    return sp.Symbol(coordinate_name(q) + "_ddot", real=True)


def virtual_displacement(q) -> sp.Symbol:
    """The symbol ``delta_q`` that stands for the virtual displacement of coordinate ``q``."""
    return sp.Symbol(_DELTA_PREFIX + coordinate_name(q), real=True)


def applied_functions(expr) -> set:
    """Every undefined function application in ``expr`` (coordinates and strays alike)."""
    return set(sp.sympify(expr).atoms(AppliedUndef))


def delta(expr):
    r"""Virtual variation of ``expr`` with time frozen (Wells 2.13, 4.11).

    .. math:: \delta f = \sum_r \frac{\partial f}{\partial q_r}\,\delta q_r

    taken over every coordinate function ``q_r(t)`` in ``expr``. Use it to write a virtual-work
    expression, e.g. ``-m*g*delta(b*x**2)`` for gravity on a bead on the wire ``y = b x^2``; pass the
    result as ``forces=`` to :class:`~lagrange.System`, which reads the generalized forces off as the
    coefficients of the ``delta_q`` symbols (Wells 4.12).

    >>> from lagrange import coordinates, parameters, delta
    >>> x = coordinates("x"); b = parameters("b")
    >>> delta(b*x**2)
    2*b*delta_x*x(t)
    """
    expr = sp.sympify(expr)
    if expr.atoms(sp.Derivative):
        raise ValueError(f"delta() of {expr} contains velocities: a virtual displacement freezes time")
    coords = sorted((f for f in applied_functions(expr) if is_coordinate(f)), key=str)
    out = sp.S.Zero
    for q in coords:
        s = sp.Dummy(coordinate_name(q))
        out += sp.diff(expr.subs(q, s), s).subs(s, q) * virtual_displacement(q)
    return out


def time_derivative(matrix: sp.MatrixBase) -> sp.MatrixBase:
    """d/dt of every entry of ``matrix`` (explicit time dependence included). Entry by entry:
    ``Matrix.diff`` goes through sympy's array-derivative machinery, about 3× slower (400 against 139 µs
    for a particle's position vector)."""
    return matrix.applyfunc(lambda e: e.diff(t))


@lru_cache(maxsize=256)
def _symbol_map(coords: tuple) -> dict:
    """``{q''(t): q_ddot, q'(t): q_dot, q(t): q}`` for ``coords`` (memoized: building the derivatives is the
    costly part). Callers must not mutate it."""
    m = {}
    for q in coords:
        m[q.diff(t, 2)] = acceleration_symbol(q)
        m[q.diff(t)] = velocity_symbol(q)
        m[q] = position_symbol(q)
    return m


def to_symbols(expr, coords: Sequence):
    """Replace ``q(t)``, ``q'(t)``, ``q''(t)`` by the plain symbols ``q``, ``q_dot``, ``q_ddot``.

    One structural replacement (``xreplace``, outermost match first, so ``q''(t)`` becomes ``q_ddot`` before
    its inner ``q(t)`` is reached); a fraction of the cost of ``subs``, which tries algebraic matches that
    cannot occur here (the derivatives of a coordinate are atoms of the expression tree).
    """
    return sp.sympify(expr).xreplace(_symbol_map(tuple(coords)))


def to_functions(expr, coords: Sequence):
    """Inverse of :func:`to_symbols`: plain symbols back to functions of t (for printing)."""
    return sp.sympify(expr).xreplace(_function_map(tuple(coords)))


@lru_cache(maxsize=256)
def _function_map(coords: tuple) -> dict:
    """``{q_ddot: q''(t), q_dot: q'(t), q: q(t)}`` (memoized like :func:`_symbol_map`)."""
    return {v: k for k, v in _symbol_map(coords).items()}
