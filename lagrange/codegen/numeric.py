"""Numeric models: generated ``rhs(t, y, p)`` plus vectorized energy and power for diagnostics.

Backends (``backend=``):

``"python"`` (default)
    CSE'd straight-line Python on floats with an unrolled LDLᵀ solve. Instant to build, no compiler.
``"numba"``
    The same source compiled with ``numba.njit``; the module is written to the on-disk cache
    (:func:`lagrange.codegen.numba_backend.cache_dir`, ``$LAGRANGE_CACHE_DIR``) keyed by a hash of the
    source, so numba's own cache makes re-runs skip the JIT. Needs the ``fast`` extra
    (``pip install "lagrange-dynamics[fast]"``).
``"reference"``
    Plain ``sympy.lambdify`` of M and f without CSE plus ``numpy.linalg.solve``: the slow oracle every
    fast backend is tested against.
``"auto"``
    ``"numba"`` when numba is importable, else ``"python"``.

The generated source of ``"python"`` and ``"numba"`` is also kept in the derivation cache
(:mod:`lagrange.codegen.derivation_cache`), keyed by the equations' content, so a re-run skips the CSE and
printing too.
"""

from __future__ import annotations

import builtins
import importlib.util
import inspect
import math
import weakref
from collections.abc import Callable, Mapping
from dataclasses import field, replace
from functools import cached_property

import numpy as np
import sympy as sp

from ..derive.equations import Equations
from ..errors import BackendError, ParameterError, SingularMassMatrixError, SpecError, shown
from ..model.coordinates import coordinate_name
from ..records import record
from ..safe_sympify import lambdify as _lambdify

__all__ = ["NumericModel", "ConstraintFunctions", "compile_equations", "bind_parameters", "BACKENDS"]

BACKENDS = ("python", "numba", "reference", "auto")


def _number(raw, where: str) -> float:
    """The float of a parameter value: a number, a constant sympy expression, or a string holding an
    expression of numbers, read by the spec parser (:func:`lagrange.spec.expressions.parse_expression`, which
    evaluates nothing); a string is never given to ``sympify`` (that is ``eval``). TypeError/ValueError
    otherwise."""
    if isinstance(raw, str):
        from ..spec.expressions import parse_expression

        raw = parse_expression(raw, {}, where=where)
    if isinstance(raw, sp.Basic):
        return float(raw.evalf())
    return float(raw)


def bind_parameters(eqs: Equations, params: Mapping) -> np.ndarray:
    """Values for the ``p`` vector, in the order of ``eqs.numeric_parameters``; keys may be symbols or names.

    ``params`` holds the parameters and a constant value for each input (``eqs.inputs``; a time-varying
    input's slot holds any number, refilled per call by the model's schedule). A string value is read by the
    spec parser as an expression of numbers (``"2*pi"``), never evaluated. Raises
    :class:`ParameterError` listing every missing, unknown or non-finite value.
    """
    by_name = {}
    for key, value in params.items():
        name = key.name if isinstance(key, sp.Symbol) else str(key)
        by_name[name] = value
    wanted = [s.name for s in eqs.parameters]
    inputs = [s.name for s in eqs.inputs]
    missing = [n for n in wanted if n not in by_name]
    unknown = sorted(set(by_name) - set(wanted) - set(inputs) - {s.name for s in eqs.rough_signs})
    problems = []
    if missing:
        problems.append(f"missing value(s) for parameter(s) {', '.join(missing)}")
    missing_inputs = [n for n in inputs if n not in by_name]
    if missing_inputs:
        from .input_values import input_help

        problems.append(f"missing value(s) for input(s) {', '.join(missing_inputs)}: "
                        f"{input_help(missing_inputs[0])} (compile takes constants; simulate any form)")
    if unknown:
        problems.append(
            f"unknown parameter(s) {', '.join(unknown)} (this system's parameters: "
            f"{', '.join(wanted) or 'none'})"
        )
    values = []
    for n in wanted + inputs:
        if n in by_name:
            try:
                v = _number(by_name[n], f"{'input' if n in inputs else 'parameter'} {n}")
            except OverflowError:
                problems.append(f"{'input' if n in inputs else 'parameter'} {n} = {shown(by_name[n])} is beyond the "
                                "floating-point range (about 1.8e308)")
                continue
            except (TypeError, ValueError) as exc:
                kind = "input" if n in inputs else "parameter"
                extra = " (time-varying inputs are given to simulate)" if n in inputs else ""
                why = f" ({exc})" if isinstance(exc, SpecError) else ""
                problems.append(f"{kind} {n} = {shown(by_name[n])} is not a number{extra}{why}")
                continue
            if not math.isfinite(v):
                problems.append(f"{'input' if n in inputs else 'parameter'} {n} = {v} is not finite")
            values.append(v)
    if problems:
        raise ParameterError("; ".join(problems))
    k = len(wanted)
    signs = [float(by_name.get(s.name, 1.0)) for s in eqs.rough_signs]
    return np.array(values[:k] + signs + values[k:], dtype=float)


