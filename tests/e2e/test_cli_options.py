"""Every subcommand with every option: honoured (checked against closed forms or the output) or refused with
a one-line message; spec values are defaults that flags override; SIGPIPE; a light ``--help``/``problems``.

Most runs call ``lagrange.cli.main`` in this process (cheap); what needs a fresh interpreter (imported
modules, a closed pipe) runs as a subprocess. Systems are tiny (a 1-DOF oscillator from a TOML spec).
"""

from __future__ import annotations

import csv
import json
import math
import subprocess
import sys
import textwrap

import pytest

from lagrange.cli import BACKENDS, main
from lagrange.integrate.methods import ALL_METHODS

OSC = """\
name = "osc"
coordinates = ["x"]
parameters = ["m", "k"]
T = "m/2*x_dot**2"
V = "k/2*x**2"
[params]
m = 1.0
k = 4.0
[initial]
x = 1.0
x_dot = 0.0
[simulate]
t_end = 1.0
"""

# Coulomb friction: F = dP/dx_dot = -mu m g sign(x_dot) (Wells' sign), so P = -mu m g |x_dot|
BLOCK = """\
name = "block"
coordinates = ["x"]
parameters = ["m", "k", "mu", "g"]
T = "m/2*x_dot**2"
V = "k/2*x**2"
P = "-mu*m*g*Abs(x_dot)"
[params]
m = 1.0
k = 1.0
mu = 0.1
g = 1.0
[initial]
x = 1.0
x_dot = 0.0
[simulate]
t_end = 4.0
"""

PY_OSC = """\
import lagrange as lg
x = lg.coordinates("x")
system = lg.System([x], T=x.diff(lg.t) ** 2 / 2, V=x**2 / 2)
initial = {"x": 1.0, "x_dot": 0.0}
t_end = 1.0
"""

HEAVY = ("sympy", "numpy", "scipy", "numba", "matplotlib", "pandas")


def cli(*args, capsys) -> tuple[int, str, str]:
    """Run ``lagrange args`` in this process: (exit status, stdout, stderr)."""
    try:
        status = main([str(a) for a in args])
    except SystemExit as exc:  # argparse: --help, or a usage error
        status = exc.code
    out = capsys.readouterr()
    return status, out.out, out.err


def state(stdout: str) -> dict[str, float]:
    line = next(ln for ln in stdout.splitlines() if ln.startswith("state at t="))
    return {k: float(v) for k, v in (kv.split("=") for kv in line.split(": ", 1)[1].split(", "))}


def spec(tmp_path, text: str, name: str = "s.toml", extra: str = "") -> str:
    path = tmp_path / name
    path.write_text(text + textwrap.dedent(extra))
    return str(path)


def subprocess_cli(*args, **kw):
    return subprocess.run([sys.executable, "-m", "lagrange.cli", *args], capture_output=True, text=True,
                          timeout=1800, **kw)


# --- speed: nothing heavy is imported for --help, problems or a mistyped id -------------------------------

def _modules_after(code: str) -> set[str]:
    probe = f"import sys\n{code}\nprint(' '.join(m for m in {HEAVY!r} if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    return set(out.stdout.split("\n")[-2].split())


@pytest.mark.parametrize("argv", [["--help"], ["simulate", "--help"], ["problems"], ["problems", "--chapter", "3"],
                                  ["simulate", "ex3.44"]])
def test_help_problems_and_typos_import_nothing_heavy(argv):
    code = f"from lagrange.cli import main\ntry:\n    main({argv!r})\nexcept SystemExit:\n    pass"
    assert _modules_after(code) == set()


def test_import_lagrange_is_lazy_and_every_public_name_resolves():
    assert _modules_after("import lagrange") == set()
    import lagrange

    for name in lagrange.__all__:
        assert getattr(lagrange, name) is not None, name
    assert set(lagrange.__all__) <= set(dir(lagrange))
    import lagrange.sweep.table  # noqa: F401 - importing the subpackage must not rebind the exported function

    assert callable(lagrange.sweep) and lagrange.sweep.__module__ == "lagrange.sweep.driver"
    with pytest.raises(AttributeError):
        lagrange.no_such_name  # noqa: B018


