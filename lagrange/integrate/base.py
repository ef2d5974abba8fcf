"""Fixed-step integrators: the extension point.

A scheme subclasses :class:`Integrator` and implements ``_step_impl(t, z, h) -> (z_new, iterations)``.
Rules a scheme must follow:

1. It works on canonical variables ``z = (q, p)`` through the :class:`HamiltonianModel` it is given
   (``field``, ``field_jacobian``, ``grad``, ``hess``, ``H``) and nothing else.
2. Its class attributes state its ``order``, whether it is ``symplectic`` and whether it conserves energy
   exactly (``energy_conserving``), and what structure it ``requires`` (``"separable"`` for explicit
   splitting methods); :meth:`check` verifies the requirement before a run.
3. Implicit schemes solve their equations with Newton's method using the generated Hessian, to the
   tolerance ``tol`` (relative), and raise :class:`~lagrange.errors.IntegrationError` (:class:`NewtonFailure`,
   with the last residual) when Newton fails — never return an unconverged step. The driver
   (:mod:`lagrange.integrate.fixed`) adds the step number, the state and the partial trajectory.
4. The scheme's coefficients are data at the top of its file, with the reference.
5. ``loop="compiled"`` runs a transcription of the scheme in :mod:`lagrange.integrate._geometric_loops`
   (selected in :func:`lagrange.integrate.fixed._run_compiled`); a new scheme needs one there too, and
   ``tests/numerics/test_geometric.py`` compares the two step by step.
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from ..codegen.hamiltonian_model import HamiltonianModel
from ..errors import IntegrationError, LagrangeError

__all__ = ["Integrator", "newton", "NewtonFailure", "not_converged", "diverged", "singular_jacobian", "step_prefix",
           "non_finite_state"]


class NewtonFailure(IntegrationError):
    """Newton's method failed on a step's implicit equations; ``residual`` is the last residual norm (max
    norm, inf when the iterate became non-finite) and ``iterations`` the iterations done."""

    def __init__(self, message: str, *, residual: float, iterations: int, **kwargs):
        self.residual = residual
        self.iterations = iterations
        super().__init__(message, **kwargs)


def not_converged(max_iter: int, where: str, residual: float, tol: float) -> str:
    """Why Newton failed (wording shared by the Python and the compiled step loops)."""
    return (f"Newton's method did not converge in {max_iter} iterations {where} (last residual {residual:.3g}, "
            f"tolerance {tol:.1g} relative); reduce the step")


def diverged(where: str, iteration: int) -> str:
    return f"Newton's method diverged {where}: non-finite residual at iteration {iteration}; reduce the step"


def singular_jacobian(where: str, iteration: int, residual: float) -> str:
    return (f"Newton's method failed {where}: singular Jacobian at iteration {iteration} (residual {residual:.3g}); "
            "reduce the step")


def step_prefix(name: str, t: float, h: float) -> str:
    """How a failed step's message starts: the scheme, the step's time and size."""
    return f"{name} step from t={t:.9g} with h={h:.3g}: "


def non_finite_state(name: str, t: float) -> str:
    return f"{name}: non-finite state after the step from t={t:.9g}; a blow-up, or a step too large: reduce the step"


def newton(residual, jacobian, x0, *, tol: float, max_iter: int, where: str):
    """Newton's method; returns (x, iterations). Converged when the step is at the round-off floor or
    the residual is below ``tol`` relative to the size of x.

    Raises :class:`NewtonFailure` (an :class:`~lagrange.errors.IntegrationError`) with the last residual
    when it does not converge in ``max_iter`` iterations, when an iterate or residual becomes non-finite,
    or when the Jacobian is singular.
    """
    x = np.array(x0, dtype=float)
    rnorm = float("inf")
    for it in range(1, max_iter + 1):
        r = residual(x)
        rnorm = float(np.max(np.abs(r)))
        scale = 1.0 + float(np.max(np.abs(x)))
        if not (np.isfinite(rnorm) and np.isfinite(scale)):
            raise NewtonFailure(diverged(where, it), residual=float("inf"), iterations=it)
        if rnorm <= tol * scale:
            return x, it - 1
        try:
            dx = np.linalg.solve(jacobian(x), r)
        except np.linalg.LinAlgError:
            raise NewtonFailure(singular_jacobian(where, it, rnorm), residual=rnorm, iterations=it) from None
        x -= dx
        if float(np.max(np.abs(dx))) <= 4e-16 * scale:
            return x, it
    raise NewtonFailure(not_converged(max_iter, where, rnorm, tol), residual=rnorm, iterations=max_iter)


class Integrator:
    """Base class of the fixed-step geometric integrators (see the module docstring for the rules)."""

    name: ClassVar[str] = ""
    order: ClassVar[int] = 0
    symplectic: ClassVar[bool] = False
    energy_conserving: ClassVar[bool] = False
    requires: ClassVar[str | None] = None

    def __init__(self, model: HamiltonianModel, *, tol: float = 1e-13, max_iter: int = 25):
        self.model = model
        self.tol = tol
        self.max_iter = max_iter
        self.check()

    def check(self) -> None:
        if self.requires == "separable" and not self.model.separable:
            raise LagrangeError(
                f"{self.name} needs a separable Hamiltonian H = ½ pᵀM⁻¹p + V(q) with constant M; this system's "
                "kinetic energy depends on the coordinates or t: use 'midpoint', 'gl4' or 'gl6'"
            )

    def step(self, t: float, z: np.ndarray, h: float) -> tuple[np.ndarray, int]:
        """One step of size ``h`` from ``(t, z)``; returns the new state and the Newton iterations used."""
        try:
            return self._step_impl(t, z, h)
        except NewtonFailure as exc:
            raise NewtonFailure(f"{step_prefix(self.name, t, h)}{exc}", residual=exc.residual,
                                iterations=exc.iterations, t=t) from None
        except IntegrationError as exc:
            raise IntegrationError(f"{step_prefix(self.name, t, h)}{exc}", t=t) from None

    def _step_impl(self, t: float, z: np.ndarray, h: float) -> tuple[np.ndarray, int]:  # pragma: no cover
        raise NotImplementedError
