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

A spec may declare time-varying inputs (:mod:`lagrange.model.inputs`) by name and give each a value — a
number or an expression of ``t`` and the parameters — in ``[inputs_values]`` (overridden by the CLI's
``--input NAME=VALUE``); an input without a value is refused when the system is simulated:

.. code-block:: toml

    inputs = ["F"]
    forces = {x = "F"}
    [inputs_values]
    F = "F0*cos(w*t)"

Velocities are written ``<coordinate>_dot``. Expressions go through
:func:`lagrange.spec.expressions.parse_expression`: a TOML spec never executes code. Every other value is
checked too: names must be ASCII identifiers that are not Python keywords and do not clash (a parameter
``x_dot`` next to a coordinate ``x``); ``[params]`` and ``[initial]`` take finite numbers or constant
expressions (``"pi/4"``) for declared names only; ``[simulate]`` takes ``t_end`` and the data options of
:func:`~lagrange.integrate.run.simulate`. Any violation is a :class:`~lagrange.errors.SpecError` naming the
file and the key.

A planar mechanism is declared by tables of bodies and joints, ``[[planar_bodies]]``, ``[[joints]]``,
``[[springs]]``, ``[[torques]]`` and ``[[point_forces]]`` (:mod:`lagrange.spec.planar`).

A Python spec is a file that defines ``system`` (a :class:`~lagrange.System`) and optionally
``params``, ``initial``, ``inputs`` (any value form of ``simulate``)
and ``t_end`` — or ``PROBLEM``. **It is executed as Python code**: load only
files you trust.
"""

from __future__ import annotations

import keyword
import math
import runpy
import stat
import tomllib
import unicodedata
from dataclasses import field
from pathlib import Path

from ..conventions import VELOCITY_SUFFIX, t
from ..errors import LagrangeError, SpecError
from ..model.bodies import Particle
from ..model.coordinates import coordinates as make_coordinates
from ..model.coordinates import parameters as make_parameters
from ..model.inputs import inputs as make_inputs
from ..model.system import System
from ..records import record
from .expressions import MAX_TERMS, parse_expression
from .planar import PLANAR_KEYS, planar_declaration

__all__ = ["LoadedSpec", "load_spec", "load_toml"]

_TOML_KEYS = {"name", "description", "coordinates", "parameters", "T", "V", "P", "rayleigh", "forces",
              "particles", "params", "initial", "simulate", "inputs", "inputs_values"} | PLANAR_KEYS
_PARTICLE_KEYS = {"mass", "position", "name"}
#: ``[simulate]`` keys: ``t_end`` and the keyword options of :func:`lagrange.integrate.run.simulate` that are data
_SIMULATE_KEYS = {"t_end", "method", "rtol", "atol", "n_points", "max_step", "backend", "friction",
                  "friction_epsilon", "stabilization", "baumgarte", "project_initial", "step", "loop", "max_steps",
                  "max_output_bytes"}
#: particle positions are squared in T, so they get a tighter limit on their multiplied-out size
_POSITION_TERMS = 100
MAX_SPEC_BYTES = 1_000_000
#: arrays and tables nest at most this deep in a spec (its deepest legitimate value, a list of particle
#: positions, is three levels down); deeper nesting is refused before anything walks it
MAX_SPEC_NESTING = 16


def _check_nesting(data, path: Path) -> None:
    """SpecError when arrays or tables in ``data`` nest deeper than :data:`MAX_SPEC_NESTING` (walked without
    recursion)."""
    todo = [(data, 0)]
    while todo:
        node, depth = todo.pop()
        if depth > MAX_SPEC_NESTING:
            raise SpecError(f"{path}: arrays or tables nested deeper than {MAX_SPEC_NESTING} levels; a spec "
                            "needs at most a few")
        if isinstance(node, dict):
            todo.extend((v, depth + 1) for v in node.values())
        elif isinstance(node, list):
            todo.extend((v, depth + 1) for v in node)


@record(frozen=True)
class LoadedSpec:
    system: System
    params: dict = field(default_factory=dict)
    initial: dict = field(default_factory=dict)
    t_end: float | None = None
    options: dict = field(default_factory=dict)
    label: str = ""
    problem: object | None = None
    inputs: dict = field(default_factory=dict)  # input name -> number or expression of t and the parameters


def _plain_text(text: str, key: str, path: Path, *, newlines: bool = False) -> None:
    """Refuse control and format characters (terminal escapes, carriage returns, bidirectional overrides) in
    a free-text value: the CLI prints names and descriptions, and a spec must not drive the terminal."""
    for i, ch in enumerate(text):
        if (ch == "\n" and newlines) or unicodedata.category(ch) not in ("Cc", "Cf", "Zl", "Zp", "Cs", "Co", "Cn"):
            continue
        raise SpecError(f"{path}: '{key}' contains the control character {ch.encode('unicode_escape').decode()} "
                        f"at position {i}: names and descriptions are plain text")


def _names_list(data: dict, key: str, path: Path, *, required: bool) -> list[str]:
    value = data.get(key, [])
    if required and not value:
        raise SpecError(f"{path}: '{key}' must be a non-empty list of names")
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise SpecError(f"{path}: '{key}' must be a list of name strings, got {value!r}")
    for nm in value:
        if not nm.isascii() or not nm.isidentifier() or nm.startswith("_"):
            raise SpecError(f"{path}: {nm!r} in '{key}' is not a valid name (ASCII letters, digits and _, "
                            "not starting with _ or a digit)")
        if keyword.iskeyword(nm):
            raise SpecError(f"{path}: {nm!r} in '{key}' is a Python keyword and cannot appear in expressions; "
                            f"rename it (e.g. {nm + '_'!r})")
    dups = sorted({nm for nm in value if value.count(nm) > 1})
    if dups:
        raise SpecError(f"{path}: {', '.join(dups)} listed more than once in '{key}'")
    return value


def _namespace(coord_names: list[str], param_names: list[str], path: Path,
               input_names: list[str] = ()) -> tuple[dict, tuple, tuple]:
    """The names an expression may use: t, each coordinate, its ``_dot`` velocity, the parameters and the
    inputs."""
    coords = make_coordinates(coord_names)
    coords = coords if isinstance(coords, tuple) else (coords,)
    params = make_parameters(param_names) if param_names else ()
    params = params if isinstance(params, tuple) else (params,)
    ins = make_inputs(list(input_names)) if input_names else ()
    ins = ins if isinstance(ins, tuple) else (ins,)
    names: dict = {"t": t}
    entries = [(q.func.__name__, q, "coordinate") for q in coords]
    entries += [(q.func.__name__ + VELOCITY_SUFFIX, q.diff(t), "velocity") for q in coords]
    entries += [(p.name, p, "parameter") for p in params]
    entries += [(u.name, u, "input") for u in ins]
    kinds = {"t": "time"}
    for nm, obj, kind in entries:
        if nm in names:
            raise SpecError(f"{path}: the {kind} name {nm!r} clashes with the {kinds[nm]} {nm!r}; rename one")
        names[nm], kinds[nm] = obj, kind
    return names, coords, params


def _number(value, where: str) -> float:
    """A finite real number from a TOML number or a constant expression string (``"pi/4"``)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise SpecError(f"{where}: expected a number, got {type(value).__name__} {value!r}")
    if isinstance(value, str):
        value = parse_expression(value, {}, where=where)
        if not value.is_number:
            raise SpecError(f"{where}: {value} is not a constant")
    try:
        v = float(value)
    except (TypeError, ValueError, OverflowError):
        raise SpecError(f"{where}: {value!r} is not a real number") from None
    if not math.isfinite(v):
        raise SpecError(f"{where}: {value!r} is not a finite number")
    return v


