r"""Whether a Taylor-series method can be trusted on a system: analytic, and not nearly non-analytic, equations.

The Taylor method (and heyoka) chooses its step from the decay of the solution's series coefficients: the step is
a fraction of the radius of convergence that the last coefficients suggest. That is sound for an analytic
right-hand side whose singularities show in the coefficients (Kepler's :math:`1/r`: the coefficients grow as the
orbit nears :math:`r = 0`). It fails when the right-hand side is locally almost polynomial and changes within a
short distance ahead: :math:`-kx/\sqrt{x^2 + \varepsilon^2}` is :math:`\approx -k` for :math:`|x| \gg \varepsilon`,
its non-polynomial part is of size :math:`\varepsilon^2`, the coefficients suggest a radius many times the true one,
and a step jumps across the layer :math:`|x| \lesssim \varepsilon` where the force reverses. Analysed here, in one
pass over the expression trees of ``M`` and ``f`` (and the work rate of a non-conservative system):

1. **Non-analytic or unknown functions** — ``Abs``, ``sign``, ``Piecewise``, ``Min``/``Max``, ``Heaviside``,
   ``floor``/``ceiling`` and every function other than ``sin cos tan exp log sinh cosh tanh`` (``atan`` too, which
   the tape cannot expand), and user (undefined) functions, whose smoothness is unknown: always an obstacle.
2. **Kinks**: a non-integer power of an argument that is a single even power :math:`w\,u^{2k}` or a small
   polynomial with a factor of even multiplicity (``sqrt(x**2 + 2*x*y + y**2)``; ``sqrt(x**2)`` itself reaches
   the equations as ``Abs(x)``, real coordinates): non-analytic on the hypersurface ``u = 0``, which a motion
   crosses, and invisible to the series on either side.
3. **Near-singularities** of a *singular site* — the base of a non-integer or negative power, the argument of
   ``log``, ``tanh`` or ``atan`` — judged with the run's parameter values. A base
   :math:`g = c + h` with a constant :math:`c > 0` and a state-dependent part :math:`h \ge 0` (a sum of even
   powers with non-negative coefficients, or a small polynomial of even multiplicities such as :math:`(x+y)^2`
   expanded: the form of every regularization, :math:`x^2 + \varepsilon^2`, :math:`|v|^2 + \varepsilon^2`) never
   vanishes on real states but does at complex ones at the relative distance
   :math:`\rho = \sqrt{c/|h|_{\text{scale}}}` (exact when h is a square); ``tanh(u)`` has poles at
   :math:`u = \pm i\pi/2`, ``atan(u)`` branch points at :math:`u = \pm i`: :math:`\rho = (\pi/2)/|u|_{\text{scale}}`,
   :math:`1/|u|_{\text{scale}}`. The scale is the largest value over the initial state and the *scale states*:
   per coordinate the extent :math:`Q = \max(|q_0|, \dot q_0^2/a)`, :math:`a = \max_i|\ddot q_{0,i}|` (the
   distance over which the motion turns; :math:`|\dot q_0| T` when nothing accelerates, :math:`|\ddot q_0| T^2/2`
   from rest at the origin) and the speed :math:`V = \max(|\dot q_0|, \sqrt{|\ddot q_0| Q})`, with all signs +
   and alternating. A site with
   :math:`\rho <` :data:`NEAR` (a tenth) is an obstacle.

A *genuine* singularity — an argument that vanishes on real states and changes sign there, or whose zero set has
codimension 2 or more (Kepler's and a planar spring's :math:`x^2 + y^2`, zero only at a point that a generic
motion misses) — is not an obstacle: the coefficients show it when a motion approaches it, and every method fails
at a collision alike.

:data:`NEAR` is measured (``tests/test_analyticity.py``; :math:`V = k\sqrt{x^2+\varepsilon^2}` from x = 1 and a
block with friction :math:`\mu\tanh(v/\varepsilon)`, against Radau at rtol 1e-12): at :math:`\rho \ge 0.1` the
Taylor method stays within a few tolerances, at :math:`\rho = 0.047` (tanh) and :math:`10^{-4}` (sqrt) it is
wrong by 10³–10⁷ tolerances.

:func:`obstacle` gives the first obstacle with its reason; ``method="auto"`` then excludes the Taylor method and
says why in its method line (:func:`lagrange.integrate.auto.choose`, which also estimates stiffness at the
*probe*, the real state nearest a near-singularity: the sticking phase of regularized friction is stiff there), and
an explicit ``method="taylor"`` or ``"heyoka"`` warns with :class:`~lagrange.errors.NonAnalyticWarning`
(:func:`lagrange.integrate.prepare.warn_untrusted`; non-analytic functions the tape refuses anyway). The
integrator reaches this module through :meth:`NumericModel.taylor_obstacle
<lagrange.codegen.numeric.NumericModel.taylor_obstacle>`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from ..conventions import t as _t
from ..records import record

__all__ = ["Obstacle", "obstacle", "scale_states", "NEAR"]

#: a near-singularity closer than this fraction of the motion's scale is an obstacle for the Taylor method
NEAR = 0.1
_ENTIRE = (sp.sin, sp.cos, sp.exp, sp.sinh, sp.cosh)
_SINGULAR_ARGUMENT = {sp.log: "log", sp.tanh: "tanh", sp.atan: "atan", sp.tan: "tan"}
#: analytic where defined, but without a recurrence in the Taylor tape (named as such, not as "not analytic")
_ANALYTIC_ELSEWHERE = (sp.asin, sp.acos, sp.asinh, sp.acosh, sp.atanh, sp.cot, sp.sec, sp.csc, sp.coth, sp.erf)


@record(frozen=True, slots=True)
class Obstacle:
    """Why a Taylor-series method cannot be trusted on the equations.

    Attributes
    ----------
    what : the offending sub-expression (printed)
    where : the equation it is in (``"the generalized force of x"``)
    reason : ``"not analytic"``, ``"a user function (smoothness unknown)"``, ``"a kink"`` or
        ``"a near-singularity at relative distance 1e-06"``
    kind : ``"function"`` (the Taylor tape refuses it: :class:`~lagrange.codegen.tape.TapeError`), ``"kink"`` or
        ``"near"`` (the tape runs it, and may return a wrong answer)
    probe : ``((state index, value), ...)``: the real state nearest a near-singularity (empty otherwise)
    """

    what: str
    where: str
    reason: str
    kind: str = "function"
    probe: tuple = ()

    def describe(self) -> str:
        """One line for a method label or a warning."""
        return f"{self.reason}: {self.what} in {self.where}"


def _places(eqs) -> list[tuple[str, sp.Expr]]:
    from ..model.coordinates import coordinate_name

    names = [coordinate_name(c) for c in eqs.coordinates]
    places = [(f"the generalized force of {names[i]}", e) for i, e in enumerate(eqs.forcing)]
    places += [(f"the mass matrix entry M[{names[i]}, {names[j]}]", eqs.mass_matrix[i, j])
               for i in range(eqs.n) for j in range(i, eqs.n)]
    if not eqs.is_conservative:
        places.append(("the power dh/dt of the work integral", eqs.jacobi_rate))
    return places


def _sites(eqs) -> tuple[Obstacle | None, list[tuple[str, sp.Expr, sp.Expr, str]]]:
    """One pass over the expression DAGs: the first non-analytic function (an Obstacle), else None, and the
    singular sites ``(kind, argument, node, where)``; kind ``"power"`` (non-integer), ``"division"``, ``"log"``,
    ``"tanh"``, ``"atan"`` or ``"tan"``."""
    seen: set = set()
    sites: list = []
    for where, root in _places(eqs):
        stack = [sp.sympify(root)]
        while stack:
            e = stack.pop()
            if e.is_Atom or e in seen:
                continue
            seen.add(e)
            if e.is_Add or e.is_Mul:
                stack.extend(e.args)
            elif e.is_Pow:
                base, exp = e.args
                if exp.is_Integer:
                    if exp.is_negative:
                        sites.append(("division", base, e, where))
                elif exp.is_Number:
                    sites.append(("power", base, e, where))
                else:  # b**x = exp(x log b)
                    sites.append(("log", base, e, where))
                stack.extend(e.args)
            elif e.func in _ENTIRE:
                stack.extend(e.args)
            elif e.func in _SINGULAR_ARGUMENT and len(e.args) == 1:
                sites.append((_SINGULAR_ARGUMENT[e.func], e.args[0], e, where))
                stack.extend(e.args)
            elif isinstance(e, AppliedUndef):
                return Obstacle(str(e), where, "a user function (its smoothness is unknown)"), sites
            elif e.func in _ANALYTIC_ELSEWHERE:
                return Obstacle(str(e), where, f"a function the Taylor tape does not expand ({e.func.__name__})"), sites
            else:
                return Obstacle(str(e), where, f"not analytic ({type(e).__name__})"), sites
    return None, sites


def scale_states(y0, rates, horizon: float) -> list[np.ndarray]:
    """The states the scale of an argument is measured at (see the module docstring): ``y0``, then the
    per-coordinate extents and speeds with all signs +, then with alternating signs. ``rates`` is ``f(y0)``
    (velocities then accelerations)."""
    y0 = np.asarray(y0, dtype=float)
    n = y0.size // 2
    q0, v0 = np.abs(y0[:n]), np.abs(y0[n:2 * n])
    a0 = np.abs(np.asarray(rates, dtype=float)[n:2 * n]) if rates is not None else np.zeros(n)
    T = abs(float(horizon))
    top = float(np.max(a0, initial=0.0))  # a coordinate that does not accelerate yet turns with the others
    travel = v0**2 / top if top > 0 else v0 * T
    Q = np.maximum(q0, travel)
    Q = np.where((Q == 0) & (a0 > 0), a0 * T**2 / 2, Q)
    V = np.maximum(v0, np.sqrt(a0 * Q))
    plus = np.concatenate([Q, V])
    signs = np.where(np.arange(2 * n) % 2 == 0, 1.0, -1.0)
    return [y0[:2 * n], plus, plus * signs]


def obstacle(eqs, values: Mapping | None = None, y0=None, rates=None, horizon: float = 1.0,
             t0: float = 0.0) -> Obstacle | None:
    """The first reason a Taylor-series method cannot be trusted on ``eqs`` (see the module docstring), or None.

    Parameters
    ----------
    eqs : the derived Equations (friction treatment applied)
    values : ``{symbol: number}`` for every numeric parameter (None: only what holds for all values — the
        non-analytic functions and kinks — is judged)
    y0 : the initial state, shape (2n,); rates : ``f(t0, y0)``, shape ≥ (2n,) (None: no accelerations)
    horizon : the length of the run (for the scale of a coordinate that moves without acceleration)

    >>> from lagrange import System, coordinates, parameters, t
    >>> x = coordinates("x"); k, e = parameters("k epsilon")
    >>> s = System([x], T=x.diff(t)**2 / 2, V=k * (x**2 + e**2) ** sp.Rational(1, 2))
    >>> print(obstacle(s.derived, {k: 1.0, e: 1e-6}, [1.0, 0.0], [0.0, -1.0], 20.0).describe())
    a near-singularity at relative distance 1e-06: 1/sqrt(epsilon**2 + x**2) in the generalized force of x
    >>> obstacle(s.derived, {k: 1.0, e: 0.5}, [1.0, 0.0], [0.0, -1.0], 20.0) is None
    True
    """
    found, sites = _sites(eqs)
    if found is not None:
        return found
    state = list(eqs.q) + list(eqs.qd)
    numeric = values is not None and y0 is not None
    subs = {s: sp.Float(float(v)) for s, v in (values or {}).items()}
    points = scale_states(y0, rates, horizon) if numeric else []
    t_end = max(abs(float(t0)), abs(float(t0) + float(horizon)))
    worst: tuple[float, Obstacle] | None = None
    for kind, arg, node, where in sites:
        shown = str(node)
        if kind == "power":
            kink = _kink(arg, state)
            if kink is not None:
                return Obstacle(shown, where, f"a kink where {kink} = 0 (not analytic there; a motion crosses it)",
                                "kink")
        if not numeric:
            continue
        judged = _near(kind, arg.xreplace(subs), state, points, t_end)
        if judged is not None and (worst is None or judged[0] < worst[0]):
            rho, probe = judged
            worst = (rho, Obstacle(shown, where, f"a near-singularity at relative distance {rho:.2g}", "near", probe))
    return None if worst is None else worst[1]


def _kink(arg, state) -> str | None:
    """``u`` when ``arg`` is ``w·u^(2k)`` (w a positive constant, u depending on the state), or a small polynomial
    in the state with a factor of even multiplicity (``x² + 2xy + y² = (x + y)²``), else None."""
    moving = [f for f in sp.Mul.make_args(arg) if f.free_symbols & set(state)]
    fixed = sp.Mul(*(f for f in sp.Mul.make_args(arg) if not f.free_symbols & set(state)))
    if len(moving) != 1 or not fixed.is_positive:
        return None
    u = moving[0]
    if u.is_Pow and u.exp.is_Integer and u.exp % 2 == 0:
        return str(u.base)
    even = _square_free(u, state)
    return str(even[0][0]) if even and even[0][1] else None


def _square_free(u, state) -> list[tuple[sp.Expr, bool]] | None:
    """The state-dependent factors of a small polynomial ``u`` in the state with whether each has even
    multiplicity (even ones first), or None (not a small polynomial, or a negative constant factor)."""
    used = [s for s in state if s in u.free_symbols]
    if not used or not u.is_Add or sp.count_ops(u) > _SMALL_POLYNOMIAL or not u.is_polynomial(*used):
        return None
    const, factors = sp.sqf_list(u, *used)
    if not sp.sympify(const).is_positive:
        return None
    found = [(f.as_expr(), k % 2 == 0) for f, k in factors if f.free_symbols & set(used)]
    return sorted(found, key=lambda fk: not fk[1])


#: a polynomial argument up to this many operations is factored (a square-free factorization)
_SMALL_POLYNOMIAL = 60


def _near(kind: str, arg, state, points, t_end) -> tuple[float, tuple] | None:
    """``(ρ, probe)`` of a site (arguments with parameter values) when ``ρ <`` :data:`NEAR`, else None."""
    syms = [s for s in state if s in arg.free_symbols]
    if not syms and _t not in arg.free_symbols:
        return None
    if kind in ("tanh", "atan"):
        distance = math.pi / 2 if kind == "tanh" else 1.0
        scale = _largest(arg, state, points, t_end)
        rho = distance / scale if scale else math.inf
        return (rho, _probe(arg, state)) if rho < NEAR else None
    if kind == "tan":
        return None  # real poles: genuine
    c, h = arg.as_independent(*state, _t, as_Add=True)
    if not (c.is_Number and c > 0) or not h.args or not _nonnegative(h, state):
        return None
    scale = _largest(h, state, points, t_end)
    rho = math.sqrt(float(c) / scale) if scale else math.inf
    return (rho, _probe(h, state)) if rho < NEAR else None


def _nonnegative(h, state) -> bool:
    """``h`` a sum of terms ``w·Π u_i^(2k_i)`` with ``w ≥ 0`` (structurally, no assumptions queried), or a small
    polynomial whose factors all have even multiplicity (``x² + 2xy + y²``)."""
    even = _square_free(h, state)
    if even and all(k for _, k in even):
        return True
    for term in sp.Add.make_args(h):
        coeff, rest = term.as_coeff_Mul()
        if coeff.is_negative:
            return False
        for f in sp.Mul.make_args(rest):
            if not (f.is_Pow and f.exp.is_Integer and f.exp % 2 == 0) and f.free_symbols:
                return False
            if not f.free_symbols and f.is_negative:
                return False
    return True


def _largest(e, state, points, t_end) -> float:
    """max |e| over the scale states (0 when none gives a finite number)."""
    best = 0.0
    for y in points:
        at = dict(zip(state, (sp.Float(float(v)) for v in y))) | {_t: sp.Float(t_end)}
        try:
            v = abs(complex(e.xreplace(at).evalf()))
        except (ArithmeticError, ValueError, TypeError):
            continue
        if math.isfinite(v):
            best = max(best, v)
    return best


def _probe(h, state) -> tuple:
    """The real state nearest the zero of ``h`` where each even-power base ``u`` is linear in one state
    variable (``u = αy + β → y = −β/α``): ``((index, value), ...)``; empty when none is."""
    probe = {}
    for term in sp.Add.make_args(h):
        for f in sp.Mul.make_args(term):
            u = f.base if f.is_Pow else f
            used = [s for s in state if s in u.free_symbols]
            if len(used) != 1:
                continue
            poly = sp.Poly(u, used[0]) if u.is_polynomial(used[0]) else None
            if poly is None or poly.degree() != 1 or poly.free_symbols - {used[0]}:
                continue
            a, b = (float(v) for v in poly.all_coeffs())
            probe[state.index(used[0])] = -b / a
    return tuple(sorted(probe.items()))