@record(frozen=True)
class NumericModel:
    """A compiled system with bound parameters.

    Attributes
    ----------
    equations : Equations
    params : ndarray, shape (k,) — values in the order of ``equations.parameters``
    backend : str
    source : str — the generated source of ``rhs`` (empty for the reference backend; with numba and no
        constraints the whole module, including the ``field`` the compiled integrator loops call)
    dynamics : callable ``dynamics(t, y, p) -> [q̇, q̈, λ]`` (``[q̇, q̈]`` without constraints)
    rhs : callable ``rhs(t, y, p) -> [q̇, q̈]``, shape (2n,)
    schedule : :class:`~lagrange.codegen.input_values.InputSchedule` or None — time-varying inputs: ``dynamics``
        and ``rhs`` then overwrite the input slots of any ``p`` they are given with ``schedule(t, y)``
        (:meth:`with_schedule`); None when every input is constant (bound in ``params``)
    """

    equations: Equations
    params: np.ndarray
    backend: str
    source: str
    dynamics: Callable
    _aux: Callable = field(repr=False)
    _mass_forcing: Callable = field(repr=False)
    schedule: object = None

    @property
    def n(self) -> int:
        return self.equations.n

    @property
    def m(self) -> int:
        """Number of constraints (multipliers)."""
        return self.equations.m

    def __post_init__(self):
        # the python backend unpacks p into Python floats (fast scalar arithmetic); numba wants an array
        call = tuple(float(v) for v in self.params) if self.backend == "python" else self.params
        object.__setattr__(self, "_pcall", call)
        raw = getattr(self.dynamics, "_lagrange_raw", self.dynamics)
        if self.schedule is not None:
            object.__setattr__(self, "dynamics", _scheduled(raw, self.schedule, self.equations, self.backend))
        else:
            object.__setattr__(self, "dynamics", raw)
        if self.equations.m:
            dyn, n2 = self.dynamics, 2 * self.n

            def rhs(t, y, p):
                return dyn(t, y, p)[:n2]

            object.__setattr__(self, "rhs", rhs)
        else:
            object.__setattr__(self, "rhs", self.dynamics)

    def __reduce__(self):
        """Pickle by source: the equations, parameter values, backend and generated source travel, and the
        compiled callables are rebuilt on unpickling (``exec`` of the source for ``python``, the on-disk
        cache for ``numba``), so a model can be sent to worker processes or a Dask cluster."""
        return (_rebuild_model, (self.equations, self.params, self.backend, self.source, self.schedule))

    def with_params(self, params: Mapping) -> NumericModel:
        """The same compiled code with some parameter values replaced (keys: symbols or names); cheap, no
        code generation. Raises :class:`ParameterError` for unknown or non-finite values."""
        current = {s.name: v for s, v in zip(self.equations.numeric_parameters, self.params)}
        for key, value in params.items():
            current[key.name if isinstance(key, sp.Symbol) else str(key)] = value
        return replace(self, params=bind_parameters(self.equations, current))

    def with_schedule(self, schedule) -> NumericModel:
        """The same compiled code driven by time-varying input values (an
        :class:`~lagrange.codegen.input_values.InputSchedule`, or None for the constants in ``params``)."""
        return replace(self, schedule=schedule)

    def parameters_at(self, t: float, y) -> list:
        """The ``p`` vector in force at ``(t, y)``: ``params`` with the inputs' slots refilled by the schedule."""
        p = self.params.tolist()
        if self.schedule is not None:
            k0 = self.equations.input_offset
            p[k0:k0 + len(self.equations.inputs)] = self.schedule(t, np.asarray(y)[: 2 * self.n])
        return p

    def input_values(self, t, Y) -> np.ndarray:
        """The inputs' values at output points: ``t`` shape (m,), ``Y`` shape (m, 2n) → shape (m, k), columns in
        the order of ``equations.inputs``."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        k0, k = self.equations.input_offset, len(self.equations.inputs)
        if self.schedule is not None:
            return self.schedule.many(t, Y)
        return np.broadcast_to(self.params[k0:k0 + k], (len(t), k)).copy()

    def rhs_many(self, t, Y, P=None, *, columns: bool = False) -> np.ndarray:
        """``dy/dt`` for many states (and parameter sets) at once.

        Parameters
        ----------
        t : float or ndarray, shape (k,) — one time, or one time per member
        Y : ndarray, shape (k, 2n) — states ``[q, q̇]`` in rows; with ``columns=True`` shape (2n, k), one
            member per column (each variable contiguous: the layout of the compiled kernel, no transposes)
        P : None (the bound parameters for every member) or ndarray, shape (k, len(params)); with
            ``columns=True`` shape (len(params), k)
        columns : bool — the layout of ``Y``, ``P`` and the result (default False: rows)

        Returns
        -------
        ndarray, shape (k, 2n) (``columns=True``: (2n, k)): member i is ``rhs(t[i], Y[i], P[i])`` (λ dropped
        with constraints), the same numbers as the per-member ``rhs``. With the numba backend an unconstrained
        model without time-varying inputs runs one compiled loop over the members, vectorized across them
        (:mod:`lagrange.codegen.batch_source`); a constrained model runs a compiled loop calling ``rhs`` per
        member; the other backends loop in Python.

        Raises
        ------
        ValueError
            Shapes that do not match the model.
        SingularMassMatrixError
            A member at which the mass matrix is singular (the member's state is named).
        """
        if columns:
            Yc, Pc, tt = self._column_arguments(t, Y, P)
            if self._has_column_kernel:
                out = self._run_columns(tt, Yc, Pc)
                if out is not None:
                    return out
            return np.ascontiguousarray(self._rows_many(tt, np.ascontiguousarray(Yc.T),
                                                        np.ascontiguousarray(Pc.T)).T)
        Y, P, tt = self._many_arguments(t, Y, P)
        if self._has_column_kernel:
            out = self._run_columns(tt, np.ascontiguousarray(Y.T), np.ascontiguousarray(P.T))
            if out is not None:
                return np.ascontiguousarray(out.T)
        return self._rows_many(tt, Y, P)

    @property
    def _has_column_kernel(self) -> bool:
        # structural equations have no straight-line M and f to vectorize: their compiled rhs per member
        return (self.backend == "numba" and self.schedule is None and not self.equations.m
                and not self.equations.is_structural and not self.equations.has_quadrature)

    def _run_columns(self, tt, Yc, Pc):
        """The vectorized kernel's result, shape (2n, k), or None when a member's mass matrix failed the
        pivot test or a result is not finite (the caller re-runs member by member: same numbers or the
        per-member error)."""
        kernel, n_calls = self._column_kernel
        k = Yc.shape[1]
        out = np.empty((2 * self.n, k))
        bad = kernel(tt, Yc, Pc, tuple(out), np.empty((max(n_calls, 1), k)))
        if bad or not np.isfinite(out).all():
            return None
        return out

    def _rows_many(self, tt, Y, P) -> np.ndarray:
        n2 = 2 * self.n
        if self.backend == "numba" and self.schedule is None:
            try:
                return self._compiled_many(tt, Y, P)
            except ZeroDivisionError:
                pass  # find the row below, with the error naming its state
        out = np.empty((Y.shape[0], n2))
        rows = P.tolist() if self.backend == "python" else P
        for i in range(Y.shape[0]):
            try:
                out[i] = self.dynamics(tt[i], Y[i], rows[i])[:n2]
            except ZeroDivisionError:
                raise replace(self, params=P[i]).singular_error(tt[i], Y[i]) from None
        return out

    def _many_arguments(self, t, Y, P):
        Y = np.ascontiguousarray(Y, dtype=float)
        k, width = Y.shape if Y.ndim == 2 else (0, -1)
        if width != 2 * self.n:
            raise ValueError(f"Y must have shape (k, {2 * self.n}) (rows [q, q_dot]), got {np.shape(Y)}")
        P = np.broadcast_to(self.params, (k, len(self.params))) if P is None else np.asarray(P, dtype=float)
        if P.shape != (k, len(self.params)):
            raise ValueError(f"P must have shape ({k}, {len(self.params)}) (one parameter vector per row of Y, "
                             f"in the order {', '.join(s.name for s in self.equations.numeric_parameters)}), "
                             f"got {P.shape}")
        tt = np.ascontiguousarray(np.broadcast_to(np.asarray(t, dtype=float), (k,)))
        return Y, np.ascontiguousarray(P), tt

    def _column_arguments(self, t, Y, P):
        Y = np.ascontiguousarray(Y, dtype=float)
        height, k = Y.shape if Y.ndim == 2 else (-1, 0)
        if height != 2 * self.n:
            raise ValueError(f"with columns=True, Y must have shape ({2 * self.n}, k) (columns [q, q_dot]), "
                             f"got {np.shape(Y)}")
        kp = len(self.params)
        P = np.broadcast_to(self.params[:, None], (kp, k)) if P is None else np.asarray(P, dtype=float)
        if P.shape != (kp, k):
            raise ValueError(f"with columns=True, P must have shape ({kp}, {k}) (one parameter vector per column "
                             f"of Y, rows in the order {', '.join(s.name for s in self.equations.numeric_parameters)}"
                             f"), got {P.shape}")
        tt = np.ascontiguousarray(np.broadcast_to(np.asarray(t, dtype=float), (k,)))
        return Y, np.ascontiguousarray(P), tt

    @cached_property
    def _compiled_many(self) -> Callable:
        return _numba_many(self.dynamics, 2 * self.n)

    @cached_property
    def _column_kernel(self) -> tuple[Callable, int]:
        return _numba_columns(self.equations, len(self.params))

    def multipliers(self, t: float, y: np.ndarray) -> np.ndarray:
        """λ at ``(t, y)``, shape (m,): ``Aᵀλ`` is the generalized force of the constraints."""
        try:
            return np.asarray(self.dynamics(t, y, self._pcall)[2 * self.n :], dtype=float)
        except ZeroDivisionError:
            raise self.singular_error(t, y) from None

    def fun(self, t: float, y: np.ndarray) -> np.ndarray:
        """``dy/dt`` at ``(t, y)`` with the bound parameters (the form scipy's solvers call)."""
        try:
            return self.rhs(t, y, self._pcall)
        except ZeroDivisionError:
            raise self.singular_error(t, y) from None

    def singularity(self, t: float, y: np.ndarray) -> tuple[str, str]:
        """Why the generated solve fails at ``(t, y)``: ``(kind, text)`` computed from M and the constraint
        Jacobian there (:func:`lagrange.codegen.singular.diagnose`: ``"dependent"`` constraints, a ``"mass"``
        matrix singular on the allowed motions, or an ``"ill-conditioned"`` solve at a regular configuration)."""
        from .singular import diagnose

        M, _ = self.mass_and_forcing(t, y)
        A = self.constraint_functions.matrix(t, np.asarray(y)[: self.n]) if self.m else None
        names = [coordinate_name(c) for c in self.equations.coordinates]
        state = ", ".join(f"{nm}={y[i]:.6g}" for i, nm in enumerate(names))
        return diagnose(M, A, names, self.equations.constraint_names if self.m else (), where=f"at t={t:.6g} ({state})")

    def singular_error(self, t: float, y: np.ndarray) -> SingularMassMatrixError:
        """An error naming the cause of the failed solve at ``(t, y)`` (:meth:`singularity`): the dependent
        constraints, or the coordinates of the singular mass matrix, with the ranks; or, at a regular
        configuration, the ill-conditioning."""
        return SingularMassMatrixError(self.singularity(t, y)[1])

    @cached_property
    def constraint_functions(self) -> ConstraintFunctions:
        """Numeric φ, A, b for projection and violation reports (built on first use)."""
        return ConstraintFunctions(self.equations, self.params)

    @cached_property
    def _mass_only(self) -> Callable:
        # the python module's own mass(t, y, p) (same CSE, compiled with rhs): nothing to print or lambdify
        raw = getattr(self.dynamics, "_lagrange_raw", self.dynamics)
        mass = raw.__globals__.get("mass") if self.backend == "python" else None
        if mass is not None:
            return mass
        from .cse import numeric_arguments, rename_map  # (here: not on a warm re-run's path)

        ren = rename_map(self.equations)
        tt, ys, ps = numeric_arguments(self.equations)
        # rows of floats from the math module, as the generated code uses: lambdify's numpy namespace imports
        # numpy.f2py, numpy.testing and numpy.ma (0.3 s of a warm re-run of a model with Euler angles)
        return _lambdify((tt, ys, ps), self.equations.mass_matrix.xreplace(ren).tolist(), modules="math", cse=True)

    def mass_matrix(self, t: float, y) -> np.ndarray:
        """Numeric ``M`` (n, n) at ``(t, y)``, ``y = [q, q̇]`` (M depends on t and q only). Its function is built
        on first use: one CSE'd function of M alone, a third of the cost of :meth:`mass_and_forcing` per
        call when f is not needed."""
        M = self._mass_only(float(t), np.asarray(y, dtype=float).tolist(), self.params.tolist())
        return np.array(M, dtype=float).reshape(self.n, self.n)

    def mass_and_forcing(self, t: float, y) -> tuple[np.ndarray, np.ndarray]:
        """Numeric ``M`` (n, n) and ``f`` (n,) at one state."""
        M, f = self._mass_forcing(t, np.asarray(y, dtype=float), self.parameters_at(t, y))
        return np.array(M, dtype=float).reshape(self.n, self.n), np.array(f, dtype=float).reshape(self.n)

    def diagnostics(self, t, y) -> dict[str, np.ndarray]:
        """Vectorized ``T``, ``V``, ``energy`` (T+V), ``jacobi`` (h), ``power`` (dh/dt) and the quadratic and
        velocity-free parts ``T2``, ``T0`` of T over states.

        ``t`` shape (m,), ``y`` shape (m, 2n).
        """
        t = np.asarray(t, dtype=float)
        y = np.asarray(y, dtype=float)
        cols = [y[:, i] for i in range(y.shape[1])]
        lam = [np.zeros_like(t)] * self.m
        if self.m and lam_required(self.equations):
            L = np.array([self.multipliers(ti, yi) for ti, yi in zip(t, y)]).reshape(len(t), self.m)
            lam = [L[:, k] for k in range(self.m)]
        p = list(self.params)
        if self.schedule is not None:  # per-row input values (the aux function broadcasts arrays)
            k0, U = self.equations.input_offset, self.schedule.many(t, y)
            p[k0:k0 + U.shape[1]] = [U[:, j] for j in range(U.shape[1])]
        vals = self._aux(t, cols, p, lam)
        names = ("T", "V", "jacobi", "power", "T2", "T0")
        out = {k: np.broadcast_to(np.asarray(v, dtype=float), t.shape).copy() for k, v in zip(names, vals)}
        out["energy"] = out["T"] + out["V"]
        return out

    # --- what the Taylor method and the heyoka backend consume, produced by codegen on request ---------------
    @staticmethod
    def tape_for(eqs: Equations):
        """The Taylor tape of ``eqs`` before any model is built (:func:`lagrange.codegen.tape.tape_of`; raises
        :class:`~lagrange.codegen.tape.TapeError` naming a constraint or a non-analytic function)."""
        from .tape import tape_of

        return tape_of(eqs)

    @staticmethod
    def taylor_obstacle(eqs: Equations, values=None, y0=None, rates=None, horizon: float = 1.0, t0: float = 0.0):
        """Why a Taylor-series method cannot be trusted on ``eqs`` with these parameter ``values`` from ``y0``
        (:func:`lagrange.codegen.analyticity.obstacle`: a non-analytic function, a kink or a near-singularity),
        or None."""
        from .analyticity import obstacle

        return obstacle(eqs, values, y0, rates, horizon, t0)

    def taylor_tape(self):
        """The Taylor tape of the equations (:func:`lagrange.codegen.tape.tape_of`; built once per Equations).
        Raises :class:`~lagrange.codegen.tape.TapeError` for constraints or a non-analytic function."""
        from .tape import tape_of

        return tape_of(self.equations)

    def taylor_series(self, order: int | None = None):
        """The tape's numba-compiled ``series`` for ``order`` (:func:`lagrange.codegen.taylor_source.
        compiled_series`; cached on disk). Raises BackendError without numba."""
        from .taylor_source import compiled_series

        return compiled_series(self.taylor_tape(), order)

    @staticmethod
    def taylor_interpreter():
        """``(path, None)`` of the C Taylor interpreter library, or ``(None, reason)``
        (:func:`lagrange.codegen.c_interpreter.library_path_or_reason`)."""
        from .c_interpreter import library_path_or_reason

        return library_path_or_reason()

    def heyoka_taylor(self):
        """The model's equations as heyoka expressions (:func:`lagrange.codegen.heyoka_expr.heyoka_odes`;
        built once per Equations). Raises BackendError without heyoka or for what heyoka cannot take."""
        from .heyoka_expr import heyoka_odes

        return heyoka_odes(self.equations)

    def heyoka_shape(self):
        """``n``, ``nz``, ``n_params`` of the heyoka system, after its refusals, without building it
        (:func:`lagrange.codegen.heyoka_expr.heyoka_shape`)."""
        from .heyoka_expr import heyoka_shape

        return heyoka_shape(self.equations)

    def heyoka_events(self, events, t0: float, z0) -> tuple:
        """The user's event callables traced into heyoka events (:func:`lagrange.codegen.heyoka_events.
        heyoka_events`); MethodError for one that cannot be traced."""
        from .heyoka_events import heyoka_events

        return heyoka_events(events, self.heyoka_shape().nz, t0, z0)

    def heyoka_integrator(self, tol: float, events: tuple = (), batch: int = 0):
        """``(taylor_adaptive, origin, order)``: heyoka's compiled integrator of the equations with ``events``
        (``batch`` > 0: a ``taylor_adaptive_batch`` of that size), loaded from the on-disk cache when an
        authenticated entry exists (:func:`lagrange.codegen.heyoka_jit.integrator`)."""
        from .heyoka_jit import integrator

        return integrator(self.equations, tol, events, batch)

    # -- what integration needs besides rhs: generated here on request (lagrange.integrate imports this type
    #    and nothing else from codegen; see lagrange/integrate/__init__.py) --

    @staticmethod
    def build(eqs: Equations, params: Mapping, *, backend: str = "python", baumgarte: tuple | None = None,
              inputs: Mapping | None = None) -> NumericModel:
        """:func:`compile_equations` of ``eqs``; ``baumgarte=(α, β)`` compiles ``A q̈ = c − 2α g − β² φ``
        (:func:`~lagrange.codegen.run_functions.baumgarte_rhs`) instead of ``A q̈ = c``."""
        crhs = None
        if baumgarte is not None and eqs.m:
            from .run_functions import baumgarte_rhs

            crhs = baumgarte_rhs(eqs, *baumgarte)
        return compile_equations(eqs, params, backend=backend, constraint_rhs=crhs, inputs=inputs)

    @staticmethod
    def resolve_inputs(eqs: Equations, inputs, t_span, y0) -> tuple[dict, object]:
        """``(constants, schedule)`` of the input values ``inputs``
        (:func:`~lagrange.codegen.input_values.resolve_inputs`)."""
        from .input_values import resolve_inputs

        return resolve_inputs(eqs, inputs, t_span, y0)

    @staticmethod
    def varying_routes() -> str:
        """Which routes run time-varying inputs (:data:`~lagrange.codegen.input_values.VARYING_ROUTES`)."""
        from .input_values import VARYING_ROUTES

        return VARYING_ROUTES

    @staticmethod
    def switches_of(eqs: Equations) -> list:
        """The dry-friction switches of ``eqs`` (:func:`~lagrange.codegen.switches.switching_functions`)."""
        from .switches import switching_functions

        return switching_functions(eqs)

    @staticmethod
    def regularized(eqs: Equations, epsilon: float) -> Equations:
        """``eqs`` with ``sign(u) → u/sqrt(u² + ε²)`` (:func:`~lagrange.codegen.switches.regularized_equations`)."""
        from .switches import regularized_equations

        return regularized_equations(eqs, epsilon)

    @staticmethod
    def planar_friction(eqs: Equations, treatment, epsilon) -> Equations:
        """``eqs`` with friction over a rough surface formed from its sliding components (exact |v|, floored,
        or regularized sqrt(|v|² + ε²)) (:func:`~lagrange.codegen.rough_friction.planar_friction_for`)."""
        from .rough_friction import planar_friction_for

        return planar_friction_for(eqs, treatment, epsilon)

    @staticmethod
    def cache_location() -> str:
        """Where lagrange's cache is (:func:`~lagrange.codegen.cache.cache_root`, not created): the key under
        which a process keeps the kernels it loaded from it."""
        from .cache import cache_root

        return str(cache_root())

    @staticmethod
    def load_kernel(text: str, prefix: str, what: str):
        """A self-contained numba module from its source ``text``, imported from lagrange's cache directory
        (:func:`~lagrange.codegen.numba_backend.load_cached`); BackendError naming ``what`` without numba."""
        from .numba_backend import _require_numba, load_cached

        _require_numba(what)
        return load_cached(prefix, text, f"the kernel for {what}")

    @cached_property
    def lam_required(self) -> bool:
        """Whether the power balance needs the multipliers λ (moving constraints do work)."""
        return lam_required(self.equations)

    @cached_property
    def jacobian(self) -> Callable:
        """``jac(t, y) -> (2n, 2n)`` (:func:`~lagrange.codegen.run_functions.jacobian_function`), built once."""
        from .run_functions import jacobian_function

        return jacobian_function(self)

    @cached_property
    def power(self) -> Callable:
        """``power(t, y_list, lam_list)`` = dh/dt (:func:`~lagrange.codegen.run_functions.power_function`)."""
        from .run_functions import power_function

        return power_function(self)

    @cached_property
    def sliding(self) -> Callable:
        """``v(t, y, p)``: rough constraints' sliding velocities
        (:func:`~lagrange.codegen.run_functions.sliding_functions`)."""
        from .run_functions import sliding_functions

        return sliding_functions(self)

    def switched(self, switches: list):
        """The frozen-switch pieces for the friction driver
        (:func:`~lagrange.codegen.run_functions.switched_pieces`)."""
        from .run_functions import switched_pieces

        return switched_pieces(self, switches)

    def hamiltonian(self):
        """The :class:`~lagrange.codegen.hamiltonian_model.HamiltonianModel` of these equations and parameter
        values (conservative unconstrained systems; memoized per equations and values)."""
        from .hamiltonian_model import hamiltonian_model

        return hamiltonian_model(self.equations, np.asarray(self.params, dtype=float))


def _reference_functions(eqs: Equations):
    from .cse import numeric_arguments, rename_map  # (here: not on a warm re-run's path)

    ren = rename_map(eqs)
    n = eqs.n
    tt, ys, ps = numeric_arguments(eqs)
    M = eqs.mass_matrix.xreplace(ren)
    f = eqs.forcing.xreplace(ren)
    # integrals that remain (lagrange.codegen.quadrature) by scipy's adaptive quad/nquad: the oracle stays
    # independent of the generated Gauss-Legendre sums
    modules = ["scipy", "numpy"] if eqs.has_quadrature else "numpy"
    mf = _lambdify((tt, ys, ps), (M, f), modules=modules, cse=False)

    def mass_forcing(t_, y, p):
        return mf(t_, list(y), list(p))

    m = eqs.m
    Ac = _lambdify((tt, ys, ps), (eqs.constraint_matrix.xreplace(ren), sp.Matrix(eqs.constraint_rhs).xreplace(ren),
                                    eqs.reaction_matrix.xreplace(ren)), modules="numpy") if m else None

    def rhs(t_, y, p):
        Mv, fv = mass_forcing(t_, y, p)
        Mv = np.array(Mv, dtype=float)
        if not np.all(np.isfinite(Mv)) or (not m and np.linalg.cond(Mv) > 1e15):
            raise ZeroDivisionError("mass matrix is singular")
        fv = np.array(fv, dtype=float).ravel()
        if not m:
            return np.concatenate([np.asarray(y[n:], dtype=float), np.linalg.solve(Mv, fv)])
        Av, cv, Bv = Ac(t_, list(y), list(p))
        Av = np.array(Av, dtype=float).reshape(m, n)
        K = np.block([[Mv, -np.array(Bv, dtype=float).reshape(n, m)], [Av, np.zeros((m, m))]])
        if np.linalg.cond(K) > 1e15:
            raise ZeroDivisionError("constraint Jacobian is rank deficient")
        sol = np.linalg.solve(K, np.concatenate([fv, np.array(cv, dtype=float).ravel()]))
        return np.concatenate([np.asarray(y[n:], dtype=float), sol])

    return rhs, mass_forcing


def _aux_function(eqs: Equations):
    """The diagnostics ``aux(t, cols, p, λ) -> [T, V, h, dh/dt, T2, T0]``, vectorized over the columns: a numpy
    lambdify whose generated source (``inspect.getsource``) is kept in the derivation cache like the
    right-hand side's, so a later model of the same equations execs it (no printing, no lambdify) — every run's
    verdict checks the energy. Kept only when every name the source uses is numpy's or a builtin, as lambdify's
    namespace gives it (else lambdify each time)."""
    from .derivation_cache import cached_code, cached_source

    def generate() -> str:
        f = _aux_lambdify(eqs)
        plain = all(f.__globals__.get(n, getattr(builtins, n, None)) is getattr(np, n, getattr(builtins, n, None))
                    for n in _names(f.__code__))
        return inspect.getsource(f) if plain else ""

    source = cached_source(eqs, "diagnostics T, V, h, dh/dt, T2, T0 (numpy lambdify, cse)", generate)
    if not source:
        f = _aux_lambdify(eqs)
    else:
        code = cached_code(source, "<lagrange diagnostics>")
        namespace = {n: getattr(np, n) for n in _names(code) if hasattr(np, n)}
        exec(code, namespace)  # noqa: S102 - lambdify's own text, numpy names only
        f = namespace["_lambdifygenerated"]

    def aux(t_, cols, p, lam):
        return f(t_, cols, list(p), list(lam))

    return aux


def _names(code) -> set[str]:
    """Every global name a code object (and the code objects it holds) looks up."""
    out = set(code.co_names)
    for const in code.co_consts:
        if inspect.iscode(const):
            out |= _names(const)
    return out


def _aux_lambdify(eqs: Equations):
    from .cse import numeric_arguments, rename_map  # (here: not on a warm re-run's path)

    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)
    T, h, T2, T0 = eqs.energy_parts()
    exprs = [sp.sympify(e).xreplace(ren) for e in (T, eqs.potential, h, eqs.jacobi_rate, T2, T0)]
    args = (tt, ys, ps, list(eqs.multipliers))
    if any(e.has(sp.Integral) for e in exprs):  # integrals by quadrature, one sample at a time
        from .quadrature import python_function

        g = python_function(args, exprs)

        def aux(t_, cols, p, lam):
            tv = np.broadcast_to(np.asarray(t_, dtype=float), np.shape(cols[0]))
            rows = [g(tv[i], [c[i] for c in cols], [float(np.broadcast_to(v, tv.shape)[i]) for v in p],
                      [np.broadcast_to(v, tv.shape)[i] for v in lam]) for i in range(tv.size)]
            return [np.array([r[k] for r in rows]) for k in range(len(exprs))]

        return aux
    return _lambdify(args, exprs, modules="numpy", cse=True)


def lam_required(eqs: Equations) -> bool:
    """True when the power balance needs λ (moving constraints do work)."""
    return bool(eqs.m) and bool(eqs.jacobi_rate.free_symbols & set(eqs.multipliers))


class ConstraintFunctions:
    """Numeric constraint pieces at bound parameters: ``phi(t, q)`` of the holonomic constraints,
    their Jacobian ``holonomic_matrix(t, q)``, and ``matrix(t, q)`` / ``bias(t, q)`` (A, b) of all."""

    def __init__(self, eqs: Equations, params: np.ndarray):
        from .cse import numeric_arguments, rename_map  # (here: not on a warm re-run's path)

        ren = rename_map(eqs)
        n = eqs.n
        tt, ys, ps = numeric_arguments(eqs)
        qs = ys[:n]
        self.holonomic = [k for k, ph in enumerate(eqs.constraint_positions) if ph is not None]
        phis = [eqs.constraint_positions[k].xreplace(ren) for k in self.holonomic]
        Ah = sp.Matrix([[sp.diff(ph, qj) for qj in qs] for ph in phis]) if phis else sp.zeros(0, n)
        args = (tt, qs, ps)
        self._phi = _lambdify(args, phis, modules="math", cse=True)
        self._Ah = _lambdify(args, Ah, modules="numpy", cse=True)
        self._A = _lambdify(args, eqs.constraint_matrix.xreplace(ren), modules="numpy", cse=True)
        self._b = _lambdify(args, [e.xreplace(ren) for e in eqs.constraint_bias], modules="math", cse=True)
        self._p = list(params)
        self.n, self.m = n, eqs.m

    def phi(self, t, q) -> np.ndarray:
        return np.array(self._phi(t, list(q), self._p), dtype=float)

    def holonomic_matrix(self, t, q) -> np.ndarray:
        return np.array(self._Ah(t, list(q), self._p), dtype=float).reshape(len(self.holonomic), self.n)

    def matrix(self, t, q) -> np.ndarray:
        return np.array(self._A(t, list(q), self._p), dtype=float).reshape(self.m, self.n)

    def bias(self, t, q) -> np.ndarray:
        return np.array(self._b(t, list(q), self._p), dtype=float)

    def velocity_residual(self, t, y) -> np.ndarray:
        q, qd = y[: self.n], y[self.n :]
        return self.matrix(t, q) @ qd + self.bias(t, q)


class _Lazy:
    """A function built on first call: diagnostics and the reference M, f are not needed by every run,
    and plain lambdify of a large model is slow (seconds at 10 DOF)."""

    def __init__(self, build: Callable):
        self._build = build
        self._fn: Callable | None = None

    def __call__(self, *args):
        if self._fn is None:
            self._fn = self._build()
        return self._fn(*args)


def _python_rhs(source: str) -> Callable:
    from .derivation_cache import cached_code

    namespace: dict = {"math": math, "np": np, "numpy": np}
    exec(cached_code(source, "<lagrange rhs>"), namespace)  # noqa: S102 - our own generated code
    return namespace["rhs"]


_MANY = """import numpy as np
import numba
from {module} import rhs as _rhs


@numba.njit(cache=True, error_model='python')
def rhs_many(t, Y, P):
    out = np.empty((Y.shape[0], {n2}))
    for i in range(Y.shape[0]):
        r = _rhs(t[i], Y[i], P[i])
        for j in range({n2}):
            out[i, j] = r[j]
    return out
"""


def _numba_many(rhs: Callable, n2: int) -> Callable:
    """A compiled loop over rows calling the compiled ``rhs`` (cached on disk next to it)."""
    from .numba_backend import import_module, write_module

    name, path = write_module("many", _MANY.format(module=rhs.py_func.__module__, n2=n2))
    return import_module(name, path).rhs_many


_COLUMNS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _numba_columns(eqs: Equations, n_params: int) -> tuple[Callable, int]:
    """The vectorized column kernel of an unconstrained model and its scratch rows
    (:mod:`lagrange.codegen.batch_source`), compiled and cached on disk like ``rhs``; remembered per
    equations, so models made by ``with_params`` share it."""
    memo = _COLUMNS.setdefault(eqs, {})
    if n_params not in memo:
        memo[n_params] = _build_columns(eqs, n_params)
    return memo[n_params]


def _build_columns(eqs: Equations, n_params: int) -> tuple[Callable, int]:
    from .batch_source import KERNEL, columns_source
    from .derivation_cache import cached_source
    from .numba_backend import load_cached

    def generate() -> str:
        from .cse import fuse

        src, n_calls = columns_source(fuse(eqs)[0], n_params=n_params)
        return (f"N_CALLS = {n_calls}\n\n\n@numba.njit(cache=True, error_model='numpy', "
                f"pipeline_class=NoAliasCompiler)\n{src}")

    text = ("import math\nimport numpy as np\nimport numba\n"
            "from lagrange.codegen.noalias import NoAliasCompiler\n\n") + cached_source(
        eqs, f"columns kernel; n_params {n_params}", generate)
    module = load_cached("columns", text, "the vectorized rhs_many kernel")
    return getattr(module, KERNEL), module.N_CALLS


def _scheduled(raw: Callable, schedule, eqs: Equations, backend: str) -> Callable:
    """``raw(t, y, p)`` with the input slots of ``p`` refilled by ``schedule(t, y[:2n])`` at every call."""
    k0, n2 = eqs.input_offset, 2 * eqs.n
    k1 = k0 + len(eqs.inputs)
    if backend == "python":
        def dynamics(t_, y, p):
            p = list(p)
            p[k0:k1] = schedule(t_, y[:n2])
            return raw(t_, y, p)
    else:
        def dynamics(t_, y, p):
            p = np.array(p, dtype=float)
            p[k0:k1] = schedule(t_, y[:n2])
            return raw(t_, y, p)

    dynamics._lagrange_raw = raw
    return dynamics


def _rebuild_model(eqs: Equations, params: np.ndarray, backend: str, source: str, schedule=None) -> NumericModel:
    """A NumericModel from its generated source: the unpickling path of :meth:`NumericModel.__reduce__`."""
    model = _rebuild(eqs, params, backend, source)
    return model if schedule is None else model.with_schedule(schedule)


def _rebuild(eqs: Equations, params: np.ndarray, backend: str, source: str) -> NumericModel:
    aux = _Lazy(lambda: _aux_function(eqs))
    mass_forcing = _Lazy(lambda: _reference_functions(eqs)[1])
    if backend == "reference":
        ref_rhs, mass_forcing = _reference_functions(eqs)
        return NumericModel(eqs, params, "reference", "", ref_rhs, aux, mass_forcing)
    if backend == "python":
        return NumericModel(eqs, params, "python", source, _python_rhs(source), aux, mass_forcing)
    from .numba_backend import numba_rhs

    return NumericModel(eqs, params, "numba", source, numba_rhs(source), aux, mass_forcing)


def compile_equations(eqs: Equations, params: Mapping, *, backend: str = "python",
                      constraint_rhs=None, inputs: Mapping | None = None, quadrature=None) -> NumericModel:
    """Generate numeric code for ``eqs`` and bind ``params``.

    ``constraint_rhs`` replaces ``c`` in ``A q̈ = c`` (Baumgarte stabilization,
    :func:`lagrange.codegen.run_functions.baumgarte_rhs`). ``inputs``: a constant for each of ``eqs.inputs``
    (keys: symbols or names), bound as the last entries of ``p``; time-varying values go to
    :func:`lagrange.integrate.run.simulate` (or :meth:`NumericModel.with_schedule`). ``quadrature``: the
    :class:`~lagrange.codegen.quadrature.Rule` for integrals that remain in the equations (default
    :data:`~lagrange.codegen.quadrature.DEFAULT_RULE`; the reference backend uses scipy's adaptive quadrature).

    Raises
    ------
    ParameterError
        Missing, unknown or non-finite parameter values (all listed).
    BackendError
        Unknown backend, or ``"numba"`` requested but not installed.
    """
    if backend not in BACKENDS:
        raise BackendError(f"unknown backend {backend!r}; choose one of {', '.join(BACKENDS)}")
    p = bind_parameters(eqs, {**params, **dict(inputs or {})})
    if backend == "auto":
        backend = "numba" if importlib.util.find_spec("numba") else "python"
    aux = _Lazy(lambda: _aux_function(eqs))
    mass_forcing = _Lazy(lambda: _reference_functions(eqs)[1])
    if backend == "reference":
        ref_rhs, mass_forcing = _reference_functions(eqs)
        return NumericModel(eqs, p, "reference", "", ref_rhs, aux, mass_forcing)
    from .derivation_cache import cached_source

    options = f"backend {backend}; n_params {len(p)}; constraint_rhs {sp.srepr(constraint_rhs)}"
    if quadrature is not None and eqs.has_quadrature:
        options += f"; quadrature {quadrature.order}x{quadrature.panels}"
    src = cached_source(eqs, options, lambda: _generate_source(eqs, backend, len(p), constraint_rhs, quadrature))
    if backend == "python":
        return NumericModel(eqs, p, "python", src, _python_rhs(src), aux, mass_forcing)
    from .numba_backend import numba_rhs

    return NumericModel(eqs, p, "numba", src, numba_rhs(src), aux, mass_forcing)


def _generate_source(eqs: Equations, backend: str, n_params: int, constraint_rhs, rule=None) -> str:
    """The generated source of the ``python`` or ``numba`` backend: one CSE over M and f, then printing
    (structural equations: one CSE over their kinematics, :mod:`lagrange.codegen.structural_source`)."""
    if eqs.is_structural:
        from .structural_source import structural_module_source

        return structural_module_source(eqs, backend, n_params, constraint_rhs)
    from .cse import fuse
    from .source import rhs_source

    fused, _ = fuse(eqs, constraint_rhs=constraint_rhs, printable=True)
    if backend == "python":  # with mass(t, y, p): M alone, for mass_matrix (the initial gimbal-lock check)
        return rhs_source(fused, n_params=n_params, flavour="python", with_mass=True, rule=rule)
    if eqs.m:
        return rhs_source(fused, n_params=n_params, flavour="numba", rule=rule)
    # the module also holds `field`, called by the compiled integrator loops (lagrange.codegen.rk_source)
    from .rk_source import field_module_source

    return field_module_source(eqs, fused, n_params, rule=rule)