def test_mistyped_id_answers_did_you_mean(capsys):
    status, _, err = cli("simulate", "ex3.44", capsys=capsys)
    assert status == 2 and "did you mean" in err and "ex3.4" in err


def test_help_lists_every_method_and_backend(capsys):
    status, out, _ = cli("simulate", "--help", capsys=capsys)
    assert status == 0
    flat = " ".join(out.split())
    for m in ALL_METHODS:
        assert m in flat, m
    from lagrange.codegen.numeric import BACKENDS as LIB_BACKENDS

    assert BACKENDS == LIB_BACKENDS
    for cmd in ("problems", "derive", "modes", "hamiltonian", "sweep", "bench", "check", "verify"):
        assert cli(cmd, "--help", capsys=capsys)[0] == 0


def test_problems_lists_a_chapter_and_greenspan(capsys):
    status, out, _ = cli("problems", "--chapter", "3", capsys=capsys)
    assert status == 0 and "ex3.2" in out and "ex4.1" not in out
    status, out, _ = cli("problems", capsys=capsys)
    assert status == 0 and "greenspan-14" in out and "Chapter 17" in out


# --- simulate: spec values are defaults, flags override, methods reachable --------------------------------

def test_spec_method_and_tolerance_are_honoured_and_flags_override(tmp_path, capsys):
    path = spec(tmp_path, OSC, extra='method = "LSODA"\nrtol = 1e-4\n')
    status, out, _ = cli("simulate", path, "-q", capsys=capsys)
    assert status == 0 and "method LSODA" in out and "rtol 0.0001" in out
    loose = abs(state(out)["x"] - math.cos(2.0))  # x = cos(2t), omega^2 = k/m = 4
    assert 1e-8 < loose < 1e-2
    status, out, _ = cli("simulate", path, "-q", "--method", "rk45", "--rtol", "1e-10", "--atol", "1e-12",
                         capsys=capsys)
    assert status == 0 and "method RK45" in out and "rtol 1e-10, atol 1e-12" in out
    tight = abs(state(out)["x"] - math.cos(2.0))
    assert tight < 1e-8 and tight < loose / 100


def test_spec_fixed_step_method_and_step_are_honoured(tmp_path, capsys):
    path = spec(tmp_path, OSC, extra='method = "gl4"\nstep = 0.01\n')
    status, out, _ = cli("simulate", path, "-q", capsys=capsys)
    assert status == 0 and "method gl4 (fixed step h=0.01" in out and "step 0.01" in out
    assert abs(state(out)["x"] - math.cos(2.0)) < 1e-7  # 4th order, h = 0.01
    # --method switches to an adaptive method: the spec's step no longer applies
    status, out, _ = cli("simulate", path, "-q", "--method", "Radau", capsys=capsys)
    assert status == 0 and "method Radau" in out


@pytest.mark.parametrize("method", ["dop853", "Taylor", "AUTO", "rk23", "bdf", "midpoint", "GL6", "verlet", "dg",
                                    "Verlet8"])
def test_every_method_is_reachable_case_insensitively(tmp_path, method, capsys):
    path = spec(tmp_path, OSC)
    fixed = method.lower() in ("midpoint", "gl6", "verlet", "dg", "verlet8")
    extra = ["--step", "0.005"] if fixed else ["--rtol", "1e-8"]
    status, out, err = cli("simulate", path, "-q", "--method", method, *extra, capsys=capsys)
    assert status == 0, err
    assert abs(state(out)["x"] - math.cos(2.0)) < 1e-4
    if method.lower() != "auto":
        assert f"method {method.lower()}" in out.lower()
    else:  # the choice and the reason are printed
        assert "auto: " in out and "stiff" in out


