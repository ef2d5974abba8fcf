r"""Linearization and small oscillations (Wells ch. 10), also on a constraint manifold.

About an equilibrium ``q₀`` (``q = q₀ + s``) the equations become, to first order,

.. math:: a\,\ddot s + b\,\dot s + c\,s = F(t),

with ``a = (∂²T/∂q̇∂q̇)₀`` (Wells 10.4), ``b = −(∂f/∂q̇)₀`` (damping from P, ``b = −∂²P/∂q̇∂q̇``, plus any
gyroscopic terms) and ``c = −(∂f/∂q)₀`` (``= (∂²V/∂q∂q)₀`` for a conservative system, 10.6).
Undamped frequencies solve ``|a ω² − c| = 0`` (10.10, note the book's order); damped characteristic
roots solve ``|a λ² + b λ + c| = 0`` (10.30). Normal coordinates ``g = Φᵀ a s`` with the modes Φ
normalized so that ``Φᵀ a Φ = 1`` (Wells' c_s, 10.21) give ``T = ½Σġ²``, ``V = ½Σω²g²`` (10.22). About a steady
motion b is gyroscopic (skew-symmetric, Wells 11.12): :func:`normal_modes` then takes the frequencies
``|Im λ|`` from the roots, never from (a, c) alone, and refuses a damping (symmetric) b.
Zero roots (free translation or rotation) and repeated roots are handled by the eigen-solver.

Every linearization also gives the first-order state-space model ``ẋ = 𝒜 x + ℬ δu`` (inputs ``u``:
``system.derived.inputs`` or the ``inputs=`` argument). **Constrained systems** (holonomic ``φ(q) = 0`` and
non-holonomic ``A q̇ + b = 0``) are linearized on the constraint manifold, in independent coordinates ``s``
and independent speeds ``w`` chosen automatically (or given with ``independent=`` and ``speeds=``): see
:mod:`lagrange.analysis.manifold` for the method and its equations. With holonomic constraints only, the
result also has Wells' ``a, b, c`` in the independent coordinates (so :func:`normal_modes` gives frequencies
and mode shapes, also in all coordinates); a non-holonomic system has fewer independent speeds than
coordinates and only the first-order form (use :func:`characteristic_roots`). A reference state off the
manifold, moving (explicit-time) or rough constraints, and a friction term at its switching point are
refused with :class:`~lagrange.errors.AnalysisError`.

With ``params`` the linearization is numeric (float matrices from exact derivatives, generated once per
system and reused for every operating point); without, symbolic (small systems, as Wells does).
"""

from __future__ import annotations

import dataclasses
import logging
from collections.abc import Mapping, Sequence
from dataclasses import field

import numpy as np
import scipy.linalg
import sympy as sp

from ..conventions import t
from ..errors import AnalysisError, LagrangeError
from ..limits import bounded
from ..model.coordinates import canonical_key, coordinate_name, position_symbol, velocity_symbol
from ..records import record
from ..safe_sympify import expression as _expression
from ..safe_sympify import sympify as _sympify
from ..simplification import factor, is_zero, simplify, solve
from . import manifold, operating_point
from .equilibria import Equilibrium, equilibria, equilibrium_equations

log = logging.getLogger("lagrange.analysis")

__all__ = ["equilibrium_equations", "equilibria", "Equilibrium", "linearize", "LinearModel", "Modes",
           "normal_modes", "characteristic_roots"]


def _by_name(params: Mapping | None) -> dict:
    return {getattr(k, "name", str(k)): _expression(v, where=f"parameter {getattr(k, 'name', k)}")
            for k, v in (params or {}).items()}


def _numeric_matrix(Mx, params: Mapping | None, what: str) -> np.ndarray:
    """A sympy matrix with parameter values (by name) substituted, as floats."""
    if isinstance(Mx, np.ndarray):
        return Mx
    by_name = _by_name(params)
    sub = {s: by_name[s.name] for s in Mx.free_symbols if s.name in by_name}
    out = Mx.subs(sub)
    if out.free_symbols:
        raise LagrangeError(f"missing parameter values for {sorted(map(str, out.free_symbols))} in {what}")
    if out.shape[0] * out.shape[1] == 0:
        return np.zeros(out.shape)
    return np.array(out.evalf(), dtype=float)


