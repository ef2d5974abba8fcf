r"""How long is a computed trajectory trustworthy? The horizon of validity and the finite-time Lyapunov
exponent.

On a chaotic system every integration error is amplified like :math:`e^{λt}`, so beyond some time the
computed trajectory says nothing about the true one, however small ``rtol`` was. :func:`validity_horizon`
measures that time honestly: it integrates the same initial state at two tolerances (``rtol`` and a much
tighter one) and reports the first time their states differ by more than ``threshold`` (max-norm over
``[q, q̇]``, in the units of the state). The tighter run stands in for the truth, so the horizon belongs to the
``rtol`` run. A third run from a slightly perturbed initial state (``perturbation``) gives the finite-time
Lyapunov exponent

.. math:: λ_T = \frac{1}{T} \ln\frac{d(T)}{d(0)},

with :math:`d` the Euclidean distance of the two states and T the first time d exceeds ``threshold`` (the
end of the run if it never does). For regular (quasi-periodic) motion the separation grows only linearly,
λ_T → 0 as T grows, and the horizon covers the whole run; for chaotic motion
:math:`t_h ≈ \ln(\text{threshold}/\text{error}_0)/λ`, so tightening ``rtol`` by 10³ buys about
:math:`\ln(10^3)/λ` more time — a slow, logarithmic gain.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ..integrate.run import initial_state
from ..records import record

__all__ = ["ValidityHorizon", "validity_horizon", "divergence_time", "finite_time_lyapunov"]


@record(frozen=True)
class ValidityHorizon:
    """Result of :func:`validity_horizon`.

    Attributes
    ----------
    horizon : first time the ``rtol`` run differs from the tight run by more than ``threshold``
        (``t_end`` when it never does)
    diverged : whether that happened before ``t_end``
    lyapunov : finite-time Lyapunov exponent λ_T [1/time] from the perturbed run
    lyapunov_time : the T of λ_T
    rtol, tight_rtol, threshold, t_end : the settings
    t : ndarray (k,) output times; separation : ndarray (k,) max-norm distance of the two tolerance runs
    """

    horizon: float
    diverged: bool
    lyapunov: float
    lyapunov_time: float
    rtol: float
    tight_rtol: float
    threshold: float
    t_end: float
    t: np.ndarray
    separation: np.ndarray

    def __str__(self) -> str:
        what = (f"trajectory valid (to {self.threshold:g}) until t = {self.horizon:.4g} of {self.t_end:g}"
                if self.diverged else f"trajectory valid (to {self.threshold:g}) over the whole run t ≤ {self.t_end:g}")
        return (f"{what} at rtol {self.rtol:g} (checked against rtol {self.tight_rtol:g}); finite-time Lyapunov "
                f"exponent {self.lyapunov:.3g} over t ≤ {self.lyapunov_time:.4g}")


def divergence_time(t, a, b, threshold: float) -> float | None:
    """First time at which ``max|a − b|`` (over the state) exceeds ``threshold``; None if never.

    ``t`` shape (k,), ``a``, ``b`` shape (k, m).

    >>> divergence_time([0, 1, 2], [[0.0], [0.0], [0.0]], [[0.0], [0.5], [2.0]], 1.0)
    2.0
    """
    d = np.max(np.abs(np.asarray(a, dtype=float) - np.asarray(b, dtype=float)), axis=1)
    idx = np.flatnonzero(d > threshold)
    return float(np.asarray(t, dtype=float)[idx[0]]) if idx.size else None


def finite_time_lyapunov(t, a, b, threshold: float) -> tuple[float, float]:
    """``(λ_T, T)``: ``ln(d(T)/d(0))/T`` with d the Euclidean distance of the runs ``a`` and ``b`` and T
    the first time d exceeds ``threshold`` (else the last time). ``d(0)`` must be positive.

    >>> ts = np.linspace(0, 5, 51); a = np.zeros((51, 1)); b = 1e-6 * np.exp(2 * ts)[:, None]
    >>> round(finite_time_lyapunov(ts, a, b, 1.0)[0], 6)
    2.0
    """
    t = np.asarray(t, dtype=float)
    d = np.linalg.norm(np.asarray(a, dtype=float) - np.asarray(b, dtype=float), axis=1)
    if not d[0] > 0:
        raise ValueError("the two runs must start apart (d(0) > 0) to measure a Lyapunov exponent")
    idx = np.flatnonzero(d > threshold)
    k = int(idx[0]) if idx.size else len(t) - 1
    T = float(t[k] - t[0])
    return (float(np.log(d[k] / d[0]) / T) if T > 0 else 0.0), T


def validity_horizon(system, t_end: float, initial: Mapping, params: Mapping, *, rtol: float = 1e-8,
                     tight_rtol: float | None = None, threshold: float = 1e-2, perturbation: float = 1e-9,
                     n_points: int = 2001, method: str = "DOP853", backend: str = "python") -> ValidityHorizon:
    """Horizon of validity of the ``rtol`` trajectory of ``system`` and its finite-time Lyapunov exponent.

    Parameters
    ----------
    t_end : the run is t ∈ [0, t_end]
    initial, params : as for :func:`~lagrange.integrate.run.simulate`
    rtol : tolerance of the run being judged (atol = rtol)
    tight_rtol : tolerance of the stand-in for the truth (default ``max(rtol·1e-4, 1e-13)``)
    threshold : separation (max-norm over ``[q, q̇]``, state units) at which the run is no longer valid
    perturbation : Euclidean size of the initial perturbation for the Lyapunov exponent (spread equally
        over the components of ``[q, q̇]``)
    n_points : output times on which the runs are compared

    Examples
    --------
    >>> from lagrange.examples import n_link_pendulum
    >>> h = validity_horizon(n_link_pendulum(1), 10, {"q1": 0.1, "q1_dot": 0}, {"g": 9.81}, n_points=201)
    >>> h.diverged, h.horizon
    (False, 10.0)
    """
    tight = tight_rtol if tight_rtol is not None else max(rtol * 1e-4, 1e-13)
    times = np.linspace(0.0, float(t_end), n_points)
    model = system.compile(params, backend=backend)

    def run(tol, ic):
        sol = system.simulate((0.0, float(t_end)), ic, params, method=method, rtol=tol, atol=tol, t_eval=times,
                              model=model, backend=backend)
        return sol.y

    loose, ref = run(rtol, initial), run(tight, initial)
    coords = system.derived.coordinates
    y0 = initial_state(coords, initial)
    y0p = y0 + perturbation / np.sqrt(y0.size)
    n = len(coords)
    names = [c.func.__name__ for c in coords]
    ic_p = {nm: y0p[i] for i, nm in enumerate(names)} | {nm + "_dot": y0p[n + i] for i, nm in enumerate(names)}
    lam, T = finite_time_lyapunov(times, ref, run(tight, ic_p), threshold)
    tdiv = divergence_time(times, loose, ref, threshold)
    sep = np.max(np.abs(loose - ref), axis=1)
    return ValidityHorizon(float(t_end) if tdiv is None else tdiv, tdiv is not None, lam, T, rtol, tight, threshold,
                           float(t_end), times, sep)