def test_python_spec_options_params_initial_and_overrides(tmp_path, capsys):
    path = tmp_path / "osc.py"
    path.write_text(textwrap.dedent("""\
        import lagrange as lg
        x = lg.coordinates("x")
        m, k = lg.parameters("m k")
        system = lg.System([x], T=m / 2 * x.diff(lg.t) ** 2, V=k / 2 * x**2)
        params = {m: 1.0, k: 4.0}
        initial = {x: 1.0, x.diff(lg.t): 0.0}
        t_end = 1.0
        options = {"method": "RK23", "rtol": 1e-7}
        """))
    status, out, _ = cli("simulate", path, "-q", capsys=capsys)
    assert status == 0 and "method RK23" in out and "rtol 1e-07" in out
    # --param k=9 and --initial x=2 replace the spec's Symbol-keyed values: x = 2 cos(3 t)
    status, out, _ = cli("simulate", path, "-q", "--param", "k=9", "--initial", "x=2", "--t-end", "0.5",
                         "--rtol", "1e-11", capsys=capsys)
    assert status == 0
    assert abs(state(out)["x"] - 2 * math.cos(1.5)) < 1e-8
    assert "state at t=0.5" in out


def test_corpus_problem_with_backend_outputs_and_equations(tmp_path, capsys):
    png, table = tmp_path / "p.png", tmp_path / "t.csv"
    status, out, _ = cli("simulate", "ex3.2", "--t-end", "0.5", "--backend", "reference", "--method", "dop853",
                         "--plot", png, "--csv", table, "--no-progress", capsys=capsys)
    assert status == 0 and "ex3.2:" in out and "backend reference" in out  # equations printed (no -q)
    assert png.stat().st_size > 5_000
    rows = list(csv.reader(table.open()))
    assert rows[0][0] == "t" and float(rows[-1][0]) == pytest.approx(0.5)


def test_friction_treatment_is_honoured(tmp_path, capsys):
    path = spec(tmp_path, BLOCK)
    # closed form: x = 0.1 + 0.9 cos t on [0, pi], then x = -0.1 - 0.7 cos(t - pi)
    exact = -0.1 - 0.7 * math.cos(4.0 - math.pi)
    results = {}
    for friction in ("events", "regularize"):
        status, out, err = cli("simulate", path, "-q", "--friction", friction, capsys=capsys)
        assert status == 0, err
        assert f"friction {friction}" in out
        results[friction] = state(out)["x"]
    assert abs(results["events"] - exact) < 1e-7
    assert abs(results["regularize"] - exact) < 1e-4


def test_quiet_and_progress(tmp_path, capsys, monkeypatch):
    path = spec(tmp_path, OSC)
    status, out, err = cli("simulate", path, "-q", capsys=capsys)
    assert status == 0 and "x_dot''" not in out and "x''" not in out and err == ""
    monkeypatch.setenv("LAGRANGE_PROGRESS", "1")  # report although stderr is not a terminal
    status, out, err = cli("simulate", path, capsys=capsys)
    assert status == 0 and "lagrange: integrating" in err
    status, out, err = cli("simulate", path, "--no-progress", capsys=capsys)
    assert status == 0 and err == ""
    status, out, err = cli("verify", "ex1.1", capsys=capsys)
    assert status == 0 and "verifying" in err
    status, out, err = cli("derive", path, capsys=capsys)
    assert status == 0 and f"lagrange: loading {path}" in err
    status, out, err = cli("verify", "ex1.1", "-q", capsys=capsys)
    assert status == 0 and err == ""


# --- bad input: exit 2, one line naming the problem, never an internal error ------------------------------