@record(frozen=True)
class LinearModel:
    """A linearization about a reference state.

    ``a s̈ + b ṡ + c s = F + G δu`` (Wells' a, b, c of ch. 10–11; ``G`` = :attr:`input_forces`) in the
    independent coordinates, when a second-order form exists (unconstrained or holonomic constraints only;
    else ``a = b = c = None``), and always the first-order form ``ẋ = 𝒜 x + ℬ δu`` (:attr:`A`, :attr:`B`) on
    the states ``x = (s, w)``: the independent coordinates then the independent speeds.

    Attributes
    ----------
    coordinates : tuple — the independent coordinates s (all coordinates when unconstrained)
    a, b, c : sympy matrices (symbolic route) or float arrays (numeric route, ``params`` given), or None
    forcing : ``F`` at the reference (zero at an equilibrium)
    about : dict — the reference coordinates ``{coordinate: value}``
    state_matrix, input_matrix : 𝒜 and ℬ (None: computed from a, b, c on access)
    speeds : tuple — the independent speeds ``q̇`` (derivatives)
    inputs : tuple — input symbols u (columns of ℬ)
    all_coordinates : tuple — every coordinate of the system
    coordinate_map : ``C₀`` (n × len(s)) with ``δq = C₀ s`` in all coordinates (None: identity)
    velocities : dict — reference velocities ``{q̇: value}``
    multipliers : dict — ``{constraint name: λ₀}`` at the reference
    params : dict or None — the parameter values of the numeric route
    input_forces : ``G`` (second-order form) or None
    acceleration : tuple or None — the reference accelerations ``q̈₀`` of all coordinates (zero at an
        equilibrium or a steady motion; None when not computed: unconstrained symbolic route, see ``forcing``)
    reference : str — how ``about`` was chosen when no point was given (empty when it was given)
    equilibria : tuple — the equilibria found then (the chosen one first), each an
        :class:`~lagrange.analysis.equilibria.Equilibrium`
    """

    coordinates: tuple
    a: object
    b: object
    c: object
    forcing: object
    about: dict
    state_matrix: object = None
    input_matrix: object = None
    speeds: tuple = ()
    inputs: tuple = ()
    all_coordinates: tuple = ()
    coordinate_map: object = None
    velocities: dict = field(default_factory=dict)
    multipliers: dict = field(default_factory=dict)
    params: dict | None = None
    input_forces: object = None
    acceleration: tuple | None = None
    reference: str = ""
    equilibria: tuple = ()

    def __repr__(self) -> str:
        kind = "numeric" if self.params is not None else "symbolic"
        s = ", ".join(map(coordinate_name, self.coordinates))
        w = ", ".join(velocity_symbol(coordinate_of(v)).name for v in self.speeds) if self.speeds else s + " rates"
        form = "a s'' + b s' + c s = F" if self.a is not None else "x' = A x + B u (no second-order form)"
        cons = f", multipliers {self.multipliers}" if self.multipliers else ""
        return (f"LinearModel({kind}; about {operating_point.point_text(self.about)}; {form}; independent "
                f"coordinates ({s}); independent speeds ({w}); inputs ({', '.join(u.name for u in self.inputs)})"
                f"{cons})")

    @property
    def is_constrained(self) -> bool:
        return bool(self.all_coordinates) and len(self.all_coordinates) != len(self.coordinates) or bool(
            self.multipliers)

    @property
    def states(self) -> tuple:
        """The state variables of 𝒜: the independent coordinates, then the independent speeds."""
        speeds = self.speeds or tuple(q.diff(t) for q in self.coordinates)
        return tuple(self.coordinates) + tuple(speeds)

    @property
    def A(self):
        """𝒜, the state matrix of ``ẋ = 𝒜 x + ℬ δu``."""
        if self.state_matrix is not None:
            return self.state_matrix
        a, b, c = self.a, self.b, self.c
        n = a.shape[0]
        if isinstance(a, np.ndarray):
            return np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(a, c), -np.linalg.solve(a, b)]])
        return sp.Matrix.vstack(sp.Matrix.hstack(sp.zeros(n, n), sp.eye(n)),
                                sp.Matrix.hstack(-a.LUsolve(c), -a.LUsolve(b)))

    @property
    def B(self):
        """ℬ, the input matrix of ``ẋ = 𝒜 x + ℬ δu`` (one column per input)."""
        if self.input_matrix is not None:
            return self.input_matrix
        n, k = self.a.shape[0], len(self.inputs)
        G = self.input_forces if self.input_forces is not None else (
            np.zeros((n, k)) if isinstance(self.a, np.ndarray) else sp.zeros(n, k))
        if isinstance(self.a, np.ndarray):
            return np.vstack([np.zeros((n, k)), np.linalg.solve(self.a, G) if k else np.zeros((n, 0))])
        return sp.Matrix.vstack(sp.zeros(n, k), self.a.LUsolve(G) if k else sp.zeros(n, 0))

    def _check_params(self, params: Mapping | None) -> None:
        if self.params is None or not params:
            return
        given, used = _by_name(params), _by_name(self.params)
        diff = [k for k in given if k in used and float(_sympify(given[k])) != float(_sympify(used[k]))]
        if diff:
            raise AnalysisError(f"this numeric linearization was made with other values of {', '.join(diff)}: "
                                "linearize again with the new parameters")

    def numeric(self, params: Mapping | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(a, b, c) as float arrays with parameter values substituted (keys: symbols or names)."""
        if self.a is None:
            raise AnalysisError("a non-holonomic system has no second-order (a, b, c) form: use the state matrix "
                                "(LinearModel.A, numeric_state) or characteristic_roots")
        self._check_params(params)
        return tuple(_numeric_matrix(X, params, "(a, b, c)") for X in (self.a, self.b, self.c))

    def numeric_state(self, params: Mapping | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(𝒜, ℬ) as float arrays with parameter values substituted."""
        self._check_params(params)
        if self.state_matrix is None and self.a is not None and not isinstance(self.a, np.ndarray):
            a, b, c = self.numeric(params)
            k = len(self.inputs)
            G = _numeric_matrix(self.input_forces, params, "the input forces") if k else np.zeros((a.shape[0], 0))
            n = a.shape[0]
            A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(a, c), -np.linalg.solve(a, b)]])
            return A, np.vstack([np.zeros((n, k)), np.linalg.solve(a, G)])
        return _numeric_matrix(self.A, params, "the state matrix"), _numeric_matrix(self.B, params, "the input matrix")

    def characteristic_polynomial(self, lam: sp.Symbol | None = None) -> sp.Expr:
        """``|a λ² + b λ + c|`` (Wells 10.30); with b = 0 set λ = iω for ``|c − a ω²|``. Without a
        second-order form: ``|λ I − 𝒜|``."""
        lam = lam or sp.Symbol("lambda")
        if self.a is None:
            A = sp.Matrix(self.A)
            return factor((lam * sp.eye(A.shape[0]) - A).det())
        return factor((sp.Matrix(self.a) * lam**2 + sp.Matrix(self.b) * lam + sp.Matrix(self.c)).det())

    def _second_order(self, what: str):
        """(a, c) for the undamped frequency equation; AnalysisError when there is no second-order form, or
        when b is not zero (|a ω² − c| would drop its damping or gyroscopic terms)."""
        if self.a is None:
            raise AnalysisError(f"{what} needs a second-order form, which a non-holonomic system does not have: "
                                "use characteristic_roots")
        if self.b is not None and not all(is_zero(x) for x in sp.Matrix(self.b)):
            raise AnalysisError(f"{what} |a ω² − c| holds only when b = 0; here b = {sp.Matrix(self.b).tolist()} "
                                "(damping or gyroscopic terms): use characteristic_polynomial |a λ² + b λ + c| or "
                                "characteristic_roots")
        return sp.Matrix(self.a), sp.Matrix(self.c)

    def frequency_equation(self, omega: sp.Symbol | None = None) -> sp.Expr:
        """Wells' fundamental determinant ``|a ω² − c|`` (10.10); AnalysisError when b ≠ 0 (see
        :meth:`characteristic_polynomial`)."""
        a, c = self._second_order("the frequency equation")
        omega = omega or sp.Symbol("omega", positive=True)
        return (a * omega**2 - c).det()

    def squared_frequencies(self) -> list:
        """Symbolic roots ω² of ``|a ω² − c| = 0`` (small systems; AnalysisError when b ≠ 0)."""
        a, c = self._second_order("the squared frequencies")
        w2 = sp.Symbol("w2")
        return solve((a * w2 - c).det(), w2, what="the frequency equation")

    def _repr_latex_(self) -> str:
        from ..display import linear_model_latex

        return linear_model_latex(self)


