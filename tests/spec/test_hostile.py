"""Hostile inputs for TOML specs: nothing executes, nothing hangs, every rejection is a one-line SpecError.

The number of hostile inputs tried is ``len(HOSTILE_EXPRESSIONS) + len(HOSTILE_TOML)`` (each is one
parametrized case below); the README's guarantees section cites it.
"""

from __future__ import annotations

import signal
import sys
from contextlib import contextmanager

import numpy as np
import pytest
import sympy as sp

from lagrange import SpecError, coordinates, parameters, t
from lagrange.spec.expressions import parse_expression
from lagrange.spec.loader import load_spec

SENTINEL = "lagrange_pwned_sentinel"

#: (expression, fragment of the expected error message)
HOSTILE_EXPRESSIONS = [
    # code execution attempts
    (f"__import__('pathlib').Path('{SENTINEL}').touch()", "not allowed"),
    ("__import__('os').system('echo pwned')", "not allowed"),
    ("eval('1')", "function 'eval' is not allowed"),
    ("exec('import os')", "function 'exec' is not allowed"),
    ("open('/etc/passwd')", "function 'open' is not allowed"),
    ("getattr(x, 'func')", "function 'getattr' is not allowed"),
    ("globals()", "function 'globals' is not allowed"),
    ("type(x)", "function 'type' is not allowed"),
    ("Function('f')(x)", "plain function name"),
    ("Piecewise((1, x > 0))", "function 'Piecewise' is not allowed"),
    ("Rational(1, 10**1000)", "function 'Rational' is not allowed"),
    ("factorial(10**9)", "function 'factorial' is not allowed"),
    ("Derivative(x, t)", "function 'Derivative' is not allowed"),
    ("x;import os", "cannot parse"),
    ("x\nimport os", "cannot parse"),
    # attribute chains, dunders, subscripts
    ("x.__class__.__mro__", "attribute access"),
    ("x.func", "attribute access"),
    ("().__class__.__bases__[0].__subclasses__()", "not allowed"),
    ("__builtins__", "the name '__builtins__'"),
    ("_secret", "the name '_secret'"),
    ("x[0]", "subscripting"),
    # syntax that is code, not an expression
    ("lambda: 1", "lambda is not allowed"),
    ("(lambda: 1)()", "plain function name"),
    ("[x for x in (1,)]", "list comprehension"),
    ("{x for x in (1,)}", "set comprehension"),
    ("(x for x in (1,))", "generator expression"),
    ("{1: 2}", "a dict"),
    ("f'{x}'", "f-string"),
    ("sin(*x)", "'*' unpacking"),
    ("(y := 3)", "':=' assignment"),
    ("sin(x=1)", "keyword argument"),
    ("sin(**{})", "keyword argument"),
    ("x if x else 1", "'if ... else'"),
    ("x < 1", "a comparison"),
    ("x and 1", "'and'/'or'"),
    ("not x", "unary operator Not"),
    ("x // 2", "operator FloorDiv"),
    ("x % 2", "operator Mod"),
    ("x @ x", "operator MatMult"),
    ("'a' * 10**7", "literal 'a'"),
    ("b'x'", "literal b'x'"),
    ("True", "literal True"),
    ("None", "literal None"),
    ("1j", "literal 1j"),
    ("x, 1", "a tuple"),
    ("", "cannot parse"),
    # unicode look-alikes (Python would normalize them to x / sin)
    ("\uff58", "non-ASCII"),              # fullwidth x
    ("\U0001d431", "non-ASCII"),          # mathematical bold x
    ("\u2179", "non-ASCII"),              # small roman numeral ten
    ("\uff53\uff49\uff4e(x)", "non-ASCII"),  # fullwidth sin
    ("x\u200b", "non-ASCII"),             # zero-width space
    # names sympify treats specially mean nothing unless declared
    ("I", "unknown name 'I'"),
    ("S", "unknown name 'S'"),
    ("N", "unknown name 'N'"),
    ("Q", "unknown name 'Q'"),
    ("O", "unknown name 'O'"),
    ("oo", "unknown name 'oo'"),
    ("zoo", "unknown name 'zoo'"),
    ("nan", "unknown name 'nan'"),
    ("beta", "unknown name 'beta'"),
    ("gamma", "unknown name 'gamma'"),
    ("zeta", "unknown name 'zeta'"),
    ("lambda", "cannot parse"),
    ("sin", "unknown name 'sin'"),
    # huge numbers and exponents
    ("9**9**9", "exceeds the limit"),
    ("10**10**10", "exceeds the limit"),
    ("2**(2**64)", "exceeds the limit"),
    ("x**101", "exceeds the limit"),
    ("x**-101", "exceeds the limit"),
    ("((x + 1)**100)**100", "combined exponent"),
    ("x**100*x**100", "combined exponent"),
    ("(2**100)**100", "outside the floating-point range"),
    ("(10**30)**11", "outside the floating-point range"),
    ("1" * 40, "integer literal too large"),
    ("1e308*1e308", "outside the floating-point range"),
    ("1e309", "outside the floating-point range"),
    ("1e-400", "outside the floating-point range"),
    ("1E10000", "outside the floating-point range"),  # str() of a 10,001-digit integer raises in Python 3.11+
    ("-1e-10000*x", "outside the floating-point range"),
    ("1e999999999999", "outside the floating-point range"),  # never built as an integer
    ("1e300*x*1e300", "outside the floating-point range"),
    ("1e200*x*1e200", "outside the floating-point range"),
    ("exp(1000)", "outside the floating-point range"),
    ("exp(exp(exp(100)))", "outside the floating-point range"),
    ("1/" + "9" * 400, "integer literal too large"),
    # undefined or complex constants
    ("1/0", "division by zero"),
    ("x/(2 - 2)", "division by zero"),
    ("0**-1", "undefined"),
    ("log(0)", "not a finite real number"),
    ("atan2(0, 0)", "not a finite real number"),
    ("sqrt(-1)", "not a finite real number"),
    ("acos(2)", "not a finite real number"),
    ("sqrt(-m)", "not a finite real expression"),
    # wrong arity (sympy would silently read sqrt(x, 2) as sqrt(x))
    ("sqrt(x, 2)", "sqrt takes 1 argument"),
    ("log(x, 0)", "log takes 1 argument"),
    ("atan2(x)", "atan2 takes 2 arguments"),
    ("exp()", "exp takes 1 argument"),
    # size limits: length, parts, nesting, multiplied-out size
    ("x" * 5001, "longer than"),
    ("(" * 10000 + "x" + ")" * 10000, "longer than"),
    ("sin(" * 200 + "x" + ")" * 200, "nested deeper"),
    ("-" * 100 + "x", "nested deeper"),
    ("(" * 300 + "x" + ")" * 300, "cannot parse"),
    ("x+" * 1500 + "x", "more than 2000 parts"),
    ("x**x**" * 40 + "x", "nested deeper"),
    ("(x + 1)**100*(x - 1)**100", "would expand to more than"),
    ("(x + m + 1)**60", "would expand to more than"),
]

