"""The registry of integration methods: one table that :func:`~lagrange.integrate.run.simulate`, ``method="auto"``,
the command line (``lagrange methods``, ``--method``) and the spec checks all read.

Each :class:`Method` declares its name (and aliases; names are case-insensitive), its family, its order, what it
needs and what it supports — events, holonomic and non-holonomic constraints, projection onto the constraints,
dry-friction switches, rough constraints, inputs (constant, time-varying), the compiled loop, whether it is
conservative-only and whether it takes a fixed ``step`` — and the function that runs it, named as
``"module:function"`` and imported only when the method runs (this module imports nothing heavy, so the command
line lists and checks methods without loading numpy, scipy or sympy).

``simulate`` builds a :class:`~lagrange.integrate.request.RunRequest`, checks it against the entry with
:func:`check_supported` (one :class:`~lagrange.errors.MethodError` naming the unsupported combination and listing
the methods that support it) and calls ``entry.runner()(request)``.

Adding a method
---------------
A new method is **one new file plus one entry here**: write ``lagrange/integrate/<scheme>.py`` with a function
``run(request) -> Trajectory`` (see :mod:`lagrange.integrate.request` for what the request carries, and
:func:`lagrange.integrate.scipy_ivp.run` or :func:`lagrange.integrate.fixed.run` for examples), then append a
:class:`Method` to :data:`METHODS` declaring honestly what it supports: ``simulate`` refuses every other
combination before the method is called, so the run function never sees a request it cannot honour.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable

from ..errors import InputError, MethodError
from ..records import record

__all__ = ["Method", "METHODS", "get", "find", "names", "supporting", "check_supported", "table"]


@record(frozen=True)
class Method:
    """One integration method of :func:`~lagrange.integrate.run.simulate` and what it can do.

    Attributes
    ----------
    name : the name ``simulate(method=...)`` takes (matched case-insensitively, as are ``aliases``)
    family : ``"scipy explicit RK"``, ``"scipy implicit"``, ``"Taylor series"`` or ``"fixed-step geometric"``
    order : the order of the scheme (text: ``"8"``, ``"1-12"``, ``"adaptive"``)
    run : ``"module:function"`` of the function ``run(request) -> Trajectory``, imported when the method runs
    summary : one line for the method table
    adaptive : chooses its steps from ``rtol``/``atol`` (else it takes a fixed ``step``, which it then requires)
    events, holonomic, nonholonomic, friction_switches, rough : supports user events, holonomic and
        non-holonomic constraints, dry-friction ``sign()`` switches (``friction="events"``), Wells' rough
        constraints
    projection : the constraints can be kept by projection after each step (one-step methods; the others use
        Baumgarte stabilization)
    inputs, varying_inputs : runs systems with inputs (constant values), and time-varying input values
    loops : who can run its steps: ``"python"`` (scipy or a Python loop), ``"numba"`` (a compiled numba loop),
        ``"C"`` (a loop in C), ``"LLVM"`` (heyoka's JIT-compiled loop)
    conservative_only : needs a conservative system (forces derivable from V only; no P, Q or inputs)
    dense_output : its output at ``t_eval`` comes from an interpolant (else the output is the steps recorded)
    precheck : ``"module:function"`` of ``precheck(equations)``, run before the generic check to refuse with the
        method's own, more specific error (the Taylor tape names the constraint or operation it cannot expand)
    """

    name: str
    family: str
    order: str
    run: str
    summary: str
    aliases: tuple[str, ...] = ()
    adaptive: bool = True
    events: bool = True
    holonomic: bool = True
    nonholonomic: bool = True
    projection: bool = True
    friction_switches: bool = True
    rough: bool = True
    inputs: bool = True
    varying_inputs: bool = True
    loops: tuple[str, ...] = ("python",)
    conservative_only: bool = False
    dense_output: bool = True
    precheck: str = ""

    @property
    def step_required(self) -> bool:
        """A fixed-step method: ``step=h`` is required and tolerances do not apply."""
        return not self.adaptive

    def runner(self) -> Callable:
        """The function ``run(request) -> Trajectory`` (imported now)."""
        module, _, function = self.run.partition(":")
        return getattr(importlib.import_module(module), function)

    def check_equations(self, equations) -> None:
        """Run the method's own ``precheck`` on ``equations`` (nothing when it has none)."""
        if self.precheck:
            module, _, function = self.precheck.partition(":")
            getattr(importlib.import_module(module), function)(equations)


_SCIPY = "lagrange.integrate.scipy_ivp:run"
_FIXED = "lagrange.integrate.fixed:run"
_GEOMETRIC = dict(family="fixed-step geometric", run=_FIXED, adaptive=False, events=False, holonomic=False,
                  nonholonomic=False, projection=False, friction_switches=False, rough=False, inputs=False,
                  varying_inputs=False, loops=("python", "numba"), conservative_only=True, dense_output=False)

#: every method, in the order the table lists them
METHODS: tuple[Method, ...] = (
    Method("DOP853", "scipy explicit RK", "8", _SCIPY, "Dormand-Prince 8(5,3); the default",
           loops=("python", "numba")),
    Method("RK45", "scipy explicit RK", "5", _SCIPY, "Dormand-Prince 5(4)", loops=("python", "numba")),
    Method("RK23", "scipy explicit RK", "3", _SCIPY, "Bogacki-Shampine 3(2)"),
    Method("LSODA", "scipy implicit", "1-12", _SCIPY, "Adams/BDF switching on stiffness (constraints: Baumgarte)",
           projection=False),
    Method("Radau", "scipy implicit", "5", _SCIPY, "implicit Runge-Kutta Radau IIA, generated Jacobian"),
    Method("BDF", "scipy implicit", "1-5", _SCIPY, "backward differentiation formulas (constraints: Baumgarte)",
           projection=False),
    Method("taylor", "Taylor series", "adaptive", "lagrange.integrate.taylor_run:run",
           "adaptive Taylor series of order ceil(-ln(rtol)/2 + 1), analytic unconstrained systems",
           events=False, holonomic=False, nonholonomic=False, projection=False, friction_switches=False,
           rough=False, varying_inputs=False, loops=("C", "numba"), precheck="lagrange.integrate.taylor_run:precheck"),
    Method("heyoka", "Taylor series", "adaptive", "lagrange.integrate.heyoka_run:run",
           'heyoka.py\'s LLVM-compiled Taylor method on the derived equations; pip install '
           '"lagrange-dynamics[heyoka]"', holonomic=False, nonholonomic=False, projection=False,
           friction_switches=False, rough=False, varying_inputs=False, loops=("LLVM",),
           precheck="lagrange.integrate.heyoka_run:precheck"),
    Method("midpoint", order="2", summary="implicit midpoint rule, symplectic", aliases=("implicit_midpoint",),
           **_GEOMETRIC),
    Method("gl4", order="4", summary="Gauss-Legendre collocation (2 stages), symplectic", **_GEOMETRIC),
    Method("gl6", order="6", summary="Gauss-Legendre collocation (3 stages), symplectic", **_GEOMETRIC),
    Method("verlet", order="2", summary="Stormer-Verlet, symplectic; constant M and V(q)",
           aliases=("stormer_verlet",), **_GEOMETRIC),
    Method("dg", order="2", summary="discrete gradient: energy conserved to the Newton tolerance",
           aliases=("discrete_gradient",), **_GEOMETRIC),
    Method("verlet6", order="6", summary="Kahan-Li 9-stage composition of Stormer-Verlet, symplectic; constant M "
           "and V(q)", aliases=("kahan_li6",), **_GEOMETRIC),
    Method("verlet8", order="8", summary="McLachlan 15-stage composition of Stormer-Verlet, symplectic; constant M "
           "and V(q)", aliases=("mclachlan8",), **_GEOMETRIC),
)

_BY_NAME = {key.lower(): m for m in METHODS for key in (m.name, *m.aliases)}


def find(name) -> Method | None:
    """The entry of ``name`` (case-insensitive, aliases accepted, surrounding blanks ignored), or None.

    >>> find("dop853").name, find(" GL4 ").name, find("rk4")
    ('DOP853', 'gl4', None)
    """
    if not isinstance(name, str):
        return None
    return _BY_NAME.get(name.strip().lower())


def names(*, adaptive: bool | None = None) -> tuple[str, ...]:
    """The method names in table order (only the adaptive or only the fixed-step ones when asked)."""
    return tuple(m.name for m in METHODS if adaptive is None or m.adaptive == adaptive)


def get(name) -> Method:
    """The entry of ``name``; :class:`~lagrange.errors.MethodError` listing the methods when there is none."""
    entry = find(name)
    if entry is None:
        raise MethodError(f"unknown method {name!r}; choose one of {', '.join(names())} or 'auto' "
                          "(case-insensitive; `lagrange methods` prints the table)")
    return entry


#: the features a request can need: (attribute of Method, how the message names it)
FEATURES = {
    "events": "events",
    "holonomic": "holonomic constraints",
    "nonholonomic": "non-holonomic constraints",
    "friction_switches": "dry-friction sign() switches with friction='events'",
    "rough": "rough constraints",
    "inputs": "inputs",
    "varying_inputs": "time-varying inputs",
    "dense_output": "output at given times t_eval (a fixed-step method records every stride-th step: use n_points)",
}


def supporting(*features: str) -> tuple[str, ...]:
    """The methods that support every one of ``features`` (attribute names of :class:`Method`)."""
    return tuple(m.name for m in METHODS if all(getattr(m, f) for f in features))


def check_supported(entry: Method, needs: dict[str, str], *, conservative: bool = True) -> None:
    """Refuse a request that ``entry`` cannot honour.

    ``needs`` maps each feature the request needs (a key of :data:`FEATURES`) to the detail that names it in the
    message (``"2 event functions"``, ``"the constraint rolling"``). ``conservative``: whether the system is
    conservative (for the conservative-only methods).

    Raises
    ------
    MethodError (InputError when only inputs are unsupported; both are TypeErrors)
        Naming the method, every unsupported feature with its detail, and the methods that support them all.
    """
    missing = [f for f in needs if not getattr(entry, f)]
    problems = [f"{FEATURES[f]} ({needs[f]})" if needs[f] else FEATURES[f] for f in missing]
    if entry.conservative_only and not conservative:
        problems.append("a non-conservative system (forces outside V: P, Q or inputs; these methods preserve a "
                        "Hamiltonian structure it does not have)")
    if not problems:
        return
    ok = [m for m in supporting(*missing) if not (find(m).conservative_only and not conservative)]
    kind = InputError if missing and set(missing) <= {"inputs", "varying_inputs"} else MethodError
    why = (" (time-varying inputs run on the scipy methods, which call Python per step; the compiled loops, the "
           "Taylor tape and the geometric methods take constant inputs at most)" if "varying_inputs" in missing
           else "")
    raise kind(f"method={entry.name!r} (a {entry.family} integrator) does not support {' and '.join(problems)}"
               f"{why}; methods that do: {', '.join(ok) if ok else 'none'}{' or auto' if ok else ''}")


def table() -> str:
    """The method table as text (``lagrange methods``)."""
    def yes(flag: bool) -> str:
        return "yes" if flag else "-"

    head = ("method", "family", "order", "step", "events", "holon.", "nonhol.", "friction", "rough", "inputs",
            "loops")
    rows = [head]
    for m in METHODS:
        inputs = "varying" if m.varying_inputs else ("constant" if m.inputs else "-")
        constraints = ("projection" if m.projection else "Baumgarte") if m.holonomic else "-"
        rows.append((m.name, m.family, m.order, "fixed" if m.step_required else "adaptive", yes(m.events),
                     constraints, yes(m.nonholonomic), yes(m.friction_switches), yes(m.rough), inputs,
                     "+".join(m.loops)))
    widths = [max(len(r[i]) for r in rows) for i in range(len(head))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    lines.append("")
    lines.append("auto: chosen among the methods that support the request (stiff: taylor when cheaper, else LSODA, "
                 "Radau with projection; smooth: taylor; else DOP853). Taylor only for analytic equations without a "
                 "kink or a near-singularity (a small regularization parameter).")
    lines.append("Fixed-step (geometric) methods need step=h and a conservative, unconstrained system without "
                 "inputs.")
    lines += [f"  {m.name}: {m.summary}" for m in METHODS]
    return "\n".join(lines)