def coordinate_of(v):
    """The coordinate function of a velocity ``q.diff(t)``."""
    return v.args[0] if isinstance(v, sp.Derivative) else v


def _resolve(system, names, what: str, velocity: bool) -> list[int]:
    """Indices of coordinates given by object or name (velocities too when ``velocity``)."""
    idx = []
    for k in names:
        key = canonical_key(k, system.coordinates)  # dynamicsymbols and their derivatives
        for i, q in enumerate(system.coordinates):
            keys = {q, coordinate_name(q), position_symbol(q)}
            if velocity:
                keys |= {q.diff(t), velocity_symbol(q), velocity_symbol(q).name}
            if key in keys:
                idx.append(i)
                break
        else:
            valid = ", ".join(coordinate_name(q) for q in system.coordinates)
            raise AnalysisError(f"{what}: {k} is not a coordinate of the system ({valid})")
    return idx


def _dependent(system, given, J, count_rows: Sequence[int], what: str, velocity: bool, sample) -> list[int]:
    """Dependent indices: the complement of the user's ``given`` independent ones, else chosen by pivoting."""
    eqs = system.derived
    n = eqs.n
    rows = [eqs.constraint_names[k] for k in count_rows]
    Jn = sample(J)
    if given is None:
        return manifold.choose_dependent(Jn, [s.name for s in eqs.q], f"constraints ({what})", rows)
    ind = _resolve(system, given, f"independent {what}", velocity)
    dep = [i for i in range(n) if i not in ind]
    if len(set(ind)) != len(ind) or len(dep) != Jn.shape[0]:
        raise AnalysisError(f"{n - Jn.shape[0]} independent {what} are needed (n = {n} minus {Jn.shape[0]} "
                            f"constraints: {', '.join(rows)}), got {len(set(ind))}")
    D = Jn[:, dep]
    if D.size and np.linalg.cond(D) > 1e10:
        names = ", ".join(eqs.q[i].name for i in ind)
        raise AnalysisError(f"({names}) cannot be the independent {what} here: the constraints "
                            f"{', '.join(rows)} do not determine the others (singular at the reference state)")
    return dep


