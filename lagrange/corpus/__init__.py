"""The verified problem corpus: problems with the book's answers and the checks that compare them."""

from .answers import (
    Answer,
    ConservedMomenta,
    ConstraintForce,
    EnergySplit,
    EquationsOfMotion,
    GeneralizedForces,
    JacobiIntegral,
    KineticEnergy,
    MassMatrix,
    PotentialEnergy,
    PowerFunction,
    Quantity,
    TrajectoryValues,
)
from .compare import Mismatch
from .problem import CheckResult, LazySystem, Problem, Simulation
from .registry import all_problems, get_problem, problem_ids

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
