"""Loading one corpus module and ordering problems: shared by the registry and the index (its own module, so
that neither imports the other both ways)."""

from __future__ import annotations

import importlib
import re

from ..errors import SpecError
from .problem import Problem

__all__ = ["PACKAGE"]

PACKAGE = "lagrange_problems"


def _sort_key(p: Problem):
    nums = [int(x) for x in re.findall(r"\d+", p.id)]
    return (p.chapter, nums, p.id)


def _module_problems(name: str) -> list[Problem]:
    try:
        mod = importlib.import_module(f"{PACKAGE}.{name}")
    except Exception as exc:  # noqa: BLE001 - a broken corpus module is reported by name, in one line
        raise SpecError(f"corpus module {name} failed to load: {type(exc).__name__}: {exc}") from None
    probs = getattr(mod, "PROBLEMS", None) or [getattr(mod, "PROBLEM", None)]
    for p in probs:
        if not isinstance(p, Problem):
            raise SpecError(f"corpus module {name} defines no PROBLEM")
    return list(probs)
