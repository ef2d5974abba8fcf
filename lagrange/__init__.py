"""lagrange — derive Lagrange's equations symbolically (the way D. A. Wells does) and solve them fast.

Public API (explicit re-exports only). Conventions: :mod:`lagrange.conventions`.
"""

from .analysis.driving import actuator_forces, driving_forces, static_equilibrium
from .analysis.hamilton import hamiltonian
from .analysis.small_oscillations import characteristic_roots, equilibria, linearize, normal_modes
from .analysis.steady_motion import oscillations_about_steady_motion, routhian, steady_motion_conditions
from .analysis.variational import action, euler_lagrange, variational_integrate
from .conventions import t
from .errors import (
    BackendError,
    CollisionError,
    DeclarationError,
    InconsistentConstraintError,
    InitialConditionError,
    IntegrationError,
    LagrangeError,
    ParameterError,
    SingularMassMatrixError,
    SpecError,
    SymbolicTimeoutError,
)
from .gauss.check import GaussCheck, check_gauss
from .model.bodies import Force, MaterialPoint, Particle
from .model.constraints import Differential, Holonomic, IntegrableConstraintWarning, Nonholonomic, Rough
from .model.coordinates import coordinates, delta, parameters
from .model.eliminate import eliminate
from .model.inertia import Inertia
from .model.rigid_body import RigidBody, Torque
from .model.rotations import EulerAngles, Quaternion, rot_x, rot_y, rot_z
from .model.system import System
from .printing import latex, pretty
from .sweep import sweep

__version__ = "0.1.0"

__all__ = [
    "t",
    "coordinates",
    "parameters",
    "delta",
    "System",
    "Particle",
    "Force",
    "RigidBody",
    "Torque",
    "MaterialPoint",
    "Inertia",
    "EulerAngles",
    "Quaternion",
    "rot_x",
    "rot_y",
    "rot_z",
    "Holonomic",
    "Nonholonomic",
    "Differential",
    "Rough",
    "IntegrableConstraintWarning",
    "eliminate",
    "latex",
    "equilibria",
    "linearize",
    "normal_modes",
    "characteristic_roots",
    "routhian",
    "steady_motion_conditions",
    "oscillations_about_steady_motion",
    "driving_forces",
    "actuator_forces",
    "static_equilibrium",
    "hamiltonian",
    "euler_lagrange",
    "action",
    "variational_integrate",
    "sweep",
    "pretty",
    "LagrangeError",
    "DeclarationError",
    "ParameterError",
    "InitialConditionError",
    "SingularMassMatrixError",
    "IntegrationError",
    "SpecError",
    "SymbolicTimeoutError",
    "BackendError",
    "InconsistentConstraintError",
    "CollisionError",
    "check_gauss",
    "GaussCheck",
    "__version__",
]
