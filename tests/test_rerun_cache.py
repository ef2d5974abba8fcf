"""Re-runs in a new process (issue #23 item 4): a second process that simulates the same declared model with
``method="taylor"`` loads the derived equations, the generated source and the Taylor tape from the on-disk
cache (:func:`lagrange.codegen.derivation_cache.statistics` counts hits and misses); a changed model misses;
a tampered tape entry is refused and rebuilt, and the rebuilt run gives the same answer as the cold one.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import warnings

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange.codegen import derivation_cache as dc
from lagrange.codegen import tape as tape_module
from lagrange.errors import CacheIntegrityWarning

_CHILD = textwrap.dedent("""
    import json, sys, warnings
    import lagrange as lg
    from lagrange.codegen import derivation_cache as dc
    x = lg.coordinates("x")
    m, k = lg.parameters("m k")
    V = k * x**2 / 2 + float(sys.argv[1]) * x**4
    s = lg.System([x], T=m * x.diff(lg.t)**2 / 2, V=V, name="oscillator")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        tr = s.simulate(2.0, {"x": 0.5, "x_dot": 0.0}, {"m": 1.0, "k": 4.0}, method="taylor", rtol=1e-12,
                        atol=1e-12, n_points=5)
    print(json.dumps({"stats": dc.statistics(), "final": tr.y[-1].tolist(), "method": tr.method,
                      "warnings": [type(w.message).__name__ for w in caught],
                      "loaded": sorted(m for m in sys.modules if m.split(".")[0] in ("scipy", "numba", "symengine")
                                       or m in ("numpy.f2py", "numpy.testing", "importlib.metadata"))}))
""")

#: what a re-run with ``method="taylor"`` does not use, so ``import lagrange`` plus the run must not import it:
#: scipy (its integrators, ``scipy.linalg``), numba, symengine (the derivation is loaded, not redone),
#: lambdify's numpy namespace (``numpy.f2py``, ``numpy.testing``) and ``importlib.metadata`` (symengine's version)
#: (hashlib and hmac load OpenSSL, about 5 ms: the caches use the built-in BLAKE2b, lagrange.codegen.digest)
_NOT_ON_A_TAYLOR_RERUN = ("scipy", "numba", "symengine", "numpy.f2py", "numpy.testing", "importlib.metadata",
                          "hashlib", "_hashlib", "hmac", "secrets")


def _run(cache, quartic: float = 0.0) -> dict:
    env = dict(os.environ, LAGRANGE_CACHE_DIR=str(cache))
    env.pop(dc.ENV_VAR, None)  # the default: on
    r = subprocess.run([sys.executable, "-c", _CHILD, repr(quartic)], env=env, capture_output=True, text=True,
                       timeout=240)
    assert r.returncode == 0, r.stderr[-3000:]
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_fresh_process_rerun_hits_changed_model_misses_tampered_tape_refused(tmp_path):
    """Four fresh processes on one cache directory: cold (misses, entries written), warm (every entry a hit,
    nothing rebuilt), a changed potential (misses again) and, after one byte of the tape entry is flipped,
    the same model again (the tape is refused, rebuilt and the answer unchanged)."""
    cold = _run(tmp_path)
    assert cold["method"].startswith("taylor")
    for kind in ("derived", "source", "code", "tape"):
        assert cold["stats"][kind]["hit"] == 0 and cold["stats"][kind]["miss"] >= 1, (kind, cold["stats"])
    tapes = sorted(tmp_path.glob("tape_*.arrays"))
    assert len(tapes) == 1
    # closed form of the harmonic oscillator: x = 0.5 cos(2 t)
    assert np.allclose(cold["final"], [0.5 * np.cos(4.0), -1.0 * np.sin(4.0), 0.0][: len(cold["final"])],
                       atol=1e-9)

    warm = _run(tmp_path)
    assert warm["final"] == cold["final"]  # bit for bit
    for kind in ("derived", "tape"):
        assert warm["stats"][kind] == {"hit": 1, "miss": 0, "refused": 0}, (kind, warm["stats"])
    # code: the right-hand side and the diagnostics (the energy check of the run's verdict)
    assert warm["stats"]["code"] == {"hit": 2, "miss": 0, "refused": 0}, warm["stats"]
    assert warm["stats"]["source"]["miss"] == 0
    assert not [m for m in warm["loaded"] if m.split(".")[0] in _NOT_ON_A_TAYLOR_RERUN
                or m in _NOT_ON_A_TAYLOR_RERUN], warm["loaded"]

    changed = _run(tmp_path, quartic=0.25)
    assert changed["stats"]["derived"]["miss"] == 1 and changed["stats"]["tape"] == {"hit": 0, "miss": 1,
                                                                                       "refused": 0}
    assert len(list(tmp_path.glob("tape_*.arrays"))) == 2
    assert not np.allclose(changed["final"], cold["final"])

    data = bytearray(tapes[0].read_bytes())
    data[-40] ^= 0x01  # inside the payload: the seal no longer matches
    tapes[0].write_bytes(bytes(data))
    tampered = _run(tmp_path)
    assert tampered["stats"]["tape"] == {"hit": 0, "miss": 1, "refused": 1}, tampered["stats"]
    assert "CacheIntegrityWarning" in tampered["warnings"]
    assert tampered["final"] == cold["final"]


_TOP = textwrap.dedent("""
    import json, sys
    import lagrange as lg
    from lagrange.codegen import derivation_cache as dc
    psi, th, ph = lg.coordinates("psi theta phi")
    M, g, l, I1, I3 = lg.parameters("M g l I1 I3")
    body = lg.RigidBody(M, (I1, I1, I3), orientation=lg.EulerAngles(psi, th, ph), com=(0, 0, l))
    top = lg.System([psi, th, ph], bodies=[body], V=M * g * body.centre_of_mass[2], name="top")
    initial = {"psi": 0.0, "theta": 0.6, "phi": 0.0, "psi_dot": 1.0, "theta_dot": 0.0, "phi_dot": 60.0}
    params = {"M": 1.0, "g": 9.81, "l": 0.2, "I1": 0.05, "I3": 0.02}
    tr = top.simulate(0.5, initial, params, method="taylor", rtol=1e-12, atol=1e-12, n_points=3)
    loaded = sorted(sys.modules)  # before the energy is asked for (the diagnostics are built on first use)
    R_built = "R" in vars(body)
    h = tr.energy.tolist()
    print(json.dumps({"stats": dc.statistics(), "final": tr.y[-1].tolist(), "energy": [h[0], h[-1]],
                      "loaded": loaded, "R_built": R_built}))
