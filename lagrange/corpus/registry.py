"""Discovery of the problem corpus (the ``problems/`` folder, installed as ``lagrange_problems``).

Each module of the corpus defines ``PROBLEM`` (one :class:`~lagrange.corpus.Problem`) or ``PROBLEMS``
(a list, for variants of one book problem).
"""

from __future__ import annotations

import importlib
import pkgutil
from functools import lru_cache

from ..errors import SpecError
from .modules import PACKAGE, _module_problems, _sort_key
from .problem import Problem

__all__ = ["all_problems", "get_problem", "problem_ids", "PACKAGE"]



def _module_names() -> list[str]:
    try:
        pkg = importlib.import_module(PACKAGE)
    except ImportError as exc:  # pragma: no cover - broken installation
        raise SpecError(f"the problem corpus ({PACKAGE}) is not installed: reinstall lagrange") from exc
    return [info.name for info in pkgutil.iter_modules(pkg.__path__) if not info.name.startswith("_")]


@lru_cache(maxsize=1)
def all_problems() -> tuple[Problem, ...]:
    """Every problem of the corpus, by chapter and number."""
    found: dict[str, Problem] = {}
    for name in _module_names():
        for p in _module_problems(name):
            if p.id in found:
                raise SpecError(f"problem id {p.id!r} is defined twice (in {name})")
            found[p.id] = p
    return tuple(sorted(found.values(), key=_sort_key))


def problem_ids() -> list[str]:
    """Every problem id, in corpus order."""
    return [p.id for p in all_problems()]


def get_problem(problem_id: str) -> Problem:
    """The problem with this id (case-insensitive); a SpecError suggests close ids otherwise.

    Looks the id up in the corpus index (:mod:`lagrange.corpus.index`) and imports only its module; an id
    missing from a stale index (a module changed since it was written) is searched for by importing the
    whole corpus.
    """
    from . import index

    key = problem_id.strip().lower()
    entry = index.find(key)
    if entry is not None:
        for p in _module_problems(entry["module"]):
            if p.id.lower() == key:
                return p
    if index.stale_modules():  # a module changed since the index was written: look everywhere
        for p in all_problems():
            if p.id.lower() == key:
                return p
    close = index.suggestions(key)
    hint = f"; did you mean {', '.join(close)}?" if close else "; run `lagrange problems` for the list"
    raise SpecError(f"no problem with id {problem_id!r}{hint}")