def _table(data: dict, key: str, path: Path) -> dict:
    value = data.get(key, {})
    if not isinstance(value, dict):
        raise SpecError(f"{path}: [{key}] must be a table, got {type(value).__name__}")
    return value


def _values(data: dict, key: str, allowed: dict, path: Path) -> dict:
    """``[params]`` / ``[initial]``: every key a known name, every value a finite number."""
    table = _table(data, key, path)
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        raise SpecError(f"{path}: [{key}] has unknown name(s) {', '.join(unknown)} (expected: "
                        f"{', '.join(allowed) or 'none'})")
    return {k: _number(v, f"{path.name}: {key}.{k}") for k, v in table.items()}


def _particles(data: dict, expr, path: Path) -> list:
    raw = data.get("particles", [])
    if not isinstance(raw, list):
        raise SpecError(f"{path}: 'particles' must be an array of tables ([[particles]])")
    out = []
    for i, part in enumerate(raw):
        if not isinstance(part, dict) or "mass" not in part or "position" not in part:
            raise SpecError(f"{path}: particles[{i}] needs 'mass' and 'position'")
        extra = sorted(set(part) - _PARTICLE_KEYS)
        if extra:
            raise SpecError(f"{path}: particles[{i}] has unknown key(s) {', '.join(extra)} (allowed: mass, "
                            "position, name)")
        pos = part["position"]
        if not isinstance(pos, list) or not 1 <= len(pos) <= 3:
            raise SpecError(f"{path}: particles[{i}].position must be a list of 1 to 3 expressions, got {pos!r}")
        name = part.get("name", "")
        if not isinstance(name, str):
            raise SpecError(f"{path}: particles[{i}].name must be a string")
        _plain_text(name, f"particles[{i}].name", path)
        coords = [expr(f"particles[{i}].position[{j}]", c, _POSITION_TERMS) for j, c in enumerate(pos)]
        out.append(Particle(expr(f"particles[{i}].mass", part["mass"], _POSITION_TERMS), coords, name=name))
    return out


def _simulate_table(data: dict, path: Path) -> tuple[float | None, dict]:
    sim = _table(data, "simulate", path)
    unknown = sorted(set(sim) - _SIMULATE_KEYS)
    if unknown:
        raise SpecError(f"{path}: [simulate] has unknown key(s) {', '.join(unknown)} (allowed: "
                        f"{', '.join(sorted(_SIMULATE_KEYS))})")
    t_end = sim.get("t_end")
    if t_end is not None:
        t_end = _number(t_end, f"{path.name}: simulate.t_end")
        if t_end <= 0:
            raise SpecError(f"{path}: simulate.t_end must be positive, got {t_end}")
    return t_end, {k: v for k, v in sim.items() if k != "t_end"}


