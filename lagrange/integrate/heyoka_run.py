"""The run function of ``method="heyoka"`` (registry entry in :mod:`lagrange.integrate.registry`): model, initial
state, then :func:`lagrange.integrate.heyoka_backend.integrate_heyoka` as it is, with the user's events (traced into
heyoka events; one that cannot be traced is a MethodError naming it). The registry has already refused
constraints, friction switches and time-varying inputs; constant inputs are runtime parameters of the
heyoka system (bound by name like every parameter, so a second run with other values reuses the compiled
integrator)."""

from __future__ import annotations

import importlib.util

from ..errors import BackendError, IntegrationError, LagrangeError
from ..results.trajectory import Trajectory
from .prepare import constant_input_run
from .request import RunRequest

__all__ = ["run", "precheck", "heyoka_available"]

_INSTALL = 'pip install "lagrange-dynamics[heyoka]"'


def heyoka_available() -> bool:
    """Whether ``import heyoka`` would succeed (without importing it)."""
    return importlib.util.find_spec("heyoka") is not None


def precheck(eqs) -> None:
    """Refuse before any work when heyoka is missing (BackendError naming the extra). Constraints,
    friction switches and time-varying inputs are refused by the registry (naming the methods that support
    them); a non-analytic function left in the equations by the conversion (TapeError, named)."""
    if not heyoka_available():
        raise BackendError(f"method='heyoka' needs heyoka.py, which is not installed: {_INSTALL}")


def run(req: RunRequest) -> Trajectory:
    """``method="heyoka"`` (:mod:`lagrange.integrate.heyoka_backend`)."""
    from .heyoka_backend import integrate_heyoka

    model, t_eval = constant_input_run(req, "method='heyoka' (its runtime parameters hold constants only)")
    if not req.why:  # asked for by name (auto has already excluded the Taylor methods where this warns)
        from .prepare import warn_untrusted

        warn_untrusted("heyoka", req.equations, model, req.t_span, req.y0)
    try:
        return integrate_heyoka(model, req.t_span, req.y0, t_eval, rtol=req.rtol, atol=req.atol,
                                max_step=req.max_step, label="heyoka (taylor_adaptive, LLVM)", events=req.events,
                                max_steps=req.max_steps)
    except ValueError as exc:
        if isinstance(exc, LagrangeError):
            raise
        raise IntegrationError(f"integration failed: {exc}") from exc
