r"""Force classification, work along a path and the potential of a conservative field (Wells §5.6–5.8).

A force field with generalized components ``Q_r(q, t)`` is **conservative** (at each fixed t) when the work
``Σ Q_r dq_r`` is an exact differential, i.e. its Jacobian is symmetric (Wells 5.6 in Cartesian form, 5.8 in
generalized coordinates):

.. math:: \frac{\partial Q_r}{\partial q_s} = \frac{\partial Q_s}{\partial q_r}\quad\text{for every pair } r, s.

Then ``Q_r = -∂V/∂q_r`` (5.7) with ``V(q) = -∫_{q_0}^{q} Σ Q_r dq_r`` (5.4), independent of the path. The test
holds in any coordinates: a Cartesian field ``F`` acting on a point ``r(q)`` is first reduced to generalized
forces by virtual work, ``Q_r = F·∂r/∂q_r`` (Wells 4.10), pass ``position=r(q)``.

Forces that depend on t are tested at a fixed instant (Wells 5.11): the potential then depends on t, and
``T + V`` is no longer conserved. Forces that depend on velocities are not fields: they have no potential and
are refused by the classification, but their work along a parametrized path is defined once the velocity along
it is (the path's tangent times the rate, :func:`work_along`); dry friction's does not depend on the rate.

Integrals are taken in the field's natural variables before sympy's ``integrate`` is asked: a term
``g(B) ∂B/∂q`` holding a power of an expression ``B`` (the square of a distance) is integrated in ``u = B``.
Every potential returned has been verified (its gradient is the field, numerically and symbolically).

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
from ..model.coordinates import coordinate_name, is_coordinate, position_symbol, to_symbols, velocity_symbol
from ..safe_sympify import sympify as _sympify
from ..simplification import _probe, is_zero, run_bounded
from ..simplification import simplify as _simplify
from .natural_variables import (
    expand_keeping_powers,
    integrate_by_substitution,
    numerically_zero,
    vanishes,
    zero_in_bases,
)

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


def _plain(e, coords, what: str, velocities: bool = False):
    """``e`` in plain symbols; refuses stray functions of time, and velocities unless ``velocities``."""
    try:
        e = _sympify(e) if not isinstance(e, sp.Basic) else e
    except (sp.SympifyError, TypeError) as exc:
        raise AnalysisError(f"{what} = {e!r} is not a sympy expression") from exc
    if not isinstance(e, sp.Expr):
        raise AnalysisError(f"{what} = {e!r} is not a scalar expression")
    if e.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise AnalysisError(f"{what} = {e} is not finite (it holds nan or an infinity)")
    fn_coords = [q for q in coords if is_coordinate(q)]
    derivs = e.atoms(sp.Derivative)
    if derivs and not velocities:
        raise AnalysisError(f"{what} = {e} depends on velocities: a velocity-dependent force is not a field and "
                            "has no potential (Wells 5.14); declare it as a generalized force or through P (its work "
                            "along a parametrized path is given by work_along)")
    odd = [d for d in derivs if d.args[0] not in fn_coords or d.variables != (t,)]
    if odd:
        raise AnalysisError(f"{what} = {e} contains {', '.join(map(str, odd))}: only first time derivatives of the "
                            f"coordinates {', '.join(_name(q) for q in coords)} (their velocities) can be taken")
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
    return tuple(sp.expand(Q) for Q in _forces(F, coords, syms, position))


def _forces(F, coords, syms, position, velocities: bool = False) -> tuple:
    """The generalized forces as built (products not expanded: the natural variables stay visible)."""
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
        return tuple(_plain(f, coords, f"Q[{_name(q)}]", velocities) for f, q in zip(F, coords))
    r = [_plain(x, coords, f"position[{i}]") for i, x in enumerate(position)]
    if len(F) != len(r):
        raise AnalysisError(f"{len(F)} Cartesian force components for a {len(r)}-component position")
    Fc = [_plain(f, coords, f"F[{i}]", velocities) for i, f in enumerate(F)]
    return tuple(sum((Fk * sp.diff(rk, s) for Fk, rk in zip(Fc, r)), sp.S.Zero) for s in syms)


def _name(q) -> str:
    return coordinate_name(q) if is_coordinate(q) else str(q)


# ---------------------------------------------------------------------------------------- classification

def nonconservative_pairs(F, coords: Sequence, position=None) -> list:
    r"""The coordinate pairs ``(q_r, q_s, ∂Q_r/∂q_s − ∂Q_s/∂q_r)`` that fail the exactness test (5.8).

    Empty when the field is conservative. Raises :class:`~lagrange.errors.AnalysisError` when a pair can
    neither be proven symmetric nor shown asymmetric (a very large expression); see :func:`is_conservative`.
    """
    coords, syms = _variables(coords)
    bad, undecided = _curl_pairs(_forces(F, coords, syms, position), coords, syms)
    if undecided is not None and not bad:
        raise undecided
    return bad


def _curl_pairs(Q, coords, syms) -> tuple[list, AnalysisError | None]:
    """(the pairs proven asymmetric, the error naming the first pair that could not be decided, or None)."""
    bad, undecided = [], None
    for (i, qi), (j, qj) in itertools.combinations(enumerate(coords), 2):
        curl = expand_keeping_powers(sp.diff(Q[i], syms[j]) - sp.diff(Q[j], syms[i]))
        if curl == 0:
            continue
        if _probe(curl) is True:
            bad.append((qi, qj, _tidy(curl)))
            continue
        if not is_zero(curl) and undecided is None:
            undecided = AnalysisError(
                f"cannot decide whether ∂Q[{_name(qi)}]/∂{_name(qj)} = ∂Q[{_name(qj)}]/∂{_name(qi)}: their "
                f"difference {curl} could be neither proven zero nor shown nonzero at random points")
    return bad, undecided


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
    coords, syms = _variables(coords)
    Q = _forces(F, coords, syms, position)
    bad, undecided = _curl_pairs(Q, coords, syms)
    if bad:
        return False
    if undecided is not None:  # a potential whose gradient is proven to be the field decides it
        try:
            _construct(Q, coords, syms)
        except AnalysisError as exc:
            raise AnalysisError(f"{undecided}, and no potential reproducing the field was found ({exc})") from None
    return True


# ------------------------------------------------------------------------------------------------- work

@bounded("work integral")
def work_along(F, coords: Sequence, path, over=None, position=None, rate=None):
    r"""The work ``W = ∫ Σ_r Q_r dq_r`` of a force along a path in the coordinates (Wells 5.1–5.3).

    The force may depend on the velocities ``q̇`` (dry friction ``−μN v/|v|``, Wells Ex. 6.1; viscous drag).
    Along the path the velocity is the path's tangent times the rate, ``q̇ = (dq/ds) ṡ``:

    .. math:: W = \int_{s_0}^{s_1} \sum_r Q_r\bigl(q(s), q'(s)\,\dot s\bigr)\, q_r'(s)\, ds

    **Convention.** The point moves from ``q(s0)`` to ``q(s1)``: the parameter increases along the motion when
    ``s1 > s0`` and decreases when ``s1 < s0`` (``ṡ`` has the sign of ``s1 − s0``, which must be decidable).
    A force of degree 0 in the velocities (dry friction) does the same work at any rate, so none is needed:
    its work depends on the path and its direction of travel only (``−μN`` times the length for
    Coulomb friction with constant ``N``). The work of any other velocity-dependent force depends on how
    fast the path is run: give ``rate = ṡ`` as an expression in ``s``, or it is refused.

    Parameters
    ----------
    F, coords, position
        As in :func:`generalized_forces`; components may hold the velocities of coordinate functions
        (``q.diff(t)``), not accelerations.
    path : sequence
        Either one expression per coordinate in a path parameter ``s`` (then ``over = (s, s0, s1)``), or, with
        ``over`` omitted, a polygon: a sequence of points (one value per coordinate each) joined by straight
        segments run from the first point to the last (each with ``s`` from 0 to 1), e.g. the corners of a
        rectangle with the first repeated at the end for a closed path.
    over : tuple, optional
        ``(s, s0, s1)``: the path parameter and its range, run from ``s0`` to ``s1``.
    rate : expression, optional
        ``ṡ = ds/dt`` along the path (a function of ``s``; with a polygon, of each segment's 0-to-1 parameter),
        with the sign of ``s1 − s0``. Needed only by rate-dependent forces such as viscous drag.

    Returns
    -------
    sympy expression
        The work, exact when sympy integrates it (within a few seconds); a Float from 30-digit quadrature when
        the integrand is numeric but has no closed form found quickly.

    Raises
    ------
    AnalysisError
        Bad path (wrong length, parameter missing); a velocity-dependent force on a path (or segment) with no
        tangent (a constant path or a repeated polygon point: the direction of motion is undefined), with an
        undecidable direction of travel, with an explicit t, or rate-dependent with no ``rate``; velocities of
        plain-symbol coordinates; an integral that has symbols and no closed form.

    Notes
    -----
    A field that depends on t is integrated at a fixed instant t (t stays a symbol in the result).
    The work of a conservative field around a closed path is zero; a non-conservative field's work depends on
    the path (Wells Prob. 5.2). Where the tangent vanishes at isolated points (a cusp) the friction direction
    is undefined but the integrand stays bounded, and the integral is taken as usual.

    Examples
    --------
    >>> import sympy as sp
    >>> from lagrange import coordinates, t
    >>> x, y, k = sp.symbols("x y k")
    >>> work_along([-k*y, k*x], [x, y], [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)])
    2*k
    >>> X, Y = coordinates("X Y")
    >>> mu, N, R, s = sp.symbols("mu N R s", positive=True)
    >>> speed = sp.sqrt(X.diff(t)**2 + Y.diff(t)**2)
    >>> work_along([-mu*N*X.diff(t)/speed, -mu*N*Y.diff(t)/speed], [X, Y], [R*sp.cos(s), R*sp.sin(s)],
    ...            over=(s, 0, 2*sp.pi))
    -2*pi*N*R*mu
    """
    coords, syms = _variables(coords)
    if rate is not None:
        try:
            rate = _sympify(rate)
        except (sp.SympifyError, TypeError) as exc:
            raise AnalysisError(f"rate = {rate!r} is not an expression (ds/dt as a function of s)") from exc
        if not isinstance(rate, sp.Expr) or rate.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise AnalysisError(f"rate = {rate!r} must be one finite expression: ds/dt as a function of s")
    Q = _forces(F, coords, syms, position, velocities=True)
    vsyms = [velocity_symbol(q) for q in coords if is_coordinate(q)]
    moving = any(Qr.has(v) for Qr in Q for v in vsyms)
    Q = Q if moving else tuple(sp.expand(Qr) for Qr in Q)
    if moving and not all(is_coordinate(q) for q in coords):
        raise AnalysisError("a velocity-dependent force needs every coordinate as a coordinate function "
                            "(lagrange.coordinates), whose velocity is q.diff(t); plain symbols have none")
    vel = {sym: velocity_symbol(q) for q, sym in zip(coords, syms)} if moving else {}
    if over is None:
        points = [list(p) if isinstance(p, (tuple, list, sp.MatrixBase)) else None for p in path]
        if len(points) < 2 or any(p is None or len(p) != len(coords) for p in points):
            raise AnalysisError(f"a polygon path needs at least two points with {len(coords)} values each; for a "
                                "parametrized path give over=(s, s0, s1)")
        s = sp.Dummy("s", real=True)
        total = sp.S.Zero
        for n, (a, b) in enumerate(zip(points, points[1:])):
            seg = [_sympify(ai) + s * (_sympify(bi) - _sympify(ai)) for ai, bi in zip(a, b)]
            total += _segment_work(Q, syms, vel, seg, (s, 0, 1), rate, f"segment {n + 1} of the polygon")
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
    return _tidy(_segment_work(Q, syms, vel, seg, (s, s0, s1), rate, "the path"))


def _segment_work(Q, syms, vel, seg, over, rate, what):
    s, s0, s1 = over
    if not (isinstance(s, sp.Dummy) and s.is_real):  # the parameter runs over real values, whatever it assumes
        real = sp.Dummy(str(s), real=True)
        seg = [e.xreplace({s: real}) for e in seg]
        rate = None if rate is None else rate.xreplace({s: real})
        s, over = real, (real, s0, s1)
    if vel:
        integrand = _along(Q, syms, vel, seg, over, rate, what)
    else:
        sub = dict(zip(syms, seg))
        integrand = sp.expand(sum((Qr.xreplace(sub) * sp.diff(qr, s) for Qr, qr in zip(Q, seg)), sp.S.Zero))
    if integrand == 0:
        return sp.S.Zero
    part, integrand = integrate_by_substitution(integrand, s, _INTEGRATE_SECONDS)  # terms g(B) dB/ds: G(B) at the ends
    part = part.xreplace({s: s1}) - part.xreplace({s: s0}) if part != 0 else part
    if vanishes(integrand):
        return part
    return part + _definite(integrand, s, s0, s1)


def _definite(integrand, s, s0, s1):
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


def _along(Q, syms, vel, seg, over, rate, what):
    """The integrand ``Σ Q_r(q(s), q'(s) ṡ) q_r'(s)`` of a velocity-dependent force (see :func:`work_along`)."""
    s, s0, s1 = over
    if any(Qr.has(t) for Qr in Q):
        raise AnalysisError("a velocity-dependent force that also depends on t (a moving surface, a driven "
                            "frame) has no work along a path alone: the instant at each point is not given; "
                            "integrate the motion and take the power Σ Q q̇ over time instead")
    tangent = [sp.diff(qr, s) for qr in seg]
    if all(vanishes(tc) for tc in tangent):
        raise AnalysisError(f"{what} has no tangent (it does not move: dq/ds is 0 along it), so the velocity of "
                            "a velocity-dependent force such as dry friction −μN v/|v| is undefined there; remove "
                            "the repeated point or the constant piece of the path")
    direction = _sympify(s1) - _sympify(s0)
    if direction.is_zero:
        return sp.S.Zero
    sign = 1 if direction.is_extended_positive else -1 if direction.is_extended_negative else None
    if sign is None:
        raise AnalysisError(f"cannot tell whether {what} is run toward increasing or decreasing values of its "
                            f"parameter ({s1} − {s0} has no known sign), and a velocity-dependent force depends on "
                            "the direction of travel: give limits whose order is known (e.g. positive symbols)")
    if rate is not None:
        mid = rate.xreplace({s: (_sympify(s0) + _sympify(s1)) / 2}) if not direction.has(sp.oo, -sp.oo) else rate
        if mid.is_zero or (mid.is_extended_negative and sign > 0) or (mid.is_extended_positive and sign < 0):
            raise AnalysisError(f"rate = {rate} does not run {what} from s0 to s1 (ds/dt must have the sign of "
                                "s1 − s0 and not vanish)")
    lam = sp.Dummy("sdot", positive=True)
    speed = sign * lam if rate is None else rate
    sub = dict(zip(syms, seg))
    sub.update({vel[q]: tc * speed for q, tc in zip(syms, tangent)})
    integrand = sum((Qr.xreplace(sub) * tc for Qr, tc in zip(Q, tangent)), sp.S.Zero)
    if integrand.has(sp.nan, sp.zoo):
        raise AnalysisError(f"the force is undefined along {what} (0/0 where its tangent vanishes?): {integrand}")
    if rate is None and integrand.has(lam):
        if not numerically_zero(sp.diff(integrand, lam), [integrand]):
            raise AnalysisError("the work of this velocity-dependent force depends on how fast the path is run "
                                "(it is not of degree 0 in the velocities, as dry friction is): give rate=ds/dt "
                                "as a function of the path parameter")
        integrand = integrand.xreplace({lam: 1})
    return _tidy(integrand)


# --------------------------------------------------------------------------------------------- potential

@bounded("potential")
def potential_of(F, coords: Sequence, position=None, reference: Mapping | None = None):
    r"""The potential ``V(q)`` of a conservative field, ``Q_r = −∂V/∂q_r`` (Wells 5.4, 5.7).

    ``V`` is built coordinate by coordinate: ``V = −∫Q_1 dq_1``, then for each next coordinate the part of
    ``−Q_r − ∂V/∂q_r`` (which depends only on ``q_r`` and later coordinates when the field is exact) is
    integrated in ``q_r`` and added. Each integral is first taken in the field's natural variables: the terms
    holding a power ``B(q)^p`` of an expression (a distance ``d = B^{1/2}``, for instance) are integrated in
    ``u = B`` when they are ``g(u) ∂B/∂q_r`` — so a central field ``f(d) d̂`` is integrated as ``f`` over ``d``
    in any coordinates — and only what is left goes to sympy's ``integrate``, unexpanded first.

    The result is verified before it is returned: ``∂V/∂q_r + Q_r`` must vanish at six random points (below
    1e-20 of the terms' size in 30-digit arithmetic) and be proven zero symbolically (expansion; powers of a
    common base compared as powers of one symbol; the bounded zero test of :mod:`lagrange.simplification`).

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
        differ, and the difference — or it is (or may be) conservative but no closed form was found and
        verified; that message says what to try.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y, z, A = sp.symbols("x y z A")
    >>> potential_of([A*y*z, A*x*z, A*x*y], [x, y, z])
    -A*x*y*z
    >>> G, M, m, l, h = sp.symbols("G M m l h", positive=True)
    >>> th = sp.Symbol("theta", real=True)
    >>> bob, centre = sp.Matrix([l*sp.sin(th), -l*sp.cos(th)]), sp.Matrix([0, -h])   # sphere below the pivot
    >>> d = bob - centre
    >>> V = potential_of(list(-G*M*m*d/d.norm()**3), [th], position=list(bob))
    >>> sp.simplify(V + G*M*m/sp.sqrt(h**2 - 2*h*l*sp.cos(th) + l**2))
    0
    """
    coords, syms = _variables(coords)
    Q = _forces(F, coords, syms, position)
    bad, undecided = _curl_pairs(Q, coords, syms)
    if bad:
        qi, qj, curl = bad[0]
        more = f" (and {len(bad) - 1} more pair(s))" if len(bad) > 1 else ""
        raise AnalysisError(f"the force is not conservative: ∂Q[{_name(qi)}]/∂{_name(qj)} − ∂Q[{_name(qj)}]/∂"
                            f"{_name(qi)} = {curl} ≠ 0{more}, so Σ Q dq is not exact and no potential exists")
    try:
        V = _tidy(_construct(Q, coords, syms))
    except AnalysisError as exc:
        if undecided is None:
            raise AnalysisError(f"{exc}. The field passes the exactness test (5.8), so a potential exists locally, "
                                f"but no closed form was found and verified: {_TRY}") from None
        raise AnalysisError(f"{exc}; whether the field is conservative could not be decided either ({undecided}): "
                            f"{_TRY}") from None
    if reference is not None:
        V = _tidy(V - _value_at(V, reference, coords, syms))
    fn = {s: q for q, s in zip(coords, syms) if is_coordinate(q)}
    return V.xreplace(fn) if fn else V


def _value_at(V, reference, coords, syms):
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
        raise AnalysisError(f"the potential {V} is singular at the reference configuration {dict(reference)}")
    return V0


_TRY = ("try the field in other coordinates (Cartesian components with position=r(q) often integrate where "
        "generalized forces do not), check that the same distance is written the same way in every component, or "
        "take V numerically as the work to a reference configuration (work_along with numeric parameters)")


def _construct(Q, coords, syms):
    """A verified ``V`` with ``−∂V/∂q_r = Q_r`` for every r, or :class:`AnalysisError` saying what to try."""
    V = sp.S.Zero
    for r, s in enumerate(syms):
        rest = -Q[r] - sp.diff(V, s)
        if vanishes(rest):
            continue
        V += _antiderivative(rest, s, coords[r])
    _verify(V, Q, coords, syms)
    return V


def _antiderivative(e, s, q):
    """``∫ e ds``: in the natural variables first (:func:`integrate_by_substitution`), then by sympy."""
    part, rest = integrate_by_substitution(e, s, _INTEGRATE_SECONDS)
    if vanishes(rest):
        return part
    for form in dict.fromkeys((rest, expand_keeping_powers(rest))):  # as given, then expanded (when that differs)
        try:
            out = run_bounded(sp.integrate, form, s, what=f"the potential's integral in {s}",
                              seconds=_INTEGRATE_SECONDS)
        except SymbolicTimeoutError:
            continue
        if not out.has(sp.Integral):
            return part + out
        if rest.atoms(AppliedUndef):
            return part + out  # an arbitrary given function, ∫ f1(r) dr (Wells Prob. 5.1g): the integral is the answer
    raise AnalysisError(f"no closed form found for ∫ {rest} d{_name(q)}")


def _verify(V, Q, coords, syms):
    """Raise unless ``∂V/∂q_r + Q_r`` vanishes at random points and is proven zero, for every r."""
    for r, s in enumerate(syms):
        dV = sp.diff(V, s)
        residual = dV + Q[r]
        if numerically_zero(residual, [dV, Q[r]]) is False:
            raise AnalysisError(f"the potential found, {V}, does not reproduce Q[{_name(coords[r])}] = {Q[r]} "
                                f"(−∂V/∂{_name(coords[r])} differs at random points: a piecewise or branch-cut "
                                "antiderivative?)")
        if not (expand_keeping_powers(residual) == 0 or zero_in_bases(residual) or is_zero(residual)):
            raise AnalysisError(f"the candidate potential {V} reproduces Q[{_name(coords[r])}] at random points but "
                                "could not be proven to")


def _tidy(e):
    """Bounded simplify (the input unchanged when large or slow)."""
    return _simplify(_sympify(e), limit=200)
