"""`lagrange modes` on constrained systems, through a subprocess as a user runs it."""

import json
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


CARTPOLE = '''
coordinates = ["x", "theta"]
parameters = ["M", "m", "l", "g", "F0", "w"]
inputs = ["F"]
T = "(M + m)*x_dot**2/2 + m*l*x_dot*theta_dot*cos(theta) + m*l**2*theta_dot**2/2"
V = "m*g*l*cos(theta)"
[forces]
x = "F"
[params]
M = 1
m = 0.2
l = 0.5
g = 9.81
F0 = 1
w = 2
[initial]
x = 0
theta = 0.1
x_dot = 0
theta_dot = 0
[inputs_values]
F = "F0*cos(w*t)"
[simulate]
t_end = 1
'''


def main_modes(capsys, *args):
    from lagrange.cli import main

    status = main(["modes", *args])
    out = capsys.readouterr()
    return status, out.out, out.err


def test_ex3_4_finds_its_equilibrium_and_prints_a_table(capsys):
    """The README's problem: a bob on a rubber band, r = r0 + m g/k at rest; frequencies √(k/m), √(g/r)."""
    status, out, err = main_modes(capsys, "ex3.4")
    assert status == 0, err
    r_eq = 1 + 9.81 / 40
    assert out.startswith(f"linearized about the equilibrium r = {r_eq:.6g}, theta = 0 (stable")
    head = next(line for line in out.splitlines() if line.startswith("mode"))
    assert head.split() == ["mode", "eigenvalue", "frequency", "damping", "ratio", "period", "r", "theta"]
    rows = {line.split()[0]: line.split() for line in out.splitlines() if line[:1].isdigit()}
    assert float(rows["1"][4]) == pytest.approx(np.sqrt(9.81 / r_eq), rel=1e-5)  # 6 significant digits
    assert float(rows["2"][4]) == pytest.approx(np.sqrt(40.0), rel=1e-5)
    assert float(rows["1"][6]) == pytest.approx(2 * np.pi / np.sqrt(9.81 / r_eq), rel=1e-5)
    assert rows["1"][7:] == ["0", "1"] and rows["2"][7:] == ["1", "0"]  # θ swings, r breathes
    assert "[[" not in out and "s1" not in out  # no array dumps, coordinates by name


def test_a_point_that_is_not_an_equilibrium_is_answered_with_shell_options(capsys):
    status, _, err = main_modes(capsys, "ex3.4", "--about", "r=1.245")
    assert status == 2
    assert "r'' = 0.01" in err and "--about r=1.24525 --about theta=0" in err
    assert "lagrange.equilibria" not in err and "--force" in err
    status, out, _ = main_modes(capsys, "ex3.4", "--about", "r=1.245", "--force")
    assert status == 0 and "warning: not an equilibrium" in out


def test_json_digits_and_labelled_state_matrix(capsys):
    status, out, _ = main_modes(capsys, "ex3.4", "--json")
    report = json.loads(out)
    assert status == 0 and report["about"] == pytest.approx({"r": 1 + 9.81 / 40, "theta": 0.0}, rel=1e-12)
    assert [m["frequency"] for m in report["modes"]] == pytest.approx([np.sqrt(9.81 / 1.24525), np.sqrt(40)],
                                                                      rel=1e-12)
    assert report["stable"] and report["state_matrix"]["states"] == ["r", "theta", "r_dot", "theta_dot"]
    assert [m["damping_ratio"] for m in report["modes"]] == [0.0, 0.0] and len(report["equilibria"]) == 2
    _, short, _ = main_modes(capsys, "ex3.4", "--digits", "3", "--matrix")
    assert " 2.81 " in short and "2.8068" not in short
    matrix = short.split("state matrix (x' = A x):")[1].splitlines()
    assert matrix[1].split() == ["r", "theta", "r_dot", "theta_dot"] and matrix[4].split()[0] == "r_dot"
    assert float(matrix[4].split()[1]) == pytest.approx(-40.0)  # r'' = −(k/m) δr