""")


def test_rerun_of_a_top_with_euler_angles_loads_everything_and_imports_no_scipy(tmp_path):
    """A heavy top declared with Euler angles (its run checks the mass matrix's condition at the initial state:
    the gimbal-lock warning) re-run in a fresh process: every entry a hit, the same final state bit for bit, the
    energy conserved, and none of the modules a Taylor re-run does not use imported."""
    env = dict(os.environ, LAGRANGE_CACHE_DIR=str(tmp_path))
    env.pop(dc.ENV_VAR, None)
    runs = []
    for _ in range(2):
        r = subprocess.run([sys.executable, "-c", _TOP], env=env, capture_output=True, text=True, timeout=240)
        assert r.returncode == 0, r.stderr[-3000:]
        runs.append(json.loads(r.stdout.strip().splitlines()[-1]))
    cold, warm = runs
    assert cold["stats"]["derived"] == {"hit": 0, "miss": 1, "refused": 0}
    for kind in ("derived", "tape"):
        assert warm["stats"][kind] == {"hit": 1, "miss": 0, "refused": 0}, (kind, warm["stats"])
    # code: the right-hand side and the diagnostics (the energy check of the run's verdict)
    assert warm["stats"]["code"] == {"hit": 2, "miss": 0, "refused": 0}, warm["stats"]
    assert warm["final"] == cold["final"]
    h0, h1 = warm["energy"]
    assert abs(h1 - h0) <= 1e-9 * abs(h0)  # a conservative top: T + V is an integral of the motion
    unused = [m for m in warm["loaded"] if m.split(".")[0] in _NOT_ON_A_TAYLOR_RERUN or m in _NOT_ON_A_TAYLOR_RERUN]
    assert not unused, unused
    assert not warm["R_built"]  # the rotation matrix is not needed: the centre of mass takes its z column


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv(dc.ENV_VAR, "1")
    return tmp_path


def _pendulum() -> lg.System:
    q = lg.coordinates("q")
    g = lg.parameters("g")
    return lg.System([q], T=q.diff(lg.t) ** 2 / 2, V=-g * sp.cos(q))


def _tape_arrays_equal(a, b) -> bool:
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in ("const_code", "const_vals", "code", "consts",
                                                                       "mass", "force")) \
        and (a.n, a.nz, a.n_slots, a.slot_t, a.power) == (b.n, b.nz, b.n_slots, b.slot_t, b.power)


def test_loaded_tape_equals_built_tape_and_a_forged_one_is_refused(cache, monkeypatch):
    """In process: the tape read back from disk equals the tape built from the equations (a second build of
    the same equations, cache off, is the independent truth); an entry re-sealed with the right key but
    holding an out-of-range slot fails the shape/slot check and is rebuilt (never handed to the C
    interpreter)."""
    eqs = _pendulum().derived
    built = tape_module.tape_of(eqs)
    tape_module._TAPES.clear()
    before = dc.statistics()["tape"]
    loaded = tape_module.tape_of(_pendulum().derived)
    assert dc.statistics()["tape"]["hit"] == before["hit"] + 1
    monkeypatch.setenv(dc.ENV_VAR, "0")
    assert _tape_arrays_equal(loaded, tape_module.build_tape(eqs)) and _tape_arrays_equal(loaded, built)

    arrays = tape_module._tape_arrays(built)
    bad = dict(arrays, code=arrays["code"].copy())
    bad["code"][0, 3] = int(arrays["n_slots"]) + 5  # writes outside the tape's slots
    assert tape_module._tape_valid(arrays) and not tape_module._tape_valid(bad)
    monkeypatch.setenv(dc.ENV_VAR, "1")
    entry = next(cache.glob("tape_*.arrays"))
    key = entry.stem.split("_", 1)[1]
    dc._write(entry, key, dc._pack_arrays(bad))  # sealed with the right key: only the content check can catch it
    tape_module._TAPES.clear()
    before = dc.statistics()["tape"]
    with warnings.catch_warnings():
        warnings.simplefilter("error", CacheIntegrityWarning)
        again = tape_module.tape_of(_pendulum().derived)
    after = dc.statistics()["tape"]
    assert after["refused"] == before["refused"] + 1 and after["hit"] == before["hit"]
    assert _tape_arrays_equal(again, built)


def test_loaded_equations_are_the_derived_ones(cache, monkeypatch):
    """Equations loaded from a derived entry (Add, Mul and Pow rebuilt from their stored arguments without
    evaluation) print, compare and hash exactly as a fresh derivation with the cache off (the truth)."""
    from lagrange.examples import n_link_pendulum

    first = n_link_pendulum(3).derived  # miss: derived and stored
    before = dc.statistics()["derived"]["hit"]
    loaded = n_link_pendulum(3).derived  # a new System: read back from the entry
    assert dc.statistics()["derived"]["hit"] == before + 1 and loaded is not first
    monkeypatch.setenv(dc.ENV_VAR, "0")
    fresh = n_link_pendulum(3).derived
    for name in ("mass_matrix", "forcing", "kinetic", "potential"):
        a, b = getattr(loaded, name), getattr(fresh, name)
        assert sp.srepr(a) == sp.srepr(b) and a == b and hash(a) == hash(b), name


def test_mass_matrix_function_matches_the_reference_lambdify():
    """``NumericModel.mass_matrix`` (the CSE'd function of M alone, on the math module, which the gimbal-lock
    check of every run with Euler angles calls) equals M from the reference functions (plain lambdify of M and
    f on numpy, the oracle) at random states: a heavy top (M depends on θ) and a pendulum whose length is
    prescribed in time (M depends on t)."""
    psi, th, ph = lg.coordinates("psi theta phi")
    M_, g, l_, I1, I3 = lg.parameters("M g l I1 I3")
    body = lg.RigidBody(M_, (I1, I1, I3), orientation=lg.EulerAngles(psi, th, ph), com=(0, 0, l_))
    top = lg.System([psi, th, ph], bodies=[body], V=M_ * g * body.centre_of_mass[2])
    q = lg.coordinates("q")
    m, a = lg.parameters("m a")
    length = 1 + a * sp.sin(lg.t)
    swing = lg.System([q], bodies=[lg.Particle(m, (length * sp.sin(q), -length * sp.cos(q)))],
                      V=-m * g * length * sp.cos(q))
    rng = np.random.default_rng(7)
    cases = ((top, {"M": 1.3, "g": 9.81, "l": 0.2, "I1": 0.05, "I3": 0.02}), (swing, {"m": 0.7, "a": 0.3, "g": 9.81}))
    for system, params in cases:
        model = system.compile(params)
        for _ in range(5):
            t0, y = float(rng.uniform(0, 3)), rng.uniform(-1.0, 1.0, 2 * model.n)
            ref, _ = model.mass_and_forcing(t0, y)
            got = model.mass_matrix(t0, y)
            assert got.shape == (model.n, model.n)
            np.testing.assert_allclose(got, ref, rtol=1e-13, atol=1e-15)


def test_array_records_round_trip_and_refuse_damage():
    """The tape entry's container: names and dtypes survive; a truncated record, a repeated name, an object
    array or trailing bytes raise (the entry is then refused and rebuilt), never load as something else."""
    arrays = {"code": np.arange(12, dtype=np.int32).reshape(3, 4), "x": np.linspace(0, 1, 5), "ok": np.array(True),
              "transposed": np.arange(6.0).reshape(2, 3).T, "z": np.array([1 + 2j]), "u": np.array([3], np.uint8),
              "empty": np.zeros((0, 3)), "big-endian": np.array([1.5, 2.5], dtype=">f8")}
    packed = dc._pack_arrays(arrays)
    back = dc._unpack_arrays(packed)
    assert list(back) == list(arrays)
    assert all(back[k].dtype == v.dtype and back[k].shape == v.shape and np.array_equal(back[k], v)
               and back[k].flags.writeable for k, v in arrays.items())
    for damaged in (packed[:-3], packed + b"\x01", packed + packed[: len(packed) // 2]):
        with pytest.raises(Exception):  # noqa: B017, PT011 - numpy's or ours: any refusal will do
            dc._unpack_arrays(damaged)
    with pytest.raises(ValueError):
        dc._pack_arrays({"o": np.array([object()])})


def test_compiled_code_entry_loads_and_damage_is_refused(tmp_path, monkeypatch):
    """The python backend's compiled module: a second process-like load (the in-process memo cleared) reads
    the marshalled code and gives the same function; a damaged or foreign entry is refused and recompiled."""
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv(dc.ENV_VAR, "1")
    source = "def rhs(t, y, p):\n    return [y[1], -p[0] * y[0]]\n"
    dc._CODE.clear()
    first = dc.cached_code(source, "<lagrange rhs>")
    entry = next(tmp_path.glob("code_*.pyc"))
    dc._CODE.clear()
    before = dc.statistics()["code"]
    again = dc.cached_code(source, "<lagrange rhs>")
    assert dc.statistics()["code"]["hit"] == before["hit"] + 1 and again is not first
    namespace: dict = {}
    exec(again, namespace)  # noqa: S102 - the test's own source
    assert namespace["rhs"](0.0, [0.5, 0.0], [4.0]) == [0.0, -2.0]
    key = entry.stem.split("_", 1)[1]
    dc._write(entry, key, b"not marshalled code")  # sealed with the right key: only the load can refuse it
    dc._CODE.clear()
    before = dc.statistics()["code"]
    rebuilt = dc.cached_code(source, "<lagrange rhs>")
    after = dc.statistics()["code"]
    assert after["refused"] == before["refused"] + 1 and after["hit"] == before["hit"]
    assert rebuilt.co_filename == "<lagrange rhs>"
    dc._CODE.clear()
    other = dc.cached_code(source.replace("p[0]", "p[0] * 2"), "<lagrange rhs>")  # another source, another key
    namespace = {}
    exec(other, namespace)  # noqa: S102
    assert namespace["rhs"](0.0, [0.5, 0.0], [4.0]) == [0.0, -4.0]
