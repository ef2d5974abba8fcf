r"""Budgets on the symbolic work actually done: a CPU-time deadline and a node budget, both public settings.

The estimates of :mod:`lagrange.budget` look at an expression before the work; they cannot see every way in
which sympy's work grows (``sin(sin(…(x + y)))`` twelve deep, the Pythagorean clean-up of a product of sines
over many coordinates) and an upper estimate would refuse models that derive quickly. The symbolic stages
(the derivation of a :class:`~lagrange.System`, each symbolic analysis function) therefore run under a
budget that fires on the work done:

* **time** — a deadline in CPU seconds of the process (``$LAGRANGE_SYMBOLIC_TIMEOUT``, default
  :data:`DEFAULT_TIMEOUT`). In the main thread of a POSIX process the deadline interrupts sympy wherever it
  is (an ``ITIMER_PROF`` timer and its ``SIGPROF``); elsewhere (another thread, a platform without
  ``setitimer``, or a caller that already runs a ``SIGPROF`` timer or handler of its own) it is checked
  between the per-entry operations of the stage (:func:`checkpoint`) only, so one sympy call can overrun it.
  Past the deadline the stage raises :class:`~lagrange.errors.SymbolicTimeoutError`;
* **size** — every entry a stage derives (a mass-matrix entry, a forcing term, a constraint's expanded bias)
  is counted once built (:func:`measure`): beyond ``$LAGRANGE_SYMBOLIC_BUDGET`` distinct nodes (default
  :data:`DEFAULT_NODES`) the stage raises :class:`~lagrange.errors.ExpressionTooLarge`.

Both messages name the stage, the limit, the argument and the environment variable that raise it. A clean-up
that only tidies a result (Pythagorean identities, ``simplify``) runs with a share of the budget
(:func:`tidy`): when it runs out the expression is kept as it is — the same value, less tidy — and the
stage's other clean-ups are skipped; only the stage's own deadline ends the stage.

Settings (an argument wins over the environment variable; each is validated):

====================  ==============================  ================================================
argument              environment variable            meaning
====================  ==============================  ================================================
``symbolic_timeout``  ``LAGRANGE_SYMBOLIC_TIMEOUT``   CPU seconds of one symbolic stage (``inf``: none)
``symbolic_budget``   ``LAGRANGE_SYMBOLIC_BUDGET``    nodes of one derived expression
====================  ==============================  ================================================

The arguments are those of :class:`~lagrange.System` (the default of the analysis of that system) and of each
analysis function (:func:`bounded`).

A stage started inside another (the derivation that an analysis function triggers) ends no later than the
outer stage's deadline.

>>> with stage("an example", timeout=5.0):
...     checkpoint()
>>> symbolic_timeout("1e9")
1000000000.0
"""

from __future__ import annotations

import functools
import math
import os
import signal
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TypeVar

from .errors import ExpressionTooLarge, OptionError, SymbolicTimeoutError

__all__ = ["TIMEOUT_VARIABLE", "NODES_VARIABLE", "DEFAULT_TIMEOUT", "DEFAULT_NODES", "TIDY_SHARE",
           "symbolic_timeout", "symbolic_budget", "stage", "checkpoint", "measure", "tidy", "bounded"]

TIMEOUT_VARIABLE = "LAGRANGE_SYMBOLIC_TIMEOUT"
NODES_VARIABLE = "LAGRANGE_SYMBOLIC_BUDGET"
DEFAULT_TIMEOUT = 8.0
"""CPU seconds of one symbolic stage: well above what the models of the problem corpus need (docs/guarantees.md),
low enough that runaway growth ends within seconds."""
DEFAULT_NODES = 200_000
"""Distinct nodes of one derived expression (the limit :data:`lagrange.budget.MAX_NODES` puts on inputs)."""
TIDY_SHARE = 0.25
"""Share of the stage's timeout that one clean-up may use before it is given up."""

_R = TypeVar("_R")


def _setting(value, argument: str, variable: str, default, example: str) -> tuple[float, str]:
    """``(value as a float, where it came from)``; refuses anything but a positive number."""
    source = argument
    if value is None:
        value, source = os.environ.get(variable), f"${variable}"
        if not value:
            value, source = default, argument
    x = math.nan
    if not isinstance(value, bool):
        try:
            x = float(value)
        except (TypeError, ValueError, OverflowError):
            pass
    if not x > 0:  # also NaN
        raise OptionError(f"{source} = {value!r} is not a positive number: give e.g. {argument}={example} or set "
                          f"{variable}={example}")
    return x, source


