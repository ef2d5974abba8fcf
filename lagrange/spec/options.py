"""Run options from a spec and the command line: the spec gives defaults, explicit flags override them.

Used by ``lagrange simulate`` and ``lagrange sweep`` for every kind of spec (TOML, Python, corpus problem,
``greenspan-N``). :func:`merge_run_options` validates the merged options completely before anything is
compiled: the method (case-insensitive, one of :data:`~lagrange.integrate.methods.ALL_METHODS`), ``step``
(required by the fixed-step methods, refused by the adaptive ones), the tolerances (refused by the
fixed-step methods) and the types of the numbers. :func:`check_names` refuses ``--param``/``--initial``
names the system does not have, listing the valid ones. Both raise :class:`~lagrange.errors.SpecError`
naming the option and where it came from (``--method`` or ``[simulate] method`` of the spec).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from ..errors import SpecError
from ..integrate.methods import ALL_METHODS, FIXED_STEP, canonical_method

__all__ = ["merge_run_options", "check_names", "parse_assignments", "RUN_FLAGS"]

#: options a command-line flag can set (``--max-step`` is not a flag; a spec may set it)
RUN_FLAGS = ("method", "step", "rtol", "atol", "backend", "friction")
_POSITIVE = ("step", "rtol", "atol", "max_step", "friction_epsilon")
_TOLERANCES = ("rtol", "atol", "max_step")


def parse_assignments(items: Iterable[str] | None, flag: str) -> dict[str, float]:
    """``["m=1.5", "theta=0.2"]`` → ``{"m": 1.5, "theta": 0.2}``; a SpecError names a malformed item."""
    out: dict[str, float] = {}
    for item in items or []:
        if "=" not in item:
            raise SpecError(f"--{flag} expects name=value, got {item!r}")
        key, value = (part.strip() for part in item.split("=", 1))
        if not key:
            raise SpecError(f"--{flag} {item!r}: the name is empty")
        try:
            number = float(value)
        except ValueError:
            raise SpecError(f"--{flag} {key}: {value!r} is not a number") from None
        if not math.isfinite(number):
            raise SpecError(f"--{flag} {key}: {value!r} is not a finite number")
        if key in out:
            raise SpecError(f"--{flag} {key} is given twice")
        out[key] = number
    return out


def check_names(given: Mapping[str, float], valid: Iterable[str], flag: str, label: str) -> None:
    """Refuse names in ``given`` that are not in ``valid`` (listing the valid names)."""
    valid = list(valid)
    unknown = [k for k in given if k not in valid]
    if unknown:
        kind = "parameter" if flag == "param" else "coordinate or velocity"
        plural = "s" if len(unknown) > 1 else ""
        raise SpecError(f"--{flag} {', '.join(unknown)}: unknown {kind}{plural} of {label} "
                        f"(valid: {', '.join(valid) or 'none'})")


def _where(key: str, flags: Mapping, label: str) -> str:
    return f"--{key.replace('_', '-')}" if flags.get(key) is not None else f"{label}: [simulate] {key}"


def _check_keys_and_choices(options: dict, flags: Mapping, label: str) -> None:
    """Every key a keyword of simulate(); the options with a fixed set of values take one of them."""
    import inspect

    from ..codegen.numeric import BACKENDS
    from ..integrate.compiled import LOOPS
    from ..integrate.constrained import STABILIZATIONS
    from ..integrate.run import simulate

    allowed = [name for name, par in inspect.signature(simulate).parameters.items()
               if par.kind is inspect.Parameter.KEYWORD_ONLY]
    unknown = sorted(set(options) - set(allowed))
    if unknown:
        raise SpecError(f"{label}: unknown simulate option(s) {', '.join(unknown)} (allowed: {', '.join(allowed)})")
    choices = {"backend": BACKENDS, "friction": ("events", "regularize"), "stabilization": STABILIZATIONS,
               "loop": LOOPS}
    for key, values in choices.items():
        if key in options and not hasattr(options[key], "__dataclass_fields__") and options[key] not in values:
            raise SpecError(f"{_where(key, flags, label)}: {options[key]!r} is not one of {', '.join(values)}")


def merge_run_options(spec_options: Mapping, flags: Mapping, label: str) -> dict:
    """The options of the run: ``spec_options`` overridden by every flag that is not None, validated.

    Parameters
    ----------
    spec_options : the spec's options (``[simulate]`` of a TOML file, ``options`` of a Python spec, a
        problem's ``Simulation.options``)
    flags : ``{name: value or None}`` for the names of :data:`RUN_FLAGS` (None: not given)
    label : the spec, for messages

    Returns
    -------
    dict
        Keyword options for :func:`~lagrange.integrate.run.simulate`, with ``method`` spelt as simulate
        expects (``DOP853`` when neither gives one) and ``step`` only for a fixed-step method.

    Raises
    ------
    SpecError
        An unknown method; a fixed-step method without ``step`` or with ``rtol``/``atol``/``max_step``;
        ``step`` with an adaptive method; a tolerance or step that is not a positive finite number. When
        ``--method`` switches between kinds, the spec's options of the other kind (its ``rtol`` for an
        adaptive method, its ``step`` for a fixed-step one) no longer apply and are dropped; the same
        contradiction within the spec alone, or within the flags alone, is refused.

    Examples
    --------
    >>> merge_run_options({"method": "LSODA", "rtol": 1e-4}, {"method": None, "rtol": None}, "s.toml")
    {'method': 'LSODA', 'rtol': 0.0001}
    >>> merge_run_options({"method": "LSODA", "rtol": 1e-4}, {"method": "gl4", "step": 0.01}, "s.toml")
    {'method': 'gl4', 'step': 0.01}
    """
    options = dict(spec_options)
    options.update({k: v for k, v in flags.items() if v is not None})
    _check_keys_and_choices(options, flags, label)
    raw = options.get("method", "DOP853")
    method = canonical_method(raw)
    if method is None:
        raise SpecError(f"{_where('method', flags, label)}: unknown method {raw!r}; choose one of "
                        f"{', '.join(ALL_METHODS)} (case-insensitive)")
    options["method"] = method
    for key in _POSITIVE:
        if key in options:
            value = options[key]
            if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) \
                    or value <= 0:
                raise SpecError(f"{_where(key, flags, label)}: must be a positive number, got {value!r}")
    method_flag = flags.get("method") is not None
    if method in FIXED_STEP:
        if method_flag:  # the spec's tolerances were for its own (adaptive) method: they no longer apply
            for key in _TOLERANCES:
                if flags.get(key) is None:
                    options.pop(key, None)
        if options.get("step") is None:
            raise SpecError(f"{label}: method {method} takes a fixed step: give --step H (or step = H in "
                            "[simulate])")
        given = [k for k in _TOLERANCES if k in options]
        if given:
            raise SpecError(f"{_where(given[0], flags, label)}: method {method} takes a fixed step and no "
                            f"tolerances; drop {', '.join(given)} or use an adaptive method")
    elif options.get("step") is not None and (flags.get("step") is not None or not method_flag):
        raise SpecError(f"{_where('step', flags, label)}: a step applies to the fixed-step methods "
                        f"({', '.join(FIXED_STEP)}); {method} is adaptive: set --rtol/--atol instead")
    else:
        options.pop("step", None)
    return _as_objects(options, flags, label)


def _as_objects(options: dict, flags: Mapping, label: str) -> dict:
    """The spec's flat friction and stabilization values as option objects
    (:class:`~lagrange.integrate.options.FrictionOptions`, :class:`~lagrange.integrate.options.Stabilization`),
    every value validated: a SpecError names the ``[simulate]`` key (or flag) and the limit."""
    from ..errors import MethodError, OptionError
    from ..integrate.options import MAX_POINTS, MAX_STEPS, FrictionOptions, Stabilization

    def refuse(key: str, exc: Exception):
        return SpecError(f"{_where(key, flags, label)}: {exc}")

    if "n_points" in options:
        n = options["n_points"]
        if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= MAX_POINTS:
            raise SpecError(f"{_where('n_points', flags, label)}: must be an integer between 2 and {MAX_POINTS:,}, "
                            f"got {n!r}")
    for key, limit in (("max_steps", MAX_STEPS), ("max_output_bytes", 2**62)):
        v = options.get(key, 1)
        if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= limit:
            raise SpecError(f"{_where(key, flags, label)}: must be an integer between 1 and {limit:.0e}, got {v!r}")
    if "friction_epsilon" in options or "friction" in options:
        try:
            options["friction"] = FrictionOptions(options.get("friction", "events"),
                                                  options.pop("friction_epsilon", 1e-6))
        except (OptionError, MethodError) as exc:
            raise refuse("friction", exc) from None
    keys = ("stabilization", "baumgarte", "project_initial")
    if any(k in options for k in keys):
        gains = options.pop("baumgarte", (10.0, 10.0))
        if not isinstance(gains, list | tuple) or len(gains) != 2:
            raise SpecError(f"{_where('baumgarte', flags, label)}: must be a pair [alpha, beta], got {gains!r}")
        try:
            options["stabilization"] = Stabilization(options.get("stabilization", "projection"), *gains,
                                                     project_initial=options.pop("project_initial", True))
        except (OptionError, MethodError) as exc:
            raise refuse("stabilization", exc) from None
    return options
