"""Ctrl-C (SIGINT) stops every integration loop promptly and cleanly, with the partial trajectory.

Each subprocess test starts a run far too long to finish (minutes to hours), sends SIGINT once the run has
started, and checks that the child reports :class:`~lagrange.errors.IntegrationInterrupted` carrying a
partial trajectory, exits cleanly (no segfault, no SystemError) and does so promptly. The bound on the delay
is generous (:data:`PROMPT` s, for a loaded machine): an unchunked compiled loop ignored SIGINT for more than
300 s, and the numba DOP853 loop died with SIGSEGV or SystemError.

The chunked compiled loops must give bit-identical results whatever the chunk sizes (tested by forcing a
pause after every step).
"""

import json
import os
import select
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import lagrange as lg
from lagrange.errors import IntegrationInterrupted
from lagrange.integrate import compiled
from lagrange.integrate.compiled import PAUSED, run_in_chunks

#: seconds allowed between SIGINT and the child's report (generous: 2 cores shared by many processes)
PROMPT = 10.0

CHILD = textwrap.dedent("""\
    import json, sys
    import numpy as np
    import lagrange as lg
    from lagrange.errors import IntegrationInterrupted
    x, y = lg.coordinates("x y")
    sys_ = lg.System([x, y], T=(x.diff(lg.t) ** 2 + y.diff(lg.t) ** 2) / 2,
                     V=x**2 / 2 + 2 * y**2 + x**2 * y**2 / 10)
    ic = {"x": 1.0, "y": 0.5, "x_dot": 0.0, "y_dot": 0.3}
    kw = json.loads(sys.argv[1])
    t_end = kw.pop("t_end", 1e9)  # long fixed-step runs raise max_steps (simulate refuses 1e8 steps by default)
    sys_.simulate(0.01, ic, {}, **kw)  # compile (and warm) everything first
    print("READY", flush=True)
    try:
        sys_.simulate(t_end, ic, {}, n_points=11, **kw)
        print("FINISHED", flush=True)
    except IntegrationInterrupted as exc:
        p = exc.partial
        ok = p is not None and not p.success and 0 < p.t[-1] < t_end and np.all(np.isfinite(p.y))
        print(f"INTERRUPTED t={exc.t} partial_ok={ok}", flush=True)
        sys.exit(130)
""")


def _interrupt(args: list[str], *, wait: float = 1.0, env: dict | None = None) -> tuple[float, int, str, str]:
    """Start ``args``, wait for its READY line, let it run ``wait`` s, send SIGINT: (seconds until its next
    line, exit status, that line, stderr)."""
    # Ctrl-C as from a terminal: a process started in the background by a non-interactive shell inherits
    # SIGINT ignored, and Python then installs no KeyboardInterrupt handler in the child
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env={**os.environ, **(env or {})},
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        line = proc.stdout.readline()
        assert line.startswith("READY"), (line, proc.stderr.read())
        time.sleep(wait)
        assert proc.poll() is None, "the run ended before the interrupt"
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)
        ready, _, _ = select.select([proc.stdout], [], [], 6 * PROMPT)  # never wait forever for the reply
        assert ready, f"no reply {6 * PROMPT:g} s after SIGINT: the child went on running"
        reply = proc.stdout.readline()
        delay = time.monotonic() - sent
        _, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    return delay, proc.returncode, reply, err


def _check_child(options: dict) -> None:
    delay, code, reply, err = _interrupt([sys.executable, "-c", CHILD, json.dumps(options)])
    assert code == 130, (code, reply, err)  # not -11 (SIGSEGV), not 1 (SystemError)
    assert reply.startswith("INTERRUPTED") and "partial_ok=True" in reply, (reply, err)
    assert "SystemError" not in err and "Traceback" not in err, err
    assert delay < PROMPT, delay


# --- cheap: the loops that run Python per step ---------------------------------------------------------