@bounded("linearization")
def linearize(system, about: Mapping | None = None, velocities: Mapping | None = None, *,
              params: Mapping | None = None, inputs: Sequence | None = None,
              independent: Sequence | None = None, speeds: Sequence | None = None,
              near: Mapping | None = None) -> LinearModel:
    r"""Linearize about a reference state, on the constraint manifold when there are constraints.

    Parameters
    ----------
    system : System
    about : mapping — reference values of coordinates, and also of velocities (``x.diff(t)``,
        ``"x_dot"``; default 0, non-zero for a steady motion) and inputs (default 0), keyed by object or name.
        Values may be expressions in the parameters. Unknown names raise. Coordinates left out of a point
        that names some are 0. **No coordinate given (and at rest): an equilibrium is found** — with
        ``params`` the stable one nearest to ``near`` (else the nearest), without numbers q = 0 when it is an
        equilibrium, else a sympy solution (refused when there is none); the result's ``about``,
        ``reference`` and ``equilibria`` record the choice (see :mod:`lagrange.analysis.operating_point`).
        With constraints, the speeds left out are computed from the velocity constraints (the rule of
        :func:`~lagrange.integrate.constrained.complete_speeds`: give the spin of a rolling disc alone); given
        values are never changed (an inconsistent reference state is refused).
    velocities : mapping, optional — reference velocities (the older spelling; same keys as in ``about``)
    params : mapping, optional — parameter values: the numeric route (float matrices, accurate to rounding:
        complex-step derivatives of the generated M, f, A, b, c, or their exact symbolic Jacobians when sign,
        Abs or atan2 appear; the code is generated once per system and reused). Without it the result is
        symbolic. ``params["t"]`` sets the time of a non-autonomous unconstrained system (default 0).
    inputs : sequence of Symbols, optional — the inputs u (columns of ℬ); default ``system.derived.inputs``
    independent : sequence, optional — the independent coordinates (default: chosen by pivoting, keeping
        the coordinates declared first independent)
    speeds : sequence, optional — the independent speeds (velocities or coordinate names)
    near : mapping, optional — where the equilibrium search starts (coordinates by object or name; default
        0); only with ``params`` and without coordinates in ``about``

    Returns
    -------
    LinearModel
        ``a = M₀``, ``b = −∂f/∂q̇``, ``c = −∂f/∂q``, ``F = f`` at the reference for an unconstrained system
        (Wells 10.4–10.6; a non-equilibrium reference gives a constant ``F``); on the manifold see
        :mod:`lagrange.analysis.manifold`.

    Raises
    ------
    AnalysisError
        Reference state off the constraint manifold (with the residuals), unknown names, redundant or
        singular constraints, an unusable choice of independent variables, rough or moving constraints, a
        friction term at its switching point, a singular mass matrix, or no point given and no equilibrium
        found (the message says to pass ``about=``).

    Examples
    --------
    >>> import sympy as sp
    >>> from lagrange import Holonomic, Particle, System, coordinates, parameters
    >>> x, y = coordinates("x y"); m, g, l = parameters("m g l")
    >>> s = System([x, y], bodies=[Particle(m, (x, y))], V=m*g*y, constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l)])
    >>> lin = linearize(s, {x: 0, y: -l})
    >>> lin.coordinates, sp.simplify(lin.c[0, 0] / lin.a[0, 0])
    ((x(t),), g/l)
    """
    eqs = system.derived
    declared = tuple(getattr(eqs, "inputs", ()))
    inputs = declared if inputs is None else tuple(canonical_key(u, (), declared) for u in inputs)  # specifieds
    bad = [u for u in inputs if not isinstance(u, sp.Symbol)]
    if bad:
        raise AnalysisError(f"inputs must be plain Symbols, got {bad}")
    manifold.check_supported(eqs)
    q0, v0, u0 = manifold.reference_state(system, about, velocities, inputs)
    choice = None
    if not q0 and all(is_zero(v) for v in v0.values()):  # no point given: an equilibrium, never q = 0 blindly
        choice = _choose_reference(system, params, near, u0, inputs)
        if choice is not None:
            q0 = {position_symbol(q): _sympify(v) for q, v in choice.point.items()}
            log.info(choice.describe())
    elif near is not None:
        raise TypeError("near= applies only when `about` gives no coordinates (it seeds the equilibrium search)")
    lin = _linearize_at(system, q0, v0, u0, params, inputs, independent, speeds)
    if choice is None:
        if not q0 and not v0 and eqs.m and lin.acceleration is not None and \
                not all(is_zero(a) for a in lin.acceleration):  # constrained, symbolic: q = 0 must be one
            raise AnalysisError(f"q = 0 ({operating_point.point_text(lin.about)}) is not an equilibrium (q̈ = "
                                f"{list(lin.acceleration)} there): pass `about=` (an equilibrium), or `params=` to "
                                "have one found")
        return lin
    return dataclasses.replace(lin, reference=choice.describe(), equilibria=choice.found)


