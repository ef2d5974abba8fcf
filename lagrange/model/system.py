"""The declared mechanical system: coordinates, energies, power function, forces and bodies.

A :class:`System` is immutable and validated completely on construction: every problem found is
reported at once in one :class:`~lagrange.errors.DeclarationError`. Derived results (equations,
mass matrix, …) come from the pure functions in :mod:`lagrange.derive`; the methods here are thin,
memoized conveniences over them (safe because a System never changes).

Sign conventions are those of :mod:`lagrange.conventions` (Wells' power function ``F = +∂P/∂q̇``).
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from functools import cached_property
from typing import TYPE_CHECKING, Any, NamedTuple

import sympy as sp
from sympy.core.function import AppliedUndef

from .. import limits
from ..budget import check_declared
from ..conventions import VELOCITY_SUFFIX, t
from ..conventions import t as _TIME
from ..errors import DeclarationError
from ..safe_sympify import sympify as _sympify
from .bodies import Body, Force
from .coordinates import coordinate_name, is_coordinate, normalize_time, virtual_displacement
from .forces import generalized_forces
from .inputs import inputs_in, is_input
from .integrals import evaluate_integrals

if TYPE_CHECKING:
    from ..codegen.numeric import NumericModel
    from ..derive.equations import Equations
    from ..results.trajectory import Trajectory

__all__ = ["System", "DegreesOfFreedom"]


class DegreesOfFreedom(NamedTuple):
    """Degrees of freedom of a system with ``n`` coordinates: ``configuration = n − (holonomic constraints)``,
    ``velocity = n − (all constraints)`` (Wells §12; equal without non-holonomic constraints)."""

    configuration: int
    velocity: int


def _as_coordinate_tuple(coords) -> tuple:
    if is_coordinate(coords) or isinstance(coords, sp.Basic):
        return (coords,)
    try:
        return tuple(coords)
    except TypeError:
        return (coords,)


def _sym(expr, what: str, problems: list):
    try:
        return _sympify(expr)
    except (sp.SympifyError, TypeError, SyntaxError):
        problems.append(f"{what} = {expr!r} is not a sympy expression")
        return sp.S.Zero


def _derive_expanded(system: System) -> Equations:
    """:func:`lagrange.derive.lagrange.lagrange_equations`, imported when a derivation is due (a warm re-run
    loads the equations from the derivation cache and never imports the derivation)."""
    from ..derive.lagrange import lagrange_equations

    with system.symbolic_stage("derivation"):
        return lagrange_equations(system)


class System:
    """A mechanical system declared the way Wells does.

    Parameters
    ----------
    coordinates : sequence of coordinate functions (from :func:`lagrange.coordinates`)
        The generalized coordinates, in the order used for equations and states. sympy's
        ``dynamicsymbols`` are accepted here and in every expression and body: their time ``Symbol('t')``
        becomes :data:`lagrange.t` (:func:`~lagrange.model.coordinates.normalize_time`).
    T : expression, optional
        Kinetic energy in the coordinate functions, their derivatives and ``t``. Added to the kinetic
        energy of ``bodies`` when both are given.
    V : expression
        Potential energy V(q, t). No velocities.
    P : expression
        Wells' power function; generalized force ``+∂P/∂q̇`` (P < 0 for losses).
    rayleigh : expression
        Positive Rayleigh dissipation function D; generalized force ``-∂D/∂q̇``.
    forces : dict, Force, virtual-work expression, or a list of these
        Generalized forces of everything not in V, P or D (see :mod:`lagrange.model.forces`).
    bodies : sequence of bodies (:class:`~lagrange.Particle`, …)
        Their kinetic energy is computed from their transformation equations.
    name : str, optional
    parameters : sequence of symbols, optional
        When given, any other symbol in the declaration is an error (strict mode).
    prescribed : dict ``{q(t): expression of t}``, optional
        Coordinates whose motion is prescribed (Wells Ex. 4.9): they are substituted everywhere and are
        not degrees of freedom.
    constraints : sequence, optional
        Holonomic ``φ(q, t)`` (an expression meaning ``= 0``, an ``Eq`` or :class:`~lagrange.Holonomic`)
        and non-holonomic ones (linear in the velocities, :class:`~lagrange.Nonholonomic` or Wells'
        differential form :class:`~lagrange.Differential`). All coordinates are kept and multipliers
        λ are added (Wells ch. 12); see :mod:`lagrange.model.constraints` for the sign convention and
        :func:`lagrange.eliminate` to remove superfluous coordinates instead. A tuple in the sequence (the
        constraints of a joint, :mod:`lagrange.model.joints`) counts as its members.
    derivation : {"auto", "expanded", "structural"}, optional
        How the equations are derived. ``"expanded"``: from the expanded T, differentiated twice
        (:func:`lagrange.derive.lagrange.lagrange_equations`). ``"structural"``: from each body's kinematics,
        M and f assembled numerically by the generated code (:mod:`lagrange.derive.structural`; same equations,
        set-up linear in the size of the kinematics) — only when the kinetic energy comes wholly from
        Particle and RigidBody bodies (no ``T``, no Quaternion orientation), else DeclarationError naming why.
        ``"auto"`` (default): structural where it applies and pays (at least 6 coordinates;
        :func:`lagrange.derive.derivation_choice.auto_structural`), else expanded. With structural, and whenever
        the kinetic energy comes wholly from Particles and RigidBodies whose fields pin it down
        (:func:`lagrange.derive.derivation_choice.kinetic_declaration`), :attr:`T` is built on first access only
        (the bodies' kinematics are checked at declaration; the derivation cache is keyed by those fields, so a
        warm re-run never builds T).
    symbolic_timeout : float, optional
        CPU seconds the derivation (and the symbolic analysis of this system) may take before it ends in
        :class:`~lagrange.errors.SymbolicTimeoutError`; default ``$LAGRANGE_SYMBOLIC_TIMEOUT`` or 8
        (:mod:`lagrange.limits`). ``float("inf")``: no limit.
    symbolic_budget : int, optional
        Nodes one derived expression may have before the derivation ends in
        :class:`~lagrange.errors.ExpressionTooLarge`; default ``$LAGRANGE_SYMBOLIC_BUDGET`` or 200,000.
        Neither setting changes the equations derived, only whether their derivation may finish.

    Attributes
    ----------
    T, V, P, rayleigh : sympy expressions in the coordinate functions ``q(t)``, ``q'(t)`` and ``t``
        The kinetic energy (of ``T`` and every body together; ``T_given`` is the ``T`` argument alone), the
        potential energy, Wells' power function and the Rayleigh function, after prescribed motion is
        substituted and integrals are evaluated (:mod:`lagrange.model.integrals`). :attr:`lagrangian` is
        ``T − V``. Like every user-facing expression they are in coordinate functions; generated code works
        in plain symbols (:func:`lagrange.to_symbols` converts).
    forces : dict ``{q: F_q}`` of the declared generalized forces
    constraints : tuple of normalized constraints (see :mod:`lagrange.model.constraints`)
    dof : :class:`DegreesOfFreedom` — configuration and velocity degrees of freedom

    Raises
    ------
    DeclarationError
        Listing every problem: unknown functions of t, velocities in V, accelerations anywhere,
        symbols clashing with coordinate names, a symbol named ``t`` that is not ``lagrange.t``,
        symbols outside ``parameters``, forces on unknown coordinates, no kinetic energy.

    Examples
    --------
    >>> from lagrange import System, coordinates, parameters, t
    >>> import sympy as sp
    >>> x = coordinates("x"); m, k = parameters("m k")
    >>> s = System([x], T=m*x.diff(t)**2/2, V=k*x**2/2)
    >>> s.equations()[0]
    Eq(k*x(t) + m*Derivative(x(t), (t, 2)), 0)
    """

    def __init__(
        self,
        coordinates,
        T=None,
        V=0,
        P=0,
        rayleigh=0,
        forces=None,
        bodies: Sequence[Body] = (),
        name: str | None = None,
        *,
        parameters: Sequence[sp.Symbol] | None = None,
        prescribed: Mapping | None = None,
        constraints: Sequence = (),
        description: str = "",
        derivation: str = "auto",
        symbolic_timeout: float | None = None,
        symbolic_budget: int | None = None,
    ):
        from ..derive.derivation_choice import DERIVATIONS, auto_structural, kinetic_declaration, structural_refusal

        if derivation not in DERIVATIONS:
            raise DeclarationError(f"derivation={derivation!r} is not one of {', '.join(map(repr, DERIVATIONS))}")
        if symbolic_timeout is not None:  # validated now (OptionError); None: the environment, read when deriving
            limits.symbolic_timeout(symbolic_timeout)
        if symbolic_budget is not None:
            limits.symbolic_budget(symbolic_budget)
        problems: list[str] = []
        constraints = _flatten(constraints)  # a joint (lagrange.model.joints) is a tuple of constraints
        # sympy.physics.mechanics dynamicsymbols (functions of Symbol('t')) are accepted: their time becomes t
        coordinates, T, V, P, rayleigh, forces, prescribed, constraints = (
            normalize_time(x) for x in (coordinates, T, V, P, rayleigh, forces, prescribed, constraints))
        coords = _as_coordinate_tuple(coordinates)
        bad = [c for c in coords if not is_coordinate(c)]
        for c in bad:
            if is_input(c):
                problems.append(
                    f"{c} is an input (lagrange.inputs), not a coordinate: an input is a value given at "
                    "simulate time (simulate(..., inputs={...})); declare a degree of freedom with "
                    "lagrange.coordinates"
                )
                continue
            problems.append(_not_a_coordinate(c))
        coords = tuple(c for c in coords if is_coordinate(c))
        if not coords and not bad:
            problems.append("no coordinates given")
        names = [coordinate_name(c) for c in coords]
        dups = sorted({n for n in names if names.count(n) > 1})
        if dups:
            problems.append(f"coordinate(s) {', '.join(dups)} listed more than once")

        prescribed = dict(prescribed or {})
        presc: dict = {}
        for key, value in prescribed.items():
            if not is_coordinate(key):
                problems.append(f"prescribed motion given for {key!r}, which is not a function of t")
                continue
            if key in coords:
                problems.append(
                    f"{coordinate_name(key)} is both a coordinate and prescribed: a prescribed "
                    "coordinate is not a degree of freedom, remove it from the coordinates"
                )
                continue
            val = _sym(value, f"prescribed {coordinate_name(key)}", problems)
            if val.atoms(AppliedUndef):
                problems.append(
                    f"prescribed motion of {coordinate_name(key)} = {val} must be a function of t and "
                    "parameters only"
                )
                continue
            presc[key] = val

        reserved = frozenset({"t", *names, *(f"{n}_dot" for n in names), *(f"{n}_ddot" for n in names)})

        def prep(expr, what):
            e = _sym(expr, what, problems)
            check_declared(e, what=what)  # before anything works on it (lagrange.budget)
            e = evaluate_integrals(e, what, problems, reserved)
            if presc:
                e = e.subs(presc).doit(integrals=False)  # (an integral kept for quadrature stays)
            return e

        bodies = tuple(bodies)
        for b in bodies:
            if not isinstance(b, Body):
                problems.append(f"{b!r} in bodies is not a body (Particle, RigidBody)")
        bodies = tuple(b for b in bodies if isinstance(b, Body))
        if T is None and not bodies:
            problems.append("no kinetic energy: give T or bodies (e.g. Particle(m, (x, y)))")
        T_given = prep(0 if T is None else T, "T")
        wanted = derivation == "structural" or (derivation == "auto" and auto_structural(len(coords), bodies))
        refusal = structural_refusal(T_given, bodies)  # (also a precondition of kinetic_declaration below)
        if refusal is None and _holds_integral(P, rayleigh, forces):
            refusal = ("P, the Rayleigh function or a force holds an integral (quadrature is generated for the "
                       "expanded equations)")
        if derivation == "structural" and refusal is not None:
            problems.append(f"derivation='structural' is not available: {refusal}; use derivation='expanded'")
        structural = wanted and refusal is None
        # T from bodies whose fields pin it down is built on first access of .T (a warm re-run never builds it:
        # the derivation cache is keyed by these fields); the bodies' kinematics are checked instead of T
        T_declaration = kinetic_declaration(bodies) if refusal is None and not problems else None
        from_bodies = structural or T_declaration is not None
        checked_bodies = tuple(b.subs(presc) for b in bodies) if presc and from_bodies else bodies
        kinematic_bodies = checked_bodies if structural else bodies
        T_total = None
        if not from_bodies:
            T_total = T_given
            for b in bodies:
                T_total += prep(b.kinetic_energy(), f"kinetic energy of {b!r}")

        V_e = prep(V, "V")
        P_e = prep(P, "P")
        D_e = prep(rayleigh, "rayleigh")
        raw_forces = forces
        if presc and forces is not None:
            raw_forces = _substitute_forces(forces, presc)
        F = generalized_forces(raw_forces, coords, problems) if coords else {}
        F = {q: evaluate_integrals(f, f"F_{coordinate_name(q)}", problems, reserved) for q, f in F.items()}
        for q, f in F.items():
            check_declared(f, what=f"the generalized force F_{coordinate_name(q)}")

        specs = ()
        constraints = list(constraints or ()) + [c for b in bodies for c in getattr(b, "constraints", tuple)()]
        if constraints:
            raw = [_substitute_constraint(c, presc) for c in constraints] if presc else list(constraints)
            from .constraints import normalize_constraints  # (imported only by declarations with constraints)

            specs = normalize_constraints(raw, coords, problems)
            for spec in specs:
                check_declared(spec.velocity, what=f"constraint {spec.name}")
                if spec.velocity.has(sp.Integral):
                    problems.append(f"constraint {spec.name} contains an integral: give it in closed form")
                self._check_expr(spec.name, spec.velocity, coords, presc, 1, problems, parameters)
        if from_bodies:  # each body's kinematics instead of the whole T: all at once, then per body if wrong
            found: list[str] = []
            everything = sp.Tuple(*(e for b in checked_bodies for e in _kinematics_of(b)))
            for b in checked_bodies:
                check_declared(sp.Tuple(*_kinematics_of(b)), what=f"kinematics of {b.name or b!r}")
            _check_kinematics(self, "kinematics of the bodies", everything, coords, presc, found, parameters)
            if found:
                for b in checked_bodies:
                    _check_kinematics(self, f"kinematics of {b.name or b!r}", sp.Tuple(*_kinematics_of(b)), coords,
                                      presc, problems, parameters)
        else:
            self._check_expr("T", T_total, coords, presc, 1, problems, parameters)
        _check_inputs(T_total if not from_bodies else everything, V_e, specs, presc, P_e, D_e, F, coords, problems)
        self._check_expr("V", V_e, coords, presc, 0, problems, parameters)
        self._check_expr("P", P_e, coords, presc, 1, problems, parameters)
        self._check_expr("rayleigh", D_e, coords, presc, 1, problems, parameters)
        for q, f in F.items():
            self._check_expr(f"F_{coordinate_name(q)}", f, coords, presc, 1, problems, parameters)
        if problems:
            raise DeclarationError(problems, subject=f"system {name!r}" if name else "system")

        self.coordinates: tuple = coords
        if T_total is not None:
            self.T: sp.Expr = T_total
        self.derivation: str = "structural" if structural else "expanded"
        self._kinematic_bodies = kinematic_bodies
        self._T_declaration = T_declaration
        self.T_given: sp.Expr = T_given
        self.V: sp.Expr = V_e
        self.P: sp.Expr = P_e
        self.rayleigh: sp.Expr = D_e
        self.forces: dict = F
        self.bodies: tuple = bodies
        self.name: str = name or ""
        self.description: str = description
        self.prescribed: dict = presc
        self.constraints: tuple = specs
        self._declared_parameters = tuple(parameters) if parameters is not None else None
        self.symbolic_timeout: float | None = symbolic_timeout
        self.symbolic_budget: int | None = symbolic_budget
        self._frozen = True

    # --- immutability -------------------------------------------------------------------------
    def __setattr__(self, key, value):
        if getattr(self, "_frozen", False):
            raise AttributeError(f"System is immutable; cannot set {key!r}")
        object.__setattr__(self, key, value)

    # --- validation -------------------------------------------------------------------------
    @staticmethod
    def _check_expr(what, expr, coords, presc, max_order, problems, declared) -> None:
        infinite = [str(c) for c in (sp.nan, sp.zoo, sp.oo, -sp.oo) if expr.has(c)]
        if infinite:
            problems.append(f"{what} holds {', '.join(infinite)}, not a finite number (a division by zero or an "
                            "undefined limit while building it?): give finite expressions")
        names = {coordinate_name(q) for q in coords}
        reserved = set()
        for n in names:
            reserved |= {n, n + VELOCITY_SUFFIX, n + "_ddot", "delta_" + n}
        for f in sorted(expr.atoms(AppliedUndef), key=str):
            if f in coords:
                continue
            if f.args == (t,):
                name = coordinate_name(f)
                driven = what in ("P", "rayleigh") or what.startswith("F_")
                problems.append(
                    f"{what} contains {f}, which is not a coordinate of this system "
                    f"({', '.join(sorted(names))}); add it to the coordinates or prescribe its motion"
                    + (f"; for a force given in time (a sympy specified), use an input: {name} = "
                       f"lagrange.inputs('{name}') in place of {f}, with its values given at simulate "
                       f"time (simulate(..., inputs={{{name}: value or function of t}}))" if driven else "")
                )
            else:
                problems.append(f"{what} contains {f}: coordinates must be functions of lagrange.t only")
        for d in expr.atoms(sp.Derivative):
            order = sum(c for v, c in d.variable_count)
            var_ok = all(v == t for v, _ in d.variable_count)
            if not var_ok:
                others = ", ".join(sorted({str(v) for v, _ in d.variable_count if v != t}))
                problems.append(f"{what} contains {d}: only derivatives with respect to lagrange's time t are "
                                f"allowed, not {others}")
            elif order > max_order:
                if max_order == 0:
                    problems.append(
                        f"{what} contains the velocity {d}: V must depend on coordinates and t only; "
                        "put velocity-dependent forces in P or forces"
                    )
                else:
                    problems.append(
                        f"{what} contains {d}: accelerations may not appear in T, P, D or forces"
                    )
        for s in sorted(expr.free_symbols, key=str):
            if s == t:
                continue
            if s.name == "t":
                problems.append(
                    f"{what} contains a symbol 't' that is not lagrange.t (different assumptions); "
                    "use lagrange.t for time"
                )
            elif is_input(s):
                continue  # an input: given at simulate time, never a parameter (names checked in _check_inputs)
            elif s.name in reserved:
                problems.append(
                    f"{what} contains the plain symbol {s.name!r}, which clashes with coordinate "
                    f"names; use the coordinate function {s.name.split('_dot')[0].split('_ddot')[0]}(t) "
                    "(and .diff(t) for velocities) instead"
                )
            elif declared is not None and s not in declared:
                problems.append(
                    f"{what} contains {s}, which is neither a coordinate, a declared parameter nor t"
                )

    # --- derived quantities (memoized; the System never changes) -------------------------------
    @cached_property
    def T(self) -> sp.Expr:  # noqa: F811 - set in __init__ only when the bodies' fields do not pin T down
        """The kinetic energy of ``T`` and every body together (see the class docstring). Built on first access
        when it comes wholly from bodies whose fields pin it down
        (:func:`~lagrange.derive.derivation_choice.kinetic_declaration`): the derivation cache is keyed by those
        fields, so a warm re-run never builds it."""
        total = self.T_given
        for b in self._kinematic_bodies:
            e = b.kinetic_energy()
            if self.prescribed and self.derivation != "structural":  # (as an eager T: the prescribed motion after)
                e = e.subs(self.prescribed).doit()
            total += e
        return total

    @cached_property
    def _equations(self) -> Equations:
        if self.derivation == "structural":  # seconds → a fraction: no derivation cache needed (nor its key's T)
            from ..derive.structural import structural_equations

            with self.symbolic_stage("derivation"):
                return structural_equations(self)
        # loaded from the on-disk derivation cache when this declaration was derived before (same versions)
        from ..codegen.derivation_cache import cached_equations

        return cached_equations(self, _derive_expanded)

    def symbolic_stage(self, what: str):
        """A :func:`lagrange.limits.stage` named ``what`` of this system, under its ``symbolic_timeout`` and
        ``symbolic_budget`` (None: ``$LAGRANGE_SYMBOLIC_TIMEOUT`` / ``$LAGRANGE_SYMBOLIC_BUDGET`` or the defaults)."""
        name = f" of {self.name}" if self.name else ""
        return limits.stage(f"{what}{name}", timeout=self.symbolic_timeout, budget=self.symbolic_budget)

    @property
    def derived(self) -> Equations:
        """The derived equations object (normal form ``M q̈ = f`` in plain symbols)."""
        return self._equations

    @property
    def expanded(self) -> Equations:
        """The equations in expanded form whatever :attr:`derivation` is: for ``"expanded"`` :attr:`derived`; for
        ``"structural"`` the expanded derivation (or the on-disk derivation cache), once per System and without
        deriving the structural form first — what a method that needs the whole right-hand side as one
        expression (the Taylor tape, heyoka) reads, and what the structural equations' own expanded fields are."""
        return self._equations if self.derivation != "structural" else self._expanded_equations

    def expanded_at_hand(self) -> Equations | None:
        """:attr:`expanded` when it costs no derivation — always for ``"expanded"``; for ``"structural"`` when
        this System has them already or the on-disk derivation cache holds them (loaded and kept) — else None.
        ``method="auto"`` weighs the Taylor method on a structural system only then: deriving the expanded
        equations of a large chain costs more than the run it could save."""
        if self.derivation != "structural":
            return self._equations
        if "_expanded_equations" not in self.__dict__:
            from ..codegen.derivation_cache import stored_equations

            stored = stored_equations(self)
            if stored is None:
                return None
            self.__dict__["_expanded_equations"] = stored
        return self._expanded_equations

    def __getstate__(self) -> dict:
        # a structural system's expanded equations are derived again (or loaded from the cache) where needed, not
        # shipped with it (sweep workers, pickles), as the structural equations never ship theirs
        return {k: v for k, v in self.__dict__.items() if k != "_expanded_equations"}

    @cached_property
    def _expanded_equations(self) -> Equations:
        from ..codegen.derivation_cache import cached_equations

        return cached_equations(self, _derive_expanded)

    @property
    def inputs(self) -> tuple:
        """The :class:`~lagrange.model.inputs.Input` symbols of the declaration, sorted by name: each needs a
        value at simulate time (``simulate(..., inputs={u: ...})``)."""
        return self._equations.inputs

    @property
    def parameters(self) -> tuple:
        """Parameter symbols in the order numeric models expect them (sorted by name)."""
        if self._declared_parameters is not None:
            return tuple(sorted(self._declared_parameters, key=lambda s: s.name))
        return self._equations.parameters

    def equations(self) -> list[sp.Eq]:
        r"""Lagrange's equations in Wells' form, one ``Eq`` per coordinate.

        ``d/dt(∂T/∂q̇) − ∂T/∂q + ∂V/∂q = F_q + ∂P/∂q̇ − ∂D/∂q̇``, in the coordinate functions (dots in
        Jupyter), collected in the accelerations. With constraints each equation gains the multiplier
        terms ``Σ_k λ_k A_kr`` (Wells' generalized forces of constraint) and the m constraint equations
        follow the n Lagrange equations.
        """
        from ..derive.lagrange import book_form

        return book_form(self._equations)

    @property
    def mass_matrix(self) -> sp.Matrix:
        """M = ∂²T/∂q̇∂q̇ (symmetric), in the coordinate functions."""
        from .coordinates import to_functions

        return to_functions(sp.Matrix(self._equations.mass_matrix), self.coordinates)

    @property
    def forcing(self) -> sp.Matrix:
        """f in ``M q̈ = f``, in the coordinate functions."""
        from .coordinates import to_functions

        return to_functions(sp.Matrix(self._equations.forcing), self.coordinates)

    def accelerations(self) -> sp.Matrix:
        """q̈ symbolically (small systems only; use compile() for numbers): ``M⁻¹ f``, or with constraints the
        q̈ of ``M q̈ = f + Bλ``, ``A q̈ = c`` (λ eliminated; B = Aᵀ except for rough constraints)."""
        from .coordinates import to_functions

        e = self._equations
        M, f = sp.Matrix(e.mass_matrix), sp.Matrix(e.forcing)
        if not e.m:
            return to_functions(M.LUsolve(f), self.coordinates)
        K = sp.Matrix(sp.BlockMatrix([[M, -sp.Matrix(e.reaction_matrix)],
                                      [sp.Matrix(e.constraint_matrix), sp.zeros(e.m, e.m)]]))
        sol = K.LUsolve(sp.Matrix.vstack(f, sp.Matrix(e.constraint_rhs)))
        return to_functions(sol[: e.n, 0], self.coordinates)

    def energy_split(self) -> tuple:
        """Wells' split (2.54)–(2.56) ``T = Σ A_kl q̇_k q̇_l + Σ B_k q̇_k + C`` → ``(A, B, C)``.

        ``A`` is a Matrix that already contains the 1/2 (``M = 2A``), ``B`` a column Matrix, ``C`` a scalar.
        """
        from ..derive.lagrange import energy_split

        return energy_split(self)

    def jacobi_integral(self) -> sp.Expr:
        """h = Σ q̇ ∂L/∂q̇ − L (= T + V when nothing moves and T is quadratic)."""
        from .coordinates import to_functions

        return to_functions(self._equations.jacobi, self.coordinates)

    def energy(self) -> sp.Expr:
        """Total mechanical energy T + V."""
        return self.T + self.V

    def ignorable_coordinates(self) -> dict:
        """``{q: p_q}`` for each ignorable (cyclic) coordinate and its conserved momentum ∂L/∂q̇."""
        from ..derive.lagrange import ignorable_coordinates

        return ignorable_coordinates(self)

    def generalized_forces(self) -> dict:
        """All non-potential generalized forces ``F_q + ∂P/∂q̇ − ∂D/∂q̇`` per coordinate."""
        from .coordinates import to_functions

        e = self._equations
        return {q: to_functions(e.nonconservative[i], self.coordinates) for i, q in enumerate(self.coordinates)}

    @property
    def lagrangian(self) -> sp.Expr:
        """L = T − V in the coordinate functions (P, the Rayleigh function and the forces are not part of it)."""
        return self.T - self.V

    @property
    def dof(self) -> DegreesOfFreedom:
        """``(configuration, velocity)`` degrees of freedom: n − holonomic constraints, n − all constraints."""
        n = len(self.coordinates)
        hol = sum(1 for c in self.constraints if c.kind == "holonomic")
        return DegreesOfFreedom(n - hol, n - len(self.constraints))

    @cached_property
    def declared_symbols(self) -> frozenset:
        """Every symbol of the declaration (energies, forces, constraints, prescribed motion, bodies' masses,
        positions, inertia and orientation) except ``t`` — a superset of :attr:`parameters`, which holds only
        those that survive in the equations of motion."""
        from_bodies = self.derivation == "structural" or self._T_declaration is not None
        T = self.T_given if from_bodies else self.T  # the bodies' symbols are added below (T is not built)
        exprs = [T, self.V, self.P, self.rayleigh, *self.forces.values(), *self.prescribed.values()]
        for c in self.constraints:
            exprs.append(c.velocity)
        from .rigid_body import RigidBody

        for b in self.bodies:
            if isinstance(b, RigidBody):  # its positions and R hold the symbols of its kinematics (R built on use)
                exprs += _kinematics_of(b)
                continue
            exprs += list(b.position_vectors())
            exprs += [getattr(b, a) for a in ("mass", "inertia", "com", "R", "origin") if hasattr(b, a)]
        out = set().union(*(_sympify(e).free_symbols for e in exprs))
        return frozenset(s for s in out if s != t and not s.name.startswith("delta_"))

    def bindable(self, params: Mapping | None, equations: Equations | None = None) -> dict:
        """``params`` without the values of declared parameters that cancel out of the equations of motion
        (``equations``, default :attr:`derived`; :attr:`expanded` has the same parameters).

        Those values are accepted and ignored with one :class:`~lagrange.errors.UnusedParameterWarning` naming
        them (a user's full parameter dict needs no filtering). A name the declaration does not contain is
        kept, so :func:`~lagrange.codegen.numeric.bind_parameters` reports it as unknown.
        """
        from ..errors import UnusedParameterWarning

        params = dict(params or {})
        used = {s.name for s in (self._equations if equations is None else equations).numeric_parameters}
        declared = {s.name for s in self.declared_symbols if not is_input(s)}
        if self._declared_parameters is not None:
            declared |= {s.name for s in self._declared_parameters}
        out, dropped = {}, []
        for key, value in params.items():
            name = key.name if isinstance(key, sp.Symbol) else str(key)
            if name not in used and name in declared:
                dropped.append(name)
            else:
                out[key] = value
        if dropped:
            warnings.warn(f"parameter(s) {', '.join(sorted(dropped))} of {self.name or 'the system'} cancel out of "
                          "the equations of motion; their values are ignored", UnusedParameterWarning, stacklevel=3)
        return out

    # --- numbers ------------------------------------------------------------------------------
    def compile(self, params: Mapping | None = None, *, backend: str = "python",
                inputs: Mapping | None = None, quadrature=None) -> NumericModel:
        """Generate numeric code for ``M q̈ = f`` with parameters bound to ``params``.

        Values of declared parameters that cancel out are ignored with a warning (:meth:`bindable`).
        ``inputs``: a constant value for each input of the system (:attr:`inputs`); time-varying values are
        given to :meth:`simulate`, which replaces these. ``quadrature``: the
        :class:`~lagrange.codegen.quadrature.Rule` of integrals kept for quadrature (:mod:`lagrange.model.integrals`).
        See :func:`lagrange.codegen.numeric.compile_equations`.
        """
        from ..codegen.numeric import compile_equations

        return compile_equations(self._equations, self.bindable(params), backend=backend, inputs=inputs,
                                 quadrature=quadrature)

    def multipliers_at(self, state: Mapping, params: Mapping | None = None, *, t: float = 0.0) -> dict:
        """``{constraint name: λ}`` at one state, as :meth:`Trajectory.multiplier
        <lagrange.results.trajectory.Trajectory.multiplier>` gives them along a run.

        ``state`` is keyed like ``initial`` of :meth:`simulate` (coordinates and velocities, or names); it
        must satisfy the constraints (it is not projected). ``Aᵀλ`` is the generalized constraint force
        (:meth:`constraint_forces_at`). Empty without constraints.
        """
        from ..integrate.run import initial_state

        eqs = self._equations
        if not eqs.m:
            return {}
        self._refuse_rough_at_state()
        model = self.compile(params)
        lam = model.multipliers(float(t), initial_state(eqs.coordinates, state))
        return {name: float(v) for name, v in zip(eqs.constraint_names, lam)}

    def _refuse_rough_at_state(self) -> None:
        from ..errors import LagrangeError

        if self._equations.rough_signs:
            raise LagrangeError("multipliers at a state of a system with rough constraints: the friction direction "
                                "sign(λ)·sign(v) is not fixed by the state alone; use Trajectory.multiplier of a run")

    def constraint_forces_at(self, state: Mapping, params: Mapping | None = None, *, t: float = 0.0) -> dict:
        """``{q: (Bλ)_q}`` — the generalized constraint force on each coordinate at one state (``B = Aᵀ``
        except for rough constraints); see :meth:`multipliers_at`."""
        import numpy as np

        from ..integrate.run import initial_state

        eqs = self._equations
        if not eqs.m:
            return {q: 0.0 for q in self.coordinates}
        self._refuse_rough_at_state()
        model = self.compile(params)
        y = initial_state(eqs.coordinates, state)
        lam = np.asarray(model.multipliers(float(t), y), dtype=float)
        sub = {**dict(zip(eqs.numeric_parameters, model.params)), **dict(zip(eqs.q, y[: eqs.n])),
               **dict(zip(eqs.qd, y[eqs.n:])), _TIME: float(t)}
        Bn = np.array(sp.Matrix(eqs.reaction_matrix).xreplace(sub).evalf(), dtype=float).reshape(eqs.n, eqs.m)
        return {q: float(v) for q, v in zip(self.coordinates, Bn @ lam)}

    def simulate(self, t_span, initial: Mapping, params: Mapping | None = None, **options: Any) -> Trajectory:
        """Integrate the equations of motion; see :func:`lagrange.integrate.run.simulate`."""
        from ..integrate.run import simulate

        return simulate(self, t_span, initial, params or {}, **options)

    def to_mechanics(self):
        """A formed ``sympy.physics.mechanics.LagrangesMethod`` with these equations; see
        :func:`lagrange.interop.mechanics.to_mechanics`."""
        from ..interop.mechanics import to_mechanics

        return to_mechanics(self)

    # --- display --------------------------------------------------------------------------------
    def __repr__(self) -> str:
        label = f" {self.name!r}" if self.name else ""
        names = ", ".join(coordinate_name(q) for q in self.coordinates)
        n, dof = len(self.coordinates), self.dof
        if not self.constraints:
            return f"<System{label}: {n} DOF ({names})>"
        return (f"<System{label}: {n} coordinates ({names}), {len(self.constraints)} constraint(s): "
                f"{dof.configuration} DOF in configuration, {dof.velocity} in velocity>")

    def __str__(self) -> str:
        from ..printing import format_equations

        return format_equations(self)

    def _repr_latex_(self) -> str:
        from ..printing import latex_equations

        return latex_equations(self)


