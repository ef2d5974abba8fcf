"""Numeric models: generated ``rhs(t, y, p)`` plus vectorized energy and power for diagnostics.

Backends (``backend=``):

``"python"`` (default)
    CSE'd straight-line Python on floats with an unrolled LDLᵀ solve. Instant to build, no compiler.
``"numba"``
    The same source compiled with ``numba.njit``; the module is written to the on-disk cache
    (:mod:`lagrange.codegen.cache`) keyed by a hash of the source, so numba's own cache makes re-runs
    skip the JIT. Needs the ``fast`` extra (``pip install lagrange[fast]``).
``"reference"``
    Plain ``sympy.lambdify`` of M and f without CSE plus ``numpy.linalg.solve``: the slow oracle every
    fast backend is tested against.
``"auto"``
    ``"numba"`` when numba is importable, else ``"python"``.
"""

from __future__ import annotations

import importlib.util
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from ..conventions import t
from ..derive.equations import Equations
from ..errors import BackendError, ParameterError, SingularMassMatrixError
from ..model.coordinates import coordinate_name
from .cse import fuse, rename_map
from .source import rhs_source

__all__ = ["NumericModel", "compile_equations", "bind_parameters", "BACKENDS"]

BACKENDS = ("python", "numba", "reference", "auto")


def bind_parameters(eqs: Equations, params: Mapping) -> np.ndarray:
    """Parameter values in the order of ``eqs.parameters``; keys may be symbols or names.

    Raises :class:`ParameterError` listing every missing, unknown or non-finite value.
    """
    by_name = {}
    for key, value in params.items():
        name = key.name if isinstance(key, sp.Symbol) else str(key)
        by_name[name] = value
    wanted = [s.name for s in eqs.parameters]
    missing = [n for n in wanted if n not in by_name]
    unknown = sorted(set(by_name) - set(wanted))
    problems = []
    if missing:
        problems.append(f"missing value(s) for parameter(s) {', '.join(missing)}")
    if unknown:
        problems.append(
            f"unknown parameter(s) {', '.join(unknown)} (this system's parameters: "
            f"{', '.join(wanted) or 'none'})"
        )
    values = []
    for n in wanted:
        if n in by_name:
            try:
                raw = by_name[n]
                v = float(sp.sympify(raw).evalf()) if isinstance(raw, (str, sp.Basic)) else float(raw)
            except (TypeError, ValueError, sp.SympifyError):
                problems.append(f"parameter {n} = {by_name[n]!r} is not a number")
                continue
            if not math.isfinite(v):
                problems.append(f"parameter {n} = {v} is not finite")
            values.append(v)
    if problems:
        raise ParameterError("; ".join(problems))
    return np.array(values, dtype=float)


@dataclass(frozen=True)
class NumericModel:
    """A compiled system with bound parameters.

    Attributes
    ----------
    equations : Equations
    params : ndarray, shape (k,) — values in the order of ``equations.parameters``
    backend : str
    source : str — the generated source of ``rhs`` (empty for the reference backend)
    rhs : callable ``rhs(t, y, p) -> dy`` with ``y`` of shape (2n,)
    """

    equations: Equations
    params: np.ndarray
    backend: str
    source: str
    rhs: Callable
    _aux: Callable = field(repr=False)
    _mass_forcing: Callable = field(repr=False)

    @property
    def n(self) -> int:
        return self.equations.n

    def __post_init__(self):
        # the python backend unpacks p into Python floats (fast scalar arithmetic); numba wants an array
        call = tuple(float(v) for v in self.params) if self.backend == "python" else self.params
        object.__setattr__(self, "_pcall", call)

    def fun(self, t: float, y: np.ndarray) -> np.ndarray:
        """``dy/dt`` at ``(t, y)`` with the bound parameters (the form scipy's solvers call)."""
        try:
            return self.rhs(t, y, self._pcall)
        except ZeroDivisionError:
            raise self.singular_error(t, y) from None

    def singular_error(self, t: float, y: np.ndarray) -> SingularMassMatrixError:
        """An error naming the coordinates involved in the singular mass matrix at ``(t, y)``."""
        M, _ = self.mass_and_forcing(t, y)
        w, v = np.linalg.eigh(M)
        k = int(np.argmin(np.abs(w)))
        involved = [coordinate_name(c) for c, comp in zip(self.equations.coordinates, v[:, k]) if abs(comp) > 1e-6]
        state = ", ".join(f"{coordinate_name(c)}={y[i]:.6g}" for i, c in enumerate(self.equations.coordinates))
        return SingularMassMatrixError(
            f"the mass matrix is singular at t={t:.6g} ({state}): smallest eigenvalue {w[k]:.3g}, "
            f"coordinates involved: {', '.join(involved)}. A massless point or a coordinate that does "
            "not appear in T gives no inertia: eliminate it (statics) or give it mass"
        )

    def mass_and_forcing(self, t: float, y) -> tuple[np.ndarray, np.ndarray]:
        """Numeric ``M`` (n, n) and ``f`` (n,) at one state."""
        M, f = self._mass_forcing(t, np.asarray(y, dtype=float), self.params)
        return np.array(M, dtype=float).reshape(self.n, self.n), np.array(f, dtype=float).reshape(self.n)

    def diagnostics(self, t, y) -> dict[str, np.ndarray]:
        """Vectorized ``T``, ``V``, ``energy`` (T+V), ``jacobi`` (h), ``power`` (dh/dt) and the quadratic and
        velocity-free parts ``T2``, ``T0`` of T over states.

        ``t`` shape (m,), ``y`` shape (m, 2n).
        """
        t = np.asarray(t, dtype=float)
        y = np.asarray(y, dtype=float)
        cols = [y[:, i] for i in range(y.shape[1])]
        vals = self._aux(t, cols, self.params)
        names = ("T", "V", "jacobi", "power", "T2", "T0")
        out = {k: np.broadcast_to(np.asarray(v, dtype=float), t.shape).copy() for k, v in zip(names, vals)}
        out["energy"] = out["T"] + out["V"]
        return out


