"""`lagrange check SPEC`: the Lagrange-vs-Gauss check from the shell (exit code 1 on disagreement)."""

import subprocess
import sys
import textwrap


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "lagrange.cli", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=300)


def test_check_a_corpus_problem():
    out = run("check", "ex3.3", "--samples", "2", "--seed", "3")
    assert out.returncode == 0, out.stderr
    assert "verdict: AGREE" in out.stdout and out.stdout.count("state ") == 2
    assert "power balance" in out.stdout and "balance laws: OK" in out.stdout


def test_check_not_applicable_and_errors():
    out = run("check", "p2.13")
    assert out.returncode == 0 and "not applicable (T given directly" in out.stdout
    out = run("check", "ex3.3", "--param", "zz=1")
    assert out.returncode == 2 and "unknown parameter" in out.stderr
    assert run("check", "--help").returncode == 0


PENDULUM = """
import sympy as sp
import lagrange as lg

th = lg.coordinates("theta")
m, l, g = lg.parameters("m l g")
bob = lg.Particle(m, (l * sp.sin(th), -l * sp.cos(th)))
params = {"m": 1.0, "l": 1.5, "g": 9.81}
initial = {"theta": 0.5, "theta_dot": 0.0}
"""


def test_check_python_specs_agree_and_disagree(tmp_path):
    good = tmp_path / "good.py"
    good.write_text(PENDULUM + "system = lg.System([th], bodies=[bob], V=m * g * bob.position[1])\n")
    out = run("check", str(good), "--samples", "2")
    assert out.returncode == 0 and "AGREE" in out.stdout, out.stdout + out.stderr
    # a System whose generated model is that of a longer pendulum: the check must catch it
    bad = tmp_path / "bad.py"
    bad.write_text(PENDULUM + textwrap.dedent("""
        longer = lg.Particle(m, (1.1 * l * sp.sin(th), -1.1 * l * sp.cos(th)))
        wrong = lg.System([th], bodies=[longer], V=m * g * longer.position[1])

        class Buggy(lg.System):
            def compile(self, params=None, **kw):
                return wrong.compile(params, **kw)

        system = Buggy([th], bodies=[bob], V=m * g * bob.position[1])
    """))
    out = run("check", str(bad), "--samples", "2")
    assert out.returncode == 1 and "DISAGREE" in out.stdout, out.stdout + out.stderr