def _flatten(constraints) -> list:
    """``constraints`` with each tuple or list in it (a joint's constraints) spliced in place."""
    if not isinstance(constraints, (tuple, list)):
        return constraints
    out = []
    for c in constraints:
        if isinstance(c, (tuple, list)):
            out.extend(c)
        else:
            out.append(c)
    return out


def _kinematics_of(b) -> list:
    from ..derive.derivation_choice import _kinematic_expressions

    return [sp.sympify(e) for e in _kinematic_expressions(b)]


def _check_kinematics(system, label: str, exprs: sp.Tuple, coords, presc, problems, declared) -> None:
    """The checks of T, on bodies' kinematics (masses, positions, inertias, orientations): no velocities, no
    unknown functions or symbols."""
    d = exprs.atoms(sp.Derivative)
    if d:
        problems.append(f"{label} contain the velocity {sorted(d, key=str)[0]}: positions, orientations, masses "
                        "and inertias depend on the coordinates and t only")
        return
    system._check_expr(label, exprs, coords, presc, 1, problems, declared)


def _check_inputs(T, V, specs, presc, P, D, F, coords, problems) -> None:
    """Inputs may drive the system through forces, P and the Rayleigh function only (see
    :mod:`lagrange.model.inputs`): T, V, constraints and prescribed motions are differentiated in time, which
    would need the input's derivative. Also: an input named like a coordinate, a velocity or a parameter."""
    fix = "put the input's generalized force in forces (a potential V(q, u) gives F_q = -dV/dq)"
    for what, expr in (("T", T), ("V", V)):
        for u in sorted(inputs_in([expr]), key=str):
            problems.append(f"{what} contains the input {u}: {what} is differentiated in time (d/dt dT/dq_dot, "
                            f"the power balance's dL/dt), which would need du/dt; {fix}")
    for spec in specs:
        found = inputs_in([spec.velocity] + ([spec.position] if spec.position is not None else []))
        for u in sorted(found, key=str):
            problems.append(f"constraint {spec.name} contains the input {u}: constraints are differentiated in "
                            "time (A q_ddot = c needs du/dt); a motion given in time is a prescribed motion "
                            "(prescribed={q: expression of t}) or a time-dependent constraint")
    for key, val in presc.items():
        for u in sorted(inputs_in([val]), key=str):
            problems.append(f"prescribed motion of {coordinate_name(key)} contains the input {u}: a prescribed "
                            "motion is differentiated twice; give it as an expression of t")
    names = {coordinate_name(q) for q in coords}
    used = inputs_in([P, D, *F.values()])
    others = set().union(*(_sympify(e).free_symbols for e in (T, V, P, D, *F.values())))
    clash_params = {s.name for s in others if not is_input(s)}
    for u in sorted(used, key=str):
        if u.name in names or u.name.removesuffix(VELOCITY_SUFFIX) in names:
            problems.append(f"the input {u} is named like a coordinate or velocity of this system: an input is not "
                            "a coordinate; rename it")
        elif u.name in clash_params:
            problems.append(f"the input {u} and a parameter share the name {u.name!r}: rename one of them")