def _reference_functions(eqs: Equations):
    ren = rename_map(eqs)
    n = eqs.n
    ys = sp.symbols(f"y0:{2 * n}", real=True) if n else ()
    ps = [ren[s] for s in eqs.parameters]
    tt = ren[t]
    M = eqs.mass_matrix.xreplace(ren)
    f = eqs.forcing.xreplace(ren)
    mf = sp.lambdify((tt, ys, ps), (M, f), modules="numpy", cse=False)

    def mass_forcing(t_, y, p):
        return mf(t_, list(y), list(p))

    def rhs(t_, y, p):
        Mv, fv = mass_forcing(t_, y, p)
        Mv = np.array(Mv, dtype=float)
        if not np.all(np.isfinite(Mv)) or np.linalg.cond(Mv) > 1e15:
            raise ZeroDivisionError("mass matrix is singular")
        acc = np.linalg.solve(Mv, np.array(fv, dtype=float).ravel())
        return np.concatenate([np.asarray(y[n:], dtype=float), acc])

    return rhs, mass_forcing


def _aux_function(eqs: Equations):
    ren = rename_map(eqs)
    n = eqs.n
    ys = sp.symbols(f"y0:{2 * n}", real=True)
    ps = [ren[s] for s in eqs.parameters]
    T0 = eqs.kinetic.subs({v: 0 for v in eqs.qd})
    qd = sp.Matrix(eqs.qd)
    T2 = (qd.T * eqs.mass_matrix * qd)[0, 0] / 2
    exprs = [e.xreplace(ren) for e in (eqs.kinetic, eqs.potential, eqs.jacobi, eqs.jacobi_rate, T2, T0)]
    f = sp.lambdify((ren[t], ys, ps), exprs, modules="numpy", cse=True)

    def aux(t_, cols, p):
        return f(t_, cols, list(p))

    return aux


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
    namespace: dict = {"math": math}
    exec(compile(source, "<lagrange rhs>", "exec"), namespace)  # noqa: S102 - our own generated code
    return namespace["rhs"]


def compile_equations(eqs: Equations, params: Mapping, *, backend: str = "python") -> NumericModel:
    """Generate numeric code for ``eqs`` and bind ``params``.

    Raises
    ------
    ParameterError
        Missing, unknown or non-finite parameter values (all listed).
    BackendError
        Unknown backend, or ``"numba"`` requested but not installed.
    """
    if backend not in BACKENDS:
        raise BackendError(f"unknown backend {backend!r}; choose one of {', '.join(BACKENDS)}")
    p = bind_parameters(eqs, params)
    if backend == "auto":
        backend = "numba" if importlib.util.find_spec("numba") else "python"
    aux = _Lazy(lambda: _aux_function(eqs))
    mass_forcing = _Lazy(lambda: _reference_functions(eqs)[1])
    if backend == "reference":
        ref_rhs, mass_forcing = _reference_functions(eqs)
        return NumericModel(eqs, p, "reference", "", ref_rhs, aux, mass_forcing)
    fused, _ = fuse(eqs)
    if backend == "python":
        src = rhs_source(fused, n_params=len(p), flavour="python")
        return NumericModel(eqs, p, "python", src, _python_rhs(src), aux, mass_forcing)
    from .numba_backend import numba_rhs

    src = rhs_source(fused, n_params=len(p), flavour="numba")
    return NumericModel(eqs, p, "numba", src, numba_rhs(src), aux, mass_forcing)