BAD = [
    (["simulate", "{osc}", "--method", "rk4"], "unknown method 'rk4'"),
    (["simulate", "{osc}", "--method", "gl4"], "give --step"),
    (["simulate", "{osc}", "--method", "gl4", "--step", "0.1", "--rtol", "1e-3"], "no tolerances"),
    (["simulate", "{osc}", "--step", "0.1"], "fixed-step methods"),
    (["simulate", "{osc}", "--param", "zz=1"], "unknown parameter of"),
    (["simulate", "{osc}", "--initial", "y=1"], "valid: x, x_dot"),
    (["simulate", "{osc}", "--param", "m=abc"], "not a number"),
    (["simulate", "{osc}", "--param", "m"], "name=value"),
    (["simulate", "{osc}", "--initial", "x=nan"], "not a finite number"),
    (["simulate", "{osc}", "--rtol", "-1"], "positive"),
    (["simulate", "{osc}", "--t-end", "0"], "positive"),
    (["simulate", "{osc}", "--backend", "fortran"], "invalid choice"),
    (["simulate", "{osc}", "--friction", "sticky"], "invalid choice"),
    (["simulate", "{osc}", "--model", "rigid"], "greenspan-N only"),
    (["simulate", "{osc}", "--plot", "{tmp}/nodir/p.png"], "does not exist"),
    (["simulate", "{osc}", "--plot", "{tmp}/p.xyz"], "write a .png"),
    (["simulate", "{osc}", "--animate", "{tmp}/a.avi"], ".gif or .mp4"),
    (["simulate", "{osc_bad_method}"], "[simulate] method: unknown method 'leapfrog'"),
    (["simulate", "{osc_bad_rtol}"], "[simulate] rtol: must be a positive number"),
    (["simulate", "{py_bad_option}"], "unknown simulate option(s) foo"),
    (["simulate", "{osc_bad_friction}"], "[simulate] friction: 'sticky' is not one of events, regularize"),
    (["simulate", "ex3.44"], "did you mean"),
    (["simulate", "ex7.1"], "no equations of motion"),
    (["simulate", "greenspan-99"], "greenspan-1 … greenspan-14"),
    (["simulate", "greenspan-1", "--model", "molecular", "--rtol", "1e-3"], "--rtol does not apply"),
    (["simulate", "greenspan-1", "--model", "molecular", "--atol", "1e-3"], "--atol does not apply"),
    (["simulate", "greenspan-1", "--model", "molecular", "--backend", "numba"], "--backend does not apply"),
    (["simulate", "greenspan-1", "--model", "molecular", "--friction", "events"], "--friction does not apply"),
    (["simulate", "greenspan-1", "--model", "molecular", "--initial", "X=1"], "--initial does not apply"),
    (["simulate", "greenspan-1", "--model", "molecular", "--animate", "{tmp}/a.gif"], "--animate does not apply"),
    (["simulate", "greenspan-1", "--model", "molecular", "--method", "gl4"], "discrete gradient (dg) only"),
    (["simulate", "greenspan-1", "--model", "molecular", "--param", "B=1"], "valid: A, g"),
    (["derive", "{tmp}/missing.toml"], "does not exist"),
    (["derive", "nosuch"], "no problem with id"),
    (["hamiltonian", "nosuch"], "no problem with id"),
    (["check", "{osc}", "--param", "zz=1"], "unknown parameter"),
    (["check", "{osc}", "--samples", "0"], "less than 1"),
    (["verify", "--chapter", "99"], "no problems in chapter 99"),
    (["problems", "--chapter", "99"], "no problems in chapter 99"),
    (["sweep", "{osc}", "--over", "k"], "name=start:stop:num"),
    (["sweep", "{osc}", "--over", "zz=1:2:2", "--workers", "0"], "cannot sweep zz"),
    (["sweep", "{osc}", "--over", "k=1:2:2", "--resume"], "--resume needs --store"),
    (["sweep", "{osc}", "--over", "k=1:2:2", "--param", "zz=1"], "unknown parameter"),
    (["sweep", "{osc}", "--over", "k=1:2:2", "--method", "gl4"], "give --step"),
    (["sweep", "{osc}", "--over", "k=1:2:2", "--workers", "-1"], "less than 0"),
    (["sweep", "{osc}", "--over", "k=1:2:2", "--random", "0"], "less than 1"),
    (["sweep", "{osc}", "--over", "k=1:2:2", "--out", "{tmp}/t.xlsx"], ".csv or .parquet"),
    (["sweep", "greenspan", "--over", "V=1:2:2", "--param", "g=1"], "--param does not apply"),
    (["sweep", "greenspan", "--over", "V=1:2:2", "--initial", "X=1"], "--initial does not apply"),
    (["sweep", "greenspan", "--over", "zz=1:2:2"], "--over V="),
    (["sweep", "greenspan-3", "--over", "V=1:2:2"], "lagrange sweep greenspan"),
    (["bench", "--problem", "nosuch"], "unknown benchmark problem"),
    (["bench", "--out", "{osc}"], "is not a folder"),
    (["simulate", "greenspan-1", "--model", "molecular", "--step", "1e-3", "--t-end", "1e-4"], "longer than the run"),
]