def test_a_spec_with_an_input_runs_as_simulate_accepts_it(tmp_path, capsys):
    spec = tmp_path / "cartpole.toml"
    spec.write_text(CARTPOLE)
    status, _, err = main_modes(capsys, str(spec))  # F(0) = F0 = 1 pushes the cart: no static equilibrium
    assert status == 2 and "inputs held at F = 1" in err and "--input F=0" in err and "unknown" not in err
    status, out, err = main_modes(capsys, str(spec), "--input", "F=0")
    assert status == 0, err
    assert "input F held at 0 (--input;" in out and "any value of x is an equilibrium" in out
    status, out, err = main_modes(capsys, str(spec), "--param", "F0=0")
    assert status == 0 and "input F held at 0 (the spec's value at t = 0;" in out, err
    status, out, err = main_modes(capsys, str(spec), "--param", "F0=0", "--json")  # a parameter of the input only
    assert status == 0, err
    report = json.loads(out)
    w = np.sqrt((1 + 0.2) * 9.81 / (1 * 0.5))  # the hanging cart-pole: ω² = (M + m) g/(M l)
    assert report["inputs"] == {"F": 0.0} and abs(report["about"]["theta"]) == pytest.approx(np.pi)
    assert [m["frequency"] for m in report["modes"]] == pytest.approx([0.0, 0.0, w], rel=1e-12, abs=1e-12)
    status, _, err = main_modes(capsys, str(spec), "--input", "G=0")
    assert status == 2 and "unknown input(s) G (inputs: F)" in err


def test_near_seeds_the_search(capsys, pendulum):
    status, out, err = main_modes(capsys, pendulum, "--near", "y=1.5", "--json")
    assert status == 0, err
    report = json.loads(out)  # stable preferred even from near the top
    assert report["about"] == {"x": 0.0, "y": -2.0} and report["equilibria"][1] == {"x": 0.0, "y": 2.0}


def test_damped_oscillator_table_and_digits_limits(tmp_path, capsys):
    path = tmp_path / "damped.py"
    path.write_text(textwrap.dedent('''
        from lagrange import System, coordinates, parameters, t
        x = coordinates("x")
        m, k, b = parameters("m k b")
        system = System([x], T=m * x.diff(t)**2 / 2, V=k * x**2 / 2, P=-b * x.diff(t)**2 / 2)
        params = {"m": 2.0, "k": 8.0, "b": 1.2}
    '''))
    status, out, err = main_modes(capsys, str(path), "--json")
    assert status == 0, err
    (mode,) = json.loads(out)["modes"]
    zeta, w0 = 1.2 / (2 * np.sqrt(8.0 * 2.0)), np.sqrt(8.0 / 2.0)  # ζ = b/(2√(km)), ω0 = √(k/m)
    assert mode["damping_ratio"] == pytest.approx(zeta, rel=1e-12)
    assert mode["eigenvalue"] == pytest.approx([-zeta * w0, w0 * np.sqrt(1 - zeta**2)], rel=1e-12)
    assert mode["frequency"] == pytest.approx(w0 * np.sqrt(1 - zeta**2), rel=1e-12)
    for bad in ("0", "18", "x"):
        with pytest.raises(SystemExit):
            main_modes(capsys, str(path), "--digits", bad)


def test_python_spec_input_given_as_a_function_is_held_at_its_value_at_t0(tmp_path, capsys):
    path = tmp_path / "pushed.py"
    path.write_text(textwrap.dedent('''
        import math
        from lagrange import System, coordinates, inputs, parameters, t
        x = coordinates("x")
        m, k = parameters("m k")
        F = inputs("F")
        system = System([x], T=m * x.diff(t)**2 / 2, V=k * x**2 / 2, forces={x: F})
        params = {"m": 1.0, "k": 4.0}
        inputs = {F: lambda tt: 2.0 * math.cos(tt)}
    '''))
    status, out, err = main_modes(capsys, str(path), "--json")
    assert status == 0, err
    report = json.loads(out)  # F(0) = 2 holds the spring at x = F/k = 0.5
    assert report["inputs"] == {"F": 2.0} and report["about"]["x"] == pytest.approx(0.5, rel=1e-12)
    assert report["modes"][0]["frequency"] == pytest.approx(2.0, rel=1e-12)