HOSTILE_TOML = {
    "params_code_string": ('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\n[params]\n'
                           f'm = "__import__(\'pathlib\').Path(\'{SENTINEL}\').touch() or 1"\n',
                           "params.m"),
    "initial_code_string": ('coordinates = ["x"]\nT = "x_dot**2/2"\n[initial]\n'
                            'x = "__import__(\'os\').getcwd()"\n', "initial.x"),
    "params_not_finite": ('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\n[params]\nm = inf\n',
                          "not a finite number"),
    "params_nan": ('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\n[params]\nm = nan\n',
                   "not a finite number"),
    "params_bool": ('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\n[params]\nm = true\n',
                    "expected a number"),
    "params_undeclared": ('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\n[params]\nk = 1\n',
                          "unknown name(s) k"),
    "initial_unknown": ('coordinates = ["x"]\nT = "x_dot**2/2"\n[initial]\ny = 1\n', "unknown name(s) y"),
    "V_number_inf": ('coordinates = ["x"]\nT = "x_dot**2/2"\nV = inf\n', "not a finite number"),
    "V_not_string": ('coordinates = ["x"]\nT = "x_dot**2/2"\nV = [1, 2]\n', "expected an expression"),
    "V_velocity": ('coordinates = ["x"]\nT = "x_dot**2/2"\nV = "x_dot"\n', "velocity"),
    "coordinates_string": ('coordinates = "xy"\nT = "x_dot**2/2"\n', "list of name strings"),
    "coordinates_twice": ('coordinates = ["x", "x"]\nT = "x_dot**2/2"\n', "listed more than once"),
    "coordinate_keyword": ('coordinates = ["lambda"]\nT = "1"\n', "Python keyword"),
    "coordinate_dunder": ('coordinates = ["__class__"]\nT = "1"\n', "not a valid name"),
    "coordinate_unicode": ('coordinates = ["\uff58"]\nT = "1"\n', "not a valid name"),
    "coordinate_named_t": ('coordinates = ["t"]\nT = "t_dot**2/2"\n', "clashes with the time"),
    "velocity_clash": ('coordinates = ["x", "x_dot"]\nT = "x_dot**2/2"\n', "clashes"),
    "parameter_clash": ('coordinates = ["x"]\nparameters = ["x_dot"]\nT = "x_dot**2/2"\n', "clashes"),
    "parameters_string": ('coordinates = ["x"]\nparameters = "mk"\nT = "x_dot**2/2"\n', "list of name strings"),
    "position_string": ('coordinates = ["x", "y"]\n[[particles]]\nmass = "1"\nposition = "xy"\n',
                        "position must be a list"),
    "position_too_long": ('coordinates = ["x"]\n[[particles]]\nmass = "1"\nposition = ["x", "x", "x", "x"]\n',
                          "position must be a list of 1 to 3"),
    "position_blowup": ('coordinates = ["x", "y"]\n[[particles]]\nmass = "1"\n'
                        'position = ["(x + y)**60*(x - y)**2", "y"]\n', "would expand"),
    "particle_extra_key": ('coordinates = ["x"]\n[[particles]]\nmass = "1"\nposition = ["x"]\ncode = "1"\n',
                           "unknown key(s) code"),
    "particles_not_array": ('coordinates = ["x"]\nparticles = "x"\n', "array of tables"),
    "forces_unknown": ('coordinates = ["x"]\nT = "x_dot**2/2"\n[forces]\ny = "1"\n', "not coordinates"),
    "forces_not_table": ('coordinates = ["x"]\nT = "x_dot**2/2"\nforces = "1"\n', "must be a table"),
    "simulate_unknown": ('coordinates = ["x"]\nT = "x_dot**2/2"\n[simulate]\nmodel = "x"\n', "unknown key(s) model"),
    "t_end_negative": ('coordinates = ["x"]\nT = "x_dot**2/2"\n[simulate]\nt_end = -1\n', "must be positive"),
    "top_level_exec": ('coordinates = ["x"]\nT = "x_dot**2/2"\nexec = "1"\n', "unknown key(s) exec"),
    "name_not_string": ('coordinates = ["x"]\nT = "x_dot**2/2"\nname = 3\n', "'name' must be a string"),
    "not_toml": ('coordinates = [\n', "not valid TOML"),
    "undeclared_function_of_t": ('coordinates = ["x"]\nT = "x_dot**2/2"\nV = "y"\n', "unknown name 'y'"),
    "no_kinetic_energy": ('coordinates = ["x"]\nV = "x**2"\n', "no kinetic energy"),
    # nesting: tomllib parses arrays and inline tables recursively (a RecursionError), and a parsed deep value
    # must not reach code that walks it
    "nested_arrays_deep": ('coordinates = ["x"]\nT = "x_dot**2/2"\nV = ' + "[" * 5000 + "]" * 5000 + "\n",
                           "nested deeper than"),
    "nested_arrays_params": ('coordinates = ["x"]\nparameters = ["m"]\nT = "m*x_dot**2/2"\n[params]\nm = '
                             + "[" * 60 + "1" + "]" * 60 + "\n", "nested deeper than"),
    "nested_inline_tables": ('coordinates = ["x"]\nT = "x_dot**2/2"\nV = ' + "{a = " * 3000 + "1" + "}" * 3000
                             + "\n", "nested deeper than"),
}


