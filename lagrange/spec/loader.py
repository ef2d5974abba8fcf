"""Load a SPEC for the CLI: a problem id, a Python file (code, trusted) or a TOML file (data, safe).

TOML spec format
----------------
.. code-block:: toml

    name = "spring pendulum"
    coordinates = ["r", "theta"]
    parameters = ["m", "g", "k", "r0", "b"]
    V = "-m*g*r*cos(theta) + k/2*(r - r0)**2"
    P = "-b/2*r_dot**2"                       # Wells' power function (optional)
    # T = "..."                                # or particles below (or both: they add)
    [[particles]]
    mass = "m"
    position = ["r*sin(theta)", "-r*cos(theta)"]
    [forces]                                    # generalized forces by coordinate (optional)
    theta = "0"
    [params]
    m = 1.0
    [initial]
    r = 1.2
    theta = 0.5
    r_dot = 0
    theta_dot = 0
    [simulate]
    t_end = 10

Velocities are written ``<coordinate>_dot``. Expressions go through
:func:`lagrange.spec.expressions.parse_expression`: a TOML spec never executes code.

A Python spec is a file that defines ``system`` (a :class:`~lagrange.System`) and optionally
``params``, ``initial`` and ``t_end`` — or ``PROBLEM``. **It is executed as Python code**: load only
files you trust.
"""

from __future__ import annotations

import runpy
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from ..conventions import VELOCITY_SUFFIX, t
from ..errors import LagrangeError, SpecError
from ..model.bodies import Particle
from ..model.coordinates import coordinates as make_coordinates
from ..model.coordinates import parameters as make_parameters
from ..model.system import System
from .expressions import parse_expression

__all__ = ["LoadedSpec", "load_spec", "load_toml"]

_TOML_KEYS = {"name", "description", "coordinates", "parameters", "T", "V", "P", "rayleigh", "forces",
              "particles", "params", "initial", "simulate"}


@dataclass(frozen=True)
class LoadedSpec:
    system: System
    params: dict = field(default_factory=dict)
    initial: dict = field(default_factory=dict)
    t_end: float | None = None
    options: dict = field(default_factory=dict)
    label: str = ""
    problem: object | None = None


def load_toml(path: Path) -> LoadedSpec:
    try:
        data = tomllib.loads(path.read_text())
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise SpecError(f"{path}: not valid TOML: {exc}") from None
    unknown = sorted(set(data) - _TOML_KEYS)
    if unknown:
        raise SpecError(f"{path}: unknown key(s) {', '.join(unknown)} (allowed: {', '.join(sorted(_TOML_KEYS))})")
    coord_names = data.get("coordinates")
    if not coord_names or not isinstance(coord_names, list) or not all(isinstance(c, str) for c in coord_names):
        raise SpecError(f"{path}: 'coordinates' must be a non-empty list of names")
    for nm in coord_names + list(data.get("parameters", [])):
        if not isinstance(nm, str) or not nm.isidentifier() or nm.startswith("_"):
            raise SpecError(f"{path}: {nm!r} is not a valid coordinate or parameter name")
    coords = make_coordinates(coord_names)
    coords = coords if isinstance(coords, tuple) else (coords,)
    pnames = data.get("parameters", [])
    params = make_parameters(pnames) if pnames else ()
    params = params if isinstance(params, tuple) else (params,)
    names = {"t": t}
    for q in coords:
        names[q.func.__name__] = q
        names[q.func.__name__ + VELOCITY_SUFFIX] = q.diff(t)
    for p in params:
        if p.name in names:
            raise SpecError(f"{path}: parameter {p.name!r} clashes with a coordinate or velocity name")
        names[p.name] = p

    def expr(key, value):
        return parse_expression(value, names, where=f"{path.name}: {key}")

    particles = []
    for i, part in enumerate(data.get("particles", [])):
        if not isinstance(part, dict) or "mass" not in part or "position" not in part:
            raise SpecError(f"{path}: particles[{i}] needs 'mass' and 'position'")
        pos = [expr(f"particles[{i}].position", c) for c in part["position"]]
        particles.append(Particle(expr(f"particles[{i}].mass", part["mass"]), pos, name=part.get("name", "")))
    forces = None
    if "forces" in data:
        if not isinstance(data["forces"], dict):
            raise SpecError(f"{path}: [forces] must map coordinate names to expressions")
        forces = {k: expr(f"forces.{k}", v) for k, v in data["forces"].items()}
    kwargs = {}
    for key in ("T", "V", "P", "rayleigh"):
        if key in data:
            kwargs[key] = expr(key, data[key])
    try:
        system = System(list(coords), bodies=particles, forces=forces, name=data.get("name", path.stem),
                        parameters=list(params), description=data.get("description", ""), **kwargs)
    except LagrangeError as exc:
        raise SpecError(f"{path}: {exc}") from None
    sim = data.get("simulate", {})
    return LoadedSpec(system, dict(data.get("params", {})), dict(data.get("initial", {})),
                      sim.get("t_end"), {k: v for k, v in sim.items() if k != "t_end"}, str(path))


def _load_python(path: Path) -> LoadedSpec:
    try:
        ns = runpy.run_path(str(path))
    except LagrangeError as exc:
        raise SpecError(f"{path}: {exc}") from None
    except Exception as exc:  # noqa: BLE001 - report any failure of user code as one line
        raise SpecError(f"{path}: running the file failed: {type(exc).__name__}: {exc}") from None
    if "PROBLEM" in ns and "system" not in ns:
        return _from_problem(ns["PROBLEM"])
    system = ns.get("system")
    if not isinstance(system, System):
        raise SpecError(f"{path}: a Python spec must define `system = lagrange.System(...)`")
    return LoadedSpec(system, dict(ns.get("params", {})), dict(ns.get("initial", {})), ns.get("t_end"),
                      dict(ns.get("options", {})), str(path))


def _from_problem(problem) -> LoadedSpec:
    sim = problem.simulation
    if problem.system is None:
        return LoadedSpec(None, label=problem.id, problem=problem)  # type: ignore[arg-type]
    if sim is None:
        return LoadedSpec(problem.system, label=problem.id, problem=problem)
    return LoadedSpec(problem.system, dict(sim.params), dict(sim.initial), sim.t_end, dict(sim.options),
                      problem.id, problem)


def load_spec(spec: str) -> LoadedSpec:
    """Resolve ``spec``: an existing ``.toml``/``.py`` file, else a problem id of the corpus."""
    path = Path(spec)
    if path.suffix.lower() in (".toml", ".py"):
        if not path.is_file():
            raise SpecError(f"spec file {spec!r} does not exist")
        return load_toml(path) if path.suffix.lower() == ".toml" else _load_python(path)
    if spec.lower().startswith("greenspan-"):
        return _greenspan(spec)
    from ..corpus.registry import get_problem

    return _from_problem(get_problem(spec))


def _greenspan(spec: str) -> LoadedSpec:
    """``greenspan-N``: the rigid model of Greenspan's example N (the molecular model: ``--model``)."""
    from ..discrete import greenspan as gs

    try:
        ex = gs.EXAMPLES[int(spec.split("-", 1)[1])]
    except (ValueError, KeyError):
        raise SpecError(f"{spec!r}: Greenspan's examples are greenspan-1 … greenspan-14") from None
    system, coords = gs.rigid_system(ex.masses)
    return LoadedSpec(system, {"g": gs.G}, gs.rigid_initial(ex, coords), 110.0, {}, f"greenspan-{ex.number}",
                      problem=ex)
