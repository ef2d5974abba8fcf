r"""Equations of constraint: holonomic, moving and non-holonomic (Wells 2.5, 2.20, 9.12, ch. 12).

* **Holonomic** ``φ(q, t) = 0`` (moving when t appears). Written as an expression (``= 0`` implied) or an
  ``Eq``; declared with :class:`Holonomic` or detected automatically (no velocities).
* **Non-holonomic**, Wells' differential form ``Σ_j a_kj dq_j + a_kt dt = 0``, equivalently linear in the
  velocities ``Σ_j a_kj q̇_j + a_kt = 0``. Declared with :class:`Nonholonomic` (velocity form),
  :class:`Differential` (coefficients) or detected automatically (linear in velocities).

Every constraint is brought to the velocity level ``g_k = Σ_j A_kj q̇_j + b_k = 0`` (for a holonomic one
``A = ∂φ/∂q``, ``b = ∂φ/∂t``). Multipliers enter Lagrange's equations as ``+ Aᵀλ`` on the right-hand side:
``λ_k A_kr`` is the generalized force of constraint on coordinate r (Wells' 𝓕_qr of eq. 12.3). Its
physical size and sign follow the way φ is written: for ``φ = r − l`` (a distance growing away from the
surface) ``λ`` is the normal force pushing outward; for a string ``φ = r − l`` the tension is ``−λ``.

A differential constraint that is integrable (Frobenius: ``ω ∧ dω = 0``) is really holonomic; the engine
reports it (:class:`IntegrableConstraintWarning`) and keeps it as given.
"""

from __future__ import annotations

import itertools
import warnings
from collections.abc import Mapping, Sequence

import sympy as sp

from ..conventions import t
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero
from ..symengine_bridge import FAILURES, carries, jacobian, symengine
from .coordinates import (
    coordinate_name,
    is_coordinate,
    normalize_fields,
    normalize_time,
    position_symbol,
    to_functions,
    to_symbols,
    velocity_symbol,
)

__all__ = [
    "Holonomic",
    "Nonholonomic",
    "Differential",
    "Rough",
    "ConstraintSpec",
    "IntegrableConstraintWarning",
    "normalize_constraints",
    "is_integrable",
]


class IntegrableConstraintWarning(UserWarning):
    """A differential (non-holonomic) constraint turned out to be integrable, i.e. holonomic."""


def _expr(e):
    e = _sympify(e)
    if isinstance(e, sp.Equality):
        return e.lhs - e.rhs
    return e


@record(frozen=True)
class Holonomic:
    """``φ(q, t) = 0``; ``unilateral=True`` marks a contact that can only push (see simulate events)."""

    expr: sp.Expr
    name: str = ""
    unilateral: bool = False

    def __post_init__(self):
        normalize_fields(self, ("expr",))  # sympy.physics.mechanics dynamicsymbols are accepted


@record(frozen=True)
class Rough:
    """A rough holonomic constraint ``φ(q, t) = 0`` with Coulomb friction (Wells 12.5).

    The friction force is ``μ N`` opposite to the sliding velocity ``sliding`` (an expression linear in
    the velocities, e.g. the speed along a wire); its generalized force is
    ``−μ N sign(v_s) ∂v_s/∂q̇``.

    **Sliding over a surface in any direction**: give ``sliding`` as a sequence of two (or three) components
    ``(v_1, v_2)`` of the sliding velocity along orthonormal directions of the surface, each linear in the
    velocities (a particle on a rough plane: ``(ẋ, ẏ)``; on a sphere of radius a in spherical coordinates:
    ``(a θ̇, a sinθ φ̇)``). The friction is then ``−μ N v/|v|``, generalized force
    ``−μ N Σ_i (v_i/|v|) ∂v_i/∂q̇``, and its power ``−μ N |v|``. With ``simulate(friction="events")``
    (default) ``|v|`` is exact and the run ends when the sliding speed falls to 1e-9 (sticking is not
    modelled, nor starting from rest); ``friction="regularize"`` uses ``sqrt(|v|² + ε²)`` with
    ``ε = friction_epsilon``, as for ``sign()`` friction, and runs through stops.

    The normal force is ``N = |λ| · normal`` where ``normal`` (default 1)
    converts the multiplier into the physical normal force: write φ as a signed distance (then
    ``normal = 1``) or give ``normal = |∇φ|`` in Cartesian terms. The friction depends on the unknown
    reaction, so it is solved together with the accelerations each step. Sticking (static friction)
    is not modelled: the simulation stops with an event when the sliding velocity reaches zero.
    """

    expr: sp.Expr
    mu: sp.Expr
    sliding: sp.Expr | tuple
    name: str = ""
    normal: sp.Expr = sp.S.One

    def __post_init__(self):
        if isinstance(self.sliding, (list, tuple, sp.MatrixBase)):  # planar friction: components, kept as a tuple
            object.__setattr__(self, "sliding", tuple(_sympify(v, where="Rough.sliding") for v in self.sliding))
        normalize_fields(self, ("expr", "mu", "normal") + (() if isinstance(self.sliding, tuple) else ("sliding",)))


