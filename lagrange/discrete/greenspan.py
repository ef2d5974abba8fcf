r"""Greenspan's discrete tetrahedral top on a smooth plane — the molecular model and the rigid model.

Scene (D. Greenspan, "Conservative motion of a discrete, tetrahedral top on a smooth horizontal plane",
Q. Appl. Math., 1996): four particles P1..P4 at the vertices of a regular tetrahedron of edge
``R = √(5/3)`` (where the pair force vanishes), tip P1 on the plane z = 0, gravity on P2..P4 only
(g = 0.980), spin V of P2..P4 about the axis through P1 and the centre of P2P3P4, tilt α in the XZ plane.

* **Molecular model** (the paper's): 12 Cartesian coordinates (P1's z held at 0), the pair potential
  ``φ(r) = A(−1/r³ + 1/r⁵)``, A = 10⁶, integrated with the exactly energy-conserving discrete gradient
  (:mod:`lagrange.discrete.pair_dg`), dt = 1e-5.
* **Rigid model** (what the scene needs): 5 degrees of freedom — the tip (X, Y) on the plane and Wells'
  Euler angles (ψ, θ, φ) — declared with the public API (four :class:`~lagrange.Particle` placed with
  the :class:`~lagrange.EulerAngles` rotation of the body frame), integrated by an adaptive method.

**Fall time.** The top *has fallen* at the first time t_f at which one of the weighted vertices P2, P3, P4
reaches the support plane, z = 0 (the paper's stopping rule; the tip P1 is on the plane throughout). The
rigid model locates t_f as a terminal event of its adaptive integrator (root of the dense output, to the
run's tolerance); the molecular model interpolates the height linearly inside the step where it first
becomes ≤ 0 (the scheme's positions are piecewise linear in t; error O(dt²)). Both runs stop there.

**P1 drift.** The contact point's net displacement in the plane, ``P1(t_end) − P1(0)``, and its mean
velocity, the least-squares slope of P1(t) over the run (its loops and cusps average out): the drift of the
paper's non-homogeneous tops, whose horizontal momentum Σ m_i v_i is not zero (the centre of mass, and
with it the loops of P1, move at Σ m_i v_i / Σ m_i). For a homogeneous top the momentum is exactly zero
and the horizontal centre of mass stays fixed.

Pbar is the geometric centre (the mean of the four vertices).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import NamedTuple

import numpy as np
import sympy as sp

from ..conventions import VELOCITY_SUFFIX, t
from ..errors import InitialConditionError
from ..model.bodies import Particle
from ..model.coordinates import coordinate_name, coordinates, is_coordinate, parameters
from ..model.rotations import EulerAngles
from ..model.system import System
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from .pair_dg import DGResult, PairSystem

__all__ = ["EXAMPLES", "Example", "initial_vertices", "molecular_model", "run_molecular", "rigid_system",
           "rigid_initial", "run_rigid", "Summary", "summarize", "compare_models", "EDGE", "A_PAIR", "G",
           "MolecularRun", "RigidRun"]

EDGE = float(np.sqrt(5.0 / 3.0))
A_PAIR = 1.0e6
G = 0.980


@record(frozen=True)
class Example:
    """One of the paper's examples: spin speed V, tilt α (degrees), the four masses."""

    number: int
    V: float
    alpha_deg: float
    masses: tuple = (1.0, 1.0, 1.0, 1.0)


def _m(**kw):
    m = [1.0, 1.0, 1.0, 1.0]
    for k, v in kw.items():
        m[int(k[1]) - 1] = v
    return tuple(m)


#: The paper's 14 examples.
EXAMPLES = {
    1: Example(1, 4, 15), 2: Example(2, 8, 15), 3: Example(3, 16, 15),
    4: Example(4, 4, 30), 5: Example(5, 8, 30), 6: Example(6, 16, 30),
    7: Example(7, 4, 45), 8: Example(8, 8, 45), 9: Example(9, 16, 45),
    10: Example(10, 1, 15),
    11: Example(11, 4, 15, _m(m2=0.995)),
    12: Example(12, 4, 30, _m(m2=1.005)),
    13: Example(13, 8, 30, _m(m2=1.005, m3=0.95)),
    14: Example(14, 4, 45, _m(m2=0.995, m3=0.985)),
}