def _not_a_coordinate(c) -> str:
    if isinstance(c, AppliedUndef) and len(c.args) == 1 and isinstance(c.args[0], sp.Symbol):
        return (f"{c} is a function of {c.args[0]!r}, which is not lagrange's time t: declare coordinates with "
                "lagrange.coordinates('q1 q2'), or with sympy's dynamicsymbols at their default time Symbol('t')")
    return (f"{c!r} is not a coordinate: declare coordinates with lagrange.coordinates('q1 q2'), "
            "which gives functions of lagrange.t")


def _substitute_constraint(c, presc):
    from .constraints import Differential, Holonomic, Nonholonomic

    def sub(x):
        return _sympify(x).subs(presc).doit()

    if isinstance(c, (Holonomic, Nonholonomic)):
        return type(c)(sub(c.expr), c.name, *((c.unilateral,) if isinstance(c, Holonomic) else ()))
    if isinstance(c, Differential):
        return Differential({k: sub(v) for k, v in c.coefficients.items()}, sub(c.dt), c.name)
    return sub(c)


def _holds_integral(*items) -> bool:
    """True when a declared P, Rayleigh function or force (as given: expressions, a dict of generalized forces, or
    Force/Torque objects) holds an ``Integral``."""
    for item in items:
        if isinstance(item, dict):
            item = list(item.values())
        for e in item if isinstance(item, (list, tuple)) else [item]:
            e = getattr(e, "vector", e)
            parts = e if isinstance(e, (list, tuple, sp.MatrixBase)) else [e]
            if any(isinstance(x, sp.Basic) and x.has(sp.Integral) for x in parts):
                return True
    return False


def _substitute_forces(forces, presc):
    # a prescribed coordinate has no virtual displacement: with t frozen, δs = 0 (Wells Ex. 4.9)
    frozen = {virtual_displacement(k): 0 for k in presc}

    def sub(x):
        return _sympify(x).subs(presc).doit().subs(frozen)

    items = forces if isinstance(forces, (list, tuple)) else [forces]
    out = []
    for item in items:
        if isinstance(item, Mapping):
            out.append({k: sub(v) for k, v in item.items()})
        elif isinstance(item, Force):
            at = item.at.subs(presc) if item.body is not None else item.at.subs(presc).doit()
            out.append(Force(at, item.vector.subs(presc).doit(), item.name))
        elif type(item).__name__ == "Torque":
            out.append(type(item)(item.body.subs(presc), item.vector.subs(presc).doit(), item.frame))
        else:
            out.append(sub(item))
    return out