def symbolic_timeout(value=None) -> float:
    """The CPU-time limit of a symbolic stage in seconds: ``value`` when given, else ``$LAGRANGE_SYMBOLIC_TIMEOUT``,
    else :data:`DEFAULT_TIMEOUT`. ``inf`` means no limit. Raises :class:`~lagrange.errors.OptionError` unless it
    is a positive number."""
    return _setting(value, "symbolic_timeout", TIMEOUT_VARIABLE, DEFAULT_TIMEOUT, "60")[0]


def symbolic_budget(value=None) -> int:
    """The node limit of one derived expression: ``value`` when given, else ``$LAGRANGE_SYMBOLIC_BUDGET``, else
    :data:`DEFAULT_NODES`. Raises :class:`~lagrange.errors.OptionError` unless it is a positive whole number."""
    x, source = _setting(value, "symbolic_budget", NODES_VARIABLE, DEFAULT_NODES, "1000000")
    if not math.isfinite(x) or x != int(x):
        raise OptionError(f"{source} = {value!r} is not a whole number of nodes: give e.g. symbolic_budget=1000000 "
                          f"or set {NODES_VARIABLE}=1000000")
    return int(x)


class _Stage:
    __slots__ = ("what", "seconds", "deadline", "nodes", "timed", "tidy_given_up")

    def __init__(self, what: str, seconds: float, deadline: float, nodes: int, timed: bool):
        self.what, self.seconds, self.deadline, self.nodes, self.timed = what, seconds, deadline, nodes, timed
        self.tidy_given_up = False


class _Expired(BaseException):
    """Raised inside sympy by the CPU timer; a BaseException so that sympy's ``except Exception`` cannot eat it."""


_local = threading.local()
#: signals held back while a timed stage cleans up (POSIX, where the timer is used at all)
_HELD = {getattr(signal, n) for n in ("SIGPROF", "SIGALRM", "SIGINT") if hasattr(signal, n)}
_previous_handler: list = []  # the SIGPROF handler to restore when the outermost timed stage ends


def _stack() -> list[_Stage]:
    s = getattr(_local, "stack", None)
    if s is None:
        s = _local.stack = []
    return s


def _expire(signum, frame):
    s = _stack()
    if s and s[-1].timed and time.process_time() < s[-1].deadline - 1e-3:  # a late tick of an older timer
        _arm(s[-1].deadline)
        return
    if s:
        raise _Expired


def _arm(deadline: float) -> None:
    signal.setitimer(signal.ITIMER_PROF, max(deadline - time.process_time(), 1e-3))


def _can_time() -> bool:
    """The CPU timer is ours to use: the main thread of a POSIX process, no SIGPROF timer or handler of a caller."""
    if not hasattr(signal, "setitimer") or threading.current_thread() is not threading.main_thread():
        return False
    if _previous_handler or signal.getsignal(signal.SIGPROF) is _expire:  # ours: an outer stage holds it
        return True
    return signal.getitimer(signal.ITIMER_PROF)[0] == 0.0 and signal.getsignal(signal.SIGPROF) in (
        signal.SIG_DFL, signal.SIG_IGN, None)


def _message(st: _Stage) -> str:
    return (f"the {st.what} did not finish within {st.seconds:g} CPU seconds (symbolic_timeout); allow more with "
            f"symbolic_timeout=... or ${TIMEOUT_VARIABLE}, or simplify the declaration (fewer nested functions, "
            "products multiplied out by hand, lengths declared as parameters)")


@contextmanager
def stage(what: str, *, timeout=None, budget=None) -> Iterator[None]:
    """Run the enclosed symbolic work as one stage named ``what`` under the settings ``timeout`` and ``budget``
    (:func:`symbolic_timeout`, :func:`symbolic_budget`; None: the environment or the default).

    Raises :class:`~lagrange.errors.SymbolicTimeoutError` naming ``what`` past the deadline."""
    seconds, nodes = symbolic_timeout(timeout), symbolic_budget(budget)
    s = _stack()
    deadline = time.process_time() + seconds
    if s:
        deadline = min(deadline, s[-1].deadline)
        nodes = nodes if budget is not None else s[-1].nodes
    timed = math.isfinite(deadline) and _can_time()
    st = _Stage(what, seconds, deadline, nodes, timed)
    if timed and signal.getsignal(signal.SIGPROF) is not _expire:
        _previous_handler.append(signal.signal(signal.SIGPROF, _expire))
    s.append(st)
    try:
        if timed:
            _arm(deadline)
        yield
    except _Expired:
        raise SymbolicTimeoutError(_message(st)) from None
    finally:
        # the clean-up runs with the timer's and the caller's signals held back: a handler that raises (ours, or
        # a test's SIGALRM) must not cut it short and leave the timer or its handler behind
        held = signal.pthread_sigmask(signal.SIG_BLOCK, _HELD) if timed else None
        try:
            s.pop()
            if timed:
                outer = next((o for o in reversed(s) if o.timed), None)
                if outer is not None and math.isfinite(outer.deadline):
                    _arm(outer.deadline)
                else:
                    signal.setitimer(signal.ITIMER_PROF, 0)
                    signal.signal(signal.SIGPROF, _previous_handler.pop() if _previous_handler else signal.SIG_DFL)
        finally:
            if held is not None:
                signal.pthread_sigmask(signal.SIG_SETMASK, held)


