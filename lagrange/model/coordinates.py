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
from ..safe_sympify import sympify as _sympify

__all__ = [
    "coordinates",
    "parameters",
    "unknowns",
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
    "SYMPY_TIME",
    "normalize_time",
    "canonical_key",
    "canonical_keys",
    "key_name",
]

#: The time symbol of ``sympy.physics.mechanics.dynamicsymbols`` (``Symbol('t')``, no assumptions).
SYMPY_TIME = sp.Symbol("t")

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
    """Parameters as real symbols, **positive** unless other assumptions are given.

    Positivity is what lets sympy simplify ``sqrt(m**2)`` to ``m``; it also means sympy takes the symbol
    to be positive everywhere. For a quantity that may be zero or negative (an unknown force, a reaction,
    an offset) use :func:`unknowns` or pass ``real=True``.

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


def unknowns(spec: str | Sequence[str]):
    """Unknowns (forces, reactions, offsets to solve for) as real symbols with no sign assumption.

    Use them for the quantities :func:`~lagrange.actuator_forces` and :func:`~lagrange.static_equilibrium`
    solve for: a force declared with :func:`parameters` is positive, so a solution in which it is zero or
    negative would not fit its declaration (those functions solve for real values whatever the declaration).

    >>> from lagrange import unknowns
    >>> F1, F2 = unknowns("F1 F2")
    >>> F1.is_real, F1.is_positive
    (True, None)
    """
    syms = tuple(sp.Symbol(n, real=True) for n in _names(spec))
    return syms[0] if len(syms) == 1 else syms


def normalize_time(obj):
    """``obj`` with sympy's time ``Symbol('t')`` replaced by :data:`lagrange.t` (which is real).

    This is how ``sympy.physics.mechanics.dynamicsymbols`` are accepted wherever lagrange takes expressions
    (coordinates, energies, forces, bodies, constraints): ``dynamicsymbols('q')`` is ``q(Symbol('t'))``, and
    becomes ``q(lagrange.t)``. Expressions, matrices, and lists, tuples and dicts of them are converted;
    anything else is returned as it is. Any other symbol named ``t`` is left alone (and refused by
    :class:`~lagrange.System` as a second time symbol).

    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> from lagrange import t
    >>> q = normalize_time(dynamicsymbols("q"))
    >>> q.args == (t,)
    True
    >>> normalize_time(dynamicsymbols("q").diff()) == q.diff(t)
    True
    """
    if isinstance(obj, (sp.Basic, sp.MatrixBase)):
        return obj.xreplace({SYMPY_TIME: t}) if obj.has(SYMPY_TIME) else obj
    if type(obj) in (list, tuple):
        return type(obj)(normalize_time(x) for x in obj)
    if type(obj) is dict:
        return {normalize_time(k): normalize_time(v) for k, v in obj.items()}
    return obj


def canonical_key(key, coordinates: Sequence = (), inputs: Sequence = ()):
    """A key naming a coordinate, a velocity, an acceleration or an input, in the form the system holds it.

    The one place where keys given by users are normalised; every function that takes a dict keyed by
    coordinates (initial values, ``sol[q]``, ``about=``, plots, sweeps, Gauss' check) or by inputs passes
    its keys through here before looking them up. sympy's time ``Symbol('t')`` becomes :data:`lagrange.t`
    (:func:`normalize_time`), so ``dynamicsymbols('q')``, ``dynamicsymbols('q', 1)``, ``q.diff()`` and
    ``q.diff(t, 2)`` work wherever ``q(t)`` does. An undefined function of time named like one of
    ``coordinates`` is that coordinate whatever its assumptions (``dynamicsymbols('q')`` has none,
    :func:`coordinates` makes real ones), and a function of time ``u(t)`` named like one of ``inputs`` is
    that input (sympy's specifieds are functions of time; lagrange's inputs are symbols). Names (strings)
    and anything else are returned unchanged, for the caller's own lookup and its error message.

    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> from lagrange import coordinates, t
    >>> x = coordinates("x")
    >>> canonical_key(dynamicsymbols("x", 1), [x]) == x.diff(t)
    True
    """
    if not isinstance(key, sp.Basic):
        return key
    key = normalize_time(key)
    if isinstance(key, sp.Derivative):
        if all(v == t for v, _ in key.variable_count):
            return key.xreplace({key.expr: canonical_key(key.expr, coordinates)})
        return key
    if isinstance(key, AppliedUndef) and key.args == (t,):
        name = key.func.__name__
        for c in coordinates:
            if is_coordinate(c) and c.func.__name__ == name:
                return c
        for u in inputs:
            if getattr(u, "name", None) == name:
                return u
    return key


def canonical_keys(mapping, coordinates: Sequence = (), inputs: Sequence = ()) -> dict:
    """``mapping`` (a Mapping, or None for an empty dict) with every key passed through :func:`canonical_key`.

    Two keys that name the same thing keep the last value, as in any dict."""
    return {canonical_key(k, coordinates, inputs): v for k, v in (mapping or {}).items()}


def key_name(key, coordinates: Sequence = ()) -> str:
    """The name by which a key is looked up in tables keyed by names (sweeps, sampling ranges): ``"q"`` for a
    coordinate ``q(t)`` (or sympy's ``dynamicsymbols('q')``), ``"q_dot"`` for its velocity, a symbol's name; a
    string as it is, anything else as its text.

    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> key_name(dynamicsymbols("x", 1)), key_name("x_dot")
    ('x_dot', 'x_dot')
    """
    key = canonical_key(key, coordinates)
    if is_coordinate(key):
        return coordinate_name(key)
    if isinstance(key, sp.Derivative) and is_coordinate(key.expr) and key.derivative_count == 1:
        return coordinate_name(key.expr) + VELOCITY_SUFFIX
    name = getattr(key, "name", None)
    return name if isinstance(name, str) else str(key)


def normalize_fields(obj, expressions: tuple[str, ...] = ()) -> None:
    """:func:`normalize_time` applied to every field of a frozen dataclass (its ``__post_init__``); the fields
    named in ``expressions`` are converted first by :func:`lagrange.safe_sympify.sympify` (a string is read
    as an expression of numbers, never evaluated; anything else that is not a number or a sympy object is
    refused)."""
    from dataclasses import fields

    for name in expressions:
        where = f"{type(obj).__name__}.{name}"
        object.__setattr__(obj, name, _sympify(getattr(obj, name), where=where))
    for f in fields(obj):
        object.__setattr__(obj, f.name, normalize_time(getattr(obj, f.name)))


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
    return set(_sympify(expr).atoms(AppliedUndef))


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
    expr = _sympify(expr)
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
    return _sympify(expr).xreplace(_symbol_map(tuple(coords)))


def to_functions(expr, coords: Sequence):
    """Inverse of :func:`to_symbols`: plain symbols back to functions of t (for printing)."""
    return _sympify(expr).xreplace(_function_map(tuple(coords)))


@lru_cache(maxsize=256)
def _function_map(coords: tuple) -> dict:
    """``{q_ddot: q''(t), q_dot: q'(t), q: q(t)}`` (memoized like :func:`_symbol_map`)."""
    return {v: k for k, v in _symbol_map(coords).items()}