@pytest.mark.parametrize("argv, message", BAD, ids=[" ".join(a)[:60] for a, _ in BAD])
def test_bad_input_is_one_clear_line(tmp_path, capsys, argv, message):
    files = {"osc": spec(tmp_path, OSC), "tmp": str(tmp_path),
             "osc_bad_method": spec(tmp_path, OSC, "m.toml", 'method = "leapfrog"\n'),
             "osc_bad_rtol": spec(tmp_path, OSC, "r.toml", 'rtol = "tight"\n'),
             "osc_bad_friction": spec(tmp_path, OSC, "f.toml", 'friction = "sticky"\n'),
             "py_bad_option": spec(tmp_path, PY_OSC, "o.py", 'options = {"foo": 1}\n')}
    status, out, err = cli(*(a.format(**files) for a in argv), capsys=capsys)
    assert status == 2, (out, err)
    assert message in err, err
    assert "internal error" not in err and "Traceback" not in err
    assert err.strip().splitlines()[-1].startswith(("lagrange: error:", "lagrange ")), err


# --- the other subcommands, every option -------------------------------------------------------------------

def test_derive_hamiltonian_modes_check_verify(tmp_path, capsys):
    path = spec(tmp_path, OSC)
    status, out, _ = cli("derive", path, capsys=capsys)
    assert status == 0 and "k" in out
    status, out, _ = cli("derive", path, "--latex", "--no-progress", capsys=capsys)
    assert status == 0 and ("\\frac" in out or "\\ddot" in out)
    status, out, _ = cli("hamiltonian", path, "--no-progress", capsys=capsys)
    assert status == 0 and "H =" in out
    status, out, _ = cli("modes", path, "--about", "x=0", "--param", "m=1", "--param", "k=4", "--json",
                         capsys=capsys)
    frequencies = [m["frequency"] for m in json.loads(out)["modes"]]
    assert status == 0 and frequencies == pytest.approx([2.0], rel=1e-14)  # omega = sqrt(k/m)
    status, out, _ = cli("check", "ex3.2", "--samples", "2", "--seed", "3", "--param", "m=2", "--no-progress",
                         capsys=capsys)
    assert status == 0, out
    status, out, _ = cli("verify", "ex1.1", "--chapter", "1", "-v", "--no-progress", capsys=capsys)
    assert status == 0 and "ok   ex1.1" in out and "0 failed" in out
    status, out, _ = cli("verify", "ex1.1", "--chapter", "2", capsys=capsys)  # filtered out: nothing checked
    assert status == 0 and out.startswith("0 problems")


def test_sweep_every_option(tmp_path, capsys):
    path = spec(tmp_path, OSC)
    out_csv, store = tmp_path / "table.csv", tmp_path / "store.csv"
    argv = ["sweep", path, "--over", "k=1,4", "--workers", "0", "--t-end", "0.5", "--method", "dop853",
            "--rtol", "1e-10", "--atol", "1e-12", "--backend", "python", "--param", "m=1", "--initial", "x=2",
            "--out", out_csv, "--store", store, "--no-progress"]
    status, out, err = cli(*argv, capsys=capsys)
    assert status == 0, err
    rows = list(csv.DictReader(out_csv.open()))
    assert len(rows) == 2
    for row in rows:  # x = 2 cos(sqrt(k) t)
        assert float(row["final_x"]) == pytest.approx(2 * math.cos(math.sqrt(float(row["k"])) * 0.5), abs=1e-8)
    status, out, err = cli(*argv[:-1], "--resume", "-q", capsys=capsys)  # everything is stored: nothing reruns
    assert status == 0, err
    status, out, err = cli("sweep", path, "--over", "k=1:4:3", "--random", "2", "--seed", "1", "--workers", "0",
                           "--method", "gl4", "--step", "0.01", "--friction", "events", "-q", capsys=capsys)
    assert status == 0, err
    assert "2 runs" in out