def test_scipy_loop_interrupted_with_partial():
    _check_child({"method": "DOP853", "loop": "scipy", "backend": "python"})


def test_python_fixed_step_loop_interrupted_with_partial():
    _check_child({"method": "gl4", "loop": "scipy", "step": 1e-3, "t_end": 1e5, "max_steps": 10**9})


def test_run_in_chunks_returns_none_on_ctrl_c_and_keeps_state():
    state = {"done": 0}

    def chunk(n):
        if state["done"] >= 3:
            raise KeyboardInterrupt
        state["done"] += 1
        return PAUSED

    assert run_in_chunks(chunk) is None and state["done"] == 3
    assert run_in_chunks(lambda n: 0) == 0


def test_python_fixed_step_interrupt_in_process(monkeypatch):
    """A KeyboardInterrupt raised inside a step of the Python loop: the partial trajectory ends at the last
    completed step, with the states recorded so far (compared with an uninterrupted run)."""
    from lagrange.integrate import gauss_legendre

    x = lg.coordinates("x")
    osc = lg.System([x], T=x.diff(lg.t) ** 2 / 2, V=x**2 / 2)
    ic = {"x": 1.0, "x_dot": 0.0}
    full = osc.simulate(1.0, ic, {}, method="gl4", step=0.01, n_points=11, loop="scipy")
    calls = {"n": 0}
    step = gauss_legendre.GaussLegendre4.step

    def interrupting(self, t_, z, h):
        calls["n"] += 1
        if calls["n"] == 56:
            raise KeyboardInterrupt
        return step(self, t_, z, h)

    monkeypatch.setattr(gauss_legendre.GaussLegendre4, "step", interrupting)
    with pytest.raises(KeyboardInterrupt) as info:
        osc.simulate(1.0, ic, {}, method="gl4", step=0.01, n_points=11, loop="scipy")
    exc = info.value
    assert isinstance(exc, IntegrationInterrupted) and not isinstance(exc, lg.LagrangeError)
    p = exc.partial
    assert not p.success and p.t[-1] == pytest.approx(0.55) and exc.t == pytest.approx(0.55)
    np.testing.assert_array_equal(p.t[:-1], full.t[:6])
    np.testing.assert_array_equal(p.y[:-1], full.y[:6])
    assert abs(p.y[-1, 0] - np.cos(0.55)) < 1e-8  # the state reached, x = cos t


def test_scipy_interrupt_in_process_keeps_output_times(monkeypatch):
    """Ctrl-C inside scipy's stepping (a KeyboardInterrupt in its Python code): the partial trajectory holds
    the output times reached (equal to those of an uninterrupted run) and the last accepted step."""
    from scipy.integrate import DOP853

    x = lg.coordinates("x")
    osc = lg.System([x], T=x.diff(lg.t) ** 2 / 2, V=x**2 / 2)
    ic = {"x": 1.0, "x_dot": 0.0}
    model = osc.compile({})
    full = osc.simulate(10.0, ic, {}, model=model, n_points=11)
    calls = {"n": 0}
    step = DOP853._step_impl

    def interrupting(self):
        calls["n"] += 1
        if calls["n"] == 12:
            raise KeyboardInterrupt
        return step(self)

    monkeypatch.setattr(DOP853, "_step_impl", interrupting)
    with pytest.raises(IntegrationInterrupted) as info:
        osc.simulate(10.0, ic, {}, model=model, n_points=11)
    p = info.value.partial
    k = int(np.sum(np.isin(p.t, full.t)))
    assert 0 < p.t[-1] < 10 and not p.success and k >= 2 and len(p.t) == k + 1
    np.testing.assert_array_equal(p.t[:k], full.t[:k])
    np.testing.assert_array_equal(p.y[:k], full.y[:k])
    assert abs(p.y[-1, 0] - np.cos(p.t[-1])) < 1e-7 and info.value.t == p.t[-1]


# --- compiled loops: numba compilation, slow ---------------------------------------------------------------

