"""Exceptions raised by :mod:`lagrange`.

Every exception subclasses :class:`LagrangeError` and the matching builtin, and its message names the
object at fault, the rule broken and how to fix it. Declarations are validated completely and all
problems are reported at once.
"""

from __future__ import annotations

from collections.abc import Sequence


class LagrangeError(Exception):
    """Base class of every error raised on purpose by lagrange."""


class DeclarationError(LagrangeError, ValueError):
    """A declared system (coordinates, energies, forces, bodies) is invalid.

    ``problems`` lists every rule that was broken; the message joins them.
    """

    def __init__(self, problems: Sequence[str] | str, *, subject: str = "system"):
        if isinstance(problems, str):
            problems = [problems]
        self.problems = tuple(problems)
        if len(self.problems) == 1:
            msg = f"invalid {subject}: {self.problems[0]}"
        else:
            lines = "\n".join(f"  - {p}" for p in self.problems)
            msg = f"invalid {subject} ({len(self.problems)} problems):\n{lines}"
        super().__init__(msg)


class ParameterError(LagrangeError, ValueError):
    """Parameter values are missing, unknown or not finite numbers."""


class InitialConditionError(LagrangeError, ValueError):
    """Initial conditions are missing, unknown or not finite."""


class SingularMassMatrixError(LagrangeError, ValueError):
    """The mass matrix is singular (or numerically so) at a state; the message names the coordinates.

    Raised during a run it carries the same ``t``, ``state`` and ``partial`` as :class:`IntegrationError`
    (all None when raised before integration starts).
    """

    def __init__(self, message: str, *, t: float | None = None, state: dict | None = None, partial=None):
        self.t = t
        self.state = state
        self.partial = partial
        super().__init__(message)


class IntegrationError(LagrangeError, RuntimeError):
    """Numerical integration failed; the message gives the time, the state and the likely cause.

    ``t`` and ``state`` say where it stopped; ``partial`` is the
    :class:`~lagrange.results.trajectory.Trajectory` computed up to that time (None when nothing could be
    kept).
    """

    def __init__(self, message: str, *, t: float | None = None, state: dict | None = None, partial=None):
        self.t = t
        self.state = state
        self.partial = partial
        super().__init__(message)


class SpecError(LagrangeError, ValueError):
    """A spec (problem id, Python file or TOML file) cannot be loaded."""


class BackendError(LagrangeError, RuntimeError):
    """A code-generation backend is unavailable or failed."""


class InconsistentConstraintError(LagrangeError, ValueError):
    """Constraints contradict each other at the acceleration level (a jammed mechanism, Sonneveld
    Lemma 7(ii)): no acceleration satisfies them all. ``constraints`` names the ones involved."""

    def __init__(self, message: str, *, constraints: Sequence[str] = ()):
        self.constraints = tuple(constraints)
        super().__init__(message)


class CollisionError(LagrangeError, ValueError):
    """A collision cannot happen as posed (bodies not approaching, restitution outside [0, 1]) or its
    outcome would create kinetic energy."""



class SweepError(LagrangeError, ValueError):
    """A sweep is misdeclared (unknown quantity, bad range, unpicklable task, existing store) or an optional
    dependency of sweeps is missing (the message names the extra to install)."""


class LagrangeWarning(UserWarning):
    """Base class of the warnings lagrange issues on purpose."""


class UnusedParameterWarning(LagrangeWarning):
    """Values were given for declared parameters that cancel out of the equations of motion (they are
    ignored; the warning names them)."""


class ConventionChangeWarning(LagrangeWarning, FutureWarning):
    """A call relies on a default whose convention changed (its numbers would differ under the new one): the
    call keeps the old convention for a deprecation period, and the message names the change and the call that
    states the convention explicitly. A :class:`FutureWarning`, so it is shown by default."""


class InputError(LagrangeError, TypeError):
    """A time-varying input cannot be used as given: a callable with a signature other than ``u(t)`` or
    ``u(t, y)``, or a route that cannot evaluate Python per step (the compiled loops, the Taylor tape, the
    geometric integrators) asked to run a callable or sampled input (the message names the routes that can)."""


class SymbolicTimeoutError(LagrangeError, TimeoutError):
    """A sympy computation (solve, simplify) ran out of time in every attempt (:mod:`lagrange.simplification`,
    ``$LAGRANGE_SYMPY_SECONDS`` per attempt), or a symbolic stage (a derivation, an analysis) passed its CPU-time
    deadline (:mod:`lagrange.limits`: ``symbolic_timeout=`` or ``$LAGRANGE_SYMBOLIC_TIMEOUT``)."""


__all__ = [
    "LagrangeError",
    "DeclarationError",
    "ParameterError",
    "InputError",
    "InitialConditionError",
    "SingularMassMatrixError",
    "IntegrationError",
    "SpecError",
    "BackendError",
    "SweepError",
    "InconsistentConstraintError",
    "CollisionError",
    "SymbolicTimeoutError",
    "LagrangeWarning",
    "UnusedParameterWarning",
    "ConventionChangeWarning",
    "MethodError",
    "OptionError",
]