@record(frozen=True)
class Nonholonomic:
    """``Σ a_j q̇_j + a_t = 0`` written in the velocities."""

    expr: sp.Expr
    name: str = ""

    def __post_init__(self):
        normalize_fields(self, ("expr",))


@record(frozen=True)
class Differential:
    """Wells' differential form ``Σ_j a_j dq_j + a_t dt = 0`` from its coefficients ``{q_j: a_j}``."""

    coefficients: Mapping
    dt: sp.Expr = sp.S.Zero
    name: str = ""

    def __post_init__(self):
        coefficients = {q: _sympify(a, where=f"Differential coefficient of {q}")
                        for q, a in dict(self.coefficients).items()}
        object.__setattr__(self, "coefficients", normalize_time(coefficients))
        object.__setattr__(self, "dt", normalize_time(_sympify(self.dt, where="Differential.dt")))

    def velocity_form(self):
        return sum((_sympify(a) * q.diff(t) for q, a in self.coefficients.items()), sp.S.Zero) + _sympify(self.dt)


@record(frozen=True)
class ConstraintSpec:
    """A validated constraint: ``kind`` is ``"holonomic"`` or ``"nonholonomic"``; ``velocity`` is g = A q̇ + b
    in the coordinate functions; ``position`` is φ for holonomic ones (else None)."""

    kind: str
    name: str
    velocity: sp.Expr
    position: sp.Expr | None
    unilateral: bool = False
    integrable: bool = False
    friction: tuple | None = None  # (mu, sliding velocity or tuple of components, normal factor) for rough ones


def _linear_velocity(vs, coords) -> bool:
    """True when ``vs`` contains velocities and is linear in them."""
    vs = _sympify(vs)
    return bool(vs.atoms(sp.Derivative)) and not any(
        sp.diff(vs, q.diff(t)).has(*[p.diff(t) for p in coords]) for q in coords)


def _velocity_level(phi, coords):
    """``dφ/dt = Σ ∂φ/∂q q̇ + ∂φ/∂t`` with ``∂φ/∂t`` taken at frozen coordinates (differentiated in plain
    symbols: sympy's derivative with respect to ``q(t)`` is several times slower; by symengine for large φ,
    :func:`lagrange.symengine_bridge.jacobian`)."""
    ps = to_symbols(phi, coords)
    variables = [position_symbol(q) for q in coords] + [t]
    fast = jacobian([ps], variables)
    d = fast[0] if fast is not None else [sp.diff(ps, v) for v in variables]
    rate = sum((d[j] * velocity_symbol(q) for j, q in enumerate(coords)), sp.S.Zero) + d[-1]
    return to_functions(rate, coords)


def _velocity_coefficients(e, coords):
    """``(a_j, a_t)`` of ``e = Σ a_j q̇_j + a_t`` (coefficients in the coordinate functions), in plain symbols."""
    es = to_symbols(e, coords)
    vs = [velocity_symbol(q) for q in coords]
    fast = jacobian([es], vs)
    coeffs = fast[0] if fast is not None else [sp.diff(es, v) for v in vs]
    return coeffs, es.xreplace({v: 0 for v in vs}), vs


