"""lagrange — derive Lagrange's equations symbolically (the way D. A. Wells does) and solve them fast.

Public API (explicit re-exports only). Conventions: :mod:`lagrange.conventions`.

The names are imported lazily (PEP 562): ``import lagrange`` loads no sympy, scipy, numba or matplotlib
until a name is used, so the ``lagrange`` command answers ``--help`` and ``problems`` at once.
``from lagrange import System`` and ``lagrange.System`` work as usual. To export a new name, add one
line ``"name": ".submodule"`` to :data:`_EXPORTS` and the name to ``__all__``.
"""

from __future__ import annotations

import sys
import types

from ._lazy import lazy_exports

__version__ = "0.1.0"

#: public name -> the submodule (relative to this package) that defines it; imported on first use.
#: One line per name, grouped by submodule, in the order of the old ``from .x import y`` lines.
_EXPORTS: dict[str, str] = {
    "actuator_forces": ".analysis.driving",
    "driving_forces": ".analysis.driving",
    "static_equilibrium": ".analysis.driving",
    "hamiltonian": ".analysis.hamilton",
    "characteristic_roots": ".analysis.small_oscillations",
    "equilibria": ".analysis.small_oscillations",
    "linearize": ".analysis.small_oscillations",
    "normal_modes": ".analysis.small_oscillations",
    "oscillations_about_steady_motion": ".analysis.steady_motion",
    "routhian": ".analysis.steady_motion",
    "steady_motion_conditions": ".analysis.steady_motion",
    "action": ".analysis.variational",
    "euler_lagrange": ".analysis.variational",
    "variational_integrate": ".analysis.variational",
    "is_conservative": ".analysis.conservative",
    "potential_of": ".analysis.conservative",
    "work_along": ".analysis.conservative",
    "expand_potential": ".analysis.series",
    "t": ".conventions",
    "BackendError": ".errors",
    "CollisionError": ".errors",
    "DeclarationError": ".errors",
    "InconsistentConstraintError": ".errors",
    "InitialConditionError": ".errors",
    "IntegrationError": ".errors",
    "IntegrationInterrupted": ".errors",
    "LagrangeError": ".errors",
    "ParameterError": ".errors",
    "SingularMassMatrixError": ".errors",
    "SpecError": ".errors",
    "SymbolicTimeoutError": ".errors",
    "ExpressionTooLarge": ".errors",
    "GaussCheck": ".gauss.check",
    "check_gauss": ".gauss.check",
    "Force": ".model.bodies",
    "Particle": ".model.bodies",
    "MaterialPoint": ".model.bodies",
    "Differential": ".model.constraints",
    "Holonomic": ".model.constraints",
    "IntegrableConstraintWarning": ".model.constraints",
    "Nonholonomic": ".model.constraints",
    "Rough": ".model.constraints",
    "coordinates": ".model.coordinates",
    "delta": ".model.coordinates",
    "parameters": ".model.coordinates",
    "eliminate": ".model.eliminate",
    "Inertia": ".model.inertia",
    "RigidBody": ".model.rigid_body",
    "Torque": ".model.rigid_body",
    "EulerAngles": ".model.rotations",
    "Quaternion": ".model.rotations",
    "RotationSequence": ".model.rotations",
    "rot_x": ".model.rotations",
    "rot_y": ".model.rotations",
    "rot_z": ".model.rotations",
    "System": ".model.system",
    "latex": ".printing",
    "pretty": ".printing",
    "sweep": ".sweep",
    "support_loads": ".derive.euler",
    "AnalysisError": ".errors",
    "InputError": ".errors",
    "LagrangeWarning": ".errors",
    "UnusedParameterWarning": ".errors",
    "ConventionChangeWarning": ".errors",

    "NonAnalyticWarning": ".errors",
    "InitialStateChangedWarning": ".errors",
    "CacheError": ".errors",
    "CacheIntegrityWarning": ".errors",
    "MethodError": ".errors",
    "OptionError": ".errors",
    "FrictionOptions": ".integrate.options",
    "Stabilization": ".integrate.options",
    "StepOptions": ".integrate.options",
    "from_mechanics": ".interop.mechanics",
    "to_functions": ".model.coordinates",
    "to_symbols": ".model.coordinates",
    "unknowns": ".model.coordinates",
    "EarthFrame": ".model.frames",
    "Ellipsoid": ".model.frames",
    "WELLS_1924": ".model.frames",
    "apparent_gravity": ".model.frames",
    "Frame": ".model.frames",
    "inputs": ".model.inputs",
    "PlanarBody": ".model.planar",
    "revolute": ".model.joints",
    "slider": ".model.joints",
    "pin": ".model.joints",
    "on_line": ".model.joints",
    "spherical": ".model.joints",
    "spring_potential": ".model.joints",
    "damper_power": ".model.joints",
}



class _Package(types.ModuleType):
    """Keeps an exported name that is also a subpackage (``sweep``) bound to the exported function:
    importing ``lagrange.sweep.table`` first would otherwise rebind ``lagrange.sweep`` to the module."""

    def __setattr__(self, name: str, value) -> None:
        if (isinstance(value, types.ModuleType) and name in _EXPORTS
                and value.__name__ == f"{__name__}.{name}" and _EXPORTS[name] == f".{name}"):
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package

__all__ = [
    "t",
    "coordinates",
    "parameters",
    "inputs",
    "delta",
    "System",
    "Particle",
    "Force",
    "RigidBody",
    "Torque",
    "MaterialPoint",
    "PlanarBody",
    "revolute",
    "slider",
    "pin",
    "on_line",
    "spherical",
    "spring_potential",
    "damper_power",
    "Inertia",
    "EulerAngles",
    "Quaternion",
    "RotationSequence",
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
    "from_mechanics",
    "pretty",
    "LagrangeError",
    "DeclarationError",
    "ParameterError",
    "InitialConditionError",
    "SingularMassMatrixError",
    "IntegrationError",
    "InputError",
    "SpecError",
    "SymbolicTimeoutError",
    "ExpressionTooLarge",
    "AnalysisError",
    "BackendError",
    "InconsistentConstraintError",
    "CollisionError",
    "MethodError",
    "OptionError",
    "FrictionOptions",
    "Stabilization",
    "StepOptions",
    "check_gauss",
    "GaussCheck",
    "__version__",
    "unknowns",
    "to_symbols",
    "to_functions",
    "Frame",
    "EarthFrame",
    "support_loads",
    "LagrangeWarning",
    "UnusedParameterWarning",
    "ConventionChangeWarning",

    "NonAnalyticWarning",
    "InitialStateChangedWarning",
    "CacheError",
    "CacheIntegrityWarning",
    "is_conservative",
    "potential_of",
    "work_along",
    "expand_potential",
    "Ellipsoid",
    "WELLS_1924",
    "apparent_gravity",
]

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS, __all__)