def checkpoint() -> None:
    """Raise :class:`~lagrange.errors.SymbolicTimeoutError` when the innermost stage is past its deadline (the
    check that also holds where the timer cannot interrupt sympy)."""
    s = _stack()
    if s and time.process_time() > s[-1].deadline:
        raise SymbolicTimeoutError(_message(s[-1]))


def measure(e, *, what: str) -> None:
    """Raise :class:`~lagrange.errors.ExpressionTooLarge` when ``e`` (a derived expression, named ``what``) has
    more distinct nodes than the innermost stage's budget (:func:`symbolic_budget` outside a stage)."""
    from .budget import abbreviate, node_count

    s = _stack()
    limit = s[-1].nodes if s else symbolic_budget()
    checkpoint()
    if hasattr(e, "args") and node_count(e, cap=limit) > limit:
        where = s[-1].what if s else "symbolic work"
        short = abbreviate(e)
        raise ExpressionTooLarge(
            f"{what} {short} has more than {limit:,} nodes (stage: {where}); allow more with symbolic_budget=... "
            f"or ${NODES_VARIABLE}, or simplify the declaration", stage=where, expression=short)


def tidy(fn: Callable[..., _R], e, *args, what: str = "clean-up") -> _R:
    """``fn(e, *args)``, a clean-up whose result equals ``e``, with at most :data:`TIDY_SHARE` of the stage's
    timeout: ``e`` itself when it runs out (and every later clean-up of the stage is skipped). Outside a stage
    the clean-up runs under the default settings."""
    s = _stack()
    if s and s[-1].tidy_given_up:
        return e
    outer = s[-1] if s else None
    share = TIDY_SHARE * (outer.seconds if outer is not None else symbolic_timeout())
    try:
        with stage(what, timeout=share):
            return fn(e, *args)
    except SymbolicTimeoutError:
        if outer is not None:
            outer.tidy_given_up = True
        checkpoint()  # the stage's own deadline has passed too: the stage ends here
        return e


def _settings_of(arg) -> tuple:
    """``(symbolic_timeout, symbolic_budget)`` of the System ``arg`` is or holds (``.system``), else (None, None)."""
    for obj in (arg, getattr(arg, "system", None)):
        if hasattr(obj, "symbolic_timeout") and hasattr(obj, "symbolic_budget"):
            return obj.symbolic_timeout, obj.symbolic_budget
    return None, None


def bounded(what: str) -> Callable:
    """Decorator: the function runs as one :func:`stage` named ``what`` and takes two more keyword arguments,
    ``symbolic_timeout`` and ``symbolic_budget``; left out, they are those of the System given first (or of its
    ``.system``), else the environment's or the defaults."""

    def decorate(fn):
        @functools.wraps(fn)
        def run(*args, symbolic_timeout=None, symbolic_budget=None, **kwargs):
            timeout, budget = _settings_of(args[0]) if args else (None, None)
            with stage(what, timeout=symbolic_timeout if symbolic_timeout is not None else timeout,
                       budget=symbolic_budget if symbolic_budget is not None else budget):
                return fn(*args, **kwargs)

        run.__doc__ = (fn.__doc__ or "").rstrip() + (
            "\n\n    Bounded (:mod:`lagrange.limits`): ``symbolic_timeout`` CPU seconds and ``symbolic_budget`` nodes "
            "per derived expression\n    (keyword arguments; default the system's settings, else "
            "``$LAGRANGE_SYMBOLIC_TIMEOUT`` / ``$LAGRANGE_SYMBOLIC_BUDGET``).\n")
        return run

    return decorate
