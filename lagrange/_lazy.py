"""Lazy re-exports (PEP 562) for a package's public names: the submodule is imported on first use.

Used by :mod:`lagrange` and :mod:`lagrange.corpus`, so that ``import lagrange`` (and the ``lagrange`` command's
``--help`` and ``problems``) load no sympy, scipy, numba or matplotlib until a name is used.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Mapping, Sequence


def lazy_exports(package: str, exports: Mapping[str, str], public: Sequence[str]) -> tuple[Callable, Callable]:
    """``(__getattr__, __dir__)`` for ``package``: ``exports`` maps a public name to the submodule (relative to
    the package) that defines it; the value is imported on first use and cached in the package's namespace."""

    def __getattr__(name: str):
        try:
            module = exports[name]
        except KeyError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
        value = getattr(importlib.import_module(module, package), name)
        setattr(sys.modules[package], name, value)
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(public))

    return __getattr__, __dir__
