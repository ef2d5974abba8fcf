"""Optional comparison with heyoka.py (Taylor integrator, LLVM-compiled): ``heyoka.lagrangian`` +
``taylor_adaptive``. heyoka is imported lazily; without it :func:`heyoka_available` is False and the
benchmark skips it with a note (``pip install "lagrange-dynamics[heyoka]"``).

The Lagrangian handed to heyoka is lagrange's ``T − V`` (plain symbols, parameter values substituted)
converted with ``heyoka.from_sympy``; heyoka then derives its own equations (``heyoka.lagrangian``, with
the dissipation function ``D = rayleigh − P`` for Rayleigh/Wells damping). Timed separately: heyoka's
derivation, the construction of the integrator (LLVM compilation; heyoka caches compiled code in memory,
so only the first construction in a process is a cold compile) and the integration.
"""

from __future__ import annotations

import importlib.util
import time
from collections.abc import Mapping

import numpy as np
import sympy as sp

from ..codegen.numeric import bind_parameters
from ..errors import BackendError
from ..records import record

__all__ = ["heyoka_available", "heyoka_version", "HeyokaModel", "heyoka_model", "COMPACT_OPS"]


def heyoka_available() -> bool:
    """Whether ``import heyoka`` would succeed."""
    return importlib.util.find_spec("heyoka") is not None


def heyoka_version() -> str | None:
    """heyoka.py's version, or None when it is not installed."""
    if not heyoka_available():
        return None
    import heyoka

    return str(heyoka.__version__)


@record
class HeyokaModel:
    """heyoka's ODE system for a lagrange System, and the time heyoka took to derive it."""

    odes: list
    n: int
    derive_s: float
    compact: bool  # heyoka's compact_mode (for large expressions: compiles in seconds instead of minutes)

    def integrator(self, y0, tol: float, *, compact: bool | None = None):
        """``(taylor_adaptive, construction seconds)`` starting at t = 0 from ``y0 = [q, q̇]``."""
        import heyoka as hy

        t0 = time.perf_counter()
        ta = hy.taylor_adaptive(self.odes, [float(v) for v in y0], tol=float(tol),
                                compact_mode=self.compact if compact is None else compact)
        return ta, time.perf_counter() - t0

    @staticmethod
    def propagate(ta, y0, times) -> tuple[np.ndarray, int]:
        """Reset ``ta`` to (0, y0), integrate to ``times`` (ascending, ≥ 0); ``(states (k, 2n), steps)``."""
        ta.time = 0.0
        ta.state[:] = np.asarray(y0, dtype=float)
        times = np.asarray(times, dtype=float)
        if len(times) == 1:
            res = ta.propagate_until(float(times[0]))
            return np.array(ta.state, dtype=float)[None, :], int(res[3])
        grid = times if times[0] == 0.0 else np.concatenate([[0.0], times])
        res = ta.propagate_grid(grid)
        out = np.array(res[-1], dtype=float)
        return (out if times[0] == 0.0 else out[1:]), int(res[3])


#: Lagrangians with more operations than this get heyoka's ``compact_mode``: in the default mode the LLVM
#: compilation time explodes (measured: 5-link pendulum, 186 ops: 25 s default vs 1.7 s compact; Greenspan's
#: rigid top: 120 s vs 1.2 s), while small systems compile in 0.05 s either way and run faster by default.
COMPACT_OPS = 100


def heyoka_model(system, params: Mapping) -> HeyokaModel:
    """heyoka's equations of motion for ``system`` with ``params`` substituted (``compact_mode`` when the
    Lagrangian has more than :data:`COMPACT_OPS` operations).

    Raises :class:`~lagrange.errors.BackendError` when heyoka is missing or the system is outside what
    ``heyoka.lagrangian`` takes (constraints, applied forces, dry friction, explicit time).
    """
    if not heyoka_available():
        raise BackendError("heyoka is not installed: pip install \"lagrange-dynamics[heyoka]\"")
    import heyoka as hy

    eqs = system.derived
    D = eqs.rayleigh - eqs.power_function
    reasons = []
    if eqs.m:
        reasons.append("constraints")
    if any(e != 0 for e in eqs.applied):
        reasons.append("applied forces")
    if D.atoms(sp.sign, sp.Abs):
        reasons.append("dry friction")
    values = dict(zip(eqs.parameters, bind_parameters(eqs, params)))
    # heyoka takes only dyadic rationals: every other number becomes a float (exponents are kept exact)
    L = sp.nfloat((eqs.kinetic - eqs.potential).xreplace({k: sp.Float(v) for k, v in values.items()}), exponent=False)
    D = sp.nfloat(D.xreplace({k: sp.Float(v) for k, v in values.items()}), exponent=False)
    from ..conventions import t as time_symbol

    if time_symbol in L.free_symbols or time_symbol in D.free_symbols:
        reasons.append("explicit time")
    if reasons:
        raise BackendError(f"heyoka.lagrangian does not take {', '.join(reasons)} ({eqs.name or 'this system'})")
    t0 = time.perf_counter()
    qv = hy.make_vars(*[f"hq{i}" for i in range(eqs.n)])
    qdv = hy.make_vars(*[f"hqd{i}" for i in range(eqs.n)])
    qv, qdv = (list(qv), list(qdv)) if eqs.n > 1 else ([qv], [qdv])
    table = dict(zip(eqs.q, qv)) | dict(zip(eqs.qd, qdv))
    Lh = hy.from_sympy(L, table)
    odes = hy.lagrangian(Lh, qv, qdv, hy.from_sympy(D, table)) if D != 0 else hy.lagrangian(Lh, qv, qdv)
    return HeyokaModel(odes, eqs.n, time.perf_counter() - t0, int(sp.count_ops(L)) > COMPACT_OPS)