def _choose_reference(system, params, near, u0, inputs):
    """The equilibrium to use when no point is given (see :mod:`lagrange.analysis.operating_point`); None
    for a constrained system without numbers (its own checks then refuse q = 0 unless it is an equilibrium)."""
    if params is not None:
        given = {**_by_name(params), **{u.name: v for u, v in u0.items()}}

        def stability(point):
            try:
                return _is_stable(characteristic_roots(linearize(system, dict(point), params=given, inputs=inputs)))
            except (LagrangeError, np.linalg.LinAlgError):
                return None

        return operating_point.numeric_choice(system, given, near, stability)
    if near is not None:
        raise TypeError("near= needs params= (the equilibrium search is numeric)")
    if system.derived.m:
        return None

    def sampled(point, values):
        try:
            return _is_stable(characteristic_roots(linearize(system, point, params=values, inputs=inputs)))
        except (LagrangeError, np.linalg.LinAlgError):
            return None

    return operating_point.symbolic_choice(system, u0, sampled)


def _is_stable(roots: np.ndarray) -> bool:
    top = max(1.0, float(np.max(np.abs(roots)))) if roots.size else 1.0
    return bool(np.all(roots.real <= operating_point.STABLE_TOL * top))


def _linearize_at(system, q0, v0, u0, params, inputs, independent, speeds) -> LinearModel:
    eqs = system.derived
    if not eqs.m and params is None and independent is None and speeds is None:
        return _unconstrained_symbolic(system, q0, v0, u0, inputs)
    if params is not None:
        blk = manifold.numeric_blocks(system, q0, v0, u0, params, inputs)
        sample = lambda X: X  # noqa: E731
    else:
        blk = manifold.symbolic_blocks(system, q0, v0, u0, inputs)
        values = manifold.random_values(blk)
        sample = lambda X: manifold._sample_matrix(X, values)  # noqa: E731
    hol = [k for k, ph in enumerate(eqs.constraint_positions) if ph is not None]
    A = blk["A"]
    Phi = A[hol, :] if blk["numeric"] else A.extract(hol, list(range(eqs.n)))
    dep_q = _dependent(system, independent, Phi, hol, "coordinates", False, sample)
    if len(hol) == eqs.m:  # holonomic only: the speeds are the rates of the independent coordinates
        dep_u = dep_q
        if speeds is not None and sorted(_resolve(system, speeds, "speeds", True)) != \
                [i for i in range(eqs.n) if i not in dep_q]:
            raise AnalysisError("with holonomic constraints only, the independent speeds are the rates of the "
                                "independent coordinates: give `independent=` alone")
    else:
        dep_u = _dependent(system, speeds, A, list(range(eqs.m)), "speeds", True, sample)
    try:
        red = manifold.reduce(blk, dep_q, dep_u, hol)
    except np.linalg.LinAlgError:
        raise AnalysisError("the reduced mass matrix is singular at the reference state") from None
    coords = system.coordinates
    ind_q = [coords[i] for i in red["ind_q"]]
    ref_q = {c: (float(blk["q"][i]) if blk["numeric"] else q0.get(position_symbol(c), sp.S.Zero))
             for i, c in enumerate(coords)}
    ref_v = {c.diff(t): (float(blk["v"][i]) if blk["numeric"] else blk["v"][i])
             for i, c in enumerate(coords)}
    lam = [float(x) if blk["numeric"] else x for x in (blk["lam"] if blk["numeric"] else list(blk["lam"]))]
    return LinearModel(
        tuple(ind_q), red.get("a"), red.get("b"), red.get("c"), red.get("forcing"), ref_q,
        state_matrix=red["A"], input_matrix=red["B"],
        speeds=tuple(coords[i].diff(t) for i in red["ind_u"]), inputs=inputs, all_coordinates=coords,
        coordinate_map=red["C0"], velocities=ref_v, multipliers=dict(zip(eqs.constraint_names, lam)),
        params=dict(params) if params is not None else None,
        input_forces=red.get("G"),
        acceleration=tuple(float(v) for v in blk["qdd"]) if blk["numeric"] else tuple(blk["qdd"]))


def _unconstrained_symbolic(system, q0, v0, u0, inputs) -> LinearModel:
    """Wells' symbolic a, b, c of an unconstrained system (the reference need not be an equilibrium)."""
    eqs = system.derived
    at = {s: q0.get(s, sp.S.Zero) for s in eqs.q}
    at.update({s: v0.get(s, sp.S.Zero) for s in eqs.qd})
    at.update({u: u0.get(u, sp.S.Zero) for u in inputs})
    f = sp.Matrix(eqs.forcing)
    a = sp.Matrix(eqs.mass_matrix).subs(at)
    b = -f.jacobian(list(eqs.qd)).subs(at)
    c = -f.jacobian(list(eqs.q)).subs(at)
    G = f.jacobian(list(inputs)).subs(at) if inputs else sp.zeros(eqs.n, 0)
    F = f.subs(at)
    simp = lambda M: M.applyfunc(lambda e: simplify(e, limit=199))  # noqa: E731
    return LinearModel(system.coordinates, simp(a), simp(b), simp(c), simp(F),
                       {q: at[position_symbol(q)] for q in system.coordinates}, inputs=inputs,
                       all_coordinates=system.coordinates,
                       velocities={q.diff(t): at[velocity_symbol(q)] for q in system.coordinates},
                       input_forces=simp(G))


