"""The result of a simulation: a frozen trajectory with diagnostics, lookups by coordinate, CSV export.

Energy bookkeeping
------------------
``jacobi`` is Wells' Jacobi integral :math:`h = \\sum \\dot q\\,\\partial L/\\partial\\dot q - L`
(= T + V when nothing moves). Its rate is the power of everything not in L,

.. math:: \\frac{dh}{dt} = -\\frac{\\partial L}{\\partial t}
          + \\sum_r \\dot q_r\\Big(F_{q_r} + \\frac{\\partial P}{\\partial\\dot q_r}
          - \\frac{\\partial D}{\\partial\\dot q_r}\\Big),

whose time integral ``work`` is carried along as an extra state during integration (same tolerance).
The *power balance* residual ``h(t) − h(0) − work(t)`` is zero for a correct model solved exactly: a
forgotten force, a wrong sign in P or a bad integration shows up there.
"""

from __future__ import annotations

from dataclasses import field
from functools import cached_property
from pathlib import Path

import numpy as np
import sympy as sp

from ..codegen.numeric import NumericModel
from ..conventions import VELOCITY_SUFFIX, t
from ..model.coordinates import canonical_key, coordinate_name, is_coordinate
from ..records import record
from .verdict import RunStatus, Verdict

__all__ = ["Trajectory"]


