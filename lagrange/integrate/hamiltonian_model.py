"""Moved to :mod:`lagrange.codegen.hamiltonian_model` (code generation produces the Hamiltonian pieces; a model
reaches them with :meth:`NumericModel.hamiltonian <lagrange.codegen.numeric.NumericModel.hamiltonian>`).

This name forwards there for one release, with a DeprecationWarning; it imports nothing itself (the rule of
:mod:`lagrange.integrate`).
"""

from __future__ import annotations

import importlib
import warnings

_MOVED = ("HamiltonianModel", "hamiltonian_model", "generated_source", "compiled_module")


def __getattr__(name: str):
    if name in _MOVED:
        warnings.warn(f"lagrange.integrate.hamiltonian_model.{name} moved to lagrange.codegen.hamiltonian_model",
                      DeprecationWarning, stacklevel=2)
        return getattr(importlib.import_module("lagrange.codegen.hamiltonian_model"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
