r"""Time-varying inputs: a motor torque u(t), a driving force F(t), a control law u(t, q, q̇).

An input is a real :class:`Input` symbol (a :class:`sympy.Symbol` subclass) declared with :func:`inputs`. It
enters the declaration wherever a known force does — ``forces`` (generalized forces, :class:`~lagrange.Force`
vectors, :class:`~lagrange.Torque` vectors), Wells' power function ``P`` and the Rayleigh function — and is
detected there automatically: a :class:`~lagrange.System` needs no ``inputs=`` argument. The derived
:class:`~lagrange.derive.equations.Equations` list the inputs found in ``inputs`` (sorted by name), apart from
the ``parameters``: a parameter is a number bound at compile time, an input is a value given at simulate
time (``simulate(..., inputs={u: value})``), a constant, a function of t, a feedback law of (t, y) or
sampled data (:mod:`lagrange.codegen.input_values`).

An input may **not** appear in T, V, a constraint or a prescribed motion: each of these is differentiated
in time by Lagrange's equations or by the power balance (``d/dt ∂T/∂q̇``, ``∂L/∂t``, ``φ̈``), which would need
u̇ (and ü) — values a sampled or feedback input does not have. The declaration is refused with the fix:
put the input's generalized force in ``forces`` (a force from a potential V(q, u) is ``−∂V/∂q``); a motion
given in time is a prescribed motion (``System(..., prescribed={x: expression of t})``).

Examples
--------
>>> import lagrange as lg
>>> x = lg.coordinates("x"); m, k = lg.parameters("m k"); F = lg.inputs("F")
>>> s = lg.System([x], T=m*x.diff(lg.t)**2/2, V=k*x**2/2, forces={x: F})
>>> s.derived.inputs, s.derived.parameters
((F,), (k, m))
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import sympy as sp

from ..safe_sympify import sympify as _sympify

__all__ = ["Input", "inputs", "is_input", "inputs_in"]


class Input(sp.Symbol):
    """A time-varying input of a system: a real symbol whose value is given at simulate time.

    Compares unequal to a plain ``Symbol`` of the same name (its class is part of its identity), so an
    input is never confused with a parameter. Recognised by :func:`is_input` through the class attribute
    ``is_lagrange_input`` (not by class identity, which a re-import of this module would change).
    """

    is_lagrange_input = True

    def __new__(cls, name: str, **assumptions):
        assumptions.setdefault("real", True)
        if assumptions.get("real") is not True:
            raise ValueError(f"input {name!r} must be real")
        return super().__new__(cls, name, **assumptions)


def inputs(spec: str | Sequence[str]):
    """Declare time-varying inputs as real :class:`Input` symbols.

    Like :func:`lagrange.parameters`, one name gives one symbol and several give a tuple.

    >>> from lagrange import inputs
    >>> u, F = inputs("u F")
    >>> u.is_real, type(F).__name__
    (True, 'Input')
    """
    from .coordinates import _names

    syms = tuple(Input(n) for n in _names(spec))
    return syms[0] if len(syms) == 1 else syms


def is_input(obj) -> bool:
    """True for an :class:`Input` symbol."""
    return isinstance(obj, sp.Symbol) and getattr(obj, "is_lagrange_input", False) is True


def inputs_in(exprs: Iterable) -> set:
    """The :class:`Input` symbols among the free symbols of ``exprs``."""
    out: set = set()
    for e in exprs:
        out |= {s for s in _sympify(e).free_symbols if is_input(s)}
    return out