@pytest.mark.slow
@pytest.mark.parametrize("options", [
    {"method": "DOP853", "loop": "compiled", "backend": "numba", "rtol": 1e-12, "atol": 1e-12},
    {"method": "RK45", "loop": "compiled", "backend": "numba"},
    {"method": "gl4", "loop": "compiled", "step": 1e-3, "t_end": 1e5, "max_steps": 10**9},
    {"method": "DOP853", "loop": "scipy", "backend": "numba"},
])
def test_compiled_loops_interrupted_with_partial(options):
    pytest.importorskip("numba")
    _check_child(options)


def test_heyoka_interrupted_with_partial():
    """SIGINT during a heyoka run: the partial trajectory holds the initial point and the state reached (it was
    header-only: the output points of an unfinished chunk were lost)."""
    pytest.importorskip("heyoka")
    _check_child({"method": "heyoka", "max_step": 0.01, "t_end": 1e6, "max_steps": 10**9})


@pytest.fixture(scope="module")
def henon():
    pytest.importorskip("numba")
    x, y = lg.coordinates("x y")
    s = lg.System([x, y], T=(x.diff(lg.t) ** 2 + y.diff(lg.t) ** 2) / 2,
                  V=(x**2 + y**2) / 2 + x**2 * y - y**3 / 3)
    return s, {"x": 0.1, "y": 0.2, "x_dot": 0.3, "y_dot": -0.1}


@pytest.mark.slow
@pytest.mark.parametrize("method", ["DOP853", "RK45"])
def test_compiled_rk_chunks_bit_identical(henon, monkeypatch, method):
    s, ic = henon
    model = s.compile({}, backend="numba")
    kw = dict(method=method, loop="compiled", model=model, rtol=1e-10, atol=1e-12, n_points=37)
    monkeypatch.setattr(compiled, "CHUNK_SECONDS", 1e9)  # chunks grow ×8: few pauses
    big = s.simulate(50.0, ic, {}, **kw)
    monkeypatch.setattr(compiled, "CHUNK_SECONDS", 0.0)  # a pause after every step
    one = s.simulate(50.0, ic, {}, **kw)
    np.testing.assert_array_equal(big.y, one.y)
    np.testing.assert_array_equal(big.t, one.t)
    assert big.nfev == one.nfev and big.message == one.message
    ref = s.simulate(50.0, ic, {}, **{**kw, "loop": "scipy"})
    assert np.max(np.abs(one.y - ref.y)) < 1e-8  # and still scipy's algorithm


@pytest.mark.slow
@pytest.mark.parametrize("method", ["gl4", "verlet", "dg"])
def test_compiled_geometric_chunks_bit_identical(henon, monkeypatch, method):
    s, ic = henon
    kw = dict(method=method, loop="compiled", step=0.01, n_points=33)
    monkeypatch.setattr(compiled, "CHUNK_SECONDS", 1e9)
    big = s.simulate(20.0, ic, {}, **kw)
    monkeypatch.setattr(compiled, "CHUNK_SECONDS", 0.0)
    one = s.simulate(20.0, ic, {}, **kw)
    np.testing.assert_array_equal(big.y, one.y)
    np.testing.assert_array_equal(big.t, one.t)
    assert big.message == one.message
    py = s.simulate(20.0, ic, {}, **{**kw, "loop": "scipy"})
    assert np.max(np.abs(one.y - py.y)) < 1e-9  # the Python twin of the scheme


# --- the CLI: one line, exit 130, the partial --csv ---------------------------------------------------------

LONG = """\
name = "slow oscillator"
coordinates = ["x"]
parameters = ["k"]
T = "x_dot**2/2"
V = "k*x**2/2"
[params]
k = 1.0
[initial]
x = 1.0
x_dot = 0.0
[simulate]
t_end = 1e9
n_points = 11
"""