def normalize_constraints(constraints, coords: Sequence, problems: list) -> tuple[ConstraintSpec, ...]:
    """Classify and validate every constraint; problems are appended to ``problems``.

    Rules: no accelerations; a :class:`Holonomic` constraint has no velocities; a velocity constraint
    is linear in the velocities; only coordinates of the system (and t, parameters) appear.
    """
    out = []
    for k, c in enumerate(constraints or ()):
        label = getattr(c, "name", "") or f"constraint {k + 1}"
        declared = type(c).__name__ if isinstance(c, (Holonomic, Nonholonomic, Differential, Rough)) else None
        friction = None
        if isinstance(c, Rough):
            planar = isinstance(c.sliding, tuple)
            comps = c.sliding if planar else (_sympify(c.sliding),)
            if planar and len(comps) not in (2, 3):
                problems.append(f"{label}: a sliding velocity over a surface has 2 (or 3) components, got "
                                f"{len(comps)}")
                continue
            bad = [vs for vs in comps if not _linear_velocity(vs, coords)]
            if bad:
                what = "component" if planar else "velocity"
                problems.append(f"{label}: the sliding {what} {bad[0]} must be linear in the velocities (for friction "
                                "over a surface give the components of the sliding velocity, e.g. (ẋ, ẏ); |v| is "
                                "formed by the engine)")
                continue
            friction = (_sympify(c.mu), c.sliding if planar else comps[0], _sympify(c.normal))
            c = Holonomic(c.expr, c.name)
            declared = "Holonomic"
        unilateral = bool(getattr(c, "unilateral", False))
        if isinstance(c, Differential):
            bad = [q for q in c.coefficients if not (is_coordinate(q) and q in coords)]
            if bad:
                problems.append(f"{label}: {', '.join(map(str, bad))} in the differential form are not coordinates")
                continue
            e = c.velocity_form()
        else:
            raw = c.expr if isinstance(c, (Holonomic, Nonholonomic)) else c
            try:
                e = _expr(raw)
            except (sp.SympifyError, TypeError):
                problems.append(f"{label}: {raw!r} is not an expression")
                continue
        strays = [f for f in e.atoms(sp.core.function.AppliedUndef) if f not in coords]
        if strays:
            problems.append(f"{label} ({e} = 0) contains {', '.join(map(str, strays))}, not coordinates of this system")
            continue
        orders = [sum(n for v, n in d.variable_count) for d in e.atoms(sp.Derivative)]
        if any(o > 1 for o in orders):
            problems.append(f"{label} ({e} = 0) contains an acceleration: constraints are on positions or velocities")
            continue
        has_vel = bool(orders)
        if declared == "Holonomic" and has_vel:
            problems.append(
                f"{label} is declared holonomic but contains velocities ({e} = 0): a holonomic constraint is "
                "φ(q, t) = 0; declare velocity constraints with Nonholonomic"
            )
            continue
        if not has_vel:
            if declared in ("Nonholonomic", "Differential"):
                problems.append(f"{label} is declared non-holonomic but has no velocities: use Holonomic")
                continue
            if e.free_symbols.isdisjoint({t}) and not e.atoms(sp.core.function.AppliedUndef):
                problems.append(f"{label} ({e} = 0) involves no coordinate")
                continue
            out.append(ConstraintSpec("holonomic", label, _velocity_level(e, coords), e, unilateral,
                                      friction=friction))
            continue
        # velocity constraint: must be linear in the velocities
        coeffs, a_t, vs = _velocity_coefficients(e, coords)
        if any(c_.has(*vs) for c_ in coeffs if c_ != 0):
            problems.append(
                f"{label} ({e} = 0) is not linear in the velocities: Wells' non-holonomic constraints have the "
                "form Σ a_j dq_j + a_t dt = 0"
            )
            continue
        integrable = _frobenius(coeffs + [a_t], [position_symbol(q) for q in coords] + [t])
        if integrable:
            warnings.warn(
                f"{label} ({e} = 0) is integrable: it is really a holonomic constraint (Frobenius condition "
                "holds); it is kept in velocity form, but it can be integrated to φ(q, t) = 0 and used to "
                "eliminate a coordinate",
                IntegrableConstraintWarning,
                stacklevel=3,
            )
        out.append(ConstraintSpec("nonholonomic", label, e, None, False, integrable))
    return tuple(out)


