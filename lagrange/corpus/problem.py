"""A worked problem of the book: its system, the book's answers, the citation and any correction."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import field

from ..records import record
from .answers import Answer
from .compare import Mismatch

__all__ = ["Problem", "Simulation", "CheckResult", "LazySystem"]


class LazySystem:
    """A problem's System built on first use, for declarations that take seconds to build (the Whipple
    bicycle): listing or importing the corpus must not pay for them. Every attribute is the built System's
    (``problem.system.simulate(...)``, ``.derived``, ``.coordinates``); :meth:`build` returns the System itself
    for functions that need the object."""

    def __init__(self, build, name: str = ""):
        self._build = build
        self._system = None
        self.name = name

    def build(self):
        """The System (built once)."""
        if self._system is None:
            self._system = self._build()
        return self._system

    def __getattr__(self, attr):
        if attr.startswith("__") or attr in ("_build", "_system"):
            raise AttributeError(attr)
        return getattr(self.build(), attr)

    def __repr__(self) -> str:
        return repr(self._system) if self._system is not None else f"<System {self.name!r}: built on first use>"


@record(frozen=True)
class Simulation:
    """Default numbers for ``lagrange simulate ID``: parameter values, initial state, end time."""

    params: Mapping
    initial: Mapping
    t_end: float
    options: Mapping = field(default_factory=dict)


@record(frozen=True)
class CheckResult:
    """The outcome of checking one answer of one problem (``detail`` says what disagreed)."""

    problem: str
    answer: str
    ok: bool
    detail: str = ""


@record(frozen=True)
class Problem:
    """One worked example or problem of Wells' *Lagrangian Dynamics*.

    Attributes
    ----------
    id : str — e.g. ``"ex3.2"`` (worked example), ``"p3.7"`` (problem), ``"sec1.9"``, ``"eq2.41"``
    title : one line
    chapter : int
    source : citation, e.g. ``"Wells, Example 3.2"``
    system : the System in the book's coordinates, or None for a problem without dynamics (ch. 7)
    answers : the book's answers (after documented corrections)
    correction : "" or the misprint, the corrected form and why it is right
    units : units of the numbers (Wells is unit-agnostic; Sec. 1.9 uses CGS)
    simulation : default numbers for ``lagrange simulate`` (None: no dynamics to simulate)
    ranges : sampling ranges ``{symbol name: (lo, hi)}`` for numeric comparison where the default
        (parameters in [1.1, 2.3], coordinates and velocities in [0.15, 0.85]) leaves the domain
    operating_point : the reference state for `lagrange modes`: {coordinate or velocity name: expression in the
        parameters}
    """

    id: str
    title: str
    chapter: int
    source: str
    system: object
    answers: Sequence[Answer]
    correction: str = ""
    units: str = "any consistent units"
    simulation: Simulation | None = None
    ranges: Mapping = field(default_factory=dict)
    tags: Sequence[str] = ()
    operating_point: Mapping = field(default_factory=dict)

    def check(self) -> list[CheckResult]:
        """Check every answer; never raises for a mismatch (it is reported)."""
        out = []
        for a in self.answers:
            try:
                a.check(self.system, self.ranges)
                out.append(CheckResult(self.id, a.description, True))
            except Mismatch as exc:
                out.append(CheckResult(self.id, a.description, False, str(exc)))
        return out