def load_toml(path: Path) -> LoadedSpec:
    """Load a TOML spec (data only: no code runs, every value is validated).

    Raises
    ------
    SpecError
        Naming the file, the key and what is wrong: invalid TOML, unknown keys, names that are not
        identifiers or clash, expressions the safe parser rejects, non-finite numbers, or an invalid system.
    """
    try:
        st = path.stat()
        if not stat.S_ISREG(st.st_mode):  # a FIFO or a device would block the read or never end
            raise SpecError(f"{path}: not a regular file; give the path of a .toml file")
        if st.st_size > MAX_SPEC_BYTES:
            raise SpecError(f"{path}: larger than {MAX_SPEC_BYTES} bytes; a spec is a short text file")
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise SpecError(f"{path}: not valid TOML: {exc}") from None
    except RecursionError:  # tomllib parses nested arrays and inline tables recursively
        raise SpecError(f"{path}: arrays or tables nested deeper than {MAX_SPEC_NESTING} levels; a spec needs at "
                        "most a few") from None
    except OSError as exc:
        raise SpecError(f"{path}: cannot read: {exc}") from None
    _check_nesting(data, path)
    unknown = sorted(set(data) - _TOML_KEYS)
    if unknown:
        raise SpecError(f"{path}: unknown key(s) {', '.join(unknown)} (allowed: {', '.join(sorted(_TOML_KEYS))})")
    for key in ("name", "description"):
        if not isinstance(data.get(key, ""), str):
            raise SpecError(f"{path}: '{key}' must be a string")
        _plain_text(data.get(key, ""), key, path, newlines=key == "description")
    coord_names = _names_list(data, "coordinates", path, required=True)
    input_names = _names_list(data, "inputs", path, required=False)
    names, coords, params = _namespace(coord_names, _names_list(data, "parameters", path, required=False), path,
                                       input_names)

    def expr(key, value, max_terms=MAX_TERMS):
        return parse_expression(value, names, where=f"{path.name}: {key}", max_terms=max_terms)

    particles = _particles(data, expr, path)
    forces = None
    if "forces" in data:
        table = _table(data, "forces", path)
        bad = sorted(set(table) - set(coord_names))
        if bad:
            raise SpecError(f"{path}: [forces] has {', '.join(bad)}, which are not coordinates "
                            f"({', '.join(coord_names)})")
        forces = {k: expr(f"forces.{k}", v) for k, v in table.items()}
    kwargs = {key: expr(key, data[key]) for key in ("T", "V", "P", "rayleigh") if key in data}
    planar, joints, V_springs, loads = planar_declaration(data, expr, path)  # (all empty without those tables)
    if V_springs != 0:
        kwargs["V"] = kwargs.get("V", 0) + V_springs
    if loads:
        forces = ([forces] if forces else []) + loads
    try:
        system = System(list(coords), bodies=particles + planar, forces=forces, name=data.get("name", path.stem),
                        parameters=list(params), description=data.get("description", ""), constraints=joints,
                        **kwargs)
    except LagrangeError as exc:
        raise SpecError(f"{path}: {exc}") from None
    state_names = {**{nm: None for nm in coord_names}, **{nm + VELOCITY_SUFFIX: None for nm in coord_names}}
    values = _values(data, "params", {p.name: None for p in params}, path)
    initial = _values(data, "initial", state_names, path)
    t_end, options = _simulate_table(data, path)
    return LoadedSpec(system, values, initial, t_end, options, str(path), inputs=_input_values(data, input_names,
                                                                                                names, path))


def _input_values(data: dict, input_names: list[str], names: dict, path: Path) -> dict:
    """``[inputs_values]``: for declared inputs only, a number or an expression of t and the parameters."""
    table = _table(data, "inputs_values", path)
    unknown = sorted(set(table) - set(input_names))
    if unknown:
        raise SpecError(f"{path}: [inputs_values] has unknown name(s) {', '.join(unknown)} (declared inputs: "
                        f"{', '.join(input_names) or 'none'}; declare them in 'inputs')")
    allowed = {"t": t, **{k: v for k, v in names.items() if getattr(v, "is_Symbol", False) and k != "t"
                          and k not in input_names}}
    out = {}
    for k, v in table.items():
        if isinstance(v, bool) or not isinstance(v, (int, float, str)):
            raise SpecError(f"{path.name}: inputs_values.{k}: expected a number or an expression, got {v!r}")
        out[k] = _number(v, f"{path.name}: inputs_values.{k}") if not isinstance(v, str) else parse_expression(
            v, allowed, where=f"{path.name}: inputs_values.{k} (a function of t and the parameters)")
    return out


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
                      dict(ns.get("options", {})), str(path), inputs=dict(ns.get("inputs", {})))


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
            if path.exists():  # a directory, a FIFO or a device: never opened (a FIFO would block the read)
                raise SpecError(f"spec file {spec!r} is not a regular file; give the path of a spec file")
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
