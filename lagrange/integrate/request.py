"""What :func:`~lagrange.integrate.run.simulate` hands to a method's run function: one frozen
:class:`RunRequest`, validated and resolved (the method chosen, the options as objects, the equations with the
friction treatment applied, the input values split into constants and a schedule)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ..codegen.numeric import NumericModel
from ..records import record
from .options import DEFAULT_MAX_STEPS, FrictionOptions, Stabilization, StepOptions

__all__ = ["RunRequest"]


@record(frozen=True)
class RunRequest:
    """A validated simulation request.

    Attributes
    ----------
    system : the system as given (for its name, bodies and ``compile``)
    equations : its derived equations, ``sign()`` already regularized when ``friction.treatment`` asks for it
    method : the registry name of the method (after ``auto``), ``why`` the reason when ``auto`` chose it
    t_span : ``(t0, t1)`` as floats; ``y0`` the initial state ``[q, q̇]``, shape (2n,); ``initial`` as given
    params : parameter values (the inputs' constants included), ``constants`` those constants, ``schedule`` the
        time-varying inputs (None when all are constant)
    model : the NumericModel the user passed (checked against the system), or None; with ``model_bound`` the
        model ``method="auto"`` built to decide, already holding this request's parameters, input constants
        and schedule (the run uses it as it is: no second binding)
    backend, loop : as given; rtol, atol, max_step, n_points: as given; ``t_eval`` an array or None
    events : the user's event functions (a list)
    switches : the ``sign()`` arguments to integrate with events (empty when regularized or absent)
    friction, stabilization, step : the option objects
    max_steps : the most steps the run may take (the scipy methods stop there with an IntegrationError)
    """

    system: object
    equations: object
    method: str
    why: str
    t_span: tuple[float, float]
    y0: np.ndarray
    initial: Mapping
    params: dict
    constants: dict
    schedule: object
    model: NumericModel | None
    backend: str
    loop: str
    rtol: float
    atol: float
    max_step: float
    n_points: int
    t_eval: np.ndarray | None
    events: list
    switches: list
    friction: FrictionOptions
    stabilization: Stabilization
    step: StepOptions | None
    model_bound: bool = False
    max_steps: int = DEFAULT_MAX_STEPS
