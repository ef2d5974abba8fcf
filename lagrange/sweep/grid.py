"""The points of a sweep: full grids, random (Latin-hypercube) samples, and stable run ids.

A *point* is a dict ``{name: float}`` — parameter values, initial values (``"theta"``, ``"theta_dot"``) or
any other quantity a task understands (Greenspan's spin ``V`` and tilt ``alpha_deg``). Its *run id* is a
hash of the sorted names and the exact values (``float.hex``), so the same point always gets the same id,
in any process, on any machine, in any order: that is what lets a stored sweep be resumed.
"""

from __future__ import annotations

import hashlib
import itertools
import math
from collections.abc import Mapping, Sequence

import numpy as np

from ..errors import SweepError

__all__ = ["parse_range", "grid_points", "random_points", "run_id"]


def parse_range(text: str) -> np.ndarray:
    """``"start:stop:num"`` → ``numpy.linspace(start, stop, num)``; ``"a,b,c"`` → those values; ``"x"`` → [x].

    >>> parse_range("0:1:3").tolist()
    [0.0, 0.5, 1.0]
    >>> parse_range("1,2.5").tolist()
    [1.0, 2.5]
    """
    try:
        if ":" in text:
            start, stop, num = text.split(":")
            n = int(num)
            if n < 1:
                raise ValueError
            return np.linspace(float(start), float(stop), n)
        return np.array([float(v) for v in text.split(",")])
    except ValueError:
        raise SweepError(f"{text!r} is not a range: write start:stop:num (e.g. 0:1:11) or a list a,b,c") from None


def _values(over: Mapping[str, Sequence[float]]) -> dict[str, np.ndarray]:
    if not over:
        raise SweepError("nothing to sweep: `over` must name at least one quantity with its values")
    out, problems = {}, []
    for name, vals in over.items():
        try:
            arr = np.atleast_1d(np.asarray(vals, dtype=float)) if not isinstance(vals, str) else parse_range(vals)
        except (TypeError, ValueError) as exc:  # a string among the values is refused, never evaluated
            if isinstance(exc, SweepError):
                raise
            problems.append(f"{name}: values must be numbers ({exc})")
            continue
        except OverflowError:
            problems.append(f"{name}: values must be numbers within the floating-point range (about 1.8e308)")
            continue
        if arr.ndim != 1 or arr.size == 0:
            problems.append(f"{name}: give a non-empty 1-D sequence of values")
        elif not np.all(np.isfinite(arr)):
            problems.append(f"{name}: values must be finite")
        out[str(name)] = arr
    if problems:
        raise SweepError("; ".join(problems))
    return out


def grid_points(over: Mapping[str, Sequence[float]]) -> list[dict[str, float]]:
    """Every combination of the values (the last name varies fastest).

    >>> grid_points({"a": [1, 2], "b": [0, 5]})
    [{'a': 1.0, 'b': 0.0}, {'a': 1.0, 'b': 5.0}, {'a': 2.0, 'b': 0.0}, {'a': 2.0, 'b': 5.0}]
    """
    vals = _values(over)
    names = list(vals)
    return [dict(zip(names, map(float, combo))) for combo in itertools.product(*vals.values())]


def random_points(over: Mapping[str, Sequence[float]], n: int, *, seed: int | None = 0) -> list[dict[str, float]]:
    """``n`` points spread over the box ``[min, max]`` of each name's values by a Latin hypercube
    (:class:`scipy.stats.qmc.LatinHypercube`: every one of the n equal slices of each range holds one point).

    >>> pts = random_points({"a": (0, 1), "b": (10, 20)}, 4, seed=1)
    >>> sorted(int(p["a"] * 4) for p in pts), all(10 <= p["b"] <= 20 for p in pts)
    ([0, 1, 2, 3], True)
    """
    from scipy.stats import qmc

    if int(n) < 1:
        raise SweepError(f"the number of random points must be at least 1, got {n}")
    vals = _values(over)
    lo = np.array([v.min() for v in vals.values()])
    hi = np.array([v.max() for v in vals.values()])
    unit = qmc.LatinHypercube(d=len(vals), seed=seed).random(int(n))
    pts = lo + unit * (hi - lo)
    return [dict(zip(vals, map(float, row))) for row in pts]


def run_id(point: Mapping[str, float]) -> str:
    """A stable 16-hex-digit id of a point: SHA-256 of the sorted ``name=float.hex(value)`` pairs.

    >>> run_id({"a": 1.0, "b": 2}) == run_id({"b": 2.0, "a": 1})
    True
    """
    parts = []
    for name in sorted(point):
        v = float(point[name])
        parts.append(f"{name}={v.hex() if math.isfinite(v) else v}")
    return hashlib.sha256(";".join(parts).encode()).hexdigest()[:16]
