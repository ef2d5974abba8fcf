r"""The reference point of a linearization when none is given: an equilibrium, never q = 0 by default.

:func:`~lagrange.analysis.small_oscillations.linearize` (and so :func:`normal_modes` and
:func:`characteristic_roots` given a System) called without coordinates in ``about`` and at rest uses

* **with numbers** (``params``): the static equilibria found by
  :func:`~lagrange.analysis.equilibria.equilibria_near` around ``near`` (default: every coordinate 0); the
  chosen one is the stable one nearest to ``near``, else (none stable) the nearest one. Stable means every
  characteristic root has ``Re λ ≤ 1e-6 max(1, |λ|max)`` (Wells 10.17);
* **without numbers**: q = 0 when it is an equilibrium (the conditions vanish identically); otherwise the
  equilibrium conditions are solved with sympy (bounded, unconstrained systems) and the isolated real
  solutions are ranked the same way, stability and distance being judged at sampled parameter values
  (:data:`N_SAMPLES` fixed sets, each parameter a rational in [0.1, 10] respecting its sign; stable means
  stable at every sample). No solution: refused, asking for ``about=``.

The choice is recorded: :attr:`LinearModel.about` holds the point, :attr:`LinearModel.reference` says how it
was chosen and lists the other equilibria found (:attr:`LinearModel.equilibria`), and the same sentence is
logged at ``INFO`` level on the ``lagrange.analysis`` logger.
"""

from __future__ import annotations

import logging
import random
from collections.abc import Callable, Mapping

import numpy as np
import sympy as sp

from ..conventions import t
from ..errors import AnalysisError, LagrangeError
from ..model.coordinates import coordinate_name, position_symbol
from ..records import record
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero, simplify
from .equilibria import MAX_STARTS, Equilibrium, equilibria, equilibria_near, without_drive_terms

__all__ = ["ReferenceChoice", "numeric_choice", "symbolic_choice", "point_text"]

log = logging.getLogger("lagrange.analysis")

#: a root with Re λ above this fraction of max(1, |λ|max) makes an equilibrium unstable
STABLE_TOL = 1e-6


def point_text(point: Mapping, digits: int = 6) -> str:
    """``r = 1.24525, theta = 0``: a point by coordinate name (floats to ``digits`` significant digits)."""
    parts = []
    for k, v in point.items():
        name = coordinate_name(k) if hasattr(k, "args") and not isinstance(k, sp.Symbol) else getattr(k, "name", k)
        parts.append(f"{name} = {_number(v, digits)}")
    return ", ".join(parts) or "(no coordinates)"


def _number(v, digits: int) -> str:
    if isinstance(v, (float, np.floating)):
        return f"{float(v):.{digits}g}"
    return str(v)


@record(frozen=True)
class ReferenceChoice:
    """The equilibrium a linearization used and the others found.

    Attributes
    ----------
    point : Equilibrium — the chosen point ``{coordinate: value}``
    found : tuple of Equilibrium — every equilibrium found, the chosen one first
    stable : tuple — for each of ``found``: True, False, or None (could not be decided, e.g. a singular mass
        matrix there)
    how : str — how the point was found (``"numeric search"``, ``"q = 0 is an equilibrium"``, ``"sympy solve"``)
    """

    point: Equilibrium
    found: tuple
    stable: tuple
    how: str

    def describe(self, digits: int = 6) -> str:
        """One sentence: the point used, its stability, and the other equilibria found."""
        word = {True: "stable", False: "unstable", None: "stability unknown"}[self.stable[0]]
        text = f"linearized about the equilibrium {point_text(self.point, digits)} ({word}; {self.how})"
        free = getattr(self.point, "free", ())
        if free:
            text += f"; any value of {', '.join(map(coordinate_name, free))} is an equilibrium"
        if len(self.found) > 1:
            others = "; ".join(f"{point_text(e, digits)} ({'stable' if s else 'unstable' if s is False else '?'})"
                               for e, s in zip(self.found[1:], self.stable[1:]))
            text += f"; other equilibria found: {others}"
        return text


def _rank(found: list, stable: list, distance: list) -> list[int]:
    """Indices of ``found``: stable ones first, then by distance."""
    return sorted(range(len(found)), key=lambda i: (stable[i] is not True, distance[i]))


def numeric_choice(system, params: Mapping, near: Mapping | None,
                   stability: Callable[[Equilibrium], bool | None]) -> ReferenceChoice:
    """The equilibrium to linearize about with numbers (see the module docstring); AnalysisError naming the
    start when none is found."""
    found = equilibria_near(system, params, near)
    if not found:
        start = point_text(_near_point(system, near))
        inputs = getattr(system.derived, "inputs", ())
        held = ", ".join(f"{u.name} = {_number(float(_sympify(params.get(u.name, 0))), 6)}" for u in inputs)
        other = (f"; or hold the inputs at other values (`about={{{inputs[0].name!r}: 0}}`, in the shell "
                 f"`--input {inputs[0].name}=0`)") if inputs else ""
        held = f" with the inputs held at {held}" if held else ""
        raise AnalysisError(f"no static equilibrium found near {start}{held} (from {MAX_STARTS} starting points): "
                            "the system has none at these values; give the point to linearize at (`about=`, in the "
                            f"shell `--about q=VALUE`; a steady motion with its velocities){other}")
    stable = [stability(e) for e in found]
    order = _rank(found, stable, list(range(len(found))))  # found is sorted by distance already
    return ReferenceChoice(found[order[0]], tuple(found[i] for i in order), tuple(stable[i] for i in order),
                           f"nearest to {point_text(_near_point(system, near))}"
                           + (", stable preferred" if len(found) > 1 else ""))