def _tilt(alpha: float) -> np.ndarray:
    c, s = np.cos(alpha), np.sin(alpha)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _body_vertices(R: float = EDGE) -> np.ndarray:
    s3, s6 = np.sqrt(3.0), np.sqrt(6.0)
    return np.array([[0, 0, 0], [0, R * s3 / 3, R * s6 / 3], [R / 2, -R * s3 / 6, R * s6 / 3],
                     [-R / 2, -R * s3 / 6, R * s6 / 3]], dtype=float)


def initial_vertices(ex: Example) -> tuple[np.ndarray, np.ndarray]:
    """Positions and velocities (4, 3) of the paper's initial state: spin V, tilt α in the XZ plane."""
    s3 = np.sqrt(3.0)
    V = ex.V
    v = np.array([[0, 0, 0], [V, 0, 0], [-V / 2, -V * s3 / 2, 0], [-V / 2, V * s3 / 2, 0]], dtype=float)
    Rt = _tilt(np.radians(ex.alpha_deg))
    return _body_vertices() @ Rt.T, v @ Rt.T


def molecular_model(masses=(1.0, 1.0, 1.0, 1.0), A: float = A_PAIR, g: float = G) -> PairSystem:
    """The paper's molecular top: φ(r) = A(−1/r³ + 1/r⁵), weights on P2..P4, P1's z held at 0."""
    r = sp.Symbol("r", positive=True)
    return PairSystem(masses, A * (-1 / r**3 + 1 / r**5), r, weights=[0.0, g, g, g], fixed=[(0, 2)])


class MolecularRun(NamedTuple):
    """A run of the molecular model: unpacks as ``(model, result)``; :attr:`summary` is what the paper reports
    (fall, P1 drift …) and ``result`` carries the energy drift and the solver's counts."""

    model: PairSystem
    result: DGResult

    @property
    def summary(self) -> Summary:
        """The summary over the molecular run's steps: fell, fall time (the crossing interpolated inside the
        step), P1's drift and drift rate."""
        r = self.result
        return summarize(r.t, r.x, r.fell, r.fall_time)


def run_molecular(ex: Example, t_end: float = 110.0, *, dt: float = 1e-5, record_every: int = 5000,
                  A: float = A_PAIR, g: float = G, offset=(0.0, 0.0, 0.0), solver: str = "auto") -> MolecularRun:
    """The paper's run (``A``, ``g``: the pair-potential strength and gravity; ``offset``: a horizontal
    translation of the whole top, which changes nothing but the output's origin; ``solver``: see
    :meth:`~lagrange.discrete.pair_dg.PairSystem.integrate`); returns :class:`MolecularRun`."""
    off = np.asarray(offset, dtype=float)
    if off.shape != (3,) or not np.all(np.isfinite(off)) or off[2] != 0.0:
        raise InitialConditionError(f"offset={offset!r}: a finite horizontal translation (dx, dy, 0); the support "
                                    "plane is z = 0")
    model = molecular_model(ex.masses, A=A, g=g)
    x0, v0 = initial_vertices(ex)
    steps = int(round(t_end / dt))
    res = model.integrate(x0 + off, v0, dt=dt, steps=steps, record_every=record_every, fall_particles=[1, 2, 3],
                          solver=solver)
    return MolecularRun(model, res)


def rigid_system(masses=(1.0, 1.0, 1.0, 1.0)) -> tuple[System, tuple]:
    """The 5-DOF rigid top: tip (X, Y) on the plane, Euler angles (ψ, θ, φ) of the body frame whose axes
    are the untilted lab axes; returns (system, coordinates)."""
    X, Y, psi, th, ph = coordinates("X Y psi theta phi")
    g = parameters("g")
    R = EulerAngles(psi, th, ph).matrix
    tip = sp.Matrix([X, Y, 0])
    s3, s6 = sp.sqrt(3), sp.sqrt(6)
    e = sp.sqrt(sp.Rational(5, 3))
    body = [sp.Matrix([0, 0, 0]), sp.Matrix([0, e * s3 / 3, e * s6 / 3]), sp.Matrix([e / 2, -e * s3 / 6, e * s6 / 3]),
            sp.Matrix([-e / 2, -e * s3 / 6, e * s6 / 3])]
    ms = [sp.nsimplify(mi) for mi in masses]
    parts = [Particle(ms[i], tip + R * body[i], name=f"P{i + 1}") for i in range(4)]
    V = sum((ms[i] * g * parts[i].position[2] for i in range(1, 4)), sp.S.Zero)
    return System([X, Y, psi, th, ph], bodies=parts, V=V, name="Greenspan's top (rigid)"), (X, Y, psi, th, ph)


