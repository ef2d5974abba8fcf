r"""Force classification, work along a path and the potential of a conservative field (Wells §5.6–5.8).

A force field with generalized components ``Q_r(q, t)`` is **conservative** (at each fixed t) when the work
``Σ Q_r dq_r`` is an exact differential, i.e. its Jacobian is symmetric (Wells 5.6 in Cartesian form, 5.8 in
generalized coordinates):

.. math:: \frac{\partial Q_r}{\partial q_s} = \frac{\partial Q_s}{\partial q_r}\quad\text{for every pair } r, s.

Then ``Q_r = -∂V/∂q_r`` (5.7) with ``V(q) = -∫_{q_0}^{q} Σ Q_r dq_r`` (5.4), independent of the path. The test
holds in any coordinates: a Cartesian field ``F`` acting on a point ``r(q)`` is first reduced to generalized
forces by virtual work, ``Q_r = F·∂r/∂q_r`` (Wells 4.10), pass ``position=r(q)``.

Forces that depend on t are tested at a fixed instant (Wells 5.11): the potential then depends on t, and
``T + V`` is no longer conserved. Forces that depend on velocities are not fields and are refused.

This is a property of a force field. ``System.derived.is_conservative`` is a different thing: whether the
Jacobi integral of the whole system is conserved (see :class:`~lagrange.derive.equations.Equations`).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence

import sympy as sp
from sympy.core.function import AppliedUndef

from ..conventions import t
from ..errors import AnalysisError, SymbolicTimeoutError
from ..limits import bounded
from ..model.coordinates import coordinate_name, is_coordinate, position_symbol, to_symbols
from ..safe_sympify import sympify as _sympify
from ..simplification import _probe, is_zero, run_bounded
from ..simplification import simplify as _simplify

__all__ = ["generalized_forces", "is_conservative", "nonconservative_pairs", "potential_of", "work_along"]

_INTEGRATE_SECONDS = 4.0  # per attempt (4 attempts) of a symbolic integral
_NUMERIC_INTEGRATE_SECONDS = 0.5  # per attempt before falling back to quadrature


# ------------------------------------------------------------------------------------------------ inputs

def _variables(coords: Sequence) -> tuple[list, list]:
    """(the user's coordinates, plain symbols standing for them)."""
    coords = list(coords)
    if not coords:
        raise AnalysisError("no coordinates given: a force field needs the coordinates it depends on")
    syms = []
    for q in coords:
        if is_coordinate(q):
            syms.append(position_symbol(q))
        elif isinstance(q, sp.Symbol):
            syms.append(q)
        else:
            raise AnalysisError(f"{q!r} is not a coordinate: give coordinate functions (lagrange.coordinates) or "
                                "plain symbols")
    if len(set(syms)) != len(syms):
        raise AnalysisError(f"the coordinates {', '.join(map(str, coords))} repeat a name")
    return coords, syms


def _plain(e, coords, what: str):
    """``e`` in plain symbols; refuses velocities and stray functions of time."""
    try:
        e = _sympify(e) if not isinstance(e, sp.Basic) else e
    except (sp.SympifyError, TypeError) as exc:
        raise AnalysisError(f"{what} = {e!r} is not a sympy expression") from exc
    fn_coords = [q for q in coords if is_coordinate(q)]
    if e.atoms(sp.Derivative):
        raise AnalysisError(f"{what} = {e} depends on velocities: a velocity-dependent force is not a field and "
                            "has no potential (Wells 5.14); declare it as a generalized force or through P")
    e = to_symbols(e, fn_coords) if fn_coords else e
    strays = [f for f in e.atoms(AppliedUndef) if t in f.args]  # other functions (f1(r), Prob 5.1g) are data
    if strays:
        raise AnalysisError(f"{what} = {e} contains {', '.join(map(str, strays))}, which are not among the "
                            f"coordinates {', '.join(_name(q) for q in coords)}")
    return e


def generalized_forces(F, coords: Sequence, position=None) -> tuple:
    r"""The generalized forces ``Q_r`` of a force field, in plain symbols of ``coords``.

    Parameters
    ----------
    F : sequence or mapping
        Without ``position``: the generalized forces, one per coordinate (a sequence in the order of ``coords``
        or a mapping ``{q: Q_q}``; missing coordinates get 0). With ``position``: the Cartesian components of a
        force acting on the point ``position``, as expressions in the coordinates.
    coords : sequence
        Coordinate functions (:func:`lagrange.coordinates`) or plain symbols.
    position : sequence, optional
        The Cartesian position ``r(q)`` of the point the force acts on; then ``Q_r = F·∂r/∂q_r`` (Wells 4.10).

    Returns
    -------
    tuple of sympy expressions, one per coordinate, in plain symbols.

    Raises
    ------
    AnalysisError
        Wrong number of components, a velocity-dependent component, or an unknown function of time.
    """
    coords, syms = _variables(coords)
    if isinstance(F, Mapping):
        unknown = [k for k in F if k not in coords]
        if unknown:
            raise AnalysisError(f"force components given for {', '.join(map(str, unknown))}, which are not among "
                                "the coordinates")
        if position is not None:
            raise AnalysisError("with position= give the Cartesian components of the force as a sequence")
        F = [F.get(q, 0) for q in coords]
    F = list(F)
    if position is None:
        if len(F) != len(coords):
            raise AnalysisError(f"{len(F)} force components for {len(coords)} coordinates: give one generalized "
                                "force per coordinate (or the Cartesian components with position=)")
        return tuple(_plain(f, coords, f"Q[{_name(q)}]") for f, q in zip(F, coords))
    r = [_plain(x, coords, f"position[{i}]") for i, x in enumerate(position)]
    if len(F) != len(r):
        raise AnalysisError(f"{len(F)} Cartesian force components for a {len(r)}-component position")
    Fc = [_plain(f, coords, f"F[{i}]") for i, f in enumerate(F)]
    return tuple(sp.expand(sum((Fk * sp.diff(rk, s) for Fk, rk in zip(Fc, r)), sp.S.Zero)) for s in syms)


def _name(q) -> str:
    return coordinate_name(q) if is_coordinate(q) else str(q)


# ---------------------------------------------------------------------------------------- classification

def nonconservative_pairs(F, coords: Sequence, position=None) -> list:
    r"""The coordinate pairs ``(q_r, q_s, ∂Q_r/∂q_s − ∂Q_s/∂q_r)`` that fail the exactness test (5.8).

    Empty when the field is conservative. Raises :class:`~lagrange.errors.AnalysisError` when a pair can
    neither be proven symmetric nor shown asymmetric (a very large expression); see :func:`is_conservative`.
    """
    coords, syms = _variables(coords)
    Q = generalized_forces(F, coords, position)
    bad = []
    for (i, qi), (j, qj) in itertools.combinations(enumerate(coords), 2):
        curl = sp.diff(Q[i], syms[j]) - sp.diff(Q[j], syms[i])
        if curl == 0:
            continue
        if _probe(curl) is True:
            bad.append((qi, qj, _tidy(curl)))
            continue
        if not is_zero(curl):
            raise AnalysisError(f"cannot decide whether ∂Q[{_name(qi)}]/∂{_name(qj)} = ∂Q[{_name(qj)}]/∂{_name(qi)}: "
                                f"their difference {curl} could be neither proven zero nor evaluated")
    return bad


@bounded("test for a potential")
def is_conservative(F, coords: Sequence, position=None) -> bool:
    r"""True when the force field is conservative (the work ``Σ Q_r dq_r`` is exact), Wells (5.6)/(5.8).

    .. math:: \frac{\partial Q_r}{\partial q_s} = \frac{\partial Q_s}{\partial q_r}\quad(r \ne s)

    The test is local (a curl-free field on a domain with a hole, such as ``(−y, x)/(x² + y²)``, passes it
    although its work around the hole is not zero). A field depending on t is tested at fixed t (Wells 5.11).

    Parameters
    ----------
    F, coords, position
        As in :func:`generalized_forces`: generalized forces (sequence or ``{q: Q}``), or with ``position=r(q)``
        the Cartesian components of the force on that point, in any coordinates.

    Raises
    ------
    AnalysisError
        A component depends on velocities or on a function that is not a coordinate, the component count is
        wrong, or the test cannot be decided.

    Notes
    -----
    This classifies a force field. ``System.derived.is_conservative`` answers a different question: whether
    the system's Jacobi integral is conserved.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y, k = sp.symbols("x y k")
    >>> is_conservative([-k*x, -k*y], [x, y]), is_conservative([-k*y, k*x], [x, y])
    (True, False)
    """
    return not nonconservative_pairs(F, coords, position)


# ------------------------------------------------------------------------------------------------- work

@bounded("work integral")
def work_along(F, coords: Sequence, path, over=None, position=None):
    r"""The work ``W = ∫ Σ_r Q_r dq_r`` of a force field along a path in the coordinates (Wells 5.1–5.3).

    Parameters
    ----------
    F, coords, position
        As in :func:`generalized_forces`.
    path : sequence
        Either one expression per coordinate in a path parameter ``s`` (then ``over = (s, s0, s1)``), or, with
        ``over`` omitted, a polygon: a sequence of points (one value per coordinate each) joined by straight
        segments, e.g. the corners of a rectangle with the first repeated at the end for a closed path.
    over : tuple, optional
        ``(s, s0, s1)``: the path parameter and its range.

    Returns
    -------
    sympy expression
        The work, exact when sympy integrates it (within a few seconds); a Float from 30-digit quadrature when
        the integrand is numeric but has no closed form found quickly.

    Raises
    ------
    AnalysisError
        Bad path (wrong length, parameter missing) or an integral that has symbols and no closed form.

    Notes
    -----
    A field that depends on t is integrated at a fixed instant t (t stays a symbol in the result).
    The work of a conservative field around a closed path is zero; a non-conservative field's work depends on
    the path (Wells Prob. 5.2).

    Examples
    --------
    >>> import sympy as sp
    >>> x, y, k = sp.symbols("x y k")
    >>> work_along([-k*y, k*x], [x, y], [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)])
    2*k
    """
    coords, syms = _variables(coords)
    Q = generalized_forces(F, coords, position)
    if over is None:
        points = [list(p) if isinstance(p, (tuple, list, sp.MatrixBase)) else None for p in path]
        if len(points) < 2 or any(p is None or len(p) != len(coords) for p in points):
            raise AnalysisError(f"a polygon path needs at least two points with {len(coords)} values each; for a "
                                "parametrized path give over=(s, s0, s1)")
        s = sp.Dummy("s")
        total = sp.S.Zero
        for a, b in zip(points, points[1:]):
            seg = [_sympify(ai) + s * (_sympify(bi) - _sympify(ai)) for ai, bi in zip(a, b)]
            total += _segment_work(Q, syms, seg, (s, 0, 1))
        return _tidy(total)
    try:
        s, s0, s1 = over
    except (TypeError, ValueError) as exc:
        raise AnalysisError(f"over must be (s, s0, s1), got {over!r}") from exc
    path = list(path)
    if len(path) != len(coords):
        raise AnalysisError(f"the path gives {len(path)} expressions for {len(coords)} coordinates")
    seg = [_sympify(e) for e in path]
    if not any(e.has(s) for e in seg):
        raise AnalysisError(f"the path does not depend on its parameter {s}")
    return _tidy(_segment_work(Q, syms, seg, (s, s0, s1)))


def _segment_work(Q, syms, seg, over):
    s, s0, s1 = over
    sub = dict(zip(syms, seg))
    integrand = sum((Qr.xreplace(sub) * sp.diff(qr, s) for Qr, qr in zip(Q, seg)), sp.S.Zero)
    integrand = sp.expand(integrand)
    if integrand == 0:
        return sp.S.Zero
    numeric = not (integrand.free_symbols - {s} or _sympify(s0).free_symbols or _sympify(s1).free_symbols)
    seconds = _NUMERIC_INTEGRATE_SECONDS if numeric else _INTEGRATE_SECONDS  # quadrature is the fallback
    try:
        W = run_bounded(sp.integrate, integrand, (s, s0, s1), what="the work integral", seconds=seconds)
    except SymbolicTimeoutError:
        W = sp.Integral(integrand, (s, s0, s1))
    if not W.has(sp.Integral):
        return W
    if not numeric:
        raise AnalysisError(f"the work integral ∫ {integrand} d{s} has no closed form sympy finds within the time "
                            "limit: give numeric values for the parameters to integrate it numerically")
    return sp.Integral(integrand, (s, s0, s1)).evalf(30)


# --------------------------------------------------------------------------------------------- potential

@bounded("potential")
def potential_of(F, coords: Sequence, position=None, reference: Mapping | None = None):
    r"""The potential ``V(q)`` of a conservative field, ``Q_r = −∂V/∂q_r`` (Wells 5.4, 5.7).

    ``V`` is built coordinate by coordinate: ``V = −∫Q_1 dq_1``, then for each next coordinate the part of
    ``−Q_r − ∂V/∂q_r`` (which depends only on ``q_r`` and later coordinates when the field is exact) is
    integrated in ``q_r`` and added. The result is then checked: ``−∂V/∂q_r = Q_r`` for every r.

    Parameters
    ----------
    F, coords, position
        As in :func:`generalized_forces`.
    reference : mapping, optional
        ``{q: q_0}``: the reference configuration where ``V = 0`` (Wells' definition of V as the work done
        from the configuration to the reference one). Without it the additive constant is whatever the
        indefinite integrals give.

    Returns
    -------
    sympy expression in the coordinates (as given: functions stay functions, symbols stay symbols).

    Raises
    ------
    AnalysisError
        The field is not conservative — the message names the first coordinate pair whose cross-derivatives
        differ, and the difference — or an integral has no closed form.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y, z, A = sp.symbols("x y z A")
    >>> potential_of([A*y*z, A*x*z, A*x*y], [x, y, z])
    -A*x*y*z
    """
    coords, syms = _variables(coords)
    bad = nonconservative_pairs(F, coords, position)
    if bad:
        qi, qj, curl = bad[0]
        more = f" (and {len(bad) - 1} more pair(s))" if len(bad) > 1 else ""
        raise AnalysisError(f"the force is not conservative: ∂Q[{_name(qi)}]/∂{_name(qj)} − ∂Q[{_name(qj)}]/∂"
                            f"{_name(qi)} = {curl} ≠ 0{more}, so Σ Q dq is not exact and no potential exists")
    Q = generalized_forces(F, coords, position)
    V = sp.S.Zero
    for r, s in enumerate(syms):
        rest = sp.expand(-Q[r] - sp.diff(V, s))
        if is_zero(rest):
            continue
        V += _integrate(rest, s, coords[r])
    for r, s in enumerate(syms):
        if not is_zero(sp.diff(V, s) + Q[r]):
            raise AnalysisError(f"the potential found, {V}, does not reproduce Q[{_name(coords[r])}] = {Q[r]}; the "
                                "integration went wrong (a piecewise or branch-cut antiderivative?)")
    if reference is not None:
        ref = {}
        for q, v in reference.items():
            if q not in coords:
                raise AnalysisError(f"the reference configuration names {q}, not a coordinate")
            ref[syms[coords.index(q)]] = _sympify(v)
        missing = [_name(q) for q, s in zip(coords, syms) if V.has(s) and s not in ref]
        if missing:
            raise AnalysisError(f"the reference configuration must give {', '.join(missing)}")
        V0 = V.xreplace(ref)
        if V0.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            raise AnalysisError(f"the potential {V} is singular at the reference configuration {reference}")
        V = V - V0
    V = _tidy(V)
    fn = {s: q for q, s in zip(coords, syms) if is_coordinate(q)}
    return V.xreplace(fn) if fn else V


def _integrate(e, s, q):
    try:
        out = run_bounded(sp.integrate, e, s, what=f"the potential's integral in {s}", seconds=_INTEGRATE_SECONDS)
    except SymbolicTimeoutError:
        out = None
    if out is not None and out.has(sp.Integral) and e.atoms(AppliedUndef):
        return out  # an arbitrary given function, e.g. ∫ f1(r) dr (Wells Prob. 5.1g): the integral is the answer
    if out is None or out.has(sp.Integral):
        raise AnalysisError(f"∫ {e} d{_name(q)} has no closed form sympy can find: the potential cannot be written")
    return out


def _tidy(e):
    """Bounded simplify (the input unchanged when large or slow)."""
    return _simplify(_sympify(e), limit=200)