@record(frozen=True)
class Modes:
    """Numeric normal modes of ``a s̈ + b s + c s = 0`` with ``b`` zero or gyroscopic (skew-symmetric).

    Without ``b`` (``kind == "undamped"``) the modes are real, ``c Φ = a Φ ω²`` with ``Φᵀ a Φ = I``. With a
    gyroscopic ``b`` (``kind == "gyroscopic"``, e.g. about a steady motion) the frequencies are ``|Im λ|`` of
    the roots of ``|a λ² + b λ + c| = 0`` and the shapes are complex (each coordinate's amplitude and phase:
    the motion in mode k is ``Re(Φ_k e^{iω_k t})``); see :func:`normal_modes`.

    Attributes
    ----------
    omega : ndarray (n,) — angular frequencies, ascending (0 for rigid-body modes)
    shapes : ndarray (n, n) — column s is mode s, normalized so that ``shapesᴴ a shapes`` has a unit diagonal
        (``shapesᵀ a shapes = I`` for real modes, Wells 10.21); complex for gyroscopic modes
    a, c : the matrices used
    coordinates : tuple — the coordinates of the rows of ``shapes`` (the independent ones when constrained)
    all_coordinates : tuple — every coordinate of the system
    full_shapes : ndarray (n_all, n) — the modes in all coordinates, ``C₀ shapes`` (``δq = C₀ s``)
    b : the gyroscopic matrix used (None: zero)
    roots : ndarray (2n,) complex or None — the characteristic roots the gyroscopic frequencies come from
    """

    omega: np.ndarray
    shapes: np.ndarray
    a: np.ndarray
    c: np.ndarray
    coordinates: tuple = ()
    all_coordinates: tuple = ()
    full_shapes: np.ndarray | None = None
    b: np.ndarray | None = None
    roots: np.ndarray | None = None

    @property
    def kind(self) -> str:
        """``"undamped"`` (b = 0: real modes) or ``"gyroscopic"`` (skew-symmetric b: complex modes)."""
        return "undamped" if self.b is None else "gyroscopic"

    def _real_modes(self, what: str) -> None:
        if self.b is not None:
            raise AnalysisError(f"{what} needs real modes (b = 0); gyroscopic modes are complex and not "
                                "a-orthogonal: use Modes.motion (the exact linear solution) or simulate")

    @property
    def periods(self) -> np.ndarray:
        """2π/ω (infinite for zero modes)."""
        with np.errstate(divide="ignore"):
            return np.where(self.omega > 0, 2 * np.pi / np.where(self.omega > 0, self.omega, 1), np.inf)

    def ratios(self, reference: int = 0) -> np.ndarray:
        """Mode shapes scaled so that component ``reference`` is 1 (Wells' cofactor ratios d_rs/d_1s; complex
        for gyroscopic modes: amplitude ratio and phase)."""
        return self.shapes / self.shapes[reference, :]

    def normal_coordinates(self, s) -> np.ndarray:
        """``g = Φᵀ a s`` (Wells 10.25) for displacement(s) ``s`` of shape (n,) or (m, n); real modes only
        (AnalysisError for gyroscopic modes)."""
        self._real_modes("normal_coordinates")
        return np.asarray(s) @ (self.shapes.T @ self.a).T

    def fit(self, s0, v0):
        """Amplitude and phase of each mode for initial displacements ``s0`` and velocities ``v0``:
        ``s(t) = Σ Φ_s A_s cos(ω_s t + φ_s)`` (Wells 10.27–10.28); a zero mode gets ``g = g0 + ġ0 t``
        (returned as A = g0, phase = ġ0 for those). Real modes only (AnalysisError for gyroscopic modes)."""
        self._real_modes("fit")
        g0, gd0 = self.normal_coordinates(s0), self.normal_coordinates(v0)
        A, ph = np.empty_like(g0), np.empty_like(g0)
        for k, w in enumerate(self.omega):
            if w > 1e-12:
                A[k] = np.hypot(g0[k], gd0[k] / w)
                ph[k] = np.arctan2(-gd0[k] / w, g0[k])
            else:
                A[k], ph[k] = g0[k], gd0[k]
        return A, ph

    def motion(self, s0, v0, times) -> np.ndarray:
        """The linear solution at ``times``, shape (m, n) (gyroscopic modes: ``exp(𝒜 t)`` of the state matrix)."""
        times = np.asarray(times, dtype=float)
        if self.b is not None:
            x0 = np.concatenate([np.asarray(s0, dtype=float), np.asarray(v0, dtype=float)])
            A = _state_matrix(self.a, self.b, self.c)
            n = self.a.shape[0]
            return np.array([(scipy.linalg.expm(A * tk) @ x0)[:n] for tk in times.ravel()]).reshape(-1, n)
        A, ph = self.fit(s0, v0)
        g = np.empty((len(times), len(self.omega)))
        for k, w in enumerate(self.omega):
            g[:, k] = A[k] * np.cos(w * times + ph[k]) if w > 1e-12 else A[k] + ph[k] * times
        return g @ self.shapes.T

    def _repr_html_(self) -> str:
        from ..display import modes_html

        return modes_html(self)


