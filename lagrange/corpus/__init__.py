"""The verified problem corpus: problems with the book's answers and the checks that compare them.

Names are imported lazily (PEP 562) so :mod:`lagrange.corpus.index` (what ``lagrange problems`` reads)
loads without sympy; one line ``"name": ".submodule"`` in :data:`_EXPORTS` per public name.
"""

from __future__ import annotations

from .._lazy import lazy_exports

#: public name -> the submodule that defines it (imported on first use)
_EXPORTS: dict[str, str] = {
    "Answer": ".answers",
    "ConservedMomenta": ".answers",
    "ConstraintForce": ".answers",
    "EnergySplit": ".answers",
    "EquationsOfMotion": ".answers",
    "GeneralizedForces": ".answers",
    "JacobiIntegral": ".answers",
    "KineticEnergy": ".answers",
    "MassMatrix": ".answers",
    "PotentialEnergy": ".answers",
    "PowerFunction": ".answers",
    "Quantity": ".answers",
    "TrajectoryValues": ".answers",
    "Mismatch": ".compare",
    "CheckResult": ".problem",
    "LazySystem": ".problem",
    "Problem": ".problem",
    "Simulation": ".problem",
    "all_problems": ".registry",
    "get_problem": ".registry",
    "problem_ids": ".registry",
}



__all__ = [
    "Answer",
    "ConservedMomenta",
    "ConstraintForce",
    "EnergySplit",
    "EquationsOfMotion",
    "GeneralizedForces",
    "JacobiIntegral",
    "KineticEnergy",
    "MassMatrix",
    "PotentialEnergy",
    "PowerFunction",
    "Quantity",
    "TrajectoryValues",
    "Mismatch",
    "CheckResult",
    "Problem",
    "LazySystem",
    "Simulation",
    "all_problems",
    "get_problem",
    "problem_ids",
]

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS, __all__)
