r"""The small-oscillation report of one system at one reference point (what ``lagrange modes`` shows).

:func:`modes_report` linearizes (:func:`~lagrange.analysis.small_oscillations.linearize`), at the given point
or, with none, at the equilibrium found (:mod:`lagrange.analysis.operating_point`), checks that the point is an
equilibrium or a steady motion, and tabulates one row per mode: the characteristic root λ (one row per
complex pair ``Re λ ± i|Im λ|``; a part below :data:`ROUNDING` of the largest root is shown as 0), the
frequency ``ω = |Im λ|``, the damping ratio ``ζ = −Re λ/|λ|``, the period
``2π/ω`` and the mode shape by coordinate (the displacement part of the eigenvector of the state matrix, in
all coordinates, scaled so that its largest component is 1; a k-fold root gets the null vectors of
``𝒜 − λI`` one per row, repeating the last when the root is defective). Inputs are held at constant values (their value
at t = 0 unless given). The CLI only formats the returned :class:`ModesReport`.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import sympy as sp

from ..conventions import VELOCITY_SUFFIX, t
from ..errors import AnalysisError, LagrangeError
from ..model.coordinates import coordinate_name
from ..records import record
from ..safe_sympify import sympify as _sympify
from .equilibria import equilibria_near
from .operating_point import STABLE_TOL, point_text
from .small_oscillations import LinearModel, characteristic_roots, linearize

__all__ = ["ModeRow", "ModesReport", "modes_report", "input_values_at_start", "symbolic_residual"]

#: the largest acceleration at the reference (relative to 1 + max|𝒜|) still counted as an equilibrium
RESIDUAL_TOL = 1e-8


#: parts of a root below this fraction of max(1, |λ|max) are rounding of the eigen-solver: shown as 0
ROUNDING = 1e-12


@record(frozen=True)
class ModeRow:
    """One mode: ``eigenvalue`` (the root with Im ≥ 0 of a pair), ``frequency`` ω = |Im λ|, ``damping_ratio``
    ζ = −Re λ/|λ| (nan for λ = 0), ``period`` 2π/ω (inf for ω = 0) and ``shape`` ``{coordinate name: complex
    amplitude}`` (largest 1)."""

    eigenvalue: complex
    frequency: float
    damping_ratio: float
    period: float
    shape: dict


@record(frozen=True)
class ModesReport:
    """Everything ``lagrange modes`` prints (see the module docstring).

    Attributes
    ----------
    linear : LinearModel — the linearization (``linear.about``: the point used)
    roots : ndarray — every characteristic root, sorted
    rows : tuple of ModeRow — one per real root or complex pair, by frequency
    stable : bool — every ``Re λ ≤ 1e-6 max(1, |λ|max)``
    kind : str — ``"equilibrium"`` or ``"steady motion"`` (non-zero reference velocities)
    residual : float — ``max |q̈|`` at the reference (0 at an equilibrium or steady motion)
    is_reference : bool — the residual is below :data:`RESIDUAL_TOL` (else linearized anyway, ``force``)
    inputs : dict — ``{input name: the constant value it was held at}``
    state_labels : tuple of str — the states of ``state_matrix`` (coordinates, then ``q_dot`` speeds)
    state_matrix : ndarray — 𝒜
    shape_coordinates : tuple of str — the columns of each row's shape
    """

    linear: LinearModel
    roots: np.ndarray
    rows: tuple
    stable: bool
    kind: str
    residual: float
    is_reference: bool
    inputs: dict
    state_labels: tuple
    state_matrix: np.ndarray
    shape_coordinates: tuple

    def to_dict(self) -> dict:
        """A JSON-ready dict (complex numbers as ``[re, im]``, inf and nan as None)."""
        lin = self.linear
        return {
            "about": {coordinate_name(q): _json(v) for q, v in lin.about.items()},
            "velocities": {coordinate_name(v.args[0]) + VELOCITY_SUFFIX: _json(x) for v, x in lin.velocities.items()},
            "inputs": {k: _json(v) for k, v in self.inputs.items()},
            "reference": lin.reference or "given",
            "equilibria": [{coordinate_name(q): _json(v) for q, v in e.items()} for e in lin.equilibria],
            "kind": self.kind, "residual": _json(self.residual), "is_reference": self.is_reference,
            "stable": self.stable,
            "modes": [{"eigenvalue": _json(r.eigenvalue), "frequency": _json(r.frequency),
                       "damping_ratio": _json(r.damping_ratio), "period": _json(r.period),
                       "shape": {k: _json(v) for k, v in r.shape.items()}} for r in self.rows],
            "roots": [_json(z) for z in self.roots],
            "state_matrix": {"states": list(self.state_labels), "rows": self.state_matrix.tolist()},
            "multipliers": {k: _json(v) for k, v in lin.multipliers.items()},
        }


def _json(v):
    if isinstance(v, (complex, np.complexfloating)):
        return [_json(v.real), _json(v.imag)]
    try:
        x = float(v)
    except (TypeError, ValueError):
        return str(v)
    return x if np.isfinite(x) else None


def input_values_at_start(values: Mapping, params: Mapping) -> dict:
    """Input values ``{name: number or expression of t and the parameters}`` held constant: each at its value
    at t = 0 with the parameters' values (by name) substituted; AnalysisError naming a value that is not a
    number then."""
    out = {}
    for name, value in values.items():
        if callable(value) and not isinstance(value, sp.Basic):  # a function of t, as simulate takes it
            try:
                value = float(value(0.0))
            except Exception as exc:  # noqa: BLE001 - user code: any failure is reported by name
                raise AnalysisError(f"input {name}: its function could not be evaluated at t = 0 ({exc}); give "
                                    "a number") from None
        v = _sympify(value)
        v = v.xreplace({s: _sympify(params[s.name]) for s in v.free_symbols if s.name in params}).xreplace({t: 0})
        try:
            out[name] = float(v)
        except (TypeError, ValueError):
            raise AnalysisError(f"input {name} = {value} is not a number at t = 0 (missing values for "
                                f"{', '.join(sorted(map(str, v.free_symbols)))})") from None
    return out


def modes_report(system, params: Mapping, about: Mapping | None = None, *, inputs: Mapping | None = None,
                 force: bool = False, near: Mapping | None = None) -> ModesReport:
    """Linearize ``system`` with numbers and tabulate its modes (see the module docstring).

    ``about``: coordinates (and velocities ``q_dot``) by name; none: the equilibrium found nearest to ``near``
    (stable preferred). ``inputs``: constant input values by name (default 0). Raises
    :class:`~lagrange.errors.AnalysisError` when a given point is neither an equilibrium nor a steady motion
    (listing the equilibria found near it) unless ``force``.
    """
    inputs = dict(inputs or {})
    values = {**{getattr(k, "name", str(k)): v for k, v in params.items()}, **inputs}
    lin = linearize(system, about or None, params=values, near=near)
    A, _ = lin.numeric_state()
    A = np.asarray(A, dtype=float)
    acc = np.abs(np.asarray(lin.acceleration if lin.acceleration is not None else (), dtype=float))
    residual = float(acc.max()) if acc.size else 0.0
    moving = any(float(v) != 0 for v in lin.velocities.values())
    kind = "steady motion" if moving else "equilibrium"
    ok = residual <= RESIDUAL_TOL * (1.0 + float(np.max(np.abs(A))) if A.size else 1.0)
    if not ok and not force:
        raise AnalysisError(_not_a_reference(system, lin, values, kind, moving))
    roots = characteristic_roots(lin)
    top = max(1.0, float(np.max(np.abs(roots)))) if roots.size else 1.0
    stable = bool(np.all(roots.real <= STABLE_TOL * top))
    C0 = lin.coordinate_map
    C0 = None if C0 is None else _float(C0)
    names = tuple(coordinate_name(q) for q in (lin.all_coordinates if C0 is not None else lin.coordinates))
    rows = tuple(_rows(A, roots, len(lin.coordinates), C0, names, top))
    speeds = lin.speeds or tuple(q.diff(t) for q in lin.coordinates)
    labels = tuple(coordinate_name(q) for q in lin.coordinates) + tuple(
        coordinate_name(v.args[0]) + VELOCITY_SUFFIX for v in speeds)
    return ModesReport(lin, roots, rows, stable, kind, residual, ok, inputs, labels, A, names)


def _float(X) -> np.ndarray:
    return np.asarray(X, dtype=float) if isinstance(X, np.ndarray) else np.array(sp.Matrix(X).evalf(), dtype=float)


def _rows(A: np.ndarray, roots: np.ndarray, n: int, C0, names: tuple, top: float) -> list[ModeRow]:
    """One row per real root and per complex pair (the member with Im > 0), by frequency then Re λ."""
    picked = [z for z in roots if z.imag >= -ROUNDING * top]
    rows = []
    seen: list[complex] = []
    for z in sorted(picked, key=lambda z: (abs(z.imag), z.real)):
        z = complex(0.0 if abs(z.real) <= ROUNDING * top else z.real, 0.0 if abs(z.imag) <= ROUNDING * top else z.imag)
        repeat = sum(1 for w in seen if abs(w - z) <= 1e-9 * top)  # a repeated root: the next null vector
        seen.append(z)
        w = abs(z.imag)
        mag = abs(z)
        zeta = -z.real / mag + 0.0 if mag > ROUNDING * top else float("nan")
        period = 2 * np.pi / w if w > 0 else float("inf")
        _, sv, vh = np.linalg.svd(A - z * np.eye(A.shape[0]))
        k = min(repeat, A.shape[0] - 1)
        k = k if sv[-1 - k] <= 1e-9 * max(1.0, float(sv[0])) else 0  # defective: fewer eigenvectors than roots
        vec = vh[-1 - k].conj()[:n]
        if C0 is not None:
            vec = C0 @ vec
        big = vec[np.argmax(np.abs(vec))] if vec.size else 1.0
        vec = vec / big if abs(big) > 0 else vec
        vec = np.where(np.abs(vec) < 1e-10, 0.0, vec)
        rows.append(ModeRow(z, w, zeta, period, dict(zip(names, (complex(v) for v in vec)))))
    return rows


def symbolic_residual(lin: LinearModel) -> list:
    """The accelerations (or, unconstrained, the forcing F) at a symbolic reference, at t = 0, simplified:
    all zero at an equilibrium."""
    from ..simplification import simplify

    residual = lin.acceleration if lin.acceleration is not None else tuple(lin.forcing)
    return [simplify(_sympify(e).subs(t, 0)) for e in residual]


def _not_a_reference(system, lin, values, kind: str, moving: bool) -> str:
    """The refusal of a point that is not an equilibrium: the accelerations there and the equilibria found
    near it, as ``--about`` options."""
    acc = ", ".join(f"{coordinate_name(q)}'' = {float(a) + 0.0:.4g}" for q, a in zip(lin.all_coordinates or
                                                                          lin.coordinates, lin.acceleration))
    text = f"the reference state ({point_text(lin.about)}) is not {'a' if moving else 'an'} {kind}: {acc} there"
    if moving:
        return text + "; give a steady motion in --about (coordinates and q_dot velocities), or pass --force"
    try:
        found = equilibria_near(system, values, {q: float(v) for q, v in lin.about.items()})[:4]
    except LagrangeError:  # the advice is optional: the refusal stands without it
        found = []
    if not found:
        return text + "; no equilibrium was found near it: pass --force to linearize there anyway"
    options = ["  " + " ".join(f"--about {coordinate_name(q)}={float(v):.10g}" for q, v in e.items()) for e in found]
    return (text + "; equilibria found near it:\n" + "\n".join(options)
            + "\nor leave out --about to use the stable one nearest to q = 0, or pass --force to linearize there "
              "anyway")