def _linear(linear, params, kw: dict) -> LinearModel:
    """A LinearModel as given, or linearize a System numerically with ``params`` and the keywords."""
    if isinstance(linear, LinearModel):
        if kw:
            raise TypeError(f"{', '.join(kw)}: only with a System (this is already linearized)")
        return linear
    return linearize(linear, kw.pop("about", None), params=params if params is not None else {}, **kw)


def normal_modes(linear, params: Mapping | None = None, **kwargs) -> Modes:
    r"""Normal modes of ``a s̈ + b ṡ + c s = 0``: undamped (b = 0) or gyroscopic (b skew-symmetric).

    * ``b = 0``: the generalized symmetric eigenproblem ``c Φ = a Φ ω²`` (scipy.linalg.eigh; Wells 10.10),
      real shapes with ``Φᵀ a Φ = I``.
    * ``b`` skew-symmetric (gyroscopic, e.g. about a steady motion, Wells 11.12): the quadratic eigenproblem
      :math:`(a\lambda^2 + b\lambda + c)\,\phi = 0`, solved as the eigenproblem of the state matrix
      :math:`\mathcal A`. The motion is stable (to first order) only when every root is on the imaginary
      axis, :math:`\lambda = \pm i\omega`; the frequencies are :math:`\omega = |\operatorname{Im}\lambda|`,
      one per ± pair, and the shapes the complex displacement parts of the eigenvectors of
      :math:`+i\omega` (``Modes.kind == "gyroscopic"``). ``c`` need not be positive definite (gyroscopic
      stabilization, e.g. a sleeping top).
    * ``b`` with a symmetric (damping) part: refused (:class:`~lagrange.errors.AnalysisError`): the roots are
      not on the imaginary axis and the undamped modes of (a, c) would silently ignore the damping. Use
      :func:`characteristic_roots` (damped frequencies ``|Im λ|``, damping ratios ``−Re λ/|λ|``).

    ``b`` counts as zero, or as purely skew, when its (symmetric) part is below 1e-12 of the scale
    ``max(‖b‖, √(‖a‖‖c‖))``; roots count as imaginary when ``|Re λ| ≤ 1e-6 max(1, |λ|max)``.

    ``linear`` is a :class:`LinearModel` or a System (then linearized numerically with ``params`` and the
    keywords of :func:`linearize`: ``about=``, ``velocities=``, ``independent=``, ...). Constrained systems
    (holonomic constraints) give the modes in the independent coordinates (``shapes``) and in all
    coordinates (``full_shapes``). Raises :class:`~lagrange.errors.LagrangeError` when ``a`` is not positive
    definite, the equilibrium or steady motion is unstable (``c`` has negative eigenvalues, or a gyroscopic
    root off the imaginary axis: no oscillation), ``b`` has a damping part, or the system is non-holonomic
    (no second-order form: use :func:`characteristic_roots`)."""
    linear = _linear(linear, params, kwargs)
    a, b, c = linear.numeric(params)
    c = (c + c.T) / 2
    C0 = linear.coordinate_map
    full = (lambda Phi: Phi) if C0 is None else (
        lambda Phi: _numeric_matrix(C0, params or linear.params, "the coordinate map") @ Phi)
    coords = tuple(linear.coordinates), tuple(linear.all_coordinates or linear.coordinates)
    scale = max(float(np.linalg.norm(b)), float(np.sqrt(np.linalg.norm(a) * np.linalg.norm(c))))
    damping, gyro = (b + b.T) / 2, (b - b.T) / 2
    if np.linalg.norm(damping) > _B_ZERO * scale:
        raise AnalysisError("b has a symmetric (damping) part, so the motion has no undamped normal modes and "
                            "the modes of (a, c) alone would ignore it: use characteristic_roots (damped "
                            "frequencies |Im λ|, damping ratios −Re λ/|λ|) or LinearModel.A")
    if np.linalg.norm(gyro) > _B_ZERO * scale:
        return _gyroscopic_modes(a, gyro, c, full, coords)
    try:
        w2, Phi = scipy.linalg.eigh(c, a)
    except np.linalg.LinAlgError as exc:
        raise LagrangeError(f"the mass matrix at {operating_point.point_text(linear.about)} is not positive "
                            f"definite: {exc}") from None
    scale = max(1.0, float(np.max(np.abs(w2))))
    if np.any(w2 < -1e-10 * scale):
        raise LagrangeError(f"unstable equilibrium at {operating_point.point_text(linear.about)}: negative ω² "
                            f"{w2[w2 < 0]} (c is not positive semi-definite); characteristic_roots gives the "
                            "growth rates")
    w2 = np.where(np.abs(w2) < 1e-12 * scale, 0.0, w2)
    return Modes(np.sqrt(np.maximum(w2, 0.0)), Phi, a, c, *coords, full(Phi))


#: b (or its symmetric part) below this fraction of max(‖b‖, √(‖a‖‖c‖)) is rounding: counted as zero
_B_ZERO = 1e-12
#: a root with |Re λ| below this fraction of max(1, |λ|max) is on the imaginary axis
_IMAGINARY = 1e-6


def _state_matrix(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    n = a.shape[0]
    return np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(a, c), -np.linalg.solve(a, b)]])


