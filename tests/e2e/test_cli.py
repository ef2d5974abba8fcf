"""The command line through a subprocess, as a user runs it."""

import subprocess
import sys

import pytest


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "lagrange.cli", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=300)


def test_help_everywhere():
    for cmd in ([], ["derive"], ["simulate"], ["problems"], ["verify"]):
        out = run(*cmd, "--help")
        assert out.returncode == 0 and "usage: lagrange" in out.stdout


def test_problems_derive_simulate(tmp_path):
    out = run("problems", "--chapter", "3")
    assert out.returncode == 0 and "ex3.2" in out.stdout and "Chapter 3" in out.stdout
    out = run("derive", "ex3.2")
    assert out.returncode == 0 and "x\u0308" in out.stdout
    out = run("derive", "ex3.2", "--latex")
    assert out.returncode == 0 and r"\ddot{x}" in out.stdout
    png, csv = tmp_path / "a.png", tmp_path / "a.csv"
    out = run("simulate", "ex3.2", "--t-end", "2", "--plot", str(png), "--csv", str(csv))
    assert out.returncode == 0, out.stderr
    assert png.stat().st_size > 10_000 and csv.read_text().startswith("t,x,x_dot")
    assert "power-balance residual" in out.stdout or "energy drift" in out.stdout


@pytest.mark.parametrize(
    "args, message",
    [
        (["derive", "nosuch"], "no problem with id"),
        (["simulate", "ex3.2", "--param", "m=abc"], "not a number"),
        (["simulate", "ex3.2", "--param", "zz=1"], "unknown parameter"),
        (["derive", "missing.toml"], "does not exist"),
    ],
)
def test_errors_are_one_line(args, message):
    out = run(*args)
    assert out.returncode == 2
    assert message in out.stderr
    assert "Traceback" not in out.stderr and len(out.stderr.strip().splitlines()) == 1


def test_verify_runs_the_book_checks():
    out = run("verify", "ex3.2", "ex6.1")
    assert out.returncode == 0 and "0 failed" in out.stdout


def test_modes_and_hamiltonian_commands():
    out = run("modes", "sec1.9", "--digits", "10")
    assert out.returncode == 0, out.stderr
    assert "8.164965809" in out.stdout and "19.36491673" in out.stdout  # Wells: 8.16 and 19.37 rad/s
    out = run("hamiltonian", "ex3.3")
    assert out.returncode == 0 and "H =" in out.stdout and "dp_theta/dt =" in out.stdout


def test_derive_prints_tidy_wrapped_equations():
    """`lagrange derive` of Wells' double pendulum on strings: cos(φ − θ) instead of the products of sines and
    cosines, no line wider than the terminal ($COLUMNS; 100 columns when it is unset and not a terminal)."""
    import os
    import unicodedata

    width = 72
    out = subprocess.run([sys.executable, "-m", "lagrange.cli", "derive", "ex12.2"], capture_output=True,
                         text=True, timeout=300, env={**os.environ, "COLUMNS": str(width)})
    assert out.returncode == 0, out.stderr
    assert "cos(φ - θ)" in out.stdout and "sin(φ)⋅sin(θ)" not in out.stdout
    lines = out.stdout.splitlines()
    assert max(sum(1 for c in line if not unicodedata.combining(c)) for line in lines) <= width
    assert max(len(line) for line in lines) > 60  # the width is used, not a narrow fixed default
    assert "[constraint string2, multiplier λ2]" in lines
