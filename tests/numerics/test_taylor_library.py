"""The C Taylor interpreter's library: built at install time or at run time, sealed, verified before loading;
a damaged runtime-built library (truncated, bit-flipped, unsealed) is rebuilt, never loaded (loading a
truncated library used to kill every run with SIGBUS); and Ctrl-C stops a long Taylor run promptly with the
partial trajectory."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from lagrange.codegen import c_interpreter

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def private_cache(monkeypatch, tmp_path):
    """A cache directory of its own and no installed extension module (as in a source checkout)."""
    if c_interpreter.compiler() is None:
        pytest.skip("no C compiler here")
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(c_interpreter, "extension_path", lambda: None)
    c_interpreter.forget()
    yield tmp_path
    c_interpreter.forget()


def _kepler_runs(path: Path) -> bool:
    """Load the library at ``path`` and integrate Kepler's orbit with it against the closed form."""
    from lagrange.bench.problems import kepler_state, kepler_system
    from lagrange.integrate import c_taylor
    from lagrange.integrate.taylor import integrate_taylor

    assert isinstance(c_taylor.load(path), c_taylor.CTaylor)
    model = kepler_system().compile({"m": 1.0, "mu": 1.0})
    tt = np.linspace(0, 7.0, 8)
    sol = integrate_taylor(model, (0, 7.0), kepler_state([0.0])[0], tt, rtol=1e-12, atol=1e-12, engine="c")
    return bool(np.max(np.abs(sol.y - kepler_state(tt))) < 1e-9)


def _damage(path: Path, how: str) -> None:
    data = bytearray(path.read_bytes())
    if how == "truncated":
        path.write_bytes(bytes(data[: len(data) // 2]))
    elif how == "bit-flipped":
        data[len(data) // 2] ^= 0x10
        path.write_bytes(bytes(data))
    else:  # the seal removed: an unauthenticated library is not loaded either
        c_interpreter._seal_path(path).unlink()


@pytest.mark.parametrize("how", ["truncated", "bit-flipped", "unsealed"])
def test_a_damaged_library_is_detected_and_rebuilt(private_cache, how):
    path, reason = c_interpreter.library_path_or_reason()
    assert reason is None and path.parent == private_cache and c_interpreter._verify(path)
    _damage(path, how)
    assert not c_interpreter._verify(path)
    c_interpreter.forget()  # a new process
    again, reason = c_interpreter.library_path_or_reason()
    assert again == path and reason is None and c_interpreter._verify(path)
    assert path.read_bytes()[:4] == b"\x7fELF" or sys.platform != "linux"
    names = sorted(p.name for p in private_cache.iterdir() if p.name != "secret.key")  # the cache's MAC key
    assert names == [path.name, path.name + ".mac"]  # no temp files


@pytest.mark.slow  # a new process imports and derives (several seconds); the in-process tests run by default
def test_a_truncated_library_does_not_kill_a_new_process(private_cache):
    """The crash of issue #21: a truncated ctaylor_*.so made every method='taylor' run die with SIGBUS."""
    path, _ = c_interpreter.library_path_or_reason()
    _damage(path, "truncated")
    code = ("import numpy as np; from lagrange.codegen import c_interpreter as ci; ci.extension_path = lambda: None\n"
            "from lagrange.examples import n_link_pendulum\n"
            "s = n_link_pendulum(1); r = s.simulate(2, {'q1': 0.5, 'q1_dot': 0.0}, {'g': 9.81}, method='taylor')\n"
            "assert 'interpreted tape, c' in r.method, r.method; print('ok', r.y[-1, 0])")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT / ".pp"), str(ROOT)]))
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.startswith("ok") and c_interpreter._verify(path)


def test_the_rebuilt_library_integrates_correctly(private_cache):
    path, _ = c_interpreter.library_path_or_reason()
    _damage(path, "bit-flipped")
    c_interpreter.forget()
    path, _ = c_interpreter.library_path_or_reason()
    assert _kepler_runs(path)