def _gyroscopic_modes(a: np.ndarray, b: np.ndarray, c: np.ndarray, full, coords) -> Modes:
    """The modes of ``a s̈ + b ṡ + c s = 0`` with skew ``b`` (see :func:`normal_modes`)."""
    n = a.shape[0]
    try:
        np.linalg.cholesky((a + a.T) / 2)
        A = _state_matrix(a, b, c)
    except np.linalg.LinAlgError as exc:
        raise LagrangeError(f"the mass matrix at the reference is not positive definite: {exc}") from None
    roots = _roots_deflated(A)
    top = max(1.0, float(np.max(np.abs(roots))))
    off = roots[np.abs(roots.real) > _IMAGINARY * top]
    if off.size:
        raise LagrangeError(f"unstable: the gyroscopic system has roots off the imaginary axis {off} (growing "
                            "motion, no normal modes); characteristic_roots gives them all")
    lam, vecs = np.linalg.eig(A)
    order = np.argsort(lam.imag)[n:]  # the n roots of largest Im λ: +iω of each pair (one of a double 0)
    omega = np.sort(np.abs(roots.imag))[1::2]  # one per ± pair, from the deflated (accurate) roots
    omega = np.where(omega < 1e-12 * top, 0.0, omega)
    pick = order[np.argsort(lam.imag[order])]
    Phi = vecs[:n, pick].astype(complex)
    for k in range(n):  # the largest component real and positive, then φᴴ a φ = 1
        v = Phi[:, k]
        big = v[np.argmax(np.abs(v))]
        v = v * (abs(big) / big) if big != 0 else v
        norm = np.sqrt(abs(np.real(np.conj(v) @ a @ v)))
        Phi[:, k] = v / norm if norm > 0 else v
    return Modes(omega, Phi, a, c, *coords, full(Phi), b, roots)


def characteristic_roots(linear, params: Mapping | None = None, **kwargs) -> np.ndarray:
    """Eigenvalues of the state matrix 𝒜 (= roots of ``|a λ² + b λ + c| = 0`` when there is a second-order
    form; damped or gyroscopic), sorted; stable when every real part ≤ 0 (Wells 10.17).

    ``linear`` is a :class:`LinearModel` or a System, linearized numerically with ``params`` and the
    keywords of :func:`linearize` (e.g. ``characteristic_roots(bicycle, about={...}, params={...})``; the
    derivatives are generated once per system and reused for every operating point). A constrained system
    has ``len(states)`` roots, on the manifold.

    Exact zero roots are deflated before the eigen-solver runs: a state whose row or column of 𝒜 vanishes (an
    ignorable coordinate, a conserved speed — e.g. a bicycle's position, heading, wheel angles and forward
    speed) contributes a root 0 exactly, and the remaining roots are those of 𝒜 without that state (block
    triangular form). Left in, such zeros often form Jordan chains, which the solver returns as ±√eps
    (~1e-8) and which then hide a small physical root such as a capsize mode at its critical speed."""
    linear = _linear(linear, params, kwargs)
    A, _ = linear.numeric_state(params)
    return _roots_deflated(np.asarray(A))


def _roots_deflated(A: np.ndarray) -> np.ndarray:
    """Eigenvalues of A, zero rows/columns (to 1e-14 of the largest entry) split off exactly as roots 0."""
    if not A.size:
        return np.zeros(0, dtype=complex)
    tol = 1e-14 * float(np.max(np.abs(A))) if np.any(A) else 0.0
    keep = np.arange(A.shape[0])
    zeros = 0
    while keep.size:
        sub = np.abs(A[np.ix_(keep, keep)])
        empty = np.flatnonzero((sub.max(axis=0) <= tol) | (sub.max(axis=1) <= tol))
        if not empty.size:
            break
        keep = np.delete(keep, empty[0])
        zeros += 1
    B = A[np.ix_(keep, keep)]
    rest = np.linalg.eigvals(B) if keep.size else np.zeros(0, dtype=complex)
    if 0 < keep.size <= _EXACT_EIG_MAX and np.min(np.abs(rest)) < 1e-4 * max(1.0, float(np.max(np.abs(B)))):
        rest = _eigvals_extended(B)  # a cluster near 0 (a critical point): defective roots need more digits
    return np.sort_complex(np.concatenate([rest.astype(complex), np.zeros(zeros, dtype=complex)]))


#: blocks up to this size get their near-zero roots from 50-digit arithmetic (mpmath; milliseconds)
_EXACT_EIG_MAX = 12


def _eigvals_extended(B: np.ndarray) -> np.ndarray:
    """Eigenvalues of the float matrix B computed in 50-digit arithmetic, rounded to double.

    Near a critical point roots coalesce into a defective (Jordan) cluster, and a double-precision eigen-solver
    returns a k-fold root only to eps^(1/k) (a rolling disc at its critical spin: 3e-6 instead of 1e-8); the
    exact eigenvalues of the same float matrix are resolved here to about (1e-50)^(1/k)."""
    import mpmath

    with mpmath.workdps(50):
        ev = mpmath.eig(mpmath.matrix(B.tolist()), left=False, right=False)
        return np.array([complex(mpmath.re(v), mpmath.im(v)) for v in ev], dtype=complex)
