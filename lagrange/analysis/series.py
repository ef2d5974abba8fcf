r"""Series expansion of a potential about a point (Wells §5.10, eq. 10.6) or for a large distance (Ex. 5.6).

About a finite point ``q₀`` the multivariate Taylor series in the displacements ``δq = q − q₀`` is

.. math:: V(q_0 + \delta q) = V_0 + \sum_r \frac{\partial V}{\partial q_r}\Big|_0 \delta q_r
          + \frac12 \sum_{r,s} \frac{\partial^2 V}{\partial q_r\,\partial q_s}\Big|_0 \delta q_r\,\delta q_s
          + \dots

computed as ``Σ_k (1/k!) dᵏ/dεᵏ V(q₀ + ε δq)|_{ε=0}``. The quadratic part ``½ δqᵀ K δq`` gives the stiffness
matrix ``K`` of small oscillations (Wells 10.2); when K vanishes (springs unstretched at equilibrium, Ex. 5.5,
Prob. 5.5) the quartic term governs and linearization says nothing.

About ``q = ∞`` (one coordinate) the series is in powers of ``1/q`` — the multipole expansion for ``r ≫ s``
(Ex. 5.6, Probs. 5.9, 5.22).
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp
from sympy.core.function import AppliedUndef

from ..errors import AnalysisError, SymbolicTimeoutError
from ..limits import bounded
from ..model.coordinates import (
    canonical_keys,
    coordinate_name,
    is_coordinate,
    normalize_time,
    position_symbol,
    to_symbols,
)
from ..records import record
from ..safe_sympify import sympify as _sympify
from ..simplification import run_bounded

__all__ = ["PotentialSeries", "expand_potential"]

_SERIES_SECONDS = 20.0


@record(frozen=True, slots=True)
class PotentialSeries:
    r"""A truncated series of a potential.

    Attributes
    ----------
    expr : sympy expression
        The truncated series (the sum of :attr:`terms`), in the coordinates as given.
    terms : tuple
        ``terms[k]`` is the homogeneous part of degree k in the displacements ``q − q₀`` (about a finite point),
        or the coefficient times ``q^{−k}`` (about infinity); ``len(terms) == order + 1``.
    about : dict
        The expansion point ``{q: q₀}``.
    order : int
        The highest degree kept.
    gradient : tuple
        ``∂V/∂q`` at the point (finite point only; empty about infinity).
    stiffness : sympy.ImmutableMatrix
        The Hessian ``K = ∂²V/∂q∂q`` at the point (finite point only), so ``terms[2] = ½ δqᵀ K δq``.
    """

    expr: sp.Expr
    terms: tuple
    about: dict
    order: int
    gradient: tuple = ()
    stiffness: sp.ImmutableMatrix | None = None

    def _repr_latex_(self) -> str:
        from ..display import potential_series_latex

        return potential_series_latex(self)

    @property
    def quadratic_form(self) -> sp.Expr:
        """The degree-2 part ``½ δqᵀ K δq`` (about a finite point)."""
        return self.terms[2] if len(self.terms) > 2 else sp.S.Zero


def _check_about(about) -> list:
    if not isinstance(about, Mapping) or not about:
        raise AnalysisError("about must be a mapping {coordinate: value} giving the expansion point")
    coords = list(about)
    for q in coords:
        if not (is_coordinate(q) or isinstance(q, sp.Symbol)):
            raise AnalysisError(f"{q!r} in about= is not a coordinate (a coordinate function or a plain symbol)")
    return coords


@bounded("expansion of the potential")
def expand_potential(V, about: Mapping, order: int = 2) -> PotentialSeries:
    r"""The Taylor series of ``V`` about the point ``about`` to degree ``order`` (Wells §5.10, eq. 10.6).

    .. math:: V \approx \sum_{k=0}^{\mathrm{order}} \frac{1}{k!}
              \Big(\sum_r \delta q_r \frac{\partial}{\partial q_r}\Big)^k V\Big|_{q_0}, \qquad \delta q = q - q_0

    Parameters
    ----------
    V : sympy expression
        The potential, in coordinate functions or plain symbols; other symbols (parameters, t) are constants.
    about : mapping
        ``{q: q₀}``, the expansion point for each coordinate expanded (coordinates not listed are constants).
        A single coordinate may be ``sympy.oo``: then the series is in powers of ``1/q`` up to ``q^{−order}``
        (a far-field / multipole expansion, Ex. 5.6).
    order : int
        The highest degree kept (2 for small oscillations, 4 for quartic potentials).

    Returns
    -------
    PotentialSeries
        ``expr`` (the truncated series), ``terms`` (by degree), ``gradient`` and ``stiffness`` at the point.

    Raises
    ------
    AnalysisError
        ``V`` depends on velocities or on a function not listed, the point is not a mapping, ``order`` is not a
        non-negative integer, V is singular at the point, or ∞ is mixed with other coordinates.

    Examples
    --------
    >>> import sympy as sp
    >>> x, k, s, l0 = sp.symbols("x k s l0", positive=True)
    >>> V = k/2*(sp.sqrt(s**2 + x**2) - l0)**2          # Wells Prob. 5.5
    >>> expand_potential(V, {x: 0}, 4).terms[4]
    k*l0*x**4/(8*s**3)
    """
    if isinstance(about, Mapping):  # sympy's dynamicsymbols: their time becomes lagrange.t, in V too
        about = canonical_keys(about)
    coords = _check_about(about)
    if not isinstance(order, int) or isinstance(order, bool) or order < 0:
        raise AnalysisError(f"order must be a non-negative integer, got {order!r}")
    V = normalize_time(_sympify(V))
    if V.atoms(sp.Derivative):
        raise AnalysisError(f"V = {V} depends on velocities: a potential depends on the coordinates (and t) only")
    fn = [q for q in coords if is_coordinate(q)]
    Vs = to_symbols(V, fn) if fn else V
    syms = [position_symbol(q) if is_coordinate(q) else q for q in coords]
    strays = Vs.atoms(AppliedUndef)
    if strays:
        raise AnalysisError(f"V contains {', '.join(map(str, strays))}, not in about=: list every coordinate V "
                            "depends on, with its expansion point")
    point = {s: _sympify(about[q]) for q, s in zip(coords, syms)}
    back = {position_symbol(q): q for q in fn}
    infinite = [s for s, v in point.items() if v in (sp.oo, -sp.oo)]
    if infinite:
        if len(point) > 1:
            raise AnalysisError("an expansion about ∞ is in one coordinate only (the large distance); expand the "
                                "others separately")
        return _about_infinity(Vs, infinite[0], point[infinite[0]], order, about, back)
    return _about_point(Vs, syms, point, order, about, back)


def _about_point(Vs, syms, point, order, about, back) -> PotentialSeries:
    eps = sp.Dummy("epsilon")
    h = [sp.Dummy(f"h{i}") for i in range(len(syms))]
    W = Vs.xreplace({s: point[s] + eps * hi for s, hi in zip(syms, h)})
    terms = []
    d = W
    for k in range(order + 1):
        if k:
            d = sp.diff(d, eps)
        c = d.xreplace({eps: 0}) / sp.factorial(k)
        c = c.doit()
        if c.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            where = ", ".join(f"{_label(s, back)} = {v}" for s, v in point.items())
            raise AnalysisError(f"V is singular at {where}: its degree-{k} Taylor coefficient is not finite")
        terms.append(c)
    disp = {hi: s - point[s] for s, hi in zip(syms, h)}
    terms = [_light(c).xreplace(disp) for c in terms]
    # gradient and Hessian read off the degree-1 and degree-2 parts (no second differentiation of V)
    grad = tuple(_light(sp.diff(terms[1], s)) if order >= 1 else _light(sp.diff(Vs, s).xreplace(point))
                 for s in syms)
    if order >= 2:
        K = sp.ImmutableMatrix(len(syms), len(syms), lambda i, j: _light(sp.diff(terms[2], syms[i], syms[j])))
    else:
        K = sp.ImmutableMatrix(len(syms), len(syms),
                               lambda i, j: _light(sp.diff(Vs, syms[i], syms[j]).xreplace(point)))
    terms = tuple(c.xreplace(back) for c in terms)
    return PotentialSeries(expr=sp.Add(*terms), terms=terms, about=dict(about), order=order,
                           gradient=grad, stiffness=K)


def _about_infinity(Vs, s, direction, order, about, back) -> PotentialSeries:
    u = sp.Dummy("u", positive=True)
    sign = 1 if direction == sp.oo else -1
    W = Vs.xreplace({s: sign / u})
    try:
        ser = run_bounded(lambda: sp.series(W, u, 0, order + 1).removeO(), what="the series about infinity",
                          seconds=_SERIES_SECONDS)
    except SymbolicTimeoutError as exc:
        raise AnalysisError(f"sympy could not expand V in 1/{_label(s, back)} within the time limit") from exc
    if ser.has(sp.log) or not ser.is_polynomial(u):
        raise AnalysisError(f"V has no power series in 1/{_label(s, back)} (it grows or has logarithms far away)")
    terms = tuple(_light(ser.coeff(u, k) * (sign / s) ** k).xreplace(back) for k in range(order + 1))
    return PotentialSeries(expr=sp.Add(*terms), terms=terms, about=dict(about), order=order)


def _light(e):
    """Cheap tidying (no ``simplify``: it took seconds per coefficient): combine over a common denominator
    when that is not larger, and pull out common factors."""
    e = sp.factor_terms(sp.expand(e))
    c = sp.factor_terms(sp.cancel(e)) if not e.has(sp.Pow) or sp.count_ops(e) < 200 else e
    return c if sp.count_ops(c) <= sp.count_ops(e) else e


def _label(s, back) -> str:
    q = back.get(s)
    return coordinate_name(q) if q is not None else str(s)