def _euler_from_matrix(Rm: np.ndarray) -> tuple[float, float, float]:
    """Wells' (ψ, θ, φ) of R = Rz(ψ)Rx(θ)Rz(φ) (0 < θ < π)."""
    th = float(np.arccos(np.clip(Rm[2, 2], -1, 1)))
    psi = float(np.arctan2(Rm[0, 2], -Rm[1, 2]))
    ph = float(np.arctan2(Rm[2, 0], Rm[2, 1]))
    return psi, th, ph


def rigid_initial(ex: Example, coords) -> dict:
    """Initial state of the rigid model equivalent to the paper's: orientation = the tilt, angular velocity
    = spin about the body axis P1→centre of P2P3P4, tip at rest."""
    X, Y, psi, th, ph = coords
    a, b, c = _euler_from_matrix(_tilt(np.radians(ex.alpha_deg)))
    spin = -ex.V * np.sqrt(3.0) / EDGE  # body z component (v2 = (V, 0, 0) at P2 = (0, R/√3, h))
    # body ω = (0, 0, spin): Wells 8.11 gives ψ̇ = θ̇ = 0, φ̇ = spin
    return {X: 0.0, Y: 0.0, psi: a, th: b, ph: c, X.diff(t): 0.0, Y.diff(t): 0.0, psi.diff(t): 0.0,
            th.diff(t): 0.0, ph.diff(t): spin}


def _vertex_function(system: System):
    pos = [p.position for p in system.bodies]
    from ..model.coordinates import to_symbols

    exprs = [to_symbols(P, system.coordinates) for P in pos]
    syms = [to_symbols(q, system.coordinates) for q in system.coordinates]
    f = _lambdify([syms], [list(e) for e in exprs], "numpy")
    return lambda q: np.array(f(list(q)), dtype=float)


class RigidRun(NamedTuple):
    """A run of the rigid model: unpacks as ``(system, trajectory, vertices)`` (vertices (k, 4, 3) at the output
    times); :attr:`summary` says whether and when the top fell and how far P1 drifted."""

    system: System
    trajectory: object
    vertices: np.ndarray

    @property
    def fall_time(self) -> float | None:
        """The first fall event (a weighted vertex reaching z = 0), or None."""
        return self._fall()[0]

    def _fall(self):
        sol = self.trajectory
        events = [(float(te[0]), ye[0]) for te, ye in zip(sol.t_events or [], sol.y_events or []) if len(te)]
        return min(events, key=lambda e: e[0]) if events else (None, None)

    @property
    def summary(self) -> Summary:
        """The summary over the output times and, when the top fell, the state at the fall (the event), so
        that ``summary.t[-1]`` is the fall time in both models."""
        fall, y = self._fall()
        t, verts = self.trajectory.t, self.vertices
        if fall is not None and fall > t[-1]:
            n = len(self.system.coordinates)
            t = np.append(t, fall)
            verts = np.concatenate([verts, _vertex_function(self.system)(y[:n])[None]])
        return summarize(t, verts, fall is not None, fall)


