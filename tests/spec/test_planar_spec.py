"""The planar tables of a TOML spec ([[planar_bodies]], [[joints]], [[springs]], [[torques]], [[point_forces]])
through ``lagrange simulate``, against closed forms, and their refusals."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import sympy as sp

from lagrange import SpecError
from lagrange.cli import main
from lagrange.spec.loader import load_spec

SLIDER_CRANK = """
name = "slider-crank"
coordinates = ["phi", "x2", "y2", "t2", "x3"]
parameters = ["r", "l", "m", "I"]

[[planar_bodies]]
name = "crank"
mass = "m"
inertia = "I"
angle = "phi"
points = { P = ["r", "0"] }

[[planar_bodies]]
name = "rod"
mass = "m"
inertia = "m*l**2/12"
position = ["x2", "y2"]
angle = "t2"
points = { A = ["-l/2", "0"], B = ["l/2", "0"] }

[[planar_bodies]]
name = "piston"
mass = "m"
inertia = "I"
position = ["x3", "0"]
points = { O = ["0", "0"] }

[[joints]]
type = "revolute"
points = ["crank.P", "rod.A"]

[[joints]]
type = "revolute"
points = ["rod.B", "piston.O"]

[params]
r = 0.3
l = 1.0
m = 1.0
I = 0.2

[initial]
phi = 0
x2 = 0.8
y2 = 0
t2 = 0
x3 = 1.3
phi_dot = 5
x2_dot = 0
y2_dot = 0.75
t2_dot = -1.5
x3_dot = 0

[simulate]
t_end = 2
rtol = 1e-10
atol = 1e-10
"""


def test_slider_crank_spec_through_the_cli(tmp_path, capsys):
    spec = tmp_path / "slider_crank.toml"
    spec.write_text(SLIDER_CRANK)
    out = tmp_path / "run.csv"
    assert main(["simulate", str(spec), "--csv", str(out), "--no-progress"]) == 0
    with out.open() as fh:
        rows = list(csv.DictReader(fh))
    phi = np.array([float(r["phi"]) for r in rows])
    x3 = np.array([float(r["x3"]) for r in rows])
    closed = 0.3 * np.cos(phi) + np.sqrt(1.0 - (0.3 * np.sin(phi)) ** 2)
    assert np.max(np.abs(x3 - closed)) < 1e-7
    assert float(rows[-1]["t"]) == pytest.approx(2.0)


PENDULUM = """
coordinates = ["th"]
parameters = ["m", "l", "k", "F", "tau"]

[[planar_bodies]]
name = "bar"
mass = "m"
inertia = "m*l**2/12"
angle = "th"
com = ["l/2", "0"]
points = { tip = ["l", "0"] }

[[springs]]
points = ["bar.tip", ["l", "1"]]
k = "k"

[[torques]]
body = "bar"
torque = "tau"

[[point_forces]]
at = "bar.tip"
force = ["0", "-F"]
"""


def test_springs_torques_and_point_forces_tables(tmp_path):
    spec = tmp_path / "bar.toml"
    spec.write_text(PENDULUM)
    system = load_spec(str(spec)).system
    th = system.coordinates[0]
    m, l, k, F, tau = sp.symbols("m l k F tau", positive=True)
    subs = {s: {x.name: x for x in (m, l, k, F, tau)}[s.name] for s in system.declared_symbols}
    V = k / 2 * ((l * sp.cos(th) - l) ** 2 + (l * sp.sin(th) - 1) ** 2)
    expected = -sp.diff(V, th) + tau - F * l * sp.cos(th)
    got = system.forcing[0].xreplace(subs)
    assert sp.simplify(got - expected) == 0
    assert sp.simplify(system.mass_matrix[0, 0].xreplace(subs) - m * l**2 / 3) == 0


@pytest.mark.parametrize("edit, message", [
    (('points = ["crank.P", "rod.A"]', 'points = ["crank.Q", "rod.A"]'), "no point named 'Q'"),
    (('points = ["crank.P", "rod.A"]', 'points = ["wheel.P", "rod.A"]'), "no planar body named 'wheel'"),
    (('points = ["crank.P", "rod.A"]', 'points = ["crank.P", "crank.P"]'), "both points are on body 'crank'"),
    (('type = "revolute"', 'type = "weld"'), "is not a joint type"),
    (('type = "revolute"', 'type = ["revolute"]'), "is not a joint type"),
    (('points = { O = ["0", "0"] }', 'points = { O = ["0", "0", "1"] }'), "list of 2 expressions"),
    (('angle = "t2"', 'angle = "t2"\ncolour = "red"'), "unknown key"),
    (('position = ["x3", "0"]', 'position = "rod"'), "is not a point"),
    (('inertia = "I"\nangle', 'inertia = "__import__(1)"\nangle'), "not allowed"),
])
def test_planar_spec_refusals(tmp_path, edit, message):
    text = SLIDER_CRANK.replace(edit[0], edit[1], 1)
    assert text != SLIDER_CRANK
    spec = tmp_path / "bad.toml"
    spec.write_text(text)
    with pytest.raises(SpecError, match=message):
        load_spec(str(spec))


JOINTS = """
coordinates = ["x1", "y1", "a1", "x2", "y2", "a2"]
parameters = ["l"]

[[planar_bodies]]
name = "arm"
mass = "1"
inertia = "1"
position = ["x1", "y1"]
angle = "a1"
points = { O = ["-l/2", "0"] }

[[planar_bodies]]
name = "block"
mass = "1"
inertia = "1"
position = ["x2", "y2"]
angle = "a2"
points = { C = ["0", "0"] }

[[joints]]
type = "pin"
point = "arm.O"
at = ["0", "1"]

[[joints]]
type = "slider"
guide = "arm.O"
follower = "block.C"
axis = ["1", "0"]
angle = "pi/2"

[[joints]]
type = "on_line"
point = "block.C"
through = ["0", "0"]
direction = ["0", "1"]
"""


def test_pin_slider_and_on_line_tables(tmp_path):
    spec = tmp_path / "joints.toml"
    spec.write_text(JOINTS)
    system = load_spec(str(spec)).system
    x1, y1, a1, x2, y2, a2 = system.coordinates
    (l,) = [s for s in system.declared_symbols if s.name == "l"]
    ox, oy = x1 - l / 2 * sp.cos(a1), y1 - l / 2 * sp.sin(a1)
    expected = [ox, oy - 1,                                                  # pin at (0, 1)
                sp.cos(a1) * (y2 - oy) - sp.sin(a1) * (x2 - ox), a2 - a1 - sp.pi / 2,   # slider along the arm
                -x2]                                                         # on the y axis
    assert [c.name for c in system.constraints][:2] == ["pin arm.O (x)", "pin arm.O (y)"]
    got = [c.position for c in system.constraints]
    assert len(got) == len(expected)
    assert all(sp.simplify(g - e) == 0 for g, e in zip(got, expected))