def test_cli_interrupt_writes_partial_csv(tmp_path):
    spec = tmp_path / "slow.toml"
    spec.write_text(LONG)
    out = tmp_path / "partial.csv"
    # the CLI prints nothing before the run with -q; a wrapper announces READY once the run has started
    wrapper = textwrap.dedent(f"""\
        import sys
        from lagrange import cli
        import lagrange.integrate.scipy_ivp as run
        real = run.solve_ivp
        def announced(*a, **k):
            print("READY", flush=True)
            return real(*a, **k)
        run.solve_ivp = announced
        code = cli.main(["simulate", {str(spec)!r}, "-q", "--csv", {str(out)!r}])
        print(f"EXIT {{code}}", flush=True)
        sys.exit(code)
    """)
    delay, code, reply, err = _interrupt([sys.executable, "-c", wrapper], wait=1.5)
    assert code == 130 and reply.strip() == "EXIT 130", (code, reply, err)
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("lagrange: interrupted at t=") and str(out) in lines[0], err
    assert delay < PROMPT
    import pandas as pd

    table = pd.read_csv(out)
    assert len(table) >= 2 and table["t"].iloc[0] == 0.0 and 0 < table["t"].iloc[-1] < 1e9
    assert np.allclose(table["x"], np.cos(table["t"]), atol=1e-6)  # the computed part is right


def test_interrupted_is_a_keyboard_interrupt_not_an_exception():
    exc = IntegrationInterrupted("x", t=1.0)
    assert isinstance(exc, KeyboardInterrupt) and not isinstance(exc, Exception) and exc.partial is None
    assert lg.IntegrationInterrupted is IntegrationInterrupted



def _boxing_failure():
    """What numba raises when Ctrl-C arrives while it boxes a result through Python (the pending signal
    raises in ``_numba_unpickle``)."""
    try:
        raise KeyboardInterrupt
    except KeyboardInterrupt as ki:
        err = SystemError("CPUDispatcher(<function rhs>) returned a result with an exception set")
        err.__cause__ = ki
        return err


def test_interrupt_of_recognizes_numba_boxing_failures():
    from lagrange.integrate.stepper import interrupt_of

    err = _boxing_failure()
    assert interrupt_of(err) is err.__cause__
    assert interrupt_of(SystemError("other")) is None and interrupt_of(ValueError("x")) is None


def test_boxing_failure_in_scipy_and_ensemble_runs_is_an_interrupt(monkeypatch):
    import dataclasses

    from lagrange.sweep import integrate_ensemble

    x = lg.coordinates("x")
    osc = lg.System([x], T=x.diff(lg.t) ** 2 / 2, V=x**2 / 2)
    model = osc.compile({})
    calls = {"n": 0}

    def failing(*args):
        calls["n"] += 1
        if calls["n"] == 100:
            raise _boxing_failure()
        return model.dynamics(*args)

    with pytest.raises(IntegrationInterrupted) as info:
        osc.simulate(10.0, {"x": 1.0, "x_dot": 0.0}, {}, model=dataclasses.replace(model, dynamics=failing),
                     n_points=11, method="RK45")
    assert info.value.partial is not None and 0 < info.value.t < 10
    many = model.rhs_many
    calls["n"] = 0

    def failing_many(*args):
        calls["n"] += 1
        if calls["n"] == 30:
            raise _boxing_failure()
        return many(*args)

    monkeypatch.setattr(type(model), "rhs_many", lambda self, *a: failing_many(*a))
    with pytest.raises(KeyboardInterrupt):
        integrate_ensemble(model, 10.0, [[1.0, 0.0], [0.5, 0.0]])
    monkeypatch.undo()
    with pytest.raises(SystemError):  # a SystemError of another cause is not mistaken for Ctrl-C
        osc.simulate(1.0, {"x": 1.0, "x_dot": 0.0}, {}, model=dataclasses.replace(
            model, dynamics=lambda *a: (_ for _ in ()).throw(SystemError("bug"))), n_points=3)