@pytest.mark.slow  # compiles the discrete-gradient loop with numba (tens of seconds when not cached)
def test_greenspan_molecular_every_option(tmp_path, capsys):
    table, png = tmp_path / "m.csv", tmp_path / "m.png"
    status, out, err = cli("simulate", "greenspan-2", "--model", "molecular", "--t-end", "0.01", "--step", "2e-5",
                           "--method", "DG", "--param", "g=0.5", "--param", "A=1e6", "--csv", table, "--plot", png,
                           "-q", capsys=capsys)
    assert status == 0, err
    assert "dt = 2e-05" in out and "500 steps" in out
    rows = list(csv.reader(table.open()))
    assert rows[0][:2] == ["t", "x1_x"] and len(rows) == 502 and float(rows[-1][0]) == pytest.approx(0.01)
    assert png.stat().st_size > 5_000


# --- SIGPIPE -----------------------------------------------------------------------------------------------

def test_closed_pipe_ends_quietly():
    proc = subprocess.Popen([sys.executable, "-m", "lagrange.cli", "problems", "--chapter", "3"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()  # the reader is gone before anything is written (like `| head -0`)
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=120) == 141
    assert err == ""


# --- slow: whole runs ------------------------------------------------------------------------------------

@pytest.mark.slow
def test_greenspan_rigid_every_option(tmp_path):
    import numpy as np

    from lagrange.discrete.greenspan import EXAMPLES, initial_vertices

    table, png = tmp_path / "g.csv", tmp_path / "g.png"
    out = subprocess_cli("simulate", "greenspan-1", "--t-end", "0.5", "--method", "lsoda", "--rtol", "1e-7",
                         "--atol", "1e-9", "--backend", "python", "--param", "g=0.5", "--initial", "X=0.25",
                         "--csv", str(table), "--plot", str(png), "--model", "rigid", "-q", "--no-progress")
    assert out.returncode == 0, out.stderr
    assert "LSODA, rtol 1e-07, atol 1e-09" in out.stdout
    rows = list(csv.DictReader(table.open()))
    assert float(rows[0]["X"]) == 0.25 and float(rows[0]["Y"]) == 0.0 and float(rows[-1]["t"]) == 0.5
    # g honoured: E(0) = 1/2 sum |v|^2 + g (z2 + z3 + z4) of the paper's initial state, unit masses
    x, v = initial_vertices(EXAMPLES[1])
    assert float(rows[0]["energy"]) == pytest.approx(0.5 * float(np.sum(v**2)) + 0.5 * float(x[1:, 2].sum()),
                                                     rel=1e-9)
    assert png.stat().st_size > 5_000


@pytest.mark.slow
def test_animation_with_progress(tmp_path):
    gif = tmp_path / "a.gif"
    env = {**__import__("os").environ, "LAGRANGE_PROGRESS": "1"}
    out = subprocess_cli("simulate", "ex3.2", "--t-end", "1", "--animate", str(gif), env=env)
    assert out.returncode == 0, out.stderr
    assert gif.stat().st_size > 5_000
    assert "lagrange: writing the animation" in out.stderr and "lagrange: integrating ex3.2" in out.stderr


def test_compilation_note(tmp_path, monkeypatch, capsys):
    from lagrange.codegen.numba_backend import write_module
    from lagrange.progress import reporting

    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv("LAGRANGE_PROGRESS", "1")
    with reporting():
        write_module("probe", "x = 1\n")  # a new module: numba will compile it once
        write_module("probe", "x = 1\n")  # cached: no note
    err = capsys.readouterr().err
    assert err.count("compiling the generated probe code with numba (one time") == 1
    with reporting(False):
        write_module("probe", "x = 2\n")
    assert capsys.readouterr().err == ""


@pytest.mark.slow
def test_bench_quick_one_problem(tmp_path):
    out = subprocess_cli("bench", "--quick", "--problem", "kepler", "--no-heyoka", "--out", str(tmp_path),
                         "--no-progress")
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "workprecision.md").exists()


@pytest.mark.slow
def test_sweep_greenspan_map():
    out = subprocess_cli("sweep", "greenspan", "--over", "V=8,16", "--over", "alpha_deg=15", "--t-end", "2",
                         "--method", "dop853", "--rtol", "1e-7", "--workers", "0", "--no-progress")
    assert out.returncode == 0, out.stderr
    assert "2 runs" in out.stdout
