"""`lagrange modes` on constrained systems, through a subprocess as a user runs it."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

PENDULUM = textwrap.dedent('''
    import sympy as sp
    from lagrange import Holonomic, Particle, System, coordinates, parameters

    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    system = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
                    constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")], name="Cartesian pendulum")
    params = {"m": 1.0, "g": 9.81, "l": 2.0}
''')

DISC_PROBLEM = textwrap.dedent('''
    import sympy as sp
    from lagrange import Nonholonomic, System, coordinates, parameters, t
    from lagrange.corpus.problem import Problem, Simulation

    x, y, q1, q2, q3 = coordinates("x y q1 q2 q3")
    m, g, r, W = parameters("m g r Omega")
    xd, yd, q1d, q2d, q3d = (c.diff(t) for c in (x, y, q1, q2, q3))
    s1, c1, s2, c2 = sp.sin(q1), sp.cos(q1), sp.sin(q2), sp.cos(q2)
    vc = (xd + r * (c2 * s1 * q2d + s2 * c1 * q1d), yd + r * (s2 * s1 * q1d - c2 * c1 * q2d), -r * s2 * q2d)
    T = (m / 2 * sum(v**2 for v in vc)
         + sp.Rational(1, 2) * (m * r**2 / 4 * (q2d**2 + (q1d * c2) ** 2) + m * r**2 / 2 * (q1d * s2 + q3d) ** 2))
    disc = System([x, y, q1, q2, q3], T=T, V=m * g * r * c2,
                    constraints=[Nonholonomic(xd - r * c1 * q3d, name="roll x"),
                                 Nonholonomic(yd - r * s1 * q3d, name="roll y")])
    PROBLEM = Problem("disc", "rolling disc", 0, "test", disc, (),
                      simulation=Simulation({"m": 1.0, "g": 1.0, "r": 1.0}, {}, 1.0),
                      operating_point={"q3_dot": W, "x_dot": r * W})
''')


def run(*args):
    return subprocess.run([sys.executable, "-m", "lagrange.cli", "modes", *args], capture_output=True, text=True,
                          timeout=300)


@pytest.fixture()
def pendulum(tmp_path):
    path = tmp_path / "pendulum.py"
    path.write_text(PENDULUM)
    return str(path)


def test_cartesian_pendulum_frequency_and_refusals(pendulum):
    """Regression: the CLI printed zero frequencies with exit status 0."""
    out = run(pendulum, "--about", "y=-2", "--digits", "9")
    assert out.returncode == 0, out.stderr
    assert "independent coordinates (x)" in out.stdout
    assert f"{np.sqrt(9.81 / 2):.8f}" in out.stdout  # ω = sqrt(g/l)
    assert "string = -9.81" in out.stdout  # λ = −m g: the tension is −λ
    off = run(pendulum, "--about", "x=0.3", "--about", "y=-1")
    assert off.returncode == 2 and "string: φ = -0.956" in off.stderr and "internal error" not in off.stderr


@pytest.mark.slow
def test_unstable_top_singular_default_and_unknown_names(pendulum):
    bad = run(pendulum, "--about", "y=-2", "--param", "k=3", "--about", "z=1")
    assert bad.returncode == 2 and "unknown parameter(s) k (parameters: g, l, m)" in bad.stderr
    top = run(pendulum, "--about", "y=2", "--digits", "9")
    assert top.returncode == 0 and "unstable" in top.stdout and "2.21472346" in top.stdout
    found = run(pendulum)  # no point given: the stable equilibrium is found (q = 0 is singular: 0/0 gradient)
    assert found.returncode == 0 and "equilibrium x = 0, y = -2 (stable" in found.stdout, found.stderr
    assert "x = 0, y = 2 (unstable)" in found.stdout and "LAPACK" not in found.stderr
    singular = run(pendulum, "--about", "x=0", "--about", "y=0")  # given there: refused, not a LAPACK trace
    assert singular.returncode == 2 and "singular" in singular.stderr and "LAPACK" not in singular.stderr
    unknown = run(pendulum, "--about", "z=1")
    assert unknown.returncode == 2 and "valid: x, y, x_dot, y_dot" in unknown.stderr


@pytest.mark.slow
def test_rolling_disc_operating_point_and_steady_motion(tmp_path):
    path = tmp_path / "disc.py"
    path.write_text(DISC_PROBLEM)
    # the problem's operating point: upright, rolling at spin Ω
    out = run(str(path), "--param", "Omega=1", "--digits", "9")
    assert out.returncode == 0, out.stderr
    assert "independent speeds (x_dot, q1_dot, q2_dot)" in out.stdout and "steady motion check" in out.stdout
    assert f"{np.sqrt(0.8 * (3 - 1)):.8f}" in out.stdout and "stable" in out.stdout  # λ² = (4/5)(g/r − 3Ω²)
    lean = run(str(path), "--about", "q2=0.2", "--param", "Omega=1")
    assert lean.returncode == 2 and "not a steady motion" in lean.stderr and "--force" in lean.stderr
    forced = run(str(path), "--about", "q2=0.2", "--param", "Omega=1", "--force")
    assert forced.returncode == 0 and "warning: not a steady motion" in forced.stdout