def run_rigid(ex: Example, t_end: float = 110.0, *, t_eval=None, rtol: float = 1e-10, atol: float = 1e-12,
              backend: str = "python", params: Mapping | None = None, initial: Mapping | None = None,
              **options) -> RigidRun:
    """The rigid model over ``t_end`` with a terminal event when a weighted vertex reaches z = 0.

    ``params`` (``{"g": …}``) and ``initial`` (by coordinate name, ``"theta_dot"``…) override the paper's
    values; ``options`` go to :func:`~lagrange.integrate.run.simulate` (``method`` …: an adaptive one,
    since the fall is an event). Returns :class:`RigidRun` ``(system, trajectory, vertices)`` with vertices
    (k, 4, 3) at the output times and ``.summary`` (fall, fall time, P1 drift)."""
    system, coords = rigid_system(ex.masses)
    verts = _vertex_function(system)
    n = len(coords)
    events = []
    for i in (1, 2, 3):
        def ev(t_, y, i=i):
            return float(verts(y[:n])[i, 2])

        ev.terminal = True
        ev.direction = -1
        events.append(ev)
    if t_eval is None:
        t_eval = np.linspace(0.0, t_end, 2201)
    start = {coordinate_name(k) if is_coordinate(k) else coordinate_name(k.expr) + VELOCITY_SUFFIX: v
             for k, v in rigid_initial(ex, coords).items()}
    sol = system.simulate(t_end, {**start, **(initial or {})}, {"g": G, **(params or {})}, t_eval=t_eval,
                          events=events, rtol=rtol, atol=atol, backend=backend, **options)
    V = np.array([verts(y[:n]) for y in sol.y])
    return RigidRun(system, sol, V)


@record(frozen=True)
class Summary:
    """What the paper reports of a run: the path of P1 in the plane, of Pbar, Pbar's height range, the fall."""

    t: np.ndarray
    P1: np.ndarray  # (k, 2) path of the contact point in the plane
    Pbar: np.ndarray  # (k, 3) path of the geometric centre
    zbar_range: tuple
    fell: bool
    fall_time: float | None
    P1_drift: np.ndarray  # (2,) P1(t_end) − P1(0)
    P1_drift_rate: np.ndarray  # (2,) least-squares slope of P1(t): the mean velocity of the contact point

    def _repr_html_(self) -> str:
        from ..display import greenspan_summary_html

        return greenspan_summary_html(self)

    def report(self) -> list[str]:
        """The lines the CLI prints: fall (with its definition) and P1's drift."""
        fall = (f"the top falls at t = {self.fall_time:.6g} (a weighted vertex reaches the plane z = 0)"
                if self.fell else f"the top does not fall by t = {self.t[-1]:.6g} (no weighted vertex reaches z = 0)")
        dx, dy = self.P1_drift
        ux, uy = self.P1_drift_rate
        return [fall, f"P1 drift: ({dx:+.6f}, {dy:+.6f}), |{np.hypot(dx, dy):.6f}| over the run; mean velocity "
                      f"({ux:+.3e}, {uy:+.3e}) per unit time"]


def summarize(t, vertices, fell: bool, fall_time: float | None) -> Summary:
    """Summary of vertex positions (k, 4, 3) at times t (k ≥ 1): P1's path and drift, Pbar's path and height
    range, the fall (see the module's definitions)."""
    t = np.asarray(t, dtype=float)
    P1 = vertices[:, 0, :2]
    Pbar = vertices.mean(axis=1)
    drift = P1[-1] - P1[0]
    if len(t) > 1 and np.ptp(t) > 0:
        tc = t - t.mean()
        rate = (tc @ (P1 - P1.mean(axis=0))) / (tc @ tc)
    else:
        rate = np.zeros(2)
    return Summary(t, P1, Pbar, (float(Pbar[:, 2].min()), float(Pbar[:, 2].max())), fell, fall_time, drift, rate)


def compare_models(ex: Example, t_end: float, *, dt: float = 1e-5, record_every: int = 5000) -> Mapping:
    """Run both models and report the largest differences of P1 and Pbar over the common output times."""
    run = run_molecular(ex, t_end, dt=dt, record_every=record_every)
    mol = run.result
    ms = run.summary
    rigid = run_rigid(ex, float(mol.t[-1]), t_eval=mol.t)
    sol = rigid.trajectory
    rs = rigid.summary
    k = min(len(ms.t), len(rs.t))
    return {
        "example": ex.number,
        "molecular": ms,
        "rigid": rs,
        "max_P1_difference": float(np.max(np.linalg.norm(ms.P1[:k] - rs.P1[:k], axis=1))),
        "max_Pbar_difference": float(np.max(np.linalg.norm(ms.Pbar[:k] - rs.Pbar[:k], axis=1))),
        "molecular_energy_drift": float(mol.energy_drift / abs(mol.energy[0])),
        "rigid_energy_error": float(sol.energy_error()),
    }