class AnalysisError(LagrangeError, ValueError):
    """An analysis (linearization, equilibria, steady motion, Hamilton's equations) cannot be done for this
    system or reference state: the message names the unsupported combination, or the residual of a reference
    state that is off the constraint manifold or not an equilibrium."""


__all__ += ["AnalysisError"]


class CacheError(LagrangeError, PermissionError):
    """The cache directory cannot be trusted: owned by another user, writable by group or others, or its
    secret readable by others (the message names the path and the fix; ``LAGRANGE_CACHE_TRUST=1`` is the
    explicit opt-out, see :mod:`lagrange.codegen.cache`)."""


class CacheIntegrityWarning(LagrangeWarning):
    """A cache entry failed authentication (planted, copied under another name, edited or damaged): it was
    ignored and rebuilt, never loaded. Issued once per process."""


__all__ += ["CacheError", "CacheIntegrityWarning"]


class IntegrationInterrupted(KeyboardInterrupt):
    """A run stopped by Ctrl-C (SIGINT): every integration loop raises it within about a second of the signal.

    It is a :class:`KeyboardInterrupt` (and deliberately *not* a :class:`LagrangeError`): ``except Exception``
    and ``except LagrangeError`` handlers, a sweep's per-run error capture among them, must not swallow a
    user's Ctrl-C. Like :class:`IntegrationError` it carries ``t`` and ``state`` (where the run was when it
    stopped) and ``partial``, the :class:`~lagrange.results.trajectory.Trajectory` computed up to there
    (``success=False``; None when nothing could be kept). Catching it as ``KeyboardInterrupt`` is enough.
    """

    def __init__(self, message: str, *, t: float | None = None, state: dict | None = None, partial=None):
        self.t = t
        self.state = state
        self.partial = partial
        super().__init__(message)


__all__ += ["IntegrationInterrupted"]


class MethodError(LagrangeError, TypeError):
    """An integration method (or loop, friction or stabilization treatment) that does not exist, or that does
    not support what the run asks for (events, constraints, friction switches, inputs, ...): the message names
    the method, the unsupported combination and the methods that do support it
    (:mod:`lagrange.integrate.registry`)."""


class OptionError(LagrangeError, ValueError):
    """A value of a simulate option (or of a spec's ``[simulate]`` table) is out of range: the message names
    the option, the value and the limit (:mod:`lagrange.integrate.options`)."""


class ExpressionTooLarge(LagrangeError, ValueError):
    """A symbolic stage (declaration, expansion, differentiation, tidy-up, zero test, CSE, printing,
    simplification) would exceed its size budget (:mod:`lagrange.budget`): the expression would multiply out
    to too many terms, carries an exponent or a tower of exponentials beyond the limits, or has too many
    nodes. ``stage`` names the stage, ``expression`` is the expression abbreviated; the message says which
    limit was exceeded and by how much."""

    def __init__(self, message: str, *, stage: str = "", expression: str = ""):
        self.stage = stage
        self.expression = expression
        super().__init__(message)


__all__ += ["ExpressionTooLarge"]


class NonAnalyticWarning(LagrangeWarning):
    """A Taylor-series method (``method="taylor"`` or ``"heyoka"``) was asked to run equations that are not
    analytic, or nearly not (a kink, a regularization with a small parameter): its step control can step across
    the layer and return a wrong answer. The message names the expression and suggests DOP853 or Radau
    (:mod:`lagrange.codegen.analyticity`)."""


__all__ += ["NonAnalyticWarning"]


class AccuracyWarning(LagrangeWarning):
    """A run reached its end but failed one of its own accuracy checks (power balance, constraint drift, the
    fixed-step error estimate, the Taylor method's local error; see
    :mod:`lagrange.results.verdict`): the message names the check, the number, the limit and what to try. The
    trajectory's ``success`` is False and its ``verdict`` holds every check."""


__all__ += ["AccuracyWarning"]


class ExpressionTypeError(LagrangeError, TypeError):
    """A value given where an expression is expected is neither a number, a sympy object, a container of
    them nor a string of numbers (:mod:`lagrange.safe_sympify`): it is refused, never converted through its
    text (sympy's own fallback parses ``str(value)``, which is ``eval``)."""


__all__ += ["ExpressionTypeError", "shown"]


def shown(value, limit: int = 80) -> str:
    """``repr(value)`` for an error message, cut to about ``limit`` characters; never raises (the repr of an
    integer of more than 4,300 digits does: then its size is given)."""
    try:
        text = repr(value)
    except ValueError:
        text = f"<an integer of {value.bit_length() * 0.30103:.0f} digits>" if isinstance(value, int) else \
            f"<a {type(value).__name__}>"
    return text if len(text) <= limit else text[: limit - 5] + " ...>"


class InitialStateChangedWarning(LagrangeWarning):
    """A value the user gave in the initial state was changed to satisfy the constraints (an inconsistent
    state projected onto them): the message names each changed value (given → used) and the violated
    constraints; the trajectory records them (``Trajectory.initial_adjustments``)."""


__all__ += ["InitialStateChangedWarning"]