def is_integrable(coefficients: Sequence, a_t, coords: Sequence) -> bool:
    r"""Frobenius test for one Pfaffian form ``ω = Σ a_j dq_j + a_t dt`` in the variables (q, t):
    ``ω ∧ dω = 0``, i.e. for every triple of variables
    ``a_i(∂_j a_k − ∂_k a_j) + a_j(∂_k a_i − ∂_i a_k) + a_k(∂_i a_j − ∂_j a_i) = 0``.

    First numerically (:func:`_frobenius_numeric`): one component clearly nonzero at a random point proves the
    form non-integrable, which settles a rolling constraint in a fraction of a second (the symbolic test took 74 s
    of a bicycle declared with multiplied-out rotation matrices). Only when every component
    vanishes at the sample points (or they cannot be evaluated) is each triple proved zero symbolically.
    """
    coords = list(coords)
    a = [to_symbols(c, coords) for c in coefficients] + [to_symbols(a_t, coords)]
    return _frobenius(a, [position_symbol(q) for q in coords] + [t])


def _frobenius(a: list, syms: list) -> bool:
    """:func:`is_integrable` for coefficients ``a`` (plain symbols) of the differentials of ``syms``."""
    # only variables that carry a coefficient or appear in one matter
    involved = [i for i, s in enumerate(syms) if a[i] != 0 or any(ai.has(s) for ai in a)]
    if len(involved) < 3:
        return True
    if _frobenius_float(a, syms, involved) is False or _frobenius_numeric(a, syms, involved) is False:
        return False
    for i, j, k in itertools.combinations(involved, 3):
        expr = (a[i] * (sp.diff(a[k], syms[j]) - sp.diff(a[j], syms[k]))
                + a[j] * (sp.diff(a[i], syms[k]) - sp.diff(a[k], syms[i]))
                + a[k] * (sp.diff(a[j], syms[i]) - sp.diff(a[i], syms[j])))
        if not is_zero(expr):
            return False
    return True


#: a component of ω ∧ dω counts as clearly nonzero in double precision above this fraction of the size of its
#: terms (rounding is ~1e-16 of it: eight digits of margin)
_FROBENIUS_FLOAT_MARGIN = 1e-8


def _random_point(rnd, symbols: list) -> list:
    """Exact rationals in (0.3, 1.7), negated at random for symbols not known to be nonnegative."""
    out = []
    for s in symbols:
        x = sp.Rational(rnd.randint(3000, 17000), 10000)
        out.append(x if (s.is_positive or s.is_nonnegative) or rnd.random() < 0.5 else -x)
    return out


def _frobenius_float(a: list, syms: list, involved: list) -> bool | None:
    """False when ``ω ∧ dω`` has a clearly nonzero component at each of two random points, evaluated in double
    precision from exact symbolic derivatives (symengine: ``∂a_k/∂q_j`` differentiated exactly, compiled once by
    ``symengine.Lambdify``); None otherwise (a component within rounding of zero, no symengine, or coefficients
    it does not carry), and the caller goes on to the 40-digit test (:func:`_frobenius_numeric`) and the
    symbolic proof.

    "Clearly nonzero" is above :data:`_FROBENIUS_FLOAT_MARGIN` (1e-8) of ``max|a_i| · max(|∂a_k/∂q_j|, |a_i|)``:
    eight digits above double rounding, so an integrable form is never declared non-integrable here; the
    rolling constraints of a bicycle are settled in milliseconds instead of a second each at 40 digits.
    """
    import math
    import random

    se = symengine()
    params = sorted(set().union(*(ai.free_symbols for ai in a)) - set(syms), key=sp.default_sort_key)
    if len(involved) < 3 or se is None or not carries(a, syms + params):
        return None
    idx = list(involved)
    try:
        ses = [se.Symbol(s.name) for s in syms + params]
        sa = [se.sympify(a[i]) for i in idx]
        grads = [e.diff(ses[j]) for e in sa for j in idx]
        f = se.Lambdify(ses, sa + grads, real=True)
    except FAILURES:
        return None
    rnd = random.Random(20456)
    m = len(idx)
    clear = 0
    for _ in range(8):
        point = [float(x) for x in _random_point(rnd, syms + params)]
        try:
            out = [float(x) for x in f(point)]
        except (TypeError, ValueError, ZeroDivisionError, OverflowError, RuntimeError):
            continue
        if not all(math.isfinite(x) for x in out):
            continue
        val = dict(zip(idx, out[:m]))
        grad = {(k, j): out[m + r * m + c] for r, k in enumerate(idx) for c, j in enumerate(idx)}
        # the scale of the derivatives is at least that of the coefficients (the point is O(1)): a derivative
        # that is zero but not recognised as such evaluates to rounding noise and must not set the scale
        top = max(abs(x) for x in out[:m])
        size = top * max([abs(x) for x in out[m:]] + [top])
        if size == 0.0:
            continue
        worst = max(abs(val[i] * (grad[k, j] - grad[j, k]) + val[j] * (grad[i, k] - grad[k, i])
                        + val[k] * (grad[j, i] - grad[i, j])) for i, j, k in itertools.combinations(idx, 3))
        if worst <= _FROBENIUS_FLOAT_MARGIN * size:
            return None  # zero here, to rounding: left to the exact tests
        clear += 1
        if clear == 2:
            return False
    return None


