"""The planar-mechanism tables of a TOML spec: ``[[planar_bodies]]``, ``[[joints]]``, ``[[springs]]``,
``[[torques]]`` and ``[[point_forces]]`` (:mod:`lagrange.model.planar`, :mod:`lagrange.model.joints`).

.. code-block:: toml

    [[planar_bodies]]
    name = "crank"
    mass = "m1"
    inertia = "I1"                    # about the centre of mass
    position = ["0", "0"]             # or "other.P": hinged at point P of body other (declared before)
    angle = "phi"
    com = ["r/2", "0"]                # optional, body coordinates
    points = { P = ["r", "0"] }       # named points, body coordinates

    [[joints]]
    type = "revolute"                 # revolute: points = ["a.P", "b.Q"]
    points = ["crank.P", "rod.A"]     # pin: point = "a.P", at = [x, y]
                                      # on_line: point, through = [x, y], direction = [ux, uy]
                                      # slider: follower = "b.Q", guide = "a.P" or [x, y], axis, angle

    [[springs]]                       # adds ½ k (ℓ − ℓ0)² to V
    points = ["rod.B", ["xc", "yc"]]  # body points or fixed positions
    k = "k"
    rest_length = "l0"

    [[torques]]
    body = "crank"
    torque = "tau"

    [[point_forces]]
    at = "rod.B"
    force = ["0", "-F"]

Every name is checked (unknown body or point, unknown key, a joint type that does not exist) and every
expression goes through the safe parser; a problem is a :class:`~lagrange.errors.SpecError` naming the table,
its index and the key.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import LagrangeError, SpecError
from ..model.bodies import Force
from ..model.joints import on_line, pin, revolute, slider, spring_potential
from ..model.planar import PlanarBody

__all__ = ["PLANAR_KEYS", "planar_declaration"]

#: the top-level keys this module reads
PLANAR_KEYS = {"planar_bodies", "joints", "springs", "torques", "point_forces"}

_BODY_KEYS = {"name", "mass", "inertia", "position", "angle", "com", "points"}
_JOINT_KEYS = {
    "revolute": {"type", "name", "points"},
    "pin": {"type", "name", "point", "at"},
    "on_line": {"type", "name", "point", "through", "direction"},
    "slider": {"type", "name", "follower", "guide", "axis", "angle"},
}
_SPRING_KEYS = {"points", "k", "rest_length"}
_TORQUE_KEYS = {"body", "torque"}
_FORCE_KEYS = {"at", "force"}
_POSITION_TERMS = 100


def _tables(data: dict, key: str, path: Path) -> list[dict]:
    raw = data.get(key, [])
    if not isinstance(raw, list) or not all(isinstance(x, dict) for x in raw):
        raise SpecError(f"{path}: '{key}' must be an array of tables ([[{key}]])")
    return raw


def _check_keys(table: dict, allowed: set, where: str, path: Path, required: tuple = ()) -> None:
    extra = sorted(set(table) - allowed)
    if extra:
        raise SpecError(f"{path}: {where} has unknown key(s) {', '.join(extra)} (allowed: "
                        f"{', '.join(sorted(allowed))})")
    missing = [k for k in required if k not in table]
    if missing:
        raise SpecError(f"{path}: {where} needs {', '.join(repr(k) for k in missing)}")


class _Declaration:
    """Reads the tables in order, keeping the bodies declared so far (a body may be hinged to an earlier one)."""

    def __init__(self, data: dict, expr, path: Path):
        self.data, self.expr, self.path = data, expr, path
        self.bodies: dict[str, PlanarBody] = {}

    def pair(self, value, where: str) -> tuple:
        if not isinstance(value, list) or len(value) != 2:
            raise SpecError(f"{self.path}: {where} must be a list of 2 expressions [x, y], got {value!r}")
        return tuple(self.expr(f"{where}[{j}]", v, _POSITION_TERMS) for j, v in enumerate(value))

    def point(self, ref, where: str):
        """``"body.P"`` → the material point; a list of 2 expressions → a fixed position (when allowed)."""
        if isinstance(ref, list):
            return self.pair(ref, where)
        if not isinstance(ref, str) or ref.count(".") != 1:
            raise SpecError(f"{self.path}: {where} = {ref!r} is not a point: write 'body.point' (a named point of a "
                            "declared planar body) or [x, y]")
        body, name = ref.split(".")
        if body not in self.bodies:
            raise SpecError(f"{self.path}: {where} = {ref!r}: no planar body named {body!r} (declared so far: "
                            f"{', '.join(self.bodies) or 'none'})")
        try:
            return self.bodies[body].point(name)
        except LagrangeError as exc:
            raise SpecError(f"{self.path}: {where}: {exc}") from None

    def body_point(self, ref, where: str):
        p = self.point(ref, where)
        if isinstance(p, tuple):
            raise SpecError(f"{self.path}: {where} must be a body's point 'body.point', got {ref!r}")
        return p

    def planar_bodies(self) -> list[PlanarBody]:
        for i, b in enumerate(_tables(self.data, "planar_bodies", self.path)):
            where = f"planar_bodies[{i}]"
            _check_keys(b, _BODY_KEYS, where, self.path, ("name", "mass", "inertia"))
            name = b["name"]
            if not isinstance(name, str) or not name.isascii() or not name.isidentifier():
                raise SpecError(f"{self.path}: {where}.name must be an identifier, got {name!r}")
            if name in self.bodies:
                raise SpecError(f"{self.path}: {where}: a planar body named {name!r} is declared twice")
            points = b.get("points", {})
            if not isinstance(points, dict):
                raise SpecError(f"{self.path}: {where}.points must be a table {{P = [a, b]}}")
            for key in points:
                if not key.isascii() or not key.isidentifier():
                    raise SpecError(f"{self.path}: {where}.points: {key!r} is not an identifier")
            position = self.point(b.get("position", ["0", "0"]), f"{where}.position")
            try:
                self.bodies[name] = PlanarBody(
                    self.expr(f"{where}.mass", b["mass"], _POSITION_TERMS),
                    self.expr(f"{where}.inertia", b["inertia"], _POSITION_TERMS), position,
                    self.expr(f"{where}.angle", b.get("angle", "0"), _POSITION_TERMS),
                    com=self.pair(b.get("com", ["0", "0"]), f"{where}.com"),
                    points={k: self.pair(v, f"{where}.points.{k}") for k, v in points.items()}, name=name)
            except LagrangeError as exc:
                raise SpecError(f"{self.path}: {where}: {exc}") from None
        return list(self.bodies.values())

    def joints(self) -> list:
        out = []
        for i, j in enumerate(_tables(self.data, "joints", self.path)):
            where = f"joints[{i}]"
            kind = j.get("type")
            if not isinstance(kind, str) or kind not in _JOINT_KEYS:
                raise SpecError(f"{self.path}: {where}.type = {kind!r} is not a joint type ("
                                f"{', '.join(sorted(_JOINT_KEYS))})")
            name = j.get("name", "")
            if not isinstance(name, str):
                raise SpecError(f"{self.path}: {where}.name must be a string")
            try:
                out.append(self._joint(kind, j, where, name))
            except LagrangeError as exc:
                if isinstance(exc, SpecError):
                    raise
                raise SpecError(f"{self.path}: {where}: {exc}") from None
        return out

    def _joint(self, kind: str, j: dict, where: str, name: str) -> tuple:
        if kind == "revolute":
            _check_keys(j, _JOINT_KEYS[kind], where, self.path, ("points",))
            pts = j["points"]
            if not isinstance(pts, list) or len(pts) != 2:
                raise SpecError(f"{self.path}: {where}.points must be two points ['a.P', 'b.Q']")
            return revolute(self.body_point(pts[0], f"{where}.points[0]"),
                            self.body_point(pts[1], f"{where}.points[1]"), name)
        if kind == "pin":
            _check_keys(j, _JOINT_KEYS[kind], where, self.path, ("point",))
            return pin(self.body_point(j["point"], f"{where}.point"), self.pair(j.get("at", ["0", "0"]),
                                                                              f"{where}.at"), name)
        if kind == "on_line":
            _check_keys(j, _JOINT_KEYS[kind], where, self.path, ("point", "direction"))
            return on_line(self.body_point(j["point"], f"{where}.point"),
                           self.pair(j.get("through", ["0", "0"]), f"{where}.through"),
                           self.pair(j["direction"], f"{where}.direction"), name)
        _check_keys(j, _JOINT_KEYS[kind], where, self.path, ("follower", "guide"))
        return slider(self.point(j["guide"], f"{where}.guide"), self.body_point(j["follower"], f"{where}.follower"),
                      self.pair(j.get("axis", ["1", "0"]), f"{where}.axis"),
                      self.expr(f"{where}.angle", j.get("angle", "0")), name)

    def springs(self):
        V = 0
        for i, s in enumerate(_tables(self.data, "springs", self.path)):
            where = f"springs[{i}]"
            _check_keys(s, _SPRING_KEYS, where, self.path, ("points", "k"))
            pts = s["points"]
            if not isinstance(pts, list) or len(pts) != 2:
                raise SpecError(f"{self.path}: {where}.points must be two points (body points or [x, y])")
            V += spring_potential(self.point(pts[0], f"{where}.points[0]"), self.point(pts[1], f"{where}.points[1]"),
                                  self.expr(f"{where}.k", s["k"]),
                                  self.expr(f"{where}.rest_length", s.get("rest_length", "0")))
        return V

    def loads(self) -> list:
        out = []
        for i, tq in enumerate(_tables(self.data, "torques", self.path)):
            where = f"torques[{i}]"
            _check_keys(tq, _TORQUE_KEYS, where, self.path, ("body", "torque"))
            if not isinstance(tq["body"], str) or tq["body"] not in self.bodies:
                raise SpecError(f"{self.path}: {where}.body = {tq['body']!r} is not a declared planar body "
                                f"({', '.join(self.bodies) or 'none'})")
            out.append(self.bodies[tq["body"]].torque(self.expr(f"{where}.torque", tq["torque"])))
        for i, f in enumerate(_tables(self.data, "point_forces", self.path)):
            where = f"point_forces[{i}]"
            _check_keys(f, _FORCE_KEYS, where, self.path, ("at", "force"))
            out.append(Force(self.body_point(f["at"], f"{where}.at"), self.pair(f["force"], f"{where}.force")))
        return out


def planar_declaration(data: dict, expr, path: Path) -> tuple[list, list, object, list]:
    """``(bodies, constraints, V, loads)`` from the planar tables of a spec (each empty when absent):
    ``expr(key, value[, max_terms])`` parses one expression."""
    d = _Declaration(data, expr, path)
    bodies = d.planar_bodies()
    return bodies, d.joints(), d.springs(), d.loads()
