"""The run function of ``method="taylor"`` (registry entry in :mod:`lagrange.integrate.registry`): model, initial
state, then :func:`lagrange.integrate.taylor.integrate_taylor` as it is. The registry has already refused events,
constraints, friction switches and time-varying inputs."""

from __future__ import annotations

from ..codegen.numeric import NumericModel
from ..errors import IntegrationError, LagrangeError
from ..results.trajectory import Trajectory
from .prepare import constant_input_run
from .request import RunRequest

__all__ = ["run", "taylor_ready", "precheck"]


def precheck(eqs) -> None:
    """Refuse constrained equations with the tape's own error, which names the constraint (a TapeError)."""
    if eqs.m:
        NumericModel.tape_for(eqs)


def taylor_ready(eqs) -> bool:
    """Whether ``method="taylor"`` can run ``eqs`` here (a C compiler or numba, analytic unconstrained
    equations)."""
    from .taylor import available_interpreter

    if available_interpreter() is None:
        return False
    try:
        NumericModel.tape_for(eqs)
    except TypeError as exc:  # TapeError (a LagrangeError): not analytic (sign, Abs, ...)
        if not isinstance(exc, LagrangeError):
            raise
        return False
    return True


def run(req: RunRequest) -> Trajectory:
    """``method="taylor"`` (:mod:`lagrange.integrate.taylor`)."""
    from .taylor import integrate_taylor, interpreter

    model, t_eval = constant_input_run(req, "method='taylor' (its tape holds constants only)")
    if not req.why:  # asked for by name (auto has already excluded the Taylor methods where this warns)
        from .prepare import warn_untrusted

        warn_untrusted("taylor", req.equations, model, req.t_span, req.y0)
    how = "compiled series" if model.backend == "numba" else f"interpreted tape, {interpreter()}"
    label = f"taylor ({how}" + (f"; auto: {req.why})" if req.why else ")")
    try:
        return integrate_taylor(model, req.t_span, req.y0, t_eval, rtol=req.rtol, atol=req.atol,
                                max_step=req.max_step, label=label, max_steps=req.max_steps)
    except ValueError as exc:
        raise IntegrationError(f"integration failed: {exc}") from exc