_FROBENIUS_DIGITS = 40
_FROBENIUS_POINTS = 2


def _frobenius_numeric(a: list, syms: list, involved: list) -> bool | None:
    """False when ``ω ∧ dω`` has a component that is clearly nonzero at a random point; None otherwise
    (every component vanishes at :data:`_FROBENIUS_POINTS` points, or no point could be evaluated).

    The coefficients are evaluated in 40-digit arithmetic (mpmath) and differentiated by central differences
    of step 1e-15 (error ~1e-30, relative); a component counts as nonzero above 1e-15 of the size of its
    terms — far above the arithmetic's noise and far below any genuine value, so a False is a proof up to the
    precision used. Random points are exact rationals in (0.3, 1.7) with signs drawn for symbols not known to
    be positive (seeded: the verdict is reproducible).
    """
    import random

    import mpmath

    params = sorted(set().union(*(ai.free_symbols for ai in a)) - set(syms), key=sp.default_sort_key)
    try:
        f = _lambdify(syms + params, a, modules="mpmath")
    except Exception:  # noqa: BLE001 - anything lambdify cannot print is left to the symbolic test
        return None
    rnd = random.Random(20456)
    idx = list(involved)
    n_ok = 0
    with mpmath.workdps(_FROBENIUS_DIGITS):
        h = mpmath.mpf(10) ** -15
        for _ in range(4 * _FROBENIUS_POINTS):
            point = []
            for s in syms + params:
                x = mpmath.mpf(rnd.randint(3000, 17000)) / 10000
                point.append(x if (s.is_positive or s.is_nonnegative) or rnd.random() < 0.5 else -x)
            try:
                val = [mpmath.mpf(v) for v in f(*point)]
                grad = {}
                for j in idx:
                    up, down = list(point), list(point)
                    up[j] += h
                    down[j] -= h
                    fu, fd = f(*up), f(*down)
                    for k in idx:
                        grad[k, j] = (mpmath.mpf(fu[k]) - mpmath.mpf(fd[k])) / (2 * h)
            except (TypeError, ValueError, ZeroDivisionError, OverflowError):
                continue  # complex, undefined or infinite here: try another point
            top = max([abs(val[i]) for i in idx] + [mpmath.mpf(0)])
            # derivative scale floored at the coefficients' (the point is O(1)): the difference quotient of a
            # constant written as sin² + cos² is noise, ~1e-25, and must not set the scale
            size = top * max([abs(g_) for g_ in grad.values()] + [top])
            if not mpmath.isfinite(size):
                continue
            for i, j, k in itertools.combinations(idx, 3):
                comp = (val[i] * (grad[k, j] - grad[j, k]) + val[j] * (grad[i, k] - grad[k, i])
                        + val[k] * (grad[j, i] - grad[i, j]))
                if abs(comp) > mpmath.mpf(10) ** -15 * size:
                    return False
            n_ok += 1
            if n_ok == _FROBENIUS_POINTS:
                return None
    return None


def constraint_names(specs: Sequence[ConstraintSpec]) -> list[str]:
    return [s.name for s in specs]


def describe(spec: ConstraintSpec, coords) -> str:
    kind = spec.kind + (" (integrable)" if spec.integrable else "")
    body = spec.position if spec.position is not None else spec.velocity
    return f"{spec.name}: {kind}, {body} = 0 in ({', '.join(coordinate_name(q) for q in coords)})"