@pytest.mark.slow
def test_the_extension_module_builds_and_runs(tmp_path):
    """What ``pip install`` builds (setup.py's optional extension): compiled with setuptools into a scratch
    directory, importable as a module, and its interpreter integrates Kepler's orbit correctly."""
    if c_interpreter.compiler() is None:
        pytest.skip("no C compiler here")
    import runpy

    from setuptools import Distribution

    extensions = runpy.run_path(str(ROOT / "setup.py"), run_name="setup_probe")["extensions"]()
    assert [e.name for e in extensions] == ["lagrange.integrate._ctaylor"] and extensions[0].optional
    dist = Distribution({"ext_modules": extensions, "script_name": "setup.py", "src_root": str(ROOT)})
    cmd = dist.get_command_obj("build_ext")
    cmd.build_lib, cmd.build_temp = str(tmp_path), str(tmp_path / "tmp")
    cwd = os.getcwd()
    os.chdir(ROOT)  # the sources are relative to the project root, as in a build
    try:
        cmd.ensure_finalized()
        cmd.run()
    finally:
        os.chdir(cwd)
    built = list((tmp_path / "lagrange" / "integrate").glob("_ctaylor*"))
    assert len(built) == 1
    import importlib.util

    spec = importlib.util.spec_from_file_location("lagrange.integrate._ctaylor", built[0])
    module = importlib.util.module_from_spec(spec)  # runs PyInit__ctaylor (not put into sys.modules)
    assert "Taylor" in module.__doc__
    assert _kepler_runs(built[0])


_CHILD = """
import sys, time
import numpy as np
from lagrange.bench.problems import kepler_state, kepler_system
from lagrange.integrate.taylor import integrate_taylor
engine = sys.argv[1]
model = kepler_system().compile({"m": 1.0, "mu": 1.0}, backend="numba" if engine == "series" else "python")
y0 = kepler_state([0.0])[0]
integrate_taylor(model, (0, 1.0), y0, [1.0], rtol=1e-15, atol=1e-15, engine=engine)  # compiles/loads first
T = 1e9  # about 1.6e8 revolutions: hours of work
tt = np.linspace(0, T, 1001)
print("started", flush=True)
try:
    integrate_taylor(model, (0, T), y0, tt, rtol=1e-15, atol=1e-15, engine=engine)
except KeyboardInterrupt as exc:
    caught = time.time()
    part = exc.partial
    ok = part is not None and not part.success and np.all(np.isfinite(part.y))
    print("interrupted", len(part.t), part.message, ok, caught, flush=True)
    sys.exit(0)
print("finished?", flush=True)
sys.exit(3)
"""


@pytest.mark.slow
@pytest.mark.parametrize("engine", ["c", "series"])
def test_ctrl_c_stops_a_long_taylor_run_promptly(engine):
    """SIGINT to a process in a long Taylor run: a clean KeyboardInterrupt carrying the partial trajectory,
    seconds after the signal (the run itself would take hours; the C loop used to answer 19 s late)."""
    from lagrange.integrate.taylor import available_interpreter

    if engine == "c" and available_interpreter() != "c":
        pytest.skip("no C interpreter here")
    if engine == "series":
        pytest.importorskip("numba")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT / ".pp"), str(ROOT)]))
    proc = subprocess.Popen([sys.executable, "-c", _CHILD, engine], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True,  # Ctrl-C as from a terminal, even when this
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # runs in background
    try:
        assert proc.stdout.readline().strip() == "started"
        time.sleep(2.0)
        assert proc.poll() is None  # still integrating
        sent = time.time()
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0, err[-2000:]
    words = out.split()
    assert words[0] == "interrupted" and int(words[1]) >= 1 and "Ctrl-C" in out and words[-2] == "True"
    latency = float(words[-1]) - sent  # signal sent -> KeyboardInterrupt caught in the child
    assert latency < 5.0, latency  # generous on a loaded 2-core machine; the chunks last about 0.1 s