@contextmanager
def _time_limit(seconds: int):
    """Fail (instead of hanging the suite) when a hostile input takes too long."""
    if not hasattr(signal, "SIGALRM"):  # pragma: no cover - Windows
        yield
        return

    def _timeout(signum, frame):
        raise TimeoutError(f"took longer than {seconds} s")

    old = signal.signal(signal.SIGALRM, _timeout)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


@pytest.fixture
def no_sympy_eval(monkeypatch):
    """Make sympy's string parser (which calls eval) unusable: a spec must never reach it."""
    import sympy.parsing.sympy_parser as sp_parser

    def forbidden(*args, **kwargs):
        raise AssertionError("a spec string reached sympy's eval-based parser")

    monkeypatch.setattr(sp_parser, "parse_expr", forbidden)
    monkeypatch.setattr(sp_parser, "eval_expr", forbidden)


@pytest.mark.parametrize(("text", "fragment"), HOSTILE_EXPRESSIONS)
def test_hostile_expression_rejected(text, fragment, tmp_path, monkeypatch, no_sympy_eval):
    monkeypatch.chdir(tmp_path)
    x = coordinates("x")
    m = parameters("m")
    with _time_limit(10), pytest.raises(SpecError) as exc:
        parse_expression(text, {"x": x, "m": m}, where="V")
    msg = str(exc.value)
    assert msg.startswith("V: ") and "\n" not in msg and fragment in msg, msg
    assert not (tmp_path / SENTINEL).exists()


