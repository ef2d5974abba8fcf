import pytest
import sympy as sp

from lagrange import SpecError, coordinates, parameters, t
from lagrange.simplification import is_zero
from lagrange.spec.expressions import parse_expression
from lagrange.spec.loader import load_spec

TOML = """
name = "spring pendulum"
coordinates = ["r", "theta"]
parameters = ["m", "g", "k", "r0", "b"]
V = "-m*g*r*cos(theta) + k/2*(r - r0)**2"
P = "-b/2*r_dot**2"
[[particles]]
mass = "m"
position = ["r*sin(theta)", "-r*cos(theta)"]
[params]
m = 1.0
g = 9.81
k = 40.0
r0 = 1.0
b = 0.1
[initial]
r = 1.2
theta = 0.5
r_dot = 0
theta_dot = 0
[simulate]
t_end = 3
"""


def test_toml_spec_round_trip(tmp_path):
    path = tmp_path / "pend.toml"
    path.write_text(TOML)
    spec = load_spec(str(path))
    r, th = coordinates("r theta")
    m, g, k, r0, b = parameters("m g k r0 b")
    e_r = spec.system.equations()[0]
    assert is_zero(e_r.lhs - e_r.rhs - (m * r.diff(t, 2) - m * r * th.diff(t) ** 2 + k * (r - r0)
                                            - m * g * sp.cos(th) + b * r.diff(t)))
    sol = spec.system.simulate(spec.t_end, spec.initial, spec.params)
    assert sol.energy_error() < 1e-7


def test_decimal_literals_are_exact():
    x = coordinates("x")
    assert parse_expression("0.5*x**2", {"x": x}) == sp.Rational(1, 2) * x**2


HOSTILE = [
    "__import__('os').system('echo pwned')",
    "x.__class__.__mro__",
    "(lambda: 1)()",
    "open('/etc/passwd')",
    "x[0]",
    "'a' * 10",
    "[x for x in (1,)]",
    "2**10**10",
    "x**1000",
    "sin(x, y=1)",
    "eval('1')",
    "_secret",
    "getattr(x, 'func')",
    "sin(" * 200 + "x" + ")" * 200,
    "x+" * 3000 + "x",
    "True",
]


@pytest.mark.parametrize("text", HOSTILE)
def test_hostile_expressions_rejected(text):
    x = coordinates("x")
    with pytest.raises(SpecError):
        parse_expression(text, {"x": x}, where="V")


def test_unknown_name_and_bad_keys(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('coordinates = ["x"]\nT = "m*x_dot**2/2"\n')
    with pytest.raises(SpecError, match="unknown name 'm'"):
        load_spec(str(path))
    path.write_text('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\nexec = "1"\n')
    with pytest.raises(SpecError, match="unknown key"):
        load_spec(str(path))
    path.write_text('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\nV = "x_dot"\n')
    with pytest.raises(SpecError, match="velocity"):
        load_spec(str(path))


def test_python_spec_and_problem_id(tmp_path):
    path = tmp_path / "osc.py"
    path.write_text(
        "from lagrange import System, coordinates, parameters, t\n"
        "x = coordinates('x'); m, k = parameters('m k')\n"
        "system = System([x], T=m*x.diff(t)**2/2, V=k*x**2/2)\n"
        "params = {'m': 1, 'k': 1}\ninitial = {'x': 1, 'x_dot': 0}\nt_end = 1\n"
    )
    spec = load_spec(str(path))
    assert spec.t_end == 1 and spec.params == {"m": 1, "k": 1}
    assert load_spec("EX3.2").problem.id == "ex3.2"
    with pytest.raises(SpecError, match="no problem"):
        load_spec("ex99.99")
    with pytest.raises(SpecError, match="does not exist"):
        load_spec(str(tmp_path / "missing.toml"))