def _near_point(system, near: Mapping | None) -> dict:
    near = near or {}
    out = {}
    for q in system.coordinates:
        v = next((near[k] for k in (q, coordinate_name(q), position_symbol(q)) if k in near), 0.0)
        out[q] = float(v)
    return out


#: parameter samples at which a symbolic equilibrium's stability is judged (stable only if stable at all)
N_SAMPLES = 8


def _samples(system) -> list[dict]:
    """Fixed rational values of the parameters, log-uniform in [0.1, 10], respecting their sign assumptions."""
    rnd = random.Random(7)
    out = []
    for _ in range(N_SAMPLES):
        values = {}
        for p in system.derived.parameters:
            x = sp.Rational(round(10 ** rnd.uniform(-1, 1), 4)).limit_denominator(10000)
            values[p] = -x if (p.is_negative or p.is_nonpositive) else x
        out.append(values)
    return out


def symbolic_choice(system, u0: Mapping, stability: Callable[[Mapping, Mapping], bool | None]) -> ReferenceChoice:
    """The equilibrium to linearize about without numbers (unconstrained systems; see the module docstring).

    ``stability(point, params)`` judges a float point at float parameter values."""
    eqs = system.derived
    rest = {v: 0 for v in eqs.qd}
    at0 = {**rest, **{s: 0 for s in eqs.q}, **{u: u0.get(u, 0) for u in getattr(eqs, "inputs", ())}}
    f0 = [_sympify(e).xreplace(at0) for e in eqs.forcing]
    driven = any(e.has(t) for e in f0)
    if driven:  # a time-dependent drive (A sin ωt) is the forcing of the linear model, not part of the statics
        f0 = [without_drive_terms(e) for e in f0]
    if all(is_zero(e) for e in f0):
        zero = Equilibrium({q: sp.S.Zero for q in system.coordinates})
        return ReferenceChoice(zero, (zero,), (None,), "q = 0 is an equilibrium"
                               + (" (of the system without its time-dependent drive)" if driven else ""))
    shown = point_text({q: 0 for q in system.coordinates})
    residual = ", ".join(f"{coordinate_name(q)}: {simplify(-e)}" for q, e in zip(system.coordinates, f0))
    refuse = (f"q = 0 ({shown}) is not an equilibrium (∂V/∂q − F_q there: {residual})")
    try:
        sols = equilibria(system, without_drive=driven)
    except LagrangeError as exc:
        raise AnalysisError(f"{refuse} and the equilibrium conditions could not be solved symbolically ({exc}): "
                            "pass `about=` (an equilibrium), or `params=` to search numerically") from None
    samples = _samples(system)
    cands, stable, dist = [], [], []
    qsyms = {position_symbol(q) for q in system.coordinates}
    for sol in sols:
        values = [_sympify(sol[q]).xreplace({u: u0.get(u, 0) for u in getattr(eqs, "inputs", ())})
                  for q in system.coordinates]
        if any(v.free_symbols & qsyms or v.has(sp.nan, sp.zoo, sp.oo) for v in values):
            continue  # a family (a free coordinate): not an isolated point
        verdicts, norm = [], None
        for sample in samples:
            try:
                num = [complex(v.xreplace(sample).evalf()) for v in values]
            except (TypeError, ValueError):
                verdicts.append(None)
                continue
            if any(abs(z.imag) > 1e-12 * max(1.0, abs(z)) for z in num):
                verdicts.append(None)  # not real at these parameter values
                continue
            point = {q: z.real for q, z in zip(system.coordinates, num)}
            verdicts.append(stability(point, {p.name: float(v) for p, v in sample.items()}))
            norm = float(np.linalg.norm([z.real for z in num])) if norm is None else norm
        if norm is None:
            continue
        cands.append(Equilibrium(dict(zip(system.coordinates, values)), sol.multipliers))
        stable.append(True if all(v is True for v in verdicts) else False if False in verdicts else None)
        dist.append(norm)
    if not cands:
        raise AnalysisError(f"{refuse} and sympy found no isolated real equilibrium: pass `about=` (the state to "
                            "linearize at), or `params=` to search numerically")
    order = _rank(cands, stable, dist)
    how = "sympy solve" + (", the one stable at sampled parameter values preferred" if len(cands) > 1 else "")
    return ReferenceChoice(cands[order[0]], tuple(cands[i] for i in order), tuple(stable[i] for i in order), how)