@record(frozen=True, repr=False)  # (its own __repr__)
class Trajectory:
    """A simulated trajectory.

    Attributes
    ----------
    t : ndarray, shape (m,)
    y : ndarray, shape (m, 2n) — ``[q, q̇]`` per row
    model : NumericModel used (parameters bound)
    method : str — integrator used, and why when chosen automatically
    success : bool; message : str; nfev : int
    work : ndarray (m,) or None — ∫ dh/dt dt from t0, present when the system is not conservative
    initial : (t0, y0) — the initial state (output times need not include t0)
    t_events, y_events : lists from scipy (one entry per event function)
    initial_constraint_violation : ``{constraint: (φ, A q̇ + b)}`` of the user's initial state (constrained systems)
    initial_adjustments : ``{name: (given value, value used)}`` of each initial value the run did not take as
        given: computed from the velocity constraints (given value None) or changed by the projection onto the
        constraints (:func:`lagrange.integrate.constrained.consistent_initial`)
    switches : dry friction with ``friction="events"``: (switched model, σ of every ``sign()`` at the output
        times (m, K), every stick/slip mode change as :class:`lagrange.integrate.switching.Transition`)
    verdict : the run's own accuracy checks (:class:`lagrange.results.verdict.Verdict`), computed once by
        :func:`lagrange.simulate`; None for a trajectory that stopped early or was built elsewhere. ``success``
        is False when a check failed; :attr:`status` says which of the three outcomes it was.
    """

    t: np.ndarray
    y: np.ndarray
    model: NumericModel
    method: str
    success: bool
    message: str
    nfev: int
    work: np.ndarray | None = None
    t_events: list = field(default_factory=list)
    y_events: list = field(default_factory=list)
    initial: tuple = ()  # (t0, y0): the work integral starts there, whatever the output times
    switches: tuple = ()  # (switched model, sigma (m, K), Transition tuple) when sign() switches were integrated
    initial_constraint_violation: dict = field(default_factory=dict)  # user's state before projection
    initial_adjustments: dict = field(default_factory=dict)  # {name: (given or None, used)} of the initial state
    point_params: np.ndarray | None = None  # per output point parameter vectors (rough-constraint signs)
    verdict: Verdict | None = None  # the run's own accuracy checks (lagrange.results.verdict)

    @property
    def status(self) -> RunStatus:
        """:attr:`RunStatus.SUCCESS <lagrange.results.verdict.RunStatus.SUCCESS>` (reached the end, every check
        passed), ``INACCURATE`` (reached the end, a check of :attr:`verdict` failed) or ``STOPPED``."""
        if self.verdict is not None and not self.verdict.ok:
            return RunStatus.INACCURATE
        return RunStatus.SUCCESS if self.success else RunStatus.STOPPED

    @property
    def coordinates(self) -> tuple:
        """The coordinate functions, in state order."""
        return self.model.equations.coordinates

    @property
    def names(self) -> list[str]:
        """Column names: coordinates then ``<name>_dot``."""
        qs = [coordinate_name(c) for c in self.coordinates]
        return qs + [q + VELOCITY_SUFFIX for q in qs]

    def _column(self, key) -> int | str:
        n = self.model.n
        inputs = self.model.equations.inputs
        if isinstance(key, str):
            names = self.names
            if key in names:
                return names.index(key)
            if key.endswith("_ddot") and key[:-5] in names[:n]:
                return ("acc", names.index(key[:-5]))  # type: ignore[return-value]
            if key in [u.name for u in inputs]:
                return ("input", [u.name for u in inputs].index(key))  # type: ignore[return-value]
            raise KeyError(f"{key!r} is not a coordinate, velocity or input of this trajectory "
                           f"({', '.join(names + [u.name for u in inputs])})")
        key = canonical_key(key, self.coordinates, inputs)  # dynamicsymbols and their derivatives
        if isinstance(key, sp.Symbol) and key in inputs:
            return ("input", inputs.index(key))  # type: ignore[return-value]
        if is_coordinate(key) and key in self.coordinates:
            return self.coordinates.index(key)
        if isinstance(key, sp.Derivative) and key.expr in self.coordinates:
            order = sum(c for v, c in key.variable_count if v == t)
            i = self.coordinates.index(key.expr)
            if order == 1:
                return n + i
            if order == 2:
                return ("acc", i)  # type: ignore[return-value]
        raise KeyError(f"{key!r} is not a coordinate, velocity or acceleration of this trajectory")

    def __getitem__(self, key) -> np.ndarray:
        """``sol[theta]``, ``sol[theta.diff(t)]``, ``sol[theta.diff(t, 2)]``, an input ``sol[u]`` (its values at
        the output times) or by name ``sol["theta_dot"]``, ``sol["u"]``."""
        col = self._column(key)
        if isinstance(col, tuple):
            if col[0] == "input":
                return self.input_values[:, col[1]]
            return self.accelerations[:, col[1]]
        return self.y[:, col]

    @cached_property
    def input_values(self) -> np.ndarray:
        """The inputs' values at every output time, shape (m, k), columns in the order of
        ``model.equations.inputs`` (empty second axis without inputs); ``sol[u]`` is one column."""
        return self.model.input_values(self.t, self.y)

    @cached_property
    def accelerations(self) -> np.ndarray:
        """q̈ at every output time, shape (m, n), from the model's right-hand side."""
        n = self.model.n
        if self.switches:
            sw_model, sigma = self.switches[:2]
            k = len(self.model.equations.parameters)  # p = [parameters, σ's, inputs]
            p, pin = self.model.params[:k], self.model.params[k:]
            rows = [sw_model.rhs(ti, yi, np.concatenate([p, si, pin])).__getitem__(slice(n, None))
                    for ti, yi, si in zip(self.t, self.y, sigma)]
        else:
            rows = [self._model_at(i).fun(ti, yi)[n:] for i, (ti, yi) in enumerate(zip(self.t, self.y))]
        return np.array(rows, dtype=float).reshape(len(self.t), n)

    @cached_property
    def multipliers(self) -> np.ndarray:
        """λ at every output time, shape (m_times, m) (empty second axis without constraints).

        ``Aᵀλ`` is the generalized force of the constraints (see :mod:`lagrange.model.constraints`)."""
        m = self.model.m
        if not m:
            return np.empty((len(self.t), 0))
        return np.array([self._model_at(i).multipliers(ti, yi)
                         for i, (ti, yi) in enumerate(zip(self.t, self.y))]).reshape(len(self.t), m)

    def _model_at(self, i: int):
        """The model with the parameters in force at output point i (friction signs may change)."""
        if self.point_params is None:
            return self.model
        import dataclasses

        return dataclasses.replace(self.model, params=self.point_params[i])

    def multiplier(self, name: str) -> np.ndarray:
        """λ of the constraint called ``name`` over time."""
        names = self.model.equations.constraint_names
        if name not in names:
            raise KeyError(f"no constraint named {name!r}; constraints: {', '.join(names) or 'none'}")
        return self.multipliers[:, names.index(name)]

    @cached_property
    def constraint_violation(self) -> dict[str, np.ndarray]:
        """Per constraint: ``position`` |φ| (holonomic; 0 otherwise) and ``velocity`` |A q̇ + b| over time."""
        m, n = self.model.m, self.model.n
        if not m:
            return {}
        cf = self.model.constraint_functions
        pos = np.zeros((len(self.t), m))
        vel = np.zeros((len(self.t), m))
        for i, (ti, yi) in enumerate(zip(self.t, self.y)):
            if cf.holonomic:
                pos[i, cf.holonomic] = np.abs(cf.phi(ti, yi[:n]))
            vel[i] = np.abs(cf.velocity_residual(ti, yi))
        return {"position": pos, "velocity": vel}

    def max_constraint_violation(self) -> float:
        """Largest |φ| or |A q̇ + b| over the run (0 without constraints)."""
        v = self.constraint_violation
        return float(max(np.max(v["position"]), np.max(v["velocity"]))) if v else 0.0

    @cached_property
    def diagnostics(self) -> dict[str, np.ndarray]:
        """T, V, energy (T+V), jacobi (h) and power (dh/dt) at every output time."""
        return self.model.diagnostics(self.t, self.y)

    @property
    def energy(self) -> np.ndarray:
        """T + V at every output time."""
        return self.diagnostics["energy"]

    @property
    def jacobi(self) -> np.ndarray:
        """The Jacobi integral h = Σ q̇ ∂L/∂q̇ − L at every output time."""
        return self.diagnostics["jacobi"]

    def power_balance(self) -> np.ndarray:
        """``h(t) − h(0) − ∫ dh/dt`` — zero up to integration error for a consistent model."""
        h = self.jacobi
        w = self.work if self.work is not None else np.zeros_like(h)
        if self.initial:
            t0, y0 = self.initial
            h0 = self.model.diagnostics(np.array([t0]), np.asarray(y0)[None, :])["jacobi"][0]
        else:
            h0 = h[0]
        return h - h0 - w

    def energy_error(self, *, relative: bool = True) -> float:
        """Largest power-balance residual over the run, relative to the largest of max|h|, max|T|, max|V|,
        max|T2|, max|T0| (the parts of h that may cancel) and max|work| when ``relative`` (absolute when all
        of them vanish).

        For a conservative system this is the drift of the Jacobi integral (the energy when nothing
        moves).
        """
        r = float(np.max(np.abs(self.power_balance())))
        if not relative:
            return r
        d = self.diagnostics
        parts = [np.max(np.abs(d[k])) for k in ("jacobi", "T", "V", "T2", "T0")]
        if self.work is not None:
            parts.append(np.max(np.abs(self.work)))
        scale = float(max(parts))
        # every energy zero (e.g. a body at rest in inertial space seen from a rotating frame): absolute
        return r / scale if scale > 1e-12 else r

    # --- export -------------------------------------------------------------------------------
    def to_csv(self, path: str | Path) -> Path:
        """Write ``t``, the state columns, the inputs' values (when the system has inputs), the diagnostics and,
        with constraints, one ``lambda_<name>`` column per constraint (its multiplier, :meth:`multiplier`) to a
        CSV file."""
        path = Path(path)
        d = self.diagnostics
        U = self.input_values
        lam_names = [f"lambda_{name}" for name in self.model.equations.constraint_names]
        lam = self.multipliers if lam_names else np.empty((len(self.t), 0))
        with path.open("w", newline="") as fh:
            import csv

            w = csv.writer(fh)
            w.writerow(["t", *self.names, *(u.name for u in self.model.equations.inputs), "energy", "jacobi",
                        "power_balance", *lam_names])
            pb = self.power_balance()
            for i in range(len(self.t)):
                w.writerow([repr(float(self.t[i])), *(repr(float(v)) for v in self.y[i]),
                            *(repr(float(v)) for v in U[i]),
                            repr(float(d["energy"][i])), repr(float(d["jacobi"][i])), repr(float(pb[i])),
                            *(repr(float(v)) for v in lam[i])])
        return path

    def plot(self, path: str | Path | None = None, **kwargs):
        """One panel per coordinate against time, phase portraits, power balance and λ by constraint name;
        ``coordinates=``, ``ax=``, ``title=`` (see :func:`lagrange.plot.plot_trajectory`). Writes a PNG when
        ``path`` is given, never changing the matplotlib backend."""
        from ..plot import plot_trajectory

        return plot_trajectory(self, path, **kwargs)

    def __repr__(self) -> str:
        return (
            f"<Trajectory {len(self.t)} points, t=[{self.t[0]:.6g}, {self.t[-1]:.6g}], "
            f"method={self.method}, nfev={self.nfev}, success={self.success}"
            + (f", verdict: {self.verdict.summary()}" if self.verdict is not None else "") + ">"
        )

    def _repr_html_(self) -> str:
        """A summary table for Jupyter (:func:`lagrange.display.trajectory_html`)."""
        from ..display import trajectory_html

        return trajectory_html(self)