@pytest.mark.parametrize("case", sorted(HOSTILE_TOML))
def test_hostile_toml_rejected(case, tmp_path, monkeypatch, no_sympy_eval):
    text, fragment = HOSTILE_TOML[case]
    monkeypatch.chdir(tmp_path)
    path = tmp_path / f"{case}.toml"
    path.write_text(text, encoding="utf-8")
    with _time_limit(20), pytest.raises(SpecError) as exc:
        load_spec(str(path))
    assert fragment in str(exc.value), str(exc.value)
    assert not (tmp_path / SENTINEL).exists()


@pytest.mark.skipif(not hasattr(__import__("os"), "mkfifo"), reason="needs FIFOs (POSIX)")
def test_spec_that_is_a_fifo_is_refused_at_once(tmp_path):
    """A FIFO given as the spec would block the read until someone writes to it: refused without opening."""
    import os

    path = tmp_path / "spec.toml"
    os.mkfifo(path)
    with _time_limit(10), pytest.raises(SpecError, match="not a regular file"):
        load_spec(str(path))


def test_hostile_spec_through_the_cli_runs_nothing(tmp_path, monkeypatch, capsys):
    """The CLI reports one line and a non-zero exit; the payload never runs."""
    from lagrange.cli import main

    monkeypatch.chdir(tmp_path)
    path = tmp_path / "evil.toml"
    path.write_text(HOSTILE_TOML["params_code_string"][0])
    assert main(["simulate", str(path), "--t-end", "0.1"]) != 0
    err = capsys.readouterr().err
    assert "params.m" in err and "Traceback" not in err
    assert not (tmp_path / SENTINEL).exists()


def test_sympy_special_names_are_plain_parameters(tmp_path, no_sympy_eval):
    """Declared as parameters, sympy's special names (E, I, S, N, Q, O, beta, gamma, zeta) are ordinary
    symbols: the oscillator m ẍ = −k x written with them has the closed-form solution."""
    path = tmp_path / "names.toml"
    path.write_text(
        'coordinates = ["x"]\nparameters = ["E", "I", "S", "N", "Q", "O", "beta", "gamma", "zeta"]\n'
        'T = "(E + I)*x_dot**2/2"\nV = "(S*N + Q - O)*beta*gamma*zeta*x**2/2"\n'
        '[params]\nE = 0.5\nI = 0.5\nS = 2\nN = 2\nQ = "pi/pi"\nO = 1\nbeta = 1\ngamma = 1\nzeta = 1\n'
        '[initial]\nx = 1\nx_dot = 0\n[simulate]\nt_end = 2\n'
    )
    spec = load_spec(str(path))
    sol = spec.system.simulate(spec.t_end, spec.initial, spec.params)
    x = spec.system.coordinates[0]
    assert np.max(np.abs(sol[x] - np.cos(2.0 * sol.t))) < 1e-7  # ω² = (2·2 + 1 − 1)/1 = 4


def test_constant_expressions_allowed_as_values(tmp_path):
    path = tmp_path / "pend.toml"
    path.write_text('coordinates = ["th"]\nparameters = ["g"]\nT = "th_dot**2/2"\nV = "-g*cos(th)"\n'
                    '[params]\ng = "9.81"\n[initial]\nth = "pi/4"\nth_dot = 0\n')
    spec = load_spec(str(path))
    assert spec.initial["th"] == pytest.approx(np.pi / 4, abs=0) and spec.params["g"] == 9.81


def test_exact_literals_and_long_sums():
    x = coordinates("x")
    assert parse_expression("1e-3*x + 2.5e2", {"x": x}) == sp.Rational(1, 1000) * x + 250
    long_sum = "+".join(f"{i}*x**{i % 7}" for i in range(250))  # one nesting level, 250 terms
    expected = sum(i * x ** (i % 7) for i in range(250))
    assert sp.expand(parse_expression(long_sum, {"x": x}) - expected) == 0
    assert parse_expression(1e-3, {"x": x}) == sp.Rational(1, 1000)


def test_counts_documented():
    """The guarantees section cites these numbers; keep them honest."""
    n_expr, n_toml = len(HOSTILE_EXPRESSIONS), len(HOSTILE_TOML)
    assert n_expr >= 100 and n_toml >= 30
    print(f"hostile inputs: {n_expr} expressions + {n_toml} TOML files = {n_expr + n_toml}", file=sys.stderr)


def test_time_symbol_usable():
    x = coordinates("x")
    assert parse_expression("x*sin(t)", {"x": x, "t": t}) == x * sp.sin(t)
